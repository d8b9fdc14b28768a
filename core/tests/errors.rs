//! Bad input gives a typed error carrying the numbers (DOMAIN.md §10 oracle 33 and the issue's
//! list: NaN/inf, zero-length vectors, collinear POINTS, EULNU outside 0…180), never a panic.

use crate::support;

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::{Limits, Machine};
use schwenkbar_core::orientation::{self, Context, PlaneError, VectorName};
use schwenkbar_core::plane::{AxialAngle, PlaneDef, RotaryAxis};
use schwenkbar_core::solve::{self, SolveError, SolveOptions};
use schwenkbar_testkit::assert_close;
use support::{block, spatial};

fn err(def: PlaneDef<f64>) -> PlaneError {
    orientation::orientation(&def, &Context::default()).expect_err("must be rejected")
}

#[test]
fn range_errors_carry_word_value_and_range() {
    let cases = [
        (PlaneDef::Euler { eulpr: 0.0, eulnu: -5.0, eulrot: 0.0 }, "EULNU", -5.0, 0.0, 180.0),
        (PlaneDef::Euler { eulpr: 0.0, eulnu: 180.5, eulrot: 0.0 }, "EULNU", 180.5, 0.0, 180.0),
        (PlaneDef::Projected { propr: 90.0, promin: 0.0, rot: 0.0 }, "PROPR", 90.0, -89.9999, 89.9999),
        (spatial(360.0, 0.0, 0.0), "SPA", 360.0, -359.9999, 359.9999),
        (PlaneDef::Euler { eulpr: 0.0, eulnu: 10.0, eulrot: -1.0 }, "EULROT", -1.0, 0.0, 360.0),
    ];
    for (def, word, value, min, max) in cases {
        assert_eq!(err(def), PlaneError::OutOfRange { word, value, min, max });
    }
    // Boundary values written in the block pass.
    assert!(orientation::orientation(&spatial(359.9999, -359.9999, 0.0), &Context::default()).is_ok());
    assert!(
        orientation::orientation(
            &PlaneDef::Euler { eulpr: -180.0, eulnu: 180.0, eulrot: 360.0 },
            &Context::default()
        )
        .is_ok()
    );
    // Seed S1's tip writes EULPR+270, outside the stated input range −180…+180
    // (unconfirmed::EULPR_LIMIT): refused with the numbers; EULPR-90 is the same plane.
    assert_eq!(
        err(PlaneDef::Euler { eulpr: 270.0, eulnu: 45.0, eulrot: 0.0 }),
        PlaneError::OutOfRange { word: "EULPR", value: 270.0, min: -180.0, max: 180.0 }
    );
    let msg = PlaneError::OutOfRange { word: "EULNU", value: -5.0, min: 0.0, max: 180.0 };
    assert_eq!(msg.message().de, "Winkel nicht erlaubt: EULNU = -5 (erlaubt 0 … 180)");
    assert_eq!(msg.message().en, "Entered angle not permitted: EULNU = -5 (allowed 0 … 180)");
    let msg = PlaneError::OutOfRange { word: "NX", value: 120.0, min: -99.9999999, max: 99.9999999 };
    assert_eq!(msg.message().de, "Eingabewert falsch: NX = 120 (erlaubt -99.9999999 … 99.9999999)");
    let msg = PlaneError::OutOfRange { word: "PROPR", value: 90.0, min: -89.9999, max: 89.9999 };
    assert!(msg.message().de.starts_with("Winkel nicht erlaubt"));
}

#[test]
fn not_finite_is_reported_with_the_word() {
    assert!(
        matches!(err(spatial(0.0, f64::NAN, 0.0)), PlaneError::NotFinite { word: "SPB", value } if value.is_nan())
    );
    assert_eq!(
        err(PlaneDef::Vector { base: [1.0, 0.0, 0.0], normal: [0.0, f64::INFINITY, 1.0] }),
        PlaneError::NotFinite { word: "NY", value: f64::INFINITY }
    );
}

#[test]
fn vectors_and_points() {
    assert_eq!(
        err(PlaneDef::Vector { base: [1.0, 0.0, 0.0], normal: [0.0, 0.0, 0.0] }),
        PlaneError::ZeroVector { vector: VectorName::Normal, length: 0.0 }
    );
    assert_eq!(
        err(PlaneDef::Vector { base: [0.0, 0.0, 0.0], normal: [0.0, 0.0, 1.0] }),
        PlaneError::ZeroVector { vector: VectorName::Base, length: 0.0 }
    );
    match err(PlaneDef::Vector { base: [0.0, 0.0, 2.0], normal: [0.0, 0.0, -1.0] }) {
        PlaneError::BaseParallelToNormal { base, normal, angle } => {
            assert_eq!((base, normal), ([0.0, 0.0, 2.0], [0.0, 0.0, -1.0]));
            assert_close!(angle, 180.0, 1e-9);
        }
        other => panic!("{other:?}"),
    }
    let p1 = [1.0, 2.0, 3.0];
    assert_eq!(
        err(PlaneDef::Points { p1, p2: p1, p3: [0.0, 0.0, 0.0] }),
        PlaneError::ZeroVector { vector: VectorName::P1P2, length: 0.0 }
    );
    match err(PlaneDef::Points { p1: [0.0; 3], p2: [10.0, 10.0, 0.0], p3: [-5.0, -5.0, 0.0] }) {
        PlaneError::CollinearPoints { p3, sine, .. } => {
            assert_eq!(p3, [-5.0, -5.0, 0.0]);
            assert!(sine < 1e-9);
        }
        other => panic!("{other:?}"),
    }
    // P3 = P1 is collinear too, not a division by zero.
    assert!(matches!(
        err(PlaneDef::Points { p1: [0.0; 3], p2: [10.0, 0.0, 0.0], p3: [0.0; 3] }),
        PlaneError::CollinearPoints { .. }
    ));
}

