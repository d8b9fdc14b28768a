//! The tools and the machine a real program runs with: TOOL DEF, a shop's tool table, the machine
//! picked for the program and the blank on its table.

use super::*;

#[test]
fn tool_def_gives_the_called_tool_its_length_and_radius() {
    same("TOOL DEF 2 L+75 R+5", "TOOL DEF 2 L+75 R+5");
    same("TOOL DEF 0", "TOOL DEF 0");
    let noted = [
        DiagCode::Lenient { kind: Lenient::BlankAfterAddress, text: "R 3,5".into() },
        DiagCode::Lenient { kind: Lenient::DecimalComma, text: "3,5".into() },
    ];
    same_said("TOOL DEF 7 R 3,5", "TOOL DEF 7 R+3.5", &noted);
    let (p, sim) = run("0 BEGIN PGM T MM\n\
         1 TOOL DEF 2 L+75 R+5\n\
         2 TOOL CALL 2 Z S1000\n\
         3 END PGM T MM\n");
    let s = after(&p, &sim, 2);
    assert_eq!((s.tool.length, s.tool.radius), (75.0, 5.0));
    assert_eq!((s.q[&108], s.q[&114]), (5.0, 75.0), "Q108/Q114 preassigned");
}

/// A tool length under 30 mm is the difference to a zero tool (TNC 370/426 manuals, ch. 4.2):
/// the simulated tool is 100 mm + L long (`unconfirmed::physical_tool_length`), Q114 keeps the
/// program's L, and the TOOL CALL says so. Oracle: 100 − 55.606 = 44.394; with L+1 taken as
/// 1 mm the holder (Ø52) would sit 1 mm above the tip and hit the blank at the first plunge.
#[test]
fn a_tool_length_under_30_mm_is_a_difference_to_a_zero_tool() {
    let (p, sim) = run("0 BEGIN PGM T MM\n\
         1 BLK FORM 0.1 Z X+0 Y+0 Z-35\n\
         2 BLK FORM 0.2 X+30 Y+30 Z+0\n\
         3 TOOL DEF 5 L-55.606 R+3\n\
         4 TOOL DEF 6 L+1 R+7\n\
         5 TOOL CALL 5 Z S1000\n\
         6 TOOL CALL 6 Z S1000 DL+0.5\n\
         7 L X+15 Y+15 Z+25 R0 FMAX M3\n\
         8 L Z-20 F200\n\
         9 L Z+25 FMAX\n\
         10 END PGM T MM\n");
    let s = after(&p, &sim, 5);
    assert!((s.tool.length - 44.394).abs() < 1e-9, "{}", s.tool.length);
    assert!((s.q[&114] + 55.606).abs() < 1e-9, "Q114 is the control's L");
    let said = s.message().expect("said on the TOOL CALL");
    assert!(
        said.de.contains("L=-55.606 gilt als Differenz zum Nullwerkzeug: simuliert mit L=+44.394"),
        "{said:?}"
    );
    let s = after(&p, &sim, 6);
    assert!((s.tool.length - 101.5).abs() < 1e-9, "100 + 1 + DL 0.5: {}", s.tool.length);
    assert!((s.q[&114] - 1.5).abs() < 1e-9);
    assert!(after(&p, &sim, 8).tool.length > 100.0, "the plunge runs without a holder collision");
}

/// The shop's tool table replaces the shipped one: its L, R, R2 and deltas (added to the TOOL
/// CALL's, as the manuals' "delta values" say) reach the run; a tool it lacks runs with the
/// stated default and a note naming it.
#[test]
fn a_shop_tool_table_gives_the_called_tools() {
    use schwenkbar_core::sim::tools::{ToolShape, read_tool_table};
    let table = read_tool_table(
        "BEGIN TOOL.T MM\n\
         T  NAME        L     R    R2   DL    DR\n\
         5  TORUS_D20   +90   +10  +2   +0,5  -0,1\n\
         [END]\n",
    )
    .expect("table");
    let (program, _) = parse(
        "0 BEGIN PGM T MM\n1 TOOL CALL 5 Z S1000 DL+0.25\n2 TOOL CALL \"TORUS_D20\" Z\n3 TOOL CALL 1 Z\n4 END PGM T MM\n",
    );
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&program, &m, &SimOptions { tools: Some(table.into()), ..SimOptions::default() });
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s = after(&program, &sim, 1);
    assert_eq!((s.tool.length, s.tool.radius), (90.75, 9.9), "90 + 0.5 + 0.25, 10 − 0.1");
    assert_eq!(s.tool.shape, ToolShape::Bull { corner_radius: 2.0 });
    assert_eq!(after(&program, &sim, 2).tool.number, 5, "called by its name");
    let s = after(&program, &sim, 3);
    assert!(!s.tool.known, "tool 1 is in the shipped table, not in the shop's");
    let said = s.message().expect("said");
    assert_eq!(said.de, "Werkzeug 1 nicht in der Werkzeugtabelle: L=100 R=5 angenommen");
}

