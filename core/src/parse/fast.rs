//! The fast path: the common straight line, read in one pass over its bytes into the compact
//! block, without the general parser's word readers, scratch buffers or allocations.
//!   line := blank* [/ blank*] digits blank+ [/ blank*] L { blank+ (X|Y|Z)num | Fnum | FMAX | R0|RL|RR } blank*
//!   num  := [+|-] digits [. digits] | [+|-] . digits       (at most 9 digits, m < 2^27, ≤ 15 decimals)
//! Anything else (a comment, a Q parameter, an M function, `I`, another axis, an error) is
//! left to the general parser, which reads the same text to the same block: the differential
//! tests (`core/tests/fast_path.rs`) compare both on fixtures and generated programs.

use crate::ast::{CompactLine, Decimal, FEED_MAX, FEED_VALUE, HAS_NUMBER, RadiusComp, SKIP};

/// A line the fast path read: leading blanks, block number, the compact line.
pub(super) struct FastLine {
    pub(super) lead: usize,
    pub(super) number: u32,
    pub(super) line: CompactLine,
}

fn is_blank(b: u8) -> bool {
    b == b' ' || b == b'\t'
}

/// Reads `text` (one physical line without its break), or `None` for the general parser.
pub(super) fn straight_line(text: &str) -> Option<FastLine> {
    let b = text.as_bytes();
    let mut i = blanks(b, 0);
    let lead = i;
    let mut present = HAS_NUMBER;
    if b.get(i) == Some(&b'/') {
        present |= SKIP;
        i = blanks(b, i + 1);
    }
    let digits_start = i;
    let mut number = 0u32;
    while let Some(&d) = b.get(i).filter(|d| d.is_ascii_digit()) {
        // Nine digits always fit a u32; longer numbers are the general parser's.
        if i - digits_start == 9 {
            return None;
        }
        number = number * 10 + u32::from(d - b'0');
        i += 1;
    }
    if i == digits_start || !b.get(i).copied().is_some_and(is_blank) {
        return None;
    }
    i = blanks(b, i);
    if b.get(i) == Some(&b'/') {
        present |= SKIP;
        i = blanks(b, i + 1);
    }
    if b.get(i) != Some(&b'L') {
        return None;
    }
    i += 1;
    let mut words = [Decimal::default(); 4];
    let mut comp = None;
    // Axes in the order X, Y, Z, each once (any other order is kept as written by the general
    // form): the next axis allowed. The slot is computed, not matched: a jump table's indirect
    // branch, taken to X, Y, Z and F in turn, mispredicts (a fifth of the fast path's time).
    let mut next_axis = 0;
    loop {
        let after = blanks(b, i);
        let Some(&key) = b.get(after) else { break };
        if after == i {
            return None;
        }
        i = after + 1;
        let axis = usize::from(key.wrapping_sub(b'X'));
        let slot = if axis < 3 {
            if axis < next_axis {
                return None;
            }
            next_axis = axis + 1;
            axis
        } else if key == b'F' {
            if present & (FEED_MAX | FEED_VALUE) != 0 {
                return None;
            }
            if b[i..].starts_with(b"MAX") && b.get(i + 3).is_none_or(|&c| is_blank(c)) {
                present |= FEED_MAX;
                i += 3;
                continue;
            }
            3
        } else if key == b'R' {
            let c = match b.get(i) {
                Some(b'0') => RadiusComp::R0,
                Some(b'L') => RadiusComp::Rl,
                Some(b'R') => RadiusComp::Rr,
                _ => return None,
            };
            if comp.is_some() {
                return None;
            }
            comp = Some(c);
            i += 1;
            continue;
        } else {
            return None;
        };
        let (decimal, end) = decimal(b, i)?;
        words[slot] = decimal;
        present |= 1 << slot;
        i = end;
    }
    let column = u8::try_from(lead + 1).ok()?;
    Some(FastLine { lead, number, line: CompactLine { words, present, comp, column } })
}

fn blanks(b: &[u8], mut i: usize) -> usize {
    while b.get(i).copied().is_some_and(is_blank) {
        i += 1;
    }
    i
}

/// `[+|-] digits [. digits]` ending its word, as a [`Decimal`], and where it ended. Inlined into
/// its one caller: returned through memory it cost a tenth of the parser's time.
#[inline(always)]
fn decimal(b: &[u8], mut i: usize) -> Option<(Decimal, usize)> {
    let negative = b.get(i) == Some(&b'-');
    i += usize::from(matches!(b.get(i), Some(b'+' | b'-')));
    let start = i;
    let (mut mantissa, mut dot) = (0u32, None);
    while let Some(&c) = b.get(i) {
        let digit = c.wrapping_sub(b'0');
        if digit < 10 {
            // May wrap only beyond nine digits, which are refused below.
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u32::from(digit));
        } else if c == b'.' && dot.is_none() {
            dot = Some(i);
        } else {
            break;
        }
        i += 1;
    }
    let digits = i - start - usize::from(dot.is_some());
    let decimals = dot.map_or(0, |d| i - d - 1);
    // Whatever stopped the number must be a blank: the caller refuses words that run together.
    if digits == 0 || digits > 9 || mantissa >= Decimal::MANTISSA_LIMIT || decimals > Decimal::MAX_DECIMALS {
        return None;
    }
    Some((Decimal::new(negative, mantissa, decimals as u32), i))
}
