//! TCPM (M128/M129 and FUNCTION TCPM / FUNCTION RESET TCPM, issue 17): with TCPM active a
//! block with rotary axes keeps the tool tip on the programmed point in the W-CS while the
//! linear axes compensate, at the block's end and all along its motion; M129 and FUNCTION RESET
//! TCPM cancel it. The oracle is the rigid-body forward model (`Kin::tip_wcs` of the simulated
//! axes), not the inverse map the simulator uses.

use glam::DVec3;
use proptest::prelude::*;
use schwenkbar_core::ast::{PathCtrl, Tcpm, TcpmAxis, TcpmFeed};
use schwenkbar_core::diag::{DiagCode, Expected};
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Kin, SegmentPath, SimErrorCode, SimOptions, Simulation, simulate};
use schwenkbar_core::{BlockBody, Lang, format_program, parse};
use schwenkbar_testkit::assert_close;

/// The tool tip along a compensated rotary move (issue 17).
const TIP: f64 = 1e-6;

/// The shipped machines without their collision bodies: the random poses here put the tool
/// anywhere near the table, and what is checked is where TCPM puts the tip, not whether the
/// machine hits itself (`core/tests/collision.rs`).
fn machines() -> Vec<Machine> {
    Machine::builtin_ids()
        .iter()
        .filter_map(|id| Machine::builtin(id).ok())
        .map(|mut m| {
            m.bodies.clear();
            m
        })
        .collect()
}

/// `A+12.5 C-30` for the machine's two rotary axes.
fn rotary_words(m: &Machine, a: [f64; 2]) -> String {
    let j = m.joints();
    format!("{}{:+} {}{:+}", j[0].axis.letter(), a[0], j[1].axis.letter(), a[1])
}

/// A rotary target inside the axis' limits: `u` ∈ [0, 1) across the range (±120° when endless
/// or unlimited).
fn inside(m: &Machine, u: [f64; 2]) -> [f64; 2] {
    let j = m.joints();
    let pick = |k: usize| match j[k].limits.filter(|_| !j[k].endless) {
        Some(l) => {
            let (lo, hi) = (l.min.max(-120.0), l.max.min(120.0));
            lo + u[k] * (hi - lo)
        }
        None => -120.0 + u[k] * 240.0,
    };
    // Four decimals, as a program writes them.
    [(pick(0) * 1e4).round() / 1e4, (pick(1) * 1e4).round() / 1e4]
}

/// The tip (W-CS) after each step and along every segment, by the forward model.
fn tips_along(m: &Machine, program: &str) -> (Simulation, Vec<(DVec3, Vec<DVec3>)>) {
    let (p, diags) = parse(program);
    assert!(diags.iter().all(|d| !d.is_error()), "{program}: {diags:?}");
    let sim = simulate(&p, m, &SimOptions::default());
    let tips = sim
        .states(&p)
        .map(|s| {
            let kin = Kin::new(m, s.tool.length);
            let along = s
                .segments
                .iter()
                .flat_map(|seg| (0..=8).map(move |k| seg.axes_at(f64::from(k) / 8.0)))
                .map(|a| kin.tip_wcs(&a))
                .collect();
            (s.tip_wcs, along)
        })
        .collect();
    (sim, tips)
}

/// How the generated program switches TCPM on and off.
#[derive(Debug, Clone, Copy)]
enum Switch {
    /// `M128` in the first rotary move (it acts from that block's start), `M129` alone.
    M128,
    /// `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS` and `FUNCTION RESET TCPM`, each alone.
    Function,
}

/// Where a [`tcpm_program`]'s steps are: the steps that hold the tip (the switching block and
/// the two rotary moves), then the move with X +5 mm, the block that switches TCPM off and a
/// rotary move after it.
struct Steps {
    held: std::ops::Range<usize>,
    straight: usize,
    off: usize,
    after: usize,
}

