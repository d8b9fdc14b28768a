//! The `--machine` argument of `run` and `solve`: a shipped machine's id or the path of a machine
//! description (`.json`), the instructor's own machine.

use std::path::Path;

use schwenkbar_core::machine::{Machine, MachineError};

/// The machine `arg` names. A shipped id wins; anything else ending in `.json` or naming an
/// existing file is read as a description. The error is the text for stderr: for a file, every
/// problem on its own line as `FILE: field: message`, German first, then the English under it.
pub(crate) fn load(arg: &str) -> Result<Machine, String> {
    let unknown = match Machine::builtin(arg) {
        Ok(m) => return Ok(m),
        Err(e) => e,
    };
    if !arg.ends_with(".json") && !Path::new(arg).is_file() {
        return Err(format!("{unknown}; known: {} or a FILE.json", Machine::builtin_ids().join(", ")));
    }
    let text = std::fs::read_to_string(arg).map_err(|e| format!("{arg}: {e}"))?;
    Machine::from_json(&text).map_err(|e| match e {
        MachineError::Invalid { issues } => issues
            .iter()
            .map(|issue| {
                let m = issue.message();
                format!("{arg}: {}\n{arg}: {}", m.de, m.en)
            })
            .collect::<Vec<_>>()
            .join("\n"),
        MachineError::UnknownId { .. } => format!("{arg}: {e}"),
    })
}
