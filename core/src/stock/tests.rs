use glam::DVec3;
use schwenkbar_testkit::assert_close;

use super::*;
use crate::sim::tools::ToolShape;

fn blank(min: [f64; 3], max: [f64; 3]) -> Blank {
    Blank { min: DVec3::from_array(min), max: DVec3::from_array(max) }
}

#[test]
fn a_new_stock_is_the_blank() {
    let s = Stock::new(&blank([0.0, 0.0, -40.0], [100.0, 100.0, 0.0]), 0.25).expect("stock");
    assert_eq!(s.cells(), [400, 400, 160]);
    assert_close!(s.volume(), 400_000.0, 1e-6);
    assert_eq!(s.spans(2, 3, 4), &[Span { lo: -40.0, hi: 0.0 }]);
    assert!(s.memory_bytes() < 16 << 20, "{}", s.memory_bytes());
}

#[test]
fn a_huge_blank_gets_a_coarser_resolution_not_an_oom() {
    let s = Stock::new(&blank([0.0; 3], [1e6, 1e6, 1e6]), 0.25).expect("stock");
    let n = s.cells();
    assert!(n[0] * n[1] + n[1] * n[2] + n[2] * n[0] <= MAX_RAYS);
    assert!(s.resolution() > 1000.0);
    assert_eq!(Stock::new(&blank([0.0; 3], [f64::INFINITY, 1.0, 1.0]), 0.25), Err(StockError::InvalidBlank));
    assert_eq!(Stock::new(&blank([0.0; 3], [1.0, 1.0, 0.0]), 0.25), Err(StockError::InvalidBlank));
    assert!(Stock::new(&blank([0.0; 3], [1.0, 1.0, 1.0]), f64::NAN).is_ok());
}

#[test]
fn a_plunge_removes_a_cylinder() {
    let mut s = Stock::new(&blank([-10.0, -10.0, -20.0], [10.0, 10.0, 0.0]), 0.1).expect("stock");
    let tool = Cutter::new(ToolShape::Flat, 4.0, 50.0, 0.025);
    let r = s.cut(&tool, DVec3::Z, DVec3::new(0.0, 0.0, 5.0), DVec3::new(0.0, 0.0, -10.0));
    let exact = std::f64::consts::PI * 16.0 * 10.0;
    assert!((r.volume - exact).abs() < 0.01 * exact, "{} vs {exact}", r.volume);
    assert_close!(8000.0 - s.volume(), r.volume, 1e-6);
    // The Z ray through the axis now starts at the hole's floor.
    let (i, j) = (100, 100);
    assert_close!(s.ray_position(2, i, j).0, 0.05, 1e-12);
    assert_close!(s.spans(2, i, j)[0].hi, -10.0, 1e-9);
    // Cutting the same again removes nothing.
    let again = s.cut(&tool, DVec3::Z, DVec3::new(0.0, 0.0, 5.0), DVec3::new(0.0, 0.0, -10.0));
    assert!(again.depth < 1e-9, "{}", again.depth);
}

#[test]
fn mesh_of_the_blank_is_six_merged_faces_and_stl_has_them() {
    let s = Stock::new(&blank([0.0; 3], [4.0, 3.0, 2.0]), 1.0).expect("stock");
    let m = StockMesh::of(&s);
    // Per grid, one strip per row and side: rows 3 (X rays over Y·Z rows of Z) …
    assert!(m.flags.iter().all(|f| f & mesh::flag::CUT == 0));
    let area: f64 = m
        .positions
        .chunks_exact(3)
        .map(|t| {
            let p = t
                .iter()
                .map(|v| DVec3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2])))
                .collect::<Vec<_>>();
            0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length()
        })
        .sum();
    assert_close!(area, 2.0 * (12.0 + 6.0 + 8.0), 1e-6);
    let stl = m.to_stl();
    assert_eq!(stl.len(), 84 + 50 * m.triangles());
}

