//! Keeping the trainee's work: the program text under a key of its own (so moving the cursor
//! in a 100,000-block program does not rewrite megabytes), the trainer's small state (cursor,
//! machine), the preferences both pages share (language, classroom projector) and the course's
//! progress, each as one short versioned text record (`s2;cursor=7;machine=ac-table`), plus the
//! share link's fragment. Pure; the browser side is in `schwenkbar-web`'s `browser.rs`. An old
//! or corrupt record is reported and replaced by the default, never a dead page.
//!
//! A record is `<kind><version>;key=value;…` with the values percent-encoded: readable in the
//! browser's storage inspector, no JSON parser in the bundle, and an old layout recognised by
//! its kind letter and version.

use crate::i18n::{Lang, Text};

/// The localStorage keys.
pub const STATE_KEY: &str = "schwenkbar.state";
pub const PROGRAM_KEY: &str = "schwenkbar.program";
pub const PREFS_KEY: &str = "schwenkbar.prefs";
pub const COURSE_KEY: &str = "schwenkbar.kurs";
/// The program a sample, an import or a share link last replaced (one undo step after a reload).
pub const REPLACED_KEY: &str = "schwenkbar.replaced";

/// What the browser kept for the trainer, as read at start-up (each `None` when not there).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Stored {
    /// The small state record ([`Saved`]).
    pub state: Option<String>,
    /// The preferences record ([`Prefs`]).
    pub prefs: Option<String>,
    /// The program text.
    pub program: Option<String>,
    /// The machine editor's own machines ([`crate::saved_machines`]).
    pub machines: Option<String>,
    /// The program last replaced ([`REPLACED_KEY`]).
    pub replaced: Option<String>,
    /// The shop's tool table, a `TOOL.T` text ([`crate::tool_table::TOOLS_KEY`]).
    pub tools: Option<String>,
}

/// Why a saved record could not be used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RestoreError {
    Corrupt,
    /// Written by an earlier build: another version of the record, or the JSON the builds
    /// before records wrote.
    OldVersion,
}

/// Writes a record: `kind` and `version` first, then the fields in order.
#[must_use]
pub fn write_record(kind: char, version: u32, fields: &[(&str, &str)]) -> String {
    let mut out = format!("{kind}{version}");
    for (key, value) in fields {
        out.push(';');
        out.push_str(key);
        out.push('=');
        escape_into(&mut out, value);
    }
    out
}

/// A record's value keeps every character but `%`, `;`, `=` and control characters, which are
/// written `%XX` (so the lessons' `1:3,0:0` stay readable).
fn escape_into(out: &mut String, value: &str) {
    for c in value.chars() {
        match c {
            '%' | ';' | '=' | '\0'..='\u{1f}' => out.push_str(&format!("%{:02X}", u32::from(c))),
            c => out.push(c),
        }
    }
}

fn unescape(s: &str) -> Option<String> {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find('%') {
        out.push_str(&rest[..i]);
        let hex = rest.get(i + 1..i + 3)?;
        let b = u8::from_str_radix(hex, 16)
            .ok()
            .filter(|b| hex.bytes().all(|h| h.is_ascii_hexdigit()) && *b < 0x80)?;
        out.push(char::from(b));
        rest = &rest[i + 3..];
    }
    out.push_str(rest);
    Some(out)
}

/// Reads a record written by [`write_record`] with these `keys`, in this order: the values,
/// decoded. Another version of the same kind, or JSON (the builds before records), is
/// `OldVersion`; anything else that does not match exactly is `Corrupt`.
pub fn read_record<const N: usize>(
    text: &str,
    kind: char,
    version: u32,
    keys: [&str; N],
) -> Result<[String; N], RestoreError> {
    let text = text.trim();
    if text.starts_with('{') {
        return Err(RestoreError::OldVersion);
    }
    let mut parts = text.split(';');
    let head = parts.next().unwrap_or_default();
    let digits = head.strip_prefix(kind).ok_or(RestoreError::Corrupt)?;
    let found: u32 = match digits.bytes().all(|b| b.is_ascii_digit()) {
        true => digits.parse().map_err(|_| RestoreError::Corrupt)?,
        false => return Err(RestoreError::Corrupt),
    };
    if found != version {
        return Err(RestoreError::OldVersion);
    }
    let mut out: [String; N] = std::array::from_fn(|_| String::new());
    for (slot, key) in out.iter_mut().zip(keys) {
        let (k, v) = parts.next().and_then(|p| p.split_once('=')).ok_or(RestoreError::Corrupt)?;
        if k != key {
            return Err(RestoreError::Corrupt);
        }
        *slot = unescape(v).ok_or(RestoreError::Corrupt)?;
    }
    match parts.next() {
        None => Ok(out),
        Some(_) => Err(RestoreError::Corrupt),
    }
}

