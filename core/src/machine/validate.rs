//! The one check of a machine description ([`MachineDef`]): every reader (the compiled-in
//! machines, [`Machine::from_json`], the machine editor and its saved record in `schwenkbar-app`) goes through [`validate`], which
//! reports every problem it finds, not only the first, each with the path of its field
//! ([`MachinePath`], written `chain[1].direction`, `geometry.linear_limits.X`) so that the editor
//! shows it at the field that has the same path.
//!
//! The rules:
//! - `id`, `name.de` and `name.en` are not empty (blanks only count as empty);
//! - `chain` has exactly two rotary axes: the solver ([`crate::kinematics`]) solves for two;
//! - each `axis` is `A`, `B` or `C`, and no letter appears twice;
//! - each `carrier` is `table` or `head`, and the **chain order** is workpiece → tool: every
//!   table axis before every head axis (a head axis followed by a table axis is reported at the
//!   table axis's `carrier`). The order is what the kinematics read: the last axis is the master
//!   (the first seen from the tool, DOMAIN.md §3.1), so a head axis before a table axis would make
//!   a table axis the master on a machine whose tool is tilted by the head;
//! - every number is finite; `direction` is a unit vector (the zero vector has its own message),
//!   the two directions are not parallel, and the master's is not the tool axis at home;
//! - rotary `limits` and `geometry.linear_limits` have min < max (min = max would be an axis that
//!   cannot move), an `endless` axis has no limits;
//! - the rapid rates are > 0, and `geometry.start` lies within the linear limits;
//! - each collision body (`collision[i]`) has a name in both languages, a `carrier` that is
//!   `bed`, `head` or the letter of a table axis of the chain, exactly one shape (`box` or
//!   `cylinder`), finite numbers, a box size and a cylinder radius and height > 0 and a cylinder
//!   direction that is a unit vector.

use glam::DVec3;
use serde::Serialize;

use super::path::{BodyField, GeometryField, JointField, MachinePath};
use super::{
    Body, BodyCarrier, BodyDef, BodyShape, Carrier, Limits, Machine, MachineDef, MachineGeometry, RotaryJoint,
};
use crate::lang::{Lang, Text};
use crate::number::prose;
use crate::plane::RotaryAxis;

/// Direction tolerance: |direction| must be 1 within this (so 0.7071067811865476 works).
const UNIT_TOL: f64 = 1e-6;
/// Sine below which two axis directions count as parallel (derived, numerical).
const PARALLEL_TOL: f64 = 1e-6;

/// One problem of a machine description: where it is and what it is.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MachineIssue {
    /// The field ([`MachinePath::Whole`] for the description as a whole: unreadable JSON).
    pub path: MachinePath,
    pub problem: Problem,
}

impl MachineIssue {
    pub(super) fn at(path: MachinePath, problem: Problem) -> MachineIssue {
        MachineIssue { path, problem }
    }

    /// The message in German and English, with the field path in front (when there is one).
    #[must_use]
    pub fn message(&self) -> Text {
        let text = self.problem.message();
        if self.path == MachinePath::Whole {
            return text;
        }
        Text::owned(format!("{}: {}", self.path, text.de), format!("{}: {}", self.path, text.en))
    }
}

impl std::fmt::Display for MachineIssue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.message().get(Lang::En))
    }
}

