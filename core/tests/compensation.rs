//! Tool radius compensation RL/RR and APPR/DEP through the whole simulator, against tool centre
//! paths written out here by hand from the manual's description (not from the simulator's
//! geometry): RL puts the tool centre R to the left of the contour in the direction of travel,
//! RR to the right; at an outside corner the centre runs on a quarter circle of radius R around
//! the corner point, at an inside corner to the intersection of the two offset paths; an arc's
//! radius grows or shrinks by R (TNC 620 / iTNC 530 Klartext manuals, "Tool radius
//! compensation"); the APPR/DEP auxiliary points as the TNC7 manual draws them. Tool 1 of
//! `static/tools.json` has R = 5. Tolerance 1e-6 mm: the points go through the kinematics.

use glam::DVec3;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{
    ApprDepReason, Kin, SegmentPath, SimErrorCode, SimOptions, Simulation, State, simulate,
};
use schwenkbar_core::{Program, parse};
use schwenkbar_testkit::assert_close;

const TOL: f64 = 1e-6;

/// The contour's height on the tool axis.
const H: f64 = -5.0;

fn p(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, H)
}

/// One piece of an expected tool centre path.
#[derive(Debug, Clone, Copy)]
enum Piece {
    Line(DVec3, DVec3),
    /// Centre, radius, start angle and turned angle (degrees, + counter-clockwise), at height H.
    Arc(DVec3, f64, f64, f64),
}

impl Piece {
    fn at(self, f: f64) -> DVec3 {
        match self {
            Piece::Line(a, b) => a.lerp(b, f),
            Piece::Arc(c, r, from, sweep) => {
                let t = (from + f * sweep).to_radians();
                c + r * DVec3::new(t.cos(), t.sin(), 0.0)
            }
        }
    }
}

/// A program: `TOOL CALL 1` (with `tool_extra` words), then `body` numbered from 3.
fn program(tool_extra: &str, body: &[&str]) -> String {
    let mut s = format!("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000 F500{tool_extra}\n2 L Z+0 R0 FMAX M91\n");
    for (k, line) in body.iter().enumerate() {
        s.push_str(&format!("{} {line}\n", k + 3));
    }
    s.push_str(&format!("{} END PGM T MM\n", body.len() + 3));
    s
}

fn run(src: &str) -> (Program, Machine, Simulation) {
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{src}\n{diags:?}");
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    (program, m, sim)
}

fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
    let step = sim.first_step[idx].expect("executed") as usize;
    sim.state_at(program, step).expect("state")
}

/// The block's segments against the expected pieces, each turned into the W-CS by `to_wcs`.
fn check(
    program: &Program,
    m: &Machine,
    sim: &Simulation,
    number: u32,
    want: &[Piece],
    to_wcs: &dyn Fn(DVec3) -> DVec3,
) {
    let s = after(program, sim, number);
    let kin = Kin::new(m, s.tool.length);
    assert_eq!(s.segments.len(), want.len(), "block {number}: {:?}", s.segments);
    for (k, (seg, piece)) in s.segments.iter().zip(want).enumerate() {
        let arc = matches!(seg.path, SegmentPath::Arc(_));
        assert_eq!(arc, matches!(piece, Piece::Arc(..)), "block {number} piece {k}: {:?}", seg.path);
        for f in [0.0, 0.25, 0.5, 0.75, 1.0] {
            assert_close!(
                kin.tip_wcs(&seg.axes_at(f)),
                to_wcs(piece.at(f)),
                TOL,
                "block {number} piece {k} at {f}"
            );
        }
    }
}

fn untilted(v: DVec3) -> DVec3 {
    v
}

/// The square (0,0)–(50,0)–(50,50)–(0,50), counter-clockwise or clockwise, with `comp` switched
/// on in block 6 and off (R0) in block 11; block 3 is `first` (a PLANE or a comment).
fn square(first: &str, comp: &str, ccw: bool) -> String {
    let on = format!("L X+0 Y+0 {comp}");
    let sides: [&str; 4] =
        if ccw { ["L X+50", "L Y+50", "L X+0", "L Y+0"] } else { ["L Y+50", "L X+50", "L Y+0", "L X+0"] };
    let mut body = vec![first, "L X-20 Y-20 Z+10 R0 FMAX", "L Z-5 F500", on.as_str()];
    body.extend(sides);
    body.extend(["L X-20 Y-20 R0", "L Z+10 FMAX"]);
    program("", &body)
}

