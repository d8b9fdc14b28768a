//! What a key, a click or the shell asks of the trainer, and which of it a link preview or an
//! open question lets through.

use schwenkbar_core::plane::PlaneKind;

use crate::dialog::Key;
use crate::i18n::Text;

#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// The `SPEC FCT` key.
    SpecFct,
    /// Softkey `BEARB.-EBENE SCHWENKEN`.
    TiltPlane,
    /// A PLANE function softkey: opens its dialog.
    Function(PlaneKind),
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
    /// The text editor's window, bytes `at` of the program text, now reads `text`.
    EditText {
        at: std::ops::Range<usize>,
        text: String,
    },
    ToggleTextEditing,
    ShowMachines,
    /// MASCHINE WÄHLEN → EIGENE MASCHINEN.
    ShowOwnMachines,
    SelectMachine(String),
    /// MASCHINE WÄHLEN → EDITIEREN: the machine editor page on the current machine.
    EditMachine,
    ShowSamples,
    LoadSample(String),
    ShowFiles,
    /// IMPORT by key: opens the file picker ([`crate::effect::Effect::PickFile`]).
    PickFile,
    /// A file was read: its bytes (Latin-1 or UTF-8).
    Import(Vec<u8>),
    /// HERUNTERLADEN and LINK TEILEN: carried out by the shell ([`crate::effect::Effect`]).
    Download,
    Share,
    /// The opened share link: take its program as the own one, or keep the own one (also the
    /// answer "keep mine" to a sample or an import over unexported edits).
    TakeLink,
    KeepOwn,
    /// The answer "replace" to a sample or an import over unexported edits.
    ConfirmReplace,
    /// The machine offered for an imported program: take it, or keep the machine.
    TakeMachineOffer,
    KeepMachine,
    /// RÜCKGÄNGIG (Ctrl+Z) and WIEDERHERSTELLEN (Ctrl+Y): the program one step back or forward.
    Undo,
    Redo,
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
    /// Simulate the program the start left unsimulated ([`super::AppState::sim_pending`]; sent by the
    /// shell once the simulator's code is there).
    Simulate,
    /// The right-hand rule on a plane you rotate, in place of the machine view.
    ToggleRightHand,
    ToggleLang,
    ToggleProjector,
    /// The ROHTEIL switch: show or hide the stock.
    ToggleStock,
    /// Cut the run's stock now (sent by the shell for [`crate::effect::Effect::BuildStock`], after a render).
    BuildStock,
    /// The stock's first pass one share on ([`crate::effect::Effect::PassStock`]).
    PassStock,
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
                | Action::ToggleStock
                | Action::BuildStock
                | Action::PassStock
        )
    }
}

impl Action {
    /// While "replace the own program?" is asked: the answers, and what only looks or
    /// switches the screen.
    pub(super) fn allowed_while_asked(&self) -> bool {
        matches!(
            self,
            Action::ConfirmReplace
                | Action::KeepOwn
                | Action::Back
                | Action::Abort
                | Action::CursorUp
                | Action::CursorDown
                | Action::CursorTo(_)
                | Action::Notice(_)
                | Action::ToggleLang
                | Action::ToggleProjector
                | Action::ToggleRightHand
                | Action::PassStock
        )
    }
}
