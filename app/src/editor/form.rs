//! The form as typed: every field of a [`MachineDef`] kept as its text, to and from the
//! description, and checked ([`check`]) with each problem at its field's path.

use std::borrow::Cow;

use schwenkbar_core::machine::{
    BodyDef, BoxDef, Carrier, CylinderDef, GeometryDef, JointDef, Limits, LinearLimitsDef, Machine,
    MachineDef, MachineGeometry, MachineIssue, MachinePath,
};
use schwenkbar_core::number::parse_input;

use super::Field;
use crate::i18n::Text;
use crate::saved_machines;

/// One rotary axis as typed.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct JointForm {
    pub axis: String,
    /// `table` or `head`, the JSON's word.
    pub carrier: String,
    pub direction: [String; 3],
    pub pivot: [String; 3],
    pub endless: bool,
    /// Both empty: no limit switches.
    pub min: String,
    pub max: String,
}

/// One collision body as typed: only the fields of its shape hold text (switching the shape
/// fills the other's from it, [`BodyForm::switch_to`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BodyForm {
    pub name: [String; 2],
    /// `bed`, `head` or a table axis letter, the JSON's word.
    pub carrier: String,
    /// A cylinder (`false`: a box).
    pub cylinder: bool,
    /// Box: centre and edge lengths along X, Y, Z.
    pub center: [String; 3],
    pub size: [String; 3],
    /// Cylinder: the centre of one end face, the unit direction to the other, radius, height.
    pub base: [String; 3],
    pub direction: [String; 3],
    pub radius: String,
    pub height: String,
}

impl BodyForm {
    /// The form of a description. A body with both shapes (only from an imported file) keeps
    /// its box; one with none shows an empty box, whose fields are then reported.
    #[must_use]
    pub fn of(b: &BodyDef) -> BodyForm {
        let mut f = BodyForm {
            name: [b.name.de.to_string(), b.name.en.to_string()],
            carrier: b.carrier.to_string(),
            ..BodyForm::default()
        };
        match (b.cuboid, b.cylinder) {
            (None, Some(c)) => {
                f.cylinder = true;
                f.base = texts(c.base);
                f.direction = texts(c.direction);
                f.radius = text(c.radius);
                f.height = text(c.height);
            }
            (Some(c), _) => {
                f.center = texts(c.center);
                f.size = texts(c.size);
            }
            (None, None) => {}
        }
        f
    }

    /// A new body: a 100 mm cube on the bed, below the table, for the trainee to place.
    #[must_use]
    pub fn new_body(n: usize) -> BodyForm {
        BodyForm {
            name: [format!("Körper {n}"), format!("body {n}")],
            carrier: "bed".into(),
            cylinder: false,
            center: texts([0.0, 0.0, -600.0]),
            size: texts([100.0; 3]),
            ..BodyForm::default()
        }
    }

    /// Makes the body a cylinder (`true`) or a box, its new fields derived from the old ones
    /// when they are numbers (a box's inscribed upright cylinder, a cylinder's bounding box),
    /// the old ones emptied.
    pub fn switch_to(&mut self, cylinder: bool) {
        if cylinder == self.cylinder {
            return;
        }
        let v3 = |v: &[String; 3]| -> Option<[f64; 3]> {
            Some([parse_input(&v[0])?, parse_input(&v[1])?, parse_input(&v[2])?])
        };
        if cylinder {
            if let (Some(c), Some(s)) = (v3(&self.center), v3(&self.size)) {
                self.base = texts([c[0], c[1], c[2] - 0.5 * s[2]]);
                self.direction = texts([0.0, 0.0, 1.0]);
                self.radius = text(0.5 * s[0].min(s[1]));
                self.height = text(s[2]);
            }
            self.center = Default::default();
            self.size = Default::default();
        } else {
            let (r, h) = (parse_input(&self.radius), parse_input(&self.height));
            if let (Some(b), Some(d), Some(r), Some(h)) = (v3(&self.base), v3(&self.direction), r, h) {
                self.center = std::array::from_fn(|k| text(b[k] + 0.5 * h * d[k]));
                // The bounding box of a cylinder along the unit vector d: h·|dₖ| + 2r·√(1 − dₖ²).
                self.size = std::array::from_fn(|k| {
                    text(h * d[k].abs() + 2.0 * r * (1.0 - d[k] * d[k]).max(0.0).sqrt())
                });
            }
            self.base = Default::default();
            self.direction = Default::default();
            self.radius.clear();
            self.height.clear();
        }
        self.cylinder = cylinder;
    }
}

