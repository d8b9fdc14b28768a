//! All UI state in one reducer (yew `Reducible`), pure and tested natively.
//!
//! The softkey row works like the control's: a key such as `SPEC FCT` replaces the row with the
//! softkeys of that area, `END`/the back softkey returns one level; a PLANE function opens the
//! dialog ([`crate::dialog`]), whose finished block is inserted after the cursor.

use std::rc::Rc;

use schwenkbar_core::machine::Carrier;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::plane::Positioning;
use schwenkbar_core::sim::{SimOptions, Simulation, State, simulate};
use schwenkbar_core::{BlockBody, Program, edit};
use yew::Reducible;

use crate::dialog::{Dialog, Function, Key, Outcome};
use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::persist::{self, Saved, Shared};
use crate::run::{Run, SPEEDS, SimRef};
use crate::samples;

/// Which softkey row is shown when no dialog is open.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SoftkeyLevel {
    /// Programming mode, top level.
    #[default]
    Main,
    /// After the `SPEC FCT` key: special functions.
    SpecFct,
    /// After `BEARB.-EBENE SCHWENKEN`: the PLANE functions.
    TiltPlane,
    /// Choice of the machine (kinematics).
    Machines,
    /// Sample programs to open.
    Samples,
    /// Import, download, share link.
    Files,
}

/// A side effect asked for by the reducer and carried out by the app shell (`app.rs` with
/// `browser.rs`), which reports the outcome with [`Action::Notice`]. Keeping them as data keeps
/// the reducer pure: a softkey clicked and the same softkey pressed as F-key ask for the same.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// Offer the program as a `.h` file.
    Download { name: String, text: String },
    /// Put the share link (this page's address with `#fragment`) on the clipboard, else into
    /// the address bar.
    Share { fragment: String },
    /// Open the file picker for IMPORT (F1 on the DATEI row; a click opens it directly).
    PickFile,
    /// Move the keyboard focus into the program text area (TEXT EDITIEREN).
    FocusEditor,
    /// The share link's fragment has been read: take it out of the address bar, so that a
    /// reload shows the trainee's own work and not the link again.
    ConsumeFragment,
}

/// The effects asked for by the last transition; `seq` counts every effect ever asked for, so
/// the shell runs each list once.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Effects {
    pub seq: u64,
    pub list: Rc<[Effect]>,
}

/// A share link opened over the trainee's own program: the link's program is shown (and can be
/// run), the own one is kept aside and nothing is saved until the trainee decides.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkPreview {
    pub own: Rc<Document>,
    pub own_cursor: usize,
    pub own_machine: Option<Rc<Machine>>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct AppState {
    pub lang: Lang,
    /// Classroom projector: large type and softkeys, secondary panels hidden.
    pub projector: bool,
    pub level: SoftkeyLevel,
    /// The open PLANE dialog and, when it edits an existing block, that block's index.
    pub dialog: Option<(Dialog, Option<usize>)>,
    pub doc: Rc<Document>,
    /// Index of the cursor block in `doc.program.blocks`.
    pub cursor: usize,
    /// The selected machine; `None` only if a machine definition failed to load (reported).
    pub machine: Option<Rc<Machine>>,
    /// A message in the dialog line outside a dialog (e.g. why a key did nothing).
    pub message: Option<Text>,
    /// Free text editing of the whole program.
    pub text_editing: bool,
    /// The program simulated on the machine (recomputed when either changes).
    pub sim: Option<SimRef>,
    /// Program run mode, when active.
    pub run: Option<Run>,
    /// The right-hand-rule demonstration in place of the machine view.
    pub right_hand: bool,
    /// A share link shown as a preview: "Übernehmen?".
    pub link: Option<LinkPreview>,
    /// Side effects asked for by the last transition.
    pub effects: Effects,
}

impl Default for AppState {
    fn default() -> Self {
        AppState {
            lang: Lang::default(),
            projector: false,
            level: SoftkeyLevel::Main,
            dialog: None,
            doc: Rc::new(Document::new(samples::DEFAULT.text.to_owned())),
            cursor: 0,
            machine: Machine::builtin(DEFAULT_MACHINE).ok().map(Rc::new),
            message: None,
            text_editing: false,
            sim: None,
            run: None,
            right_hand: false,
            link: None,
            effects: Effects::default(),
        }
        .simulated()
    }
}

/// The seed's first example machine.
pub const DEFAULT_MACHINE: &str = "ac-table";