/// The hand-written centre paths of blocks 6…11 for each of the four cases (R = 5).
fn square_paths(comp: &str, ccw: bool) -> Vec<Vec<Piece>> {
    use Piece::{Arc, Line};
    let ps = p(-20.0, -20.0);
    match (comp, ccw) {
        // Tool outside, the contour turns left at every corner: quarter circles, counter-clockwise.
        ("RR", true) => vec![
            vec![Line(ps, p(0.0, -5.0))],
            vec![Line(p(0.0, -5.0), p(50.0, -5.0))],
            vec![Arc(p(50.0, 0.0), 5.0, -90.0, 90.0), Line(p(55.0, 0.0), p(55.0, 50.0))],
            vec![Arc(p(50.0, 50.0), 5.0, 0.0, 90.0), Line(p(50.0, 55.0), p(0.0, 55.0))],
            vec![Arc(p(0.0, 50.0), 5.0, 90.0, 90.0), Line(p(-5.0, 50.0), p(-5.0, 0.0))],
            vec![Line(p(-5.0, 0.0), ps)],
        ],
        // Tool outside, the contour turns right: quarter circles, clockwise.
        ("RL", false) => vec![
            vec![Line(ps, p(-5.0, 0.0))],
            vec![Line(p(-5.0, 0.0), p(-5.0, 50.0))],
            vec![Arc(p(0.0, 50.0), 5.0, 180.0, -90.0), Line(p(0.0, 55.0), p(50.0, 55.0))],
            vec![Arc(p(50.0, 50.0), 5.0, 90.0, -90.0), Line(p(55.0, 50.0), p(55.0, 0.0))],
            vec![Arc(p(50.0, 0.0), 5.0, 0.0, -90.0), Line(p(50.0, -5.0), p(0.0, -5.0))],
            vec![Line(p(0.0, -5.0), ps)],
        ],
        // Tool inside: the corners of the square shrunk by R, no arcs.
        ("RL", true) => vec![
            vec![Line(ps, p(0.0, 5.0))],
            vec![Line(p(0.0, 5.0), p(45.0, 5.0))],
            vec![Line(p(45.0, 5.0), p(45.0, 45.0))],
            vec![Line(p(45.0, 45.0), p(5.0, 45.0))],
            vec![Line(p(5.0, 45.0), p(5.0, 0.0))],
            vec![Line(p(5.0, 0.0), ps)],
        ],
        _ => vec![
            vec![Line(ps, p(5.0, 0.0))],
            vec![Line(p(5.0, 0.0), p(5.0, 45.0))],
            vec![Line(p(5.0, 45.0), p(45.0, 45.0))],
            vec![Line(p(45.0, 45.0), p(45.0, 5.0))],
            vec![Line(p(45.0, 5.0), p(0.0, 5.0))],
            vec![Line(p(0.0, 5.0), ps)],
        ],
    }
}

#[test]
fn a_compensated_square_is_offset_by_r_with_quarter_circles_at_its_outside_corners() {
    for (comp, ccw) in [("RR", true), ("RL", false), ("RL", true), ("RR", false)] {
        let (prog, m, sim) = run(&square(";", comp, ccw));
        assert!(sim.error.is_none(), "{comp} ccw={ccw}: {:?}", sim.error);
        for (k, want) in square_paths(comp, ccw).iter().enumerate() {
            check(&prog, &m, &sim, 6 + k as u32, want, &untilted);
        }
        // After R0 the tool centre is on the programmed point again.
        assert_close!(after(&prog, &sim, 12).tip_ics, DVec3::new(-20.0, -20.0, 10.0), TOL);
    }
}

/// Rz(c)·Ry(b)·Rx(a) applied to v, written out (DOMAIN.md §2.1).
fn spatial(a: f64, b: f64, c: f64, v: DVec3) -> DVec3 {
    let (sa, ca) = a.to_radians().sin_cos();
    let (sb, cb) = b.to_radians().sin_cos();
    let (sc, cc) = c.to_radians().sin_cos();
    let x = DVec3::new(v.x, ca * v.y - sa * v.z, sa * v.y + ca * v.z);
    let y = DVec3::new(cb * x.x + sb * x.z, x.y, -sb * x.x + cb * x.z);
    DVec3::new(cc * y.x - sc * y.y, sc * y.x + cc * y.y, y.z)
}

