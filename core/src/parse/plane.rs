//! PLANE blocks into the shared [`crate::plane`] vocabulary, with the control's input checks.
//!   plane := PLANE def [MOVE [DIST v] [feed] | TURN [MB v|MB MAX] [feed] | STAY] [SEQ±|SYM±] [COORD ROT|TABLE ROT]
//!   def   := SPATIAL SPA SPB SPC | PROJECTED PROPR PROMIN ROT | EULER EULPR EULNU EULROT | VECTOR BX…NZ | POINTS P1X…P3Z | RELATIV SPA|SPB|SPC | AXIAL {[I]A|B|C} | RESET
//!
//! `def`'s keyword is one of [`PlaneKind`]'s words, and its words are `cut` once the keyword is
//! read; the options after it come in any order, each at most once (a loop over one option
//! word at a time, which nom's `permutation` cannot say: it would take each exactly once).

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{cut, map, opt, value};
use nom::sequence::preceded;

use super::Cx;
use super::words::{
    Named, Step, Why, at_boundary, axis_word, choice, duplicate, expected, fault, feed, hard, invalid,
    keyword, kw, lex, missing, or_expected, sign, sp, spanned, word_len, word_value,
};
use crate::ast::{Axis, BlockBody};
use crate::diag::{DiagCode, Expected};
use crate::plane::{
    AxialAngle, Feed, MoveBack, PlaneBlock, PlaneDef, PlaneKind, Positioning, RelAxis, RotaryAxis, Selection,
    TransformMode, Value, Word, check,
};

/// `KEY value` that must be there; a written number is checked with [`check`].
fn mandatory<'a>(cx: &Cx, word: Word, i: &'a str) -> Step<'a, Value> {
    let i = sp(i);
    let Some(after) = i.strip_prefix(word.as_str()) else { return missing(i, word.as_str()) };
    let (rest, v) = cut(lex(word_value)).parse(after)?;
    checked(cx, word, v, i, rest);
    Ok((rest, v))
}

/// Reports a written number outside the input range of `word` (an error that does not stop the
/// block); the span runs from the word at `at` to `rest`, where its value ends. Q parameters
/// are checked when the program runs.
fn checked(cx: &Cx, word: Word, v: Value, at: &str, rest: &str) {
    if let Value::Number(x) = v
        && let Err(code) = check(word, x)
    {
        cx.error(at, at.len() - rest.len(), code);
    }
}

fn triple<'a>(cx: &Cx, words: [Word; 3], i: &'a str) -> Step<'a, [Value; 3]> {
    let [a, b, c] = words;
    map(
        (
            |i: &'a str| mandatory(cx, a, i),
            |i: &'a str| mandatory(cx, b, i),
            |i: &'a str| mandatory(cx, c, i),
        ),
        |(a, b, c)| [a, b, c],
    )
    .parse(i)
}

/// The kind of definition by its keyword (the words of the control's softkey row).
fn kind(i: &str) -> Step<'_, PlaneKind> {
    const DEFS: &str = "SPATIAL|PROJECTED|EULER|VECTOR|POINTS|RELATIV|AXIAL|RESET";
    let i = sp(i);
    match PlaneKind::ALL.into_iter().find_map(|k| keyword(i, k.as_str()).map(|rest| (rest, k))) {
        Some(found) => Ok(found),
        None => expected(i, Expected::Nc(DEFS)),
    }
}

/// The whole block; `body` starts with `PLANE` (what else is a recoverable stop).
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn plane<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (i, kind) = preceded(tag("PLANE"), cut(kind)).parse(body)?;
    // Each kind's words, `cut`: its keyword is read.
    let (i, def) = match kind {
        PlaneKind::Spatial => triple(cx, [Word::Spa, Word::Spb, Word::Spc], i)
            .map(|(r, [spa, spb, spc])| (r, PlaneDef::Spatial { spa, spb, spc })),
        PlaneKind::Projected => triple(cx, [Word::Propr, Word::Promin, Word::Rot], i)
            .map(|(r, [propr, promin, rot])| (r, PlaneDef::Projected { propr, promin, rot })),
        PlaneKind::Euler => triple(cx, [Word::Eulpr, Word::Eulnu, Word::Eulrot], i)
            .map(|(r, [eulpr, eulnu, eulrot])| (r, PlaneDef::Euler { eulpr, eulnu, eulrot })),
        PlaneKind::Vector => vector(cx, i),
        PlaneKind::Points => points(cx, i),
        PlaneKind::Relativ => relativ(cx, i),
        PlaneKind::Axial => axial(i),
        PlaneKind::Reset => Ok((i, PlaneDef::Reset)),
    }
    .map_err(hard)?;
    let (i, block) = options(cx, i, def)?;
    Ok((i, BlockBody::Plane(Box::new(block))))
}