#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// The `SPEC FCT` key.
    SpecFct,
    /// Softkey `BEARB.-EBENE SCHWENKEN`.
    TiltPlane,
    /// A PLANE function softkey: opens its dialog.
    Function(Function),
    /// A key while the dialog is open (ENT, NO ENT, END, digits, dialog softkeys).
    DialogKey(Key),
    /// `DEL`/Esc: aborts the dialog without inserting anything.
    Abort,
    /// The `END` key or the back softkey outside a dialog: one softkey level up.
    Back,
    /// ENT outside a dialog: reopens the PLANE block under the cursor.
    Open,
    CursorUp,
    CursorDown,
    /// A click on a block.
    CursorTo(usize),
    /// The program text changed (typed or pasted in the editor).
    SetText(String),
    ToggleTextEditing,
    ShowMachines,
    SelectMachine(String),
    ShowSamples,
    LoadSample(String),
    ShowFiles,
    /// IMPORT by key: opens the file picker ([`Effect::PickFile`]).
    PickFile,
    /// A file was read: its bytes (Latin-1 or UTF-8).
    Import(Vec<u8>),
    /// HERUNTERLADEN and LINK TEILEN: carried out by the shell ([`Effect`]).
    Download,
    Share,
    /// The opened share link: take its program as the own one, or keep the own one.
    TakeLink,
    KeepOwn,
    /// The app shell reports the outcome of a side effect in the dialog line.
    Notice(Text),
    /// Program run: enter (single block), step, play/pause (Satzfolge), speed, back to start.
    StartRun,
    RunNext,
    RunPrev,
    RunPlay,
    RunFaster,
    RunSlower,
    RunToStart,
    /// The Satzfolge timer fired while step `.0` was shown.
    RunTick(usize),
    /// The right-hand rule on a plane you rotate, in place of the machine view.
    ToggleRightHand,
    ToggleLang,
    ToggleProjector,
}

/// Whether executed step `step` is a PLANE block that moves the rotary axes (MOVE or TURN):
/// in the classroom the run stops before it and asks the class first.
fn swivels(sim: &Simulation, program: &Program, step: usize) -> bool {
    let Some(record) = sim.records.get(step).filter(|r| r.executed) else { return false };
    matches!(
        program.blocks.get(record.block as usize).map(|b| &b.body),
        Some(BlockBody::Plane(p)) if matches!(p.positioning, Some(Positioning::Move { .. } | Positioning::Turn { .. }))
    )
}

impl Action {
    /// While a share link is previewed: looking at it and running it is allowed, changing a
    /// program is not until the trainee took the link or kept the own program.
    fn allowed_in_link_preview(&self) -> bool {
        matches!(
            self,
            Action::TakeLink
                | Action::KeepOwn
                | Action::CursorUp
                | Action::CursorDown
                | Action::CursorTo(_)
                | Action::Notice(_)
                | Action::Back
                | Action::StartRun
                | Action::RunNext
                | Action::RunPrev
                | Action::RunPlay
                | Action::RunFaster
                | Action::RunSlower
                | Action::RunToStart
                | Action::RunTick(_)
                | Action::ToggleRightHand
                | Action::ToggleLang
                | Action::ToggleProjector
        )
    }
}

