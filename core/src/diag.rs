//! Diagnostics: what is wrong where, in German (as the control says it) and English.
//!
//! The parser records a [`Diagnostic`] and carries on with the next block (rust-analyzer's
//! `(T, Vec<Error>)` shape), so a broken program still shows everything that could be read.

use serde::Serialize;

pub use crate::lang::Lang;
use crate::lang::Text;
use crate::span::Span;

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
    /// Said once per file, at the first block whose number is not above the one before.
    BlockNumberNotAscending {
        previous: u32,
        number: u32,
    },
    /// Said once per file, at the first block without a number.
    MissingBlockNumber,
    /// A line of only a data transfer's control characters (ETX, which ends a serial transfer of
    /// the control, or SUB, an old file system's end of file), kept by the program that saved
    /// the transfer: not a block, said on the line.
    TransferMark,
    /// Said once per file, at the first block numbered `N…` (as ISO programs and some CAM
    /// systems write it): read as its block number.
    BlockNumberPrefixed {
        number: u32,
    },
    /// Said once per file, at the first comment block written without a blank after its number
    /// (`12;created by …`, as some CAM systems write it): read as `12 ;created by …`.
    CommentAfterNumber {
        number: u32,
    },
    /// Said once per kind and file, at its first occurrence: a spelling read as its canonical
    /// form ([`Lenient`]); `text` as written there.
    Lenient {
        kind: Lenient,
        text: String,
    },
    PgmNameMismatch {
        begin: String,
        end: String,
    },
    MissingEndPgm,
    /// `BEGIN PGM  MM`: no program name.
    PgmNameMissing,
    /// `BEGIN PGM SP1 1002 MM`: a blank in the program name.
    PgmNameBlank,
    /// `END PGM name` without MM or INCH.
    EndPgmUnitMissing,
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

/// What the parser would have accepted where it stopped: NC words, the same in both languages
/// (`SPC`, `MOVE|TURN|STAY`), or a description of the word in German and English.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Expected {
    /// NC words as written in the program (alternatives separated by `|`).
    Nc(&'static str),
    /// A blank between two words.
    Blank,
    BlockNumber,
    Number,
    /// A whole number in the range of a label or cycle number.
    NumberU32,
    Name,
    /// A name in double quotes.
    QuotedName,
    Axis,
    /// A label: its number or its quoted name.
    LabelNumberOrName,
    /// An operand of a Q formula.
    Operand,
    /// A formula with fewer terms.
    ShorterFormula,
    /// A formula with fewer nested parentheses.
    LessNesting,
}

impl Expected {
    /// The text shown after "erwartet:" / "expected:".
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Expected::Nc(words) => Text::new(words, words),
            Expected::Blank => Text::new("Leerzeichen", "blank"),
            Expected::BlockNumber => Text::new("Satznummer", "block number"),
            Expected::Number => Text::new("Zahl", "number"),
            Expected::NumberU32 => Text::new("Zahl 0…4294967295", "number 0…4294967295"),
            Expected::Name => Text::new("Name", "name"),
            Expected::QuotedName => Text::new("\"Name\"", "\"name\""),
            Expected::Axis => Text::new("Achse", "axis"),
            Expected::LabelNumberOrName => Text::new("Nummer|\"Name\"", "number|\"name\""),
            Expected::Operand => Text::new("Zahl|Q|(|Funktion", "number|Q|(|function"),
            Expected::ShorterFormula => Text::new("kürzere Formel", "shorter formula"),
            Expected::LessNesting => Text::new("weniger Verschachtelung", "less nesting"),
        }
    }
}

/// One finding, located by line, column (both 1-based, columns count characters) and byte span.
/// It keeps what was found ([`DiagCode`]) and what was expected; the message is rendered in the
/// language asked for when it is shown ([`Diagnostic::message`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    pub severity: Severity,
    pub code: DiagCode,
    pub line: u32,
    pub column: u32,
    pub span: Span,
    /// What the parser would have accepted at that point (`SPC`, `MOVE|TURN|STAY`): the help.
    pub expected: Option<Expected>,
}

