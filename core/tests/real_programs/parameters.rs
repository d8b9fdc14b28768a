//! Q, QR and QL parameters and the FN functions as real programs use them: SYSREAD, TABREAD,
//! jumps, repeats and tools from parameters.

use super::*;

#[test]
fn qr_and_ql_parameters_wherever_q_is_allowed() {
    same("QR1 = 5", "QR1 = +5");
    same("L X+QR20 Y-QL3 FMAX", "L X+QR20 Y-QL3 FMAX");
    same("BLK FORM 0.2 X+QR1 Y+QR2 Z+0", "BLK FORM 0.2 X+QR1 Y+QR2 Z+0");
    same("FN 0:QL2=QR1", "FN 0: QL2 = QR1");
    match body("L X+QR20 Y-QL3 Z+Q7") {
        BlockBody::L(l) => {
            let v: Vec<_> = l.axes.iter().map(|w| w.value).collect();
            assert_eq!(
                v,
                [
                    Value::Param { index: QR_BASE + 20, negate: false },
                    Value::Param { index: QL_BASE + 3, negate: true },
                    Value::Param { index: 7, negate: false },
                ]
            );
        }
        other => panic!("{other:?}"),
    }
    // QL/QR beyond the control's 0…499, Q beyond its range: an error, never another parameter.
    for bad in ["QL500 = 1", "L X+QR500", "Q1000000 = 1"] {
        let (_, d) = parse(&format!("1 {bad}\n"));
        assert!(d.iter().any(|d| d.is_error()), "{bad}");
    }
}

#[test]
fn qr_and_ql_values_reach_the_machine() {
    let (p, sim) = run("0 BEGIN PGM Q MM\n\
         1 TOOL CALL 1 Z S1000\n\
         2 QR1 = 5\n\
         3 QL2 = QR1 * 3\n\
         4 L X+QL2 Y-QR1 Z+20 R0 FMAX\n\
         5 END PGM Q MM\n");
    let s = after(&p, &sim, 4);
    assert!((s.tip_wcs.x - 15.0).abs() < 1e-9 && (s.tip_wcs.y + 5.0).abs() < 1e-9, "{:?}", s.tip_wcs);
}

#[test]
fn fn_functions_the_trainer_does_not_compute_are_kept_and_said() {
    same("FN18: SYSREAD Q32 = ID270 NR1 IDX3", "FN 18: SYSREAD Q32 = ID270 NR1 IDX3");
    same("FN15: PRINT Q1/Q2", "FN 15: PRINT Q1/Q2");
    same("FN 16: F-PRINT TNC:\\MASKE.A/SCREEN:", "FN 16: F-PRINT TNC:\\MASKE.A/SCREEN:");
    same("FN 28: TABREAD Q80 =0 /\"Stueck\"", "FN 28: TABREAD Q80 =0 /\"Stueck\"");
    let (p, sim) = run("0 BEGIN PGM F MM\n1 FN 18: SYSREAD Q32 = ID990 NR2\n2 END PGM F MM\n");
    let m = after(&p, &sim, 1).message().expect("said on its block");
    assert!(m.de.contains("nicht simuliert") && m.en.contains("not simulated"), "{m:?}");
    // FN 14 stops the run with the program's own error.
    let (program, _) = parse("0 BEGIN PGM F MM\n1 FN 14: ERROR = 1000\n2 END PGM F MM\n");
    let sim = simulate(&program, &Machine::builtin("ac-table").expect("m"), &SimOptions::default());
    let e = sim.error.expect("FN 14 stops");
    assert_eq!(e.block, 1);
}

#[test]
fn sysread_gives_the_positions_the_simulator_knows() {
    same("FN18 : SYSREAD Q12 = ID240 NR1 IDX2", "FN 18: SYSREAD Q12 = ID240 NR1 IDX2");
    same("FN 18: SYSREAD QL1 = ID50 NR2 IDXQ11", "FN 18: SYSREAD QL1 = ID50 NR2 IDXQ11");
    let (p, sim) = run("0 BEGIN PGM S MM\n\
         1 TOOL CALL 1 Z S2000\n\
         2 L X+10 Y+5 Z+20 R0 FMAX\n\
         3 FN 18: SYSREAD Q1 = ID270 NR1 IDX1\n\
         4 FN 18: SYSREAD Q3 = ID270 NR1 IDX3\n\
         5 FN 18: SYSREAD Q4 = ID240 NR1 IDX3\n\
         6 FN 18: SYSREAD Q5 = ID20 NR4\n\
         7 FN 18: SYSREAD Q6 = ID10 NR1\n\
         8 END PGM S MM\n");
    let s = after(&p, &sim, 7);
    // The active coordinate system is the programmed one; the REF system the machine axes.
    assert_eq!((s.q[&1], s.q[&3]), (10.0, 20.0));
    assert!((s.q[&4] - s.axes.linear.z).abs() < 1e-12, "{} vs {:?}", s.q[&4], s.axes.linear);
    assert_eq!((s.q[&5], s.q[&6]), (2000.0, 0.0));
}

