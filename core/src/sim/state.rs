//! What a step leaves behind: the machine's [`State`] after a block (axes, tool, spindle,
//! frames, the active plane, the segments of its motion) and the position display's values
//! during that motion.

use std::collections::BTreeMap;
use std::sync::Arc;

use glam::{DMat3, DVec3};
use serde::Serialize;

use super::{ActiveTransform, Kin, MachineAxes, Note, Segment};
use crate::lang::Text;
use crate::machine::Machine;
use crate::solve::Explanation;

/// Origin and axes (columns) of a coordinate system, in M-CS.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Frame {
    pub origin: DVec3,
    pub axes: DMat3,
}

/// The control's coordinate systems in M-CS.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Frames {
    pub wcs: Frame,
    pub wpl: Frame,
    pub ics: Frame,
}

/// A rotary axis as it stands: a point on it and its direction, both in M-CS (3D view).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pivot {
    pub axis: crate::plane::RotaryAxis,
    pub point: DVec3,
    pub direction: DVec3,
}

/// The active tool.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToolState {
    /// Number as called (0 for a tool called by name, or before the first TOOL CALL).
    pub number: u32,
    pub name: String,
    /// Tool axis letter of the TOOL CALL.
    pub axis: char,
    /// Length incl. DL, mm.
    pub length: f64,
    /// Radius incl. DR, mm.
    pub radius: f64,
    /// Cutting shape from the tool table (flat for an unknown tool).
    pub shape: super::tools::ToolShape,
    /// Found in the tool table (else default length and radius).
    pub known: bool,
    /// F of the TOOL CALL (used by `F AUTO`), mm/min.
    pub feed: f64,
}

/// Direction of the spindle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SpindleDir {
    Off,
    /// M3.
    Cw,
    /// M4.
    Ccw,
}

/// Spindle speed and direction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spindle {
    pub speed: f64,
    pub dir: SpindleDir,
}

/// The blank from BLK FORM, W-CS.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Blank {
    pub min: DVec3,
    pub max: DVec3,
}

/// Where the active tilt came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TiltSource {
    Plane,
    Cycle19,
}

/// The active tilted working plane.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ActivePlane {
    /// The block that defined it.
    pub block: usize,
    pub source: TiltSource,
    /// R realised by the machine (columns = tilted axes in W-CS).
    pub orientation: DMat3,
    pub spatial: [f64; 3],
    pub tool_axis: [f64; 3],
    pub explanation: Arc<Explanation>,
}

/// Everything about the machine after one executed block.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct State {
    pub step: usize,
    pub block: usize,
    pub line: u32,
    pub axes: MachineAxes,
    pub tool: ToolState,
    pub spindle: Spindle,
    /// Modal feed, mm/min.
    pub feed: f64,
    pub blank: Option<Blank>,
    pub transforms: Vec<ActiveTransform>,
    pub frames: Frames,
    pub pivots: [Pivot; 2],
    /// Physical tool tip in M-CS.
    pub tip_mcs: DVec3,
    /// Physical tool tip relative to the workpiece, W-CS.
    pub tip_wcs: DVec3,
    /// The control's position in the I-CS (what unprogrammed coordinates keep).
    pub tip_ics: DVec3,
    /// Tool axis (tip → spindle) in M-CS.
    pub tool_axis_mcs: DVec3,
    /// Whether the control computes the linear axes from the rotary ones here (a tilt or TCPM,
    /// [`crate::unconfirmed::COMPENSATION_ONLY_WHEN_TILTED`]): then IST follows the tool tip,
    /// else the linear axes.
    #[serde(skip)]
    pub compensating: bool,
    pub q: BTreeMap<u32, f64>,
    pub plane: Option<Arc<ActivePlane>>,
    /// The solve explanation of this block (PLANE, cycle 19).
    pub explanation: Option<Arc<Explanation>>,
    /// What the block tells the trainee ([`Note::text`] words it).
    pub note: Option<Note>,
    pub segments: Vec<Segment>,
    /// M30/M2 or END PGM reached.
    pub ended: bool,
    /// `false` if the block was only listed (after M30/M2, or skipped with `/`).
    pub executed: bool,
    /// The program's unit (`BEGIN PGM … MM|INCH`): every length and feed above is in mm and
    /// mm/min; the position display shows them in this unit ([`State::shown`]).
    pub unit: crate::ast::Unit,
}

