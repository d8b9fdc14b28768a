//! The typed syntax tree of a Klartext program: what was written, block by block, not what the
//! machine would do (that is the interpreter's job). Spans, lines and columns are left out of
//! `PartialEq`, so two programs compare equal when they say the same thing.

use serde::Serialize;

use crate::plane::{Feed, PlaneBlock, Value};

mod axes;
mod block;
mod cycles;
mod path;
mod q;

pub use axes::{Axis, AxisWord, AxisWords};
pub use block::Block;
pub(crate) use block::{CompactLine, Decimal, FEED_MAX, FEED_VALUE, HAS_NUMBER, SKIP};

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