/// The whole description as typed, every number as its text.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Form {
    pub id: String,
    pub name: [String; 2],
    pub description: [String; 2],
    /// Chain order workpiece → tool: `[slave, master]`.
    pub joints: [JointForm; 2],
    pub preset: [String; 3],
    /// X, Y, Z, each `[min, max]`.
    pub linear: [[String; 2]; 3],
    pub rapid_linear: String,
    pub rapid_rotary: String,
    pub start: [String; 3],
    /// The table's clamping surface centre; all three empty: none (the preset stays fixed).
    pub table_top: [String; 3],
    /// The collision bodies.
    pub collision: Vec<BodyForm>,
}

/// A number as the form shows it: Rust's shortest form that reads back to the same value.
fn text(x: f64) -> String {
    format!("{x}")
}

fn texts(v: [f64; 3]) -> [String; 3] {
    v.map(text)
}

impl Form {
    /// The form of a description (a missing geometry field shows its default); `None` when
    /// the chain has not exactly two axes (the form has two).
    #[must_use]
    pub fn of(def: &MachineDef) -> Option<Form> {
        let joints: [JointForm; 2] = def
            .chain
            .iter()
            .map(|j| JointForm {
                axis: j.axis.to_string(),
                carrier: j.carrier.to_string(),
                direction: texts(j.direction),
                pivot: texts(j.pivot),
                endless: j.endless,
                min: j.limits.map(|l| text(l.min)).unwrap_or_default(),
                max: j.limits.map(|l| text(l.max)).unwrap_or_default(),
            })
            .collect::<Vec<_>>()
            .try_into()
            .ok()?;
        let d = MachineGeometry::default();
        let g = def.geometry.unwrap_or(GeometryDef {
            preset: None,
            linear_limits: None,
            rapid_linear: None,
            rapid_rotary: None,
            start: None,
            table_top: None,
        });
        let lin = g.linear_limits.unwrap_or(LinearLimitsDef { x: None, y: None, z: None });
        let linear = [lin.x, lin.y, lin.z]
            .into_iter()
            .zip(d.linear_limits)
            .map(|(l, default)| {
                let l = l.unwrap_or(default);
                [text(l.min), text(l.max)]
            })
            .collect::<Vec<_>>()
            .try_into()
            .ok()?;
        Some(Form {
            id: def.id.to_string(),
            name: [def.name.de.to_string(), def.name.en.to_string()],
            description: [def.description.de.to_string(), def.description.en.to_string()],
            joints,
            preset: texts(g.preset.unwrap_or(d.preset.to_array())),
            linear,
            rapid_linear: text(g.rapid_linear.unwrap_or(d.rapid_linear)),
            rapid_rotary: text(g.rapid_rotary.unwrap_or(d.rapid_rotary)),
            start: texts(g.start.unwrap_or(d.start.to_array())),
            table_top: g.table_top.map(texts).unwrap_or_default(),
            collision: def.collision.iter().map(BodyForm::of).collect(),
        })
    }

    /// What may carry a collision body of this form: the bed, the head and each table axis of
    /// the chain as typed (the word, its label).
    #[must_use]
    pub fn body_carriers(&self) -> Vec<(String, Text)> {
        let mut out = vec![
            ("bed".to_owned(), Text::new("Bett (bed)", "bed")),
            ("head".to_owned(), Text::new("Kopf (head)", "head")),
        ];
        for j in &self.joints {
            let axis = j.axis.trim().to_ascii_uppercase();
            if Carrier::from_word(&j.carrier) == Some(Carrier::Table) && !axis.is_empty() {
                out.push((
                    axis.clone(),
                    Text::owned(format!("Tischachse {axis}"), format!("table axis {axis}")),
                ));
            }
        }
        out
    }

    /// The text of an input; the endless switch reads `"1"` or `""`.
    #[must_use]
    pub fn value(&self, field: Field) -> String {
        match field {
            Field::Endless(i) => if self.joints[i.min(1)].endless { "1" } else { "" }.to_owned(),
            Field::BodyShape(i) => match self.collision.get(i) {
                Some(b) if b.cylinder => "cylinder".to_owned(),
                Some(_) => "box".to_owned(),
                None => String::new(),
            },
            f => self.slot_read(f).cloned().unwrap_or_default(),
        }
    }

