//! Motion segments: what the axes do during a block, evaluable at any time fraction for the 3D
//! view's animation.

use glam::{DMat3, DVec3};
use serde::Serialize;

use crate::axes::AxisValues;
use crate::plane::RotaryAxis;

use super::geometry::Kin;

/// Every machine axis: X Y Z (M-CS, mm) and the two rotary axes (degrees) in the machine's chain
/// order workpiece → tool (`letters` names them, e.g. `[C, A]` on `ac-table`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MachineAxes {
    pub linear: DVec3,
    pub rotary: [f64; 2],
    pub letters: [RotaryAxis; 2],
}

impl MachineAxes {
    /// The value of a rotary axis by letter, if the machine has it.
    #[must_use]
    pub fn rotary_axis(&self, axis: RotaryAxis) -> Option<f64> {
        self.letters.iter().position(|&l| l == axis).map(|i| self.rotary[i])
    }

    /// The rotary axes keyed by letter (for the solver and the UI).
    #[must_use]
    pub fn rotary_values(&self) -> AxisValues {
        let mut v = AxisValues::default();
        for (l, x) in self.letters.iter().zip(self.rotary) {
            v.set(*l, x);
        }
        v
    }

    /// `[("X", x), ("Y", y), ("Z", z), (rotary letters…)]` in the order the control displays
    /// them (linear, then rotary alphabetically). An array: a run's listing calls it per row.
    #[must_use]
    pub fn named(&self) -> [(char, f64); 5] {
        let [(l0, r0), (l1, r1)] = [0, 1].map(|i| (self.letters[i].letter(), self.rotary[i]));
        let (first, second) = if l1 < l0 { ((l1, r1), (l0, r0)) } else { ((l0, r0), (l1, r1)) };
        [('X', self.linear.x), ('Y', self.linear.y), ('Z', self.linear.z), first, second]
    }
}

/// What kind of motion a segment is (the 3D view draws them differently).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SegmentKind {
    /// `FMAX` positioning.
    Rapid,
    /// Feed move.
    Feed,
    /// `MB`/`MB MAX` retract along the tool axis before a TURN swivel.
    Retract,
    /// PLANE … MOVE: rotary and linear axes together.
    SwivelMove,
    /// PLANE … TURN: only the rotary axes.
    SwivelTurn,
    /// PLANE … STAY: no axis moves, only the working plane turns ([`SegmentPath::Stay`]).
    SwivelStay,
    /// A motion produced by a cycle (rapid parts of a cycle are `Rapid`).
    CycleFeed,
}

impl SegmentKind {
    /// A positioning, which must not touch the material (a rapid, an MB retract, the swivel of
    /// MOVE/TURN), as against a motion that may cut.
    #[must_use]
    pub fn is_positioning(self) -> bool {
        matches!(
            self,
            SegmentKind::Rapid | SegmentKind::Retract | SegmentKind::SwivelMove | SegmentKind::SwivelTurn
        )
    }
}

/// How the axes get from `start` to `end`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "path", rename_all = "snake_case")]
pub enum SegmentPath {
    /// Every axis linear in time (rotary axes by `rotary_delta`, the short way for endless axes).
    Linear,
    /// PLANE … MOVE: the rotary axes linear in time; the linear axes follow so that the centre of
    /// rotation `centre` (W-CS) stays fixed on the workpiece and the tool tip stands `dist` from
    /// it along the tool axis (DOMAIN.md §4; formula in [`crate::sim`]).
    Move(Box<MovePath>),
    /// PLANE … STAY (and PLANE RESET STAY): the axes stand still; the working plane turns from
    /// `from` to `to` (orientations in W-CS, columns = tilted axes) for the view to interpolate.
    Stay { from: DMat3, to: DMat3 },
    /// An arc or a helix (C, CR, CT, CP, RND, APPR/DEP arcs) with the rotary axes standing still:
    /// the linear axes at fraction f are `centre + u·cos(f·sweep) + v·sin(f·sweep) + f·lead`
    /// ([`ArcPath`]), so every fraction is exactly on the arc.
    Arc(Box<ArcPath>),
    /// A block with rotary axes under TCPM (M128): the rotary axes linear in time; the linear
    /// axes follow so that the tool tip runs straight from `from` to `to` (W-CS) — standing
    /// still when the block programs only rotary axes.
    Tcpm(Box<TcpmPath>),
}

