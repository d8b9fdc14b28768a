//! The Klartext parser: text → [`Program`] + [`Diagnostic`]s. Never panics, never gives up:
//! a block that cannot be read becomes [`BlockBody::Invalid`] with an error and the parser
//! carries on with the next line.
//!
//! Line-oriented on purpose (DOMAIN.md §8: one block per line, a cycle definition owns its `~`
//! continuation lines): the driver splits lines and block headers by hand and recovers at the
//! next line, so time is linear in the input. Each block family is a nom 8 parser over the
//! block's text (`plane.rs`, `motion.rs`, …): `alt` of its kinds and words, `cut` once a
//! keyword has begun a word, with the parser's own error (`words::NcError`: where, the words
//! expected there, or a diagnostic of its own such as a missing or doubled word). A family's
//! recoverable stop (`Err::Error`) means "not one of my blocks" and the block is kept as an
//! unknown one; a hard stop (`Err::Failure`) is the block's error. Findings that do not stop a
//! block (a value out of range, a warning) go to the shared `Cx` while the parser runs.
//!
//! nom 8.0 hands back an all-matching `space0`'s or `digit0`'s empty rest at the wrong address
//! (the start of the input), and diagnostics are placed by address: blanks are skipped with
//! `words::blanks`/`words::lex`, never with `space0` inside a combinator, and `words::run`
//! gives a word reader's rest as the suffix of its input. `Cx::fail` is the one conversion of a
//! stop into the block's [`Diagnostic`] (the word labelled, what was expected as help, or the
//! stop's own diagnostic). Spellings the control's editor never writes (a decimal comma, a
//! blank after an address letter: `lenient.rs`) are rewritten in place with the same length
//! before the block is read. The checks across blocks (BEGIN/END PGM names, block numbers, each lenient
//! spelling: a warning once per file) are [`AcrossBlocks`], made block by block here and again
//! by an edit's splice. The common straight line is read in one pass over its bytes by
//! `fast.rs` before the general parser is asked, into a compact [`Block`] (40 bytes, numbers
//! packed); anything it does not know goes the general way, which gives the same block
//! (`core/tests/fast_path.rs`).

mod across;
mod approach;
mod cx;
mod cycles;
mod fast;
mod frame;
mod function;
mod labels_q;
mod lenient;
mod lines;
mod motion;
mod pattern;
mod plane;
mod tool;
mod transforms;
mod typed;
mod words;

use std::borrow::Cow;

use crate::ast::{Block, BlockBody, Program, Span};
use crate::diag::{DiagCode, Diagnostic, Expected, Severity};

pub use across::AcrossBlocks;
pub(crate) use cx::Cx;
pub(crate) use labels_q::tabread_targets;
pub use lenient::Lenient;
use lines::{Lines, PhysLine, count_newlines};
pub use typed::{PlaneTextError, parse_value, plane_block};
pub(crate) use words::Step;

/// Splits `text` at the first `;` outside double quotes: (body, comment). The program pane's
/// colours split there too.
#[must_use]
pub fn split_comment(text: &str) -> (&str, Option<&str>) {
    let mut quoted = false;
    for (i, b) in text.bytes().enumerate() {
        match b {
            b'"' => quoted = !quoted,
            b';' if !quoted => return (&text[..i], Some(&text[i + 1..])),
            _ => {}
        }
    }
    (text, None)
}

fn starts_new_block(text: &str) -> bool {
    let t = text.trim_start().as_bytes();
    matches!(t.first(), Some(b'0'..=b'9' | b'/')) || n_number(t).is_some()
}

/// The length of an `N` block number's prefix (`N25 L …`: 1) when `text` starts with one.
fn n_number(text: &[u8]) -> Option<usize> {
    (text.first() == Some(&b'N') && text.get(1).is_some_and(u8::is_ascii_digit)).then_some(1)
}

/// Parses a Klartext program (or a single block without block number).
///
/// Returns the blocks that could be read and every finding; never panics.
#[must_use]
pub fn parse(src: &str) -> (Program, Vec<Diagnostic>) {
    parse_with(src, true)
}

