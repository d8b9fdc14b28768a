//! The typed syntax tree of a Klartext program: what was written, block by block, not what the
//! machine would do (that is the interpreter's job). Spans, lines and columns are left out of
//! `PartialEq`, so two programs compare equal when they say the same thing.

use serde::Serialize;

use crate::plane::{Feed, PlaneBlock, Sign, Value};

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

/// Tool radius compensation `R0`, `RL`, `RR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum RadiusComp {
    R0,
    Rl,
    Rr,
}

/// A straight line `L X… Y… Z… A… R0 FMAX M91 M3`. Kept small and inline: CAM programs are
/// millions of these (memory budget in issue 3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Line {
    pub axes: Box<[AxisWord]>,
    pub comp: Option<RadiusComp>,
    pub feed: Option<Feed>,
    pub m: Box<[u32]>,
}

/// `PR…`/`PA…` of a polar block, `IPR`/`IPA` incremental.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PolarWord {
    pub value: Value,
    pub incremental: bool,
}

/// Words of the arc and polar path blocks (`CC`, `C`, `CR`, `CT`, `LP`, `CP`); which of them a
/// block may carry depends on its kind.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Motion {
    pub axes: Box<[AxisWord]>,
    pub polar_radius: Option<PolarWord>,
    pub polar_angle: Option<PolarWord>,
    /// `R…` of `CR`.
    pub radius: Option<Value>,
    /// `DR+` / `DR-`: direction of rotation.
    pub direction: Option<Sign>,
    pub comp: Option<RadiusComp>,
    pub feed: Option<Feed>,
    pub m: Box<[u32]>,
}

/// `FN 1: ADDITION` … `FN 5: SQUARE ROOT` (`FN 4: Q4 = +8 DIV +Q2`, `FN 5: Q20 = SQRT 4`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum FnOp {
    Add,
    Sub,
    Mul,
    Div,
    Sqrt,
}

impl FnOp {
    /// The FN number.
    #[must_use]
    pub fn number(self) -> u32 {
        match self {
            FnOp::Add => 1,
            FnOp::Sub => 2,
            FnOp::Mul => 3,
            FnOp::Div => 4,
            FnOp::Sqrt => 5,
        }
    }

    /// The operator word as the control writes it between the operands (`SQRT` before the one).
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            FnOp::Add => "+",
            FnOp::Sub => "-",
            FnOp::Mul => "*",
            FnOp::Div => "DIV",
            FnOp::Sqrt => "SQRT",
        }
    }
}

/// `FN n: Q<target> = a op b`; `FN 5` has only `a` (`SQRT a`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FnMath {
    pub op: FnOp,
    pub target: u32,
    pub a: Value,
    pub b: Option<Value>,
}

/// The condition of a jump: `FN 9` EQU, `FN 10` NE, `FN 11` GT, `FN 12` LT.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum JumpIf {
    Equ,
    Ne,
    Gt,
    Lt,
}

impl JumpIf {
    #[must_use]
    pub fn number(self) -> u32 {
        match self {
            JumpIf::Equ => 9,
            JumpIf::Ne => 10,
            JumpIf::Gt => 11,
            JumpIf::Lt => 12,
        }
    }

    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            JumpIf::Equ => "EQU",
            JumpIf::Ne => "NE",
            JumpIf::Gt => "GT",
            JumpIf::Lt => "LT",
        }
    }

    /// Whether the jump is taken for the values `a`, `b`.
    #[must_use]
    pub fn holds(self, a: f64, b: f64) -> bool {
        match self {
            JumpIf::Equ => a == b,
            JumpIf::Ne => a != b,
            JumpIf::Gt => a > b,
            JumpIf::Lt => a < b,
        }
    }
}

/// `FN 12: IF +Q25 LT +Q35 GOTO LBL 2`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FnJump {
    pub condition: JumpIf,
    pub a: Value,
    pub b: Value,
    pub label: Label,
}

/// The path of an approach or departure: `LT` straight tangential, `LN` straight perpendicular,
/// `CT` arc tangential, `LCT` arc tangential to the contour and a straight line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum ApprKind {
    Lt,
    Ln,
    Ct,
    Lct,
}

