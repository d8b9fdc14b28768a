//! What a cut removes, against closed forms worked by hand: drills, face mills and ball noses
//! square and tilted to the part, a pocket cycle, CAM output in tiny moves.

use super::*;

/// Centroid (x, y) of the hole's cross-section at height `z`: the gaps between the spans of the
/// X rays at that height, weighted by their length.
fn hole_centre(stock: &Stock, z: f64, near: DVec3) -> DVec3 {
    let n = stock.cells();
    let (mut w, mut sx, mut sy) = (0.0, 0.0, 0.0);
    // X rays: grid 0, indexed (y, z).
    let k = ((z - stock.bounds().0.z) / stock.spacing().z) as usize;
    for i in 0..n[1] {
        let (y, _) = stock.ray_position(0, i, k);
        if (y - near.y).abs() > 10.0 {
            continue;
        }
        for pair in stock.spans(0, i, k).windows(2) {
            let (g0, g1) = (pair[0].hi, pair[1].lo);
            if (0.5 * (g0 + g1) - near.x).abs() < 10.0 {
                let len = g1 - g0;
                w += len;
                sx += len * 0.5 * (g0 + g1);
                sy += len * y;
            }
        }
    }
    assert!(w > 0.0, "no hole at z {z}");
    DVec3::new(sx / w, sy / w, stock.ray_position(0, 0, k).1)
}

#[test]
fn drill_square_to_a_plane_tilted_spb15() {
    let src = format!(
        "{BLANK}TOOL CALL 8 Z S4000 F150\nL Z+0 R0 FMAX M91\nPLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n\
         L X+50 Y+50 Z+20 R0 FMAX\nL Z-20 F150\nL Z+20 FMAX\nM30\n"
    );
    let (_, _, c) = run(&src, StockOptions::default());
    // The hole: axis t through P = R·(50, 50, 0) (the I-CS point in the W-CS); the tip at
    // P − 20·t; the top face z = 0 meets the axis at s₀ = −P.z / t.z above P. The volume below
    // an oblique plane cut of a cylinder is π r² × its length on the axis (the plane does not
    // reach the point), and the 118° point is a cone of height r / tan 59°.
    let t = tilt();
    let p = 50.0 * DVec3::new(t.z, 0.0, -t.x) + DVec3::new(0.0, 50.0, 0.0);
    let s0 = -p.z / t.z;
    let (r, h) = (4.0, 4.0 / 59f64.to_radians().tan());
    let pi = std::f64::consts::PI;
    let exact = pi * r * r * (s0 + 20.0 - h) + pi * r * r * h / 3.0;
    within_one_percent(removed(&c), exact);

    // The hole's axis on the stock: centroids of two cross-sections.
    let stock = c.final_stock().expect("stock");
    let (z1, z2) = (-3.0, -25.0);
    let c1 = hole_centre(&stock, z1, p + t * ((z1 - p.z) / t.z));
    let c2 = hole_centre(&stock, z2, p + t * ((z2 - p.z) / t.z));
    let measured = (c1 - c2).normalize();
    let angle = measured.angle_between(t).to_degrees();
    assert!(angle < 0.1, "hole axis {measured} vs tool axis {t}: {angle}°");
    assert!(c.notes.is_empty(), "{:?}", c.notes);
}

#[test]
fn face_mill_pass_over_the_tilted_plane_is_a_prism() {
    let src = face_mill_15();
    let (_, _, c) = run(&src, StockOptions::default());
    // Removed: the blank above z' = −2 (x·sin15 + z·cos15 ≥ −2) within |y − 50| ≤ 25; for each
    // x the depth below z = 0 is (2 + x·sin15)/cos15 (< 40 on the blank), so the volume is
    // 50 · ∫₀¹⁰⁰ (2 + x·sin15)/cos15 dx.
    let (s, co) = (15f64.to_radians().sin(), 15f64.to_radians().cos());
    let exact = 50.0 * (200.0 + 5000.0 * s) / co;
    within_one_percent(removed(&c), exact);
}

