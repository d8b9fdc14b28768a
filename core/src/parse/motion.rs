//! Path blocks: straight lines, arcs, polar moves, rounding and chamfer, lone M functions.
//!   path := (L|CC|C|CR|CT|LP|CP) { [I]axis±v | [I]PR v | [I]PA v | R v | DR± | R0|RL|RR | feed | Mn | R|F|M }
//!   (a lone R, F or M is an old control's empty word: see `words::empty_word`)
//!   rnd  := RND R v [feed]        chf := CHF v [feed]        m_only := Mn { Mn }
//!   after M140: [MB (MAX|v) [feed]]      after M128: [F v]

use nom::Parser;
use nom::branch::alt;
use nom::bytes::complete::tag;
use nom::combinator::{cut, map};
use nom::sequence::preceded;

use super::Cx;
use super::words::{
    Named, NcError, Step, Stop, at_boundary, axis_word, boundary, choice, duplicate, empty_word,
    end_of_block, expected, feed, hard, invalid, keyword, letters, m_function, missing, not_allowed,
    or_expected, sign, soft, sp, word_value,
};
use crate::ast::{AxisWord, BlockBody, Line, MWords, Motion, PolarWord, RadiusComp};
use crate::diag::Expected;
use crate::plane::{Feed, MoveBack, Sign, Value};

const EXPECTED: &str = "X|Y|Z|A|B|C|R0|RL|RR|F|M";

/// One word of a path block.
#[derive(Clone, Copy)]
enum PathWord {
    /// An old control's empty `R`, `F` or `M` (`words::empty_word`): nothing programmed.
    Empty,
    M(u32),
    Axis(AxisWord),
    Feed(Feed),
    Comp(RadiusComp),
    Direction(Sign),
    PolarRadius(PolarWord),
    PolarAngle(PolarWord),
    Radius(Value),
    Speed(Value),
}

/// Words of a path block, with where each optional word stood (for "not allowed here").
#[derive(Default)]
struct Words<'a> {
    polar_radius: Option<(PolarWord, &'a str)>,
    polar_angle: Option<(PolarWord, &'a str)>,
    radius: Option<(Value, &'a str)>,
    direction: Option<(Sign, &'a str)>,
    comp: Option<(RadiusComp, &'a str)>,
    feed: Option<(Feed, &'a str)>,
    speed: Option<(Value, &'a str)>,
    first_m: Option<&'a str>,
    m_words: MWords,
}

/// `[I]PR v` or `[I]PA v` (`key`): recoverable unless the key is followed by a value's start.
fn polar<'a>(key: &'static str) -> impl Parser<&'a str, Output = PolarWord, Error = NcError<'a>> {
    move |i: &'a str| {
        let (incremental, rest) = match i.strip_prefix('I') {
            Some(r) => (true, r),
            None => (false, i),
        };
        let Some(rest) = rest.strip_prefix(key).filter(|r| {
            r.starts_with(['+', '-', '.', '0', '1', '2', '3', '4', '5', '6', '7', '8', '9', 'Q'])
        }) else {
            return expected(i, Expected::Nc(key));
        };
        let (r, value) = word_value(rest).map_err(hard)?;
        Ok((r, PolarWord { value, incremental }))
    }
}

/// `key` directly followed by a value that ends its word; hard once the key is read.
fn keyed<'a>(key: &'static str) -> impl Parser<&'a str, Output = Value, Error = NcError<'a>> {
    preceded(tag(key), cut(word_value))
}

/// The radius-compensation words `R0`, `RL`, `RR`.
pub(super) fn comp(i: &str) -> Step<'_, RadiusComp> {
    const COMP: &[(&str, RadiusComp)] =
        &[("R0", RadiusComp::R0), ("RL", RadiusComp::Rl), ("RR", RadiusComp::Rr)];
    choice(COMP, "R0|RL|RR").parse(i)
}

/// `DR+` or `DR-` as one word.
fn direction(i: &str) -> Step<'_, Sign> {
    let (r, _) = tag("DR").parse(i)?;
    match sign(r) {
        Ok((r, s)) if at_boundary(r) => Ok((r, s)),
        _ => invalid(i, Some(Expected::Nc("DR+|DR-"))),
    }
}

/// One word of a path block, tried in the order that tells them apart (`R0` before `R…`).
fn path_word(i: &str) -> Step<'_, PathWord> {
    let empty = |i| match empty_word(i, b"RFM") {
        Some(r) => Ok((r, PathWord::Empty)),
        None => expected(i, Expected::Nc(EXPECTED)),
    };
    // An `M` that is not a whole M function is not one (`M3X`): the other words are tried.
    let m = map(|i| m_function(i).map_err(soft), PathWord::M);
    alt((
        empty,
        m,
        map(axis_word, PathWord::Axis),
        map(feed, PathWord::Feed),
        map(comp, PathWord::Comp),
        map(direction, PathWord::Direction),
        map(polar("PR"), PathWord::PolarRadius),
        map(polar("PA"), PathWord::PolarAngle),
        map(keyed("R"), PathWord::Radius),
        map(keyed("S"), PathWord::Speed),
    ))
    .parse(i)
}

