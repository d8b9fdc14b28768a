use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, simulate};
use schwenkbar_core::stock::{Cutting, StockOptions};
use schwenkbar_core::{parse, sample};
fn main() {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(14_000);
    let src = sample::cam_program(n);
    let (program, _) = parse(&src);
    let machine = Machine::builtin("ac-table").unwrap();
    let sim = simulate(&program, &machine, &SimOptions::default());
    let t = std::time::Instant::now();
    let cutting = Cutting::new(&program, &sim, StockOptions { resolution: 0.25, checkpoints: 0 });
    let t1 = t.elapsed().as_secs_f64();
    let s = cutting.final_stock().unwrap();

    println!("{t1:.3} s; vol {:.3} digest {:x}", s.volume(), s.digest());
}
