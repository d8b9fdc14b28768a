//! The words every block family shares: blanks, numbers, values, feeds, M functions.
//!   value  := [+|-] ( (Q|QL|QR)\<digits> | \<digits>[.\<digits>] | .\<digits> )
//!   feed   := FMAX | F MAX | F AUTO | F value

use nom::bytes::complete::{tag, take_till1, take_until, take_while1};
use nom::character::complete::{char, digit0, digit1, one_of, space0};
use nom::combinator::opt;
use nom::error::{ErrorKind, ParseError};
use nom::sequence::{preceded, terminated};
use nom::{IResult, Parser};

use crate::diag::{DiagCode, Expected};
use crate::plane::{Feed, Sign, Value};

/// The parser's nom error: where a word reader stopped and why ([`Why`]: what it wanted there,
/// or a diagnostic of its own, whose span is then `at` itself). As nom's `Err::Error` it is
/// recoverable: the word is not there, the caller may try another one (a whole family's
/// `Err::Error`: the block is not of this family). As `Err::Failure` (nom's `cut`) it is hard:
/// the word began but is malformed, no alternative can help. [`super::Cx::fail`] turns either
/// into the block's one diagnostic. Small and `Copy`: a stop is moved through every combinator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct NcError<'a> {
    pub(crate) at: &'a str,
    pub(crate) why: Why,
}

/// Why a reader stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Why {
    /// The word at the stop cannot be read; nothing more to say.
    Unsaid,
    /// The word at the stop cannot be read; this was expected there.
    Expected(Expected),
    /// A mandatory word is not there ([`DiagCode::MissingWord`]).
    Missing(&'static str),
    /// The same word twice ([`DiagCode::Duplicate`]).
    Duplicate(Named),
    /// A word this block does not take ([`DiagCode::NotAllowed`]).
    NotAllowed,
    /// `SEQ` and `SYM` in one PLANE block.
    SeqWithSym,
}

/// How a duplicate names its word.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Named {
    /// A name of the grammar (an axis letter, `DR2`).
    Given(&'static str),
    /// The first so many bytes at the stop, as written.
    Written(usize),
    /// A cycle's parameter by its number, `QS` for a string parameter (`Q200`, `QS500`).
    Param { index: u32, string: bool },
}

impl NcError<'_> {
    /// What was expected where the stop is an unreadable word.
    pub(crate) fn expected(&self) -> Option<Expected> {
        match self.why {
            Why::Expected(what) => Some(what),
            _ => None,
        }
    }

    /// The diagnostic of a stop with one of its own, `None` for an unreadable word.
    pub(crate) fn code(&self) -> Option<DiagCode> {
        let written = |n: usize| self.at.get(..n).unwrap_or(self.at).to_owned();
        Some(match self.why {
            Why::Unsaid | Why::Expected(_) => return None,
            Why::Missing(word) => DiagCode::MissingWord { word },
            Why::Duplicate(Named::Given(word)) => DiagCode::Duplicate { word: word.to_owned() },
            Why::Duplicate(Named::Written(n)) => DiagCode::Duplicate { word: written(n) },
            Why::Duplicate(Named::Param { index, string }) => {
                DiagCode::Duplicate { word: format!("{}{index}", if string { "QS" } else { "Q" }) }
            }
            Why::NotAllowed => DiagCode::NotAllowed { word: self.at.to_owned() },
            Why::SeqWithSym => DiagCode::SeqWithSym,
        })
    }
}

impl<'a> ParseError<&'a str> for NcError<'a> {
    fn from_error_kind(input: &'a str, _: ErrorKind) -> Self {
        NcError { at: input, why: Why::Unsaid }
    }

    /// The innermost stop says best what was wrong.
    fn append(_: &'a str, _: ErrorKind, other: Self) -> Self {
        other
    }
}

/// Why a word reader stopped.
pub(crate) type Stop<'a> = nom::Err<NcError<'a>>;

/// One step of a word reader: nom's result with the parser's error.
pub(crate) type Step<'a, T> = IResult<&'a str, T, NcError<'a>>;

/// A recoverable stop at `at` naming what was expected.
pub(crate) fn expected<'a, T>(at: &'a str, what: Expected) -> Step<'a, T> {
    Err(nom::Err::Error(NcError { at, why: Why::Expected(what) }))
}

/// A hard stop (no alternative can help) at `at`.
pub(crate) fn failure<'a, T>(at: &'a str, what: Expected) -> Step<'a, T> {
    invalid(at, Some(what))
}

/// A hard stop on the word at `at`, naming what was expected there if it can.
pub(crate) fn invalid<'a, T>(at: &'a str, what: Option<Expected>) -> Step<'a, T> {
    Err(nom::Err::Failure(NcError { at, why: what.map_or(Why::Unsaid, Why::Expected) }))
}

