//! Diagnostics: what is wrong where, in German (as the control says it) and English.
//!
//! The parser records a [`Diagnostic`] and carries on with the next block (rust-analyzer's
//! `(T, Vec<Error>)` shape), so a broken program still shows everything that could be read.

use std::fmt::Write as _;

use serde::Serialize;

use crate::ast::Span;

/// Error: the control would refuse the block. Warning: it would run, but look again.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
}

impl Severity {
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// Language of a message and of the UI. German is the default: the trainees are mostly
/// German-speaking machinists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, serde::Deserialize)]
pub enum Lang {
    #[default]
    De,
    En,
}

impl Lang {
    /// Picks the text for this language.
    #[must_use]
    pub fn t<'a>(self, de: &'a str, en: &'a str) -> &'a str {
        match self {
            Lang::De => de,
            Lang::En => en,
        }
    }

    #[must_use]
    pub fn other(self) -> Lang {
        match self {
            Lang::De => Lang::En,
            Lang::En => Lang::De,
        }
    }

    /// The HTML `lang` code.
    #[must_use]
    pub fn code(self) -> &'static str {
        self.t("de", "en")
    }
}

/// What was found, with the numbers that matter (machine-readable; the messages are built
/// from it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum DiagCode {
    /// A word that cannot be read here.
    InvalidInput,
    /// A mandatory word is missing (`PLANE SPATIAL` without `SPC`).
    MissingWord {
        word: &'static str,
    },
    /// An angle outside its input range (DOMAIN.md §5).
    AngleNotPermitted {
        word: &'static str,
        value: f64,
        min: f64,
        max: f64,
    },
    /// Any other value outside its input range (DOMAIN.md §5).
    ValueOutOfRange {
        word: &'static str,
        value: f64,
        min: f64,
        max: f64,
    },
    /// The same word twice in one block.
    Duplicate {
        word: String,
    },
    /// A word that this kind of block does not take.
    NotAllowed {
        word: String,
    },
    /// `SEQ` and `SYM` in the same PLANE block.
    SeqWithSym,
    /// `PLANE VECTOR` with a zero normal or base vector.
    ZeroVector {
        word: &'static str,
    },
    BlockNumberNotAscending {
        previous: u32,
        number: u32,
    },
    MissingBlockNumber,
    PgmNameMismatch {
        begin: String,
        end: String,
    },
    MissingEndPgm,
    /// A well-formed block of a kind the trainer does not model.
    UnknownBlock,
    /// `CYCL DEF … ~` not followed by its parameter lines (the manual prints it that way).
    CycleParamsElided {
        cycle: u32,
    },
    /// A block ends in `~` but no continuation line follows.
    ContinuationMissing,
    /// `PLANE …` without `MOVE`, `TURN` or `STAY`.
    MissingPositioning,
}

/// One finding, located by line, column (both 1-based, columns count characters) and byte span.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    pub severity: Severity,
    pub code: DiagCode,
    pub line: u32,
    pub column: u32,
    pub span: Span,
    pub message_de: String,
    pub message_en: String,
    /// What the parser would have accepted at that point (`SPC`, `MOVE|TURN|STAY`).
    pub expected: Option<String>,
}

impl Diagnostic {
    /// Builds the messages from the code.
    #[must_use]
    pub fn new(severity: Severity, code: DiagCode, span: Span, line: u32, column: u32) -> Self {
        let (message_de, message_en) = messages(&code);
        Diagnostic { severity, code, line, column, span, message_de, message_en, expected: None }
    }

    #[must_use]
    pub fn with_expected(mut self, expected: Option<&str>) -> Self {
        if let Some(e) = expected {
            let _ = write!(self.message_de, " (erwartet: {e})");
            let _ = write!(self.message_en, " (expected: {e})");
            self.expected = Some(e.to_owned());
        }
        self
    }

    #[must_use]
    pub fn message(&self, lang: Lang) -> &str {
        match lang {
            Lang::De => &self.message_de,
            Lang::En => &self.message_en,
        }
    }

    #[must_use]
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// A value or range bound the way the manual prints it (`359.9999`, `0`, `-180`), with the
/// decimal comma in the German message.
fn n(v: f64, lang: Lang) -> String {
    crate::number::prose(v, None, lang)
}

fn messages(code: &DiagCode) -> (String, String) {
    use Lang::{De, En};
    match code {
        DiagCode::InvalidInput => ("Eingabewert falsch".into(), "Invalid input".into()),
        DiagCode::MissingWord { word } => {
            (format!("Eingabe fehlt: {word}"), format!("Missing input: {word}"))
        }
        DiagCode::AngleNotPermitted { word, value, min, max } => (
            format!("Winkel nicht erlaubt: {word} {} ({}…{})", n(*value, De), n(*min, De), n(*max, De)),
            format!(
                "Entered angle not permitted: {word} {} ({}…{})",
                n(*value, En),
                n(*min, En),
                n(*max, En)
            ),
        ),
        DiagCode::ValueOutOfRange { word, value, min, max } => (
            format!(
                "Eingabebereich überschritten: {word} {} ({}…{})",
                n(*value, De),
                n(*min, De),
                n(*max, De)
            ),
            format!("Value out of range: {word} {} ({}…{})", n(*value, En), n(*min, En), n(*max, En)),
        ),
        DiagCode::Duplicate { word } => {
            (format!("Doppelt programmiert: {word}"), format!("Programmed twice: {word}"))
        }
        DiagCode::NotAllowed { word } => {
            (format!("{word} hier nicht erlaubt"), format!("{word} not permitted in this block"))
        }
        DiagCode::SeqWithSym => {
            ("SEQ und SYM nicht gleichzeitig erlaubt".into(), "SEQ and SYM cannot be combined".into())
        }
        DiagCode::ZeroVector { word } => (
            format!("Eingabewert falsch: {word} ist Nullvektor"),
            format!("Invalid input: {word} is a zero vector"),
        ),
        DiagCode::BlockNumberNotAscending { previous, number } => (
            format!("Satznummer nicht aufsteigend: {number} nach {previous}"),
            format!("Block number not ascending: {number} after {previous}"),
        ),
        DiagCode::MissingBlockNumber => ("Satznummer fehlt".into(), "Block number missing".into()),
        DiagCode::PgmNameMismatch { begin, end } => (
            format!("Programmname falsch: END PGM {end} zu BEGIN PGM {begin}"),
            format!("Wrong program name: END PGM {end} for BEGIN PGM {begin}"),
        ),
        DiagCode::MissingEndPgm => ("END PGM fehlt".into(), "END PGM missing".into()),
        DiagCode::UnknownBlock => ("Unbekannter NC-Satz".into(), "Unknown NC block".into()),
        DiagCode::CycleParamsElided { cycle } => (
            format!("Zyklusparameter ausgelassen: CYCL DEF {cycle}"),
            format!("Cycle parameters left out: CYCL DEF {cycle}"),
        ),
        DiagCode::ContinuationMissing => {
            ("Fortsetzungszeile fehlt".into(), "Continuation line missing".into())
        }
        DiagCode::MissingPositioning => (
            "Positionierverhalten fehlt (MOVE/TURN/STAY)".into(),
            "Positioning missing (MOVE/TURN/STAY)".into(),
        ),
    }
}