#[test]
fn axial_needs_existing_axes() {
    let m = Machine::builtin("ac-table").unwrap();
    let def =
        PlaneDef::Axial { axes: vec![AxialAngle { axis: RotaryAxis::B, value: 10.0, incremental: false }] };
    let ctx = Context { machine: Some(&m), ..Context::default() };
    assert_eq!(
        orientation::orientation(&def, &ctx),
        Err(PlaneError::AxisNotOnMachine { axis: RotaryAxis::B, machine: "ac-table".into() })
    );
    assert_eq!(orientation::orientation(&def, &Context::default()), Err(PlaneError::MachineRequired));
}

#[test]
fn axial_positions_directly_and_checks_limits() {
    let m = Machine::builtin("ba-table").unwrap();
    let opts =
        SolveOptions { start: AxisValues::default().with(RotaryAxis::B, 30.0), ..SolveOptions::default() };
    let def =
        |a| PlaneDef::Axial { axes: vec![AxialAngle { axis: RotaryAxis::A, value: a, incremental: false }] };
    let e = solve::solve_block(&m, &block(def(-45.0), None, None), DMat3::IDENTITY, &opts).unwrap();
    let axes = e.chosen_axes().unwrap();
    assert_eq!((axes.a, axes.b), (Some(-45.0), Some(30.0)), "B not programmed: stays");
    assert_close!(e.orientation, orientation::rows(&m.forward(&axes)), 1e-12);
    let e = solve::solve_block(&m, &block(def(-120.0), None, None), DMat3::IDENTITY, &opts).unwrap();
    assert_eq!(
        e.error,
        Some(SolveError::AxisOutOfLimit { axis: RotaryAxis::A, value: -120.0, min: -100.0, max: 180.0 })
    );
    assert_eq!(e.error.unwrap().message().de, "Winkel nicht erlaubt");
    assert_eq!(e.error.unwrap().detail().de, "A-120 außerhalb des Verfahrbereichs -100 … +180");
}

#[test]
fn unreachable_tool_axis() {
    // The 45° nutating head cannot point the tool below the horizontal.
    let m = Machine::builtin("b45-nutating").unwrap();
    let e = solve::solve(&m, &orientation::spatial(120.0, 0.0, 0.0), &SolveOptions::default());
    assert!(matches!(e.error, Some(SolveError::Unreachable { tool_axis }) if tool_axis[2] < 0.0));
    assert!(e.candidates.is_empty() && e.chosen.is_none());
}

#[test]
fn non_finite_solver_input() {
    let m = Machine::builtin("ac-table").unwrap();
    let opts = SolveOptions {
        start: AxisValues::default().with(RotaryAxis::C, f64::NAN),
        ..SolveOptions::default()
    };
    let e = solve::solve(&m, &DMat3::IDENTITY, &opts);
    assert!(matches!(e.error, Some(SolveError::NotFinite { what: "start position", .. })));
    let opts =
        SolveOptions { limits: vec![(RotaryAxis::A, Limits { min: f64::NEG_INFINITY, max: 0.0 })], ..opts };
    let e = solve::solve(&m, &DMat3::from_cols_array(&[f64::NAN; 9]), &opts);
    assert!(matches!(e.error, Some(SolveError::NotFinite { what: "orientation", .. })));
}

#[test]
fn builtin_machines_load_and_name_master_and_slave() {
    let expect = [
        ("ac-table", RotaryAxis::A, RotaryAxis::C, 0.0),
        ("ba-table", RotaryAxis::A, RotaryAxis::B, -90.0),
        ("bc-head-table", RotaryAxis::B, RotaryAxis::C, 0.0),
        ("ca-head", RotaryAxis::A, RotaryAxis::C, 0.0),
        ("b45-nutating", RotaryAxis::B, RotaryAxis::C, 0.0),
    ];
    assert_eq!(Machine::builtin_ids().len(), expect.len());
    for (id, master, slave, sym) in expect {
        let m = Machine::builtin(id).unwrap();
        assert_eq!((m.master().axis, m.slave().axis), (master, slave), "{id}");
        assert_close!(schwenkbar_core::kinematics::symmetry_point(&m), sym, 1e-9, "{id} symmetry point");
        // The files on disk are the ones compiled in.
        let path = format!("{}/../static/machines/{id}.json", env!("CARGO_MANIFEST_DIR"));
        let disk = std::fs::read_to_string(&path).unwrap();
        assert_eq!(Machine::from_json(&disk).unwrap(), m);
    }
}
