//! Q parameters: formulas, FN maths, conditional jumps and the labels they jump to.

use serde::Serialize;

use crate::plane::Value;

/// The numeric parameters share one index space in the AST (`Value::Param`, `Expr::Param`, a
/// Q target, the simulator's table): `Q n` is `n`, `QL n` (local to the program) is
/// `QL_BASE + n`, `QR n` (remanent) is `QR_BASE + n`. The control numbers Q0…Q1999,
/// QL0…QL499 and QR0…QR499 (TNC 640 user's manual, "Q parameters"), so plain indices stay far
/// below `QL_BASE`; the parser refuses a larger one. The simulator treats all three kinds the
/// same (a run is one program from the start).
pub const QL_BASE: u32 = 1_000_000;
/// See [`QL_BASE`].
pub const QR_BASE: u32 = 2_000_000;

/// A parameter index written as the program writes it (`Q5`, `QL5`, `QR5`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct QName(pub u32);

impl QName {
    /// `("QL", 5)` for `QL5`.
    #[must_use]
    pub fn parts(self) -> (&'static str, u32) {
        match self.0 {
            n if n >= QR_BASE => ("QR", n - QR_BASE),
            n if n >= QL_BASE => ("QL", n - QL_BASE),
            n => ("Q", n),
        }
    }
}

impl std::fmt::Display for QName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (kind, n) = self.parts();
        write!(f, "{kind}{n}")
    }
}

/// `FN 1: ADDITION` … `FN 5: SQUARE ROOT` (`FN 4: Q4 = +8 DIV +Q2`, `FN 5: Q20 = SQRT 4`) and
/// the trigonometric `FN 6: SINE`, `FN 7: COSINE` (degrees) and `FN 8: ROOT SUM OF SQUARES`
/// (`Q10 = +5 LEN +4`) of the TNC manuals' Q parameter chapter. (`FN 13: ANGLE` is not
/// modelled: which operand is the sine the sources at hand do not say.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum FnOp {
    Add,
    Sub,
    Mul,
    Div,
    Sqrt,
    Sin,
    Cos,
    Len,
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
            FnOp::Sin => 6,
            FnOp::Cos => 7,
            FnOp::Len => 8,
        }
    }

    /// The operation of FN number `n`.
    #[must_use]
    pub fn of(n: u32) -> Option<FnOp> {
        Some(match n {
            1 => FnOp::Add,
            2 => FnOp::Sub,
            3 => FnOp::Mul,
            4 => FnOp::Div,
            5 => FnOp::Sqrt,
            6 => FnOp::Sin,
            7 => FnOp::Cos,
            8 => FnOp::Len,
            _ => return None,
        })
    }

    /// Takes one operand, written after the word (`SQRT a`, `SIN a`).
    #[must_use]
    pub fn unary(self) -> bool {
        matches!(self, FnOp::Sqrt | FnOp::Sin | FnOp::Cos)
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
            FnOp::Sin => "SIN",
            FnOp::Cos => "COS",
            FnOp::Len => "LEN",
        }
    }
}

/// `FN n: Q<target> = a op b`; the unary ones have only `a` (`SQRT a`).
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

/// `FN 18: SYSREAD Q32 = ID270 NR1 IDX3`: a datum of the control read into a parameter
/// (iTNC 530 technical manual, "Data transfer NC > NC program (FN18: SYSREAD)": group `ID`,
/// system data number `NR`, index `IDX`, each a number or a Q parameter).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SysRead {
    pub target: u32,
    pub id: u32,
    pub nr: Value,
    pub idx: Option<Value>,
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
