//! Side effects as data: the reducer asks, the app shell (`app.rs` with `browser.rs`) carries
//! them out and reports back with [`Action::Notice`].

use std::rc::Rc;

#[cfg(doc)]
use super::Action;
use super::AppState;

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

impl AppState {
    pub(super) fn emit(&mut self, effect: Effect) {
        let mut list = self.effects.list.to_vec();
        list.push(effect);
        self.effects = Effects { seq: self.effects.seq + 1, list: list.into() };
    }
}
