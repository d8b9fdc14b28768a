//! Machining positions: the items of `PATTERN DEF` (for `CYCL CALL PAT`) and the patterns of
//! cycles 220 MUSTER KREIS and 221 MUSTER LINIEN, in the working plane of the I-CS.
//!
//! Sources: the HEIDENHAIN user manual's "PATTERN DEF" section (POS, ROW, PAT, FRAME, CIRC,
//! PITCHCIRC and their words) and the cycle manual's cycles 220 and 221. Angles in degrees from
//! the reference axis, positive counter-clockwise.

use glam::DVec2;

use super::{MAX_CYCLE_MOVES, Params, polar, turned};
use crate::ast::PatternKind;
use crate::sim::error::SimErrorCode;
use crate::unconfirmed;

/// The evaluated words of one `PATTERN DEF` item (a word not written is 0, a count 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PatternValues {
    pub kind: PatternKind,
    pub x: f64,
    pub y: f64,
    /// The surface coordinate: acts in addition to the cycle's Q203 (manual: "If you define a
    /// workpiece surface in Z not equal to 0, this value is effective in addition to the
    /// workpiece surface Q203 that you defined in the machining cycle").
    pub z: f64,
    pub d: f64,
    pub dx: f64,
    pub dy: f64,
    pub num: f64,
    pub numx: f64,
    pub numy: f64,
    pub rot: f64,
    pub rotx: f64,
    pub roty: f64,
    pub start: f64,
    pub step: f64,
}

/// A count word as a number of points (negative or not a number: none).
fn count(n: f64) -> usize {
    if n.is_finite() && n >= 1.0 { (n.round() as usize).min(MAX_CYCLE_MOVES) } else { 0 }
}

/// The points of a grid: `cols` along `e1` spaced `d1`, `rows` along `e2` spaced `d2`, from
/// `origin`, row by row, every other row backwards (cycle 221's order; `PATTERN DEF` PAT and
/// FRAME by [`unconfirmed::PATTERN_GRID_ORDER`]). `edge_only`: the frame's points.
fn grid(
    origin: DVec2,
    e1: DVec2,
    e2: DVec2,
    (d1, d2): (f64, f64),
    (cols, rows): (usize, usize),
    edge_only: bool,
) -> Vec<DVec2> {
    let mut out = Vec::new();
    let rows = rows.min(MAX_CYCLE_MOVES / cols.max(1));
    for j in 0..rows {
        for k in 0..cols {
            let i = if j % 2 == 1 && unconfirmed::PATTERN_GRID_ORDER { cols - 1 - k } else { k };
            let edge = i == 0 || j == 0 || i + 1 == cols || j + 1 == rows;
            if edge || !edge_only {
                out.push(origin + e1 * (d1 * i as f64) + e2 * (d2 * j as f64));
            }
        }
    }
    out
}

/// The machining positions of one `PATTERN DEF` item, each with its surface shift Z.
///
/// POS: the point. ROW: NUM points from X/Y spaced D along the reference axis turned by ROT
/// about the starting point. PAT: NUMX × NUMY points spaced DX, DY; ROT turns the whole pattern
/// about the starting point, ROTX only the reference axis and ROTY only the minor axis (which
/// shears the grid). FRAME: the points of PAT on its edges. CIRC: NUM points evenly on the
/// full circle of diameter D about X/Y from the angle START. PITCHCIRC: NUM points from START,
/// STEP degrees apart.
pub(crate) fn pattern_points(v: &PatternValues) -> Vec<(DVec2, f64)> {
    let o = DVec2::new(v.x, v.y);
    let points = match v.kind {
        PatternKind::Pos => vec![o],
        PatternKind::Row => {
            let e = polar(v.rot);
            (0..count(v.num)).map(|k| o + e * (v.d * k as f64)).collect()
        }
        PatternKind::Pat | PatternKind::Frame => grid(
            o,
            polar(v.rot + v.rotx),
            polar(v.rot + v.roty + 90.0),
            (v.dx, v.dy),
            (count(v.numx), count(v.numy)),
            v.kind == PatternKind::Frame,
        ),
        PatternKind::Circ => {
            let n = count(v.num);
            (0..n).map(|k| o + 0.5 * v.d * polar(v.start + 360.0 * k as f64 / n as f64)).collect()
        }
        PatternKind::PitchCirc => {
            (0..count(v.num)).map(|k| o + 0.5 * v.d * polar(v.start + v.step * k as f64)).collect()
        }
    };
    points.into_iter().map(|p| (p, v.z)).collect()
}

