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

/// Splits a line into classed pieces that concatenate back to the line.
#[must_use]
pub fn highlight(line: &str) -> Vec<(Class, &str)> {
    let (code, comment) = match line.find(';') {
        Some(i) => (&line[..i], Some(&line[i..])),
        None => (line, None),
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
        let pieces = highlight(line);
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
        let pieces = highlight("  Q200=+2 ;SICHERHEITS-ABST. ~");
        assert_eq!(pieces[1], (Class::Word, "Q200=+2"));
        assert_eq!(pieces.last().map(|p| p.0), Some(Class::Comment));
    }
}
