//! Program frame (empty, comment and structure blocks are read by the driver in `parse.rs`).
//!   begin := BEGIN PGM [name] MM|INCH         (a missing name or one with blanks: a warning)
//!   end   := END PGM [name] [MM|INCH]         (a missing name or unit: a warning)
//!   (`IN` for `INCH`: a lenient reading, said once per file by `lenient.rs`)

use nom::Parser;
use nom::branch::alt;
use nom::combinator::cut;

use super::Cx;
use super::words::{Step, choice, end_of_block, expected, invalid, keyword, kw, sp, token};
use crate::ast::{BlockBody, Unit};
use crate::diag::{DiagCode, Expected};

/// The unit word: `MM`, `INCH` (or `IN`, a lenient reading).
fn unit(i: &str) -> Step<'_, Unit> {
    let inch = |i| match keyword(i, "IN").filter(|_| crate::unconfirmed::IMPORT_LENIENT_SPELLINGS) {
        Some(r) => Ok((r, Unit::Inch)),
        None => expected(i, Expected::Nc("IN")),
    };
    alt((choice(&[("MM", Unit::Mm), ("INCH", Unit::Inch)], "MM|INCH"), inch)).parse(i)
}

/// `BEGIN PGM …` or `END PGM …`.
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn pgm<'a>(cx: &Cx, body: &'a str) -> Step<'a, BlockBody> {
    let (rest, begin) = choice(&[("BEGIN", true), ("END", false)], "BEGIN|END").parse(body)?;
    let (rest, _) = cut(kw("PGM")).parse(rest)?;
    let rest = sp(rest);
    // An exporting simulator writes `BEGIN PGM  MM` and `END PGM` without the name (the control
    // writes the file's name there): read as a program without a name, said once at BEGIN PGM.
    let (rest, name) = match token(rest) {
        Ok((r, unit)) if matches!(unit, "MM" | "INCH" | "IN") && sp(r).is_empty() => (rest, ""),
        Ok(ok) => blank_in_name(rest, ok),
        Err(_) if rest.is_empty() => (rest, ""),
        Err(e) => return Err(super::words::hard(e)),
    };
    if name.is_empty() && begin {
        cx.warn(body, body.len() - rest.len(), DiagCode::PgmNameMissing);
    }
    if name.contains(' ') && begin {
        cx.warn(body, body.len() - rest.len(), DiagCode::PgmNameBlank);
    }
    let rest = sp(rest);
    let (rest, unit) = match unit(rest) {
        Ok(ok) => ok,
        Err(nom::Err::Error(_)) if rest.is_empty() && !begin => {
            // The unit of END PGM changes nothing: BEGIN PGM's applies.
            cx.warn(body, body.len(), DiagCode::EndPgmUnitMissing);
            (rest, Unit::Mm)
        }
        Err(_) => {
            return invalid(rest, Some(Expected::Nc("MM|INCH")));
        }
    };
    let (rest, ()) = end_of_block(rest)?;
    let name = name.to_owned();
    Ok((rest, if begin { BlockBody::BeginPgm { name, unit } } else { BlockBody::EndPgm { name, unit } }))
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