/// What is wrong with a field. Every variant carries the numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum Problem {
    /// Not JSON of the machine schema (a syntax error, a missing or unknown field, a wrong type).
    Json { message: String, line: usize, column: usize },
    /// An id or name with no text.
    Empty,
    /// Not exactly two rotary axes.
    AxisCount { count: usize },
    /// An axis letter other than A, B, C.
    UnknownAxis { letter: String },
    /// The same letter twice in the chain.
    DuplicateAxis { axis: RotaryAxis },
    /// A carrier other than `table` or `head`.
    UnknownCarrier { carrier: String },
    /// A table axis listed after a head axis.
    TableAfterHead { axis: RotaryAxis },
    /// A number that is NaN or infinite.
    NotFinite { value: f64 },
    /// `direction` is (0, 0, 0).
    ZeroDirection,
    /// `direction` is not a unit vector (tolerance 1e-6).
    DirectionNotUnit { length: f64 },
    /// `min` is not below `max`.
    LimitsInverted { min: f64, max: f64 },
    /// An endless (modulo) axis with limit switches.
    EndlessWithLimits,
    /// The two axes are parallel: they cannot tilt the tool in two directions.
    ParallelAxes { slave: RotaryAxis, master: RotaryAxis },
    /// The master axis is parallel to the tool axis at home: it cannot tilt the tool.
    MasterAlongTool { axis: RotaryAxis },
    /// A rapid rate ≤ 0.
    NotPositive { value: f64 },
    /// The start position of a linear axis outside its limits.
    StartOutside { axis: char, value: f64, min: f64, max: f64 },
    /// A collision body's carrier that is neither `bed`, `head` nor a table axis of the chain
    /// (`table_axes`: the letters that are).
    UnknownBodyCarrier { carrier: String, table_axes: String },
    /// A collision body with no shape or with both `box` and `cylinder`.
    BodyShapeCount { count: usize },
}

/// A number in running text of each language (`-12,5` / `-12.5`).
fn num(x: f64) -> [String; 2] {
    [prose(x, None, Lang::De), prose(x, None, Lang::En)]
}

