//! Coordinate transformations (DOMAIN.md §6).
//!   trans := TRANS DATUM (AXIS {axis±v} | RESET) | TRANS MIRROR (AXIS {X|Y|Z…} | RESET)
//!          | TRANS ROTATION ([I]ROT v | RESET)

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{cut, opt, value};

use super::Cx;
use super::words::{
    Named, Step, axis_word, choice, duplicate, hard, invalid, kw, lex, missing, or_expected, sp, whole,
    word_value,
};
use crate::ast::{Axis, BlockBody};
use crate::diag::Expected;

#[derive(Clone, Copy)]
enum Kind {
    Datum,
    Mirror,
    Rotation,
}

/// `TRANS …` (`TRANS SCALE` and others are a recoverable stop: kept as unknown blocks).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn trans<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let kind = choice(
        &[("DATUM", Kind::Datum), ("MIRROR", Kind::Mirror), ("ROTATION", Kind::Rotation)],
        "DATUM|MIRROR|ROTATION",
    );
    let (i, (_, kind)) = (kw("TRANS"), kind).parse(body)?;
    let (i, reset) = opt(whole(kw("RESET"))).parse(i)?;
    match (kind, reset.is_some()) {
        (Kind::Datum, true) => Ok((i, BlockBody::TransDatumReset)),
        (Kind::Mirror, true) => Ok((i, BlockBody::TransMirrorReset)),
        (Kind::Rotation, true) => Ok((i, BlockBody::TransRotationReset)),
        (Kind::Datum, false) => datum(cx, i),
        (Kind::Mirror, false) => mirror(i),
        (Kind::Rotation, false) => rotation(i),
    }
}

/// `AXIS`, or else a stop naming `AXIS|RESET`.
fn axis_keyword(i: &str) -> Step<'_, &'static str> {
    cut(lex(or_expected(kw("AXIS"), Expected::Nc("AXIS|RESET")))).parse(i)
}

/// `AXIS X+10 Y-5`: axis words, each at most once, at least one.
fn datum<'a>(cx: &Cx, i: &'a str) -> Step<'a, BlockBody> {
    let (mut r, _) = axis_keyword(i)?;
    r = sp(r);
    cx.clear_words();
    while !r.is_empty() {
        let (rest, w) = axis_word(r).map_err(hard)?;
        cx.push_axis(r, rest, w)?;
        r = sp(rest);
    }
    if cx.axis_count() == 0 {
        return missing(r, "X|Y|Z");
    }
    Ok((r, BlockBody::TransDatum { axes: cx.take_axes() }))
}

/// `AXIS X Y`: axis letters, each at most once, at least one.
fn mirror(i: &str) -> Step<'_, BlockBody> {
    let (mut r, _) = axis_keyword(i)?;
    r = sp(r);
    let mut axes: Vec<Axis> = Vec::new();
    while !r.is_empty() {
        let Some((rest, a)) =
            Axis::ALL.iter().find_map(|&a| kw(a.as_str()).parse(r).ok().map(|(x, _)| (x, a)))
        else {
            return invalid(r, Some(Expected::Nc("X|Y|Z")));
        };
        if axes.contains(&a) {
            return duplicate(r, 1, Named::Given(a.as_str()));
        }
        axes.push(a);
        r = sp(rest);
    }
    if axes.is_empty() {
        return missing(r, "X|Y|Z");
    }
    Ok((r, BlockBody::TransMirror { axes: axes.into_boxed_slice() }))
}

/// `ROT v` or `IROT v`.
fn rotation(i: &str) -> Step<'_, BlockBody> {
    let i = sp(i);
    let key: Step<'_, bool> = alt((value(true, tag("IROT")), value(false, tag("ROT")))).parse(i);
    let Ok((after, incremental)) = key else {
        return missing(i, "ROT");
    };
    let (rest, rot) = whole(lex(word_value)).parse(after).map_err(hard)?;
    Ok((rest, BlockBody::TransRotation { rot, incremental }))
}