/// From `start`: rotary moves to `a` and `b` under TCPM, X +5 mm with a move to `c`, TCPM off,
/// back to `a` with the linear axes left alone.
fn tcpm_program(m: &Machine, switch: Switch, start: DVec3, [a, b, c]: [[f64; 2]; 3]) -> (String, Steps) {
    let (a, b, c) = (rotary_words(m, a), rotary_words(m, b), rotary_words(m, c));
    let x = start.x + 5.0;
    let head = format!(
        "0 BEGIN PGM TCPM MM\n1 TOOL CALL 1 Z S2000\n2 L X{:+.4} Y{:+.4} Z{:+.4} R0 FMAX\n",
        start.x, start.y, start.z
    );
    match switch {
        Switch::M128 => (
            format!(
                "{head}3 L {a} F1000 M128\n4 L {b} F1000\n5 L X{x:+.4} {c} F1000\n6 M129\n7 L {a} FMAX\n8 END PGM TCPM MM\n"
            ),
            Steps { held: 3..5, straight: 5, off: 6, after: 7 },
        ),
        Switch::Function => (
            format!(
                "{head}3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n4 L {a} F1000\n5 L {b} F1000\n6 L X{x:+.4} {c} F1000\n7 FUNCTION RESET TCPM\n8 L {a} FMAX\n9 END PGM TCPM MM\n"
            ),
            Steps { held: 3..6, straight: 6, off: 7, after: 8 },
        ),
    }
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(40))]

    /// M128 and FUNCTION TCPM keep the tip, on every machine and for the same poses: the steps
    /// under TCPM with rotary axes only hold it at the programmed point, the step with X +5 mm
    /// runs it straight; M129 / FUNCTION RESET TCPM cancel it: the rotary move after them leaves
    /// the linear axes where they are (the tip goes with the table or the head).
    #[test]
    fn tcpm_keeps_the_tool_tip_and_its_reset_cancels_it(
        x in -40.0..40.0f64, y in -40.0..40.0f64, z in 0.0..60.0f64,
        u in prop::array::uniform6(0.0..1.0f64),
    ) {
        for switch in [Switch::M128, Switch::Function] {
            let mut checked = 0;
            for m in machines() {
                // Near the table, or 150 mm higher where a swivel head would leave the Z travel.
                let runs = [0.0, 150.0].into_iter().find_map(|lift| {
                    let start = DVec3::new((x * 1e4).round() / 1e4, (y * 1e4).round() / 1e4, (z * 1e4).round() / 1e4 + lift);
                    let poses = [inside(&m, [u[0], u[1]]), inside(&m, [u[2], u[3]]), inside(&m, [u[4], u[5]])];
                    let (text, steps) = tcpm_program(&m, switch, start, poses);
                    let (sim, tips) = tips_along(&m, &text);
                    // A compensated position outside the travel is the control's limit error.
                    sim.error.is_none().then_some((text, steps, sim, tips))
                });
                let Some((text, steps, sim, tips)) = runs else { continue };
                checked += 1;
                let tip = tips[2].0;
                for step in steps.held {
                    assert_close!(tips[step].0, tip, TIP, "{} {switch:?} step {step}\n{text}", m.id);
                    for along in &tips[step].1 {
                        assert_close!(*along, tip, TIP, "{} {switch:?} along step {step}\n{text}", m.id);
                    }
                }
                let moved = tip + DVec3::X * 5.0;
                let straight = &tips[steps.straight];
                assert_close!(straight.0, moved, TIP, "{} {switch:?} step {}\n{text}", m.id, steps.straight);
                let n = straight.1.len();
                for (k, along) in straight.1.iter().enumerate() {
                    // Evenly spaced on the straight line from `tip` to `moved`.
                    let expected = tip.lerp(moved, k as f64 / (n - 1) as f64);
                    assert_close!(*along, expected, TIP, "{} {switch:?} along step {}\n{text}", m.id, steps.straight);
                }
                assert_close!(tips[steps.off].0, moved, TIP, "{} {switch:?} TCPM off\n{text}", m.id);
                let (p, _) = parse(&text);
                let states: Vec<_> = sim.states(&p).collect();
                assert_close!(
                    states[steps.after].axes.linear, states[steps.off].axes.linear, 1e-9,
                    "{} {switch:?} after TCPM off\n{text}", m.id
                );
            }
            prop_assert!(checked >= 4, "{switch:?}: only {checked} machines could run the case");
        }
    }
}

