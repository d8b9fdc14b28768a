//! Property tests of the simulator on every shipped machine: the rigid-body model agrees with the
//! kinematics' forward orientation, the W-CS ↔ linear-axis map round-trips, a MOVE swivel keeps
//! the tool tip on the workpiece, and no program text makes the simulator panic.

use glam::DVec3;
use proptest::prelude::*;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Kin, MachineAxes, SegmentKind, SimOptions, simulate};
use schwenkbar_core::{parse, sample};
use schwenkbar_testkit::assert_close;

const EXACT: f64 = 1e-9;
/// The tool tip along a MOVE swivel (issue 5).
const TIP: f64 = 1e-6;

fn machines() -> Vec<Machine> {
    Machine::builtin_ids().iter().filter_map(|id| Machine::builtin(id).ok()).collect()
}

fn axes(m: &Machine, linear: DVec3, rotary: [f64; 2]) -> MachineAxes {
    let j = m.joints();
    MachineAxes { linear, rotary, letters: [j[0].axis, j[1].axis] }
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(64))]

    /// Wᵀ·H (workpiece pose, head pose) is the kinematics' R_machine, and the tool axis in W-CS
    /// is its third column.
    #[test]
    fn rigid_body_model_matches_forward_kinematics(s in -180.0..180.0f64, ma in -180.0..180.0f64, len in 0.0..300.0f64) {
        for m in machines() {
            let kin = Kin::new(&m, len);
            let rel = kin.workpiece_pose([s, ma]).m.transpose() * kin.head_pose([s, ma]).m;
            assert_close!(rel, m.forward_deg(s, ma), EXACT, "{}", m.id);
            assert_close!(kin.tool_axis_wcs([s, ma]), m.forward_deg(s, ma).z_axis, EXACT, "{}", m.id);
        }
    }

    /// L = wcs_to_linear(p) puts the physical tool tip on p.
    #[test]
    fn linear_axes_put_the_tip_on_the_point(s in -180.0..180.0f64, ma in -180.0..180.0f64,
                                            x in -200.0..200.0f64, y in -200.0..200.0f64, z in -100.0..300.0f64) {
        for m in machines() {
            let kin = Kin::new(&m, 80.0);
            let p = DVec3::new(x, y, z);
            let l = kin.wcs_to_linear([s, ma]).apply(p);
            assert_close!(kin.tip_wcs(&axes(&m, l, [s, ma])), p, EXACT, "{}", m.id);
        }
    }

    /// PLANE … MOVE on every machine: wherever the control finds a permitted solution, the tool
    /// tip stays on the workpiece along the whole swivel.
    #[test]
    fn move_keeps_the_tip_on_every_machine(spa in -60.0..60.0f64, spb in -60.0..60.0f64, spc in -90.0..90.0f64) {
        let src = format!(
            "0 BEGIN PGM P MM\n1 TOOL CALL 16 Z S1000 F1000\n2 L X+50 Y+50 Z+30 R0 FMAX\n\
             3 PLANE SPATIAL SPA{spa:+.3} SPB{spb:+.3} SPC{spc:+.3} MOVE F1000\n4 END PGM P MM\n"
        );
        let (p, _) = parse(&src);
        let mut checked = 0;
        for m in machines() {
            let sim = simulate(&p, &m, &SimOptions::default());
            if sim.error.is_some() {
                continue; // unreachable or beyond a limit switch: the control refuses, nothing moves
            }
            let st = sim.state_at(&p, 3).expect("state of the PLANE block");
            let kin = Kin::new(&m, st.tool.length);
            for seg in st.segments.iter().filter(|g| g.kind == SegmentKind::SwivelMove) {
                let tip0 = kin.tip_wcs(&seg.start);
                assert_close!(tip0, DVec3::new(50.0, 50.0, 30.0), EXACT, "{}", m.id);
                for k in 0..=32 {
                    let a = seg.axes_at(f64::from(k) / 32.0);
                    assert_close!(kin.tip_wcs(&a), tip0, TIP, "{} at {k}/32", m.id);
                }
                checked += 1;
            }
        }
        // ac-table has no rotary limit switches: at least its swivel is always checked.
        prop_assert!(checked >= 1, "no MOVE swivel was checked for {src}");
    }

    /// Any mix of the blocks the simulator knows, with random numbers, never panics; the run
    /// either ends or stops with a message, and every recorded step can be stepped to.
    #[test]
    fn random_programs_never_panic(picks in proptest::collection::vec((0usize..35, -400.0..400.0f64, 0u32..4), 1..30),
                                   machine in 0usize..5) {
        let vocab = |k: usize, v: f64, n: u32| -> String {
            match k {
                0 => format!("L X{v:+.3} Y{:+.3} Z{:+.3} R0 F500", v / 2.0, v / 4.0),
                1 => format!("L Z{v:+.3} R0 FMAX M91"),
                2 => format!("PLANE SPATIAL SPA{:+.2} SPB{:+.2} SPC{:+.2} TURN MB MAX FMAX", v / 5.0, v / 7.0, v / 3.0),
                3 => format!("PLANE SPATIAL SPA+0 SPB{:+.2} SPC+0 MOVE DIST{:+.1} F1000", v / 5.0, v / 10.0),
                4 => "PLANE RESET STAY".to_string(),
                5 => format!("PLANE RELATIV SPB{:+.2} STAY", v / 9.0),
                6 => format!("PLANE AXIAL B{:+.2} TURN FMAX", v / 4.0),
                7 => format!("TRANS DATUM AXIS X{v:+.2} Y+0 Z+0"),
                8 => "TRANS MIRROR AXIS X".to_string(),
                9 => format!("TRANS ROTATION ROT{v:+.1}"),
                10 => format!("Q{n} = Q{} / {v:+.1}", n + 1),
                11 => format!("FN 0: Q{n} = {v:+.3}"),
                12 => format!("L A+Q{} C+Q122 R0 FMAX", 120 + n % 3),
                13 => format!("LBL {n}"),
                14 => format!("CALL LBL {n} REP {}", n * 3),
                15 => format!("CALL LBL {n}"),
                16 => "LBL 0".to_string(),
                17 => "CYCL DEF 200 BOHREN ~\n  Q200=+2 ~\n  Q201=-5 ~\n  Q206=+150 ~\n  Q202=+0 ~\n  Q210=+0 ~\n  Q203=+0 ~\n  Q204=+20 ~\n  Q211=+0".to_string(),
                18 => format!("L X{v:+.1} R0 FMAX M99"),
                19 => format!("CYCL DEF 19.1 A{:+.1} B+0 C+0", v / 6.0),
                20 => format!("TOOL CALL {n} Z S1000 F{}", v.abs()),
                21 => "M30".to_string(),
                22 => format!("CYCL DEF 7.1 X{v:+.2}"),
                23 => format!("CC X{:+.2} Y{:+.2}", v / 3.0, v / 5.0),
                24 => format!("C X{:+.2} Y{v:+.2} DR{}", v / 2.0, if n % 2 == 0 { '+' } else { '-' }),
                25 => format!("CR X{v:+.2} Y{:+.2} R{:+.2} DR-", v / 3.0, v / (f64::from(n) - 1.5)),
                26 => format!("CT X{:+.2} Y{v:+.2}", v / 7.0),
                27 => format!("RND R{:+.2}", v.abs() / 20.0),
                28 => format!("CHF {:+.2}", v.abs() / 30.0),
                29 => format!("LP PR{:+.2} IPA{v:+.1}", v.abs() / 4.0),
                30 => format!("CP IPA{:+.1} IZ{:+.2} DR{}", v * 3.0, v / 50.0, if n % 2 == 0 { '+' } else { '-' }),
                31 => format!("FN 4: Q{n} = +Q{} DIV {v:+.1}", n + 1),
                32 => format!("FN 12: IF +Q{n} LT {v:+.1} GOTO LBL {}", n % 3),
                33 => format!("APPR LCT X{v:+.2} Y+0 R5 RR F200"),
                _ => "CYCL CALL".to_string(),
            }
        };
        let mut src = String::from("0 BEGIN PGM R MM\n");
        for (i, (k, v, n)) in picks.iter().enumerate() {
            src.push_str(&format!("{} {}\n", i + 1, vocab(*k, *v, *n)));
        }
        src.push_str(&format!("{} END PGM R MM\n", picks.len() + 1));
        let (p, _) = parse(&src);
        let ms = machines();
        let m = &ms[machine % ms.len()];
        let sim = simulate(&p, m, &SimOptions { max_steps: Some(5_000), checkpoint_interval: 7, ..SimOptions::default() });
        let n = sim.len();
        for s in sim.states(&p) {
            for seg in &s.segments {
                let _ = seg.axes_at(0.5);
                prop_assert!(seg.duration.is_finite() && seg.duration >= 0.0);
            }
        }
        if n > 0 {
            prop_assert!(sim.state_at(&p, n - 1).is_some());
            prop_assert_eq!(sim.state_at(&p, n / 2).map(|s| s.axes), Some(sim.records[n / 2].axes));
        }
        prop_assert!(sim.state_at(&p, n).is_none());
    }
}

