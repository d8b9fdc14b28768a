//! What the solver returns: the candidates, the rule that decided, the control's error and
//! the texts the "why" panel shows for them.

use glam::DMat3;
use serde::Serialize;

use super::words::{axis_word, fmt_deg, selection_word, sign_char};
use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::Limits;
use crate::orientation;
use crate::plane::{RotaryAxis, Selection, Sign, TransformMode};
use crate::unconfirmed::{self, Decision};

/// What the solver needs besides the orientation: where the axes stand and what the block asks.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SolveOptions {
    /// Current rotary axis positions; a missing axis stands at 0°.
    pub start: AxisValues,
    /// Limit overrides for this call (the seed's "−90 < A < +10"); the last one per axis wins.
    pub limits: Vec<(RotaryAxis, Limits)>,
    /// `SEQ±`/`SYM±`; `solve_block` takes the block's own if it has one.
    pub selection: Option<Selection>,
    /// `COORD ROT`/`TABLE ROT`; `solve_block` takes the block's own if it has one.
    pub transform: Option<TransformMode>,
}

/// An axis value outside its limit switches.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LimitViolation {
    pub axis: RotaryAxis,
    pub value: f64,
    pub min: f64,
    pub max: f64,
}

/// Why a candidate was not taken.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "why", rename_all = "snake_case")]
pub enum Exclusion {
    /// Outside the limit switches.
    OutOfLimits(LimitViolation),
    /// On the wrong side for `SEQ±`/`SYM±`.
    WrongSide { selection: Selection },
    /// The other candidate has the shorter path.
    LongerPath { path: f64, chosen_path: f64 },
    /// Equal path; the tie rule ([`unconfirmed::tie_prefers`]) preferred the other.
    LostTie { path: f64 },
}

/// One way the machine can reach the orientation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Candidate {
    /// The axis values as the control would position them.
    pub axes: AxisValues,
    /// Master and slave values (the same numbers as in `axes`).
    pub master: f64,
    pub slave: f64,
    /// Inside every limit switch.
    pub in_limits: bool,
    /// The first limit it violates.
    pub violation: Option<LimitViolation>,
    /// Path from the start positions ([`unconfirmed::path_length`]).
    pub path: f64,
    /// Rotation γ about the tool axis still to be done mathematically, degrees.
    pub residual: f64,
    /// Why it was not taken (None for the chosen one, or when an error left none chosen).
    pub excluded: Option<Exclusion>,
}

/// What the inverse kinematics found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum KinematicCase {
    /// Two solutions, mirror images about the symmetry point.
    Two,
    /// One solution (edge of the reachable range).
    One,
    /// Tool axis parallel to the slave axis: the slave is free (DOMAIN.md §3.4).
    SlaveFree,
    /// The tool axis cannot be reached.
    Unreachable,
    /// PLANE AXIAL: axis values programmed directly.
    Axial,
    /// PLANE RESET.
    Reset,
}

/// The rule that decided.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "rule", rename_all = "snake_case")]
pub enum Rule {
    /// PLANE AXIAL: no choice to make.
    Axial,
    /// PLANE RESET: back to the home position.
    Reset,
    /// Only one solution exists (or the slave axis is free).
    Unique { free: Option<RotaryAxis> },
    /// `SEQ±`: the master's sign relative to its home 0°.
    Seq { sign: Sign, master: RotaryAxis },
    /// `SEQ±` with both solutions on that side: the nearer one.
    SeqNearer { sign: Sign, master: RotaryAxis },
    /// `SYM±`: the master's side relative to its symmetry point.
    Sym { sign: Sign, master: RotaryAxis, symmetry_point: f64 },
    /// No selection; only one solution inside the limits.
    OnlyInLimits,
    /// No selection; the shorter path from the current positions.
    ShortestPath,
    /// No selection; equal paths, the tie rule decided.
    Tie { master: RotaryAxis },
    /// No selection; no solution inside the limits.
    NoneInLimits,
    /// The kinematics cannot reach the tool axis.
    Unreachable,
}

