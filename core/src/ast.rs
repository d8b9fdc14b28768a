//! The typed syntax tree of a Klartext program: what was written, block by block, not what the
//! machine would do (that is the interpreter's job). Spans, lines and columns are left out of
//! `PartialEq`, so two programs compare equal when they say the same thing.

use std::borrow::Cow;
use std::fmt;

use serde::Serialize;

use crate::plane::{Feed, PlaneBlock, Value};

mod cycles;
mod path;
mod q;

pub use cycles::{
    CycleDef, CycleDefOld, CycleParam, CycleValue, OldCycleData, OldCycleWord, PatternItem, PatternKey,
    PatternKind,
};
pub use path::{ApprDep, ApprKind, Line, MWords, Motion, PolarWord, RadiusComp};
pub use q::{BinOp, Expr, FnJump, FnMath, FnOp, Func, JumpIf, Label, QL_BASE, QName, QR_BASE, SysRead};

pub use crate::span::Span;

/// A whole NC program (or a single block typed without frame).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Program {
    pub blocks: Vec<Block>,
}

/// One NC block: usually one line, a cycle definition also owns its `~` continuation lines.
///
/// Kept to 40 bytes, because CAM programs are millions of blocks (issue 16: the AST within the
/// file's size): offsets and line as `u32`, and the common straight line `L X… Y… Z… F…` in a
/// compact inline form ([`CompactLine`]); every other block is boxed ([`GeneralBlock`]). The
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

/// The axis words of a path block: up to three inline (a straight line is usually `X Y Z`), more
/// on the heap. Reads as a slice.
#[derive(Clone)]
pub struct AxisWords(Words);

#[derive(Clone)]
enum Words {
    Inline { len: u8, words: [AxisWord; 3] },
    Heap(Box<[AxisWord]>),
}

impl Default for AxisWords {
    fn default() -> Self {
        let none = AxisWord { axis: Axis::X, value: Value::Number(0.0), incremental: false };
        AxisWords(Words::Inline { len: 0, words: [none; 3] })
    }
}

impl AxisWords {
    /// Appends inline; only called with room left (at most three words).
    fn push(&mut self, word: AxisWord) {
        if let Words::Inline { len, words } = &mut self.0
            && let Some(slot) = words.get_mut(usize::from(*len))
        {
            *slot = word;
            *len += 1;
        }
    }
}

impl From<&[AxisWord]> for AxisWords {
    fn from(words: &[AxisWord]) -> Self {
        if words.len() <= 3 {
            let mut inline = AxisWords::default();
            words.iter().for_each(|&w| inline.push(w));
            inline
        } else {
            AxisWords(Words::Heap(words.into()))
        }
    }
}

impl From<Vec<AxisWord>> for AxisWords {
    fn from(words: Vec<AxisWord>) -> Self {
        AxisWords::from(&words[..])
    }
}

impl std::ops::Deref for AxisWords {
    type Target = [AxisWord];

    fn deref(&self) -> &[AxisWord] {
        match &self.0 {
            Words::Inline { len, words } => &words[..usize::from(*len)],
            Words::Heap(words) => words,
        }
    }
}

impl PartialEq for AxisWords {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl fmt::Debug for AxisWords {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        (**self).fmt(f)
    }
}

impl Serialize for AxisWords {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        (**self).serialize(ser)
    }
}

