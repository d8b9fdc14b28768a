//! The text editor's window (issue 16): a text area holding a 100,000-block program makes the
//! browser lay out 4 MB per keystroke (seconds), so above [`WHOLE_UP_TO`] lines it holds only
//! whole lines around the caret and the program stays in the [`Document`]. What is typed in
//! the window replaces the window's bytes of the text ([`Document::replaced`]); the window
//! moves when the caret comes near an edge beyond which more program lies.

use std::ops::Range;

use super::Document;

/// Programs of at most this many lines are wholly in the text area (select all, copy, paste
/// and undo as in any text area).
pub const WHOLE_UP_TO: usize = 2_000;
/// Lines of the window above and below the caret's line.
const HALF: usize = 100;
/// The window moves when the caret is this many lines from an edge with program beyond.
const MARGIN: usize = 30;

impl Document {
    /// Byte offset of line `line`'s start (the text's end beyond the last line).
    #[must_use]
    pub fn line_start(&self, line: usize) -> usize {
        self.line_starts.get(line).copied().unwrap_or(self.text.len())
    }

    /// The 0-based line of byte `at`.
    #[must_use]
    pub fn line_of(&self, at: usize) -> usize {
        self.line_starts.partition_point(|&s| s <= at).saturating_sub(1)
    }

    /// The bytes of the text the text area holds with the caret on line `line`: all of it up to
    /// [`WHOLE_UP_TO`] lines, else the whole lines from `HALF` above to `HALF` below.
    #[must_use]
    pub fn window_at(&self, line: usize) -> Range<usize> {
        if self.line_starts.len() <= WHOLE_UP_TO + 1 {
            return 0..self.text.len();
        }
        let first = line.saturating_sub(HALF);
        self.line_start(first)..self.line_start(first + 2 * HALF)
    }

    /// Whether the window `window` should move to [`Document::window_at`] the caret at byte
    /// `caret`: the caret near an edge beyond which more program lies, a paste made it too
    /// long, or the program became small enough to be held whole.
    #[must_use]
    pub fn window_moves(&self, window: &Range<usize>, caret: usize) -> bool {
        let whole = 0..self.text.len();
        if self.line_starts.len() <= WHOLE_UP_TO + 1 {
            return *window != whole;
        }
        let (first, end, line) = (self.line_of(window.start), self.line_of(window.end), self.line_of(caret));
        (window.start > 0 && line < first + MARGIN)
            || (window.end < whole.end && line + MARGIN > end)
            || self.window_oversized(window)
    }

    /// Whether `window` holds far more lines than a window does (a paste into it): the text area
    /// must not be laid out with it (seconds for 100,000 lines) before it holds the window again.
    #[must_use]
    pub fn window_oversized(&self, window: &Range<usize>) -> bool {
        self.line_starts.len() > WHOLE_UP_TO + 1
            && self.line_of(window.end).saturating_sub(self.line_of(window.start)) > 4 * HALF
    }
}

/// The byte offset in `s` of the UTF-16 offset `units` (the text area counts in UTF-16),
/// at most `s.len()`.
#[must_use]
pub fn byte_of_utf16(s: &str, units: usize) -> usize {
    let mut seen = 0;
    for (i, c) in s.char_indices() {
        if seen >= units {
            return i;
        }
        seen += c.len_utf16();
    }
    s.len()
}

/// The UTF-16 offset of byte `at` of `s` (a char boundary).
#[must_use]
pub fn utf16_of_byte(s: &str, at: usize) -> usize {
    s.get(..at).map_or(0, |h| h.encode_utf16().count())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(lines: usize) -> Document {
        Document::new((0..lines).map(|i| format!("{i} L X+{i} FMAX\n")).collect())
    }

    #[test]
    fn a_small_program_is_held_whole_and_a_big_one_around_the_caret() {
        let small = program(WHOLE_UP_TO);
        assert_eq!(small.window_at(1_500), 0..small.text.len());
        assert!(!small.window_moves(&(0..small.text.len()), 10));
        let big = program(10_000);
        let w = big.window_at(5_000);
        assert_eq!((big.line_of(w.start), big.line_of(w.end)), (5_000 - HALF, 5_000 + HALF));
        assert!(
            big.text[w.clone()].starts_with(&format!("{} L", 5_000 - HALF))
                && big.text[..w.end].ends_with('\n')
        );
        assert!(!big.window_moves(&w, big.line_starts[5_000]));
        assert!(big.window_moves(&w, big.line_starts[5_000 - HALF + 1]), "near the top edge");
        assert!(big.window_moves(&w, big.line_starts[5_000 + HALF - 1]), "near the bottom edge");
        let top = big.window_at(3);
        assert_eq!(top.start, 0);
        assert!(!big.window_moves(&top, 0), "nothing above the first line");
        let bottom = big.window_at(9_999);
        assert_eq!(bottom.end, big.text.len());
        assert!(!big.window_moves(&bottom, big.text.len()), "nothing below the last line");
        // A window is never oversized; the whole program pasted into one is, and moves.
        assert!(![w.clone(), top, bottom].iter().any(|w| big.window_oversized(w)));
        let pasted = 0..big.text.len();
        assert!(big.window_oversized(&pasted) && big.window_moves(&pasted, big.line_starts[5_000]));
        assert!(!small.window_oversized(&(0..small.text.len())), "a small program is held whole");
    }

    #[test]
    fn utf16_offsets_map_to_bytes_and_back() {
        let s = "Ü1 L X+1\n𝔘";
        for (units, byte) in [(0, 0), (1, 2), (8, 9), (9, 10), (11, 14), (99, 14)] {
            assert_eq!(byte_of_utf16(s, units), byte);
        }
        assert_eq!(utf16_of_byte(s, 10), 9);
        assert_eq!(utf16_of_byte(s, 14), 11);
    }
}
