//! Cycle definitions and calls.
//!   def  := CYCL DEF n name [~] { NL (Q\<n>=(value|PREDEF|FMAX|MAX|FAUTO|AUTO) | QS\<n>="text") [;label] [~] }
//!           (continuation lines, DOMAIN.md §8)
//!   old  := CYCL DEF n.0 name | CYCL DEF n.s words
//!   call := CYCL CALL { Mn } | CYCL CALL PAT [F…] { Mn } | CYCL CALL POS X… Y… Z… [F…|FMAX] { Mn }
//!   (CYCL CALL POS with all three axes: iTNC 530 cycle manual, DOMAIN.md §11)

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::character::complete::char;
use nom::combinator::{cut, map, opt, value};
use nom::sequence::{preceded, terminated};

use super::Cx;
use super::words::{
    Named, Step, axis_word, boundary, def_keyword, duplicate, empty_word, end_of_block, expected, feed, hard,
    invalid, keyword, kw, letters, lex, m_function, missing, not_allowed, or_expected, quoted, run, sp, uint,
    word_value,
};
use crate::ast::{
    Axis, BlockBody, CycleDef, CycleDefOld, CycleParam, CycleValue, OldCycleData, OldCycleWord,
};
use crate::diag::{DiagCode, Expected};

/// `CYCL DEF` (also `CYCL DEF9.0`, the number run on) or `TCH PROBE` (`probe`).
fn def_head(i: &str, probe: bool) -> Step<'_, ()> {
    let rest = if probe {
        keyword(i, "TCH").map(sp).and_then(|r| keyword(r, "PROBE"))
    } else {
        keyword(i, "CYCL").map(sp).and_then(def_keyword)
    };
    match rest {
        Some(r) => Ok((sp(r), ())),
        None => invalid(i, Some(Expected::Nc(if probe { "TCH PROBE" } else { "CYCL DEF" }))),
    }
}

/// `QS` (a string parameter: `true`) or `Q`.
fn key(i: &str) -> Step<'_, bool> {
    alt((value(true, tag("QS")), value(false, tag("Q")))).parse(i)
}

/// One parameter line `Q200=2 ;SICHERHEITS-ABST. ~` or `QS500="TEXT"`: index, value, label.
fn param_line(line: &str) -> Step<'_, (u32, CycleValue, Option<&str>)> {
    let (body, label) = super::split_comment(line);
    let body = super::strip_tilde(body.trim());
    let label = label.map(|l| super::strip_tilde(l.trim()));
    // `QS500="TEXT"`: a string parameter takes a quoted text and nothing else.
    let (q, string) = match key(body) {
        Ok(found) => found,
        Err(_) => return invalid(body, Some(Expected::Nc("Q…="))),
    };
    let (r, (index, _)) = (cut(uint), cut(lex(or_expected(char('='), Expected::Nc("="))))).parse(q)?;
    let (r, value) = if string {
        let text_of = map(preceded(tag("QS"), cut(uint)), CycleValue::TextOf);
        cut(lex(alt((text_of, map(quoted, |text: &str| CycleValue::Text(text.to_owned())))))).parse(r)?
    } else {
        cut(lex(cycle_value)).parse(r)?
    };
    let (rest, ()) = end_of_block(r)?;
    Ok((rest, (index, value, label.filter(|l| !l.is_empty()))))
}

/// `CYCL DEF 200 BOHREN` (without its `~`) and its parameter lines (whole source lines).
/// With `probe`, the same for a touch-probe cycle `TCH PROBE 400 BASISDREHUNG ~`.
pub(super) fn cycle_def<'a>(
    cx: &Cx,
    header: &'a str,
    params: &[&'a str],
    probe: bool,
) -> Step<'a, BlockBody> {
    let (rest, number) = preceded(|i| def_head(i, probe), cut(uint)).parse(header)?;
    let name = rest.trim().to_owned();
    let mut out = Vec::with_capacity(params.len());
    for (k, line) in params.iter().enumerate() {
        let (_, (index, value, label)) = param_line(line)?;
        let string = value.is_text();
        if out.iter().any(|p: &CycleParam| p.index == index && p.value.is_text() == string) {
            let body = super::strip_tilde(super::split_comment(line).0.trim());
            return duplicate(body, body.len(), Named::Param { index, string });
        }
        if k + 1 == params.len() && line.trim_end().ends_with('~') {
            let t = line.trim_end();
            cx.warn(&t[t.len() - 1..], 1, DiagCode::ContinuationMissing);
        }
        out.push(CycleParam { index, value, label: label.map(str::to_owned) });
    }
    let def = Box::new(CycleDef { number, name, params: out });
    Ok((&header[header.len()..], if probe { BlockBody::TouchProbe(def) } else { BlockBody::CycleDef(def) }))
}

/// The value of a parameter line: a number or Q parameter, or `PREDEF`, `FMAX`, `FAUTO` (CAM
/// systems also write `AUTO`, and `MAX` for `FMAX`).
fn cycle_value(i: &str) -> Step<'_, CycleValue> {
    let word = |w: &'static str, v: CycleValue| value(v, terminated(tag(w), boundary));
    let words = alt((
        word("PREDEF", CycleValue::Predef),
        word("FMAX", CycleValue::Fmax),
        word("MAX", CycleValue::Fmax),
        word("FAUTO", CycleValue::Fauto),
        word("AUTO", CycleValue::Fauto),
        map(word_value, CycleValue::Value),
    ));
    run(words, i)
}

