//! The instructor's own machines, made in the machine editor (`maschine.html`) and run in the
//! trainer: one short versioned text record per machine ([`to_record`], `m2;id=…;…`; version 1 records still read), the list of
//! them one record a line under [`MACHINES_KEY`], and the same record in the trainer's share
//! link. The trainer reads it without a JSON parser (its bundle has none); both pages read and
//! write it through this one module, and every machine read goes through
//! [`MachineDef::validate`], so a record can never bring in a machine the JSON could not.
//!
//! Numbers are written with Rust's shortest round-trip form (`{}` of `f64`), so a machine read
//! back is bit for bit the machine written ([`Machine`] equality).

use std::borrow::Cow;

use schwenkbar_core::machine::{
    BodyDef, BoxDef, CylinderDef, GeometryDef, JointDef, Limits, LinearLimitsDef, Machine, MachineDef,
};
use schwenkbar_core::number::parse_f64;

use crate::i18n::Text;
use crate::persist::{RestoreError, read_record, write_record};

/// The localStorage key of the editor's machines (one record a line).
pub const MACHINES_KEY: &str = "schwenkbar.machines";

/// How many own machines are kept: the trainer lists them on one softkey row beside ENDE.
pub const MAX_SAVED: usize = 7;

const KIND: char = 'm';
/// Version 2 added `table_top`; a version 1 record (its first 20 keys) still reads.
const VERSION: u32 = 2;
/// The collision bodies' records are still version 1.
const BODY_VERSION: u32 = 1;
const KEYS: [&str; 21] = [
    "id",
    "name.de",
    "name.en",
    "description.de",
    "description.en",
    "c0.axis",
    "c0.carrier",
    "c0.direction",
    "c0.pivot",
    "c0.limits",
    "c1.axis",
    "c1.carrier",
    "c1.direction",
    "c1.pivot",
    "c1.limits",
    "preset",
    "linear_limits",
    "rapid",
    "start",
    "collision",
    "table_top",
];
/// The collision bodies: one record of these keys each ([`body_record`]), a line each.
const BODY_KIND: char = 'b';
const BODY_KEYS: [&str; 5] = ["name.de", "name.en", "carrier", "shape", "numbers"];
/// `c*.limits` of an endless axis (else `min max`, or empty for none).
const ENDLESS: &str = "endless";

fn vec3(v: [f64; 3]) -> String {
    format!("{} {} {}", v[0], v[1], v[2])
}

fn numbers<const N: usize>(s: &str) -> Result<[f64; N], RestoreError> {
    let mut out = [0.0; N];
    let mut words = s.split(' ');
    for slot in &mut out {
        *slot = words.next().and_then(parse_f64).ok_or(RestoreError::Corrupt)?;
    }
    match words.next() {
        None => Ok(out),
        Some(_) => Err(RestoreError::Corrupt),
    }
}

fn limits_text(j: &JointDef) -> String {
    match (j.endless, j.limits) {
        (true, _) => ENDLESS.to_owned(),
        (false, Some(l)) => format!("{} {}", l.min, l.max),
        (false, None) => String::new(),
    }
}

/// A validated machine as one record line.
#[must_use]
pub fn to_record(machine: &Machine) -> String {
    let def = machine.to_def();
    let geo = &machine.geometry;
    let [x, y, z] = geo.linear_limits;
    let joint = |i: usize| def.chain.get(i).cloned();
    let (c0, c1) = (joint(0), joint(1));
    let field = |j: &Option<JointDef>, f: fn(&JointDef) -> String| j.as_ref().map(f).unwrap_or_default();
    let values: [String; 21] = [
        def.id.to_string(),
        def.name.de.to_string(),
        def.name.en.to_string(),
        def.description.de.to_string(),
        def.description.en.to_string(),
        field(&c0, |j| j.axis.to_string()),
        field(&c0, |j| j.carrier.to_string()),
        field(&c0, |j| vec3(j.direction)),
        field(&c0, |j| vec3(j.pivot)),
        field(&c0, limits_text),
        field(&c1, |j| j.axis.to_string()),
        field(&c1, |j| j.carrier.to_string()),
        field(&c1, |j| vec3(j.direction)),
        field(&c1, |j| vec3(j.pivot)),
        field(&c1, limits_text),
        vec3(geo.preset.to_array()),
        format!("{} {} {} {} {} {}", x.min, x.max, y.min, y.max, z.min, z.max),
        format!("{} {}", geo.rapid_linear, geo.rapid_rotary),
        vec3(geo.start.to_array()),
        def.collision.iter().map(body_record).collect::<Vec<_>>().join("\n"),
        geo.table_top.map(|t| vec3(t.to_array())).unwrap_or_default(),
    ];
    let fields: Vec<(&str, &str)> = KEYS.iter().copied().zip(values.iter().map(String::as_str)).collect();
    write_record(KIND, VERSION, &fields)
}

