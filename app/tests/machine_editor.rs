//! The machine editor page's reducer (`editor.rs`), the own machines' record
//! (`saved_machines.rs`) and the trainer's side of them: listing, running, EDITIEREN, the share
//! link.

use std::borrow::Cow;

use glam::DMat3;
use schwenkbar_app::editor::{EditorAction, EditorState, Field, Form, rows};
use schwenkbar_app::effect::{Effect, Reducer};
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::persist::{self, Stored};
use schwenkbar_app::saved_machines::{self, LIST_DAMAGED, MACHINES_KEY};
use schwenkbar_app::softkeys::row;
use schwenkbar_app::state::{Action, AppState, SoftkeyLevel};
use schwenkbar_core::machine::{BodyField, JointField, Machine, MachinePath};
use schwenkbar_core::plane::{PlaneBlock, RotaryAxis, Value};
use schwenkbar_core::solve::{self, SolveOptions};
use schwenkbar_core::{BlockBody, parse};
use schwenkbar_testkit::assert_close;
use schwenkbar_testkit::seq_sym::{self, Expect};

fn editor() -> EditorState {
    EditorState::start(None, None, None).0
}

fn then(s: &EditorState, a: EditorAction) -> EditorState {
    s.apply(a).0
}

fn set(s: &EditorState, field: Field, value: &str) -> EditorState {
    then(s, EditorAction::Set(field, value.to_owned()))
}

/// The value a `Save`/`SaveFile` effect carries.
fn saved_value(fx: &[Effect]) -> String {
    fx.iter()
        .find_map(|e| match e {
            Effect::Save { key, value } if *key == MACHINES_KEY => Some(value.clone()),
            _ => None,
        })
        .expect("the machines are saved")
}

#[test]
fn opens_a_copy_of_a_shipped_machine_valid_and_with_an_own_id() {
    let s = editor();
    assert_eq!(s.lang(), Lang::De);
    assert!(s.valid, "{:?}", s.issues);
    assert_eq!(s.form.id, "ac-table-eigen");
    let preview = s.preview.as_ref().expect("preview");
    let shipped = Machine::builtin("ac-table").expect("shipped");
    assert_eq!(preview.joints(), shipped.joints());
    assert_eq!(preview.geometry, shipped.geometry);
    // From the trainer's EDITIEREN: the fragment names the machine.
    let s = EditorState::start(None, None, Some("#ba-table")).0;
    assert_eq!(s.form.id, "ba-table-eigen");
    let s = EditorState::start(None, Some("p1;lang=en;classroom=0"), Some("#nope")).0;
    assert_eq!((s.form.id.as_str(), s.lang()), ("ac-table-eigen", Lang::En));
    assert!(s.message.expect("told").en.contains("nope"));
}

