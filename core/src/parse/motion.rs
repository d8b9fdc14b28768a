//! Path blocks: straight lines, arcs, polar moves, rounding and chamfer, lone M functions.
//!   path := (L|CC|C|CR|CT|LP|CP) { [I]axis±v | [I]PR v | [I]PA v | R v | DR± | R0|RL|RR | feed | Mn | R|F|M }
//!   (a lone R, F or M is an old control's empty word: see `words::empty_word`)
//!   rnd  := RND R v [feed]        chf := CHF v [feed]        m_only := Mn { Mn }
//!   after M140: [MB (MAX|v) [feed]]      after M128: [F v]

use super::Cx;
use super::words::{
    Step, Stop, at_boundary, axis_word, empty_word, feed, hard, keyword, m_function, sign, sp, word_value,
};
use crate::ast::{BlockBody, Line, MWords, Motion, PolarWord, RadiusComp};
use crate::diag::{DiagCode, Expected};
use crate::plane::{Feed, MoveBack, Sign, Value};

const EXPECTED: &str = "X|Y|Z|A|B|C|R0|RL|RR|F|M";

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

fn polar<'a>(i: &'a str, key: &'static str) -> Option<Step<'a, PolarWord>> {
    let (incremental, rest) = match i.strip_prefix('I') {
        Some(r) => (true, r),
        None => (false, i),
    };
    let rest = rest.strip_prefix(key)?;
    if !rest.starts_with(['+', '-', '.', '0', '1', '2', '3', '4', '5', '6', '7', '8', '9', 'Q']) {
        return None;
    }
    Some(word_value(rest).map(|(r, value)| (r, PolarWord { value, incremental })))
}

/// Stores `v` in `slot` unless the word was already there.
pub(super) fn once<'a, T>(
    cx: &mut Cx,
    slot: &mut Option<(T, &'a str)>,
    v: T,
    at: &'a str,
    len: usize,
) -> bool {
    if slot.is_some() {
        let word = at[..len.min(at.len())].to_owned();
        cx.error(at, len, DiagCode::Duplicate { word });
        return false;
    }
    *slot = Some((v, at));
    true
}