/// `0`/`1` in a record.
pub(crate) fn flag(b: bool) -> &'static str {
    if b { "1" } else { "0" }
}

pub(crate) fn read_flag(s: &str) -> Result<bool, RestoreError> {
    match s {
        "0" => Ok(false),
        "1" => Ok(true),
        _ => Err(RestoreError::Corrupt),
    }
}

/// The trainer's small state beside the program.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Saved {
    pub cursor: usize,
    pub machine: String,
    /// The program has edits never exported (a sample or an import over it asks first).
    pub unexported: bool,
}

impl Saved {
    const KIND: char = 's';
    /// 1 was the JSON object of the builds before records (with language and projector mode,
    /// now in [`Prefs`]); 2 had no `unexported` (read as unexported: asking once too often
    /// loses nothing).
    const VERSION: u32 = 3;

    #[must_use]
    pub fn to_record(&self) -> String {
        write_record(
            Self::KIND,
            Self::VERSION,
            &[
                ("cursor", &self.cursor.to_string()),
                ("machine", &self.machine),
                ("unexported", flag(self.unexported)),
            ],
        )
    }

    pub fn from_record(text: &str) -> Result<Saved, RestoreError> {
        let (cursor, machine, unexported) =
            match read_record(text, Self::KIND, Self::VERSION, ["cursor", "machine", "unexported"]) {
                Ok([cursor, machine, unexported]) => (cursor, machine, read_flag(&unexported)?),
                Err(RestoreError::OldVersion) => {
                    let [cursor, machine] = read_record(text, Self::KIND, 2, ["cursor", "machine"])?;
                    (cursor, machine, true)
                }
                Err(e) => return Err(e),
            };
        // `usize::from_str` takes a leading '+'; a record never has one.
        if !cursor.bytes().all(|b| b.is_ascii_digit()) {
            return Err(RestoreError::Corrupt);
        }
        Ok(Saved { cursor: cursor.parse().map_err(|_| RestoreError::Corrupt)?, machine, unexported })
    }
}

impl RestoreError {
    /// The trainer's message for a small state it could not use.
    #[must_use]
    pub fn message(self) -> Text {
        match self {
            RestoreError::Corrupt => Text::new(
                "Gespeicherter Zustand war beschädigt: Cursor und Maschine zurückgesetzt, Programm behalten",
                "The saved state was corrupt: cursor and machine reset, program kept",
            ),
            RestoreError::OldVersion => Text::new(
                "Gespeicherter Zustand stammt von einer älteren Version: Cursor und Maschine zurückgesetzt, Programm behalten",
                "The saved state is from an older version: cursor and machine reset, program kept",
            ),
        }
    }
}

/// What both pages share: the language and the classroom projector (the trainer's projector
/// mode is the course's instructor view), saved once.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Prefs {
    pub lang: Lang,
    pub classroom: bool,
}

/// Why saved preferences were not used.
pub const PREFS_UNREADABLE: Text = Text::new(
    "Gespeicherte Einstellungen (Sprache, Projektor) waren unlesbar und wurden zurückgesetzt",
    "The saved settings (language, projector) could not be read and were reset",
);

impl Prefs {
    const KIND: char = 'p';
    const VERSION: u32 = 1;

    #[must_use]
    pub fn to_record(&self) -> String {
        write_record(
            Self::KIND,
            Self::VERSION,
            &[("lang", self.lang.code()), ("classroom", flag(self.classroom))],
        )
    }