impl Problem {
    /// The message, German and English.
    #[must_use]
    pub fn message(&self) -> Text {
        match self {
            Problem::Json { message, line, column } => Text::owned(
                format!("Maschinendatei nicht lesbar (Zeile {line}, Spalte {column}): {message}"),
                format!("Machine file unreadable (line {line}, column {column}): {message}"),
            ),
            Problem::Empty => Text::new("darf nicht leer sein", "must not be empty"),
            Problem::AxisCount { count } => Text::owned(
                format!("{count} Drehachsen: genau 2 werden unterstützt"),
                format!("{count} rotary axes: exactly 2 are supported"),
            ),
            Problem::UnknownAxis { letter } => Text::owned(
                format!("unbekannte Drehachse „{letter}“ (A, B oder C)"),
                format!("unknown rotary axis \"{letter}\" (A, B or C)"),
            ),
            Problem::DuplicateAxis { axis } => Text::owned(
                format!("Achse {axis} steht zweimal in der Kette"),
                format!("axis {axis} appears twice in the chain"),
            ),
            Problem::UnknownCarrier { carrier } => Text::owned(
                format!("unbekannter Träger „{carrier}“ (table = Tisch oder head = Kopf)"),
                format!("unknown carrier \"{carrier}\" (table or head)"),
            ),
            Problem::TableAfterHead { axis } => Text::owned(
                format!(
                    "Tischachse {axis} nach einer Kopfachse: die Kette läuft Werkstück → Tisch → Kopf → Werkzeug"
                ),
                format!(
                    "table axis {axis} after a head axis: the chain runs workpiece → table → head → tool"
                ),
            ),
            Problem::NotFinite { value } => Text::owned(
                format!("keine endliche Zahl ({value})"),
                format!("not a finite number ({value})"),
            ),
            Problem::ZeroDirection => {
                Text::new("Richtung ist der Nullvektor", "direction is the zero vector")
            }
            Problem::DirectionNotUnit { length } => {
                let [de, en] = num(*length);
                Text::owned(
                    format!("Richtung ist kein Einheitsvektor (Länge {de})"),
                    format!("direction is not a unit vector (length {en})"),
                )
            }
            Problem::LimitsInverted { min, max } => {
                let ([min_de, min_en], [max_de, max_en]) = (num(*min), num(*max));
                Text::owned(
                    format!("min {min_de} muss kleiner als max {max_de} sein"),
                    format!("min {min_en} must be less than max {max_en}"),
                )
            }
            Problem::EndlessWithLimits => Text::new(
                "endlose Achse mit Endschaltern: limits weglassen oder endless entfernen",
                "endless axis with limit switches: drop limits or endless",
            ),
            Problem::ParallelAxes { slave, master } => Text::owned(
                format!("Achsen {slave} und {master} sind parallel: sie schwenken nicht in zwei Richtungen"),
                format!("axes {slave} and {master} are parallel: they cannot tilt in two directions"),
            ),
            Problem::MasterAlongTool { axis } => Text::owned(
                format!(
                    "Masterachse {axis} liegt in Grundstellung parallel zur Werkzeugachse: sie schwenkt das Werkzeug nicht"
                ),
                format!("master axis {axis} is parallel to the tool axis at home: it cannot tilt the tool"),
            ),
            Problem::NotPositive { value } => {
                let [de, en] = num(*value);
                Text::owned(
                    format!("muss größer als 0 sein ({de})"),
                    format!("must be greater than 0 ({en})"),
                )
            }
            Problem::StartOutside { axis, value, min, max } => {
                let ([v_de, v_en], [min_de, min_en], [max_de, max_en]) = (num(*value), num(*min), num(*max));
                Text::owned(
                    format!("Startposition {axis} {v_de} außerhalb der Grenzen {min_de} … {max_de}"),
                    format!("start position {axis} {v_en} outside the limits {min_en} … {max_en}"),
                )
            }
            Problem::UnknownBodyCarrier { carrier, table_axes } => {
                let (de, en) = if table_axes.is_empty() {
                    (String::new(), String::new())
                } else {
                    (
                        format!(" oder eine Tischachse: {table_axes}"),
                        format!(" or a table axis: {table_axes}"),
                    )
                };
                Text::owned(
                    format!(
                        "unbekannter Träger „{carrier}“ des Kollisionskörpers (bed = Bett, head = Kopf{de})"
                    ),
                    format!("unknown carrier \"{carrier}\" of the collision body (bed, head{en})"),
                )
            }
            Problem::BodyShapeCount { count } => Text::owned(
                format!("{count} Formen: ein Kollisionskörper ist genau eine Form, box oder cylinder"),
                format!("{count} shapes: a collision body is exactly one shape, box or cylinder"),
            ),
        }
    }
}

/// Checks `def` and builds the machine, or lists every problem (the rules are in the module
/// docs). Problems that depend on an earlier field (two directions parallel, the start within the
/// limits) are only looked at when that field itself is sound, so each cause is reported once.
pub(super) fn validate(def: &MachineDef) -> Result<Machine, Vec<MachineIssue>> {
    let mut issues = Vec::new();
    for (path, text) in [
        (MachinePath::Id, &*def.id),
        (MachinePath::Name(Lang::De), &*def.name.de),
        (MachinePath::Name(Lang::En), &*def.name.en),
    ] {
        if text.trim().is_empty() {
            issues.push(MachineIssue::at(path, Problem::Empty));
        }
    }
    let before_chain = issues.len();
    let joints: Vec<Option<RotaryJoint>> =
        def.chain.iter().enumerate().map(|(i, j)| joint(i, j, &mut issues)).collect();
    chain_order(&joints, &mut issues);
    let chain = two_axes(joints, &mut issues);
    let chain_sound = chain.is_some() && issues.len() == before_chain;
    let geometry = geometry(def.geometry.as_ref(), &mut issues);
    let bodies: Vec<Body> = def
        .collision
        .iter()
        .enumerate()
        .filter_map(|(i, b)| body(i, b, def, chain_sound, &mut issues))
        .collect();
    match chain {
        Some(chain) if issues.is_empty() => {
            let [slave, master] = &chain;
            let symmetry = super::symmetry_positions_of(slave.direction, master.direction);
            Ok(Machine {
                id: def.id.to_string(),
                name: def.name.clone(),
                description: def.description.clone(),
                chain,
                symmetry,
                geometry,
                bodies,
            })
        }
        _ => Err(issues),
    }
}

