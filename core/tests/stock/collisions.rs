//! The material the tool must not meet: a rapid or a swivel into the blank is said on its block
//! (issue 32 item 3); runs that stay clear cost no cutting.

use super::*;

#[test]
fn a_rapid_into_the_blank_is_reported_on_its_block_and_cuts() {
    let src = format!("{BLANK}TOOL CALL 1 Z\nL X+50 Y+50 Z+10 R0 FMAX\nL Z-5 FMAX\nL Z+10 FMAX\nM30\n");
    let (program, sim, c) = run(&src, StockOptions::default());
    let block = program.blocks.iter().position(|b| b.line() == 5).expect("block of line 5");
    let step = sim.step_of_block(block).expect("ran");
    let notes: Vec<_> = c.notes.iter().map(|n| (n.step, n.kind)).collect();
    assert_eq!(notes, vec![(step, StockNoteKind::RapidIntoMaterial)]);
    assert_eq!(c.notes[0].block, block);
    assert!(c.notes[0].message().de.starts_with("Eilgang ins Material"));
    within_one_percent(removed(&c), std::f64::consts::PI * 25.0 * 5.0);
    assert!(sim.error.is_none());
}

/// The crash the trainer exists to prevent (issue 32): the drill 5 mm deep, then the plane
/// swivelled with TURN. Worked by hand: the A table turns the blank 30° about the X axis through
/// the machine's pivot while the tool stands in its hole, so the hole's wall sweeps through the
/// tool: material is removed at the PLANE block. With `MB MAX` the tool first leaves along its
/// axis (through its own hole: nothing new is cut) and the swivel is free.
#[test]
fn a_swivel_with_the_tool_in_the_material_is_a_collision_on_the_plane_block() {
    let plane = |mb: &str| {
        format!(
            "{BLANK}TOOL CALL 1 Z S1000\nL X+50 Y+50 Z+10 R0 FMAX\nL Z-5 F100\n\
             PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN{mb} FMAX\nM30\n"
        )
    };
    // 0.5 mm rays: the drill's sweep through the material is caught as at the default 0.25.
    let coarse = StockOptions { resolution: 0.5, checkpoints: 3 };
    let (program, sim, c) = run(&plane(""), coarse);
    let block = program.blocks.iter().position(|b| b.line() == 6).expect("the PLANE block");
    let notes: Vec<_> = c.notes.iter().map(|n| (n.block, n.kind)).collect();
    assert_eq!(notes, vec![(block, StockNoteKind::SwivelInMaterial)]);
    assert!(c.notes[0].message().de.contains("MB MAX"), "{}", c.notes[0].message().de);
    // The same without a stock to show: the check the CLI and a hidden stock make.
    let collisions = Cutting::collisions(&program, &sim, coarse, usize::MAX);
    assert_eq!(collisions.notes, c.notes);
    assert_eq!(collisions.unchecked, None);
    // A check with too little work allowed says where it stopped instead of passing silently.
    let short = Cutting::collisions(&program, &sim, coarse, 10);
    assert!(short.notes.is_empty());
    let (step, at) = short.unchecked.expect("stopped");
    assert!(at < block && step < sim.step_of_block(block).expect("ran"), "{at} before {block}");
    assert!(short.unchecked_message().is_some());

    let (program, sim, c) = run(&plane(" MB MAX"), coarse);
    assert!(c.notes.is_empty(), "{:?}", c.notes);
    assert_eq!(Cutting::collisions(&program, &sim, coarse, usize::MAX), Default::default());
}

#[test]
fn musterprogramm_has_no_collision_with_its_material() {
    let (program, sim, c) = run(&musterprogramm(), StockOptions::default());
    assert!(c.notes.iter().all(|n| !n.is_collision()), "{:?}", c.notes);
    assert_eq!(Cutting::collisions(&program, &sim, StockOptions::default(), usize::MAX), Default::default());
}

/// Rapids above the blank and retracts straight up the tool axis cannot meet material: the
/// check needs no cut at all (work 0 would otherwise say where it stopped).
#[test]
fn rapids_above_the_blank_and_retracts_need_no_cutting() {
    let src = format!(
        "{BLANK}TOOL CALL 1 Z S1000\nL X+20 Y+20 Z+5 R0 FMAX\nL Z-5 F100\nL X+80 F500\n\
         L Z+5 FMAX\nL X+20 Y+80 FMAX\nL Z-3 F100\nL Z+50 FMAX\nM30\n"
    );
    let (program, sim, c) = run(&src, StockOptions::default());
    assert!(c.notes.is_empty(), "{:?}", c.notes);
    assert_eq!(Cutting::collisions(&program, &sim, StockOptions::default(), 0), Default::default());
    // A lateral rapid at depth is checked, and with no work allowed that is said.
    let lateral = src.replace("L Z+5 FMAX\nL X+20 Y+80 FMAX", "L X+20 Y+80 FMAX");
    let (program, sim, c) = run(&lateral, StockOptions::default());
    assert!(c.notes.iter().any(|n| n.kind == StockNoteKind::RapidIntoMaterial), "{:?}", c.notes);
    assert!(Cutting::collisions(&program, &sim, StockOptions::default(), 0).unchecked.is_some());
}
