//! Face milling: 232 PLANFRAESEN and 233 PLANFRAESEN (the newer cycle, simulated through the
//! path of 232).

use glam::DVec3;

use super::{CycleMove, CycleRun, MAX_CYCLE_MOVES, Params, feed, rapid};
use crate::sim::error::SimErrorCode;
use crate::sim::note::Note;
use crate::unconfirmed;

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
pub(super) fn face_mill_232(p: &Params, pos: DVec3, tool_radius: f64) -> Result<CycleRun, SimErrorCode> {
    let (x0, y0, z_top, z_end) = (p.get(225)?, p.get(226)?, p.get(227)?, p.get(386)?);
    let (l1, l2, cut) = (p.get(218)?, p.get(219)?, p.get(202)?);
    let allowance = p.get(369)?.max(0.0);
    let k = p.get(370)?;
    let (f_mill, f_finish, f_pre) = (p.get(207)?, p.get(385)?, p.get(253)?);
    let (clear, side, clear2) = (p.get(200)?, p.get(357)?, p.get(204)?);

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
    let strategy = p.or(389, 0.0);
    let note = (strategy != 0.0 && unconfirmed::CYCLE232_STRATEGY)
        .then_some(Note::FaceStrategy { cycle: p.cycle, strategy });
    for (n, &(z, f)) in levels.iter().enumerate() {
        if n > 0 {
            out.push(rapid(DVec3::new(last_x(&out), last_y(&out), z_top + clear)));
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
                return Ok(CycleRun { moves: out, note });
            }
        }
    }
    out.push(rapid(DVec3::new(last_x(&out), last_y(&out), z2)));
    Ok(CycleRun { moves: out, note })
}

/// Cycle 233 PLANFRAESEN: the face Q218 × Q219 placed by Q367 relative to the tool position
/// (0 = the tool is at its centre, 1…4 = at its lower left, lower right, upper right, upper left
/// corner, as in cycle 251), from Q227 down to Q386, rows along the reference axis (Q350 = 1) or
/// the minor axis (Q350 = 2). Simulated through cycle 232's meander with the same parameters
/// Q202, Q369, Q370, Q207, Q385, Q253, Q357, Q200, Q204 ([`unconfirmed::CYCLE233_AS_232`]): the
/// side limits Q347–Q349 and the strategies Q389 are not simulated.
#[inline(never)]
pub(super) fn face_mill_233(p: &Params, pos: DVec3, tool_radius: f64) -> Result<CycleRun, SimErrorCode> {
    let (l1, l2) = (p.get(218)?, p.get(219)?);
    let (h1, h2) = (0.5 * l1, 0.5 * l2);
    let centre_offset = match p.or(367, 0.0) as i64 {
        1 => (h1, h2),
        2 => (-h1, h2),
        3 => (-h1, -h2),
        4 => (h1, -h2),
        _ => (0.0, 0.0),
    };
    let (cx, cy) = (pos.x + centre_offset.0, pos.y + centre_offset.1);
    let across = p.or(350, 1.0) == 2.0;
    let mut q = p.clone();
    // 232's start point is the lower left corner; along the minor axis the rows run in Y, so
    // the rectangle is milled with X and Y exchanged and exchanged back.
    let swap = |v: DVec3| if across { DVec3::new(v.y, v.x, v.z) } else { v };
    let (corner, sides) =
        if across { ((cy - h2, cx - h1), (l2, l1)) } else { ((cx - h1, cy - h2), (l1, l2)) };
    q.set(225, corner.0);
    q.set(226, corner.1);
    q.set(218, sides.0);
    q.set(219, sides.1);
    let mut run = face_mill_232(&q, swap(pos), tool_radius)?;
    for m in &mut run.moves {
        m.target = swap(m.target);
    }
    let limits = [347, 348, 349].iter().any(|&i| p.or(i, 0.0) != 0.0);
    if (limits || p.or(389, 0.0) != 0.0) && unconfirmed::CYCLE233_AS_232 {
        run.note = Some(Note::Cycle233AsMeander);
    }
    Ok(run)
}

fn last_x(out: &[CycleMove]) -> f64 {
    out.last().map_or(0.0, |m| m.target.x)
}

fn last_y(out: &[CycleMove]) -> f64 {
    out.last().map_or(0.0, |m| m.target.y)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::params;
    use super::*;

    fn p232() -> Params {
        params(
            232,
            &[
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
            ],
        )
    }

    #[test]
    fn face_milling_covers_the_rectangle_at_each_depth() {
        let moves = face_mill_232(&p232(), DVec3::new(0.0, 0.0, 100.0), 25.0).expect("cycle").moves;
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

    #[test]
    fn face_233_around_the_tool_position_along_either_axis() {
        // Q367 = 0: the face 110 × 100 centred on the tool at (50, 50): X from −5 to 105, Y from
        // 0 to 100, as the 232 above; rows along X (Q350 = 1) end beside the face at x = −5 − 27
        // and 105 + 27; along Y (Q350 = 2) at y = 0 − 27 and 100 + 27.
        let mut p = p232();
        p.cycle = 233;
        let along_x = face_mill_233(&p, DVec3::new(50.0, 50.0, 100.0), 25.0).expect("cycle").moves;
        let cuts = |m: &[CycleMove]| -> Vec<DVec3> {
            m.iter().filter(|m| m.feed == Some(500.0)).map(|m| m.target).collect()
        };
        assert!(cuts(&along_x).iter().all(|v| (v.x + 32.0).abs() < 1e-9 || (v.x - 132.0).abs() < 1e-9));
        p.set(350, 2.0);
        let along_y = face_mill_233(&p, DVec3::new(50.0, 50.0, 100.0), 25.0).expect("cycle").moves;
        assert!(cuts(&along_y).iter().all(|v| (v.y + 27.0).abs() < 1e-9 || (v.y - 127.0).abs() < 1e-9));
        let xs: Vec<f64> = cuts(&along_y).iter().map(|v| v.x).collect();
        let (lo, hi) = xs.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        assert!((lo + 5.0).abs() < 1e-9 && (hi - 105.0).abs() < 1e-9, "{lo} {hi}");
    }
}
