//! The sweeps against closed forms worked by hand and against the general enumeration.

use super::*;
use schwenkbar_testkit::{Rng, assert_close};

const Z: [DVec3; 3] = [DVec3::X, DVec3::Y, DVec3::Z];

#[test]
fn standing_cylinder_against_rays_along_each_axis() {
    let c = Cutter::new(ToolShape::Flat, 5.0, 50.0, 0.01);
    let p = DVec3::new(10.0, 0.0, 0.0);
    // Along Z through the axis: the tool's length.
    let (a, b) = c.ray_interval(&Z, p, p, DVec3::new(10.0, 0.0, 0.0), DVec3::Z).expect("hit");
    assert_close!(a, 0.0, 1e-9);
    assert_close!(b, 50.0, 1e-9);
    // Along X at height 1, 3 off the axis: chord 2·√(25 − 9) = 8.
    let (a, b) = c.ray_interval(&Z, p, p, DVec3::new(0.0, 3.0, 1.0), DVec3::X).expect("hit");
    assert_close!(a, 6.0, 1e-9);
    assert_close!(b, 14.0, 1e-9);
    assert!(c.ray_interval(&Z, p, p, DVec3::new(0.0, 6.0, 1.0), DVec3::X).is_none());
    assert!(c.ray_interval(&Z, p, p, DVec3::new(0.0, 0.0, -1.0), DVec3::X).is_none());
}

#[test]
fn moving_cylinder_sweeps_a_slot_with_round_ends() {
    let c = Cutter::new(ToolShape::Flat, 5.0, 50.0, 0.01);
    let (p0, p1) = (DVec3::ZERO, DVec3::new(20.0, 0.0, 0.0));
    let (a, b) = c.ray_interval(&Z, p0, p1, DVec3::new(0.0, 4.0, 1.0), DVec3::X).expect("hit");
    assert_close!(a, -3.0, 1e-9);
    assert_close!(b, 23.0, 1e-9);
    // Across the slot: its width.
    let (a, b) = c.ray_interval(&Z, p0, p1, DVec3::new(7.0, 0.0, 1.0), DVec3::Y).expect("hit");
    assert_close!(a, -5.0, 1e-9);
    assert_close!(b, 5.0, 1e-9);
    // Plunge along the axis: the tool plus the travel.
    let down = DVec3::new(0.0, 0.0, -10.0);
    let (a, b) = c.ray_interval(&Z, p0, down, DVec3::new(1.0, 1.0, 0.0), DVec3::Z).expect("hit");
    assert_close!(a, -10.0, 1e-9);
    assert_close!(b, 50.0, 1e-9);
}

#[test]
fn ball_and_drill_tips() {
    let ball = Cutter::new(ToolShape::Ball, 5.0, 50.0, 0.01);
    // Ray along Z 3 off the axis: the sphere's bottom at 5 − √(25 − 9) = 1.
    let (a, _) =
        ball.ray_interval(&Z, DVec3::ZERO, DVec3::ZERO, DVec3::new(3.0, 0.0, 0.0), DVec3::Z).expect("hit");
    assert_close!(a, 1.0, 1e-9);
    let drill = Cutter::new(ToolShape::Drill { point_angle: 90.0 }, 4.0, 50.0, 0.01);
    // 90° point: the cone rises 1 per 1 of radius.
    let (a, _) =
        drill.ray_interval(&Z, DVec3::ZERO, DVec3::ZERO, DVec3::new(3.0, 0.0, 0.0), DVec3::Z).expect("hit");
    assert_close!(a, 3.0, 1e-9);
    // A tilted drill moving laterally: the far end of a ray along its axis line is the top.
    let t = DVec3::new(1.0, 0.0, 1.0).normalize();
    let f = frame_of(t);
    let (a, b) = drill.ray_interval(&f, DVec3::ZERO, DVec3::Y, DVec3::ZERO, t).expect("hit");
    assert_close!(a, 0.0, 1e-9);
    assert_close!(b, 50.0, 1e-9);
}

