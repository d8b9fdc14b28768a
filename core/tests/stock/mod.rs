//! The stock (issue 14) against closed forms: programs run through the simulator, cut at 0.25 mm
//! unless a test says otherwise. Volumes within 1 % (the figure), angles within 0.1°. A
//! file per idea: what a cut removes, the same stock however it is reached, the material the
//! tool must not meet, the mesh the view and the STL get.

mod collisions;
mod mesh;
mod reached;
mod volumes;

use glam::DVec3;
use proptest::prelude::*;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Blank, SimOptions, Simulation, simulate};
use schwenkbar_core::stock::{
    Cutting, Stock, StockCursor, StockMesh, StockNoteKind, StockOptions, TiledMesh,
};
use schwenkbar_core::{Program, parse};

fn run(src: &str, options: StockOptions) -> (Program, Simulation, Cutting) {
    let (program, _) = parse(src);
    let machine = Machine::builtin("ac-table").expect("shipped machine");
    let sim = simulate(&program, &machine, &SimOptions::default());
    assert!(sim.error.is_none(), "{:?}", sim.error);
    let cutting = Cutting::new(&program, &sim, options);
    (program, sim, cutting)
}

fn musterprogramm() -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../static/programs/musterprogramm1.h");
    std::fs::read_to_string(path).expect("Musterprogramm 1")
}

const BLANK: &str = "BLK FORM 0.1 Z X+0 Y+0 Z-40\nBLK FORM 0.2 X+100 Y+100 Z+0\n";

const BLANK_VOLUME: f64 = 100.0 * 100.0 * 40.0;

fn removed(c: &Cutting) -> f64 {
    BLANK_VOLUME - c.final_stock().expect("stock").volume()
}

fn within_one_percent(actual: f64, exact: f64) {
    eprintln!(
        "removed {actual:.1} mm³, closed form {exact:.1} mm³, {:+.3} %",
        100.0 * (actual / exact - 1.0)
    );
    assert!((actual - exact).abs() <= 0.01 * exact, "removed {actual:.1} mm³, closed form {exact:.1} mm³");
}

fn tilt() -> DVec3 {
    let b = 15f64.to_radians();
    DVec3::new(b.sin(), 0.0, b.cos())
}

/// One pass of the face mill (tool 16) 2 mm below the plane tilted SPB+15 through the blank's
/// top edge, across the whole blank.
fn face_mill_15() -> String {
    format!(
        "{BLANK}TOOL CALL 16 Z S5000 F500\nL Z+0 R0 FMAX M91\nPLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n\
         L X-40 Y+50 Z+50 R0 FMAX\nL Z-2 F500\nL X+140\nL Z+50 FMAX\nM30\n"
    )
}