impl ApprKind {
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            ApprKind::Lt => "LT",
            ApprKind::Ln => "LN",
            ApprKind::Ct => "CT",
            ApprKind::Lct => "LCT",
        }
    }
}

/// `APPR CT X+10 Y+20 Z-10 CCA180 R+10 RR F100`, `DEP LT LEN12.5 F100`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ApprDep {
    pub kind: ApprKind,
    /// APPR: the first contour point; DEP LCT: the end point.
    pub axes: Box<[AxisWord]>,
    /// `LEN`: distance to the auxiliary point (LT, LN).
    pub len: Option<Value>,
    /// `CCA`: central angle of the arc (CT).
    pub cca: Option<Value>,
    /// `R`: radius of the arc (CT, LCT).
    pub radius: Option<Value>,
    pub comp: Option<RadiusComp>,
    pub feed: Option<Feed>,
    pub m: Box<[u32]>,
}

/// What a `PATTERN DEF` item defines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum PatternKind {
    /// `POS1 (X… Y… Z…)`: one point.
    Pos,
    /// `ROW1 (X… Y… D… NUM… ROT… Z…)`: points on a line.
    Row,
    /// `PAT1 (X… Y… DX… DY… NUMX… NUMY… ROT… ROTX… ROTY… Z…)`: a grid.
    Pat,
    /// `FRAME1 (…)`: the edge points of a grid, words as `PAT`.
    Frame,
    /// `CIRC1 (X… Y… D… START… NUM… Z…)`: a full circle.
    Circ,
    /// `PITCHCIRC1 (X… Y… D… START… STEP… NUM… Z…)`: a pitch circle.
    PitchCirc,
}

impl PatternKind {
    pub const ALL: [PatternKind; 6] = [
        PatternKind::PitchCirc,
        PatternKind::Circ,
        PatternKind::Frame,
        PatternKind::Pat,
        PatternKind::Pos,
        PatternKind::Row,
    ];

    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            PatternKind::Pos => "POS",
            PatternKind::Row => "ROW",
            PatternKind::Pat => "PAT",
            PatternKind::Frame => "FRAME",
            PatternKind::Circ => "CIRC",
            PatternKind::PitchCirc => "PITCHCIRC",
        }
    }

    /// The words the item takes, in the order the control writes them.
    #[must_use]
    pub fn keys(self) -> &'static [PatternKey] {
        use PatternKey::*;
        match self {
            PatternKind::Pos => &[X, Y, Z],
            PatternKind::Row => &[X, Y, D, Num, Rot, Z],
            PatternKind::Pat | PatternKind::Frame => &[X, Y, Dx, Dy, NumX, NumY, Rot, RotX, RotY, Z],
            PatternKind::Circ => &[X, Y, D, Start, Num, Z],
            PatternKind::PitchCirc => &[X, Y, D, Start, Step, Num, Z],
        }
    }
}

/// A word inside a `PATTERN DEF` item.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum PatternKey {
    X,
    Y,
    Z,
    D,
    Dx,
    Dy,
    Num,
    NumX,
    NumY,
    Rot,
    RotX,
    RotY,
    Start,
    Step,
}

impl PatternKey {
    /// Longest first, so that a prefix never shadows a longer word (`NUMX` before `NUM`).
    pub const BY_LENGTH: [PatternKey; 14] = [
        PatternKey::Start,
        PatternKey::NumX,
        PatternKey::NumY,
        PatternKey::RotX,
        PatternKey::RotY,
        PatternKey::Step,
        PatternKey::Num,
        PatternKey::Rot,
        PatternKey::Dx,
        PatternKey::Dy,
        PatternKey::D,
        PatternKey::X,
        PatternKey::Y,
        PatternKey::Z,
    ];

    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            PatternKey::X => "X",
            PatternKey::Y => "Y",
            PatternKey::Z => "Z",
            PatternKey::D => "D",
            PatternKey::Dx => "DX",
            PatternKey::Dy => "DY",
            PatternKey::Num => "NUM",
            PatternKey::NumX => "NUMX",
            PatternKey::NumY => "NUMY",
            PatternKey::Rot => "ROT",
            PatternKey::RotX => "ROTX",
            PatternKey::RotY => "ROTY",
            PatternKey::Start => "START",
            PatternKey::Step => "STEP",
        }
    }
}

