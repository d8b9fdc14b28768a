//! Program frame (empty, comment and structure blocks are read by the driver in `parse.rs`).
//!   begin := BEGIN PGM [name] MM|INCH         (a missing name or one with blanks: a warning)
//!   end   := END PGM [name] [MM|INCH]         (a missing name or unit: a warning)
//!   (`IN` for `INCH`: a lenient reading, said once per file by `lenient.rs`)

use super::Cx;
use super::words::{keyword, sp, token};
use crate::ast::{BlockBody, Unit};
use crate::diag::{DiagCode, Expected};

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
    // An exporting simulator writes `BEGIN PGM  MM` and `END PGM` without the name (the control
    // writes the file's name there): read as a program without a name, said once at BEGIN PGM.
    let (rest, name) = match token(rest) {
        Ok((r, unit)) if matches!(unit, "MM" | "INCH" | "IN") && sp(r).is_empty() => (rest, ""),
        Ok(ok) => blank_in_name(rest, ok),
        Err(_) if rest.is_empty() => (rest, ""),
        Err(e) => return cx.fail(e),
    };
    if name.is_empty() && begin {
        cx.warn(body, body.len() - rest.len(), DiagCode::PgmNameMissing);
    }
    if name.contains(' ') && begin {
        cx.warn(body, body.len() - rest.len(), DiagCode::PgmNameBlank);
    }
    let rest = sp(rest);
    let (rest, unit) = if let Some(r) = keyword(rest, "MM") {
        (r, Unit::Mm)
    } else if let Some(r) = keyword(rest, "INCH")
        .or_else(|| keyword(rest, "IN").filter(|_| crate::unconfirmed::IMPORT_LENIENT_SPELLINGS))
    {
        (r, Unit::Inch)
    } else if rest.is_empty() && !begin {
        // The unit of END PGM changes nothing: BEGIN PGM's applies.
        cx.warn(body, body.len(), DiagCode::EndPgmUnitMissing);
        (rest, Unit::Mm)
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

/// A name with blanks (`SP1 1002 MM`, as an exporting simulator writes it): the words up to the
/// unit at the end of the block, when the first word (`read`) is not followed by the unit.
fn blank_in_name<'a>(from: &'a str, read: (&'a str, &'a str)) -> (&'a str, &'a str) {
    let after = sp(read.0);
    if after.is_empty() || ["MM", "INCH", "IN"].iter().any(|u| keyword(after, u).is_some()) {
        return read;
    }
    let Some(unit) = from.trim_end().rfind([' ', '\t']).map(|k| k + 1) else { return read };
    if !matches!(&from.trim_end()[unit..], "MM" | "INCH" | "IN") {
        return read;
    }
    (&from[unit..], from[..unit].trim_end())
}
