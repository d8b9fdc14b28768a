//! Property tests per machine: inverse kinematics against forward kinematics, angle round trips,
//! the mirror symmetry of the two solutions, and "bad input never panics".

use crate::support;

use glam::DMat3;
use proptest::prelude::*;
use schwenkbar_core::angle::wrap180;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::kinematics::{self, ToolAxisSolution};
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation::{self, Context};
use schwenkbar_core::plane::{AxialAngle, PlaneDef, RelAxis, RotaryAxis, Selection, Sign, TransformMode};
use schwenkbar_core::solve::{self, KinematicCase, SolveOptions};
use schwenkbar_testkit::assert_close;
use support::block;

const EXACT: f64 = 1e-9;

fn machines() -> Vec<Machine> {
    Machine::builtin_ids().iter().map(|id| Machine::builtin(id).unwrap()).collect()
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(256))]
    /// Random reachable orientation (forward kinematics of random axis values and a random γ):
    /// every candidate reproduces the tool axis, and with its residual the whole orientation;
    /// the axis values we started from are among the candidates.
    #[test]
    fn inverse_matches_forward(slave in -180.0..180.0f64, master in -180.0..180.0f64, gamma in -180.0..180.0f64,
                               start_s in -180.0..180.0f64, start_m in -180.0..180.0f64) {
        for m in machines() {
            let r = m.forward_deg(slave, master) * DMat3::from_rotation_z(gamma.to_radians());
            let (sa, ma) = (m.slave().axis, m.master().axis);
            let opts = SolveOptions {
                start: AxisValues::default().with(sa, start_s).with(ma, start_m),
                limits: vec![],
                ..SolveOptions::default()
            };
            let e = solve::solve(&m, &r, &opts);
            prop_assert!(e.case != KinematicCase::Unreachable, "{}: {:?}", m.id, e.error);
            for c in &e.candidates {
                let fk = m.forward(&c.axes);
                assert_close!(fk.z_axis, r.z_axis, EXACT, "{} candidate {:?}", m.id, c.axes);
                assert_close!(fk * DMat3::from_rotation_z(c.residual.to_radians()), r, EXACT, "{} with γ", m.id);
            }
            if e.case == KinematicCase::Two {
                let found = e.candidates.iter().any(|c| wrap180(c.master - master).abs() < 1e-6
                    && wrap180(c.slave - slave).abs() < 1e-6);
                prop_assert!(found, "{}: ({slave}, {master}) not among {:?}", m.id, e.candidates);
            }
        }
    }

    /// The two solutions mirror about the symmetry point: θ2 = 2·θsym − θ1 (mod 360).
    #[test]
    fn solutions_mirror_about_the_symmetry_point(slave in -180.0..180.0f64, master in -180.0..180.0f64) {
        for m in machines() {
            let t = m.forward_deg(slave, master).z_axis;
            let sym = kinematics::symmetry_point(&m);
            if let ToolAxisSolution::Two { solutions: [a, b] } = kinematics::solve_tool_axis(&m, t) {
                assert_close!(wrap180(a.master + b.master - 2.0 * sym).abs(), 0.0, 1e-7, "{}: {a:?} {b:?} sym {sym}", m.id);
            }
            // The other symmetry position works as well (they are 180° apart).
            let [p, q] = kinematics::symmetry_positions(&m);
            assert_close!(wrap180(q - p).abs(), 180.0, EXACT);
        }
    }

    /// SYM+ and SYM− pick the two different solutions whenever both exist and no limit interferes.
    #[test]
    fn sym_plus_and_minus_differ(slave in -180.0..180.0f64, master in -170.0..170.0f64) {
        for m in machines() {
            let r = m.forward_deg(slave, master);
            let mut opts = SolveOptions::default();
            // Limits off for this property: the seed's rule is about the side only.
            for j in m.joints() {
                opts.limits.push((j.axis, schwenkbar_core::machine::Limits { min: -1e6, max: 1e6 }));
            }
            let e0 = solve::solve(&m, &r, &opts);
            if e0.case != KinematicCase::Two { continue; }
            let mut pick = |s| {
                opts.selection = Some(Selection::Sym(s));
                solve::solve(&m, &r, &opts).chosen_axes()
            };
            let (plus, minus) = (pick(Sign::Plus), pick(Sign::Minus));
            prop_assert!(plus.is_some() && minus.is_some() && plus != minus, "{}: {plus:?} {minus:?}", m.id);
        }
    }

    /// The choice obeys its rule on every machine: a chosen solution is inside the limits, on the
    /// requested SEQ/SYM side, and without a selection no in-limit candidate has a shorter path.
    #[test]
    fn the_choice_obeys_its_rule(slave in -180.0..180.0f64, master in -180.0..180.0f64,
                                 start_s in -200.0..200.0f64, start_m in -100.0..100.0f64, sel in 0usize..5) {
        let selection = [None, Some(Selection::Seq(Sign::Plus)), Some(Selection::Seq(Sign::Minus)),
                         Some(Selection::Sym(Sign::Plus)), Some(Selection::Sym(Sign::Minus))][sel];
        for m in machines() {
            let r = m.forward_deg(slave, master);
            let start = AxisValues::default().with(m.slave().axis, start_s).with(m.master().axis, start_m);
            let e = solve::solve(&m, &r, &SolveOptions { start, selection, ..SolveOptions::default() });
            let Some(i) = e.chosen else { continue };
            let c = &e.candidates[i];
            prop_assert!(c.in_limits, "{}: chose {:?} outside the limits", m.id, c.axes);
            if e.case != KinematicCase::Two { continue; }
            match selection {
                Some(Selection::Seq(Sign::Plus)) => prop_assert!(c.master >= 0.0),
                Some(Selection::Seq(Sign::Minus)) => prop_assert!(c.master < 0.0),
                Some(Selection::Sym(Sign::Plus)) => prop_assert!(wrap180(c.master - e.symmetry_point) >= 0.0),
                Some(Selection::Sym(Sign::Minus)) => prop_assert!(wrap180(c.master - e.symmetry_point) < 0.0),
                None => {
                    for o in e.candidates.iter().filter(|o| o.in_limits) {
                        prop_assert!(c.path <= o.path + 1e-6, "{}: {:?} longer than {:?}", m.id, c, o);
                    }
                }
            }
        }
    }

    /// spatial → matrix → spatial, away from SPB = ±90°.
    #[test]
    fn spatial_round_trip(a in -179.9..180.0f64, b in -89.0..89.0f64, c in -179.9..180.0f64) {
        let got = orientation::to_spatial(&orientation::spatial(a, b, c));
        assert_close!(got, [a, b, c], EXACT);
    }

    /// Euler → matrix → Euler, away from EULNU = 0°/180°.
    #[test]
    fn euler_round_trip(p in -179.9..180.0f64, n in 0.5..179.5f64, r in 0.0..359.9f64) {
        let got = orientation::to_euler(&orientation::euler(p, n, r));
        assert_close!(got, [p, n, r], EXACT);
    }

    /// Any orientation converts to spatial and Euler angles that rebuild it (singular or not).
    #[test]
    fn inverse_always_rebuilds(a in -360.0..360.0f64, b in prop_oneof![Just(90.0), Just(-90.0), -360.0..360.0f64],
                               c in -360.0..360.0f64) {
        let r = orientation::spatial(a, b, c);
        let s = orientation::to_spatial(&r);
        assert_close!(orientation::spatial(s[0], s[1], s[2]), r, 1e-8);
        let e = orientation::to_euler(&r);
        assert_close!(orientation::euler(e[0], e[1], e[2]), r, 1e-8);
    }

    /// Any numbers (NaN, ±inf, huge) in any PLANE function: no panic; an error or a rotation.
    #[test]
    fn bad_input_never_panics(v in proptest::collection::vec(prop_oneof![
            Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY), Just(0.0), Just(1e300),
            -400.0..400.0f64], 9),
            kind in 0usize..8, sel in 0usize..5, tr in 0usize..3) {
        let defs = [
            PlaneDef::Spatial { spa: v[0], spb: v[1], spc: v[2] },
            PlaneDef::Euler { eulpr: v[0], eulnu: v[1], eulrot: v[2] },
            PlaneDef::Projected { propr: v[0], promin: v[1], rot: v[2] },
            PlaneDef::Vector { base: [v[0], v[1], v[2]], normal: [v[3], v[4], v[5]] },
            PlaneDef::Points { p1: [v[0], v[1], v[2]], p2: [v[3], v[4], v[5]], p3: [v[6], v[7], v[8]] },
            PlaneDef::Relativ { axis: RelAxis::Spb, angle: v[0] },
            PlaneDef::Axial { axes: vec![AxialAngle { axis: RotaryAxis::A, value: v[0], incremental: false },
                                          AxialAngle { axis: RotaryAxis::C, value: v[1], incremental: true }] },
            PlaneDef::Reset,
        ];
        let selection = [None, Some(Selection::Seq(Sign::Plus)), Some(Selection::Seq(Sign::Minus)),
                         Some(Selection::Sym(Sign::Plus)), Some(Selection::Sym(Sign::Minus))][sel];
        let transform = [None, Some(TransformMode::CoordRot), Some(TransformMode::TableRot)][tr];
        let def = defs[kind].clone();
        if let Ok(r) = orientation::orientation(&def, &Context::default()) {
            prop_assert!(r.is_finite());
            assert_close!(r.transpose() * r, DMat3::IDENTITY, 1e-9);
        }
        for m in machines() {
            let start = AxisValues::default().with(m.slave().axis, v[4]).with(m.master().axis, v[5]);
            let opts = SolveOptions { start, ..SolveOptions::default() };
            if let Ok(e) = solve::solve_block(&m, &block(def.clone(), selection, transform), DMat3::IDENTITY, &opts) {
                // Whatever happened is explained: a choice or an error, never both, never neither.
                prop_assert!(e.chosen.is_some() != e.error.is_some(), "{e:#?}");
                let reason = e.rule.text();
                prop_assert!(!reason.de.is_empty() && !reason.en.is_empty());
                serde_json::to_string(&e).map_err(|x| TestCaseError::fail(x.to_string()))?;
            }
        }
    }

    /// Arbitrary text as a machine description: no panic.
    #[test]
    fn machine_json_never_panics(s in ".{0,200}") {
        let _ = Machine::from_json(&s);
    }
}
