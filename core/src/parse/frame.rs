//! Program frame (empty, comment and structure blocks are read by the driver in `parse.rs`).
//!   begin := BEGIN PGM name MM|INCH
//!   end   := END PGM name MM|INCH

use super::Cx;
use super::words::{keyword, sp, token};
use crate::ast::{BlockBody, Unit};
use crate::diag::Expected;

/// `BEGIN PGM …` or `END PGM …`.
pub(super) fn pgm(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let (rest, begin) = match (keyword(body, "BEGIN"), keyword(body, "END")) {
        (Some(r), _) => (r, true),
        (None, Some(r)) => (r, false),
        (None, None) => return super::unknown(cx, body),
    };
    let rest = sp(rest);
    let Some(rest) = keyword(rest, "PGM") else { return cx.invalid(rest, Some(Expected::Nc("PGM"))) };
    let rest = sp(rest);
    let (rest, name) = match token(rest) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let rest = sp(rest);
    let (rest, unit) = if let Some(r) = keyword(rest, "MM") {
        (r, Unit::Mm)
    } else if let Some(r) = keyword(rest, "INCH") {
        (r, Unit::Inch)
    } else {
        return cx.invalid(rest, Some(Expected::Nc("MM|INCH")));
    };
    let rest = sp(rest);
    if !rest.is_empty() {
        return cx.invalid(rest, None);
    }
    let name = name.to_owned();
    Some(if begin { BlockBody::BeginPgm { name, unit } } else { BlockBody::EndPgm { name, unit } })
}