/// One collision body as a record: its names, carrier, `box` (centre, size) or `cylinder`
/// (base, direction, radius, height) and those numbers.
fn body_record(b: &BodyDef) -> String {
    let (shape, numbers) = match (b.cuboid, b.cylinder) {
        (Some(c), _) => ("box", format!("{} {}", vec3(c.center), vec3(c.size))),
        (None, Some(c)) => {
            ("cylinder", format!("{} {} {} {}", vec3(c.base), vec3(c.direction), c.radius, c.height))
        }
        // Not in a validated machine, which is all this module writes.
        (None, None) => ("", String::new()),
    };
    let fields = [
        ("name.de", b.name.de.as_ref()),
        ("name.en", b.name.en.as_ref()),
        ("carrier", b.carrier.as_ref()),
        ("shape", shape),
        ("numbers", numbers.as_str()),
    ];
    write_record(BODY_KIND, BODY_VERSION, &fields)
}

fn body(text: &str) -> Result<BodyDef, RestoreError> {
    let [de, en, carrier, shape, numbers_text] = read_record(text, BODY_KIND, BODY_VERSION, BODY_KEYS)?;
    let (cuboid, cylinder) = match shape.as_str() {
        "box" => {
            let [x, y, z, a, b, c] = numbers(&numbers_text)?;
            (Some(BoxDef { center: [x, y, z], size: [a, b, c] }), None)
        }
        "cylinder" => {
            let [x, y, z, u, v, w, radius, height] = numbers(&numbers_text)?;
            (None, Some(CylinderDef { base: [x, y, z], direction: [u, v, w], radius, height }))
        }
        _ => return Err(RestoreError::Corrupt),
    };
    Ok(BodyDef { name: Text::owned(de, en), carrier: Cow::Owned(carrier), cuboid, cylinder })
}

fn joint(
    axis: String,
    carrier: String,
    direction: &str,
    pivot: &str,
    limits: &str,
) -> Result<JointDef, RestoreError> {
    let (limits, endless) = match limits {
        ENDLESS => (None, true),
        "" => (None, false),
        l => {
            let [min, max] = numbers(l)?;
            (Some(Limits { min, max }), false)
        }
    };
    Ok(JointDef {
        axis: Cow::Owned(axis),
        carrier: Cow::Owned(carrier),
        direction: numbers(direction)?,
        pivot: numbers(pivot)?,
        limits,
        endless,
    })
}

/// Reads one record line and validates the machine; a record that reads but describes no valid
/// machine is `Corrupt` (nothing but this module writes it, and it writes valid machines only).
pub fn from_record(text: &str) -> Result<Machine, RestoreError> {
    let [
        id,
        name_de,
        name_en,
        desc_de,
        desc_en,
        a0,
        k0,
        d0,
        p0,
        l0,
        a1,
        k1,
        d1,
        p1,
        l1,
        preset,
        lin,
        rapid,
        start,
        collision,
        table_top,
    ] = match read_record(text, KIND, VERSION, KEYS) {
        Err(RestoreError::OldVersion) => {
            let v1: [String; 20] = read_record(text, KIND, 1, std::array::from_fn(|i| KEYS[i]))?;
            let mut all: [String; 21] = Default::default();
            for (slot, v) in all.iter_mut().zip(v1) {
                *slot = v;
            }
            all
        }
        read => read?,
    };
    let [xn, xx, yn, yx, zn, zx] = numbers(&lin)?;
    let [rapid_linear, rapid_rotary] = numbers(&rapid)?;
    let def = MachineDef {
        id: Cow::Owned(id),
        name: Text::owned(name_de, name_en),
        description: Text::owned(desc_de, desc_en),
        chain: Cow::Owned(vec![joint(a0, k0, &d0, &p0, &l0)?, joint(a1, k1, &d1, &p1, &l1)?]),
        geometry: Some(GeometryDef {
            preset: Some(numbers(&preset)?),
            linear_limits: Some(LinearLimitsDef {
                x: Some(Limits { min: xn, max: xx }),
                y: Some(Limits { min: yn, max: yx }),
                z: Some(Limits { min: zn, max: zx }),
            }),
            rapid_linear: Some(rapid_linear),
            rapid_rotary: Some(rapid_rotary),
            start: Some(numbers(&start)?),
            table_top: if table_top.is_empty() { None } else { Some(numbers(&table_top)?) },
        }),
        collision: Cow::Owned(collision.lines().map(body).collect::<Result<_, _>>()?),
    };
    def.validate().map_err(|_| RestoreError::Corrupt)
}

