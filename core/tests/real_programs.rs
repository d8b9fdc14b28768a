//! Programs as CAM systems, shops and trainees write them (issue 30): every family reads as the
//! control's own spelling (the same AST, `fmt` writes the control's form), lenient spellings are
//! said once per file, and every block runs: executed, or said on its block, never skipped.
//! Oracles: closed forms worked by hand (sin 30° = 0.5, 3–4–5, a retract of 50 mm along an
//! untilted Z axis, the cycle's set-up clearance above the surface).

use schwenkbar_core::ast::{BlockBody, CycleValue, QL_BASE, QR_BASE};
use schwenkbar_core::diag::{DiagCode, Severity};
use schwenkbar_core::format::format_program;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::parse::Lenient;
use schwenkbar_core::plane::{MoveBack, Value};
use schwenkbar_core::sim::{SimOptions, Simulation, State, simulate};
use schwenkbar_core::{Program, parse};

/// `written` and `canonical` (one block each, numbered 1) give the same block and `fmt` text;
/// `written` with exactly the diagnostics `said`.
fn same_said(written: &str, canonical: &str, said: &[DiagCode]) {
    let (a, da) = parse(&format!("1 {written}\n"));
    let (b, db) = parse(&format!("1 {canonical}\n"));
    assert!(db.is_empty(), "{canonical}: {db:?}");
    let codes: Vec<_> = da.iter().map(|d| d.code.clone()).collect();
    assert_eq!(codes, said, "{written}");
    assert!(da.iter().all(|d| d.severity == Severity::Warning), "{written}: {da:?}");
    assert_eq!(a.blocks[0].body(), b.blocks[0].body(), "{written} ≠ {canonical}");
    assert_eq!(format_program(&a), format_program(&b), "fmt writes the control's spelling");
}

fn same(written: &str, canonical: &str) {
    same_said(written, canonical, &[]);
}

/// The body of the one block of `src`, read without a diagnostic.
fn body(src: &str) -> BlockBody {
    let (p, d) = parse(&format!("1 {src}\n"));
    assert!(d.is_empty(), "{src}: {d:?}");
    p.blocks[0].body().into_owned()
}

fn run(src: &str) -> (Program, Simulation) {
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{src}\n{diags:?}");
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    assert!(sim.error.is_none(), "{src}\n{:?}", sim.error);
    (program, sim)
}

fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
    let step = sim.first_step[idx].expect("executed") as usize;
    sim.state_at(program, step).expect("state")
}

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
    let m = after(&p, &sim, 1).message.expect("said on its block");
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
    let m = s.message.expect("said on its block");
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
    let m = after(&p, &sim, 2).message.expect("said on its block");
    assert!(m.de.contains("Q10 = 0 angenommen") && m.de.contains("Q12 bleibt 5"), "{m:?}");
    assert!(m.en.contains("Q11 = 0 assumed") && m.en.contains("Q12 stays 5"), "{m:?}");
}

