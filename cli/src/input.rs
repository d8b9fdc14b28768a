//! Reading NC files (UTF-8 or the control's Latin-1, see `schwenkbar_core::text`).

use std::path::Path;

pub(crate) fn read(path: &Path) -> Result<String, String> {
    std::fs::read(path).map(schwenkbar_core::text::decode).map_err(|e| format!("{}: {e}", path.display()))
}