/// One chain entry, or `None` (with its issues pushed) when a field is wrong.
fn joint(i: usize, j: &super::JointDef, issues: &mut Vec<MachineIssue>) -> Option<RotaryJoint> {
    let before = issues.len();
    let at = |field: JointField| MachinePath::Joint(i, field);
    let axis = RotaryAxis::from_letter(&j.axis);
    if axis.is_none() {
        issues.push(MachineIssue::at(
            at(JointField::Axis),
            Problem::UnknownAxis { letter: j.axis.to_string() },
        ));
    }
    let carrier = Carrier::from_word(&j.carrier);
    if carrier.is_none() {
        issues.push(MachineIssue::at(
            at(JointField::Carrier),
            Problem::UnknownCarrier { carrier: j.carrier.to_string() },
        ));
    }
    let direction = DVec3::from_array(j.direction);
    if let Some(value) = not_finite(&j.direction) {
        issues.push(MachineIssue::at(at(JointField::Direction), Problem::NotFinite { value }));
    } else if direction == DVec3::ZERO {
        issues.push(MachineIssue::at(at(JointField::Direction), Problem::ZeroDirection));
    } else if (direction.length() - 1.0).abs() > UNIT_TOL {
        issues.push(MachineIssue::at(
            at(JointField::Direction),
            Problem::DirectionNotUnit { length: direction.length() },
        ));
    }
    if let Some(value) = not_finite(&j.pivot) {
        issues.push(MachineIssue::at(at(JointField::Pivot), Problem::NotFinite { value }));
    }
    if let Some(l) = j.limits {
        if let Some(problem) = limits_problem(l) {
            issues.push(MachineIssue::at(at(JointField::Limits), problem));
        } else if j.endless {
            issues.push(MachineIssue::at(at(JointField::Endless), Problem::EndlessWithLimits));
        }
    }
    match (axis, carrier) {
        (Some(axis), Some(carrier)) if issues.len() == before => Some(RotaryJoint {
            axis,
            carrier,
            direction: direction / direction.length(),
            pivot: DVec3::from_array(j.pivot),
            limits: j.limits,
            endless: j.endless,
        }),
        _ => None,
    }
}

/// The first NaN or infinite number, if any.
fn not_finite(values: &[f64]) -> Option<f64> {
    values.iter().copied().find(|x| !x.is_finite())
}

/// What is wrong with a min/max pair, if anything.
fn limits_problem(l: Limits) -> Option<Problem> {
    if let Some(value) = not_finite(&[l.min, l.max]) {
        Some(Problem::NotFinite { value })
    } else if l.min >= l.max {
        Some(Problem::LimitsInverted { min: l.min, max: l.max })
    } else {
        None
    }
}

/// Duplicate letters and the table-before-head order, on the joints that could be read.
fn chain_order(joints: &[Option<RotaryJoint>], issues: &mut Vec<MachineIssue>) {
    let mut head_seen = false;
    for (i, j) in joints.iter().enumerate() {
        let Some(j) = j else { continue };
        if joints[..i].iter().flatten().any(|k| k.axis == j.axis) {
            issues.push(MachineIssue::at(
                MachinePath::Joint(i, JointField::Axis),
                Problem::DuplicateAxis { axis: j.axis },
            ));
        }
        match j.carrier {
            Carrier::Head => head_seen = true,
            Carrier::Table if head_seen => issues.push(MachineIssue::at(
                MachinePath::Joint(i, JointField::Carrier),
                Problem::TableAfterHead { axis: j.axis },
            )),
            Carrier::Table => {}
        }
    }
}

