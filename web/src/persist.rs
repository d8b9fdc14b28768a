//! Keeping the trainee's work: the cursor, machine, language and projector mode as versioned
//! JSON, the program text under a key of its own (so moving the cursor in a 100,000-block
//! program does not rewrite megabytes), and the share link's fragment. Pure; the browser side
//! is in `browser.rs`. A corrupt or old saved state is reported and replaced by the default,
//! never a dead page.
//!
//! The state is one flat JSON object, written and read by hand here rather than with
//! serde_json, which cost about 7 KB gzip of the bundle for these five fields. The format is the
//! one serde wrote (`{"version":1,"cursor":7,"machine":"ac-table","lang":"En","projector":false}`),
//! so a state saved by an earlier build still loads.

use crate::i18n::{Lang, Text};

/// The localStorage keys; the version is inside the state, so an old layout is recognised.
pub const STATE_KEY: &str = "schwenkbar.state";
pub const PROGRAM_KEY: &str = "schwenkbar.program";
pub const VERSION: u32 = 1;

#[derive(Debug, Clone, PartialEq)]
pub struct Saved {
    pub version: u32,
    pub cursor: usize,
    pub machine: String,
    pub lang: Lang,
    pub projector: bool,
}

/// Why a saved state could not be used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RestoreError {
    Corrupt,
    OldVersion,
}

impl RestoreError {
    #[must_use]
    pub fn message(self) -> Text {
        match self {
            RestoreError::Corrupt => Text::new(
                "Gespeicherter Zustand war beschädigt: Cursor, Maschine und Sprache zurückgesetzt, Programm behalten",
                "The saved state was corrupt: cursor, machine and language reset, program kept",
            ),
            RestoreError::OldVersion => Text::new(
                "Gespeicherter Zustand stammt von einer älteren Version: Cursor, Maschine und Sprache zurückgesetzt, Programm behalten",
                "The saved state is from an older version: cursor, machine and language reset, program kept",
            ),
        }
    }
}

/// Reads a saved state: any JSON object with a `version` (else `Corrupt`); another version is
/// `OldVersion` whatever else it holds; this version needs every field with the right type
/// (unknown fields are ignored, a field given twice is `Corrupt`).
pub fn restore(json: &str) -> Result<Saved, RestoreError> {
    let mut r = Reader { s: json.as_bytes(), i: 0 };
    let fields = r.object_at_top().ok_or(RestoreError::Corrupt)?;
    let mut found: [Option<&Value>; 5] = [None; 5];
    for (key, value) in &fields {
        let Some(slot) = ["version", "cursor", "machine", "lang", "projector"].iter().position(|k| k == key)
        else {
            continue;
        };
        if found[slot].replace(value).is_some() {
            return Err(RestoreError::Corrupt);
        }
    }
    let [version, cursor, machine, lang, projector] = found;
    let version = match version {
        Some(&Value::Int(v)) => u32::try_from(v).map_err(|_| RestoreError::Corrupt)?,
        _ => return Err(RestoreError::Corrupt),
    };
    if version != VERSION {
        return Err(RestoreError::OldVersion);
    }
    match (cursor, machine, lang, projector) {
        (
            Some(&Value::Int(cursor)),
            Some(Value::Str(machine)),
            Some(Value::Str(lang)),
            Some(&Value::Bool(projector)),
        ) => Ok(Saved {
            version,
            cursor: usize::try_from(cursor).map_err(|_| RestoreError::Corrupt)?,
            machine: machine.clone(),
            lang: match lang.as_str() {
                "De" => Lang::De,
                "En" => Lang::En,
                _ => return Err(RestoreError::Corrupt),
            },
            projector,
        }),
        _ => Err(RestoreError::Corrupt),
    }
}