/// [`parse`] without its fast path for straight lines: every block through the general
/// parser. The same program and diagnostics (the differential tests compare the two).
#[doc(hidden)]
#[must_use]
pub fn parse_general(src: &str) -> (Program, Vec<Diagnostic>) {
    parse_with(src, false)
}

fn parse_with(src: &str, fast_path: bool) -> (Program, Vec<Diagnostic>) {
    let src = src.strip_prefix('\u{feff}').unwrap_or(src);
    let mut p = Parser { src, blocks: Vec::new(), diags: Vec::new(), cx: Cx::new(), block_lines: Vec::new() };
    // One block per line in the common case: reserve once instead of doubling (memory budget).
    p.blocks.reserve_exact(count_newlines(src.as_bytes()) + 1);
    let mut lines = Lines { src, pos: 0, number: 0 }.peekable();
    let mut across = AcrossBlocks::default();
    while let Some(first) = lines.next() {
        let text = &src[first.start..first.end];
        // A transfer mark is said on its own line (so a text parsed again in part says what a
        // whole parse says: app/src/document/splice.rs); the last block's lines stay, a missing
        // END PGM is placed after them.
        if is_transfer_mark(text) {
            let block_lines = std::mem::replace(&mut p.block_lines, vec![first]);
            p.diag_at(Severity::Warning, DiagCode::TransferMark, first.start, first.end, None);
            p.block_lines = block_lines;
            continue;
        }
        // Tried first: its lines are never blank and never continued (it refuses `~`).
        let fast = if fast_path { fast::straight_line(text) } else { None };
        if fast.is_some() || !text.trim().is_empty() {
            // A blank line keeps the last block's lines: a missing END PGM is placed after them.
            p.block_lines.clear();
            p.block_lines.push(first);
        }
        let block = if let Some(f) = fast {
            let span = Span::new(first.start + f.lead, first.end);
            Block::compact(f.number, span, first.number, f.line)
        } else if text.trim().is_empty() {
            continue;
        } else {
            // A block ending in `~` owns the following lines that do not start a new block.
            let mut last = first;
            while src[last.start..last.end].trim_end().ends_with('~') {
                match lines.peek() {
                    Some(next)
                        if !src[next.start..next.end].trim().is_empty()
                            && !starts_new_block(&src[next.start..next.end]) =>
                    {
                        last = *next;
                        p.block_lines.push(last);
                        lines.next();
                    }
                    _ => break,
                }
            }
            p.block()
        };
        across
            .check(src, &block, |severity, code, span| p.diag_at(severity, code, span.start, span.end, None));
        p.blocks.push(block);
    }
    if across.end_missing() {
        let at = src.len();
        p.diag_at(Severity::Warning, DiagCode::MissingEndPgm, at, at, None);
    }
    (Program { blocks: p.blocks }, p.diags)
}

/// A line of only a data transfer's control characters and blanks ([`DiagCode::TransferMark`]).
fn is_transfer_mark(text: &str) -> bool {
    // The first character decides for almost every line (the parser's speed budget).
    let t = text.trim_start();
    t.starts_with(['\u{3}', '\u{1a}'])
        && t.chars().all(|c| matches!(c, '\u{3}' | '\u{1a}') || c.is_whitespace())
}

struct Parser<'s> {
    src: &'s str,
    blocks: Vec<Block>,
    diags: Vec<Diagnostic>,
    cx: Cx,
    block_lines: Vec<PhysLine>,
}

