//! A changed text parsed again only where it changed (issue 16: typing in a 100,000-block
//! program). The changed bytes (common prefix and suffix of the old and new text) are widened
//! to lines where the parser starts afresh — after a line that does not end in `~`, before a
//! line that starts a block or is blank — and only that region is parsed; the blocks, the
//! diagnostics and the line index after it move by the change in length and lines. The checks
//! across blocks (ascending block numbers, BEGIN/END PGM names, a missing END PGM) are made
//! again over the whole program, in the order the parser makes them. Checked against
//! [`Document::new`] by `tests/edit_properties.rs`.

use std::ops::Range;

use schwenkbar_core::ast::Span;
use schwenkbar_core::diag::DiagCode;
use schwenkbar_core::parse::AcrossBlocks;
use schwenkbar_core::{Block, Diagnostic, Program, Severity, parse};

use super::Document;

/// The region of the text parsed again: `start..old_end` of the old text is `start..new_end`
/// of the new one.
struct Region {
    start: usize,
    old_end: usize,
    new_end: usize,
}

/// The common prefix and suffix of `old` and `new` in bytes (together at most the shorter).
fn common(old: &[u8], new: &[u8]) -> (usize, usize) {
    let prefix = old.iter().zip(new).take_while(|(a, b)| a == b).count();
    let room = old.len().min(new.len()) - prefix;
    let suffix = old.iter().rev().zip(new.iter().rev()).take(room).take_while(|(a, b)| a == b).count();
    (prefix, suffix)
}

/// Where the parser starts afresh around a change of `old` (`old_len` bytes) into `new` that
/// kept the first `prefix` and the last `suffix` bytes, or `None` when only a full parse is
/// right (a byte order mark, which the parser strips).
fn region(old: &str, new: &str, prefix: usize, suffix: usize) -> Option<Region> {
    if old.starts_with('\u{feff}') || new.starts_with('\u{feff}') {
        return None;
    }
    let n = new.as_bytes();
    // Back to a line whose line above (unchanged) does not continue into it.
    let line_start = |at: usize| n[..at].iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let mut start = line_start(prefix);
    while start > 0 {
        let above = line_start(start - 1);
        if !new[above..start - 1].trim_end().ends_with('~') {
            break;
        }
        start = above;
    }
    // On to a line (unchanged, in the common suffix) that starts a block or is blank.
    let mut new_end = new.len();
    let mut at = new.len() - suffix;
    while let Some(i) = n[at..].iter().position(|&b| b == b'\n') {
        let line = at + i + 1;
        let rest = &new[line..];
        let text = &rest[..rest.find('\n').unwrap_or(rest.len())];
        if text.trim().is_empty() || matches!(text.trim_start().as_bytes().first(), Some(b'0'..=b'9' | b'/'))
        {
            new_end = line;
            break;
        }
        at = line;
    }
    if new[start..new_end].starts_with('\u{feff}') {
        return None;
    }
    Some(Region { start, old_end: new_end + old.len() - new.len(), new_end })
}

/// The checks across blocks are the parser's; they are made again over the spliced program.
fn across_blocks(code: &DiagCode) -> bool {
    matches!(
        code,
        DiagCode::BlockNumberNotAscending { .. }
            | DiagCode::MissingBlockNumber
            | DiagCode::BlockNumberPrefixed { .. }
            | DiagCode::CommentAfterNumber { .. }
            | DiagCode::Lenient { .. }
            | DiagCode::PgmNameMismatch { .. }
            | DiagCode::MissingEndPgm
    )
}

fn shift_block(mut b: Block, bytes: isize, lines: isize) -> Block {
    b.shift(bytes, lines as i32);
    b
}

fn shift_diag(mut d: Diagnostic, bytes: isize, lines: isize) -> Diagnostic {
    d.span = Span::new(d.span.start.wrapping_add_signed(bytes), d.span.end.wrapping_add_signed(bytes));
    d.line = d.line.wrapping_add_signed(lines as i32);
    d
}

impl Document {
    /// The document after its text became `text`, parsed again only around the change, and the
    /// blocks that may differ: every block before them is the same block, every block after
    /// them one of the last blocks of this document (moved in the text).
    #[must_use]
    pub fn edited(&self, text: String) -> (Document, Range<usize>) {
        let (prefix, suffix) = common(self.text.as_bytes(), text.as_bytes());
        self.spliced(text, prefix, suffix)
    }

    /// The document after the bytes `at` of its text became `insert` (the text area's window
    /// typed in), or `None` when `at` is not a range of the text. Only `at` is compared, not
    /// the megabytes around it.
    #[must_use]
    pub fn replaced(&self, at: Range<usize>, insert: &str) -> Option<(Document, Range<usize>)> {
        let old = self.text.get(at.clone())?;
        let (prefix, suffix) = common(old.as_bytes(), insert.as_bytes());
        let mut text = String::with_capacity(self.text.len() - old.len() + insert.len());
        text.push_str(&self.text[..at.start]);
        text.push_str(insert);
        text.push_str(&self.text[at.end..]);
        Some(self.spliced(text, at.start + prefix, self.text.len() - at.end + suffix))
    }

