//! M functions as real programs write them: with the words that belong to them (`M140 MB`,
//! `M128 F`, `M120 LA`), in machine coordinates (`M91`, `M92`), and each one the simulator does
//! not model said on its block.

use super::*;

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