/// The chain as `[slave, master]` when it has exactly two sound axes that can tilt the tool.
fn two_axes(joints: Vec<Option<RotaryJoint>>, issues: &mut Vec<MachineIssue>) -> Option<[RotaryJoint; 2]> {
    if joints.len() != 2 {
        issues.push(MachineIssue::at(MachinePath::Chain, Problem::AxisCount { count: joints.len() }));
        return None;
    }
    let [Some(slave), Some(master)]: [Option<RotaryJoint>; 2] = joints.try_into().ok()? else {
        return None;
    };
    if slave.direction.cross(master.direction).length() < PARALLEL_TOL {
        let problem = Problem::ParallelAxes { slave: slave.axis, master: master.axis };
        issues.push(MachineIssue::at(MachinePath::Joint(1, JointField::Direction), problem));
    } else if master.direction.cross(DVec3::Z).length() < PARALLEL_TOL {
        issues.push(MachineIssue::at(
            MachinePath::Joint(1, JointField::Direction),
            Problem::MasterAlongTool { axis: master.axis },
        ));
    }
    Some([slave, master])
}

/// `geometry` with its defaults filled in; its issues pushed.
fn geometry(def: Option<&super::GeometryDef>, issues: &mut Vec<MachineIssue>) -> MachineGeometry {
    let mut g = MachineGeometry::default();
    let Some(def) = def else { return g };
    let mut vec3 =
        |field: GeometryField, v: Option<[f64; 3]>, slot: &mut DVec3| match v.map(|v| (v, not_finite(&v))) {
            Some((_, Some(value))) => {
                issues.push(MachineIssue::at(MachinePath::Geometry(field), Problem::NotFinite { value }))
            }
            Some((v, None)) => *slot = DVec3::from_array(v),
            None => {}
        };
    vec3(GeometryField::Preset, def.preset, &mut g.preset);
    vec3(GeometryField::Start, def.start, &mut g.start);
    if let Some(top) = def.table_top {
        let mut at = DVec3::ZERO;
        vec3(GeometryField::TableTop, Some(top), &mut at);
        g.table_top = not_finite(&top).is_none().then_some(at);
    }
    let start_sound = def.start.is_none_or(|v| not_finite(&v).is_none());
    let mut limits_sound = [true; 3];
    if let Some(l) = def.linear_limits {
        for (i, lim) in [l.x, l.y, l.z].into_iter().enumerate() {
            let Some(lim) = lim else { continue };
            match limits_problem(lim) {
                Some(problem) => {
                    issues.push(MachineIssue::at(
                        MachinePath::Geometry(GeometryField::LinearLimits(i)),
                        problem,
                    ));
                    limits_sound[i] = false;
                }
                None => g.linear_limits[i] = lim,
            }
        }
    }
    for (field, v, slot) in [
        (GeometryField::RapidLinear, def.rapid_linear, &mut g.rapid_linear),
        (GeometryField::RapidRotary, def.rapid_rotary, &mut g.rapid_rotary),
    ] {
        match v {
            Some(value) if !value.is_finite() => {
                issues.push(MachineIssue::at(MachinePath::Geometry(field), Problem::NotFinite { value }))
            }
            Some(value) if value <= 0.0 => {
                issues.push(MachineIssue::at(MachinePath::Geometry(field), Problem::NotPositive { value }))
            }
            Some(value) => *slot = value,
            None => {}
        }
    }
    if start_sound {
        for (i, letter) in ['X', 'Y', 'Z'].into_iter().enumerate() {
            let (value, lim) = (g.start[i], g.linear_limits[i]);
            if limits_sound[i] && !lim.contains(value) {
                let problem = Problem::StartOutside { axis: letter, value, min: lim.min, max: lim.max };
                issues.push(MachineIssue::at(MachinePath::Geometry(GeometryField::Start), problem));
            }
        }
    }
    g
}