#[must_use]
pub fn to_json(saved: &Saved) -> String {
    let mut out = format!("{{\"version\":{},\"cursor\":{},\"machine\":\"", saved.version, saved.cursor);
    for c in saved.machine.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push_str(match saved.lang {
        Lang::De => "\",\"lang\":\"De\"",
        Lang::En => "\",\"lang\":\"En\"",
    });
    out.push_str(if saved.projector { ",\"projector\":true}" } else { ",\"projector\":false}" });
    out
}

/// A JSON value as far as the saved state needs it: nested objects and arrays are checked and
/// dropped, numbers other than non-negative integers count as `Other`.
#[derive(Debug, PartialEq)]
enum Value {
    Str(String),
    Int(u64),
    Bool(bool),
    Other,
}

/// A strict JSON reader (RFC 8259) over the saved state's bytes; every method returns `None` on
/// anything that is not JSON.
struct Reader<'a> {
    s: &'a [u8],
    i: usize,
}

impl Reader<'_> {
    /// Nesting deeper than this is refused (as serde_json does), so a hostile state cannot
    /// exhaust the stack.
    const MAX_DEPTH: u32 = 128;

    /// The whole text as one object: its members in order.
    fn object_at_top(&mut self) -> Option<Vec<(String, Value)>> {
        self.expect(b'{')?;
        let fields = self.members(1)?;
        self.skip_ws();
        (self.i == self.s.len()).then_some(fields)
    }

    fn skip_ws(&mut self) {
        while matches!(self.s.get(self.i), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.i += 1;
        }
    }

    /// The next byte after blanks, consumed.
    fn next(&mut self) -> Option<u8> {
        self.skip_ws();
        let b = *self.s.get(self.i)?;
        self.i += 1;
        Some(b)
    }

    fn expect(&mut self, b: u8) -> Option<()> {
        (self.next()? == b).then_some(())
    }

    /// The members of an object whose `{` has been read.
    fn members(&mut self, depth: u32) -> Option<Vec<(String, Value)>> {
        let mut fields = Vec::new();
        self.skip_ws();
        if self.s.get(self.i) == Some(&b'}') {
            self.i += 1;
            return Some(fields);
        }
        loop {
            self.expect(b'"')?;
            let key = self.string()?;
            self.expect(b':')?;
            fields.push((key, self.value(depth)?));
            match self.next()? {
                b',' => {}
                b'}' => return Some(fields),
                _ => return None,
            }
        }
    }

    fn value(&mut self, depth: u32) -> Option<Value> {
        if depth >= Self::MAX_DEPTH {
            return None;
        }
        match self.next()? {
            b'"' => self.string().map(Value::Str),
            b'{' => self.members(depth + 1).map(|_| Value::Other),
            b'[' => {
                self.skip_ws();
                if self.s.get(self.i) == Some(&b']') {
                    self.i += 1;
                    return Some(Value::Other);
                }
                loop {
                    self.value(depth + 1)?;
                    match self.next()? {
                        b',' => {}
                        b']' => return Some(Value::Other),
                        _ => return None,
                    }
                }
            }
            b't' => self.word(b"rue", Value::Bool(true)),
            b'f' => self.word(b"alse", Value::Bool(false)),
            b'n' => self.word(b"ull", Value::Other),
            b'-' | b'0'..=b'9' => {
                self.i -= 1;
                self.number()
            }
            _ => None,
        }
    }

    fn word(&mut self, rest: &[u8], value: Value) -> Option<Value> {
        let end = self.i + rest.len();
        (self.s.get(self.i..end)? == rest).then(|| {
            self.i = end;
            value
        })
    }

    fn digits(&mut self) -> usize {
        let start = self.i;
        while self.s.get(self.i).is_some_and(u8::is_ascii_digit) {
            self.i += 1;
        }
        self.i - start
    }

    /// `-?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?`; a plain non-negative integer that fits
    /// is `Int`.
    fn number(&mut self) -> Option<Value> {
        let negative = self.s.get(self.i) == Some(&b'-');
        self.i += usize::from(negative);
        let start = self.i;
        let n = self.digits();
        if n == 0 || (n > 1 && self.s[start] == b'0') {
            return None;
        }
        let int = std::str::from_utf8(&self.s[start..self.i]).ok()?.parse::<u64>().ok();
        let mut plain = true;
        if self.s.get(self.i) == Some(&b'.') {
            self.i += 1;
            plain = false;
            (self.digits() > 0).then_some(())?;
        }
        if matches!(self.s.get(self.i), Some(b'e' | b'E')) {
            self.i += 1;
            plain = false;
            if matches!(self.s.get(self.i), Some(b'+' | b'-')) {
                self.i += 1;
            }
            (self.digits() > 0).then_some(())?;
        }
        Some(match int {
            Some(v) if plain && !negative => Value::Int(v),
            _ => Value::Other,
        })
    }

    /// The rest of a string whose `"` has been read, unescaped.
    fn string(&mut self) -> Option<String> {
        let mut out = Vec::new();
        loop {
            let b = *self.s.get(self.i)?;
            self.i += 1;
            match b {
                b'"' => return String::from_utf8(out).ok(),
                b'\\' => {
                    let e = *self.s.get(self.i)?;
                    self.i += 1;
                    let c = match e {
                        b'"' | b'\\' | b'/' => char::from(e),
                        b'b' => '\u{8}',
                        b'f' => '\u{c}',
                        b'n' => '\n',
                        b'r' => '\r',
                        b't' => '\t',
                        b'u' => {
                            let hi = self.hex4()?;
                            let code = if (0xD800..0xDC00).contains(&hi) {
                                // A high surrogate must be followed by an escaped low one.
                                self.word(b"\\u", Value::Other)?;
                                let lo = self.hex4()?;
                                if !(0xDC00..0xE000).contains(&lo) {
                                    return None;
                                }
                                0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)
                            } else {
                                hi
                            };
                            char::from_u32(code)?
                        }
                        _ => return None,
                    };
                    out.extend_from_slice(c.encode_utf8(&mut [0; 4]).as_bytes());
                }
                0..0x20 => return None,
                b => out.push(b),
            }
        }
    }

    fn hex4(&mut self) -> Option<u32> {
        let h = std::str::from_utf8(self.s.get(self.i..self.i + 4)?).ok()?;
        self.i += 4;
        // from_str_radix would take a leading '+'.
        h.bytes().all(|b| b.is_ascii_hexdigit()).then_some(())?;
        u32::from_str_radix(h, 16).ok()
    }
}

