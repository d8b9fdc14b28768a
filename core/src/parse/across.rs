//! The checks across blocks: block numbers, the END PGM name, the lenient spellings said once
//! per file, a BEGIN PGM without END PGM.

use super::{lenient, n_number, split_comment};
use crate::ast::{Block, BlockBody, Span};
use crate::diag::{DiagCode, Lenient, Severity};

/// The checks across blocks, made block by block in program order: block numbers ascending,
/// the END PGM name equal to the BEGIN PGM name, a BEGIN PGM without END PGM. The parser makes
/// them, and an edit that re-read only some blocks makes them again over the whole program
/// (`Document::edited` in the app).
///
/// Block numbers are the control's own bookkeeping (its editor numbers the blocks itself), so
/// numbers that are missing, not ascending, written `N…` or followed by a comment without a
/// blank (`12;…`) are never an error: each is said once per file, a warning at its first
/// block, and the blocks run in their order in the file
/// (`unconfirmed::IMPORT_BLOCK_NUMBERS_ARE_WARNINGS`).
#[derive(Debug, Default)]
pub struct AcrossBlocks {
    previous: Option<u32>,
    begin: Option<String>,
    end_seen: bool,
    not_ascending_said: bool,
    missing_said: bool,
    prefixed_said: bool,
    glued_said: bool,
    lenient_said: [bool; Lenient::ALL.len()],
}

impl AcrossBlocks {
    /// The findings `block` (of the text `src`) adds, each with its severity and span.
    pub fn check(&mut self, src: &str, block: &Block, mut found: impl FnMut(Severity, DiagCode, Span)) {
        let span = block.span();
        let numbers = if crate::unconfirmed::IMPORT_BLOCK_NUMBERS_ARE_WARNINGS {
            Severity::Warning
        } else {
            Severity::Error
        };
        let text = src.get(span.start..).unwrap_or("");
        let lead = text.len() - text.trim_start_matches('/').trim_start().len();
        if let Some(n) = block.number() {
            let prefix = n_number(&text.as_bytes()[lead..]).unwrap_or(0);
            let digits = prefix + text[lead + prefix..].bytes().take_while(u8::is_ascii_digit).count();
            // From the block's start (a skip `/` included), where the splice places it too.
            let at = Span::new(span.start, span.start + lead + digits);
            if prefix > 0 && !std::mem::replace(&mut self.prefixed_said, true) {
                found(numbers, DiagCode::BlockNumberPrefixed { number: n }, at);
            }
            if text[lead + digits..].starts_with(';') && !std::mem::replace(&mut self.glued_said, true) {
                found(numbers, DiagCode::CommentAfterNumber { number: n }, at);
            }
            if let Some(previous) = self.previous.filter(|&p| n <= p)
                && !std::mem::replace(&mut self.not_ascending_said, true)
            {
                found(numbers, DiagCode::BlockNumberNotAscending { previous, number: n }, at);
            }
            self.previous = Some(n);
        } else if !std::mem::replace(&mut self.missing_said, true) {
            found(numbers, DiagCode::MissingBlockNumber, Span::new(span.start, span.start));
        }
        if let Some(body) = block.stored_body()
            && !matches!(body, BlockBody::CycleDef(_) | BlockBody::TouchProbe(_))
            && self.lenient_said.contains(&false)
        {
            let invalid = matches!(body, BlockBody::Invalid { .. } | BlockBody::Unknown { .. });
            self.lenient(src, span, invalid, &mut found);
        }
        match block.stored_body() {
            Some(BlockBody::BeginPgm { name, .. }) if self.begin.is_none() => self.begin = Some(name.clone()),
            Some(BlockBody::EndPgm { name, .. }) => {
                self.end_seen = true;
                if let Some(begin) = self.begin.as_ref().filter(|b| !b.eq_ignore_ascii_case(name)) {
                    let severity = if crate::unconfirmed::END_PGM_NAME_IS_BOOKKEEPING {
                        Severity::Warning
                    } else {
                        Severity::Error
                    };
                    found(
                        severity,
                        DiagCode::PgmNameMismatch { begin: begin.clone(), end: name.clone() },
                        span,
                    );
                }
            }
            _ => {}
        }
    }

    /// The lenient spellings of the block at `span` not yet said in this file; a comment in
    /// parentheses only when the parser read it (not in an `invalid` or unknown block, which
    /// keeps it as written, nor in a block continued over lines).
    fn lenient(
        &mut self,
        src: &str,
        span: Span,
        invalid: bool,
        found: &mut impl FnMut(Severity, DiagCode, Span),
    ) {
        // Without the lenient reading the block is refused as written: nothing to say here.
        if !crate::unconfirmed::IMPORT_LENIENT_SPELLINGS {
            return;
        }
        let mut at = span.start;
        let text = src.get(span.start..span.end).unwrap_or("");
        // The parser reads a comment in parentheses only in a block of one line.
        let invalid = invalid || text.contains('\n');
        for (k, line) in text.split('\n').enumerate() {
            let (body, _) = split_comment(line);
            lenient::first_of_each(body, k == 0, |kind, a, b| {
                let kept_as_written = invalid && kind == Lenient::ParenComment;
                if !kept_as_written && !std::mem::replace(&mut self.lenient_said[kind as usize], true) {
                    let text = body[a..b].to_owned();
                    found(Severity::Warning, DiagCode::Lenient { kind, text }, Span::new(at + a, at + b));
                }
            });
            at += line.len() + 1;
        }
    }

    /// After the last block: a BEGIN PGM without END PGM (a warning at the end of the text).
    #[must_use]
    pub fn end_missing(&self) -> bool {
        self.begin.is_some() && !self.end_seen
    }
}
