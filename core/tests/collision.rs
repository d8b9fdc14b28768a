//! Collision checking (issue 17): NC programs on `ac-table` whose collisions are known from the
//! machine's bodies by hand, and the static shape tests against brute-force sampling and the
//! closed-form distance of axis-parallel boxes.

use glam::{DMat3, DVec3};
use proptest::prelude::*;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::parse;
use schwenkbar_core::plane::RotaryAxis;
use schwenkbar_core::sim::collision::{
    Obb, Placed, RESOLUTION, point_obb_distance, segment_obb_distance, segment_segment_distance, separation,
    swept_obb_gap, touch,
};
use schwenkbar_core::sim::{Collision, SegmentKind, SimOptions, Simulation, simulate};
use schwenkbar_testkit::collision::{LOW_TOOL, SEQ_MINUS_SWIVEL};

/// Runs `body` (the blocks between BEGIN and END PGM, numbered from 1) on `ac-table`.
fn run(body: &[&str]) -> (Simulation, String) {
    let mut text = String::from("0 BEGIN PGM T MM\n");
    for (i, line) in body.iter().enumerate() {
        text.push_str(&format!("{} {line}\n", i + 1));
    }
    text.push_str(&format!("{} END PGM T MM\n", body.len() + 1));
    let (program, diags) = parse(&text);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}\n{text}");
    let m = Machine::builtin("ac-table").expect("machine");
    (simulate(&program, &m, &SimOptions::default()), text)
}

/// The collision that stopped the run at block `number`.
fn collision_at(sim: &Simulation, text: &str, number: usize) -> Collision {
    let e = sim.error.as_ref().unwrap_or_else(|| panic!("no error\n{text}"));
    assert_eq!(e.block, number, "{e:?}\n{text}");
    sim.collision().unwrap_or_else(|| panic!("not a collision: {e:?}")).clone()
}

/// The 100 × 100 × 40 blank of Musterprogramm 1, centred on the C axis of `ac-table` (preset
/// X−50 Y−50 Z−160: the blank is M-CS X, Y −50…50, Z −200…−160; the rotary table's face at
/// Z−210, radius 50, 10 mm below the blank as if on parallels; the A axis along X through
/// Z−150).
const BLANK: [&str; 2] = ["BLK FORM 0.1 Z X+0 Y+0 Z-40", "BLK FORM 0.2 X+100 Y+100 Z+0"];

/// The shared scene ([`schwenkbar_testkit::collision`]): a tool 100 mm long with its tip 5 mm
/// above the table's face, beside the blank at M-CS Y+60, then `swivel`. Tilting A− lifts the +Y
/// side of the table: its rim (M-CS Y+50 Z−210, 78 mm from the A axis) swings through the tool
/// (Y 55…65, Z −205…−140).
fn low_tool_then(retract: Option<&str>, swivel: &str) -> (Simulation, String, usize) {
    let mut body: Vec<&str> = LOW_TOOL.to_vec();
    body.extend(retract);
    body.push(swivel);
    let n = body.len();
    let (sim, text) = run(&body);
    (sim, text, n)
}

#[test]
fn a_long_tool_near_the_table_collides_when_turn_tilts_the_table() {
    let (sim, text, n) = low_tool_then(None, "PLANE AXIAL A-30 TURN FMAX");
    let c = collision_at(&sim, &text, n);
    assert_eq!(c.kind, SegmentKind::SwivelTurn, "{c:?}");
    assert!(["tool", "tool holder"].contains(&&*c.a.en), "{c:?}");
    assert!(c.fraction > 0.0 && c.fraction < 1.0, "{c:?}");
    // The axes at the moment of contact lie on the way from A+0 to A−30.
    let a = c.axes.rotary_axis(RotaryAxis::A).expect("A");
    assert!(a < 0.0 && a > -30.0, "{a}");
    let e = sim.error.as_ref().expect("error");
    assert!(e.message.de.starts_with("Kollision: ") && e.message.en.starts_with("Collision: "), "{e:?}");
    assert!(e.message.de.contains(&*c.b.de) && e.message.en.contains(&*c.b.en), "{e:?}");
    // Every state before the colliding block is kept.
    assert_eq!(sim.len(), n, "BEGIN PGM and the blocks before");
}