    pub fn from_record(text: &str) -> Result<Prefs, RestoreError> {
        let [lang, classroom] = read_record(text, Self::KIND, Self::VERSION, ["lang", "classroom"])?;
        let lang = match lang.as_str() {
            "de" => Lang::De,
            "en" => Lang::En,
            _ => return Err(RestoreError::Corrupt),
        };
        Ok(Prefs { lang, classroom: read_flag(&classroom)? })
    }

    /// A first visit's preferences: the browser's language (`navigator.language`, e.g. `de-AT`,
    /// `en-US`) where it is German or another language (English then), no projector.
    #[must_use]
    pub fn first_visit(browser_language: &str) -> Prefs {
        let german = browser_language.get(..2).is_some_and(|p| p.eq_ignore_ascii_case("de"));
        Prefs { lang: if german { Lang::De } else { Lang::En }, classroom: false }
    }

    /// The preferences at start-up and, when the saved ones could not be used, why.
    #[must_use]
    pub fn load(saved: Option<&str>) -> (Prefs, Option<Text>) {
        match saved.map(Prefs::from_record) {
            None => (Prefs::default(), None),
            Some(Ok(p)) => (p, None),
            Some(Err(_)) => (Prefs::default(), Some(PREFS_UNREADABLE)),
        }
    }
}

/// What a share link carries.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Shared {
    pub program: String,
    pub block: usize,
    pub machine: Option<String>,
    /// An own machine's record ([`crate::saved_machines::to_record`]): the link carries the
    /// whole machine, since the receiver does not have it.
    pub own_machine: Option<String>,
    /// Open in program run at `block` (the instructor's "look at this moment").
    pub run: bool,
    /// The sender's own tool table (a `TOOL.T` text): the receiver's run uses it.
    pub tools: Option<String>,
}

/// The URL fragment (without `#`) of a share link.
#[must_use]
pub fn share_fragment(shared: &Shared) -> String {
    let mut out = format!("pgm={}&block={}", percent_encode(&shared.program), shared.block);
    if let Some(m) = &shared.machine {
        out.push_str("&machine=");
        out.push_str(&percent_encode(m));
    }
    if let Some(record) = &shared.own_machine {
        out.push_str("&mdef=");
        out.push_str(&percent_encode(record));
    }
    if shared.run {
        out.push_str("&run=1");
    }
    if let Some(t) = &shared.tools {
        out.push_str("&tools=");
        out.push_str(&percent_encode(t));
    }
    out
}

/// Reads a share link's fragment (with or without `#`); `None` if it carries no program.
#[must_use]
pub fn parse_fragment(fragment: &str) -> Option<Shared> {
    let mut shared = Shared {
        program: String::new(),
        block: 0,
        machine: None,
        own_machine: None,
        run: false,
        tools: None,
    };
    let mut has_program = false;
    for pair in fragment.trim_start_matches('#').split('&') {
        let (key, value) = pair.split_once('=')?;
        match key {
            "pgm" => {
                shared.program = percent_decode(value)?;
                has_program = true;
            }
            "block" => shared.block = value.parse().ok()?,
            "machine" => shared.machine = Some(percent_decode(value)?),
            "mdef" => shared.own_machine = Some(percent_decode(value)?),
            "run" => shared.run = value == "1",
            "tools" => shared.tools = Some(percent_decode(value)?),
            _ => {}
        }
    }
    has_program.then_some(shared)
}