#[test]
fn cam_sample_runs_on_the_table_machines() {
    let (p, _) = parse(&sample::cam_program(12_000));
    for id in ["ac-table", "ca-head"] {
        let m = Machine::builtin(id).expect("machine");
        let sim = simulate(&p, &m, &SimOptions::default());
        assert!(sim.error.is_none(), "{id}: {:?}", sim.error);
        assert_eq!(sim.len(), p.blocks.len());
    }
}

/// Every fixture program of the repository on every machine: the run ends or stops with a
/// message in both languages, and every recorded step can be stepped to.
#[test]
fn every_fixture_runs_on_every_machine() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures");
    let mut files = Vec::new();
    for dir in ["ok", "err", "sim"] {
        for e in std::fs::read_dir(root.join(dir)).expect("fixture dir").flatten() {
            if e.path().extension().is_some_and(|x| x == "h") {
                files.push(e.path());
            }
        }
    }
    assert!(files.len() > 20, "{} fixtures", files.len());
    let opts = SimOptions { max_steps: Some(20_000), ..SimOptions::default() };
    for f in &files {
        let (p, _) = parse(&std::fs::read_to_string(f).expect("read"));
        for m in machines() {
            let sim = simulate(&p, &m, &opts);
            if let Some(e) = &sim.error {
                assert!(!e.message.de.is_empty() && !e.message.en.is_empty(), "{}: {e:?}", f.display());
                assert_eq!(e.step, sim.len());
            }
            assert_eq!(sim.states(&p).count(), sim.len(), "{} on {}", f.display(), m.id);
        }
    }
}

