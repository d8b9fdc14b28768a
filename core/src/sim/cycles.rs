//! The machining cycles the simulator moves: 200 (drilling) and 232 (face milling), as tool
//! paths in the I-CS (the tool axis is the I-CS Z axis, so they run in the tilted plane).
//! Other cycles are reported as not simulated by the caller.

use glam::DVec3;

use crate::unconfirmed;

use super::error::SimErrorCode;

/// One move of a cycle: I-CS target and feed (`None` = FMAX).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CycleMove {
    pub target: DVec3,
    pub feed: Option<f64>,
}

/// Upper bound of moves one cycle call may produce (a tiny stepover must not exhaust memory).
pub(crate) const MAX_CYCLE_MOVES: usize = 100_000;

fn rapid(target: DVec3) -> CycleMove {
    CycleMove { target, feed: None }
}

fn feed(target: DVec3, f: f64) -> CycleMove {
    CycleMove { target, feed: Some(f) }
}

/// Cycle 200 BOHREN at the current position `pos` (I-CS). Parameters: Q200 set-up clearance,
/// Q201 depth (negative), Q206 plunge feed, Q202 plunge depth per peck, Q203 surface coordinate,
/// Q204 2nd set-up clearance (Q210/Q211 dwell times do not move an axis).
///
/// Sequence (HEIDENHAIN cycle 200 description, DOMAIN.md §8 for the parameter names): FMAX in
/// the tool axis to Q203+Q200; per peck: feed Q206 down by Q202 (the last peck to Q203+Q201),
/// FMAX back to Q203+Q200 and FMAX down to Q200 above the depth reached; at the bottom FMAX to
/// Q203+Q200, then FMAX to Q203+Q204 if that is higher.
pub(crate) fn drill_200(
    q: &dyn Fn(u32) -> Result<f64, SimErrorCode>,
    pos: DVec3,
) -> Result<Vec<CycleMove>, SimErrorCode> {
    let (clear, depth, f, peck, surface, clear2) = (q(200)?, q(201)?, q(206)?, q(202)?, q(203)?, q(204)?);
    if depth > 0.0 && unconfirmed::CYCLE_POSITIVE_DEPTH_IS_ERROR {
        return Err(SimErrorCode::DepthSign { value: depth });
    }
    let total = depth.abs();
    let at = |z: f64| DVec3::new(pos.x, pos.y, z);
    let safe = surface + clear;
    let mut out = vec![rapid(at(safe))];
    if total == 0.0 {
        // HEIDENHAIN: depth 0 → the cycle is not executed; only the pre-position remains.
        return Ok(out);
    }
    let step = if peck > 0.0 && peck < total { peck } else { total };
    let mut reached = 0.0_f64;
    while reached < total && out.len() < MAX_CYCLE_MOVES {
        if reached > 0.0 {
            out.push(rapid(at(safe)));
            out.push(rapid(at(surface - reached + clear)));
        }
        reached = (reached + step).min(total);
        out.push(feed(at(surface - reached), f));
    }
    out.push(rapid(at(safe)));
    if clear2 > clear {
        out.push(rapid(at(surface + clear2)));
    }
    Ok(out)
}

/// Cycle 232 PLANFRAESEN, strategy Q389 = 0 (meander), over the rectangle Q225/Q226 (start in
/// the 1st/2nd axis), Q218/Q219 (side lengths), from Q227 (start in the 3rd axis) down to Q386
/// (end in the 3rd axis) in cuts of at most Q202, leaving Q369 for a finishing cut at Q385.
/// Q207 milling feed, Q253 pre-positioning feed, Q200 set-up clearance, Q357 lateral clearance,
/// Q204 2nd set-up clearance, Q370 max. stepover factor ([`unconfirmed::cycle232_stepover`]).
///
/// Sequence (HEIDENHAIN cycle 232 description): to the start point beside the surface (offset by
/// tool radius + Q357) at FMAX, first in the plane when above the 2nd set-up clearance, else
/// first up to it; down at Q253; per depth meander rows at Q207 with the stepover at Q253; FMAX
/// up to Q200 and back to the start point for the next depth; finally FMAX to Q227 + Q204.
/// Other strategies (Q389 = 1, 2) are simulated as meanders too ([`unconfirmed::CYCLE232_STRATEGY`]).
pub(crate) fn face_mill_232(
    q: &dyn Fn(u32) -> Result<f64, SimErrorCode>,
    pos: DVec3,
    tool_radius: f64,
) -> Result<Vec<CycleMove>, SimErrorCode> {
    let (x0, y0, z_top, z_end) = (q(225)?, q(226)?, q(227)?, q(386)?);
    let (l1, l2, cut) = (q(218)?, q(219)?, q(202)?);
    let allowance = q(369)?.max(0.0);
    let k = q(370)?;
    let (f_mill, f_finish, f_pre) = (q(207)?, q(385)?, q(253)?);
    let (clear, side, clear2) = (q(200)?, q(357)?, q(204)?);

    let r = tool_radius.max(0.0);
    let x_a = x0 - r - side;
    let x_b = x0 + l1 + r + side;
    let z2 = z_top + clear2;
    let stepover = unconfirmed::cycle232_stepover(k, r);
    let rows = if l2.abs() <= f64::EPSILON || stepover <= 0.0 {
        1
    } else {
        ((l2.abs() / stepover).ceil() as usize).clamp(1, MAX_CYCLE_MOVES) + 1
    };
    let dy = if rows > 1 { l2 / (rows - 1) as f64 } else { 0.0 };

    // Depth levels: roughing down to z_end + allowance, then a finishing level at z_end.
    let rough_floor = z_end + allowance;
    let mut levels: Vec<(f64, f64)> = Vec::new();
    let per = if cut > 0.0 { cut } else { (z_top - rough_floor).abs().max(f64::MIN_POSITIVE) };
    let mut z = z_top;
    while z - rough_floor > 1e-9 && levels.len() < MAX_CYCLE_MOVES {
        z = (z - per).max(rough_floor);
        levels.push((z, f_mill));
    }
    if levels.is_empty() {
        levels.push((rough_floor, f_mill));
    }
    if allowance > 0.0 {
        levels.push((z_end, f_finish));
    }

    let mut out = Vec::new();
    let start = |z: f64| DVec3::new(x_a, y0, z);
    if pos.z >= z2 {
        out.push(rapid(DVec3::new(x_a, y0, pos.z)));
        out.push(rapid(start(z2)));
    } else {
        out.push(rapid(DVec3::new(pos.x, pos.y, z2)));
        out.push(rapid(start(z2)));
    }
    out.push(feed(start(z_top + clear), f_pre));
    for (n, &(z, f)) in levels.iter().enumerate() {
        if n > 0 {
            out.push(rapid(DVec3::new(out_last_x(&out), out_last_y(&out), z_top + clear)));
            out.push(rapid(start(z_top + clear)));
        }
        out.push(feed(start(z), f_pre));
        let mut x_here = x_a;
        for i in 0..rows {
            let y = y0 + dy * i as f64;
            if i > 0 {
                out.push(feed(DVec3::new(x_here, y, z), f_pre));
            }
            x_here = if x_here == x_a { x_b } else { x_a };
            out.push(feed(DVec3::new(x_here, y, z), f));
            if out.len() >= MAX_CYCLE_MOVES {
                return Ok(out);
            }
        }
    }
    out.push(rapid(DVec3::new(out_last_x(&out), out_last_y(&out), z2)));
    Ok(out)
}

