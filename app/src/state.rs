//! All UI state in one reducer (yew `Reducible`), pure and tested natively.
//!
//! The softkey row works like the control's: a key such as `SPEC FCT` replaces the row with the
//! softkeys of that area, `END`/the back softkey returns one level; a PLANE function opens the
//! dialog ([`crate::dialog`]), whose finished block is inserted after the cursor.

use std::rc::Rc;
use std::sync::Arc;

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::tools::ToolEntry;
use schwenkbar_core::{BlockBody, edit};

use crate::dialog::{Dialog, Key, Outcome};
use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::persist;
use crate::run::{Run, SPEEDS, SimRef};
use crate::samples;
use crate::stock::StockRef;

mod action;
mod history;
mod replace;
mod run_mode;
mod start;
#[cfg(test)]
mod tests;

/// One transition with its effects dropped, for tests that follow the state (the effects are
/// tested on their own).
#[cfg(test)]
pub(crate) trait Then {
    fn then(&self, action: Action) -> AppState;
}

#[cfg(test)]
impl Then for AppState {
    fn then(&self, action: Action) -> AppState {
        self.apply(action).0
    }
}

pub use crate::effect::{Effect, Reducer};
pub use action::Action;
use history::Change;
pub use history::History;
pub use replace::{MachineOffer, Replacement};
use run_mode::next_or_ask;
pub use start::LinkPreview;

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
    /// The own machines made in the machine editor.
    OwnMachines,
    /// Sample programs to open.
    Samples,
    /// Import, download, share link.
    Files,
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
    /// The own machines saved by the machine editor (and one a share link brought), listed
    /// beside the shipped ones.
    pub own_machines: Rc<[Machine]>,
    /// A message in the dialog line outside a dialog (e.g. why a key did nothing).
    pub message: Option<Text>,
    /// Free text editing of the whole program.
    pub text_editing: bool,
    /// The program simulated on the machine (recomputed when either changes).
    pub sim: Option<SimRef>,
    /// The trainer's own start shows its first screen before it simulates (the simulator's code
    /// is loaded after the first screen, `scripts/split_pages.py`): `sim` is made by
    /// [`Action::Simulate`], or before any other action.
    pub sim_pending: bool,
    /// Program run mode, when active.
    pub run: Option<Run>,
    /// The right-hand-rule demonstration in place of the machine view.
    pub right_hand: bool,
    /// A share link shown as a preview: "Übernehmen?".
    pub link: Option<LinkPreview>,
    /// A lesson's trainer: nothing is saved, the cursor's PLANE block is told to the course.
    pub embedded: bool,
    /// The ROHTEIL switch: the 3D view draws the stock (the blank as the run has cut it).
    pub stock_shown: bool,
    /// The cut stock of `sim`: made after a program run starts ([`Effect::BuildStock`]), shown
    /// or not (its collisions with the material are said either way), never while typing;
    /// dropped when the simulation changes.
    pub stock: Option<StockRef>,
    /// The programs before the shown one (RÜCKGÄNGIG, Ctrl+Z) and after it (Ctrl+Y).
    pub history: History,
    /// The program has edits made here that were never exported (downloaded or shared): a
    /// sample or an import over it asks first.
    pub unexported: bool,
    /// A sample or an imported file waiting for "replace the own program?".
    pub replace: Option<Replacement>,
    /// An imported program moves rotary axes the machine does not have: the shipped machine
    /// that has them, offered (F1 takes it, F2 or END keeps the machine).
    pub machine_offer: Option<MachineOffer>,
    /// The shop's tool table (from the machine editor page, or a share link for this visit);
    /// `None`: the shipped one.
    pub tools: Option<Arc<[ToolEntry]>>,
}

/// What an action does to the program, for the history and the "unexported" mark.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ProgramChange {
    /// An edit of the trainee's: a step back is kept.
    Edit(Change),
    /// A new program (sample, import, link): its own code keeps the replaced one.
    Fresh,
    /// Undo, redo, the own program back from a link preview.
    Travel,
    /// Anything else.
    Aside,
}

impl Default for AppState {
    fn default() -> Self {
        AppState::unsimulated().simulated(None)
    }
}

impl AppState {
    /// The default state before its simulation.
    fn unsimulated() -> AppState {
        AppState {
            lang: Lang::default(),
            projector: false,
            level: SoftkeyLevel::Main,
            dialog: None,
            doc: Rc::new(Document::new(samples::DEFAULT.text.to_owned())),
            cursor: 0,
            machine: Machine::builtin(DEFAULT_MACHINE).ok().map(Rc::new),
            own_machines: Rc::from([]),
            message: None,
            text_editing: false,
            sim: None,
            sim_pending: false,
            run: None,
            right_hand: false,
            link: None,
            embedded: false,
            // On: a trainee sees the part being made without asking (issue 32); the first pass
            // and the view's cuts go on in bounded shares, so no frame waits for them.
            stock_shown: true,
            stock: None,
            history: History::default(),
            unexported: false,
            replace: None,
            machine_offer: None,
            tools: None,
        }
    }
}

