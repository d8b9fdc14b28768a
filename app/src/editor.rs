//! The machine editor page (`maschine.html`): a form over a [`MachineDef`], every field kept as
//! typed, checked at every change by [`MachineDef::validate`] with each problem shown at its
//! field (matched by the issue's path, [`Field::path`]), a 3D preview of the last valid machine,
//! saving in the browser ([`crate::saved_machines`]), export and import of the same JSON as
//! `static/machines/*.json`. Pure, like the trainer's reducer; `schwenkbar-web` renders the rows
//! ([`rows`]) and carries out the effects.

use std::rc::Rc;

use schwenkbar_core::machine::{Machine, MachineDef, MachinePath};

use crate::effect::{Effect, Reducer};
use crate::i18n::{Lang, Text};
use crate::persist::{self, Prefs};
use crate::saved_machines::{self, MACHINES_KEY, MAX_SAVED};
use crate::tool_table::{ToolAction, ToolTableState};

mod form;
mod rows;
pub use form::{BodyForm, FieldIssue, Form, JointForm, check};
pub use rows::{Field, Row, SECTIONS, rows, section_title};

/// The shipped machine the editor opens when nothing else is asked for.
pub const DEFAULT_START: &str = "ac-table";

/// Files larger than this are not read: a machine description is about 1 KB.
pub const MAX_IMPORT_BYTES: usize = 256 * 1024;

/// The editor page's state.
#[derive(Debug, Clone, PartialEq)]
pub struct EditorState {
    pub prefs: Prefs,
    pub form: Form,
    /// The form's problems, at their fields ([`check`]).
    pub issues: Vec<FieldIssue>,
    /// The last valid machine: the 3D view shows it while the form has problems (`None` only
    /// before any form was valid, e.g. a broken file imported first).
    pub preview: Option<Rc<Machine>>,
    /// The form is a valid machine (the preview is it).
    pub valid: bool,
    /// The own machines saved in the browser.
    pub saved: Vec<Machine>,
    /// Why the last import was refused (the form stays as it was).
    pub import_issues: Vec<Text>,
    /// The line under the title: what the last action did.
    pub message: Option<Text>,
    /// The shop's tool table, beside the machine.
    pub tools: ToolTableState,
}

/// What the page can be asked to do.
#[derive(Debug, Clone, PartialEq)]
pub enum EditorAction {
    /// A field's new text.
    Set(Field, String),
    SetEndless(usize, bool),
    /// Start from a shipped machine (as a copy with an own id) or a saved one, by id.
    Open(String),
    /// Keep the machine in the browser (the trainer lists it).
    Save,
    /// Drop the saved machine with the form's id.
    Delete,
    /// A new collision body (a cube on the bed, [`BodyForm::new_body`]).
    AddBody,
    /// Drop collision body i.
    RemoveBody(usize),
    /// Offer the machine as a JSON file.
    Export,
    /// A file's bytes to import.
    Import(Vec<u8>),
    ToggleLang,
    /// An effect's outcome (a refused save).
    Notice(Text),
    /// The tool table's action.
    Tools(ToolAction),
}

impl EditorState {
    /// The status line: valid, or how many problems and what the preview shows meanwhile.
    #[must_use]
    pub fn status(&self) -> Text {
        if self.valid {
            Text::new("Maschine gültig", "Machine valid")
        } else {
            let n = self.issues.len();
            Text::owned(
                format!("{n} Fehler: die Vorschau zeigt den letzten gültigen Stand"),
                format!("{n} problem(s): the preview shows the last valid state"),
            )
        }
    }

    /// The page with the tool table kept under [`crate::tool_table::TOOLS_KEY`].
    #[must_use]
    pub fn with_tools(mut self, saved: Option<&str>) -> EditorState {
        self.tools = ToolTableState::start(saved);
        self
    }

