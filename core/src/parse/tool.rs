//! Blank form and tool call.
//!   blk  := BLK FORM 0.1 (X|Y|Z) axis… | BLK FORM 0.2 [I]axis…
//!   tool := TOOL CALL [n|"name"] [X|Y|Z] { S v | F v | DL v | DR v | DR2 v }
//!   def  := TOOL DEF (n|"name") [L v] [R v]     (`TOOL DEF1` read as `TOOL DEF 1`)

use super::Cx;
use super::words::{Step, axis_word, def_keyword, keyword, q_param, quoted, sp, uint, word_value};
use crate::ast::{Axis, BlkForm, BlockBody, ToolCall, ToolRef};
use crate::diag::{DiagCode, Expected};
use crate::plane::Value;

fn tool_axis(i: &str) -> Option<(&str, Axis)> {
    [("X", Axis::X), ("Y", Axis::Y), ("Z", Axis::Z)]
        .into_iter()
        .find_map(|(k, a)| keyword(i, k).map(|r| (r, a)))
}

/// `BLK FORM 0.1 Z X+0 Y+0 Z-40`, `BLK FORM 0.2 X+100 Y+100 Z+0`.
pub(super) fn blk_form(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(rest) = keyword(body, "BLK").map(sp).and_then(|r| keyword(r, "FORM")) else {
        return super::unknown(cx, body);
    };
    let rest = sp(rest);
    let (mut i, part) = match (keyword(rest, "0.1"), keyword(rest, "0.2")) {
        (Some(r), _) => (sp(r), 1),
        (None, Some(r)) => (sp(r), 2),
        // `BLK FORM CYLINDER …` and friends: not modelled.
        _ => return super::unknown(cx, body),
    };
    let mut axis = None;
    if part == 1 {
        match tool_axis(i) {
            Some((r, a)) => {
                axis = Some(a);
                i = sp(r);
            }
            None => return cx.invalid(i, Some(Expected::Nc("X|Y|Z"))),
        }
    }
    cx.axes.clear();
    while !i.is_empty() {
        match axis_word(i) {
            Ok((r, w)) => {
                if cx.axes.iter().any(|a| a.axis == w.axis) {
                    cx.error(i, i.len() - r.len(), DiagCode::Duplicate { word: w.axis.as_str().to_owned() });
                    return None;
                }
                if part == 1 && w.incremental {
                    return cx.invalid(i, Some(Expected::Nc("X|Y|Z")));
                }
                cx.axes.push(w);
                i = sp(r);
            }
            Err(e) => return cx.fail(e),
        }
    }
    Some(BlockBody::BlkForm(Box::new(BlkForm { part, tool_axis: axis, axes: cx.take_axes() })))
}

/// The tool of `TOOL CALL`/`TOOL DEF`: a number, a `"name"`, a numeric parameter holding the
/// number (`Q5`, `QL5`, `QR5`) or a string parameter holding the name (`QS5`), as the TNC
/// dialog takes them; `None` if `i` starts none of them.
fn tool_ref(i: &str) -> Option<Step<'_, ToolRef>> {
    if i.starts_with('"') {
        return Some(quoted(i).map(|(r, name)| (r, ToolRef::Name(name.to_owned()))));
    }
    if i.as_bytes().first().is_some_and(u8::is_ascii_digit) {
        return Some(uint(i).map(|(r, n)| (r, ToolRef::Number(n))));
    }
    if let Some(digits) =
        i.strip_prefix("QS").filter(|d| d.as_bytes().first().is_some_and(u8::is_ascii_digit))
    {
        return Some(uint(digits).map(|(r, n)| (r, ToolRef::StringParam(n))));
    }
    q_param(i).map(|q| q.map(|(r, index)| (r, ToolRef::Param(index))))
}

/// `TOOL DEF 2 L+75 R+5`, `TOOL DEF 0`, `TOOL DEF "name"`.
// Out of line in wasm, like the other rare families (see labels_q.rs).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn tool_def(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(mut i) = keyword(body, "TOOL").map(sp).and_then(def_keyword).map(sp) else {
        return super::unknown(cx, body);
    };
    let tool = match tool_ref(i) {
        Some(Ok((r, t))) => {
            i = sp(r);
            t
        }
        Some(Err(e)) => return cx.fail(e),
        None => return cx.invalid(i, Some(Expected::LabelNumberOrName)),
    };
    let (mut length, mut radius) = (None, None);
    while !i.is_empty() {
        let slot = match i.as_bytes()[0] {
            b'L' => &mut length,
            b'R' => &mut radius,
            _ => return cx.invalid(i, Some(Expected::Nc("L|R"))),
        };
        match word_value(&i[1..]) {
            Ok((r, v)) => {
                if slot.replace(v).is_some() {
                    cx.error(i, i.len() - r.len(), DiagCode::Duplicate { word: i[..1].to_owned() });
                    return None;
                }
                i = sp(r);
            }
            Err(e) => return cx.fail(e),
        }
    }
    Some(BlockBody::ToolDef { tool, length, radius })
}

/// `TOOL CALL 16 Z S5000 F1000`, `TOOL CALL "name" Z S50 DL+0 DR+0`.
pub(super) fn tool_call(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(mut i) = keyword(body, "TOOL").map(sp).and_then(|r| keyword(r, "CALL")).map(sp) else {
        return super::unknown(cx, body);
    };
    let mut call = ToolCall::default();
    match tool_ref(i) {
        Some(Ok((r, t))) => {
            call.tool = Some(t);
            i = sp(r);
        }
        Some(Err(e)) => return cx.fail(e),
        None => {}
    }
    if let Some((r, a)) = tool_axis(i) {
        call.axis = Some(a);
        i = sp(r);
    }
    while !i.is_empty() {
        let at = i;
        // Longest key first: `DR2` before `DR`.
        let (key, slot): (&str, &mut Option<Value>) = if i.starts_with("DR2") {
            ("DR2", &mut call.dr2)
        } else if i.starts_with("DR") {
            ("DR", &mut call.dr)
        } else if i.starts_with("DL") {
            ("DL", &mut call.dl)
        } else if i.starts_with('S') {
            ("S", &mut call.speed)
        } else if i.starts_with('F') {
            ("F", &mut call.feed)
        } else {
            return cx.invalid(at, Some(Expected::Nc("S|F|DL|DR|DR2")));
        };
        match word_value(&i[key.len()..]) {
            Ok((r, v)) => {
                if slot.is_some() {
                    cx.error(at, at.len() - r.len(), DiagCode::Duplicate { word: key.to_owned() });
                    return None;
                }
                *slot = Some(v);
                i = sp(r);
            }
            Err(e) => return cx.fail(e),
        }
    }
    Some(BlockBody::ToolCall(Box::new(call)))
}
