//! Compiles the shipped data of `static/` into Rust constants, so that the wasm bundle carries
//! no JSON parser (serde_json and the derived deserialisers were about 8 KB gzip of it).
//! The JSON files stay the single source: this script reads them, checks them as strictly as
//! [`Machine::from_json`](../src/machine.rs) does (unknown or missing fields, wrong types fail
//! the build), and writes
//!   - `builtin_machines.rs`: `BUILTIN_IDS` and `BUILTIN`, the machine descriptions as written,
//!     validated at run time by the same code as a JSON file from the command line (so a wrong
//!     axis letter or carrier is left to that check, with its message);
//!   - `tools.rs`: `DEFAULT_TOOL` and `TOOLS`, the tool table.
//!
//! Native unit tests compare both with what serde_json makes of the same files.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde_json::{Map, Value};

/// The shipped machines in display order (file `static/machines/<id>.json`).
const MACHINES: [&str; 5] = ["ac-table", "ba-table", "bc-head-table", "ca-head", "b45-nutating"];

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let static_dir = manifest.join("../static");

    let mut code = String::from("/// The ids of the shipped machines, in display order.\n");
    let _ = writeln!(code, "const BUILTIN_IDS: [&str; {}] = {MACHINES:?};", MACHINES.len());
    code.push_str("/// The shipped machines, compiled from `static/machines/*.json` by `build.rs`.\n");
    // The numbers are the files' (e.g. 0.7071067811865476 for a 45° axis), not constants to name.
    code.push_str("#[allow(clippy::approx_constant)]\n");
    let _ = writeln!(code, "static BUILTIN: [MachineDef; {}] = [", MACHINES.len());
    for id in MACHINES {
        let path = static_dir.join(format!("machines/{id}.json"));
        let v = read_json(&path);
        let ctx = path.display().to_string();
        code.push_str(&machine(&ctx, id, &v));
    }
    code.push_str("];\n");
    std::fs::write(out.join("builtin_machines.rs"), code).expect("write builtin_machines.rs");

    let path = static_dir.join("tools.json");
    let v = read_json(&path);
    let ctx = path.display().to_string();
    let table = object(&ctx, &v, &["default", "tools"]);
    let mut code =
        String::from("/// The shipped tool table, compiled from `static/tools.json` by `build.rs`.\n");
    let _ = writeln!(code, "const DEFAULT_TOOL: RawTool = {};", tool(&ctx, required(&ctx, table, "default")));
    let tools = array(&ctx, required(&ctx, table, "tools"));
    let _ = writeln!(code, "const TOOLS: [RawTool; {}] = [", tools.len());
    for t in tools {
        let _ = writeln!(code, "    {},", tool(&ctx, t));
    }
    code.push_str("];\n");
    std::fs::write(out.join("tools.rs"), code).expect("write tools.rs");
}

