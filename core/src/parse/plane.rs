//! PLANE blocks into the shared [`crate::plane`] vocabulary, with the control's input checks.
//!   plane := PLANE def [MOVE [DIST v] [feed] | TURN [MB v|MB MAX] [feed] | STAY] [SEQ±|SYM±] [COORD ROT|TABLE ROT]
//!   def   := SPATIAL SPA SPB SPC | PROJECTED PROPR PROMIN ROT | EULER EULPR EULNU EULROT | VECTOR BX…NZ | POINTS P1X…P3Z | RELATIV SPA|SPB|SPC | AXIAL {[I]A|B|C} | RESET

use super::Cx;
use super::words::{at_boundary, axis_word, feed, keyword, sign, sp, word_value};
use crate::ast::{Axis, BlockBody};
use crate::diag::{DiagCode, Expected};
use crate::plane::{
    AxialAngle, Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, RelAxis, RotaryAxis, Selection,
    TransformMode, Value, Word, check,
};

/// `KEY value` that must be there; checks a written number with [`check`].
fn mandatory<'a>(cx: &mut Cx, i: &'a str, word: Word) -> Option<(&'a str, Value)> {
    let i = sp(i);
    let Some(after) = i.strip_prefix(word.as_str()) else {
        let len = i.find([' ', '\t']).unwrap_or(i.len());
        cx.error(i, len, DiagCode::MissingWord { word: word.as_str() });
        return None;
    };
    let (rest, v) = match word_value(sp(after)) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    checked(cx, word, v, i, rest);
    Some((rest, v))
}

/// Reports a written number outside the input range of `word`; the span runs from the word at
/// `at` to `rest`, where its value ends. Q parameters are checked when the program runs.
fn checked(cx: &mut Cx, word: Word, v: Value, at: &str, rest: &str) {
    if let Value::Number(x) = v
        && let Err(code) = check(word, x)
    {
        cx.error(at, at.len() - rest.len(), code);
    }
}

fn triple<'a>(cx: &mut Cx, i: &'a str, words: [Word; 3]) -> Option<(&'a str, [Value; 3])> {
    let (i, a) = mandatory(cx, i, words[0])?;
    let (i, b) = mandatory(cx, i, words[1])?;
    let (i, c) = mandatory(cx, i, words[2])?;
    Some((i, [a, b, c]))
}