impl Rule {
    /// The text for the trainee.
    #[must_use]
    pub fn text(&self) -> Text {
        let t = Text::owned;
        let pm = |sign: Sign, de: [&'static str; 2], en: [&'static str; 2]| match sign {
            Sign::Plus => (de[0], en[0]),
            Sign::Minus => (de[1], en[1]),
        };
        match *self {
            Rule::Axial => Text::new(
                "PLANE AXIAL: Achswinkel direkt programmiert, keine Auswahl nötig",
                "PLANE AXIAL: axis angles programmed directly, nothing to choose",
            ),
            Rule::Reset => Text::new(
                "PLANE RESET: Drehachsen zurück in die Grundstellung",
                "PLANE RESET: rotary axes back to the home position",
            ),
            Rule::Unique { free: None } => Text::new("Nur eine Lösung möglich", "Only one solution exists"),
            Rule::Unique { free: Some(a) } => t(
                format!("Nur eine Lösung: Werkzeugachse parallel zur Achse {a}, {a} ist frei"),
                format!("Only one solution: tool axis parallel to axis {a}, {a} is free"),
            ),
            Rule::Seq { sign, master } => {
                let (de, en) = pm(sign, ["positiv", "negativ"], ["positive", "negative"]);
                let s = sign_char(sign);
                t(
                    format!(
                        "SEQ{s}: Master-Achse {master} muss {de} sein (bezogen auf die Grundstellung 0°)"
                    ),
                    format!("SEQ{s}: master axis {master} must be {en} (relative to its home position 0°)"),
                )
            }
            Rule::SeqNearer { sign, master } => {
                let (de, en) = pm(sign, ["positiv", "negativ"], ["positive", "negative"]);
                let s = sign_char(sign);
                t(
                    format!("SEQ{s}: beide Lösungen haben {master} {de}, die Steuerung nimmt die nähere"),
                    format!("SEQ{s}: both solutions have {master} {en}, the control takes the nearer one"),
                )
            }
            Rule::Sym { sign, master, symmetry_point } => {
                let (de, en) = pm(sign, ["positiven", "negativen"], ["positive", "negative"]);
                let (s, p) = (sign_char(sign), axis_word(master, symmetry_point));
                t(
                    format!("SYM{s}: Master-Achse {master} im {de} Halbraum ab dem Symmetriepunkt {p}"),
                    format!(
                        "SYM{s}: master axis {master} in the {en} half-space from the symmetry point {p}"
                    ),
                )
            }
            Rule::OnlyInLimits => Text::new(
                "Nur eine Lösung liegt im Verfahrbereich",
                "Only one solution lies inside the traverse range",
            ),
            Rule::ShortestPath => Text::new(
                "Kürzester Weg von der aktuellen Position der Drehachsen",
                "Shortest path from the current rotary axis positions",
            ),
            Rule::Tie { master } => t(
                format!("Beide Wege gleich lang: Lösung mit {master} positiver (Annahme, nicht bestätigt)"),
                format!("Equal paths: the solution with the larger {master} (assumption, unconfirmed)"),
            ),
            Rule::NoneInLimits => {
                Text::new("Keine Lösung im Verfahrbereich", "No solution inside the traverse range")
            }
            Rule::Unreachable => Text::new(
                "Diese Werkzeugachse ist mit der Kinematik nicht erreichbar",
                "This tool axis cannot be reached with this kinematics",
            ),
        }
    }
}

/// Why no axis position was chosen. Every variant carries the numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum SolveError {
    /// The selected (or only) solution lies outside a limit switch.
    AxisOutOfLimit { axis: RotaryAxis, value: f64, min: f64, max: f64 },
    /// `SEQ±`/`SYM±` asks for a side no solution is on; `values` = the master values found.
    NoSolutionOnSide { selection: Selection, master: RotaryAxis, values: [f64; 2] },
    /// No solution inside the limits (each candidate carries its violation).
    NoSolutionInLimits { candidates: usize },
    /// The kinematics cannot reach the tool axis.
    Unreachable { tool_axis: [f64; 3] },
    /// A NaN or infinite orientation, start position or limit.
    NotFinite { what: &'static str, value: f64 },
}

impl SolveError {
    /// The control's message: "Winkel nicht erlaubt" \[S2\] /
    /// "Entered angle not permitted" [M:TNC7basic-SYM].
    #[must_use]
    pub fn message(&self) -> Text {
        match self {
            SolveError::Unreachable { .. } if unconfirmed::UNREACHABLE_IS_SEPARATE_ERROR => {
                Text::new("Winkel nicht berechenbar", "Angle cannot be calculated")
            }
            SolveError::NotFinite { .. } => Text::new("Ungültiger Zahlenwert", "Invalid number"),
            _ => Text::new("Winkel nicht erlaubt", "Entered angle not permitted"),
        }
    }