/// Two passes of the face mill (tool 16, R 25) 2 mm deep over the whole 100 × 100 blank, then
/// an Ø10 hole 10 deep in the middle: the material left is the box from Z−40 to Z−2 (exact along Z: the
/// Z rays end where the face mill left them), 20,000 mm³ removed by the face mill plus the hole.
#[test]
fn the_box_around_the_material_left_and_the_volume_removed() {
    let blank = Blank { min: DVec3::new(0.0, 0.0, -40.0), max: DVec3::new(100.0, 100.0, 0.0) };
    let untouched = Stock::new(&blank, 0.25).expect("stock");
    assert_eq!(untouched.material_bounds(), Some(untouched.bounds()));
    let src = format!(
        "{BLANK}TOOL CALL 16 Z S5000 F500\nL X-40 Y+25 Z+50 R0 FMAX\nL Z-2 F500\nL X+140\nL Y+75\nL X-40\n\
         L Z+50 FMAX\nTOOL CALL 1 Z S3000\nL X+50 Y+50 Z+10 R0 FMAX\nL Z-12 F200\nL Z+10 FMAX\nM30\n"
    );
    let (_, _, c) = run(&src, StockOptions::default());
    let stock = c.final_stock().expect("stock");
    let (lo, hi) = stock.material_bounds().expect("material left");
    let close = |a: DVec3, b: DVec3| (a - b).abs().max_element() < 1e-9;
    assert!(close(lo, DVec3::new(0.0, 0.0, -40.0)), "{lo}");
    assert!(close(hi, DVec3::new(100.0, 100.0, -2.0)), "{hi}");
    // Tool 1 (flat, R 5): a hole 10 deep below the milled face.
    let hole = std::f64::consts::PI * 25.0 * 10.0;
    within_one_percent(removed(&c), 20_000.0 + hole);
}

#[test]
fn ball_nose_slot() {
    let src = format!(
        "{BLANK}TOOL CALL 12 Z S4000 F500\nL X-10 Y+50 Z+10 R0 FMAX\nL Z-8 F500\nL X+110\nL Z+10 FMAX\nM30\n"
    );
    let (_, _, c) = run(&src, StockOptions::default());
    // Cross-section: the half disc of the ball (R = 5) under a 10 × 3 rectangle of the shank
    // (8 deep), along the 100 mm blank.
    let exact = 100.0 * (std::f64::consts::PI * 25.0 / 2.0 + 10.0 * 3.0);
    within_one_percent(removed(&c), exact);
}

#[test]
fn tilted_ball_nose_plunge_into_the_tilted_face() {
    // A plunge along the tool axis into the face milled in the same plane (a flat pass first):
    // the cylinder above the ball's centre, plus the half sphere.
    let src = format!(
        "{BLANK}TOOL CALL 16 Z S5000 F500\nL Z+0 R0 FMAX M91\nPLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n\
         L X-40 Y+50 Z+50 R0 FMAX\nL Z-2 F500\nL X+140\nL Z+50 FMAX\n\
         TOOL CALL 12 Z S4000 F500\nL X+50 Y+50 Z+20 R0 FMAX\nL Z-12 F100\nL Z+20 FMAX\nM30\n"
    );
    let (_, _, with_ball) = run(&src, StockOptions::default());
    let face = 50.0 * (200.0 + 5000.0 * 15f64.to_radians().sin()) / 15f64.to_radians().cos();
    // Ball nose R 5 plunged 10 below the face z' = −2 (to z' = −12): half sphere + cylinder 5.
    let pi = std::f64::consts::PI;
    let exact = face + 2.0 / 3.0 * pi * 125.0 + pi * 25.0 * 5.0;
    within_one_percent(removed(&with_ball), exact);
}

