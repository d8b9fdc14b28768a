//! The instructor's own machine (issue 17): the check of a machine description, one test per
//! rule, each made by editing one field of a shipped file; the seed's SEQ/SYM table on edited
//! copies; and the export → import round trip.

use crate::support;

use glam::DMat3;
use schwenkbar_core::machine::{Machine, MachineDef, MachineError, MachineIssue, Problem};
use schwenkbar_core::plane::RotaryAxis;
use schwenkbar_core::solve::{self, SolveOptions};
use schwenkbar_testkit::assert_close;
use schwenkbar_testkit::seq_sym::{self, Expect};
use serde_json::{Value, json};
use support::{axis_values, limits, plane_block, rotary};

/// A shipped machine file as JSON, to be edited.
fn shipped(id: &str) -> Value {
    let path = format!("{}/../static/machines/{id}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(&path).expect("machine file")).expect("JSON")
}

/// `ac-table.json` with one edit.
fn ac_with(edit: impl FnOnce(&mut Value)) -> Value {
    let mut v = shipped("ac-table");
    edit(&mut v);
    v
}

/// Every issue `from_json` reports for `v`.
fn issues(v: &Value) -> Vec<MachineIssue> {
    match Machine::from_json(&v.to_string()) {
        Err(MachineError::Invalid { issues }) => issues,
        other => panic!("expected an invalid machine, got {other:?}"),
    }
}

/// The one issue of `issues`, at `path`, its message with `de` and `en` in it: the problem.
fn only(issues: Vec<MachineIssue>, path: &str, de: &str, en: &str) -> Problem {
    let [issue] = <[MachineIssue; 1]>::try_from(issues).unwrap_or_else(|i| panic!("one issue, got {i:#?}"));
    assert_eq!(issue.path.to_string(), path);
    let m = issue.message();
    assert!(m.de.starts_with(&format!("{path}: ")) || path.is_empty(), "{}", m.de);
    assert!(m.de.contains(de), "German {:?} lacks {de:?}", m.de);
    assert!(m.en.contains(en), "English {:?} lacks {en:?}", m.en);
    issue.problem
}

/// [`only`] of the JSON `v`.
fn one(v: &Value, path: &str, de: &str, en: &str) -> Problem {
    only(issues(v), path, de, en)
}

/// The issues of `ac-table` read as a description and edited as an editor would (numbers JSON
/// cannot carry, NaN and ∞).
fn def_issues(edit: impl FnOnce(&mut MachineDef)) -> Vec<MachineIssue> {
    let mut def = MachineDef::from_json(&shipped("ac-table").to_string()).expect("readable");
    edit(&mut def);
    def.validate().expect_err("invalid machine")
}

#[test]
fn shipped_files_are_valid_and_equal_to_the_compiled_in_machines() {
    for id in Machine::builtin_ids() {
        assert_eq!(Machine::from_json(&shipped(id).to_string()), Machine::builtin(id), "{id}");
    }
    assert!(matches!(Machine::builtin("nope"), Err(MachineError::UnknownId { .. })));
}

#[test]
fn empty_id_and_names() {
    assert_eq!(
        one(&ac_with(|v| v["id"] = json!("")), "id", "darf nicht leer sein", "must not be empty"),
        Problem::Empty
    );
    one(&ac_with(|v| v["name"]["de"] = json!("  ")), "name.de", "leer", "empty");
    one(&ac_with(|v| v["name"]["en"] = json!("")), "name.en", "leer", "empty");
}

#[test]
fn exactly_two_rotary_axes() {
    let one_axis = ac_with(|v| v["chain"].as_array_mut().unwrap().truncate(1));
    assert_eq!(one(&one_axis, "chain", "1 Drehachsen", "1 rotary axes"), Problem::AxisCount { count: 1 });
    let three = ac_with(|v| {
        let b = json!({"axis": "B", "carrier": "head", "direction": [0, 1, 0]});
        v["chain"].as_array_mut().unwrap().push(b);
    });
    assert_eq!(one(&three, "chain", "genau 2", "exactly 2"), Problem::AxisCount { count: 3 });
}

#[test]
fn unknown_axis_letter() {
    let v = ac_with(|v| v["chain"][1]["axis"] = json!("X"));
    assert_eq!(
        one(&v, "chain[1].axis", "unbekannte Drehachse „X“", "unknown rotary axis \"X\""),
        Problem::UnknownAxis { letter: "X".into() }
    );
}

#[test]
fn duplicate_axis() {
    let v = ac_with(|v| v["chain"][1]["axis"] = json!("C"));
    assert_eq!(
        one(&v, "chain[1].axis", "Achse C steht zweimal", "axis C appears twice"),
        Problem::DuplicateAxis { axis: RotaryAxis::C }
    );
}

#[test]
fn carrier_is_table_or_head() {
    let v = ac_with(|v| v["chain"][0]["carrier"] = json!("bed"));
    assert_eq!(
        one(&v, "chain[0].carrier", "unbekannter Träger „bed“", "unknown carrier \"bed\""),
        Problem::UnknownCarrier { carrier: "bed".into() }
    );
}

/// The chain order rule: workpiece → tool, every table axis before every head axis.
#[test]
fn table_axes_come_before_head_axes() {
    let v = ac_with(|v| v["chain"][0]["carrier"] = json!("head"));
    assert_eq!(
        one(&v, "chain[1].carrier", "Tischachse A nach einer Kopfachse", "table axis A after a head axis"),
        Problem::TableAfterHead { axis: RotaryAxis::A }
    );
    // Table then head is the mixed machines' order (bc-head-table): accepted (without the
    // cradle's collision bodies, which cannot ride a head axis).
    let mixed = ac_with(|v| {
        v["chain"][1]["carrier"] = json!("head");
        v.as_object_mut().map(|o| o.remove("collision"));
    });
    assert!(Machine::from_json(&mixed.to_string()).is_ok());
}

#[test]
fn zero_direction() {
    let v = ac_with(|v| v["chain"][0]["direction"] = json!([0, 0, 0]));
    assert_eq!(one(&v, "chain[0].direction", "Nullvektor", "zero vector"), Problem::ZeroDirection);
}

#[test]
fn direction_not_unit() {
    let v = ac_with(|v| v["chain"][1]["direction"] = json!([2.5, 0, 0]));
    assert_eq!(
        one(&v, "chain[1].direction", "kein Einheitsvektor (Länge 2,5)", "not a unit vector (length 2.5)"),
        Problem::DirectionNotUnit { length: 2.5 }
    );
}

#[test]
fn parallel_axes() {
    let v = ac_with(|v| v["chain"][1]["direction"] = json!([0, 0, -1]));
    assert_eq!(
        one(&v, "chain[1].direction", "Achsen C und A sind parallel", "axes C and A are parallel"),
        Problem::ParallelAxes { slave: RotaryAxis::C, master: RotaryAxis::A }
    );
}

#[test]
fn master_along_the_tool_axis() {
    let v = ac_with(|v| {
        v["chain"][0]["direction"] = json!([1, 0, 0]);
        v["chain"][1]["direction"] = json!([0, 0, 1]);
    });
    assert_eq!(
        one(&v, "chain[1].direction", "Masterachse A", "master axis A is parallel to the tool axis"),
        Problem::MasterAlongTool { axis: RotaryAxis::A }
    );
}

#[test]
fn rotary_limits_min_below_max() {
    let v = ac_with(|v| v["chain"][1]["limits"] = json!({"min": 10, "max": -10.5}));
    assert_eq!(
        one(
            &v,
            "chain[1].limits",
            "min 10 muss kleiner als max -10,5 sein",
            "min 10 must be less than max -10.5"
        ),
        Problem::LimitsInverted { min: 10.0, max: -10.5 }
    );
}

#[test]
fn endless_axis_without_limits() {
    let mut v = shipped("ba-table");
    v["chain"][0]["limits"] = json!({"min": -10, "max": 10});
    assert_eq!(one(&v, "chain[0].endless", "endlose Achse", "endless axis"), Problem::EndlessWithLimits);
}

#[test]
fn linear_limits_min_below_max() {
    let v = ac_with(|v| v["geometry"]["linear_limits"]["Y"] = json!({"min": 600, "max": -600}));
    assert_eq!(
        one(&v, "geometry.linear_limits.Y", "muss kleiner als max", "must be less than max"),
        Problem::LimitsInverted { min: 600.0, max: -600.0 }
    );
}

#[test]
fn start_within_the_linear_limits() {
    let v = ac_with(|v| v["geometry"]["start"] = json!([0, 0, 12.5]));
    assert_eq!(
        one(
            &v,
            "geometry.start",
            "Startposition Z 12,5 außerhalb der Grenzen -500 … 0",
            "start position Z 12.5 outside"
        ),
        Problem::StartOutside { axis: 'Z', value: 12.5, min: -500.0, max: 0.0 }
    );
    // The default start (0, 0, 0) must lie within limits that are given.
    let v = ac_with(|v| {
        v["geometry"].as_object_mut().unwrap().remove("start");
        v["geometry"]["linear_limits"]["X"] = json!({"min": 100, "max": 700});
    });
    one(&v, "geometry.start", "Startposition X 0", "start position X 0");
}

#[test]
fn rapid_rates_positive() {
    let v = ac_with(|v| v["geometry"]["rapid_rotary"] = json!(0));
    assert_eq!(
        one(&v, "geometry.rapid_rotary", "größer als 0", "greater than 0"),
        Problem::NotPositive { value: 0.0 }
    );
}

/// One edit of a description.
type Edit = fn(&mut MachineDef);

#[test]
fn non_finite_numbers() {
    let cases: [(&str, Edit); 5] = [
        ("chain[0].direction", |d| d.chain.to_mut()[0].direction[2] = f64::NAN),
        ("chain[1].pivot", |d| d.chain.to_mut()[1].pivot[0] = f64::INFINITY),
        ("chain[1].limits", |d| {
            d.chain.to_mut()[1].limits =
                Some(schwenkbar_core::machine::Limits { min: f64::NEG_INFINITY, max: 0.0 });
        }),
        ("geometry.preset", |d| d.geometry.as_mut().unwrap().preset = Some([0.0, f64::NAN, 0.0])),
        ("geometry.rapid_linear", |d| d.geometry.as_mut().unwrap().rapid_linear = Some(f64::INFINITY)),
    ];
    for (path, edit) in cases {
        let p = only(def_issues(edit), path, "keine endliche Zahl", "not a finite number");
        assert!(matches!(p, Problem::NotFinite { value } if !value.is_finite()), "{path}: {p:?}");
    }
}

#[test]
fn unreadable_json_is_one_issue_with_line_and_column() {
    let p = only(
        issues_of_text("{\n  \"id\": "),
        "",
        "Maschinendatei nicht lesbar (Zeile 2",
        "Machine file unreadable (line 2",
    );
    assert!(matches!(p, Problem::Json { line: 2, .. }), "{p:?}");
    // A field the schema does not know, a missing one: the same.
    one(&ac_with(|v| v["chain"][0]["colour"] = json!("red")), "", "nicht lesbar", "unknown field `colour`");
    one(
        &ac_with(|v| v.as_object_mut().unwrap().remove("chain").map(drop).unwrap()),
        "",
        "nicht lesbar",
        "chain",
    );
}

fn issues_of_text(text: &str) -> Vec<MachineIssue> {
    match Machine::from_json(text) {
        Err(MachineError::Invalid { issues }) => issues,
        other => panic!("expected an invalid machine, got {other:?}"),
    }
}

/// Every problem is reported, not only the first, each at its field.
#[test]
fn all_problems_are_reported_at_once() {
    let v = ac_with(|v| {
        v["id"] = json!("");
        v["chain"][0]["direction"] = json!([0, 0, 0]);
        v["chain"][1]["axis"] = json!("D");
        v["geometry"]["start"] = json!([800, 0, 0]);
    });
    let paths: Vec<String> = issues(&v).into_iter().map(|i| i.path.to_string()).collect();
    assert_eq!(paths, ["id", "chain[0].direction", "chain[1].axis", "geometry.start"]);
}

/// `ac-table` or `ba-table` with what does not touch the solution edited: names, description,
/// a pivot, a linear limit.
fn edited(id: &str) -> Machine {
    let mut v = shipped(id);
    v["id"] = json!(format!("{id}-copy"));
    v["name"] = json!({"de": "Meine Maschine", "en": "My machine"});
    v["description"] = json!({"de": "Kopie", "en": "Copy"});
    v["chain"][1]["pivot"] = json!([10, -20, -250]);
    v["geometry"]["linear_limits"]["X"] = json!({"min": -900, "max": 900});
    Machine::from_json(&v.to_string()).unwrap_or_else(|e| panic!("{id}: {e}"))
}

#[test]
fn seed_seq_sym_rows_on_edited_copies() {
    let machines = [("ac-table", edited("ac-table")), ("ba-table", edited("ba-table"))];
    let rows = seq_sym::rows();
    assert_eq!(rows.len(), 15, "rows of seq_sym.tsv");
    for row in rows {
        let (_, machine) = machines.iter().find(|(id, _)| *id == row.machine).expect("row's machine");
        let start = axis_values(&row.start_axes());
        let limits = row.limit_range().map(limits).into_iter().collect();
        let opts = SolveOptions { start, limits, ..SolveOptions::default() };
        for text in row.blocks() {
            let e = solve::solve_block(machine, &plane_block(&text), DMat3::IDENTITY, &opts).unwrap();
            let id = format!("oracle {} on {}: {text}", row.oracle, machine.id);
            match &row.expect {
                Expect::Chosen(axes) => {
                    let chosen = e.chosen_axes().unwrap_or_else(|| panic!("{id}: no solution"));
                    for &(letter, value) in axes {
                        assert_close!(
                            chosen.get(rotary(letter)).unwrap_or(f64::NAN),
                            value,
                            1e-4,
                            "{id} {letter}"
                        );
                    }
                }
                Expect::Refused(msg) => {
                    assert!(e.chosen.is_none(), "{id}: chose {:?}", e.chosen_axes());
                    assert_eq!(e.error.expect("refusal").message().de, *msg, "{id}");
                }
            }
        }
    }
}

/// The editor's export and import: machine → JSON → machine gives the same machine, for every
/// shipped machine and an edited one; the description survives its own JSON too.
#[test]
fn round_trip_through_json() {
    let mut machines: Vec<Machine> =
        Machine::builtin_ids().iter().map(|id| Machine::builtin(id).unwrap()).collect();
    machines.push(edited("ba-table"));
    for m in machines {
        let json = m.to_json();
        assert_eq!(Machine::from_json(&json).as_ref(), Ok(&m), "{}:\n{json}", m.id);
        let def = m.to_def();
        assert_eq!(MachineDef::from_json(&def.to_json()), Ok(def), "{}", m.id);
    }
}

// ---- collision bodies (`collision[i]`); ac-table: 0 the bed (box), 3 the C rotary table
// (cylinder on C), 4 the A cradle (box on A) ----

#[test]
fn a_body_rides_the_bed_the_head_or_a_table_axis_of_the_chain() {
    let p = one(
        &ac_with(|v| v["collision"][4]["carrier"] = json!("B")),
        "collision[4].carrier",
        "unbekannter Träger „B“ des Kollisionskörpers (bed = Bett, head = Kopf oder eine Tischachse: C, A)",
        "unknown carrier \"B\" of the collision body (bed, head or a table axis: C, A)",
    );
    assert_eq!(p, Problem::UnknownBodyCarrier { carrier: "B".into(), table_axes: "C, A".into() });
    // A head axis carries no body of its own: head bodies ride the head as a whole.
    let mut v = shipped("bc-head-table");
    v["collision"][0]["carrier"] = json!("B");
    one(&v, "collision[0].carrier", "Tischachse: C)", "table axis: C)");
    // A machine with no table axis offers bed and head only.
    let mut v = shipped("ca-head");
    v["collision"][0]["carrier"] = json!("table");
    one(&v, "collision[0].carrier", "(bed = Bett, head = Kopf)", "(bed, head)");
}

#[test]
fn a_body_is_exactly_one_shape() {
    let none = ac_with(|v| v["collision"][0].as_object_mut().map(|o| o.remove("box")).map(drop).unwrap());
    assert_eq!(
        one(
            &none,
            "collision[0]",
            "0 Formen: ein Kollisionskörper ist genau eine Form",
            "0 shapes: a collision body is exactly one shape"
        ),
        Problem::BodyShapeCount { count: 0 }
    );
    let both = ac_with(|v| {
        v["collision"][0]["cylinder"] =
            json!({"base": [0, 0, 0], "direction": [0, 0, 1], "radius": 5, "height": 5});
    });
    assert_eq!(one(&both, "collision[0]", "2 Formen", "2 shapes"), Problem::BodyShapeCount { count: 2 });
}

/// One edit of a machine file.
type JsonEdit = fn(&mut Value);

#[test]
fn body_sizes_are_positive() {
    let cases: [(&str, JsonEdit, f64); 5] = [
        ("collision[0].box.size", |v| v["collision"][0]["box"]["size"][1] = json!(0), 0.0),
        ("collision[4].box.size", |v| v["collision"][4]["box"]["size"][2] = json!(-24), -24.0),
        ("collision[3].cylinder.radius", |v| v["collision"][3]["cylinder"]["radius"] = json!(0), 0.0),
        ("collision[3].cylinder.radius", |v| v["collision"][3]["cylinder"]["radius"] = json!(-50), -50.0),
        ("collision[3].cylinder.height", |v| v["collision"][3]["cylinder"]["height"] = json!(-30), -30.0),
    ];
    for (path, edit, value) in cases {
        let p = one(&ac_with(edit), path, "muss größer als 0 sein", "must be greater than 0");
        assert_eq!(p, Problem::NotPositive { value }, "{path}");
    }
}

#[test]
fn a_cylinder_direction_is_a_unit_vector() {
    let zero = ac_with(|v| v["collision"][3]["cylinder"]["direction"] = json!([0, 0, 0]));
    assert_eq!(
        one(
            &zero,
            "collision[3].cylinder.direction",
            "Richtung ist der Nullvektor",
            "direction is the zero vector"
        ),
        Problem::ZeroDirection
    );
    let long = ac_with(|v| v["collision"][3]["cylinder"]["direction"] = json!([0, 0, 2]));
    assert_eq!(
        one(
            &long,
            "collision[3].cylinder.direction",
            "kein Einheitsvektor (Länge 2)",
            "not a unit vector (length 2)"
        ),
        Problem::DirectionNotUnit { length: 2.0 }
    );
}

#[test]
fn body_numbers_are_finite_and_names_not_empty() {
    let cases: [(&str, Edit); 5] = [
        ("collision[0].box.center", |d| {
            d.collision.to_mut()[0].cuboid.as_mut().unwrap().center[0] = f64::NAN
        }),
        ("collision[0].box.size", |d| {
            d.collision.to_mut()[0].cuboid.as_mut().unwrap().size[2] = f64::INFINITY
        }),
        ("collision[3].cylinder.base", |d| {
            d.collision.to_mut()[3].cylinder.as_mut().unwrap().base[1] = f64::NAN
        }),
        ("collision[3].cylinder.direction", |d| {
            d.collision.to_mut()[3].cylinder.as_mut().unwrap().direction[2] = f64::NEG_INFINITY;
        }),
        ("collision[3].cylinder.radius", |d| {
            d.collision.to_mut()[3].cylinder.as_mut().unwrap().radius = f64::NAN
        }),
    ];
    for (path, edit) in cases {
        let p = only(def_issues(edit), path, "keine endliche Zahl", "not a finite number");
        assert!(matches!(p, Problem::NotFinite { value } if !value.is_finite()), "{path}: {p:?}");
    }
    one(
        &ac_with(|v| v["collision"][4]["name"]["en"] = json!(" ")),
        "collision[4].name.en",
        "darf nicht leer sein",
        "must not be empty",
    );
}
