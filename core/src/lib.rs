//! `schwenkbar-core`: everything the trainer knows about tilting the working plane on a
//! HEIDENHAIN TNC, with no browser dependency (architecture invariant, see ARCHITECTURE.md).
//!
//! Data flow: text → [`parse()`] (AST with spans + diagnostics) → interpret (machine states per
//! block) → kinematics (orientation ↔ axis angles).

pub mod angle;
pub mod ast;
pub mod axes;
pub mod course;
pub mod diag;
pub mod edit;
pub mod format;
pub mod kinematics;
pub mod lang;
pub mod machine;
pub mod number;
pub mod orientation;
pub mod parse;
pub mod plane;
pub mod sample;
pub mod sim;
pub mod solve;
pub mod span;
pub mod stock;
pub mod text;
pub mod unconfirmed;

pub use ast::{Block, BlockBody, Program};
pub use diag::{Diagnostic, Severity};
pub use format::format_program;
pub use lang::{Lang, Text};
pub use parse::{parse, parse_general};
