//! The spellings and blocks of CAM systems, shops, old controls and training simulators: read as
//! the control's own spelling, said once per file, and run.

use super::*;

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
    let m = state.message().expect("said on its block");
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
    assert!(max.message().is_some_and(|m| m.de.contains("M140")), "said on its block");
}

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

/// A comment block run on over the next lines with `~`, and `12;` without the blank: one
/// comment each, as if written on one line with the blank; the missing blank said once per file.
#[test]
fn comments_wrapped_with_a_tilde_or_written_against_the_number() {
    let (p, d) = parse(
        "0 BEGIN PGM C MM\n1 ;free to use~\n under these terms~\n as written\n2 L X+1 R0 FMAX ;move~\n there\n3 END PGM C MM\n",
    );
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(p.blocks.len(), 4);
    assert_eq!(p.blocks[1].comment(), Some("free to use under these terms as written"));
    assert_eq!(p.blocks[2].body(), parse("2 L X+1 R0 FMAX\n").0.blocks[0].body());
    assert_eq!(p.blocks[2].comment(), Some("move there"));

    let (p, d) =
        parse("0 BEGIN PGM C MM\n12;created by CAM\n13; --- TOOLLIST\n14 L X+1 R0 FMAX\n15 END PGM C MM\n");
    assert_eq!(
        d.iter().map(|d| (d.severity, d.code.clone(), d.line)).collect::<Vec<_>>(),
        [(Severity::Warning, DiagCode::CommentAfterNumber { number: 12 }, 2)]
    );
    assert_eq!(p.blocks[1].comment(), Some("created by CAM"));
    assert_eq!(p.blocks[2].comment(), Some("--- TOOLLIST"));
    assert_eq!(
        format_program(&p),
        format_program(
            &parse(
                "0 BEGIN PGM C MM\n12 ;created by CAM\n13 ; --- TOOLLIST\n14 L X+1 R0 FMAX\n15 END PGM C MM\n"
            )
            .0
        )
    );
    let m = DiagCode::CommentAfterNumber { number: 12 }.message();
    assert!(m.de.contains("12;") && m.en.contains("12;"), "{m:?}");
    // A letter right after the number stays refused.
    assert!(parse("1L X+1\n").1.iter().any(|d| d.is_error()));
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

/// What a CAM post for another control writes: `M128.` with its number format's point, a
/// straight line without `L`, `R0` in a straight departure; and an old-style cycle spelt
/// `CYCLE DEF`, as a family of trainee programs has it. Each is read as the control's own
/// spelling and said once per kind and file; what would change the meaning stays refused.
#[test]
fn a_point_after_m_a_line_without_l_and_r0_in_dep_lt() {
    let point = |t: &str| DiagCode::Lenient { kind: Lenient::PointAfterM, text: t.into() };
    same_said("L M128. F10000", "L M128 F10000", &[point("M128.")]);
    same_said("M129.", "M129", &[point("M129.")]);
    let no_l = |t: &str| DiagCode::Lenient { kind: Lenient::MissingL, text: t.into() };
    same_said("Z0.0 B0.0 C0.0 FMAX M91", "L Z+0 B+0 C+0 FMAX M91", &[no_l("Z0.0")]);
    same_said("X-.5 Y+Q11 R0 F500", "L X-0.5 Y+Q11 R0 F500", &[no_l("X-.5")]);
    same_said("C270.", "L C+270", &[no_l("C270.")]);
    let r0 = DiagCode::Lenient { kind: Lenient::RadiusInDep, text: "R0".into() };
    same_said("DEP LT LEN10 R0", "DEP LT LEN10", std::slice::from_ref(&r0));
    same_said("DEP LN LEN+5 R0 F200 M9", "DEP LN LEN5 F200 M9", std::slice::from_ref(&r0));
    let spelt = DiagCode::Lenient { kind: Lenient::CycleSpeltOut, text: "CYCLE DEF".into() };
    same_said("CYCLE DEF 9.0 DWELL TIME", "CYCL DEF 9.0 DWELL TIME", std::slice::from_ref(&spelt));
    same_said("CYCLE DEF 9.1 5", "CYCL DEF 9.1 5", std::slice::from_ref(&spelt));
    // Not these: the circle `C`, the radius of an arc departure, a point inside a number.
    same("C X+5 Y+0 DR+", "C X+5 Y+0 DR+");
    assert!(parse("1 DEP CT CCA90 R0 F100\n").1.iter().any(|d| d.is_error()));
    assert!(parse("1 L M128.5\n").1.iter().any(|d| d.is_error()));
    // Once per kind in a file of many such blocks, at the first; the run goes through them.
    let src: String = std::iter::once("0 BEGIN PGM NX MM\n1 TOOL CALL 1 Z S1000\n".to_owned())
        .chain((2..=40).map(|n| format!("{n} X+{n}. Y{}. Z-1. F500 M3.\n", n % 7)))
        .chain(std::iter::once("41 L Z+50 R0 FMAX\n42 END PGM NX MM\n".to_owned()))
        .collect();
    let (program, sim) = run(&src);
    let d = parse(&src).1;
    assert_eq!(d.iter().filter(|d| matches!(d.code, DiagCode::Lenient { .. })).count(), 2, "{d:?}");
    let tip = after(&program, &sim, 40).tip_ics;
    assert!(tip.distance(glam::DVec3::new(40.0, 5.0, -1.0)) < 1e-9, "{tip}");
}

/// `M120 LA5` (the radius compensation computes 5 blocks ahead) is read with its words, written
/// back as written, and said on its block as not simulated; so are the feed functions M109,
/// M110, M116 and M136 (the run's times take F in mm/min on the path).
#[test]
fn m120_with_its_look_ahead_and_the_feed_functions_not_simulated() {
    for (written, la) in [("M120 LA5", 5.0), ("L X+10 Y+0 RL F200 M120 LA3", 3.0)] {
        let b = body(written);
        let words = match &b {
            BlockBody::MFunctions(m, w) => (m.to_vec(), *w),
            BlockBody::L(l) => (l.m.to_vec(), l.m_words),
            other => panic!("{written}: {other:?}"),
        };
        assert_eq!(words.0, [120], "{written}");
        assert_eq!(words.1.look_ahead, Some(Value::Number(la)), "{written}");
        same(written, written);
    }
    let (program, sim) = run("0 BEGIN PGM LA MM\n1 TOOL CALL 1 Z S1000\n2 M120 LA5\n3 END PGM LA MM\n");
    let state = after(&program, &sim, 2);
    let message = state.message().expect("said");
    assert!(message.de.contains("M120 nicht simuliert"), "{message:?}");
    // The feed functions the run does not model say so too.
    for m in [109, 110, 116, 136] {
        let src = format!(
            "0 BEGIN PGM F MM\n1 TOOL CALL 1 Z S1000\n2 M{m}\n3 L X+1 R0 F100 M{m}\n4 END PGM F MM\n"
        );
        let (program, sim) = run(&src);
        for block in [2, 3] {
            let message = after(&program, &sim, block).message().expect("said");
            assert!(
                message.de.contains(&format!("M{m} nicht simuliert")),
                "M{m} in block {block}: {message:?}"
            );
        }
    }
    // LA without a value stays refused.
    assert!(parse("1 M120 LA\n").1.iter().any(|d| d.is_error()));
}

/// A spindle speed in a path block, as CAM posts and a simulator's examples write it
/// (`L Z-45. F1000. S6000`, `C Y-31.391 Z47.513 F1000. S5000 DR+`): Klartext changes the speed
/// only with `TOOL CALL S…`, so it is read leniently, said once per file, kept in the block
/// (`fmt` writes it after the feed: there is no other spelling) and the spindle turns at it
/// from that block on.
#[test]
fn a_spindle_speed_in_a_path_block_is_read_and_sets_the_speed() {
    let (p, d) = parse(
        "0 BEGIN PGM S MM\n1 TOOL CALL 1 Z S1000\n2 L Z-45. F1000. S6000 M3\n\
         3 C X+1 Y+0 DR+ S7000\n4 L X+1 Y+0 FMAX\n5 LP PR+1 PA+90 S+Q1\n6 END PGM S MM\n",
    );
    let said: Vec<_> = d.iter().map(|d| d.code.clone()).collect();
    let speed = DiagCode::Lenient { kind: Lenient::SpeedInPath, text: "S6000".into() };
    assert_eq!(said, [speed], "said once, at its first block");
    assert_eq!(
        format_program(&p).lines().nth(2),
        Some("2 L Z-45 F1000 S6000 M3"),
        "kept in the block, written after the feed"
    );
    let BlockBody::C(m) = &*p.blocks[3].body() else { panic!("an arc") };
    assert_eq!(m.speed, Some(Value::Number(7000.0)));
    let BlockBody::Lp(m) = &*p.blocks[5].body() else { panic!("a polar line") };
    assert_eq!(m.speed, Some(Value::Param { index: 1, negate: false }));
    assert_eq!(format_program(&parse(&format_program(&p)).0), format_program(&p), "fmt is stable");
    let (program, sim) = run("0 BEGIN PGM S MM\n1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+10 R0 FMAX M3\n\
         3 L Z+5 F1000 S6000\n4 CC X+5 Y+0\n5 C X+10 Y+0 DR+ S7000\n6 L Z+20 FMAX\n7 END PGM S MM\n");
    let speed = |n| after(&program, &sim, n).spindle.speed;
    assert_eq!([speed(2), speed(3), speed(5), speed(6)], [1000.0, 6000.0, 7000.0, 7000.0]);
    // Not a speed: the circle centre `CC` takes none, and a second one is programmed twice.
    assert!(parse("1 CC X+0 Y+0 S500\n").1.iter().any(|d| d.is_error()));
    assert!(parse("1 L X+0 S500 S600\n").1.iter().any(|d| d.is_error()));
}

/// No M function passes silently: each the run does not model is said on its block, in every
/// block that carries M functions (a line, an arc, a block of its own), and a machine maker's own
/// number too. M13/M14 turn the spindle on with the coolant, M0 and M6 stop it (HEIDENHAIN's M
/// function overview, DOMAIN.md §8); M0 says that the control halts there.
#[test]
fn every_m_function_not_modelled_is_said_and_m13_m14_m0_m6_set_the_spindle() {
    use schwenkbar_core::sim::SpindleDir;
    let src = "0 BEGIN PGM M MM\n1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+50 R0 FMAX M13\n3 M8\n\
               4 L X+10 R0 F100 M90 M25\n5 CC X+0 Y+0\n6 C X-10 Y+0 DR+ M7\n7 M0\n8 M14\n9 M6\n\
               10 M30\n11 END PGM M MM\n";
    let (program, sim) = run(src);
    let message = |n| after(&program, &sim, n).message().map(|m| m.de).unwrap_or_default();
    let spindle = |n| after(&program, &sim, n).spindle.dir;
    assert_eq!(message(3), "M8 nicht simuliert");
    assert_eq!(message(4), "M90, M25 nicht simuliert");
    assert!(message(6).contains("M7 nicht simuliert"), "{}", message(6));
    assert!(message(7).starts_with("M0: die Steuerung hält hier an"), "{}", message(7));
    assert_eq!(message(9), "M6 nicht simuliert");
    for n in [2, 8, 10] {
        assert!(!message(n).contains("nicht simuliert"), "block {n}: {}", message(n));
    }
    let expected = [
        (2, SpindleDir::Cw),
        (6, SpindleDir::Cw),
        (7, SpindleDir::Off),
        (8, SpindleDir::Ccw),
        (9, SpindleDir::Off),
    ];
    for (n, dir) in expected {
        assert_eq!(spindle(n), dir, "block {n}");
    }
}

/// `M92` (the machine tool builder's additional machine datum, no distance given by any shipped
/// machine) moves in machine coordinates as `M91` does: a CAM post's safe position
/// `L Z+0 R0 FMAX M92` ends at the machine's Z0 (the top of its travel), not at the workpiece's
/// Z0, whatever the preset; the block says the assumption. A later block without M92 is in
/// workpiece coordinates again.
#[test]
fn m92_moves_in_machine_coordinates_as_m91_does() {
    let src = |m| {
        format!(
            "0 BEGIN PGM M MM\n1 TOOL CALL 1 Z S1000\n2 L X+10 Y+20 Z+30 R0 FMAX\n\
             3 L Z+0 R0 FMAX M{m}\n4 L X-5 Y+7 R0 FMAX M{m}\n5 L Z+30 R0 FMAX\n6 END PGM M MM\n"
        )
    };
    let (p91, s91) = run(&src(91));
    let (p92, s92) = run(&src(92));
    for n in [3, 4, 5] {
        assert_eq!(after(&p92, &s92, n).axes, after(&p91, &s91, n).axes, "block {n}");
    }
    let (z0, xy) = (after(&p92, &s92, 3).axes.linear, after(&p92, &s92, 4).axes.linear);
    assert_eq!(z0.z, 0.0, "machine Z0");
    assert_eq!((xy.x, xy.y), (-5.0, 7.0), "machine X/Y");
    // Block 5 is in workpiece coordinates again: the tip 30 mm above the workpiece datum.
    assert!((after(&p92, &s92, 5).tip_wcs.z - 30.0).abs() < 1e-9);
    let said = after(&p92, &s92, 3).message().expect("said").de;
    assert!(said.starts_with("M92:") && said.contains("M91"), "{said}");
}

/// An exporting simulator writes a blank in the program name (`BEGIN PGM SP1 1002 MM`), which
/// the control's file names do not allow: read with the whole name and said once.
#[test]
fn a_program_name_with_a_blank() {
    let (p, d) = parse("0 BEGIN PGM SP1 1002 MM\n1 L X+1 R0 FMAX\n2 END PGM SP1 1002 MM\n");
    assert_eq!(d.iter().map(|d| d.code.clone()).collect::<Vec<_>>(), [DiagCode::PgmNameBlank]);
    assert!(matches!(&*p.blocks[0].body(), BlockBody::BeginPgm { name, .. } if name == "SP1 1002"));
    assert!(format_program(&p).starts_with("0 BEGIN PGM SP1 1002 MM\n"));
    // The END PGM name is compared whole.
    let d = parse("0 BEGIN PGM SP1 1002 MM\n1 END PGM SP1 MM\n").1;
    assert!(d.iter().any(|d| matches!(d.code, DiagCode::PgmNameMismatch { .. })), "{d:?}");
    // Without a unit at the end it stays refused.
    assert!(parse("0 BEGIN PGM SP1 1002\n").1.iter().any(|d| d.is_error()));
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