/// What a block says.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum BlockBody {
    /// `BEGIN PGM name MM|INCH`.
    BeginPgm {
        name: String,
        unit: Unit,
    },
    /// `END PGM name MM|INCH`.
    EndPgm {
        name: String,
        unit: Unit,
    },
    /// Nothing but (maybe) a comment: `1 ;`, `4 ; text`.
    Empty,
    /// Structure item `* - text`; `text` is everything after the `*`, trimmed.
    Structure {
        text: String,
    },
    /// `BLK FORM 0.1 Z X… Y… Z…` / `BLK FORM 0.2 [I]X… …`.
    BlkForm(Box<BlkForm>),
    /// `TOOL CALL n|"name" Z S… F… DL… DR…`.
    ToolCall(Box<ToolCall>),
    /// Straight line `L`.
    L(Line),
    /// `CC`: circle centre / pole.
    Cc(Box<Motion>),
    /// `C`: circle around CC.
    C(Box<Motion>),
    /// `CR`: circle with radius.
    Cr(Box<Motion>),
    /// `CT`: tangential circle.
    Ct(Box<Motion>),
    /// `LP`: polar straight line.
    Lp(Box<Motion>),
    /// `CP`: polar circle.
    Cp(Box<Motion>),
    /// `RND R…`: rounding.
    Rnd {
        radius: Value,
        feed: Option<Feed>,
    },
    /// `CHF …`: chamfer.
    Chf {
        length: Value,
        feed: Option<Feed>,
    },
    /// A block of only M functions (`M30`, `M99`, `M140 MB MAX`).
    MFunctions(Box<[u32]>, MWords),
    /// New-style `CYCL DEF 200 BOHREN ~` with its `Q…=` continuation lines.
    CycleDef(Box<CycleDef>),
    /// Old-style cycle with sub-numbers: `CYCL DEF 7.0 NULLPUNKT`, `CYCL DEF 7.1 X+10`.
    CycleDefOld(Box<CycleDefOld>),
    /// `CYCL CALL [F…] [M…]`.
    CyclCall {
        m: Box<[u32]>,
    },
    /// `CYCL CALL PAT [F…] [M…]`: the cycle at every point of the last `PATTERN DEF`.
    CyclCallPat {
        feed: Option<Feed>,
        m: Box<[u32]>,
    },
    /// `CYCL CALL POS X… Y… Z… [FMAX|F…] [M…]`: the cycle at this position.
    CyclCallPos(Box<Line>),
    /// `PATTERN DEF POS1 (…) ROW1 (…) …`: machining positions for `CYCL CALL PAT`.
    PatternDef(Box<[PatternItem]>),
    /// `APPR LT|LN|CT|LCT …`: approach the contour.
    Appr(Box<ApprDep>),
    /// `DEP LT|LN|CT|LCT …`: depart from the contour.
    Dep(Box<ApprDep>),
    Plane(Box<PlaneBlock>),
    /// `TRANS DATUM AXIS X… Y… Z…`.
    TransDatum {
        axes: Box<[AxisWord]>,
    },
    TransDatumReset,
    /// `TRANS MIRROR AXIS X Y`.
    TransMirror {
        axes: Box<[Axis]>,
    },
    TransMirrorReset,
    /// `TRANS ROTATION ROT…` (`IROT` incremental).
    TransRotation {
        rot: Value,
        incremental: bool,
    },
    TransRotationReset,
    /// `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS`: TCPM on, with its three modes.
    FunctionTcpm(Tcpm),
    /// `FUNCTION RESET TCPM`.
    FunctionResetTcpm,
    /// `LBL n|"name"`; `LBL 0` ends a subprogram.
    Lbl(Label),
    /// `CALL LBL n [REP m]`.
    CallLbl {
        label: Label,
        /// `REP n`, or `REP Q…` ([`crate::unconfirmed::REP_FROM_PARAMETER`]).
        rep: Option<Value>,
    },
    /// `CALL PGM path`.
    CallPgm {
        path: String,
    },
    /// `Q1 = expr` or `FN 0: Q1 = value`.
    QAssign {
        target: u32,
        expr: Expr,
        fn0: bool,
    },
    /// `FN 1..5: Q… = a op b`: the arithmetic functions.
    FnMath(Box<FnMath>),
    /// `FN 9..12: IF a EQU|NE|GT|LT b GOTO LBL …`: conditional jumps.
    FnJump(Box<FnJump>),
    /// `TOOL DEF n [L…] [R…]`: a tool defined in the program (older programs and CAM output);
    /// a later `TOOL CALL n` takes its length and radius instead of the tool table's.
    ToolDef {
        tool: ToolRef,
        length: Option<Value>,
        radius: Option<Value>,
    },
    /// `STOP [M…]`: the program run stops until NC start.
    Stop {
        m: Box<[u32]>,
    },
    /// `QS n = …`: a string parameter (kept verbatim after the `=`; strings are not simulated).
    QsAssign {
        index: u32,
        text: String,
    },
    /// `TCH PROBE n name ~` with its `Q…=` lines: a touch-probe cycle (not simulated, kept as a
    /// cycle definition so its parameters are read and written back).
    TouchProbe(Box<CycleDef>),
    /// A line in parentheses before `BEGIN PGM`, as a training simulator writes its setup
    /// sheet (machine, blank, tool list): the program's header, shown as it is.
    Header {
        text: String,
    },
    /// `FN 18: SYSREAD Q… = ID… NR… [IDX…]`.
    SysRead(Box<SysRead>),
    /// `FN n: …` of a function this trainer does not compute (`FN 14: ERROR`, `FN 15: PRINT`,
    /// `FN 16: F-PRINT`, `FN 18: SYSREAD`, `FN 19: PLC`, …): the text after the colon, verbatim.
    /// The run says so on the block; `FN 14` stops it, as the control's error message does.
    FnOther {
        number: u32,
        text: String,
    },
    /// A well-formed block of a kind this trainer does not model (kept verbatim, with a warning).
    Unknown {
        text: String,
    },
    /// A block that could not be read (kept verbatim, with an error).
    Invalid {
        text: String,
    },
}

/// `MM` or `INCH`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Unit {
    Mm,
    Inch,
}

