//! Approaching and departing the contour (TNC 620 Klartext manual, "Approaching and departing
//! a contour": `APPR LT X+20 Y+20 Z-10 LEN15 RR F100`, `APPR CT X+10 Y+20 Z-10 CCA180 R+10 RR
//! F100`, `DEP LT LEN12.5 F100`, `DEP CT CCA 180 R+8 F100`, `DEP LCT X+10 Y+12 R+8 F100`).
//!   appr := APPR (LT|LN|CT|LCT) { axis | LEN v | CCA v | R v | RL|RR|R0 | F… | M n }
//!   dep  := DEP (LT|LN|CT|LCT) { axis | LEN v | CCA v | R v | F… | M n }
//! Which words each kind takes, and which it needs, is checked here; what they do is the
//! simulator's.

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{cut, map};
use nom::sequence::preceded;

use super::Cx;
use super::motion::{comp, once};
use super::words::{
    Step, axis_word, boundary, expected, feed, hard, keyword, letters, lex, m_function, missing, not_allowed,
    or_expected, soft, sp, word_value,
};
use crate::ast::{ApprDep, ApprKind, AxisWord, BlockBody, RadiusComp};
use crate::diag::Expected;
use crate::plane::{Feed, Value};

/// A word and where it stood.
type At<'a, T> = Option<(T, &'a str)>;

#[derive(Default)]
struct Words<'a> {
    len: At<'a, Value>,
    cca: At<'a, Value>,
    radius: At<'a, Value>,
    comp: At<'a, RadiusComp>,
    feed: At<'a, Feed>,
    first_axis: Option<&'a str>,
}

/// One word of an approach or departure.
#[derive(Clone, Copy)]
enum ApprWord {
    M(u32),
    Axis(AxisWord),
    Feed(Feed),
    Comp(RadiusComp),
    Len(Value),
    Cca(Value),
    Radius(Value),
}

fn appr_word(i: &str) -> Step<'_, ApprWord> {
    // An `M` that is not a whole M function is not one: the other words are tried.
    let m = map(|i| m_function(i).map_err(soft), ApprWord::M);
    alt((
        m,
        map(axis_word, ApprWord::Axis),
        map(feed, ApprWord::Feed),
        map(comp, ApprWord::Comp),
        map(preceded(tag("LEN"), cut(lex(word_value))), ApprWord::Len),
        map(preceded(tag("CCA"), cut(lex(word_value))), ApprWord::Cca),
        map(preceded(tag("R"), cut(word_value)), ApprWord::Radius),
    ))
    .parse(i)
}

/// `APPR …` (`approach`) or `DEP …`: the whole block `body`.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn appr_dep<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (rest, head) = letters(body)?;
    let approach = head == "APPR";
    cx.clear_words();
    let (rest, ()) = cut(boundary).parse(rest)?;
    let kind = |i| {
        [ApprKind::Lct, ApprKind::Lt, ApprKind::Ln, ApprKind::Ct]
            .into_iter()
            .find_map(|k| keyword(i, k.as_str()).map(|r| (r, k)))
            .map_or_else(|| expected(i, Expected::Nc("LT|LN|CT|LCT")), Ok)
    };
    let (i, kind) = cut(lex(kind)).parse(rest)?;
    let mut i = sp(i);
    let mut w = Words::default();
    while !i.is_empty() {
        let at = i;
        let (r, word) =
            or_expected(appr_word, Expected::Nc("X|Y|Z|LEN|CCA|R|RL|RR|F|M")).parse(i).map_err(hard)?;
        match word {
            ApprWord::M(m) => cx.push_m(m),
            ApprWord::Axis(word) => {
                cx.push_axis(at, r, word)?;
                w.first_axis.get_or_insert(at);
            }
            ApprWord::Feed(f) => once(&mut w.feed, f, at, at.len() - r.len())?,
            ApprWord::Comp(c) => once(&mut w.comp, c, at, 2)?,
            ApprWord::Len(v) => once(&mut w.len, v, at, 3)?,
            ApprWord::Cca(v) => once(&mut w.cca, v, at, 3)?,
            ApprWord::Radius(v) => once(&mut w.radius, v, at, 1)?,
        }
        i = sp(r);
    }
    build(cx, approach, kind, w, i)
}

fn build<'a>(cx: &Cx, approach: bool, kind: ApprKind, w: Words<'a>, end: &'a str) -> Step<'a, BlockBody> {
    // The words of each kind, from the manual's dialog (DEP LT/LN/CT end away from the contour
    // by LEN or the arc, only DEP LCT names an end point; DEP switches the compensation off).
    let (takes_len, takes_arc, takes_axes) = match kind {
        ApprKind::Lt | ApprKind::Ln => (true, false, approach),
        ApprKind::Ct => (false, true, approach),
        ApprKind::Lct => (false, false, true),
    };
    let takes_radius = takes_arc || kind == ApprKind::Lct;
    let present = [
        (w.len.map(|x| x.1), takes_len),
        (w.cca.map(|x| x.1), takes_arc),
        (w.radius.map(|x| x.1), takes_radius),
        (w.comp.map(|x| x.1), approach),
        (w.first_axis, takes_axes),
    ];
    if let Some(at) = present.into_iter().find_map(|(at, allowed)| at.filter(|_| !allowed)) {
        return not_allowed(at);
    }
    let absent = if takes_len && w.len.is_none() {
        Some("LEN")
    } else if takes_arc && w.cca.is_none() {
        Some("CCA")
    } else if takes_radius && w.radius.is_none() {
        Some("R")
    } else {
        None
    };
    if let Some(word) = absent {
        return missing(end, word);
    }
    let node = Box::new(ApprDep {
        kind,
        axes: cx.take_axes(),
        len: w.len.map(|x| x.0),
        cca: w.cca.map(|x| x.0),
        radius: w.radius.map(|x| x.0),
        comp: w.comp.map(|x| x.0),
        feed: w.feed.map(|x| x.0),
        m: cx.take_m(),
    });
    Ok((end, if approach { BlockBody::Appr(node) } else { BlockBody::Dep(node) }))
}