/// `rest` follows the word `PLANE`.
pub(super) fn plane(cx: &mut Cx, rest: &str) -> Option<BlockBody> {
    let i = sp(rest);
    const DEFS: &str = "SPATIAL|PROJECTED|EULER|VECTOR|POINTS|RELATIV|AXIAL|RESET";
    let (i, def) = if let Some(r) = keyword(i, "SPATIAL") {
        let (r, [spa, spb, spc]) = triple(cx, r, [Word::Spa, Word::Spb, Word::Spc])?;
        (r, PlaneDef::Spatial { spa, spb, spc })
    } else if let Some(r) = keyword(i, "PROJECTED") {
        let (r, propr) = mandatory(cx, r, Word::Propr)?;
        let (r, promin) = mandatory(cx, r, Word::Promin)?;
        let (r, rot) = mandatory(cx, r, Word::Rot)?;
        (r, PlaneDef::Projected { propr, promin, rot })
    } else if let Some(r) = keyword(i, "EULER") {
        let (r, eulpr) = mandatory(cx, r, Word::Eulpr)?;
        let (r, eulnu) = mandatory(cx, r, Word::Eulnu)?;
        let (r, eulrot) = mandatory(cx, r, Word::Eulrot)?;
        (r, PlaneDef::Euler { eulpr, eulnu, eulrot })
    } else if let Some(r) = keyword(i, "VECTOR") {
        let at = sp(r);
        let (r, base) = triple(cx, r, [Word::Bx, Word::By, Word::Bz])?;
        let at_n = sp(r);
        let (r, normal) = triple(cx, r, [Word::Nx, Word::Ny, Word::Nz])?;
        for (word, v, at) in [("B", base, at), ("N", normal, at_n)] {
            if v.iter().all(|x| matches!(x, Value::Number(n) if *n == 0.0)) {
                cx.error(at, 2, DiagCode::ZeroVector { word });
            }
        }
        (r, PlaneDef::Vector { base, normal })
    } else if let Some(r) = keyword(i, "POINTS") {
        let (r, p1) = triple(cx, r, [Word::P1x, Word::P1y, Word::P1z])?;
        let (r, p2) = triple(cx, r, [Word::P2x, Word::P2y, Word::P2z])?;
        let (r, p3) = triple(cx, r, [Word::P3x, Word::P3y, Word::P3z])?;
        (r, PlaneDef::Points { p1, p2, p3 })
    } else if let Some(r) = keyword(i, "RELATIV") {
        let r = sp(r);
        let (key, axis) = match r.get(..3) {
            Some("SPA") => (Word::Spa, RelAxis::Spa),
            Some("SPB") => (Word::Spb, RelAxis::Spb),
            Some("SPC") => (Word::Spc, RelAxis::Spc),
            _ => {
                cx.error(r, r.find(' ').unwrap_or(r.len()), DiagCode::MissingWord { word: "SPA|SPB|SPC" });
                return None;
            }
        };
        let (r, angle) = mandatory(cx, r, key)?;
        (r, PlaneDef::Relativ { axis, angle })
    } else if let Some(r) = keyword(i, "AXIAL") {
        axial(cx, r)?
    } else if let Some(r) = keyword(i, "RESET") {
        (r, PlaneDef::Reset)
    } else {
        return cx.invalid(i, Some(Expected::Nc(DEFS)));
    };
    let block = options(cx, i, def)?;
    Some(BlockBody::Plane(Box::new(block)))
}

/// `PLANE AXIAL B-45`, `PLANE AXIAL A+0 IC+90` (range UNCONFIRMED, not checked).
fn axial<'a>(cx: &mut Cx, r: &'a str) -> Option<(&'a str, PlaneDef)> {
    let mut i = sp(r);
    let mut axes: Vec<AxialAngle> = Vec::new();
    loop {
        let at = i;
        let w = match axis_word(i) {
            Ok((rest, w)) => {
                i = sp(rest);
                w
            }
            Err(nom::Err::Error(_)) => break,
            Err(e) => return cx.fail(e),
        };
        let axis = match w.axis {
            Axis::A => RotaryAxis::A,
            Axis::B => RotaryAxis::B,
            Axis::C => RotaryAxis::C,
            _ => return cx.invalid(at, Some(Expected::Nc("A|B|C"))),
        };
        if axes.iter().any(|a| a.axis == axis) {
            cx.error(at, at.len() - i.len(), DiagCode::Duplicate { word: w.axis.as_str().to_owned() });
            return None;
        }
        axes.push(AxialAngle { axis, value: w.value, incremental: w.incremental });
    }
    if axes.is_empty() {
        let len = i.find(' ').unwrap_or(i.len());
        cx.error(i, len, DiagCode::MissingWord { word: "A|B|C" });
        return None;
    }
    Some((i, PlaneDef::Axial { axes }))
}

