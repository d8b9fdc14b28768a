//! The PLANE softkey dialog, as on the control (DOMAIN.md §7, seed S0 §2.3): after
//! SPEC FCT → BEARB.-EBENE SCHWENKEN → function, the dialog line asks for each value in the
//! control's order, then the positioning behaviour and its values, then the optional SEQ/SYM and
//! COORD ROT/TABLE ROT. Pure: the reducer owns a `Dialog` and feeds it keys.
//!
//! Values are checked with the core's own rules (`plane::input_range`, `parse::parse_value`), so
//! the dialog and the parser can never disagree about what is allowed.

use schwenkbar_core::diag::DiagCode;
use schwenkbar_core::format::plane_text;
use schwenkbar_core::parse::parse_value;
use schwenkbar_core::plane::{
    self, Feed, MoveBack, PlaneKind, RelAxis, Selection, Sign, TransformMode, Value, Word,
};
use schwenkbar_core::unconfirmed::Decision;

use crate::i18n::Text;

mod block;
mod fields;
#[cfg(test)]
mod tests;

pub use fields::Field;
use fields::{AXIAL, EULER, POINTS, PROJECTED, RELATIV, SPATIAL, VECTOR, t};

/// The values a PLANE function asks before the positioning behaviour, in the control's order
/// (the prompts of [`PlaneKind::words`]; RELATIV's one angle is written with the chosen axis).
#[must_use]
pub fn fields(function: PlaneKind) -> &'static [Field] {
    match function {
        PlaneKind::Spatial => &SPATIAL,
        PlaneKind::Projected => &PROJECTED,
        PlaneKind::Euler => &EULER,
        PlaneKind::Vector => &VECTOR,
        PlaneKind::Points => &POINTS,
        PlaneKind::Relativ => &RELATIV,
        PlaneKind::Axial => &AXIAL,
        PlaneKind::Reset => &[],
    }
}

/// SEQ/SYM and COORD ROT/TABLE ROT: not for AXIAL (unambiguous, DOMAIN.md §2.7) nor RESET.
#[must_use]
pub fn has_solution_options(function: PlaneKind) -> bool {
    !matches!(function, PlaneKind::Axial | PlaneKind::Reset)
}

/// Where the dialog stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    /// RELATIV: which spatial angle (softkeys SPA/SPB/SPC).
    RelAxis,
    /// The function's value `i`.
    Value(usize),
    /// Softkeys MOVE / TURN / STAY.
    Positioning,
    /// MOVE: `DIST`.
    Dist,
    /// TURN: `MB` (softkey MB MAX).
    MoveBack,
    /// MOVE/TURN: `F` (softkeys F AUTO, FMAX).
    Feed,
    /// Softkeys SEQ+ SEQ− SYM+ SYM−, NO ENT skips.
    Selection,
    /// Softkeys COORD ROT / TABLE ROT, NO ENT skips.
    Transform,
}

/// The positioning behaviour chosen by softkey, before its values are known.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PosKind {
    Move,
    Turn,
    Stay,
}

/// A key of the control's keyboard (or the physical keyboard mapped onto it).
#[derive(Debug, Clone, PartialEq)]
pub enum Key {
    /// A character typed into the value: digits, `.`, `-`, `+`, `Q`, letters (refused at ENT).
    Char(char),
    Backspace,
    /// `-/+`: toggles the sign of the value being typed.
    ToggleSign,
    Ent,
    NoEnt,
    End,
    RelAxis(RelAxis),
    Positioning(PosKind),
    /// `MB MAX` at the MB prompt.
    MbMax,
    FAuto,
    FMax,
    Selection(Selection),
    Transform(TransformMode),
}

/// What a key press did.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The dialog goes on (maybe with a message).
    Continue,
    /// The block is complete: its text (without block number).
    Finished(String),
}

/// A message in the dialog line; the value stays for correction.
pub type Message = Text;

