//! `schwenkbar-core`: everything the trainer knows about tilting the working plane on a
//! HEIDENHAIN TNC, with no browser dependency (architecture invariant, see ARCHITECTURE.md).
//!
//! Data flow: text → [`parse`] (AST with spans + diagnostics) → interpret (machine states per
//! block) → kinematics (orientation ↔ axis angles).

pub mod angle;
pub mod axes;
pub mod kinematics;
pub mod machine;
pub mod orientation;
pub mod plane;
pub mod solve;
pub mod unconfirmed;
