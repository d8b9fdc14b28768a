//! The words every block family shares: blanks, numbers, values, feeds, M functions.
//!   value  := [+|-] ( (Q|QL|QR)<digits> | <digits>[.<digits>] | .<digits> )
//!   feed   := FMAX | F MAX | F AUTO | F value

use crate::diag::Expected;
use crate::plane::{Feed, Sign, Value};

/// Why a word reader stopped: where, and what it wanted there (if it can say).
///
/// `Expected` is recoverable: the word is not there, the caller may try another one.
/// `Cut` is hard: the word started but is malformed, no alternative can help.
/// [`super::Cx::fail`] turns either into the block's one diagnostic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Stop<'a> {
    Expected { at: &'a str, what: Option<Expected> },
    Cut { at: &'a str, what: Option<Expected> },
}

impl<'a> Stop<'a> {
    /// The same stop as a hard one (the word has begun, so its absence is an error).
    pub(crate) fn cut(self) -> Self {
        match self {
            Stop::Expected { at, what } | Stop::Cut { at, what } => Stop::Cut { at, what },
        }
    }
}

/// One step of a word reader: the rest of the input and what was read, or where it stopped.
pub(crate) type Step<'a, T> = Result<(&'a str, T), Stop<'a>>;

/// A recoverable stop at `at` naming what was expected.
pub(crate) fn expected<'a, T>(at: &'a str, what: Expected) -> Step<'a, T> {
    Err(Stop::Expected { at, what: Some(what) })
}

/// A hard stop (no alternative can help) at `at`.
pub(crate) fn failure<'a, T>(at: &'a str, what: Expected) -> Step<'a, T> {
    Err(Stop::Cut { at, what: Some(what) })
}

/// The longest non-empty prefix of ASCII bytes matching `f`; a nameless recoverable stop if
/// there is none.
fn ascii_run(i: &str, f: impl Fn(&u8) -> bool) -> Step<'_, &str> {
    match i.bytes().position(|b| !f(&b)).unwrap_or(i.len()) {
        0 => Err(Stop::Expected { at: i, what: None }),
        // Only ASCII bytes matched, so `n` is a char boundary.
        n => Ok((&i[n..], &i[..n])),
    }
}

fn is_blank(c: char) -> bool {
    c == ' ' || c == '\t'
}

/// Zero or more blanks.
pub(crate) fn sp(i: &str) -> &str {
    i.trim_start_matches(is_blank)
}

/// `true` at the end of a word: end of input or a blank.
pub(crate) fn at_boundary(i: &str) -> bool {
    i.as_bytes().first().is_none_or(|&b| b == b' ' || b == b'\t')
}

/// A keyword that must stand alone (`TURN`, `FMAX`, `RESET`), followed by a blank or the end.
pub(crate) fn keyword<'a>(i: &'a str, kw: &'static str) -> Option<&'a str> {
    let rest = i.strip_prefix(kw)?;
    at_boundary(rest).then_some(rest)
}

/// Unsigned decimal integer (block numbers, M functions, cycle numbers).
pub(crate) fn uint(i: &str) -> Step<'_, u32> {
    let (rest, digits) = ascii_run(i, u8::is_ascii_digit)?;
    match digits.parse::<u32>() {
        Ok(v) => Ok((rest, v)),
        Err(_) => failure(i, Expected::NumberU32),
    }
}

/// A number as the control writes it: optional sign, optional leading or trailing dot.
pub(crate) fn number(i: &str) -> Step<'_, f64> {
    let b = i.as_bytes();
    let mut n = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let start = n;
    while b.get(n).is_some_and(u8::is_ascii_digit) {
        n += 1;
    }
    let mut digits = n - start;
    if b.get(n) == Some(&b'.') {
        n += 1;
        let f = n;
        while b.get(n).is_some_and(u8::is_ascii_digit) {
            n += 1;
        }
        digits += n - f;
    }
    if digits == 0 {
        return expected(i, Expected::Number);
    }
    // All bytes up to `n` are ASCII, so `n` is a char boundary.
    match crate::number::parse_f64(&i[..n]) {
        Some(v) if v.is_finite() => Ok((&i[n..], v)),
        _ => failure(i, Expected::Number),
    }
}

/// A number or a Q parameter (`+Q27`, `-Q120`).
pub(crate) fn value(i: &str) -> Step<'_, Value> {
    let (after_sign, negate) = match i.as_bytes().first() {
        Some(b'-') => (&i[1..], true),
        Some(b'+') => (&i[1..], false),
        _ => (i, false),
    };
    if let Some(q) = q_param(after_sign) {
        let (rest, index) = q?;
        return Ok((rest, Value::Param { index, negate }));
    }
    let (rest, v) = number(i)?;
    Ok((rest, Value::Number(v)))
}

/// A numeric parameter `Q<n>`, `QL<n>` or `QR<n>` as its index in the AST
/// ([`crate::ast::QL_BASE`]); `None` if `i` starts none of them.
pub(crate) fn q_param(i: &str) -> Option<Step<'_, u32>> {
    let after = i.strip_prefix('Q')?;
    let (digits, base, max) = match after.as_bytes().first() {
        Some(b'L') => (&after[1..], crate::ast::QL_BASE, 499),
        Some(b'R') => (&after[1..], crate::ast::QR_BASE, 499),
        _ => (after, 0, crate::ast::QL_BASE - 1),
    };
    if !digits.as_bytes().first().is_some_and(u8::is_ascii_digit) {
        return None;
    }
    Some(match uint(digits) {
        Ok((rest, n)) if n <= max => Ok((rest, base + n)),
        Ok(_) => failure(i, Expected::Nc("Q0…Q1999|QL0…QL499|QR0…QR499")),
        Err(e) => Err(e),
    })
}

