//! Schwenkbar's browser shell (filled in by the foundation issue).

/// Mounts the app on the document body.
pub fn start() {}
