//! The blocks of real programs beyond the path words: cycles with symbolic parameters, string
//! parameters, STOP, touch probes, setup-sheet headers, inch programs, transfer marks; every
//! family runs or says on its block why not.

use super::*;

#[test]
fn cycle_parameters_with_symbolic_values() {
    let def = |v: &str| format!("0 BEGIN PGM C MM\n1 CYCL DEF 200 BOHREN ~\n  Q206={v} ;VORSCHUB TIEFENZ.\n");
    let value = |v: &str| match parse(&def(v)).0.blocks[1].body().into_owned() {
        BlockBody::CycleDef(c) => c.params[0].value.clone(),
        other => panic!("{other:?}"),
    };
    assert_eq!(value("AUTO"), CycleValue::Fauto);
    assert_eq!(value("MAX"), CycleValue::Fmax);
    assert_eq!(value(" MAX"), CycleValue::Fmax);
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

    // FMAX and FAUTO are words for feed rates: as a depth the run stops at the call with the
    // control's "Eingabewert falsch", never drilling 99999 mm deep.
    let stop = src.replace("Q201=-10 ", "Q201=MAX ");
    let (program, diags) = parse(&stop);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let sim = simulate(&program, &Machine::builtin("ac-table").expect("m"), &SimOptions::default());
    let e = sim.error.expect("a depth of FMAX stops");
    assert_eq!(e.block, 4);
    let (m, detail) = (e.code.message(), e.code.detail());
    assert_eq!(m.de, "Eingabewert falsch");
    assert!(detail.de.contains("Q201=FMAX") && detail.en.contains("no feed rate"), "{detail:?}");
    // A parameter no simulated cycle reads needs no feed: cycle 22's Q11=AUTO without a feed in
    // the TOOL CALL runs, and the call says the cycle is not simulated.
    let (p, sim) = run("0 BEGIN PGM C MM\n\
        1 TOOL CALL 1 Z S1000\n\
        2 CYCL DEF 22 AUSRAEUMEN ~\n\
        \x20 Q10=-10 ;ZUSTELL-TIEFE ~\n\
        \x20 Q11=AUTO ;VORSCHUB TIEFENZ. ~\n\
        \x20 Q208=MAX ;VORSCHUB RUECKZUG\n\
        3 L X+0 Y+0 Z+50 R0 FMAX M3\n\
        4 CYCL CALL\n\
        5 END PGM C MM\n");
    let m = after(&p, &sim, 4).message().expect("said on its block");
    assert!(m.de.contains("Zyklus 22 nicht simuliert"), "{m:?}");
}

/// Cycle 225's text in a string parameter line (`QS500="…"`): read with its text, written back
/// as the control writes it; a Q parameter takes no text and a QS parameter nothing else.
#[test]
fn a_string_parameter_line_keeps_its_text() {
    let def = |line: &str| {
        format!(
            "0 BEGIN PGM C MM\n1 CYCL DEF 225 GRAVIEREN ~\n  {line} ~\n  Q513=+5 ;HOEHE\n2 END PGM C MM\n"
        )
    };
    let (p, d) = parse(&def("QS500=\"P2002-B8 2.0L\" ;TEXT"));
    assert!(d.is_empty(), "{d:?}");
    let BlockBody::CycleDef(c) = p.blocks[1].body().into_owned() else { panic!("a cycle") };
    assert_eq!((c.params[0].index, &c.params[0].value), (500, &CycleValue::Text("P2002-B8 2.0L".into())));
    assert_eq!(c.params[0].label.as_deref(), Some("TEXT"));
    assert_eq!(c.params[1].value, CycleValue::Value(Value::Number(5.0)));
    let text = format_program(&p);
    assert!(text.contains("QS500=\"P2002-B8 2.0L\" ;TEXT ~"), "{text}");
    assert_eq!(format_program(&parse(&text).0), text, "fmt is stable");
    for refused in ["Q500=\"AB\"", "QS500=+1", "QS500=\"AB"] {
        let (_, d) = parse(&def(refused));
        assert!(d.iter().any(|d| d.is_error()), "{refused}: {d:?}");
    }
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
        assert!(after(&p, &sim, n).message().is_some(), "block {n} says what it does");
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
            assert!(s.message().is_some(), "block {i} not modelled and not said: {:?}", b.body());
        }
    }
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
    let first = after(&pi, &si, 0).message().expect("the unit is said");
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
    let said = s.message().expect("said on the header line");
    assert!(said.de.contains("100 × 90 × 20,5") && said.en.contains("100 × 90 × 20.5"), "{said:?}");
    let end = after(&p, &sim, 2);
    assert_eq!(end.blank, Some(blank), "kept to the end");

    let with_blk = "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X-10 Y-10 Z-5\n2 BLK FORM 0.2 X+10 Y+10 Z+0\n\
        3 TOOL CALL 1 Z S1000\n4 END PGM P MM\n";
    let (p, sim) = run(&format!("{header}{with_blk}"));
    let s = sim.state_at(&p, sim.first_step[1].expect("run") as usize).expect("state");
    assert_eq!(s.blank, None, "the BLK FORM applies, not the header");
    assert!(s.message().is_some_and(|m| m.en.contains("BLK FORM, which applies")));
    let blank = after(&p, &sim, 3).blank.expect("BLK FORM");
    assert_eq!(blank.max.to_array(), [10.0, 10.0, 0.0]);
}

