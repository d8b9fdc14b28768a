//! Blank form and tool call.
//!   blk  := BLK FORM 0.1 (X|Y|Z) axis… | BLK FORM 0.2 [I]axis…
//!   tool := TOOL CALL [n|"name"] [X|Y|Z] { S v | F v | DL v | DR v | DR2 v }
//!   def  := TOOL DEF (n|"name") [L v] [R v]     (`TOOL DEF1` read as `TOOL DEF 1`)

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{cut, map, opt, value};
use nom::sequence::preceded;

use super::Cx;
use super::words::{
    Named, Step, axis_word, choice, def_keyword, duplicate, expected, hard, invalid, kw, lex, or_expected,
    q_param, quoted, sp, uint, word_value,
};
use crate::ast::{Axis, BlkForm, BlockBody, ToolCall, ToolRef};
use crate::diag::Expected;

/// The tool axis `X`, `Y` or `Z` standing alone.
fn tool_axis(i: &str) -> Step<'_, Axis> {
    choice(&[("X", Axis::X), ("Y", Axis::Y), ("Z", Axis::Z)], "X|Y|Z").parse(i)
}

/// `BLK FORM 0.1 Z X+0 Y+0 Z-40`, `BLK FORM 0.2 X+100 Y+100 Z+0`; `BLK FORM CYLINDER …` and
/// friends are not modelled (a recoverable stop: an unknown block).
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn blk_form<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let part = choice(&[("0.1", 1u8), ("0.2", 2u8)], "0.1|0.2");
    let (i, (_, _, part)) = (kw("BLK"), kw("FORM"), part).parse(body)?;
    let (mut i, axis) = if part == 1 { map(cut(lex(tool_axis)), Some).parse(i)? } else { (i, None) };
    cx.clear_words();
    i = sp(i);
    while !i.is_empty() {
        let (r, w) = axis_word(i).map_err(hard)?;
        cx.push_axis(i, r, w)?;
        if part == 1 && w.incremental {
            return invalid(i, Some(Expected::Nc("X|Y|Z")));
        }
        i = sp(r);
    }
    Ok((i, BlockBody::BlkForm(Box::new(BlkForm { part, tool_axis: axis, axes: cx.take_axes() }))))
}

/// The tool of `TOOL CALL`/`TOOL DEF`: a number, a `"name"`, a numeric parameter holding the
/// number (`Q5`, `QL5`, `QR5`) or a string parameter holding the name (`QS5`), as the TNC
/// dialog takes them; a recoverable stop if `i` starts none of them.
fn tool_ref(i: &str) -> Step<'_, ToolRef> {
    let param = |i| q_param(i).unwrap_or_else(|| expected(i, Expected::Nc("Q|QL|QR")));
    or_expected(
        alt((
            map(quoted, |name| ToolRef::Name(name.to_owned())),
            map(uint, ToolRef::Number),
            map(preceded(tag("QS"), uint), ToolRef::StringParam),
            map(param, ToolRef::Param),
        )),
        Expected::LabelNumberOrName,
    )
    .parse(i)
}

/// `TOOL DEF` and `TOOL DEF1` (the number run on).
fn tool_def_head(i: &str) -> Step<'_, ()> {
    let (i, _) = kw("TOOL").parse(i)?;
    match def_keyword(sp(i)) {
        Some(r) => Ok((r, ())),
        None => expected(i, Expected::Nc("DEF")),
    }
}

/// `TOOL DEF 2 L+75 R+5`, `TOOL DEF 0`, `TOOL DEF "name"`.
// Out of line in wasm, like the other rare families (see labels_q.rs).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn tool_def(body: &str) -> Step<'_, BlockBody> {
    let (i, ()) = tool_def_head(body)?;
    let (mut i, tool) = cut(lex(tool_ref)).parse(i)?;
    let (mut length, mut radius) = (None, None);
    i = sp(i);
    while !i.is_empty() {
        let at = i;
        let word = alt((
            map(preceded(tag("L"), cut(word_value)), |v| ("L", v)),
            map(preceded(tag("R"), cut(word_value)), |v| ("R", v)),
        ));
        let (r, (key, v)) = or_expected(word, Expected::Nc("L|R")).parse(i).map_err(hard)?;
        let slot = if key == "L" { &mut length } else { &mut radius };
        if slot.replace(v).is_some() {
            return duplicate(at, at.len() - r.len(), Named::Given(key));
        }
        i = sp(r);
    }
    Ok((i, BlockBody::ToolDef { tool, length, radius }))
}

/// One word after the tool of a `TOOL CALL`.
#[derive(Clone, Copy)]
enum CallWord {
    Dr2,
    Dr,
    Dl,
    Speed,
    Feed,
}

/// `TOOL CALL 16 Z S5000 F1000`, `TOOL CALL "name" Z S50 DL+0 DR+0`.
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn tool_call(body: &str) -> Step<'_, BlockBody> {
    let (i, _) = (kw("TOOL"), kw("CALL")).parse(body)?;
    let mut call = ToolCall::default();
    let (i, tool) = lex(opt(tool_ref)).parse(i)?;
    call.tool = tool;
    let (mut i, axis) = lex(opt(tool_axis)).parse(i)?;
    call.axis = axis;
    i = sp(i);
    // Longest key first: `DR2` before `DR`.
    let key = alt((
        value(("DR2", CallWord::Dr2), tag("DR2")),
        value(("DR", CallWord::Dr), tag("DR")),
        value(("DL", CallWord::Dl), tag("DL")),
        value(("S", CallWord::Speed), tag("S")),
        value(("F", CallWord::Feed), tag("F")),
    ));
    let mut word = (or_expected(key, Expected::Nc("S|F|DL|DR|DR2")), word_value);
    while !i.is_empty() {
        let at = i;
        let (r, ((key, which), v)) = word.parse(i).map_err(hard)?;
        let slot = match which {
            CallWord::Dr2 => &mut call.dr2,
            CallWord::Dr => &mut call.dr,
            CallWord::Dl => &mut call.dl,
            CallWord::Speed => &mut call.speed,
            CallWord::Feed => &mut call.feed,
        };
        if slot.is_some() {
            return duplicate(at, at.len() - r.len(), Named::Given(key));
        }
        *slot = Some(v);
        i = sp(r);
    }
    Ok((i, BlockBody::ToolCall(Box::new(call))))
}