impl Parser<'_> {
    /// Line and 1-based character column of a byte offset.
    fn locate(&self, at: usize) -> (u32, u32) {
        let at = at.min(self.src.len());
        let line = self
            .block_lines
            .iter()
            .rev()
            .find(|l| l.start <= at)
            .copied()
            .or_else(|| {
                // Offsets after the last block (END PGM missing): count from the last line break.
                let start = self.src[..at].rfind('\n').map_or(0, |i| i + 1);
                let number = self.src[..at].bytes().filter(|&b| b == b'\n').count() as u32 + 1;
                Some(PhysLine { start, end: at, number })
            })
            .unwrap_or(PhysLine { start: 0, end: 0, number: 1 });
        let prefix = self.src.get(line.start..at).unwrap_or("");
        (line.number, prefix.chars().count() as u32 + 1)
    }

    fn diag_at(
        &mut self,
        sev: Severity,
        code: DiagCode,
        start: usize,
        end: usize,
        expected: Option<Expected>,
    ) {
        let (line, column) = self.locate(start);
        self.diags
            .push(Diagnostic::new(sev, code, Span::new(start, end), line, column).with_expected(expected));
    }

    /// Reads the block made of `self.block_lines`.
    fn block(&mut self) -> Block {
        let src = self.src;
        let first = self.block_lines[0];
        let last = self.block_lines[self.block_lines.len() - 1];
        let line_text = &src[first.start..first.end];
        let lead = line_text.len() - line_text.trim_start().len();
        let span = Span::new(first.start + lead, last.end);
        let (line, column) = (first.number, line_text[..lead].chars().count() as u32 + 1);

        // Header: [/] [number] [/]
        let mut rest = &line_text[lead..];
        let mut skip = false;
        if let Some(r) = rest.strip_prefix('/') {
            skip = true;
            rest = r.trim_start();
        }
        let mut number = None;
        // `N25 L …`: the number read, the prefix said once per file (AcrossBlocks).
        if let Some(n) = n_number(rest.as_bytes()) {
            rest = &rest[n..];
        }
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        if digits > 0 {
            let at = first.start + (line_text.len() - rest.len());
            match rest[..digits].parse::<u32>() {
                Ok(n) => number = Some(n),
                Err(_) => self.diag_at(
                    Severity::Error,
                    DiagCode::InvalidInput,
                    at,
                    at + digits,
                    Some(Expected::BlockNumber),
                ),
            }
            rest = &rest[digits..];
            // `12;comment`: a CAM system's comment block without the blank (AcrossBlocks says it
            // once per file); `12X` is neither a block number nor a word.
            if !rest.is_empty() && !rest.starts_with([' ', '\t', ';']) {
                let at = first.start + (line_text.len() - rest.len());
                self.diag_at(Severity::Error, DiagCode::InvalidInput, at, at + 1, Some(Expected::Blank));
            }
            rest = rest.trim_start();
            if let Some(r) = rest.strip_prefix('/') {
                skip = true;
                rest = r.trim_start();
            }
        }

        let (body_text, comment) = split_comment(rest);
        let mut body_text = body_text.trim();
        let mut comment = comment.map(|c| c.trim().to_owned());
        let continued = self.block_lines.len() > 1;
        let dangling_tilde = line_text.trim_end().ends_with('~');
        // The continuation mark after the body or after the comment (`Q200=2 ;LABEL ~`); a line
        // with both marks (`Q203=+0 ~ ;KOOR. ~`) keeps neither in its comment, or fmt's one
        // mark at the end would read back as the comment's.
        if body_text.ends_with('~') {
            body_text = strip_tilde(body_text);
        }
        if let Some(c) = comment.as_mut()
            && c.ends_with('~')
        {
            *c = strip_tilde(c).to_owned();
        }
        // `L IX-80 (MODAL DRILL POINT)`: the parentheses are the block's comment (AcrossBlocks
        // says it once per file); a block that stays invalid or unknown keeps them as written.
        let mut paren = None;
        if comment.is_none()
            && !continued
            && crate::unconfirmed::IMPORT_LENIENT_SPELLINGS
            && let Some(p) = lenient::paren_comment(body_text.as_bytes())
        {
            let inner = body_text[p + 1..].trim_end();
            comment = Some(inner[..inner.len() - 1].trim().to_owned());
            paren = Some(body_text);
            body_text = body_text[..p].trim_end();
        }
        let body_start = first.start + (body_text.as_ptr() as usize - line_text.as_ptr() as usize);

        let probe = body_text.strip_prefix("TCH PROBE").is_some_and(|r| !is_old_cycle(r));
        let is_cycle = probe || body_text.strip_prefix("CYCL DEF").is_some_and(|r| !is_old_cycle(r));
        // Non-cycle blocks continued with `~` are read as one line: join their words and keep a
        // map from the joined text back to the source for diagnostics.
        let mut segments: Vec<(usize, usize)> = Vec::new();
        let text: Cow<'_, str> = if continued && !is_cycle {
            let mut joined = String::from(body_text);
            segments.push((0, body_start));
            // Once a line's comment ran on with `~`, the lines after it are its text (a long
            // comment block as the control wraps it: `3 ;This program is free~`).
            let mut in_comment = comment.is_some();
            for l in &self.block_lines[1..] {
                let line = &src[l.start..l.end];
                let (b, c) = if in_comment { ("", Some(line)) } else { split_comment(line) };
                in_comment |= c.is_some();
                let b = strip_tilde(b.trim());
                if let Some(c) = c {
                    let c = strip_tilde(c.trim());
                    if !c.is_empty() {
                        let all = comment.get_or_insert_with(String::new);
                        if !all.is_empty() {
                            all.push(' ');
                        }
                        all.push_str(c);
                    }
                }
                if !b.is_empty() {
                    if !joined.is_empty() {
                        joined.push(' ');
                    }
                    let src_start = b.as_ptr() as usize - src.as_ptr() as usize;
                    segments.push((joined.len(), src_start));
                    joined.push_str(b);
                }
            }
            Cow::Owned(joined)
        } else {
            Cow::Borrowed(body_text)
        };

        // A decimal comma or a blank after an address letter: read as written canonically
        // (the same length, so offsets stay); AcrossBlocks says it once per file. A block that
        // stays invalid keeps the text as written (`written`): nothing the user typed is changed.
        // A `*` line is text (a structure block): nothing in it is read as a word.
        let (text, written) = match (is_cycle || text.starts_with('*'), lenient::normalize(&text)) {
            (false, Some(canonical)) if crate::unconfirmed::IMPORT_LENIENT_SPELLINGS => {
                (Cow::Owned(canonical), Some(text))
            }
            _ => (text, None),
        };
        self.cx.base = text.as_ptr() as usize;
        // A cycle's parameter lines follow its header in the source: offsets reach up to there.
        self.cx.len = if is_cycle { last.end - body_start } else { text.len() };
        self.cx.issues.get_mut().clear();
        let body = if is_cycle {
            let params: Vec<&str> = self.block_lines[1..].iter().map(|l| &src[l.start..l.end]).collect();
            match cycles::cycle_def(&self.cx, &text, &params, probe) {
                Ok((_, block)) => Some(block),
                Err(stop) => self.cx.fail(stop),
            }
        } else {
            parse_body(&self.cx, &text)
        };
        let body = match body {
            Some(body) if !matches!(body, BlockBody::Unknown { .. }) => body,
            // Not read, so not rewritten either: kept as written, its parentheses included.
            unread => {
                if paren.is_some() {
                    comment = None;
                }
                let as_written = paren.unwrap_or_else(|| written.as_deref().unwrap_or(&text).trim_end());
                match unread {
                    Some(_) => BlockBody::Unknown { text: as_written.to_owned() },
                    None => invalid(as_written),
                }
            }
        };
        if dangling_tilde && !continued {
            let code = match &body {
                BlockBody::CycleDef(c) => DiagCode::CycleParamsElided { cycle: c.number },
                _ => DiagCode::ContinuationMissing,
            };
            let at = first.start + line_text.trim_end().len() - 1;
            self.diag_at(Severity::Warning, code, at, at + 1, None);
        }
        // Map issue offsets back to the source.
        let issues = std::mem::take(self.cx.issues.get_mut());
        for issue in &issues {
            let to_src = |off: usize| -> usize {
                match segments.iter().rev().find(|(j, _)| *j <= off) {
                    Some((j, s)) => s + (off - j),
                    None => body_start + off,
                }
            };
            let (start, end) = (to_src(issue.start), to_src(issue.end));
            self.diag_at(issue.severity, issue.code.clone(), start, end.max(start), issue.expected);
        }
        *self.cx.issues.get_mut() = issues;
        self.cx.issues.get_mut().clear();
        Block::new(number, skip, body, comment, span, line, column)
    }
}

