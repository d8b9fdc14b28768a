//! A program that replaces the shown one: a sample or an import, at once or asked over the
//! trainee's unexported work, the replaced one kept one undo step back; the machine offered for
//! an imported program.

use std::rc::Rc;

use schwenkbar_core::machine::Machine;

use super::{AppState, Change, Effect, SoftkeyLevel};
use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::persist;

/// The machine offered for an imported program ([`AppState::machine_offer`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MachineOffer {
    pub id: &'static str,
    /// The rotary axes the program moves, as letters (`B, C`).
    pub axes: String,
}

/// A program that would replace the trainee's unexported work, held until they answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Replacement {
    pub doc: Rc<Document>,
    /// A sample's machine.
    pub machine: Option<&'static str>,
    /// What it is, for the question and the message after.
    pub what: Text,
}

impl Replacement {
    /// The question in the dialog line.
    #[must_use]
    pub fn question(&self) -> Text {
        Text::owned(
            format!(
                "Ihr Programm hat Änderungen, die nicht exportiert wurden. Durch „{}“ ersetzen? F1 = ERSETZEN, F2/END = BEHALTEN",
                self.what.get(Lang::De)
            ),
            format!(
                "Your program has edits that were never exported. Replace it with “{}”? F1 = REPLACE, F2/END = KEEP",
                self.what.get(Lang::En)
            ),
        )
    }
}

impl AppState {
    /// IMPORT: a text file becomes the program; a binary file (an image, a CAD model, a zip)
    /// is refused and the program stays.
    pub(super) fn import(&mut self, bytes: Vec<u8>, fx: &mut Vec<Effect>) {
        if schwenkbar_core::text::looks_binary(&bytes) {
            self.message = Some(Text::new(
                "Datei ist kein NC-Programm (Binärdatei): nicht importiert",
                "The file is not an NC program (binary file): not imported",
            ));
            return;
        }
        self.level = SoftkeyLevel::Main;
        self.replace_with(
            Replacement {
                doc: Rc::new(Document::new(schwenkbar_core::text::decode(bytes))),
                machine: None,
                what: Text::new("Importierte Datei", "Imported file"),
            },
            fx,
        );
    }

    /// A sample or an import: at once over a program without unexported edits, else asked.
    pub(super) fn replace_with(&mut self, r: Replacement, fx: &mut Vec<Effect>) {
        if self.unexported && !self.embedded {
            self.message = Some(r.question());
            self.replace = Some(r);
        } else {
            self.replace_now(r, fx);
        }
    }

    /// The program becomes `r`'s; the one it replaces stays one undo step back (and in the
    /// browser, for an undo after a reload).
    pub(super) fn replace_now(&mut self, r: Replacement, fx: &mut Vec<Effect>) {
        let before = std::mem::replace(&mut self.doc, r.doc);
        self.keep_replaced(&before, fx);
        self.history.record(before, Change::Whole);
        self.unexported = false;
        self.cursor = 0;
        self.machine_offer = None;
        if let Some(m) = r.machine {
            self.select_machine(m);
        }
        self.message = Some(Text::owned(
            format!("{} geöffnet – Ihr bisheriges Programm: RÜCKGÄNGIG (Strg+Z)", r.what.get(Lang::De)),
            format!("{} opened – your previous program: UNDO (Ctrl+Z)", r.what.get(Lang::En)),
        ));
        if r.machine.is_none() {
            self.offer_machine();
        }
    }

    /// After an import: when the program moves a rotary axis the machine does not have, the
    /// first shipped machine that has every one it moves is offered (issue 31: one key to
    /// accept, the choice stays with the trainee).
    pub(super) fn offer_machine(&mut self) {
        let axes = schwenkbar_core::sim::programmed_rotary_axes(&self.doc.program);
        let has_all = |m: &Machine| axes.iter().all(|a| m.joints().iter().any(|j| j.axis == *a));
        if axes.is_empty() || self.machine.as_deref().is_some_and(has_all) {
            return;
        }
        let Some(id) =
            Machine::builtin_ids().into_iter().find(|id| Machine::builtin(id).is_ok_and(|m| has_all(&m)))
        else {
            return;
        };
        let letters = axes.iter().map(|a| a.letter().to_string()).collect::<Vec<_>>().join(", ");
        let name = Machine::builtin(id).map(|m| m.name).ok();
        let (de, en) = name.map_or((id.to_owned(), id.to_owned()), |n| (n.de.to_string(), n.en.to_string()));
        self.message = Some(Text::owned(
            format!(
                "Das Programm bewegt die Drehachsen {letters}, die Maschine hat sie nicht: „{de}“ übernehmen? F1 = ÜBERNEHMEN, F2/END = BEHALTEN"
            ),
            format!(
                "The program moves the rotary axes {letters}, which the machine lacks: take “{en}”? F1 = TAKE, F2/END = KEEP"
            ),
        ));
        self.machine_offer = Some(MachineOffer { id, axes: letters });
    }

    /// Keeps a replaced program in the browser beside the shown one (not a lesson's trainer).
    pub(super) fn keep_replaced(&self, before: &Document, fx: &mut Vec<Effect>) {
        if !self.embedded {
            fx.push(Effect::Save { key: persist::REPLACED_KEY, value: before.text.clone() });
        }
    }
}
