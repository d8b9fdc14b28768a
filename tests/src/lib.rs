//! Shared helpers for the cross-crate tests: where the fixture programs live, and (in the
//! browser) mounting the app and pressing its keys.

#[cfg(target_arch = "wasm32")]
pub mod browser;

use std::path::PathBuf;

/// Folder of the fixture programs (`tests/fixtures`), for native tests.
#[must_use]
pub fn fixtures_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fixtures")
}
