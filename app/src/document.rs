//! The program being edited: its text, what the core's parser read from it, and a line index.
//! Parsed once per change of text (only the changed blocks again, [`Document::edited`]); every
//! view reads the same result.

use std::rc::Rc;

use schwenkbar_core::{Diagnostic, Program, parse};

use crate::i18n::Lang;

mod splice;
mod window;

pub use window::{WHOLE_UP_TO, byte_of_utf16, utf16_of_byte};

#[derive(Debug, Clone)]
pub struct Document {
    pub text: String,
    pub program: Program,
    pub diagnostics: Vec<Diagnostic>,
    /// Byte offset of each line's start.
    line_starts: Vec<usize>,
}

/// Two documents are equal when their texts are: everything else is parsed from the text, by
/// `Document::new`, the only way to make one (`line_starts` is private). So comparing two
/// states is one string compare instead of a walk through two ASTs, and the derived deep
/// comparison (about 1 KB gzip) stays out of the bundle. The views compare by identity
/// ([`DocRef`]).
impl PartialEq for Document {
    fn eq(&self, other: &Document) -> bool {
        std::ptr::eq(self, other) || self.text == other.text
    }
}

/// Equal texts are an equivalence; with `Eq`, `Rc<Document>`'s comparison (every prop check)
/// is a pointer compare first, not a walk through megabytes of the same text.
impl Eq for Document {}

/// A document handed to the views, compared by identity: a view re-renders when the program
/// is another document. Comparing the texts (every prop check of every view that shows the
/// program) cost milliseconds a keystroke in a 4 MB program.
#[derive(Debug, Clone)]
pub struct DocRef(pub Rc<Document>);

impl PartialEq for DocRef {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0)
    }
}

impl std::ops::Deref for DocRef {
    type Target = Document;
    fn deref(&self) -> &Document {
        &self.0
    }
}

impl Document {
    #[must_use]
    pub fn new(text: String) -> Document {
        let (program, diagnostics) = parse(&text);
        let line_starts = std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect();
        Document { text, program, diagnostics, line_starts }
    }

    /// Index of the last block (0 for an empty program).
    #[must_use]
    pub fn last_index(&self) -> usize {
        self.program.blocks.len().saturating_sub(1)
    }

    /// Number of errors (the control would refuse these blocks).
    #[must_use]
    pub fn error_count(&self) -> usize {
        self.diagnostics.iter().filter(|d| d.is_error()).count()
    }

    /// Number of text lines (a final line break does not open another line).
    #[must_use]
    pub fn line_count(&self) -> usize {
        let n = self.line_starts.len();
        if self.text.ends_with('\n') { n - 1 } else { n }
    }

    /// Text of line `i` (0-based) without its line break.
    #[must_use]
    pub fn line(&self, i: usize) -> &str {
        let Some(&start) = self.line_starts.get(i) else { return "" };
        let end = self.line_starts.get(i + 1).map_or(self.text.len(), |&e| e - 1);
        self.text.get(start..end).unwrap_or("").trim_end_matches('\r')
    }

    /// Whether 0-based line `i` continues a comment that a line before it in the same block ran
    /// on with `~` (as the parser reads it: in a cycle every line has its own label instead).
    #[must_use]
    pub fn comment_continues(&self, i: usize) -> bool {
        let Some(b) = self.block_at_line(i) else { return false };
        let Some((first, _)) = self.block_lines(b).filter(|&(_, last)| i <= last) else { return false };
        let cycle = self.program.blocks[b].stored_body().is_some_and(|body| {
            matches!(
                body,
                schwenkbar_core::BlockBody::CycleDef(_) | schwenkbar_core::BlockBody::TouchProbe(_)
            )
        });
        !cycle && (first..i).any(|k| schwenkbar_core::parse::split_comment(self.line(k)).1.is_some())
    }

    /// The block a 0-based line belongs to (continuation lines belong to the block above).
    #[must_use]
    pub fn block_at_line(&self, line: usize) -> Option<usize> {
        let line1 = u32::try_from(line + 1).ok()?;
        match self.program.blocks.binary_search_by_key(&line1, |b| b.line()) {
            Ok(i) => Some(i),
            Err(0) => None,
            Err(i) => Some(i - 1),
        }
    }

    /// First and last 0-based line of block `index`.
    #[must_use]
    pub fn block_lines(&self, index: usize) -> Option<(usize, usize)> {
        let b = self.program.blocks.get(index)?;
        let first = (b.line() as usize).saturating_sub(1);
        let end = b.span().end.saturating_sub(1).max(b.span().start);
        let last = self.line_starts.partition_point(|&s| s <= end).saturating_sub(1);
        Some((first, last.max(first)))
    }

