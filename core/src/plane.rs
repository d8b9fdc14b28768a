//! The PLANE function family as written in a Klartext block, shared by the parser (which
//! produces it), the orientation maths and the solver (which consume it).
//!
//! Grammar sketch (DOMAIN.md §5, seeds S0/S1):
//!   PLANE \<def> [MOVE [DIST d] [F…] | TURN [MB d|MB MAX] [F…|F AUTO|FMAX] | STAY]
//!         [SEQ±|SYM±] [COORD ROT|TABLE ROT]
//!
//! Every type is generic over the value `V`: the parser writes [`crate::plane::Value`]
//! (a number or a Q parameter), the interpreter resolves Q parameters to `f64`
//! with [`PlaneBlock::try_map`] before the maths sees it.

use serde::{Deserialize, Serialize};

mod slots;
mod words;

pub use slots::{PlaneKind, PlaneSlots};
pub use words::{FEED_LIMIT, InputRange, PROJECTED_LIMIT, SPATIAL_LIMIT, Word, check, input_range};

/// A number as written, or a Q parameter standing where a number may stand (`SPB+Q27`, `A-Q120`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Value {
    Number(f64),
    /// `Q<index>`, negated when written `-Q<index>`.
    Param {
        index: u32,
        negate: bool,
    },
}

/// `+` or `-` in `SEQ+`, `SYM-`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Sign {
    Plus,
    Minus,
}

/// The axis of a one-angle `PLANE RELATIV` block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum RelAxis {
    Spa,
    Spb,
    Spc,
}

/// A machine rotary axis letter as programmed in `PLANE AXIAL` and `L A… B… C…`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum RotaryAxis {
    A,
    B,
    C,
}

/// How the working plane is defined (the word after `PLANE`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum PlaneDef<V = Value> {
    /// `SPATIAL SPA SPB SPC`: rotations about the fixed W-CS axes, order A, B, C.
    Spatial { spa: V, spb: V, spc: V },
    /// `PROJECTED PROPR PROMIN ROT`.
    Projected { propr: V, promin: V, rot: V },
    /// `EULER EULPR EULNU EULROT`: Z, X', Z''.
    Euler { eulpr: V, eulnu: V, eulrot: V },
    /// `VECTOR BX BY BZ NX NY NZ`: base vector (tilted X) and normal vector (tool axis).
    Vector { base: [V; 3], normal: [V; 3] },
    /// `POINTS P1X P1Y P1Z P2X … P3Z`.
    Points { p1: [V; 3], p2: [V; 3], p3: [V; 3] },
    /// `RELATIV SPA|SPB|SPC`: one incremental spatial angle about the active tilted axis.
    Relativ { axis: RelAxis, angle: V },
    /// `AXIAL A… B… C…`: machine axis angles directly; `incremental` for `IA…`.
    Axial { axes: Vec<AxialAngle<V>> },
    /// `RESET`: cancel the tilt.
    Reset,
}

/// One axis word of `PLANE AXIAL`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AxialAngle<V = Value> {
    pub axis: RotaryAxis,
    pub value: V,
    pub incremental: bool,
}

/// Feed of a swivel: `F…`, `FMAX` (also written `F MAX`), `F AUTO`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Feed<V = Value> {
    Value(V),
    Max,
    Auto,
}

/// `MB d` or `MB MAX`: retract along the tool axis before a TURN swivel.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum MoveBack<V = Value> {
    Dist(V),
    Max,
}

/// Positioning behaviour (Positionierverhalten), DOMAIN.md §4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Positioning<V = Value> {
    /// Rotary and linear axes together, tool tip kept relative to the workpiece.
    Move { dist: Option<V>, feed: Option<Feed<V>> },
    /// Only the rotary axes move.
    Turn { move_back: Option<MoveBack<V>>, feed: Option<Feed<V>> },
    /// Only the coordinate system tilts; the axes are positioned later (Q120–Q122).
    Stay,
}

/// `SEQ±` (relative to the master axis' home) or `SYM±` (relative to its symmetry point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Selection {
    Seq(Sign),
    Sym(Sign),
}

/// `COORD ROT` (rotate mathematically) or `TABLE ROT` (turn the free table axis).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TransformMode {
    CoordRot,
    TableRot,
}

impl TransformMode {
    /// The mode when the block programs neither ([`crate::unconfirmed::DEFAULT_TABLE_ROT`]).
    #[must_use]
    pub const fn unprogrammed() -> TransformMode {
        if crate::unconfirmed::DEFAULT_TABLE_ROT { TransformMode::TableRot } else { TransformMode::CoordRot }
    }
}

/// A whole `PLANE …` block body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlaneBlock<V = Value> {
    pub def: PlaneDef<V>,
    /// `None` only where the control allows it to be left out (never for a complete block
    /// written by the dialog; the parser reports a missing one).
    pub positioning: Option<Positioning<V>>,
    pub selection: Option<Selection>,
    pub transform: Option<TransformMode>,
}