    fn slot_read(&self, field: Field) -> Option<&String> {
        let j = |i: usize| self.joints.get(i);
        Some(match field {
            Field::Id => &self.id,
            Field::Name(l) => self.name.get(l)?,
            Field::Description(l) => self.description.get(l)?,
            Field::Axis(i) => &j(i)?.axis,
            Field::Carrier(i) => &j(i)?.carrier,
            Field::Direction(i, c) => j(i)?.direction.get(c)?,
            Field::Pivot(i, c) => j(i)?.pivot.get(c)?,
            Field::Endless(_) => return None,
            Field::Min(i) => &j(i)?.min,
            Field::Max(i) => &j(i)?.max,
            Field::Preset(c) => self.preset.get(c)?,
            Field::Linear(a, m) => self.linear.get(a)?.get(m)?,
            Field::RapidLinear => &self.rapid_linear,
            Field::RapidRotary => &self.rapid_rotary,
            Field::Start(c) => self.start.get(c)?,
            Field::TableTop(c) => self.table_top.get(c)?,
            Field::BodyName(i, l) => self.collision.get(i)?.name.get(l)?,
            Field::BodyCarrier(i) => &self.collision.get(i)?.carrier,
            Field::BodyShape(_) => return None,
            Field::BodyCenter(i, c) => self.collision.get(i)?.center.get(c)?,
            Field::BodySize(i, c) => self.collision.get(i)?.size.get(c)?,
            Field::BodyBase(i, c) => self.collision.get(i)?.base.get(c)?,
            Field::BodyDirection(i, c) => self.collision.get(i)?.direction.get(c)?,
            Field::BodyRadius(i) => &self.collision.get(i)?.radius,
            Field::BodyHeight(i) => &self.collision.get(i)?.height,
        })
    }

    /// The text of `field`, to be written (the reducer sets what was typed).
    pub(super) fn slot(&mut self, field: Field) -> Option<&mut String> {
        Some(match field {
            Field::Id => &mut self.id,
            Field::Name(l) => self.name.get_mut(l)?,
            Field::Description(l) => self.description.get_mut(l)?,
            Field::Axis(i) => &mut self.joints.get_mut(i)?.axis,
            Field::Carrier(i) => &mut self.joints.get_mut(i)?.carrier,
            Field::Direction(i, c) => self.joints.get_mut(i)?.direction.get_mut(c)?,
            Field::Pivot(i, c) => self.joints.get_mut(i)?.pivot.get_mut(c)?,
            Field::Endless(_) => return None,
            Field::Min(i) => &mut self.joints.get_mut(i)?.min,
            Field::Max(i) => &mut self.joints.get_mut(i)?.max,
            Field::Preset(c) => self.preset.get_mut(c)?,
            Field::Linear(a, m) => self.linear.get_mut(a)?.get_mut(m)?,
            Field::RapidLinear => &mut self.rapid_linear,
            Field::RapidRotary => &mut self.rapid_rotary,
            Field::Start(c) => self.start.get_mut(c)?,
            Field::TableTop(c) => self.table_top.get_mut(c)?,
            Field::BodyName(i, l) => self.collision.get_mut(i)?.name.get_mut(l)?,
            Field::BodyCarrier(i) => &mut self.collision.get_mut(i)?.carrier,
            Field::BodyShape(_) => return None,
            Field::BodyCenter(i, c) => self.collision.get_mut(i)?.center.get_mut(c)?,
            Field::BodySize(i, c) => self.collision.get_mut(i)?.size.get_mut(c)?,
            Field::BodyBase(i, c) => self.collision.get_mut(i)?.base.get_mut(c)?,
            Field::BodyDirection(i, c) => self.collision.get_mut(i)?.direction.get_mut(c)?,
            Field::BodyRadius(i) => &mut self.collision.get_mut(i)?.radius,
            Field::BodyHeight(i) => &mut self.collision.get_mut(i)?.height,
        })
    }