/// `CYCL CALL …` and old-style `CYCL DEF 7.1 …`; `CYCL END` and the like are a recoverable stop
/// (an exporting simulator writes them: no Klartext block, kept as one the trainer does not
/// model).
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn cycle_other<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (rest, _) = kw("CYCL").parse(body)?;
    let rest = sp(rest);
    if let Some(i) = keyword(rest, "CALL").map(sp) {
        return cut(|i| cycle_call(cx, i)).parse(i);
    }
    let Some(rest) = def_keyword(rest).map(sp) else {
        if letters(rest).is_ok() {
            return expected(rest, Expected::Nc("DEF|CALL"));
        }
        return invalid(rest, Some(Expected::Nc("DEF|CALL")));
    };
    let (after, number) = cut(uint).parse(rest)?;
    let Some(after) = after.strip_prefix('.') else {
        return cycle_def(cx, body, &[], false);
    };
    let (after, sub) = cut(uint).parse(after)?;
    let text = after.trim();
    let data = if sub == 0 {
        OldCycleData::Name(text.to_owned())
    } else if matches!(number, 7 | 8 | 10 | 11 | 19) {
        OldCycleData::Words(old_words(sp(after), number == 8)?.1)
    } else {
        OldCycleData::Text(text.to_owned())
    };
    Ok((&after[after.len()..], BlockBody::CycleDefOld(Box::new(CycleDefOld { number, sub, data }))))
}

/// `POS X… Y… Z… [F…] {Mn}`, `PAT [F…] {Mn}` or `{Mn}` after `CYCL CALL`.
fn cycle_call<'a>(cx: &Cx, i: &'a str) -> Step<'a, BlockBody> {
    if let Some(r) = keyword(i, "POS") {
        // The words of a straight line without radius compensation.
        return match super::motion::path_after(cx, "L", r)? {
            (rest, BlockBody::L(line)) if line.comp.is_none() => {
                // All three axes, as the iTNC 530 cycle manual demands of CYCL CALL POS.
                let has = |a: Axis| line.axes.iter().any(|w| w.axis == a);
                match [(Axis::X, "X"), (Axis::Y, "Y"), (Axis::Z, "Z")].into_iter().find(|(a, _)| !has(*a)) {
                    Some((_, word)) => missing(&r[r.len()..], word),
                    None => Ok((rest, BlockBody::CyclCallPos(Box::new(line)))),
                }
            }
            _ => not_allowed(r.split([' ', '\t']).find(|w| matches!(*w, "R0" | "RL" | "RR")).unwrap_or(r)),
        };
    }
    let (i, pat) = opt(kw("PAT")).parse(i)?;
    let pat = pat.is_some();
    let mut i = sp(i);
    let mut f = None;
    if pat && i.starts_with('F') {
        let (r, v) = feed(i).map_err(hard)?;
        f = Some(v);
        i = sp(r);
    }
    cx.clear_words();
    while !i.is_empty() {
        if let Some(r) = empty_word(i, b"M") {
            i = sp(r);
            continue;
        }
        let (r, m) = m_function(i)
            .or_else(|_| invalid(i, Some(Expected::Nc(if pat { "F|M" } else { "PAT|POS|M" }))))?;
        cx.push_m(m);
        i = sp(r);
    }
    let m = cx.take_m();
    Ok((i, if pat { BlockBody::CyclCallPat { feed: f, m } } else { BlockBody::CyclCall { m } }))
}

/// Words of cycles 7 (datum), 8 (mirror), 10 (rotation), 11 (scaling), 19 (working plane); an
/// axis letter alone is a mirrored axis only in cycle 8 (`mirror`), elsewhere `X + 0` is `X+0`.
fn old_words(mut i: &str, mirror: bool) -> Step<'_, Vec<OldCycleWord>> {
    let mirrored =
        |i| match Axis::ALL.iter().find_map(|&a| keyword(i, a.as_str()).map(|r| (r, a))).filter(|_| mirror) {
            Some((r, a)) => Ok((r, OldCycleWord::MirrorAxis(a))),
            None => expected(i, Expected::Axis),
        };
    let mut word = alt((
        map(preceded(tag("IROT"), cut(lex(word_value))), |value| OldCycleWord::Rot {
            value,
            incremental: true,
        }),
        map(preceded(tag("ROT"), cut(lex(word_value))), |value| OldCycleWord::Rot {
            value,
            incremental: false,
        }),
        map(preceded(tag("SCL"), cut(lex(word_value))), OldCycleWord::Scl),
        map(preceded(tag("F"), cut(word_value)), OldCycleWord::Feed),
        mirrored,
        map(axis_word, OldCycleWord::Axis),
    ));
    let mut out = Vec::new();
    while !i.is_empty() {
        let (r, w) = word.parse(i).map_err(hard)?;
        out.push(w);
        i = sp(r);
    }
    Ok((i, out))
}