/// Percent-encodes everything but the unreserved characters of RFC 3986.
pub fn percent_encode(s: &str) -> String {
    let mut out = String::with_capacity(s.len() * 3 / 2);
    for b in s.bytes() {
        if b.is_ascii_alphanumeric() || b"-_.~".contains(&b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// A URL component back from [`percent_encode`] (`+` read as a blank); `None` when malformed.
pub fn percent_decode(s: &str) -> Option<String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' => {
                let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
                out.push(u8::from_str_radix(hex, 16).ok()?);
                i += 3;
            }
            b'+' => {
                out.push(b' ');
                i += 1;
            }
            b => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_round_trip_with_any_machine_id() {
        for machine in ["ac-table", "a;b=c%", "Ä 45° \u{1F600}", "", "tab\tnew\nline+%41"] {
            for unexported in [false, true] {
                let s = Saved { cursor: 12, machine: machine.into(), unexported };
                assert_eq!(Saved::from_record(&s.to_record()), Ok(s), "{machine}");
            }
        }
        assert_eq!(
            Saved { cursor: 7, machine: "ac-table".into(), unexported: true }.to_record(),
            "s3;cursor=7;machine=ac-table;unexported=1"
        );
        // The record before the undo history is read, its program taken as unexported.
        assert_eq!(
            Saved::from_record("s2;cursor=7;machine=ac-table"),
            Ok(Saved { cursor: 7, machine: "ac-table".into(), unexported: true })
        );
        for p in [Prefs::default(), Prefs { lang: Lang::En, classroom: true }] {
            assert_eq!(Prefs::from_record(&p.to_record()), Ok(p));
        }
        assert_eq!(Prefs { lang: Lang::En, classroom: true }.to_record(), "p1;lang=en;classroom=1");
    }

    #[test]
    fn old_and_corrupt_records_are_told_apart() {
        // The JSON of the builds before records, and another version of the same kind: old.
        for old in [
            r#"{"version":1,"cursor":10,"machine":"ac-table","lang":"De","projector":true}"#,
            "{kaputt",
            "s1;cursor=1;machine=x",
            "s4;cursor=1;machine=x;more=1",
        ] {
            assert_eq!(Saved::from_record(old), Err(RestoreError::OldVersion), "{old}");
        }
        for bad in [
            "",
            "s2",
            "s2;cursor=1",
            "s2;cursor=+1;machine=x",
            "s2;cursor=-1;machine=x",
            "s2;cursor=99999999999999999999999;machine=x",
            "s2;machine=x;cursor=1",
            "s2;cursor=1;machine=x;extra=1",
            "s2;cursor=1;machine=%ZZ",
            "s3;cursor=1;machine=x",
            "s3;cursor=1;machine=x;unexported=2",
            "s2x;cursor=1;machine=x",
            "p1;lang=de;classroom=0",
            "x",
        ] {
            assert_eq!(Saved::from_record(bad), Err(RestoreError::Corrupt), "{bad}");
        }
        for bad in ["p1;lang=fr;classroom=0", "p1;lang=de;classroom=2", "p1;lang=de"] {
            assert_eq!(Prefs::from_record(bad), Err(RestoreError::Corrupt), "{bad}");
        }
        assert_eq!(Prefs::load(Some("p1;lang=xx;classroom=0")), (Prefs::default(), Some(PREFS_UNREADABLE)));
        assert_eq!(Prefs::load(None), (Prefs::default(), None));
        for (browser, lang) in [
            ("de", Lang::De),
            ("de-AT", Lang::De),
            ("DE-ch", Lang::De),
            ("en-US", Lang::En),
            ("fr", Lang::En),
            ("", Lang::En),
            ("d", Lang::En),
        ] {
            assert_eq!(Prefs::first_visit(browser), Prefs { lang, classroom: false }, "{browser}");
        }
        let huge = format!("s2;cursor=1;machine={}", "x".repeat(1_000_000));
        assert_eq!(Saved::from_record(&huge).map(|s| s.machine.len()), Ok(1_000_000));
    }

    #[test]
    fn share_fragment_round_trips_umlauts_blanks_and_symbols() {
        let s = Shared {
            program: "0 BEGIN PGM Ä MM\n1 L X+1 ; a&b=c%\n".into(),
            block: 7,
            machine: Some("ac-table".into()),
            own_machine: None,
            run: true,
            tools: Some("BEGIN TOOL .T MM\nT L R\n1 +1 +1\n".into()),
        };
        let f = share_fragment(&s);
        assert!(!f.contains('\n') && !f.contains(' ') && f.matches('&').count() == 4, "{f}");
        assert_eq!(parse_fragment(&format!("#{f}")), Some(s));
    }

    #[test]
    fn broken_fragments_are_ignored() {
        assert_eq!(parse_fragment(""), None);
        assert_eq!(parse_fragment("#block=3"), None);
        assert_eq!(parse_fragment("#pgm=%ZZ"), None);
        assert_eq!(parse_fragment("#pgm=abc&block=x"), None);
    }
}
