//! The words of a PLANE block with their input ranges: one table ([`Word::range`]) and one
//! check ([`check`]) for the parser and the softkey dialog.

use serde::{Deserialize, Serialize};

use crate::diag::DiagCode;

/// Input range of a PLANE word and whether it is an angle (out of range: "Winkel nicht
/// erlaubt") or another value. One table for the parser and the softkey dialog.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputRange {
    pub min: f64,
    pub max: f64,
    pub angle: bool,
}

impl InputRange {
    /// Values are checked as written; a tolerance keeps `359.9999` itself inside.
    const EPS: f64 = 1e-9;

    #[must_use]
    pub fn contains(&self, x: f64) -> bool {
        x >= self.min - Self::EPS && x <= self.max + Self::EPS
    }
}

/// Input range of a spatial angle SPA/SPB/SPC on the iTNC 530 (DOMAIN.md §5, [M:iTNC-p494]);
/// PLANE RELATIV uses it too (UNCONFIRMED, DOMAIN.md §5 "probably ±359.9999").
pub const SPATIAL_LIMIT: f64 = 359.9999;
/// Input range of PROPR/PROMIN (DOMAIN.md §5, [M:iTNC-p496]).
pub const PROJECTED_LIMIT: f64 = 89.9999;
/// Feed rates: 0 to 99 999.999 mm/min (TNC 426/430 user's manual, "Technical Information",
/// input format of TNC functions, easymanua.ls/heidenhain/tnc-430/manual?p=494). A feed is
/// never negative.
pub const FEED_LIMIT: f64 = 99_999.999;

/// A word of the PLANE dialog that takes a number: the angles and components of the eight
/// functions (`IA`/`IB`/`IC` of AXIAL are [`Word::A`]…[`Word::C`] written incrementally) and
/// the positioning words `DIST`, `MB`, `F`. The parser and the dialog check a value with
/// [`check`], against the one table [`Word::range`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Word {
    Spa,
    Spb,
    Spc,
    Propr,
    Promin,
    Rot,
    Eulpr,
    Eulnu,
    Eulrot,
    Bx,
    By,
    Bz,
    Nx,
    Ny,
    Nz,
    P1x,
    P1y,
    P1z,
    P2x,
    P2y,
    P2z,
    P3x,
    P3y,
    P3z,
    A,
    B,
    C,
    /// MOVE: distance centre of rotation – tool tip.
    Dist,
    /// TURN: retract along the tool axis.
    Mb,
    /// The feed of the swivel.
    F,
}

impl Word {
    /// Every word, in the order of the PLANE functions and then MOVE/TURN.
    pub const ALL: [Word; 30] = [
        Word::Spa,
        Word::Spb,
        Word::Spc,
        Word::Propr,
        Word::Promin,
        Word::Rot,
        Word::Eulpr,
        Word::Eulnu,
        Word::Eulrot,
        Word::Bx,
        Word::By,
        Word::Bz,
        Word::Nx,
        Word::Ny,
        Word::Nz,
        Word::P1x,
        Word::P1y,
        Word::P1z,
        Word::P2x,
        Word::P2y,
        Word::P2z,
        Word::P3x,
        Word::P3y,
        Word::P3z,
        Word::A,
        Word::B,
        Word::C,
        Word::Dist,
        Word::Mb,
        Word::F,
    ];

    /// The NC word as written (`SPA`, `P2X`, `DIST`).
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Word::Spa => "SPA",
            Word::Spb => "SPB",
            Word::Spc => "SPC",
            Word::Propr => "PROPR",
            Word::Promin => "PROMIN",
            Word::Rot => "ROT",
            Word::Eulpr => "EULPR",
            Word::Eulnu => "EULNU",
            Word::Eulrot => "EULROT",
            Word::Bx => "BX",
            Word::By => "BY",
            Word::Bz => "BZ",
            Word::Nx => "NX",
            Word::Ny => "NY",
            Word::Nz => "NZ",
            Word::P1x => "P1X",
            Word::P1y => "P1Y",
            Word::P1z => "P1Z",
            Word::P2x => "P2X",
            Word::P2y => "P2Y",
            Word::P2z => "P2Z",
            Word::P3x => "P3X",
            Word::P3y => "P3Y",
            Word::P3z => "P3Z",
            Word::A => "A",
            Word::B => "B",
            Word::C => "C",
            Word::Dist => "DIST",
            Word::Mb => "MB",
            Word::F => "F",
        }
    }

    /// The word written `text` (`"SPA"` → [`Word::Spa`]); `None` for anything else.
    #[must_use]
    pub fn from_name(text: &str) -> Option<Word> {
        Word::ALL.into_iter().find(|w| w.as_str() == text)
    }

    /// Its input range (DOMAIN.md §5, iTNC 530 manual figures; the UNCONFIRMED ones are named in
    /// [`crate::unconfirmed`]). The one table for the parser, the orientation maths and the
    /// dialog.
    #[must_use]
    pub fn range(self) -> InputRange {
        use crate::unconfirmed::{
            AXIAL_LIMIT, EULPR_LIMIT, POINTS_COORD_LIMIT, POSITIONING_LENGTH_LIMIT, VECTOR_COMPONENT_LIMIT,
        };
        let r = |min, max, angle| InputRange { min, max, angle };
        match self {
            Word::Spa | Word::Spb | Word::Spc => r(-SPATIAL_LIMIT, SPATIAL_LIMIT, true),
            Word::Propr | Word::Promin => r(-PROJECTED_LIMIT, PROJECTED_LIMIT, true),
            Word::Rot | Word::Eulrot => r(0.0, 360.0, true),
            Word::Eulpr => r(-EULPR_LIMIT, EULPR_LIMIT, true),
            Word::Eulnu => r(0.0, 180.0, true),
            Word::Bx | Word::By | Word::Bz | Word::Nx | Word::Ny | Word::Nz => {
                r(-VECTOR_COMPONENT_LIMIT, VECTOR_COMPONENT_LIMIT, false)
            }
            Word::P1x
            | Word::P1y
            | Word::P1z
            | Word::P2x
            | Word::P2y
            | Word::P2z
            | Word::P3x
            | Word::P3y
            | Word::P3z => r(-POINTS_COORD_LIMIT, POINTS_COORD_LIMIT, false),
            Word::A | Word::B | Word::C => r(-AXIAL_LIMIT, AXIAL_LIMIT, true),
            // A distance and a retract length: not negative (see POSITIONING_LENGTH_LIMIT).
            Word::Dist | Word::Mb => r(0.0, POSITIONING_LENGTH_LIMIT, false),
            Word::F => r(0.0, FEED_LIMIT, false),
        }
    }
}