#[test]
fn every_field_edits_its_part_of_the_description() {
    let s = editor();
    // A body of each shape (ac-table's bed is a box, its rotary table a cylinder).
    assert!(!s.form.collision[0].cylinder && s.form.collision[3].cylinder);
    for r in rows(&s.form) {
        for field in r.fields {
            if let Field::Endless(i) = field {
                let on = then(&s, EditorAction::SetEndless(i, true));
                assert!(on.form.to_def().0.chain[i].endless);
                assert_eq!(on.form.value(field), "1");
                continue;
            }
            let value = match field {
                Field::Axis(_) => "B",
                Field::Carrier(_) | Field::BodyCarrier(_) => "head",
                Field::BodyShape(i) => {
                    // The other shape: its rows change, the body stays one shape.
                    let other = if s.form.collision[i].cylinder { "box" } else { "cylinder" };
                    let next = set(&s, field, other);
                    assert_eq!(next.form.value(field), other);
                    let b = &next.form.to_def().0.collision[i];
                    assert_eq!(
                        (b.cuboid.is_some(), b.cylinder.is_some()),
                        (other == "box", other == "cylinder")
                    );
                    continue;
                }
                _ => "12,5",
            };
            let next = set(&s, field, value);
            assert_eq!(next.form.value(field), value, "{field:?}");
            let def = next.form.to_def().0;
            let read = match field {
                Field::Id => def.id.to_string(),
                Field::Name(0) => def.name.de.to_string(),
                Field::Name(_) => def.name.en.to_string(),
                Field::Description(0) => def.description.de.to_string(),
                Field::Description(_) => def.description.en.to_string(),
                Field::Axis(i) => def.chain[i].axis.to_string(),
                Field::Carrier(i) => def.chain[i].carrier.to_string(),
                Field::Direction(i, c) => def.chain[i].direction[c].to_string(),
                Field::Pivot(i, c) => def.chain[i].pivot[c].to_string(),
                Field::Min(i) => def.chain[i].limits.expect("limits").min.to_string(),
                Field::Max(i) => def.chain[i].limits.expect("limits").max.to_string(),
                Field::Endless(_) => unreachable!("handled above"),
                Field::Preset(c) => def.geometry.and_then(|g| g.preset).expect("preset")[c].to_string(),
                Field::Linear(a, m) => {
                    let l = def.geometry.and_then(|g| g.linear_limits).expect("limits");
                    let l = [l.x, l.y, l.z][a].expect("axis");
                    [l.min, l.max][m].to_string()
                }
                Field::RapidLinear => def.geometry.and_then(|g| g.rapid_linear).expect("rate").to_string(),
                Field::RapidRotary => def.geometry.and_then(|g| g.rapid_rotary).expect("rate").to_string(),
                Field::Start(c) => def.geometry.and_then(|g| g.start).expect("start")[c].to_string(),
                Field::TableTop(c) => {
                    def.geometry.and_then(|g| g.table_top).expect("table top")[c].to_string()
                }
                Field::BodyName(i, 0) => def.collision[i].name.de.to_string(),
                Field::BodyName(i, _) => def.collision[i].name.en.to_string(),
                Field::BodyCarrier(i) => def.collision[i].carrier.to_string(),
                Field::BodyShape(_) => unreachable!("handled above"),
                Field::BodyCenter(i, c) => def.collision[i].cuboid.expect("box").center[c].to_string(),
                Field::BodySize(i, c) => def.collision[i].cuboid.expect("box").size[c].to_string(),
                Field::BodyBase(i, c) => def.collision[i].cylinder.expect("cylinder").base[c].to_string(),
                Field::BodyDirection(i, c) => {
                    def.collision[i].cylinder.expect("cylinder").direction[c].to_string()
                }
                Field::BodyRadius(i) => def.collision[i].cylinder.expect("cylinder").radius.to_string(),
                Field::BodyHeight(i) => def.collision[i].cylinder.expect("cylinder").height.to_string(),
            };
            let typed_as_text =
                matches!(field, Field::Id | Field::Name(_) | Field::Description(_) | Field::BodyName(..));
            let expected = if value == "12,5" && !typed_as_text { "12.5" } else { value };
            assert_eq!(read, expected, "{field:?}");
        }
    }
}

