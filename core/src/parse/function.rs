//! The `FUNCTION` blocks the simulator runs (DOMAIN.md §6); every other `FUNCTION …` is kept as
//! an unknown block.
//!   tcpm  := FUNCTION TCPM (F TCP|F CONT) (AXIS POS|AXIS SPAT) (PATHCTRL AXIS|PATHCTRL VECTOR)
//!   reset := FUNCTION RESET TCPM

use nom::Parser;
use nom::branch::alt;
use nom::combinator::{cut, map};
use nom::sequence::preceded;

use super::words::{Step, expected, failure, hard, keyword, kw, sp, whole};
use crate::ast::{BlockBody, PathCtrl, Tcpm, TcpmAxis, TcpmFeed};
use crate::diag::Expected;

/// `FUNCTION TCPM …` or `FUNCTION RESET TCPM`; every other `FUNCTION …` is a recoverable stop.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn function(body: &str) -> Step<'_, BlockBody> {
    let tcpm = preceded(kw("TCPM"), cut(whole(map(|i| tcpm(sp(i)).map_err(hard), BlockBody::FunctionTcpm))));
    let reset = preceded((kw("RESET"), kw("TCPM")), cut(whole(|i| Ok((i, BlockBody::FunctionResetTcpm)))));
    preceded(kw("FUNCTION"), alt((tcpm, reset))).parse(body)
}

/// The three mode words, in the control's order; each must be there.
fn tcpm(i: &str) -> Step<'_, Tcpm> {
    let (i, feed) =
        mode(i, "F", [("TCP", TcpmFeed::Tcp), ("CONT", TcpmFeed::Cont)], ["F TCP|F CONT", "TCP|CONT"])?;
    let (i, axis) = mode(
        i,
        "AXIS",
        [("POS", TcpmAxis::Pos), ("SPAT", TcpmAxis::Spat)],
        ["AXIS POS|AXIS SPAT", "POS|SPAT"],
    )?;
    let (i, path) = mode(
        i,
        "PATHCTRL",
        [("AXIS", PathCtrl::Axis), ("VECTOR", PathCtrl::Vector)],
        ["PATHCTRL AXIS|PATHCTRL VECTOR", "AXIS|VECTOR"],
    )?;
    Ok((i, Tcpm { feed, axis, path }))
}

/// `key choice`: the key missing stops at its place naming the whole word, a wrong choice stops
/// at the choice naming the choices.
fn mode<'a, T: Copy>(
    i: &'a str,
    key: &'static str,
    choices: [(&'static str, T); 2],
    what: [&'static str; 2],
) -> Step<'a, T> {
    let Some(after) = keyword(i, key).map(sp) else { return expected(i, Expected::Nc(what[0])) };
    match choices.iter().find_map(|&(word, v)| keyword(after, word).map(|rest| (sp(rest), v))) {
        Some(found) => Ok(found),
        None => failure(after, Expected::Nc(what[1])),
    }
}
