//! Prints the states of a program: `cargo run --example sim_dump -- FILE MACHINE`.
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, simulate};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(file), Some(id)) = (args.get(1), args.get(2)) else {
        eprintln!("usage: sim_dump FILE MACHINE");
        return;
    };
    let Ok(src) = std::fs::read_to_string(file) else { return };
    let Ok(m) = Machine::builtin(id) else { return };
    let (p, _) = schwenkbar_core::parse(&src);
    let sim = simulate(&p, &m, &SimOptions::default());
    for s in sim.states(&p) {
        let a = s.axes;
        println!(
            "{:3} L{:3} X{:9.3} Y{:9.3} Z{:9.3} {}{:8.3} {}{:8.3} tipW {:?} tipI {:?} segs {} {:?}",
            s.step,
            s.line,
            a.linear.x,
            a.linear.y,
            a.linear.z,
            a.letters[0],
            a.rotary[0],
            a.letters[1],
            a.rotary[1],
            s.tip_wcs.to_array().map(|v| (v * 1000.0).round() / 1000.0),
            s.tip_ics.to_array().map(|v| (v * 1000.0).round() / 1000.0),
            s.segments.len(),
            s.message.map(|m| m.de)
        );
    }
    println!("error: {:?}", sim.error.map(|e| (e.line, e.message.de, e.detail.de)));
}