/// A training simulator's export, written here in its dialect: a message header, `BEGIN PGM  MM`
/// without a name, `TOOL DEF1`, `CYCL END` and `END PGM` without name and unit. It opens with a
/// warning for each and runs to its end; `CYCL END` is said on its block. A named program still
/// needs its name at the end, and BEGIN PGM its unit.
#[test]
fn a_training_simulators_export_opens_and_runs() {
    same("TOOL DEF1 L+30 R+4", "TOOL DEF 1 L+30 R+4");
    let src = "($Message(\"Load the machine settings first\") )\n\
        BEGIN PGM  MM\n\
        TOOL DEF1 L+30,000 R+4,000\n\
        TOOL CALL 1 Z S1500\n\
        L Z+5.000 R0 F9999 M13\n\
        L X+10 Y+10\n\
        CYCL END\n\
        END PGM\n";
    let (p, diags) = parse(src);
    let codes: Vec<_> = diags.iter().map(|d| d.code.clone()).collect();
    for code in [DiagCode::PgmNameMissing, DiagCode::EndPgmUnitMissing, DiagCode::UnknownBlock] {
        assert!(codes.contains(&code), "{code:?} in {codes:?}");
    }
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let sim = simulate(&p, &Machine::builtin("ac-table").expect("machine"), &SimOptions::default());
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let cycl_end =
        p.blocks.iter().position(|b| matches!(&*b.body(), BlockBody::Unknown { .. })).expect("kept");
    let state = sim.state_at(&p, sim.first_step[cycl_end].expect("executed") as usize).expect("state");
    let m = state.message.expect("said on its block");
    assert!(m.de.contains("nicht simuliert: CYCL END"), "{m:?}");
    assert_eq!(format_program(&parse(&format_program(&p)).0), format_program(&p), "fmt is stable");
    // Another name in END PGM (`unconfirmed::END_PGM_NAME_IS_BOOKKEEPING`): said, not refused,
    // and the program runs to its end.
    let (p, d) = parse("0 BEGIN PGM X MM\n1 L X+0 R0 FMAX\n2 END PGM\n");
    assert!(d.iter().any(|d| !d.is_error() && matches!(d.code, DiagCode::PgmNameMismatch { .. })), "{d:?}");
    assert!(d.iter().all(|d| !d.is_error()), "{d:?}");
    let sim = simulate(&p, &Machine::builtin("ac-table").expect("machine"), &SimOptions::default());
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let (_, d) = parse("0 BEGIN PGM YL-01 MM\n1 L Z+0 R0 FMAX\n2 END PGM 100 MM\n");
    let said: Vec<_> = d.iter().filter(|d| matches!(d.code, DiagCode::PgmNameMismatch { .. })).collect();
    assert_eq!(said.len(), 1, "{d:?}");
    assert!(
        said[0].code.message().de.contains("END PGM 100 zu BEGIN PGM YL-01"),
        "{:?}",
        said[0].code.message()
    );
    let (_, d) = parse("0 BEGIN PGM X\n1 END PGM X MM\n");
    assert!(d.iter().any(|d| d.is_error()), "BEGIN PGM needs its unit: {d:?}");
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

#[test]
fn an_old_controls_empty_words_are_words_not_programmed() {
    // TNC 155/355 listings print `R F M` where nothing was entered: the same block without them.
    same("L X+32.000 Y+0.000 R F5000 M13", "L X+32 Y+0 F5000 M13");
    same("L Y+6.500 R F M", "L Y+6.5");
    same("CYCL CALL M", "CYCL CALL");
    same("CALL LBL 1 REP", "CALL LBL 1");
    // … but a value after a blank and F's own MAX and AUTO stay the words they are.
    same("L X+1 F MAX", "L X+1 FMAX");
    same("L X+1 RL F AUTO", "L X+1 RL F AUTO");
    let (_, d) = parse("1 L X+1 F M3\n");
    assert!(d.is_empty(), "{d:?}");
    let (_, d) = parse("1 L X+1 R\n");
    assert!(d.is_empty(), "{d:?}");
    // The feed and the radius compensation stay as they were: 5000 mm/min after `F`, RL after `R`.
    let src = "0 BEGIN PGM OLD MM\n1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+2 R0 F5000\n\
               3 L X+10 R F M\n4 L Y+10 RL F200\n5 L X+20 R F M\n6 L Z+50 R0 F M\n7 END PGM OLD MM\n";
    let (program, sim) = run(src);
    assert_eq!(after(&program, &sim, 3).feed, 5000.0);
    let s5 = after(&program, &sim, 5);
    assert_eq!(s5.feed, 200.0);
    // With RL kept the tool centre stands the radius left of X+20 Y+10; with R0 it would not.
    let tip = |src: &str| {
        let (p, s) = run(src);
        after(&p, &s, 5).tip_wcs
    };
    assert_eq!(s5.tip_wcs, tip(&src.replace("5 L X+20 R F M", "5 L X+20 RL")));
    assert_ne!(s5.tip_wcs, tip(&src.replace("5 L X+20 R F M", "5 L X+20 R0")));
}

#[test]
fn m140_mb_and_the_feed_of_m128_belong_to_their_m_function() {
    same("L M140 MB MAX", "L M140 MB MAX");
    same("M140 MB MAX", "M140 MB MAX");
    same("M140 MB 50", "M140 MB+50");
    same("L X+1 FQ3 M128 FQ9", "L X+1 FQ3 M128 FQ9");
    same("M128 F25000", "M128 F25000");
    match body("L X+1 F500 M128 F1000") {
        BlockBody::L(l) => {
            assert!(
                matches!(l.feed, Some(schwenkbar_core::plane::Feed::Value(Value::Number(f))) if f == 500.0)
            );
            assert_eq!(l.m_words.m128_feed, Some(Value::Number(1000.0)));
        }
        other => panic!("{other:?}"),
    }
    match body("M140 MB MAX M9") {
        BlockBody::MFunctions(m, w) => {
            assert_eq!(&*m, &[140, 9]);
            assert_eq!(w.mb, Some(MoveBack::Max));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn m140_retracts_along_the_tool_axis() {
    let (p, sim) = run("0 BEGIN PGM R MM\n\
         1 TOOL CALL 1 Z S1000\n\
         2 L X+10 Y+5 Z+2 R0 FMAX\n\
         3 M140 MB+50\n\
         4 L M140 MB MAX\n\
         5 END PGM R MM\n");
    let (before, up) = (after(&p, &sim, 2), after(&p, &sim, 3));
    // Untilted: the tool axis is Z, so the tip rises by exactly 50 and stays over X10 Y5.
    assert!((up.tip_wcs - before.tip_wcs - glam::DVec3::new(0.0, 0.0, 50.0)).length() < 1e-9);
    let max = after(&p, &sim, 4);
    assert!(max.tip_wcs.z > up.tip_wcs.z && (max.tip_wcs.x - 10.0).abs() < 1e-9, "{:?}", max.tip_wcs);
    assert!(max.message.is_some_and(|m| m.de.contains("M140")), "said on its block");
}

#[test]
fn cycle_parameters_with_symbolic_values() {
    let def = |v: &str| format!("0 BEGIN PGM C MM\n1 CYCL DEF 200 BOHREN ~\n  Q206={v} ;VORSCHUB TIEFENZ.\n");
    let value = |v: &str| match parse(&def(v)).0.blocks[1].body().into_owned() {
        BlockBody::CycleDef(c) => c.params[0].value,
        other => panic!("{other:?}"),
    };
    assert_eq!(value("AUTO"), CycleValue::Fauto);
    assert_eq!(value(" FAUTO"), CycleValue::Fauto);
    assert_eq!(value("FMAX"), CycleValue::Fmax);
    assert_eq!(value("PREDEF"), CycleValue::Predef);
    assert_eq!(value("-Q5"), CycleValue::Value(Value::Param { index: 5, negate: true }));
    assert_eq!(value("+QR15"), CycleValue::Value(Value::Param { index: QR_BASE + 15, negate: false }));
    let (p, _) = parse(&def("AUTO"));
    assert!(format_program(&p).contains("Q206=FAUTO"), "{}", format_program(&p));

    // Cycle 200 with PREDEF set-up clearance (2 mm, unconfirmed::predef) and FAUTO/FMAX feeds:
    // the tool goes down to Q203 + 2 first (cycle manual: "to the set-up clearance above the
    // workpiece surface").
    let src = "0 BEGIN PGM C MM\n\
        1 TOOL CALL 1 Z S1000 F300\n\
        2 CYCL DEF 200 BOHREN ~\n\
        \x20 Q200=PREDEF ;SICHERHEITS-ABST. ~\n\
        \x20 Q201=-10 ;TIEFE ~\n\
        \x20 Q206=AUTO ;VORSCHUB TIEFENZ. ~\n\
        \x20 Q202=+10 ;ZUSTELL-TIEFE ~\n\
        \x20 Q210=+0 ;VERWEILZEIT OBEN ~\n\
        \x20 Q203=+0 ;KOOR. OBERFL. ~\n\
        \x20 Q204=PREDEF ;2. SICHERHEITS-ABST. ~\n\
        \x20 Q211=+0 ;VERWEILZEIT UNTEN ~\n\
        \x20 Q395=+0 ;BEZUG TIEFE ~\n\
        \x20 Q208=FMAX ;VORSCHUB RUECKZUG\n\
        3 L X+10 Y+10 Z+60 R0 FMAX M3\n\
        4 CYCL CALL\n\
        5 END PGM C MM\n";
    let (p, sim) = run(src);
    let s = after(&p, &sim, 4);
    let m = Machine::builtin("ac-table").expect("m");
    let kin = schwenkbar_core::sim::Kin::new(&m, s.tool.length);
    let first = kin.tip_wcs(&s.segments[0].axes_at(1.0));
    assert!((first.z - 2.0).abs() < 1e-9, "first stop {first:?}");
    let deepest = s.segments.iter().map(|g| kin.tip_wcs(&g.axes_at(1.0)).z).fold(f64::INFINITY, f64::min);
    assert!((deepest + 10.0).abs() < 1e-9, "{deepest}");
}

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
    let said = s.message.expect("said on the TOOL CALL");
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
    let said = s.message.expect("said");
    assert_eq!(said.de, "Werkzeug 1 nicht in der Werkzeugtabelle: L=100 R=5 angenommen");
}

#[test]
fn lenient_spellings_are_said_once_per_kind_and_file() {
    let comma = DiagCode::Lenient { kind: Lenient::DecimalComma, text: "+27,975".into() };
    same_said("L X+27,975 Y-26,5 R0 FMAX", "L X+27.975 Y-26.5 R0 FMAX", &[comma]);
    let blank = DiagCode::Lenient { kind: Lenient::BlankAfterAddress, text: "Z 25.000".into() };
    same_said("L Z 25.000 FMAX", "L Z+25 FMAX", &[blank]);
    same("CYCL DEF 7.1  X + 0", "CYCL DEF 7.1 X+0");
    // Many lines, one note of each kind.
    let src: String = (1..=200).map(|n| format!("{n} L X+{n},5 Y {n} F 500\n")).collect();
    let (program, d) = parse(&src);
    assert_eq!(program.blocks.len(), 200);
    let kinds: Vec<_> = d
        .iter()
        .filter_map(|d| match &d.code {
            DiagCode::Lenient { kind, .. } => Some(*kind),
            _ => None,
        })
        .collect();
    assert_eq!(kinds, [Lenient::DecimalComma, Lenient::BlankAfterAddress], "{d:?}");
    assert!(d.iter().all(|d| !d.is_error()));
}

#[test]
fn stop_qs_touch_probe_and_a_setup_header_run_and_are_said() {
    same("STOP", "STOP");
    same("STOP M0", "STOP M0");
    same("QS10 = \"ABC\"", "QS10 = \"ABC\"");
    let src = "(Maschine: Fraese 5 Achsen)\n\
        (Quader: QX100 QY90 QZ20)\n\
        0 BEGIN PGM P MM\n\
        1 TOOL CALL 1 Z S1000\n\
        2 STOP\n\
        3 QS1 = \"TEXT\"\n\
        4 TCH PROBE 412 BEZUGSPUNKT KREIS INNEN ~\n\
        \x20 Q321=+50 ;MITTE 1. ACHSE ~\n\
        \x20 Q322=+50 ;MITTE 2. ACHSE\n\
        5 CYCL DEF 392 ATC ~\n\
        \x20 Q240=0 ;MODE\n\
        6 M30\n\
        7 END PGM P MM\n";
    let (p, sim) = run(src);
    assert!(matches!(&*p.blocks[0].body(), BlockBody::Header { text } if text.contains("Maschine")));
    match &*p.blocks[6].body() {
        BlockBody::TouchProbe(c) => assert_eq!((c.number, c.params.len()), (412, 2)),
        other => panic!("{other:?}"),
    }
    assert_eq!(format_program(&parse(&format_program(&p)).0), format_program(&p), "fmt is stable");
    for n in [2, 3, 4] {
        assert!(after(&p, &sim, n).message.is_some(), "block {n} says what it does");
    }
}

/// Never silent (the brief): over a program of every family (its one jump not taken), each
/// block is executed with its own record, or is a comment/structure/header block; no block is
/// left out.
#[test]
fn every_block_of_every_family_runs_or_says_why_not() {
    let src = std::fs::read_to_string(format!(
        "{}/../tests/fixtures/ok/real_families.h",
        env!("CARGO_MANIFEST_DIR")
    ))
    .expect("fixture");
    let (p, sim) = run(&src);
    for (i, b) in p.blocks.iter().enumerate() {
        let quiet = matches!(
            &*b.body(),
            BlockBody::Empty
                | BlockBody::Structure { .. }
                | BlockBody::Header { .. }
                | BlockBody::EndPgm { .. }
        );
        let Some(step) = sim.first_step[i] else {
            assert!(quiet, "block {i} never ran: {:?}", b.body());
            continue;
        };
        let s = sim.state_at(&p, step as usize).expect("state");
        // END PGM after M30 is listed, not executed (unconfirmed::LIST_BLOCKS_AFTER_END).
        assert!(s.executed || quiet, "block {i} listed only");
        if matches!(
            &*b.body(),
            BlockBody::Unknown { .. }
                | BlockBody::FnOther { .. }
                | BlockBody::TouchProbe(_)
                | BlockBody::QsAssign { .. }
        ) {
            assert!(s.message.is_some(), "block {i} not modelled and not said: {:?}", b.body());
        }
    }
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

/// The same part written in inches and in millimetres: every length × 25.4, every F × 2.54
/// (1/10 inch/min). The oracle is the millimetre program, converted by hand.
const INCH_PART: &str = "0 BEGIN PGM IN INCH
1 BLK FORM 0.1 Z X-2 Y-2 Z-1
2 BLK FORM 0.2 X+2 Y+2 Z+0
3 TOOL CALL 1 Z S3000 F100 DL+0.01
4 L Z+2 R0 FMAX M3
5 L X+1 Y+0.5 F200
6 FN 18: SYSREAD Q5 = ID270 NR1 IDX1
7 CC X+0 Y+0.5
8 C X-1 Y+0.5 DR+
9 CR X+0 Y-0.5 R+1 DR-
10 L Z+0.5 FMAX
11 CYCL DEF 200 BOHREN ~
  Q200=+0.1 ;SICHERHEITS-ABST. ~
  Q201=-0.5 ;TIEFE ~
  Q206=+50 ;VORSCHUB TIEFENZ. ~
  Q202=+0.25 ;ZUSTELL-TIEFE ~
  Q210=+0 ;VERWEILZEIT OBEN ~
  Q203=+0 ;KOOR. OBERFLAECHE ~
  Q204=+1 ;2. SICHERHEITS-ABST. ~
  Q211=+0 ;VERWEILZEIT UNTEN
12 L X+0.5 Y+0.5 FMAX M99
13 CYCL DEF 7.0 NULLPUNKT
14 CYCL DEF 7.1 X+0.1
15 L IX+0.25 F300
16 PLANE SPATIAL SPA+0 SPB+10 SPC+0 TURN MB+0.5 F200 SEQ-
17 L Z+1 FMAX
18 PLANE RESET TURN F500
19 L M140 MB+1
20 END PGM IN INCH
";

const MM_PART: &str = "0 BEGIN PGM IN MM
1 BLK FORM 0.1 Z X-50.8 Y-50.8 Z-25.4
2 BLK FORM 0.2 X+50.8 Y+50.8 Z+0
3 TOOL CALL 1 Z S3000 F254 DL+0.254
4 L Z+50.8 R0 FMAX M3
5 L X+25.4 Y+12.7 F508
6 FN 18: SYSREAD Q5 = ID270 NR1 IDX1
7 CC X+0 Y+12.7
8 C X-25.4 Y+12.7 DR+
9 CR X+0 Y-12.7 R+25.4 DR-
10 L Z+12.7 FMAX
11 CYCL DEF 200 BOHREN ~
  Q200=+2.54 ;SICHERHEITS-ABST. ~
  Q201=-12.7 ;TIEFE ~
  Q206=+127 ;VORSCHUB TIEFENZ. ~
  Q202=+6.35 ;ZUSTELL-TIEFE ~
  Q210=+0 ;VERWEILZEIT OBEN ~
  Q203=+0 ;KOOR. OBERFLAECHE ~
  Q204=+25.4 ;2. SICHERHEITS-ABST. ~
  Q211=+0 ;VERWEILZEIT UNTEN
12 L X+12.7 Y+12.7 FMAX M99
13 CYCL DEF 7.0 NULLPUNKT
14 CYCL DEF 7.1 X+2.54
15 L IX+6.35 F762
16 PLANE SPATIAL SPA+0 SPB+10 SPC+0 TURN MB+12.7 F508 SEQ-
17 L Z+25.4 FMAX
18 PLANE RESET TURN F1270
19 L M140 MB+25.4
20 END PGM IN MM
";

#[test]
fn an_inch_program_moves_the_machine_as_its_millimetre_twin() {
    let (pi, si) = run(INCH_PART);
    let (pm, sm) = run(MM_PART);
    assert_eq!(si.states(&pi).count(), sm.states(&pm).count());
    let close = |a: f64, b: f64, what: &str| assert!((a - b).abs() < 1e-9, "{what}: {a} ≠ {b}");
    for n in 1..=19 {
        let (a, b) = (after(&pi, &si, n), after(&pm, &sm, n));
        for k in 0..3 {
            close(a.axes.linear[k], b.axes.linear[k], &format!("block {n} axis {k}"));
            close(a.tip_ics[k], b.tip_ics[k], &format!("block {n} IST {k}"));
        }
        for k in 0..2 {
            close(a.axes.rotary[k], b.axes.rotary[k], &format!("block {n} rotary {k}"));
        }
        close(a.tool.length, b.tool.length, "tool length");
        close(a.feed, b.feed, &format!("block {n} feed (mm/min)"));
        assert_eq!(a.segments.len(), b.segments.len(), "block {n}: the same moves");
        // Linear motion takes the same time; the rotary share of a swivel keeps F as written
        // (°/min), so the TURN blocks differ.
        if !matches!(n, 16 | 18) {
            close(a.duration(), b.duration(), &format!("block {n} duration"));
        }
        assert_eq!(a.blank, b.blank, "the blank in mm");
    }
    // The position display shows the program's unit: X+1 Y+0.5 after block 5.
    let s5 = after(&pi, &si, 5);
    assert_eq!(s5.unit, schwenkbar_core::ast::Unit::Inch);
    close(s5.shown(s5.tip_ics.x), 1.0, "IST X in inches");
    close(s5.shown_feed(s5.feed), 200.0, "F as written");
    // Q parameters keep the program's numbers: SYSREAD gives inches, Q114 the length in inches.
    close(after(&pi, &si, 6).q[&5], 1.0, "SYSREAD X in inches");
    close(after(&pm, &sm, 6).q[&5], 25.4, "SYSREAD X in mm");
    close(after(&pi, &si, 3).q[&114] * 25.4, after(&pm, &sm, 3).q[&114], "Q114");
    // The drill reaches Q201 = -0.5 inch = -12.7 mm below the surface.
    let drilled = after(&pi, &si, 12);
    let deepest = drilled.segments.iter().map(|s| s.end.linear.z).fold(f64::INFINITY, f64::min);
    let deepest_mm =
        after(&pm, &sm, 12).segments.iter().map(|s| s.end.linear.z).fold(f64::INFINITY, f64::min);
    close(deepest, deepest_mm, "the deepest point of the drill");
    // The first block says the unit.
    let first = after(&pi, &si, 0).message.expect("the unit is said");
    assert!(first.de.contains("Inch") && first.en.contains("inches"), "{first:?}");
}

/// A setup-sheet header's blank is the program's when it has no BLK FORM (placed as
/// `unconfirmed::HEADER_BLANK_AT_DATUM` says); with a BLK FORM the BLK FORM applies.
#[test]
fn a_setup_sheet_header_gives_its_blank_when_the_program_has_none() {
    let header = "(Maschine: Fraese 5 Achsen)\n(Quader: QX100 QY90 QZ20,5)\n(T1 FRAESER D10)\n";
    let body = "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S1000\n2 L Z+50 R0 FMAX\n3 END PGM P MM\n";
    let (p, sim) = run(&format!("{header}{body}"));
    let s = sim.state_at(&p, sim.first_step[1].expect("run") as usize).expect("state");
    let blank = s.blank.expect("the header's blank");
    assert_eq!((blank.min.to_array(), blank.max.to_array()), ([0.0, 0.0, -20.5], [100.0, 90.0, 0.0]));
    let said = s.message.expect("said on the header line");
    assert!(said.de.contains("100 × 90 × 20,5") && said.en.contains("100 × 90 × 20.5"), "{said:?}");
    let end = after(&p, &sim, 2);
    assert_eq!(end.blank, Some(blank), "kept to the end");

    let with_blk = "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X-10 Y-10 Z-5\n2 BLK FORM 0.2 X+10 Y+10 Z+0\n\
        3 TOOL CALL 1 Z S1000\n4 END PGM P MM\n";
    let (p, sim) = run(&format!("{header}{with_blk}"));
    let s = sim.state_at(&p, sim.first_step[1].expect("run") as usize).expect("state");
    assert_eq!(s.blank, None, "the BLK FORM applies, not the header");
    assert!(s.message.is_some_and(|m| m.en.contains("BLK FORM, which applies")));
    let blank = after(&p, &sim, 3).blank.expect("BLK FORM");
    assert_eq!(blank.max.to_array(), [10.0, 10.0, 0.0]);
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
    assert!(s.message.is_some_and(|m| m.en.contains("Tool \"QS1\" not in the tool table")));

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
