//! The PLANE function family as written in a Klartext block, shared by the parser (which
//! produces it), the orientation maths and the solver (which consume it).
//!
//! Grammar sketch (DOMAIN.md §5, seeds S0/S1):
//!   PLANE <def> [MOVE [DIST d] [F…] | TURN [MB d|MB MAX] [F…|F AUTO|FMAX] | STAY]
//!         [SEQ±|SYM±] [COORD ROT|TABLE ROT]
//!
//! Every type is generic over the value `V`: the parser writes [`crate::plane::Value`]
//! (a number or a Q parameter), the interpreter resolves Q parameters to `f64`
//! with [`PlaneBlock::try_map`] before the maths sees it.

use serde::{Deserialize, Serialize};

use crate::diag::DiagCode;

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

/// Input range of a PLANE word and whether it is an angle (out of range: "Winkel nicht
/// erlaubt") or another value. One table for the parser and the softkey dialog.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputRange {
    pub min: f64,
    pub max: f64,
    pub angle: bool,
}

impl InputRange {
    /// Values are checked as written; a tolerance keeps `359.9999` itself inside.
    const EPS: f64 = 1e-9;

    #[must_use]
    pub fn contains(&self, x: f64) -> bool {
        x >= self.min - Self::EPS && x <= self.max + Self::EPS
    }
}

/// Input range of a spatial angle SPA/SPB/SPC on the iTNC 530 (DOMAIN.md §5, [M:iTNC-p494]);
/// PLANE RELATIV uses it too (UNCONFIRMED, DOMAIN.md §5 "probably ±359.9999").
pub const SPATIAL_LIMIT: f64 = 359.9999;
/// Input range of PROPR/PROMIN (DOMAIN.md §5, [M:iTNC-p496]).
pub const PROJECTED_LIMIT: f64 = 89.9999;
/// Feed rates: 0 to 99 999.999 mm/min (TNC 426/430 user's manual, "Technical Information",
/// input format of TNC functions, easymanua.ls/heidenhain/tnc-430/manual?p=494). A feed is
/// never negative.
pub const FEED_LIMIT: f64 = 99_999.999;

/// A word of the PLANE dialog that takes a number: the angles and components of the eight
/// functions (`IA`/`IB`/`IC` of AXIAL are [`Word::A`]…[`Word::C`] written incrementally) and
/// the positioning words `DIST`, `MB`, `F`. The parser and the dialog check a value with
/// [`check`], against the one table [`Word::range`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Word {
    Spa,
    Spb,
    Spc,
    Propr,
    Promin,
    Rot,
    Eulpr,
    Eulnu,
    Eulrot,
    Bx,
    By,
    Bz,
    Nx,
    Ny,
    Nz,
    P1x,
    P1y,
    P1z,
    P2x,
    P2y,
    P2z,
    P3x,
    P3y,
    P3z,
    A,
    B,
    C,
    /// MOVE: distance centre of rotation – tool tip.
    Dist,
    /// TURN: retract along the tool axis.
    Mb,
    /// The feed of the swivel.
    F,
}

impl Word {
    /// Every word, in the order of the PLANE functions and then MOVE/TURN.
    pub const ALL: [Word; 30] = [
        Word::Spa,
        Word::Spb,
        Word::Spc,
        Word::Propr,
        Word::Promin,
        Word::Rot,
        Word::Eulpr,
        Word::Eulnu,
        Word::Eulrot,
        Word::Bx,
        Word::By,
        Word::Bz,
        Word::Nx,
        Word::Ny,
        Word::Nz,
        Word::P1x,
        Word::P1y,
        Word::P1z,
        Word::P2x,
        Word::P2y,
        Word::P2z,
        Word::P3x,
        Word::P3y,
        Word::P3z,
        Word::A,
        Word::B,
        Word::C,
        Word::Dist,
        Word::Mb,
        Word::F,
    ];