/// The values programmed in TOOL CALL (group 60: NR1 T, NR2 the tool axis as 0 = X, 1 = Y,
/// 2 = Z, NR3 S) and the active compensation (group 200: NR1 the radius, NR2 the length, the
/// oversizes included), as the technical manuals' data-transfer tables list them: tool 7 of
/// L+80 R+6 called with DL+0.5 DR-0.2 about Y at S3000.
#[test]
fn sysread_gives_the_tool_call_and_the_active_compensation() {
    let (p, sim) = run("0 BEGIN PGM S MM\n\
         1 TOOL DEF 7 L+80 R+6\n\
         2 TOOL CALL 7 Y S3000 DL+0.5 DR-0.2\n\
         3 FN 18: SYSREAD Q1 = ID60 NR1\n\
         4 FN 18: SYSREAD Q2 = ID60 NR2\n\
         5 FN 18: SYSREAD Q3 = ID60 NR3\n\
         6 FN 18: SYSREAD Q4 = ID200 NR1\n\
         7 FN 18: SYSREAD Q5 = ID200 NR2\n\
         8 END PGM S MM\n");
    let s = after(&p, &sim, 7);
    assert_eq!((s.q[&1], s.q[&2], s.q[&3]), (7.0, 1.0, 3000.0));
    assert!((s.q[&4] - 5.8).abs() < 1e-12 && (s.q[&5] - 80.5).abs() < 1e-12, "{} {}", s.q[&4], s.q[&5]);
}

/// `FN 18: SYSREAD … ID50` reads the tool table (iTNC 530 technical manual, "FN18: SYSREAD",
/// group 50: NR1 L, NR2 R, NR4 DL, IDX the tool number): of a tool the program defines, of the
/// active tool without IDX, and of a tool nobody defined the stated default tool, said.
#[test]
fn sysread_id50_gives_the_tool_data() {
    let (p, sim) = run("0 BEGIN PGM S MM\n\
         1 TOOL DEF 7 L+80 R+6\n\
         2 FN 0: Q11 = 7\n\
         3 FN 18: SYSREAD Q1 = ID50 NR1 IDXQ11\n\
         4 FN 18: SYSREAD Q2 = ID50 NR2 IDX7\n\
         5 TOOL CALL 7 Z S1000\n\
         6 FN 18: SYSREAD Q3 = ID50 NR2\n\
         7 FN 18: SYSREAD Q4 = ID50 NR4\n\
         8 FN 18: SYSREAD Q5 = ID50 NR1 IDX4711\n\
         9 END PGM S MM\n");
    let s = after(&p, &sim, 8);
    assert_eq!((s.q[&1], s.q[&2], s.q[&3], s.q[&4]), (80.0, 6.0, 6.0, 0.0));
    assert!(s.q[&5] > 0.0, "the default tool has a length");
    let m = s.message().expect("said on its block");
    assert!(m.de.contains("Werkzeug 4711 nicht in der Werkzeugtabelle"), "{m:?}");
    assert!(m.en.contains("tool 4711 not in the tool table"), "{m:?}");
}

/// `FN 28: TABREAD` of a table the simulation does not have (`unconfirmed::TABREAD_ASSUMES_ZERO`):
/// the parameters it fills, one per column, get 0 when they have no value and keep one they
/// have; the block says which.
#[test]
fn tabread_without_the_table_assumes_zero_and_says_so() {
    let (p, sim) = run("0 BEGIN PGM T MM\n\
         1 Q12 = 5\n\
         2 FN 28: TABREAD Q10 = 0 / \"X,Y,Z\"\n\
         3 FN 1: Q10 = +Q10 + +1\n\
         4 END PGM T MM\n");
    let s = after(&p, &sim, 3);
    assert_eq!((s.q[&10], s.q[&11], s.q[&12]), (1.0, 0.0, 5.0));
    let m = after(&p, &sim, 2).message().expect("said on its block");
    assert!(m.de.contains("Q10 = 0 angenommen") && m.de.contains("Q12 bleibt 5"), "{m:?}");
    assert!(m.en.contains("Q11 = 0 assumed") && m.en.contains("Q12 stays 5"), "{m:?}");
}

