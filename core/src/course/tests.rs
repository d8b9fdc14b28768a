//! Every exercise against its own solution and typical mistake (round trip through the parser,
//! the orientation maths, the solver and the simulator), and fixed variants against oracles
//! computed independently (DOMAIN.md numbers, hand-derived matrices).

use super::*;
use crate::plane::RotaryAxis;
use crate::solve::SolveOptions;

const ALL: [Spec; 20] = [
    Spec::Lean,
    Spec::TurnAboutZ,
    Spec::LeanAndTurn,
    Spec::DialogTurn,
    Spec::DialogMove,
    Spec::EulerToOther,
    Spec::Chamfer,
    Spec::Choose(ChooseKind::OtherMachine),
    Spec::Choose(ChooseKind::ShortestPath),
    Spec::Choose(ChooseKind::Option),
    Spec::Choose(ChooseKind::Limits),
    Spec::Choose(ChooseKind::TableRot),
    Spec::Choose(ChooseKind::CoordRot),
    Spec::Run(RunKind::Turn),
    Spec::Run(RunKind::Stay),
    Spec::Run(RunKind::StayQ120),
    Spec::Run(RunKind::ResetStay),
    Spec::Run(RunKind::ResetTurn),
    Spec::Run(RunKind::Musterprogramm1),
    Spec::Run(RunKind::DatumThenPlane),
];

fn verdict(spec: Spec, variant: u32, answer: &str) -> Verdict {
    Exercise::generate(spec, variant).check(&Answer::typed(answer))
}

fn hint(v: &Verdict) -> Option<Hint> {
    match v {
        Verdict::Wrong { hint, .. } => Some(*hint),
        _ => None,
    }
}

#[test]
fn every_variant_accepts_its_solution_and_the_equivalent_and_rejects_the_typical_mistake() {
    let mut all = ALL.to_vec();
    all.push(Spec::Run(RunKind::DatumThenMirror));
    for spec in all {
        for variant in 0..25 {
            let ex = Exercise::generate(spec, variant);
            let ok = ex.check(&Answer::typed(&ex.solution));
            assert!(ok.is_correct(), "{spec:?} v{variant}: solution {:?} → {ok:?}", ex.solution);
            let eq = ex.check(&Answer::typed(&ex.equivalent));
            assert!(eq.is_correct(), "{spec:?} v{variant}: equivalent {:?} → {eq:?}", ex.equivalent);
            let (wrong, expected) = &ex.typical_mistake;
            let v = ex.check(wrong);
            assert_eq!(hint(&v), Some(*expected), "{spec:?} v{variant}: mistake {wrong:?} → {v:?}");
        }
    }
}

#[test]
fn fresh_variants_change_the_numbers() {
    for spec in ALL {
        let prompts: std::collections::BTreeSet<String> =
            (0..30).map(|v| Exercise::generate(spec, v).prompt.de).collect();
        assert!(prompts.len() >= 3, "{spec:?}: only {} different prompts", prompts.len());
    }
}

#[test]
fn lean_accepts_every_form_of_the_same_orientation() {
    // Variant 0: 15° towards +X. Ry(15)·ez = (sin 15, 0, cos 15), Ry(15)·ex = (cos 15, 0, −sin 15).
    for ok in [
        "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX",
        "10 PLANE SPATIAL SPA+0 SPB+15 SPC+0",
        // Rz(90)·Rx(15)·Rz(270) = Ry(15) (derived by hand; EULROT is entered 0…360).
        "PLANE EULER EULPR+90 EULNU+15 EULROT+270 TURN FMAX",
        "PLANE VECTOR BX+0.9659 BY+0 BZ-0.2588 NX+0.2588 NY+0 NZ+0.9659 TURN FMAX",
        // PROJECTED PROPR+15 → SPATIAL (0, 15, 0) (DOMAIN.md oracle 12).
        "PLANE PROJECTED PROPR+15 PROMIN+0 ROT+0 TURN FMAX",
    ] {
        assert!(verdict(Spec::Lean, 0, ok).is_correct(), "{ok}");
    }
    assert_eq!(
        hint(&verdict(Spec::Lean, 0, "PLANE SPATIAL SPA+0 SPB-15 SPC+0 TURN FMAX")),
        Some(Hint::RightHand)
    );
    assert_eq!(
        hint(&verdict(Spec::Lean, 0, "PLANE SPATIAL SPA-15 SPB+0 SPC+0 TURN FMAX")),
        Some(Hint::Wrong)
    );
    // Same tool axis, plane turned 90° about it.
    assert_eq!(
        hint(&verdict(Spec::Lean, 0, "PLANE EULER EULPR+90 EULNU+15 EULROT+0 TURN FMAX")),
        Some(Hint::TurnedAboutToolAxis)
    );
    assert!(matches!(verdict(Spec::Lean, 0, "PLANE SPATIAL SPA+0 SPB+1x5 SPC+0"), Verdict::Unreadable(_)));
    assert!(matches!(verdict(Spec::Lean, 0, "PLANE EULER EULPR+0 EULNU-5 EULROT+0"), Verdict::Unreadable(_)));
    assert!(matches!(verdict(Spec::Lean, 0, "L X+10"), Verdict::Unreadable(_)));
}

