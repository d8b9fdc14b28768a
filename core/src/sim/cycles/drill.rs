//! The drilling family: 200 BOHREN, 201 REIBEN, 203 UNIVERSAL-BOHREN, 205
//! UNIVERSAL-TIEFBOHREN, 208 BOHRFRAESEN, each at the position where it is called.
//!
//! Common to all (HEIDENHAIN cycle manual, each cycle's "Cycle run"): the tool first moves at
//! FMAX in the tool axis to the set-up clearance Q200 above the surface Q203; the depth Q201 is
//! negative (a positive one is the control's error, depth 0 does not execute the cycle); at the
//! end the tool returns to the set-up clearance and, if the 2nd set-up clearance Q204 is larger,
//! at FMAX to Q204. A retraction feed Q208 of 0 retracts at the plunging feed Q206.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};

use super::{EPS, MAX_CYCLE_MOVES, Params, arc, depth, feed, rapid};
use crate::sim::error::SimErrorCode;
use crate::unconfirmed;

use super::CycleMove;

type R<T> = Result<T, SimErrorCode>;

/// The retraction feed: Q208, or the plunging feed Q206 when Q208 is 0 (manual, cycles 201,
/// 203: "If you enter Q208 = 0, the tool retracts at the feed rate Q206"; cycle 205 the same,
/// [`unconfirmed::CYCLE205_Q208_ZERO_IS_Q206`]).
fn retract_feed(q208: f64, q206: f64) -> f64 {
    if q208 > 0.0 { q208 } else { q206 }
}

/// The common frame of a drilling cycle: the hole's axis and its heights.
struct Hole {
    at: DVec2,
    surface: f64,
    clear: f64,
    clear2: f64,
}

impl Hole {
    fn new(p: &Params, pos: DVec3) -> R<Hole> {
        Ok(Hole { at: pos.truncate(), surface: p.get(203)?, clear: p.get(200)?, clear2: p.get(204)? })
    }

    /// The point `d` below the surface (negative `d` = above).
    fn below(&self, d: f64) -> DVec3 {
        self.at.extend(self.surface - d)
    }

    fn safe(&self) -> DVec3 {
        self.at.extend(self.surface + self.clear)
    }

    /// FMAX to the 2nd set-up clearance when it is above the set-up clearance.
    fn finish(&self, out: &mut Vec<CycleMove>) {
        if self.clear2 > self.clear {
            out.push(rapid(self.at.extend(self.surface + self.clear2)));
        }
    }
}

/// Cycle 200 BOHREN: FMAX to Q200 above Q203; per infeed Q202 at Q206, FMAX back to Q200 (dwell
/// Q210) and FMAX down to Q200 above the depth reached ("to the set-up clearance above the first
/// plunging depth"), until Q201; FMAX to Q200, then Q204 (manual, cycle 200 "Cycle run").
pub(super) fn drill_200(p: &Params, pos: DVec3) -> R<Vec<CycleMove>> {
    let hole = Hole::new(p, pos)?;
    let (f, step) = (p.get(206)?, p.get(202)?);
    let total = depth(p)?;
    let mut out = vec![rapid(hole.safe())];
    if total == 0.0 {
        return Ok(out);
    }
    let mut reached = 0.0;
    let mut made = 0;
    loop {
        reached = next_depth(
            reached,
            unconfirmed::decremented_infeed(step, 0.0, 0.0, made, total - reached),
            total,
        );
        made += 1;
        out.push(feed(hole.below(reached), f));
        if reached >= total || out.len() >= MAX_CYCLE_MOVES {
            break;
        }
        out.push(rapid(hole.safe()));
        out.push(rapid(hole.below(reached - hole.clear)));
    }
    out.push(rapid(hole.safe()));
    hole.finish(&mut out);
    Ok(out)
}

fn next_depth(reached: f64, step: f64, total: f64) -> f64 {
    let d = reached + step;
    if total - d <= EPS { total } else { d }
}

/// Cycle 201 REIBEN: FMAX to Q200 above Q203, at Q206 to the depth Q201 (dwell Q211), back to Q200
/// at the retraction feed Q208, then FMAX to Q204 (manual, cycle 201 "Cycle run").
#[inline(never)]
pub(super) fn ream_201(p: &Params, pos: DVec3) -> R<Vec<CycleMove>> {
    let hole = Hole::new(p, pos)?;
    let f = p.get(206)?;
    let back = retract_feed(p.get(208)?, f);
    let total = depth(p)?;
    let mut out = vec![rapid(hole.safe())];
    if total == 0.0 {
        return Ok(out);
    }
    out.push(feed(hole.below(total), f));
    out.push(feed(hole.safe(), back));
    hole.finish(&mut out);
    Ok(out)
}