/// The seed's first example machine.
pub const DEFAULT_MACHINE: &str = "ac-table";

/// The machine editor's page (its own bundle, beside `index.html`).
pub const EDITOR_PAGE: &str = "maschine.html";

impl Reducer for AppState {
    type Action = Action;

    /// The pure transition: the next state and the side effects it asks for (saving what
    /// changed, downloads, the Satzfolge timer, …), which the web shell carries out.
    fn apply(&self, action: Action) -> (AppState, Vec<Effect>) {
        let mut effects = Vec::new();
        let next = match (action, self.sim_pending) {
            // Keeps the start's message (a link opened, a damaged record) and comes in a link
            // preview or a question as well.
            (Action::Simulate, true) => self.clone().simulated(None),
            (Action::Simulate, false) => self.clone(),
            // Whatever a key does, it does on the simulated program.
            (action, true) => self.clone().simulated(None).transition(action, &mut effects),
            (action, false) => self.transition(action, &mut effects),
        };
        next.follow_ups(Some(self), &mut effects);
        (next, effects)
    }
}

impl AppState {
    fn transition(&self, action: Action, fx: &mut Vec<Effect>) -> AppState {
        let mut next = self.clone();
        // After a text edit: the blocks that may differ (the others are the old ones).
        let mut changed = None;
        next.message = None;
        if self.link.is_some() && !action.allowed_in_link_preview() {
            next.message = Some(Text::new(
                "Zuerst entscheiden: LINK ÜBERNEHMEN oder EIGENES BEHALTEN",
                "Decide first: TAKE LINK or KEEP MINE",
            ));
            return next;
        }
        if let Some(r) = self.replace.as_ref().filter(|_| !action.allowed_while_asked()) {
            next.message = Some(r.question());
            return next;
        }
        let change = self.change_of(&action);
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
            Action::Back | Action::KeepMachine if self.machine_offer.is_some() => {
                next.machine_offer = None;
                next.message = Some(Text::new("Maschine behalten", "Machine kept"));
            }
            Action::KeepMachine => {}
            Action::TakeMachineOffer => {
                if let Some(offer) = next.machine_offer.take() {
                    next.select_machine(offer.id);
                }
            }
            Action::Back if self.replace.is_some() => {
                next.replace = None;
                next.message = Some(Text::new("Eigenes Programm behalten", "Own program kept"));
            }
            Action::Back if self.run.is_some() => next.run = None,
            Action::Back => {
                if next.dialog.take().is_none() {
                    next.level = match self.level {
                        SoftkeyLevel::TiltPlane => SoftkeyLevel::SpecFct,
                        SoftkeyLevel::OwnMachines => SoftkeyLevel::Machines,
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
                let (doc, blocks) = self.doc.edited(text);
                next.doc = Rc::new(doc);
                changed = Some(blocks);
                next.cursor = self.cursor.min(next.doc.last_index());
            }
            Action::EditText { at, text } => match self.doc.replaced(at, &text) {
                Some((doc, blocks)) => {
                    next.doc = Rc::new(doc);
                    changed = Some(blocks);
                    next.cursor = self.cursor.min(next.doc.last_index());
                }
                // The editor's window is made from this document, so this cannot happen; if
                // it does, the typing is said lost rather than put in the wrong place.
                None => {
                    next.message = Some(Text::new("Eingabe nicht übernommen", "Input not taken"));
                }
            },
            Action::ToggleTextEditing => {
                next.text_editing = !self.text_editing;
                if next.text_editing {
                    fx.push(Effect::FocusEditor);
                }
            }
            Action::ShowMachines => next.level = SoftkeyLevel::Machines,
            Action::ShowOwnMachines => next.level = SoftkeyLevel::OwnMachines,
            Action::EditMachine => {
                let id = self.machine.as_ref().map_or(DEFAULT_MACHINE, |m| m.id.as_str());
                fx.push(Effect::OpenPage { url: format!("{EDITOR_PAGE}#{}", persist::percent_encode(id)) });
            }
            Action::SelectMachine(id) => next.select_machine(&id),
            Action::ShowSamples => next.level = SoftkeyLevel::Samples,
            Action::LoadSample(id) => match samples::by_id(&id) {
                Some(sample) => next.replace_with(
                    Replacement {
                        doc: Rc::new(Document::new(sample.text.to_owned())),
                        machine: Some(sample.machine),
                        what: sample.title.clone(),
                    },
                    fx,
                ),
                None => next.message = Some(Text::new("Beispiel unbekannt", "Unknown sample")),
            },
            Action::ShowFiles => next.level = SoftkeyLevel::Files,
            Action::PickFile => fx.push(Effect::PickFile),
            Action::Import(bytes) => next.import(bytes, fx),
            Action::Download => {
                next.unexported = false;
                fx.push(Effect::Download { name: self.file_name(), text: self.doc.text.clone() })
            }
            Action::Share => {
                next.unexported = false;
                fx.push(Effect::Share { fragment: self.share_fragment() })
            }
            Action::TakeLink => {
                if let Some(own) = next.link.take() {
                    next.keep_replaced(&own.own, fx);
                    next.history.record(own.own, Change::Whole);
                    next.unexported = false;
                }
                next.message = Some(Text::new(
                    "Programm aus dem Link übernommen – Ihr bisheriges: RÜCKGÄNGIG (Strg+Z)",
                    "Program from the link taken – your previous one: UNDO (Ctrl+Z)",
                ));
            }
            Action::KeepOwn if self.replace.is_some() => {
                next.replace = None;
                next.message = Some(Text::new("Eigenes Programm behalten", "Own program kept"));
            }
            Action::ConfirmReplace => {
                if let Some(r) = next.replace.take() {
                    next.replace_now(r, fx);
                }
            }
            Action::Undo | Action::Redo => next.travel(action == Action::Undo),
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
                    next_or_ask(run, sim, p, classroom);
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
                        next_or_ask(run, sim, p, classroom);
                        run.playing &= !run.asking;
                    }
                });
            }
            Action::RunFaster => next.run_step(|run, _, _| run.speed = (run.speed + 1).min(SPEEDS.len() - 1)),
            Action::RunSlower => next.run_step(|run, _, _| run.speed = run.speed.saturating_sub(1)),
            // Done by `apply`, before any transition.
            Action::Simulate => {}
            Action::ToggleRightHand => next.right_hand = !self.right_hand,
            Action::ToggleLang => next.lang = self.lang.other(),
            Action::ToggleProjector => next.projector = !self.projector,
            Action::ToggleStock => next.stock_shown = !self.stock_shown,
            Action::BuildStock => {
                if let Some(sim) = self.sim.as_ref().filter(|_| self.wants_stock()) {
                    next.stock = Some(StockRef::of(sim, &self.doc));
                    fx.push(Effect::PassStock);
                }
            }
            // The stock is shared (`Rc`): its pass goes on in place, and the render that
            // follows shows the notes it found.
            Action::PassStock => {
                if let Some(stock) = &self.stock
                    && !stock.pass_on(crate::stock::PASS_RAYS)
                {
                    fx.push(Effect::PassStock);
                }
            }
        }
        if !Rc::ptr_eq(&self.doc, &next.doc) {
            match change {
                ProgramChange::Edit(kind) => {
                    next.history.record(self.doc.clone(), kind);
                    next.unexported = true;
                }
                ProgramChange::Fresh | ProgramChange::Travel | ProgramChange::Aside => {}
            }
        } else if change == ProgramChange::Aside {
            // Another key between two runs of typing: the next typed edit is a step of its own.
            next.history.break_typing();
        }
        let machine_changed = match (&self.machine, &next.machine) {
            (Some(a), Some(b)) => !Rc::ptr_eq(a, b),
            (a, b) => a.is_some() != b.is_some(),
        };
        if !Rc::ptr_eq(&self.doc, &next.doc) || machine_changed {
            next = next.simulated(changed.filter(|_| !machine_changed));
        }
        next
    }

    /// Re-runs the simulation (after the program or the machine changed; after a text edit
    /// that kept the blocks outside `changed`, from the checkpoint before the first step that
    /// reaches a changed block) and keeps an open run at the same step where it still exists.
    #[must_use]
    fn simulated(mut self, changed: Option<std::ops::Range<usize>>) -> AppState {
        self.sim_pending = false;
        let resumed = changed.zip(self.sim.as_ref()).map(|(c, sim)| sim.resumed(&self.doc.program, c));
        self.sim = resumed.or_else(|| {
            self.machine.as_ref().map(|m| SimRef::with_tools(&self.doc.program, m, self.tools.clone()))
        });
        self.stock = None;
        match (&self.sim, self.run.as_mut()) {
            (Some(sim), Some(run)) => run.go_to(&sim.0, &self.doc.program, run.step),
            (None, Some(_)) => self.run = None,
            _ => {}
        }
        self.sync_cursor_to_run();
        self
    }

    /// One step back (`back`) or forward in the program's history.
    fn travel(&mut self, back: bool) {
        let current = self.doc.clone();
        let to = if back { self.history.undo(current) } else { self.history.redo(current) };
        match to {
            Some(doc) => {
                self.doc = doc;
                self.unexported = true;
                self.cursor = self.cursor.min(self.doc.last_index());
                self.run = None;
                self.dialog = None;
                self.message = Some(if back {
                    Text::new("Änderung rückgängig gemacht", "Change undone")
                } else {
                    Text::new("Änderung wiederhergestellt", "Change redone")
                });
            }
            None => {
                self.message = Some(if back {
                    Text::new("Nichts rückgängig zu machen", "Nothing to undo")
                } else {
                    Text::new("Nichts wiederherzustellen", "Nothing to redo")
                });
            }
        }
    }

    /// How `action` would change the program, for the history.
    fn change_of(&self, action: &Action) -> ProgramChange {
        let breaks = |old: &str, new: &str| old.matches('\n').count() != new.matches('\n').count();
        match action {
            Action::SetText(text) => {
                ProgramChange::Edit(Change::Typing { new_line: breaks(&self.doc.text, text) })
            }
            Action::EditText { at, text } => {
                let old = self.doc.text.get(at.clone()).unwrap_or_default();
                ProgramChange::Edit(Change::Typing { new_line: breaks(old, text) })
            }
            Action::LoadSample(_) | Action::Import(_) | Action::ConfirmReplace | Action::TakeLink => {
                ProgramChange::Fresh
            }
            Action::Undo | Action::Redo | Action::KeepOwn => ProgramChange::Travel,
            Action::DialogKey(_) => ProgramChange::Edit(Change::Whole),
            _ => ProgramChange::Aside,
        }
    }

    fn select_machine(&mut self, id: &str) {
        self.machine_offer = None;
        let own = || self.own_machines.iter().find(|m| m.id == id).cloned().ok_or(());
        match Machine::builtin(id).or_else(|_| own()) {
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
        match self.doc.program.blocks.get(self.cursor).and_then(schwenkbar_core::Block::stored_body) {
            Some(BlockBody::Plane(plane)) => self.dialog = Some((Dialog::reopen(plane), Some(self.cursor))),
            _ => {
                self.message = Some(Text::new(
                    "Nur PLANE-Sätze lassen sich im Dialog öffnen",
                    "Only PLANE blocks open in the dialog",
                ))
            }
        }
    }

    /// Whether the stock is to be cut: in a program run, not yet made for this simulation. It is
    /// cut with the ROHTEIL switch off too: a rapid or a swivel into the material is a collision
    /// to be said whether or not the part is drawn.
    #[must_use]
    pub fn wants_stock(&self) -> bool {
        self.run.is_some()
            && self.sim.as_ref().is_some_and(|sim| !self.stock.as_ref().is_some_and(|s| s.is_for(sim)))
    }

    /// The stock made for the current simulation, shown or not.
    fn run_stock(&self) -> Option<&StockRef> {
        let sim = self.sim.as_ref()?;
        self.stock.as_ref().filter(|s| s.is_for(sim))
    }

    /// The collision of the shown run step with the material (a rapid into it, a swivel with the
    /// tool in it), for the why panel; the dialog line says it too.
    #[must_use]
    pub fn material_note(&self) -> Option<Text> {
        let run = self.run.as_ref()?;
        self.run_stock()?.notes_at(run.step)
    }

    /// The stock to draw (switch on, made for the current simulation).
    #[must_use]
    pub fn shown_stock(&self) -> Option<StockRef> {
        self.run_stock().filter(|_| self.stock_shown).cloned()
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
            return e.message.get(self.lang).to_owned();
        }
        if let (Some(machine), true) = (&self.machine, self.run.as_ref().is_some_and(|r| r.asking)) {
            return self.prediction_question(machine);
        }
        self.dialog_text().get(self.lang).to_owned()
    }

    /// The dialog line: the open dialog's prompt or message, else what the control expects.
    #[must_use]
    pub fn dialog_text(&self) -> Text {
        if let Some((d, _)) = &self.dialog {
            return d.message.clone().unwrap_or_else(|| d.prompt());
        }
        if let Some(m) = &self.message {
            return m.clone();
        }
        if let Some(run) = &self.run {
            // The stock's note on the shown block (a collision with the material), drawn or not.
            if let Some(note) = self.material_note() {
                return note;
            }
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
            SoftkeyLevel::OwnMachines => Text::new(
                "Eigene Maschine wählen (im Maschinen-Editor gespeichert)",
                "Select an own machine (saved in the machine editor)",
            ),
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