#[test]
fn dialog_exercises_check_the_positioning_too() {
    assert!(verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX").is_correct());
    assert!(verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX").is_correct());
    assert_eq!(
        hint(&verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 STAY")),
        Some(Hint::Positioning)
    );
    assert!(verdict(Spec::DialogMove, 0, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST50 F1000").is_correct());
    assert_eq!(
        hint(&verdict(Spec::DialogMove, 0, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST20 F1000")),
        Some(Hint::Positioning)
    );
}

#[test]
fn euler_to_other_wants_another_form() {
    // EULER (90, 45, 0) = SPATIAL (45, 0, 90) (DOMAIN.md oracle 3).
    assert!(verdict(Spec::EulerToOther, 0, "PLANE SPATIAL SPA+45 SPB+0 SPC+90 TURN FMAX").is_correct());
    assert_eq!(
        hint(&verdict(Spec::EulerToOther, 0, "PLANE EULER EULPR+90 EULNU+45 EULROT+0 TURN FMAX")),
        Some(Hint::SameForm)
    );
    assert_eq!(
        hint(&verdict(Spec::EulerToOther, 0, "PLANE SPATIAL SPA-45 SPB+0 SPC+90")),
        Some(Hint::RightHand)
    );
}

#[test]
fn chamfer_at_eulpr_0_tilts_towards_minus_y() {
    // Rz(0)·Rx(45)·ez = (0, −0.7071, 0.7071); the same as SPATIAL SPA+45.
    let ex = Exercise::generate(Spec::Chamfer, 0);
    assert!(ex.prompt.de.contains("−Y"), "{}", ex.prompt.de);
    assert!(verdict(Spec::Chamfer, 0, "PLANE EULER EULPR+0 EULNU+45 EULROT+0 TURN FMAX").is_correct());
    assert!(verdict(Spec::Chamfer, 0, "PLANE SPATIAL SPA+45 SPB+0 SPC+0 TURN FMAX").is_correct());
    assert_eq!(
        hint(&verdict(Spec::Chamfer, 0, "PLANE EULER EULPR+180 EULNU+45 EULROT+0 TURN FMAX")),
        Some(Hint::RightHand)
    );
    // EULPR+270 is outside the input range (unconfirmed::EULPR_RANGE): the control's message.
    assert!(matches!(
        verdict(Spec::Chamfer, 0, "PLANE EULER EULPR+270 EULNU+45 EULROT+0"),
        Verdict::Unreadable(_)
    ));
}

#[test]
fn choose_matches_the_seed_tables() {
    let choose = |k| Spec::Choose(k);
    // Row 15: SEQ−/SYM− from A0 C0 → A−45 C−90.
    assert!(verdict(choose(ChooseKind::Option), 0, "A-45 C-90").is_correct());
    assert_eq!(hint(&verdict(choose(ChooseKind::Option), 0, "A+45 C+90")), Some(Hint::OtherSolution));
    // Row 16: no option from C−105 → A−45 C−90 (15° of C travel instead of 195°).
    assert!(verdict(choose(ChooseKind::ShortestPath), 0, "PLANE AXIAL A-45 C-90").is_correct());
    assert!(verdict(choose(ChooseKind::ShortestPath), 0, "l a-45,0 c-90 r0 fmax").is_correct());
    // Row 20: −90 < A < +10 with SYM+ → "Winkel nicht erlaubt".
    assert!(verdict(choose(ChooseKind::Limits), 0, "Winkel nicht erlaubt").is_correct());
    assert!(Exercise::generate(choose(ChooseKind::Limits), 0).check(&Answer::ControlError).is_correct());
    assert_eq!(hint(&verdict(choose(ChooseKind::Limits), 0, "A+45 C+90")), Some(Hint::ControlRefuses));
    assert_eq!(hint(&verdict(choose(ChooseKind::ShortestPath), 0, "error")), Some(Hint::ControlFinds));
    // Oracle 28: B/C head-table, SPB+30 from B0 C0 → B+30 C+0.
    assert!(verdict(choose(ChooseKind::OtherMachine), 0, "B+30 C+0").is_correct());
    // Oracle 30: SPC+30 TABLE ROT → A+0 C+30 (sign unconfirmed, unconfirmed.rs).
    assert!(verdict(choose(ChooseKind::TableRot), 0, "A+0 C+30").is_correct());
    assert!(matches!(verdict(choose(ChooseKind::Option), 0, "A-45"), Verdict::Unreadable(_)));
    assert!(matches!(verdict(choose(ChooseKind::Option), 0, "A-4x C-90"), Verdict::Unreadable(_)));
    assert_eq!(hint(&verdict(choose(ChooseKind::Option), 0, "A-30 C-90")), Some(Hint::Wrong));
}

#[test]
fn run_values_match_hand_computed_positions() {
    let run = |k| Spec::Run(k);
    // Musterprogramm 1, block 10: SPB+15 on the A/C table from A0 C0 → A+15 C+90 (tie rule).
    assert!(verdict(run(RunKind::Musterprogramm1), 0, "+15").is_correct());
    assert!(verdict(run(RunKind::Musterprogramm1), 0, "A = 15,000").is_correct());
    assert_eq!(hint(&verdict(run(RunKind::Musterprogramm1), 0, "-15")), Some(Hint::RightHand));
    assert!(matches!(verdict(run(RunKind::Musterprogramm1), 0, "fünfzehn"), Verdict::Unreadable(_)));
    // TURN SPB+45 → A+45; STAY → A stays 0, Q120 = +45; RESET STAY → A still +45.
    assert!(verdict(run(RunKind::Turn), 0, "45").is_correct());
    assert!(verdict(run(RunKind::Stay), 0, "0").is_correct());
    assert!(verdict(run(RunKind::StayQ120), 0, "Q120=+45").is_correct());
    assert!(verdict(run(RunKind::ResetStay), 0, "+45").is_correct());
    assert!(verdict(run(RunKind::ResetTurn), 0, "0").is_correct());
    // TRANS DATUM X+40, SPB+30, L X+0 Y+0 Z+10 → tip at 40 + 10·sin 30° = 45 in W-CS.
    assert!(verdict(run(RunKind::DatumThenPlane), 0, "45").is_correct());
    // TRANS DATUM X+50, MIRROR X, L X+20 → 50 − 20 = 30.
    assert!(verdict(run(RunKind::DatumThenMirror), 0, "30").is_correct());
}

#[test]
fn seed_rows_give_the_seed_results() {
    use crate::solve::solve_block;
    // DOMAIN.md oracles 13–27: expected (A, slave) or None for "Winkel nicht erlaubt".
    let expected: [(u8, Option<(f64, f64)>); 15] = [
        (13, Some((45.0, 90.0))),
        (14, Some((45.0, 90.0))),
        (15, Some((-45.0, -90.0))),
        (16, Some((-45.0, -90.0))),
        (17, Some((45.0, 90.0))),
        (18, Some((-45.0, -90.0))),
        (19, Some((-45.0, -90.0))),
        (20, None),
        (21, Some((-45.0, -90.0))),
        (22, Some((45.0, 90.0))),
        (23, Some((-45.0, 0.0))),
        (24, None),
        (25, None),
        (26, Some((-45.0, 0.0))),
        (27, Some((-45.0, 0.0))),
    ];
    let rows = seed_rows();
    assert_eq!(rows.len(), expected.len());
    for (row, (number, want)) in rows.iter().zip(expected) {
        assert_eq!(row.number, number);
        let machine = Machine::builtin(row.machine).unwrap();
        let opts = SolveOptions { start: row.start, limits: row.limits.clone(), ..SolveOptions::default() };
        let e = solve_block(&machine, &row.block, DMat3::IDENTITY, &opts).unwrap();
        let slave = if row.machine == "ba-table" { RotaryAxis::B } else { RotaryAxis::C };
        let got = e.chosen_axes().map(|a| (a.get(RotaryAxis::A).unwrap(), a.get(slave).unwrap()));
        match (got, want) {
            (None, None) => assert!(e.error_message.is_some(), "row {number}"),
            (Some(g), Some(w)) => {
                assert!((g.0 - w.0).abs() < 1e-9 && (g.1 - w.1).abs() < 1e-9, "row {number}: {g:?} vs {w:?}")
            }
            (g, w) => panic!("row {number}: {g:?} vs {w:?}"),
        }
    }
}