impl std::fmt::Display for Word {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Checks a number typed or written for `word` against its input range: the one check of the
/// parser and the PLANE dialog. `Err` is the diagnostic the parser reports (the dialog shows
/// its message): [`DiagCode::AngleNotPermitted`] for an angle ("Winkel nicht erlaubt"),
/// [`DiagCode::ValueOutOfRange`] for any other value (a negative `DIST`, `MB` or `F` too),
/// [`DiagCode::InvalidInput`] for NaN or ±∞.
///
/// # Errors
/// The value is not finite or outside [`Word::range`].
pub fn check(word: Word, value: f64) -> Result<(), DiagCode> {
    if !value.is_finite() {
        return Err(DiagCode::InvalidInput);
    }
    let r = word.range();
    if r.contains(value) {
        return Ok(());
    }
    let (word, min, max) = (word.as_str(), r.min, r.max);
    Err(if r.angle {
        DiagCode::AngleNotPermitted { word, value, min, max }
    } else {
        DiagCode::ValueOutOfRange { word, value, min, max }
    })
}

/// The input range of the word written `word` (see [`Word::range`]); `None` for a word without
/// one.
#[must_use]
pub fn input_range(word: &str) -> Option<InputRange> {
    Word::from_name(word).map(Word::range)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::{PlaneTextError, plane_block};

    #[test]
    fn one_check_for_parser_and_dialog() {
        assert_eq!(check(Word::Spb, 45.0), Ok(()));
        assert!(matches!(check(Word::Eulpr, 270.0), Err(DiagCode::AngleNotPermitted { word: "EULPR", .. })));
        for word in [Word::Dist, Word::Mb, Word::F] {
            assert_eq!(check(word, 0.0), Ok(()));
            assert!(matches!(check(word, -5.0), Err(DiagCode::ValueOutOfRange { min: 0.0, .. })), "{word}");
        }
        assert_eq!(check(Word::F, f64::NAN), Err(DiagCode::InvalidInput));
        for w in Word::ALL {
            assert_eq!(Word::from_name(w.as_str()), Some(w));
            assert_eq!(input_range(w.as_str()), Some(w.range()));
        }
        assert_eq!(input_range("X"), None);
    }

    #[test]
    fn the_parser_refuses_a_negative_dist_mb_or_feed_with_the_checks_diagnostic() {
        for (text, word) in [
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE DIST-5 F500", "DIST-5"),
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB-5 FMAX", "MB-5"),
            ("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE F-3", "F-3"),
        ] {
            let Err(PlaneTextError::Invalid(d)) = plane_block(text) else { panic!("{text} accepted") };
            assert!(matches!(d.code, DiagCode::ValueOutOfRange { .. }), "{text}: {:?}", d.code);
            assert_eq!(&text[d.span.start..d.span.end], word);
        }
        assert!(plane_block("PLANE SPATIAL SPA+0 SPB+45 SPC+0 MOVE DIST+5 F500").is_ok());
    }

    #[test]
    fn plane_block_wants_exactly_one_plane() {
        assert_eq!(plane_block("L X+0"), Err(PlaneTextError::NoPlane));
        let two = "1 PLANE RESET STAY\n2 PLANE RESET STAY";
        assert_eq!(plane_block(two), Err(PlaneTextError::SeveralPlanes));
        let b = plane_block("PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 TURN FMAX").expect("one block");
        assert_eq!(b.numbers(), Err(1));
    }
}
