//! Where in the source text: a leaf every layer may use (the AST, the diagnostics, the parser),
//! so that the diagnostics need not import the AST.

use serde::Serialize;

/// A byte range `start..end` into the source text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

impl Span {
    #[must_use]
    pub fn new(start: usize, end: usize) -> Self {
        Span { start, end }
    }
}
