//! A program's physical lines, found eight bytes at a time.

/// A physical line: byte range without the line break, 1-based number.
#[derive(Debug, Clone, Copy)]
pub(super) struct PhysLine {
    pub(super) start: usize,
    pub(super) end: usize,
    pub(super) number: u32,
}

/// Splits into lines (`\n`, `\r\n` and a lone `\r` at the end of a line).
pub(super) struct Lines<'a> {
    pub(super) src: &'a str,
    pub(super) pos: usize,
    pub(super) number: u32,
}

impl Iterator for Lines<'_> {
    type Item = PhysLine;

    fn next(&mut self) -> Option<PhysLine> {
        if self.pos >= self.src.len() {
            return None;
        }
        let rest = &self.src.as_bytes()[self.pos..];
        let (len, next) = match find_newline(rest) {
            Some(i) => (i, self.pos + i + 1),
            None => (rest.len(), self.src.len()),
        };
        let mut end = self.pos + len;
        if end > self.pos && self.src.as_bytes()[end - 1] == b'\r' {
            end -= 1;
        }
        self.number += 1;
        let line = PhysLine { start: self.pos, end, number: self.number };
        self.pos = next;
        Some(line)
    }
}

const ONES: u64 = 0x0101_0101_0101_0101;
const HIGH: u64 = 0x8080_8080_8080_8080;

/// `\n`s in `b`, eight bytes at a time (wasm32 has no vectorised byte loop).
pub(super) fn count_newlines(b: &[u8]) -> usize {
    let mut chunks = b.chunks_exact(8);
    let mut n = 0;
    for chunk in &mut chunks {
        let word = u64::from_le_bytes(chunk.try_into().unwrap_or_default()) ^ (ONES * u64::from(b'\n'));
        // Exactly the high bit of each zero byte (no carries between bytes).
        let low7 = !HIGH;
        n += (!(((word & low7) + low7) | word | low7)).count_ones() as usize;
    }
    n + chunks.remainder().iter().filter(|&&c| c == b'\n').count()
}

/// Index of the first `\n`, eight bytes at a time: the parser's fast path spends a quarter of its
/// time finding line ends byte by byte otherwise.
fn find_newline(b: &[u8]) -> Option<usize> {
    let mut chunks = b.chunks_exact(8);
    let mut at = 0;
    for chunk in &mut chunks {
        let word = u64::from_le_bytes(chunk.try_into().unwrap_or_default()) ^ (ONES * u64::from(b'\n'));
        // The lowest high bit set marks the first zero byte, i.e. the first `\n` (a borrow only
        // carries upwards, so the false hits are above a true one).
        let zero = word.wrapping_sub(ONES) & !word & HIGH;
        if zero != 0 {
            return Some(at + (zero.trailing_zeros() / 8) as usize);
        }
        at += 8;
    }
    chunks.remainder().iter().position(|&c| c == b'\n').map(|i| at + i)
}
