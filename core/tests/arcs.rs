//! Arcs, helices, polar moves, RND/CHF corners and FN jumps through the whole simulator, checked
//! against closed forms written out here by hand (not the simulator's geometry): points of the
//! planar circle x = c + r·(cos θ·e1 + sin θ·e2) with the main plane of the tool axis (Z → XY,
//! Y → ZX, X → YZ; DR+ counter-clockwise seen against the tool axis, TNC 620 Klartext manual
//! "Fundamentals of path functions"), turned into the tilted plane by a hand-written
//! Rz(SPC)·Ry(SPB)·Rx(SPA) (DOMAIN.md §2.1), and the tangent points of a rounding from the
//! corner's angle. Tolerance 1e-6 mm: the points go through the machine's kinematics and back.

use glam::DVec3;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Kin, SegmentPath, SimErrorCode, SimOptions, Simulation, State, simulate};
use schwenkbar_core::{BlockBody, Program, parse};
use schwenkbar_testkit::assert_close;

const TOL: f64 = 1e-6;

/// Parses (no errors allowed) and runs on the A/C table.
fn run(src: &str) -> (Program, Machine, Simulation) {
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{src}\n{diags:?}");
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    (program, m, sim)
}

/// The state after the block with this number.
fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
    let step = sim.first_step[idx].expect("executed") as usize;
    sim.state_at(program, step).expect("state")
}

/// The tool tip in the I-CS at `f` of the block's motion.
fn ics(m: &Machine, s: &State, f: f64) -> DVec3 {
    s.tip_ics_at(m, f)
}

/// A program: header, `TOOL CALL 16 <axis>`, then `body` lines numbered from 3.
fn program(axis: char, body: &[String]) -> String {
    let mut s = format!("0 BEGIN PGM T MM\n1 TOOL CALL 16 {axis} S1000 F1000\n2 L Z+0 R0 FMAX M91\n");
    for (k, line) in body.iter().enumerate() {
        s.push_str(&format!("{} {line}\n", k + 3));
    }
    s.push_str(&format!("{} END PGM T MM\n", body.len() + 3));
    s
}

/// `(letter, index)` of the plane axes and the tool axis: e1 (angle 0°), e2 (angle +90°), n.
fn plane_axes(tool: char) -> [(char, usize); 3] {
    match tool {
        'Z' => [('X', 0), ('Y', 1), ('Z', 2)],
        'Y' => [('Z', 2), ('X', 0), ('Y', 1)],
        _ => [('Y', 1), ('Z', 2), ('X', 0)],
    }
}

/// The point at angle `deg` on the circle around (c1, c2) of radius r, at height h on the tool
/// axis, in I-CS coordinates for tool axis `tool`.
fn on_circle(tool: char, c: (f64, f64), r: f64, deg: f64, h: f64) -> DVec3 {
    let [(_, i1), (_, i2), (_, n)] = plane_axes(tool);
    let mut p = DVec3::ZERO;
    p[i1] = c.0 + r * deg.to_radians().cos();
    p[i2] = c.1 + r * deg.to_radians().sin();
    p[n] = h;
    p
}

/// Axis words `A±a B±b C±c` for a point in the plane (two plane coordinates and the tool axis).
fn words(tool: char, p: DVec3) -> String {
    plane_axes(tool).iter().map(|&(l, i)| format!("{l}{:+.6}", p[i])).collect::<Vec<_>>().join(" ")
}