#[test]
fn musterprogramm_face_is_inclined_15_degrees_and_the_hole_is_at_the_point() {
    let (_, sim, c) = run(&musterprogramm(), StockOptions::default());
    let step = sim.step_of_block(13).expect("block 13 ran");
    let stock = c.stock_at(step).expect("stock");
    // Least squares z = a·x + b·y + e over the cut top ends of the Z rays.
    let n = stock.cells();
    let mut m = [[0.0f64; 3]; 3];
    let mut v = [0.0f64; 3];
    let mut count = 0usize;
    for j in 0..n[1] {
        for i in 0..n[0] {
            // Z rays: grid 2, indexed (i over X, j over Y).
            let (x, y) = stock.ray_position(2, i, j);
            let Some(top) = stock.spans(2, i, j).last() else { continue };
            if top.hi > -0.01 {
                continue;
            }
            let row = [x, y, 1.0];
            for r in 0..3 {
                for k in 0..3 {
                    m[r][k] += row[r] * row[k];
                }
                v[r] += row[r] * top.hi;
            }
            count += 1;
        }
    }
    assert!(count > 100_000, "{count} cut ends");
    let sol = solve3(m, v);
    let slope = (sol[0] * sol[0] + sol[1] * sol[1]).sqrt().atan().to_degrees();
    assert!((slope - 15.0).abs() < 0.1, "face inclined by {slope}°");
    assert!(sol[0] < 0.0, "falls toward +X: {sol:?}");

    // Block 28: the hole at I-CS (50, 50, 0) of the tilted plane, 20 deep along the tool axis.
    let step = sim.step_of_block(28).expect("block 28 ran");
    let stock = c.stock_at(step).expect("stock");
    let t = tilt();
    let p = 50.0 * DVec3::new(t.z, 0.0, -t.x) + DVec3::new(0.0, 50.0, 0.0);
    for s in [1.0, 5.0, 10.0, 17.0] {
        assert!(!stock.material_at(p - s * t), "no hole {s} below the point");
        assert!(stock.material_at(p - s * t + DVec3::new(0.0, 6.0, 0.0)), "wall beside the hole");
    }
    assert!(stock.material_at(p - 21.0 * t), "the hole ends");
    assert!(c.notes.is_empty(), "{:?}", c.notes);
}