/// Without M128 (and without a tilt) a rotary move leaves the linear axes where they are: the
/// tip travels with the table or the head. With M128 the same block keeps it; after M129 it
/// travels again.
#[test]
fn without_m128_a_rotary_move_carries_the_tip_along() {
    let m = Machine::builtin("ac-table").expect("shipped");
    let text = "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+20 Y+10 Z+30 R0 FMAX\n3 L A+30 C+45 FMAX\n4 L A+0 C+0 FMAX M128\n5 L A+30 C+45 FMAX\n6 L A+0 C+0 FMAX M129\n7 L A+30 C+45 FMAX\n8 END PGM T MM\n";
    let (sim, tips) = tips_along(&m, text);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let start = tips[2].0;
    assert!((tips[3].0 - start).length() > 10.0, "the tip went with the table: {:?}", tips[3].0);
    assert_close!(tips[4].0, tips[3].0, TIP, "M128 from the block's start holds the tip");
    assert_close!(tips[5].0, tips[3].0, TIP, "TCPM holds it");
    assert_close!(tips[6].0, tips[3].0, TIP, "M129 acts at the block's end");
    assert!((tips[7].0 - tips[6].0).length() > 10.0, "after M129 the tip moves again");
    // The compensated blocks are drawn as TCPM paths, the others as straight axis moves.
    let (p, _) = parse(text);
    let kinds: Vec<bool> =
        sim.states(&p).map(|s| s.segments.iter().any(|g| matches!(g.path, SegmentPath::Tcpm(_)))).collect();
    assert_eq!(kinds, [false, false, false, false, true, true, true, false, false]);
}

/// The run says when TCPM goes on and off, in German and English.
#[test]
fn m128_and_m129_are_said_in_the_run() {
    let m = Machine::builtin("ac-table").expect("shipped");
    let (p, _) = parse("0 BEGIN PGM T MM\n1 M128\n2 L A+10 FMAX\n3 M129\n4 END PGM T MM\n");
    let sim = simulate(&p, &m, &SimOptions::default());
    let messages: Vec<_> = sim.states(&p).map(|s| s.message()).collect();
    let on = messages[1].as_ref().expect("M128 said");
    assert!(on.de.contains("TCPM aktiv") && on.en.contains("TCPM on"), "{on:?}");
    let off = messages[3].as_ref().expect("M129 said");
    assert!(off.de.contains("TCPM aus") && off.en.contains("TCPM off"), "{off:?}");
}

/// The same moves under FUNCTION TCPM … AXIS POS and under M128 give the same axes, step by step.
#[test]
fn function_tcpm_moves_the_axes_as_m128_does() {
    let m = Machine::builtin("ac-table").expect("shipped");
    let moves = "2 L X+20 Y+10 Z+30 R0 FMAX\n4 L A+30 C+45 F1000\n5 L X+25 A-10 C+90 F1000\n";
    let with = |on: &str, off: &str| {
        let text = format!(
            "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n3 {on}\n{moves}6 {off}\n7 L A+0 C+0 FMAX\n8 END PGM T MM\n"
        );
        let (p, _) = parse(&text);
        let sim = simulate(&p, &m, &SimOptions::default());
        assert!(sim.error.is_none(), "{:?}", sim.error);
        sim.states(&p).map(|s| (s.axes.linear, s.axes.rotary)).collect::<Vec<_>>()
    };
    let function = with("FUNCTION TCPM F CONT AXIS POS PATHCTRL VECTOR", "FUNCTION RESET TCPM");
    let m128 = with("M128", "M129");
    assert_eq!(function.len(), m128.len());
    for (k, (f, m)) in function.iter().zip(&m128).enumerate() {
        assert_close!(f.0, m.0, 1e-9, "linear axes at step {k}");
        assert_eq!(f.1, m.1, "rotary axes at step {k}");
    }
}

fn run_error(text: &str) -> (usize, SimErrorCode, schwenkbar_core::Text) {
    let m = Machine::builtin("ac-table").expect("shipped");
    let (p, diags) = parse(text);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let e = simulate(&p, &m, &SimOptions::default()).error.expect("the run stops");
    (e.block, e.code, e.message)
}

/// The tool axis (tip → spindle, W-CS) of a state's axes, by the forward model (the head's
/// pose applied to Z, seen from the workpiece's pose), not the solver that chose the axes.
fn tool_axis_wcs(m: &Machine, s: &schwenkbar_core::sim::State) -> DVec3 {
    Kin::new(m, s.tool.length).tool_axis_wcs(s.axes.rotary)
}

