//! A value or a PLANE block typed on its own: a dialog field, a typed answer, a command-line
//! argument.

use super::{parse, words};
use crate::ast::BlockBody;
use crate::diag::Diagnostic;
use crate::plane::Value;

/// A whole string as one value (`15`, `-7.5`, `.5`, `+Q27`), as typed into a dialog field;
/// `None` if it is anything else. Uses the parser's own number rules.
#[must_use]
pub fn parse_value(text: &str) -> Option<Value> {
    match words::value(text) {
        Ok(("", v)) => Some(v),
        _ => None,
    }
}

/// Why a text is not one PLANE block (see [`plane_block`]).
#[derive(Debug, Clone, PartialEq)]
pub enum PlaneTextError {
    /// The first error the parser found in the text.
    Invalid(Box<Diagnostic>),
    /// No PLANE block in the text.
    NoPlane,
    /// More than one PLANE block.
    SeveralPlanes,
}

impl PlaneTextError {
    /// The message in `lang`.
    #[must_use]
    pub fn message(&self, lang: crate::Lang) -> String {
        match self {
            PlaneTextError::Invalid(d) => d.message(lang),
            PlaneTextError::NoPlane => lang
                .t(
                    "Kein PLANE-Satz erkannt (er beginnt mit PLANE)",
                    "No PLANE block found (it starts with PLANE)",
                )
                .to_owned(),
            PlaneTextError::SeveralPlanes => lang
                .t(
                    "Mehr als ein PLANE-Satz: bitte genau einen",
                    "More than one PLANE block: please exactly one",
                )
                .to_owned(),
        }
    }
}

/// The one PLANE block of `text` (a typed answer, a command-line argument, one line of a
/// program): the first parse error, or no PLANE block, or more than one, is an error. Other
/// blocks around it are allowed.
///
/// # Errors
/// See [`PlaneTextError`].
pub fn plane_block(text: &str) -> Result<crate::plane::PlaneBlock, PlaneTextError> {
    let (program, diags) = parse(text);
    if let Some(d) = diags.into_iter().find(Diagnostic::is_error) {
        return Err(PlaneTextError::Invalid(Box::new(d)));
    }
    let mut planes = program.blocks.into_iter().filter_map(|b| match b.into_body() {
        BlockBody::Plane(p) => Some(p),
        _ => None,
    });
    match (planes.next(), planes.next()) {
        (Some(p), None) => Ok(*p),
        (None, _) => Err(PlaneTextError::NoPlane),
        (Some(_), Some(_)) => Err(PlaneTextError::SeveralPlanes),
    }
}
