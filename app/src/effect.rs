//! Side effects as data: a transition returns what it wants done outside (`apply(&self, a) ->
//! (Self, Vec<Effect>)`), the web shell carries it out (`schwenkbar-web`'s `effects.rs` with
//! `browser.rs`) and reports the outcome back as a notice action. The reducers stay pure: a
//! softkey clicked and the same softkey pressed as F-key ask for the same, and the tests read
//! what would be saved, downloaded or scheduled.

/// One side effect, for the trainer or the course.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// Keep `value` in the browser's storage under `key` (one of [`crate::persist`]'s keys).
    Save { key: &'static str, value: String },
    /// Offer the program as a `.h` file.
    Download { name: String, text: String },
    /// Offer `text` as a UTF-8 file named `name` (the machine editor's JSON export).
    SaveFile { name: String, text: String },
    /// Go to another page of the app (the trainer's EDITIEREN opens the machine editor).
    OpenPage { url: String },
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
    /// Satzfolge: send `RunTick(step)` after `ms` milliseconds.
    Tick { step: usize, ms: u64 },
    /// Send `BuildStock` once the screen is painted (cutting a run's stock takes about a
    /// second in the browser; the run's first render should not wait for it).
    BuildStock,
    /// Send `PassStock` once the screen is painted again: the stock's first pass goes on by a
    /// share ([`crate::stock::PASS_RAYS`]) until every note of the run is known.
    PassStock,
    /// Send `Simulate` once the simulator's code is there: the trainer's first screen is shown
    /// before it (`AppState::sim_pending`; the page loads that code after its first screen).
    Simulate,
    /// A lesson's trainer tells the course which PLANE block its cursor is on (`None`: none).
    TellCourse(Option<String>),
}

/// A page's state: one pure transition that returns the effects it asks for. The web shell
/// holds either page's state the same way.
pub trait Reducer: Sized {
    type Action;

    /// The next state and the effects it asks for.
    fn apply(&self, action: Self::Action) -> (Self, Vec<Effect>);

    /// Whether `action` changes nothing, so the shell need not re-render.
    fn ignores(&self, _action: &Self::Action) -> bool {
        false
    }
}
