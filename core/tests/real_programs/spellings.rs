//! The spellings of CAM systems, shops, old controls and training simulators (numbers, words,
//! comments, names): read as the control's own spelling, said once per file, and run.

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
    // A line that starts with another word only a path block has, as an NX post for an older
    // control writes them.
    same_said("R0 F MAX M99", "L R0 FMAX M99", &[no_l("R0")]);
    same_said("RL F250.", "L RL F250", &[no_l("RL")]);
    same_said("FMAX", "L FMAX", &[no_l("FMAX")]);
    let (a, d) = parse("1 S1000 M3\n");
    let speed = DiagCode::Lenient { kind: Lenient::SpeedInPath, text: "S1000".into() };
    assert_eq!(d.iter().map(|d| d.code.clone()).collect::<Vec<_>>(), [no_l("S1000"), speed]);
    assert_eq!(a.blocks[0].body(), parse("1 L S1000 M3\n").0.blocks[0].body());
    // The run-on name of a program call, as `LBL1` and `TOOL DEF1`.
    same("CALL PGM100", "CALL PGM 100");
    // Not these: words that only start like a path word.
    for other in ["SQL X", "RLX", "FUNCTION RESET TCPM", "FN 0: Q1 = +1"] {
        let (_, d) = parse(&format!("1 {other}\n"));
        assert!(!d.iter().any(|d| d.code == no_l(other.split(' ').next().unwrap_or(""))), "{other}: {d:?}");
    }
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

/// The same simulator writes a feed in its tool definition (`TOOL DEF1 L+30,000 F300`) and a
/// comment in parentheses after a block's words (`L IX-80 (MODAL DRILL POINT)`): read without
/// the feed and with the parentheses as the block's comment, each said once per file; the
/// parentheses of a formula stay the formula's, and the run uses the tool's length and radius.
#[test]
fn a_training_simulators_tool_feed_and_comments_in_parentheses() {
    let feed = |t: &str| DiagCode::Lenient { kind: Lenient::FeedInToolDef, text: t.into() };
    let paren = |t: &str| DiagCode::Lenient { kind: Lenient::ParenComment, text: t.into() };
    same_said("TOOL DEF 1 L+30 F300", "TOOL DEF 1 L+30", &[feed("F300")]);
    same_said("TOOL DEF 2 L+30 F+Q5 R+4", "TOOL DEF 2 L+30 R+4", &[feed("F+Q5")]);
    same_said("L IX-80 (MODAL DRILL POINT)", "L IX-80 ;MODAL DRILL POINT", &[paren("(MODAL DRILL POINT)")]);
    same_said(
        "L X+90 Y+90 M89 (M89 (MODAL) START)  ",
        "L X+90 Y+90 M89 ;M89 (MODAL) START",
        &[paren("(M89 (MODAL) START)")],
    );
    // Words inside the parentheses are the comment's: no other spelling is said for them.
    same_said("CC X+50 Y+50 (POS X 5,5 M3.)", "CC X+50 Y+50 ;POS X 5,5 M3.", &[paren("(POS X 5,5 M3.)")]);
    // A formula's parentheses, a quoted name and a `;` comment are not a comment in parentheses.
    assert!(matches!(body("Q1 = Q2 * (Q3 + 1)"), BlockBody::QAssign { .. }));
    assert!(matches!(body("FN 0: Q1 = (Q3 + 1)"), BlockBody::QAssign { .. }));
    assert!(matches!(body("PATTERN DEF ROW1 (X+25 Y+33.5 D+8 NUM5 ROT+0 Z+0)"), BlockBody::PatternDef(_)));
    assert!(parse("1 L X+1 (A) ;B\n").1.iter().any(|d| d.is_error()), "the comment is the one after ;");
    assert!(parse("1 TOOL CALL 1 Z S500 F300\n").1.is_empty(), "a TOOL CALL's feed is its own");
    // A block that stays unknown or invalid keeps its parentheses as written and says nothing
    // of them.
    for (src, unknown) in [("POS1 (X+25 Y+33.5 Z+0) ~", true), ("L X+ (A)", false)] {
        let (p, d) = parse(&format!("1 {src}\n"));
        let written = src.trim_end_matches(" ~");
        match &*p.blocks[0].body() {
            BlockBody::Unknown { text } => assert!(unknown && text == written, "{text}"),
            BlockBody::Invalid { text } => assert!(!unknown && text == written, "{text}"),
            other => panic!("{other:?}"),
        }
        assert_eq!(p.blocks[0].comment(), None);
        assert!(!d.iter().any(|d| matches!(d.code, DiagCode::Lenient { .. })), "{d:?}");
    }
    // An unknown block is not read, so none of its spellings is rewritten either.
    let (p, _) = parse("1 BLK FORM CYLINDER Z R5,5 L20 F300\n");
    assert!(
        matches!(&*p.blocks[0].body(), BlockBody::Unknown { text } if text == "BLK FORM CYLINDER Z R5,5 L20 F300"),
        "{:?}",
        p.blocks[0].body()
    );
    let (p, _) = parse("1 TOOL DEFL R0 F30\n");
    assert!(format_program(&p).contains("F30"), "{}", format_program(&p));
    // A continuation mark after the parentheses is the line's.
    same_said("L IX-80 (A) ~", "L IX-80 ;A", &[DiagCode::ContinuationMissing, paren("(A)")]);

    let src = "0 BEGIN PGM SIM MM\n\
        1 TOOL DEF1 L+30,000 R+4,000 F300\n\
        2 TOOL DEF 2 L+20 F100\n\
        3 TOOL CALL 1 Z S1500\n\
        4 L X+0 Y+0 Z+50 R0 FMAX M3 (START)\n\
        5 L X+40 Y+5 (POSITION)\n\
        6 L Z-1 F200 (PLUNGE)\n\
        7 END PGM SIM MM\n";
    let (p, d) = parse(src);
    let codes: Vec<_> = d.iter().map(|d| d.code.clone()).collect();
    assert_eq!(codes.iter().filter(|c| **c == feed("F300")).count(), 1, "once per file: {codes:?}");
    assert_eq!(codes.iter().filter(|c| **c == paren("(START)")).count(), 1, "once per file: {codes:?}");
    assert!(d.iter().all(|d| !d.is_error()), "{d:?}");
    assert_eq!(p.blocks[5].comment(), Some("POSITION"));
    assert!(format_program(&p).contains("5 L X+40 Y+5 ; POSITION\n"), "{}", format_program(&p));
    assert_eq!(format_program(&parse(&format_program(&p)).0), format_program(&p), "fmt is stable");
    let (program, sim) = run(src);
    let state = after(&program, &sim, 6);
    assert_eq!(state.tool.length, 30.0, "the defined tool's length");
    assert_eq!(state.tool.radius, 4.0, "and radius");
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
