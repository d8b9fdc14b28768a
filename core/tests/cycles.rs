//! The machining cycles (issue 15) through the whole simulator: the calls (`CYCL CALL PAT` with
//! `PATTERN DEF`, 220/221, `CYCL CALL POS`, `M89`) put the cycle at the closed-form points of the
//! working plane, every move of a cycle lies in the tilted I-CS (points read back from the
//! machine axes through the kinematics), helices stay on their cylinder at any fraction, and
//! the control's errors stop the run at the calling block. The cycles' own move sequences are
//! checked against the manual in the unit tests of `core/src/sim/cycles/`.

use std::collections::BTreeSet;

use glam::{DVec2, DVec3};
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{
    Kin, Segment, SegmentKind, SegmentPath, SimErrorCode, SimOptions, Simulation, State, simulate,
};
use schwenkbar_core::{Program, parse};

const MACHINES: [&str; 5] = ["ac-table", "ba-table", "bc-head-table", "ca-head", "b45-nutating"];
const TOL: f64 = 1e-6;

fn fixture(name: &str) -> String {
    let path = format!("{}/../tests/fixtures/sim/{name}.h", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn run_on(src: &str, machine: &str) -> (Program, Machine, Simulation) {
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{src}\n{diags:?}");
    let m = Machine::builtin(machine).expect("machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    (program, m, sim)
}

fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
    let step = sim.first_step[idx].expect("executed") as usize;
    sim.state_at(program, step).expect("state")
}

/// The tool tip in the I-CS at fraction `f` of segment `g` of the state's block.
fn ics(m: &Machine, s: &State, g: &Segment, f: f64) -> DVec3 {
    let travel = Kin::new(m, s.tool.length).tip_wcs(&g.axes_at(f)) - s.tip_wcs;
    let ics_in_wcs = s.frames.wcs.axes.transpose() * s.frames.ics.axes;
    s.tip_ics + ics_in_wcs.transpose() * travel
}

/// The I-CS end points of the block's moves that reach `depth` (the bottoms of the holes).
fn bottoms(m: &Machine, s: &State, depth: f64) -> BTreeSet<(i64, i64)> {
    s.segments
        .iter()
        .map(|g| ics(m, s, g, 1.0))
        .filter(|p| (p.z - depth).abs() < TOL)
        .map(|p| ((p.x * 1000.0).round() as i64, (p.y * 1000.0).round() as i64))
        .collect()
}

fn key(p: DVec2) -> (i64, i64) {
    ((p.x * 1000.0).round() as i64, (p.y * 1000.0).round() as i64)
}

#[test]
fn the_cycle_fixtures_run_without_errors_on_every_machine() {
    for name in ["drill_pattern_euler", "pocket_spatial", "cycle_calls"] {
        for id in MACHINES {
            let (_, _, sim) = run_on(&fixture(name), id);
            assert!(sim.error.is_none(), "{name} on {id}: {:?}", sim.error);
        }
    }
}

#[test]
fn pattern_def_and_221_drill_at_their_points_along_the_tilted_tool_axis() {
    for id in MACHINES {
        let (p, m, sim) = run_on(&fixture("drill_pattern_euler"), id);
        // CYCL CALL PAT: ROW1 (X−20 Y−25 D+20 NUM3) and CIRC1 (X+0 Y+10 D30 START+90 NUM4):
        // 90°, 180°, 270°, 0° on the radius 15; each 12 deep (cycle 203).
        let s = after(&p, &sim, 11);
        let mut want: BTreeSet<(i64, i64)> = [(-20.0, -25.0), (0.0, -25.0), (20.0, -25.0)]
            .iter()
            .map(|&(x, y)| key(DVec2::new(x, y)))
            .collect();
        for k in 0..4 {
            let a = (90.0 + 90.0 * f64::from(k)).to_radians();
            want.insert(key(DVec2::new(15.0 * a.cos(), 10.0 + 15.0 * a.sin())));
        }
        assert_eq!(bottoms(&m, &s, -12.0), want, "{id}");
        // Every feed move runs along the tool axis of the tilted plane: X, Y of the I-CS stay.
        for g in s.segments.iter().filter(|g| g.kind == SegmentKind::CycleFeed) {
            let (a, b) = (ics(&m, &s, g, 0.0), ics(&m, &s, g, 1.0));
            assert!((a.truncate() - b.truncate()).length() < TOL, "{id}: {a} → {b}");
        }
        // 221: 3 × 2 from (−30, 30), 15 and 8 apart, at its own surface Q203 = −1: 5 deep → −6.
        let s = after(&p, &sim, 13);
        let want: BTreeSet<_> =
            [(-30.0, 30.0), (-15.0, 30.0), (0.0, 30.0), (-30.0, 38.0), (-15.0, 38.0), (0.0, 38.0)]
                .iter()
                .map(|&(x, y)| key(DVec2::new(x, y)))
                .collect();
        assert_eq!(bottoms(&m, &s, -6.0), want, "{id}");
        // Between the points at the 2nd set-up clearance (Q301 = 1): Q203 + Q204 = 19 (the
        // tool starts above it, at 20, where cycle 203 left it).
        let rapid_ends: BTreeSet<i64> = s
            .segments
            .iter()
            .filter(|g| g.kind == SegmentKind::Rapid)
            .map(|g| (ics(&m, &s, g, 1.0).z * 1000.0).round() as i64)
            .collect();
        assert_eq!(rapid_ends.iter().rev().take(2).copied().collect::<Vec<_>>(), vec![20000, 19000], "{id}");
    }
}

#[test]
fn the_pocket_is_milled_in_the_tilted_plane_and_its_arcs_are_exact() {
    for id in MACHINES {
        let (p, m, sim) = run_on(&fixture("pocket_spatial"), id);
        let s = after(&p, &sim, 9);
        let feeds: Vec<&Segment> = s.segments.iter().filter(|g| g.kind == SegmentKind::CycleFeed).collect();
        assert!(feeds.iter().any(|g| matches!(g.path, SegmentPath::Arc(_))), "{id}");
        // Depth levels of the I-CS: −3 and −5.9 (roughing to Q201 + Q369), −6 (finishing); the
        // helix plunges from 2 and −1 above them. Every point of every milling move at any
        // fraction lies within the 40 × 30 pocket turned by 10° (less the tool radius 5).
        let turn = DVec2::from_angle(-10f64.to_radians());
        for g in &feeds {
            for f in [0.0, 0.3, 0.5, 0.8, 1.0] {
                let q = ics(&m, &s, g, f);
                let local = turn.rotate(q.truncate());
                assert!(local.x.abs() <= 15.0 + TOL && local.y.abs() <= 10.0 + TOL, "{id}: {q}");
                assert!(q.z >= -6.0 - TOL && q.z <= 2.0 + TOL, "{id}: {q}");
            }
        }
        let levels: BTreeSet<i64> =
            feeds.iter().map(|g| (ics(&m, &s, g, 1.0).z * 1000.0).round() as i64).collect();
        assert!([-3000, -5900, -6000].iter().all(|z| levels.contains(z)), "{id}: {levels:?}");
    }
}

#[test]
fn the_bore_milling_helix_stays_on_its_cylinder_in_a_tilted_plane() {
    let src = "0 BEGIN PGM H MM\n1 TOOL CALL 1 Z S5000 F800\n2 L Z+0 R0 FMAX M91\n\
               3 PLANE SPATIAL SPA+20 SPB+0 SPC+30 TURN FMAX\n\
               4 CYCL DEF 208 BOHRFRAESEN ~\n  Q200=+2 ~\n  Q201=-6 ~\n  Q206=+150 ~\n  Q334=+1.5 ~\n  Q203=+0 ~\n  Q204=+20 ~\n  Q335=+18 ~\n  Q342=+0 ~\n  Q351=+1\n\
               5 L X+10 Y+5 Z+30 R0 FMAX M99\n6 END PGM H MM\n";
    for id in ["ac-table", "bc-head-table", "ca-head"] {
        let (p, m, sim) = run_on(src, id);
        assert!(sim.error.is_none(), "{id}: {:?}", sim.error);
        let s = after(&p, &sim, 5);
        let arcs: Vec<&Segment> =
            s.segments.iter().filter(|g| matches!(g.path, SegmentPath::Arc(_))).collect();
        // Semicircle, 8/1.5 = 5.33 turns in 6 pieces, the full circle at depth: 8 arcs.
        assert_eq!(arcs.len(), 8, "{id}");
        for g in &arcs[1..] {
            for f in [0.1, 0.25, 0.5, 0.9] {
                let q = ics(&m, &s, g, f);
                let r = (q.truncate() - DVec2::new(10.0, 5.0)).length();
                // Bore Ø 18, tool Ø 10: the tool centre on radius 4.
                assert!((r - 4.0).abs() < TOL, "{id}: radius {r} at {f}");
            }
        }
        // The helix descends by the pitch 1.5 per full turn.
        let (a, b) = (ics(&m, &s, arcs[1], 0.0), ics(&m, &s, arcs[1], 1.0));
        assert!((a.z - b.z - 1.5).abs() < TOL, "{id}: {a} {b}");
    }
}

fn drilling(body: &str) -> String {
    format!(
        "0 BEGIN PGM D MM\n1 TOOL CALL 8 Z S4000 F150\n2 L Z+0 R0 FMAX M91\n\
         3 CYCL DEF 200 BOHREN ~\n  Q200=+2 ~\n  Q201=-5 ~\n  Q206=+150 ~\n  Q202=+5 ~\n  Q210=+0 ~\n  Q203=+0 ~\n  Q204=+10 ~\n  Q211=+0\n\
         {body}99 END PGM D MM\n"
    )
}

/// Per block: its number, the hole bottoms (I-CS, µm) it drilled and its lowest point.
type Holes = Vec<(u32, BTreeSet<(i64, i64)>, f64)>;

/// The holes each block drilled.
fn holes(src: &str) -> Holes {
    let (p, m, sim) = run_on(src, "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    p.blocks
        .iter()
        .filter_map(|b| b.number())
        .filter(|&n| n > 3 && n < 99)
        .map(|n| {
            let s = after(&p, &sim, n);
            let lowest = s.segments.iter().map(|g| ics(&m, &s, g, 1.0).z).fold(f64::MAX, f64::min);
            (n, bottoms(&m, &s, lowest), lowest)
        })
        .collect()
}

#[test]
fn m89_calls_the_last_defined_cycle_at_every_positioning_block_until_m99_or_a_new_cycl_def() {
    // "M89 as a cycle-call is modally effective, i.e. for every following positioning block
    // there will be a call of the last-programmed machining-cycle" (TNC 306/406 technical
    // manual, "M-function M89"); on the iTNC 530 it ends with M99 in the last positioning block
    // or with a new CYCL DEF (iTNC 530 cycle manual; DOMAIN.md §11) — a CYCL CALL ending it is
    // the old controls' rule only.
    let src = drilling(
        "4 L X+10 Y+10 Z+20 R0 FMAX M89\n5 L X+20\n6 L X+30 M99\n7 L X+40\n8 M89\n9 L X+50\n\
         10 CYCL CALL\n11 L X+60\n\
         12 CYCL DEF 200 BOHREN ~\n  Q200=+2 ~\n  Q201=-7 ~\n  Q206=+150 ~\n  Q202=+5 ~\n  Q210=+0 ~\n  Q203=+0 ~\n  Q204=+10 ~\n  Q211=+0\n\
         13 L X+70\n14 L X+80 M89\n15 L X+90\n",
    );
    let got: Vec<(u32, Option<i64>)> = holes(&src)
        .into_iter()
        .map(|(n, h, z)| (n, (!h.is_empty() && z < -4.0).then(|| z.round() as i64)))
        .collect();
    // 4, 5: M89 active; 6: M99 calls once more and ends it; 7 not; 8 (M89 alone) starts it
    // again but does not position; 9 drills; the CYCL CALL 10 drills and leaves M89 on, so 11
    // drills; the CYCL DEF 12 (7 deep) ends it: 13 does not drill; 14 starts it again with the
    // new cycle, 15 drills 7 deep.
    assert_eq!(
        got,
        vec![
            (4, Some(-5)),
            (5, Some(-5)),
            (6, Some(-5)),
            (7, None),
            (8, None),
            (9, Some(-5)),
            (10, Some(-5)),
            (11, Some(-5)),
            (12, None),
            (13, None),
            (14, Some(-7)),
            (15, Some(-7))
        ]
    );
}

#[test]
fn cycl_call_pos_without_all_three_axes_is_refused() {
    // "In the CYCL CALL POS block you must always program all three coordinate axes" (iTNC 530
    // cycle manual; DOMAIN.md §11).
    for (block, missing) in [
        ("CYCL CALL POS X+10 Y+20 FMAX", "Z"),
        ("CYCL CALL POS X+10 Z+0", "Y"),
        ("CYCL CALL POS Y+1 Z+0", "X"),
    ] {
        let (_, d) = schwenkbar_core::parse(&format!("1 {block}\n"));
        assert_eq!(d.len(), 1, "{block}: {d:?}");
        assert_eq!(d[0].code, schwenkbar_core::diag::DiagCode::MissingWord { word: missing }, "{block}");
        assert!(d[0].is_error());
    }
    let (_, d) = schwenkbar_core::parse("1 CYCL CALL POS X+10 Y+20 Z+0 FMAX\n");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn cycl_call_pos_drills_there_with_its_z_as_a_surface_shift() {
    let src = drilling(
        "4 L Z+30 R0 FMAX\n5 CYCL CALL POS X+10 Y+20 Z-3 FMAX\n6 CYCL CALL POS X+40 Y+20 Z+0 FMAX\n",
    );
    let got = holes(&src);
    assert_eq!(got[1].1, BTreeSet::from([key(DVec2::new(10.0, 20.0))]));
    assert!((got[1].2 + 8.0).abs() < TOL, "Q203 0 + Z−3, depth 5: {}", got[1].2);
    assert_eq!(got[2].1, BTreeSet::from([key(DVec2::new(40.0, 20.0))]));
    assert!((got[2].2 + 5.0).abs() < TOL, "{}", got[2].2);
}

#[test]
fn cycle_220_arcs_between_the_points_and_overrides_the_surface() {
    // Three holes on Ø 40 about (50, 50) from 30°, 120° apart, along the circle (Q365 = 1) at
    // the set-up clearance (Q301 = 0); Q203 = −2 of cycle 220 replaces cycle 200's 0.
    let src = drilling(
        "4 L Z+30 R0 FMAX\n5 CYCL DEF 220 MUSTER KREIS ~\n  Q216=+50 ~\n  Q217=+50 ~\n  Q244=+40 ~\n  Q245=+30 ~\n  Q246=+360 ~\n  Q247=+120 ~\n  Q241=+3 ~\n  Q200=+2 ~\n  Q203=-2 ~\n  Q204=+10 ~\n  Q301=+0 ~\n  Q365=+1\n",
    );
    let (p, m, sim) = run_on(&src, "ac-table");
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let s = after(&p, &sim, 5);
    let want: BTreeSet<_> = (0..3)
        .map(|k| {
            let a = (30.0 + 120.0 * f64::from(k)).to_radians();
            key(DVec2::new(50.0 + 20.0 * a.cos(), 50.0 + 20.0 * a.sin()))
        })
        .collect();
    assert_eq!(bottoms(&m, &s, -7.0), want);
    let arcs: Vec<&Segment> = s.segments.iter().filter(|g| matches!(g.path, SegmentPath::Arc(_))).collect();
    assert_eq!(arcs.len(), 2, "two moves along the circle");
    for g in arcs {
        assert_eq!(g.kind, SegmentKind::Rapid);
        let q = ics(&m, &s, g, 0.5);
        assert!(((q.truncate() - DVec2::new(50.0, 50.0)).length() - 20.0).abs() < TOL);
        assert!((q.z - 0.0).abs() < TOL, "at Q203 + Q200 = 0: {q}");
    }
}

fn error_of(src: &str) -> (u32, SimErrorCode, String) {
    let (p, _, sim) = run_on(src, "ac-table");
    let e = sim.error.expect("an error");
    let number = p.blocks[e.block].number().expect("numbered");
    (number, e.code, format!("{} {}", e.message.de, e.detail.de))
}

/// A stop that comes from the tool's size, with a tool the table does not have: the size was
/// the default tool's (L=100 R=5, `static/tools.json`), and the stop says so with the numbers:
/// for a tool called by number or name, for a `TOOL DEF` that only preselects the tool (as CAM
/// posts write it), and with no tool called at all (T0).
#[test]
fn a_stop_from_an_assumed_tool_size_says_the_tool_was_assumed() {
    let bore = |tool: &str| {
        format!(
            "0 BEGIN PGM E MM\n{tool}2 CYCL DEF 208 BOHRFRAESEN ~\n  Q200=+2 ~\n  Q201=-6 ~\n  Q206=+150 ~\n  Q334=+1.5 ~\n  Q203=+0 ~\n  Q204=+20 ~\n  Q335=+8 ~\n  Q342=+0 ~\n  Q351=+1\n3 L X+0 Y+0 Z+30 R0 FMAX M99\n4 END PGM E MM\n"
        )
    };
    let (_, code, text) = error_of(&bore("1 TOOL CALL 99 Z S5000 F800\n"));
    assert_eq!(code, SimErrorCode::ToolTooLarge { cycle: 208, tool_diameter: 10.0, size: 8.0 });
    assert!(text.contains("(Werkzeug 99 nicht in der Werkzeugtabelle: L=100 R=5 angenommen)"), "{text}");
    let (p, _, sim) = run_on(&bore("1 TOOL CALL \"T433219138\" Z S5000 F800\n"), "ac-table");
    let e = sim.error.expect("an error");
    assert_eq!(p.blocks[e.block].number(), Some(3));
    assert!(
        e.detail.en.ends_with("(Tool \"T433219138\" not in the tool table: assuming L=100 R=5)"),
        "{}",
        e.detail.en
    );
    let (_, _, text) = error_of(&bore("1 TOOL DEF 7\n1 TOOL CALL 7 Z S5000 F800\n"));
    assert!(text.contains("(Werkzeug 7 nicht in der Werkzeugtabelle: L=100 R=5 angenommen)"), "{text}");
    let (_, _, text) = error_of(&bore(""));
    assert!(
        text.contains("(kein Werkzeug aufgerufen (T0): Standardwerkzeug L=100 R=5 angenommen)"),
        "{text}"
    );
    // A TOOL DEF that gives the radius: the size is the program's, nothing assumed.
    let (_, code, text) = error_of(&bore("1 TOOL DEF 7 L+80 R+5\n1 TOOL CALL 7 Z S5000 F800\n"));
    assert_eq!(code, SimErrorCode::ToolTooLarge { cycle: 208, tool_diameter: 10.0, size: 8.0 });
    assert!(!text.contains("Werkzeugtabelle") && !text.contains("angenommen"), "{text}");
    // A stop that has nothing to do with the tool's size says nothing of it.
    let (_, code, text) = error_of(&drilling("4 CYCL CALL PAT FMAX\n"));
    assert_eq!(code, SimErrorCode::NoPattern);
    assert!(!text.contains("Werkzeugtabelle"), "{text}");
}

#[test]
fn the_cycles_errors_stop_the_run_at_the_calling_block() {
    // Bore Ø 8 with the Ø 10 end mill of tool 1.
    let src = "0 BEGIN PGM E MM\n1 TOOL CALL 1 Z S5000 F800\n2 CYCL DEF 208 BOHRFRAESEN ~\n  Q200=+2 ~\n  Q201=-6 ~\n  Q206=+150 ~\n  Q334=+1.5 ~\n  Q203=+0 ~\n  Q204=+20 ~\n  Q335=+8 ~\n  Q342=+0 ~\n  Q351=+1\n3 L X+0 Y+0 Z+30 R0 FMAX M99\n4 END PGM E MM\n";
    let (n, code, text) = error_of(src);
    assert_eq!((n, code), (3, SimErrorCode::ToolTooLarge { cycle: 208, tool_diameter: 10.0, size: 8.0 }));
    assert!(text.contains("Werkzeug-Radius zu groß") && text.contains("Zyklus 208"), "{text}");
    assert!(!text.contains("Werkzeugtabelle"), "tool 1 is in the table: {text}");
    let (n, code, _) = error_of(&drilling("4 CYCL CALL PAT FMAX\n"));
    assert_eq!((n, code), (4, SimErrorCode::NoPattern));
    let (n, code, text) = error_of(&drilling(
        "4 CYCL DEF 201 REIBEN ~\n  Q200=+2 ~\n  Q201=+5 ~\n  Q206=+100 ~\n  Q211=+0 ~\n  Q208=+0 ~\n  Q203=+0 ~\n  Q204=+10\n5 L X+0 Y+0 Z+20 R0 FMAX M99\n",
    ));
    assert_eq!((n, code), (5, SimErrorCode::DepthSign { cycle: 201, value: 5.0 }));
    assert!(text.contains("Vorzeichen Tiefe falsch") && text.contains("Zyklus 201"), "{text}");
    // Cycle 220 with no machining cycle before it.
    let src = "0 BEGIN PGM E MM\n1 CYCL DEF 221 MUSTER LINIEN ~\n  Q225=+0 ~\n  Q226=+0 ~\n  Q237=+10 ~\n  Q238=+10 ~\n  Q242=+2 ~\n  Q243=+1 ~\n  Q224=+0 ~\n  Q200=+2 ~\n  Q203=+0 ~\n  Q204=+10 ~\n  Q301=+1\n2 END PGM E MM\n";
    assert_eq!(error_of(src).1, SimErrorCode::NoCycle);
}

/// A cycle defined without its parameter lines, its parameters set as blocks of their own
/// (`Q201 = -5`, as a training simulator's examples write it): the call reads them from the
/// global Q parameters Q200… (the cycles' range in the user's manuals), so it drills exactly as
/// the same values written in the definition; a parameter changed before the next call changes
/// that call; with none set the parameters were left out and the run stops at the call.
#[test]
fn a_cycle_without_parameter_lines_takes_them_from_q200_at_its_call() {
    let inline = holes(&drilling("4 L X+10 Y+10 Z+20 R0 FMAX M99\n5 L X+20 M99\n"));
    let split = "0 BEGIN PGM D MM\n1 TOOL CALL 8 Z S4000 F150\n2 L Z+0 R0 FMAX M91\n3 CYCL DEF 200 BOHREN\n\
        31 Q200 = 2\n32 Q201 = -5\n33 Q206 = 150\n34 Q202 = 5\n35 Q210 = 0\n36 Q203 = +0\n37 Q204 = 10\n38 Q211 = 0\n\
        40 L X+10 Y+10 Z+20 R0 FMAX M99\n50 L X+20 M99\n99 END PGM D MM\n";
    let got = holes(split);
    let calls = |h: &Holes| {
        h.iter().filter(|(_, b, _)| !b.is_empty()).map(|(_, b, z)| (b.clone(), *z)).collect::<Vec<_>>()
    };
    assert_eq!(calls(&got), calls(&inline), "the same holes at the same depth");
    assert_eq!(calls(&got).iter().map(|(_, z)| *z).collect::<Vec<_>>(), [-5.0, -5.0]);
    let (p, _, sim) = run_on(split, "ac-table");
    let m = after(&p, &sim, 3).message().expect("said on the definition");
    assert!(m.de.contains("ohne Parameterzeilen") && m.en.contains("Q200"), "{m:?}");
    // Deeper for the second call only.
    let deeper = split.replace("50 L X+20 M99", "45 Q201 = -8\n50 L X+20 M99");
    let depths: Vec<f64> =
        holes(&deeper).iter().filter(|(_, b, _)| !b.is_empty()).map(|(_, _, z)| *z).collect();
    assert_eq!(depths, [-5.0, -8.0]);
    // Nothing set: left out, the stop at the call.
    let none = "0 BEGIN PGM D MM\n1 TOOL CALL 8 Z S4000 F150\n2 CYCL DEF 200 BOHREN\n3 L X+10 Y+10 Z+20 R0 FMAX M99\n4 END PGM D MM\n";
    assert_eq!(error_of(none).0, 3);
    assert_eq!(error_of(none).1, SimErrorCode::CycleParamsMissing { cycle: 200 });
    // Only some set: the first one missing is named.
    let some = none.replace("3 L X", "21 Q200 = 2\n22 Q201 = -5\n3 L X");
    assert!(
        matches!(error_of(&some).1, SimErrorCode::CycleParamMissing { cycle: 200, .. }),
        "{:?}",
        error_of(&some)
    );
}