/// A value that must end its word (`SPA+0 ` but not `SPA+0X`).
pub(crate) fn word_value(i: &str) -> Step<'_, Value> {
    let (rest, v) = value(i)?;
    if at_boundary(rest) { Ok((rest, v)) } else { failure(rest, Expected::Blank) }
}

/// `FMAX`, `F MAX`, `F AUTO` or `F` value. Stops with `Expected` (not `Cut`) if no `F` is there.
pub(crate) fn feed(i: &str) -> Step<'_, Feed> {
    if let Some(rest) = keyword(i, "FMAX") {
        return Ok((rest, Feed::Max));
    }
    let Some(after_f) = i.strip_prefix('F') else {
        return expected(i, Expected::Nc("F"));
    };
    let spaced = sp(after_f);
    if let Some(rest) = keyword(spaced, "MAX") {
        return Ok((rest, Feed::Max));
    }
    if let Some(rest) = keyword(spaced, "AUTO") {
        return Ok((rest, Feed::Auto));
    }
    match word_value(after_f) {
        Ok((rest, v)) => Ok((rest, Feed::Value(v))),
        Err(Stop::Expected { at, .. }) => Err(Stop::Cut { at, what: Some(Expected::Nc("F…|FMAX|F AUTO")) }),
        Err(e) => Err(e),
    }
}

/// `M` followed by digits, as one word.
pub(crate) fn m_function(i: &str) -> Step<'_, u32> {
    let Some(rest) = i.strip_prefix('M') else { return Err(Stop::Expected { at: i, what: None }) };
    let (rest, m) = uint(rest)?;
    if at_boundary(rest) { Ok((rest, m)) } else { failure(rest, Expected::Blank) }
}

/// `+` or `-` directly after a word (`DR+`, `SEQ-`).
pub(crate) fn sign(i: &str) -> Step<'_, Sign> {
    match i.as_bytes().first() {
        Some(b'+') => Ok((&i[1..], Sign::Plus)),
        Some(b'-') => Ok((&i[1..], Sign::Minus)),
        _ => expected(i, Expected::Nc("+|-")),
    }
}

/// A run of upper-case letters (the key of a word).
pub(crate) fn letters(i: &str) -> Step<'_, &str> {
    ascii_run(i, u8::is_ascii_uppercase)
}

/// Everything up to the next blank (a name, a path).
pub(crate) fn token(i: &str) -> Step<'_, &str> {
    let n = i.find([' ', '\t']).unwrap_or(i.len());
    if n == 0 { expected(i, Expected::Name) } else { Ok((&i[n..], &i[..n])) }
}

/// A `"quoted"` name.
pub(crate) fn quoted(i: &str) -> Step<'_, &str> {
    let Some(inner) = i.strip_prefix('"') else { return expected(i, Expected::QuotedName) };
    match inner.find('"') {
        Some(end) => Ok((&inner[end + 1..], &inner[..end])),
        None => failure(i, Expected::Nc("\"")),
    }
}

/// ` + v` or ` - v`: a sign with blanks around it before an unsigned value; `Some((negative,
/// value))`.
fn spaced_sign(i: &str) -> Option<(bool, &str)> {
    let t = i.trim_start_matches([' ', '\t']);
    let (negative, v) = match t.as_bytes().first() {
        Some(b'+') => (false, &t[1..]),
        Some(b'-') => (true, &t[1..]),
        _ => return None,
    };
    let v = v.trim_start_matches([' ', '\t']);
    let blank = t.len() < i.len() || v.len() + 1 < t.len();
    let unsigned = v.as_bytes().first().is_some_and(|b| b.is_ascii_digit() || *b == b'.' || *b == b'Q');
    (blank && unsigned).then_some((negative, v))
}

/// An axis word `[I]X±v`; `Expected` if the input does not start with an axis letter.
pub(crate) fn axis_word(i: &str) -> Step<'_, crate::ast::AxisWord> {
    let (incremental, rest) = match i.strip_prefix('I') {
        Some(r) => (true, r),
        None => (false, i),
    };
    let Some(axis) = rest.as_bytes().first().copied().and_then(crate::ast::Axis::from_byte) else {
        return expected(i, Expected::Axis);
    };
    // An axis letter followed by a letter is another word (`CC`, `AUTO`).
    let after = &rest[1..];
    if after.as_bytes().first().is_none_or(|b| b.is_ascii_alphabetic()) {
        return expected(i, Expected::Axis);
    }
    // `Z + Q13`, `X - 5` (blanks around the sign, as some CAM systems write): the same word as
    // `Z+Q13`, `X-5`.
    if let Some((sign, value)) = spaced_sign(after) {
        let (rest, value) = word_value(value).map_err(Stop::cut)?;
        let value = match (sign, value) {
            (true, Value::Number(v)) => Value::Number(-v),
            (true, Value::Param { index, negate }) => Value::Param { index, negate: !negate },
            (false, v) => v,
        };
        return Ok((rest, crate::ast::AxisWord { axis, value, incremental }));
    }
    let (rest, value) = word_value(after).map_err(Stop::cut)?;
    Ok((rest, crate::ast::AxisWord { axis, value, incremental }))
}
