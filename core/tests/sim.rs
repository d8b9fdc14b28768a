//! The simulator (issue 5) on the fixture programs in `tests/fixtures/sim/` and the completed
//! Musterprogramm 1. Tolerances: 1e-9 where two computations of the same number must agree,
//! 1e-6 for the tool tip along a MOVE swivel (issue 5), 1e-4 for DOMAIN.md's 4-decimal oracles.

// The oracle numbers are DOMAIN.md's 4-decimal values (0.7071), kept as printed there.
#![allow(clippy::approx_constant)]

use crate::support;

use glam::{DMat3, DVec3};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation;
use schwenkbar_core::plane::{RelAxis, RotaryAxis};
use schwenkbar_core::sim::{
    ActiveTransform, Kin, Level, SegmentKind, SegmentPath, SimErrorCode, SimOptions, Simulation, State,
    simulate, simulate_listed,
};
use schwenkbar_core::solve::{self, SolveOptions};
use schwenkbar_core::unconfirmed::MB_MAX_CLEARANCE;
use schwenkbar_core::{Program, parse};
use schwenkbar_testkit::assert_close;
use support::{block, spatial};

const EXACT: f64 = 1e-9;
const TIP: f64 = 1e-6;
const ORACLE: f64 = 1e-4;

fn source(rel: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn run(rel: &str, machine: &str) -> (Program, Machine, Simulation) {
    run_with(rel, machine, &SimOptions::default())
}

fn run_with(rel: &str, machine: &str, opts: &SimOptions) -> (Program, Machine, Simulation) {
    let (program, diags) = parse(&source(rel));
    assert!(diags.iter().all(|d| !d.is_error()), "{rel}: {diags:?}");
    let m = Machine::builtin(machine).expect("shipped machine");
    let sim = simulate(&program, &m, opts);
    (program, m, sim)
}

/// The state after the (first) execution of the block with this block number.
fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block exists");
    let step = sim.first_step[idx].expect("block executed") as usize;
    sim.state_at(program, step).expect("state")
}

fn executions(program: &Program, sim: &Simulation, number: u32) -> usize {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block exists") as u32;
    sim.records.iter().filter(|r| r.block == idx && r.executed).count()
}

fn kin_of(m: &Machine, s: &State) -> Kin {
    Kin::new(m, s.tool.length)
}

/// Solves `PLANE SPATIAL spa spb spc` from `start` with the kinematics' own solver.
fn solver_axes(m: &Machine, spa: f64, spb: f64, spc: f64, start: AxisValues) -> AxisValues {
    let opts = SolveOptions { start, ..SolveOptions::default() };
    let e = solve::solve_block(m, &block(spatial(spa, spb, spc), None, None), DMat3::IDENTITY, &opts)
        .expect("valid block");
    e.chosen_axes().expect("a solution")
}

const MUSTER: &str = "static/programs/musterprogramm1.h";