    /// "2 Fehler · 1 Warnung": the diagnostics counted, with the word in the right number.
    #[must_use]
    pub fn summary(&self, l: Lang) -> String {
        let count = |n: usize, one: (&str, &str), many: (&str, &str)| {
            let (de, en) = if n == 1 { one } else { many };
            format!("{n} {}", l.t(de, en))
        };
        let errors = self.error_count();
        match (errors, self.diagnostics.len() - errors) {
            (0, 0) => l.t("keine Fehler", "no errors").to_owned(),
            (e, 0) => count(e, ("Fehler", "error"), ("Fehler", "errors")),
            (0, w) => count(w, ("Warnung", "warning"), ("Warnungen", "warnings")),
            (e, w) => format!(
                "{} · {}",
                count(e, ("Fehler", "error"), ("Fehler", "errors")),
                count(w, ("Warnung", "warning"), ("Warnungen", "warnings"))
            ),
        }
    }

    /// Where a diagnostic at `line` (1-based) is, as the control names it: the block number
    /// written in the program ("Satz 1: "), else the line of a block without a number
    /// ("Zeile 3: ").
    #[must_use]
    pub fn where_label(&self, line: u32, l: Lang) -> String {
        let number = self
            .block_at_line((line as usize).saturating_sub(1))
            .and_then(|b| self.program.blocks.get(b))
            .and_then(|b| b.number());
        match number {
            Some(n) => format!("{} {n}: ", l.t("Satz", "Block")),
            None => format!("{} {line}: ", l.t("Zeile", "Line")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_agree_with_their_number() {
        let summary = |text: &str, l| Document::new(text.into()).summary(l);
        assert_eq!(summary("0 BEGIN PGM T MM\n1 END PGM T MM\n", Lang::De), "keine Fehler");
        // One warning: block numbers that do not ascend (said once per file).
        let warned = "0 BEGIN PGM T MM\n5 L X+1 FMAX\n3 L X+2 FMAX\n6 END PGM T MM\n";
        let doc = Document::new(warned.into());
        assert_eq!((doc.error_count(), doc.diagnostics.len()), (0, 1), "{:?}", doc.diagnostics);
        assert_eq!(summary(warned, Lang::De), "1 Warnung");
        let both = "0 BEGIN PGM T MM\n1 PLANE SPATIAL SPA+400 SPB+0 SPC+0 STAY\n5 L X+1 FMAX\n3 L X+2 FMAX\n\
                    6 END PGM T MM\n";
        let doc = Document::new(both.into());
        assert_eq!((doc.error_count(), doc.diagnostics.len()), (1, 2), "{:?}", doc.diagnostics);
        assert_eq!(summary(both, Lang::De), "1 Fehler · 1 Warnung");
        assert_eq!(summary(both, Lang::En), "1 error · 1 warning");
    }

    #[test]
    fn a_diagnostic_is_placed_by_its_block_number() {
        let doc = Document::new("0 BEGIN PGM T MM\n1 PLANE SPATIAL SPA+400 SPB+0 SPC+0 STAY\nL X+1\n".into());
        let error = doc.diagnostics.iter().find(|d| d.is_error()).expect("SPA+400 is refused");
        assert_eq!(doc.where_label(error.line, Lang::De), "Satz 1: ");
        assert_eq!(doc.where_label(3, Lang::En), "Line 3: ", "a block without a number");
    }

    #[test]
    fn documents_are_equal_exactly_when_their_texts_are() {
        let a = Document::new("0 BEGIN PGM A MM\n1 L X+1 FMAX\n".into());
        let b = Document::new(a.text.clone());
        assert!(a == b && a.program == b.program && a.diagnostics == b.diagnostics);
        assert!(a != Document::new("0 BEGIN PGM A MM\n1 L X+2 FMAX\n".into()));
    }

    #[test]
    fn lines_and_blocks_map_both_ways_including_cycle_continuations() {
        let doc = Document::new(
            "0 BEGIN PGM T MM\n1 CYCL DEF 200 BOHREN ~\n  Q200=+2 ;SICHERHEITS-ABST. ~\n  Q201=-5 ;TIEFE\n2 END PGM T MM\n"
                .to_owned(),
        );
        assert_eq!(doc.line_count(), 5);
        assert_eq!(doc.line(2), "  Q200=+2 ;SICHERHEITS-ABST. ~");
        assert_eq!(doc.block_at_line(3), Some(1));
        assert_eq!(doc.block_at_line(4), Some(2));
        assert_eq!(doc.block_lines(1), Some((1, 3)));
        assert_eq!(doc.block_lines(2), Some((4, 4)));
        assert_eq!(doc.line(99), "");
    }

    #[test]
    fn a_wrapped_comment_continues_over_its_lines_but_a_cycle_label_does_not() {
        let doc = Document::new(
            "0 BEGIN PGM T MM\n1 ;free~\n under these~\n terms\n2 CYCL DEF 200 BOHREN ;B ~\n  Q200=+2 ;A ~\n  Q201=-5 ;T\n\n3 L X+1 R0 FMAX ;x\n4 END PGM T MM\n"
                .to_owned(),
        );
        let continues: Vec<usize> = (0..doc.line_count()).filter(|&i| doc.comment_continues(i)).collect();
        assert_eq!(continues, [2, 3], "the wrapped comment's lines, not the cycle's or a blank line");
    }
}
