//! Spellings the control's editor never writes but programs from elsewhere contain: a decimal
//! comma (`X-49,000`), a blank between an address letter and its value (`L Z 25.000 FMAX`,
//! `S 5000`), a point after an M function (`M128.`), `R0` in a straight departure
//! (`DEP LT LEN10 R0`), an old-style cycle spelt `CYCLE DEF` and a straight line without its
//! `L` (`Z0.0 B0.0 C0.0 FMAX M91`), a spindle speed in a path block (`L Z-45. F1000. S6000`).
//! The parser reads the block as if it were written canonically, rewriting the text in place with
//! the same length, so every offset of a diagnostic stays where it was (a missing `L` is read by
//! the dispatcher instead, `parse_body`; a path block's `S` by its own parser, which keeps it as
//! the block's speed: Klartext has no other spelling for it); [`super::AcrossBlocks`] says each kind once per file,
//! at its first block (`unconfirmed::IMPORT_LENIENT_SPELLINGS`).
pub use crate::diag::Lenient;

/// The address letters whose value may follow after blanks.
fn is_address(b: u8) -> bool {
    matches!(b, b'X' | b'Y' | b'Z' | b'A' | b'B' | b'C' | b'U' | b'V' | b'W' | b'S' | b'F' | b'R')
}

fn is_blank(b: u8) -> bool {
    b == b' ' || b == b'\t'
}

/// Where an unsigned value starts: a digit or point. A sign after the blank (`Z -5`,
/// `Z + Q13`) is the word reader's own spelling with blanks around the sign, read as before.
fn starts_value(b: &[u8]) -> bool {
    b.first().is_some_and(|c| c.is_ascii_digit() || *c == b'.')
}

/// The linear and rotary axes a straight line moves.
fn is_axis(b: u8) -> bool {
    matches!(b, b'X' | b'Y' | b'Z' | b'A' | b'B' | b'C' | b'U' | b'V' | b'W')
}

/// Whether `body` (a block's text after its number) starts with a word only a path block has:
/// an axis word (`Z0.0`, `X+Q11`, `Y-.5`), a radius compensation (`R0`, `RL`, `RR`), a feed
/// (`F250.`, `F MAX`, `FMAX`) or a spindle speed (`S1000`): a straight line written without `L`
/// (`0560 R0 F MAX M99` and `0270 S1000 M3`, as an NX post for an older control writes them).
pub(crate) fn lacks_l(body: &[u8]) -> bool {
    let value_at =
        |i: usize| body.get(i).is_some_and(|c| c.is_ascii_digit() || matches!(c, b'+' | b'-' | b'.'));
    let word_ends = |i: usize| body.get(i).is_none_or(|&c| is_blank(c));
    match body.first() {
        Some(&c) if is_axis(c) => value_at(1),
        Some(b'R') => matches!(body.get(1), Some(b'0' | b'L' | b'R')) && word_ends(2),
        Some(b'F') => {
            let after = body[1..].iter().take_while(|&&c| is_blank(c)).count() + 1;
            value_at(1) || (body[after..].starts_with(b"MAX") && word_ends(after + 3))
        }
        Some(b'S') => body.get(1).is_some_and(u8::is_ascii_digit),
        _ => false,
    }
}

/// Where `IN` stands as the unit of a `BEGIN PGM`/`END PGM` block (`word`: from its first
/// word on), read as `INCH` by the frame's parser.
fn unit_in(word: &[u8]) -> Option<usize> {
    if !(word.starts_with(b"BEGIN PGM") || word.starts_with(b"END PGM")) {
        return None;
    }
    let end = word.iter().rposition(|&c| !is_blank(c))? + 1;
    (end >= 3 && &word[end - 2..end] == b"IN" && is_blank(word[end - 3])).then_some(end - 2)
}