    /// The page at load: the saved machines and preferences as stored, and the URL fragment
    /// (`#id`, from the trainer's EDITIEREN) naming the machine to start from.
    #[must_use]
    pub fn start(
        machines: Option<&str>,
        prefs: Option<&str>,
        fragment: Option<&str>,
    ) -> (EditorState, Vec<Effect>) {
        let (prefs, prefs_notice) = Prefs::load(prefs);
        let (saved, damaged) = machines.map(saved_machines::list_from_record).unwrap_or_default();
        let mut fx = Vec::new();
        if damaged.is_some() {
            fx.push(Effect::Save { key: MACHINES_KEY, value: saved_machines::list_to_record(&saved) });
        }
        let mut state = EditorState {
            prefs,
            form: Form::default(),
            issues: Vec::new(),
            preview: None,
            valid: false,
            saved,
            import_issues: Vec::new(),
            message: None,
            tools: ToolTableState::start(None),
        };
        let wanted = fragment
            .map(|f| f.trim_start_matches('#'))
            .filter(|f| !f.is_empty())
            .and_then(persist::percent_decode);
        let asked = wanted.as_deref().unwrap_or(DEFAULT_START);
        if !state.open(asked) {
            state.open(DEFAULT_START);
            state.message = Some(Text::owned(
                format!("Maschine „{asked}“ unbekannt: {DEFAULT_START} geöffnet"),
                format!("Unknown machine \"{asked}\": {DEFAULT_START} opened"),
            ));
        }
        state.message = damaged.or(prefs_notice).or(state.message);
        (state, fx)
    }

    #[must_use]
    pub fn lang(&self) -> Lang {
        self.prefs.lang
    }

    /// The messages at a row's path.
    pub fn issues_at(&self, path: MachinePath) -> impl Iterator<Item = &FieldIssue> + '_ {
        self.issues.iter().filter(move |i| i.path == path)
    }

    /// Issues whose path no row shows (the page lists them at the top).
    #[must_use]
    pub fn unplaced(&self) -> Vec<&FieldIssue> {
        let paths: Vec<MachinePath> = rows(&self.form).iter().map(Row::path).collect();
        self.issues.iter().filter(|i| !paths.contains(&i.path)).collect()
    }

    /// Opens a machine by id: a saved one as it is, a shipped one as a copy with an own id.
    fn open(&mut self, id: &str) -> bool {
        let machine = self.saved.iter().find(|m| m.id == id).cloned().or_else(|| copy_of_shipped(id));
        let Some(machine) = machine else { return false };
        let Some(form) = Form::of(&machine.to_def()) else { return false };
        self.form = form;
        self.import_issues.clear();
        self.recheck();
        true
    }

    fn recheck(&mut self) {
        let (machine, issues) = check(&self.form);
        self.issues = issues;
        self.valid = machine.is_some();
        if let Some(m) = machine {
            self.preview = Some(Rc::new(m));
        }
    }

    fn import(&mut self, bytes: &[u8]) {
        self.import_issues.clear();
        if bytes.len() > MAX_IMPORT_BYTES {
            self.import_issues.push(Text::owned(
                format!("Datei zu groß ({} KB): eine Maschinendatei hat etwa 1 KB", bytes.len() / 1024),
                format!("File too large ({} KB): a machine file is about 1 KB", bytes.len() / 1024),
            ));
            return;
        }
        let Ok(json) = std::str::from_utf8(bytes) else {
            self.import_issues.push(Text::new("Datei ist kein UTF-8-Text", "The file is not UTF-8 text"));
            return;
        };
        let def = match MachineDef::from_json(json) {
            Ok(def) => def,
            Err(issue) => {
                self.import_issues.push(issue.message());
                return;
            }
        };
        let Some(form) = Form::of(&def) else {
            let n = def.chain.len();
            self.import_issues.push(Text::owned(
                format!("chain: {n} Drehachsen, der Editor bearbeitet Maschinen mit genau 2"),
                format!("chain: {n} rotary axes, the editor edits machines with exactly 2"),
            ));
            return;
        };
        self.form = form;
        self.recheck();
        self.message = Some(if self.valid {
            Text::new("Maschinendatei importiert", "Machine file imported")
        } else {
            Text::new(
                "Maschinendatei importiert: Fehler an den Feldern beheben",
                "Machine file imported: fix the problems at the fields",
            )
        });
    }

    fn not_valid(&self, what: (&str, &str)) -> Text {
        let n = self.issues.len();
        Text::owned(
            format!("{}: {n} Fehler in der Maschine beheben", what.0),
            format!("{}: fix {n} problem(s) of the machine", what.1),
        )
    }

    fn save(&mut self, fx: &mut Vec<Effect>) {
        let Some(machine) = self.preview.as_deref().filter(|_| self.valid).cloned() else {
            self.message = Some(self.not_valid(("Nicht gespeichert", "Not saved")));
            return;
        };
        match self.saved.iter().position(|m| m.id == machine.id) {
            Some(i) => self.saved[i] = machine,
            None if self.saved.len() >= MAX_SAVED => {
                self.message = Some(Text::owned(
                    format!("Nicht gespeichert: höchstens {MAX_SAVED} eigene Maschinen, erst eine löschen"),
                    format!("Not saved: at most {MAX_SAVED} own machines, delete one first"),
                ));
                return;
            }
            None => self.saved.push(machine),
        }
        fx.push(Effect::Save { key: MACHINES_KEY, value: saved_machines::list_to_record(&self.saved) });
        self.message = Some(Text::new(
            "Gespeichert: im Trainer unter MASCHINE WÄHLEN → EIGENE MASCHINEN",
            "Saved: in the trainer under SELECT MACHINE → OWN MACHINES",
        ));
    }
}

