//! Coordinate transformations (DOMAIN.md §6).
//!   trans := TRANS DATUM (AXIS {axis±v} | RESET) | TRANS MIRROR (AXIS {X|Y|Z…} | RESET)
//!          | TRANS ROTATION ([I]ROT v | RESET)

use super::Cx;
use super::words::{axis_word, keyword, sp, word_value};
use crate::ast::{Axis, BlockBody};
use crate::diag::{DiagCode, Expected};

/// `TRANS …` (`TRANS SCALE` and others are kept as unknown blocks).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn trans(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(i) = keyword(body, "TRANS").map(sp) else { return super::unknown(cx, body) };
    if let Some(r) = keyword(i, "DATUM").map(sp) {
        if let Some(r) = keyword(r, "RESET") {
            return end(cx, r, BlockBody::TransDatumReset);
        }
        let Some(mut r) = keyword(r, "AXIS").map(sp) else {
            return cx.invalid(r, Some(Expected::Nc("AXIS|RESET")));
        };
        cx.axes.clear();
        while !r.is_empty() {
            match axis_word(r) {
                Ok((rest, w)) => {
                    if cx.axes.iter().any(|a| a.axis == w.axis) {
                        cx.error(
                            r,
                            r.len() - rest.len(),
                            DiagCode::Duplicate { word: w.axis.as_str().to_owned() },
                        );
                        return None;
                    }
                    cx.axes.push(w);
                    r = sp(rest);
                }
                Err(e) => return cx.fail(e),
            }
        }
        if cx.axes.is_empty() {
            cx.error(r, 0, DiagCode::MissingWord { word: "X|Y|Z" });
            return None;
        }
        return Some(BlockBody::TransDatum { axes: cx.take_axes() });
    }
    if let Some(r) = keyword(i, "MIRROR").map(sp) {
        if let Some(r) = keyword(r, "RESET") {
            return end(cx, r, BlockBody::TransMirrorReset);
        }
        let Some(mut r) = keyword(r, "AXIS").map(sp) else {
            return cx.invalid(r, Some(Expected::Nc("AXIS|RESET")));
        };
        let mut axes: Vec<Axis> = Vec::new();
        while !r.is_empty() {
            let Some((rest, a)) = Axis::ALL.iter().find_map(|&a| keyword(r, a.as_str()).map(|x| (x, a)))
            else {
                return cx.invalid(r, Some(Expected::Nc("X|Y|Z")));
            };
            if axes.contains(&a) {
                cx.error(r, 1, DiagCode::Duplicate { word: a.as_str().to_owned() });
                return None;
            }
            axes.push(a);
            r = sp(rest);
        }
        if axes.is_empty() {
            cx.error(r, 0, DiagCode::MissingWord { word: "X|Y|Z" });
            return None;
        }
        return Some(BlockBody::TransMirror { axes: axes.into_boxed_slice() });
    }
    if let Some(r) = keyword(i, "ROTATION").map(sp) {
        if let Some(r) = keyword(r, "RESET") {
            return end(cx, r, BlockBody::TransRotationReset);
        }
        let (incremental, after) = match (r.strip_prefix("IROT"), r.strip_prefix("ROT")) {
            (Some(a), _) => (true, a),
            (None, Some(a)) => (false, a),
            _ => {
                cx.error(r, r.find(' ').unwrap_or(r.len()), DiagCode::MissingWord { word: "ROT" });
                return None;
            }
        };
        return match word_value(sp(after)) {
            Ok((rest, rot)) => end(cx, rest, BlockBody::TransRotation { rot, incremental }),
            Err(e) => cx.fail(e),
        };
    }
    super::unknown(cx, body)
}

/// Nothing may follow.
pub(super) fn end(cx: &mut Cx, rest: &str, body: BlockBody) -> Option<BlockBody> {
    let rest = sp(rest);
    if rest.is_empty() { Some(body) } else { cx.invalid(rest, None) }
}