/// Where the block's first word starts in a source line: after a skip mark and the block
/// number (`/`, `N`, digits, blanks).
fn first_word(line: &[u8]) -> usize {
    let mut i = line.iter().take_while(|&&c| c == b'/' || is_blank(c)).count();
    if line.get(i) == Some(&b'N') && line.get(i + 1).is_some_and(u8::is_ascii_digit) {
        i += 1;
    }
    let digits = line[i..].iter().take_while(|c| c.is_ascii_digit()).count();
    if digits == 0 {
        return i;
    }
    i + digits + line[i + digits..].iter().take_while(|&&c| is_blank(c)).count()
}

/// Where an `S…` word stands in a path block (`L`, `C`, `CR`, `CT`, `LP`, `CP`, or a straight
/// line without its `L`): the parser reads it as the spindle speed ([`Lenient::SpeedInPath`]).
fn speed_in_path(word: &[u8]) -> Option<usize> {
    let kw = word.iter().take_while(|&&c| !is_blank(c)).count();
    if !matches!(&word[..kw], b"L" | b"C" | b"CR" | b"CT" | b"LP" | b"CP") {
        if !lacks_l(word) {
            return None;
        }
        // `S1000 M3`: a straight line without `L` whose first word is the speed.
        if word[0] == b'S' {
            return Some(0);
        }
    }
    (kw + 1..word.len()).find(|&i| {
        is_blank(word[i - 1])
            && word[i] == b'S'
            && word.get(i + 1).is_some_and(|c| c.is_ascii_digit() || matches!(c, b'+' | b'-' | b'.' | b'Q'))
    })
}

/// Where an `F…` word stands in a tool definition (`TOOL DEF1 L+30,000 F300`, a training
/// simulator's tool feed): the parser reads the block without it ([`Lenient::FeedInToolDef`]).
fn feed_in_tool_def(word: &[u8]) -> Option<usize> {
    if !word.starts_with(b"TOOL DEF") {
        return None;
    }
    (9..word.len()).find(|&i| {
        is_blank(word[i - 1])
            && word[i] == b'F'
            && word.get(i + 1).is_some_and(|c| c.is_ascii_digit() || matches!(c, b'+' | b'-' | b'.' | b'Q'))
    })
}

/// Where a comment in parentheses after a block's words starts (`L IX-80 (MODAL DRILL POINT)`:
/// the `(` after a blank, outside quotes, the block's text ending with `)`), read as the
/// block's comment ([`Lenient::ParenComment`]). `word`: the block's text from its first word.
/// Not in the blocks whose parentheses are Klartext's own: a parameter block
/// (`Q1 = Q2 * (Q3 + 1)`, `FN 0: …`), a pattern (`PATTERN DEF ROW1 (X+25 … NUM5)`), an SQL
/// statement; nor in a structure block or a header line.
pub(crate) fn paren_comment(word: &[u8]) -> Option<usize> {
    if matches!(word.first(), None | Some(b'Q' | b'*' | b'('))
        || [&b"FN"[..], b"PATTERN", b"SQL"].iter().any(|k| word.starts_with(k))
    {
        return None;
    }
    // A continuation mark after it is the line's, not the comment's.
    let last = word.iter().rposition(|&c| !is_blank(c) && c != b'~')?;
    if word[last] != b')' {
        return None;
    }
    let mut quoted = false;
    for i in 1..last {
        match word[i] {
            b'"' => quoted = !quoted,
            b'(' if !quoted && is_blank(word[i - 1]) => return Some(i),
            _ => {}
        }
    }
    None
}

/// The word `R0` in a straight departure (`DEP LT`, `DEP LN`; the arcs' `R` is their radius):
/// its start.
fn radius_in_dep(body: &[u8]) -> Option<usize> {
    let rest = body.strip_prefix(b"DEP")?;
    let blanks = rest.iter().take_while(|&&c| is_blank(c)).count();
    let kind = &rest[blanks..];
    if blanks == 0 || !(kind.starts_with(b"LT") || kind.starts_with(b"LN")) {
        return None;
    }
    let bounded = |i: usize| i == body.len() || is_blank(body[i]);
    (3..body.len().saturating_sub(1))
        .find(|&i| is_blank(body[i - 1]) && body[i..].starts_with(b"R0") && bounded(i + 2))
}