impl<V> PlaneBlock<V> {
    /// Converts every value, stopping at the first error (e.g. an undefined Q parameter).
    pub fn try_map<W, E>(&self, mut f: impl FnMut(&V) -> Result<W, E>) -> Result<PlaneBlock<W>, E> {
        let mut feed = |x: &Feed<V>| -> Result<Feed<W>, E> {
            Ok(match x {
                Feed::Value(v) => Feed::Value(f(v)?),
                Feed::Max => Feed::Max,
                Feed::Auto => Feed::Auto,
            })
        };
        let positioning = match &self.positioning {
            None => None,
            Some(Positioning::Stay) => Some(Positioning::Stay),
            Some(Positioning::Move { dist, feed: fd }) => {
                let fd = fd.as_ref().map(&mut feed).transpose()?;
                Some(Positioning::Move { dist: dist.as_ref().map(&mut f).transpose()?, feed: fd })
            }
            Some(Positioning::Turn { move_back, feed: fd }) => {
                let fd = fd.as_ref().map(&mut feed).transpose()?;
                let move_back = match move_back {
                    None => None,
                    Some(MoveBack::Max) => Some(MoveBack::Max),
                    Some(MoveBack::Dist(d)) => Some(MoveBack::Dist(f(d)?)),
                };
                Some(Positioning::Turn { move_back, feed: fd })
            }
        };
        Ok(PlaneBlock {
            def: self.def.try_map(f)?,
            positioning,
            selection: self.selection,
            transform: self.transform,
        })
    }
}

impl PlaneBlock<Value> {
    /// The block with numbers only; `Err(index)` names the first Q parameter, which has no value
    /// outside a program run.
    ///
    /// # Errors
    /// A value is a Q parameter.
    pub fn numbers(&self) -> Result<PlaneBlock<f64>, u32> {
        self.try_map(|v| match v {
            Value::Number(x) => Ok(*x),
            Value::Param { index, .. } => Err(*index),
        })
    }
}

impl<V> PlaneDef<V> {
    /// Converts every value, stopping at the first error.
    pub fn try_map<W, E>(&self, mut f: impl FnMut(&V) -> Result<W, E>) -> Result<PlaneDef<W>, E> {
        fn v3<V, W, E>(a: &[V; 3], f: &mut impl FnMut(&V) -> Result<W, E>) -> Result<[W; 3], E> {
            Ok([f(&a[0])?, f(&a[1])?, f(&a[2])?])
        }
        Ok(match self {
            PlaneDef::Spatial { spa, spb, spc } => {
                PlaneDef::Spatial { spa: f(spa)?, spb: f(spb)?, spc: f(spc)? }
            }
            PlaneDef::Projected { propr, promin, rot } => {
                PlaneDef::Projected { propr: f(propr)?, promin: f(promin)?, rot: f(rot)? }
            }
            PlaneDef::Euler { eulpr, eulnu, eulrot } => {
                PlaneDef::Euler { eulpr: f(eulpr)?, eulnu: f(eulnu)?, eulrot: f(eulrot)? }
            }
            PlaneDef::Vector { base, normal } => {
                PlaneDef::Vector { base: v3(base, &mut f)?, normal: v3(normal, &mut f)? }
            }
            PlaneDef::Points { p1, p2, p3 } => {
                PlaneDef::Points { p1: v3(p1, &mut f)?, p2: v3(p2, &mut f)?, p3: v3(p3, &mut f)? }
            }
            PlaneDef::Relativ { axis, angle } => PlaneDef::Relativ { axis: *axis, angle: f(angle)? },
            PlaneDef::Axial { axes } => PlaneDef::Axial {
                axes: axes
                    .iter()
                    .map(|a| Ok(AxialAngle { axis: a.axis, value: f(&a.value)?, incremental: a.incremental }))
                    .collect::<Result<_, E>>()?,
            },
            PlaneDef::Reset => PlaneDef::Reset,
        })
    }
}

impl RelAxis {
    /// The three in the order A, B, C (about X, Y, Z).
    pub const ALL: [RelAxis; 3] = [RelAxis::Spa, RelAxis::Spb, RelAxis::Spc];

    /// The W-CS axis the spatial angle turns about (SPA about X, SPB about Y, SPC about Z;
    /// DOMAIN.md §2.1): `X`, `Y` or `Z`.
    #[must_use]
    pub fn about(self) -> &'static str {
        match self {
            RelAxis::Spa => "X",
            RelAxis::Spb => "Y",
            RelAxis::Spc => "Z",
        }
    }

    /// The unit vector of [`RelAxis::about`].
    #[must_use]
    pub fn unit(self) -> glam::DVec3 {
        match self {
            RelAxis::Spa => glam::DVec3::X,
            RelAxis::Spb => glam::DVec3::Y,
            RelAxis::Spc => glam::DVec3::Z,
        }
    }

    /// `SPA`, `SPB` or `SPC`.
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            RelAxis::Spa => "SPA",
            RelAxis::Spb => "SPB",
            RelAxis::Spc => "SPC",
        }
    }
}

impl RotaryAxis {
    /// Its word in `PLANE AXIAL`.
    #[must_use]
    pub fn plane_word(self) -> Word {
        match self {
            RotaryAxis::A => Word::A,
            RotaryAxis::B => Word::B,
            RotaryAxis::C => Word::C,
        }
    }

    /// `A`, `B` or `C`.
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            RotaryAxis::A => "A",
            RotaryAxis::B => "B",
            RotaryAxis::C => "C",
        }
    }
}