#[test]
fn c_arcs_in_the_three_main_planes_end_exactly_and_stay_on_their_circle() {
    for tool in ['Z', 'Y', 'X'] {
        for (dr, sign) in [("DR+", 1.0), ("DR-", -1.0)] {
            let (c, r, h) = ((10.0, -5.0), 25.0, 7.0);
            let (a0, a1) = (30.0, 150.0);
            let start = on_circle(tool, c, r, a0, h);
            let end = on_circle(tool, c, r, a1, h);
            let [(l1, _), (l2, _), _] = plane_axes(tool);
            let src = program(
                tool,
                &[
                    format!("L {} R0 FMAX", words(tool, start)),
                    format!("CC {l1}{:+} {l2}{:+}", c.0, c.1),
                    format!("C {} {dr} F500", words(tool, end)),
                ],
            );
            let (p, m, sim) = run(&src);
            assert!(sim.error.is_none(), "{tool} {dr}: {:?}", sim.error);
            let s = after(&p, &sim, 5);
            assert_close!(s.tip_ics, end, TOL, "{tool} {dr} end");
            assert!(matches!(s.segments[0].path, SegmentPath::Arc(_)), "{tool} {dr}: an arc segment");
            // DR+ turns +120° (30° → 150°), DR− the other way round: −240°.
            let sweep = if sign > 0.0 { 120.0 } else { -240.0 };
            for f in [0.0, 0.25, 0.5, 0.75, 1.0] {
                let want = on_circle(tool, c, r, a0 + f * sweep, h);
                assert_close!(ics(&m, &s, f), want, TOL, "{tool} {dr} at {f}");
            }
        }
    }
}

/// With tool axis Z, `CC` naming the two axes of another main plane puts `C` and `CP` in that
/// plane (`unconfirmed::ARC_PLANE_OF_CC`): the same circle as with that plane's tool axis, the
/// ramps CAM systems write (`CC X… Z…` + `CP IPA-90 DR-`). RL/RR there is refused.
#[test]
fn arcs_in_the_plane_of_their_cc_with_tool_axis_z() {
    for plane in ['Y', 'X'] {
        let (c, r, h) = ((10.0, -5.0), 25.0, 7.0);
        let (a0, a1) = (30.0, 150.0);
        let start = on_circle(plane, c, r, a0, h);
        let end = on_circle(plane, c, r, a1, h);
        let [(l1, _), (l2, _), _] = plane_axes(plane);
        let src = program(
            'Z',
            &[
                format!("L {} R0 FMAX", words(plane, start)),
                format!("CC {l1}{:+} {l2}{:+}", c.0, c.1),
                format!("C {} DR+ F500", words(plane, end)),
                "CP IPA-60 DR- F500".to_owned(),
            ],
        );
        let (p, m, sim) = run(&src);
        assert!(sim.error.is_none(), "{plane}: {:?}", sim.error);
        let s = after(&p, &sim, 5);
        assert_close!(s.tip_ics, end, TOL, "{plane} C end");
        for f in [0.0, 0.5, 1.0] {
            assert_close!(ics(&m, &s, f), on_circle(plane, c, r, a0 + f * 120.0, h), TOL, "{plane} C at {f}");
        }
        let s = after(&p, &sim, 6);
        for f in [0.5, 1.0] {
            assert_close!(ics(&m, &s, f), on_circle(plane, c, r, a1 - f * 60.0, h), TOL, "{plane} CP at {f}");
        }
    }
    // A ramp as CAM writes it, worked by hand: from X+1 Y+5 Z+0 around CC X+0 Z+0 by −90° (DR−)
    // in the ZX plane, a turn about +Y: (cos θ, 0, −sin θ) at θ = −90° is (0, 0, +1).
    let src =
        program('Z', &["L X+1 Y+5 Z+0 R0 FMAX".into(), "CC X+0 Z+0".into(), "CP IPA-90 DR- F300".into()]);
    let (p, _, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_close!(after(&p, &sim, 5).tip_ics, DVec3::new(0.0, 5.0, 1.0), TOL, "ramp end");
    let src =
        program('Z', &["L X+1 Y+5 Z+0 RL F300".into(), "CC X+0 Z+0".into(), "CP IPA-90 DR- F300".into()]);
    let (_, _, sim) = run(&src);
    let e = sim.error.expect("RL in the ZX plane is refused");
    assert_eq!(e.code, SimErrorCode::CompensationOffPlane);
}

/// Rz(c)·Ry(b)·Rx(a) applied to p, written out (DOMAIN.md §2.1).
fn spatial(a: f64, b: f64, c: f64, p: DVec3) -> DVec3 {
    let (sa, ca) = a.to_radians().sin_cos();
    let (sb, cb) = b.to_radians().sin_cos();
    let (sc, cc) = c.to_radians().sin_cos();
    let x = DVec3::new(p.x, ca * p.y - sa * p.z, sa * p.y + ca * p.z);
    let y = DVec3::new(cb * x.x + sb * x.z, x.y, -sb * x.x + cb * x.z);
    DVec3::new(cc * y.x - sc * y.y, sc * y.x + cc * y.y, y.z)
}

#[test]
fn arcs_after_plane_spatial_lie_in_the_tilted_plane() {
    // A small deterministic generator (LCG) for the angles: SPA, SPB within ±40° so the A/C
    // table reaches every plane, SPC anywhere.
    let mut seed: u64 = 0x5eed_1234;
    let mut next = |lo: f64, hi: f64| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((seed >> 11) as f64 / (1u64 << 53) as f64)
    };
    for _ in 0..8 {
        let (a, b, c) = (next(-40.0, 40.0), next(-40.0, 40.0), next(-180.0, 180.0));
        let src = program(
            'Z',
            &[
                format!("PLANE SPATIAL SPA{a:+.4} SPB{b:+.4} SPC{c:+.4} TURN FMAX"),
                "L X+20 Y+0 Z+5 R0 FMAX".into(),
                "CC X+0 Y+0".into(),
                "C X+0 Y+20 DR+ F500".into(),
                "CR X+0 Y-20 R-20 DR+".into(),
            ],
        );
        let (p, m, sim) = run(&src);
        assert!(sim.error.is_none(), "SPA{a} SPB{b} SPC{c}: {:?}", sim.error);
        let (a, b, c) = (round4(a), round4(b), round4(c));
        for (number, from, sweep) in [(6, 0.0, 90.0), (7, 90.0, 180.0)] {
            let s = after(&p, &sim, number);
            let kin = Kin::new(&m, s.tool.length);
            let seg = &s.segments[0];
            for f in [0.0, 0.3, 0.5, 1.0] {
                let want = spatial(a, b, c, on_circle('Z', (0.0, 0.0), 20.0, from + f * sweep, 5.0));
                assert_close!(
                    kin.tip_wcs(&seg.axes_at(f)),
                    want,
                    TOL,
                    "SPA{a} SPB{b} SPC{c} block {number} at {f}"
                );
            }
        }
    }
}

