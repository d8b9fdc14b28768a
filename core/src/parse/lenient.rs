//! Spellings the control's editor never writes but programs from elsewhere contain: a decimal
//! comma (`X-49,000`) and a blank between an address letter and its value (`L Z 25.000 FMAX`,
//! `S 5000`). The parser reads the block as if it were written canonically, rewriting the
//! text in place with the same length, so every offset of a diagnostic stays where it was;
//! [`super::AcrossBlocks`] says each kind once per file, at its first block
//! (`unconfirmed::IMPORT_LENIENT_SPELLINGS`).

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

/// Each lenient spelling in `body` (one block's text without its comment), in order: its kind,
/// the bytes to show as the example, and where the value starts (for a blank after an address
/// letter: the letter at `a`, blanks up to `value`, the value up to `b`).
fn scan(body: &[u8], mut found: impl FnMut(Lenient, usize, usize, usize)) {
    // A header line or text in quotes is kept as written.
    if body.first() == Some(&b'(') {
        return;
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
        }
    }
}

/// `body` read canonically, or `None` when it has no lenient spelling: each decimal comma a
/// point, each value moved next to its address letter (`Z  25.0` → `Z25.0  `).
pub(crate) fn normalize(body: &str) -> Option<String> {
    let mut found = Vec::new();
    scan(body.as_bytes(), |kind, a, b, at| found.push((kind, a, b, at)));
    if found.is_empty() {
        return None;
    }
    let mut bytes = body.as_bytes().to_vec();
    // Commas first: a value that moves takes its point with it.
    for &(kind, _, _, at) in &found {
        if kind == Lenient::DecimalComma {
            bytes[at] = b'.';
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

/// The first occurrence of each kind in `body`: (kind, start, end).
pub(crate) fn first_of_each(body: &str, mut found: impl FnMut(Lenient, usize, usize)) {
    let mut seen = [false; 2];
    scan(body.as_bytes(), |kind, a, b, _| {
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
        ] {
            assert_eq!(normalize(text), None, "{text}");
        }
    }
}
