//! The context one block is read in: the findings that do not stop it and the conversion of a
//! stop into the block's diagnostic.

use std::cell::RefCell;

use super::words::{self, Step, Stop};
use crate::ast::{AxisWord, AxisWords};
use crate::diag::{DiagCode, Expected, Severity};

/// A finding inside one block, with offsets relative to the block text being read.
#[derive(Debug)]
pub(crate) struct Issue {
    pub(super) start: usize,
    pub(super) end: usize,
    pub(super) severity: Severity,
    pub(super) code: DiagCode,
    pub(super) expected: Option<Expected>,
}

/// Per-block context handed to the family parsers: collects the findings that do not stop a
/// block (a value out of range, a warning) while its grammar runs, and lends scratch buffers so
/// that collecting axis words does not allocate per word. Shared (`&Cx`) by the nom parsers of
/// one block, so its parts are cells.
pub(crate) struct Cx {
    pub(super) base: usize,
    pub(super) len: usize,
    pub(super) issues: RefCell<Vec<Issue>>,
    axes: RefCell<Vec<AxisWord>>,
    m: RefCell<Vec<u32>>,
}

impl Cx {
    pub(super) fn new() -> Self {
        Cx {
            base: 0,
            len: 0,
            issues: RefCell::new(Vec::new()),
            axes: RefCell::new(Vec::with_capacity(9)),
            m: RefCell::new(Vec::with_capacity(4)),
        }
    }

    /// Offset of `s` (a sub-slice of the block text) from the start of the block text.
    pub(crate) fn off(&self, s: &str) -> usize {
        (s.as_ptr() as usize).saturating_sub(self.base).min(self.len)
    }

    fn record(
        &self,
        start: usize,
        len: usize,
        severity: Severity,
        code: DiagCode,
        expected: Option<Expected>,
    ) {
        let end = (start + len).min(self.len);
        self.issues.borrow_mut().push(Issue { start, end, severity, code, expected });
    }

    pub(crate) fn error(&self, at: &str, len: usize, code: DiagCode) {
        self.record(self.off(at), len, Severity::Error, code, None);
    }

    pub(crate) fn warn(&self, at: &str, len: usize, code: DiagCode) {
        self.record(self.off(at), len, Severity::Warning, code, None);
    }

    /// Records a syntax error on the word at `at` and returns `None`.
    pub(crate) fn invalid<T>(&self, at: &str, expected: Option<Expected>) -> Option<T> {
        let word = words::word_len(at).max(1);
        self.record(self.off(at), word, Severity::Error, DiagCode::InvalidInput, expected);
        None
    }

    /// The one conversion of a stop into the block's diagnostic: a coded stop says its own
    /// (a missing word, a duplicate), any other labels the word at the stop with what was
    /// expected there as the help.
    pub(crate) fn fail<T>(&self, stop: Stop<'_>) -> Option<T> {
        let e = words::stopped_at(stop);
        match e.code() {
            Some(code) => {
                self.record(self.off(e.at), e.at.len(), Severity::Error, code, None);
                None
            }
            None => self.invalid(e.at, e.expected()),
        }
    }

    /// Adds an axis word to the block's collection; a hard stop if its axis is there already
    /// (`at`: the word, `rest`: after it).
    pub(crate) fn push_axis<'a>(&self, at: &'a str, rest: &'a str, word: AxisWord) -> Step<'a, ()> {
        let mut axes = self.axes.borrow_mut();
        if axes.iter().any(|a| a.axis == word.axis) {
            return words::duplicate(at, at.len() - rest.len(), words::Named::Given(word.axis.as_str()));
        }
        axes.push(word);
        Ok((rest, ()))
    }

    /// How many axis words are collected.
    pub(crate) fn axis_count(&self) -> usize {
        self.axes.borrow().len()
    }

    pub(crate) fn push_m(&self, m: u32) {
        self.m.borrow_mut().push(m);
    }

    /// Empties the scratch buffers at the start of a block family that uses them.
    pub(crate) fn clear_words(&self) {
        self.axes.borrow_mut().clear();
        self.m.borrow_mut().clear();
    }

    /// Takes the collected axis words as an exactly sized slice.
    pub(crate) fn take_axes(&self) -> Box<[AxisWord]> {
        let mut axes = self.axes.borrow_mut();
        let b = Box::from(&axes[..]);
        axes.clear();
        b
    }

    /// Takes the collected axis words of a straight line.
    pub(crate) fn take_line_axes(&self) -> AxisWords {
        let mut axes = self.axes.borrow_mut();
        let words = AxisWords::from(&axes[..]);
        axes.clear();
        words
    }

    pub(crate) fn take_m(&self) -> Box<[u32]> {
        let mut m = self.m.borrow_mut();
        let b = Box::from(&m[..]);
        m.clear();
        b
    }
}
