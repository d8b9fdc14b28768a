//! What the trainer opens with and what it keeps: the saved state and program, a share link
//! (over the trainee's own work only as a preview), a lesson's embedded trainer.

use std::rc::Rc;

use schwenkbar_core::BlockBody;
use schwenkbar_core::machine::Machine;

use super::{AppState, DEFAULT_MACHINE, Effect};
use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::persist::{self, Prefs, Saved, Shared, Stored};
use crate::saved_machines;
use crate::tool_table;
use schwenkbar_core::sim::tools::write_tool_table;

/// A share link opened over the trainee's own program: the link's program is shown (and can be
/// run), the own one is kept aside and nothing is saved until the trainee decides.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkPreview {
    pub own: Rc<Document>,
    pub own_cursor: usize,
    pub own_machine: Option<Rc<Machine>>,
}

impl AppState {
    /// What survives a reload beside the program and the preferences.
    #[must_use]
    pub fn saved(&self) -> Saved {
        Saved {
            cursor: self.cursor,
            machine: self.machine.as_ref().map_or_else(|| DEFAULT_MACHINE.to_owned(), |m| m.id.clone()),
            unexported: self.unexported,
        }
    }

    /// The preferences the course page shares.
    #[must_use]
    pub fn prefs(&self) -> Prefs {
        Prefs { lang: self.lang, classroom: self.projector }
    }

    /// What to keep after a transition from `before` (`None`: at start-up): the program when
    /// its text changed, the small state and the preferences when they changed, nothing of a
    /// lesson's trainer (it tells the course its cursor's PLANE block instead) or while a share
    /// link is only previewed; and the Satzfolge timer when the shown step, playing or speed
    /// changed.
    pub(super) fn follow_ups(&self, before: Option<&AppState>, fx: &mut Vec<Effect>) {
        let doc_changed = before.is_none_or(|b| !Rc::ptr_eq(&b.doc, &self.doc));
        let link_closed = before.is_some_and(|b| b.link.is_some()) && self.link.is_none();
        if self.embedded {
            if doc_changed || before.is_some_and(|b| b.cursor != self.cursor) {
                fx.push(Effect::TellCourse(self.cursor_plane_text()));
            }
        } else if self.link.is_none() {
            if doc_changed || link_closed {
                fx.push(Effect::Save { key: persist::PROGRAM_KEY, value: self.doc.text.clone() });
            }
            let saved = self.saved();
            if link_closed || before.is_none_or(|b| b.saved() != saved) {
                fx.push(Effect::Save { key: persist::STATE_KEY, value: saved.to_record() });
            }
            let prefs = self.prefs();
            if link_closed || before.is_none_or(|b| b.prefs() != prefs) {
                fx.push(Effect::Save { key: persist::PREFS_KEY, value: prefs.to_record() });
            }
        }
        if self.wants_stock() && before.is_none_or(|b| !b.wants_stock() || b.sim != self.sim) {
            fx.push(Effect::BuildStock);
        }
        let tick = |s: &AppState| s.run.as_ref().map(|r| (r.step, r.playing, r.tick_ms()));
        if let Some((step, true, ms)) = tick(self)
            && before.is_none_or(|b| tick(b) != tick(self))
        {
            fx.push(Effect::Tick { step, ms });
        }
    }

    /// The state at start-up from the saved records and program text (see [`Stored`]): a share
    /// link wins over them; a saved record that cannot be used is reported in the dialog line
    /// and replaced by the default.
    #[must_use]
    pub fn start(stored: Stored, fragment: Option<&str>) -> (AppState, Vec<Effect>) {
        AppState::started(stored, fragment, false)
    }

    /// [`AppState::start`] without the simulation, which [`super::Action::Simulate`] (or any other
    /// action) makes ([`AppState::sim_pending`]): the trainer's first screen shows the program
    /// before the simulator's code has loaded. A share link that opens a run simulates at once.
    #[must_use]
    pub fn start_unsimulated(stored: Stored, fragment: Option<&str>) -> (AppState, Vec<Effect>) {
        AppState::started(stored, fragment, true)
    }