    /// The detail with the numbers.
    #[must_use]
    pub fn detail(&self) -> Text {
        let t = Text::owned;
        match *self {
            SolveError::AxisOutOfLimit { axis, value, min, max } => {
                let (v, lo, hi) = (axis_word(axis, value), fmt_deg(min), fmt_deg(max));
                t(
                    format!("{v} außerhalb des Verfahrbereichs {lo} … {hi}"),
                    format!("{v} outside the traverse range {lo} … {hi}"),
                )
            }
            SolveError::NoSolutionOnSide { selection, master, values } => {
                let (sel, v0, v1) =
                    (selection_word(selection), axis_word(master, values[0]), axis_word(master, values[1]));
                t(
                    format!("{sel}: keine Lösung auf dieser Seite ({v0}, {v1})"),
                    format!("{sel}: no solution on that side ({v0}, {v1})"),
                )
            }
            SolveError::NoSolutionInLimits { candidates } => t(
                format!("Keine der {candidates} Lösungen liegt im Verfahrbereich"),
                format!("None of the {candidates} solutions lies inside the traverse range"),
            ),
            SolveError::Unreachable { tool_axis: [x, y, z] } => t(
                format!(
                    "Werkzeugachse {} mit dieser Kinematik nicht erreichbar",
                    crate::number::prose_vec([x, y, z], 4, crate::Lang::De)
                ),
                format!("Tool axis ({x:.4}, {y:.4}, {z:.4}) cannot be reached with this kinematics"),
            ),
            SolveError::NotFinite { what, value } => Text::same(format!("{what} = {value}")),
        }
    }
}

/// A [`Rule`] that serialises as its text, `{"de": …, "en": …}`. The text is only formatted
/// when asked for, which keeps `solve` free of string formatting (benchmark budget).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reason(pub Rule);

impl Serialize for Reason {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.text().serialize(s)
    }
}

/// The control's message for a [`SolveError`], serialised as `{"de": …, "en": …}`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorMessage(pub SolveError);

impl Serialize for ErrorMessage {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.message().serialize(s)
    }
}

/// How the residual rotation about the tool axis is done (DOMAIN.md §3.4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "by", rename_all = "snake_case")]
pub enum Realisation {
    /// In the coordinate system only (COORD ROT, and always outside the singular case).
    Mathematical,
    /// By turning the free table axis (TABLE ROT) to `value`.
    TableAxis { axis: RotaryAxis, value: f64 },
}

/// The rotation about the tool axis left after positioning the rotary axes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Residual {
    /// γ in degrees, done mathematically.
    pub gamma: f64,
    pub realised_by: Realisation,
}

/// Q120–Q122: the computed A, B, C axis angles as the control stores them (DOMAIN.md §4,
/// [M:iTNC-tech-p761]); `None` for an axis the machine does not have.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct QValues {
    #[serde(rename = "Q120")]
    pub q120: Option<f64>,
    #[serde(rename = "Q121")]
    pub q121: Option<f64>,
    #[serde(rename = "Q122")]
    pub q122: Option<f64>,
}

/// Everything the solver did, for the UI ("why the machine does this") and the CLI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Explanation {
    /// Target orientation R, row by row.
    pub orientation: [[f64; 3]; 3],
    pub tool_axis: [f64; 3],
    pub master: RotaryAxis,
    pub slave: RotaryAxis,
    /// Master value where the two solutions mirror (`kinematics::symmetry_point`).
    pub symmetry_point: f64,
    pub case: KinematicCase,
    pub selection: Option<Selection>,
    /// COORD ROT or TABLE ROT as applied (the default when the block has neither).
    pub transform: TransformMode,
    pub start: AxisValues,
    pub candidates: Vec<Candidate>,
    /// Index into `candidates`.
    pub chosen: Option<usize>,
    pub rule: Rule,
    /// `rule` as German and English text (computed when serialised).
    pub reason: Reason,
    pub error: Option<SolveError>,
    /// The control's message for `error`, German and English.
    pub error_message: Option<ErrorMessage>,
    pub residual: Option<Residual>,
    pub q: QValues,
    /// The UNCONFIRMED decisions that influenced this result.
    pub decisions: Vec<Decision>,
    /// R as solved, for [`Self::spatial`] and [`Self::euler`] (`orientation` is its rows,
    /// cleaned for display).
    #[serde(skip)]
    pub(crate) rotation: DMat3,
}

impl Explanation {
    /// The same orientation as `PLANE SPATIAL SPA SPB SPC`: made when the why panel asks, not by
    /// every solve (three of a solve's twelve `atan2`).
    #[must_use]
    pub fn spatial(&self) -> [f64; 3] {
        orientation::to_spatial(&self.rotation)
    }

    /// The same orientation as `PLANE EULER EULPR EULNU EULROT`, on request like [`Self::spatial`].
    #[must_use]
    pub fn euler(&self) -> [f64; 3] {
        orientation::to_euler(&self.rotation)
    }

    /// The chosen axis values, if any.
    #[must_use]
    pub fn chosen_axes(&self) -> Option<AxisValues> {
        self.chosen.and_then(|i| self.candidates.get(i)).map(|c| c.axes)
    }
}