#[test]
fn bull_nose_profile_stays_within_the_tolerance() {
    let tol = 0.01;
    let c = Cutter::new(ToolShape::Bull { corner_radius: 2.0 }, 5.0, 30.0, tol);
    // Rays from the corner arc's centre (r = 3, z = 2) outward through the arc: each leaves
    // the tool between the arc (2 away) and the inscribed chords (the sagitta less).
    let centre = DVec3::new(3.0, 0.0, 2.0);
    for i in 0..=50 {
        let th = std::f64::consts::FRAC_PI_2 * f64::from(i) / 50.0;
        let dir = DVec3::new(th.sin(), 0.0, -th.cos());
        let (_, b) = c.ray_interval(&Z, DVec3::ZERO, DVec3::ZERO, centre, dir).expect("hit");
        assert!(b <= 2.0 + 1e-9 && b >= 2.0 - tol - 1e-9, "angle {th}: {b}");
    }
    // The flat bottom inside the corner.
    let (a, _) =
        c.ray_interval(&Z, DVec3::ZERO, DVec3::ZERO, DVec3::new(1.0, 1.0, -5.0), DVec3::Z).expect("hit");
    assert_close!(a, 5.0, 1e-9);
}

/// One tool of each shape (the bull nose at a quarter of a 0.25 mm resolution).
fn every_shape() -> [Cutter; 4] {
    [
        Cutter::new(ToolShape::Flat, 5.0, 40.0, 0.01),
        Cutter::new(ToolShape::Ball, 5.0, 40.0, 0.01),
        Cutter::new(ToolShape::Drill { point_angle: 118.0 }, 4.0, 40.0, 0.01),
        Cutter::new(ToolShape::Bull { corner_radius: 2.0 }, 6.0, 40.0, 0.0625),
    ]
}

/// A closed form agrees with the general enumeration; a line that only grazes may be met by
/// one and not the other, in an interval of no length. Whether both met it.
fn agree(fast: Option<(f64, f64)>, general: Option<(f64, f64)>, case: &str) -> bool {
    match (fast, general) {
        (Some((a, b)), Some((x, y))) => {
            assert!((a - x).abs() < 1e-6 && (b - y).abs() < 1e-6, "{case}: {a} {b} vs {x} {y}");
            true
        }
        (None, None) => false,
        (Some((a, b)), None) | (None, Some((a, b))) => {
            assert!(b - a < 1e-5, "{case}: {a} {b}");
            false
        }
    }
}

