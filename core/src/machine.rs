//! Machines as data: the rotary axes of the kinematic chain from the workpiece to the tool,
//! read from `static/machines/*.json` (compiled in as constants by `build.rs`, for the CLI and
//! the wasm build alike; [`Machine::from_json`] reads any other file).
//!
//! JSON form (`chain` in order **workpiece → tool**, i.e. table axes first, the table axis
//! carrying the workpiece first; then head axes, the one carrying the tool last):
//! ```json
//! { "id": "ac-table", "name": {"de": "…", "en": "…"}, "description": {"de": "…", "en": "…"},
//!   "chain": [ {"axis": "C", "carrier": "table", "direction": [0,0,1], "pivot": [0,0,0], "endless": true},
//!              {"axis": "A", "carrier": "table", "direction": [1,0,0], "pivot": [0,0,0],
//!               "limits": {"min": -100, "max": 180}} ],
//!   "geometry": { "preset": [-50,-50,-160], "linear_limits": {"X": {"min": -700, "max": 700}, …},
//!                 "rapid_linear": 12000, "rapid_rotary": 5400, "start": [0,0,0] } }
//! ```
//! `direction` is the axis direction at home (all axes at 0°) in machine coordinates, a unit
//! vector, so tilted axes such as a 45° nutating head are plain data. `pivot` (mm) is a point on
//! the axis, for MOVE and the 3D view: for a **table** axis in M-CS with every axis at home, for a
//! **head** axis relative to the spindle gauge point (one tool length above the tool tip) with
//! the head at home. `geometry` (optional, every field defaulted, [`MachineGeometry`]) places the
//! preset, the linear travel and the rapid rates for the simulator ([`crate::sim`]).

use std::borrow::Cow;

use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::axes::AxisValues;
use crate::lang::Text;
use crate::plane::RotaryAxis;

/// Whether a rotary axis turns the workpiece (table) or the tool (head).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Carrier {
    Table,
    Head,
}

/// Software limit switches of a rotary axis, degrees.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Limits {
    pub min: f64,
    pub max: f64,
}

impl Limits {
    /// Tolerance of the limit check (derived: far below the 4-decimal display).
    pub const EPS: f64 = 1e-9;

    /// `true` if `value` lies inside the limits.
    #[must_use]
    pub fn contains(&self, value: f64) -> bool {
        value >= self.min - Self::EPS && value <= self.max + Self::EPS
    }
}

/// One rotary axis of the chain, validated.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RotaryJoint {
    pub axis: RotaryAxis,
    pub carrier: Carrier,
    /// Unit axis direction at home, machine coordinates.
    pub direction: DVec3,
    /// A point on the axis, mm.
    pub pivot: DVec3,
    pub limits: Option<Limits>,
    /// Modulo-360 axis: always the short way round, no limits.
    pub endless: bool,
}

/// A validated machine with two rotary axes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Machine {
    pub id: String,
    pub name: Text,
    pub description: Text,
    /// Chain order workpiece → tool: `[slave, master]` (DOMAIN.md §3.1: the master is the first
    /// rotary axis seen from the tool, i.e. the last seen from the workpiece).
    chain: [RotaryJoint; 2],
    /// The master's two symmetry positions, "the" symmetry point first (derived once from the
    /// axis directions, [`crate::kinematics::symmetry_positions_of`]).
    symmetry: [f64; 2],
    /// Where things are in the machine: preset, linear travel, rapid rates (the simulator's
    /// model, [`crate::sim`]); defaults when the JSON has no `geometry`.
    pub geometry: MachineGeometry,
}

/// The machine geometry the simulator needs beyond the rotary chain (JSON key `geometry`, every
/// field optional). The model behind it is documented in [`crate::sim`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MachineGeometry {
    /// The active preset: origin of the W-CS in M-CS with every rotary axis at 0°, mm. No basic
    /// rotation (W-CS axes parallel to M-CS at rotary zero).
    pub preset: DVec3,
    /// Software limit switches of the linear axes X, Y, Z in M-CS, mm (`MB MAX`, limit checks).
    pub linear_limits: [Limits; 3],
    /// Rapid traverse (FMAX) of the linear axes, mm/min.
    pub rapid_linear: f64,
    /// Rapid traverse (FMAX) of the rotary axes, °/min.
    pub rapid_rotary: f64,
    /// Linear axis position at program start, M-CS, mm.
    pub start: DVec3,
}