#[test]
fn on_a_tilted_plane_the_square_is_compensated_in_the_working_plane() {
    for (a, b, c) in [(20.0, 15.0, 30.0), (-35.0, 10.0, -120.0), (0.0, -25.0, 75.0)] {
        let plane = format!("PLANE SPATIAL SPA{a:+} SPB{b:+} SPC{c:+} TURN FMAX");
        for (comp, ccw) in [("RR", true), ("RL", true)] {
            let (prog, m, sim) = run(&square(&plane, comp, ccw));
            assert!(sim.error.is_none(), "{plane} {comp}: {:?}", sim.error);
            for (k, want) in square_paths(comp, ccw).iter().enumerate() {
                check(&prog, &m, &sim, 6 + k as u32, want, &|v| spatial(a, b, c, v));
            }
        }
    }
}

#[test]
fn a_compensated_full_circle_has_the_radius_r_plus_or_minus_the_tool_radius() {
    // Contour radius 30 around (50,50); RL with DR+ (counter-clockwise) keeps the tool inside,
    // RL with DR− outside; RR the other way round. TOOL CALL DR+2 makes R = 5 + 2.
    for (extra, r) in [("", 5.0), (" DL+0 DR+2", 7.0)] {
        for (comp, dr, sign, inside) in [
            ("RL", "DR+", 1.0, true),
            ("RR", "DR+", 1.0, false),
            ("RL", "DR-", -1.0, false),
            ("RR", "DR-", -1.0, true),
        ] {
            let rho = if inside { 30.0 - r } else { 30.0 + r };
            let src = program(
                extra,
                &[
                    "L X+50 Y+50 Z+10 R0 FMAX",
                    "L Z-5 F500",
                    "CC X+50 Y+50",
                    &format!("L X+80 Y+50 {comp}"),
                    &format!("C X+80 Y+50 {dr}"),
                    "L X+50 Y+50 R0",
                ],
            );
            let (prog, m, sim) = run(&src);
            assert!(sim.error.is_none(), "{comp} {dr}: {:?}", sim.error);
            let want = [Piece::Arc(p(50.0, 50.0), rho, 0.0, sign * 360.0)];
            check(&prog, &m, &sim, 7, &want, &untilted);
            let s = after(&prog, &sim, 7);
            let SegmentPath::Arc(a) = &s.segments[0].path else { panic!("an arc") };
            assert_close!(a.radius(), rho, TOL, "{comp} {dr} R{r}");
        }
    }
}

fn error_of(src: &str) -> (u32, SimErrorCode, String) {
    let (prog, _, sim) = run(src);
    let e = sim.error.expect("an error");
    (prog.blocks[e.block].number().expect("numbered"), e.code, e.message.de.to_string())
}

#[test]
fn a_contour_too_small_for_the_tool_stops_at_its_block() {
    // An inside arc of radius 3 with a tool of radius 5.
    let (n, code, de) = error_of(&program(
        "",
        &["L X+50 Y+50 Z+10 R0 FMAX", "L Z-5 F500", "CC X+50 Y+50", "L X+53 Y+50 RL", "C X+53 Y+50 DR+"],
    ));
    assert_eq!((n, de.as_str()), (7, "Werkzeug-Radius zu groß"));
    assert_eq!(code, SimErrorCode::ToolRadiusTooLarge { radius: 5.0, contour_radius: 3.0 });
    // A step of 3 mm between two inside corners: the offset paths of its neighbours meet
    // beyond it (y = 5 and y = 3 − 5), so it vanishes.
    let (n, code, de) = error_of(&program(
        "",
        &["L X-20 Y+0 Z+10 R0 FMAX", "L Z-5 F500", "L X+0 Y+0 RL", "L X+50", "L Y+3", "L X+0", "L X-20 R0"],
    ));
    assert_eq!((n, de.as_str()), (7, "Werkzeug-Radius zu groß"));
    assert_eq!(code, SimErrorCode::ContourElementTooSmall { radius: 5.0 });
    // RL to RR without R0 between them (manual: a block with R0 must stand between).
    let (n, code, _) = error_of(&program(
        "",
        &["L X-20 Y+0 Z+10 R0 FMAX", "L Z-5 F500", "L X+0 Y+0 RL", "L X+50", "L Y+50 RR"],
    ));
    assert_eq!((n, code), (7, SimErrorCode::CompensationChange));
    // APPR without RL/RR.
    let (n, code, _) =
        error_of(&program("", &["L X-20 Y+0 Z-5 R0 FMAX", "APPR LT X+0 Y+0 LEN10 F300", "L X+50"]));
    assert_eq!(
        (n, code),
        (4, SimErrorCode::ApprDep { word: "APPR", kind: "LT", reason: ApprDepReason::NoCompensation })
    );
}