/// A uniform number in `[lo, hi)`.
fn uniform(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

fn vector(rng: &mut Rng, size: f64) -> DVec3 {
    DVec3::new(uniform(rng, -size, size), uniform(rng, -size, size), uniform(rng, -size, size))
}

/// The ball's capsule against the general enumeration of the module doc (a second method)
/// on random lines and moves.
#[test]
fn a_swept_ball_in_closed_form_agrees_with_the_general_enumeration() {
    let mut rng = Rng(0x5EED_BA11);
    let mut hits = 0;
    for _ in 0..20_000 {
        let (c, r) = (uniform(&mut rng, 0.5, 8.0), uniform(&mut rng, 0.5, 8.0));
        let piece = Piece::ball(c, r);
        let o = vector(&mut rng, 12.0);
        let u = vector(&mut rng, 1.0).normalize_or(DVec3::X);
        let w = if rng.below(4) == 0 { DVec3::ZERO } else { vector(&mut rng, 10.0) };
        let case = format!("{o} {u} {w}");
        hits += usize::from(agree(
            PieceRays::new(&piece, u, w).swept_ball(o).expect("a ball"),
            piece_interval(&piece, o, u, w),
            &case,
        ));
    }
    assert!(hits > 3_000, "{hits}");
}

/// In the plane the disc's sweep with its root worked out once agrees with the capsule's
/// general quadratic (the same lines, the third components 0).
#[test]
fn a_flat_capsule_agrees_with_the_general_one() {
    let mut rng = Rng(0xF1A7_CA95);
    let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
    let mut hits = 0;
    for _ in 0..20_000 {
        let o = flat(vector(&mut rng, 12.0));
        let u = flat(vector(&mut rng, 1.0)).normalize_or(DVec3::X);
        let size = if rng.below(2) == 0 { 0.05 } else { 8.0 };
        let m = flat(vector(&mut rng, size));
        let r = uniform(&mut rng, 0.5, 6.0);
        let case = format!("{o} {u} {m} {r}");
        hits +=
            usize::from(agree(Capsule::flat(u, m, r).interval(o), Capsule::new(u, m, r).interval(o), &case));
    }
    assert!(hits > 3_000, "{hits}");
}

/// A cylinder's sweep away from its ends (the 2D capsule) against the general enumeration.
#[test]
fn a_swept_cylinder_away_from_its_ends_agrees_with_the_general_enumeration() {
    let mut rng = Rng(0xC7_11DE);
    let piece = Piece::frustum(5.0, 0.0, 2.0, 40.0);
    let mut decided = 0;
    for _ in 0..20_000 {
        let o = vector(&mut rng, 12.0) + DVec3::new(0.0, 0.0, 20.0);
        let u = match rng.below(3) {
            0 => DVec3::new(uniform(&mut rng, -1.0, 1.0), uniform(&mut rng, -1.0, 1.0), 0.0)
                .normalize_or(DVec3::X),
            _ => vector(&mut rng, 1.0).normalize_or(DVec3::Z),
        };
        let w = vector(&mut rng, 6.0);
        let all = |_: (f64, f64)| true;
        let Some(fast) =
            PieceRays::new(&piece, u, w).swept_cylinder(o, (f64::NEG_INFINITY, f64::INFINITY), all, None)
        else {
            continue;
        };
        decided += 1;
        agree(fast, piece_interval(&piece, o, u, w), &format!("{o} {u} {w}"));
    }
    assert!(decided > 10_000, "{decided}");
    // A ball or a cone is left to the enumeration.
    let any = (f64::NEG_INFINITY, f64::INFINITY);
    assert_eq!(
        PieceRays::new(&Piece::ball(5.0, 5.0), DVec3::X, DVec3::Y).swept_cylinder(
            DVec3::ZERO,
            any,
            |_| true,
            None
        ),
        None
    );
    let cone = Piece::frustum(0.0, 1.0, 0.0, 4.0);
    assert_eq!(
        PieceRays::new(&cone, DVec3::X, DVec3::Y).swept_cylinder(DVec3::ZERO, any, |_| true, None),
        None
    );
}

/// Each piece's cheap bound holds its exact interval.
#[test]
fn a_pieces_bound_holds_its_sweep() {
    let mut rng = Rng(0xB0_u64 << 32 | 0x0D);
    let tools = every_shape();
    let mut checked = 0;
    for _ in 0..20_000 {
        let tool = &tools[rng.index(tools.len())];
        let piece = tool.pieces[rng.index(tool.pieces.len())];
        let o = vector(&mut rng, 12.0) + DVec3::new(0.0, 0.0, 10.0);
        // Some lines along the axis or square to it, as the grids' rays of an upright tool.
        let u = match rng.below(4) {
            0 => DVec3::Z * if rng.below(2) == 0 { 1.0 } else { -1.0 },
            1 => DVec3::new(uniform(&mut rng, -1.0, 1.0), uniform(&mut rng, -1.0, 1.0), 0.0)
                .normalize_or(DVec3::X),
            _ => vector(&mut rng, 1.0).normalize_or(DVec3::Z),
        };
        let w = vector(&mut rng, 10.0);
        if let Some((a, b)) = piece_interval(&piece, o, u, w) {
            checked += 1;
            let rays = PieceRays::new(&piece, u, w);
            let bound = rays.slab(o).and_then(|s| rays.radial(o, s));
            let (lo, hi) = bound.expect("a bound where the sweep is met");
            assert!(lo <= a + 1e-9 && b <= hi + 1e-9, "{piece:?} {o} {u} {w}: [{a}, {b}] ⊄ [{lo}, {hi}]");
        }
    }
    assert!(checked > 2_000, "{checked}");
}

/// A random tool of `tools` moving with a random frame, upright as often as tilted (the grids'
/// rays then run along or square to the axis), short moves as CAM output has them as often as
/// long ones, and a ray along a grid axis: (tool, frame, p0, p1, ray direction, ray origin).
fn random_sweep<'t>(
    rng: &mut Rng,
    tools: &'t [Cutter],
) -> (&'t Cutter, [DVec3; 3], DVec3, DVec3, DVec3, DVec3) {
    let tool = &tools[rng.index(tools.len())];
    let frame = if rng.below(2) == 0 { Z } else { frame_of(vector(rng, 1.0) + DVec3::new(0.0, 0.0, 1.5)) };
    let p0 = vector(rng, 10.0);
    let size = if rng.below(2) == 0 { 0.05 } else { 6.0 };
    let p1 = p0 + vector(rng, size);
    let dir = [DVec3::X, DVec3::Y, DVec3::Z][rng.index(3)];
    (tool, frame, p0, p1, dir, vector(rng, 12.0))
}

