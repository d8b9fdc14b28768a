//! What a block tells the trainee without stopping the run: the simulator records a typed note
//! (`sim::Note`) on the block, worded in one place. Oracle: the program below, written here, with
//! the note each block must carry worked out from what the block does (DOMAIN.md; the manual's
//! description of STOP, M1, M140, CALL PGM and the cycles).

use schwenkbar_core::ast::BlockBody;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Note, SimOptions, simulate};
use schwenkbar_core::unconfirmed::Decision;
use schwenkbar_core::{Lang, parse};

const NOTES: &str = "(Quader: QX100 QY90 QZ20)
0 BEGIN PGM NOTES MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20
2 BLK FORM 0.2 X+100 Y+90 Z+0
3 TOOL DEF 7 L+60 R+5
4 TOOL CALL 7 Z S2000
5 L Z+50 R0 FMAX M3
6 CC X+50 Y+45
7 STOP
8 L X+50 Y+45 FMAX M1
9 L M140 MB MAX
10 CYCL DEF 200 BOHREN ~
  Q200=2 ;SICHERHEITS-ABST. ~
  Q201=-5 ;TIEFE ~
  Q206=150 ;VORSCHUB TIEFENZ. ~
  Q202=5 ;ZUSTELL-TIEFE ~
  Q210=0 ;VERWEILZEIT OBEN ~
  Q203=+0 ;KOOR. OBERFLAECHE ~
  Q204=50 ;2. SICHERHEITS-ABST. ~
  Q211=0 ;VERWEILZEIT UNTEN
11 L X+50 Y+45 FMAX M99
12 FN 18: SYSREAD Q5 = ID20 NR1
13 QS1 = \"TEXT\"
14 L X+10 M77
15 L M128
16 L M129
17 CALL PGM SUB
18 L Z-10 M92
19 M30
20 L X+0
21 END PGM NOTES MM
";

/// Each block's note by its code: the numbers the block carries, nothing worded.
#[test]
fn each_block_carries_its_note_by_code() {
    let (p, diags) = parse(NOTES);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&p, &m, &SimOptions::default());
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let note = |number: u32| {
        let i = p.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
        sim.state_at(&p, sim.first_step[i].expect("listed") as usize).expect("state").note
    };
    let header =
        p.blocks.iter().position(|b| matches!(&*b.body(), BlockBody::Header { .. })).expect("header");
    let header = sim.state_at(&p, sim.first_step[header].expect("run") as usize).expect("state").note;
    assert_eq!(header, Some(Note::HeaderBlankIgnored), "the program's BLK FORM applies");
    assert_eq!(note(3), Some(Note::ToolDef));
    assert_eq!(note(6), Some(Note::CircleCentre));
    assert_eq!(note(7), Some(Note::Halt { word: "STOP" }));
    assert_eq!(note(8), Some(Note::OptionalStop));
    assert_eq!(note(9), Some(Note::Retract { feed: None }));
    assert_eq!(note(10), Some(Note::CycleDefined { cycle: 200 }));
    // Cycle 200 at 5 mm depth in one 5 mm infeed: down to the set-up clearance, the infeed, out.
    assert!(
        matches!(note(11), Some(Note::CycleExecuted { cycle: 200, moves }) if moves >= 3),
        "{:?}",
        note(11)
    );
    assert_eq!(note(12), Some(Note::SysRead { id: 20, target: 5, value: 7.0, default_tool: None }));
    assert_eq!(note(13), Some(Note::QsNotSimulated { index: 1 }));
    assert_eq!(note(14), Some(Note::MNotSimulated { m: vec![77] }));
    assert_eq!(note(15), Some(Note::TcpmOn { word: "M128", spatial: false }));
    assert_eq!(note(16), Some(Note::TcpmOff { word: "M129" }));
    assert_eq!(note(17), Some(Note::CallPgm { path: "SUB".into() }));
    assert_eq!(note(18), Some(Note::Assumed { decision: Decision::M92Datum }));
    assert_eq!(note(20), Some(Note::AfterEnd));
    assert_eq!(note(5), None, "a straight line says nothing");
}