#[test]
fn the_machine_for_a_program_has_its_rotary_axes_and_runs_it_furthest() {
    use schwenkbar_core::plane::RotaryAxis;
    use schwenkbar_core::sim::{pick_machine, programmed_rotary_axes};
    let machines: Vec<Machine> =
        Machine::builtin_ids().iter().map(|id| Machine::builtin(id).expect("shipped")).collect();
    let program = |words: &str| {
        parse(&format!(
            "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S1000\n2 L Z+50 R0 FMAX\n3 {words}\n4 END PGM P MM\n"
        ))
        .0
    };
    let p = program("PLANE AXIAL B+30 C+45 TURN FMAX");
    assert_eq!(programmed_rotary_axes(&p), [RotaryAxis::B, RotaryAxis::C]);
    let pick = pick_machine(&p, &machines, &SimOptions::default());
    let chosen = &machines[pick.index];
    assert!(chosen.joints().iter().any(|j| j.axis == RotaryAxis::B), "{}", chosen.id);
    assert!(pick.simulation.error.is_none(), "{:?}", pick.simulation.error);
    assert!(pick.reason.de.contains("B, C") && pick.reason.de.contains(&chosen.id), "{:?}", pick.reason);
    // No rotary axis: the first machine on which it runs to the end.
    let p = program("L X+10 Y+10 R0 FMAX");
    assert!(programmed_rotary_axes(&p).is_empty());
    assert_eq!(pick_machine(&p, &machines, &SimOptions::default()).index, 0);
    // A stopped run loses to one that runs to the end: Z+5000 is beyond every machine's travel,
    // so every run stops and the one furthest wins (ties: the first).
    let p = program("L Z+5000 R0 FMAX");
    let pick = pick_machine(&p, &machines, &SimOptions::default());
    assert!(pick.simulation.error.is_some() && pick.reason.en.contains("gets furthest"), "{:?}", pick.reason);
}

/// On a machine that knows its table top the blank sits centred on the table and the preset
/// follows it; an edit of the BLK FORM moves it in a resumed run as in a fresh one; a machine
/// without a table top keeps its preset (the five teaching machines).
#[test]
fn the_blank_sits_on_the_table_of_a_machine_that_knows_it() {
    use glam::DVec3;
    use std::sync::Arc;
    let teaching = Machine::builtin("ac-table").expect("machine");
    let mut real = teaching.clone();
    real.geometry.table_top = Some(DVec3::new(0.0, 0.0, -210.0));
    let src = |z: &str| {
        format!(
            "0 BEGIN PGM T MM\n1 BLK FORM 0.1 Z X-50 Y-40 Z{z}\n2 BLK FORM 0.2 X+50 Y+40 Z+0\n\
             3 TOOL CALL 1 Z S1000\n4 L X+0 Y+0 Z+10 R0 FMAX\n5 END PGM T MM\n"
        )
    };
    let (p, _) = parse(&src("-30"));
    let sim = Arc::new(simulate(&p, &real, &SimOptions::default()));
    assert!(sim.error.is_none(), "{:?}", sim.error);
    // Blank centre (0, 0), bottom Z−30 on the C table's top at Z−210: the datum (top face) at Z−180.
    assert_eq!(sim.machine.geometry.preset, DVec3::new(0.0, 0.0, -180.0));
    assert_eq!(
        simulate(&p, &teaching, &SimOptions::default()).machine.geometry.preset,
        teaching.geometry.preset
    );
    let (q, _) = parse(&src("-60"));
    let resumed = sim.resumed(&q, 1..2);
    let fresh = simulate(&q, &real, &SimOptions::default());
    assert_eq!(resumed.machine.geometry.preset, DVec3::new(0.0, 0.0, -150.0));
    assert_eq!(resumed.records, fresh.records, "the resumed run is the fresh one");
}