    /// [`Document::edited`] with the change known: the first `prefix` and last `suffix` bytes
    /// of the text are kept.
    fn spliced(&self, text: String, prefix: usize, suffix: usize) -> (Document, Range<usize>) {
        let Some(r) = region(&self.text, &text, prefix, suffix) else {
            let doc = Document::new(text);
            let all = 0..doc.program.blocks.len();
            return (doc, all);
        };
        let (mut program, diagnostics) = parse(&text[r.start..r.new_end]);
        let first_line = self.line_starts.partition_point(|&s| s < r.start);
        let old_lines = self.line_starts.partition_point(|&s| s <= r.old_end) - first_line;
        let old = &self.program.blocks;
        let (i0, i1) = (
            old.partition_point(|b| b.span().start < r.start),
            old.partition_point(|b| b.span().start < r.old_end),
        );
        // The region's own findings and blocks, placed in the text.
        let (start, line0) = (r.start as isize, first_line as isize);
        let mut own: Vec<Diagnostic> =
            self.diagnostics.iter().filter(|d| !across_blocks(&d.code)).cloned().collect();
        let (d0, d1) = (
            own.partition_point(|d| d.span.start < r.start),
            // A finding at the very end of the region's last block (a word missing at the end
            // of the text) stands at `old_end`: the findings after are the next block's.
            own.partition_point(|d| d.span.start < old.get(i1).map_or(usize::MAX, |b| b.span().start)),
        );
        let region_diags =
            diagnostics.into_iter().filter(|d| !across_blocks(&d.code)).map(|d| shift_diag(d, start, line0));
        let mut line_starts = self.line_starts[..=first_line.min(self.line_starts.len() - 1)].to_vec();
        line_starts.extend(text[r.start..r.new_end].match_indices('\n').map(|(i, _)| r.start + i + 1));
        let new_lines = line_starts.len() - first_line;
        let (bytes, lines) =
            (text.len() as isize - self.text.len() as isize, new_lines as isize - old_lines as isize);
        let tail = own.split_off(d1).into_iter().map(|d| shift_diag(d, bytes, lines));
        own.truncate(d0);
        own.extend(region_diags);
        own.extend(tail);
        line_starts.extend(
            self.line_starts.iter().filter(|&&s| s > r.old_end).map(|&s| s.wrapping_add_signed(bytes)),
        );

        let region_end = i0 + program.blocks.len();
        let mut blocks = Vec::with_capacity(old.len() - (i1 - i0) + program.blocks.len());
        blocks.extend_from_slice(&old[..i0]);
        blocks.extend(program.blocks.drain(..).map(|b| shift_block(b, start, line0)));
        blocks.extend(old[i1..].iter().cloned().map(|b| shift_block(b, bytes, lines)));
        let first_changed = i0 + old[i0..i1].iter().zip(&blocks[i0..]).take_while(|(a, b)| a == b).count();
        let mut doc = Document { text, program: Program { blocks }, diagnostics: Vec::new(), line_starts };
        doc.diagnostics = doc.with_checks_across_blocks(own);
        (doc, first_changed..region_end)
    }

    /// `own` (every block's own findings, in block order) with the parser's checks across
    /// blocks after each block's own, as `parse` orders them.
    fn with_checks_across_blocks(&self, own: Vec<Diagnostic>) -> Vec<Diagnostic> {
        let blocks = &self.program.blocks;
        let mut out = Vec::with_capacity(own.len());
        let mut own = own.into_iter().peekable();
        let mut across = AcrossBlocks::default();
        for (i, b) in blocks.iter().enumerate() {
            let next_start = blocks.get(i + 1).map_or(usize::MAX, |n| n.span().start);
            // The block's own findings (up to its end, a missing word there included), then the
            // checks across blocks, then a finding on a line between it and the next block (a
            // transfer mark): the parser's order.
            while let Some(d) = own.next_if(|d| d.span.start <= b.span().end) {
                out.push(d);
            }
            across.check(&self.text, b, |severity, code, span| {
                // Where the parser puts it: its own line and column (a lenient spelling lies
                // inside the block, maybe on a continuation line).
                let line = self.line_of(span.start);
                let from = self.line_start(line);
                let column = self.text.get(from..span.start).map_or(0, |s| s.chars().count()) as u32 + 1;
                out.push(Diagnostic::new(severity, code, span, line as u32 + 1, column));
            });
            while let Some(d) = own.next_if(|d| d.span.start < next_start) {
                out.push(d);
            }
        }
        out.extend(own);
        if across.end_missing() {
            // Where the parser puts it: after the last block's last line, counted from there.
            let last_line = self.block_lines(blocks.len().saturating_sub(1)).map_or(0, |(_, l)| l);
            let from = self.line_starts.get(last_line).copied().unwrap_or(0);
            let column = self.text.get(from..).map_or(0, |s| s.chars().count()) as u32 + 1;
            let at = self.text.len();
            out.push(Diagnostic::new(
                Severity::Warning,
                DiagCode::MissingEndPgm,
                Span::new(at, at),
                last_line as u32 + 1,
                column,
            ));
        }
        out
    }
}