    /// The NC word as written (`SPA`, `P2X`, `DIST`).
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Word::Spa => "SPA",
            Word::Spb => "SPB",
            Word::Spc => "SPC",
            Word::Propr => "PROPR",
            Word::Promin => "PROMIN",
            Word::Rot => "ROT",
            Word::Eulpr => "EULPR",
            Word::Eulnu => "EULNU",
            Word::Eulrot => "EULROT",
            Word::Bx => "BX",
            Word::By => "BY",
            Word::Bz => "BZ",
            Word::Nx => "NX",
            Word::Ny => "NY",
            Word::Nz => "NZ",
            Word::P1x => "P1X",
            Word::P1y => "P1Y",
            Word::P1z => "P1Z",
            Word::P2x => "P2X",
            Word::P2y => "P2Y",
            Word::P2z => "P2Z",
            Word::P3x => "P3X",
            Word::P3y => "P3Y",
            Word::P3z => "P3Z",
            Word::A => "A",
            Word::B => "B",
            Word::C => "C",
            Word::Dist => "DIST",
            Word::Mb => "MB",
            Word::F => "F",
        }
    }

    /// The word written `text` (`"SPA"` → [`Word::Spa`]); `None` for anything else.
    #[must_use]
    pub fn from_name(text: &str) -> Option<Word> {
        Word::ALL.into_iter().find(|w| w.as_str() == text)
    }

    /// Its input range (DOMAIN.md §5, iTNC 530 manual figures; the UNCONFIRMED ones are named in
    /// [`crate::unconfirmed`]). The one table for the parser, the orientation maths and the
    /// dialog.
    #[must_use]
    pub fn range(self) -> InputRange {
        use crate::unconfirmed::{
            AXIAL_LIMIT, EULPR_LIMIT, POINTS_COORD_LIMIT, POSITIONING_LENGTH_LIMIT, VECTOR_COMPONENT_LIMIT,
        };
        let r = |min, max, angle| InputRange { min, max, angle };
        match self {
            Word::Spa | Word::Spb | Word::Spc => r(-SPATIAL_LIMIT, SPATIAL_LIMIT, true),
            Word::Propr | Word::Promin => r(-PROJECTED_LIMIT, PROJECTED_LIMIT, true),
            Word::Rot | Word::Eulrot => r(0.0, 360.0, true),
            Word::Eulpr => r(-EULPR_LIMIT, EULPR_LIMIT, true),
            Word::Eulnu => r(0.0, 180.0, true),
            Word::Bx | Word::By | Word::Bz | Word::Nx | Word::Ny | Word::Nz => {
                r(-VECTOR_COMPONENT_LIMIT, VECTOR_COMPONENT_LIMIT, false)
            }
            Word::P1x
            | Word::P1y
            | Word::P1z
            | Word::P2x
            | Word::P2y
            | Word::P2z
            | Word::P3x
            | Word::P3y
            | Word::P3z => r(-POINTS_COORD_LIMIT, POINTS_COORD_LIMIT, false),
            Word::A | Word::B | Word::C => r(-AXIAL_LIMIT, AXIAL_LIMIT, true),
            // A distance and a retract length: not negative (see POSITIONING_LENGTH_LIMIT).
            Word::Dist | Word::Mb => r(0.0, POSITIONING_LENGTH_LIMIT, false),
            Word::F => r(0.0, FEED_LIMIT, false),
        }
    }
}

impl std::fmt::Display for Word {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Checks a number typed or written for `word` against its input range: the one check of the
/// parser and the PLANE dialog. `Err` is the diagnostic the parser reports (the dialog shows
/// its message): [`DiagCode::AngleNotPermitted`] for an angle ("Winkel nicht erlaubt"),
/// [`DiagCode::ValueOutOfRange`] for any other value (a negative `DIST`, `MB` or `F` too),
/// [`DiagCode::InvalidInput`] for NaN or ±∞.
///
/// # Errors
/// The value is not finite or outside [`Word::range`].
pub fn check(word: Word, value: f64) -> Result<(), DiagCode> {
    if !value.is_finite() {
        return Err(DiagCode::InvalidInput);
    }
    let r = word.range();
    if r.contains(value) {
        return Ok(());
    }
    let (word, min, max) = (word.as_str(), r.min, r.max);
    Err(if r.angle {
        DiagCode::AngleNotPermitted { word, value, min, max }
    } else {
        DiagCode::ValueOutOfRange { word, value, min, max }
    })
}

/// The input range of the word written `word` (see [`Word::range`]); `None` for a word without
/// one.
#[must_use]
pub fn input_range(word: &str) -> Option<InputRange> {
    Word::from_name(word).map(Word::range)
}

/// Which PLANE function a definition uses (the softkey of the dialog).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum PlaneKind {
    Spatial,
    Projected,
    Euler,
    Vector,
    Points,
    Relativ,
    Axial,
    Reset,
}