/// Three readings found in public programs (measured, not committed): the retract's own feed
/// after `M140 MB` (CAM posts write `M140 MB MAX F5000`; unconfirmed::M140_FEED_AFTER_MB), a
/// string parameter given another's text in a cycle (`QS500=QS10`, an engraving program), and
/// the ETX a serial transfer ends with, kept after END PGM by the program that saved it.
/// Oracle: 50 mm retracted at 500 mm/min take 6 s; the ETX line is no block and said on its line.
#[test]
fn m140_with_a_feed_a_string_parameter_from_another_and_a_transfer_mark_are_read() {
    let b = body("M140 MB MAX F5000");
    let BlockBody::MFunctions(m, w) = &b else { panic!("{b:?}") };
    assert_eq!((&**m, w.mb), (&[140][..], Some(MoveBack::Max)));
    assert!(matches!(w.mb_feed, Some(schwenkbar_core::plane::Feed::Value(_))), "{w:?}");
    same("L Z+10 FMAX M140 MB 50 F500", "L Z+10 FMAX M140 MB+50 F500");
    // A CAM post's `IN` for the unit: read as INCH, said once per file.
    let unit_in = DiagCode::Lenient { kind: Lenient::UnitIn, text: "IN".into() };
    let (p, d) = parse("0010 BEGIN PGM T IN\n0020 L X+1 R0 FMAX\n0030 END PGM T IN\n");
    assert_eq!(d.iter().map(|d| d.code.clone()).collect::<Vec<_>>(), [unit_in], "once per file");
    let (inch, d) = parse("10 BEGIN PGM T INCH\n20 L X+1 R0 FMAX\n30 END PGM T INCH\n");
    assert!(d.is_empty(), "{d:?}");
    let bodies = |p: &Program| p.blocks.iter().map(|b| b.body().into_owned()).collect::<Vec<_>>();
    assert_eq!(bodies(&p), bodies(&inch), "IN reads as INCH");
    assert_eq!(format_program(&p), format_program(&inch), "fmt writes INCH");
    let src = "0 BEGIN PGM R MM\n1 TOOL CALL 1 Z S1000\n2 L Z+10 R0 FMAX\n3 M140 MB 50 F500\n\
               4 M140 MB 20\n5 END PGM R MM\n\u{3}\n";
    let (p, d) = parse(src);
    let marks: Vec<_> = d.iter().filter(|d| d.code == DiagCode::TransferMark).collect();
    assert_eq!(
        marks.iter().map(|d| (d.line, d.severity)).collect::<Vec<_>>(),
        [(7, Severity::Warning)],
        "{d:?}"
    );
    assert!(d.iter().all(|d| !d.is_error()), "{d:?}");
    assert_eq!(p.blocks.len(), 6, "the ETX lines are no blocks");
    let (p, sim) = run(src);
    let retract = after(&p, &sim, 3);
    let seg = retract.segments.last().expect("the retract");
    assert!((seg.end.linear.z - seg.start.linear.z - 50.0).abs() < 1e-9, "{seg:?}");
    assert!((seg.duration - 6.0).abs() < 1e-9, "50 mm at 500 mm/min: {}", seg.duration);
    assert_eq!(retract.note, Some(schwenkbar_core::sim::Note::Retract { feed: Some(500.0) }));
    assert!(retract.message().expect("said").de.contains("500 mm/min"));
    let rapid = after(&p, &sim, 4);
    assert_eq!(rapid.note, Some(schwenkbar_core::sim::Note::Retract { feed: None }));
    let cycle = "0 BEGIN PGM G MM\n1 CYCL DEF 225 GRAVIEREN ~\n  QS500=QS10 ;GRAVIERTEXT ~\n  Q513=+10 ;ZEICHENHOEHE\n\
                 2 END PGM G MM\n";
    let (p, d) = parse(cycle);
    assert!(d.is_empty(), "{d:?}");
    match &*p.blocks[1].body() {
        BlockBody::CycleDef(c) => assert_eq!(c.params[0].value, CycleValue::TextOf(10)),
        other => panic!("{other:?}"),
    }
    assert!(format_program(&p).contains("QS500=QS10"), "{}", format_program(&p));
    assert_eq!(format_program(&parse(&format_program(&p)).0), format_program(&p), "fmt is stable");
}