/// Stores `v` in `slot`, where the word `at` (its first `len` bytes) stood; a hard stop if the
/// word was already there.
pub(super) fn once<'a, T>(
    slot: &mut Option<(T, &'a str)>,
    v: T,
    at: &'a str,
    len: usize,
) -> Result<(), Stop<'a>> {
    if slot.is_some() {
        return duplicate(at, len, Named::Written(len)).map(|(_, ())| ());
    }
    *slot = Some((v, at));
    Ok(())
}

/// `L`, `CC`, `C`, `CR`, `CT`, `LP`, `CP`, `RND`, `CHF`: the whole block `body`.
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn path<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (rest, kw) = letters(body)?;
    path_after(cx, kw, rest)
}

/// A path block `kw` from `rest` on (right after the keyword; `CYCL CALL POS` reads its words
/// as those of `L`).
pub(super) fn path_after<'a>(cx: &Cx, kw: &str, rest: &'a str) -> Step<'a, BlockBody> {
    cx.clear_words();
    let (rest, ()) = cut(boundary).parse(rest)?;
    match kw {
        "RND" | "CHF" => rounding(kw == "RND", sp(rest)),
        _ => path_words(cx, kw, sp(rest)),
    }
}

/// A straight line written without its `L` (`Z0.0 B0.0 C0.0 FMAX M91`, `body` starting with
/// the first axis word), read as `L` (`lenient::lacks_l`).
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn line_without_l<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    cx.clear_words();
    path_words(cx, "L", body)
}

/// The words of a path block `kw` from `i` on: any number of [`path_word`]s, each at most once.
fn path_words<'a>(cx: &Cx, kw: &str, mut i: &'a str) -> Step<'a, BlockBody> {
    let mut w = Words::default();
    while !i.is_empty() {
        let at = i;
        let (r, word) = or_expected(path_word, Expected::Nc(EXPECTED)).parse(i).map_err(hard)?;
        let len = at.len() - r.len();
        let mut r = r;
        match word {
            PathWord::Empty => {}
            PathWord::M(m) => {
                w.first_m.get_or_insert(at);
                cx.push_m(m);
                r = m_args(m, r, &mut w.m_words).map_err(hard)?;
            }
            PathWord::Axis(word) => {
                cx.push_axis(at, r, word)?;
            }
            PathWord::Feed(f) => once(&mut w.feed, f, at, len)?,
            PathWord::Comp(c) => once(&mut w.comp, c, at, len)?,
            PathWord::Direction(s) => once(&mut w.direction, s, at, len)?,
            PathWord::PolarRadius(p) => once(&mut w.polar_radius, p, at, len)?,
            PathWord::PolarAngle(p) => once(&mut w.polar_angle, p, at, len)?,
            PathWord::Radius(v) => once(&mut w.radius, v, at, len)?,
            PathWord::Speed(v) => once(&mut w.speed, v, at, len)?,
        }
        i = sp(r);
    }
    build(cx, kw, w, i)
}

/// Checks which words the block kind takes and builds the node.
fn build<'a>(cx: &Cx, kw: &str, w: Words<'a>, end: &'a str) -> Step<'a, BlockBody> {
    let allowed = |word: &str| -> bool {
        match kw {
            "L" | "CT" => matches!(word, "comp" | "feed" | "speed" | "m"),
            "CC" => false,
            "C" => matches!(word, "dir" | "comp" | "feed" | "speed" | "m"),
            "CR" => matches!(word, "radius" | "dir" | "comp" | "feed" | "speed" | "m"),
            "LP" => matches!(word, "pr" | "pa" | "comp" | "feed" | "speed" | "m"),
            "CP" => matches!(word, "pa" | "dir" | "comp" | "feed" | "speed" | "m"),
            _ => false,
        }
    };
    let present: [(&str, Option<&str>); 8] = [
        ("pr", w.polar_radius.map(|p| p.1)),
        ("pa", w.polar_angle.map(|p| p.1)),
        ("radius", w.radius.map(|p| p.1)),
        ("dir", w.direction.map(|p| p.1)),
        ("comp", w.comp.map(|p| p.1)),
        ("feed", w.feed.map(|p| p.1)),
        ("speed", w.speed.map(|p| p.1)),
        ("m", w.first_m),
    ];
    if let Some(at) = present.into_iter().find_map(|(word, at)| at.filter(|_| !allowed(word))) {
        return not_allowed(at);
    }
    if kw == "CR" && w.radius.is_none() {
        return missing(end, "R");
    }
    // CP needs the end point's angle (manual: "Polar coordinates angle PA: angular position of
    // the arc end point").
    if kw == "CP" && w.polar_angle.is_none() {
        return missing(end, "PA");
    }
    let comp = w.comp.map(|c| c.0);
    let feed = w.feed.map(|f| f.0);
    let speed = w.speed.map(|s| s.0);
    if kw == "L" {
        let m_words = w.m_words;
        let axes = cx.take_line_axes();
        return Ok((end, BlockBody::L(Line { axes, comp, feed, speed, m: cx.take_m(), m_words })));
    }
    let motion = Box::new(Motion {
        axes: cx.take_axes(),
        polar_radius: w.polar_radius.map(|p| p.0),
        polar_angle: w.polar_angle.map(|p| p.0),
        radius: w.radius.map(|p| p.0),
        direction: w.direction.map(|p| p.0),
        comp,
        feed,
        speed,
        m: cx.take_m(),
    });
    Ok((
        end,
        match kw {
            "CC" => BlockBody::Cc(motion),
            "C" => BlockBody::C(motion),
            "CR" => BlockBody::Cr(motion),
            "CT" => BlockBody::Ct(motion),
            "LP" => BlockBody::Lp(motion),
            _ => BlockBody::Cp(motion),
        },
    ))
}

