//! Machine-specific behaviour beyond the seed oracles: the nutating head, a free head axis with
//! TABLE ROT, SEQ with both solutions on one side, and the unconfirmed-decision catalogue.

use crate::support;

use glam::{DMat3, DVec3};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::kinematics::{self, ToolAxisSolution};
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation;
use schwenkbar_core::plane::{RotaryAxis, Selection, Sign, TransformMode};
use schwenkbar_core::solve::{self, KinematicCase, Realisation, Rule, SolveOptions};
use schwenkbar_core::unconfirmed::Decision;
use schwenkbar_testkit::assert_close;
use support::{block, spatial};

#[test]
fn nutating_head_reaches_the_horizontal_at_b180() {
    let m = Machine::builtin("b45-nutating").unwrap();
    let t = m.forward(&AxisValues::default().with(RotaryAxis::B, 180.0)).z_axis;
    assert_close!(t, DVec3::Y, 1e-12);
    // Tool vertical: the C table is parallel to the tool axis, C is free.
    assert!(
        matches!(kinematics::solve_tool_axis(&m, DVec3::Z), ToolAxisSolution::SlaveFree { master } if master.abs() < 1e-9)
    );
    // A tilt of 30° about X: two solutions, B mirrored about the symmetry point B0.
    let r = orientation::spatial(-30.0, 0.0, 0.0);
    let e = solve::solve(&m, &r, &SolveOptions::default());
    assert_eq!(e.case, KinematicCase::Two);
    let (b1, b2) = (e.candidates[0].master, e.candidates[1].master);
    assert!(b1 > 0.0 && b2 < 0.0, "candidate 1 on the SYM+ side: {b1} {b2}");
    assert_close!(b1 + b2, 0.0, 1e-9);
    for c in &e.candidates {
        assert_close!(m.forward(&c.axes).z_axis, r.z_axis, 1e-9);
    }
}

#[test]
fn table_rot_on_a_free_head_axis_is_done_mathematically() {
    let m = Machine::builtin("ca-head").unwrap();
    let start = AxisValues::default().with(RotaryAxis::C, 5.0);
    let opts = SolveOptions { start, ..SolveOptions::default() };
    let e = solve::solve_block(
        &m,
        &block(spatial(0.0, 0.0, 45.0), None, Some(TransformMode::TableRot)),
        DMat3::IDENTITY,
        &opts,
    )
    .unwrap();
    assert_eq!(e.case, KinematicCase::SlaveFree);
    assert!(e.decisions.contains(&Decision::TableRotHeadAxis), "{:?}", e.decisions);
    let res = e.residual.unwrap();
    assert_eq!(res.realised_by, Realisation::Mathematical);
    assert_close!(res.gamma, 40.0, 1e-9, "head C stays at 5, γ does the rest");
    assert_eq!(e.chosen_axes().unwrap().c, Some(5.0));
}

#[test]
fn default_transform_is_coord_rot_and_says_so() {
    let m = Machine::builtin("ac-table").unwrap();
    let e = solve::solve(&m, &orientation::spatial(0.0, 0.0, 30.0), &SolveOptions::default());
    assert_eq!(e.transform, TransformMode::CoordRot);
    assert!(
        e.decisions.contains(&Decision::DefaultTransform)
            && e.decisions.contains(&Decision::CoordRotFreeAxis)
    );
}

#[test]
fn seq_with_both_solutions_on_the_same_side_takes_the_nearer() {
    // B/A: solutions A−45/B0 and A−135/B180 are both negative; SEQ− takes the nearer (seed S2).
    let m = Machine::builtin("ba-table").unwrap();
    let start = AxisValues::default().with(RotaryAxis::A, -95.0).with(RotaryAxis::B, 180.0);
    let opts =
        SolveOptions { start, selection: Some(Selection::Seq(Sign::Minus)), ..SolveOptions::default() };
    let e = solve::solve(&m, &orientation::spatial(-45.0, 0.0, 0.0), &opts);
    assert_eq!(e.rule, Rule::SeqNearer { sign: Sign::Minus, master: RotaryAxis::A });
    // From A−95 B180: −135/180 is 40 away, −45/0 is 50+180 away, but −135 violates A ≥ −100.
    assert_eq!(e.error.map(|x| x.message().de), Some("Winkel nicht erlaubt".into()));
    assert!(e.decisions.contains(&Decision::SeqSameSide));
}

#[test]
fn relativ_blocks_compose_through_solve_block() {
    use schwenkbar_core::plane::{PlaneDef, RelAxis};
    let m = Machine::builtin("ac-table").unwrap();
    let mut active = DMat3::IDENTITY;
    for (axis, angle) in [(RelAxis::Spa, 45.0), (RelAxis::Spb, 45.0)] {
        let e = solve::solve_block(
            &m,
            &block(PlaneDef::Relativ { axis, angle }, None, None),
            active,
            &SolveOptions::default(),
        )
        .unwrap();
        let rows = e.orientation;
        active = DMat3::from_cols_array_2d(&rows).transpose();
    }
    assert_close!(orientation::to_spatial(&active), [54.7356, 30.0, 35.2644], 1e-4);
}

#[test]
fn every_decision_has_distinct_texts() {
    let mut seen = std::collections::HashSet::new();
    for d in Decision::ALL {
        let t = d.text();
        assert!(!t.de.is_empty() && !t.en.is_empty() && t.de != t.en, "{d:?}");
        assert!(seen.insert(t.en), "duplicate text for {d:?}");
    }
}