/// The feed and radius-compensation words every path block may carry (`F…`, `R0`, `RL`, `RR`)
/// at `i`: `None` if `i` starts neither, else the rest and whether the word was new.
pub(super) fn feed_or_comp<'a>(
    cx: &mut Cx,
    i: &'a str,
    feed_slot: &mut Option<(Feed, &'a str)>,
    comp: &mut Option<(RadiusComp, &'a str)>,
) -> Option<Result<(&'a str, bool), Stop<'a>>> {
    if i.starts_with('F') {
        return Some(feed(i).map(|(r, f)| (r, once(cx, feed_slot, f, i, i.len() - r.len()))));
    }
    let (r, c) = [("R0", RadiusComp::R0), ("RL", RadiusComp::Rl), ("RR", RadiusComp::Rr)]
        .into_iter()
        .find_map(|(word, c)| keyword(i, word).map(|r| (r, c)))?;
    Some(Ok((r, once(cx, comp, c, i, 2))))
}

/// `L`, `CC`, `C`, `CR`, `CT`, `LP`, `CP`, `RND`, `CHF` (`rest` follows the keyword).
pub(super) fn path(cx: &mut Cx, kw: &str, rest: &str) -> Option<BlockBody> {
    cx.axes.clear();
    cx.m.clear();
    if !at_boundary(rest) {
        return cx.invalid(rest, Some(Expected::Blank));
    }
    match kw {
        "RND" | "CHF" => return rounding(cx, kw, sp(rest)),
        _ => {}
    }
    path_words(cx, kw, sp(rest))
}

/// A straight line written without its `L` (`Z0.0 B0.0 C0.0 FMAX M91`, `body` starting with
/// the first axis word), read as `L` (`lenient::lacks_l`).
pub(super) fn line_without_l(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    cx.axes.clear();
    cx.m.clear();
    path_words(cx, "L", body)
}

/// The words of a path block `kw` from `i` on.
fn path_words(cx: &mut Cx, kw: &str, mut i: &str) -> Option<BlockBody> {
    let mut w = Words::default();
    while !i.is_empty() {
        let at = i;
        if let Some(r) = empty_word(i, b"RFM") {
            i = sp(r);
            continue;
        }
        if let Ok((r, m)) = m_function(i) {
            w.first_m.get_or_insert(at);
            cx.m.push(m);
            i = match m_args(m, r, &mut w.m_words) {
                Ok(r) => sp(r),
                Err(e) => return cx.fail(e),
            };
            continue;
        }
        match axis_word(i) {
            Ok((r, word)) => {
                if cx.axes.iter().any(|a| a.axis == word.axis) {
                    let len = at.len() - r.len();
                    cx.error(at, len, DiagCode::Duplicate { word: word.axis.as_str().to_owned() });
                    return None;
                }
                cx.axes.push(word);
                i = sp(r);
                continue;
            }
            Err(nom::Err::Error(_)) => {}
            Err(e) => return cx.fail(e),
        }
        let (r, ok) = if let Some(read) = feed_or_comp(cx, i, &mut w.feed, &mut w.comp) {
            match read {
                Ok(read) => read,
                Err(e) => return cx.fail(e),
            }
        } else if let Some(after) = i.strip_prefix("DR") {
            match sign(after) {
                Ok((r, s)) if at_boundary(r) => (r, once(cx, &mut w.direction, s, at, 3)),
                _ => return cx.invalid(at, Some(Expected::Nc("DR+|DR-"))),
            }
        } else if let Some(res) = polar(i, "PR") {
            match res {
                Ok((r, p)) => (r, once(cx, &mut w.polar_radius, p, at, i.len() - r.len())),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(res) = polar(i, "PA") {
            match res {
                Ok((r, p)) => (r, once(cx, &mut w.polar_angle, p, at, i.len() - r.len())),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(after) = i.strip_prefix('R') {
            match word_value(after) {
                Ok((r, v)) => (r, once(cx, &mut w.radius, v, at, i.len() - r.len())),
                Err(e) => return cx.fail(e),
            }
        } else if let Some(after) = i.strip_prefix('S') {
            match word_value(after) {
                Ok((r, v)) => (r, once(cx, &mut w.speed, v, at, i.len() - r.len())),
                Err(e) => return cx.fail(e),
            }
        } else {
            return cx.invalid(at, Some(Expected::Nc(EXPECTED)));
        };
        if !ok {
            return None;
        }
        i = sp(r);
    }
    build(cx, kw, w, i)
}

/// Checks which words the block kind takes and builds the node.
fn build(cx: &mut Cx, kw: &str, w: Words<'_>, end: &str) -> Option<BlockBody> {
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
    for (word, at) in present {
        if let Some(at) = at
            && !allowed(word)
        {
            let len = at.find([' ', '\t']).unwrap_or(at.len());
            let text = at[..len].to_owned();
            cx.error(at, len, DiagCode::NotAllowed { word: text });
            return None;
        }
    }
    if kw == "CR" && w.radius.is_none() {
        cx.error(end, 0, DiagCode::MissingWord { word: "R" });
        return None;
    }
    // CP needs the end point's angle (manual: "Polar coordinates angle PA: angular position of
    // the arc end point").
    if kw == "CP" && w.polar_angle.is_none() {
        cx.error(end, 0, DiagCode::MissingWord { word: "PA" });
        return None;
    }
    let comp = w.comp.map(|c| c.0);
    let feed = w.feed.map(|f| f.0);
    let speed = w.speed.map(|s| s.0);
    if kw == "L" {
        let m_words = w.m_words;
        let axes = cx.take_line_axes();
        return Some(BlockBody::L(Line { axes, comp, feed, speed, m: cx.take_m(), m_words }));
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
    Some(match kw {
        "CC" => BlockBody::Cc(motion),
        "C" => BlockBody::C(motion),
        "CR" => BlockBody::Cr(motion),
        "CT" => BlockBody::Ct(motion),
        "LP" => BlockBody::Lp(motion),
        _ => BlockBody::Cp(motion),
    })
}

/// `RND R…` and `CHF …`, each with an optional feed.
fn rounding(cx: &mut Cx, kw: &str, i: &str) -> Option<BlockBody> {
    let v = if kw == "RND" {
        match i.strip_prefix('R') {
            Some(r) => word_value(r),
            None => return cx.invalid(i, Some(Expected::Nc("R"))),
        }
    } else {
        word_value(i)
    };
    let (rest, v) = match v {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let rest = sp(rest);
    let (rest, f) = if rest.is_empty() {
        (rest, None)
    } else {
        match feed(rest) {
            Ok((r, f)) => (sp(r), Some(f)),
            Err(e) => return cx.fail(e),
        }
    };
    if !rest.is_empty() {
        return cx.invalid(rest, None);
    }
    Some(if kw == "RND" {
        BlockBody::Rnd { radius: v, feed: f }
    } else {
        BlockBody::Chf { length: v, feed: f }
    })
}

/// `STOP` with optional M functions (`STOP M0`); `rest` follows the keyword.
// Out of line in wasm, like the other rare families (see labels_q.rs).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn stop(cx: &mut Cx, rest: &str) -> Option<BlockBody> {
    if !at_boundary(rest) {
        return super::unknown(cx, rest);
    }
    let rest = sp(rest);
    if rest.is_empty() {
        return Some(BlockBody::Stop { m: Box::default() });
    }
    match m_only(cx, rest)? {
        BlockBody::MFunctions(m, _) => Some(BlockBody::Stop { m }),
        _ => None,
    }
}

/// A block of only M functions (`M30`, `M99`, `M140 MB MAX`).
pub(super) fn m_only(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    cx.m.clear();
    let mut words = MWords::default();
    let mut i = body;
    while !i.is_empty() {
        match m_function(i).and_then(|(r, m)| m_args(m, r, &mut words).map(|r| (r, m))) {
            Ok((r, m)) => {
                cx.m.push(m);
                i = sp(r);
            }
            Err(e) => return cx.fail(e),
        }
    }
    Some(BlockBody::MFunctions(cx.take_m(), words))
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