#[test]
fn fn_6_7_8_compute_as_the_manual_says() {
    same("FN6: Q1 = SIN +30", "FN 6: Q1 = SIN +30");
    same("FN 8: Q3 = +3 LEN +4", "FN 8: Q3 = +3 LEN +4");
    let (p, sim) = run("0 BEGIN PGM T MM\n\
         1 FN 6: Q1 = SIN +30\n\
         2 FN 7: Q2 = COS +60\n\
         3 FN 8: Q3 = +3 LEN +4\n\
         4 END PGM T MM\n");
    let q = after(&p, &sim, 3).q;
    assert!((q[&1] - 0.5).abs() < 1e-12 && (q[&2] - 0.5).abs() < 1e-12, "{q:?}");
    assert!((q[&3] - 5.0).abs() < 1e-12, "{q:?}");
}

#[test]
fn jumps_and_calls_to_a_label_written_without_a_blank() {
    same("FN9: IF +Q18 EQU -10 GOTO LBL1", "FN 9: IF +Q18 EQU -10 GOTO LBL 1");
    same("CALL LBL1", "CALL LBL 1");
    same("LBL1", "LBL 1");
    same("FN 12: IF +Q1 LT +Q2 GOTO LBL\"name\"", "FN 12: IF +Q1 LT +Q2 GOTO LBL \"name\"");
}

/// `TOOL CALL Q5`, `TOOL CALL QL5`, `TOOL CALL QS5` and `TOOL DEF Q6`: the tool number from a
/// numeric parameter; a string parameter's name is not simulated (an unknown tool, said).
#[test]
fn a_tool_called_by_a_parameter() {
    use schwenkbar_core::ast::ToolRef;
    same("TOOL CALL Q5 Z S1000", "TOOL CALL Q5 Z S1000");
    same("TOOL CALL QL5 Z", "TOOL CALL QL5 Z");
    same("TOOL CALL QS5 Z", "TOOL CALL QS5 Z");
    same("TOOL DEF Q6 L+75 R+5", "TOOL DEF Q6 L+75 R+5");
    match body("TOOL CALL QL5 Z") {
        BlockBody::ToolCall(t) => assert_eq!(t.tool, Some(ToolRef::Param(QL_BASE + 5))),
        other => panic!("{other:?}"),
    }
    let src = "0 BEGIN PGM T MM\n1 Q5 = 8\n2 TOOL CALL Q5 Z S1000\n3 Q6 = 40\n\
        4 TOOL DEF Q6 L+75 R+6\n5 TOOL CALL 40 Z\n6 TOOL CALL QS1 Z\n7 END PGM T MM\n";
    let (p, sim) = run(src);
    let t = after(&p, &sim, 2).tool;
    // Tool 8 of the shipped table: BOHRER_D8, L120 R4.
    assert_eq!((t.number, t.name.as_str(), t.length, t.radius, t.known), (8, "BOHRER_D8", 120.0, 4.0, true));
    let t = after(&p, &sim, 5).tool;
    assert_eq!((t.number, t.length, t.radius, t.known), (40, 75.0, 6.0, true), "TOOL DEF Q6 defined tool 40");
    let s = after(&p, &sim, 6);
    assert!(!s.tool.known && s.tool.name == "QS1", "{:?}", s.tool);
    assert!(s.message().is_some_and(|m| m.en.contains("Tool \"QS1\" not in the tool table")));

    let (p, _) = parse("0 BEGIN PGM T MM\n1 Q5 = -2\n2 TOOL CALL Q5 Z\n3 END PGM T MM\n");
    let sim = simulate(&p, &Machine::builtin("ac-table").expect("machine"), &SimOptions::default());
    let e = sim.error.expect("a negative tool number stops");
    assert_eq!(e.line, 3);
    assert!(e.detail.de.contains("Q5 = -2 ist keine Werkzeugnummer"), "{:?}", e.detail);
}

/// `CALL LBL 1 REPQ13` (`unconfirmed::REP_FROM_PARAMETER`): the repeats from a parameter, read
/// as `REP Q13`; a parameter that holds no whole number stops at the call.
#[test]
fn repeats_from_a_parameter() {
    same("CALL LBL 1 REPQ13", "CALL LBL 1 REP Q13");
    same("CALL LBL 1 REP 2", "CALL LBL 1 REP 2");
    let src = |q: &str| {
        format!(
            "0 BEGIN PGM R MM\n1 Q13 = {q}\n2 Q1 = 0\n3 LBL 1\n4 Q1 = Q1 + 1\n5 CALL LBL 1 REPQ13\n\
             6 END PGM R MM\n"
        )
    };
    let (p, sim) = run(&src("2"));
    // REP 2: the section runs 1 + 2 times.
    assert_eq!(after(&p, &sim, 6).q[&1], 3.0);
    let (p, _) = parse(&src("1.5"));
    let sim = simulate(&p, &Machine::builtin("ac-table").expect("machine"), &SimOptions::default());
    let e = sim.error.expect("1.5 repeats stop");
    assert_eq!(e.line, 6);
    assert!(e.detail.en.contains("REP Q13 = 1.5"), "{:?}", e.detail);
}
