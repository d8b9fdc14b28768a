//! `PATTERN DEF`: machining positions for `CYCL CALL PAT` (TNC 640 Klartext manual, "Pattern
//! definition PATTERN DEF": `POS1 (X+25 Y+33.5 Z+0)`, `ROW1 (X+25 Y+33.5 D+8 NUM5 ROT+0 Z+0)`,
//! `PAT1 (X+25 Y+33.5 DX+8 DY+10 NUMX5 NUMY4 ROT+0 ROTX+0 ROTY+0 Z+0)`, `FRAME1 (…)` with the
//! words of `PAT`, `CIRC1 (X+25 Y+33 D80 START+45 NUM8 Z+0)`,
//! `PITCHCIRC1 (X+25 Y+33 D80 START+45 STEP30 NUM8 Z+0)`). Written over `~` lines, which the
//! driver joins.
//!   def  := PATTERN DEF item { item }      item := KIND\<n> ( { KEY value } )

use super::Cx;
use super::words::{keyword, sp, uint, word_value};
use crate::ast::{BlockBody, PatternItem, PatternKey, PatternKind};
use crate::diag::{DiagCode, Expected};

/// `PATTERN DEF …` (`body` is the whole block text).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn pattern_def(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let Some(mut i) = keyword(body, "PATTERN").map(sp).and_then(|r| keyword(r, "DEF")).map(sp) else {
        return super::unknown(cx, body);
    };
    let mut items = Vec::new();
    if i.is_empty() {
        return cx.invalid(i, Some(Expected::Nc("POS|ROW|PAT|FRAME|CIRC|PITCHCIRC")));
    }
    while !i.is_empty() {
        let at = i;
        let Some((r, kind)) = PatternKind::ALL.into_iter().find_map(|k| {
            i.strip_prefix(k.as_str()).filter(|r| r.starts_with(|c: char| c.is_ascii_digit())).map(|r| (r, k))
        }) else {
            return cx.invalid(i, Some(Expected::Nc("POS|ROW|PAT|FRAME|CIRC|PITCHCIRC")));
        };
        let (r, index) = match uint(r) {
            Ok(ok) => ok,
            Err(e) => return cx.fail(e),
        };
        let Some(mut r) = sp(r).strip_prefix('(').map(sp) else {
            return cx.invalid(sp(r), Some(Expected::Nc("(")));
        };
        let mut words = Vec::with_capacity(kind.keys().len());
        loop {
            if let Some(after) = r.strip_prefix(')') {
                r = after;
                break;
            }
            if r.is_empty() {
                return cx.invalid(r, Some(Expected::Nc(")")));
            }
            let Some((after, key)) =
                PatternKey::BY_LENGTH.into_iter().find_map(|k| r.strip_prefix(k.as_str()).map(|a| (a, k)))
            else {
                return cx
                    .invalid(r, Some(Expected::Nc("X|Y|Z|D|DX|DY|NUM|NUMX|NUMY|ROT|ROTX|ROTY|START|STEP")));
            };
            let word = &r[..key.as_str().len()];
            if !kind.keys().contains(&key) {
                cx.error(r, word.len(), DiagCode::NotAllowed { word: word.to_owned() });
                return None;
            }
            if words.iter().any(|(k, _)| *k == key) {
                cx.error(r, word.len(), DiagCode::Duplicate { word: word.to_owned() });
                return None;
            }
            // The closing parenthesis may follow a value directly: `Z+0)`.
            let end = after.find([' ', '\t', ')']).unwrap_or(after.len());
            match word_value(&after[..end]) {
                Ok(("", v)) => words.push((key, v)),
                Ok((rest, _)) => return cx.invalid(rest, Some(Expected::Blank)),
                Err(e) => return cx.fail(e),
            }
            r = sp(&after[end..]);
        }
        for key in [PatternKey::X, PatternKey::Y] {
            if !words.iter().any(|(k, _)| *k == key) {
                cx.error(at, kind.as_str().len(), DiagCode::MissingWord { word: key.as_str() });
                return None;
            }
        }
        items.push(PatternItem { kind, index, words: words.into_boxed_slice() });
        i = sp(r);
    }
    Some(BlockBody::PatternDef(items.into_boxed_slice()))
}
