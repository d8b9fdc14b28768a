//! What the trainer opens with and what it keeps: the saved state and program, a share link
//! (over the trainee's own work only as a preview), a lesson's embedded trainer.

use std::rc::Rc;

use schwenkbar_core::BlockBody;
use schwenkbar_core::machine::Machine;

use super::{Action, AppState, DEFAULT_MACHINE, Effect};
use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::persist::{self, Saved, Shared};

/// A share link opened over the trainee's own program: the link's program is shown (and can be
/// run), the own one is kept aside and nothing is saved until the trainee decides.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkPreview {
    pub own: Rc<Document>,
    pub own_cursor: usize,
    pub own_machine: Option<Rc<Machine>>,
}

impl Action {
    /// While a share link is previewed: looking at it and running it is allowed, changing a
    /// program is not until the trainee took the link or kept the own program.
    pub(super) fn allowed_in_link_preview(&self) -> bool {
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