/// Rounded to the 4 decimals the program text carries.
fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

#[test]
fn helix_rises_by_its_pitch_per_turn() {
    // Two turns (IPA+720) down by 6 mm: 3 mm per turn, linear in the turned angle.
    let src = program(
        'Z',
        &[
            "CC X+50 Y+50".into(),
            "LP PR+20 PA+0 R0 FMAX".into(),
            "L Z+2 R0 FMAX".into(),
            "CP IPA+720 IZ-6 DR+ F200".into(),
        ],
    );
    let (p, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s = after(&p, &sim, 6);
    for (f, deg) in [(0.125, 90.0), (0.25, 180.0), (0.5, 360.0), (0.625, 450.0), (1.0, 720.0)] {
        let want = on_circle('Z', (50.0, 50.0), 20.0, deg, 2.0 - 3.0 * deg / 360.0);
        assert_close!(ics(&m, &s, f), want, TOL, "helix at {f}");
    }
}

#[test]
fn polar_line_goes_to_pr_pa_around_the_pole() {
    let src = program(
        'Z',
        &[
            "L X+0 Y+0 Z+0 R0 FMAX".into(),
            "CC X+10 Y+20".into(),
            "LP PR+30 PA+60 R0 FMAX".into(),
            "LP IPR+5 IPA-90".into(),
        ],
    );
    let (p, _, sim) = run(&src);
    let s = after(&p, &sim, 5);
    assert_close!(s.tip_ics, on_circle('Z', (10.0, 20.0), 30.0, 60.0, 0.0), TOL);
    let s = after(&p, &sim, 6);
    assert_close!(s.tip_ics, on_circle('Z', (10.0, 20.0), 35.0, -30.0, 0.0), TOL);
}

#[test]
fn cr_with_r_plus_takes_the_short_arc_and_r_minus_the_long_one() {
    // From (0,0) to (20,0) with radius 20: the centres are (10, ±√300); the short arc turns
    // 60°, the long one 300°. DR+ R+ runs below the chord, DR+ R− around the far side.
    let k = 300f64.sqrt();
    for (r, dr, centre_y, from, sweep) in [
        ("R+20", "DR+", k, 240.0, 60.0),
        ("R-20", "DR+", -k, 120.0, 300.0),
        ("R+20", "DR-", -k, 120.0, -60.0),
        ("R-20", "DR-", k, 240.0, -300.0),
    ] {
        let src = program('Z', &["L X+0 Y+0 Z+5 R0 FMAX".into(), format!("CR X+20 Y+0 {r} {dr} F500")]);
        let (p, m, sim) = run(&src);
        let s = after(&p, &sim, 4);
        for f in [0.0, 0.25, 0.5, 1.0] {
            let want = on_circle('Z', (10.0, centre_y), 20.0, from + f * sweep, 5.0);
            assert_close!(ics(&m, &s, f), want, TOL, "{r} {dr} at {f}");
        }
    }
}

#[test]
fn ct_continues_tangentially_from_the_line_before() {
    // Along +X to (0,0), then CT to (20,20): the circle tangent to the X axis at the origin
    // through (20,20) has its centre at (0,20), r = 20; a quarter turn counter-clockwise.
    let src = program('Z', &["L X-10 Y+0 Z+5 R0 FMAX".into(), "L X+0 F500".into(), "CT X+20 Y+20".into()]);
    let (p, m, sim) = run(&src);
    let s = after(&p, &sim, 5);
    for f in [0.0, 0.5, 1.0] {
        assert_close!(
            ics(&m, &s, f),
            on_circle('Z', (0.0, 20.0), 20.0, -90.0 + 90.0 * f, 5.0),
            TOL,
            "at {f}"
        );
    }
}

#[test]
fn rnd_and_chf_at_a_right_angle_corner() {
    // Corner (50,0) between +X and +Y. RND R5: tangent points P ∓ r·tan(45°)·d = (45,0),
    // (50,5), centre (45,5). CHF 5: the same points joined by a straight line.
    for (corner, mid) in [
        (
            "RND R5",
            DVec3::new(
                45.0 + 5.0 * (-45f64).to_radians().cos(),
                5.0 + 5.0 * (-45f64).to_radians().sin(),
                0.0,
            ),
        ),
        ("CHF 5", DVec3::new(47.5, 2.5, 0.0)),
    ] {
        let src = program(
            'Z',
            &["L X+0 Y+0 Z+0 R0 FMAX".into(), "L X+50 F500".into(), corner.into(), "L Y+50".into()],
        );
        let (p, m, sim) = run(&src);
        assert!(sim.error.is_none(), "{corner}: {:?}", sim.error);
        assert_close!(after(&p, &sim, 4).tip_ics, DVec3::new(45.0, 0.0, 0.0), TOL, "{corner} T1");
        let s = after(&p, &sim, 5);
        assert_close!(s.tip_ics, DVec3::new(50.0, 5.0, 0.0), TOL, "{corner} T2");
        assert_close!(ics(&m, &s, 0.5), mid, TOL, "{corner} middle");
        assert_close!(after(&p, &sim, 6).tip_ics, DVec3::new(50.0, 50.0, 0.0), TOL, "{corner} end");
    }
}

#[test]
fn rnd_and_chf_at_a_general_corner() {
    // Corner (50,0) between d1 = +X and d2 = (−0.6, 0.8): deflection α with cos α = −0.6, so
    // tan(α/2) = 2. RND R10: T1 = (50 − 20, 0), T2 = (50,0) + 20·d2 = (38,16), centre (30,10).
    // CHF 10: T1 = (40,0), T2 = (44,8).
    let cases = [
        ("RND R10", DVec3::new(30.0, 0.0, 0.0), DVec3::new(38.0, 16.0, 0.0)),
        ("CHF 10", DVec3::new(40.0, 0.0, 0.0), DVec3::new(44.0, 8.0, 0.0)),
    ];
    for (corner, t1, t2) in cases {
        let src = program(
            'Z',
            &["L X+0 Y+0 Z+0 R0 FMAX".into(), "L X+50 F500".into(), corner.into(), "L X+20 Y+40".into()],
        );
        let (p, m, sim) = run(&src);
        assert!(sim.error.is_none(), "{corner}: {:?}", sim.error);
        assert_close!(after(&p, &sim, 4).tip_ics, t1, TOL, "{corner} T1");
        let s = after(&p, &sim, 5);
        assert_close!(s.tip_ics, t2, TOL, "{corner} T2");
        if corner.starts_with("RND") {
            for f in [0.25, 0.5, 0.75] {
                assert_close!(
                    ics(&m, &s, f).distance(DVec3::new(30.0, 10.0, 0.0)),
                    10.0,
                    TOL,
                    "{corner} radius at {f}"
                );
            }
        }
    }
}

#[test]
fn rnd_between_a_line_and_an_arc() {
    // Line along +X to (50,0), then C around CC (80,0) counter-clockwise: at its start the
    // arc heads −Y, a right turn. The rounding's centre is r below the line and r + 30 from
    // (80,0): (80 − √(35² − 5²), −5); it touches the line above it and the circle on the ray
    // from (80,0) through it.
    let fx = 80.0 - (35f64 * 35.0 - 25.0).sqrt();
    let centre = DVec3::new(fx, -5.0, 0.0);
    let t2 = DVec3::new(80.0, 0.0, 0.0) + 30.0 * (centre - DVec3::new(80.0, 0.0, 0.0)) / 35.0;
    let src = program(
        'Z',
        &[
            "L X+0 Y+0 Z+0 R0 FMAX".into(),
            "L X+50 F500".into(),
            "RND R5".into(),
            "CC X+80 Y+0".into(),
            "C X+110 Y+0 DR+".into(),
        ],
    );
    let (p, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_close!(after(&p, &sim, 4).tip_ics, DVec3::new(fx, 0.0, 0.0), TOL, "T1");
    let s = after(&p, &sim, 5);
    assert_close!(s.tip_ics, t2, TOL, "T2");
    assert_close!(ics(&m, &s, 0.5).distance(centre), 5.0, TOL, "on the rounding");
    let s = after(&p, &sim, 7);
    assert_close!(s.tip_ics, DVec3::new(110.0, 0.0, 0.0), TOL, "arc end");
    assert_close!(ics(&m, &s, 0.5).distance(DVec3::new(80.0, 0.0, 0.0)), 30.0, TOL, "arc radius");
}

fn error_of(src: &str) -> (u32, SimErrorCode) {
    let (p, _, sim) = run(src);
    let e = sim.error.expect("an error");
    (p.blocks[e.block].number().expect("numbered"), e.code)
}

#[test]
fn geometry_errors_stop_at_their_block() {
    let (n, code) = error_of(&program('Z', &["L X+10 Y+0 Z+10 R0 FMAX".into(), "C X+0 Y+10 DR+".into()]));
    assert_eq!((n, code), (4, SimErrorCode::NoCircleCentre { word: "C" }));
    let (n, code) =
        error_of(&program('Z', &["L X+0 Y+0 Z+10 R0 FMAX".into(), "CR X+50 Y+0 R+20 DR+".into()]));
    assert_eq!((n, code), (4, SimErrorCode::RadiusTooSmall { radius: 20.0, chord: 50.0 }));
    let (n, code) = error_of(&program('Z', &["CT X+10 Y+10".into()]));
    assert_eq!((n, code), (3, SimErrorCode::NoTangent));
    let (n, code) = error_of(&program('Z', &["LP PR+10 PA+0".into()]));
    assert_eq!((n, code), (3, SimErrorCode::NoCircleCentre { word: "LP" }));
    let (n, code) = error_of(&program(
        'Z',
        &["L X+10 Y+0 Z+10 R0 FMAX".into(), "CC X+0 Y+0".into(), "C X+0 Y+15 DR+".into()],
    ));
    assert!(n == 5 && matches!(code, SimErrorCode::CircleEnd { .. }), "{n} {code:?}");
    // RND too big for the line before it, and RND with nothing after it.
    let (n, code) = error_of(&program(
        'Z',
        &["L X+0 Y+0 Z+0 R0 FMAX".into(), "L X+5 F500".into(), "RND R10".into(), "L Y+50".into()],
    ));
    assert_eq!((n, code), (5, SimErrorCode::CornerTooLarge { word: "RND", value: 10.0 }));
    let (n, code) = error_of(&program(
        'Z',
        &["L X+0 Y+0 Z+0 R0 FMAX".into(), "L X+50 F500".into(), "CHF 5".into(), "M30".into()],
    ));
    assert_eq!((n, code), (5, SimErrorCode::CornerWithoutContour { word: "CHF" }));
    for code in
        [SimErrorCode::NoCircleCentre { word: "C" }, SimErrorCode::NoTangent, SimErrorCode::ChamferNeedsLines]
    {
        let (m, d) = (code.message(), code.detail());
        assert!(!m.de.is_empty() && !m.en.is_empty() && m.de != m.en && d.de != d.en, "{code:?}");
    }
}

#[test]
fn fn_jumps_loop_and_fn_maths_compute() {
    let src =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/fixtures/sim/fn_math_loop.h"))
            .expect("fixture");
    let (p, _, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let idx = p.blocks.iter().position(|b| b.number() == Some(10)).expect("block 10") as u32;
    assert_eq!(sim.records.iter().filter(|r| r.block == idx && r.executed).count(), 3, "three passes");
    let last = sim.state_at(&p, sim.len() - 1).expect("state");
    // Q1 = 3 after three passes; Q3 = 30, Q4 = 15, Q5 = √15, Q6 = 2; block 13 and 18 skipped.
    for (q, v) in [(1, 3.0), (3, 30.0), (4, 15.0), (5, 15f64.sqrt()), (6, 2.0)] {
        assert_close!(last.q[&q], v, 1e-12, "Q{q}");
    }
    assert_close!(last.tip_ics, DVec3::new(30.0, 15f64.sqrt(), 50.0), TOL);
    for n in [13, 18] {
        let idx = p.blocks.iter().position(|b| b.number() == Some(n)).expect("block") as u32;
        assert!(sim.records.iter().all(|r| r.block != idx || !r.executed), "block {n} jumped over");
    }
}

#[test]
fn fn_blocks_are_typed_nodes() {
    let (p, d) =
        parse("1 FN 12: IF +Q25 LT +Q35 GOTO LBL 2\n2 FN 4: Q4 = +8 DIV +Q2\n3 FN 5: Q20 = SQRT 4\n");
    assert!(d.is_empty(), "{d:?}");
    assert!(p.blocks.iter().all(|b| matches!(*b.body(), BlockBody::FnJump(_) | BlockBody::FnMath(_))));
}

#[test]
fn every_prefix_of_the_new_blocks_parses_without_panic() {
    let src = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/fixtures/ok/contour_manual.h"
    ))
    .expect("fixture");
    for line in src.lines() {
        for (i, _) in line.char_indices() {
            let _ = parse(&line[..i]);
            let _ = parse(&line[i..]);
        }
    }
}

#[test]
fn the_contour_fixtures_run_without_errors_on_every_machine() {
    for name in ["contour_arcs", "polar_helix", "arcs_tilted", "fn_math_loop"] {
        let path = format!("{}/../tests/fixtures/sim/{name}.h", env!("CARGO_MANIFEST_DIR"));
        let (p, d) = parse(&std::fs::read_to_string(&path).expect("fixture"));
        assert!(d.is_empty(), "{name}: {d:?}");
        for id in ["ac-table", "ba-table", "bc-head-table", "ca-head", "b45-nutating"] {
            let m = Machine::builtin(id).expect("machine");
            let sim = simulate(&p, &m, &SimOptions::default());
            assert!(sim.error.is_none(), "{name} on {id}: {:?}", sim.error);
        }
    }
}

#[test]
fn the_stock_is_cut_along_the_arc_not_along_its_chords() {
    use schwenkbar_core::stock::{Cutting, StockOptions};
    let src = "0 BEGIN PGM S MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n\
               3 TOOL CALL 1 Z S1000 F500\n4 L X+80 Y+50 Z+5 R0 FMAX\n5 L Z-5 F300\n6 CC X+50 Y+50\n\
               7 C X+80 Y+50 DR+\n8 L Z+5 FMAX\n9 END PGM S MM\n";
    let (p, _, sim) = run(src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let r = sim.state_at(&p, sim.len() - 1).expect("state").tool.radius;
    let stock = Cutting::new(&p, &sim, StockOptions::default()).final_stock().expect("stock");
    // An end mill of radius 5 (tool 1). Within 0.6 mm of the swept band's edges (resolution
    // 0.25 mm): inside cut, outside not, at angles between any two straight pieces; chords
    // of 45° (sagitta 30·(1 − cos 22.5°) = 2.3 mm) would cut into the island.
    for deg in [13.0, 37.0, 100.0, 200.0, 333.0] {
        let at = |radius: f64| on_circle('Z', (50.0, 50.0), radius, deg, -3.0);
        assert!(!stock.material_at(at(30.0)), "cut on the circle at {deg}°");
        assert!(!stock.material_at(at(30.0 + r - 0.6)), "cut at the outer edge at {deg}°");
        assert!(!stock.material_at(at(30.0 - r + 0.6)), "cut at the inner edge at {deg}°");
        assert!(stock.material_at(at(30.0 + r + 0.6)), "outside stays at {deg}°");
        assert!(stock.material_at(at(30.0 - r - 0.6)), "the island stays at {deg}°");
    }
}

#[test]
fn rnd_between_two_arcs_touches_both_circles() {
    // C counter-clockwise around (0,0) from (50,0) to (0,50), heading −X there; then clockwise
    // around (50,50), heading +Y: a right turn. The R5 rounding's centre f lies r outside the
    // first circle on the ray through T1 and r inside the second; T2 is on the second circle.
    let src = program(
        'Z',
        &[
            "L X+50 Y+0 Z+0 R0 FMAX".into(),
            "CC X+0 Y+0".into(),
            "C X+0 Y+50 DR+ F500".into(),
            "RND R5".into(),
            "CC X+50 Y+50".into(),
            "C X+100 Y+50 DR-".into(),
        ],
    );
    let (p, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let c2 = DVec3::new(50.0, 50.0, 0.0);
    let t1 = after(&p, &sim, 5).tip_ics;
    assert_close!(t1.length(), 50.0, TOL, "T1 on the first circle");
    let f = t1 * (55.0 / 50.0);
    assert_close!(f.distance(c2), 45.0, TOL, "centre r inside the second circle");
    let s = after(&p, &sim, 6);
    assert_close!(s.tip_ics.distance(c2), 50.0, TOL, "T2 on the second circle");
    for x in [0.0, 0.5, 1.0] {
        assert_close!(ics(&m, &s, x).distance(f), 5.0, TOL, "rounding at {x}");
    }
    assert_close!(after(&p, &sim, 8).tip_ics, DVec3::new(100.0, 50.0, 0.0), TOL, "second arc ends");
}

/// A RND before an arc in the plane of its CC: the rounding has no working-plane element to
/// meet, so the RND block stops with the control's message instead of a made-up corner.
#[test]
fn a_rounding_before_an_arc_in_another_plane_is_refused() {
    let src = program(
        'Z',
        &[
            "L X+0 Y+5 Z+0 R0 FMAX".into(),
            "L X+1 F300".into(),
            "RND R0.5".into(),
            "CC X+2 Z+0".into(),
            "CP IPA-90 DR- F300".into(),
        ],
    );
    let (_, _, sim) = run(&src);
    let e = sim.error.expect("the RND is refused");
    assert!(matches!(e.code, SimErrorCode::CornerWithoutContour { .. }), "{:?}", e.code);
    assert_eq!(e.line, 6, "at the RND block");
}