    /// The description the form stands for and the fields whose text is no number (their
    /// value is NaN in the description; [`check`] reports them instead of validate's "not
    /// finite").
    #[must_use]
    pub fn to_def(&self) -> (MachineDef, Vec<FieldIssue>) {
        let mut bad = Vec::new();
        let mut num = |field: Field, s: &str| match parse_input(s) {
            Some(v) => v,
            None => {
                let path = field.path();
                if !bad.iter().any(|b: &FieldIssue| b.path == path) {
                    bad.push(FieldIssue { path, message: NOT_A_NUMBER });
                }
                f64::NAN
            }
        };
        let mut v3 = |f: fn(usize) -> Field, v: &[String; 3]| -> [f64; 3] {
            [num(f(0), &v[0]), num(f(1), &v[1]), num(f(2), &v[2])]
        };
        let preset = v3(Field::Preset, &self.preset);
        let start = v3(Field::Start, &self.start);
        let table_top = (!self.table_top.iter().all(|t| t.trim().is_empty()))
            .then(|| v3(Field::TableTop, &self.table_top));
        let mut chain = Vec::with_capacity(2);
        for (i, j) in self.joints.iter().enumerate() {
            let direction = [0, 1, 2].map(|c| num(Field::Direction(i, c), &j.direction[c]));
            let pivot = [0, 1, 2].map(|c| num(Field::Pivot(i, c), &j.pivot[c]));
            let limits = match (j.min.trim().is_empty(), j.max.trim().is_empty()) {
                (true, true) => None,
                _ => Some(Limits { min: num(Field::Min(i), &j.min), max: num(Field::Max(i), &j.max) }),
            };
            chain.push(JointDef {
                axis: Cow::Owned(j.axis.trim().to_ascii_uppercase()),
                carrier: Cow::Owned(j.carrier.clone()),
                direction,
                pivot,
                limits,
                endless: j.endless,
            });
        }
        let lim = |a: usize, num: &mut dyn FnMut(Field, &str) -> f64| Limits {
            min: num(Field::Linear(a, 0), &self.linear[a][0]),
            max: num(Field::Linear(a, 1), &self.linear[a][1]),
        };
        let (x, y, z) = (lim(0, &mut num), lim(1, &mut num), lim(2, &mut num));
        let rapid_linear = num(Field::RapidLinear, &self.rapid_linear);
        let rapid_rotary = num(Field::RapidRotary, &self.rapid_rotary);
        let collision = self
            .collision
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let mut v3 = |f: fn(usize, usize) -> Field, v: &[String; 3]| -> [f64; 3] {
                    [0, 1, 2].map(|c| num(f(i, c), &v[c]))
                };
                let (cuboid, cylinder) = if b.cylinder {
                    let base = v3(Field::BodyBase, &b.base);
                    let direction = v3(Field::BodyDirection, &b.direction);
                    let radius = num(Field::BodyRadius(i), &b.radius);
                    let height = num(Field::BodyHeight(i), &b.height);
                    (None, Some(CylinderDef { base, direction, radius, height }))
                } else {
                    let center = v3(Field::BodyCenter, &b.center);
                    (Some(BoxDef { center, size: v3(Field::BodySize, &b.size) }), None)
                };
                BodyDef {
                    name: Text::owned(b.name[0].clone(), b.name[1].clone()),
                    carrier: Cow::Owned(b.carrier.trim().to_owned()),
                    cuboid,
                    cylinder,
                }
            })
            .collect();
        let def = MachineDef {
            id: Cow::Owned(self.id.trim().to_owned()),
            name: Text::owned(self.name[0].clone(), self.name[1].clone()),
            description: Text::owned(self.description[0].clone(), self.description[1].clone()),
            chain: Cow::Owned(chain),
            geometry: Some(GeometryDef {
                preset: Some(preset),
                linear_limits: Some(LinearLimitsDef { x: Some(x), y: Some(y), z: Some(z) }),
                rapid_linear: Some(rapid_linear),
                rapid_rotary: Some(rapid_rotary),
                start: Some(start),
                table_top,
            }),
            collision: Cow::Owned(collision),
        };
        (def, bad)
    }
}

/// A message at a field (or, at [`MachinePath::Whole`], about the whole description).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldIssue {
    pub path: MachinePath,
    pub message: Text,
}

const NOT_A_NUMBER: Text = Text::new("keine Zahl (z. B. -12,5)", "not a number (e.g. -12.5)");
const SHIPPED_ID: Text = Text::new(
    "Kennung einer mitgelieferten Maschine: bitte eine eigene wählen",
    "the id of a shipped machine: choose one of your own",
);

/// The form's description checked: its numbers, then [`MachineDef::validate`] (a problem of a
/// field that is no number is not said twice), then the editor's own rule that an own machine
/// does not take a shipped machine's id. The machine when there is no problem.
#[must_use]
pub fn check(form: &Form) -> (Option<Machine>, Vec<FieldIssue>) {
    let (def, mut issues) = form.to_def();
    let validated = def.validate();
    if let Err(found) = &validated {
        for MachineIssue { path, problem } in found {
            if !issues.iter().any(|i| i.path == *path) {
                issues.push(FieldIssue { path: *path, message: problem.message() });
            }
        }
    }
    if saved_machines::is_shipped(&def.id) {
        issues.push(FieldIssue { path: Field::Id.path(), message: SHIPPED_ID });
    }
    match validated {
        Ok(m) if issues.is_empty() => (Some(m), issues),
        _ => (None, issues),
    }
}