/// `POINTS P1X… P3Z`: three points.
fn points<'a>(cx: &Cx, i: &'a str) -> Step<'a, PlaneDef> {
    let (r, p1) = triple(cx, [Word::P1x, Word::P1y, Word::P1z], i)?;
    let (r, p2) = triple(cx, [Word::P2x, Word::P2y, Word::P2z], r)?;
    let (r, p3) = triple(cx, [Word::P3x, Word::P3y, Word::P3z], r)?;
    Ok((r, PlaneDef::Points { p1, p2, p3 }))
}

/// `VECTOR BX… BY… BZ… NX… NY… NZ…`: a zero base or normal vector is an error that does not
/// stop the block.
fn vector<'a>(cx: &Cx, i: &'a str) -> Step<'a, PlaneDef> {
    let (r, (at, base)) =
        lex(spanned(|i: &'a str| triple(cx, [Word::Bx, Word::By, Word::Bz], i))).parse(i)?;
    let (r, (at_n, normal)) =
        lex(spanned(|i: &'a str| triple(cx, [Word::Nx, Word::Ny, Word::Nz], i))).parse(r)?;
    for (word, v, at) in [("B", base, at), ("N", normal, at_n)] {
        if v.iter().all(|x| matches!(x, Value::Number(n) if *n == 0.0)) {
            cx.error(at, 2, DiagCode::ZeroVector { word });
        }
    }
    Ok((r, PlaneDef::Vector { base, normal }))
}

/// `RELATIV SPA|SPB|SPC v`.
fn relativ<'a>(cx: &Cx, i: &'a str) -> Step<'a, PlaneDef> {
    let i = sp(i);
    let (key, axis) = match i.get(..3) {
        Some("SPA") => (Word::Spa, RelAxis::Spa),
        Some("SPB") => (Word::Spb, RelAxis::Spb),
        Some("SPC") => (Word::Spc, RelAxis::Spc),
        _ => return missing(i, "SPA|SPB|SPC"),
    };
    let (r, angle) = mandatory(cx, key, i)?;
    Ok((r, PlaneDef::Relativ { axis, angle }))
}

/// `PLANE AXIAL B-45`, `PLANE AXIAL A+0 IC+90` (range UNCONFIRMED, not checked): rotary axis
/// words, each at most once, at least one.
fn axial(i: &str) -> Step<'_, PlaneDef> {
    let mut i = sp(i);
    let mut axes: Vec<AxialAngle> = Vec::new();
    loop {
        let at = i;
        let w = match axis_word(i) {
            Ok((rest, w)) => {
                i = sp(rest);
                w
            }
            Err(nom::Err::Error(_)) => break,
            Err(e) => return Err(e),
        };
        let axis = match w.axis {
            Axis::A => RotaryAxis::A,
            Axis::B => RotaryAxis::B,
            Axis::C => RotaryAxis::C,
            _ => return invalid(at, Some(Expected::Nc("A|B|C"))),
        };
        if axes.iter().any(|a| a.axis == axis) {
            return duplicate(at, at.len() - i.len(), Named::Given(w.axis.as_str()));
        }
        axes.push(AxialAngle { axis, value: w.value, incremental: w.incremental });
    }
    if axes.is_empty() {
        return missing(i, "A|B|C");
    }
    Ok((i, PlaneDef::Axial { axes }))
}

/// One option word after the definition.
#[derive(Clone, Copy)]
enum Opt {
    Positioning(Positioning),
    Selection(Selection),
    Transform(TransformMode),
}

/// `MOVE [DIST v] [feed]`.
fn move_words<'a>(cx: &Cx, i: &'a str) -> Step<'a, Positioning> {
    let dist = preceded(lex(tag("DIST")), cut(lex(word_value)));
    let (r, dist) = lex(opt(spanned(dist))).parse(i)?;
    if let Some((at, v)) = dist {
        checked(cx, Word::Dist, v, at, &at[at.len()..]);
    }
    let (r, feed) = opt_feed(cx, sp(r))?;
    Ok((r, Positioning::Move { dist: dist.map(|d| d.1), feed }))
}

