//! Reading NC files (UTF-8 or the control's Latin-1, see `schwenkbar_core::text`).

use std::path::Path;

pub(crate) fn read(path: &Path) -> Result<String, String> {
    std::fs::read(path).map(schwenkbar_core::text::decode).map_err(|e| format!("{}: {e}", path.display()))
}

/// [`read`], or the message on stderr and exit code 2 (the subcommands' common failure).
pub(crate) fn read_or_report(path: &Path) -> Result<String, std::process::ExitCode> {
    read(path).map_err(|e| {
        eprintln!("error: {e}");
        std::process::ExitCode::from(2)
    })
}