/// Each problem a trainee can type, with the field it must be shown at and its German words.
#[test]
fn every_validation_message_reaches_its_field_in_german() {
    type Edit = fn(&EditorState) -> EditorState;
    let cases: Vec<(&str, Edit, &str, &str)> = vec![
        ("empty id", |s| set(s, Field::Id, " "), "id", "darf nicht leer sein"),
        ("shipped id", |s| set(s, Field::Id, "ac-table"), "id", "mitgelieferten Maschine"),
        ("empty name", |s| set(s, Field::Name(0), ""), "name.de", "darf nicht leer sein"),
        ("empty English name", |s| set(s, Field::Name(1), ""), "name.en", "darf nicht leer sein"),
        ("axis letter", |s| set(s, Field::Axis(0), "D"), "chain[0].axis", "unbekannte Drehachse „D“"),
        ("axis twice", |s| set(s, Field::Axis(1), "C"), "chain[1].axis", "Achse C steht zweimal"),
        ("carrier", |s| set(s, Field::Carrier(1), "bed"), "chain[1].carrier", "unbekannter Träger „bed“"),
        (
            "table after head",
            |s| set(s, Field::Carrier(0), "head"),
            "chain[1].carrier",
            "Tischachse A nach einer Kopfachse",
        ),
        (
            "zero direction",
            |s| set(&set(s, Field::Direction(0, 2), "0"), Field::Direction(0, 1), "0"),
            "chain[0].direction",
            "Richtung ist der Nullvektor",
        ),
        (
            "not unit",
            |s| set(s, Field::Direction(0, 2), "2"),
            "chain[0].direction",
            "kein Einheitsvektor (Länge 2)",
        ),
        (
            "parallel",
            |s| set(&set(s, Field::Direction(1, 0), "0"), Field::Direction(1, 2), "1"),
            "chain[1].direction",
            "Achsen C und A sind parallel",
        ),
        (
            "master along the tool",
            |s| {
                let s = set(&set(s, Field::Direction(0, 2), "0"), Field::Direction(0, 0), "1");
                set(&set(&s, Field::Direction(1, 0), "0"), Field::Direction(1, 2), "1")
            },
            "chain[1].direction",
            "Masterachse A liegt in Grundstellung parallel zur Werkzeugachse",
        ),
        (
            "rotary limits",
            |s| set(&set(s, Field::Min(1), "10"), Field::Max(1), "-10"),
            "chain[1].limits",
            "min 10 muss kleiner als max -10 sein",
        ),
        ("one limit missing", |s| set(s, Field::Min(1), "10"), "chain[1].limits", "keine Zahl"),
        (
            "endless with limits",
            |s| {
                let s = set(&set(s, Field::Min(0), "-10"), Field::Max(0), "10");
                then(&s, EditorAction::SetEndless(0, true))
            },
            "chain[0].endless",
            "endlose Achse mit Endschaltern",
        ),
        ("pivot no number", |s| set(s, Field::Pivot(1, 2), "abc"), "chain[1].pivot", "keine Zahl"),
        ("preset no number", |s| set(s, Field::Preset(0), "1..2"), "geometry.preset", "keine Zahl"),
        (
            "linear limits",
            |s| set(s, Field::Linear(1, 0), "700"),
            "geometry.linear_limits.Y",
            "min 700 muss kleiner als max 600 sein",
        ),
        ("rapid", |s| set(s, Field::RapidLinear, "0"), "geometry.rapid_linear", "muss größer als 0 sein (0)"),
        (
            "rapid rotary",
            |s| set(s, Field::RapidRotary, "-5"),
            "geometry.rapid_rotary",
            "muss größer als 0 sein (-5)",
        ),
        (
            "start outside",
            |s| set(s, Field::Start(2), "10"),
            "geometry.start",
            "Startposition Z 10 außerhalb der Grenzen -500 … 0",
        ),
        ("infinite", |s| set(s, Field::Start(0), "inf"), "geometry.start", "keine Zahl"),
        ("body name", |s| set(s, Field::BodyName(1, 0), " "), "collision[1].name.de", "darf nicht leer sein"),
        (
            "body carrier",
            |s| set(s, Field::BodyCarrier(3), "B"),
            "collision[3].carrier",
            "unbekannter Träger „B“ des Kollisionskörpers (bed = Bett, head = Kopf oder eine Tischachse: C, A)",
        ),
        (
            "box size",
            |s| set(s, Field::BodySize(0, 2), "0"),
            "collision[0].box.size",
            "muss größer als 0 sein (0)",
        ),
        ("box centre", |s| set(s, Field::BodyCenter(0, 1), "x"), "collision[0].box.center", "keine Zahl"),
        (
            "cylinder radius",
            |s| set(s, Field::BodyRadius(3), "-5"),
            "collision[3].cylinder.radius",
            "muss größer als 0 sein (-5)",
        ),
        (
            "cylinder height",
            |s| set(s, Field::BodyHeight(3), "0"),
            "collision[3].cylinder.height",
            "muss größer als 0 sein (0)",
        ),
        (
            "cylinder direction",
            |s| set(s, Field::BodyDirection(3, 2), "2"),
            "collision[3].cylinder.direction",
            "Einheitsvektor",
        ),
    ];
    let good = editor();
    // The paths as written (the schema's JSON paths): what the page's `data-path` says.
    let paths: Vec<String> = rows(&good.form).iter().map(|r| r.path().to_string()).collect();
    for (name, edit, path, german) in cases {
        let s = edit(&good);
        assert!(!s.valid, "{name}");
        assert!(paths.iter().any(|p| p == path), "{name}: no row shows {path}");
        assert!(s.unplaced().is_empty(), "{name}: {:?}", s.unplaced());
        let at: Vec<&str> =
            s.issues.iter().filter(|i| i.path.to_string() == path).map(|i| i.message.de.as_ref()).collect();
        assert!(at.iter().any(|m| m.contains(german)), "{name}: at {path}: {at:?}, all: {:?}", s.issues);
        // The preview stays on the last valid machine.
        assert!(s.preview.is_some(), "{name}");
    }
}