/// Cutting a ray with the pieces that can reach its material removes exactly what cutting it
/// with the whole sweep removes, for every tool shape, tilted, on random rays and material.
#[test]
fn skipping_pieces_without_material_removes_the_same_material() {
    use super::super::{Dexel, Span};
    let mut rng = Rng(0xD3_7E15);
    let tools = every_shape();
    let mut removed = 0;
    for _ in 0..20_000 {
        let (tool, frame, p0, p1, dir, r0) = random_sweep(&mut rng, &tools);
        // One to three spans along the ray.
        let mut ends: Vec<f64> =
            (0..2 * (1 + rng.index(3))).map(|_| uniform(&mut rng, -30.0, 50.0)).collect();
        ends.sort_by(f64::total_cmp);
        let spans: Vec<Span> = ends.chunks(2).map(|e| Span { lo: e[0], hi: e[1] }).collect();
        let cut = |interval: Option<(f64, f64)>| {
            let mut dexel = Dexel::Many(spans.clone());
            if let Some((a, b)) = interval {
                dexel.subtract(a, b, &mut Vec::new());
            }
            dexel
        };
        let whole = cut(tool.ray_interval(&frame, p0, p1, r0, dir));
        let skipped = cut(tool.sweep(frame, p0, p1).rays(dir).material_interval(r0, &spans));
        // The same spans; an end may differ in roundoff, a piece's end found by another of
        // the equivalent methods (a closed form or the enumeration).
        let same = whole.spans().len() == skipped.spans().len()
            && whole
                .spans()
                .iter()
                .zip(skipped.spans())
                .all(|(a, b)| (a.lo - b.lo).abs() < 1e-9 && (a.hi - b.hi).abs() < 1e-9);
        assert!(same, "{frame:?} {p0} {p1} {r0} {dir}: {:?} vs {:?}", whole.spans(), skipped.spans());
        removed += usize::from(whole.spans() != spans.as_slice());
    }
    assert!(removed > 2_000, "{removed}");
}

/// The whole sweep's interval on a line, with every shortcut (closed forms, ends that the
/// pieces before hold), against the general enumeration of every piece joined (a second
/// method), for every tool shape, upright and tilted, on random moves and lines.
#[test]
fn a_sweeps_interval_agrees_with_every_piece_enumerated() {
    let mut rng = Rng(0x5EE9_0A11);
    let tools = every_shape();
    let mut hits = 0;
    for _ in 0..20_000 {
        let (tool, frame, p0, p1, dir, r0) = random_sweep(&mut rng, &tools);
        let local = |v: DVec3| DVec3::new(frame[0].dot(v), frame[1].dot(v), frame[2].dot(v));
        let (o, u, w) = (local(r0 - p0), local(dir), -local(p1 - p0));
        let general = tool
            .pieces
            .iter()
            .filter_map(|p| piece_interval(p, o, u, w))
            .reduce(|(a, b), (c, d)| (a.min(c), b.max(d)));
        let case = format!("{frame:?} {p0} {p1} {r0} {dir}");
        hits += usize::from(agree(tool.ray_interval(&frame, p0, p1, r0, dir), general, &case));
    }
    assert!(hits > 3_000, "{hits}");
}

#[test]
fn nothing_for_a_tool_without_size() {
    let c = Cutter::new(ToolShape::Flat, 0.0, 50.0, 0.01);
    assert!(c.ray_interval(&Z, DVec3::ZERO, DVec3::X, DVec3::ZERO, DVec3::X).is_none());
    let c = Cutter::new(ToolShape::Flat, f64::NAN, 50.0, 0.01);
    assert!(c.pieces.is_empty());
}