fn read_json(path: &Path) -> Value {
    println!("cargo::rerun-if-changed={}", path.display());
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn machine(ctx: &str, id: &str, v: &Value) -> String {
    let m = object(ctx, v, &["id", "name", "description", "chain", "geometry", "collision"]);
    let json_id = string(ctx, required(ctx, m, "id"));
    assert_eq!(json_id, id, "{ctx}: id does not match the file name");
    let mut s = format!("    MachineDef {{\n        id: Cow::Borrowed({id:?}),\n");
    for key in ["name", "description"] {
        let t = object(ctx, required(ctx, m, key), &["de", "en"]);
        let (de, en) = (string(ctx, required(ctx, t, "de")), string(ctx, required(ctx, t, "en")));
        let _ = writeln!(s, "        {key}: Text::new({de:?}, {en:?}),");
    }
    s.push_str("        chain: Cow::Borrowed(&[\n");
    for j in array(ctx, required(ctx, m, "chain")) {
        let j = object(ctx, j, &["axis", "carrier", "direction", "pivot", "limits", "endless"]);
        let _ = writeln!(
            s,
            "            JointDef {{ axis: Cow::Borrowed({:?}), carrier: Cow::Borrowed({:?}), direction: {}, pivot: {}, limits: {}, endless: {} }},",
            string(ctx, required(ctx, j, "axis")),
            string(ctx, required(ctx, j, "carrier")),
            vec3(ctx, required(ctx, j, "direction")),
            j.get("pivot").map_or_else(|| "[0.0, 0.0, 0.0]".to_string(), |p| vec3(ctx, p)),
            option(j.get("limits"), |l| limits(ctx, l)),
            j.get("endless").is_some_and(|e| e.as_bool().unwrap_or_else(|| panic!("{ctx}: endless {e}"))),
        );
    }
    s.push_str("        ]),\n");
    let geometry = option(m.get("geometry"), |g| {
        let g = object(
            ctx,
            g,
            &["preset", "linear_limits", "rapid_linear", "rapid_rotary", "start", "table_top"],
        );
        let linear = option(g.get("linear_limits"), |l| {
            let l = object(ctx, l, &["X", "Y", "Z"]);
            format!(
                "LinearLimitsDef {{ x: {}, y: {}, z: {} }}",
                option(l.get("X"), |x| limits(ctx, x)),
                option(l.get("Y"), |x| limits(ctx, x)),
                option(l.get("Z"), |x| limits(ctx, x)),
            )
        });
        format!(
            "GeometryDef {{ preset: {}, linear_limits: {linear}, rapid_linear: {}, rapid_rotary: {}, start: {}, table_top: {} }}",
            option(g.get("preset"), |p| vec3(ctx, p)),
            option(g.get("rapid_linear"), |x| float(ctx, x)),
            option(g.get("rapid_rotary"), |x| float(ctx, x)),
            option(g.get("start"), |p| vec3(ctx, p)),
            option(g.get("table_top"), |p| vec3(ctx, p)),
        )
    });
    let _ = writeln!(s, "        geometry: {geometry},");
    s.push_str("        collision: Cow::Borrowed(&[\n");
    for b in m.get("collision").map(|c| array(ctx, c).as_slice()).unwrap_or_default() {
        s.push_str(&body(ctx, b));
    }
    s.push_str("        ]),\n    },\n");
    s
}

/// A collision body as `BodyDef { name, carrier, cuboid, cylinder }` (machine/body.rs).
fn body(ctx: &str, v: &Value) -> String {
    let b = object(ctx, v, &["name", "carrier", "box", "cylinder"]);
    let t = object(ctx, required(ctx, b, "name"), &["de", "en"]);
    let (de, en) = (string(ctx, required(ctx, t, "de")), string(ctx, required(ctx, t, "en")));
    let cuboid = option(b.get("box"), |c| {
        let c = object(ctx, c, &["center", "size"]);
        format!(
            "BoxDef {{ center: {}, size: {} }}",
            vec3(ctx, required(ctx, c, "center")),
            vec3(ctx, required(ctx, c, "size"))
        )
    });
    let cylinder = option(b.get("cylinder"), |c| {
        let c = object(ctx, c, &["base", "direction", "radius", "height"]);
        format!(
            "CylinderDef {{ base: {}, direction: {}, radius: {}, height: {} }}",
            vec3(ctx, required(ctx, c, "base")),
            vec3(ctx, required(ctx, c, "direction")),
            float(ctx, required(ctx, c, "radius")),
            float(ctx, required(ctx, c, "height"))
        )
    });
    format!(
        "            BodyDef {{ name: Text::new({de:?}, {en:?}), carrier: Cow::Borrowed({:?}), cuboid: {cuboid}, cylinder: {cylinder} }},\n",
        string(ctx, required(ctx, b, "carrier")),
    )
}

/// A tool row as `RawTool { number, name, length, radius, shape, corner_radius, point_angle }`;
/// `number` defaults to 0, `shape` to flat, and unknown
/// fields are ignored, as the serde schema of `ToolEntry` does.
fn tool(ctx: &str, v: &Value) -> String {
    let Value::Object(t) = v else { panic!("{ctx}: tool {v} is not an object") };
    let number = t.get("number").map_or(0, |n| {
        n.as_u64().and_then(|n| u32::try_from(n).ok()).unwrap_or_else(|| panic!("{ctx}: tool number {n}"))
    });
    // The shape fields are optional so that tables without them stay readable (sim/tools.rs).
    let shape = match t.get("shape").map(|s| string(ctx, s)) {
        None | Some("flat") => "Flat",
        Some("ball") => "Ball",
        Some("bull") => "Bull",
        Some("drill") => "Drill",
        Some(other) => panic!("{ctx}: tool shape {other:?}, expected flat, ball, bull or drill"),
    };
    format!(
        "RawTool {{ number: {number}, name: {:?}, length: {}, radius: {}, shape: ShapeKind::{shape}, \
         corner_radius: {}, point_angle: {} }}",
        string(ctx, required(ctx, t, "name")),
        float(ctx, required(ctx, t, "length")),
        float(ctx, required(ctx, t, "radius")),
        option(t.get("corner_radius"), |v| float(ctx, v)),
        option(t.get("point_angle"), |v| float(ctx, v)),
    )
}

/// `null` counts as absent, as serde's `Option` fields take it.
fn option(v: Option<&Value>, f: impl FnOnce(&Value) -> String) -> String {
    match v {
        None | Some(Value::Null) => "None".to_string(),
        Some(v) => format!("Some({})", f(v)),
    }
}

fn limits(ctx: &str, v: &Value) -> String {
    // serde's derived `Limits` ignores unknown fields (it has no deny_unknown_fields).
    let Value::Object(l) = v else { panic!("{ctx}: limits {v} is not an object") };
    format!(
        "Limits {{ min: {}, max: {} }}",
        float(ctx, required(ctx, l, "min")),
        float(ctx, required(ctx, l, "max"))
    )
}

fn vec3(ctx: &str, v: &Value) -> String {
    let a = array(ctx, v);
    assert_eq!(a.len(), 3, "{ctx}: {v} is not three numbers");
    format!("[{}, {}, {}]", float(ctx, &a[0]), float(ctx, &a[1]), float(ctx, &a[2]))
}

/// A Rust literal that reads back as the same f64 (`{:?}` prints the shortest round-trip form).
fn float(ctx: &str, v: &Value) -> String {
    let x = v.as_f64().unwrap_or_else(|| panic!("{ctx}: {v} is not a number"));
    format!("{x:?}")
}

fn string<'a>(ctx: &str, v: &'a Value) -> &'a str {
    v.as_str().unwrap_or_else(|| panic!("{ctx}: {v} is not a string"))
}

fn array<'a>(ctx: &str, v: &'a Value) -> &'a Vec<Value> {
    v.as_array().unwrap_or_else(|| panic!("{ctx}: {v} is not an array"))
}

/// An object with only the `allowed` keys (serde's `deny_unknown_fields`).
fn object<'a>(ctx: &str, v: &'a Value, allowed: &[&str]) -> &'a Map<String, Value> {
    let Value::Object(m) = v else { panic!("{ctx}: {v} is not an object") };
    if let Some(k) = m.keys().find(|k| !allowed.contains(&k.as_str())) {
        panic!("{ctx}: unknown field {k:?}, expected one of {allowed:?}");
    }
    m
}

fn required<'a>(ctx: &str, m: &'a Map<String, Value>, key: &str) -> &'a Value {
    m.get(key).unwrap_or_else(|| panic!("{ctx}: missing field {key:?}"))
}
