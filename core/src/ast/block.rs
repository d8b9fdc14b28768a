//! How a block is kept: the common straight line `L X… Y… Z… F…` inline and packed
//! ([`CompactLine`]), every other block boxed ([`GeneralBlock`]); the accessors give the same view
//! of either.

use std::borrow::Cow;
use std::fmt;

use serde::Serialize;

use super::{Axis, AxisWord, AxisWords, BlockBody, Line, MWords, RadiusComp, Span};
use crate::plane::{Feed, Value};

/// One NC block: usually one line, a cycle definition also owns its `~` continuation lines.
///
/// Kept to 40 bytes, because CAM programs are millions of blocks (issue 16: the AST within the
/// file's size): offsets and line as `u32`, and the common straight line `L X… Y… Z… F…` in a
/// compact inline form (`CompactLine`); every other block is boxed (`GeneralBlock`). The
/// accessors give the same view of either.
#[derive(Clone)]
pub struct Block {
    start: u32,
    end: u32,
    line: u32,
    number: u32,
    repr: Repr,
}

#[derive(Clone)]
enum Repr {
    Line(CompactLine),
    General(Box<GeneralBlock>),
}

/// Whatever does not fit the compact form.
#[derive(Clone)]
struct GeneralBlock {
    number: Option<u32>,
    skip: bool,
    body: BlockBody,
    comment: Option<String>,
    column: u32,
}

/// `[/]n L` with `X`, `Y`, `Z` (each at most once, in this order) and `F`, each a plain number
/// of few digits ([`Decimal`]), `FMAX`, `R0`/`RL`/`RR`; no comment, no M function.
#[derive(Clone, Copy, PartialEq, Debug)]
pub(crate) struct CompactLine {
    /// X, Y, Z and the feed, valid where `present` says.
    pub(crate) words: [Decimal; 4],
    /// Bits 0–2: X, Y, Z; 3: `F` value; 4: `FMAX`; 5: a block number; 6: block skip.
    pub(crate) present: u8,
    pub(crate) comp: Option<RadiusComp>,
    /// 1-based column of the block's first character.
    pub(crate) column: u8,
}

pub(crate) const HAS_NUMBER: u8 = 1 << 5;
pub(crate) const SKIP: u8 = 1 << 6;
pub(crate) const FEED_VALUE: u8 = 1 << 3;
pub(crate) const FEED_MAX: u8 = 1 << 4;

/// A decimal number `±m / 10^e` as written (`-12.5000`: m = 125000, e = 4), packed as sign (bit
/// 31), e (bits 27–30) and m < 2^27 (bits 0–26). Its `f64` is bit for bit what
/// [`crate::number::parse_f64`] reads from the same text: m < 2^53 and 10^e (e ≤ 22) are both
/// exact, so the one division rounds correctly (Clinger's fast path, which `parse_f64` takes for
/// such numbers too).
#[derive(Clone, Copy, PartialEq, Debug, Default)]
pub(crate) struct Decimal(pub(crate) u32);

impl Decimal {
    pub(crate) const MANTISSA_LIMIT: u32 = 1 << 27;
    pub(crate) const MAX_DECIMALS: usize = 15;

    pub(crate) fn new(negative: bool, mantissa: u32, decimals: u32) -> Self {
        Decimal(u32::from(negative) << 31 | decimals << 27 | mantissa)
    }

    pub(crate) fn value(self) -> f64 {
        let m = f64::from(self.0 & (Self::MANTISSA_LIMIT - 1));
        let p = (0..(self.0 >> 27) & 15).fold(1.0, |p, _| p * 10.0);
        let v = m / p;
        if self.0 >> 31 == 1 { -v } else { v }
    }
}

impl CompactLine {
    fn line(&self) -> Line {
        let mut axes = AxisWords::default();
        for (k, axis) in [Axis::X, Axis::Y, Axis::Z].into_iter().enumerate() {
            if self.present & (1 << k) != 0 {
                axes.push(AxisWord { axis, value: Value::Number(self.words[k].value()), incremental: false });
            }
        }
        let feed = if self.present & FEED_VALUE != 0 {
            Some(Feed::Value(Value::Number(self.words[3].value())))
        } else if self.present & FEED_MAX != 0 {
            Some(Feed::Max)
        } else {
            None
        };
        Line { axes, comp: self.comp, feed, speed: None, m: Box::default(), m_words: MWords::default() }
    }
}

/// Offsets beyond 4 GiB are clamped: such a text is not an NC program anyone can load.
fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

impl Block {
    /// A block of any kind.
    #[must_use]
    pub fn new(
        number: Option<u32>,
        skip: bool,
        body: BlockBody,
        comment: Option<String>,
        span: Span,
        line: u32,
        column: u32,
    ) -> Self {
        Block {
            start: to_u32(span.start),
            end: to_u32(span.end),
            line,
            number: number.unwrap_or(0),
            repr: Repr::General(Box::new(GeneralBlock { number, skip, body, comment, column })),
        }
    }

