//! The machine editor page (`maschine.html`): a form over a [`MachineDef`], every field kept as
//! typed, checked at every change by [`MachineDef::validate`] with each problem shown at its
//! field (matched by the issue's path, [`Field::path`]), a 3D preview of the last valid machine,
//! saving in the browser ([`crate::saved_machines`]), export and import of the same JSON as
//! `static/machines/*.json`. Pure, like the trainer's reducer; `schwenkbar-web` renders the rows
//! ([`rows`]) and carries out the effects.

use std::borrow::Cow;
use std::rc::Rc;

use schwenkbar_core::machine::{
    BodyDef, BodyField, BoxDef, Carrier, CylinderDef, GeometryDef, GeometryField, JointDef, JointField,
    Limits, LinearLimitsDef, Machine, MachineDef, MachineGeometry, MachineIssue, MachinePath,
};
use schwenkbar_core::number::parse_input;

use crate::effect::{Effect, Reducer};
use crate::i18n::{Lang, Text};
use crate::persist::{self, Prefs};
use crate::saved_machines::{self, MACHINES_KEY, MAX_SAVED};
use crate::tool_table::{ToolAction, ToolTableState};

/// The shipped machine the editor opens when nothing else is asked for.
pub const DEFAULT_START: &str = "ac-table";

/// Files larger than this are not read: a machine description is about 1 KB.
pub const MAX_IMPORT_BYTES: usize = 256 * 1024;

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

/// One input of the form.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    Id,
    /// 0 German, 1 English.
    Name(usize),
    Description(usize),
    /// The joint's index in the chain.
    Axis(usize),
    Carrier(usize),
    /// Joint, component x/y/z.
    Direction(usize, usize),
    Pivot(usize, usize),
    Endless(usize),
    Min(usize),
    Max(usize),
    Preset(usize),
    /// Linear axis X/Y/Z, 0 min or 1 max.
    Linear(usize, usize),
    RapidLinear,
    RapidRotary,
    Start(usize),
    TableTop(usize),
    /// Collision body, then as for the machine (language, component).
    BodyName(usize, usize),
    BodyCarrier(usize),
    /// `box` or `cylinder`.
    BodyShape(usize),
    BodyCenter(usize, usize),
    BodySize(usize, usize),
    BodyBase(usize, usize),
    BodyDirection(usize, usize),
    BodyRadius(usize),
    BodyHeight(usize),
}

impl Field {
    /// The path of [`MachineIssue`]s about this field, as [`MachineDef::validate`] reports it.
    #[must_use]
    pub fn path(self) -> MachinePath {
        let lang = |l: usize| if l == 0 { Lang::De } else { Lang::En };
        let joint = |i: usize, f: JointField| MachinePath::Joint(i, f);
        let body = |i: usize, f: BodyField| MachinePath::BodyField(i, f);
        match self {
            Field::Id => MachinePath::Id,
            Field::Name(l) => MachinePath::Name(lang(l)),
            Field::Description(l) => MachinePath::Description(lang(l)),
            Field::Axis(i) => joint(i, JointField::Axis),
            Field::Carrier(i) => joint(i, JointField::Carrier),
            Field::Direction(i, _) => joint(i, JointField::Direction),
            Field::Pivot(i, _) => joint(i, JointField::Pivot),
            Field::Endless(i) => joint(i, JointField::Endless),
            Field::Min(i) | Field::Max(i) => joint(i, JointField::Limits),
            Field::Preset(_) => MachinePath::Geometry(GeometryField::Preset),
            Field::Linear(a, _) => MachinePath::Geometry(GeometryField::LinearLimits(a)),
            Field::RapidLinear => MachinePath::Geometry(GeometryField::RapidLinear),
            Field::RapidRotary => MachinePath::Geometry(GeometryField::RapidRotary),
            Field::Start(_) => MachinePath::Geometry(GeometryField::Start),
            Field::TableTop(_) => MachinePath::Geometry(GeometryField::TableTop),
            Field::BodyName(i, l) => body(i, BodyField::Name(lang(l))),
            Field::BodyCarrier(i) => body(i, BodyField::Carrier),
            Field::BodyShape(i) => MachinePath::Body(i),
            Field::BodyCenter(i, _) => body(i, BodyField::BoxCenter),
            Field::BodySize(i, _) => body(i, BodyField::BoxSize),
            Field::BodyBase(i, _) => body(i, BodyField::CylinderBase),
            Field::BodyDirection(i, _) => body(i, BodyField::CylinderDirection),
            Field::BodyRadius(i) => body(i, BodyField::CylinderRadius),
            Field::BodyHeight(i) => body(i, BodyField::CylinderHeight),
        }
    }
}

