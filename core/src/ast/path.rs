//! Path blocks: straight lines, arcs and polar moves, radius compensation, approaching and
//! departing the contour.

use serde::Serialize;

use super::{AxisWord, AxisWords};
use crate::plane::{Feed, MoveBack, Sign, Value};

/// Tool radius compensation `R0`, `RL`, `RR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum RadiusComp {
    R0,
    Rl,
    Rr,
}

/// A straight line `L X… Y… Z… A… R0 FMAX M91 M3`. Its axis words are inline, so a compact
/// block's line is made without allocating (see [`super::Block::body`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Line {
    pub axes: AxisWords,
    pub comp: Option<RadiusComp>,
    pub feed: Option<Feed>,
    /// `S…`: a spindle speed in the block, as CAM posts and simulators write it (Klartext
    /// changes it with `TOOL CALL S…`; read leniently, [`crate::diag::Lenient::SpeedInPath`]).
    pub speed: Option<Value>,
    pub m: Box<[u32]>,
    pub m_words: MWords,
}

/// Words that belong to an M function rather than to the block: the retract of `M140`
/// (`M140 MB MAX`, `M140 MB+50`: "retraction in the tool axis direction", TNC 640 user's
/// manual), the feed of `M128` (`M128 F1000`: the largest feed of the compensating moves) and
/// the look-ahead of `M120` (`M120 LA5`: how many blocks a radius-compensated contour is
/// computed ahead, 0 to 99). Each is written right after its M function; the feed of the
/// retract right after `MB` (`M140 MB MAX F5000`, [`crate::unconfirmed::M140_FEED_AFTER_MB`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct MWords {
    pub mb: Option<MoveBack>,
    pub mb_feed: Option<Feed>,
    pub m128_feed: Option<Value>,
    pub look_ahead: Option<Value>,
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
    /// `S…`, as [`Line::speed`].
    pub speed: Option<Value>,
    pub m: Box<[u32]>,
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