#[test]
fn retracting_first_with_m91_or_mb_max_makes_the_same_swivel_free() {
    for (retract, swivel) in [
        (Some("L Z+0 R0 FMAX M91"), "PLANE AXIAL A-30 TURN FMAX"),
        (None, "PLANE AXIAL A-30 TURN MB MAX FMAX"),
    ] {
        let (sim, text, _) = low_tool_then(retract, swivel);
        assert!(sim.error.is_none(), "{:?}\n{text}", sim.error);
    }
}

/// The holder of a 40 mm tool (L80, DL−40: holder 14 mm long, radius 26 mm) stands beside the
/// blank, its axis at M-CS X+80, 4 mm from the blank's face at X+50, its lower end 9 mm below the
/// blank's top. Turning C by φ brings the nearest face to 80·cos φ − 50 mm of the holder's axis
/// (the foot within the face): 30 mm at C+0 and at C+90, below the holder's 26 mm between about
/// 18° and 72°. So the move is free at both ends and collides in between.
#[test]
fn a_collision_only_in_the_middle_of_a_rotary_move_is_found() {
    let mut body: Vec<&str> = BLANK.to_vec();
    body.extend([
        "TOOL CALL 1 Z S3000 DL-40",
        "L Z+0 R0 FMAX M91",
        "L X+130 Y+50 R0 FMAX",
        "L Z-35 R0 FMAX",
        "L C+90 FMAX",
    ]);
    let (sim, text) = run(&body);
    let c = collision_at(&sim, &text, body.len());
    assert_eq!((&*c.a.en, &*c.b.en), ("tool holder", "blank"), "{c:?}");
    assert!(c.fraction > 0.1 && c.fraction < 0.9, "{c:?}");
    // Start and end are free: the program without the turn, and with the turn made up high
    // before the tool comes down.
    let mut free = body.clone();
    free.pop();
    let (sim, text) = run(&free);
    assert!(sim.error.is_none(), "{:?}\n{text}", sim.error);
    let mut turned = body.clone();
    turned.truncate(turned.len() - 3);
    turned.extend(["L C+90 FMAX", "L X+130 Y+50 R0 FMAX", "L Z-35 R0 FMAX"]);
    let (sim, text) = run(&turned);
    assert!(sim.error.is_none(), "{:?}\n{text}", sim.error);
}

/// The same holder, moved straight across the blank at rapid from far beside it to far beyond
/// it (every head-side body, the spindle too, clear of the blank at both ends), through the
/// blank in between: it touches the face Y+100 when its axis reaches Y+126, after 74 of its
/// 300 mm. The broad phase of a translation must look at the whole sweep.
#[test]
fn a_straight_rapid_through_the_blank_is_found_though_both_ends_are_free() {
    let setup = |x: &'static str| {
        let mut body: Vec<&str> = BLANK.to_vec();
        body.extend(["TOOL CALL 1 Z S3000 DL-40", "L Z+0 R0 FMAX M91", x, "L Z-35 R0 FMAX"]);
        body
    };
    for x in ["L X+50 Y+200 R0 FMAX", "L X+50 Y-100 R0 FMAX"] {
        let (sim, text) = run(&setup(x));
        assert!(sim.error.is_none(), "{:?}\n{text}", sim.error);
    }
    let mut body = setup("L X+50 Y+200 R0 FMAX");
    body.push("L Y-100 R0 FMAX");
    let (sim, text) = run(&body);
    let c = collision_at(&sim, &text, body.len());
    assert_eq!((&*c.a.en, &*c.b.en), ("tool holder", "blank"), "{c:?}");
    assert!((c.fraction - 74.0 / 300.0).abs() < RESOLUTION / 300.0 + 1e-9, "{c:?}");
}