/// A row of the page: its label, its inputs and the issue path whose messages it shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// 0 the machine, 1 and 2 the rotary axes in chain order, 3 the geometry, 4 + i collision
    /// body i ([`section_title`]).
    pub section: usize,
    pub label: Text,
    pub fields: Vec<Field>,
}

impl Row {
    /// The path of the issues shown at this row.
    #[must_use]
    pub fn path(&self) -> MachinePath {
        self.fields.first().map_or(MachinePath::Whole, |f| f.path())
    }
}

/// The sections before the collision bodies: the machine, the two rotary axes, the geometry.
pub const SECTIONS: usize = 4;

/// The title of section `s` ([`Row::section`]) of `form`: a rotary axis is named by its place in
/// the chain and by what carries it as typed (a table-table machine's master is on the table,
/// a head-head machine's slave on the head).
#[must_use]
pub fn section_title(s: usize, form: &Form) -> Text {
    let joint = |i: usize, de: &str, en: &str| {
        let (on_de, on_en) = match form.joints[i].carrier.as_str() {
            "table" => (", am Tisch", ", on the table"),
            "head" => (", am Kopf", ", on the head"),
            _ => ("", ""),
        };
        Text::owned(format!("{de}{on_de})"), format!("{en}{on_en})"))
    };
    match s {
        0 => Text::new("Maschine", "Machine"),
        1 => joint(0, "1. Drehachse (Slave", "1st rotary axis (slave"),
        2 => joint(1, "2. Drehachse (Master", "2nd rotary axis (master"),
        3 => Text::new("Geometrie", "Geometry"),
        _ => Text::owned(format!("Kollisionskörper {}", s - 3), format!("Collision body {}", s - 3)),
    }
}