fn out_last_x(out: &[CycleMove]) -> f64 {
    out.last().map_or(0.0, |m| m.target.x)
}

fn out_last_y(out: &[CycleMove]) -> f64 {
    out.last().map_or(0.0, |m| m.target.y)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(list: &'static [(u32, f64)]) -> impl Fn(u32) -> Result<f64, SimErrorCode> {
        move |i| {
            list.iter()
                .find(|(k, _)| *k == i)
                .map(|(_, v)| *v)
                .ok_or(SimErrorCode::CycleParamMissing { cycle: 0, param: i })
        }
    }

    #[test]
    fn drilling_pecks_to_depth_and_back() {
        let q = params(&[(200, 2.0), (201, -20.0), (206, 150.0), (202, 5.0), (203, 0.0), (204, 50.0)]);
        let moves = drill_200(&q, DVec3::new(50.0, 50.0, 0.0)).expect("cycle");
        let feeds: Vec<f64> = moves.iter().filter(|m| m.feed.is_some()).map(|m| m.target.z).collect();
        assert_eq!(feeds, vec![-5.0, -10.0, -15.0, -20.0]);
        let last = moves.last().expect("moves").target;
        assert!((last - DVec3::new(50.0, 50.0, 50.0)).length() < 1e-12);
        assert!(moves.iter().all(|m| (m.target.x - 50.0).abs() < 1e-12 && (m.target.y - 50.0).abs() < 1e-12));
    }

    #[test]
    fn positive_depth_is_refused() {
        let q = params(&[(200, 2.0), (201, 5.0), (206, 150.0), (202, 5.0), (203, 0.0), (204, 50.0)]);
        assert_eq!(drill_200(&q, DVec3::ZERO), Err(SimErrorCode::DepthSign { value: 5.0 }));
    }

    #[test]
    fn face_milling_covers_the_rectangle_at_each_depth() {
        let q = params(&[
            (225, -5.0),
            (226, 0.0),
            (227, 2.0),
            (386, 0.0),
            (218, 110.0),
            (219, 100.0),
            (202, 1.0),
            (369, 0.0),
            (370, 0.7),
            (207, 500.0),
            (385, 500.0),
            (253, 750.0),
            (200, 2.0),
            (357, 2.0),
            (204, 50.0),
        ]);
        let moves = face_mill_232(&q, DVec3::new(0.0, 0.0, 100.0), 25.0).expect("cycle");
        let cut_levels: std::collections::BTreeSet<i64> = moves
            .iter()
            .filter(|m| m.feed == Some(500.0))
            .map(|m| (m.target.z * 1000.0).round() as i64)
            .collect();
        assert_eq!(cut_levels.into_iter().collect::<Vec<_>>(), vec![0, 1000]);
        let ys: Vec<f64> = moves.iter().filter(|m| m.feed == Some(500.0)).map(|m| m.target.y).collect();
        let (ymin, ymax) = ys.iter().fold((f64::MAX, f64::MIN), |(a, b), &y| (a.min(y), b.max(y)));
        assert!(ymin.abs() < 1e-9 && (ymax - 100.0).abs() < 1e-9, "{ymin} {ymax}");
        let xs: Vec<f64> = moves.iter().filter(|m| m.feed == Some(500.0)).map(|m| m.target.x).collect();
        assert!(xs.iter().any(|&x| (x - (-5.0 - 27.0)).abs() < 1e-9));
        assert!(xs.iter().any(|&x| (x - (105.0 + 27.0)).abs() < 1e-9));
        assert!((moves.last().expect("moves").target.z - 52.0).abs() < 1e-12);
    }
}
