//! Program run (Programmlauf Einzelsatz / Satzfolge) over the core's simulation: which executed
//! step is shown, playing or not, at what speed. Pure; the app shell's timer sends `RunTick`.

use std::ops::Range;
use std::rc::Rc;
use std::sync::Arc;

use schwenkbar_core::Program;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::tools::ToolEntry;
use schwenkbar_core::sim::{SimOptions, Simulation, State, simulate};

/// The simulation of the current program on the current machine, compared by identity (it is
/// recomputed, never edited). An `Arc`: a run the next edit stops early keeps this one for the
/// edit after ([`Simulation::resumed`]) without copying it.
#[derive(Debug, Clone)]
pub struct SimRef(pub Arc<Simulation>);

impl SimRef {
    /// The program simulated on the machine with the control's defaults.
    #[must_use]
    pub fn of(program: &Program, machine: &Machine) -> SimRef {
        SimRef::with_tools(program, machine, None)
    }

    /// [`SimRef::of`] with the shop's tool table (`None`: the shipped one).
    #[must_use]
    pub fn with_tools(program: &Program, machine: &Machine, tools: Option<Arc<[ToolEntry]>>) -> SimRef {
        SimRef(Arc::new(simulate(program, machine, &SimOptions { tools, ..SimOptions::default() })))
    }

    /// The simulation of `program`, an edit of the simulated program that kept its blocks
    /// outside `changed` ([`Simulation::resumed`]).
    #[must_use]
    pub fn resumed(&self, program: &Program, changed: Range<usize>) -> SimRef {
        SimRef(Arc::new(self.0.resumed(program, changed)))
    }
}

impl PartialEq for SimRef {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// A machine state handed to the views, compared by identity: a view re-renders when the run
/// shows another state, and comparing two states field by field would cost time and code.
#[derive(Debug, Clone)]
pub struct StateRef(pub Rc<State>);

impl PartialEq for StateRef {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0)
    }
}

impl std::ops::Deref for StateRef {
    type Target = State;
    fn deref(&self) -> &State {
        &self.0
    }
}

/// Playback speeds, as factors of the real motion time.
pub const SPEEDS: [f64; 7] = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];

#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Index into the simulation's executed steps.
    pub step: usize,
    /// Satzfolge: blocks follow each other by themselves.
    pub playing: bool,
    /// Index into [`SPEEDS`].
    pub speed: usize,
    /// The machine state after `step`.
    pub state: Option<Rc<State>>,
    /// The run reached the block the control refuses.
    pub stopped_by_error: bool,
    /// Classroom: the class is asked where the next block swivels before it runs.
    pub asking: bool,
}

impl Run {
    #[must_use]
    pub fn new(sim: &Simulation, program: &Program, step: usize) -> Run {
        let mut run =
            Run { step: 0, playing: false, speed: 2, state: None, stopped_by_error: false, asking: false };
        run.go_to(sim, program, step);
        run
    }

    /// Shows step `step` (clamped to the executed ones).
    pub fn go_to(&mut self, sim: &Simulation, program: &Program, step: usize) {
        self.step = step.min(sim.len().saturating_sub(1));
        self.state = sim.state_at(program, self.step).map(Rc::new);
        self.stopped_by_error = false;
        self.asking = false;
    }

    /// One block on; at the end (or at the refused block) playing stops. `true` if it moved.
    pub fn next(&mut self, sim: &Simulation, program: &Program) -> bool {
        if self.step + 1 < sim.len() {
            self.go_to(sim, program, self.step + 1);
            return true;
        }
        self.playing = false;
        self.stopped_by_error = sim.error.is_some();
        false
    }

    pub fn prev(&mut self, sim: &Simulation, program: &Program) {
        self.go_to(sim, program, self.step.saturating_sub(1));
        self.playing = false;
    }

    #[must_use]
    pub fn speed_factor(&self) -> f64 {
        SPEEDS.get(self.speed).copied().unwrap_or(1.0)
    }

    /// How long the shown block takes at the chosen speed, for the Satzfolge timer (at least a
    /// glance, at most a few seconds, so an empty block does not flash by and a long cycle does
    /// not stall the lesson).
    #[must_use]
    pub fn tick_ms(&self) -> u64 {
        let secs = self.state.as_ref().map_or(0.0, |s| s.duration()) / self.speed_factor();
        (secs.clamp(0.25, 4.0) * 1000.0) as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use schwenkbar_core::machine::Machine;
    use schwenkbar_core::sim::{SimOptions, simulate};

    fn sim_of(text: &str, machine: &str) -> (Program, Simulation) {
        let (p, _) = schwenkbar_core::parse(text);
        let m = Machine::builtin(machine).expect("shipped");
        let s = simulate(&p, &m, &SimOptions::default());
        (p, s)
    }

    #[test]
    fn stepping_through_musterprogramm_1_reaches_the_swivel_and_the_end() {
        let (p, sim) = sim_of(crate::samples::MUSTERPROGRAMM_1.text, "ac-table");
        let mut run = Run::new(&sim, &p, 0);
        while run.state.as_ref().is_some_and(|s| s.block < 10) {
            assert!(run.next(&sim, &p));
        }
        let s = run.state.as_ref().expect("state after block 10");
        assert_eq!(s.block, 10);
        let c = s.axes.rotary_axis(schwenkbar_core::plane::RotaryAxis::C).expect("C");
        let a = s.axes.rotary_axis(schwenkbar_core::plane::RotaryAxis::A).expect("A");
        assert!((a - 15.0).abs() < 1e-9 && (c - 90.0).abs() < 1e-9, "A{a} C{c}");
        while run.next(&sim, &p) {}
        assert!(!run.stopped_by_error);
        run.prev(&sim, &p);
        assert_eq!(run.step, sim.len() - 2);
    }

    #[test]
    fn the_refused_block_stops_the_run() {
        let (p, sim) = sim_of(crate::samples::SAMPLES[3].text, "ba-table");
        let mut run = Run::new(&sim, &p, 0);
        run.playing = true;
        while run.next(&sim, &p) {}
        assert!(run.stopped_by_error && !run.playing);
        assert_eq!(sim.error.as_ref().map(|e| &*e.message.de), Some("Winkel nicht erlaubt"));
    }
}