/// The words are made from the code with its numbers, in both languages; the code is what the
/// CLI's JSON and a test can match.
#[test]
fn a_note_is_worded_from_its_numbers_and_serialised_with_its_code() {
    let n = Note::PatternCall { cycle: 200, points: 4, moves: 20 };
    let t = n.text();
    assert_eq!(t.get(Lang::De), "CYCL CALL PAT: Zyklus 200 an 4 Punkten ausgeführt (20 Bewegungen)");
    assert_eq!(t.get(Lang::En), "CYCL CALL PAT: cycle 200 executed at 4 points (20 moves)");
    let t = Note::Tabread { values: vec![(5, Some(2.5)), (6, None)] }.text();
    assert_eq!(
        t.get(Lang::De),
        "FN 28: TABREAD – die Tabelle wird nicht simuliert: Q5 bleibt 2,5000, Q6 = 0 angenommen"
    );
    assert_eq!(
        t.get(Lang::En),
        "FN 28: TABREAD – the table is not simulated: Q5 stays 2.5000, Q6 = 0 assumed"
    );
    let t = Note::ToolNotInTable { number: 0, name: "FRAESER_D19".into(), length: 50.0, radius: 5.0 }.text();
    assert_eq!(t.get(Lang::En), "Tool \"FRAESER_D19\" not in the tool table: assuming L=50 R=5");
    let json = serde_json::to_value(&n).expect("json");
    assert_eq!(json, serde_json::json!({"code": "pattern_call", "cycle": 200, "points": 4, "moves": 20}));
}

/// A stop that comes from what the trainer does not simulate says so: a touch-probe cycle's
/// result parameter (Q150 to Q166, Q180 to Q182: the cycle manuals' "Measurement results in Q
/// parameters") read after the cycle ran. Not said for another parameter, nor without a probe
/// cycle before.
#[test]
fn a_probe_result_read_after_an_unsimulated_probe_says_why_it_has_no_value() {
    let machine = Machine::builtin("ac-table").expect("machine");
    let detail = |middle: &str| {
        let src =
            format!("0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S2000\n{middle}9 Q1 = Q160 + Q5\n10 END PGM P MM\n");
        let (program, _) = parse(&src);
        let sim = simulate(&program, &machine, &SimOptions::default());
        let e = sim.error.expect("the run stops");
        (e.line, e.detail)
    };
    let probe = "2 TCH PROBE 427 MESSEN KOORDINATE ~\n  Q263=+0 ~\n  Q264=+0 ~\n  Q261=-5 ~\n  Q320=+2 ~\n  Q272=+3 ~\n  Q267=-1 ~\n  Q260=+50 ~\n  Q281=+0 ~\n  Q288=+0 ~\n  Q289=+0 ~\n  Q309=+0 ~\n  Q330=+0\n";
    let (line, text) = detail(probe);
    assert_eq!(line, 16);
    assert_eq!(
        text.get(Lang::En),
        "Q160 has no value yet (TCH PROBE 427 does not measure in the trainer: touch-probe cycles save their results in Q150 to Q166 and Q180 to Q182)"
    );
    assert!(
        text.get(Lang::De).starts_with("Q160 wurde noch kein Wert zugewiesen (TCH PROBE 427 misst nicht")
    );
    // Without the probe cycle: the plain stop.
    let (_, text) = detail("2 L Z+50 R0 FMAX\n");
    assert_eq!(text.get(Lang::En), "Q160 has no value yet");
    // A parameter no probe cycle writes: the plain stop.
    let (_, text) = detail(&format!("{probe}3 Q160 = 1\n"));
    assert_eq!(text.get(Lang::En), "Q5 has no value yet");
}