impl PlaneKind {
    /// The eight functions in the order of the control's softkey row.
    pub const ALL: [PlaneKind; 8] = [
        PlaneKind::Spatial,
        PlaneKind::Projected,
        PlaneKind::Euler,
        PlaneKind::Vector,
        PlaneKind::Points,
        PlaneKind::Relativ,
        PlaneKind::Axial,
        PlaneKind::Reset,
    ];

    /// The word after `PLANE` (`SPATIAL`, `RELATIV`).
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            PlaneKind::Spatial => "SPATIAL",
            PlaneKind::Projected => "PROJECTED",
            PlaneKind::Euler => "EULER",
            PlaneKind::Vector => "VECTOR",
            PlaneKind::Points => "POINTS",
            PlaneKind::Relativ => "RELATIV",
            PlaneKind::Axial => "AXIAL",
            PlaneKind::Reset => "RESET",
        }
    }

    /// The words the dialog asks for, in the control's order (one slot each, see
    /// [`PlaneSlots`]). RELATIV asks for one angle, written with the chosen axis (`rel_axis`);
    /// AXIAL has a slot for each of A, B, C.
    #[must_use]
    pub fn words(self, rel_axis: RelAxis) -> &'static [Word] {
        use Word::*;
        match self {
            PlaneKind::Spatial => &[Spa, Spb, Spc],
            PlaneKind::Projected => &[Propr, Promin, Rot],
            PlaneKind::Euler => &[Eulpr, Eulnu, Eulrot],
            PlaneKind::Vector => &[Bx, By, Bz, Nx, Ny, Nz],
            PlaneKind::Points => &[P1x, P1y, P1z, P2x, P2y, P2z, P3x, P3y, P3z],
            PlaneKind::Relativ => match rel_axis {
                RelAxis::Spa => &[Spa],
                RelAxis::Spb => &[Spb],
                RelAxis::Spc => &[Spc],
            },
            PlaneKind::Axial => &[A, B, C],
            PlaneKind::Reset => &[],
        }
    }
}

/// A PLANE definition as the dialog holds it: one optional value per prompt of its kind
/// ([`PlaneKind::words`]), the RELATIV axis and the AXIAL increments. [`PlaneDef::slots`] and
/// [`PlaneSlots::def`] convert both ways, so the flattening is written once.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneSlots<V = Value> {
    pub kind: PlaneKind,
    /// In the order of [`PlaneKind::words`]; AXIAL: A, B, C, `None` where not programmed.
    pub values: Vec<Option<V>>,
    /// RELATIV: its axis (`Spa` otherwise).
    pub rel_axis: RelAxis,
    /// AXIAL: `IA`, `IB`, `IC` (incremental) per slot.
    pub incremental: [bool; 3],
}

impl<V: Clone> PlaneSlots<V> {
    /// Empty slots of `kind`.
    #[must_use]
    pub fn new(kind: PlaneKind, rel_axis: RelAxis) -> Self {
        let values = vec![None; kind.words(rel_axis).len()];
        PlaneSlots { kind, values, rel_axis, incremental: [false; 3] }
    }

