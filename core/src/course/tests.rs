//! Every exercise against its own solution and typical mistake (round trip through the parser,
//! the orientation maths, the solver and the simulator), and fixed variants against oracles
//! computed independently (DOMAIN.md numbers, hand-derived matrices).

use super::*;
use crate::plane::RotaryAxis;
use crate::solve::SolveOptions;

const ALL: [Spec; 21] = [
    Spec::Lean,
    Spec::ProgramLean,
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
            // The solution as shown in either language is an answer the check accepts.
            for shown in [&ex.solution.de, &ex.solution.en, &ex.equivalent.de, &ex.equivalent.en] {
                let ok = ex.check(&Answer::typed(shown));
                assert!(ok.is_correct(), "{spec:?} v{variant}: {shown:?} → {ok:?}");
            }
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
            (0..30).map(|v| Exercise::generate(spec, v).prompt.de.into_owned()).collect();
        assert!(prompts.len() >= 3, "{spec:?}: only {} different prompts", prompts.len());
    }
}

#[test]
fn lean_accepts_every_form_of_the_same_orientation() {
    // ProgramLean variant 0: 15° towards +X (Musterprogramm 1's plane). Ry(15)·ez = (sin 15, 0, cos 15), Ry(15)·ex = (cos 15, 0, −sin 15).
    for ok in [
        "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX",
        "10 PLANE SPATIAL SPA+0 SPB+15 SPC+0",
        // Rz(90)·Rx(15)·Rz(270) = Ry(15) (derived by hand; EULROT is entered 0…360).
        "PLANE EULER EULPR+90 EULNU+15 EULROT+270 TURN FMAX",
        "PLANE VECTOR BX+0.9659 BY+0 BZ-0.2588 NX+0.2588 NY+0 NZ+0.9659 TURN FMAX",
        // PROJECTED PROPR+15 → SPATIAL (0, 15, 0) (DOMAIN.md oracle 12).
        "PLANE PROJECTED PROPR+15 PROMIN+0 ROT+0 TURN FMAX",
    ] {
        assert!(verdict(Spec::ProgramLean, 0, ok).is_correct(), "{ok}");
    }
    assert_eq!(
        hint(&verdict(Spec::ProgramLean, 0, "PLANE SPATIAL SPA+0 SPB-15 SPC+0 TURN FMAX")),
        Some(Hint::RightHand)
    );
    assert_eq!(
        hint(&verdict(Spec::ProgramLean, 0, "PLANE SPATIAL SPA-15 SPB+0 SPC+0 TURN FMAX")),
        Some(Hint::Wrong)
    );
    // Same tool axis, plane turned 90° about it.
    assert_eq!(
        hint(&verdict(Spec::ProgramLean, 0, "PLANE EULER EULPR+90 EULNU+15 EULROT+0 TURN FMAX")),
        Some(Hint::TurnedAboutToolAxis)
    );
    assert!(matches!(
        verdict(Spec::ProgramLean, 0, "PLANE SPATIAL SPA+0 SPB+1x5 SPC+0"),
        Verdict::Unreadable(_)
    ));
    assert!(matches!(
        verdict(Spec::ProgramLean, 0, "PLANE EULER EULPR+0 EULNU-5 EULROT+0"),
        Verdict::Unreadable(_)
    ));
    assert!(matches!(verdict(Spec::ProgramLean, 0, "L X+10"), Verdict::Unreadable(_)));
}