/// A standing tool inside a box removes its own volume, whatever its orientation: flat
/// πR²L; ball πR²(L − R) + ⅔πR³; drill πR²(L − h) + ⅓πR²h with h = R / tan(φ/2); bull nose
/// πR²(L − rc) + π(R − rc)²rc + the revolved quarter disc of the corner, 2π(R − rc + 4rc/3π)·πrc²/4
/// (Pappus's centroid theorem).
#[test]
fn a_tool_standing_in_the_block_removes_its_own_volume_in_any_orientation() {
    use std::f64::consts::PI;
    let (r, l, rc) = (4.0, 12.0, 1.5);
    let h = r / (59f64.to_radians()).tan();
    let cases = [
        (ToolShape::Flat, PI * r * r * l),
        (ToolShape::Ball, PI * r * r * (l - r) + 2.0 / 3.0 * PI * r * r * r),
        (ToolShape::Drill { point_angle: 118.0 }, PI * r * r * (l - h) + PI * r * r * h / 3.0),
        (
            ToolShape::Bull { corner_radius: rc },
            PI * r * r * (l - rc)
                + PI * (r - rc).powi(2) * rc
                + 2.0 * PI * (r - rc + 4.0 * rc / (3.0 * PI)) * PI * rc * rc / 4.0,
        ),
    ];
    let axes = [DVec3::Z, DVec3::new(1.0, 2.0, 3.0).normalize(), DVec3::new(-1.0, 0.3, -0.2).normalize()];
    for (shape, exact) in cases {
        for axis in axes {
            let mut s = Stock::new(&blank([-20.0; 3], [20.0; 3]), 0.2).expect("stock");
            let tool = Cutter::new(shape, r, l, 0.05);
            let tip = -0.5 * l * axis;
            let removed = s.cut(&tool, axis, tip, tip).volume;
            assert!((removed - exact).abs() < 0.01 * exact, "{shape:?} along {axis}: {removed} vs {exact}");
        }
    }
}

/// A long tool whose shank leaves the block (the cut visits only the rays of the part of the tool
/// that can reach the stock's box): along each axis, in both directions, the volume removed is
/// the cylinder's part inside, π r² × the distance from the tip to the face. Tilted and moving,
/// every ray of the small block holds what the same ray of a block three times as large (which
/// the tool never leaves) holds inside the small one.
#[test]
fn a_tool_leaving_the_block_cuts_only_its_part_inside() {
    use std::f64::consts::PI;
    let r = 3.0;
    for k in 0..3 {
        for sign in [1.0, -1.0] {
            let mut axis = DVec3::ZERO;
            axis[k] = sign;
            let mut s = Stock::new(&blank([-20.0; 3], [20.0; 3]), 0.2).expect("stock");
            let tool = Cutter::new(ToolShape::Flat, r, 100.0, 0.05);
            let tip = 8.0 * axis;
            let removed = s.cut(&tool, axis, tip, tip).volume;
            let exact = PI * r * r * 12.0;
            assert!((removed - exact).abs() < 0.01 * exact, "along {axis}: {removed} vs {exact}");
        }
    }
    let h = 0.4;
    // Rays of both blocks coincide: 40 mm is 100 ray spacings.
    let offset = (40.0 / h) as usize;
    for axis in [DVec3::new(1.0, 0.2, 0.1), DVec3::new(-0.3, 1.0, 2.0), DVec3::new(0.4, -0.4, -1.0)] {
        let axis = axis.normalize();
        let (p0, p1) = (DVec3::new(-5.0, 3.0, 1.0), DVec3::new(7.0, -2.0, 4.0));
        let cut = |half: f64| {
            let mut s = Stock::new(&blank([-half; 3], [half; 3]), h).expect("stock");
            s.cut(&Cutter::new(ToolShape::Ball, r, 45.0, 0.05), axis, p0, p1);
            s
        };
        let (small, large) = (cut(20.0), cut(60.0));
        assert_eq!((small.resolution(), large.resolution()), (h, h));
        let n = small.cells();
        for d in 0..3 {
            let (a, b) = others(d);
            for j in 0..n[b] {
                for i in 0..n[a] {
                    let inside: Vec<_> = large
                        .spans(d, i + offset, j + offset)
                        .iter()
                        .map(|s| (s.lo.max(-20.0), s.hi.min(20.0)))
                        .filter(|(lo, hi)| hi > lo)
                        .collect();
                    let own: Vec<_> = small.spans(d, i, j).iter().map(|s| (s.lo, s.hi)).collect();
                    assert_eq!(own.len(), inside.len(), "{axis} ray {d} {i} {j}: {own:?} vs {inside:?}");
                    for (x, y) in own.iter().zip(&inside) {
                        assert!(
                            (x.0 - y.0).abs() < 1e-9 && (x.1 - y.1).abs() < 1e-9,
                            "{own:?} vs {inside:?}"
                        );
                    }
                }
            }
        }
    }
}

