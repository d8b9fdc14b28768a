//! Syntax colours for the program pane: a block line split into classed pieces. Display only;
//! what a block means is the parser's business.

/// The class of a piece of a block line (CSS class `nc-…`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// The leading block number.
    Number,
    /// Keywords: `PLANE`, `SPATIAL`, `L`, `CYCL DEF`, `TURN`, `FMAX`, …
    Keyword,
    /// An address letter with its value: `SPB+15`, `X-600`, `Q200=+2`, `M91`.
    Word,
    /// `;` and what follows.
    Comment,
    /// Blanks.
    Space,
}

impl Class {
    #[must_use]
    pub fn css(self) -> &'static str {
        match self {
            Class::Number => "nc-number",
            Class::Keyword => "nc-keyword",
            Class::Word => "nc-word",
            Class::Comment => "nc-comment",
            Class::Space => "nc-space",
        }
    }
}

/// Splits a line into classed pieces that concatenate back to the line; `in_comment`: the line
/// continues a comment the block's line before ran on with `~` (all of it is comment text).
#[must_use]
pub fn highlight(line: &str, in_comment: bool) -> Vec<(Class, &str)> {
    if in_comment {
        return vec![(Class::Comment, line)];
    }
    // The comment starts at the first `;` outside a quoted text (`QS500="A;B"`), as the parser
    // reads it.
    let (code, comment) = match schwenkbar_core::parse::split_comment(line) {
        (code, Some(_)) => (code, Some(&line[code.len()..])),
        (code, None) => (code, None),
    };
    let mut out = Vec::new();
    let mut first_word = true;
    let mut rest = code;
    while !rest.is_empty() {
        let blank = rest.len() - rest.trim_start().len();
        if blank > 0 {
            out.push((Class::Space, &rest[..blank]));
            rest = &rest[blank..];
            continue;
        }
        let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let word = &rest[..len];
        let class = if first_word && word.trim_start_matches('/').chars().all(|c| c.is_ascii_digit()) {
            Class::Number
        } else if word.chars().any(|c| c.is_ascii_digit() || c == '+' || c == '-' || c == '=') {
            Class::Word
        } else {
            Class::Keyword
        };
        first_word = false;
        out.push((class, word));
        rest = &rest[len..];
    }
    if let Some(c) = comment {
        out.push((Class::Comment, c));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_block_splits_into_number_keywords_words_and_comment() {
        let line = "10 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX ; Einschwenken";
        let pieces = highlight(line, false);
        assert_eq!(pieces.iter().map(|(_, s)| *s).collect::<String>(), line);
        let classes: Vec<_> =
            pieces.iter().filter(|(c, _)| *c != Class::Space).map(|(c, s)| (*c, *s)).collect();
        assert_eq!(
            classes,
            [
                (Class::Number, "10"),
                (Class::Keyword, "PLANE"),
                (Class::Keyword, "SPATIAL"),
                (Class::Word, "SPA+0"),
                (Class::Word, "SPB+15"),
                (Class::Word, "SPC+0"),
                (Class::Keyword, "TURN"),
                (Class::Keyword, "FMAX"),
                (Class::Comment, "; Einschwenken"),
            ]
        );
    }

    #[test]
    fn continuation_line_has_no_block_number() {
        let pieces = highlight("  Q200=+2 ;SICHERHEITS-ABST. ~", false);
        assert_eq!(pieces[1], (Class::Word, "Q200=+2"));
        assert_eq!(pieces.last().map(|p| p.0), Some(Class::Comment));
    }

    #[test]
    fn a_quoted_semicolon_is_text_and_a_wrapped_comment_stays_a_comment() {
        let pieces = highlight("  QS500=\"A;B\" ;TEXT ~", false);
        assert_eq!(pieces[1], (Class::Word, "QS500=\"A;B\""));
        assert_eq!(pieces.last(), Some(&(Class::Comment, ";TEXT ~")));
        assert_eq!(highlight(" under the terms of~", true), [(Class::Comment, " under the terms of~")]);
    }
}