/// A hard stop with a diagnostic of its own, marking `len` bytes from `at`.
pub(crate) fn fault<T>(at: &str, len: usize, why: Why) -> Step<'_, T> {
    Err(nom::Err::Failure(NcError { at: at.get(..len).unwrap_or(at), why }))
}

/// A hard stop "the same word twice" on `len` bytes from `at`, naming `word`.
pub(crate) fn duplicate<T>(at: &str, len: usize, word: Named) -> Step<'_, T> {
    fault(at, len, Why::Duplicate(word))
}

/// A hard stop "missing word" at `at`, marking the word there (nothing at the end).
pub(crate) fn missing<'a, T>(at: &'a str, word: &'static str) -> Step<'a, T> {
    fault(at, word_len(at), Why::Missing(word))
}

/// A hard stop "not allowed in this block" on the word at `at`.
pub(crate) fn not_allowed<T>(at: &str) -> Step<'_, T> {
    fault(at, word_len(at), Why::NotAllowed)
}

/// The length of the word at `i`: up to the next blank.
pub(crate) fn word_len(i: &str) -> usize {
    i.find([' ', '\t']).unwrap_or(i.len())
}

/// The same stop as a hard one (the word has begun, so its absence is an error): what nom's
/// `cut` makes of a parser, for a stop already made.
pub(crate) fn hard(e: Stop<'_>) -> Stop<'_> {
    match e {
        nom::Err::Error(e) => nom::Err::Failure(e),
        e => e,
    }
}

/// The same stop as a recoverable one: the word is not this one, another may be.
pub(crate) fn soft(e: Stop<'_>) -> Stop<'_> {
    match e {
        nom::Err::Failure(e) => nom::Err::Error(e),
        e => e,
    }
}

/// Where a reader stopped and what it expected there. Every reader is nom's `complete` kind,
/// so an incomplete input does not occur; were it to, it reads as a stop at the end.
pub(crate) fn stopped_at(e: Stop<'_>) -> NcError<'_> {
    match e {
        nom::Err::Error(e) | nom::Err::Failure(e) => e,
        nom::Err::Incomplete(_) => NcError { at: "", why: Why::Unsaid },
    }
}

/// Runs a nom parser to the end of `i` (nom's complete mode) and gives its rest as the suffix
/// of `i` it is: every diagnostic is placed by the rest's address, and nom 8.0 hands back an
/// empty rest at the start of the input instead of at its end (the unit test
/// `an_empty_rest_lies_at_the_end_of_the_input` pins it).
pub(crate) fn run<'a, O>(
    mut p: impl Parser<&'a str, Output = O, Error = NcError<'a>>,
    i: &'a str,
) -> Step<'a, O> {
    let (rest, o) = p.parse_complete(i)?;
    Ok((&i[i.len() - rest.len()..], o))
}

/// Zero or more blanks.
pub(crate) fn sp(i: &str) -> &str {
    run(space0, i).map_or(i, |(rest, _)| rest)
}

/// `true` at the end of a word: end of input or a blank.
pub(crate) fn at_boundary(i: &str) -> bool {
    i.as_bytes().first().is_none_or(|&b| b == b' ' || b == b'\t')
}

/// The end of a word as a nom parser: consumes nothing, stops unless at a blank or the end.
pub(crate) fn boundary(i: &str) -> Step<'_, ()> {
    if at_boundary(i) { Ok((i, ())) } else { expected(i, Expected::Blank) }
}

/// Blanks as a nom parser (nom 8.0's `space0` gives an all-blank input's empty rest at its
/// start: `sp` places it at the end).
pub(crate) fn blanks(i: &str) -> Step<'_, ()> {
    Ok((sp(i), ()))
}

/// `p` after blanks.
pub(crate) fn lex<'a, O>(
    p: impl Parser<&'a str, Output = O, Error = NcError<'a>>,
) -> impl Parser<&'a str, Output = O, Error = NcError<'a>> {
    preceded(blanks, p)
}

/// The keyword `word` standing alone (followed by a blank or the end), after blanks; a
/// recoverable stop naming it otherwise.
pub(crate) fn kw<'a>(word: &'static str) -> impl Parser<&'a str, Output = &'static str, Error = NcError<'a>> {
    move |i: &'a str| {
        let i = sp(i);
        match keyword(i, word) {
            Some(rest) => Ok((rest, word)),
            None => expected(i, Expected::Nc(word)),
        }
    }
}