/// The tool tip's path under TCPM ([`SegmentPath::Tcpm`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TcpmPath {
    pub kin: Kin,
    /// The tip in W-CS at the start and at the end.
    pub from: DVec3,
    pub to: DVec3,
}

/// An arc in the linear axes (M-CS): the I-CS arc carried through the fixed I-CS → axes map,
/// which only rotates, mirrors and shifts, so it stays an arc of the same radius.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ArcPath {
    /// Linear axes of the centre at the start's height along the tool axis.
    pub centre: DVec3,
    /// From the centre to the start (length = radius).
    pub u: DVec3,
    /// `u` turned by +90° about the working plane's normal (in the direction DR+).
    pub v: DVec3,
    /// Turned angle, radians; positive = DR+ (counter-clockwise seen against the tool axis).
    pub sweep: f64,
    /// Displacement along the tool axis over the whole arc (helix), linear in the fraction.
    pub lead: DVec3,
}

impl ArcPath {
    /// The linear axes at fraction `f` (0…1).
    #[must_use]
    pub fn at(&self, f: f64) -> DVec3 {
        let (s, c) = (f * self.sweep).sin_cos();
        self.centre + self.u * c + self.v * s + f * self.lead
    }

    /// The radius.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.u.length()
    }
}

/// The data a MOVE swivel needs to place the linear axes at any fraction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MovePath {
    pub kin: Kin,
    /// The centre of rotation in W-CS (fixed relative to the workpiece).
    pub centre: DVec3,
    /// `DIST`, mm (tool tip to centre of rotation).
    pub dist: f64,
}

/// One motion of one executed block.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Segment {
    /// Index of the executed step ([`super::Simulation::records`]).
    pub step: usize,
    /// Index of the block in the program.
    pub block: usize,
    pub kind: SegmentKind,
    pub start: MachineAxes,
    pub end: MachineAxes,
    /// Rotary travel in degrees (end − start, the short way for endless axes).
    pub rotary_delta: [f64; 2],
    /// Duration in seconds from the feed (`FMAX` = the machine's rapid rates).
    pub duration: f64,
    pub path: SegmentPath,
}

impl Segment {
    /// The axes at `fraction` of the segment's time (clamped to 0…1; NaN counts as 0).
    #[must_use]
    pub fn axes_at(&self, fraction: f64) -> MachineAxes {
        let f = if fraction.is_nan() { 0.0 } else { fraction.clamp(0.0, 1.0) };
        if f >= 1.0 {
            return self.end;
        }
        let rotary = [
            self.start.rotary[0] + f * self.rotary_delta[0],
            self.start.rotary[1] + f * self.rotary_delta[1],
        ];
        let linear = match &self.path {
            SegmentPath::Linear | SegmentPath::Stay { .. } => self.start.linear.lerp(self.end.linear, f),
            SegmentPath::Move(m) => move_linear(m, rotary),
            SegmentPath::Arc(a) => a.at(f),
            // L = W(preset + tip) − H(0), as for MOVE (sim.rs doc).
            SegmentPath::Tcpm(t) => t.kin.wcs_to_linear(rotary).apply(t.from.lerp(t.to, f)),
        };
        MachineAxes { linear, rotary, letters: self.start.letters }
    }
}

/// MOVE: tip in W-CS = centre + DIST·t(θ), t = tool axis in W-CS; L = W(preset + tip) − H(0).
pub(crate) fn move_linear(m: &MovePath, rotary: [f64; 2]) -> DVec3 {
    let tip = m.centre + m.dist * m.kin.tool_axis_wcs(rotary);
    m.kin.wcs_to_linear(rotary).apply(tip)
}