    /// The definition, or `None` while a mandatory value is missing (AXIAL: while all three are).
    #[must_use]
    pub fn def(&self) -> Option<PlaneDef<V>> {
        let v = |i: usize| self.values.get(i).cloned().flatten();
        let v3 = |i: usize| Some([v(i)?, v(i + 1)?, v(i + 2)?]);
        Some(match self.kind {
            PlaneKind::Spatial => PlaneDef::Spatial { spa: v(0)?, spb: v(1)?, spc: v(2)? },
            PlaneKind::Projected => PlaneDef::Projected { propr: v(0)?, promin: v(1)?, rot: v(2)? },
            PlaneKind::Euler => PlaneDef::Euler { eulpr: v(0)?, eulnu: v(1)?, eulrot: v(2)? },
            PlaneKind::Vector => PlaneDef::Vector { base: v3(0)?, normal: v3(3)? },
            PlaneKind::Points => PlaneDef::Points { p1: v3(0)?, p2: v3(3)?, p3: v3(6)? },
            PlaneKind::Relativ => PlaneDef::Relativ { axis: self.rel_axis, angle: v(0)? },
            PlaneKind::Axial => {
                let axes: Vec<AxialAngle<V>> = [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]
                    .into_iter()
                    .enumerate()
                    .filter_map(|(i, axis)| {
                        Some(AxialAngle { axis, value: v(i)?, incremental: self.incremental[i] })
                    })
                    .collect();
                if axes.is_empty() {
                    return None;
                }
                PlaneDef::Axial { axes }
            }
            PlaneKind::Reset => PlaneDef::Reset,
        })
    }
}

impl<V> PlaneDef<V> {
    /// Which PLANE function this is.
    #[must_use]
    pub fn kind(&self) -> PlaneKind {
        match self {
            PlaneDef::Spatial { .. } => PlaneKind::Spatial,
            PlaneDef::Projected { .. } => PlaneKind::Projected,
            PlaneDef::Euler { .. } => PlaneKind::Euler,
            PlaneDef::Vector { .. } => PlaneKind::Vector,
            PlaneDef::Points { .. } => PlaneKind::Points,
            PlaneDef::Relativ { .. } => PlaneKind::Relativ,
            PlaneDef::Axial { .. } => PlaneKind::Axial,
            PlaneDef::Reset => PlaneKind::Reset,
        }
    }

    /// Every value with its word, in the order written (`SPA`, `SPB`, `SPC`; AXIAL: the axes
    /// programmed, as written).
    #[must_use]
    pub fn values(&self) -> Vec<(Word, &V)> {
        let rel = match self {
            PlaneDef::Relativ { axis, .. } => *axis,
            _ => RelAxis::Spa,
        };
        let words = self.kind().words(rel);
        let refs: Vec<&V> = match self {
            PlaneDef::Spatial { spa: a, spb: b, spc: c }
            | PlaneDef::Projected { propr: a, promin: b, rot: c }
            | PlaneDef::Euler { eulpr: a, eulnu: b, eulrot: c } => vec![a, b, c],
            PlaneDef::Vector { base, normal } => base.iter().chain(normal).collect(),
            PlaneDef::Points { p1, p2, p3 } => p1.iter().chain(p2).chain(p3).collect(),
            PlaneDef::Relativ { angle, .. } => vec![angle],
            PlaneDef::Axial { axes } => {
                return axes.iter().map(|a| (a.axis.plane_word(), &a.value)).collect();
            }
            PlaneDef::Reset => Vec::new(),
        };
        words.iter().copied().zip(refs).collect()
    }
}

