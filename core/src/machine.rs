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
//!                 "rapid_linear": 12000, "rapid_rotary": 5400, "start": [0,0,0],
//!                 "table_top": [0,0,-210] } }
//! ```
//! `direction` is the axis direction at home (all axes at 0°) in machine coordinates, a unit
//! vector, so tilted axes such as a 45° nutating head are plain data. `pivot` (mm) is a point on
//! the axis, for MOVE and the 3D view: for a **table** axis in M-CS with every axis at home, for a
//! **head** axis relative to the spindle gauge point (one tool length above the tool tip) with
//! the head at home. `geometry` (optional, every field defaulted, [`MachineGeometry`]) places the
//! preset, the linear travel and the rapid rates for the simulator ([`crate::sim`]), and with
//! `table_top` puts each program's blank on the table ([`crate::sim::placed`]); `collision`
//! (optional) lists the collision bodies (`body`).

use std::borrow::Cow;

use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::axes::AxisValues;
use crate::lang::Text;
use crate::plane::RotaryAxis;

mod body;
mod path;
mod validate;
pub use body::{Body, BodyCarrier, BodyDef, BodyShape, BoxDef, CylinderDef};
pub use path::{BodyField, GeometryField, JointField, MachinePath};
pub use validate::{MachineIssue, Problem};

/// Whether a rotary axis turns the workpiece (table) or the tool (head).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Carrier {
    Table,
    Head,
}

impl Carrier {
    /// Its word in the JSON: `table` or `head`.
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            Carrier::Table => "table",
            Carrier::Head => "head",
        }
    }

    /// The carrier of a JSON word.
    #[must_use]
    pub fn from_word(word: &str) -> Option<Carrier> {
        [Carrier::Table, Carrier::Head].into_iter().find(|c| c.word() == word)
    }
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
    /// axis directions, [`symmetry_positions_of`]).
    symmetry: [f64; 2],
    /// Where things are in the machine: preset, linear travel, rapid rates (the simulator's
    /// model, [`crate::sim`]); defaults when the JSON has no `geometry`.
    pub geometry: MachineGeometry,
    /// The collision bodies of bed, table and head (`body`); none when the JSON has none.
    pub bodies: Vec<Body>,
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
    /// The centre of the table's clamping surface, M-CS with every rotary axis at 0°, mm. With
    /// it a program's blank is placed on the table and the preset follows it
    /// ([`crate::sim::placed`]); without it the preset stays where `preset` says.
    pub table_top: Option<DVec3>,
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
            table_top: None,
        }
    }
}

/// Why a machine could not be had.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum MachineError {
    /// No built-in machine with this id.
    UnknownId { id: String },
    /// The description cannot be read or used: every problem found, each with its field.
    Invalid { issues: Vec<MachineIssue> },
}

impl std::fmt::Display for MachineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MachineError::UnknownId { id } => write!(f, "no built-in machine {id:?}"),
            MachineError::Invalid { issues } => {
                for (i, issue) in issues.iter().enumerate() {
                    if i > 0 {
                        f.write_str("; ")?;
                    }
                    write!(f, "{issue}")?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for MachineError {}

/// A machine description as written, before validation ([`MachineDef::validate`]): read from
/// JSON ([`MachineDef::from_json`]), compiled in from `static/machines/*.json` by `build.rs` (the
/// borrowed `Cow`s, so the wasm needs no JSON parser), or made by an editor. Every field is kept
/// as typed (the axis letter and carrier as strings) so that a wrong value is reported with its
/// field path instead of failing the whole read.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MachineDef {
    pub id: Cow<'static, str>,
    pub name: Text,
    pub description: Text,
    pub chain: Cow<'static, [JointDef]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub geometry: Option<GeometryDef>,
    /// The collision bodies (`body`).
    #[serde(default, skip_serializing_if = "no_bodies")]
    pub collision: Cow<'static, [BodyDef]>,
}

fn no_bodies(bodies: &[BodyDef]) -> bool {
    bodies.is_empty()
}

/// `geometry` as written; a missing field keeps its default ([`MachineGeometry::default`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GeometryDef {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<[f64; 3]>,
    /// `{"X": {"min", "max"}, "Y": …, "Z": …}`; a missing axis keeps its default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub linear_limits: Option<LinearLimitsDef>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rapid_linear: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rapid_rotary: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub table_top: Option<[f64; 3]>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinearLimitsDef {
    #[serde(rename = "X", default, skip_serializing_if = "Option::is_none")]
    pub x: Option<Limits>,
    #[serde(rename = "Y", default, skip_serializing_if = "Option::is_none")]
    pub y: Option<Limits>,
    #[serde(rename = "Z", default, skip_serializing_if = "Option::is_none")]
    pub z: Option<Limits>,
}

/// One entry of `chain` as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointDef {
    /// `"A"`, `"B"` or `"C"`.
    pub axis: Cow<'static, str>,
    /// `"table"` or `"head"`.
    pub carrier: Cow<'static, str>,
    pub direction: [f64; 3],
    #[serde(default)]
    pub pivot: [f64; 3],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<Limits>,
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub endless: bool,
}