impl AppState {
    /// The pure transition; `Reducible::reduce` only wraps it.
    #[must_use]
    pub fn apply(&self, action: Action) -> AppState {
        let mut next = self.clone();
        next.message = None;
        next.effects.list = Rc::from([]);
        if self.link.is_some() && !action.allowed_in_link_preview() {
            next.message = Some(Text::new(
                "Zuerst entscheiden: LINK ÜBERNEHMEN oder EIGENES BEHALTEN",
                "Decide first: TAKE LINK or KEEP MINE",
            ));
            return next;
        }
        match action {
            Action::SpecFct => {
                next.dialog = None;
                next.level = SoftkeyLevel::SpecFct;
            }
            Action::TiltPlane if self.level == SoftkeyLevel::SpecFct => next.level = SoftkeyLevel::TiltPlane,
            Action::TiltPlane => {}
            Action::Function(f) => next.dialog = Some((Dialog::new(f), None)),
            Action::DialogKey(key) => next.dialog_key(key),
            Action::Abort => {
                next.dialog = None;
                next.message = Some(Text::new("Dialog abgebrochen", "Dialog aborted"));
            }
            Action::Back if self.run.is_some() => next.run = None,
            Action::Back => {
                if next.dialog.take().is_none() {
                    next.level = match self.level {
                        SoftkeyLevel::TiltPlane => SoftkeyLevel::SpecFct,
                        _ => SoftkeyLevel::Main,
                    };
                }
            }
            Action::Open => next.open_cursor_block(),
            // The dialog is modal, as on the control: the cursor stays where the block goes.
            Action::CursorUp | Action::CursorDown | Action::CursorTo(_) if self.dialog.is_some() => {}
            Action::CursorUp | Action::CursorDown | Action::CursorTo(_) if self.run.is_some() => {
                next.run_cursor(action);
            }
            Action::CursorUp => next.cursor = self.cursor.saturating_sub(1),
            Action::CursorDown => next.cursor = (self.cursor + 1).min(self.doc.last_index()),
            Action::CursorTo(i) => next.cursor = i.min(self.doc.last_index()),
            Action::SetText(text) => {
                next.doc = Rc::new(Document::new(text));
                next.cursor = self.cursor.min(next.doc.last_index());
            }
            Action::ToggleTextEditing => {
                next.text_editing = !self.text_editing;
                if next.text_editing {
                    next.emit(Effect::FocusEditor);
                }
            }
            Action::ShowMachines => next.level = SoftkeyLevel::Machines,
            Action::SelectMachine(id) => next.select_machine(&id),
            Action::ShowSamples => next.level = SoftkeyLevel::Samples,
            Action::LoadSample(id) => match samples::by_id(&id) {
                Some(sample) => {
                    next.doc = Rc::new(Document::new(sample.text.to_owned()));
                    next.cursor = 0;
                    next.select_machine(sample.machine);
                }
                None => next.message = Some(Text::new("Beispiel unbekannt", "Unknown sample")),
            },
            Action::ShowFiles => next.level = SoftkeyLevel::Files,
            Action::PickFile => next.emit(Effect::PickFile),
            Action::Import(bytes) => next.import(bytes),
            Action::Download => {
                next.emit(Effect::Download { name: self.file_name(), text: self.doc.text.clone() })
            }
            Action::Share => next.emit(Effect::Share { fragment: self.share_fragment() }),
            Action::TakeLink => {
                next.link = None;
                next.message =
                    Some(Text::new("Programm aus dem Link übernommen", "Program from the link taken"));
            }
            Action::KeepOwn => {
                if let Some(own) = next.link.take() {
                    next.run = None;
                    next.doc = own.own;
                    next.cursor = own.own_cursor.min(next.doc.last_index());
                    next.machine = own.own_machine;
                    next.message = Some(Text::new("Eigenes Programm behalten", "Own program kept"));
                }
            }
            Action::Notice(text) => next.message = Some(text),
            Action::StartRun => next.start_run(),
            Action::RunNext => {
                let classroom = self.projector;
                next.run_step(|run, sim, p| {
                    run.playing = false;
                    if classroom && !run.asking && swivels(sim, p, run.step + 1) {
                        run.asking = true;
                    } else {
                        run.next(sim, p);
                    }
                });
            }
            Action::RunPrev => next.run_step(|run, sim, p| run.prev(sim, p)),
            Action::RunToStart => next.run_step(|run, sim, p| {
                run.playing = false;
                run.go_to(sim, p, 0);
            }),
            Action::RunPlay => next.run_step(|run, sim, p| {
                if run.asking {
                    // NC start after the question: reveal, then go on.
                    run.next(sim, p);
                    run.playing = true;
                    return;
                }
                run.playing = !run.playing;
                if run.playing && run.step + 1 >= sim.len() {
                    run.go_to(sim, p, 0);
                }
            }),
            Action::RunTick(step) => {
                let classroom = self.projector;
                next.run_step(|run, sim, p| {
                    if run.playing && run.step == step {
                        if classroom && !run.asking && swivels(sim, p, run.step + 1) {
                            run.playing = false;
                            run.asking = true;
                        } else {
                            run.next(sim, p);
                        }
                    }
                });
            }
            Action::RunFaster => next.run_step(|run, _, _| run.speed = (run.speed + 1).min(SPEEDS.len() - 1)),
            Action::RunSlower => next.run_step(|run, _, _| run.speed = run.speed.saturating_sub(1)),
            Action::ToggleRightHand => next.right_hand = !self.right_hand,
            Action::ToggleLang => next.lang = self.lang.other(),
            Action::ToggleProjector => next.projector = !self.projector,
        }
        let machine_changed = match (&self.machine, &next.machine) {
            (Some(a), Some(b)) => !Rc::ptr_eq(a, b),
            (a, b) => a.is_some() != b.is_some(),
        };
        if !Rc::ptr_eq(&self.doc, &next.doc) || machine_changed {
            next = next.simulated();
        }
        next
    }

    /// Re-runs the simulation (after the program or the machine changed) and keeps an open run
    /// at the same step where it still exists.
    #[must_use]
    fn simulated(mut self) -> AppState {
        self.sim = self
            .machine
            .as_ref()
            .map(|m| SimRef(Rc::new(simulate(&self.doc.program, m, &SimOptions::default()))));
        match (&self.sim, self.run.as_mut()) {
            (Some(sim), Some(run)) => run.go_to(&sim.0, &self.doc.program, run.step),
            (None, Some(_)) => self.run = None,
            _ => {}
        }
        self.sync_cursor_to_run();
        self
    }