impl MachineGeometry {
    /// Linear travel when the JSON gives none: ±1000 mm in X and Y, Z from −1000 to 0 (so that
    /// `L Z+0 M91` is the top of the travel, as in seed S0). Derived, illustrative.
    pub const DEFAULT_LIMITS: [Limits; 3] = [
        Limits { min: -1000.0, max: 1000.0 },
        Limits { min: -1000.0, max: 1000.0 },
        Limits { min: -1000.0, max: 0.0 },
    ];
    /// FMAX of the linear axes when the JSON gives none, mm/min (illustrative).
    pub const DEFAULT_RAPID_LINEAR: f64 = 10_000.0;
    /// FMAX of the rotary axes when the JSON gives none, °/min (illustrative).
    pub const DEFAULT_RAPID_ROTARY: f64 = 5_400.0;
}

impl Default for MachineGeometry {
    fn default() -> Self {
        MachineGeometry {
            preset: DVec3::ZERO,
            linear_limits: Self::DEFAULT_LIMITS,
            rapid_linear: Self::DEFAULT_RAPID_LINEAR,
            rapid_rotary: Self::DEFAULT_RAPID_ROTARY,
            start: DVec3::ZERO,
        }
    }
}

/// A machine description that cannot be used. Every variant carries the numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum MachineError {
    /// Not valid JSON for the machine schema.
    Json { message: String, line: usize, column: usize },
    /// No built-in machine with this id.
    UnknownId { id: String },
    /// An axis letter other than A, B, C.
    UnknownAxis { letter: String },
    /// The same letter twice in the chain.
    DuplicateAxis { axis: RotaryAxis },
    /// The solver handles exactly two rotary axes.
    AxisCount { count: usize },
    /// A number that is NaN or infinite.
    NotFinite { axis: RotaryAxis, field: &'static str, value: f64 },
    /// `direction` is not a unit vector (tolerance 1e-6).
    DirectionNotUnit { axis: RotaryAxis, direction: [f64; 3], length: f64 },
    /// `limits.min` is not below `limits.max`.
    LimitsInverted { axis: RotaryAxis, min: f64, max: f64 },
    /// An endless (modulo) axis cannot have limit switches.
    EndlessWithLimits { axis: RotaryAxis, min: f64, max: f64 },
    /// A bad value in `geometry` (not finite, inverted limits, rapid ≤ 0).
    Geometry { field: &'static str, value: f64 },
    /// A table axis listed after a head axis (the chain runs workpiece → table → bed → head → tool).
    TableAfterHead { axis: RotaryAxis },
    /// The two axes are parallel: they cannot tilt the tool in two directions.
    ParallelAxes { slave: RotaryAxis, master: RotaryAxis, sine: f64 },
    /// The master axis is parallel to the tool axis at home: it cannot tilt the tool.
    MasterAlongTool { axis: RotaryAxis, sine: f64 },
}

impl std::fmt::Display for MachineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MachineError::Json { message, line, column } => {
                write!(f, "machine JSON {line}:{column}: {message}")
            }
            MachineError::UnknownId { id } => write!(f, "no built-in machine {id:?}"),
            MachineError::UnknownAxis { letter } => write!(f, "unknown rotary axis {letter:?} (A, B or C)"),
            MachineError::DuplicateAxis { axis } => write!(f, "axis {axis} appears twice"),
            MachineError::AxisCount { count } => write!(f, "{count} rotary axes; exactly 2 are supported"),
            MachineError::NotFinite { axis, field, value } => write!(f, "axis {axis}: {field} = {value}"),
            MachineError::DirectionNotUnit { axis, direction, length } => {
                write!(f, "axis {axis}: direction {direction:?} has length {length}, not 1")
            }
            MachineError::LimitsInverted { axis, min, max } => {
                write!(f, "axis {axis}: limits min {min} ≥ max {max}")
            }
            MachineError::EndlessWithLimits { axis, min, max } => {
                write!(f, "axis {axis}: endless but limited to {min} … {max}")
            }
            MachineError::Geometry { field, value } => write!(f, "geometry: {field} = {value}"),
            MachineError::TableAfterHead { axis } => write!(f, "table axis {axis} listed after a head axis"),
            MachineError::ParallelAxes { slave, master, sine } => {
                write!(f, "axes {slave} and {master} are parallel (sine {sine})")
            }
            MachineError::MasterAlongTool { axis, sine } => {
                write!(f, "master axis {axis} is parallel to the tool axis at home (sine {sine})")
            }
        }
    }
}

impl std::error::Error for MachineError {}

/// A machine description as written, before validation: read from JSON by
/// [`Machine::from_json`], or compiled in from `static/machines/*.json` by `build.rs` (the
/// borrowed `Cow`s), so that both go through the same checks and the wasm needs no JSON parser.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMachine {
    id: Cow<'static, str>,
    name: Text,
    description: Text,
    chain: Cow<'static, [RawJoint]>,
    #[serde(default)]
    geometry: Option<RawGeometry>,
}