/// Every row of the page for `form`, in order (a body's rows are those of its shape).
#[must_use]
pub fn rows(form: &Form) -> Vec<Row> {
    let row = |section, label: Text, fields: Vec<Field>| Row { section, label, fields };
    let mut out = vec![
        row(0, Text::new("Kennung (Dateiname)", "Id (file name)"), vec![Field::Id]),
        row(0, Text::new("Name deutsch", "Name in German"), vec![Field::Name(0)]),
        row(0, Text::new("Name englisch", "Name in English"), vec![Field::Name(1)]),
        row(0, Text::new("Beschreibung deutsch", "Description in German"), vec![Field::Description(0)]),
        row(0, Text::new("Beschreibung englisch", "Description in English"), vec![Field::Description(1)]),
    ];
    for i in 0..2 {
        let s = i + 1;
        out.extend([
            row(s, Text::new("Achse (A, B, C)", "Axis (A, B, C)"), vec![Field::Axis(i)]),
            row(s, Text::new("Träger", "Carrier"), vec![Field::Carrier(i)]),
            row(
                s,
                Text::new("Richtung x y z", "Direction x y z"),
                (0..3).map(|c| Field::Direction(i, c)).collect(),
            ),
            row(
                s,
                Text::new("Drehpunkt x y z (mm)", "Pivot x y z (mm)"),
                (0..3).map(|c| Field::Pivot(i, c)).collect(),
            ),
            row(s, Text::new("Endlos (Modulo 360°)", "Endless (modulo 360°)"), vec![Field::Endless(i)]),
            row(
                s,
                Text::new("Software-Endschalter min max (°)", "Software limit switches min max (°)"),
                vec![Field::Min(i), Field::Max(i)],
            ),
        ]);
    }
    out.push(row(
        3,
        Text::new("Bezugspunkt (Preset) x y z (mm)", "Preset x y z (mm)"),
        (0..3).map(Field::Preset).collect(),
    ));
    out.push(row(
        3,
        Text::new(
            "Tischmitte x y z (mm; leer: Preset fest, sonst Rohteil auf dem Tisch)",
            "Table centre x y z (mm; empty: fixed preset, else the blank on the table)",
        ),
        (0..3).map(Field::TableTop).collect(),
    ));
    for (a, letter) in ['X', 'Y', 'Z'].iter().enumerate() {
        out.push(row(
            3,
            Text::owned(
                format!("Verfahrbereich {letter} min max (mm)"),
                format!("Travel {letter} min max (mm)"),
            ),
            vec![Field::Linear(a, 0), Field::Linear(a, 1)],
        ));
    }
    out.extend([
        row(
            3,
            Text::new("Eilgang linear (mm/min)", "Rapid traverse linear (mm/min)"),
            vec![Field::RapidLinear],
        ),
        row(
            3,
            Text::new("Eilgang Drehachsen (°/min)", "Rapid traverse rotary (°/min)"),
            vec![Field::RapidRotary],
        ),
        row(
            3,
            Text::new("Startposition X Y Z (mm)", "Start position X Y Z (mm)"),
            (0..3).map(Field::Start).collect(),
        ),
    ]);
    for (i, b) in form.collision.iter().enumerate() {
        let s = 4 + i;
        let xyz = |f: fn(usize, usize) -> Field| (0..3).map(|c| f(i, c)).collect();
        out.extend([
            row(s, Text::new("Name deutsch", "Name in German"), vec![Field::BodyName(i, 0)]),
            row(s, Text::new("Name englisch", "Name in English"), vec![Field::BodyName(i, 1)]),
            row(s, Text::new("Träger", "Carrier"), vec![Field::BodyCarrier(i)]),
            row(s, Text::new("Form", "Shape"), vec![Field::BodyShape(i)]),
        ]);
        if b.cylinder {
            out.extend([
                row(
                    s,
                    Text::new("Mitte der Grundfläche x y z (mm)", "Base centre x y z (mm)"),
                    xyz(Field::BodyBase),
                ),
                row(s, Text::new("Richtung x y z", "Direction x y z"), xyz(Field::BodyDirection)),
                row(s, Text::new("Radius (mm)", "Radius (mm)"), vec![Field::BodyRadius(i)]),
                row(s, Text::new("Höhe (mm)", "Height (mm)"), vec![Field::BodyHeight(i)]),
            ]);
        } else {
            out.extend([
                row(s, Text::new("Mitte x y z (mm)", "Centre x y z (mm)"), xyz(Field::BodyCenter)),
                row(s, Text::new("Kantenlängen x y z (mm)", "Edge lengths x y z (mm)"), xyz(Field::BodySize)),
            ]);
        }
    }
    out
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

    fn slot(&mut self, field: Field) -> Option<&mut String> {
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

/// A message at a field (or, with an empty path, about the whole description).
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

/// The editor page's state.
#[derive(Debug, Clone, PartialEq)]
pub struct EditorState {
    pub prefs: Prefs,
    pub form: Form,
    /// The form's problems, at their fields ([`check`]).
    pub issues: Vec<FieldIssue>,
    /// The last valid machine: the 3D view shows it while the form has problems (`None` only
    /// before any form was valid, e.g. a broken file imported first).
    pub preview: Option<Rc<Machine>>,
    /// The form is a valid machine (the preview is it).
    pub valid: bool,
    /// The own machines saved in the browser.
    pub saved: Vec<Machine>,
    /// Why the last import was refused (the form stays as it was).
    pub import_issues: Vec<Text>,
    /// The line under the title: what the last action did.
    pub message: Option<Text>,
    /// The shop's tool table, beside the machine.
    pub tools: ToolTableState,
}

/// What the page can be asked to do.
#[derive(Debug, Clone, PartialEq)]
pub enum EditorAction {
    /// A field's new text.
    Set(Field, String),
    SetEndless(usize, bool),
    /// Start from a shipped machine (as a copy with an own id) or a saved one, by id.
    Open(String),
    /// Keep the machine in the browser (the trainer lists it).
    Save,
    /// Drop the saved machine with the form's id.
    Delete,
    /// A new collision body (a cube on the bed, [`BodyForm::new_body`]).
    AddBody,
    /// Drop collision body i.
    RemoveBody(usize),
    /// Offer the machine as a JSON file.
    Export,
    /// A file's bytes to import.
    Import(Vec<u8>),
    ToggleLang,
    /// An effect's outcome (a refused save).
    Notice(Text),
    /// The tool table's action.
    Tools(ToolAction),
}

impl EditorState {
    /// The page with the tool table kept under [`crate::tool_table::TOOLS_KEY`].
    #[must_use]
    pub fn with_tools(mut self, saved: Option<&str>) -> EditorState {
        self.tools = ToolTableState::start(saved);
        self
    }

    /// The page at load: the saved machines and preferences as stored, and the URL fragment
    /// (`#id`, from the trainer's EDITIEREN) naming the machine to start from.
    #[must_use]
    pub fn start(
        machines: Option<&str>,
        prefs: Option<&str>,
        fragment: Option<&str>,
    ) -> (EditorState, Vec<Effect>) {
        let (prefs, prefs_notice) = Prefs::load(prefs);
        let (saved, damaged) = machines.map(saved_machines::list_from_record).unwrap_or_default();
        let mut fx = Vec::new();
        if damaged.is_some() {
            fx.push(Effect::Save { key: MACHINES_KEY, value: saved_machines::list_to_record(&saved) });
        }
        let mut state = EditorState {
            prefs,
            form: Form::default(),
            issues: Vec::new(),
            preview: None,
            valid: false,
            saved,
            import_issues: Vec::new(),
            message: None,
            tools: ToolTableState::start(None),
        };
        let wanted = fragment
            .map(|f| f.trim_start_matches('#'))
            .filter(|f| !f.is_empty())
            .and_then(persist::percent_decode);
        let asked = wanted.as_deref().unwrap_or(DEFAULT_START);
        if !state.open(asked) {
            state.open(DEFAULT_START);
            state.message = Some(Text::owned(
                format!("Maschine „{asked}“ unbekannt: {DEFAULT_START} geöffnet"),
                format!("Unknown machine \"{asked}\": {DEFAULT_START} opened"),
            ));
        }
        state.message = damaged.or(prefs_notice).or(state.message);
        (state, fx)
    }

    #[must_use]
    pub fn lang(&self) -> Lang {
        self.prefs.lang
    }

    /// The messages at a row's path.
    pub fn issues_at(&self, path: MachinePath) -> impl Iterator<Item = &FieldIssue> + '_ {
        self.issues.iter().filter(move |i| i.path == path)
    }

    /// Issues whose path no row shows (the page lists them at the top).
    #[must_use]
    pub fn unplaced(&self) -> Vec<&FieldIssue> {
        let paths: Vec<MachinePath> = rows(&self.form).iter().map(Row::path).collect();
        self.issues.iter().filter(|i| !paths.contains(&i.path)).collect()
    }

    /// Opens a machine by id: a saved one as it is, a shipped one as a copy with an own id.
    fn open(&mut self, id: &str) -> bool {
        let machine = self.saved.iter().find(|m| m.id == id).cloned().or_else(|| copy_of_shipped(id));
        let Some(machine) = machine else { return false };
        let Some(form) = Form::of(&machine.to_def()) else { return false };
        self.form = form;
        self.import_issues.clear();
        self.recheck();
        true
    }

    fn recheck(&mut self) {
        let (machine, issues) = check(&self.form);
        self.issues = issues;
        self.valid = machine.is_some();
        if let Some(m) = machine {
            self.preview = Some(Rc::new(m));
        }
    }

    fn import(&mut self, bytes: &[u8]) {
        self.import_issues.clear();
        if bytes.len() > MAX_IMPORT_BYTES {
            self.import_issues.push(Text::owned(
                format!("Datei zu groß ({} KB): eine Maschinendatei hat etwa 1 KB", bytes.len() / 1024),
                format!("File too large ({} KB): a machine file is about 1 KB", bytes.len() / 1024),
            ));
            return;
        }
        let Ok(json) = std::str::from_utf8(bytes) else {
            self.import_issues.push(Text::new("Datei ist kein UTF-8-Text", "The file is not UTF-8 text"));
            return;
        };
        let def = match MachineDef::from_json(json) {
            Ok(def) => def,
            Err(issue) => {
                self.import_issues.push(issue.message());
                return;
            }
        };
        let Some(form) = Form::of(&def) else {
            let n = def.chain.len();
            self.import_issues.push(Text::owned(
                format!("chain: {n} Drehachsen, der Editor bearbeitet Maschinen mit genau 2"),
                format!("chain: {n} rotary axes, the editor edits machines with exactly 2"),
            ));
            return;
        };
        self.form = form;
        self.recheck();
        self.message = Some(if self.valid {
            Text::new("Maschinendatei importiert", "Machine file imported")
        } else {
            Text::new(
                "Maschinendatei importiert: Fehler an den Feldern beheben",
                "Machine file imported: fix the problems at the fields",
            )
        });
    }

    fn not_valid(&self, what: (&str, &str)) -> Text {
        let n = self.issues.len();
        Text::owned(
            format!("{}: {n} Fehler in der Maschine beheben", what.0),
            format!("{}: fix {n} problem(s) of the machine", what.1),
        )
    }

    fn save(&mut self, fx: &mut Vec<Effect>) {
        let Some(machine) = self.preview.as_deref().filter(|_| self.valid).cloned() else {
            self.message = Some(self.not_valid(("Nicht gespeichert", "Not saved")));
            return;
        };
        match self.saved.iter().position(|m| m.id == machine.id) {
            Some(i) => self.saved[i] = machine,
            None if self.saved.len() >= MAX_SAVED => {
                self.message = Some(Text::owned(
                    format!("Nicht gespeichert: höchstens {MAX_SAVED} eigene Maschinen, erst eine löschen"),
                    format!("Not saved: at most {MAX_SAVED} own machines, delete one first"),
                ));
                return;
            }
            None => self.saved.push(machine),
        }
        fx.push(Effect::Save { key: MACHINES_KEY, value: saved_machines::list_to_record(&self.saved) });
        self.message = Some(Text::new(
            "Gespeichert: im Trainer unter MASCHINE WÄHLEN → EIGENE MASCHINEN",
            "Saved: in the trainer under SELECT MACHINE → OWN MACHINES",
        ));
    }
}

/// A shipped machine as the start of an own one: its id and names marked as a copy.
fn copy_of_shipped(id: &str) -> Option<Machine> {
    let mut m = Machine::builtin(id).ok()?;
    m.id = format!("{id}-eigen");
    m.name = Text::owned(format!("{} (eigene)", m.name.de), format!("{} (own)", m.name.en));
    Some(m)
}

impl Reducer for EditorState {
    type Action = EditorAction;

    fn apply(&self, action: EditorAction) -> (EditorState, Vec<Effect>) {
        let mut next = self.clone();
        let mut fx = Vec::new();
        match action {
            EditorAction::Set(Field::BodyShape(i), value) => {
                if let Some(b) = next.form.collision.get_mut(i) {
                    b.switch_to(value == "cylinder");
                }
                next.recheck();
            }
            EditorAction::Set(field, value) => {
                if let Some(slot) = next.form.slot(field) {
                    *slot = value;
                }
                next.recheck();
            }
            EditorAction::SetEndless(i, on) => {
                if let Some(j) = next.form.joints.get_mut(i) {
                    j.endless = on;
                }
                next.recheck();
            }
            EditorAction::Open(id) => {
                if next.open(&id) {
                    next.message = None;
                }
            }
            EditorAction::AddBody => {
                let n = next.form.collision.len() + 1;
                next.form.collision.push(BodyForm::new_body(n));
                next.recheck();
            }
            EditorAction::RemoveBody(i) => {
                if i < next.form.collision.len() {
                    next.form.collision.remove(i);
                    next.recheck();
                }
            }
            EditorAction::Save => next.save(&mut fx),
            EditorAction::Delete => {
                let id = next.form.id.trim().to_owned();
                let before = next.saved.len();
                next.saved.retain(|m| m.id != id);
                next.message = Some(if next.saved.len() < before {
                    fx.push(Effect::Save {
                        key: MACHINES_KEY,
                        value: saved_machines::list_to_record(&next.saved),
                    });
                    Text::owned(format!("„{id}“ gelöscht"), format!("\"{id}\" deleted"))
                } else {
                    Text::owned(format!("„{id}“ ist nicht gespeichert"), format!("\"{id}\" is not saved"))
                });
            }
            EditorAction::Export => {
                if let Some(m) = next.preview.as_ref().filter(|_| next.valid) {
                    fx.push(Effect::SaveFile { name: format!("{}.json", m.id), text: m.to_json() });
                } else {
                    next.message = Some(next.not_valid(("Nicht exportiert", "Not exported")));
                }
            }
            EditorAction::Import(bytes) => next.import(&bytes),
            EditorAction::ToggleLang => {
                next.prefs.lang = next.prefs.lang.other();
                fx.push(Effect::Save { key: persist::PREFS_KEY, value: next.prefs.to_record() });
            }
            EditorAction::Notice(text) => next.message = Some(text),
            EditorAction::Tools(a) => {
                let (tools, more) = next.tools.apply(a);
                next.tools = tools;
                fx.extend(more);
            }
        }
        (next, fx)
    }
}
