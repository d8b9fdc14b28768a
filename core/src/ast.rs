//! The typed syntax tree of a Klartext program: what was written, block by block, not what the
//! machine would do (that is the interpreter's job). Spans, lines and columns are left out of
//! `PartialEq`, so two programs compare equal when they say the same thing.

use serde::Serialize;

use crate::plane::{Feed, PlaneBlock, Value};

mod cycles;
mod path;
mod q;

pub use cycles::{
    CycleDef, CycleDefOld, CycleParam, OldCycleData, OldCycleWord, PatternItem, PatternKey, PatternKind,
};
pub use path::{ApprDep, ApprKind, Line, Motion, PolarWord, RadiusComp};
pub use q::{BinOp, Expr, FnJump, FnMath, FnOp, Func, JumpIf, Label};

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

/// A whole NC program (or a single block typed without frame).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Program {
    pub blocks: Vec<Block>,
}

/// One NC block: usually one line, a cycle definition also owns its `~` continuation lines.
#[derive(Debug, Clone, Serialize)]
pub struct Block {
    /// The leading block number; `None` when it was left out (a single typed block).
    pub number: Option<u32>,
    /// A leading `/`: the block is skipped when block skip is on.
    pub skip: bool,
    pub body: BlockBody,
    /// Text after `;`, trimmed; `Some("")` for a bare `1 ;`.
    pub comment: Option<String>,
    /// Bytes of the block from its first non-blank character to the end of its last line.
    pub span: Span,
    /// 1-based line and column of the block's first character.
    pub line: u32,
    pub column: u32,
}

impl PartialEq for Block {
    fn eq(&self, other: &Self) -> bool {
        self.number == other.number
            && self.skip == other.skip
            && self.body == other.body
            && self.comment == other.comment
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
    /// A block of only M functions (`M30`, `M99`).
    MFunctions(Box<[u32]>),
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
    /// `LBL n|"name"`; `LBL 0` ends a subprogram.
    Lbl(Label),
    /// `CALL LBL n [REP m]`.
    CallLbl {
        label: Label,
        rep: Option<u32>,
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
    use super::{Block, BlockBody, Line};

    /// CAM programs are millions of blocks: the memory budget (≤ 6× the file) depends on these.
    #[test]
    fn blocks_stay_small() {
        assert!(std::mem::size_of::<Line>() <= 56, "Line is {}", std::mem::size_of::<Line>());
        assert!(std::mem::size_of::<BlockBody>() <= 56, "BlockBody is {}", std::mem::size_of::<BlockBody>());
        assert!(std::mem::size_of::<Block>() <= 120, "Block is {}", std::mem::size_of::<Block>());
    }
}