/// One replayed step as the stock plans it ([`super::Simulation::motions_from`]): the blank,
/// the tool and the motions, without the rest of a [`State`].
#[derive(Debug, Clone, PartialEq)]
pub struct StepMotion {
    pub step: usize,
    pub block: usize,
    pub blank: Option<Blank>,
    pub tool: ToolState,
    pub segments: Vec<Segment>,
}

impl StepMotion {
    /// How long the step's motion takes, seconds (sum of its segments).
    #[must_use]
    pub fn duration(&self) -> f64 {
        duration(&self.segments)
    }
}

/// How long `segments` take one after the other, seconds.
fn duration(segments: &[Segment]) -> f64 {
    segments.iter().map(|s| s.duration).sum()
}

/// One executed step as a listing shows it (`simulate_listed`): the same values as the
/// step's [`State`].
#[derive(Debug, Clone, PartialEq)]
pub struct ListingRow {
    pub step: usize,
    pub block: usize,
    pub line: u32,
    pub axes: MachineAxes,
    /// The active plane's spatial angles SPA, SPB, SPC.
    pub spatial: Option<[f64; 3]>,
    pub note: Option<Note>,
}

impl State {
    /// The block's note in words ([`Note::text`]).
    #[must_use]
    pub fn message(&self) -> Option<Text> {
        self.note.as_ref().map(Note::text)
    }

    /// A length in mm as the position display shows it: in the program's unit.
    #[must_use]
    pub fn shown(&self, mm: f64) -> f64 {
        mm / self.unit.mm()
    }

    /// A feed in mm/min as the program writes F ([`crate::ast::Unit::feed_mm_per_min`]).
    #[must_use]
    pub fn shown_feed(&self, mm_per_min: f64) -> f64 {
        mm_per_min / self.unit.feed_mm_per_min()
    }

    /// How long the block's motion takes, seconds (sum of its segments).
    #[must_use]
    pub fn duration(&self) -> f64 {
        duration(&self.segments)
    }

    /// The segment moving at `fraction` (0…1) of the block's motion time and how far into it;
    /// `None` at the end of the motion or for a block without one.
    #[must_use]
    pub fn segment_at(&self, fraction: f64) -> Option<(&Segment, f64)> {
        let total = self.duration();
        if fraction.is_nan() || fraction >= 1.0 || total <= 0.0 {
            return None;
        }
        let mut t = fraction.max(0.0) * total;
        for seg in &self.segments {
            if t <= seg.duration && seg.duration > 0.0 {
                return Some((seg, t / seg.duration));
            }
            t -= seg.duration;
        }
        None
    }

    /// Every axis (REF) at `fraction` of the block's motion.
    #[must_use]
    pub fn axes_at(&self, fraction: f64) -> MachineAxes {
        self.segment_at(fraction).map_or(self.axes, |(seg, f)| seg.axes_at(f))
    }

    /// The position display's IST at `fraction` of the block's motion
    /// ([`State::tip_ics_with`] at that moment's axes). At the end it is `tip_ics`; during a
    /// straight move it runs along the programmed line, during a swivel it follows the tip.
    #[must_use]
    pub fn tip_ics_at(&self, machine: &Machine, fraction: f64) -> DVec3 {
        match self.segment_at(fraction) {
            Some((seg, f)) => self.tip_ics_with(machine, &seg.axes_at(f)),
            None => self.tip_ics,
        }
    }

    /// IST with the machine at `axes` in this state's working plane: `tip_ics + Rᵀ·Δ`, R the
    /// I-CS axes in W-CS and Δ what moved in W-CS since this state — the tool tip when the
    /// control compensates, else the linear axes themselves (3-axis behaviour: a rotary move
    /// leaves X, Y, Z where they are).
    #[must_use]
    pub fn tip_ics_with(&self, machine: &Machine, axes: &MachineAxes) -> DVec3 {
        let travel_wcs = if self.compensating {
            Kin::new(machine, self.tool.length).tip_wcs(axes) - self.tip_wcs
        } else {
            axes.linear - self.axes.linear
        };
        let ics_in_wcs = self.frames.wcs.axes.transpose() * self.frames.ics.axes;
        self.tip_ics + ics_in_wcs.transpose() * travel_wcs
    }
}