/// `TURN [MB v|MB MAX] [feed]`.
fn turn_words<'a>(cx: &Cx, i: &'a str) -> Step<'a, Positioning> {
    let mb = preceded(lex(tag("MB")), cut(lex(alt((value(None, kw("MAX")), map(word_value, Some))))));
    let (r, mb) = lex(opt(spanned(mb))).parse(i)?;
    let move_back = mb.map(|(at, v)| match v {
        None => MoveBack::Max,
        Some(v) => {
            checked(cx, Word::Mb, v, at, &at[at.len()..]);
            MoveBack::Dist(v)
        }
    });
    let (r, feed) = opt_feed(cx, sp(r))?;
    Ok((r, Positioning::Turn { move_back, feed }))
}

/// `SEQ±` or `SYM±` as one word.
fn selection(i: &str) -> Step<'_, Selection> {
    let (r, seq) = alt((value(true, tag("SEQ")), value(false, tag("SYM")))).parse(i)?;
    match sign(r) {
        Ok((r, s)) if at_boundary(r) => Ok((r, if seq { Selection::Seq(s) } else { Selection::Sym(s) })),
        _ => invalid(i, Some(Expected::Nc("SEQ+|SEQ-|SYM+|SYM-"))),
    }
}

/// The option words that stand alone, by their keyword (`SEQ±`/`SYM±` carry their sign).
#[derive(Clone, Copy)]
enum OptWord {
    Move,
    Turn,
    Stay,
    Coord,
    Table,
}

const OPTION_WORDS: &[(&str, OptWord)] = &[
    ("MOVE", OptWord::Move),
    ("TURN", OptWord::Turn),
    ("STAY", OptWord::Stay),
    ("COORD", OptWord::Coord),
    ("TABLE", OptWord::Table),
];

/// One option word with what belongs to it.
fn option<'a>(cx: &Cx, i: &'a str) -> Step<'a, Opt> {
    const OPTIONS: &str = "MOVE|TURN|STAY|SEQ±|SYM±|COORD ROT|TABLE ROT";
    let Ok((r, word)) = choice(OPTION_WORDS, OPTIONS).parse(i) else {
        return or_expected(selection, Expected::Nc(OPTIONS)).parse(i).map(|(r, s)| (r, Opt::Selection(s)));
    };
    let rot = |r, mode| cut(kw("ROT")).parse(r).map(|(r, _)| (r, Opt::Transform(mode)));
    match word {
        OptWord::Move => move_words(cx, r).map(|(r, p)| (r, Opt::Positioning(p))),
        OptWord::Turn => turn_words(cx, r).map(|(r, p)| (r, Opt::Positioning(p))),
        OptWord::Stay => Ok((r, Opt::Positioning(Positioning::Stay))),
        OptWord::Coord => rot(r, TransformMode::CoordRot),
        OptWord::Table => rot(r, TransformMode::TableRot),
    }
}

/// Positioning, selection and transformation words, in any order, each at most once.
fn options<'a>(cx: &Cx, mut i: &'a str, def: PlaneDef) -> Step<'a, PlaneBlock> {
    let mut block = PlaneBlock { def, positioning: None, selection: None, transform: None };
    loop {
        i = sp(i);
        if i.is_empty() {
            break;
        }
        let at = i;
        let (rest, o) = option(cx, i).map_err(hard)?;
        match o {
            Opt::Positioning(p) => {
                if block.positioning.is_some() {
                    let len = word_len(at);
                    return duplicate(at, len, Named::Written(len));
                }
                block.positioning = Some(p);
            }
            Opt::Selection(sel) => match block.selection {
                None => block.selection = Some(sel),
                Some(prev) => {
                    return if matches!(
                        (prev, sel),
                        (Selection::Seq(_), Selection::Sym(_)) | (Selection::Sym(_), Selection::Seq(_))
                    ) {
                        fault(at, 4, Why::SeqWithSym)
                    } else {
                        duplicate(at, 4, Named::Written(4))
                    };
                }
            },
            Opt::Transform(t) => {
                if block.transform.is_some() {
                    let len = at.len() - rest.len();
                    return duplicate(at, len, Named::Written(len));
                }
                block.transform = Some(t);
            }
        }
        i = rest;
    }
    if block.positioning.is_none() {
        cx.warn(i, 0, DiagCode::MissingPositioning);
    }
    Ok((i, block))
}

/// An optional feed after MOVE/TURN, checked against its range.
fn opt_feed<'a>(cx: &Cx, r: &'a str) -> Step<'a, Option<Feed>> {
    let (rest, f) = opt(feed).parse(r)?;
    if let Some(Feed::Value(v)) = f {
        checked(cx, Word::F, v, r, rest);
    }
    Ok((rest, f))
}
