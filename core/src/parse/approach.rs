//! Approaching and departing the contour (TNC 620 Klartext manual, "Approaching and departing
//! a contour": `APPR LT X+20 Y+20 Z-10 LEN15 RR F100`, `APPR CT X+10 Y+20 Z-10 CCA180 R+10 RR
//! F100`, `DEP LT LEN12.5 F100`, `DEP CT CCA 180 R+8 F100`, `DEP LCT X+10 Y+12 R+8 F100`).
//!   appr := APPR (LT|LN|CT|LCT) { axis | LEN v | CCA v | R v | RL|RR|R0 | F… | M n }
//!   dep  := DEP (LT|LN|CT|LCT) { axis | LEN v | CCA v | R v | F… | M n }
//! Which words each kind takes, and which it needs, is checked here; what they do is the
//! simulator's.

use super::Cx;
use super::motion::{feed_or_comp, once};
use super::words::{at_boundary, axis_word, keyword, m_function, sp, word_value};
use crate::ast::{ApprDep, ApprKind, BlockBody, RadiusComp};
use crate::diag::{DiagCode, Expected};
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

/// `APPR …` (`approach`) or `DEP …`; `rest` follows the keyword.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn appr_dep(cx: &mut Cx, approach: bool, rest: &str) -> Option<BlockBody> {
    cx.axes.clear();
    cx.m.clear();
    if !at_boundary(rest) {
        return cx.invalid(rest, Some(Expected::Blank));
    }
    let i = sp(rest);
    let Some((mut i, kind)) = [ApprKind::Lct, ApprKind::Lt, ApprKind::Ln, ApprKind::Ct]
        .into_iter()
        .find_map(|k| keyword(i, k.as_str()).map(|r| (sp(r), k)))
    else {
        return cx.invalid(i, Some(Expected::Nc("LT|LN|CT|LCT")));
    };
    let mut w = Words::default();
    while !i.is_empty() {
        let at = i;
        if let Ok((r, m)) = m_function(i) {
            cx.m.push(m);
            i = sp(r);
            continue;
        }
        match axis_word(i) {
            Ok((r, word)) => {
                if cx.axes.iter().any(|a| a.axis == word.axis) {
                    cx.error(
                        at,
                        at.len() - r.len(),
                        DiagCode::Duplicate { word: word.axis.as_str().to_owned() },
                    );
                    return None;
                }
                w.first_axis.get_or_insert(at);
                cx.axes.push(word);
                i = sp(r);
                continue;
            }
            Err(nom::Err::Error(_)) => {}
            Err(e) => return cx.fail(e),
        }
        let valued = |key: &str| -> Option<&str> { i.strip_prefix(key).map(sp) };
        let (r, ok) = if let Some(read) = feed_or_comp(cx, i, &mut w.feed, &mut w.comp) {
            match read {
                Ok(read) => read,
                Err(e) => return cx.fail(e),
            }
        } else if let Some(v) = valued("LEN") {
            match word_value(v) {
                Ok((r, v)) => (r, once(cx, &mut w.len, v, at, 3)),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(v) = valued("CCA") {
            match word_value(v) {
                Ok((r, v)) => (r, once(cx, &mut w.cca, v, at, 3)),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(v) = i.strip_prefix('R') {
            match word_value(v) {
                Ok((r, v)) => (r, once(cx, &mut w.radius, v, at, 1)),
                Err(e) => return cx.fail(e),
            }
        } else {
            return cx.invalid(at, Some(Expected::Nc("X|Y|Z|LEN|CCA|R|RL|RR|F|M")));
        };
        if !ok {
            return None;
        }
        i = sp(r);
    }
    build(cx, approach, kind, w, i)
}

fn build(cx: &mut Cx, approach: bool, kind: ApprKind, w: Words<'_>, end: &str) -> Option<BlockBody> {
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
    for (at, allowed) in present {
        if let Some(at) = at
            && !allowed
        {
            let len = at.find([' ', '\t']).unwrap_or(at.len());
            cx.error(at, len, DiagCode::NotAllowed { word: at[..len].to_owned() });
            return None;
        }
    }
    let missing = if takes_len && w.len.is_none() {
        Some("LEN")
    } else if takes_arc && w.cca.is_none() {
        Some("CCA")
    } else if takes_radius && w.radius.is_none() {
        Some("R")
    } else {
        None
    };
    if let Some(word) = missing {
        cx.error(end, 0, DiagCode::MissingWord { word });
        return None;
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
    Some(if approach { BlockBody::Appr(node) } else { BlockBody::Dep(node) })
}