/// APPR in block 5, the contour `L X+50` from (0,0) in block 6, DEP in block 7; the tool stands
/// at `ps` (height −5) before.
fn appr_dep(ps: (f64, f64), appr: &str, dep: &str) -> String {
    program(
        "",
        &[
            &format!("L X{:+} Y{:+} Z+10 R0 FMAX", ps.0, ps.1),
            "L Z-5 F500",
            appr,
            "L X+50",
            dep,
            "L Z+10 R0 FMAX",
        ],
    )
}

#[test]
fn each_approach_kind_follows_its_auxiliary_point() {
    use Piece::{Arc, Line};
    // First contour element +X from PA = (0,0); RR puts the tool centre at PA_c = (0,−5).
    let ps = p(-30.0, -30.0);
    let pa_c = p(0.0, -5.0);
    let cases: [(&str, (f64, f64), Vec<Piece>); 5] = [
        // PH on the tangent, LEN before PA.
        (
            "APPR LT X+0 Y+0 LEN10 RR F300",
            (-30.0, -30.0),
            vec![Line(ps, p(-10.0, -5.0)), Line(p(-10.0, -5.0), pa_c)],
        ),
        // PH perpendicular, LEN + R from PA.
        (
            "APPR LN X+0 Y+0 LEN10 RR F300",
            (-30.0, -30.0),
            vec![Line(ps, p(0.0, -15.0)), Line(p(0.0, -15.0), pa_c)],
        ),
        // RR with R+: clockwise; centre R below PA_c, PH a quarter turn before.
        (
            "APPR CT X+0 Y+0 CCA90 R+10 RR F300",
            (-30.0, -30.0),
            vec![Line(ps, p(-10.0, -15.0)), Arc(p(0.0, -15.0), 10.0, 180.0, -90.0)],
        ),
        // RL with R+: counter-clockwise, centre above PA_c = (0,5).
        (
            "APPR CT X+0 Y+0 CCA90 R+10 RL F300",
            (-30.0, -30.0),
            vec![Line(ps, p(-10.0, 15.0)), Arc(p(0.0, 15.0), 10.0, 180.0, 90.0)],
        ),
        // The line from PS = (−10,−40) straight up touches the circle around (0,−15) at (−10,−15).
        (
            "APPR LCT X+0 Y+0 R10 RR F300",
            (-10.0, -40.0),
            vec![Line(p(-10.0, -40.0), p(-10.0, -15.0)), Arc(p(0.0, -15.0), 10.0, 180.0, -90.0)],
        ),
    ];
    for (appr, start, want) in cases {
        let (prog, m, sim) = run(&appr_dep(start, appr, "DEP LT LEN10 F300"));
        assert!(sim.error.is_none(), "{appr}: {:?}", sim.error);
        check(&prog, &m, &sim, 5, &want, &untilted);
        let y = if appr.contains("RL") { 5.0 } else { -5.0 };
        check(&prog, &m, &sim, 6, &[Line(p(0.0, y), p(50.0, y))], &untilted);
    }
    // The tool axis moves on the way to PH.
    let src = program("", &["L X-30 Y-30 Z+10 R0 FMAX", "APPR LT X+0 Y+0 Z-5 LEN10 RR F300", "L X+50"]);
    let (prog, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    check(
        &prog,
        &m,
        &sim,
        4,
        &[Line(DVec3::new(-30.0, -30.0, 10.0), p(-10.0, -5.0)), Line(p(-10.0, -5.0), pa_c)],
        &untilted,
    );
}

#[test]
fn each_departure_kind_leaves_from_the_last_contour_point() {
    use Piece::{Arc, Line};
    // The contour ends at PE = (50,0) heading +X; RR: the tool centre stands at (50,−5).
    let pe_c = p(50.0, -5.0);
    let cases: [(&str, Vec<Piece>, DVec3); 4] = [
        ("DEP LT LEN10 F300", vec![Line(pe_c, p(60.0, -5.0))], p(60.0, -5.0)),
        ("DEP LN LEN10 F300", vec![Line(pe_c, p(50.0, -15.0))], p(50.0, -15.0)),
        ("DEP CT CCA90 R+10 F300", vec![Arc(p(50.0, -15.0), 10.0, 90.0, -90.0)], p(60.0, -15.0)),
        (
            "DEP LCT X+60 Y-40 Z+10 R10 F300",
            vec![Arc(p(50.0, -15.0), 10.0, 90.0, -90.0), Line(p(60.0, -15.0), DVec3::new(60.0, -40.0, 10.0))],
            DVec3::new(60.0, -40.0, 10.0),
        ),
    ];
    for (dep, want, end) in cases {
        let (prog, m, sim) = run(&appr_dep((-30.0, -30.0), "APPR LT X+0 Y+0 LEN10 RR F300", dep));
        assert!(sim.error.is_none(), "{dep}: {:?}", sim.error);
        check(&prog, &m, &sim, 7, &want, &untilted);
        // The compensation is off: the next block moves the tool centre to its programmed point.
        assert_close!(after(&prog, &sim, 8).tip_ics, DVec3::new(end.x, end.y, 10.0), TOL, "{dep}");
    }
}

#[test]
fn the_compensated_fixture_runs_without_errors_on_every_machine() {
    let path = format!("{}/../tests/fixtures/sim/contour_rl.h", env!("CARGO_MANIFEST_DIR"));
    let (p, d) = parse(&std::fs::read_to_string(&path).expect("fixture"));
    assert!(d.is_empty(), "{d:?}");
    for id in ["ac-table", "ba-table", "bc-head-table", "ca-head", "b45-nutating"] {
        let m = Machine::builtin(id).expect("machine");
        let sim = simulate(&p, &m, &SimOptions::default());
        assert!(sim.error.is_none(), "contour_rl on {id}: {:?}", sim.error);
    }
}

#[test]
fn blocks_without_motion_between_two_elements_keep_the_inside_corner() {
    use Piece::Line;
    // RL on a left turn: an inside corner at (50,0), also with M8 and an `L` without axes
    // between the two elements; the compensation stays on through them.
    let src = program(
        "",
        &[
            "L X-20 Y+0 Z+10 R0 FMAX",
            "L Z-5 F500",
            "L X+0 Y+0 RL",
            "L X+50",
            "M8",
            "L F400",
            "L Y+50",
            "L X+70 Y+70 R0",
        ],
    );
    let (prog, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    check(&prog, &m, &sim, 6, &[Line(p(0.0, 5.0), p(45.0, 5.0))], &untilted);
    check(&prog, &m, &sim, 9, &[Line(p(45.0, 5.0), p(45.0, 50.0))], &untilted);
    check(&prog, &m, &sim, 10, &[Line(p(45.0, 50.0), p(70.0, 70.0))], &untilted);
}

#[test]
fn an_inside_corner_between_a_line_and_an_arc_ends_on_the_grown_circle() {
    use Piece::{Arc, Line};
    // RL: the line +X to (50,0), then clockwise around (70,0) (radius 20) heading +Y: a left
    // turn, inside. The line's path y = 5 meets the arc's path, radius 20 + 5 (RL is outside a
    // clockwise arc), at x = 70 − √(25² − 5²).
    let x = 70.0 - (25.0_f64 * 25.0 - 25.0).sqrt();
    let from = 5.0_f64.atan2(x - 70.0).to_degrees();
    let src = program(
        "",
        &[
            "L X-20 Y+0 Z+10 R0 FMAX",
            "L Z-5 F500",
            "L X+0 Y+0 RL",
            "L X+50",
            "CC X+70 Y+0",
            "C X+90 Y+0 DR-",
            "L X+120 R0",
        ],
    );
    let (prog, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    check(&prog, &m, &sim, 6, &[Line(p(0.0, 5.0), p(x, 5.0))], &untilted);
    check(&prog, &m, &sim, 8, &[Arc(p(70.0, 0.0), 25.0, from, -from)], &untilted);
    check(&prog, &m, &sim, 9, &[Line(p(95.0, 0.0), p(120.0, 0.0))], &untilted);
}

#[test]
fn an_inside_rounding_of_the_tool_radius_leaves_the_tool_standing_at_its_centre() {
    use Piece::Line;
    // RND R5 at the inside corner (50,0) of RL with R = 5: its path shrinks to its centre (45,5).
    let src = program(
        "",
        &[
            "L X-20 Y+0 Z+10 R0 FMAX",
            "L Z-5 F500",
            "L X+0 Y+0 RL",
            "L X+50",
            "RND R5",
            "L Y+50",
            "L X+70 Y+70 R0",
        ],
    );
    let (prog, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    check(&prog, &m, &sim, 6, &[Line(p(0.0, 5.0), p(45.0, 5.0))], &untilted);
    check(&prog, &m, &sim, 7, &[], &untilted);
    check(&prog, &m, &sim, 8, &[Line(p(45.0, 5.0), p(45.0, 50.0))], &untilted);
    // R4.9 is smaller than the tool: the control's error on the RND block.
    let (n, code, _) = error_of(&src.replace("RND R5", "RND R4.9"));
    assert_eq!(n, 7);
    assert!(matches!(code, SimErrorCode::ToolRadiusTooLarge { .. }), "{code:?}");
}

proptest::proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(256))]
    /// Any mix of compensated contour blocks, approach and departure with random numbers never
    /// panics; every segment stays finite and evaluable, and every recorded step can be stepped to.
    #[test]
    fn random_compensated_contours_never_panic(
        picks in proptest::collection::vec((0usize..20, -80.0..80.0f64, 0u32..4), 1..24),
        machine in 0usize..5,
    ) {
        let comp = |n: u32| ["RL", "RR", "R0", ""][n as usize % 4];
        let vocab = |k: usize, v: f64, n: u32| -> String {
            match k {
                0 => format!("L X{v:+.2} Y{:+.2} {}", v / 3.0, comp(n)),
                1 => format!("L X{v:+.2} {}", comp(n)),
                2 => format!("L Y{v:+.2}"),
                3 => format!("CC X{:+.2} Y{:+.2}", v / 2.0, v / 5.0),
                4 => format!("C X{:+.2} Y{v:+.2} DR{} {}", v / 2.0, if n % 2 == 0 { '+' } else { '-' }, comp(n)),
                5 => format!("CR X{v:+.2} Y{:+.2} R{:+.2} DR-", v / 3.0, v / (f64::from(n) - 1.5)),
                6 => format!("CT X{:+.2} Y{v:+.2}", v / 7.0),
                7 => format!("RND R{:+.2}", v.abs() / 10.0),
                8 => format!("CHF {:+.2}", v.abs() / 20.0),
                9 => format!("APPR LT X{v:+.2} Y+0 LEN{:+.1} RL F200", v.abs() / 8.0),
                10 => format!("APPR LN X+0 Y{v:+.2} LEN{:+.1} RR F200", v.abs() / 8.0),
                11 => format!("APPR CT X{v:+.2} Y+5 CCA{:.1} R{:+.1} {} F200", v.abs(), v / 9.0, comp(n)),
                12 => format!("APPR LCT X{v:+.2} Y+0 R{:.1} RL F200", v.abs() / 6.0),
                13 => format!("DEP LT LEN{:+.1} F200", v.abs() / 4.0),
                14 => format!("DEP LN LEN{:+.1}", v.abs() / 4.0),
                15 => format!("DEP CT CCA{:.1} R{:+.1}", v.abs() * 2.0, v / 7.0),
                16 => format!("DEP LCT X{v:+.2} Y{:+.2} R{:.1}", v / 2.0, v.abs() / 9.0),
                17 => format!("L Z{:+.2}", v / 20.0),
                18 => format!("TOOL CALL 1 Z S1000 DL+0 DR{:+.2}", v / 40.0),
                _ => format!("LP PR{:+.2} IPA{v:+.1} {}", v.abs() / 3.0, comp(n)),
            }
        };
        let mut src = String::from("0 BEGIN PGM R MM\n1 TOOL CALL 1 Z S1000 F500\n2 L Z-5 R0 F500\n");
        for (i, (k, v, n)) in picks.iter().enumerate() {
            src.push_str(&format!("{} {}\n", i + 3, vocab(*k, *v, *n)));
        }
        src.push_str(&format!("{} END PGM R MM\n", picks.len() + 3));
        let (p, _) = parse(&src);
        let ids = Machine::builtin_ids();
        let m = Machine::builtin(ids[machine % ids.len()]).expect("machine");
        let sim = simulate(&p, &m, &SimOptions { max_steps: Some(2_000), checkpoint_interval: 5, ..SimOptions::default() });
        let n = sim.len();
        for s in sim.states(&p) {
            for seg in &s.segments {
                for f in [0.0, 0.5, 1.0] {
                    proptest::prop_assert!(seg.axes_at(f).linear.is_finite(), "{src}");
                }
                proptest::prop_assert!(seg.duration.is_finite() && seg.duration >= 0.0);
            }
        }
        if n > 0 {
            proptest::prop_assert!(sim.state_at(&p, n - 1).is_some());
        }
    }
}

/// Distance from `q` to the segment `a`–`b` in the XY plane.
fn to_segment(q: DVec3, a: DVec3, b: DVec3) -> f64 {
    let (q, a, b) = (q.truncate(), a.truncate(), b.truncate());
    let d = b - a;
    let f = ((q - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + f * d).distance(q)
}

proptest::proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(256))]
    /// RR around any convex polygon run counter-clockwise: every corner is an outside corner, so
    /// every point of the tool centre path is exactly R + DR from the polygon (its distance to
    /// the nearest edge, computed here), on every block of the contour.
    #[test]
    fn around_a_convex_polygon_the_tool_centre_keeps_the_distance_r(
        angles in proptest::collection::btree_set(0u32..360, 3..8),
        dr in -2.0..2.0f64,
    ) {
        let corners: Vec<DVec3> = angles
            .iter()
            .map(|&a| {
                let t = f64::from(a).to_radians();
                p(40.0 * t.cos(), 40.0 * t.sin())
            })
            .collect();
        let edges = corners.len();
        // Every edge must turn left at its end (a strictly convex polygon).
        let turns_left = (0..edges).all(|i| {
            let (a, b, c) = (corners[i], corners[(i + 1) % edges], corners[(i + 2) % edges]);
            (b - a).truncate().perp_dot((c - b).truncate()) > 1e-3
        });
        proptest::prop_assume!(turns_left);
        let mut body = vec!["L X-90 Y-90 Z+10 R0 FMAX".to_string(), "L Z-5 F500".to_string()];
        body.push(format!("L X{:+.9} Y{:+.9} RR", corners[0].x, corners[0].y));
        for k in 1..=edges {
            let c = corners[k % edges];
            body.push(format!("L X{:+.9} Y{:+.9}", c.x, c.y));
        }
        body.push("L X-90 Y-90 R0".to_string());
        let refs: Vec<&str> = body.iter().map(String::as_str).collect();
        let (prog, m, sim) = run(&program(&format!(" DL+0 DR{dr:+.6}"), &refs));
        proptest::prop_assert!(sim.error.is_none(), "{:?}", sim.error);
        let r = 5.0 + (dr * 1e6).round() / 1e6;
        for k in 1..=edges {
            let s = after(&prog, &sim, 5 + k as u32);
            let kin = Kin::new(&m, s.tool.length);
            for seg in &s.segments {
                for i in 0..=10 {
                    let q = kin.tip_wcs(&seg.axes_at(f64::from(i) / 10.0));
                    let d = (0..edges)
                        .map(|e| to_segment(q, corners[e], corners[(e + 1) % edges]))
                        .fold(f64::INFINITY, f64::min);
                    proptest::prop_assert!((d - r).abs() < 1e-6, "edge {k}: {q} is {d} from the polygon, not {r}");
                }
            }
        }
    }
}

#[test]
fn a_reversal_is_an_outside_corner_with_a_half_circle() {
    use Piece::{Arc, Line};
    // RR: along +X to (50,0) and straight back: the tool goes round the end on a half circle.
    let src = program(
        "",
        &["L X-20 Y-20 Z+10 R0 FMAX", "L Z-5 F500", "L X+0 Y+0 RR", "L X+50", "L X+10", "L X-20 Y-20 R0"],
    );
    let (prog, m, sim) = run(&src);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    check(&prog, &m, &sim, 6, &[Line(p(0.0, -5.0), p(50.0, -5.0))], &untilted);
    check(
        &prog,
        &m,
        &sim,
        7,
        &[Arc(p(50.0, 0.0), 5.0, -90.0, 180.0), Line(p(50.0, 5.0), p(10.0, 5.0))],
        &untilted,
    );
}