/// Each lenient spelling in `body` (one block's text without its comment), in order: its kind,
/// the bytes to show as the example, and where the value starts (for a blank after an address
/// letter: the letter at `a`, blanks up to `value`, the value up to `b`). `start`: where the
/// block's first word is when `body` is the block's first line (the spellings that depend on
/// the block's kind are found only there).
fn scan(body: &[u8], start: Option<usize>, mut found: impl FnMut(Lenient, usize, usize, usize)) {
    // A header line or text in quotes is kept as written.
    if body.first() == Some(&b'(') {
        return;
    }
    // A comment in parentheses is the block's comment: nothing in it is a word.
    let paren = start.filter(|&w| w <= body.len()).and_then(|w| Some(w + paren_comment(&body[w..])?));
    let body = match paren {
        Some(p) => {
            let end = body.iter().rposition(|&c| c == b')').map_or(body.len(), |e| e + 1);
            found(Lenient::ParenComment, p, end, p);
            &body[..p]
        }
        None => body,
    };
    if let Some(w) = start.filter(|&w| w <= body.len()) {
        let word = &body[w..];
        if lacks_l(word) {
            let end = w + word.iter().take_while(|&&c| !is_blank(c)).count();
            found(Lenient::MissingL, w, end, w);
        }
        if let Some(unit) = unit_in(word) {
            found(Lenient::UnitIn, w + unit, w + unit + 2, w + unit);
        }
        if let Some(s) = speed_in_path(word) {
            let end = s + word[s..].iter().take_while(|&&c| !is_blank(c)).count();
            found(Lenient::SpeedInPath, w + s, w + end, w + s);
        }
        if let Some(f) = feed_in_tool_def(word) {
            let end = f + word[f..].iter().take_while(|&&c| !is_blank(c)).count();
            found(Lenient::FeedInToolDef, w + f, w + end, w + f);
        }
        if let Some(r) = radius_in_dep(word) {
            found(Lenient::RadiusInDep, w + r, w + r + 2, w + r);
        }
        // Only an old-style cycle (`9.0`): a new one's parameters follow on their own lines,
        // which the parser reads only after `CYCL DEF` itself.
        if let Some(rest) = word.strip_prefix(b"CYCLE DEF ")
            && rest.first().is_some_and(u8::is_ascii_digit)
            && rest.iter().find(|c| !c.is_ascii_digit()) == Some(&b'.')
        {
            found(Lenient::CycleSpeltOut, w, w + 9, w + 4);
        }
    }
    let mut quoted = false;
    for i in 0..body.len() {
        let b = body[i];
        if b == b'"' {
            quoted = !quoted;
        } else if quoted {
        } else if b == b','
            && i > 0
            && body[i - 1].is_ascii_digit()
            && body.get(i + 1).is_some_and(u8::is_ascii_digit)
        {
            // The whole number as the example: `-49,000`.
            let start = i - body[..i]
                .iter()
                .rev()
                .take_while(|c| c.is_ascii_digit() || matches!(c, b'+' | b'-'))
                .count();
            let end = i + 1 + body[i + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
            found(Lenient::DecimalComma, start, end, i);
        } else if is_address(b)
            && (i == 0 || is_blank(body[i - 1]))
            && body.get(i + 1).copied().is_some_and(is_blank)
        {
            let j = i + 1 + body[i + 1..].iter().take_while(|&&c| is_blank(c)).count();
            if starts_value(&body[j..]) {
                let k = j + 1 + body[j + 1..].iter().take_while(|&&c| !is_blank(c) && c != b'"').count();
                found(Lenient::BlankAfterAddress, i, k, j);
            }
        } else if b == b'M' && (i == 0 || is_blank(body[i - 1])) {
            let digits = body[i + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
            let point = i + 1 + digits;
            if digits > 0
                && body.get(point) == Some(&b'.')
                && (point + 1 == body.len() || is_blank(body[point + 1]))
            {
                found(Lenient::PointAfterM, i, point + 1, point);
            }
        }
    }
}

/// `body` (a block's text after its number) read canonically, or `None` when it has no lenient
/// spelling to rewrite: each decimal comma a point, each value moved next to its address letter
/// (`Z  25.0` → `Z25.0  `), the point after an M function, the `R0` of a straight departure and
/// the feed of a tool definition blanked.
pub(crate) fn normalize(body: &str) -> Option<String> {
    let mut found = Vec::new();
    scan(body.as_bytes(), Some(0), |kind, a, b, at| {
        if !matches!(kind, Lenient::MissingL | Lenient::UnitIn | Lenient::SpeedInPath | Lenient::ParenComment)
        {
            found.push((kind, a, b, at));
        }
    });
    if found.is_empty() {
        return None;
    }
    let mut bytes = body.as_bytes().to_vec();
    // Commas first: a value that moves takes its point with it.
    for &(kind, a, b, at) in &found {
        match kind {
            Lenient::DecimalComma => bytes[at] = b'.',
            Lenient::PointAfterM => bytes[at] = b' ',
            Lenient::RadiusInDep | Lenient::FeedInToolDef => bytes[a..b].fill(b' '),
            // `CYCLE DEF` → `CYCL  DEF`.
            Lenient::CycleSpeltOut => bytes[at] = b' ',
            Lenient::BlankAfterAddress
            | Lenient::MissingL
            | Lenient::UnitIn
            | Lenient::SpeedInPath
            | Lenient::ParenComment => {}
        }
    }
    for &(kind, a, b, value) in &found {
        if kind == Lenient::BlankAfterAddress {
            bytes[a + 1..b].rotate_left(value - a - 1);
        }
    }
    // Only ASCII bytes were moved or replaced by ASCII bytes.
    String::from_utf8(bytes).ok()
}

/// The first occurrence of each kind in the source line `line` (without its comment): (kind,
/// start, end). `first`: the block's first line, starting with its number.
pub(crate) fn first_of_each(line: &str, first: bool, mut found: impl FnMut(Lenient, usize, usize)) {
    let mut seen = [false; Lenient::ALL.len()];
    let body = line.as_bytes();
    scan(body, first.then(|| first_word(body)), |kind, a, b, _| {
        let k = kind as usize;
        if !seen[k] {
            seen[k] = true;
            found(kind, a, b);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rewrites_in_place_with_the_same_length() {
        for (text, want) in [
            ("L Z 25.000 FMAX", "L Z25.000  FMAX"),
            ("BLK FORM 0.1 Z X-49,000 Y-30,000 Z-10,000", "BLK FORM 0.1 Z X-49.000 Y-30.000 Z-10.000"),
            ("TOOL CALL 3 Z S 5000,000", "TOOL CALL 3 Z S5000.000 "),
            ("L X  5 Y-2", "L X5   Y-2"),
            ("Q4 = Q4 + 0,001", "Q4 = Q4 + 0.001"),
            ("L M128. F10000.", "L M128  F10000."),
            ("DEP LT LEN10 R0", "DEP LT LEN10   "),
            ("DEP LN LEN5 R0 F200", "DEP LN LEN5    F200"),
            ("CYCLE DEF 9.0 DWELL TIME", "CYCL  DEF 9.0 DWELL TIME"),
            ("TOOL DEF1 L+30,000 F300", "TOOL DEF1 L+30.000     "),
        ] {
            let got = normalize(text).unwrap_or_else(|| panic!("{text}"));
            assert_eq!(got, want);
            assert_eq!(got.len(), text.len());
        }
    }

    #[test]
    fn leaves_canonical_and_other_spellings_alone() {
        for text in [
            "L Z+25 FMAX",
            "L Z + Q13 FMAX",
            "BLK FORM 0.1 Z X+0 Y+0 Z-40",
            "CYCL DEF 8.1 X Y",
            "TOOL CALL 1 Z S5000",
            "QS1 = \"X 5,5\"",
            "( Quader: QX100 QY90 QZ20 )",
            "CALL LBL 5 REP 2",
            "DEP CT CCA90 R5 F100",
            "L M128.5",
            "Z0.0 B0.0",
            "CYCLE DEF 200 BOHREN",
            "TOOL CALL 1 Z S500 F300",
        ] {
            assert_eq!(normalize(text), None, "{text}");
        }
    }
}