    fn started(stored: Stored, fragment: Option<&str>, lazily: bool) -> (AppState, Vec<Effect>) {
        let Stored { state: saved, prefs, program, machines, replaced, tools } = stored;
        let mut state = AppState::unsimulated();
        let (prefs, prefs_notice) = Prefs::load(prefs.as_deref());
        state.lang = prefs.lang;
        state.projector = prefs.classroom;
        state.message = prefs_notice;
        // The program is what the trainee typed: it is kept even when the small state beside
        // it cannot be read.
        let own_work = program.is_some();
        if let Some(text) = program {
            state.doc = Rc::new(Document::new(text));
        }
        // The program a sample, an import or a link last replaced: one undo step back.
        if let Some(text) = replaced {
            state.history = super::History::with(Rc::new(Document::new(text)));
        }
        let mut fx = Vec::new();
        if let Some(text) = machines {
            let (own, damaged) = saved_machines::list_from_record(&text);
            if let Some(why) = damaged {
                // Written back at once, so the damage is reported once.
                fx.push(Effect::Save {
                    key: saved_machines::MACHINES_KEY,
                    value: saved_machines::list_to_record(&own),
                });
                state.message = Some(why);
            }
            state.own_machines = own.into();
        }
        match tool_table::read_saved(tools.as_deref()) {
            Ok(t) => state.tools = t,
            // The text stays stored: the editor page shows the shipped table until one is kept.
            Err(why) => state.message = Some(why),
        }
        match saved.as_deref().map(Saved::from_record) {
            None => {}
            Some(Ok(s)) => {
                state.cursor = s.cursor.min(state.doc.last_index());
                state.select_machine(&s.machine);
                state.unexported = s.unexported && own_work;
            }
            Some(Err(e)) => state.message = Some(e.message()),
        }
        if fragment.is_some() {
            // Read once: a reload must not apply the link again over what was done since.
            fx.push(Effect::ConsumeFragment);
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
            // The sender's tool table, for this visit only (the own one stays stored).
            if let Some(text) = shared.tools.as_deref() {
                match tool_table::read_saved(Some(text)) {
                    Ok(t) => state.tools = t,
                    Err(_) => {
                        state.message = Some(Text::new(
                            "Werkzeugtabelle im Link beschädigt: die eigene gilt",
                            "The link's tool table is corrupt: the own one applies",
                        ));
                    }
                }
            }
            // An own machine travels whole; the receiver keeps it for this visit only.
            match shared.own_machine.as_deref().map(saved_machines::from_record) {
                Some(Ok(m)) => {
                    let id = m.id.clone();
                    let mut own: Vec<Machine> =
                        state.own_machines.iter().filter(|o| o.id != id).cloned().collect();
                    own.push(m);
                    state.own_machines = own.into();
                    state.select_machine(&id);
                }
                Some(Err(_)) => {
                    state.message = Some(Text::new(
                        "Maschine im Link beschädigt: Standardmaschine gewählt",
                        "The link's machine is corrupt: the default machine chosen",
                    ));
                }
                None => {
                    if let Some(m) = shared.machine {
                        state.select_machine(&m);
                    }
                }
            }
            state.message = Some(match state.link {
                Some(_) => Text::new(
                    "Programm aus dem Link (Vorschau): übernehmen? Ihr eigenes Programm bleibt bis dahin gespeichert",
                    "Program from the link (preview): take it? Your own program stays saved until then",
                ),
                None => Text::new("Programm aus dem Link geöffnet", "Program opened from the link"),
            });
        }
        if run || !lazily {
            state = state.simulated(None);
        }
        if run {
            state.start_run();
            // A link that runs into the control's stop shows the stop's message, not "opened"
            // (a preview over the trainee's own program keeps its question).
            if state.link.is_none() && state.run.as_ref().is_some_and(|r| r.stopped_by_error) {
                state.message = None;
            }
        }
        state.sim_pending = state.sim.is_none();
        if state.sim_pending {
            fx.push(Effect::Simulate);
        }
        state.follow_ups(None, &mut fx);
        (state, fx)
    }

    /// A lesson's trainer: its own program and machine, the cursor on the first PLANE block,
    /// in projector mode in the instructor view (`classroom`); nothing of the trainee's saved
    /// work is read or written. Simulated lazily like the trainer's start
    /// ([`AppState::start_unsimulated`]): every lesson is a deep link, and its first screen
    /// shows the program before the simulator's code has loaded.
    #[must_use]
    pub fn embedded(program: &str, machine: &str, lang: Lang, classroom: bool) -> (AppState, Vec<Effect>) {
        let mut state = AppState { lang, projector: classroom, embedded: true, ..AppState::unsimulated() };
        state.doc = Rc::new(Document::new(program.to_owned()));
        state.cursor = state
            .doc
            .program
            .blocks
            .iter()
            .position(|b| matches!(b.stored_body(), Some(BlockBody::Plane(_))))
            .unwrap_or(0);
        state.select_machine(machine);
        state.sim_pending = true;
        let mut fx = vec![Effect::Simulate];
        state.follow_ups(None, &mut fx);
        (state, fx)
    }

    /// The cursor block's text when it is a PLANE block (the course takes it as an answer).
    #[must_use]
    pub fn cursor_plane_text(&self) -> Option<String> {
        let block = self.doc.program.blocks.get(self.cursor)?;
        matches!(block.stored_body(), Some(BlockBody::Plane(_)))
            .then(|| self.doc.text.get(block.span().start..block.span().end))?
            .map(str::to_owned)
    }

    /// The share link's fragment for the current program, block and machine.
    #[must_use]
    pub fn share_fragment(&self) -> String {
        let own = self.machine.as_deref().filter(|m| !saved_machines::is_shipped(&m.id));
        persist::share_fragment(&Shared {
            program: self.doc.text.clone(),
            block: self.cursor,
            machine: self.machine.as_ref().map(|m| m.id.clone()),
            own_machine: own.map(saved_machines::to_record),
            run: self.run.is_some(),
            tools: self.tools.as_deref().map(write_tool_table),
        })
    }

    /// File name for the download: the program's name from `BEGIN PGM`.
    #[must_use]
    pub fn file_name(&self) -> String {
        let name = self.doc.program.blocks.iter().find_map(|b| match b.stored_body()? {
            BlockBody::BeginPgm { name, .. } => Some(name.as_str()),
            _ => None,
        });
        format!("{}.h", name.unwrap_or("PGM"))
    }
}