/// The states of a program that runs to its end.
fn states(m: &Machine, program: &str) -> Vec<schwenkbar_core::sim::State> {
    let (p, diags) = parse(program);
    assert!(diags.iter().all(|d| !d.is_error()), "{program}: {diags:?}");
    let sim = simulate(&p, m, &SimOptions::default());
    assert!(sim.error.is_none(), "{}: {:?}", m.id, sim.error);
    sim.states(&p).collect()
}

/// AXIS SPAT (iTNC 530 manual, "Interpretation of the programmed rotary axis coordinates": `L
/// A+0 B+45 C+0` sets the tool orientation to the spatial angle B+45): on every machine the
/// tool axis ends at (sin 45°, 0, cos 45°) in the W-CS, worked by hand, and the tip stays on
/// the programmed point at the end and all along the swivel.
#[test]
fn axis_spat_b45_tilts_the_tool_45_degrees_about_y_and_keeps_the_tip() {
    let want = DVec3::new(45f64.to_radians().sin(), 0.0, 45f64.to_radians().cos());
    for m in machines() {
        let text = "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+10 Y+5 Z+150 R0 FMAX\n3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n4 L A+0 B+45 C+0 F1000\n5 END PGM T MM\n";
        let (sim, tips) = tips_along(&m, text);
        assert!(sim.error.is_none(), "{}: {:?}", m.id, sim.error);
        let s = states(&m, text);
        assert_close!(tool_axis_wcs(&m, &s[4]), want, 1e-9, "{}: tool axis", m.id);
        assert_close!(tool_axis_wcs(&m, &s[2]), DVec3::Z, 1e-9, "{}: upright before", m.id);
        let held = tips[2].0;
        assert_close!(held, DVec3::new(10.0, 5.0, 150.0), 1e-9, "{}", m.id);
        for (k, (tip, along)) in tips.iter().enumerate().skip(3) {
            assert_close!(*tip, held, TIP, "{}: tip after step {k}", m.id);
            for (i, a) in along.iter().enumerate() {
                assert_close!(*a, held, TIP, "{}: tip along step {k} at {i}/8", m.id);
            }
        }
        let e = s[4].explanation.as_ref().expect("the why panel gets the choice");
        assert!(e.decisions.contains(&schwenkbar_core::unconfirmed::Decision::TcpmAxisSpat));
        let note = s[4].message().expect("a note");
        assert!(note.de.starts_with("AXIS SPAT: SPA+0 SPB+45 SPC+0 → "), "{}", note.de);
    }
}