    fn emit(&mut self, effect: Effect) {
        let mut list = self.effects.list.to_vec();
        list.push(effect);
        self.effects = Effects { seq: self.effects.seq + 1, list: list.into() };
    }

    /// IMPORT: a text file becomes the program; a binary file (an image, a CAD model, a zip)
    /// is refused and the program stays.
    fn import(&mut self, bytes: Vec<u8>) {
        if schwenkbar_core::text::looks_binary(&bytes) {
            self.message = Some(Text::new(
                "Datei ist kein NC-Programm (Binärdatei): nicht importiert",
                "The file is not an NC program (binary file): not imported",
            ));
            return;
        }
        self.doc = Rc::new(Document::new(schwenkbar_core::text::decode(bytes)));
        self.cursor = 0;
        self.level = SoftkeyLevel::Main;
        self.message = Some(Text::new("Datei importiert", "File imported"));
    }

    fn start_run(&mut self) {
        self.dialog = None;
        self.text_editing = false;
        match &self.sim {
            Some(sim) if !sim.0.is_empty() => {
                let step = sim.0.first_step.get(self.cursor).copied().flatten().unwrap_or(0) as usize;
                self.run = Some(Run::new(&sim.0, &self.doc.program, step));
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
        let step = sim.first_step.get(self.cursor).copied().flatten()?;
        sim.state_at(&self.doc.program, step as usize).map(Rc::new)
    }

    /// Applies `f` to the open run with the simulation and program, then moves the cursor along.
    fn run_step(&mut self, f: impl FnOnce(&mut Run, &Simulation, &Program)) {
        let (Some(run), Some(sim)) = (self.run.as_mut(), self.sim.as_ref()) else { return };
        f(run, &sim.0, &self.doc.program);
        self.sync_cursor_to_run();
    }

    /// In run mode the cursor shows the block of the current step; a click or an arrow key
    /// jumps there.
    fn run_cursor(&mut self, action: Action) {
        let target = match action {
            Action::CursorUp => self.cursor.saturating_sub(1),
            Action::CursorDown => (self.cursor + 1).min(self.doc.last_index()),
            Action::CursorTo(i) => i,
            _ => return,
        };
        let step = self.sim.as_ref().and_then(|s| s.0.first_step.get(target).copied().flatten());
        match step {
            Some(step) => self.run_step(|run, sim, p| {
                run.playing = false;
                run.go_to(sim, p, step as usize);
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
    fn sync_cursor_to_run(&mut self) {
        let Some(run) = &self.run else { return };
        let refused = self.sim.as_ref().and_then(|s| s.0.error.as_ref()).filter(|_| run.stopped_by_error);
        if let Some(block) = refused.map(|e| e.block).or(run.state.as_ref().map(|s| s.block)) {
            self.cursor = block;
        }
    }

    fn select_machine(&mut self, id: &str) {
        match Machine::builtin(id) {
            Ok(m) => {
                self.machine = Some(Rc::new(m));
                self.level = SoftkeyLevel::Main;
            }
            Err(_) => self.message = Some(Text::new("Maschine unbekannt", "Unknown machine")),
        }
    }

    fn dialog_key(&mut self, key: Key) {
        let Some((dialog, editing)) = self.dialog.as_mut() else { return };
        if let Outcome::Finished(text) = dialog.key(key) {
            let editing = *editing;
            self.dialog = None;
            let (source, cursor) = match editing {
                Some(index) => (edit::replace_block(&self.doc.text, &self.doc.program, index, &text), index),
                None => edit::insert_after(&self.doc.text, &self.doc.program, self.cursor, &text),
            };
            self.doc = Rc::new(Document::new(source));
            self.cursor = cursor.min(self.doc.last_index());
            self.level = SoftkeyLevel::TiltPlane;
        }
    }

    fn open_cursor_block(&mut self) {
        match self.doc.program.blocks.get(self.cursor).map(|b| &b.body) {
            Some(BlockBody::Plane(plane)) => self.dialog = Some((Dialog::reopen(plane), Some(self.cursor))),
            _ => {
                self.message = Some(Text::new(
                    "Nur PLANE-Sätze lassen sich im Dialog öffnen",
                    "Only PLANE blocks open in the dialog",
                ))
            }
        }
    }

    /// The dialog line in the UI language: the control's error message when a run stopped, else
    /// [`AppState::dialog_text`].
    #[must_use]
    pub fn dialog_line(&self) -> String {
        let error = self
            .run
            .as_ref()
            .filter(|r| r.stopped_by_error && self.dialog.is_none() && self.message.is_none());
        if let Some(e) = error.and(self.sim.as_ref()).and_then(|s| s.0.error.as_ref()) {
            return self.lang.t(&e.message.de, &e.message.en).to_owned();
        }
        if let (Some(machine), true) = (&self.machine, self.run.as_ref().is_some_and(|r| r.asking)) {
            return self.prediction_question(machine);
        }
        self.dialog_text().get(self.lang).to_owned()
    }

    /// The classroom's question before a swivel: "Wohin schwenkt der Tisch? Welche Werte haben
    /// A und C?" (master first, as the control names the solution).
    fn prediction_question(&self, machine: &Machine) -> String {
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

    /// The dialog line: the open dialog's prompt or message, else what the control expects.
    #[must_use]
    pub fn dialog_text(&self) -> Text {
        if let Some((d, _)) = &self.dialog {
            return d.message.unwrap_or_else(|| d.prompt());
        }
        if let Some(m) = self.message {
            return m;
        }
        if let Some(run) = &self.run {
            return if run.playing {
                Text::new("Programmlauf Satzfolge", "Program run, full sequence")
            } else {
                Text::new(
                    "Programmlauf Einzelsatz: NC-Start für den nächsten Satz",
                    "Program run, single block: NC start for the next block",
                )
            };
        }
        match self.level {
            SoftkeyLevel::Main => Text::new("Programm-Einspeichern/Editieren", "Programming"),
            SoftkeyLevel::SpecFct => {
                Text::new("Sonderfunktionen: Bereich wählen", "Special functions: select an area")
            }
            SoftkeyLevel::TiltPlane => Text::new(
                "Bearbeitungsebene schwenken: Funktion wählen",
                "Tilt the working plane: select a function",
            ),
            SoftkeyLevel::Machines => Text::new("Maschine wählen", "Select the machine"),
            // The samples are written as for a German control; English says so.
            SoftkeyLevel::Samples => Text::new(
                "Beispielprogramm öffnen",
                "Open a sample program (its comments are in German, as written for the control)",
            ),
            SoftkeyLevel::Files => Text::new(
                "Datei: importieren, herunterladen, Link teilen",
                "File: import, download, share a link",
            ),
        }
    }
}

impl AppState {
    /// What survives a reload.
    #[must_use]
    pub fn saved(&self) -> Saved {
        Saved {
            version: persist::VERSION,
            cursor: self.cursor,
            machine: self.machine.as_ref().map_or_else(|| DEFAULT_MACHINE.to_owned(), |m| m.id.clone()),
            lang: self.lang,
            projector: self.projector,
        }
    }

    /// The state at start-up from the saved state JSON and program text: a share link wins over
    /// them; a saved state that cannot be used is reported in the dialog line and replaced by
    /// the default.
    #[must_use]
    pub fn start(saved: Option<&str>, program: Option<String>, fragment: Option<&str>) -> AppState {
        let mut state = AppState::default();
        // The program is what the trainee typed: it is kept even when the small state beside
        // it cannot be read.
        let own_work = program.is_some();
        if let Some(text) = program {
            state.doc = Rc::new(Document::new(text));
        }
        match saved.map(persist::restore) {
            None => {}
            Some(Ok(s)) => {
                state.lang = s.lang;
                state.projector = s.projector;
                state.cursor = s.cursor.min(state.doc.last_index());
                state.select_machine(&s.machine);
            }
            Some(Err(e)) => state.message = Some(e.message()),
        }
        if fragment.is_some() {
            // Read once: a reload must not apply the link again over what was done since.
            state.emit(Effect::ConsumeFragment);
        }
        let shared = fragment.and_then(persist::parse_fragment);
        let run = shared.as_ref().is_some_and(|s| s.run);
        if let Some(shared) = shared {
            // Over the trainee's own, different program the link opens as a preview.
            if own_work && state.doc.text != shared.program {
                state.link = Some(LinkPreview {
                    own: state.doc.clone(),
                    own_cursor: state.cursor,
                    own_machine: state.machine.clone(),
                });
            }
            state.doc = Rc::new(Document::new(shared.program));
            state.cursor = shared.block.min(state.doc.last_index());
            if let Some(m) = shared.machine {
                state.select_machine(&m);
            }
            state.message = Some(match state.link {
                Some(_) => Text::new(
                    "Programm aus dem Link (Vorschau): übernehmen? Ihr eigenes Programm bleibt bis dahin gespeichert",
                    "Program from the link (preview): take it? Your own program stays saved until then",
                ),
                None => Text::new("Programm aus dem Link geöffnet", "Program opened from the link"),
            });
        }
        // The default's simulation is of the default program: simulate what was restored.
        state = state.simulated();
        if run {
            state.start_run();
        }
        state
    }

    /// A lesson's trainer: its own program and machine, the cursor on the first PLANE block,
    /// in projector mode in the instructor view (`classroom`); nothing of the trainee's saved
    /// work is read or written.
    #[must_use]
    pub fn embedded(program: &str, machine: &str, lang: Lang, classroom: bool) -> AppState {
        let mut state = AppState { lang, projector: classroom, ..AppState::default() };
        state.doc = Rc::new(Document::new(program.to_owned()));
        state.cursor =
            state.doc.program.blocks.iter().position(|b| matches!(b.body, BlockBody::Plane(_))).unwrap_or(0);
        state.select_machine(machine);
        state.simulated()
    }

    /// The cursor block's text when it is a PLANE block (the course takes it as an answer).
    #[must_use]
    pub fn cursor_plane_text(&self) -> Option<String> {
        let block = self.doc.program.blocks.get(self.cursor)?;
        matches!(block.body, BlockBody::Plane(_))
            .then(|| self.doc.text.get(block.span.start..block.span.end))?
            .map(str::to_owned)
    }

    /// The share link's fragment for the current program, block and machine.
    #[must_use]
    pub fn share_fragment(&self) -> String {
        persist::share_fragment(&Shared {
            program: self.doc.text.clone(),
            block: self.cursor,
            machine: self.machine.as_ref().map(|m| m.id.clone()),
            run: self.run.is_some(),
        })
    }

    /// File name for the download: the program's name from `BEGIN PGM`.
    #[must_use]
    pub fn file_name(&self) -> String {
        let name = self.doc.program.blocks.iter().find_map(|b| match &b.body {
            BlockBody::BeginPgm { name, .. } => Some(name.as_str()),
            _ => None,
        });
        format!("{}.h", name.unwrap_or("PGM"))
    }
}

impl Reducible for AppState {
    type Action = Action;

    fn reduce(self: Rc<Self>, action: Action) -> Rc<Self> {
        Rc::new(self.apply(action))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialog::PosKind;

    fn keys(mut s: AppState, text: &str) -> AppState {
        for c in text.chars() {
            s = s.apply(Action::DialogKey(Key::Char(c)));
        }
        s.apply(Action::DialogKey(Key::Ent))
    }

    #[test]
    fn spatial_dialog_inserts_the_block_after_the_cursor_with_the_next_number() {
        let mut s = AppState::default()
            .apply(Action::SetText("0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91\n2 END PGM T MM\n".into()));
        s = s.apply(Action::CursorTo(1));
        s = s.apply(Action::SpecFct).apply(Action::TiltPlane).apply(Action::Function(Function::Spatial));
        s = keys(keys(keys(s, "0"), "15"), "0");
        s = s.apply(Action::DialogKey(Key::Positioning(PosKind::Turn)));
        s = s.apply(Action::DialogKey(Key::NoEnt)).apply(Action::DialogKey(Key::FMax));
        s = s.apply(Action::DialogKey(Key::NoEnt)).apply(Action::DialogKey(Key::NoEnt));
        assert!(s.dialog.is_none());
        assert_eq!(
            s.doc.text,
            "0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91\n2 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n3 END PGM T MM\n"
        );
        assert_eq!(s.cursor, 2);
        assert!(s.doc.diagnostics.is_empty());
    }

    #[test]
    fn abort_keeps_the_program_and_ent_reopens_a_plane_block() {
        let s = AppState::default();
        let before = s.doc.text.clone();
        let s = s.apply(Action::Function(Function::Euler));
        let s = keys(s, "45").apply(Action::Abort);
        assert!(s.dialog.is_none());
        assert_eq!(s.doc.text, before);
        // Musterprogramm 1, block 10 is the PLANE SPATIAL block.
        let s = s.apply(Action::CursorTo(10)).apply(Action::Open);
        let (d, editing) = s.dialog.as_ref().expect("dialog reopened");
        assert_eq!((d.function, *editing), (Function::Spatial, Some(10)));
        let s = s.apply(Action::CursorTo(9));
        assert_eq!(s.cursor, 10, "the cursor stays while the dialog is open");
        let s = s.apply(Action::Abort).apply(Action::CursorTo(9)).apply(Action::Open);
        assert!(s.dialog.is_none());
        assert!(s.message.is_some(), "ENT on a non-PLANE block says why nothing opens");
    }

    #[test]
    fn samples_select_their_machine_and_unknown_ids_are_reported() {
        let s = AppState::default().apply(Action::LoadSample("winkel_nicht_erlaubt".into()));
        assert_eq!(s.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));
        let t = s.apply(Action::SelectMachine("no-such".into()));
        assert_eq!(t.machine, s.machine);
        assert!(t.message.is_some());
    }

    #[test]
    fn state_survives_a_reload_and_a_corrupt_one_falls_back_with_a_message() {
        let s = AppState::default()
            .apply(Action::LoadSample("stay_q120".into()))
            .apply(Action::CursorTo(7))
            .apply(Action::ToggleLang);
        let json = persist::to_json(&s.saved());
        let back = AppState::start(Some(&json), Some(s.doc.text.clone()), None);
        assert_eq!((back.doc.text.as_str(), back.cursor, back.lang), (s.doc.text.as_str(), 7, Lang::En));
        assert_eq!(back.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table"));
        assert_eq!(back.message, None);
        let sim = back.sim.as_ref().expect("simulated");
        assert_eq!(
            sim.0.first_step.len(),
            back.doc.program.blocks.len(),
            "the restored program is the one simulated"
        );

        let broken = AppState::start(Some("{\"version\":1,\"cursor\":"), Some("0 L X+1".into()), None);
        assert_eq!(broken.doc.text, "0 L X+1", "the program typed is kept");
        assert_eq!(
            broken.message.map(|m| m.en),
            Some("The saved state was corrupt: cursor, machine and language reset, program kept")
        );
    }

    #[test]
    fn share_link_opens_the_same_program_at_the_same_block_and_machine() {
        let s = AppState::default()
            .apply(Action::LoadSample("winkel_nicht_erlaubt".into()))
            .apply(Action::CursorTo(8));
        let opened = AppState::start(None, None, Some(&format!("#{}", s.share_fragment())));
        assert_eq!(opened.doc.text, s.doc.text);
        assert_eq!(opened.cursor, 8);
        assert_eq!(opened.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));
        assert_eq!(s.file_name(), "WINKEL.h");
        assert!(opened.run.is_none());
        let running = AppState::default().apply(Action::CursorTo(10)).apply(Action::StartRun);
        let opened = AppState::start(None, None, Some(&running.share_fragment()));
        let shown = opened.run.as_ref().and_then(|r| r.state.as_ref()).map(|s| s.block);
        assert_eq!(shown, Some(10), "the link opens the run at block 10");
    }

    #[test]
    fn run_steps_to_the_swivel_and_stops_on_the_refused_block() {
        let mut s = AppState::default().apply(Action::StartRun);
        assert_eq!(s.cursor, 0);
        while s.cursor < 10 {
            s = s.apply(Action::RunNext);
        }
        let shown = s.run.as_ref().and_then(|r| r.state.clone()).expect("state");
        let (axis, a) = shown.axes.named()[3];
        assert!(axis == 'A' && (a - 15.0).abs() < 1e-9, "{axis}{a}");
        assert_eq!(s.apply(Action::CursorTo(25)).cursor, 25, "a click jumps there");
        let s = s.apply(Action::Back);
        assert!(s.run.is_none());

        let mut s = AppState::default()
            .apply(Action::LoadSample("winkel_nicht_erlaubt".into()))
            .apply(Action::StartRun);
        s = s.apply(Action::RunPlay);
        for step in 0..20 {
            s = s.apply(Action::RunTick(s.run.as_ref().map_or(step, |r| r.step)));
        }
        let run = s.run.as_ref().expect("run");
        assert!(run.stopped_by_error && !run.playing);
        assert_eq!(s.cursor, 8, "the cursor stands on the refused block");
        assert_eq!(s.dialog_line(), "Winkel nicht erlaubt");
    }

    #[test]
    fn language_switch_changes_the_dialog_line_and_keeps_the_program() {
        let s = AppState::default().apply(Action::SpecFct);
        assert_eq!(s.dialog_text().get(s.lang), "Sonderfunktionen: Bereich wählen");
        let en = s.apply(Action::ToggleLang);
        assert_eq!(en.dialog_text().get(en.lang), "Special functions: select an area");
        assert_eq!(en.doc, s.doc);
    }

    #[test]
    fn a_link_over_own_work_is_a_preview_until_the_trainee_decides() {
        let own = "0 BEGIN PGM MEIN MM\n1 L Z+0 R0 FMAX M91\n2 END PGM MEIN MM\n".to_owned();
        let saved = persist::to_json(&AppState::default().saved());
        let link =
            AppState::default().apply(Action::LoadSample("winkel_nicht_erlaubt".into())).share_fragment();
        let s = AppState::start(Some(&saved), Some(own.clone()), Some(&link));
        assert!(s.link.is_some());
        assert_ne!(s.doc.text, own, "the link's program is shown");
        assert!(s.effects.list.contains(&Effect::ConsumeFragment), "the fragment is read once");
        assert!(s.dialog_text().de.contains("übernehmen?"));
        // Editing is held back; looking and running are not.
        let held = s.apply(Action::SetText("0 L X+1".into()));
        assert_eq!(held.doc, s.doc);
        assert!(held.message.is_some_and(|m| m.de.contains("LINK ÜBERNEHMEN")));
        assert!(s.apply(Action::StartRun).run.is_some());
        let kept = s.apply(Action::StartRun).apply(Action::KeepOwn);
        assert_eq!(
            (kept.doc.text.as_str(), kept.link.is_none(), kept.run.is_none()),
            (own.as_str(), true, true)
        );
        assert_eq!(kept.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table"));
        assert_eq!(kept.sim.as_ref().map(|s| s.0.first_step.len()), Some(3), "the own program is simulated");
        let taken = s.apply(Action::TakeLink);
        assert_eq!((taken.doc.text.as_str(), taken.link.is_none()), (s.doc.text.as_str(), true));
        assert_eq!(taken.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));

        // No own work, or the same program: nothing to ask.
        assert!(AppState::start(None, None, Some(&link)).link.is_none());
        let same = AppState::start(Some(&saved), Some(s.doc.text.clone()), Some(&link));
        assert!(same.link.is_none());
    }

    #[test]
    fn a_binary_file_is_not_imported_and_the_program_stays() {
        let s = AppState::default().apply(Action::ShowFiles);
        let png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0\0\0\x01\0".to_vec();
        let refused = s.apply(Action::Import(png));
        assert_eq!(refused.doc, s.doc);
        assert!(refused.message.is_some_and(|m| m.de.contains("kein NC-Programm")));
        let imported = s.apply(Action::Import(b"0 BEGIN PGM I MM\r\n1 END PGM I MM\r\n".to_vec()));
        assert_eq!(imported.doc.program.blocks.len(), 2);
        assert_eq!(imported.message.map(|m| m.en), Some("File imported"));
    }

    #[test]
    fn text_editing_asks_for_the_focus_in_the_editor() {
        let s = AppState::default().apply(Action::ToggleTextEditing);
        assert_eq!(&*s.effects.list, [Effect::FocusEditor]);
        assert!(s.apply(Action::ToggleTextEditing).effects.list.is_empty());
    }

    #[test]
    fn the_classroom_run_asks_before_a_swivel_and_reveals_on_nc_start() {
        let to_block_9 = |projector: bool| {
            let mut s = AppState { projector, ..AppState::default() }.apply(Action::StartRun);
            while s.cursor < 9 {
                s = s.apply(Action::RunNext);
            }
            s
        };
        // Musterprogramm 1, block 10: PLANE SPATIAL … TURN on the A/C table.
        let s = to_block_9(true).apply(Action::RunNext);
        let run = s.run.as_ref().expect("run");
        assert!(run.asking);
        assert_eq!(run.state.as_ref().map(|st| st.block), Some(9), "block 10 has not run yet");
        assert_eq!(
            s.dialog_line(),
            "Vorhersage: Wohin schwenkt der Tisch? Welche Werte haben A und C? NC-Start zeigt es."
        );
        let revealed = s.apply(Action::RunNext);
        let run = revealed.run.as_ref().expect("run");
        assert!(!run.asking);
        assert_eq!(run.state.as_ref().map(|st| st.block), Some(10), "NC start reveals block 10");
        // The other solution is there to be shown as the ghost.
        assert!(
            run.state
                .as_ref()
                .and_then(|st| st.explanation.as_ref())
                .is_some_and(|e| e.candidates.len() == 2)
        );
        // Outside the classroom the run does not stop to ask.
        let plain = to_block_9(false).apply(Action::RunNext);
        assert_eq!(plain.run.as_ref().and_then(|r| r.state.as_ref()).map(|st| st.block), Some(10));
        // In a full sequence the run stops at the question and NC start goes on after it.
        let mut playing = to_block_9(true).apply(Action::RunPlay);
        let step = playing.run.as_ref().map_or(0, |r| r.step);
        playing = playing.apply(Action::RunTick(step));
        let run = playing.run.as_ref().expect("run");
        assert!(run.asking && !run.playing);
        let on = playing.apply(Action::RunPlay);
        let run = on.run.as_ref().expect("run");
        assert!(run.playing && !run.asking);
        assert_eq!(run.state.as_ref().map(|st| st.block), Some(10));
    }
}