/// The list record: one machine a line (a record escapes its line breaks, so a line is a record).
#[must_use]
pub fn list_to_record(machines: &[Machine]) -> String {
    machines.iter().map(to_record).collect::<Vec<_>>().join("\n")
}

/// Why some saved machines were dropped.
pub const LIST_DAMAGED: Text = Text::new(
    "Gespeicherte eigene Maschinen waren teilweise beschädigt: die lesbaren behalten, der Rest verworfen",
    "Some saved own machines were corrupt: the readable ones kept, the rest dropped",
);

/// The saved machines (at most [`MAX_SAVED`], each id once, none with a shipped machine's id)
/// and, when a line could not be used, why. The caller writes the list back then, so the damage
/// is reported once.
#[must_use]
pub fn list_from_record(text: &str) -> (Vec<Machine>, Option<Text>) {
    let mut out: Vec<Machine> = Vec::new();
    let mut damaged = false;
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        match from_record(line) {
            Ok(m) if out.len() < MAX_SAVED && !out.iter().any(|o| o.id == m.id) && !is_shipped(&m.id) => {
                out.push(m);
            }
            _ => damaged = true,
        }
    }
    (out, damaged.then_some(LIST_DAMAGED))
}

/// `true` for the id of a shipped machine (an own machine never takes one: the trainer would
/// not know which is meant).
#[must_use]
pub fn is_shipped(id: &str) -> bool {
    Machine::builtin_ids().contains(&id)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shipped() -> Vec<Machine> {
        Machine::builtin_ids().iter().map(|id| Machine::builtin(id).expect("shipped")).collect()
    }

    #[test]
    fn every_shipped_machine_round_trips_exactly() {
        for m in shipped() {
            let record = to_record(&m);
            assert!(!record.contains('\n'), "{record}");
            // The collision bodies travel too (every shipped machine has some).
            assert!(!m.to_def().collision.is_empty() && record.contains("collision=b1"), "{record}");
            assert_eq!(from_record(&record), Ok(m.clone()), "{record}");
        }
    }

    #[test]
    fn awkward_names_and_numbers_round_trip() {
        let mut def = Machine::builtin("ba-table").expect("shipped").to_def();
        def.id = Cow::Borrowed("mine;=%\n");
        def.name = Text::owned("Mäschine; 45° = %".into(), "line\nbreak".into());
        let mut chain = def.chain.to_vec();
        chain[0].pivot = [0.1 + 0.2, -1e-300, 123_456_789.123_456_78];
        def.chain = Cow::Owned(chain);
        let m = def.validate().expect("valid");
        assert_eq!(from_record(&to_record(&m)), Ok(m));
    }

    #[test]
    fn corrupt_records_are_reported_and_never_panic() {
        let good = to_record(&shipped()[0]);
        let mut cases = vec![
            String::new(),
            "m1".into(),
            "m2;id=x".into(),
            good.replace("c0.direction=", "c0.direction=x"),
            good.replace("rapid=", "rapid=1 "),
            good.replacen("box", "sphere", 1),
            good.replacen("cylinder", "box", 1),
            good.replacen("id=", "ix=", 1),
            good[..good.len() / 2].to_owned(),
        ];
        // Reads, but no valid machine: a zero direction.
        cases.push(good.replace("c0.direction=0 0 1", "c0.direction=0 0 0"));
        for bad in &cases {
            assert!(from_record(bad).is_err(), "{bad}");
        }
        let (list, why) = list_from_record(&format!("{good}\nkaputt\n{good}"));
        assert_eq!(list.len(), 0, "a shipped id is never an own machine");
        assert_eq!(why, Some(LIST_DAMAGED));
    }

    #[test]
    fn the_list_keeps_own_machines_once_each() {
        let mut own = shipped();
        for (i, m) in own.iter_mut().enumerate() {
            m.id = format!("own-{i}");
        }
        let record = list_to_record(&own);
        assert_eq!(list_from_record(&record), (own.clone(), None));
        let twice = format!("{record}\n{}", to_record(&own[0]));
        assert_eq!(list_from_record(&twice), (own, Some(LIST_DAMAGED)));
        assert_eq!(list_from_record(""), (Vec::new(), None));
    }
}