#[derive(Debug, Clone, PartialEq)]
pub struct Dialog {
    pub function: PlaneKind,
    pub step: Step,
    /// What is being typed at the current prompt.
    pub input: String,
    pub rel_axis: RelAxis,
    /// Entered values of [`fields`]`(function)`, `None` = skipped with NO ENT (optional ones only).
    pub values: Vec<Option<Value>>,
    /// PLANE AXIAL: which of A, B, C is incremental (`IA…`, typed with a leading `I`).
    pub incremental: [bool; 3],
    pub positioning: Option<PosKind>,
    pub dist: Option<Value>,
    pub move_back: Option<MoveBack>,
    pub feed: Option<Feed>,
    pub selection: Option<Selection>,
    pub transform: Option<TransformMode>,
    pub message: Option<Message>,
}

const MSG_INVALID: Text =
    t("Eingabewert falsch: Zahl oder Q-Parameter erwartet", "Invalid input: a number or Q parameter");
const MSG_REQUIRED: Text = t("Eingabe erforderlich", "Entry required");
const MSG_CHOOSE_POS: Text =
    t("Positionierverhalten wählen: MOVE, TURN oder STAY", "Select positioning: MOVE, TURN or STAY");
const MSG_AXIAL_EMPTY: Text = t("Mindestens einen Achswinkel eingeben", "Enter at least one axis angle");
const MSG_SEQ_SYM: Text = t("SEQ und SYM schließen sich aus", "SEQ and SYM exclude each other");

impl Dialog {
    /// Opens the dialog for `function` (the function softkey).
    #[must_use]
    pub fn new(function: PlaneKind) -> Dialog {
        let step = match function {
            PlaneKind::Relativ => Step::RelAxis,
            PlaneKind::Reset => Step::Positioning,
            _ => Step::Value(0),
        };
        Dialog {
            function,
            step,
            input: String::new(),
            rel_axis: RelAxis::Spa,
            values: Vec::new(),
            incremental: [false; 3],
            positioning: None,
            dist: None,
            move_back: None,
            feed: None,
            selection: None,
            transform: None,
            message: None,
        }
    }