impl<V: Clone> PlaneDef<V> {
    /// The definition as the dialog's slots (the inverse of [`PlaneSlots::def`]).
    #[must_use]
    pub fn slots(&self) -> PlaneSlots<V> {
        let rel_axis = match self {
            PlaneDef::Relativ { axis, .. } => *axis,
            _ => RelAxis::Spa,
        };
        let mut slots = PlaneSlots::new(self.kind(), rel_axis);
        if let PlaneDef::Axial { axes } = self {
            for a in axes {
                let i = a.axis as usize;
                slots.values[i] = Some(a.value.clone());
                slots.incremental[i] = a.incremental;
            }
        } else {
            slots.values = self.values().into_iter().map(|(_, v)| Some(v.clone())).collect();
        }
        slots
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::{PlaneTextError, plane_block};

    #[test]
    fn one_check_for_parser_and_dialog() {
        assert_eq!(check(Word::Spb, 45.0), Ok(()));
        assert!(matches!(check(Word::Eulpr, 270.0), Err(DiagCode::AngleNotPermitted { word: "EULPR", .. })));
        for word in [Word::Dist, Word::Mb, Word::F] {
            assert_eq!(check(word, 0.0), Ok(()));
            assert!(matches!(check(word, -5.0), Err(DiagCode::ValueOutOfRange { min: 0.0, .. })), "{word}");
        }
        assert_eq!(check(Word::F, f64::NAN), Err(DiagCode::InvalidInput));
        for w in Word::ALL {
            assert_eq!(Word::from_name(w.as_str()), Some(w));
            assert_eq!(input_range(w.as_str()), Some(w.range()));
        }
        assert_eq!(input_range("X"), None);
    }

    #[test]
    fn the_parser_refuses_a_negative_dist_mb_or_feed_with_the_checks_diagnostic() {
        for (text, word) in [
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE DIST-5 F500", "DIST-5"),
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB-5 FMAX", "MB-5"),
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE F-3", "F-3"),
        ] {
            let Err(PlaneTextError::Invalid(d)) = plane_block(text) else { panic!("{text} accepted") };
            assert!(matches!(d.code, DiagCode::ValueOutOfRange { .. }), "{text}: {:?}", d.code);
            assert_eq!(&text[d.span.start..d.span.end], word);
        }
        assert!(plane_block("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE DIST+5 F500").is_ok());
    }

    #[test]
    fn plane_block_wants_exactly_one_plane() {
        assert_eq!(plane_block("L X+0"), Err(PlaneTextError::NoPlane));
        let two = "1 PLANE RESET STAY\n2 PLANE RESET STAY";
        assert_eq!(plane_block(two), Err(PlaneTextError::SeveralPlanes));
        let b = plane_block("PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 TURN FMAX").expect("one block");
        assert_eq!(b.numbers(), Err(1));
    }

    #[test]
    fn slots_and_values_round_trip_every_kind() {
        for text in [
            "PLANE SPATIAL SPA+1 SPB+2 SPC+3 STAY",
            "PLANE PROJECTED PROPR+1 PROMIN+2 ROT+3 STAY",
            "PLANE EULER EULPR+1 EULNU+2 EULROT+3 STAY",
            "PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+1 STAY",
            "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+1 P2Y+0 P2Z+0 P3X+0 P3Y+1 P3Z+0 STAY",
            "PLANE RELATIV SPB+10 STAY",
            "PLANE AXIAL IC+5 A+10 STAY",
            "PLANE RESET STAY",
        ] {
            let def = plane_block(text).expect(text).def;
            let slots = def.slots();
            assert_eq!(slots.kind, def.kind());
            assert_eq!(slots.values.len(), slots.kind.words(slots.rel_axis).len(), "{text}");
            if def.kind() != PlaneKind::Axial {
                assert_eq!(slots.def().as_ref(), Some(&def), "{text}");
            }
            assert!(text.contains(def.kind().as_str()));
            for (word, _) in def.values() {
                assert!(text.contains(word.as_str()), "{text}: {word}");
            }
        }
        // AXIAL slots are A, B, C whatever the order written; `def` writes them in that order.
        let axial = plane_block("PLANE AXIAL IC+5 A+10 STAY").expect("axial").def;
        let slots = axial.slots();
        assert_eq!(slots.values, vec![Some(Value::Number(10.0)), None, Some(Value::Number(5.0))]);
        assert_eq!(slots.incremental, [false, false, true]);
        let again = slots.def().expect("two axes");
        assert_eq!(again.slots(), slots);
        assert_eq!(PlaneSlots::<f64>::new(PlaneKind::Axial, RelAxis::Spa).def(), None);
        assert_eq!(PlaneSlots::<f64>::new(PlaneKind::Spatial, RelAxis::Spa).def(), None);
    }
}
