//! Program run mode: starting a run, stepping, the cursor following it, and the classroom's
//! question before a swivel (projector mode and the course's instructor view).

use std::rc::Rc;

use glam::DVec3;
use schwenkbar_core::machine::{Carrier, Machine};
use schwenkbar_core::plane::Positioning;
use schwenkbar_core::sim::{Collision, MachineAxes, Simulation, State};
use schwenkbar_core::{BlockBody, Program};

use super::{Action, AppState};
use crate::i18n::{Lang, Text};
use crate::run::Run;

/// Whether executed step `step` is a PLANE block that moves the rotary axes (MOVE or TURN).
fn swivels(sim: &Simulation, program: &Program, step: usize) -> bool {
    let Some(record) = sim.records.get(step).filter(|r| r.executed) else { return false };
    matches!(
        program.blocks.get(record.block as usize).and_then(schwenkbar_core::Block::stored_body),
        Some(BlockBody::Plane(p)) if matches!(p.positioning, Some(Positioning::Move { .. } | Positioning::Turn { .. }))
    )
}

/// One step on: in the classroom (`classroom`) a swivel that has not been asked about yet is
/// asked first (`run.asking`), the next NC start runs it.
pub(super) fn next_or_ask(run: &mut Run, sim: &Simulation, program: &Program, classroom: bool) {
    if classroom && !run.asking && swivels(sim, program, run.step + 1) {
        run.asking = true;
    } else {
        run.next(sim, program);
    }
}

impl AppState {
    pub(super) fn start_run(&mut self) {
        self.dialog = None;
        self.text_editing = false;
        match &self.sim {
            Some(sim) if !sim.0.is_empty() => {
                let stop = sim.0.error.as_ref().filter(|e| e.block <= self.cursor);
                let (step, stopped) = match (sim.0.step_of_block(self.cursor), stop) {
                    (Some(step), _) => (step, false),
                    // The control stops before it reaches the cursor's block (or on it, e.g. a
                    // collision in its swivel): the run stands where it stopped, as after
                    // playing there, with the control's message.
                    (None, Some(_)) => (sim.0.len() - 1, true),
                    (None, None) => (0, false),
                };
                let mut run = Run::new(&sim.0, &self.doc.program, step);
                run.stopped_by_error = stopped;
                self.run = Some(run);
                self.sync_cursor_to_run();
            }
            Some(sim) => {
                self.message = Some(match &sim.0.error {
                    Some(_) => Text::new(
                        "Programmlauf nicht möglich: Fehler im ersten Satz",
                        "Cannot run: error in the first block",
                    ),
                    None => Text::new("Kein Satz zum Ausführen", "No block to run"),
                })
            }
            None => self.message = Some(Text::new("Keine Maschine gewählt", "No machine selected")),
        }
    }

    /// The machine state the 3D view shows: the run's step, else the state after the cursor
    /// block (if the run reaches it).
    #[must_use]
    pub fn shown_state(&self) -> Option<Rc<State>> {
        if let Some(run) = &self.run {
            return run.state.clone();
        }
        let sim = &self.sim.as_ref()?.0;
        let step = sim.step_of_block(self.cursor)?;
        sim.state_at(&self.doc.program, step).map(Rc::new)
    }

    /// The collision that stopped the run, while the run stands there: the view shows the
    /// moment of contact ([`crate::scene::SceneState::at_collision`]).
    #[must_use]
    pub fn shown_collision(&self) -> Option<&Collision> {
        self.run.as_ref().filter(|r| r.stopped_by_error)?;
        self.sim.as_ref()?.0.collision()
    }

    /// Where the position display stands while the run stands at a collision: REF at the
    /// contact and IST in the plane still active then ([`State::tip_ics_with`]), not the last
    /// finished block.
    #[must_use]
    pub fn stop_position(&self) -> Option<(MachineAxes, DVec3)> {
        let c = self.shown_collision()?;
        let state = self.run.as_ref()?.state.as_ref()?;
        Some((c.axes, state.tip_ics_with(self.machine.as_ref()?, &c.axes)))
    }

    /// Applies `f` to the open run with the simulation and program, then moves the cursor along.
    pub(super) fn run_step(&mut self, f: impl FnOnce(&mut Run, &Simulation, &Program)) {
        let (Some(run), Some(sim)) = (self.run.as_mut(), self.sim.as_ref()) else { return };
        f(run, &sim.0, &self.doc.program);
        self.sync_cursor_to_run();
    }

    /// In run mode the cursor shows the block of the current step; a click or an arrow key
    /// jumps there.
    pub(super) fn run_cursor(&mut self, action: Action) {
        let target = match action {
            Action::CursorUp => self.cursor.saturating_sub(1),
            Action::CursorDown => (self.cursor + 1).min(self.doc.last_index()),
            Action::CursorTo(i) => i,
            _ => return,
        };
        let step = self.sim.as_ref().and_then(|s| s.0.step_of_block(target));
        match step {
            Some(step) => self.run_step(|run, sim, p| {
                run.playing = false;
                run.go_to(sim, p, step);
            }),
            None => {
                self.message = Some(Text::new(
                    "Dieser Satz wird im Programmlauf nicht erreicht",
                    "The run does not reach this block",
                ))
            }
        }
    }

    /// The cursor follows the run; when the control refused a block it stands on that block.
    pub(super) fn sync_cursor_to_run(&mut self) {
        let Some(run) = &self.run else { return };
        let refused = self.sim.as_ref().and_then(|s| s.0.error.as_ref()).filter(|_| run.stopped_by_error);
        if let Some(block) = refused.map(|e| e.block).or(run.state.as_ref().map(|s| s.block)) {
            self.cursor = block;
        }
    }

    /// The classroom's question before a swivel: "Wohin schwenkt der Tisch? Welche Werte haben
    /// A und C?" (master first, as the control names the solution).
    pub(super) fn prediction_question(&self, machine: &Machine) -> String {
        let [slave, master] = machine.joints();
        let (m, s) = (master.axis.letter(), slave.axis.letter());
        match (self.lang, master.carrier) {
            (Lang::De, Carrier::Table) => format!(
                "Vorhersage: Wohin schwenkt der Tisch? Welche Werte haben {m} und {s}? NC-Start zeigt es."
            ),
            (Lang::De, Carrier::Head) => format!(
                "Vorhersage: Wohin schwenkt der Kopf? Welche Werte haben {m} und {s}? NC-Start zeigt es."
            ),
            (Lang::En, Carrier::Table) => {
                format!("Predict: where does the table swivel? What are {m} and {s}? NC start shows it.")
            }
            (Lang::En, Carrier::Head) => {
                format!("Predict: where does the head swivel? What are {m} and {s}? NC start shows it.")
            }
        }
    }
}