    /// The field asked at the current step, if it is a value prompt.
    #[must_use]
    pub fn field(&self) -> Option<&'static Field> {
        match self.step {
            Step::Value(i) => fields(self.function).get(i),
            _ => None,
        }
    }

    /// The NC word of the current prompt (`SPB`, `DIST`, `MB`, `F`), for the dialog line and
    /// the input range.
    #[must_use]
    pub fn word(&self) -> Option<Word> {
        match self.step {
            Step::Value(_) if self.function == PlaneKind::Relativ => Some(rel_word(self.rel_axis)),
            Step::Value(_) => self.field().map(|f| f.word),
            Step::Dist => Some(Word::Dist),
            Step::MoveBack => Some(Word::Mb),
            Step::Feed => Some(Word::F),
            Step::RelAxis | Step::Positioning | Step::Selection | Step::Transform => None,
        }
    }

    /// The prompt of the dialog line.
    #[must_use]
    pub fn prompt(&self) -> Text {
        match self.step {
            Step::RelAxis => {
                t("Raumwinkel wählen: SPA, SPB oder SPC", "Select the spatial angle: SPA, SPB or SPC")
            }
            Step::Value(_) => self.field().map_or(t("", ""), |f| f.prompt.clone()),
            Step::Positioning => t("Positionierverhalten?", "Positioning behaviour?"),
            Step::Dist => t("Abst. Drehpunkt von WZ-Spitze?", "Dist. tool tip – center of rot.?"),
            Step::MoveBack => t("Rückzuglänge in der Werkzeugachse?", "Retraction length in the tool axis?"),
            Step::Feed => t("Vorschub? F=", "Feed rate? F="),
            Step::Selection => {
                t("Schwenklösung wählen? (optional)", "Select the tilting solution? (optional)")
            }
            Step::Transform => t("Transformationsart? (optional)", "Type of transformation? (optional)"),
        }
    }

    /// The UNCONFIRMED decision behind the current prompt's German wording, if it is not the
    /// manual's (said in the German dialog).
    #[must_use]
    pub fn wording(&self) -> Option<Decision> {
        match self.field() {
            Some(f) if f.confirmed => None,
            _ => Some(Decision::DialogWording),
        }
    }

    /// The one-line help under the prompt.
    #[must_use]
    pub fn help(&self) -> Text {
        match self.step {
            Step::RelAxis => t(
                "SPA dreht um die aktive X-Achse, SPB um Y, SPC um Z.",
                "SPA turns about the active X axis, SPB about Y, SPC about Z.",
            ),
            Step::Value(_) => self.field().map_or(t("", ""), |f| f.help.clone()),
            Step::Positioning => t(
                "MOVE: Linearachsen gleichen aus, die WZ-Spitze bleibt. TURN: nur Drehachsen. STAY: nur das Koordinatensystem.",
                "MOVE: linear axes compensate, the tool tip stays. TURN: rotary axes only. STAY: coordinate system only.",
            ),
            Step::Dist => t(
                "Abstand Drehpunkt – Werkzeugspitze, inkremental. NO ENT: ohne DIST.",
                "Distance centre of rotation – tool tip, incremental. NO ENT: without DIST.",
            ),
            Step::MoveBack => t(
                "Rückzug in der Werkzeugachse vor dem Schwenken, inkremental; Softkey MB MAX: bis zum Endschalter. NO ENT: kein Rückzug.",
                "Retract along the tool axis before tilting, incremental; softkey MB MAX: to the limit switch. NO ENT: no retract.",
            ),
            Step::Feed => t(
                "Bahnvorschub beim Einschwenken in mm/min; Softkeys F AUTO, FMAX. NO ENT: ohne F.",
                "Path feed while tilting, mm/min; softkeys F AUTO, FMAX. NO ENT: without F.",
            ),
            Step::Selection => t(
                "SEQ: Master-Achse bezogen auf ihre Grundstellung 0°; SYM: bezogen auf ihren Symmetriepunkt. NO ENT: die Steuerung wählt den kürzesten Weg.",
                "SEQ: master axis relative to its home 0°; SYM: relative to its symmetry point. NO ENT: the control takes the shortest path.",
            ),
            Step::Transform => t(
                "Wirkt nur, wenn allein SPC ≠ 0 ist: COORD ROT dreht nur rechnerisch, TABLE ROT dreht den Rundtisch.",
                "Only matters when SPC alone is non-zero: COORD ROT rotates mathematically, TABLE ROT turns the rotary table.",
            ),
        }
    }

    /// Handles one key. Errors leave everything entered in place and set `message`.
    pub fn key(&mut self, key: Key) -> Outcome {
        self.message = None;
        match key {
            Key::Char(c) => {
                if self.takes_value() {
                    self.input.push(c);
                }
                Outcome::Continue
            }
            Key::Backspace => {
                self.input.pop();
                Outcome::Continue
            }
            Key::ToggleSign => {
                if self.takes_value() {
                    self.input = toggle_sign(&self.input);
                }
                Outcome::Continue
            }
            Key::Ent => self.ent(),
            Key::NoEnt => self.no_ent(),
            Key::End => self.end(),
            Key::RelAxis(axis) if self.step == Step::RelAxis => {
                self.rel_axis = axis;
                self.goto(Step::Value(0));
                Outcome::Continue
            }
            Key::Positioning(kind) if self.step == Step::Positioning => {
                if self.positioning != Some(kind) {
                    self.dist = None;
                    self.move_back = None;
                    self.feed = None;
                }
                self.positioning = Some(kind);
                self.goto(match kind {
                    PosKind::Move => Step::Dist,
                    PosKind::Turn => Step::MoveBack,
                    PosKind::Stay => self.after_positioning(),
                });
                self.finish_if_done()
            }
            Key::MbMax if self.step == Step::MoveBack => {
                self.move_back = Some(MoveBack::Max);
                self.goto(Step::Feed);
                Outcome::Continue
            }
            Key::FAuto | Key::FMax if self.step == Step::Feed => {
                self.feed = Some(if key == Key::FAuto { Feed::Auto } else { Feed::Max });
                self.goto(self.after_positioning());
                self.finish_if_done()
            }
            // SEQ/SYM softkeys select without advancing (ENT confirms), so that choosing SYM after
            // SEQ can be answered like the control answers a conflicting entry.
            Key::Selection(s) if self.step == Step::Selection => {
                let conflict = matches!(
                    (self.selection, s),
                    (Some(Selection::Seq(_)), Selection::Sym(_))
                        | (Some(Selection::Sym(_)), Selection::Seq(_))
                );
                if conflict {
                    return self.fail(MSG_SEQ_SYM);
                }
                self.selection = Some(s);
                Outcome::Continue
            }
            Key::Transform(m) if self.step == Step::Transform => {
                self.transform = Some(m);
                self.finish()
            }
            // A softkey of another step (e.g. clicked twice quickly): ignored like on the control.
            _ => Outcome::Continue,
        }
    }

    /// Whether the current step takes typed input.
    #[must_use]
    pub fn takes_value(&self) -> bool {
        matches!(self.step, Step::Value(_) | Step::Dist | Step::MoveBack | Step::Feed)
    }

    fn ent(&mut self) -> Outcome {
        match self.step {
            Step::RelAxis => {
                self.goto(Step::Value(0));
                Outcome::Continue
            }
            Step::Positioning => match self.positioning {
                Some(kind) => self.key(Key::Positioning(kind)),
                None => self.fail(MSG_CHOOSE_POS),
            },
            Step::Selection => {
                self.goto(Step::Transform);
                Outcome::Continue
            }
            // ENT confirms what is chosen (a reopened block's COORD ROT stays); NO ENT clears it.
            Step::Transform => self.finish(),
            Step::Value(_) | Step::Dist | Step::MoveBack | Step::Feed => {
                if self.input.trim().is_empty() {
                    return if self.required() { self.fail(MSG_REQUIRED) } else { self.no_ent() };
                }
                if let Some(choice) = self.softkey_word() {
                    return self.key(choice);
                }
                let value = match self.checked_value() {
                    Ok(v) => v,
                    Err(m) => return self.fail(m),
                };
                self.store(Some(value));
                self.advance()
            }
        }
    }

    fn no_ent(&mut self) -> Outcome {
        match self.step {
            Step::Value(_) | Step::Dist | Step::MoveBack | Step::Feed if self.required() => {
                self.fail(MSG_REQUIRED)
            }
            Step::Positioning => self.fail(MSG_CHOOSE_POS),
            Step::RelAxis => self.ent(),
            Step::Selection => {
                self.selection = None;
                self.goto(Step::Transform);
                Outcome::Continue
            }
            Step::Transform => {
                self.transform = None;
                self.finish()
            }
            Step::Value(_) | Step::Dist | Step::MoveBack | Step::Feed => {
                self.store(None);
                self.advance()
            }
        }
    }

    /// END: confirm what is typed, skip the optional rest, insert the block.
    fn end(&mut self) -> Outcome {
        loop {
            let before = self.step;
            let outcome = match self.step {
                Step::Selection | Step::Transform => return self.finish(),
                Step::Value(_) | Step::Dist | Step::MoveBack | Step::Feed
                    if !self.input.trim().is_empty() =>
                {
                    self.ent()
                }
                // A chosen (reopened) positioning is confirmed; none chosen → its message.
                Step::Positioning => self.ent(),
                _ => self.no_ent(),
            };
            if self.message.is_some() || matches!(outcome, Outcome::Finished(_)) {
                return outcome;
            }
            if self.step == before {
                return outcome;
            }
        }
    }

    fn required(&self) -> bool {
        match self.step {
            Step::Value(_) => self.field().is_some_and(|f| f.required),
            _ => false,
        }
    }

    /// `MAX`, `AUTO` typed (or prefilled by a reopened block) at a prompt whose softkeys they
    /// name: the softkey itself. Without this a reopened `MB MAX` or `FMAX` would be dropped.
    fn softkey_word(&self) -> Option<Key> {
        let typed = self.input.trim().to_ascii_uppercase();
        let prefix = self.word().map_or("", Word::as_str);
        let word = typed.strip_prefix(prefix).unwrap_or(&typed).trim_start();
        match (self.step, word) {
            (Step::MoveBack, "MAX") => Some(Key::MbMax),
            (Step::Feed, "MAX") => Some(Key::FMax),
            (Step::Feed, "AUTO") => Some(Key::FAuto),
            _ => None,
        }
    }

    /// What is typed as the parser reads it: a decimal comma (German `12,5`) is a point, and
    /// at a PLANE AXIAL prompt a leading `I` (the control's I key) marks an incremental angle.
    fn typed(&self) -> (String, bool) {
        let text = self.input.trim().replace(',', ".");
        match text.strip_prefix(['I', 'i']) {
            Some(rest) if self.function == PlaneKind::Axial && matches!(self.step, Step::Value(_)) => {
                (rest.trim_start().to_owned(), true)
            }
            _ => (text, false),
        }
    }

    /// Reads the typed value and checks it as the parser does (`plane::check`: the one input
    /// range table); the dialog line says it in the control's short words.
    fn checked_value(&self) -> Result<Value, Message> {
        let (typed, _) = self.typed();
        let value = parse_value(&typed).ok_or(MSG_INVALID)?;
        if let (Value::Number(x), Some(word)) = (value, self.word()) {
            plane::check(word, x).map_err(|code| match code {
                DiagCode::AngleNotPermitted { .. } => {
                    t("Winkel nicht erlaubt", "Entered angle not permitted")
                }
                _ => t("Eingabewert außerhalb des Bereichs", "Input value out of range"),
            })?;
        }
        Ok(value)
    }

    fn store(&mut self, value: Option<Value>) {
        match self.step {
            Step::Value(i) => {
                if self.values.len() <= i {
                    self.values.resize(i + 1, None);
                }
                self.values[i] = value;
                let incremental = value.is_some() && self.typed().1;
                if let Some(flag) = self.incremental.get_mut(i) {
                    *flag = incremental;
                }
            }
            Step::Dist => self.dist = value,
            Step::MoveBack => self.move_back = value.map(MoveBack::Dist),
            Step::Feed => self.feed = value.map(Feed::Value),
            _ => {}
        }
    }

    fn advance(&mut self) -> Outcome {
        let next = match self.step {
            Step::Value(i) if i + 1 < fields(self.function).len() => Step::Value(i + 1),
            Step::Value(_) => {
                if self.function == PlaneKind::Axial && self.values.iter().all(Option::is_none) {
                    self.goto(Step::Value(0));
                    return self.fail(MSG_AXIAL_EMPTY);
                }
                Step::Positioning
            }
            Step::Dist | Step::MoveBack => Step::Feed,
            Step::Feed => self.after_positioning(),
            other => other,
        };
        self.goto(next);
        self.finish_if_done()
    }

    /// After the positioning values: SEQ/SYM if the function has them, else the block is done.
    fn after_positioning(&self) -> Step {
        if has_solution_options(self.function) { Step::Selection } else { Step::Transform }
    }

    fn finish_if_done(&mut self) -> Outcome {
        if self.step == Step::Transform && !has_solution_options(self.function) {
            return self.finish();
        }
        Outcome::Continue
    }

    fn finish(&mut self) -> Outcome {
        match self.block() {
            Ok(block) => Outcome::Finished(plane_text(&block)),
            Err(m) => self.fail(m),
        }
    }

    fn goto(&mut self, step: Step) {
        self.step = step;
        self.input = self.prefill();
    }

    /// A reopened block shows its stored value at each prompt, the softkey choices by name
    /// (`MAX`, `AUTO`), so that ENT or END keeps them (`softkey_word`).
    fn prefill(&self) -> String {
        let v = match self.step {
            Step::Value(i) => {
                let incremental = self.incremental.get(i).copied().unwrap_or(false);
                let value = self.values.get(i).copied().flatten().map(value_text);
                return value.map(|v| if incremental { format!("I{v}") } else { v }).unwrap_or_default();
            }
            Step::Dist => self.dist,
            Step::MoveBack => match self.move_back {
                Some(MoveBack::Dist(v)) => Some(v),
                Some(MoveBack::Max) => return "MAX".to_owned(),
                None => None,
            },
            Step::Feed => match self.feed {
                Some(Feed::Value(v)) => Some(v),
                Some(Feed::Max) => return "MAX".to_owned(),
                Some(Feed::Auto) => return "AUTO".to_owned(),
                None => None,
            },
            _ => None,
        };
        v.map(value_text).unwrap_or_default()
    }

    fn fail(&mut self, message: Message) -> Outcome {
        self.message = Some(message);
        Outcome::Continue
    }

    /// The softkeys of the current step (the reducer turns them into the softkey row).
    #[must_use]
    pub fn softkeys(&self) -> Vec<(Key, &'static str)> {
        match self.step {
            Step::RelAxis => vec![
                (Key::RelAxis(RelAxis::Spa), "SPA"),
                (Key::RelAxis(RelAxis::Spb), "SPB"),
                (Key::RelAxis(RelAxis::Spc), "SPC"),
            ],
            Step::Positioning => vec![
                (Key::Positioning(PosKind::Move), "MOVE"),
                (Key::Positioning(PosKind::Turn), "TURN"),
                (Key::Positioning(PosKind::Stay), "STAY"),
            ],
            Step::MoveBack => vec![(Key::MbMax, "MB MAX")],
            Step::Feed => vec![(Key::FAuto, "F AUTO"), (Key::FMax, "FMAX")],
            Step::Selection => vec![
                (Key::Selection(Selection::Seq(Sign::Plus)), "SEQ+"),
                (Key::Selection(Selection::Seq(Sign::Minus)), "SEQ-"),
                (Key::Selection(Selection::Sym(Sign::Plus)), "SYM+"),
                (Key::Selection(Selection::Sym(Sign::Minus)), "SYM-"),
            ],
            Step::Transform => vec![
                (Key::Transform(TransformMode::CoordRot), "COORD ROT"),
                (Key::Transform(TransformMode::TableRot), "TABLE ROT"),
            ],
            Step::Value(_) | Step::Dist => Vec::new(),
        }
    }
}

fn rel_word(axis: RelAxis) -> Word {
    PlaneKind::Relativ.words(axis)[0]
}

/// A value as the trainee would type it again (no `+`).
fn value_text(v: Value) -> String {
    match v {
        Value::Number(x) => format!("{x}"),
        Value::Param { index, negate } => {
            format!("{}{}", if negate { "-" } else { "" }, schwenkbar_core::ast::QName(index))
        }
    }
}

/// The control's `-/+` key: flips the sign of what is typed (after an incremental `I`).
fn toggle_sign(input: &str) -> String {
    let s = input.trim();
    if let Some(rest) = s.strip_prefix(['I', 'i']) {
        return format!("I{}", toggle_sign(rest));
    }
    if let Some(rest) = s.strip_prefix('-') {
        rest.to_owned()
    } else if let Some(rest) = s.strip_prefix('+') {
        format!("-{rest}")
    } else {
        format!("-{s}")
    }
}