/// The spatial angles are relative to the active (tilted) coordinate system and modal: after
/// PLANE SPATIAL SPB+30, `B+15` makes 45° about Y; `IB+5` then 50°; `A+20` tilts about the
/// plane's X as well: t = Ry(30°)·Ry(15°)·Rx(20°)·ez, by hand (sin45·cos20, −sin20, cos45·cos20).
/// A and C missing in the first block count as 0° with a note. A block without A, B, C leaves
/// the rotary axes where they are.
#[test]
fn axis_spat_angles_are_relative_to_the_tilted_plane_and_modal() {
    let m = Machine::builtin("bc-head-table").expect("shipped");
    let text = "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+0 Y+0 Z+150 R0 FMAX\n3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN F2000\n4 L X+0 Y+0 Z+100 R0 FMAX\n5 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n6 L B+15 F1000\n7 L IB+5 F1000\n8 L X+5 F1000\n9 L B+15 A+20 F1000\n10 END PGM T MM\n";
    let s = states(&m, text);
    let (s45, c45) = (45f64.to_radians().sin(), 45f64.to_radians().cos());
    let (s50, c50) = (50f64.to_radians().sin(), 50f64.to_radians().cos());
    let (s20, c20) = (20f64.to_radians().sin(), 20f64.to_radians().cos());
    let (s30, c30) = (30f64.to_radians().sin(), 30f64.to_radians().cos());
    assert_close!(tool_axis_wcs(&m, &s[4]), DVec3::new(s30, 0.0, c30), 1e-9, "the plane");
    assert_close!(tool_axis_wcs(&m, &s[6]), DVec3::new(s45, 0.0, c45), 1e-9, "B+15 on SPB+30");
    let note = s[6].message().expect("a note");
    assert!(
        note.de.contains("fehlende gelten als 0°") && note.en.contains("missing ones count as 0°"),
        "{}",
        note.de
    );
    assert_close!(tool_axis_wcs(&m, &s[7]), DVec3::new(s50, 0.0, c50), 1e-9, "IB+5");
    assert!(!s[7].message().expect("a note").de.contains("fehlende"));
    assert_eq!(s[8].axes.rotary, s[7].axes.rotary, "a block without A, B, C keeps the rotary axes");
    assert_close!(
        tool_axis_wcs(&m, &s[9]),
        DVec3::new(s45 * c20, -s20, c45 * c20),
        1e-9,
        "A+20, B back to 15"
    );
    // The tip stays where block 8 left it (5 mm along the plane's X).
    assert_close!(s[9].tip_wcs, s[8].tip_wcs, TIP);
    assert_close!(s[8].tip_wcs - s[7].tip_wcs, DVec3::new(5.0 * c30, 0.0, -5.0 * s30), 1e-9);
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(40))]

    /// AXIS SPAT on every machine, random spatial angles with tilts up to 60° (inside every
    /// shipped machine's reach near the table): the tool axis ends at Rz(C)·Ry(B)·Rx(A)·ez (the
    /// product written out here by hand) and the tip stays at the programmed point.
    #[test]
    fn axis_spat_reaches_the_spatial_angles_on_every_machine(
        a in -60.0..60.0f64, b in -60.0..60.0f64, c in -180.0..180.0f64,
    ) {
        let (a, b, c) = ((a * 100.0).round() / 100.0, (b * 100.0).round() / 100.0, (c * 100.0).round() / 100.0);
        let (sa, ca) = a.to_radians().sin_cos();
        let (sb, cb) = b.to_radians().sin_cos();
        let (sc, cc) = c.to_radians().sin_cos();
        // Rx(A)·ez = (0, −sA, cA); Ry(B) then Rz(C).
        let (x, y, z) = (sb * ca, -sa, cb * ca);
        let want = DVec3::new(cc * x - sc * y, sc * x + cc * y, z);
        let text = format!("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+10 Y-5 Z+20 R0 FMAX\n3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n4 L A{a:+} B{b:+} C{c:+} F1000\n5 END PGM T MM\n");
        for m in machines() {
            let (p, _) = parse(&text);
            let sim = simulate(&p, &m, &SimOptions::default());
            prop_assert!(sim.error.is_none(), "{}: {:?}", m.id, sim.error);
            let s: Vec<_> = sim.states(&p).collect();
            let t = tool_axis_wcs(&m, &s[4]);
            prop_assert!((t - want).length() < 1e-9, "{}: {t} vs {want}", m.id);
            prop_assert!((s[4].tip_wcs - DVec3::new(10.0, -5.0, 20.0)).length() < TIP, "{}: tip {}", m.id, s[4].tip_wcs);
        }
    }
}

/// An orientation the machine cannot reach stops the run on the positioning block with the
/// solver's message; FUNCTION RESET TCPM and M129 end AXIS SPAT (A, B, C are axis angles again).
#[test]
fn axis_spat_unreachable_stops_and_the_reset_ends_it() {
    let m = Machine::builtin("bc-head-table").expect("shipped");
    let (p, _) = parse(
        "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+0 Y+0 Z+150 R0 FMAX\n3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n4 L A+0 B+130 C+0 F1000\n5 END PGM T MM\n",
    );
    let e = simulate(&p, &m, &SimOptions::default()).error.expect("B ±130 is outside −110…110");
    assert_eq!(e.block, 4);
    assert!(matches!(e.code, SimErrorCode::Solve { .. }), "{:?}", e.code);
    for reset in ["FUNCTION RESET TCPM", "M129"] {
        let text = format!(
            "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 L X+0 Y+0 Z+150 R0 FMAX\n3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n4 L A+0 B+20 C+0 F1000\n5 {reset}\n6 L B+10 C+30 F1000\n7 END PGM T MM\n"
        );
        let s = states(&m, &text);
        let b = m.joints().iter().position(|j| j.axis.letter() == 'B').expect("B");
        assert_close!(s[6].axes.rotary[b], 10.0, 1e-9, "{reset}: B+10 is the axis angle");
        assert_close!(s[6].axes.rotary[1 - b], 30.0, 1e-9, "{reset}: C+30 is the axis angle");
    }
}