/// `SPA−30` on `ac-table` has two solutions: A−30 C+0 lifts the +Y side of the table into the
/// tool standing there, A+30 C±180 lowers it (and turns the round table and the square blank,
/// which stay clear of the holder). SEQ− picks the colliding one; the error names the other.
#[test]
fn the_other_solution_is_named_when_its_swivel_is_free() {
    let (sim, text, n) = low_tool_then(None, SEQ_MINUS_SWIVEL);
    let c = collision_at(&sim, &text, n);
    let alt = c.alternative.as_ref().unwrap_or_else(|| panic!("no alternative: {c:?}"));
    assert_eq!(alt.word, "SEQ+");
    assert!((alt.axes.a.expect("A") - 30.0).abs() < 1e-6, "{alt:?}");
    let e = sim.error.as_ref().expect("error");
    assert!(e.detail.de.contains("Die andere Lösung (SEQ+) wäre kollisionsfrei"), "{}", e.detail.de);
    assert!(e.detail.en.contains("The other solution (SEQ+) would be collision-free"), "{}", e.detail.en);
    let note = c.alternative_note().expect("note");
    assert!(
        note.de.starts_with("Die gewählte Lösung kollidiert (") && note.de.contains("SEQ+ (A+30"),
        "{}",
        note.de
    );
    assert!(note.en.ends_with("would be collision-free."), "{}", note.en);
    // And that solution, asked for, runs.
    let (sim, text, _) = low_tool_then(None, "PLANE SPATIAL SPA-30 SPB+0 SPC+0 TURN FMAX SEQ+");
    assert!(sim.error.is_none(), "{:?}\n{text}", sim.error);
}

/// Both Musterprogramme run without a collision on every shipped machine (the bodies are sized
/// so that the course's programs fit; `euler_fasen.h` on `ba-table` turns the table upside down,
/// A+135, and chamfers next to the cradle: a collision there is the machine's, not the check's).
/// A tool 100 mm long (radius 5) coming down over the C axis onto the rotary table's face
/// (W-CS Z−50, see [`BLANK`]): through the blank (cutting, not a collision) it touches the face
/// when its tip reaches Z−50. In one move the contact is at that height; in 0.2 mm steps it is
/// found in the step that gets within the check's resolution of it (20 − 0.2·k ≤ −50 + RESOLUTION:
/// step 350) — the check that carries what it knows from step to step misses nothing.
#[test]
fn a_descent_in_tiny_steps_stops_where_one_move_does() {
    let head = || -> Vec<String> {
        BLANK
            .iter()
            .chain(&[
                "TOOL CALL 1 Z S3000 DL+20",
                "L Z+0 R0 FMAX M91",
                "L X+50 Y+50 R0 FMAX",
                "L Z+20 R0 FMAX",
            ])
            .map(|b| b.to_string())
            .collect()
    };
    let run_owned = |body: &[String]| run(&body.iter().map(String::as_str).collect::<Vec<_>>());
    let mut one = head();
    one.push("L Z-60 F1000".into());
    let (sim, text) = run_owned(&one);
    let c = collision_at(&sim, &text, one.len());
    assert_eq!((&*c.a.en, &*c.b.en), ("tool", "C rotary table"), "{c:?}");
    // The Z axis where the tip stands at W-CS Z+20 (the block before; A and C at 0).
    let at_20 = sim.records.last().expect("the blocks before").axes.linear.z;
    let tip = |z: f64| z - at_20 + 20.0;
    let at_face = -50.0 - 1e-6..=-50.0 + RESOLUTION + 1e-6;
    let z = tip(c.axes.linear.z);
    assert!(at_face.contains(&z), "tip at Z{z}");
    let mut steps = head();
    let before = steps.len();
    steps.extend((0..400).map(|_| "L IZ-0.2 F1000".to_string()));
    let (sim, text) = run_owned(&steps);
    let c = collision_at(&sim, &text, before + 350);
    assert_eq!((&*c.a.en, &*c.b.en), ("tool", "C rotary table"), "{c:?}");
    let z = tip(c.axes.linear.z);
    assert!(at_face.contains(&z), "tip at Z{z}");
}

#[test]
fn the_sample_programs_run_free_on_every_machine() {
    for file in ["musterprogramm1.h", "musterprogramm2.h", "stay_q120.h"] {
        let path = format!("{}/../static/programs/{file}", env!("CARGO_MANIFEST_DIR"));
        let (program, _) = parse(&std::fs::read_to_string(&path).expect("program"));
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("machine");
            let sim = simulate(&program, &m, &SimOptions::default());
            assert!(sim.collision().is_none(), "{file} on {id}: {:?}", sim.error);
        }
    }
}

// ---- static shapes ----

fn aabb(min: DVec3, max: DVec3) -> Obb {
    Obb { center: 0.5 * (min + max), axes: DMat3::IDENTITY, half: 0.5 * (max - min) }
}

/// Closed-form distance of two axis-parallel boxes: the length of the per-axis gaps.
fn aabb_distance(a: &Obb, b: &Obb) -> f64 {
    let gap = ((b.center - a.center).abs() - a.half - b.half).max(DVec3::ZERO);
    gap.length()
}

