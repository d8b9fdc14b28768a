//! The page's inputs ([`Field`]), each with the path validate reports it under, and its rows
//! in sections ([`rows`]).

use schwenkbar_core::machine::{BodyField, GeometryField, JointField, MachinePath};

use super::Form;
use crate::i18n::{Lang, Text};

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
    /// The path of `MachineIssue`s about this field, as `MachineDef::validate` reports it.
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