/// TOOL CALL, M91 and M92 with TCPM on (either kind) stop the run (DOMAIN.md §6: reset
/// before them); after the reset they run.
#[test]
fn tool_call_and_m91_m92_need_tcpm_reset_first() {
    for (on, block, word) in [
        ("FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", "TOOL CALL 2 Z S3000", "TOOL CALL"),
        ("M128", "TOOL CALL 2 Z S3000", "TOOL CALL"),
        ("FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", "L Z-10 R0 FMAX M91", "M91"),
        ("M128", "L Z-10 R0 FMAX M92", "M92"),
    ] {
        let text = format!("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 {on}\n3 {block}\n4 END PGM T MM\n");
        let (at, code, message) = run_error(&text);
        assert_eq!((at, code), (3, SimErrorCode::TcpmActive { word }), "{text}");
        assert!(message.de.contains("TCPM") && message.en.contains("TCPM"), "{message:?}");
        for off in ["FUNCTION RESET TCPM", "M129"] {
            let text = format!(
                "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S2000\n2 {on}\n3 {off}\n4 {block}\n5 END PGM T MM\n"
            );
            let m = Machine::builtin("ac-table").expect("shipped");
            let (p, _) = parse(&text);
            let error = simulate(&p, &m, &SimOptions::default()).error;
            assert!(error.is_none(), "{text}{error:?}");
        }
    }
}

/// Every combination of the three modes is read into the typed block and written back exactly.
#[test]
fn function_tcpm_parses_and_formats_back_exactly() {
    for feed in [TcpmFeed::Tcp, TcpmFeed::Cont] {
        for axis in [TcpmAxis::Pos, TcpmAxis::Spat] {
            for path in [PathCtrl::Axis, PathCtrl::Vector] {
                let t = Tcpm { feed, axis, path };
                let [f, a, c] = t.words();
                let text = format!(
                    "0 BEGIN PGM T MM\n1 FUNCTION TCPM {f} {a} {c}\n2 FUNCTION RESET TCPM\n3 END PGM T MM\n"
                );
                let (p, diags) = parse(&text);
                assert!(diags.is_empty(), "{text}: {diags:?}");
                assert_eq!(*p.blocks[1].body(), BlockBody::FunctionTcpm(t));
                assert_eq!(*p.blocks[2].body(), BlockBody::FunctionResetTcpm);
                assert_eq!(format_program(&p), text);
            }
        }
    }
}

/// A malformed FUNCTION TCPM is one error at the wrong word, naming what belongs there.
#[test]
fn a_malformed_function_tcpm_names_the_word_and_what_was_expected() {
    for (block, word, expected) in [
        ("FUNCTION TCPM F XYZ AXIS POS PATHCTRL AXIS", "XYZ", "TCP|CONT"),
        ("FUNCTION TCPM AXIS POS PATHCTRL AXIS", "AXIS", "F TCP|F CONT"),
        ("FUNCTION TCPM F TCP AXIS ROT PATHCTRL AXIS", "ROT", "POS|SPAT"),
        ("FUNCTION TCPM F TCP PATHCTRL AXIS", "PATHCTRL", "AXIS POS|AXIS SPAT"),
        ("FUNCTION TCPM F TCP AXIS POS", "", "PATHCTRL AXIS|PATHCTRL VECTOR"),
        ("FUNCTION TCPM F CONT AXIS POS PATHCTRL LINE", "LINE", "AXIS|VECTOR"),
    ] {
        let text = format!("1 {block}");
        let (_, diags) = parse(&text);
        assert_eq!(diags.len(), 1, "{text}: {diags:?}");
        let d = &diags[0];
        assert_eq!(
            (d.code.clone(), d.expected),
            (DiagCode::InvalidInput, Some(Expected::Nc(expected))),
            "{text}"
        );
        let at = if word.is_empty() {
            text.len()
        } else {
            text.find(&format!(" {word}")).expect("in the text") + 1
        };
        assert_eq!(d.span.start, at, "{text}");
        assert_eq!(&text[d.span.start..d.span.end], word, "{text}");
        assert!(
            d.message(Lang::De).contains(expected) && d.message(Lang::En).contains(expected),
            "{}",
            d.message(Lang::De)
        );
    }
    let (_, diags) = parse("1 FUNCTION RESET TCPM X+0");
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].span.start, "1 FUNCTION RESET TCPM ".len());
}