/// Points on a grid filling a box (corners included), `n` per edge.
fn grid_in(o: &Obb, n: usize) -> Vec<DVec3> {
    let mut out = Vec::new();
    let s = |k: usize| 2.0 * k as f64 / (n - 1) as f64 - 1.0;
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let l = DVec3::new(s(i), s(j), s(k)) * o.half;
                out.push(o.center + o.axes * l);
            }
        }
    }
    out
}

/// Points filling a cylinder: rings at `n` heights, `n` radii, 24 angles.
fn grid_in_cylinder(base: DVec3, dir: DVec3, r: f64, h: f64, n: usize) -> Vec<DVec3> {
    let (e1, e2) = dir.any_orthonormal_pair();
    let mut out = Vec::new();
    for i in 0..n {
        let z = h * i as f64 / (n - 1) as f64;
        for j in 0..n {
            let rr = r * j as f64 / (n - 1) as f64;
            for k in 0..24 {
                let t = std::f64::consts::TAU * k as f64 / 24.0;
                out.push(base + dir * z + (e1 * t.cos() + e2 * t.sin()) * rr);
            }
        }
    }
    out
}

fn v3() -> impl Strategy<Value = DVec3> {
    (-100.0..100.0f64, -100.0..100.0f64, -100.0..100.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn size() -> impl Strategy<Value = DVec3> {
    (1.0..60.0f64, 1.0..60.0f64, 1.0..60.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = DVec3> {
    v3().prop_filter_map("not zero", |v| v.try_normalize())
}

/// A box passing another's corner diagonally (worked by hand in the XY plane): no face axis
/// parts them (the sweep covers X −6…6 and Y 0…12, the box X and Y −1…1), the axis
/// (1, −1, 0)/√2 = d × Z does: the path's centre line passes 6/√2 from the box's centre, each box
/// reaches √2 towards it, so they stay 6/√2 − 2√2 = √2 apart.
#[test]
fn a_diagonal_sweep_past_a_corner_is_parted_by_its_own_axis() {
    let b = aabb(DVec3::splat(-1.0), DVec3::splat(1.0));
    let a = aabb(DVec3::new(-6.0, 0.0, -1.0), DVec3::new(-4.0, 2.0, 1.0));
    let gap = swept_obb_gap(&a, DVec3::new(10.0, 10.0, 0.0), &b);
    assert!((gap - 2f64.sqrt()).abs() < 1e-12, "{gap}");
    // Swept on to the other side of the box it passes through it.
    assert!(swept_obb_gap(&a, DVec3::new(10.0, -2.0, 0.0), &b) < 0.0);
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(256))]

    /// A box swept along an axis fills the box from its start to its end: the swept test's gap
    /// is exactly that box's widest per-axis gap to an axis-parallel box (closed form).
    #[test]
    fn an_axis_parallel_sweep_is_the_box_it_fills(c1 in v3(), s1 in size(), c2 in v3(), s2 in size(), k in 0..3usize, l in -150.0..150.0f64) {
        let (a, b) = (aabb(c1 - s1, c1 + s1), aabb(c2 - s2, c2 + s2));
        let mut d = DVec3::ZERO;
        d[k] = l;
        let filled = aabb((c1 - s1).min(c1 - s1 + d), (c1 + s1).max(c1 + s1 + d));
        let widest = ((b.center - filled.center).abs() - filled.half - b.half).max_element();
        let gap = swept_obb_gap(&a, d, &b);
        prop_assert!((gap - widest).abs() < 1e-9, "{} vs {}", gap, widest);
    }

    /// Turned boxes, any translation: the swept gap never exceeds the distance of points
    /// sampled in the moving box at 17 places along the way (each at least the true distance),
    /// so a motion it clears by d keeps the boxes at least d apart.
    #[test]
    fn a_swept_box_stays_apart_by_its_gap(c1 in v3(), s1 in size(), u1 in unit(), t1 in 0.0..6.3f64,
                                          c2 in v3(), s2 in size(), u2 in unit(), t2 in 0.0..6.3f64, d in v3()) {
        let a = Obb { center: c1, axes: DMat3::from_axis_angle(u1, t1), half: s1 };
        let b = Obb { center: c2, axes: DMat3::from_axis_angle(u2, t2), half: s2 };
        let sampled = (0..=16)
            .flat_map(|i| grid_in(&Obb { center: a.center + d * (f64::from(i) / 16.0), ..a }, 5))
            .map(|p| point_obb_distance(p, &b))
            .fold(f64::INFINITY, f64::min);
        let gap = swept_obb_gap(&a, d, &b);
        prop_assert!(gap <= sampled + 1e-9, "{} > {}", gap, sampled);
    }

    /// Axis-parallel boxes: the separating-axis test says "touch within m" exactly when no
    /// per-axis gap exceeds m, and it always does within the closed-form distance.
    #[test]
    fn axis_parallel_boxes_agree_with_the_closed_form(c1 in v3(), s1 in size(), c2 in v3(), s2 in size(), m in 0.0..20.0f64) {
        let (a, b) = (aabb(c1 - s1, c1 + s1), aabb(c2 - s2, c2 + s2));
        let gap = ((b.center - a.center).abs() - a.half - b.half).max(DVec3::ZERO);
        prop_assert_eq!(touch(&Placed::Box(a), &Placed::Box(b), m), gap.max_element() <= m);
        let d = aabb_distance(&a, &b);
        prop_assert!(touch(&Placed::Box(a), &Placed::Box(b), d + 1e-9));
    }

    /// Turned boxes: a sampled point of one inside the other means they touch; when they touch
    /// with margin 0, the sampled distance between them is small (the sampling's spacing).
    #[test]
    fn turned_boxes_agree_with_sampled_points(c1 in v3(), s1 in size(), u1 in unit(), t1 in 0.0..6.3f64,
                                              c2 in v3(), s2 in size(), u2 in unit(), t2 in 0.0..6.3f64) {
        let a = Obb { center: c1 * 0.3, axes: DMat3::from_axis_angle(u1, t1), half: s1 };
        let b = Obb { center: c2 * 0.3, axes: DMat3::from_axis_angle(u2, t2), half: s2 };
        let pts = grid_in(&a, 9);
        let sampled = pts.iter().map(|p| point_obb_distance(*p, &b)).fold(f64::INFINITY, f64::min);
        let t = touch(&Placed::Box(a), &Placed::Box(b), 0.0);
        if sampled == 0.0 {
            prop_assert!(t, "a sampled point inside, but no touch");
        }
        // A touch at margin 0 with the nearest sampled point far away cannot be (grid spacing
        // of a is at most 2·60/8 = 15 mm per axis, so within √3·7.5 of any point of a).
        if t {
            prop_assert!(sampled <= 13.0, "touch reported, sampled distance {}", sampled);
        }
    }

    /// `separation`, the lower bound the check carries from motion to motion: exactly the
    /// largest per-axis gap for axis-parallel boxes, never above their closed-form distance.
    #[test]
    fn separation_of_axis_parallel_boxes_is_their_widest_gap(c1 in v3(), s1 in size(), c2 in v3(), s2 in size()) {
        let (a, b) = (aabb(c1 - s1, c1 + s1), aabb(c2 - s2, c2 + s2));
        let gaps = (b.center - a.center).abs() - a.half - b.half;
        let sep = separation(&Placed::Box(a), &Placed::Box(b));
        prop_assert!((sep - gaps.max_element()).abs() < 1e-9, "{} vs {}", sep, gaps.max_element());
        prop_assert!(sep <= aabb_distance(&a, &b) + 1e-9);
    }

    /// Turned boxes and cylinders: the bound never exceeds the sampled distance (which is at
    /// least the true one), so a pair it calls apart by d is at least d apart.
    #[test]
    fn separation_never_exceeds_the_sampled_distance(c1 in v3(), s1 in size(), u1 in unit(), t1 in 0.0..6.3f64,
                                                     base in v3(), dir in unit(), r in 1.0..40.0f64, h in 1.0..120.0f64,
                                                     base2 in v3(), dir2 in unit(), r2 in 1.0..40.0f64, h2 in 1.0..120.0f64) {
        let o = Obb { center: c1 * 0.3, axes: DMat3::from_axis_angle(u1, t1), half: s1 };
        let cyl = Placed::cylinder(base * 0.3, dir, r, h);
        let cyl2 = Placed::cylinder(base2 * 0.3, dir2, r2, h2);
        let pts = grid_in_cylinder(base * 0.3, dir, r, h, 9);
        let to_box = pts.iter().map(|p| point_obb_distance(*p, &o)).fold(f64::INFINITY, f64::min);
        prop_assert!(separation(&cyl, &Placed::Box(o)) <= to_box + 1e-9);
        prop_assert!(separation(&Placed::Box(o), &cyl) <= to_box + 1e-9);
        let pts2 = grid_in_cylinder(base2 * 0.3, dir2, r2, h2, 5);
        let coarse = grid_in_cylinder(base * 0.3, dir, r, h, 5);
        let between = coarse.iter().flat_map(|p| pts2.iter().map(move |q| (*p - *q).length())).fold(f64::INFINITY, f64::min);
        prop_assert!(separation(&cyl, &cyl2) <= between + 1e-9, "{} > {}", separation(&cyl, &cyl2), between);
        let b2 = Obb { center: base2 * 0.3, axes: DMat3::from_axis_angle(dir2, t1), half: DVec3::new(r2, h2, r2) };
        let box_box = grid_in(&o, 9).iter().map(|p| point_obb_distance(*p, &b2)).fold(f64::INFINITY, f64::min);
        prop_assert!(separation(&Placed::Box(o), &Placed::Box(b2)) <= box_box + 1e-9);
    }

    /// Segment–segment distance: never more than the brute-force minimum over sampled points,
    /// and at most the sampling's spacing below it.
    #[test]
    fn segment_distance_agrees_with_sampling(p1 in v3(), q1 in v3(), p2 in v3(), q2 in v3()) {
        let d = segment_segment_distance(p1, q1, p2, q2);
        let n = 400;
        let a: Vec<DVec3> = (0..=n).map(|k| p1.lerp(q1, k as f64 / n as f64)).collect();
        let b: Vec<DVec3> = (0..=n).map(|k| p2.lerp(q2, k as f64 / n as f64)).collect();
        let brute = a.iter().flat_map(|x| b.iter().map(move |y| (*x - *y).length())).fold(f64::INFINITY, f64::min);
        let spacing = ((q1 - p1).length() + (q2 - p2).length()) / n as f64;
        prop_assert!(d <= brute + 1e-9, "{} > {}", d, brute);
        prop_assert!(d >= brute - spacing, "{} < {} − {}", d, brute, spacing);
    }

    /// Segment–box distance against the closed-form point–box distance at sampled points.
    #[test]
    fn segment_box_distance_agrees_with_sampling(p in v3(), q in v3(), c in v3(), s in size(), u in unit(), t in 0.0..6.3f64) {
        let o = Obb { center: c * 0.5, axes: DMat3::from_axis_angle(u, t), half: s };
        let d = segment_obb_distance(p, q, &o);
        let n = 4000;
        let brute = (0..=n).map(|k| point_obb_distance(p.lerp(q, k as f64 / n as f64), &o)).fold(f64::INFINITY, f64::min);
        let spacing = (q - p).length() / n as f64;
        prop_assert!(d <= brute + 1e-6, "{} > {}", d, brute);
        prop_assert!(d >= brute - spacing - 1e-6, "{} < {}", d, brute);
    }

    /// Cylinder against box: a sampled point of the cylinder inside the box means they touch
    /// (no contact missed); a touch at margin 0 has the cylinder's sampled points close to the box.
    #[test]
    fn cylinder_and_box_agree_with_sampled_points(base in v3(), dir in unit(), r in 1.0..40.0f64, h in 1.0..120.0f64,
                                                 c in v3(), s in size(), u in unit(), t in 0.0..6.3f64) {
        let base = base * 0.3;
        let o = Obb { center: c * 0.3, axes: DMat3::from_axis_angle(u, t), half: s };
        let cyl = Placed::cylinder(base, dir, r, h);
        let pts = grid_in_cylinder(base, dir, r, h, 9);
        let sampled = pts.iter().map(|p| point_obb_distance(*p, &o)).fold(f64::INFINITY, f64::min);
        let hit = touch(&cyl, &Placed::Box(o), 0.0);
        if sampled == 0.0 {
            prop_assert!(hit, "a sampled point inside, but no touch");
        }
        if hit {
            // The capsule-and-box pair leaves at most the corner regions of the cylinder's box
            // (≤ r·(√2 − 1) beyond it) plus the sampling's spacing.
            let spacing = (h / 8.0).max(r / 8.0 + r * std::f64::consts::TAU / 24.0);
            prop_assert!(sampled <= r * (2f64.sqrt() - 1.0) + spacing + 1e-9, "sampled {}", sampled);
        }
    }
}