/// The first material along a ray (the depth under the pointer): worked by hand on a block with
/// a Ø8 hole 20 deep at (50, 50). Straight down the hole its floor Z−20 (the Z rays hold it
/// exactly), beside it the top face; slanting into the hole's mouth the wall, where the line
/// (50, 44 + s, 6 − s) meets y = 54 (s = 10: Z−4), to a ray spacing; a ray that passes above
/// or misses the block meets nothing.
#[test]
fn the_first_material_along_a_ray_is_the_floor_the_face_or_the_wall() {
    let mut s = Stock::new(&blank([0.0, 0.0, -40.0], [100.0, 100.0, 0.0]), 0.25).expect("stock");
    let tool = Cutter::new(ToolShape::Flat, 4.0, 50.0, 0.025);
    s.cut(&tool, DVec3::Z, DVec3::new(50.0, 50.0, 5.0), DVec3::new(50.0, 50.0, -20.0));
    let down = DVec3::NEG_Z;
    let floor = s.first_material(DVec3::new(50.0, 50.0, 100.0), down).expect("floor");
    assert_close!(floor.z, -20.0, 1e-6);
    let face = s.first_material(DVec3::new(20.0, 30.0, 100.0), down).expect("face");
    assert_close!(face.z, 0.0, 1e-6);
    assert_close!(face, DVec3::new(20.0, 30.0, 0.0), 1e-6);
    let wall = s.first_material(DVec3::new(50.0, 44.0, 6.0), DVec3::new(0.0, 1.0, -1.0)).expect("wall");
    assert!((wall - DVec3::new(50.0, 54.0, -4.0)).length() < 0.25 * 2f64.sqrt(), "{wall}");
    assert_eq!(s.first_material(DVec3::new(50.0, 50.0, 100.0), DVec3::X), None);
    assert_eq!(s.first_material(DVec3::new(-10.0, 50.0, -10.0), DVec3::NEG_X), None);
    assert_eq!(s.first_material(DVec3::new(50.0, 50.0, 100.0), DVec3::ZERO), None);
    // Past the blank's side along X is no material (not the next row's ray).
    assert!(!s.material_at(DVec3::new(100.1, 50.0, -1.0)));
    assert!(s.material_at(DVec3::new(99.9, 50.0, -1.0)));
}

/// A ray of one span cut without the scratch list gives what the general cut gives the same
/// span held as a list (the second method): the length removed and the pieces left, for a cut
/// missing it, touching it, inside it, over either end, over all of it and leaving a sliver
/// shorter than `MIN_SPAN`.
#[test]
fn a_one_span_ray_is_cut_as_the_general_cut_cuts_it() {
    let span = Span { lo: -10.0, hi: 5.0 };
    let mut scratch = Vec::new();
    for (lo, hi) in [
        (6.0, 8.0),
        (5.0, 8.0),
        (-12.0, -10.0),
        (-2.0, 1.0),
        (-12.0, 0.0),
        (0.0, 9.0),
        (-11.0, 6.0),
        (-10.0 + 5e-8, 5.0 - 5e-8),
        (-10.0, 5.0),
    ] {
        let (mut one, mut many) = (Dexel::One(span), Dexel::Many(vec![span]));
        let (a, b) = (one.subtract(lo, hi, &mut scratch), many.subtract(lo, hi, &mut scratch));
        assert_eq!(a, b, "removed by [{lo}, {hi}]");
        assert_eq!(one.spans(), many.spans(), "left by [{lo}, {hi}]");
    }
}