    /// A straight line in the compact form.
    pub(crate) fn compact(number: u32, span: Span, line: u32, compact: CompactLine) -> Self {
        Block { start: to_u32(span.start), end: to_u32(span.end), line, number, repr: Repr::Line(compact) }
    }

    /// The leading block number; `None` when it was left out (a single typed block).
    #[must_use]
    pub fn number(&self) -> Option<u32> {
        match &self.repr {
            Repr::Line(l) => (l.present & HAS_NUMBER != 0).then_some(self.number),
            Repr::General(g) => g.number,
        }
    }

    /// A leading `/`: the block is skipped when block skip is on.
    #[must_use]
    pub fn skip(&self) -> bool {
        match &self.repr {
            Repr::Line(l) => l.present & SKIP != 0,
            Repr::General(g) => g.skip,
        }
    }

    /// What the block says (built on the spot for a compact straight line; nothing allocated).
    #[must_use]
    pub fn body(&self) -> Cow<'_, BlockBody> {
        match &self.repr {
            Repr::Line(l) => Cow::Owned(BlockBody::L(l.line())),
            Repr::General(g) => Cow::Borrowed(&g.body),
        }
    }

    /// The body as stored, borrowed for as long as the block: every kind of block but a compact
    /// straight line (`None`, see [`Block::body`]). For questions about other kinds of block.
    #[must_use]
    pub fn stored_body(&self) -> Option<&BlockBody> {
        match &self.repr {
            Repr::Line(_) => None,
            Repr::General(g) => Some(&g.body),
        }
    }

    /// The body, taken out of the block.
    #[must_use]
    pub fn into_body(self) -> BlockBody {
        match self.repr {
            Repr::Line(l) => BlockBody::L(l.line()),
            Repr::General(g) => g.body,
        }
    }

    /// Text after `;`, trimmed; `Some("")` for a bare `1 ;`.
    #[must_use]
    pub fn comment(&self) -> Option<&str> {
        match &self.repr {
            Repr::Line(_) => None,
            Repr::General(g) => g.comment.as_deref(),
        }
    }

    /// Bytes of the block from its first non-blank character to the end of its last line.
    #[must_use]
    pub fn span(&self) -> Span {
        Span::new(self.start as usize, self.end as usize)
    }

    /// The same block moved by an edit before it: `bytes` further in the text, `lines` further down.
    pub fn shift(&mut self, bytes: isize, lines: i32) {
        self.start = to_u32((self.start as usize).wrapping_add_signed(bytes));
        self.end = to_u32((self.end as usize).wrapping_add_signed(bytes));
        self.line = self.line.wrapping_add_signed(lines);
    }

    /// 1-based line of the block's first character.
    #[must_use]
    pub fn line(&self) -> u32 {
        self.line
    }

    /// 1-based column of the block's first character.
    #[must_use]
    pub fn column(&self) -> u32 {
        match &self.repr {
            Repr::Line(l) => u32::from(l.column),
            Repr::General(g) => g.column,
        }
    }

    /// Whether the block is held in the compact form (for the tests of the parser's fast path).
    #[doc(hidden)]
    #[must_use]
    pub fn is_compact(&self) -> bool {
        matches!(self.repr, Repr::Line(_))
    }
}

impl PartialEq for Block {
    fn eq(&self, other: &Self) -> bool {
        self.number() == other.number()
            && self.skip() == other.skip()
            && self.body() == other.body()
            && self.comment() == other.comment()
    }
}

impl fmt::Debug for Block {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Block")
            .field("number", &self.number())
            .field("skip", &self.skip())
            .field("body", &*self.body())
            .field("comment", &self.comment())
            .field("span", &self.span())
            .field("line", &self.line)
            .field("column", &self.column())
            .finish()
    }
}

impl Serialize for Block {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = ser.serialize_struct("Block", 7)?;
        s.serialize_field("number", &self.number())?;
        s.serialize_field("skip", &self.skip())?;
        s.serialize_field("body", &*self.body())?;
        s.serialize_field("comment", &self.comment())?;
        s.serialize_field("span", &self.span())?;
        s.serialize_field("line", &self.line)?;
        s.serialize_field("column", &self.column())?;
        s.end()
    }
}

#[cfg(test)]
mod tests {
    use super::{Block, Decimal};

    /// CAM programs are millions of blocks: the memory budget (≤ 2× the file) depends on this.
    #[test]
    fn blocks_stay_small() {
        assert!(std::mem::size_of::<Block>() <= 40, "Block is {}", std::mem::size_of::<Block>());
    }

    /// The packed decimal reads back exactly as the general number reader reads its text.
    #[test]
    fn decimals_read_as_the_number_reader_does() {
        for (text, negative, m, e) in [
            ("-12.5000", true, 125_000, 4),
            ("+0.1", false, 1, 1),
            ("-0", true, 0, 0),
            ("+134217727", false, 134_217_727, 0),
            ("0.000000000000003", false, 3, 15),
            ("9.99999", false, 999_999, 5),
        ] {
            let want = crate::number::parse_f64(text).map(f64::to_bits);
            assert_eq!(Some(Decimal::new(negative, m, e).value().to_bits()), want, "{text}");
        }
    }
}