fn solve3(m: [[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    let a = glam::DMat3::from_cols_array_2d(&m).transpose();
    (a.inverse() * DVec3::from_array(v)).to_array()
}

#[test]
fn pocket_251_removes_its_volume() {
    // Cycle 251 with roughing and finishing (Q215 = 0, allowances 0.2 side and 0.1 floor), 40 × 30
    // with corner radius 8, 6 deep, turned by Q224 = 20° in a plane turned by SPC+30, about
    // (50, 50): the finished pocket is the rounded rectangle × depth,
    // V = 6 · (40 · 30 − (4 − π) · 8²), the flat end mill of tool 1 (radius 5 < 8).
    let src = format!(
        "{BLANK}TOOL CALL 1 Z S6000 F800\nL Z+0 R0 FMAX M91\nTRANS DATUM AXIS X+50 Y+50 Z+0\n\
         PLANE SPATIAL SPA+0 SPB+0 SPC+30 TURN FMAX\n\
         CYCL DEF 251 RECHTECKTASCHE ~\n  Q215=+0 ~\n  Q218=+40 ~\n  Q219=+30 ~\n  Q220=+8 ~\n  Q368=+0.2 ~\n  Q224=+20 ~\n  Q367=+0 ~\n  Q207=+500 ~\n  Q351=+1 ~\n  Q201=-6 ~\n  Q202=+2.5 ~\n  Q369=+0.1 ~\n  Q206=+150 ~\n  Q338=+0 ~\n  Q200=+2 ~\n  Q203=+0 ~\n  Q204=+20 ~\n  Q370=+1 ~\n  Q366=+1 ~\n  Q385=+300\n\
         L X+0 Y+0 Z+30 R0 FMAX M99\nPLANE RESET TURN FMAX\nM30\n"
    );
    let (_, _, c) = run(&src, StockOptions::default());
    let exact = 6.0 * (40.0 * 30.0 - (4.0 - std::f64::consts::PI) * 64.0);
    within_one_percent(removed(&c), exact);
    assert!(c.notes.is_empty(), "{:?}", c.notes);
}

/// Issue 32 item 4: CAM output moves a few hundredths of a millimetre per block; consecutive cuts
/// on one short straight line are cut as one sweep (`plan.rs`, `MERGE_LENGTH`). A flat Ø10 mill
/// going round a circle of radius 20 at 4 mm depth in 0.03 mm moves (4 decimals, as a post
/// writes them) cuts the annulus 15 ≤ ρ ≤ 25 (closed form): every Z ray's top and every X ray's
/// span ends at z = −2 lie where the annulus says, within 5 µm (the merge's 1/64 of the
/// resolution, the moves' rounding and their sagitta). Planning in shares merges the same cuts.
#[test]
fn tiny_cam_moves_cut_the_closed_form_groove_however_they_are_planned() {
    let (centre, rp, r, depth) = (50.0, 20.0, 5.0, 4.0);
    let n = (std::f64::consts::TAU * rp / 0.03).round() as usize;
    let mut src = format!(
        "{BLANK}TOOL CALL 1 Z S4000 F500\nL X+{:.4} Y+{centre:.4} Z+10 R0 FMAX\nL Z-{depth} F500\n",
        centre + rp
    );
    for k in 1..=n {
        let a = std::f64::consts::TAU * k as f64 / n as f64;
        src.push_str(&format!("L X{:+.4} Y{:+.4}\n", centre + rp * a.cos(), centre + rp * a.sin()));
    }
    src.push_str("L Z+10 FMAX\nM30\n");
    let options = StockOptions { resolution: 0.25, checkpoints: 2 };
    let (program, sim, whole) = run(&src, options);
    let stock = whole.final_stock().expect("stock");
    let tol = 0.005;
    let rho = |x: f64, y: f64| (x - centre).hypot(y - centre);
    let [nx, ny, nz] = stock.cells();
    let mut checked = 0;
    for j in 0..ny {
        for i in 0..nx {
            let (x, y) = stock.ray_position(2, i, j);
            let top = stock.spans(2, i, j).last().map_or(f64::NAN, |s| s.hi);
            let d = rho(x, y);
            if d > rp - r + tol && d < rp + r - tol {
                assert!(
                    (top + depth).abs() < 1e-9,
                    "Z ray at ({x}, {y}), ρ = {d}: top {top}, floor −{depth}"
                );
            } else if d < rp - r - tol || d > rp + r + tol {
                assert!(top.abs() < 1e-9, "Z ray at ({x}, {y}), ρ = {d}: top {top}, uncut 0");
            }
        }
    }
    // X rays at z = −2: every span end inside the blank lies on ρ = 15 or ρ = 25.
    let k = (0..nz).min_by(|&a, &b| {
        let z = |k: usize| (stock.ray_position(0, 0, k).1 + 2.0).abs();
        z(a).total_cmp(&z(b))
    });
    let k = k.expect("rows");
    for j in 0..ny {
        let (y, _) = stock.ray_position(0, j, k);
        for s in stock.spans(0, j, k) {
            for x in [s.lo, s.hi].into_iter().filter(|x| *x > 1e-9 && *x < 100.0 - 1e-9) {
                let off = (rho(x, y) - (rp - r)).abs().min((rho(x, y) - (rp + r)).abs());
                assert!(off < tol, "X ray y = {y}: span end x = {x} is {off} mm off the annulus");
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked} span ends on the groove's walls");
    // Planned in shares (the browser's way), the same cuts merge: the same stock at the end and
    // halfway round.
    let mut parts = Cutting::unplanned(options);
    while !parts.plan_on(&program, &sim, 5) {}
    assert_eq!(parts.final_stock().map(|s| s.digest()), Some(stock.digest()));
    let half = sim.len() / 2;
    assert_eq!(parts.stock_at(half).map(|s| s.digest()), whole.stock_at(half).map(|s| s.digest()));
}