impl MachineDef {
    /// Reads a description without validating it. A JSON or schema error (a missing field, a
    /// string where a number belongs) is one issue at the top level.
    pub fn from_json(json: &str) -> Result<MachineDef, MachineIssue> {
        serde_json::from_str(json).map_err(|e| MachineIssue {
            path: MachinePath::Whole,
            problem: Problem::Json { message: e.to_string(), line: e.line(), column: e.column() },
        })
    }

    /// The description as pretty JSON, in the form [`MachineDef::from_json`] reads.
    #[must_use]
    pub fn to_json(&self) -> String {
        // Plain structs with string keys: serde_json cannot fail on them (a NaN is written null).
        serde_json::to_string_pretty(self).expect("a machine description serialises")
    }

    /// Checks the description and builds the machine, or lists every problem found
    /// (`validate`).
    pub fn validate(&self) -> Result<Machine, Vec<MachineIssue>> {
        validate::validate(self)
    }
}

// `BUILTIN_IDS: [&str; 5]` and `static BUILTIN: [MachineDef; 5]`, generated by build.rs from
// `static/machines/*.json`.
include!(concat!(env!("OUT_DIR"), "/builtin_machines.rs"));

impl Machine {
    /// The ids of the shipped machines, in display order.
    #[must_use]
    pub fn builtin_ids() -> [&'static str; 5] {
        BUILTIN_IDS
    }

    /// A shipped machine by id.
    pub fn builtin(id: &str) -> Result<Machine, MachineError> {
        let def = BUILTIN
            .iter()
            .find(|m| m.id == id)
            .ok_or_else(|| MachineError::UnknownId { id: id.to_string() })?;
        def.validate().map_err(|issues| MachineError::Invalid { issues })
    }

    /// Reads and validates a machine description.
    pub fn from_json(json: &str) -> Result<Machine, MachineError> {
        MachineDef::from_json(json)
            .map_err(|issue| vec![issue])
            .and_then(|def| def.validate())
            .map_err(|issues| MachineError::Invalid { issues })
    }

    /// The description this machine is read from, every geometry field written out: the
    /// editor's export, which [`MachineDef::validate`] turns back into an equal machine.
    #[must_use]
    pub fn to_def(&self) -> MachineDef {
        let g = &self.geometry;
        let [x, y, z] = g.linear_limits;
        MachineDef {
            id: Cow::Owned(self.id.clone()),
            name: self.name.clone(),
            description: self.description.clone(),
            chain: self
                .chain
                .iter()
                .map(|j| JointDef {
                    axis: Cow::Borrowed(j.axis.word()),
                    carrier: Cow::Borrowed(j.carrier.word()),
                    direction: j.direction.to_array(),
                    pivot: j.pivot.to_array(),
                    limits: j.limits,
                    endless: j.endless,
                })
                .collect(),
            geometry: Some(GeometryDef {
                preset: Some(g.preset.to_array()),
                linear_limits: Some(LinearLimitsDef { x: Some(x), y: Some(y), z: Some(z) }),
                rapid_linear: Some(g.rapid_linear),
                rapid_rotary: Some(g.rapid_rotary),
                start: Some(g.start.to_array()),
                table_top: g.table_top.map(|t| t.to_array()),
            }),
            collision: self
                .bodies
                .iter()
                .map(|b| {
                    b.to_def(match b.carrier {
                        BodyCarrier::Bed => Cow::Borrowed("bed"),
                        BodyCarrier::Head => Cow::Borrowed("head"),
                        BodyCarrier::Table { joint } => {
                            Cow::Borrowed(self.chain.get(joint).map_or("", |j| j.axis.word()))
                        }
                    })
                })
                .collect(),
        }
    }

    /// [`Machine::to_def`] as JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        self.to_def().to_json()
    }

    /// The rotary axes in chain order workpiece → tool.
    #[must_use]
    pub fn joints(&self) -> &[RotaryJoint; 2] {
        &self.chain
    }

    /// The master axis: first rotary axis seen from the tool (DOMAIN.md §3.1, \[S2\]).
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

/// The symmetry positions for slave direction `us` and master direction `um` (unit vectors).
///
/// Derived: the two solutions differ only in the sign of the component of c along n = u_s × u_m,
/// so they mirror about the master positions where c(θ) = Rot(u_m, θ)·ez lies in the plane of
/// u_s and u_m: n·c(θ) = cos θ (n·ez) + sin θ (n·(u_m × ez)) = 0. Where the slave axis can be
/// parallel to the tool axis (every common machine), that position is one of these two.
#[must_use]
pub fn symmetry_positions_of(us: DVec3, um: DVec3) -> [f64; 2] {
    let n = us.cross(um);
    let a = n.dot(DVec3::Z);
    let b = n.dot(um.cross(DVec3::Z));
    let p = crate::angle::wrap180(crate::angle::atan2d(-a, b));
    let q = crate::angle::wrap180(p + 180.0);
    let along_slave = |deg: f64| (DMat3::from_axis_angle(um, deg.to_radians()) * DVec3::Z).dot(us);
    let p_first = if crate::unconfirmed::SYMMETRY_POINT_CODIRECTIONAL {
        along_slave(p) >= along_slave(q)
    } else {
        p.abs() <= q.abs()
    };
    if p_first { [p, q] } else { [q, p] }
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