#[test]
fn dialog_exercises_check_the_positioning_too() {
    // Variant 0: DialogTurn 25° towards +X (lesson 3's steps), DialogMove 30° towards −X.
    assert!(verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN FMAX").is_correct());
    assert!(verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN MB MAX FMAX").is_correct());
    assert_eq!(
        hint(&verdict(Spec::DialogTurn, 0, "PLANE SPATIAL SPA+0 SPB+25 SPC+0 STAY")),
        Some(Hint::Positioning)
    );
    assert!(verdict(Spec::DialogMove, 0, "PLANE SPATIAL SPA+0 SPB-30 SPC+0 MOVE DIST50 F1000").is_correct());
    assert_eq!(
        hint(&verdict(Spec::DialogMove, 0, "PLANE SPATIAL SPA+0 SPB-30 SPC+0 MOVE DIST20 F1000")),
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
    // A−15 C−90 is the machine's other solution of SPB+15, not a sign error.
    assert_eq!(hint(&verdict(run(RunKind::Musterprogramm1), 0, "-15")), Some(Hint::OtherSolution));
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

/// The product's seed rows (the bench's set-ups) paired with the table's rows in
/// tests/fixtures/oracles/seq_sym.tsv, one to one and in order.
fn seed_rows_with_the_table() -> Vec<(SeedRow, schwenkbar_testkit::seq_sym::Row)> {
    let (rows, table) = (seed_rows(), schwenkbar_testkit::seq_sym::rows());
    assert_eq!(rows.len(), table.len(), "seed_rows() and seq_sym.tsv");
    rows.into_iter().zip(table).collect()
}

/// The single PLANE block of a typed text, numbers only.
fn typed_plane(text: &str) -> PlaneBlock<f64> {
    let (program, diags) = crate::parse(text);
    assert!(!diags.iter().any(|d| d.is_error()), "{text}: {diags:?}");
    let [block] = program.blocks.as_slice() else { panic!("{text}: not one block") };
    let Some(crate::BlockBody::Plane(plane)) = block.stored_body() else {
        panic!("{text}: not a PLANE block")
    };
    plane
        .try_map(|v| match v {
            crate::plane::Value::Number(x) => Ok(*x),
            crate::plane::Value::Param { .. } => Err(()),
        })
        .unwrap_or_else(|()| panic!("{text}: a Q parameter"))
}

fn rotary(letter: char) -> RotaryAxis {
    RotaryAxis::from_letter(&letter.to_string()).expect("a rotary axis letter")
}

#[test]
fn seed_rows_are_the_rows_of_the_oracle_table() {
    // The course keeps its own copy (it runs in the browser); this holds it to the one table
    // the tests read. Where the seed's column says "SYM=SEQ", the course takes SYM, the first.
    for (row, want) in seed_rows_with_the_table() {
        let n = want.oracle;
        assert_eq!(row.number, n);
        assert_eq!(row.machine, want.machine, "row {n}");
        assert_eq!(row.block, typed_plane(&want.blocks()[0]), "row {n}");
        let start = want.start_axes().iter().fold(AxisValues::default(), |v, &(l, x)| v.with(rotary(l), x));
        assert_eq!(row.start, start, "row {n}");
        let limits: Vec<_> = want
            .limit_range()
            .map(|(l, min, max)| (rotary(l), crate::machine::Limits { min, max }))
            .into_iter()
            .collect();
        assert_eq!(row.limits, limits, "row {n}");
    }
}

#[test]
fn seed_rows_give_the_seed_results() {
    use crate::solve::solve_block;
    use schwenkbar_testkit::{assert_close, seq_sym::Expect};
    for (row, want) in seed_rows_with_the_table() {
        let number = row.number;
        let machine = Machine::builtin(row.machine).unwrap();
        let opts = SolveOptions { start: row.start, limits: row.limits.clone(), ..SolveOptions::default() };
        let e = solve_block(&machine, &row.block, DMat3::IDENTITY, &opts).unwrap();
        match (e.chosen_axes(), &want.expect) {
            (None, Expect::Refused(msg)) => {
                assert_eq!(
                    e.error_message.map(|m| m.0.message().de),
                    Some(msg.as_str().into()),
                    "row {number}"
                )
            }
            (Some(got), Expect::Chosen(axes)) => {
                let got: Vec<f64> =
                    axes.iter().map(|&(l, _)| got.get(rotary(l)).unwrap_or(f64::NAN)).collect();
                let axes: Vec<f64> = axes.iter().map(|&(_, x)| x).collect();
                assert_close!(got, axes, 1e-9, "row {number}");
            }
            (got, want) => panic!("row {number}: {got:?} vs {want:?}"),
        }
    }
}

/// The tool axis (column 2) or the plane's X axis (column 0) of `R`.
fn column(r: &DMat3, c: usize) -> glam::DVec3 {
    r.col(c)
}

#[test]
fn every_sign_rule_a_hint_states_agrees_with_the_orientation_maths() {
    use super::orientation::SIGN_RULES;
    for (i, rule) in SIGN_RULES.iter().enumerate() {
        let mut angles = [0.0; 3];
        angles[i] = 10.0;
        let turned = crate::orientation::spatial(angles[0], angles[1], angles[2]);
        let start = column(&DMat3::IDENTITY, rule.column);
        let moved = column(&turned, rule.column) - start;
        assert!(moved.normalize().dot(rule.towards) > 0.99, "{}+ moves {start} along {moved}", rule.word);
    }
}

fn hint_text(v: &Verdict) -> String {
    match v {
        Verdict::Wrong { text, .. } => format!("{} | {}", text.de, text.en),
        other => panic!("not a wrong answer: {other:?}"),
    }
}

#[test]
fn the_sign_hint_talks_about_the_angle_of_the_task() {
    // Lesson 2: TurnAboutZ (SPC+30) with SPC flipped talks about SPC only; Lean (SPA+20) about SPA.
    let spc = verdict(Spec::TurnAboutZ, 0, "PLANE SPATIAL SPA+0 SPB+0 SPC-30 TURN FMAX");
    assert_eq!(hint(&spc), Some(Hint::RightHand));
    let text = hint_text(&spc);
    assert!(text.contains("SPC+") && !text.contains("SPB+") && !text.contains("SPA+"), "{text}");
    let spa = verdict(Spec::Lean, 0, "PLANE SPATIAL SPA-20 SPB+0 SPC+0 TURN FMAX");
    assert_eq!(hint(&spa), Some(Hint::RightHand));
    let text = hint_text(&spa);
    assert!(text.contains("SPA+") && !text.contains("SPB+") && !text.contains("SPC+"), "{text}");
    // The sign error in a run (lesson 9): the simulator's X with SPB flipped, hint about SPB.
    let ex = Exercise::generate(Spec::Run(RunKind::DatumThenPlane), 0);
    let (wrong, h) = &ex.typical_mistake;
    assert_eq!(*h, Hint::RightHand);
    let text = hint_text(&ex.check(wrong));
    assert!(text.contains("SPB+") && !text.contains("SPA+"), "{text}");
    // TRANS DATUM X+40, SPB−30, Z+10 → 40 − 10·sin 30° = 35.
    assert_eq!(wrong, &Answer::Text("X+35".into()));
}

#[test]
fn the_lean_tasks_differ_in_their_variant_0() {
    // Lessons 2, 3 (twice) and 8 each ask another lean: the targets differ as orientations.
    let targets: Vec<DMat3> = [Spec::Lean, Spec::DialogTurn, Spec::DialogMove, Spec::ProgramLean]
        .iter()
        .map(|&s| match Exercise::generate(s, 0).check {
            Check::Orientation { target, .. } => target,
            other => panic!("{s:?}: {other:?}"),
        })
        .collect();
    for (i, a) in targets.iter().enumerate() {
        for b in &targets[i + 1..] {
            assert!(!a.abs_diff_eq(*b, 1e-6), "the same lean twice: {a}");
        }
    }
}

#[test]
fn the_refusal_is_shown_in_the_ui_language() {
    use crate::solve::solve_block;
    // Seed row 20: −90 < A < +10 with SYM+ → the solver's refusal, in both languages.
    let ex = Exercise::generate(Spec::Choose(ChooseKind::Limits), 0);
    let machine = Machine::builtin("ac-table").unwrap();
    let row = seed_rows().into_iter().find(|r| r.number == 20).unwrap();
    let opts = SolveOptions { start: row.start, limits: row.limits.clone(), ..SolveOptions::default() };
    let e = solve_block(&machine, &row.block, DMat3::IDENTITY, &opts).unwrap();
    let m = e.error_message.expect("the control refuses").0.message();
    assert_eq!(ex.solution, m);
    assert_ne!(ex.solution.de, ex.solution.en);
    assert!(ex.prompt.en.contains(&*m.en), "{}", ex.prompt.en);
    for typed in [&m.de, &m.en] {
        assert!(ex.check(&Answer::typed(typed)).is_correct(), "{typed}");
    }
}

/// The solver's two solutions of block `number` of the exercise's program, started from the
/// axes' home position A+0 C+0 on its machine: (chosen, other).
fn candidates_of(ex: &Exercise, number: u32) -> (AxisValues, AxisValues) {
    use crate::solve::solve_block;
    let (text, machine) = ex.program.clone().expect("a program");
    let (program, _) = crate::parse(&text);
    let block = program
        .blocks
        .iter()
        .find(|b| b.number() == Some(number))
        .and_then(|b| match b.stored_body()? {
            crate::BlockBody::Plane(p) => p
                .try_map(|v| match v {
                    crate::plane::Value::Number(x) => Ok(*x),
                    crate::plane::Value::Param { .. } => Err(()),
                })
                .ok(),
            _ => None,
        })
        .expect("a PLANE block with numbers");
    let machine = Machine::builtin(machine).unwrap();
    let e = solve_block(&machine, &block, DMat3::IDENTITY, &SolveOptions::default()).unwrap();
    let chosen = e.chosen.unwrap();
    let other = (0..e.candidates.len()).find(|&i| i != chosen).expect("two solutions");
    (e.candidates[chosen].axes, e.candidates[other].axes)
}

use crate::axes::AxisValues;

#[test]
fn the_other_solution_of_a_run_gets_the_other_solution_hint_with_the_rule() {
    // Lessons 4, 8 and 9: the asked axis at the solver's other solution of the PLANE block.
    for (kind, block, axis) in [
        (RunKind::Turn, 6, RotaryAxis::A),
        (RunKind::StayQ120, 6, RotaryAxis::A),
        (RunKind::Musterprogramm1, 10, RotaryAxis::A),
    ] {
        let ex = Exercise::generate(Spec::Run(kind), 0);
        let (chosen, other) = candidates_of(&ex, block);
        // What the hint says: both positions give the same tool axis (forward kinematics).
        let machine = Machine::builtin("ac-table").unwrap();
        let (tc, to) = (machine.forward(&chosen).col(2), machine.forward(&other).col(2));
        assert!((tc - to).length() < 1e-9 && chosen != other, "{kind:?}: {tc} vs {to}");
        let word = crate::solve::fmt_deg(other.get(axis).unwrap());
        let v = ex.check(&Answer::typed(&word));
        assert_eq!(hint(&v), Some(Hint::OtherSolution), "{kind:?}: {word} → {v:?}");
        let text = hint_text(&v);
        assert!(text.contains("andere Lösung derselben Lage") && !text.contains("Rechte-Hand"), "{text}");
        // The chosen one is right, and the hint names the solver's rule for choosing it.
        let right = crate::solve::fmt_deg(chosen.get(axis).unwrap());
        assert!(ex.check(&Answer::typed(&right)).is_correct(), "{kind:?}: {right}");
        let Check::Value(c) = &ex.check else { panic!("a value exercise") };
        let e = c.decider.as_deref().expect("the PLANE block's explanation");
        let reason = e.rule.text();
        assert!(text.contains(&*reason.de) && text.contains(&*reason.en), "{text}");
    }
}

#[test]
fn the_stay_questions_get_what_stay_does() {
    let ex = Exercise::generate(Spec::Run(RunKind::Stay), 0);
    // The position the solver computes for SPB+45 is not where A stands after STAY.
    let (chosen, _) = candidates_of(&ex, 6);
    let computed = crate::solve::fmt_deg(chosen.get(RotaryAxis::A).unwrap());
    let v = ex.check(&Answer::typed(&computed));
    assert_eq!(hint(&v), Some(Hint::Stay), "{computed}");
    assert!(hint_text(&v).contains("Q120"));
    assert_eq!(hint(&ex.check(&Answer::typed("-10"))), Some(Hint::Stay));
    // Q120 holds the computed angle even though nothing moves.
    let q = Exercise::generate(Spec::Run(RunKind::StayQ120), 0);
    assert!(q.check(&Answer::typed(&computed)).is_correct());
    assert_eq!(hint(&q.check(&Answer::typed("0"))), Some(Hint::Stay));
    // PLANE RESET STAY: the axes stay tilted.
    let r = Exercise::generate(Spec::Run(RunKind::ResetStay), 0);
    let (tilt, _) = candidates_of(&r, 6);
    assert!(r.check(&Answer::typed(&crate::solve::fmt_deg(tilt.get(RotaryAxis::A).unwrap()))).is_correct());
    let v = r.check(&Answer::typed("0"));
    assert_eq!(hint(&v), Some(Hint::Stay));
    assert!(hint_text(&v).contains("PLANE RESET STAY"));
}

#[test]
fn coord_rot_and_table_rot_get_their_own_hints() {
    use crate::plane::TransformMode;
    use crate::solve::solve_block;
    let machine = Machine::builtin("ac-table").unwrap();
    let solve_as = |mode| {
        let mut block = plane(spatial_def([0.0, 0.0, 30.0]), Some(TURN_FMAX));
        block.transform = Some(mode);
        let e = solve_block(&machine, &block, DMat3::IDENTITY, &SolveOptions::default()).unwrap();
        e.chosen_axes().unwrap()
    };
    let (coord, table) = (solve_as(TransformMode::CoordRot), solve_as(TransformMode::TableRot));
    // What the hints say: the tool stays vertical (A does not tilt); COORD ROT leaves the table
    // (C) where it stood, TABLE ROT turns it.
    for axes in [coord, table] {
        assert!(axes.get(RotaryAxis::A).unwrap().abs() < 1e-9);
    }
    assert!(coord.get(RotaryAxis::C).unwrap().abs() < 1e-9);
    assert!(table.get(RotaryAxis::C).unwrap().abs() > 1.0);
    for (kind, mixed_up) in [(ChooseKind::TableRot, coord), (ChooseKind::CoordRot, table)] {
        let ex = Exercise::generate(Spec::Choose(kind), 0);
        let v = ex.check(&Answer::typed(&crate::solve::axis_words(&mixed_up)));
        assert_eq!(hint(&v), Some(Hint::Transform), "{kind:?}");
        let text = hint_text(&v);
        let (this, other) = if kind == ChooseKind::TableRot {
            ("TABLE ROT", "COORD ROT")
        } else {
            ("COORD ROT", "TABLE ROT")
        };
        assert!(
            text.starts_with(&format!("Das ist die Stellung mit {other}"))
                && text.contains(&format!("{this}:")),
            "{text}"
        );
        // Any other wrong position, or "the control refuses", still gets what the mode does.
        let v = ex.check(&Answer::typed("A+20 C+5"));
        assert_eq!(hint(&v), Some(Hint::Transform));
        assert!(hint_text(&v).starts_with(&format!("{this}:")));
        let v = ex.check(&Answer::ControlError);
        assert_eq!(hint(&v), Some(Hint::ControlFinds));
        assert!(hint_text(&v).contains(&format!("{this}:")));
    }
}