impl Diagnostic {
    #[must_use]
    pub fn new(severity: Severity, code: DiagCode, span: Span, line: u32, column: u32) -> Self {
        Diagnostic { severity, code, line, column, span, expected: None }
    }

    #[must_use]
    pub fn with_expected(mut self, expected: Option<Expected>) -> Self {
        self.expected = expected;
        self
    }

    /// The message in `lang`, with what was expected (German as the control words it).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        let mut m = self.code.message().get(lang).to_owned();
        if let Some(help) = self.help(lang) {
            m.push_str(lang.t(" (erwartet: ", " (expected: "));
            m.push_str(&help);
            m.push(')');
        }
        m
    }

    /// What would have been accepted, in `lang` (`None` where the parser cannot say).
    #[must_use]
    pub fn help(&self, lang: Lang) -> Option<String> {
        self.expected.map(|e| e.text().get(lang).to_owned())
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

impl DiagCode {
    /// The message, German as the control words it.
    #[must_use]
    pub fn message(&self) -> Text {
        use Lang::{De, En};
        let t = Text::owned;
        match self {
            DiagCode::InvalidInput => Text::new("Eingabewert falsch", "Invalid input"),
            DiagCode::MissingWord { word } => {
                t(format!("Eingabe fehlt: {word}"), format!("Missing input: {word}"))
            }
            DiagCode::AngleNotPermitted { word, value, min, max } => t(
                format!("Winkel nicht erlaubt: {word} {} ({}…{})", n(*value, De), n(*min, De), n(*max, De)),
                format!(
                    "Entered angle not permitted: {word} {} ({}…{})",
                    n(*value, En),
                    n(*min, En),
                    n(*max, En)
                ),
            ),
            DiagCode::ValueOutOfRange { word, value, min, max } => t(
                format!(
                    "Eingabebereich überschritten: {word} {} ({}…{})",
                    n(*value, De),
                    n(*min, De),
                    n(*max, De)
                ),
                format!("Value out of range: {word} {} ({}…{})", n(*value, En), n(*min, En), n(*max, En)),
            ),
            DiagCode::Duplicate { word } => {
                t(format!("Doppelt programmiert: {word}"), format!("Programmed twice: {word}"))
            }
            DiagCode::NotAllowed { word } => {
                t(format!("{word} hier nicht erlaubt"), format!("{word} not permitted in this block"))
            }
            DiagCode::SeqWithSym => {
                Text::new("SEQ und SYM nicht gleichzeitig erlaubt", "SEQ and SYM cannot be combined")
            }
            DiagCode::ZeroVector { word } => t(
                format!("Eingabewert falsch: {word} ist Nullvektor"),
                format!("Invalid input: {word} is a zero vector"),
            ),
            DiagCode::BlockNumberNotAscending { previous, number } => t(
                format!(
                    "Satznummern nicht aufsteigend (zuerst {number} nach {previous}): die Sätze laufen in ihrer Reihenfolge in der Datei"
                ),
                format!(
                    "Block numbers not ascending (first {number} after {previous}): the blocks run in their order in the file"
                ),
            ),
            DiagCode::MissingBlockNumber => Text::new(
                "Satznummern fehlen (zuerst hier): die Sätze laufen in ihrer Reihenfolge in der Datei",
                "Block numbers missing (first here): the blocks run in their order in the file",
            ),
            DiagCode::TransferMark => Text::new(
                "Steuerzeichen der Datenübertragung (ETX/SUB) überlesen: kein NC-Satz",
                "Data transfer control character (ETX/SUB) skipped: not an NC block",
            ),
            DiagCode::BlockNumberPrefixed { number } => t(
                format!("N-Satznummern gelesen (zuerst N{number}): Klartext schreibt die Nummer ohne N"),
                format!("N block numbers read (first N{number}): Klartext writes the number without N"),
            ),
            DiagCode::CommentAfterNumber { number } => t(
                format!(
                    "Kommentar direkt nach der Satznummer gelesen (zuerst {number};): Klartext schreibt ein Leerzeichen davor"
                ),
                format!(
                    "Comment right after the block number read (first {number};): Klartext writes a blank before it"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::DecimalComma, text } => t(
                format!("Dezimalkomma gelesen (zuerst „{text}“): Klartext schreibt einen Dezimalpunkt"),
                format!("Decimal comma read (first \"{text}\"): Klartext writes a decimal point"),
            ),
            DiagCode::Lenient { kind: Lenient::BlankAfterAddress, text } => t(
                format!(
                    "Leerzeichen nach dem Adressbuchstaben gelesen (zuerst „{text}“): Klartext schreibt den Wert direkt dahinter"
                ),
                format!(
                    "Blank after the address letter read (first \"{text}\"): Klartext writes the value right after it"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::PointAfterM, text } => t(
                format!(
                    "Punkt nach der M-Funktion gelesen (zuerst „{text}“): Klartext schreibt M-Funktionen ohne Punkt"
                ),
                format!(
                    "Point after the M function read (first \"{text}\"): Klartext writes M functions without a point"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::RadiusInDep, text } => t(
                format!(
                    "„{text}“ im DEP-Satz überlesen: DEP hebt die Radiuskorrektur selbst auf (Klartext: DEP … LEN/R … F … M)"
                ),
                format!(
                    "\"{text}\" in the DEP block skipped: DEP cancels the radius compensation itself (Klartext: DEP … LEN/R … F … M)"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::MissingL, text } => t(
                format!("Geradensätze ohne L gelesen (zuerst „{text}“): Klartext beginnt eine Gerade mit L"),
                format!(
                    "Straight-line blocks without L read (first \"{text}\"): Klartext starts a straight line with L"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::UnitIn, text } => t(
                format!("„{text}“ als INCH gelesen: Klartext schreibt die Einheit MM oder INCH"),
                format!("\"{text}\" read as INCH: Klartext writes the unit MM or INCH"),
            ),
            DiagCode::Lenient { kind: Lenient::SpeedInPath, text } => t(
                format!(
                    "Drehzahl im Verfahrsatz gelesen (zuerst „{text}“): Klartext programmiert die Drehzahl mit TOOL CALL S…"
                ),
                format!(
                    "Spindle speed in a path block read (first \"{text}\"): Klartext programs the speed with TOOL CALL S…"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::FeedInToolDef, text } => t(
                format!(
                    "„{text}“ im TOOL DEF überlesen: Klartext definiert im TOOL DEF nur Länge und Radius (L, R), den Vorschub im Verfahrsatz"
                ),
                format!(
                    "\"{text}\" in TOOL DEF skipped: Klartext's TOOL DEF defines only the length and radius (L, R), the feed goes in a path block"
                ),
            ),
            DiagCode::Lenient { kind: Lenient::ParenComment, text } => t(
                format!(
                    "Kommentar in Klammern gelesen (zuerst „{text}“): Klartext schreibt einen Kommentar nach ;"
                ),
                format!("Comment in parentheses read (first \"{text}\"): Klartext writes a comment after ;"),
            ),
            DiagCode::Lenient { kind: Lenient::CycleSpeltOut, text } => t(
                format!("„{text}“ als CYCL DEF gelesen: Klartext schreibt CYCL"),
                format!("\"{text}\" read as CYCL DEF: Klartext writes CYCL"),
            ),
            DiagCode::PgmNameMismatch { begin, end } => t(
                format!(
                    "Programmname falsch: END PGM {end} zu BEGIN PGM {begin}; gelesen als Ende von {begin} (der Name ist Buchführung der Steuerung)"
                ),
                format!(
                    "Wrong program name: END PGM {end} for BEGIN PGM {begin}; read as the end of {begin} (the name is the control's bookkeeping)"
                ),
            ),
            DiagCode::MissingEndPgm => Text::new("END PGM fehlt", "END PGM missing"),
            DiagCode::PgmNameMissing => Text::new(
                "Programmname fehlt: gelesen als Programm ohne Namen (die Steuerung schreibt den Dateinamen)",
                "Program name missing: read as a program without a name (the control writes the file name)",
            ),
            DiagCode::PgmNameBlank => Text::new(
                "Programmname mit Leerzeichen gelesen: die Steuerung erlaubt kein Leerzeichen im Dateinamen (Benutzerhandbuch TNC 620/320: Dateinamen)",
                "Program name with a blank read: the control allows no blank in a file name (TNC 620/320 user's manual: file names)",
            ),
            DiagCode::EndPgmUnitMissing => Text::new(
                "Maßeinheit fehlt: END PGM gelesen mit der Einheit von BEGIN PGM",
                "Unit missing: END PGM read with the unit of BEGIN PGM",
            ),
            DiagCode::UnknownBlock => Text::new("Unbekannter NC-Satz", "Unknown NC block"),
            DiagCode::CycleParamsElided { cycle } => t(
                format!("Zyklusparameter ausgelassen: CYCL DEF {cycle}"),
                format!("Cycle parameters left out: CYCL DEF {cycle}"),
            ),
            DiagCode::ContinuationMissing => {
                Text::new("Fortsetzungszeile fehlt", "Continuation line missing")
            }
            DiagCode::MissingPositioning => Text::new(
                "Positionierverhalten fehlt (MOVE/TURN/STAY)",
                "Positioning missing (MOVE/TURN/STAY)",
            ),
        }
    }
}

/// A spelling read leniently (the parser's `lenient.rs` reads it; its warning is said here).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Lenient {
    /// `49,000` for `49.000`.
    DecimalComma,
    /// `Z 25.000` for `Z25.000`.
    BlankAfterAddress,
    /// `M128.` for `M128` (a CAM post's number format on an M function).
    PointAfterM,
    /// `DEP LT LEN10 R0`: the departure ends the compensation itself, `R0` says nothing more.
    RadiusInDep,
    /// `Z0.0 B0.0 C0.0 FMAX M91` for `L Z0.0 B0.0 C0.0 FMAX M91` (a CAM post for another control).
    MissingL,
    /// `CYCLE DEF 9.0 DWELL TIME` for `CYCL DEF 9.0 …` (an old-style cycle with its word spelt out).
    CycleSpeltOut,
    /// `BEGIN PGM 100 IN` for `BEGIN PGM 100 INCH` (a CAM post's abbreviation of the unit).
    UnitIn,
    /// `L Z-45. F1000. S6000` (a CAM post's or simulator's speed change in a path block; the
    /// control changes the speed with `TOOL CALL S…`): the spindle turns at it from that block on.
    SpeedInPath,
    /// `TOOL DEF1 L+30,000 F300` (a training simulator's tool feed; Klartext's TOOL DEF has
    /// only the length and radius): read without the feed.
    FeedInToolDef,
    /// `L IX-80 (MODAL DRILL POINT)` for `L IX-80 ;MODAL DRILL POINT` (a training simulator's
    /// comment after the words): read as the block's comment.
    ParenComment,
}

impl Lenient {
    pub const ALL: [Lenient; 10] = [
        Lenient::DecimalComma,
        Lenient::BlankAfterAddress,
        Lenient::PointAfterM,
        Lenient::RadiusInDep,
        Lenient::MissingL,
        Lenient::CycleSpeltOut,
        Lenient::UnitIn,
        Lenient::SpeedInPath,
        Lenient::FeedInToolDef,
        Lenient::ParenComment,
    ];
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expected_words_are_translated_nc_words_are_not() {
        let d = Diagnostic::new(Severity::Error, DiagCode::InvalidInput, Span::new(0, 1), 1, 1)
            .with_expected(Some(Expected::BlockNumber));
        assert_eq!(d.message(Lang::De), "Eingabewert falsch (erwartet: Satznummer)");
        assert_eq!(d.message(Lang::En), "Invalid input (expected: block number)");
        let d = d.with_expected(Some(Expected::Nc("MOVE|TURN|STAY")));
        assert_eq!(d.help(Lang::En).as_deref(), Some("MOVE|TURN|STAY"));
        assert_eq!(d.message(Lang::De), "Eingabewert falsch (erwartet: MOVE|TURN|STAY)");
    }
}