/// Cycle 203 UNIVERSAL-BOHREN (manual, cycle 203 "Cycle run"): FMAX to Q200 above Q203; each
/// infeed at Q206, the first Q202, each next smaller by the decrement Q212 but not below the
/// minimum plunging depth Q205. After an infeed the tool breaks the chip, retracting by Q256
/// ([`unconfirmed::CHIP_BREAK_AT_RETRACTION_FEED`]), Q213 times; after the next infeed it
/// retracts at Q208 to Q200 (dwell Q210) and returns at FMAX to Q200 above the depth reached, and
/// the count starts again. At depth (dwell Q211) it retracts at Q208 to Q200, then FMAX to Q204.
#[inline(never)]
pub(super) fn drill_203(p: &Params, pos: DVec3) -> R<Vec<CycleMove>> {
    let hole = Hole::new(p, pos)?;
    let f = p.get(206)?;
    let (first, decrement, breaks_max, min) = (p.get(202)?, p.get(212)?, p.get(213)?, p.get(205)?);
    let back = retract_feed(p.get(208)?, f);
    let lift = p.get(256)?;
    let total = depth(p)?;
    let mut out = vec![rapid(hole.safe())];
    if total == 0.0 {
        return Ok(out);
    }
    let (mut reached, mut made, mut breaks) = (0.0, 0, 0.0);
    loop {
        let step = unconfirmed::decremented_infeed(first, decrement, min, made, total - reached);
        reached = next_depth(reached, step, total);
        made += 1;
        out.push(feed(hole.below(reached), f));
        if reached >= total || out.len() >= MAX_CYCLE_MOVES {
            break;
        }
        if breaks < breaks_max {
            breaks += 1.0;
            out.push(chip_break(&hole, reached, lift, back));
        } else {
            breaks = 0.0;
            out.push(feed(hole.safe(), back));
            out.push(rapid(hole.below(reached - hole.clear)));
        }
    }
    out.push(feed(hole.safe(), back));
    hole.finish(&mut out);
    Ok(out)
}

/// The retraction by Q256 that breaks the chip at depth `reached`.
fn chip_break(hole: &Hole, reached: f64, lift: f64, back: f64) -> CycleMove {
    let to = hole.below(reached - lift.max(0.0));
    if unconfirmed::CHIP_BREAK_AT_RETRACTION_FEED { feed(to, back) } else { rapid(to) }
}

/// Cycle 205 UNIVERSAL-TIEFBOHREN (manual, cycle 205 "Cycle run"): FMAX to Q200 above Q203; with
/// a deepened starting point Q379 at the pre-positioning feed Q253 to Q200 above it. Each infeed
/// at Q206 (Q202, less Q212 per infeed, at least Q205); within an infeed the tool breaks the chip
/// after every Q257 by retracting Q256. After an infeed it retracts at Q208 to Q200 and returns at
/// FMAX to the advanced stop distance above the depth reached: Q258 at the first, Q259 at the
/// last, in between in proportion ([`unconfirmed::advanced_stop_distance`]). At depth (dwell Q211)
/// at Q208 to Q200, then FMAX to Q204. Without Q208 (older software) the retraction is rapid.
#[inline(never)]
pub(super) fn peck_205(p: &Params, pos: DVec3) -> R<Vec<CycleMove>> {
    let hole = Hole::new(p, pos)?;
    let f = p.get(206)?;
    let (first, decrement, min) = (p.get(202)?, p.get(212)?, p.get(205)?);
    let (upper, lower) = (p.get(258)?, p.get(259)?);
    let (break_every, lift) = (p.get(257)?, p.get(256)?);
    // An older definition has no Q208 (`unconfirmed::CYCLE205_WITHOUT_Q208_FEED`).
    let q208 = p.or(208, unconfirmed::CYCLE205_WITHOUT_Q208_FEED);
    let back = if unconfirmed::CYCLE205_Q208_ZERO_IS_Q206 { retract_feed(q208, f) } else { q208 };
    let total = depth(p)?;
    let mut out = vec![rapid(hole.safe())];
    if total == 0.0 {
        return Ok(out);
    }
    let deepened = p.or(379, 0.0).clamp(0.0, total);
    if deepened > 0.0 {
        out.push(feed(hole.below(deepened - hole.clear), p.get(253)?));
    }
    let (mut reached, mut made) = (deepened, 0);
    while reached < total && out.len() < MAX_CYCLE_MOVES {
        let step = unconfirmed::decremented_infeed(first, decrement, min, made, total - reached);
        let target = next_depth(reached, step, total);
        made += 1;
        if break_every > 0.0 {
            let mut d = reached + break_every;
            while target - d > EPS && out.len() < MAX_CYCLE_MOVES {
                out.push(feed(hole.below(d), f));
                out.push(chip_break(&hole, d, lift, back));
                d += break_every;
            }
        }
        out.push(feed(hole.below(target), f));
        reached = target;
        if reached >= total {
            break;
        }
        out.push(feed(hole.safe(), back));
        let stop = unconfirmed::advanced_stop_distance(upper, lower, reached, total);
        out.push(rapid(hole.below(reached - stop)));
    }
    out.push(feed(hole.safe(), back));
    hole.finish(&mut out);
    Ok(out)
}