/// The first of `table`'s keywords standing alone here (after blanks), as its value; a
/// recoverable stop expecting `what` otherwise. One loop over a table where an `alt` of
/// `value(…, kw(…))` would unroll a parser per word.
pub(crate) fn choice<'a, T: Copy>(
    table: &'static [(&'static str, T)],
    what: &'static str,
) -> impl Parser<&'a str, Output = T, Error = NcError<'a>> {
    move |i: &'a str| {
        let i = sp(i);
        match table.iter().find_map(|&(word, v)| keyword(i, word).map(|rest| (rest, v))) {
            Some(found) => Ok(found),
            None => expected(i, Expected::Nc(what)),
        }
    }
}

/// The end of the block, after blanks: anything else is a hard stop on the word there.
pub(crate) fn end_of_block(i: &str) -> Step<'_, ()> {
    let rest = sp(i);
    if rest.is_empty() {
        Ok((rest, ()))
    } else {
        Err(nom::Err::Failure(NcError { at: rest, why: Why::Unsaid }))
    }
}

/// `p`, and then nothing but blanks up to the end of the block.
pub(crate) fn whole<'a, O>(
    p: impl Parser<&'a str, Output = O, Error = NcError<'a>>,
) -> impl Parser<&'a str, Output = O, Error = NcError<'a>> {
    terminated(p, end_of_block)
}

/// `p` with what it consumed: the text of the word it read (a diagnostic's span).
pub(crate) fn spanned<'a, O>(
    mut p: impl Parser<&'a str, Output = O, Error = NcError<'a>>,
) -> impl Parser<&'a str, Output = (&'a str, O), Error = NcError<'a>> {
    move |i: &'a str| {
        let (rest, o) = p.parse(i)?;
        Ok((rest, (&i[..i.len() - rest.len()], o)))
    }
}

/// `p`, its recoverable stop said as expecting `what` at the place it was tried.
pub(crate) fn or_expected<'a, O>(
    mut p: impl Parser<&'a str, Output = O, Error = NcError<'a>>,
    what: Expected,
) -> impl Parser<&'a str, Output = O, Error = NcError<'a>> {
    move |i: &'a str| match p.parse(i) {
        Err(nom::Err::Error(_)) => expected(i, what),
        r => r,
    }
}

/// A keyword that must stand alone (`TURN`, `FMAX`, `RESET`), followed by a blank or the end.
pub(crate) fn keyword<'a>(i: &'a str, kw: &'static str) -> Option<&'a str> {
    let (rest, _) = run(tag(kw), i).ok()?;
    at_boundary(rest).then_some(rest)
}

/// `DEF` as a keyword, also run together with the number after it: `CYCL DEF 9.0` and
/// `TOOL DEF 1` as the control writes them, `CYCL DEF9.0` and `TOOL DEF1` as some programs do.
pub(crate) fn def_keyword(i: &str) -> Option<&str> {
    i.strip_prefix("DEF").filter(|r| at_boundary(r) || r.starts_with(|c: char| c.is_ascii_digit()))
}

/// Unsigned decimal integer (block numbers, M functions, cycle numbers).
pub(crate) fn uint(i: &str) -> Step<'_, u32> {
    let (rest, digits) = run(digit1, i)?;
    match digits.parse::<u32>() {
        Ok(v) => Ok((rest, v)),
        Err(_) => failure(i, Expected::NumberU32),
    }
}

/// A number as the control writes it: optional sign, optional leading or trailing dot.
pub(crate) fn number(i: &str) -> Step<'_, f64> {
    // What the sequence consumed, taken by hand: nom 8.0's `recognize` gave `+` for `+0` at the
    // end of the input.
    let (rest, _) = run((opt(one_of("+-")), digit0, opt((char('.'), digit0))), i)?;
    let text = &i[..i.len() - rest.len()];
    if !text.bytes().any(|b| b.is_ascii_digit()) {
        return expected(i, Expected::Number);
    }
    match crate::number::parse_f64(text) {
        Some(v) if v.is_finite() => Ok((rest, v)),
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

/// `FMAX`, `F MAX`, `F AUTO` or `F` value: a recoverable stop if no `F` is there, a hard one
/// once it began.
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
        Err(nom::Err::Error(e)) => failure(e.at, Expected::Nc("F…|FMAX|F AUTO")),
        Err(e) => Err(e),
    }
}

/// `M` followed by digits, as one word.
pub(crate) fn m_function(i: &str) -> Step<'_, u32> {
    let (rest, m) = run(preceded(char('M'), uint), i)?;
    if at_boundary(rest) { Ok((rest, m)) } else { failure(rest, Expected::Blank) }
}