/// One collision body, or `None` (with its issues pushed) when a field is wrong.
fn body(
    i: usize,
    b: &BodyDef,
    def: &MachineDef,
    chain_sound: bool,
    issues: &mut Vec<MachineIssue>,
) -> Option<Body> {
    let before = issues.len();
    let at = |field: BodyField| MachinePath::BodyField(i, field);
    for (field, text) in [(BodyField::Name(Lang::De), &*b.name.de), (BodyField::Name(Lang::En), &*b.name.en)]
    {
        if text.trim().is_empty() {
            issues.push(MachineIssue::at(at(field), Problem::Empty));
        }
    }
    let table_axis = |j: &super::JointDef| Carrier::from_word(&j.carrier) == Some(Carrier::Table);
    let carrier = match &*b.carrier {
        "bed" => Some(BodyCarrier::Bed),
        "head" => Some(BodyCarrier::Head),
        word => def
            .chain
            .iter()
            .position(|j| table_axis(j) && *j.axis == *word)
            .map(|joint| BodyCarrier::Table { joint }),
    };
    // A body's axis is only looked up in a sound chain (a wrong chain is reported at the chain,
    // once).
    if carrier.is_none() && chain_sound {
        let table_axes: Vec<&str> = def.chain.iter().filter(|j| table_axis(j)).map(|j| &*j.axis).collect();
        issues.push(MachineIssue::at(
            at(BodyField::Carrier),
            Problem::UnknownBodyCarrier { carrier: b.carrier.to_string(), table_axes: table_axes.join(", ") },
        ));
    }
    let mut positive = |field: BodyField, values: &[f64]| {
        if let Some(value) = not_finite(values) {
            issues.push(MachineIssue::at(at(field), Problem::NotFinite { value }));
        } else if let Some(&value) = values.iter().find(|&&v| v <= 0.0) {
            issues.push(MachineIssue::at(at(field), Problem::NotPositive { value }));
        }
    };
    let shape = match (b.cuboid, b.cylinder) {
        (Some(c), None) => {
            positive(BodyField::BoxSize, &c.size);
            if let Some(value) = not_finite(&c.center) {
                issues.push(MachineIssue::at(at(BodyField::BoxCenter), Problem::NotFinite { value }));
            }
            Some(BodyShape::Box {
                center: DVec3::from_array(c.center),
                half: 0.5 * DVec3::from_array(c.size),
            })
        }
        (None, Some(c)) => {
            positive(BodyField::CylinderRadius, &[c.radius]);
            positive(BodyField::CylinderHeight, &[c.height]);
            if let Some(value) = not_finite(&c.base) {
                issues.push(MachineIssue::at(at(BodyField::CylinderBase), Problem::NotFinite { value }));
            }
            let direction = DVec3::from_array(c.direction);
            if let Some(value) = not_finite(&c.direction) {
                issues.push(MachineIssue::at(at(BodyField::CylinderDirection), Problem::NotFinite { value }));
            } else if direction == DVec3::ZERO {
                issues.push(MachineIssue::at(at(BodyField::CylinderDirection), Problem::ZeroDirection));
            } else if (direction.length() - 1.0).abs() > UNIT_TOL {
                issues.push(MachineIssue::at(
                    at(BodyField::CylinderDirection),
                    Problem::DirectionNotUnit { length: direction.length() },
                ));
            }
            Some(BodyShape::Cylinder {
                base: DVec3::from_array(c.base),
                direction: direction.normalize_or_zero(),
                radius: c.radius,
                height: c.height,
            })
        }
        (a, c) => {
            let count = usize::from(a.is_some()) + usize::from(c.is_some());
            issues.push(MachineIssue::at(MachinePath::Body(i), Problem::BodyShapeCount { count }));
            None
        }
    };
    match (carrier, shape) {
        (Some(carrier), Some(shape)) if issues.len() == before => {
            Some(Body { name: b.name.clone(), carrier, shape })
        }
        _ => None,
    }
}