/// `RND R…` and `CHF …`, each with an optional feed.
fn rounding(rnd: bool, i: &str) -> Step<'_, BlockBody> {
    let (rest, v) = if rnd {
        preceded(or_expected(tag("R"), Expected::Nc("R")), word_value).parse(i)
    } else {
        word_value(i)
    }
    .map_err(hard)?;
    let rest = sp(rest);
    let (rest, feed) =
        if rest.is_empty() { (rest, None) } else { map(feed, Some).parse(rest).map_err(hard)? };
    let (rest, ()) = end_of_block(rest)?;
    Ok((rest, if rnd { BlockBody::Rnd { radius: v, feed } } else { BlockBody::Chf { length: v, feed } }))
}

/// `STOP` with optional M functions (`STOP M0`): the whole block `body`.
// Out of line in wasm, like the other rare families (see labels_q.rs).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn stop<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (rest, _) = tag("STOP").parse(body)?;
    if !at_boundary(rest) {
        return invalid(rest, None);
    }
    let (rest, (m, _)) = m_functions(cx, sp(rest))?;
    Ok((rest, BlockBody::Stop { m }))
}

/// A block of only M functions (`M30`, `M99`, `M140 MB MAX`).
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn m_only<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    map(|i| m_functions(cx, i), |(m, words)| BlockBody::MFunctions(m, words)).parse(body)
}

/// M functions with the words that belong to them, up to the end of the block.
fn m_functions<'a>(cx: &Cx, mut i: &'a str) -> Step<'a, (Box<[u32]>, MWords)> {
    cx.clear_words();
    let mut words = MWords::default();
    while !i.is_empty() {
        let (r, m) = m_function(i).map_err(hard)?;
        let r = m_args(m, r, &mut words).map_err(hard)?;
        cx.push_m(m);
        i = sp(r);
    }
    Ok((i, (cx.take_m(), words)))
}

/// The words after M function `m` that belong to it ([`MWords`]): `MB MAX`, `MB+50` or `MB 50`
/// after `M140`, each with an optional feed; `F…` after `M128` (so `L X+1 F500 M128 F1000` has both feeds). The rest.
#[cfg_attr(target_arch = "wasm32", inline(never))]
fn m_args<'a>(m: u32, i: &'a str, words: &mut MWords) -> Result<&'a str, Stop<'a>> {
    let t = sp(i);
    match m {
        140 => {
            let Some(after) = t.strip_prefix("MB") else { return Ok(i) };
            let v = sp(after);
            let r = if let Some(r) = keyword(v, "MAX") {
                words.mb = Some(MoveBack::Max);
                r
            } else {
                let (r, d) = word_value(v).map_err(hard)?;
                words.mb = Some(MoveBack::Dist(d));
                r
            };
            // The retract's own feed, right after MB (unconfirmed::M140_FEED_AFTER_MB).
            let t = sp(r);
            if !t.starts_with('F') {
                return Ok(r);
            }
            let (r, f) = feed(t)?;
            words.mb_feed = Some(f);
            Ok(r)
        }
        120 if t.starts_with("LA") => {
            let (r, v) = word_value(&t[2..]).map_err(hard)?;
            words.look_ahead = Some(v);
            Ok(r)
        }
        128 if t.starts_with('F') && keyword(t, "FMAX").is_none() => {
            let (r, f) = feed(t)?;
            match f {
                Feed::Value(v) => {
                    words.m128_feed = Some(v);
                    Ok(r)
                }
                _ => Ok(i),
            }
        }
        _ => Ok(i),
    }
}