/// What a share link carries.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Shared {
    pub program: String,
    pub block: usize,
    pub machine: Option<String>,
    /// Open in program run at `block` (the instructor's "look at this moment").
    pub run: bool,
}

/// The URL fragment (without `#`) of a share link.
#[must_use]
pub fn share_fragment(shared: &Shared) -> String {
    let mut out = format!("pgm={}&block={}", percent_encode(&shared.program), shared.block);
    if let Some(m) = &shared.machine {
        out.push_str("&machine=");
        out.push_str(&percent_encode(m));
    }
    if shared.run {
        out.push_str("&run=1");
    }
    out
}

/// Reads a share link's fragment (with or without `#`); `None` if it carries no program.
#[must_use]
pub fn parse_fragment(fragment: &str) -> Option<Shared> {
    let mut shared = Shared { program: String::new(), block: 0, machine: None, run: false };
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
            "run" => shared.run = value == "1",
            _ => {}
        }
    }
    has_program.then_some(shared)
}

/// Percent-encodes everything but the unreserved characters of RFC 3986.
fn percent_encode(s: &str) -> String {
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

fn percent_decode(s: &str) -> Option<String> {
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

    fn saved() -> Saved {
        Saved { version: VERSION, cursor: 1, machine: "ba-table".into(), lang: Lang::En, projector: true }
    }

    #[test]
    fn saved_state_round_trips() {
        assert_eq!(restore(&to_json(&saved())), Ok(saved()));
    }

    #[test]
    fn corrupt_and_old_states_are_recognised() {
        assert_eq!(restore("{\"version\":1,\"cursor\":"), Err(RestoreError::Corrupt));
        assert_eq!(restore("not json at all"), Err(RestoreError::Corrupt));
        assert_eq!(restore("{\"version\":1,\"cursor\":\"x\"}"), Err(RestoreError::Corrupt));
        assert_eq!(restore("{\"version\":0,\"text\":\"x\"}"), Err(RestoreError::OldVersion));
        // Not JSON, or not quite: each is reported, none panics.
        for bad in [
            "",
            "{}",
            "[1]",
            "{\"version\":1}",
            "{\"version\":1.0,\"cursor\":1,\"machine\":\"ac-table\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":-1,\"machine\":\"ac-table\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"ac-table\",\"lang\":\"Fr\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"ac-table\",\"lang\":\"De\",\"projector\":1}",
            "{\"version\":1,\"cursor\":1,\"cursor\":2,\"machine\":\"a\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"a\",\"lang\":\"De\",\"projector\":true} x",
            "{\"version\":1,\"cursor\":01,\"machine\":\"a\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"a\\ud800\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"a\\x\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,\"machine\":\"a\nb\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":1,\"cursor\":1,,\"machine\":\"a\",\"lang\":\"De\",\"projector\":true}",
            "{\"version\":99999999999,\"cursor\":1}",
            "{\"version\":tru}",
        ] {
            assert_eq!(restore(bad), Err(RestoreError::Corrupt), "{bad}");
        }
        let deep = format!("{{\"version\":1,\"x\":{}{}}}", "[".repeat(100_000), "]".repeat(100_000));
        assert_eq!(
            restore(&deep),
            Err(RestoreError::Corrupt),
            "deep nesting is refused, not a stack overflow"
        );
        // An older layout with anything in it is old, not corrupt.
        assert_eq!(
            restore("{\"text\":\"1 L\",\"version\":0,\"view\":{\"zoom\":1.5e0,\"axes\":[true,null,-2]}}"),
            Err(RestoreError::OldVersion)
        );
    }

    #[test]
    fn the_format_is_the_one_serde_json_wrote() {
        // A state saved by the builds that used serde_json loads, and is written the same way.
        let old = "{\"version\":1,\"cursor\":1,\"machine\":\"ba-table\",\"lang\":\"En\",\"projector\":true}";
        assert_eq!(to_json(&saved()), old);
        assert_eq!(restore(old), Ok(saved()));
        let spaced = " {\r\n \"projector\" : true , \"lang\":\"En\", \"extra\": {\"a\": [1, 2.5, \"x\"]},\n\t\"machine\":\"ba-table\", \"cursor\":1,\"version\":1 } ";
        assert_eq!(restore(spaced), Ok(saved()));
    }

    #[test]
    fn machine_ids_with_quotes_escapes_and_non_ascii_round_trip() {
        for machine in ["a\"b\\c", "tab\there\u{1}", "Ä 45° \u{1F600}"] {
            let s = Saved { machine: machine.into(), ..saved() };
            assert_eq!(restore(&to_json(&s)), Ok(s), "{machine}");
        }
        let escaped = "{\"version\":1,\"cursor\":0,\"machine\":\"\\u00c4\\/\\ud83d\\ude00\\n\",\"lang\":\"De\",\"projector\":false}";
        assert_eq!(restore(escaped).map(|s| s.machine), Ok("Ä/\u{1F600}\n".to_string()));
    }

    #[test]
    fn share_fragment_round_trips_umlauts_blanks_and_symbols() {
        let s = Shared {
            program: "0 BEGIN PGM Ä MM\n1 L X+1 ; a&b=c%\n".into(),
            block: 7,
            machine: Some("ac-table".into()),
            run: true,
        };
        let f = share_fragment(&s);
        assert!(!f.contains('\n') && !f.contains(' ') && f.matches('&').count() == 3, "{f}");
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
