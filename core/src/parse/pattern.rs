//! `PATTERN DEF`: machining positions for `CYCL CALL PAT` (TNC 640 Klartext manual, "Pattern
//! definition PATTERN DEF": `POS1 (X+25 Y+33.5 Z+0)`, `ROW1 (X+25 Y+33.5 D+8 NUM5 ROT+0 Z+0)`,
//! `PAT1 (X+25 Y+33.5 DX+8 DY+10 NUMX5 NUMY4 ROT+0 ROTX+0 ROTY+0 Z+0)`, `FRAME1 (…)` with the
//! words of `PAT`, `CIRC1 (X+25 Y+33 D80 START+45 NUM8 Z+0)`,
//! `PITCHCIRC1 (X+25 Y+33 D80 START+45 STEP30 NUM8 Z+0)`). Written over `~` lines, which the
//! driver joins.
//!   def  := PATTERN DEF item { item }      item := KIND\<n> ( { KEY value } )

use nom::Parser;
use nom::bytes::complete::tag;
use nom::combinator::cut;

use super::words::{Named, Step, Why, duplicate, fault, invalid, kw, lex, or_expected, sp, uint, word_value};
use crate::ast::{BlockBody, PatternItem, PatternKey, PatternKind};
use crate::diag::Expected;

const KINDS: Expected = Expected::Nc("POS|ROW|PAT|FRAME|CIRC|PITCHCIRC");

/// `PATTERN DEF …` (`body` is the whole block text): one or more items.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn pattern_def(body: &str) -> Step<'_, BlockBody> {
    let (mut i, _) = (kw("PATTERN"), kw("DEF")).parse(body)?;
    i = sp(i);
    if i.is_empty() {
        return invalid(i, Some(KINDS));
    }
    let mut items = Vec::new();
    while !i.is_empty() {
        let (r, item) = item(i)?;
        items.push(item);
        i = sp(r);
    }
    Ok((i, BlockBody::PatternDef(items.into_boxed_slice())))
}

/// The kind of an item, its number run on (`POS1`).
fn kind(i: &str) -> Step<'_, PatternKind> {
    match PatternKind::ALL.into_iter().find_map(|k| {
        i.strip_prefix(k.as_str()).filter(|r| r.starts_with(|c: char| c.is_ascii_digit())).map(|r| (r, k))
    }) {
        Some(found) => Ok(found),
        None => invalid(i, Some(KINDS)),
    }
}

/// `KIND<n> ( { KEY value } )`: the keys its kind takes, each at most once, `X` and `Y` always.
fn item(i: &str) -> Step<'_, PatternItem> {
    let at = i;
    let (r, (kind, index, _)) =
        (kind, cut(uint), cut(lex(or_expected(tag("("), Expected::Nc("("))))).parse(i)?;
    let mut r = sp(r);
    let mut words = Vec::with_capacity(kind.keys().len());
    loop {
        if let Some(after) = r.strip_prefix(')') {
            r = after;
            break;
        }
        if r.is_empty() {
            return invalid(r, Some(Expected::Nc(")")));
        }
        let Some((after, key)) =
            PatternKey::BY_LENGTH.into_iter().find_map(|k| r.strip_prefix(k.as_str()).map(|a| (a, k)))
        else {
            return invalid(r, Some(Expected::Nc("X|Y|Z|D|DX|DY|NUM|NUMX|NUMY|ROT|ROTX|ROTY|START|STEP")));
        };
        let word = &r[..key.as_str().len()];
        if !kind.keys().contains(&key) {
            return fault(r, word.len(), Why::NotAllowed);
        }
        if words.iter().any(|(k, _)| *k == key) {
            return duplicate(r, word.len(), Named::Written(word.len()));
        }
        // The closing parenthesis may follow a value directly: `Z+0)`.
        let end = after.find([' ', '\t', ')']).unwrap_or(after.len());
        match cut(word_value).parse(&after[..end])? {
            ("", v) => words.push((key, v)),
            (rest, _) => return invalid(rest, Some(Expected::Blank)),
        }
        r = sp(&after[end..]);
    }
    if let Some(key) =
        [PatternKey::X, PatternKey::Y].into_iter().find(|key| !words.iter().any(|(k, _)| k == key))
    {
        return fault(at, kind.as_str().len(), Why::Missing(key.as_str()));
    }
    Ok((r, PatternItem { kind, index, words: words.into_boxed_slice() }))
}