#[derive(Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGeometry {
    #[serde(default)]
    preset: Option<[f64; 3]>,
    /// `{"X": {"min", "max"}, "Y": …, "Z": …}`; a missing axis keeps its default.
    #[serde(default)]
    linear_limits: Option<RawLinearLimits>,
    #[serde(default)]
    rapid_linear: Option<f64>,
    #[serde(default)]
    rapid_rotary: Option<f64>,
    #[serde(default)]
    start: Option<[f64; 3]>,
}

#[derive(Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLinearLimits {
    #[serde(rename = "X", default)]
    x: Option<Limits>,
    #[serde(rename = "Y", default)]
    y: Option<Limits>,
    #[serde(rename = "Z", default)]
    z: Option<Limits>,
}

#[derive(Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawJoint {
    axis: Cow<'static, str>,
    carrier: Carrier,
    direction: [f64; 3],
    #[serde(default)]
    pivot: [f64; 3],
    #[serde(default)]
    limits: Option<Limits>,
    #[serde(default)]
    endless: bool,
}

// `BUILTIN_IDS: [&str; 5]` and `static BUILTIN: [RawMachine; 5]`, generated by build.rs from
// `static/machines/*.json`.
include!(concat!(env!("OUT_DIR"), "/builtin_machines.rs"));

/// Direction tolerance: |direction| must be 1 within this (so 0.7071067811865476 works).
const UNIT_TOL: f64 = 1e-6;
/// Sine below which two axis directions count as parallel (derived, numerical).
const PARALLEL_TOL: f64 = 1e-6;

impl Machine {
    /// The ids of the shipped machines, in display order.
    #[must_use]
    pub fn builtin_ids() -> [&'static str; 5] {
        BUILTIN_IDS
    }

    /// A shipped machine by id.
    pub fn builtin(id: &str) -> Result<Machine, MachineError> {
        let raw = BUILTIN
            .iter()
            .find(|m| m.id == id)
            .ok_or_else(|| MachineError::UnknownId { id: id.to_string() })?;
        Machine::from_raw(raw)
    }

    /// Reads and validates a machine description.
    pub fn from_json(json: &str) -> Result<Machine, MachineError> {
        let raw: RawMachine = serde_json::from_str(json).map_err(|e| MachineError::Json {
            message: e.to_string(),
            line: e.line(),
            column: e.column(),
        })?;
        Machine::from_raw(&raw)
    }

    /// Validates a machine description, from a JSON file or compiled in.
    fn from_raw(raw: &RawMachine) -> Result<Machine, MachineError> {
        let mut joints = Vec::with_capacity(raw.chain.len());
        for j in raw.chain.iter() {
            joints.push(validate_joint(j)?);
        }
        let chain: [RotaryJoint; 2] =
            joints.try_into().map_err(|v: Vec<RotaryJoint>| MachineError::AxisCount { count: v.len() })?;
        let [slave, master] = &chain;
        if slave.axis == master.axis {
            return Err(MachineError::DuplicateAxis { axis: slave.axis });
        }
        if slave.carrier == Carrier::Head && master.carrier == Carrier::Table {
            return Err(MachineError::TableAfterHead { axis: master.axis });
        }
        let sine = slave.direction.cross(master.direction).length();
        if sine < PARALLEL_TOL {
            return Err(MachineError::ParallelAxes { slave: slave.axis, master: master.axis, sine });
        }
        let sine = master.direction.cross(DVec3::Z).length();
        if sine < PARALLEL_TOL {
            return Err(MachineError::MasterAlongTool { axis: master.axis, sine });
        }
        let symmetry = crate::kinematics::symmetry_positions_of(slave.direction, master.direction);
        let geometry = validate_geometry(raw.geometry)?;
        Ok(Machine {
            id: raw.id.to_string(),
            name: raw.name.clone(),
            description: raw.description.clone(),
            chain,
            symmetry,
            geometry,
        })
    }

    /// The rotary axes in chain order workpiece → tool.
    #[must_use]
    pub fn joints(&self) -> &[RotaryJoint; 2] {
        &self.chain
    }

    /// The master axis: first rotary axis seen from the tool (DOMAIN.md §3.1, [S2]).
    #[must_use]
    pub fn master(&self) -> &RotaryJoint {
        &self.chain[1]
    }

    /// The slave axis: the other one, nearest the workpiece.
    #[must_use]
    pub fn slave(&self) -> &RotaryJoint {
        &self.chain[0]
    }

    /// The master's two symmetry positions in degrees, "the" symmetry point first.
    #[must_use]
    pub fn symmetry_positions(&self) -> [f64; 2] {
        self.symmetry
    }

    /// The joint with this letter, if the machine has it.
    #[must_use]
    pub fn joint(&self, axis: RotaryAxis) -> Option<&RotaryJoint> {
        self.chain.iter().find(|j| j.axis == axis)
    }

