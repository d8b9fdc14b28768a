//! The small tool table shipped in `static/tools.json` (compiled in): number, name, length and
//! radius; an unknown tool gets the table's default length and radius.

use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use crate::ast::ToolRef;

/// One row of the tool table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ToolEntry {
    #[serde(default)]
    pub number: u32,
    pub name: String,
    /// mm.
    pub length: f64,
    /// mm.
    pub radius: f64,
}

#[derive(Deserialize)]
struct Table {
    default: ToolEntry,
    tools: Vec<ToolEntry>,
}

const JSON: &str = include_str!("../../../static/tools.json");

/// Used only if the shipped JSON were broken (a unit test guards against that).
const FALLBACK: ToolEntry = ToolEntry { number: 0, name: String::new(), length: 100.0, radius: 5.0 };

fn table() -> &'static Option<Table> {
    static T: OnceLock<Option<Table>> = OnceLock::new();
    T.get_or_init(|| serde_json::from_str(JSON).ok())
}

/// The shipped tool table.
#[must_use]
pub fn tool_table() -> &'static [ToolEntry] {
    table().as_ref().map_or(&[], |t| t.tools.as_slice())
}

/// The entry for a tool reference, `(entry, known)`; unknown tools get the default length and
/// radius with the number or name as written.
#[must_use]
pub fn lookup(tool: &ToolRef) -> (ToolEntry, bool) {
    let found = tool_table().iter().find(|t| match tool {
        ToolRef::Number(n) => t.number == *n,
        ToolRef::Name(s) => t.name.eq_ignore_ascii_case(s),
    });
    if let Some(t) = found {
        return (t.clone(), true);
    }
    let mut d = table().as_ref().map_or(FALLBACK, |t| t.default.clone());
    match tool {
        ToolRef::Number(n) => d.number = *n,
        ToolRef::Name(s) => {
            d.number = 0;
            d.name = s.clone();
        }
    }
    (d, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_table_parses_and_has_the_musterprogramm_tools() {
        assert!(table().is_some());
        let (t16, known) = lookup(&ToolRef::Number(16));
        assert!(known);
        assert!(t16.radius > 0.0 && t16.length > 0.0);
        assert!(lookup(&ToolRef::Number(8)).1);
        let (u, known) = lookup(&ToolRef::Number(999));
        assert!(!known);
        assert_eq!(u.number, 999);
        assert!((u.length - 100.0).abs() < 1e-12);
    }
}
