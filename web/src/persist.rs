//! Keeping the trainee's work: the cursor, machine, language and projector mode as versioned
//! JSON, the program text under a key of its own (so moving the cursor in a 100,000-block
//! program does not rewrite megabytes), and the share link's fragment. Pure; the browser side
//! is in `browser.rs`. A corrupt or old saved state is reported and replaced by the default,
//! never a dead page.

use serde::{Deserialize, Serialize};

use crate::i18n::{Lang, Text};

/// The localStorage keys; the version is inside the state, so an old layout is recognised.
pub const STATE_KEY: &str = "schwenkbar.state";
pub const PROGRAM_KEY: &str = "schwenkbar.program";
pub const VERSION: u32 = 1;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
                "Gespeicherter Zustand war beschädigt: Vorgabe geladen",
                "The saved state was corrupt: defaults loaded",
            ),
            RestoreError::OldVersion => Text::new(
                "Gespeicherter Zustand stammt von einer älteren Version: Vorgabe geladen",
                "The saved state is from an older version: defaults loaded",
            ),
        }
    }
}

/// Reads a saved state.
pub fn restore(json: &str) -> Result<Saved, RestoreError> {
    #[derive(Deserialize)]
    struct Versioned {
        version: u32,
    }
    let v: Versioned = serde_json::from_str(json).map_err(|_| RestoreError::Corrupt)?;
    if v.version != VERSION {
        return Err(RestoreError::OldVersion);
    }
    serde_json::from_str(json).map_err(|_| RestoreError::Corrupt)
}

#[must_use]
pub fn to_json(saved: &Saved) -> String {
    // Serialising plain strings and numbers cannot fail; an empty string would only mean
    // "nothing saved" on the next load.
    serde_json::to_string(saved).unwrap_or_default()
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