    /// Forward kinematics from axis values (missing axes at 0°): the orientation of the tool
    /// relative to the workpiece, R = Π Rot(uᵢ, θᵢ) in chain order workpiece → tool
    /// (DOMAIN.md §3.1; a table axis turns the workpiece by −θ, which is the same product).
    #[must_use]
    pub fn forward(&self, axes: &AxisValues) -> DMat3 {
        let [s, m] = &self.chain;
        self.forward_deg(axes.get(s.axis).unwrap_or(0.0), axes.get(m.axis).unwrap_or(0.0))
    }

    /// [`Machine::forward`] with `(slave, master)` in degrees.
    #[must_use]
    pub fn forward_deg(&self, slave: f64, master: f64) -> DMat3 {
        let [s, m] = &self.chain;
        DMat3::from_axis_angle(s.direction, slave.to_radians())
            * DMat3::from_axis_angle(m.direction, master.to_radians())
    }

    /// Effective limits of an axis: an override if given, else the machine's.
    #[must_use]
    pub fn limits_of(&self, axis: RotaryAxis, overrides: &[(RotaryAxis, Limits)]) -> Option<Limits> {
        overrides.iter().rev().find(|(a, _)| *a == axis).map(|(_, l)| *l).or_else(|| self.joint(axis)?.limits)
    }
}

fn validate_geometry(raw: Option<RawGeometry>) -> Result<MachineGeometry, MachineError> {
    let mut g = MachineGeometry::default();
    let Some(raw) = raw else { return Ok(g) };
    let finite3 = |field: &'static str, v: [f64; 3]| match v.iter().find(|x| !x.is_finite()) {
        Some(&value) => Err(MachineError::Geometry { field, value }),
        None => Ok(DVec3::from_array(v)),
    };
    if let Some(p) = raw.preset {
        g.preset = finite3("preset", p)?;
    }
    if let Some(p) = raw.start {
        g.start = finite3("start", p)?;
    }
    if let Some(l) = raw.linear_limits {
        for (i, (lim, field)) in
            [(l.x, "linear_limits.X"), (l.y, "linear_limits.Y"), (l.z, "linear_limits.Z")]
                .into_iter()
                .enumerate()
        {
            if let Some(lim) = lim {
                if !(lim.min.is_finite() && lim.max.is_finite()) || lim.min >= lim.max {
                    return Err(MachineError::Geometry { field, value: lim.min });
                }
                g.linear_limits[i] = lim;
            }
        }
    }
    for (v, field, slot) in [
        (raw.rapid_linear, "rapid_linear", &mut g.rapid_linear),
        (raw.rapid_rotary, "rapid_rotary", &mut g.rapid_rotary),
    ] {
        if let Some(v) = v {
            if !v.is_finite() || v <= 0.0 {
                return Err(MachineError::Geometry { field, value: v });
            }
            *slot = v;
        }
    }
    Ok(g)
}

fn validate_joint(j: &RawJoint) -> Result<RotaryJoint, MachineError> {
    let axis = RotaryAxis::from_letter(&j.axis)
        .ok_or_else(|| MachineError::UnknownAxis { letter: j.axis.to_string() })?;
    let finite = |field: &'static str, v: &[f64]| match v.iter().find(|x| !x.is_finite()) {
        Some(&value) => Err(MachineError::NotFinite { axis, field, value }),
        None => Ok(()),
    };
    finite("direction", &j.direction)?;
    finite("pivot", &j.pivot)?;
    let direction = DVec3::from_array(j.direction);
    let length = direction.length();
    if (length - 1.0).abs() > UNIT_TOL {
        return Err(MachineError::DirectionNotUnit { axis, direction: j.direction, length });
    }
    if let Some(l) = j.limits {
        finite("limits", &[l.min, l.max])?;
        if l.min >= l.max {
            return Err(MachineError::LimitsInverted { axis, min: l.min, max: l.max });
        }
        if j.endless {
            return Err(MachineError::EndlessWithLimits { axis, min: l.min, max: l.max });
        }
    }
    Ok(RotaryJoint {
        axis,
        carrier: j.carrier,
        direction: direction / length,
        pivot: DVec3::from_array(j.pivot),
        limits: j.limits,
        endless: j.endless,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// build.rs compiles the machine files into constants; they must say what the files say.
    #[test]
    fn compiled_in_machines_are_the_json_files() {
        for id in Machine::builtin_ids() {
            let path = format!("{}/../static/machines/{id}.json", env!("CARGO_MANIFEST_DIR"));
            let json = std::fs::read_to_string(&path).expect("machine file");
            assert_eq!(Machine::builtin(id), Machine::from_json(&json), "{id}");
            assert!(Machine::builtin(id).is_ok(), "{id}");
        }
    }
}