/// Cycle 220 MUSTER KREIS: the points on the circle of diameter Q244 about Q216/Q217 from the
/// starting angle Q245, Q247 apart (Q247 = 0: from Q245 to the stopping angle Q246,
/// [`unconfirmed::cycle220_step`]), Q241 of them. Also returns the centre and the stepping angle
/// for the moves along the circle (Q365 = 1).
pub(crate) fn circle_220(p: &Params) -> Result<(Vec<DVec2>, DVec2, f64), SimErrorCode> {
    let centre = DVec2::new(p.get(216)?, p.get(217)?);
    let (d, start, stop, step, n) = (p.get(244)?, p.get(245)?, p.get(246)?, p.get(247)?, count(p.get(241)?));
    let step = if step != 0.0 { step } else { unconfirmed::cycle220_step(start, stop, n) };
    let points = (0..n).map(|k| centre + 0.5 * d * polar(start + step * k as f64)).collect();
    Ok((points, centre, step))
}

/// Cycle 221 MUSTER LINIEN: Q242 columns Q237 apart along the reference axis and Q243 lines
/// Q238 apart, from Q225/Q226, turned by Q224 about the starting point; line by line, every
/// other line backwards ("All subsequent lines are processed in a reciprocating movement").
pub(crate) fn grid_221(p: &Params) -> Result<Vec<DVec2>, SimErrorCode> {
    let o = DVec2::new(p.get(225)?, p.get(226)?);
    let rot = p.get(224)?;
    let e1 = turned(DVec2::X, rot);
    let e2 = turned(DVec2::Y, rot);
    let mut out = Vec::new();
    let (cols, rows) = (count(p.get(242)?), count(p.get(243)?));
    let (d1, d2) = (p.get(237)?, p.get(238)?);
    let rows = rows.min(MAX_CYCLE_MOVES / cols.max(1));
    for j in 0..rows {
        for k in 0..cols {
            let i = if j % 2 == 1 { cols - 1 - k } else { k };
            out.push(o + e1 * (d1 * i as f64) + e2 * (d2 * j as f64));
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::params;
    use super::*;

    fn close(a: &[DVec2], b: &[DVec2]) {
        assert_eq!(a.len(), b.len(), "{a:?} vs {b:?}");
        for (p, q) in a.iter().zip(b) {
            assert!((*p - *q).length() < 1e-9, "{a:?} vs {b:?}");
        }
    }

    fn item(kind: PatternKind) -> PatternValues {
        PatternValues {
            kind,
            x: 10.0,
            y: 20.0,
            z: 0.0,
            d: 0.0,
            dx: 0.0,
            dy: 0.0,
            num: 1.0,
            numx: 1.0,
            numy: 1.0,
            rot: 0.0,
            rotx: 0.0,
            roty: 0.0,
            start: 0.0,
            step: 0.0,
        }
    }

    fn xy(v: Vec<(DVec2, f64)>) -> Vec<DVec2> {
        v.into_iter().map(|(p, _)| p).collect()
    }

    #[test]
    fn circle_points_are_at_equal_angle_steps_from_start() {
        // CIRC1 (X+10 Y+20 D80 START+45 NUM8 Z−2): 10 + 40 cos(45° + k·45°), 20 + 40 sin(…).
        let v = PatternValues { d: 80.0, start: 45.0, num: 8.0, z: -2.0, ..item(PatternKind::Circ) };
        let got = pattern_points(&v);
        assert!(got.iter().all(|(_, z)| *z == -2.0));
        let want: Vec<DVec2> = (0..8)
            .map(|k| {
                let a = (45.0 + 45.0 * k as f64).to_radians();
                DVec2::new(10.0 + 40.0 * a.cos(), 20.0 + 40.0 * a.sin())
            })
            .collect();
        close(&xy(got), &want);
        // PITCHCIRC1 (… START+90 STEP−30 NUM3): 90°, 60°, 30°.
        let v = PatternValues { d: 80.0, start: 90.0, step: -30.0, num: 3.0, ..item(PatternKind::PitchCirc) };
        let want: Vec<DVec2> = [90.0f64, 60.0, 30.0]
            .iter()
            .map(|a| DVec2::new(10.0 + 40.0 * a.to_radians().cos(), 20.0 + 40.0 * a.to_radians().sin()))
            .collect();
        close(&xy(pattern_points(&v)), &want);
    }

    #[test]
    fn rows_grids_and_frames() {
        // ROW1 (X+10 Y+20 D+8 NUM3 ROT+90): up the Y axis.
        let v = PatternValues { d: 8.0, num: 3.0, rot: 90.0, ..item(PatternKind::Row) };
        close(
            &xy(pattern_points(&v)),
            &[DVec2::new(10.0, 20.0), DVec2::new(10.0, 28.0), DVec2::new(10.0, 36.0)],
        );
        // PAT1 3 × 2, DX 5, DY 4: the first row forwards, the second backwards.
        let v = PatternValues { dx: 5.0, dy: 4.0, numx: 3.0, numy: 2.0, ..item(PatternKind::Pat) };
        let p = |x: f64, y: f64| DVec2::new(x, y);
        close(
            &xy(pattern_points(&v)),
            &[p(10.0, 20.0), p(15.0, 20.0), p(20.0, 20.0), p(20.0, 24.0), p(15.0, 24.0), p(10.0, 24.0)],
        );
        // ROTY+45 shears: the second row moves along (−sin 45°, cos 45°)·4.
        let v = PatternValues { roty: 45.0, ..v };
        let s = 4.0 * std::f64::consts::FRAC_1_SQRT_2;
        assert!((xy(pattern_points(&v))[3] - p(20.0 - s, 20.0 + s)).length() < 1e-9);
        // FRAME1 3 × 3: the 8 edge points, the centre (15, 24) left out.
        let v = PatternValues { dx: 5.0, dy: 4.0, numx: 3.0, numy: 3.0, ..item(PatternKind::Frame) };
        let got = xy(pattern_points(&v));
        assert_eq!(got.len(), 8);
        assert!(got.iter().all(|q| (*q - p(15.0, 24.0)).length() > 1.0));
        // A negative count is no point.
        assert!(pattern_points(&PatternValues { num: -2.0, ..item(PatternKind::Row) }).is_empty());
    }

    #[test]
    fn cycle_220_full_circle_and_arc_and_cycle_221_meander() {
        let circle = |start: f64, stop: f64, step: f64, n: f64| {
            params(
                220,
                &[(216, 0.0), (217, 0.0), (244, 20.0), (245, start), (246, stop), (247, step), (241, n)],
            )
        };
        let on = |deg: f64| 10.0 * polar(deg);
        // Q247 = 0, 0°…360°, 4 points: 90° apart.
        let (pts, _, step) = circle_220(&circle(0.0, 360.0, 0.0, 4.0)).expect("pattern");
        close(&pts, &[on(0.0), on(90.0), on(180.0), on(270.0)]);
        assert_eq!(step, 90.0);
        // 0°…90°, 4 points: both ends included, 30° apart.
        let (pts, _, _) = circle_220(&circle(0.0, 90.0, 0.0, 4.0)).expect("pattern");
        close(&pts, &[on(0.0), on(30.0), on(60.0), on(90.0)]);
        // An explicit stepping angle wins over the stopping angle.
        let (pts, _, _) = circle_220(&circle(10.0, 90.0, -20.0, 2.0)).expect("pattern");
        close(&pts, &[on(10.0), on(-10.0)]);
        // 221: 3 columns 10 apart, 2 lines 5 apart, from (1, 2); the second line backwards.
        let p = params(
            221,
            &[(225, 1.0), (226, 2.0), (237, 10.0), (238, 5.0), (242, 3.0), (243, 2.0), (224, 0.0)],
        );
        let q = |x: f64, y: f64| DVec2::new(x, y);
        close(
            &grid_221(&p).expect("pattern"),
            &[q(1.0, 2.0), q(11.0, 2.0), q(21.0, 2.0), q(21.0, 7.0), q(11.0, 7.0), q(1.0, 7.0)],
        );
    }
}