/// One item of `PATTERN DEF`: `POS1 (X+25 Y+33.5 Z+0)`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PatternItem {
    pub kind: PatternKind,
    /// The number after the keyword (`POS1` → 1).
    pub index: u32,
    /// The words in the order written.
    pub words: Box<[(PatternKey, Value)]>,
}

impl PatternItem {
    /// The value of a word, if written.
    #[must_use]
    pub fn get(&self, key: PatternKey) -> Option<Value> {
        self.words.iter().find(|(k, _)| *k == key).map(|(_, v)| *v)
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

/// `CYCL DEF 200 BOHREN ~` plus parameter lines.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleDef {
    pub number: u32,
    /// The cycle name as written (`BOHREN`, `PLANFRAESEN`); may be empty.
    pub name: String,
    pub params: Vec<CycleParam>,
}

/// One continuation line `Q200=+2 ;SICHERHEITS-ABST.`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleParam {
    pub index: u32,
    pub value: Value,
    /// The text after `;` without the trailing `~`; a label only, the control ignores it.
    pub label: Option<String>,
}

/// Old-style cycle block `CYCL DEF 7.1 X+10`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleDefOld {
    pub number: u32,
    /// The digit after the dot: `0` for the header with the name.
    pub sub: u32,
    pub data: OldCycleData,
}

/// Contents of an old-style cycle block.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum OldCycleData {
    /// `x.0` header: the cycle name.
    Name(String),
    /// Words of cycles 7, 8, 10, 11, 19 (`X+10`, `ROT+45`, `SCL 0.5`, `F…`, mirror axis `X`).
    Words(Vec<OldCycleWord>),
    /// Any other sub-block (`1.1 ABST 2`), kept verbatim.
    Text(String),
}

/// One word of an old-style cycle sub-block.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum OldCycleWord {
    Axis(AxisWord),
    /// A bare axis letter (cycle 8 mirror).
    MirrorAxis(Axis),
    Rot {
        value: Value,
        incremental: bool,
    },
    Scl(Value),
    Feed(Value),
}

/// `LBL 1`, `LBL "name"`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub enum Label {
    Number(u32),
    Name(String),
}

/// A Q parameter formula (`Q36 = TAN Q8 * Q9`). Parentheses are not kept: the tree says what
/// they meant, the formatter writes back the ones that are needed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Expr {
    /// A number; a sign written before a number is folded into it.
    Num(f64),
    Param(u32),
    Pi,
    Neg(Box<Expr>),
    Func(Func, Box<Expr>),
    Bin(BinOp, Box<Expr>, Box<Expr>),
}

/// Binary operators of Q formulas.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

/// Functions of Q formulas (applied to the operand that follows).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Sq,
    Abs,
    Int,
    Frac,
    Ln,
    Log,
    Exp,
    Sgn,
}

impl Func {
    pub const ALL: [Func; 15] = [
        Func::Asin,
        Func::Acos,
        Func::Atan,
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Sqrt,
        Func::Sq,
        Func::Abs,
        Func::Int,
        Func::Frac,
        Func::Ln,
        Func::Log,
        Func::Exp,
        Func::Sgn,
    ];

    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Func::Sin => "SIN",
            Func::Cos => "COS",
            Func::Tan => "TAN",
            Func::Asin => "ASIN",
            Func::Acos => "ACOS",
            Func::Atan => "ATAN",
            Func::Sqrt => "SQRT",
            Func::Sq => "SQ",
            Func::Abs => "ABS",
            Func::Int => "INT",
            Func::Frac => "FRAC",
            Func::Ln => "LN",
            Func::Log => "LOG",
            Func::Exp => "EXP",
            Func::Sgn => "SGN",
        }
    }
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
