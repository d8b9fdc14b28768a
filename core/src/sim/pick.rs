//! The machine a program was written for, among the ones at hand (`schwenkbar run --machine
//! auto`): the machines whose rotary axes include every rotary axis the program names (`L B…
//! C…`, `PLANE AXIAL`, cycle 19), and of those the one on which the run gets furthest — to its
//! end if it can — the first in the list on a tie. Trying is the honest test: the limits, the
//! pivots and the collisions of each machine decide, not a guess from the letters alone.

use crate::ast::{Axis, BlockBody, OldCycleData, OldCycleWord, Program};
use crate::lang::Text;
use crate::machine::Machine;
use crate::plane::{PlaneDef, RotaryAxis};

use super::{SimOptions, Simulation, simulate};

/// The machine chosen, its run and why it was chosen.
pub struct Pick {
    /// Index into the candidates.
    pub index: usize,
    pub simulation: Simulation,
    pub reason: Text,
}

fn rotary(a: Axis) -> Option<RotaryAxis> {
    match a {
        Axis::A => Some(RotaryAxis::A),
        Axis::B => Some(RotaryAxis::B),
        Axis::C => Some(RotaryAxis::C),
        _ => None,
    }
}

/// The rotary axes the program names, in A, B, C order.
#[must_use]
pub fn programmed_rotary_axes(program: &Program) -> Vec<RotaryAxis> {
    let mut seen = [false; 3];
    for b in &program.blocks {
        let body = b.body();
        let mut mark = |a: RotaryAxis| seen[a as usize] = true;
        match &*body {
            BlockBody::L(l) => l.axes.iter().filter_map(|w| rotary(w.axis)).for_each(&mut mark),
            BlockBody::Plane(p) => {
                if let PlaneDef::Axial { axes } = &p.def {
                    axes.iter().for_each(|a| mark(a.axis));
                }
            }
            BlockBody::CycleDefOld(c) if c.number == 19 => {
                if let OldCycleData::Words(words) = &c.data {
                    for w in words {
                        if let OldCycleWord::Axis(a) = w
                            && let Some(r) = rotary(a.axis)
                        {
                            mark(r);
                        }
                    }
                }
            }
            _ => {}
        }
    }
    [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C].into_iter().filter(|&a| seen[a as usize]).collect()
}

/// Of `candidates` (at least one), the machine for `program` (see the module docs).
///
/// # Panics
/// Never with at least one candidate; with none there is nothing to pick (a caller's bug).
#[must_use]
pub fn pick_machine(program: &Program, candidates: &[Machine], options: &SimOptions) -> Pick {
    let axes = programmed_rotary_axes(program);
    let has_all = |m: &Machine| axes.iter().all(|a| m.joints().iter().any(|j| j.axis == *a));
    let fitting: Vec<usize> = (0..candidates.len()).filter(|&i| has_all(&candidates[i])).collect();
    let tried = if fitting.is_empty() { (0..candidates.len()).collect() } else { fitting.clone() };
    let mut best: Option<(usize, Simulation)> = None;
    for i in tried {
        let sim = simulate(program, &candidates[i], options);
        let better = best.as_ref().is_none_or(|(_, b)| score(&sim) > score(b));
        if better {
            best = Some((i, sim));
        }
    }
    let (index, simulation) = best.unwrap_or_else(|| (0, simulate(program, &candidates[0], options)));
    let letters = axes.iter().map(|a| a.letter().to_string()).collect::<Vec<_>>().join(", ");
    let id = &candidates[index].id;
    let axes_de = if axes.is_empty() {
        "keine Drehachse im Programm".to_owned()
    } else if fitting.is_empty() {
        format!("Drehachsen {letters} im Programm, keine Maschine hat alle")
    } else {
        format!("Drehachsen {letters} im Programm")
    };
    let axes_en = if axes.is_empty() {
        "no rotary axis in the program".to_owned()
    } else if fitting.is_empty() {
        format!("rotary axes {letters} in the program, no machine has them all")
    } else {
        format!("rotary axes {letters} in the program")
    };
    let (run_de, run_en) = if simulation.error.is_none() {
        ("läuft bis zum Ende".to_owned(), "runs to its end".to_owned())
    } else {
        let n = simulation.records.len();
        (format!("läuft am weitesten ({n} Sätze)"), format!("gets furthest ({n} blocks)"))
    };
    let reason = Text::owned(
        format!("Maschine automatisch gewählt: {id} ({axes_de}; {run_de})"),
        format!("Machine chosen automatically: {id} ({axes_en}; {run_en})"),
    );
    Pick { index, simulation, reason }
}

/// A run to the end beats any stopped run; then the more executed blocks.
fn score(sim: &Simulation) -> (bool, usize) {
    (sim.error.is_none(), sim.records.len())
}