#[test]
fn musterprogramm1_on_ac_table_runs_all_38_blocks() {
    let (p, m, sim) = run(MUSTER, "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_eq!(p.blocks.len(), 38);
    assert_eq!(sim.len(), 38);
    for (i, first) in sim.first_step.iter().enumerate() {
        assert_eq!(*first, Some(i as u32), "block {i} has its state in order");
    }

    // Block 10: the rotary axes stand where the solver says for SPB+15 from A0 C0 ...
    let s9 = after(&p, &sim, 9);
    let s10 = after(&p, &sim, 10);
    let zero = AxisValues::default().with(RotaryAxis::A, 0.0).with(RotaryAxis::C, 0.0);
    let want = solver_axes(&m, 0.0, 15.0, 0.0, zero);
    let got = s10.axes.rotary_values();
    assert_close!([got.a.expect("A"), got.c.expect("C")], [want.a.expect("A"), want.c.expect("C")], EXACT);
    assert_close!([got.a.expect("A"), got.c.expect("C")], [15.0, 90.0], EXACT, "A+15 C+90 (tie to +)");
    // ... and the linear axes did not move during the TURN swivel.
    assert_close!(s10.axes.linear, s9.axes.linear, EXACT);
    assert_close!(s10.axes.linear, DVec3::new(-600.0, 500.0, 0.0), EXACT, "the M91 safe position");
    assert_eq!(s10.segments.len(), 1);
    let seg = &s10.segments[0];
    assert_eq!(seg.kind, SegmentKind::SwivelTurn);
    for k in 0..=20 {
        assert_close!(seg.axes_at(f64::from(k) / 20.0).linear, s9.axes.linear, EXACT);
    }
    assert_close!(s10.q[&120], 15.0, EXACT);
    assert_close!(s10.q[&122], 90.0, EXACT);
    let plane = s10.plane.as_ref().expect("tilted");
    assert_close!(plane.spatial, [0.0, 15.0, 0.0], EXACT);

    // Block 13 calls cycle 232 in the tilted plane: real motion, ending at Q227 + Q204 = 52.
    let s13 = after(&p, &sim, 13);
    assert!(s13.segments.len() > 10);
    assert_close!(s13.tip_ics.z, 52.0, EXACT);
    // Block 18: the axes are back at 0.
    let s18 = after(&p, &sim, 18);
    assert_close!(s18.axes.rotary, [0.0, 0.0], EXACT);
    assert!(s18.plane.is_none());
    // Block 28 drills with cycle 200 at X+50 Y+50 of the tilted plane.
    let s28 = after(&p, &sim, 28);
    assert_close!(s28.tip_ics, DVec3::new(50.0, 50.0, 50.0), EXACT);
    let deepest = s28
        .segments
        .iter()
        .map(|g| kin_of(&m, &s28).tip_wcs(&g.end))
        .map(|t| plane_r(&s28).transpose() * t)
        .fold(f64::MAX, |a, t| a.min(t.z));
    assert_close!(deepest, -20.0, EXACT, "Q201 = -20 along the tilted tool axis");
    let s35 = after(&p, &sim, 35);
    assert!(s35.ended);
    assert!(after(&p, &sim, 37).message().is_some(), "listed after M30, not executed");
}

fn plane_r(s: &State) -> DMat3 {
    s.plane.as_ref().map_or(DMat3::IDENTITY, |p| p.orientation)
}

#[test]
fn every_segment_starts_and_ends_where_the_records_say() {
    let (p, _, sim) = run(MUSTER, "ac-table");
    let mut prev = sim.state_at(&p, 0).expect("state").axes;
    for s in sim.states(&p) {
        if let Some(first) = s.segments.first() {
            assert_close!(first.axes_at(0.0).linear, prev.linear, EXACT, "step {}", s.step);
            assert_close!(first.axes_at(0.0).rotary, prev.rotary, EXACT);
        }
        for w in s.segments.windows(2) {
            assert_close!(w[0].end.linear, w[1].start.linear, EXACT);
        }
        if let Some(last) = s.segments.last() {
            assert_close!(last.axes_at(1.0).linear, s.axes.linear, EXACT);
            assert!(last.duration > 0.0, "step {}: a move takes time", s.step);
        }
        assert_eq!(s.axes, sim.records[s.step].axes);
        prev = s.axes;
    }
}

#[test]
fn move_keeps_the_tool_tip_on_the_workpiece_turn_does_not() {
    let (p, m, sim) = run("tests/fixtures/sim/swivel_move.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s4 = after(&p, &sim, 4);
    let s5 = after(&p, &sim, 5);
    let kin = kin_of(&m, &s5);
    let seg = &s5.segments[0];
    assert_eq!(seg.kind, SegmentKind::SwivelMove);
    assert_close!(s5.axes.rotary_values().a.expect("A"), 15.0, EXACT);
    let tip0 = kin.tip_wcs(&s4.axes);
    assert_close!(tip0, DVec3::new(50.0, 50.0, 20.0), EXACT);
    let mut linear_moved = 0.0_f64;
    for k in 0..=400 {
        let a = seg.axes_at(f64::from(k) / 400.0);
        assert_close!(kin.tip_wcs(&a), tip0, TIP, "fraction {k}/400");
        linear_moved = linear_moved.max((a.linear - s4.axes.linear).length());
    }
    assert!(linear_moved > 1.0, "the linear axes compensate ({linear_moved} mm)");
    assert_close!(s5.tip_wcs, tip0, TIP);

    // PLANE RESET MOVE DIST+30: the centre of rotation 30 mm below the tip stays on the workpiece.
    let s7 = after(&p, &sim, 7);
    let seg = &s7.segments[0];
    let centre0 = kin.tip_wcs(&seg.start) - 30.0 * kin.tool_axis_wcs(seg.start.rotary);
    for k in 0..=100 {
        let a = seg.axes_at(f64::from(k) / 100.0);
        let centre = kin.tip_wcs(&a) - 30.0 * kin.tool_axis_wcs(a.rotary);
        assert_close!(centre, centre0, TIP, "fraction {k}/100");
    }
    assert_close!(s7.axes.rotary, [0.0, 0.0], EXACT);

    // The same swivel with TURN moves the tip relative to the workpiece.
    let (p, m, sim) = run("tests/fixtures/sim/swivel_turn.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s4 = after(&p, &sim, 4);
    let s5 = after(&p, &sim, 5);
    let kin = kin_of(&m, &s5);
    assert_eq!(
        s5.segments.iter().map(|s| s.kind).collect::<Vec<_>>(),
        [SegmentKind::Retract, SegmentKind::SwivelTurn]
    );
    assert_close!(s5.segments[0].end.linear, s4.axes.linear + DVec3::new(0.0, 0.0, 10.0), EXACT, "MB+10");
    let turn = &s5.segments[1];
    let drift = (kin.tip_wcs(&turn.axes_at(1.0)) - kin.tip_wcs(&turn.axes_at(0.0))).length();
    assert!(drift > 1.0, "TURN: the tip moves on the workpiece by {drift} mm");
    // PLANE RESET TURN MB MAX: up to just before the Z limit switch (0), then the rotary axes home.
    let s6 = after(&p, &sim, 6);
    assert_close!(s6.segments[0].end.linear.z, m.geometry.linear_limits[2].max - MB_MAX_CLEARANCE, EXACT);
    assert_close!(s6.axes.rotary, [0.0, 0.0], EXACT);
}

#[test]
fn stay_moves_nothing_and_q120_to_q122_position_the_axes_later() {
    let (p, m, sim) = run("tests/fixtures/sim/swivel_stay.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s4 = after(&p, &sim, 4);
    let s5 = after(&p, &sim, 5);
    assert_eq!(s5.axes, s4.axes);
    assert_eq!(s5.segments.len(), 1, "one STAY segment for the view");
    let stay = &s5.segments[0];
    assert_eq!(stay.kind, SegmentKind::SwivelStay);
    for k in 0..=10 {
        assert_eq!(stay.axes_at(f64::from(k) / 10.0), s4.axes, "STAY: no axis moves");
    }
    assert!(
        matches!(stay.path, SegmentPath::Stay { from, to } if from == DMat3::IDENTITY && to == orientation::spatial(0.0, 15.0, 0.0))
    );
    let zero = AxisValues::default().with(RotaryAxis::A, 0.0).with(RotaryAxis::C, 0.0);
    let want = solver_axes(&m, 0.0, 15.0, 0.0, zero);
    assert_close!([s5.q[&120], s5.q[&122]], [want.a.expect("A"), want.c.expect("C")], EXACT);
    assert!(!s5.q.contains_key(&121), "ac-table has no B axis");
    let e = s5.explanation.as_ref().expect("explanation");
    assert_close!(e.q.q120.expect("Q120"), s5.q[&120], EXACT);

    let s6 = after(&p, &sim, 6);
    assert_close!(s6.axes.rotary_values().a.expect("A"), s5.q[&120], EXACT);
    assert_close!(s6.axes.rotary_values().c.expect("C"), s5.q[&122], EXACT);
    assert_close!(s6.axes.linear, s5.axes.linear, EXACT, "L A… C… moves only the rotary axes");
    // Now L X+0 Y+0 Z+10 in the tilted plane puts the tip on that point of the workpiece.
    let s7 = after(&p, &sim, 7);
    let r = orientation::spatial(0.0, 15.0, 0.0);
    assert_close!(s7.tip_wcs, r * DVec3::new(0.0, 0.0, 10.0), EXACT);
    assert_close!(s7.tip_ics, DVec3::new(0.0, 0.0, 10.0), EXACT);
    // PLANE RESET STAY leaves the axes tilted.
    let s8 = after(&p, &sim, 8);
    assert_eq!(s8.axes, s7.axes);
    assert!(s8.plane.is_none());
}

#[test]
fn datum_shift_before_the_tilt_moves_the_wpl_origin() {
    let (p, _, sim) = run("tests/fixtures/sim/datum_then_tilt.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let r = orientation::spatial(0.0, 30.0, 0.0);
    let d = DVec3::new(50.0, 50.0, 0.0);
    let s6 = after(&p, &sim, 6);
    // WPL-CS origin = W-CS origin + datum, in M-CS: the frame offset by the workpiece pose.
    let wcs = s6.frames.wcs;
    assert_close!(s6.frames.wpl.origin, wcs.origin + wcs.axes * d, EXACT);
    assert_close!(s6.frames.wpl.axes, wcs.axes * r, EXACT);
    assert_eq!(
        s6.transforms.first(),
        Some(&ActiveTransform::Datum { level: Level::Wcs, offset: [50.0, 50.0, 0.0] })
    );
    let s7 = after(&p, &sim, 7);
    assert_close!(s7.tip_wcs, d + r * DVec3::new(0.0, 0.0, 10.0), EXACT);
    // A shift programmed with the tilt active acts in the tilted plane (I-CS).
    let s9 = after(&p, &sim, 9);
    assert_close!(s9.tip_wcs, d + r * DVec3::new(10.0, 0.0, 10.0), EXACT);
    assert_close!(s9.frames.ics.origin, wcs.origin + wcs.axes * (d + r * DVec3::new(10.0, 0.0, 0.0)), EXACT);
}

#[test]
fn mirror_before_the_tilt_mirrors_the_spatial_angles() {
    let (p, m, sim) = run("tests/fixtures/sim/mirror_then_tilt.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s6 = after(&p, &sim, 6);
    let plane = s6.plane.as_ref().expect("tilted");
    assert_close!(plane.spatial, [0.0, -15.0, 0.0], EXACT, "mirror X turns SPB+15 into SPB-15");
    assert_close!(s6.explanation.as_ref().expect("explanation").spatial(), [0.0, -15.0, 0.0], EXACT);
    let zero = AxisValues::default().with(RotaryAxis::A, 0.0).with(RotaryAxis::C, 0.0);
    let want = solver_axes(&m, 0.0, -15.0, 0.0, zero);
    assert_close!(s6.axes.rotary_values().c.expect("C"), want.c.expect("C"), EXACT);
    // The whole program is mirrored: X+20 lands at W-CS −X of the unmirrored point.
    let s7 = after(&p, &sim, 7);
    let unmirrored = orientation::spatial(0.0, 15.0, 0.0) * DVec3::new(20.0, 10.0, 10.0);
    assert_close!(s7.tip_wcs, DVec3::new(-unmirrored.x, unmirrored.y, unmirrored.z), EXACT);
}

#[test]
fn relativ_chains_match_the_orientation_oracles() {
    let (p, _, sim) = run("tests/fixtures/sim/relativ_chain.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s4 = after(&p, &sim, 4);
    let plane = s4.plane.as_ref().expect("tilted");
    let chain =
        orientation::relativ(orientation::relativ(DMat3::IDENTITY, RelAxis::Spa, 45.0), RelAxis::Spb, 45.0);
    assert_close!(plane.orientation, chain, EXACT);
    assert_close!(plane.spatial, [54.7356, 30.0, 35.2644], ORACLE, "oracle 8");
    assert_close!(plane.tool_axis, [0.7071, -0.5, 0.5], ORACLE, "oracle 8");
    let s7 = after(&p, &sim, 7);
    assert_close!(s7.plane.as_ref().expect("tilted").spatial, [45.0, 0.0, 90.0], ORACLE, "oracle 7");
    assert!(after(&p, &sim, 8).plane.is_none());
}

#[test]
fn unreachable_plane_stops_at_its_block_and_keeps_the_states_before() {
    let (p, _, sim) = run("tests/fixtures/sim/unreachable.h", "ca-head");
    let err = sim.error.as_ref().expect("the control refuses block 5");
    assert_eq!(p.blocks[err.block].number(), Some(5));
    assert_eq!(err.line, 6);
    assert_eq!(err.message.de, "Winkel nicht erlaubt");
    assert_eq!(err.message.en, "Entered angle not permitted");
    assert!(matches!(err.code, SimErrorCode::Solve { .. }));
    assert_eq!(sim.len(), 5, "blocks 0–4 keep their states");
    let s4 = sim.state_at(&p, 4).expect("state before the error");
    assert_close!(s4.tip_ics, DVec3::new(0.0, 0.0, 50.0), EXACT);
    assert!(sim.state_at(&p, 5).is_none());
}

#[test]
fn call_lbl_with_rep_and_subprograms() {
    let (p, _, sim) = run("tests/fixtures/sim/call_lbl.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_eq!(executions(&p, &sim, 6), 4, "REP 3: the section runs 1 + 3 times");
    assert_eq!(executions(&p, &sim, 13), 2, "two subprogram calls");
    let last = sim.state_at(&p, sim.len() - 1).expect("state");
    assert_close!(last.q[&1], 4.0, EXACT);
    assert_close!(last.q[&2], 16.0, EXACT);
    assert_close!(last.tip_ics, DVec3::new(40.0, 0.0, 48.0), EXACT);
}

#[test]
fn undefined_q_parameter_stops_the_run() {
    let (p, _, sim) = run("tests/fixtures/sim/undefined_q.h", "ac-table");
    let err = sim.error.as_ref().expect("Q7 is undefined");
    assert_eq!(p.blocks[err.block].number(), Some(4));
    assert_eq!(err.code, SimErrorCode::UndefinedQ { index: 7 });
    assert_eq!(err.message.de, "Q-Parameter nicht definiert");
    assert_close!(sim.state_at(&p, 3).expect("state").tip_ics.x, 5.0, EXACT, "X+Q1 with Q1 = 5");
}

#[test]
fn m99_without_a_cycle_stops_the_run() {
    let (p, _, sim) = run("tests/fixtures/sim/m99_without_cycle.h", "ac-table");
    let err = sim.error.as_ref().expect("no cycle");
    assert_eq!(p.blocks[err.block].number(), Some(3));
    assert_eq!(err.code, SimErrorCode::NoCycle);
    assert_eq!(sim.len(), 3);
}

#[test]
fn endless_loop_is_cut_off_by_the_block_budget() {
    let opts = SimOptions { max_steps: Some(10_000), ..SimOptions::default() };
    let (_, _, sim) = run_with("tests/fixtures/sim/endless.h", "ac-table", &opts);
    let err = sim.error.as_ref().expect("cut off");
    assert_eq!(err.code, SimErrorCode::BlockBudget { steps: 10_000 });
    assert!(err.detail.en.contains("endless loop"));
    assert_eq!(sim.len(), 10_000);
}

#[test]
fn elided_cycle_parameters_stop_the_call_with_a_clear_message() {
    let (p, _, sim) = run("tests/fixtures/ok/musterprogramm1_as_printed.h", "ac-table");
    let err = sim.error.as_ref().expect("the printed program lacks the Q parameters");
    assert_eq!(p.blocks[err.block].number(), Some(13));
    assert_eq!(err.code, SimErrorCode::CycleParamsMissing { cycle: 232 });
    assert!(err.detail.de.contains("CYCL DEF 232"));
    assert_eq!(sim.len(), 13);
}

#[test]
fn cycle_19_tilts_like_spatial_angles_and_cycle_200_drills_along_the_tilted_axis() {
    let (p, m, sim) = run("tests/fixtures/sim/cycle19_stay.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s6 = after(&p, &sim, 6);
    assert!(
        s6.segments.iter().all(|g| g.kind == SegmentKind::SwivelStay && g.start == g.end),
        "cycle 19 does not move the axes itself"
    );
    assert_close!([s6.q[&120], s6.q[&122]], [15.0, 90.0], EXACT);
    let s7 = after(&p, &sim, 7);
    assert_close!(s7.axes.rotary_values().a.expect("A"), 15.0, EXACT);
    let s9 = after(&p, &sim, 9);
    let kin = kin_of(&m, &s9);
    let r = orientation::spatial(0.0, 15.0, 0.0);
    for seg in &s9.segments[1..] {
        // Every drilling move ends on the tilted tool axis through X+30 Y+40 of the plane.
        let i = r.transpose() * kin.tip_wcs(&seg.end);
        assert_close!([i.x, i.y], [30.0, 40.0], EXACT);
    }
    let depth = s9.segments.iter().map(|g| (r.transpose() * kin.tip_wcs(&g.end)).z).fold(f64::MAX, f64::min);
    assert_close!(depth, -10.0, EXACT);
    assert!(after(&p, &sim, 11).plane.is_none(), "19.1 with all angles 0 resets");
    let msg = after(&p, &sim, 14).message().expect("reported");
    assert!(msg.de.contains("nicht simuliert") && msg.en.contains("not simulated"), "{msg:?}");
}

#[test]
fn state_at_from_checkpoints_equals_the_records() {
    let src = schwenkbar_core::sample::cam_program(20_000);
    let (p, _) = parse(&src);
    let m = Machine::builtin("ac-table").expect("machine");
    let opts = SimOptions { checkpoint_interval: 512, ..SimOptions::default() };
    let sim = simulate(&p, &m, &opts);
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_eq!(sim.len(), p.blocks.len());
    for step in [0, 1, 511, 512, 513, 5003, 5004, 10_007, 19_999] {
        let s = sim.state_at(&p, step).expect("state");
        assert_eq!(s.step, step);
        assert_eq!(s.axes, sim.records[step].axes, "step {step}");
        assert_eq!(s.block, sim.records[step].block as usize);
    }
    // The STAY + L A+Q120 C+Q122 pattern of the CAM program tilts the table.
    let s = sim.state_at(&p, 6).expect("state");
    assert!(s.axes.rotary.iter().any(|v| v.abs() > 1.0), "{:?}", s.axes);
}

#[test]
fn fn_jumps_make_loops_and_an_endless_one_meets_the_default_budget() {
    let (p, _, sim) = run("tests/fixtures/sim/fn_jump_loop.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    assert_eq!(executions(&p, &sim, 5), 6, "FN 12 jumps back while Q1 < 6");
    let last = sim.state_at(&p, sim.len() - 1).expect("state");
    assert_close!(last.tip_ics.x, 30.0, EXACT);

    let (p, _, sim) = run("tests/fixtures/sim/endless_fn9.h", "ac-table");
    let err = sim.error.as_ref().expect("cut off");
    let budget = 1_000_000 + 20 * p.blocks.len();
    assert_eq!(err.code, SimErrorCode::BlockBudget { steps: budget });
    assert_eq!(err.message.de, "Programmlauf abgebrochen: Satzbudget erschöpft");
    assert_eq!(sim.len(), budget, "every step before the cut keeps its state");
    assert!(sim.state_at(&p, budget - 1).is_some());
}

#[test]
fn old_style_cycles_7_8_10_and_trans_datum() {
    let (p, _, sim) = run("tests/fixtures/sim/old_cycles_7_8_10.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let tip = |n: u32| after(&p, &sim, n).tip_wcs;
    assert_close!(tip(6), DVec3::new(25.0, 15.0, 10.0), EXACT, "7.1 X+20 / 7.2 Y+10 are one shift");
    assert_close!(tip(9), DVec3::new(25.0, 10.0, 10.0), EXACT, "IX+5 adds to the active shift");
    assert_close!(tip(13), DVec3::new(1.0 - 5.0, 0.0, 10.0), EXACT, "TRANS DATUM X+1 replaces it; mirror X");
    assert_close!(
        tip(16),
        DVec3::new(1.0, 5.0, 10.0),
        EXACT,
        "mirror X after ROT+90 about the shifted datum"
    );
    assert_close!(tip(21), DVec3::new(5.0, 0.0, 10.0), EXACT, "all reset");
}

#[test]
fn plane_axial_ignores_a_preceding_mirror_and_leaves_q120_alone() {
    let (p, m, sim) = run("tests/fixtures/sim/axial_mirror.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s4 = after(&p, &sim, 4);
    assert_close!(s4.axes.rotary_values().a.expect("A"), 30.0, EXACT);
    assert_close!(s4.axes.rotary_values().c.expect("C"), 0.0, EXACT, "C not written: stays");
    let fwd = m.forward(&AxisValues::default().with(RotaryAxis::A, 30.0).with(RotaryAxis::C, 0.0));
    assert_close!(s4.plane.as_ref().expect("tilted").orientation, fwd, EXACT);
    assert!(!s4.q.contains_key(&120), "axis angles do not write Q120");
    let s7 = after(&p, &sim, 7);
    assert_close!(s7.axes.rotary, [90.0, 30.0], EXACT, "[C, A] in chain order");
}

/// Issue 17: `MB MAX` with a tilted tool axis on a head machine retracts along that axis and
/// stops just before the first linear limit switch it would reach: the end is on the tool
/// axis line, inside every limit by the clearance, and on the clearance of at least one limit
/// (the longest such retract).
#[test]
fn mb_max_along_a_tilted_tool_axis_stops_inside_the_limits() {
    let src = "0 BEGIN PGM MBMAX MM\n1 TOOL CALL 1 Z S1000\n2 L X+300 Y+0 Z+20 R0 FMAX\n\
               3 PLANE SPATIAL SPA+40 SPB+0 SPC+0 TURN FMAX\n4 PLANE RESET TURN MB MAX FMAX\n5 END PGM MBMAX MM\n";
    for machine in ["ca-head", "bc-head-table", "b45-nutating"] {
        let (p, diags) = parse(src);
        assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
        let m = Machine::builtin(machine).expect("shipped machine");
        let sim = simulate(&p, &m, &SimOptions::default());
        assert!(sim.error.is_none(), "{machine}: {:?}", sim.error);
        let s3 = after(&p, &sim, 3);
        let s4 = after(&p, &sim, 4);
        let retract = &s4.segments[0];
        assert_eq!(retract.kind, SegmentKind::Retract, "{machine}");
        let (from, to) = (s3.axes.linear, retract.end.linear);
        let d = kin_of(&m, &s3).tool_axis_mcs(s3.axes.rotary);
        let moved = to - from;
        assert!(moved.length() > 1.0, "{machine}: a retract happened");
        assert_close!(moved.cross(d).length(), 0.0, TIP, "{machine}: along the tool axis");
        assert!(moved.dot(d) > 0.0, "{machine}: away from the workpiece");
        let mut on_clearance = false;
        for (i, lim) in m.geometry.linear_limits.iter().enumerate() {
            assert!(
                to[i] <= lim.max - MB_MAX_CLEARANCE + TIP && to[i] >= lim.min + MB_MAX_CLEARANCE - TIP,
                "{machine}: axis {i} at {} inside [{}, {}] by the clearance",
                to[i],
                lim.min,
                lim.max
            );
            on_clearance |= (to[i] - (lim.max - MB_MAX_CLEARANCE)).abs() < TIP
                || (to[i] - (lim.min + MB_MAX_CLEARANCE)).abs() < TIP;
        }
        assert!(on_clearance, "{machine}: the longest retract ends on a limit's clearance: {to}");
    }
}

#[test]
fn axes_outside_their_limit_switches_stop_the_run() {
    let (p, _, sim) = run("tests/fixtures/sim/rotary_limit.h", "ca-head");
    let err = sim.error.as_ref().expect("A+200 beyond +110");
    assert_eq!(p.blocks[err.block].number(), Some(3));
    assert_eq!(err.code, SimErrorCode::RotaryLimit { axis: 'A', value: 200.0, min: -110.0, max: 110.0 });
    assert_eq!(err.message.de, "Endschalter A+");
    let (p, _, sim) = run("tests/fixtures/sim/linear_limit.h", "ac-table");
    let err = sim.error.as_ref().expect("X+2000 beyond +700");
    assert_eq!(p.blocks[err.block].number(), Some(3));
    assert_eq!(err.message.en, "Limit switch X+");
    assert_eq!(sim.len(), 3);
}

#[test]
fn rotation_and_mirror_after_the_tilt_act_in_the_tilted_plane() {
    let (p, _, sim) = run("tests/fixtures/sim/wpl_transforms.h", "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let r = orientation::spatial(0.0, 30.0, 0.0);
    let s5 = after(&p, &sim, 5);
    assert_close!(s5.tip_wcs, r * DVec3::new(0.0, 10.0, 20.0), EXACT, "ROT+90 about the tilted tool axis");
    assert!(s5.transforms.contains(&ActiveTransform::Rotation { deg: 90.0 }));
    let s8 = after(&p, &sim, 8);
    assert_close!(s8.tip_wcs, r * DVec3::new(10.0, -5.0, 20.0), EXACT, "mirror Y in the tilted plane");
    assert_eq!(
        s8.transforms.last(),
        Some(&ActiveTransform::Mirror { level: Level::Wpl, axes: [false, true, false] })
    );
    // The spatial angles are not mirrored by a mirror after the tilt.
    assert_close!(s8.plane.as_ref().expect("tilted").spatial, [0.0, 30.0, 0.0], EXACT);
}

/// The position display during a block's motion (issue 12, defect 12): REF and IST at a
/// fraction of the motion, against closed forms.
#[test]
fn display_during_a_move_follows_the_motion() {
    let src = "0 BEGIN PGM D MM\n1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+50 R0 F1000\n3 L X+100 F1000\n\
               4 PLANE SPATIAL SPA+0 SPB+0 SPC+90 STAY\n5 L X+20 F1000\n6 END PGM D MM\n";
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let m = Machine::builtin("ac-table").expect("shipped machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    let before = after(&program, &sim, 2);
    let s = after(&program, &sim, 3);
    // A straight feed move: halfway in time is halfway along X, in both displays.
    let half_ics = s.tip_ics_at(&m, 0.5);
    assert_close!(half_ics.x, 50.0, EXACT);
    assert_close!(half_ics.y, 0.0, EXACT);
    assert_close!(half_ics.z, 50.0, EXACT);
    let (x0, x1) = (before.axes.linear.x, s.axes.linear.x);
    assert_close!(s.axes_at(0.5).linear.x, (x0 + x1) / 2.0, EXACT);
    // The ends: the states before and after.
    assert!((s.tip_ics_at(&m, 0.0) - before.tip_ics).length() < EXACT);
    assert_eq!(s.tip_ics_at(&m, 1.0), s.tip_ics);
    assert_eq!(s.axes_at(1.0), s.axes);
    assert_eq!(s.axes_at(f64::NAN), s.axes, "a broken fraction shows the end");
    // In a plane turned by SPC+90 (the table stays: STAY), X+20 from I-CS X+100·… runs along
    // the turned X: IST X goes from its start to +20 while Y stays.
    let start = after(&program, &sim, 4).tip_ics;
    let t = after(&program, &sim, 5);
    let quarter = t.tip_ics_at(&m, 0.25);
    assert_close!(quarter.x, start.x + 0.25 * (20.0 - start.x), 1e-6);
    assert_close!(quarter.y, start.y, 1e-6);
}

/// IST during a rotary move follows what the control computes: without a tilt or TCPM the
/// linear axes stand still and so does IST (3-axis behaviour, `COMPENSATION_ONLY_WHEN_TILTED`),
/// although the tip moves over the tilting table; with M128 the tip stands still, and IST with it.
#[test]
fn display_during_a_rotary_move_keeps_ist_where_the_control_has_it() {
    let src = "0 BEGIN PGM D MM\n1 TOOL CALL 1 Z S1000\n2 L X+10 Y+20 Z+50 R0 F1000\n\
               3 L A-30 C+45 FMAX\n4 M128\n5 L A+0 C+0 FMAX\n6 END PGM D MM\n";
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let m = Machine::builtin("ac-table").expect("shipped machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s = after(&program, &sim, 3);
    assert_close!(s.tip_ics, DVec3::new(10.0, 20.0, 50.0), EXACT);
    for f in [0.0, 0.25, 0.5, 0.9] {
        assert_close!(s.tip_ics_at(&m, f), DVec3::new(10.0, 20.0, 50.0), EXACT, "fraction {f}");
    }
    assert_close!(s.axes_at(0.5).rotary_values().a.expect("A"), -15.0, EXACT);
    let held = after(&program, &sim, 4).tip_ics;
    let t = after(&program, &sim, 5);
    for f in [0.0, 0.5, 1.0] {
        assert_close!(t.tip_ics_at(&m, f), held, 1e-6, "M128, fraction {f}");
    }
}

/// The listing (`simulate_listed`, the CLI's table) is the states' block, axes, plane angles
/// and message, step by step, on every fixture and every shipped machine (runs that stop with
/// an error included), and on a small checkpoint interval; the listed run is the run.
#[test]
fn the_listing_shows_what_the_states_say() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures/sim");
    let mut files: Vec<_> = std::fs::read_dir(&dir).expect("fixtures").flatten().map(|e| e.path()).collect();
    files.sort();
    let mut rows = 0;
    for path in files {
        let (program, _) = parse(&std::fs::read_to_string(&path).expect("fixture"));
        for id in Machine::builtin_ids() {
            let machine = Machine::builtin(id).expect("shipped");
            // Endless loops stop at the step budget; 2,000 steps show them well enough.
            let opts = SimOptions { checkpoint_interval: 7, max_steps: Some(2000), ..SimOptions::default() };
            let mut listed = Vec::new();
            let sim = simulate_listed(&program, &machine, &opts, Some(&mut |row| listed.push(row)));
            let plain = simulate(&program, &machine, &opts);
            assert_eq!(sim.records, plain.records, "{} on {id}", path.display());
            assert_eq!(sim.error, plain.error, "{} on {id}", path.display());
            let states: Vec<State> = sim.states(&program).collect();
            assert_eq!(listed.len(), states.len(), "{} on {id}", path.display());
            assert_eq!(listed.len(), sim.len(), "{} on {id}", path.display());
            for (r, s) in listed.iter().zip(&states) {
                let what = format!("{} on {id}, step {}", path.display(), s.step);
                assert_eq!((r.step, r.block, r.line), (s.step, s.block, s.line), "{what}");
                assert_eq!(r.axes, s.axes, "{what}");
                assert_eq!(r.spatial, s.plane.as_ref().map(|p| p.spatial), "{what}");
                assert_eq!(r.note, s.note, "{what}");
            }
            rows += listed.len();
        }
    }
    assert!(rows > 1000, "the fixtures list {rows} steps");
}
