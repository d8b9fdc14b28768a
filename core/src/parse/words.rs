//! The words every block family shares: blanks, numbers, values, feeds, M functions.
//!   value  := [+|-] ( Q<digits> | <digits>[.<digits>] | .<digits> )
//!   feed   := FMAX | F MAX | F AUTO | F value

use nom::bytes::complete::{tag, take_while, take_while1};
use nom::error::{ContextError, ErrorKind, ParseError};
use nom::{IResult, Parser};

use crate::plane::{Feed, Sign, Value};

/// The parser error: where it stopped and, if known, what it wanted there.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PErr<'a> {
    pub input: &'a str,
    pub expected: Option<&'static str>,
}

impl<'a> ParseError<&'a str> for PErr<'a> {
    fn from_error_kind(input: &'a str, _kind: ErrorKind) -> Self {
        PErr { input, expected: None }
    }

    fn append(_input: &'a str, _kind: ErrorKind, other: Self) -> Self {
        other
    }
}

impl<'a> ContextError<&'a str> for PErr<'a> {
    fn add_context(_input: &'a str, ctx: &'static str, mut other: Self) -> Self {
        // The innermost context is the most precise one.
        if other.expected.is_none() {
            other.expected = Some(ctx);
        }
        other
    }
}

pub(crate) type PResult<'a, T> = IResult<&'a str, T, PErr<'a>>;

/// A recoverable error at `input` naming what was expected.
pub(crate) fn expected<'a, T>(input: &'a str, what: &'static str) -> PResult<'a, T> {
    Err(nom::Err::Error(PErr { input, expected: Some(what) }))
}

/// A hard error (no alternative can help) at `input`.
pub(crate) fn failure<'a, T>(input: &'a str, what: &'static str) -> PResult<'a, T> {
    Err(nom::Err::Failure(PErr { input, expected: Some(what) }))
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
pub(crate) fn uint(i: &str) -> PResult<'_, u32> {
    let (rest, digits) = take_while1(|c: char| c.is_ascii_digit()).parse(i)?;
    match digits.parse::<u32>() {
        Ok(v) => Ok((rest, v)),
        Err(_) => failure(i, "Zahl 0…4294967295"),
    }
}

/// A number as the control writes it: optional sign, optional leading or trailing dot.
pub(crate) fn number(i: &str) -> PResult<'_, f64> {
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
        return expected(i, "Zahl");
    }
    // All bytes up to `n` are ASCII, so `n` is a char boundary.
    match crate::number::parse_f64(&i[..n]) {
        Some(v) if v.is_finite() => Ok((&i[n..], v)),
        _ => failure(i, "Zahl"),
    }
}

/// A number or a Q parameter (`+Q27`, `-Q120`).
pub(crate) fn value(i: &str) -> PResult<'_, Value> {
    let (after_sign, negate) = match i.as_bytes().first() {
        Some(b'-') => (&i[1..], true),
        Some(b'+') => (&i[1..], false),
        _ => (i, false),
    };
    if let Some(q) = after_sign.strip_prefix('Q')
        && q.as_bytes().first().is_some_and(u8::is_ascii_digit)
    {
        let (rest, index) = uint(q)?;
        return Ok((rest, Value::Param { index, negate }));
    }
    let (rest, v) = number(i)?;
    Ok((rest, Value::Number(v)))
}

/// A value that must end its word (`SPA+0 ` but not `SPA+0X`).
pub(crate) fn word_value(i: &str) -> PResult<'_, Value> {
    let (rest, v) = value(i)?;
    if at_boundary(rest) { Ok((rest, v)) } else { failure(rest, "Leerzeichen") }
}

/// `FMAX`, `F MAX`, `F AUTO` or `F` value. Returns `Error` (not `Failure`) if no `F` is there.
pub(crate) fn feed(i: &str) -> PResult<'_, Feed> {
    if let Some(rest) = keyword(i, "FMAX") {
        return Ok((rest, Feed::Max));
    }
    let Ok((after_f, _)) = tag::<_, _, PErr<'_>>("F").parse(i) else {
        return expected(i, "F");
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
        Err(nom::Err::Error(e)) => {
            Err(nom::Err::Failure(PErr { input: e.input, expected: Some("F…|FMAX|F AUTO") }))
        }
        Err(e) => Err(e),
    }
}

/// `M` followed by digits, as one word.
pub(crate) fn m_function(i: &str) -> PResult<'_, u32> {
    let (rest, _) = tag("M").parse(i)?;
    let (rest, m) = uint(rest)?;
    if at_boundary(rest) { Ok((rest, m)) } else { failure(rest, "Leerzeichen") }
}

/// `+` or `-` directly after a word (`DR+`, `SEQ-`).
pub(crate) fn sign(i: &str) -> PResult<'_, Sign> {
    match i.as_bytes().first() {
        Some(b'+') => Ok((&i[1..], Sign::Plus)),
        Some(b'-') => Ok((&i[1..], Sign::Minus)),
        _ => expected(i, "+|-"),
    }
}

/// A run of upper-case letters (the key of a word).
pub(crate) fn letters(i: &str) -> PResult<'_, &str> {
    take_while1(|c: char| c.is_ascii_uppercase()).parse(i)
}

/// Everything up to the next blank (a name, a path).
pub(crate) fn token(i: &str) -> PResult<'_, &str> {
    let (rest, t) = take_while(|c: char| !is_blank(c)).parse(i)?;
    if t.is_empty() { expected(i, "Name") } else { Ok((rest, t)) }
}

/// A `"quoted"` name.
pub(crate) fn quoted(i: &str) -> PResult<'_, &str> {
    let Some(inner) = i.strip_prefix('"') else { return expected(i, "\"Name\"") };
    match inner.find('"') {
        Some(end) => Ok((&inner[end + 1..], &inner[..end])),
        None => failure(i, "\""),
    }
}

/// An axis word `[I]X±v`; `Error` if the input does not start with an axis letter.
pub(crate) fn axis_word(i: &str) -> PResult<'_, crate::ast::AxisWord> {
    let (incremental, rest) = match i.strip_prefix('I') {
        Some(r) => (true, r),
        None => (false, i),
    };
    let Some(axis) = rest.as_bytes().first().copied().and_then(crate::ast::Axis::from_byte) else {
        return expected(i, "Achse");
    };
    // An axis letter followed by a letter is another word (`CC`, `AUTO`).
    let after = &rest[1..];
    if after.as_bytes().first().is_none_or(|b| b.is_ascii_alphabetic()) {
        return expected(i, "Achse");
    }
    let (rest, value) = match word_value(after) {
        Ok(ok) => ok,
        Err(nom::Err::Error(e)) => return Err(nom::Err::Failure(e)),
        Err(e) => return Err(e),
    };
    Ok((rest, crate::ast::AxisWord { axis, value, incremental }))
}
