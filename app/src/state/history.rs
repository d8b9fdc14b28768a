//! The program's undo history (classroom trial II): every change of the program — typing, a
//! block from the PLANE dialog, a sample opened, a file imported, a share link taken — can be
//! taken back (Ctrl+Z, RÜCKGÄNGIG) and done again (Ctrl+Y, WIEDERHERSTELLEN), as the control's
//! own editor can. Typing is one step per line: a run of edits is one step until Enter.

use std::rc::Rc;

use crate::document::Document;

/// The programs before (and, after an undo, after) the shown one, newest last. Each entry
/// shares its text and blocks with the document it was (an `Rc`), so a step costs no copy.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct History {
    undo: Vec<Rc<Document>>,
    redo: Vec<Rc<Document>>,
    /// The newest undo step is a run of typing that later typing on the same line joins.
    typing: bool,
}

/// At most this many steps are kept back…
const MAX_STEPS: usize = 100;
/// …and at most this much program text in them (a 1M-block program is 44 MB; the newest step
/// is always kept, whatever its size, so a replaced program is never lost).
const MAX_BYTES: usize = 64 << 20;

/// What kind of change made a new program, for grouping.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// Typed in the text editor; `new_line`: the edit added or removed a line break.
    Typing { new_line: bool },
    /// Anything else: one step of its own.
    Whole,
}

impl History {
    /// A history whose one step back is `before` (the program a sample, an import or a link
    /// replaced, kept across a reload).
    #[must_use]
    pub fn with(before: Rc<Document>) -> History {
        History { undo: vec![before], ..History::default() }
    }

    /// `before` was the program until a change of kind `change`.
    pub fn record(&mut self, before: Rc<Document>, change: Change) {
        self.redo.clear();
        let joins = matches!(change, Change::Typing { new_line: false }) && self.typing;
        self.typing = matches!(change, Change::Typing { .. });
        if joins && !self.undo.is_empty() {
            return;
        }
        self.undo.push(before);
        let mut bytes = 0;
        let keep = self.undo.iter().rev().take(MAX_STEPS).take_while(|d| {
            bytes += d.text.len();
            bytes <= MAX_BYTES
        });
        let keep = keep.count().max(1);
        let drop = self.undo.len() - keep;
        self.undo.drain(..drop);
    }

    /// Ends a run of typing (the next typed edit is a step of its own).
    pub fn break_typing(&mut self) {
        self.typing = false;
    }

    /// The program one step back, `current` kept for redo.
    pub fn undo(&mut self, current: Rc<Document>) -> Option<Rc<Document>> {
        let back = self.undo.pop()?;
        self.redo.push(current);
        self.typing = false;
        Some(back)
    }

    /// The program one step forward again, `current` kept for undo.
    pub fn redo(&mut self, current: Rc<Document>) -> Option<Rc<Document>> {
        let forward = self.redo.pop()?;
        self.undo.push(current);
        self.typing = false;
        Some(forward)
    }

    #[must_use]
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    #[must_use]
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(text: &str) -> Rc<Document> {
        Rc::new(Document::new(text.to_owned()))
    }

    #[test]
    fn typing_on_one_line_is_one_step_and_enter_starts_the_next() {
        let mut h = History::default();
        h.record(doc("a"), Change::Typing { new_line: false });
        h.record(doc("ab"), Change::Typing { new_line: false });
        h.record(doc("abc"), Change::Typing { new_line: true });
        h.record(doc("abc\n"), Change::Typing { new_line: false });
        let now = doc("abc\nd");
        let one = h.undo(now).expect("a step");
        assert_eq!(one.text, "abc");
        let two = h.undo(one).expect("a step");
        assert_eq!(two.text, "a", "the typing on the first line is one step");
        assert!(h.undo(two.clone()).is_none());
        assert_eq!(h.redo(two).expect("redo").text, "abc");
    }

    #[test]
    fn a_whole_change_is_its_own_step_and_a_new_change_drops_redo() {
        let mut h = History::default();
        h.record(doc("own"), Change::Typing { new_line: false });
        h.record(doc("own+"), Change::Whole);
        let back = h.undo(doc("sample")).expect("step");
        assert_eq!(back.text, "own+");
        assert!(h.can_redo());
        h.record(back, Change::Whole);
        assert!(!h.can_redo(), "a new change forgets what was undone");
    }

    #[test]
    fn the_history_is_bounded_but_keeps_the_newest_step() {
        let mut h = History::default();
        for i in 0..(MAX_STEPS + 20) {
            h.record(doc(&i.to_string()), Change::Whole);
        }
        assert_eq!(h.undo.len(), MAX_STEPS);
        assert_eq!(h.undo.last().map(|d| d.text.as_str()), Some("119"));
        let big = format!("; {}", "x".repeat(MAX_BYTES));
        h.record(doc(&big), Change::Whole);
        assert_eq!(h.undo.len(), 1, "a step over the byte budget alone is still kept");
    }
}
