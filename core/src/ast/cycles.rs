//! Cycle definitions (new and old style) and `PATTERN DEF` points.

use serde::Serialize;

use super::{Axis, AxisWord};
use crate::plane::Value;

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

/// `CYCL DEF 200 BOHREN ~` plus parameter lines.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleDef {
    pub number: u32,
    /// The cycle name as written (`BOHREN`, `PLANFRAESEN`); may be empty.
    pub name: String,
    pub params: Vec<CycleParam>,
}

/// One continuation line `Q200=+2 ;SICHERHEITS-ABST.` (or `QS500="TEXT" ;…`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleParam {
    /// The parameter's number: `Q200` → 200, `QS500` → 500 (a [`CycleValue::Text`]).
    pub index: u32,
    pub value: CycleValue,
    /// The text after `;` without the trailing `~`; a label only, the control ignores it.
    pub label: Option<String>,
}

/// What stands after `Q…=` in a cycle definition: a number or Q parameter, or one of the words
/// the control's cycle dialog offers in its place (TNC 640 cycle manual, parameters such as
/// "Q253 F PRE-POSITIONING … alternatively FMAX, FAUTO, PREDEF").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum CycleValue {
    Value(Value),
    /// The text of a string parameter line `QS500="P2002-B8"` (cycle 225's text to engrave):
    /// only a `QS` parameter takes one, and it takes nothing else.
    Text(String),
    /// `QS500=QS10`: a string parameter given the text of another (`QS10`), as a shop's
    /// engraving program sets its text first.
    TextOf(u32),
    /// `PREDEF`: the value of the global program settings (`GLOBAL DEF`).
    Predef,
    /// `FMAX`: rapid traverse.
    Fmax,
    /// `FAUTO` (CAM systems also write `AUTO`): the feed of the `TOOL CALL`.
    Fauto,
}

impl CycleValue {
    /// A string parameter's value (`QS…=`): a text or another string parameter's.
    #[must_use]
    pub fn is_text(&self) -> bool {
        matches!(self, CycleValue::Text(_) | CycleValue::TextOf(_))
    }

    /// The word as the control writes it; `None` for a number, a Q parameter or a text.
    #[must_use]
    pub fn word(&self) -> Option<&'static str> {
        match self {
            CycleValue::Value(_) | CycleValue::Text(_) | CycleValue::TextOf(_) => None,
            CycleValue::Predef => Some("PREDEF"),
            CycleValue::Fmax => Some("FMAX"),
            CycleValue::Fauto => Some("FAUTO"),
        }
    }
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