#[test]
fn machine_geometry_is_validated_and_defaulted() {
    let base = r#"{"id": "t", "name": {"de": "t", "en": "t"}, "description": {"de": "t", "en": "t"},
        "chain": [{"axis": "C", "carrier": "table", "direction": [0,0,1]},
                  {"axis": "A", "carrier": "table", "direction": [1,0,0]}]GEO}"#;
    let m = Machine::from_json(&base.replace("GEO", "")).expect("no geometry: defaults");
    assert_eq!(m.geometry, schwenkbar_core::machine::MachineGeometry::default());
    let m = Machine::from_json(&base.replace("GEO", r#", "geometry": {"preset": [1, 2, 3]}"#))
        .expect("preset only");
    assert_eq!(m.geometry.preset, DVec3::new(1.0, 2.0, 3.0));
    for bad in [
        r#", "geometry": {"linear_limits": {"Z": {"min": 0, "max": -10}}}"#,
        r#", "geometry": {"rapid_linear": 0}"#,
        r#", "geometry": {"rapid_rotary": -5}"#,
        r#", "geometry": {"unknown": 1}"#,
    ] {
        assert!(Machine::from_json(&base.replace("GEO", bad)).is_err(), "{bad}");
    }
    for m in machines() {
        let z = m.geometry.linear_limits[2];
        assert!(z.contains(0.0), "{}: L Z+0 M91 is inside the travel", m.id);
        assert!(m.geometry.linear_limits[0].contains(-600.0) && m.geometry.linear_limits[1].contains(500.0));
    }
}
