//! Cycle definitions and calls.
//!   def  := CYCL DEF n name [~] { NL (Q\<n>=(value|PREDEF|FMAX|MAX|FAUTO|AUTO) | QS\<n>="text") [;label] [~] }
//!           (continuation lines, DOMAIN.md §8)
//!   old  := CYCL DEF n.0 name | CYCL DEF n.s words
//!   call := CYCL CALL { Mn } | CYCL CALL PAT [F…] { Mn } | CYCL CALL POS X… Y… Z… [F…|FMAX] { Mn }
//!   (CYCL CALL POS with all three axes: iTNC 530 cycle manual, DOMAIN.md §11)

use super::Cx;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{map, value};
use nom::sequence::terminated;

use super::words::{
    Step, axis_word, boundary, def_keyword, empty_word, feed, keyword, letters, m_function, quoted, run, sp,
    uint, word_value,
};
use crate::ast::{
    Axis, BlockBody, CycleDef, CycleDefOld, CycleParam, CycleValue, OldCycleData, OldCycleWord,
};
use crate::diag::{DiagCode, Expected};

/// `CYCL DEF 200 BOHREN` (without its `~`) and its parameter lines (whole source lines).
/// With `probe`, the same for a touch-probe cycle `TCH PROBE 400 BASISDREHUNG ~`.
pub(super) fn cycle_def(cx: &mut Cx, header: &str, params: &[&str], probe: bool) -> Option<BlockBody> {
    let rest = if probe {
        keyword(header, "TCH").map(sp).and_then(|r| keyword(r, "PROBE")).map(sp)
    } else {
        keyword(header, "CYCL").map(sp).and_then(def_keyword).map(sp)
    };
    let Some(rest) = rest else {
        return cx.invalid(header, Some(Expected::Nc(if probe { "TCH PROBE" } else { "CYCL DEF" })));
    };
    let (rest, number) = match uint(rest) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let name = rest.trim().to_owned();
    let mut out = Vec::with_capacity(params.len());
    for (k, line) in params.iter().enumerate() {
        let (body, label) = super::split_comment(line);
        let body = super::strip_tilde(body.trim());
        let label = label.map(|l| super::strip_tilde(l.trim()));
        // `QS500="TEXT"`: a string parameter takes a quoted text and nothing else.
        let (q, string) = match body.strip_prefix("QS") {
            Some(q) => (q, true),
            None => match body.strip_prefix('Q') {
                Some(q) => (q, false),
                None => return cx.invalid(body, Some(Expected::Nc("Q…="))),
            },
        };
        let (r, index) = match uint(q) {
            Ok(ok) => ok,
            Err(e) => return cx.fail(e),
        };
        let Some(r) = sp(r).strip_prefix('=') else {
            return cx.invalid(sp(r), Some(Expected::Nc("=")));
        };
        let value = if string {
            match sp(r).strip_prefix("QS").map(uint) {
                Some(q) => q.map(|(r, n)| (r, CycleValue::TextOf(n))),
                None => quoted(sp(r)).map(|(r, text)| (r, CycleValue::Text(text.to_owned()))),
            }
        } else {
            cycle_value(sp(r))
        };
        let (r, value) = match value {
            Ok(ok) => ok,
            Err(e) => return cx.fail(e),
        };
        if !sp(r).is_empty() {
            return cx.invalid(sp(r), None);
        }
        if out.iter().any(|p: &CycleParam| p.index == index && p.value.is_text() == string) {
            let word = if string { format!("QS{index}") } else { format!("Q{index}") };
            cx.error(body, body.len(), DiagCode::Duplicate { word });
            return None;
        }
        if k + 1 == params.len() && line.trim_end().ends_with('~') {
            let t = line.trim_end();
            cx.warn(&t[t.len() - 1..], 1, DiagCode::ContinuationMissing);
        }
        out.push(CycleParam { index, value, label: label.filter(|l| !l.is_empty()).map(str::to_owned) });
    }
    let def = Box::new(CycleDef { number, name, params: out });
    Some(if probe { BlockBody::TouchProbe(def) } else { BlockBody::CycleDef(def) })
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

/// `CYCL CALL …` and old-style `CYCL DEF 7.1 …`.
pub(super) fn cycle_other(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(rest) = keyword(body, "CYCL").map(sp) else { return super::unknown(cx, body) };
    if let Some(mut i) = keyword(rest, "CALL").map(sp) {
        if let Some(r) = keyword(i, "POS") {
            // The words of a straight line without radius compensation.
            return match super::motion::path(cx, "L", r)? {
                BlockBody::L(line) if line.comp.is_none() => {
                    // All three axes, as the iTNC 530 cycle manual demands of CYCL CALL POS.
                    let has = |a: Axis| line.axes.iter().any(|w| w.axis == a);
                    if let Some(word) = [(Axis::X, "X"), (Axis::Y, "Y"), (Axis::Z, "Z")]
                        .into_iter()
                        .find_map(|(a, word)| (!has(a)).then_some(word))
                    {
                        let end = &r[r.len()..];
                        cx.error(end, 0, DiagCode::MissingWord { word });
                        return None;
                    }
                    Some(BlockBody::CyclCallPos(Box::new(line)))
                }
                _ => {
                    let word = r.split([' ', '\t']).find(|w| matches!(*w, "R0" | "RL" | "RR")).unwrap_or(r);
                    cx.error(word, word.len(), DiagCode::NotAllowed { word: word.to_owned() });
                    None
                }
            };
        }
        let pat = keyword(i, "PAT");
        if let Some(r) = pat {
            i = sp(r);
        }
        let mut f = None;
        if pat.is_some() && i.starts_with('F') {
            match feed(i) {
                Ok((r, v)) => {
                    f = Some(v);
                    i = sp(r);
                }
                Err(e) => return cx.fail(e),
            }
        }
        cx.m.clear();
        while !i.is_empty() {
            if let Some(r) = empty_word(i, b"M") {
                i = sp(r);
                continue;
            }
            match m_function(i) {
                Ok((r, m)) => {
                    cx.m.push(m);
                    i = sp(r);
                }
                Err(_) => {
                    return cx
                        .invalid(i, Some(Expected::Nc(if pat.is_some() { "F|M" } else { "PAT|POS|M" })));
                }
            }
        }
        let m = cx.take_m();
        return Some(if pat.is_some() {
            BlockBody::CyclCallPat { feed: f, m }
        } else {
            BlockBody::CyclCall { m }
        });
    }
    let Some(rest) = def_keyword(rest).map(sp) else {
        // `CYCL END` and the like, as an exporting simulator writes: no Klartext block, kept
        // as one the trainer does not model (a warning; the run says so on the block).
        if letters(rest).is_ok() {
            return super::unknown(cx, body);
        }
        return cx.invalid(rest, Some(Expected::Nc("DEF|CALL")));
    };
    let (after, number) = match uint(rest) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let Some(after) = after.strip_prefix('.') else {
        return cycle_def(cx, body, &[], false);
    };
    let (after, sub) = match uint(after) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let text = after.trim();
    let data = if sub == 0 {
        OldCycleData::Name(text.to_owned())
    } else if matches!(number, 7 | 8 | 10 | 11 | 19) {
        OldCycleData::Words(old_words(cx, sp(after), number == 8)?)
    } else {
        OldCycleData::Text(text.to_owned())
    };
    Some(BlockBody::CycleDefOld(Box::new(CycleDefOld { number, sub, data })))
}

/// Words of cycles 7 (datum), 8 (mirror), 10 (rotation), 11 (scaling), 19 (working plane); an
/// axis letter alone is a mirrored axis only in cycle 8 (`mirror`), elsewhere `X + 0` is `X+0`.
fn old_words(cx: &mut Cx, mut i: &str, mirror: bool) -> Option<Vec<OldCycleWord>> {
    let mut out = Vec::new();
    while !i.is_empty() {
        let (r, w) = if let Some(r) = i.strip_prefix("IROT").or_else(|| i.strip_prefix("ROT")) {
            let incremental = i.starts_with('I');
            match word_value(sp(r)) {
                Ok((r, value)) => (r, OldCycleWord::Rot { value, incremental }),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(r) = i.strip_prefix("SCL") {
            match word_value(sp(r)) {
                Ok((r, v)) => (r, OldCycleWord::Scl(v)),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(r) = i.strip_prefix('F') {
            match word_value(r) {
                Ok((r, v)) => (r, OldCycleWord::Feed(v)),
                Err(e) => return cx.fail(e),
            }
        } else if let Some((r, a)) =
            Axis::ALL.iter().find_map(|&a| keyword(i, a.as_str()).map(|r| (r, a))).filter(|_| mirror)
        {
            (r, OldCycleWord::MirrorAxis(a))
        } else {
            match axis_word(i) {
                Ok((r, w)) => (r, OldCycleWord::Axis(w)),
                Err(e) => return cx.fail(e),
            }
        };
        out.push(w);
        i = sp(r);
    }
    Some(out)
}
