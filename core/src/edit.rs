//! Editing a program as the control does: a block inserted after the cursor gets the next
//! block number and the blocks after it are renumbered; a reopened block keeps its number and
//! comment. Works on the text, so everything else the trainee wrote stays exactly as written.

use crate::ast::{BlockBody, Program};

/// Byte offset where the line holding `offset` starts.
fn line_start(src: &str, offset: usize) -> usize {
    src.get(..offset).and_then(|s| s.rfind('\n')).map_or(0, |i| i + 1)
}

/// Inserts the block `body` (text without number) after block `cursor` of `program` (parsed
/// from `src`); with the cursor on `END PGM` it goes before it, as on the control. Returns the
/// new text and the index of the inserted block.
#[must_use]
pub fn insert_after(src: &str, program: &Program, cursor: usize, body: &str) -> (String, usize) {
    let blocks = &program.blocks;
    let mut at = (cursor + 1).min(blocks.len());
    if let Some(b) = blocks.get(cursor)
        && matches!(b.stored_body(), Some(BlockBody::EndPgm { .. }))
    {
        at = cursor;
    }
    let number = match at.checked_sub(1).and_then(|i| blocks.get(i)) {
        Some(prev) => prev.number().map_or(at as u32, |n| n.saturating_add(1)),
        None => 0,
    };
    let offset = blocks.get(at).map_or(src.len(), |b| line_start(src, b.span().start));
    let mut out = String::with_capacity(src.len() + body.len() + 8);
    out.push_str(&src[..offset]);
    if !out.is_empty() && !out.ends_with('\n') {
        out.push('\n');
    }
    out.push_str(&format!("{number} {body}\n"));
    // Renumber the blocks after it so the numbers keep ascending.
    let mut prev = number;
    let mut copied = offset;
    for b in &blocks[at..] {
        let Some(n) = b.number() else { continue };
        if n > prev {
            break;
        }
        let start = b.span().start + usize::from(src[b.span().start..].starts_with('/'));
        let digits = src[start..].bytes().take_while(u8::is_ascii_digit).count();
        out.push_str(&src[copied..start]);
        prev = prev.saturating_add(1);
        out.push_str(&prev.to_string());
        copied = start + digits;
    }
    out.push_str(&src[copied..]);
    (out, at)
}

/// Replaces the body of block `index` with `body`, keeping its block number, skip slash and
/// comment (ENT on a PLANE block, dialog finished).
#[must_use]
pub fn replace_block(src: &str, program: &Program, index: usize, body: &str) -> String {
    let Some(b) = program.blocks.get(index) else { return src.to_owned() };
    let mut line = String::new();
    if b.skip() {
        line.push('/');
    }
    if let Some(n) = b.number() {
        line.push_str(&format!("{n} "));
    }
    line.push_str(body);
    if let Some(c) = b.comment() {
        line.push_str(" ;");
        if !c.is_empty() {
            line.push(' ');
            line.push_str(c);
        }
    }
    let end = b.span().end.min(src.len());
    format!("{}{line}{}", &src[..b.span().start.min(end)], &src[end..])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    const PGM: &str = "0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91 ; sicher\n2 L X+0 R0 FMAX\n3 END PGM T MM\n";

    #[test]
    fn insert_after_cursor_numbers_and_renumbers() {
        let (p, _) = parse(PGM);
        let (out, at) = insert_after(PGM, &p, 1, "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX");
        assert_eq!(at, 2);
        assert_eq!(
            out,
            "0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91 ; sicher\n2 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n\
             3 L X+0 R0 FMAX\n4 END PGM T MM\n"
        );
        let (_, diags) = parse(&out);
        assert!(diags.is_empty(), "{diags:?}");
    }

    #[test]
    fn insert_on_end_pgm_goes_before_it() {
        let (p, _) = parse(PGM);
        let (out, at) = insert_after(PGM, &p, 3, "PLANE RESET STAY");
        assert_eq!(at, 3);
        assert!(out.ends_with("2 L X+0 R0 FMAX\n3 PLANE RESET STAY\n4 END PGM T MM\n"), "{out}");
    }

    #[test]
    fn insert_into_empty_text_and_after_last_line_without_newline() {
        let (p, _) = parse("");
        assert_eq!(insert_after("", &p, 0, "PLANE RESET STAY"), ("0 PLANE RESET STAY\n".to_owned(), 0));
        let src = "0 L X+0";
        let (p, _) = parse(src);
        assert_eq!(insert_after(src, &p, 0, "PLANE RESET STAY").0, "0 L X+0\n1 PLANE RESET STAY\n");
    }

    #[test]
    fn replace_keeps_number_and_comment() {
        let src = "0 BEGIN PGM T MM\n10 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX ; Einschwenken\n11 END PGM T MM\n";
        let (p, _) = parse(src);
        let out = replace_block(src, &p, 1, "PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST+50 F500");
        assert_eq!(
            out,
            "0 BEGIN PGM T MM\n10 PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST+50 F500 ; Einschwenken\n11 END PGM T MM\n"
        );
    }
}