/// Drops the continuation mark(s) at the end of a line part.
pub(crate) fn strip_tilde(s: &str) -> &str {
    s.trim_end_matches(|c: char| c == '~' || c.is_whitespace())
}

fn invalid(text: &str) -> BlockBody {
    BlockBody::Invalid { text: text.to_owned() }
}

/// `CYCL DEF 7.0 …`, `TCH PROBE 0.1 …` (`after` follows the keyword): the cycle number has a
/// sub-number.
fn is_old_cycle(after: &str) -> bool {
    let rest = words::sp(after);
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    rest.as_bytes().get(digits) == Some(&b'.')
}

/// Dispatches on the first word to the block family. A family's recoverable stop says the
/// block is not one of its kinds (`TRANS SCALE`, `FUNCTION PROG PATH`): kept as an unknown
/// block; a hard stop is the block's error.
fn parse_body(cx: &Cx, body: &str) -> Option<BlockBody> {
    if body.is_empty() {
        return Some(BlockBody::Empty);
    }
    if let Some(text) = body.strip_prefix('*') {
        return Some(BlockBody::Structure { text: text.trim().to_owned() });
    }
    if body.starts_with('(') {
        return Some(BlockBody::Header { text: body.to_owned() });
    }
    let Ok((rest, kw)) = words::letters(body) else {
        return cx.invalid(body, None);
    };
    let digit_follows = rest.as_bytes().first().is_some_and(u8::is_ascii_digit);
    let read = match kw {
        "BEGIN" | "END" => frame::pgm(cx, body),
        "BLK" => tool::blk_form(cx, body),
        "TOOL" if words::keyword(words::sp(rest), "CALL").is_some() => tool::tool_call(body),
        "TOOL" if words::def_keyword(words::sp(rest)).is_some() => tool::tool_def(body),
        "STOP" if !digit_follows => motion::stop(cx, body),
        "QS" if digit_follows => labels_q::qs_assign(body),
        "L" | "CC" | "C" | "CR" | "CT" | "LP" | "CP" | "RND" | "CHF" if !digit_follows => {
            motion::path(cx, body)
        }
        "M" if digit_follows => motion::m_only(cx, body),
        // A CAM post for another control leaves out the `L`; said once per file (`lenient`).
        _ if crate::unconfirmed::IMPORT_LENIENT_SPELLINGS && lenient::lacks_l(body.as_bytes()) => {
            motion::line_without_l(cx, body)
        }
        "APPR" | "DEP" => approach::appr_dep(cx, body),
        "PATTERN" => pattern::pattern_def(body),
        "CYCL" => cycles::cycle_other(cx, body),
        "PLANE" => plane::plane(cx, body),
        "TRANS" => transforms::trans(cx, body),
        "FUNCTION" => function::function(body),
        "LBL" | "CALL" => labels_q::label_or_call(body),
        "FN" => labels_q::fn_block(body),
        "Q" | "QL" | "QR" if digit_follows => labels_q::assign(body),
        _ => return unknown(cx, body),
    };
    read_family(cx, body, read)
}

/// What a family's read gives the block: its node, an unknown block (a recoverable stop: not
/// one of its kinds) or nothing with the stop's diagnostic.
fn read_family(cx: &Cx, body: &str, read: Step<'_, BlockBody>) -> Option<BlockBody> {
    match read {
        Ok((_, block)) => Some(block),
        Err(nom::Err::Error(_)) => unknown(cx, body),
        Err(stop) => cx.fail(stop),
    }
}

/// A block of a kind we do not model: kept with a warning if it looks like NC text.
pub(crate) fn unknown(cx: &Cx, body: &str) -> Option<BlockBody> {
    let first_word = body.split([' ', '\t']).next().unwrap_or("");
    let well_formed = first_word.bytes().all(|b| b.is_ascii_uppercase() || b.is_ascii_digit())
        && first_word.as_bytes().first().is_some_and(u8::is_ascii_uppercase)
        && !body.chars().any(char::is_control);
    if well_formed {
        cx.warn(body, first_word.len(), DiagCode::UnknownBlock);
        // Trimmed: a lenient reading may have blanked a character at the end (`A M0.`), and the
        // text must format to what reads back the same.
        Some(BlockBody::Unknown { text: body.trim_end().to_owned() })
    } else {
        cx.invalid(body, None)
    }
}