impl Unit {
    /// Millimetres per length unit of the program (an inch is 25.4 mm by definition).
    #[must_use]
    pub const fn mm(self) -> f64 {
        match self {
            Unit::Mm => 1.0,
            Unit::Inch => 25.4,
        }
    }

    /// mm/min per unit of a programmed feed F ([`crate::unconfirmed::INCH_FEED_MM_PER_MIN`]).
    #[must_use]
    pub const fn feed_mm_per_min(self) -> f64 {
        match self {
            Unit::Mm => 1.0,
            Unit::Inch => crate::unconfirmed::INCH_FEED_MM_PER_MIN,
        }
    }
}

/// Linear and rotary axis letters as written in path blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum Axis {
    X,
    Y,
    Z,
    A,
    B,
    C,
    U,
    V,
    W,
}

impl Axis {
    /// All axes in the order the control writes them.
    pub const ALL: [Axis; 9] =
        [Axis::X, Axis::Y, Axis::Z, Axis::A, Axis::B, Axis::C, Axis::U, Axis::V, Axis::W];

    #[must_use]
    pub fn from_byte(b: u8) -> Option<Axis> {
        Some(match b {
            b'X' => Axis::X,
            b'Y' => Axis::Y,
            b'Z' => Axis::Z,
            b'A' => Axis::A,
            b'B' => Axis::B,
            b'C' => Axis::C,
            b'U' => Axis::U,
            b'V' => Axis::V,
            b'W' => Axis::W,
            _ => return None,
        })
    }

    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Axis::X => "X",
            Axis::Y => "Y",
            Axis::Z => "Z",
            Axis::A => "A",
            Axis::B => "B",
            Axis::C => "C",
            Axis::U => "U",
            Axis::V => "V",
            Axis::W => "W",
        }
    }
}

/// `X+10`, `IX-5`, `A+Q120`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxisWord {
    pub axis: Axis,
    pub value: Value,
    /// Written with a leading `I` (incremental).
    pub incremental: bool,
}

/// The modes of `FUNCTION TCPM`, each always written (the control's dialog asks for all three).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Tcpm {
    pub feed: TcpmFeed,
    pub axis: TcpmAxis,
    pub path: PathCtrl,
}

/// How the programmed feed rate acts under `FUNCTION TCPM`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum TcpmFeed {
    /// `F TCP`: the relative speed of the tool tip to the workpiece.
    Tcp,
    /// `F CONT`: the contouring feed rate of the axes programmed in the block.
    Cont,
}

/// What the rotary axis coordinates of a block mean under `FUNCTION TCPM`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum TcpmAxis {
    /// `AXIS POS`: axis angles (as with `M128`).
    Pos,
    /// `AXIS SPAT`: spatial angles.
    Spat,
}

/// How `FUNCTION TCPM` interpolates between start and target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum PathCtrl {
    /// `PATHCTRL AXIS`: the rotary axes linear in time.
    Axis,
    /// `PATHCTRL VECTOR`: the tool axis in the plane of its start and end orientation.
    Vector,
}

impl Tcpm {
    /// The three mode words as the control writes them (`F TCP AXIS POS PATHCTRL AXIS`).
    #[must_use]
    pub fn words(self) -> [&'static str; 3] {
        [
            match self.feed {
                TcpmFeed::Tcp => "F TCP",
                TcpmFeed::Cont => "F CONT",
            },
            match self.axis {
                TcpmAxis::Pos => "AXIS POS",
                TcpmAxis::Spat => "AXIS SPAT",
            },
            match self.path {
                PathCtrl::Axis => "PATHCTRL AXIS",
                PathCtrl::Vector => "PATHCTRL VECTOR",
            },
        ]
    }
}

/// `BLK FORM 0.1 Z X… Y… Z…` (MIN point, with the tool axis) or `0.2 …` (MAX point).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlkForm {
    /// `1` for `0.1`, `2` for `0.2`.
    pub part: u8,
    /// The tool axis, written only in `0.1`.
    pub tool_axis: Option<Axis>,
    pub axes: Box<[AxisWord]>,
}

/// Which tool `TOOL CALL` selects.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ToolRef {
    Number(u32),
    Name(String),
    /// `TOOL CALL Q5`: the number is the parameter's value (index as [`QName`]).
    Param(u32),
    /// `TOOL CALL QS5`: the name is the string parameter's text.
    StringParam(u32),
}

/// `TOOL CALL n|"name" Z S… F… DL… DR… DR2…`.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct ToolCall {
    pub tool: Option<ToolRef>,
    pub axis: Option<Axis>,
    pub speed: Option<Value>,
    pub feed: Option<Value>,
    pub dl: Option<Value>,
    pub dr: Option<Value>,
    pub dr2: Option<Value>,
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