#[test]
fn fixing_the_field_clears_its_message_and_the_preview_follows() {
    let s = set(&set(&editor(), Field::Direction(0, 2), "0"), Field::Direction(0, 1), "0");
    assert_eq!(s.issues_at(MachinePath::Joint(0, JointField::Direction)).count(), 1);
    assert_eq!(s.preview, editor().preview, "the last valid machine is shown");
    assert_eq!(s.status().de, "1 Fehler: die Vorschau zeigt den letzten gültigen Stand");
    assert_eq!(s.status().en, "1 problem(s): the preview shows the last valid state");
    let fixed = set(&s, Field::Direction(0, 1), "1");
    assert!(fixed.valid && fixed.issues.is_empty(), "{:?}", fixed.issues);
    assert_eq!(fixed.status().de, "Maschine gültig");
    let joint = &fixed.preview.as_ref().expect("preview").joints()[0];
    assert_eq!(joint.direction, glam::DVec3::Y);
}

#[test]
fn save_and_load_round_trip_and_delete() {
    let s = set(&editor(), Field::Name(0), "Meine Fräse");
    let (saved, fx) = s.apply(EditorAction::Save);
    let record = saved_value(&fx);
    assert!(saved.message.as_ref().expect("said").de.starts_with("Gespeichert"));
    let (again, fx) = EditorState::start(Some(&record), None, Some("#ac-table-eigen"));
    assert!(fx.is_empty(), "nothing to repair: {fx:?}");
    assert_eq!(again.saved, saved.saved);
    assert_eq!(again.form, s.form);
    assert_eq!(again.preview, s.preview);
    // Saving again under the same id replaces it.
    let (twice, fx) = set(&again, Field::Pivot(1, 2), "-200").apply(EditorAction::Save);
    assert_eq!(twice.saved.len(), 1);
    assert_eq!(saved_machines::list_from_record(&saved_value(&fx)).0, twice.saved);
    let (gone, fx) = twice.apply(EditorAction::Delete);
    assert!(gone.saved.is_empty());
    assert_eq!(saved_value(&fx), "");
    // An invalid machine is not saved.
    let (bad, fx) = set(&editor(), Field::RapidLinear, "x").apply(EditorAction::Save);
    assert!(fx.is_empty());
    assert!(bad.message.expect("said").de.starts_with("Nicht gespeichert"));
}

#[test]
fn a_corrupt_saved_record_is_reported_and_replaced() {
    let good = saved_value(&editor().apply(EditorAction::Save).1);
    for corrupt in ["kaputt", "m1;id=x", &format!("{good}\n\u{0}{good}"), &"m1;".repeat(100_000)] {
        let (s, fx) = EditorState::start(Some(corrupt), None, None);
        assert_eq!(s.message, Some(LIST_DAMAGED), "{corrupt:.40}");
        let rewritten = saved_value(&fx);
        assert_eq!(saved_machines::list_from_record(&rewritten), (s.saved.clone(), None));
    }
}

#[test]
fn export_then_import_gives_an_equal_machine() {
    let s = set(&set(&editor(), Field::Pivot(0, 0), "12,25"), Field::Min(1), "-100");
    let s = set(&s, Field::Max(1), "100");
    let fx = s.apply(EditorAction::Export).1;
    let [Effect::SaveFile { name, text }] = fx.as_slice() else { panic!("{fx:?}") };
    assert_eq!(name, "ac-table-eigen.json");
    assert_eq!(Machine::from_json(text).as_ref(), Ok(s.preview.as_deref().expect("preview")));
    let imported = then(
        &EditorState::start(None, None, Some("#ba-table")).0,
        EditorAction::Import(text.clone().into_bytes()),
    );
    assert!(imported.valid && imported.import_issues.is_empty());
    assert_eq!(imported.preview, s.preview);
    assert_eq!(imported.form.joints[0].pivot[0], "12.25");
    // An invalid form is not exported.
    assert!(set(&s, Field::Id, "").apply(EditorAction::Export).1.is_empty());
}

#[test]
fn a_bad_file_is_listed_and_nothing_typed_is_lost() {
    let typed = set(&editor(), Field::Name(0), "halb getippt");
    let three_axes = {
        let mut def = Machine::builtin("ac-table").expect("shipped").to_def();
        let mut chain = def.chain.to_vec();
        chain.push(chain[0].clone());
        def.chain = Cow::Owned(chain);
        def.to_json()
    };
    for bytes in [
        b"{ kein json".to_vec(),
        vec![0xff, 0xfe, 0x00],
        three_axes.into_bytes(),
        vec![b' '; 300 * 1024],
        b"{\"id\": 5}".to_vec(),
    ] {
        let s = then(&typed, EditorAction::Import(bytes));
        assert_eq!(s.form, typed.form, "the form stays");
        assert_eq!(s.import_issues.len(), 1, "{:?}", s.import_issues);
        assert!(!s.import_issues[0].de.is_empty());
    }
    // A readable file with a problem opens with the problem at its field.
    let json = Machine::builtin("ac-table").expect("shipped").to_json().replacen("\"table\"", "\"tisch\"", 1);
    let s = then(&typed, EditorAction::Import(json.into_bytes()));
    assert!(s.import_issues.is_empty());
    assert_eq!(s.form.joints[0].carrier, "tisch");
    assert!(
        s.issues_at(MachinePath::Joint(0, JointField::Carrier)).any(|i| i.message.de.contains("„tisch“")),
        "{:?}",
        s.issues
    );
}