/// An old control's empty word: TNC 155/355 listings print the dialog's words with no value where
/// the programmer entered nothing (`L X+32,000 R F5000 M`, `L Y+6,500 R F M`, `CYCL CALL M`).
/// Nothing was programmed, so the word is read as absent (the radius compensation and the feed
/// stay as they were, no M function). The rest after the letter if `i` is one of `letters`
/// standing alone: followed by the end or by another word, not by a value written after a
/// blank (`F 500`, `R 5`) nor by `F`'s own `MAX` or `AUTO` (`F MAX`).
pub(crate) fn empty_word<'a>(i: &'a str, letters: &[u8]) -> Option<&'a str> {
    // The first byte is one of the ASCII `letters`, so slicing after it is on a char boundary.
    if !letters.contains(i.as_bytes().first()?) {
        return None;
    }
    let rest = &i[1..];
    if !at_boundary(rest) {
        return None;
    }
    let next = space0::<_, ()>(rest).map_or(rest, |(r, _)| r);
    let another_word = next.starts_with(|c: char| c.is_ascii_alphabetic() && c != 'Q')
        && keyword(next, "MAX").is_none()
        && keyword(next, "AUTO").is_none();
    (next.is_empty() || another_word).then_some(rest)
}

/// `+` or `-` directly after a word (`DR+`, `SEQ-`).
pub(crate) fn sign(i: &str) -> Step<'_, Sign> {
    match run(one_of("+-"), i) {
        Ok((rest, c)) => Ok((rest, if c == '+' { Sign::Plus } else { Sign::Minus })),
        Err(_) => expected(i, Expected::Nc("+|-")),
    }
}

/// A run of upper-case letters (the key of a word).
pub(crate) fn letters(i: &str) -> Step<'_, &str> {
    run(take_while1(|c: char| c.is_ascii_uppercase()), i)
}

/// Everything up to the next blank (a name, a path).
pub(crate) fn token(i: &str) -> Step<'_, &str> {
    run(take_till1(|c: char| c == ' ' || c == '\t'), i).or_else(|_| expected(i, Expected::Name))
}

/// A `"quoted"` name.
pub(crate) fn quoted(i: &str) -> Step<'_, &str> {
    let Ok((inner, _)) = run(char('"'), i) else {
        return expected(i, Expected::QuotedName);
    };
    match run((take_until("\""), char('"')), inner) {
        Ok((rest, (name, _))) => Ok((rest, name)),
        Err(_) => failure(i, Expected::Nc("\"")),
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
        let (rest, value) = word_value(value).map_err(hard)?;
        let value = match (sign, value) {
            (true, Value::Number(v)) => Value::Number(-v),
            (true, Value::Param { index, negate }) => Value::Param { index, negate: !negate },
            (false, v) => v,
        };
        return Ok((rest, crate::ast::AxisWord { axis, value, incremental }));
    }
    let (rest, value) = word_value(after).map_err(hard)?;
    Ok((rest, crate::ast::AxisWord { axis, value, incremental }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every reader at the very end of a block's text: nom's combinators must run complete (a
    /// streaming run would stop with "incomplete" there).
    #[test]
    fn readers_read_up_to_the_end_of_the_text() {
        assert_eq!(number("+0"), Ok(("", 0.0)));
        assert_eq!(number("-.5"), Ok(("", -0.5)));
        assert_eq!(number("7."), Ok(("", 7.0)));
        assert_eq!(value("-QR3"), Ok(("", Value::Param { index: crate::ast::QR_BASE + 3, negate: true })));
        assert_eq!(m_function("M30"), Ok(("", 30)));
        assert_eq!(sign("+"), Ok(("", Sign::Plus)));
        assert_eq!(letters("FMAX"), Ok(("", "FMAX")));
        assert_eq!(token("TNC:\\A.H"), Ok(("", "TNC:\\A.H")));
        assert_eq!(quoted("\"name\""), Ok(("", "name")));
        assert_eq!(keyword("STAY", "STAY"), Some(""));
        assert_eq!(uint("4294967296").map_err(stopped_at).unwrap_err().expected(), Some(Expected::NumberU32));
        assert!(matches!(quoted("\"open"), Err(nom::Err::Failure(_))), "an open quote is hard");
        assert!(matches!(number("X"), Err(nom::Err::Error(_))), "no number: try another word");
    }

    #[test]
    fn an_empty_rest_lies_at_the_end_of_the_input() {
        let at = |i: &str, rest: &str| rest.as_ptr() as usize - i.as_ptr() as usize;
        for i in ["100", "+0", "7.", "M30", "STAY", "\"n\"", "ABC", "-QR3"] {
            let rests = [
                number(i).map(|r| r.0),
                m_function(i).map(|r| r.0),
                letters(i).map(|r| r.0),
                quoted(i).map(|r| r.0),
                value(i).map(|r| r.0),
                token(i).map(|r| r.0),
            ];
            for rest in rests.into_iter().flatten() {
                assert_eq!(at(i, rest), i.len() - rest.len(), "{i}");
            }
        }
        assert_eq!(at("  ", sp("  ")), 2);
    }
}