/// A shipped machine as the start of an own one: its id and names marked as a copy.
fn copy_of_shipped(id: &str) -> Option<Machine> {
    let mut m = Machine::builtin(id).ok()?;
    m.id = format!("{id}-eigen");
    m.name = Text::owned(format!("{} (eigene)", m.name.de), format!("{} (own)", m.name.en));
    Some(m)
}

impl Reducer for EditorState {
    type Action = EditorAction;

    fn apply(&self, action: EditorAction) -> (EditorState, Vec<Effect>) {
        let mut next = self.clone();
        let mut fx = Vec::new();
        match action {
            EditorAction::Set(Field::BodyShape(i), value) => {
                if let Some(b) = next.form.collision.get_mut(i) {
                    b.switch_to(value == "cylinder");
                }
                next.recheck();
            }
            EditorAction::Set(field, value) => {
                if let Some(slot) = next.form.slot(field) {
                    *slot = value;
                }
                next.recheck();
            }
            EditorAction::SetEndless(i, on) => {
                if let Some(j) = next.form.joints.get_mut(i) {
                    j.endless = on;
                }
                next.recheck();
            }
            EditorAction::Open(id) => {
                if next.open(&id) {
                    next.message = None;
                }
            }
            EditorAction::AddBody => {
                let n = next.form.collision.len() + 1;
                next.form.collision.push(BodyForm::new_body(n));
                next.recheck();
            }
            EditorAction::RemoveBody(i) => {
                if i < next.form.collision.len() {
                    next.form.collision.remove(i);
                    next.recheck();
                }
            }
            EditorAction::Save => next.save(&mut fx),
            EditorAction::Delete => {
                let id = next.form.id.trim().to_owned();
                let before = next.saved.len();
                next.saved.retain(|m| m.id != id);
                next.message = Some(if next.saved.len() < before {
                    fx.push(Effect::Save {
                        key: MACHINES_KEY,
                        value: saved_machines::list_to_record(&next.saved),
                    });
                    Text::owned(format!("„{id}“ gelöscht"), format!("\"{id}\" deleted"))
                } else {
                    Text::owned(format!("„{id}“ ist nicht gespeichert"), format!("\"{id}\" is not saved"))
                });
            }
            EditorAction::Export => {
                if let Some(m) = next.preview.as_ref().filter(|_| next.valid) {
                    fx.push(Effect::SaveFile { name: format!("{}.json", m.id), text: m.to_json() });
                } else {
                    next.message = Some(next.not_valid(("Nicht exportiert", "Not exported")));
                }
            }
            EditorAction::Import(bytes) => next.import(&bytes),
            EditorAction::ToggleLang => {
                next.prefs.lang = next.prefs.lang.other();
                fx.push(Effect::Save { key: persist::PREFS_KEY, value: next.prefs.to_record() });
            }
            EditorAction::Notice(text) => next.message = Some(text),
            EditorAction::Tools(a) => {
                let (tools, more) = next.tools.apply(a);
                next.tools = tools;
                fx.extend(more);
            }
        }
        (next, fx)
    }
}