/// Cycle 208 BOHRFRAESEN (manual, cycle 208 "Cycle run"): FMAX to Q200 above Q203; the tool
/// reaches the helix on a semicircle, mills down on a helix of pitch Q334 at Q206 to the depth
/// Q201, mills a full circle at depth to remove what the plunge left, returns to the hole centre
/// and at FMAX to Q200; finally FMAX to Q204. Climb milling (Q351 = +1, M3) runs DR+, up-cut
/// (−1) DR−. A nominal diameter Q335 equal to the tool diameter drills straight to depth
/// without a helix; smaller is the control's error. With a pre-drilled diameter Q342 the tool
/// widens the hole in several helices ([`unconfirmed::BORE_MILL_STEPOVER`]); without it a
/// nominal diameter of more than twice the tool diameter is refused (the manual: "As soon as
/// you enter a value greater than 0 in Q342, the control no longer checks the ratio between the
/// nominal and tool diameters").
#[inline(never)]
pub(super) fn bore_mill_208(p: &Params, pos: DVec3, r: f64) -> R<Vec<CycleMove>> {
    let hole = Hole::new(p, pos)?;
    let (f, pitch, nominal, predrilled) = (p.get(206)?, p.get(334)?, p.get(335)?, p.get(342)?);
    // Programs written for older software leave Q351 out (CAM output for DMC machines among
    // them): the PREDEF value, climb milling (`unconfirmed::predef`).
    let dir = if p.or(351, crate::unconfirmed::predef(351).unwrap_or(1.0)) < 0.0 { -1.0 } else { 1.0 };
    let total = depth(p)?;
    let tool = 2.0 * r;
    if nominal < tool - EPS {
        return Err(SimErrorCode::ToolTooLarge { cycle: 208, tool_diameter: tool, size: nominal });
    }
    if predrilled <= 0.0 && nominal > 2.0 * tool + EPS {
        return Err(SimErrorCode::ToolTooSmall { cycle: 208, tool_diameter: tool, size: nominal });
    }
    let mut out = vec![rapid(hole.safe())];
    if total == 0.0 {
        return Ok(out);
    }
    let radius = 0.5 * (nominal - tool);
    if radius <= EPS {
        out.push(feed(hole.below(total), f));
        out.push(rapid(hole.safe()));
        hole.finish(&mut out);
        return Ok(out);
    }
    let inner = if predrilled > 0.0 { (0.5 * (predrilled - tool)).clamp(0.0, radius) } else { 0.0 };
    let passes = if inner > 0.0 {
        (((radius - inner) / (unconfirmed::BORE_MILL_STEPOVER * r).max(EPS)).ceil() as usize).clamp(1, 1000)
    } else {
        1
    };
    let top = hole.surface + hole.clear;
    let bottom = hole.surface - total;
    for k in 1..=passes {
        let rho = inner + (radius - inner) * k as f64 / passes as f64;
        let c = hole.at;
        // The semicircle from the centre to the helix start (c + ρ on the reference axis).
        out.push(arc((c + DVec2::new(rho, 0.0)).extend(top), c + DVec2::new(0.5 * rho, 0.0), dir * PI, f));
        let turns = if pitch > 0.0 { (top - bottom) / pitch } else { 1.0 };
        let mut done = 0.0;
        while turns - done > EPS && out.len() < MAX_CYCLE_MOVES {
            let part = (turns - done).min(1.0);
            done += part;
            let z = if turns - done <= EPS { bottom } else { top - done * pitch };
            let angle = dir * TAU * done;
            out.push(arc((c + rho * DVec2::from_angle(angle)).extend(z), c, dir * TAU * part, f));
        }
        let end = out.last().map_or(c.extend(bottom), |m| m.target);
        out.push(arc(end, c, dir * TAU, f));
        out.push(feed(c.extend(bottom), f));
        out.push(rapid(c.extend(top)));
    }
    hole.finish(&mut out);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{params, path};
    use super::*;

    const F: Option<f64> = Some(150.0);
    const FMAX: Option<f64> = None;

    /// A stop on the Z axis of a hole at X0 Y0 and its feed (`FMAX`: `None`).
    fn at(z: f64, f: Option<f64>) -> (f64, f64, f64, Option<f64>) {
        (0.0, 0.0, z, f)
    }

    fn drilling(cycle: u32, extra: &[(u32, f64)]) -> Params {
        let mut p =
            params(cycle, &[(200, 2.0), (201, -20.0), (206, 150.0), (202, 5.0), (203, 0.0), (204, 50.0)]);
        for &(i, v) in extra {
            p.set(i, v);
        }
        p
    }

    #[test]
    fn cycle_200_pecks_and_returns_above_each_depth_reached() {
        // Manual 200: FMAX to 2 above the surface; 5 mm at F; FMAX to 2; FMAX to 2 above the
        // depth reached; … to −20; FMAX to 2; FMAX to the 2nd set-up clearance 50.
        let got = path(&drill_200(&drilling(200, &[]), DVec3::new(50.0, 40.0, 100.0)).expect("cycle"));
        let at = |z: f64, f| (50.0, 40.0, z, f);
        #[rustfmt::skip]
        let want = vec![
            at(2.0, FMAX),
            at(-5.0, F), at(2.0, FMAX), at(-3.0, FMAX),
            at(-10.0, F), at(2.0, FMAX), at(-8.0, FMAX),
            at(-15.0, F), at(2.0, FMAX), at(-13.0, FMAX),
            at(-20.0, F), at(2.0, FMAX), at(50.0, FMAX),
        ];
        assert_eq!(got, want);
    }

    #[test]
    fn a_positive_depth_is_refused_and_depth_zero_only_positions() {
        for cycle in [200, 201, 203, 205, 208] {
            let p = drilling(
                cycle,
                &[
                    (201, 5.0),
                    (208, 0.0),
                    (212, 0.0),
                    (213, 0.0),
                    (205, 0.0),
                    (256, 0.2),
                    (258, 0.2),
                    (259, 0.2),
                    (257, 0.0),
                    (334, 2.0),
                    (335, 10.0),
                    (342, 0.0),
                    (351, 1.0),
                ],
            );
            let err = super::super::run(&p, DVec3::ZERO, 4.0).err();
            assert_eq!(err, Some(SimErrorCode::DepthSign { cycle, value: 5.0 }), "{cycle}");
        }
        let p = drilling(200, &[(201, 0.0)]);
        assert_eq!(path(&drill_200(&p, DVec3::ZERO).expect("cycle")), vec![(0.0, 0.0, 2.0, FMAX)]);
    }

    #[test]
    fn cycle_201_reams_down_and_retracts_at_the_retraction_feed() {
        let p = drilling(201, &[(208, 300.0), (211, 0.5)]);
        let got = path(&ream_201(&p, DVec3::new(10.0, 20.0, 50.0)).expect("cycle"));
        let at = |z: f64, f| (10.0, 20.0, z, f);
        assert_eq!(got, vec![at(2.0, FMAX), at(-20.0, F), at(2.0, Some(300.0)), at(50.0, FMAX)]);
        // Q208 = 0: back at the reaming feed.
        let p = drilling(201, &[(208, 0.0), (204, 0.0)]);
        let got = path(&ream_201(&p, DVec3::new(10.0, 20.0, 50.0)).expect("cycle"));
        assert_eq!(got, vec![at(2.0, FMAX), at(-20.0, F), at(2.0, F)]);
    }

    #[test]
    fn cycle_203_decrements_breaks_chips_and_retracts_every_third_infeed() {
        // Q202 6, decrement 2, minimum 3: infeeds 6, 4, 3, 3, 3, 1 (the rest) to −20. Q213 = 2
        // chip breaks (retract 0.5 at Q208 500) before each full retraction to Q200 at Q208 and
        // FMAX back to 2 above the depth reached.
        let p = drilling(203, &[(202, 6.0), (212, 2.0), (213, 2.0), (205, 3.0), (208, 500.0), (256, 0.5)]);
        let got = path(&drill_203(&p, DVec3::new(0.0, 0.0, 20.0)).expect("cycle"));
        let back = Some(500.0);
        #[rustfmt::skip]
        let want = vec![
            at(2.0, FMAX),
            at(-6.0, F), at(-5.5, back),
            at(-10.0, F), at(-9.5, back),
            at(-13.0, F), at(2.0, back), at(-11.0, FMAX),
            at(-16.0, F), at(-15.5, back),
            at(-19.0, F), at(-18.5, back),
            at(-20.0, F), at(2.0, back), at(50.0, FMAX),
        ];
        assert_eq!(got, want);
    }

    #[test]
    fn cycle_205_chip_breaks_within_an_infeed_and_stops_short_by_the_advanced_stop_distance() {
        // Q202 10 (no decrement) to −20, chip breaking every 4 (retract 0.2 at Q208 1000); after
        // the first infeed to Q200 at Q208, FMAX to the advanced stop distance above −10:
        // Q258 1 + (Q259 3 − 1)·10/20 = 2.
        let p = drilling(
            205,
            &[
                (202, 10.0),
                (212, 0.0),
                (205, 0.0),
                (258, 1.0),
                (259, 3.0),
                (257, 4.0),
                (256, 0.2),
                (208, 1000.0),
            ],
        );
        let got = path(&peck_205(&p, DVec3::new(0.0, 0.0, 20.0)).expect("cycle"));
        let back = Some(1000.0);
        #[rustfmt::skip]
        let want = vec![
            at(2.0, FMAX),
            at(-4.0, F), at(-3.8, back), at(-8.0, F), at(-7.8, back), at(-10.0, F),
            at(2.0, back), at(-8.0, FMAX),
            at(-14.0, F), at(-13.8, back), at(-18.0, F), at(-17.8, back), at(-20.0, F),
            at(2.0, back), at(50.0, FMAX),
        ];
        assert_eq!(got, want);
        // A deepened starting point 6: at Q253 to 2 above it, the first infeed from there.
        let mut p = p.clone();
        p.set(379, 6.0);
        p.set(253, 750.0);
        p.set(257, 0.0);
        let got = path(&peck_205(&p, DVec3::new(0.0, 0.0, 20.0)).expect("cycle"));
        assert_eq!(&got[..3], &[at(2.0, FMAX), at(-4.0, Some(750.0)), at(-16.0, F)]);
    }

    #[test]
    fn cycle_205_of_older_software_without_q208_retracts_at_rapid() {
        // Q202 10 to −20 without chip breaking; Q208 not written: both retractions to Q200 at
        // the rapid feed of a cycle (`unconfirmed::CYCLE205_WITHOUT_Q208_FEED`, as `Q208=FMAX`),
        // the moves otherwise as with Q208.
        const RAPID_FEED: Option<f64> = Some(crate::unconfirmed::CYCLE205_WITHOUT_Q208_FEED);
        let p = drilling(
            205,
            &[(202, 10.0), (212, 0.0), (205, 0.0), (258, 1.0), (259, 1.0), (257, 0.0), (256, 0.2)],
        );
        let got = path(&peck_205(&p, DVec3::new(0.0, 0.0, 20.0)).expect("cycle"));
        #[rustfmt::skip]
        let want = vec![
            at(2.0, FMAX), at(-10.0, F), at(2.0, RAPID_FEED), at(-9.0, FMAX), at(-20.0, F), at(2.0, RAPID_FEED), at(50.0, FMAX),
        ];
        assert_eq!(got, want);
        let mut with = p.clone();
        with.set(208, 500.0);
        let slow = path(&peck_205(&with, DVec3::new(0.0, 0.0, 20.0)).expect("cycle"));
        assert_eq!(slow[2], at(2.0, Some(500.0)), "with Q208 its feed");
    }

    /// Cycle 208 from 2 above the surface to −5 at pitch 2, not pre-drilled, DR+ (Q351 = +1);
    /// each test sets the bore (Q335).
    const BORE_208: [(u32, f64); 8] =
        [(200, 2.0), (201, -5.0), (206, 150.0), (334, 2.0), (203, 0.0), (204, 20.0), (342, 0.0), (351, 1.0)];

    #[test]
    fn cycle_208_semicircle_helix_full_circle_and_back_to_the_centre() {
        // Tool Ø 10, bore Ø 16: helix radius 3 about (40, 30). From 2 above the surface down to
        // −5 with pitch 2: 3.5 turns; DR+ (Q351 = +1).
        let mut p = params(208, &BORE_208);
        p.set(335, 16.0);
        let moves = bore_mill_208(&p, DVec3::new(40.0, 30.0, 10.0), 5.0).expect("cycle");
        let got = path(&moves);
        let at = |x: f64, y: f64, z: f64, f| (x, y, z, f);
        #[rustfmt::skip]
        let want = vec![
            at(40.0, 30.0, 2.0, FMAX),
            at(43.0, 30.0, 2.0, F),
            at(43.0, 30.0, 0.0, F), at(43.0, 30.0, -2.0, F), at(43.0, 30.0, -4.0, F),
            at(37.0, 30.0, -5.0, F),
            at(37.0, 30.0, -5.0, F),
            at(40.0, 30.0, -5.0, F),
            at(40.0, 30.0, 2.0, FMAX),
            at(40.0, 30.0, 20.0, FMAX),
        ];
        assert_eq!(got, want);
        let sweeps: Vec<f64> = moves.iter().filter_map(|m| m.arc).map(|a| a.sweep / PI).collect();
        let r = |x: f64| (x * 1e9).round() / 1e9;
        assert_eq!(sweeps.into_iter().map(r).collect::<Vec<_>>(), vec![1.0, 2.0, 2.0, 2.0, 1.0, 2.0]);
        assert!(moves.iter().filter_map(|m| m.arc).skip(1).all(|a| a.centre == DVec2::new(40.0, 30.0)));
    }

    #[test]
    fn cycle_208_without_q351_mills_as_with_climb_milling() {
        // Programs for older software leave Q351 out: the helix runs as with Q351 = +1 (DR+).
        let bore = |list: &[(u32, f64)]| {
            let mut p = params(208, list);
            p.set(335, 16.0);
            bore_mill_208(&p, DVec3::new(40.0, 30.0, 10.0), 5.0).expect("cycle")
        };
        let without: Vec<(u32, f64)> = BORE_208.iter().copied().filter(|&(q, _)| q != 351).collect();
        assert_eq!(bore(&without), bore(&BORE_208));
        let up_cut: Vec<(u32, f64)> = without.iter().copied().chain([(351, -1.0)]).collect();
        assert_ne!(bore(&without), bore(&up_cut));
    }

    #[test]
    fn cycle_208_tool_size_against_the_bore() {
        let with = |d: f64, pre: f64| {
            let mut p = params(208, &BORE_208);
            p.set(351, -1.0);
            p.set(335, d);
            p.set(342, pre);
            bore_mill_208(&p, DVec3::ZERO, 5.0)
        };
        assert_eq!(
            with(9.0, 0.0),
            Err(SimErrorCode::ToolTooLarge { cycle: 208, tool_diameter: 10.0, size: 9.0 })
        );
        assert_eq!(
            with(21.0, 0.0),
            Err(SimErrorCode::ToolTooSmall { cycle: 208, tool_diameter: 10.0, size: 21.0 })
        );
        // Equal diameters: straight to depth, no helix.
        let got = path(&with(10.0, 0.0).expect("cycle"));
        assert_eq!(
            got,
            vec![(0.0, 0.0, 2.0, FMAX), (0.0, 0.0, -5.0, F), (0.0, 0.0, 2.0, FMAX), (0.0, 0.0, 20.0, FMAX)]
        );
        // Pre-drilled Ø 20, nominal Ø 40: helix radii from 5 to 15 in steps of at most the tool
        // radius: 10 and 15, each reached on a semicircle at 2 above the surface; DR− (Q351 = −1).
        let moves = with(40.0, 20.0).expect("cycle");
        let starts: Vec<f64> =
            moves.iter().filter(|m| m.arc.is_some() && m.target.z == 2.0).map(|m| m.target.x).collect();
        assert_eq!(starts, vec![10.0, 15.0]);
        assert!(moves.iter().filter_map(|m| m.arc).all(|a| a.sweep < 0.0));
    }
}