/// Positioning, selection and transformation words, in any order, each at most once.
fn options(cx: &mut Cx, mut i: &str, def: PlaneDef) -> Option<PlaneBlock> {
    let mut block = PlaneBlock { def, positioning: None, selection: None, transform: None };
    loop {
        i = sp(i);
        if i.is_empty() {
            break;
        }
        let at = i;
        let (rest, positioning) = if let Some(r) = keyword(i, "MOVE") {
            let mut r = sp(r);
            let mut dist = None;
            if let Some(after) = r.strip_prefix("DIST") {
                match word_value(sp(after)) {
                    Ok((rr, v)) => {
                        checked(cx, Word::Dist, v, r, rr);
                        dist = Some(v);
                        r = sp(rr);
                    }
                    Err(e) => return cx.fail(e),
                }
            }
            let (r, feed) = opt_feed(cx, r)?;
            (r, Some(Positioning::Move { dist, feed }))
        } else if let Some(r) = keyword(i, "TURN") {
            let mut r = sp(r);
            let mut move_back = None;
            if let Some(after) = r.strip_prefix("MB") {
                let after = sp(after);
                if let Some(rr) = keyword(after, "MAX") {
                    move_back = Some(MoveBack::Max);
                    r = sp(rr);
                } else {
                    match word_value(after) {
                        Ok((rr, v)) => {
                            checked(cx, Word::Mb, v, r, rr);
                            move_back = Some(MoveBack::Dist(v));
                            r = sp(rr);
                        }
                        Err(e) => return cx.fail(e),
                    }
                }
            }
            let (r, feed) = opt_feed(cx, r)?;
            (r, Some(Positioning::Turn { move_back, feed }))
        } else if let Some(r) = keyword(i, "STAY") {
            (r, Some(Positioning::Stay))
        } else {
            (i, None)
        };
        if let Some(p) = positioning {
            if block.positioning.is_some() {
                let len = at.find(' ').unwrap_or(at.len());
                cx.error(at, len, DiagCode::Duplicate { word: at[..len].to_owned() });
                return None;
            }
            block.positioning = Some(p);
            i = rest;
            continue;
        }
        let seq = i.strip_prefix("SEQ").map(|r| (r, true));
        if let Some((r, is_seq)) = seq.or_else(|| i.strip_prefix("SYM").map(|r| (r, false))) {
            let Ok((r, s)) =
                sign(r).map_err(|_| ()).and_then(|(r, s)| if at_boundary(r) { Ok((r, s)) } else { Err(()) })
            else {
                return cx.invalid(at, Some(Expected::Nc("SEQ+|SEQ-|SYM+|SYM-")));
            };
            let sel = if is_seq { Selection::Seq(s) } else { Selection::Sym(s) };
            match block.selection {
                None => block.selection = Some(sel),
                Some(prev) => {
                    let code = if matches!(
                        (prev, sel),
                        (Selection::Seq(_), Selection::Sym(_)) | (Selection::Sym(_), Selection::Seq(_))
                    ) {
                        DiagCode::SeqWithSym
                    } else {
                        DiagCode::Duplicate { word: at[..4].to_owned() }
                    };
                    cx.error(at, 4, code);
                    return None;
                }
            }
            i = r;
            continue;
        }
        let transform = if let Some(r) = keyword(i, "COORD") {
            Some((r, TransformMode::CoordRot))
        } else {
            keyword(i, "TABLE").map(|r| (r, TransformMode::TableRot))
        };
        if let Some((r, t)) = transform {
            let Some(r) = keyword(sp(r), "ROT") else { return cx.invalid(sp(r), Some(Expected::Nc("ROT"))) };
            if block.transform.is_some() {
                let len = at.len() - r.len();
                cx.error(at, len, DiagCode::Duplicate { word: at[..len].to_owned() });
                return None;
            }
            block.transform = Some(t);
            i = r;
            continue;
        }
        return cx.invalid(at, Some(Expected::Nc("MOVE|TURN|STAY|SEQ±|SYM±|COORD ROT|TABLE ROT")));
    }
    if block.positioning.is_none() {
        cx.warn(i, 0, DiagCode::MissingPositioning);
    }
    Some(block)
}

/// An optional feed after MOVE/TURN.
fn opt_feed<'a>(cx: &mut Cx, r: &'a str) -> Option<(&'a str, Option<Feed>)> {
    match feed(r) {
        Ok((rest, f)) => {
            if let Feed::Value(v) = f {
                checked(cx, Word::F, v, r, rest);
            }
            Some((rest, Some(f)))
        }
        Err(nom::Err::Error(_)) => Some((r, None)),
        Err(e) => cx.fail(e),
    }
}