fn trainer_with(machines: &str) -> AppState {
    let stored = Stored { machines: Some(machines.to_owned()), ..Stored::default() };
    AppState::start(stored, None).0
}

#[test]
fn the_trainer_lists_runs_and_edits_the_saved_machines() {
    let record = saved_value(&set(&editor(), Field::Name(0), "Meine Fräse").apply(EditorAction::Save).1);
    let s = trainer_with(&record).apply(Action::ShowMachines).0;
    let keys: Vec<String> = row(&s).iter().flatten().map(|k| k.id.clone()).collect();
    assert!(
        keys.contains(&"own-machines".to_owned()) && keys.contains(&"edit-machine".to_owned()),
        "{keys:?}"
    );
    let s = s.apply(Action::ShowOwnMachines).0;
    assert_eq!(s.level, SoftkeyLevel::OwnMachines);
    let own = row(&s)[0].clone().expect("the saved machine");
    assert_eq!(own.label, "Meine Fräse");
    let s = s.apply(own.action).0;
    assert_eq!(s.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table-eigen"));
    assert!(s.sim.is_some(), "the program runs on it");
    // The choice survives a reload.
    let state = s.saved().to_record();
    let stored = Stored { machines: Some(record), state: Some(state), ..Stored::default() };
    let reloaded = AppState::start(stored, None).0;
    assert_eq!(reloaded.machine, s.machine);
    // EDITIEREN opens the editor on the current machine.
    let fx = reloaded.apply(Action::EditMachine).1;
    assert_eq!(fx, [Effect::OpenPage { url: "maschine.html#ac-table-eigen".into() }]);
    let fx = AppState::default().apply(Action::EditMachine).1;
    assert_eq!(fx, [Effect::OpenPage { url: "maschine.html#ac-table".into() }]);
    // Without own machines the row has no EIGENE MASCHINEN.
    let plain = AppState::default().apply(Action::ShowMachines).0;
    assert!(row(&plain)[5].is_none());
}

#[test]
fn the_trainer_reports_and_repairs_a_corrupt_list() {
    let (s, fx) = AppState::start(Stored { machines: Some("m1;kaputt".into()), ..Stored::default() }, None);
    assert_eq!(s.message, Some(LIST_DAMAGED));
    assert!(fx.contains(&Effect::Save { key: MACHINES_KEY, value: String::new() }));
}

#[test]
fn an_own_machine_travels_in_the_share_link() {
    let record = saved_value(&set(&editor(), Field::Pivot(1, 2), "-180,5").apply(EditorAction::Save).1);
    let s = trainer_with(&record).apply(Action::SelectMachine("ac-table-eigen".into())).0;
    let fragment = s.share_fragment();
    assert!(fragment.contains("&mdef="), "{fragment}");
    let shared = persist::parse_fragment(&fragment).expect("a link");
    assert_eq!(
        shared.own_machine.as_deref().map(saved_machines::from_record),
        Some(Ok((**s.machine.as_ref().expect("machine")).clone()))
    );
    // Opened by someone who does not have the machine.
    let (opened, _) = AppState::start(Stored::default(), Some(&format!("#{fragment}")));
    assert_eq!(opened.machine, s.machine);
    assert!(opened.sim.is_some());
    // A shipped machine travels by id only.
    assert!(!AppState::default().share_fragment().contains("mdef="));
    // A corrupt machine in a link is said, not a panic.
    let broken = fragment.replace("mdef=m2", "mdef=m2x");
    let (opened, _) = AppState::start(Stored::default(), Some(&broken));
    assert_eq!(opened.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table"));
}

/// Records of the builds before the table top (version 1, without `table_top`) still read, as
/// the same machine without a table top; the table top typed in the editor is kept.
#[test]
fn a_machine_record_of_version_1_still_reads_and_the_table_top_is_kept() {
    let record = saved_value(&editor().apply(EditorAction::Save).1);
    let record = record.lines().next().expect("one machine").to_owned();
    let v1 = record.replacen("m2;", "m1;", 1);
    let v1 = v1.strip_suffix(";table_top=").expect("no table top written");
    let old = saved_machines::from_record(v1).expect("version 1 reads");
    assert_eq!(old, saved_machines::from_record(&record).expect("version 2 reads"));
    assert_eq!(old.geometry.table_top, None);
    let s = [(0, "0"), (1, "0"), (2, "-450")]
        .into_iter()
        .fold(editor(), |s, (c, v)| set(&s, Field::TableTop(c), v));
    let record = saved_value(&s.apply(EditorAction::Save).1);
    let m = saved_machines::from_record(record.lines().next().expect("one")).expect("reads");
    assert_eq!(m.geometry.table_top, Some(glam::DVec3::new(0.0, 0.0, -450.0)));
}

fn plane_block(src: &str) -> PlaneBlock<f64> {
    let (program, _) = parse(src);
    match program.blocks.first().map(|b| b.body().into_owned()) {
        Some(BlockBody::Plane(p)) => p
            .try_map(|v| match v {
                Value::Number(x) => Ok(*x),
                Value::Param { index, .. } => Err(*index),
            })
            .unwrap_or_else(|q| panic!("{src}: Q{q}")),
        other => panic!("{src}: {other:?}"),
    }
}

fn rotary(letter: char) -> RotaryAxis {
    RotaryAxis::from_letter(&letter.to_string()).expect("rotary axis")
}

/// ac-table and ba-table edited in the editor (names, a pivot, a linear limit), saved, read back
/// through the record: the seed's SEQ/SYM table still comes out.
#[test]
fn seed_seq_sym_rows_on_edited_copies_read_through_the_record() {
    let edited = |id: &str| {
        let s = EditorState::start(None, None, Some(&format!("#{id}"))).0;
        let s = set(&set(&s, Field::Name(0), "Meine Maschine"), Field::Pivot(1, 0), "10");
        let s = set(&set(&s, Field::Linear(0, 0), "-900"), Field::Linear(0, 1), "900");
        let record = saved_value(&s.apply(EditorAction::Save).1);
        let (list, why) = saved_machines::list_from_record(&record);
        assert_eq!(why, None);
        (id.to_owned(), list.into_iter().next().expect("one machine"))
    };
    let machines = [edited("ac-table"), edited("ba-table")];
    let rows = seq_sym::rows();
    assert_eq!(rows.len(), 15);
    for r in rows {
        let (_, machine) = machines.iter().find(|(id, _)| *id == r.machine).expect("row's machine");
        let start = r
            .start_axes()
            .iter()
            .fold(Default::default(), |v: schwenkbar_core::axes::AxisValues, &(l, x)| v.with(rotary(l), x));
        let limits = r
            .limit_range()
            .map(|(l, min, max)| (rotary(l), schwenkbar_core::machine::Limits { min, max }))
            .into_iter()
            .collect();
        let opts = SolveOptions { start, limits, ..SolveOptions::default() };
        for text in r.blocks() {
            let e = solve::solve_block(machine, &plane_block(&text), DMat3::IDENTITY, &opts).expect("solved");
            let id = format!("oracle {} on {}: {text}", r.oracle, machine.id);
            match &r.expect {
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
                    assert!(e.chosen.is_none(), "{id}");
                    assert_eq!(e.error.expect("refusal").message().de, *msg, "{id}");
                }
            }
        }
    }
}

#[test]
fn the_form_of_every_shipped_machine_checks_to_that_machine() {
    for id in Machine::builtin_ids() {
        let m = Machine::builtin(id).expect("shipped");
        let form = Form::of(&m.to_def()).expect("two axes");
        let (def, bad) = form.to_def();
        assert!(bad.is_empty(), "{id}");
        assert_eq!(def.validate().as_ref(), Ok(&m), "{id}");
    }
}

#[test]
fn a_body_is_edited_added_and_removed_and_the_preview_carries_it() {
    use schwenkbar_core::machine::{BodyCarrier, BodyShape};
    let s = set(&set(&editor(), Field::BodySize(0, 0), "800"), Field::BodyCarrier(0), "C");
    assert!(s.valid, "{:?}", s.issues);
    let body = &s.preview.as_ref().expect("preview").bodies[0];
    assert_eq!(body.carrier, BodyCarrier::Table { joint: 0 }, "C is the slave, the first of the chain");
    let BodyShape::Box { half, .. } = body.shape else { panic!("{body:?}") };
    assert_eq!(half.x, 400.0);
    // The carriers offered: bed, head and the table axes of the chain as typed.
    let words: Vec<String> = s.form.body_carriers().into_iter().map(|(w, _)| w).collect();
    assert_eq!(words, ["bed", "head", "C", "A"]);
    let head_a = set(&s, Field::Carrier(1), "head");
    let words: Vec<String> = head_a.form.body_carriers().into_iter().map(|(w, _)| w).collect();
    assert_eq!(words, ["bed", "head", "C"]);

    let n = s.form.collision.len();
    let added = then(&s, EditorAction::AddBody);
    assert!(added.valid, "{:?}", added.issues);
    assert_eq!(added.form.collision.len(), n + 1);
    assert_eq!(added.form.collision[n].name[0], format!("Körper {}", n + 1));
    assert_eq!(added.preview.as_ref().expect("preview").bodies.len(), n + 1);
    assert!(rows(&added.form).iter().any(|r| r.section == 4 + n), "the new body has its rows");
    // A problem of a body moves with it when one before it goes.
    let bad = set(&added, Field::BodySize(n, 1), "-1");
    assert_eq!(bad.issues_at(MachinePath::BodyField(n, BodyField::BoxSize)).count(), 1);
    let removed = then(&bad, EditorAction::RemoveBody(0));
    assert_eq!(removed.form.collision.len(), n);
    assert_eq!(
        removed.issues_at(MachinePath::BodyField(n - 1, BodyField::BoxSize)).count(),
        1,
        "{:?}",
        removed.issues
    );
    assert!(removed.unplaced().is_empty(), "{:?}", removed.unplaced());
    assert_eq!(then(&removed, EditorAction::RemoveBody(99)).form, removed.form, "no such body: nothing");
}

#[test]
fn switching_a_bodys_shape_derives_the_other_shape() {
    // The bed, 760 × 760 × 60 at (0, 60, −310), as an upright cylinder: radius 380, from Z−340.
    let s = set(&editor(), Field::BodyShape(0), "cylinder");
    let b = &s.form.collision[0];
    assert!(b.cylinder && b.center[0].is_empty() && b.size[0].is_empty());
    assert_eq!(
        (b.base.clone(), b.direction.clone()),
        (["0", "60", "-340"].map(String::from), ["0", "0", "1"].map(String::from))
    );
    assert_eq!((b.radius.as_str(), b.height.as_str()), ("380", "60"));
    assert!(s.valid, "{:?}", s.issues);
    // And back: its bounding box, the box it came from.
    let back = set(&s, Field::BodyShape(0), "box");
    assert_eq!(back.form.collision[0], editor().form.collision[0]);
    // A shape that is not all numbers switches with empty fields, each reported.
    let broken = set(&set(&editor(), Field::BodySize(0, 0), "x"), Field::BodyShape(0), "cylinder");
    assert!(broken.form.collision[0].radius.is_empty());
    assert_eq!(broken.issues_at(MachinePath::BodyField(0, BodyField::CylinderRadius)).count(), 1);
}

#[test]
fn edited_bodies_round_trip_through_the_json_file_and_the_saved_record() {
    let mut s = set(&editor(), Field::BodyName(3, 0), "Rundtisch groß");
    s = set(&s, Field::BodyRadius(3), "62.5");
    s = set(&s, Field::BodyShape(1), "cylinder");
    s = then(&s, EditorAction::AddBody);
    let last = s.form.collision.len() - 1;
    s = set(&set(&s, Field::BodyCarrier(last), "head"), Field::BodyCenter(last, 2), "400");
    assert!(s.valid, "{:?}", s.issues);
    let machine = s.preview.as_deref().expect("preview").clone();
    // The JSON file.
    let fx = s.apply(EditorAction::Export).1;
    let [Effect::SaveFile { text, .. }] = fx.as_slice() else { panic!("{fx:?}") };
    assert_eq!(Machine::from_json(text).as_ref(), Ok(&machine));
    let imported = then(&editor(), EditorAction::Import(text.clone().into_bytes()));
    assert!(imported.valid && imported.import_issues.is_empty());
    assert_eq!(imported.form, s.form);
    // The saved record, as the editor and the trainer read it.
    let (saved, fx) = s.apply(EditorAction::Save);
    let record = saved_value(&fx);
    assert_eq!(saved_machines::list_from_record(&record).0, vec![machine.clone()]);
    let again = EditorState::start(Some(&record), None, Some("#ac-table-eigen")).0;
    assert_eq!(again.form, s.form);
    assert_eq!(again.saved, saved.saved);
    let trainer = trainer_with(&record);
    let own = trainer.own_machines.iter().find(|m| m.id == machine.id).expect("listed");
    assert_eq!(own.bodies, machine.bodies);
    assert_eq!(own.bodies[3].name.de, "Rundtisch groß");
}

#[test]
fn an_imported_body_of_both_or_no_shape_opens_as_a_box() {
    let json = editor().preview.expect("the own copy").to_json();
    let bed = r#""box": {"#;
    assert!(json.contains(bed), "{json}");
    // The bed (body 0) with a cylinder too: the form keeps its box.
    let both = json.replacen(
        bed,
        r#""cylinder": {"base": [0, 0, 0], "direction": [0, 0, 1], "radius": 1, "height": 1}, "box": {"#,
        1,
    );
    let s = then(&editor(), EditorAction::Import(both.into_bytes()));
    assert!(s.import_issues.is_empty(), "{:?}", s.import_issues);
    assert!(!s.form.collision[0].cylinder && s.valid, "{:?}", s.issues);
    assert_eq!(s.form.collision[0], editor().form.collision[0]);
    // Without a shape: an empty box, its fields reported.
    let mut def = editor().preview.expect("the own copy").to_def();
    let mut bodies = def.collision.to_vec();
    bodies[0].cuboid = None;
    def.collision = Cow::Owned(bodies);
    let s = then(&editor(), EditorAction::Import(def.to_json().into_bytes()));
    assert!(s.import_issues.is_empty(), "{:?}", s.import_issues);
    assert!(!s.valid && s.form.collision[0].size[0].is_empty());
    assert_eq!(s.issues_at(MachinePath::BodyField(0, BodyField::BoxSize)).count(), 1, "{:?}", s.issues);
}

#[test]
fn a_rotary_axis_section_names_what_carries_it() {
    use schwenkbar_app::editor::section_title;
    // The A/C table: both axes on the table (the A axis, the master, too: classroom trial II).
    let ac = EditorState::start(None, None, Some("ac-table")).0;
    assert_eq!(section_title(2, &ac.form).get(Lang::De), "2. Drehachse (Master, am Tisch)");
    assert_eq!(section_title(1, &ac.form).get(Lang::En), "1st rotary axis (slave, on the table)");
    // The fork head: both on the head.
    let ca = EditorState::start(None, None, Some("ca-head")).0;
    assert_eq!(section_title(1, &ca.form).get(Lang::De), "1. Drehachse (Slave, am Kopf)");
    // B head on a C table: the slave on the table, the master on the head.
    let bc = EditorState::start(None, None, Some("bc-head-table")).0;
    assert_eq!(section_title(1, &bc.form).get(Lang::De), "1. Drehachse (Slave, am Tisch)");
    assert_eq!(section_title(2, &bc.form).get(Lang::De), "2. Drehachse (Master, am Kopf)");
    assert_eq!(section_title(4, &bc.form).get(Lang::De), "Kollisionskörper 1");
}

/// The typed path of every row is where its field is in the machine's JSON (the schema's own
/// names, `chain[1].direction` → `/chain/1/direction`): the editor, validate and the file agree
/// on one path, on a form with a box and a cylinder body.
#[test]
fn every_rows_path_names_its_field_in_the_machine_file() {
    let s = set(&editor(), Field::BodyShape(1), "cylinder");
    let (def, bad) = s.form.to_def();
    assert!(bad.is_empty(), "{bad:?}");
    let json: serde_json::Value = serde_json::from_str(&def.to_json()).expect("JSON");
    let mut checked = 0;
    for row in rows(&s.form) {
        let path = row.path();
        assert_ne!(path, MachinePath::Whole, "{:?}", row.label);
        let written = path.to_string();
        let pointer = format!("/{}", written.replace(['.', '['], "/").replace(']', ""));
        // What the file leaves out when it has its default (an axis that is not endless, an
        // endless axis's limits, no table top): its parent is there.
        let optional = [".endless", ".limits", ".table_top"].iter().any(|o| written.ends_with(o));
        let parent = &pointer[..pointer.rfind('/').expect("a parent")];
        match json.pointer(&pointer) {
            Some(_) => checked += 1,
            None => assert!(
                optional && json.pointer(parent).is_some_and(serde_json::Value::is_object),
                "{written}: not in {json}"
            ),
        }
    }
    assert!(checked > 20, "{checked} rows' fields found in the file");
}
