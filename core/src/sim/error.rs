//! Why a run stopped: the control's message (German and English) with the numbers.

use crate::Lang;
use crate::number::prose;
use serde::Serialize;

use crate::ast::QName;
use crate::lang::Text;
use crate::orientation::PlaneError;
use crate::solve::SolveError;

use super::collision::Collision;
use super::segment::SegmentKind;

/// What went wrong at a block. Every variant carries the numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum SimErrorCode {
    /// The solver found no permitted axis position ("Winkel nicht erlaubt").
    Solve { error: SolveError },
    /// The PLANE words cannot define a plane.
    Plane { error: PlaneError },
    /// A Q parameter was read before it was given a value.
    UndefinedQ { index: u32 },
    /// A formula gave no number (division by zero, root of a negative number, …).
    Arithmetic { index: u32 },
    /// `TOOL CALL Q…` with a parameter that holds no tool number (negative or too large).
    ToolNumber { index: u32, value: f64 },
    /// `CALL LBL … REP Q…` with a parameter that holds no number of repeats.
    RepCount { index: u32, value: f64 },
    /// RL/RR on an arc in the plane of a `CC` that is not the working plane.
    CompensationOffPlane,
    /// `M99`/`CYCL CALL` with no cycle defined.
    NoCycle,
    /// The cycle was defined with its parameters left out (as printed in the seed).
    CycleParamsMissing { cycle: u32 },
    /// A cycle parameter the simulated cycle needs is missing.
    CycleParamMissing { cycle: u32, param: u32 },
    /// A cycle parameter written `PREDEF` or `FAUTO` whose value the run does not know (no
    /// global default for it, no feed in the TOOL CALL).
    CycleWordUnknown { cycle: u32, param: u32, word: &'static str },
    /// `FMAX` or `FAUTO` for a cycle parameter that is no feed rate (`Q201=FMAX`): the cycle
    /// dialog offers the words only for feed rates.
    CycleWordNotFeed { cycle: u32, param: u32, word: &'static str },
    /// A machining cycle with a positive depth Q201.
    DepthSign { cycle: u32, value: f64 },
    /// The tool is larger than the bore, pocket or slot the cycle mills (`size`: its diameter or
    /// width less the finishing allowances).
    ToolTooLarge { cycle: u32, tool_diameter: f64, size: f64 },
    /// Cycle 208 without a pre-drilled diameter: the bore is more than twice the tool diameter.
    ToolTooSmall { cycle: u32, tool_diameter: f64, size: f64 },
    /// `CYCL CALL PAT` with no `PATTERN DEF` before it.
    NoPattern,
    /// A linear axis target outside its software limit switch.
    LimitSwitch { axis: char, value: f64, min: f64, max: f64 },
    /// A rotary axis target outside its software limit switch.
    RotaryLimit { axis: char, value: f64, min: f64, max: f64 },
    /// A rotary axis the machine does not have.
    AxisNotOnMachine { axis: char },
    /// `CALL LBL` to a label that is not in the program.
    UndefinedLabel { label: String },
    /// Subprogram calls nested too deep.
    CallDepth { depth: usize },
    /// More executed blocks than the budget: an endless loop.
    BlockBudget { steps: usize },
    /// A block the parser could not read.
    InvalidBlock,
    /// `FN 14: ERROR = n`: the program itself stops with an error message.
    FnError { text: String },
    /// `C`, `LP` or `CP` with no circle centre / pole (`CC`) before it.
    NoCircleCentre { word: &'static str },
    /// `C`: the end point is not on the circle around CC through the start point.
    CircleEnd { start_radius: f64, end_radius: f64 },
    /// `CR`: the distance from start to end point is larger than the diameter.
    RadiusTooSmall { radius: f64, chord: f64 },
    /// An arc from a point to itself where a full circle is not defined (CR), or starting on its
    /// centre (C, CP).
    ArcDegenerate { word: &'static str },
    /// `CT` with no contour element before it to be tangent to.
    NoTangent,
    /// `CT` whose end point lies on the tangent of the preceding element.
    EndOnTangent,
    /// `RND`/`CHF` without a contour element before and after it.
    CornerWithoutContour { word: &'static str },
    /// `RND`/`CHF` where the two elements meet tangentially (no corner).
    NoCorner { word: &'static str },
    /// `RND`/`CHF` too large for the elements it joins.
    CornerTooLarge { word: &'static str, value: f64 },
    /// `CHF` between elements that are not both straight lines.
    ChamferNeedsLines,
    /// RL/RR: an arc whose tool centre path would have a radius < 0 (an inside arc smaller than
    /// the tool radius).
    ToolRadiusTooLarge { radius: f64, contour_radius: f64 },
    /// RL/RR: an element that vanishes between the intersections of its neighbours' tool
    /// centre paths.
    ContourElementTooSmall { radius: f64 },
    /// RL after RR (or RR after RL) without a block with R0 between them.
    CompensationChange,
    /// `TOOL CALL`, `M91` or `M92` (`word`) while TCPM is on: the manual has TCPM reset first.
    TcpmActive { word: &'static str },
    /// `APPR`/`DEP` whose path cannot be built.
    ApprDep { word: &'static str, kind: &'static str, reason: ApprDepReason },
    /// Two bodies touched during the block's motion ([`super::collision`]).
    Collision(Box<Collision>),
}

/// Why an `APPR`/`DEP` path cannot be built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ApprDepReason {
    /// No radius compensation RL/RR (APPR: in the block; DEP: on the contour before it).
    NoCompensation,
    /// APPR with no contour element after it to approach.
    NoContourAfter,
    /// DEP with no contour element before it to leave.
    NoContourBefore,
    /// LCT: the start point (APPR) or end point (DEP) lies inside the arc's circle.
    PointInsideArc,
    /// CT/LCT: the arc has radius 0.
    ZeroRadius,
}

/// The run stopped at this block; every state before it is kept.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SimError {
    /// The executed step that failed (= number of states before it).
    pub step: usize,
    /// Index of the block in the program.
    pub block: usize,
    /// 1-based source line of the block.
    pub line: u32,
    pub code: SimErrorCode,
    /// The control's message.
    pub message: Text,
    /// The detail with the numbers.
    pub detail: Text,
}

/// Why a stop from the tool's size used the default tool's: no tool was called (T0).
#[must_use]
pub fn no_tool(length: f64, radius: f64) -> Text {
    t(
        format!("kein Werkzeug aufgerufen (T0): Standardwerkzeug L={length} R={radius} angenommen"),
        format!("no tool called (T0): assuming the default tool L={length} R={radius}"),
    )
}

/// Why a touch-probe cycle's result has no value ([`SimErrorCode::is_probe_result`]): `cycle`
/// ran before and is not simulated.
#[must_use]
pub fn unprobed(cycle: u32) -> Text {
    t(
        format!(
            "TCH PROBE {cycle} misst nicht im Trainer: Tastsystemzyklen legen ihre Messwerte in Q150 bis Q166 und Q180 bis Q182 ab"
        ),
        format!(
            "TCH PROBE {cycle} does not measure in the trainer: touch-probe cycles save their results in Q150 to Q166 and Q180 to Q182"
        ),
    )
}

fn t(de: impl Into<std::borrow::Cow<'static, str>>, en: impl Into<std::borrow::Cow<'static, str>>) -> Text {
    Text { de: de.into(), en: en.into() }
}

impl SimErrorCode {
    /// Whether the stop comes from the tool's size (a bore, an arc or a contour element too
    /// small for it): with a tool the table does not have, its size was assumed, and the stop
    /// says so.
    #[must_use]
    pub fn depends_on_tool_size(&self) -> bool {
        matches!(
            self,
            SimErrorCode::ToolTooLarge { .. }
                | SimErrorCode::ToolTooSmall { .. }
                | SimErrorCode::ToolRadiusTooLarge { .. }
                | SimErrorCode::ContourElementTooSmall { .. }
        )
    }

    /// Whether the stop is a touch-probe cycle's result parameter without a value: the cycles
    /// save their measured values in Q150 to Q160, the deviations from nominal in Q161 to Q166
    /// and the class of the result in Q180 to Q182 (iTNC 530, TNC 320 and TNC 640 cycle
    /// manuals, "Measurement results in Q parameters").
    #[must_use]
    pub fn is_probe_result(&self) -> bool {
        matches!(self, SimErrorCode::UndefinedQ { index: 150..=166 | 180..=182 })
    }

    /// The control's message (wordings not found in a source are marked in
    /// [`crate::unconfirmed::SIM_MESSAGES_UNCONFIRMED`]).
    #[must_use]
    pub fn message(&self) -> Text {
        match self {
            SimErrorCode::Solve { error } => error.message(),
            SimErrorCode::Plane { error } => error.message(),
            SimErrorCode::UndefinedQ { .. } => t("Q-Parameter nicht definiert", "Q parameter not defined"),
            SimErrorCode::Arithmetic { .. } => t("Rechenfehler", "Arithmetical error"),
            SimErrorCode::ToolNumber { .. } => t("Werkzeugnummer falsch", "Tool number wrong"),
            SimErrorCode::CompensationOffPlane => {
                t("Radiuskorrektur nicht erlaubt", "Radius compensation not permitted")
            }
            SimErrorCode::RepCount { .. } | SimErrorCode::CycleWordNotFeed { .. } => {
                t("Eingabewert falsch", "Incorrect input value")
            }
            SimErrorCode::NoCycle => t("Zyklus nicht definiert", "Cycle not defined"),
            SimErrorCode::CycleParamsMissing { .. }
            | SimErrorCode::CycleParamMissing { .. }
            | SimErrorCode::CycleWordUnknown { .. } => t("Zyklusparameter fehlt", "Cycle parameter missing"),
            SimErrorCode::DepthSign { .. } => t("Vorzeichen Tiefe falsch", "Depth sign wrong"),
            SimErrorCode::ToolTooLarge { .. } => t("Werkzeug-Radius zu groß", "Tool radius too large"),
            SimErrorCode::ToolTooSmall { .. } => t("Werkzeug-Radius zu klein", "Tool radius too small"),
            SimErrorCode::NoPattern => t("Muster nicht definiert", "Pattern not defined"),
            SimErrorCode::LimitSwitch { axis, value, max, .. }
            | SimErrorCode::RotaryLimit { axis, value, max, .. } => {
                let sign = if value > max { '+' } else { '-' };
                t(format!("Endschalter {axis}{sign}"), format!("Limit switch {axis}{sign}"))
            }
            SimErrorCode::AxisNotOnMachine { .. } => t("Achse nicht vorhanden", "Axis does not exist"),
            SimErrorCode::UndefinedLabel { .. } => {
                t("Label-Nummer nicht vorhanden", "Label number not found")
            }
            SimErrorCode::CallDepth { .. } => t("Verschachtelung zu tief", "Excessive subprogramming"),
            SimErrorCode::BlockBudget { .. } => {
                t("Programmlauf abgebrochen: Satzbudget erschöpft", "Run stopped: block budget exhausted")
            }
            SimErrorCode::InvalidBlock => t("Satz fehlerhaft", "Block syntax error"),
            SimErrorCode::FnError { .. } => t("FN 14: Fehlermeldung", "FN 14: error message"),
            SimErrorCode::NoCircleCentre { .. } => {
                t("Kreismittelpunkt undefiniert", "Circle center undefined")
            }
            SimErrorCode::CircleEnd { .. } | SimErrorCode::ArcDegenerate { .. } => {
                t("Kreis-Endposition falsch", "Circle end position incorrect")
            }
            SimErrorCode::RadiusTooSmall { .. } => t("Kreisradius zu klein", "Circle radius too small"),
            SimErrorCode::NoTangent | SimErrorCode::EndOnTangent => {
                t("Tangentialer Anschluss nicht möglich", "Tangential connection not possible")
            }
            SimErrorCode::CornerWithoutContour { word }
            | SimErrorCode::NoCorner { word }
            | SimErrorCode::CornerTooLarge { word, .. } => {
                t(format!("{word} nicht möglich"), format!("{word} not possible"))
            }
            SimErrorCode::ChamferNeedsLines => t("CHF nicht möglich", "CHF not possible"),
            SimErrorCode::ToolRadiusTooLarge { .. } | SimErrorCode::ContourElementTooSmall { .. } => {
                t("Werkzeug-Radius zu groß", "Tool radius too large")
            }
            SimErrorCode::CompensationChange => {
                t("Radiuskorrektur RL/RR ohne R0 gewechselt", "Radius compensation RL/RR changed without R0")
            }
            SimErrorCode::TcpmActive { word } => t(
                format!("{word} bei aktivem TCPM nicht erlaubt"),
                format!("{word} not permitted with TCPM active"),
            ),
            SimErrorCode::ApprDep { word, kind, .. } => {
                t(format!("{word} {kind} nicht möglich"), format!("{word} {kind} not possible"))
            }
            SimErrorCode::Collision(c) => {
                let pair = c.pair();
                t(format!("Kollision: {}", pair.de), format!("Collision: {}", pair.en))
            }
        }
    }

    /// [`Self::detail`] with what the run assumed or left out that led to the stop, in brackets.
    #[must_use]
    pub fn detail_because(&self, because: &Text) -> Text {
        let detail = self.detail();
        t(format!("{} ({})", detail.de, because.de), format!("{} ({})", detail.en, because.en))
    }

    /// The detail with the numbers.
    #[must_use]
    pub fn detail(&self) -> Text {
        match self {
            SimErrorCode::Solve { error } => error.detail(),
            SimErrorCode::Plane { error } => error.message(),
            SimErrorCode::UndefinedQ { index } => t(
                format!("{} wurde noch kein Wert zugewiesen", QName(*index)),
                format!("{} has no value yet", QName(*index)),
            ),
            SimErrorCode::Arithmetic { index } => t(
                format!(
                    "{}: das Ergebnis ist keine Zahl (Division durch 0, Wurzel aus negativer Zahl …)",
                    QName(*index)
                ),
                format!(
                    "{}: the result is not a number (division by 0, root of a negative number, …)",
                    QName(*index)
                ),
            ),
            SimErrorCode::ToolNumber { index, value } => t(
                format!(
                    "{} = {} ist keine Werkzeugnummer (0 oder größer)",
                    QName(*index),
                    prose(*value, None, Lang::De)
                ),
                format!(
                    "{} = {} is no tool number (0 or more)",
                    QName(*index),
                    prose(*value, None, Lang::En)
                ),
            ),
            SimErrorCode::RepCount { index, value } => t(
                format!(
                    "REP {} = {}: die Anzahl Wiederholungen ist eine ganze Zahl von 0 bis 65534",
                    QName(*index),
                    prose(*value, None, Lang::De)
                ),
                format!(
                    "REP {} = {}: the number of repeats is a whole number from 0 to 65534",
                    QName(*index),
                    prose(*value, None, Lang::En)
                ),
            ),
            SimErrorCode::CompensationOffPlane => t(
                "RL/RR wirkt nur in der Bearbeitungsebene: ein Kreis in der Ebene des CC (z. B. CC X… Z…) braucht R0",
                "RL/RR acts in the working plane only: an arc in the plane of its CC (e.g. CC X… Z…) needs R0",
            ),
            SimErrorCode::NoCycle => {
                t("M99/CYCL CALL ohne vorheriges CYCL DEF", "M99/CYCL CALL without a preceding CYCL DEF")
            }
            SimErrorCode::CycleParamsMissing { cycle } => t(
                format!("CYCL DEF {cycle} ohne Q-Parameter (im Lehrbuch ausgelassen): bitte ergänzen"),
                format!("CYCL DEF {cycle} has no Q parameters (left out in the book): please complete it"),
            ),
            SimErrorCode::CycleParamMissing { cycle, param } => t(
                format!("CYCL DEF {cycle}: Q{param} fehlt"),
                format!("CYCL DEF {cycle}: Q{param} is missing"),
            ),
            SimErrorCode::CycleWordUnknown { cycle, param, word } => match *word {
                "PREDEF" => t(
                    format!(
                        "CYCL DEF {cycle}: Q{param}=PREDEF, aber kein Wert der globalen Programmeinstellungen \
                         (GLOBAL DEF) bekannt: bitte eine Zahl eingeben"
                    ),
                    format!(
                        "CYCL DEF {cycle}: Q{param}=PREDEF, but no value of the global program settings \
                         (GLOBAL DEF) is known: please enter a number"
                    ),
                ),
                _ => t(
                    format!("CYCL DEF {cycle}: Q{param}={word}, aber kein Vorschub im TOOL CALL"),
                    format!("CYCL DEF {cycle}: Q{param}={word}, but no feed in the TOOL CALL"),
                ),
            },
            SimErrorCode::CycleWordNotFeed { cycle, param, word } => t(
                format!(
                    "CYCL DEF {cycle}: Q{param}={word}, aber Q{param} ist kein Vorschub: bitte eine Zahl eingeben"
                ),
                format!(
                    "CYCL DEF {cycle}: Q{param}={word}, but Q{param} is no feed rate: please enter a number"
                ),
            ),
            SimErrorCode::DepthSign { cycle, value } => t(
                format!("Zyklus {cycle}: Tiefe Q201 = {} ist positiv", prose(*value, Some(4), Lang::De)),
                format!("Cycle {cycle}: depth Q201 = {} is positive", prose(*value, Some(4), Lang::En)),
            ),
            SimErrorCode::ToolTooLarge { cycle, tool_diameter, size } => t(
                format!(
                    "Zyklus {cycle}: Werkzeugdurchmesser {} größer als {} (Bohrung, Tasche oder Nut ohne Aufmaß)",
                    prose(*tool_diameter, Some(4), Lang::De),
                    prose(*size, Some(4), Lang::De)
                ),
                format!(
                    "Cycle {cycle}: tool diameter {} larger than {} (bore, pocket or slot less its allowance)",
                    prose(*tool_diameter, Some(4), Lang::En),
                    prose(*size, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::ToolTooSmall { cycle, tool_diameter, size } => t(
                format!(
                    "Zyklus {cycle}: Solldurchmesser {} größer als 2 × Werkzeugdurchmesser {}: Vorbohrdurchmesser Q342 angeben",
                    prose(*size, Some(4), Lang::De),
                    prose(*tool_diameter, Some(4), Lang::De)
                ),
                format!(
                    "Cycle {cycle}: nominal diameter {} larger than 2 × the tool diameter {}: give the roughing diameter Q342",
                    prose(*size, Some(4), Lang::En),
                    prose(*tool_diameter, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::NoPattern => t(
                "CYCL CALL PAT ohne vorheriges PATTERN DEF",
                "CYCL CALL PAT without a preceding PATTERN DEF",
            ),
            SimErrorCode::LimitSwitch { axis, value, min, max }
            | SimErrorCode::RotaryLimit { axis, value, min, max } => t(
                format!(
                    "{axis} = {} außerhalb des Verfahrbereichs {} … {}",
                    prose(*value, Some(4), Lang::De),
                    prose(*min, None, Lang::De),
                    prose(*max, None, Lang::De)
                ),
                format!("{axis} = {value:.4} outside the traverse range {min} … {max}"),
            ),
            SimErrorCode::AxisNotOnMachine { axis } => {
                t(format!("Die Maschine hat keine Achse {axis}"), format!("The machine has no axis {axis}"))
            }
            SimErrorCode::UndefinedLabel { label } => {
                t(format!("LBL {label} fehlt im Programm"), format!("LBL {label} is not in the program"))
            }
            SimErrorCode::CallDepth { depth } => t(
                format!("Mehr als {depth} verschachtelte Unterprogrammaufrufe"),
                format!("More than {depth} nested subprogram calls"),
            ),
            SimErrorCode::BlockBudget { steps } => t(
                format!("Mehr als {steps} Sätze ausgeführt: vermutlich eine Endlosschleife"),
                format!("More than {steps} blocks executed: probably an endless loop"),
            ),
            SimErrorCode::InvalidBlock => {
                t("Der Satz konnte nicht gelesen werden", "The block could not be read")
            }
            SimErrorCode::FnError { text } => t(
                format!("Das Programm hält mit seiner eigenen Fehlermeldung an: FN 14: {text}"),
                format!("The program stops with its own error message: FN 14: {text}"),
            ),
            SimErrorCode::NoCircleCentre { word } => t(
                format!("{word} braucht einen Kreismittelpunkt/Pol: vorher CC programmieren"),
                format!("{word} needs a circle centre/pole: program CC before it"),
            ),
            SimErrorCode::CircleEnd { start_radius, end_radius } => t(
                format!(
                    "Der Endpunkt liegt nicht auf dem Kreis um CC: Radius am Anfang {}, am Ende {}",
                    prose(*start_radius, Some(4), Lang::De),
                    prose(*end_radius, Some(4), Lang::De)
                ),
                format!(
                    "The end point is not on the circle around CC: radius {} at the start, {} at the end",
                    prose(*start_radius, Some(4), Lang::En),
                    prose(*end_radius, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::RadiusTooSmall { radius, chord } => t(
                format!(
                    "CR: Abstand Anfangs- zu Endpunkt {} ist größer als der Durchmesser 2·R = {}",
                    prose(*chord, Some(4), Lang::De),
                    prose(2.0 * radius, Some(4), Lang::De)
                ),
                format!(
                    "CR: the distance from start to end point {} is larger than the diameter 2·R = {}",
                    prose(*chord, Some(4), Lang::En),
                    prose(2.0 * radius, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::ArcDegenerate { word } => t(
                format!("{word}: Anfangspunkt, Endpunkt und Mittelpunkt legen keinen Kreisbogen fest"),
                format!("{word}: start point, end point and centre define no arc"),
            ),
            SimErrorCode::NoTangent => t(
                "CT braucht ein vorheriges Konturelement, an das der Kreis tangential anschließt",
                "CT needs a preceding contour element for the arc to join tangentially",
            ),
            SimErrorCode::EndOnTangent => t(
                "CT: der Endpunkt liegt auf der Tangente des vorherigen Elements (das wäre eine Gerade)",
                "CT: the end point lies on the tangent of the preceding element (that would be a straight line)",
            ),
            SimErrorCode::CornerWithoutContour { word } => t(
                format!(
                    "{word} steht zwischen zwei Konturelementen (Gerade oder Kreis) in der Bearbeitungsebene"
                ),
                format!("{word} must stand between two contour elements (line or arc) in the working plane"),
            ),
            SimErrorCode::NoCorner { word } => t(
                format!("{word}: die beiden Elemente schließen tangential an, es gibt keine Ecke"),
                format!("{word}: the two elements join tangentially, there is no corner"),
            ),
            SimErrorCode::CornerTooLarge { word, value } => t(
                format!(
                    "{word} {}: passt nicht auf die angrenzenden Konturelemente",
                    prose(*value, Some(4), Lang::De)
                ),
                format!(
                    "{word} {}: does not fit on the adjoining contour elements",
                    prose(*value, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::ChamferNeedsLines => {
                t("CHF verbindet nur zwei Geraden", "CHF joins two straight lines only")
            }
            SimErrorCode::ToolRadiusTooLarge { radius, contour_radius } => t(
                format!(
                    "Kreis R{}: mit dem Werkzeugradius {} bleibt keine Werkzeugmittelpunktsbahn (Innenkreis kleiner als das Werkzeug)",
                    prose(*contour_radius, Some(4), Lang::De),
                    prose(*radius, Some(4), Lang::De)
                ),
                format!(
                    "Arc R{}: with the tool radius {} no tool centre path is left (inside arc smaller than the tool)",
                    prose(*contour_radius, Some(4), Lang::En),
                    prose(*radius, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::ContourElementTooSmall { radius } => t(
                format!(
                    "Das Konturelement verschwindet zwischen den Schnittpunkten der korrigierten Nachbarelemente (Werkzeugradius {})",
                    prose(*radius, Some(4), Lang::De)
                ),
                format!(
                    "The contour element vanishes between the intersections of its neighbours' compensated paths (tool radius {})",
                    prose(*radius, Some(4), Lang::En)
                ),
            ),
            SimErrorCode::CompensationChange => t(
                "Zwischen Sätzen mit RL und RR muss ein Verfahrsatz in der Bearbeitungsebene mit R0 stehen",
                "Between blocks with RL and RR there must be a positioning block in the working plane with R0",
            ),
            SimErrorCode::TcpmActive { word } => t(
                format!("Vor {word} TCPM zurücksetzen: FUNCTION RESET TCPM oder M129"),
                format!("Reset TCPM before {word}: FUNCTION RESET TCPM or M129"),
            ),
            SimErrorCode::ApprDep { word, kind, reason } => match reason {
                ApprDepReason::NoCompensation => t(
                    format!("{word} {kind}: An- und Abfahren brauchen die Radiuskorrektur RL oder RR"),
                    format!("{word} {kind}: approaching and departing need radius compensation RL or RR"),
                ),
                ApprDepReason::NoContourAfter => t(
                    format!(
                        "{word} {kind}: danach folgt kein Konturelement, an das die Anfahrbahn anschließt"
                    ),
                    format!("{word} {kind}: no contour element follows for the approach path to join"),
                ),
                ApprDepReason::NoContourBefore => t(
                    format!("{word} {kind}: davor steht kein Konturelement, von dem die Abfahrbahn ausgeht"),
                    format!("{word} {kind}: no contour element precedes it for the departure path to leave"),
                ),
                ApprDepReason::PointInsideArc => t(
                    format!("{word} {kind}: der Start- bzw. Endpunkt liegt innerhalb des Kreises"),
                    format!("{word} {kind}: the start or end point lies inside the arc's circle"),
                ),
                ApprDepReason::ZeroRadius => t(
                    format!("{word} {kind}: der Radius R ist 0"),
                    format!("{word} {kind}: the radius R is 0"),
                ),
            },
            SimErrorCode::Collision(c) => collision_detail(c),
        }
    }
}

/// Where the bodies touched, the axes then, and the safe other solution if there is one.
fn collision_detail(c: &Collision) -> Text {
    let (de, en) = match c.kind {
        SegmentKind::SwivelTurn => ("beim Schwenken (TURN)", "while swivelling (TURN)"),
        SegmentKind::SwivelMove => ("beim Schwenken (MOVE)", "while swivelling (MOVE)"),
        SegmentKind::SwivelStay => ("nach dem Schwenken (STAY)", "after the swivel (STAY)"),
        SegmentKind::Retract => ("beim Rückzug (MB)", "during the retract (MB)"),
        SegmentKind::Rapid => ("im Eilgang", "at rapid traverse"),
        SegmentKind::Feed | SegmentKind::CycleFeed => ("im Vorschub", "at feed"),
    };
    let axes: Vec<String> =
        c.axes.named().into_iter().map(|(l, v)| format!("{l}{}", crate::solve::fmt_deg(v))).collect();
    let axes = axes.join(" ");
    let [pct_de, pct_en] = [Lang::De, Lang::En].map(|l| prose((c.fraction * 100.0).round(), Some(0), l));
    let mut de =
        format!("{} und {} berühren sich {de} nach {pct_de} % der Bewegung, bei {axes}", c.a.de, c.b.de);
    let mut en = format!("{} and {} touch {en} after {pct_en} % of the motion, at {axes}", c.a.en, c.b.en);
    if let Some(alt) = &c.alternative {
        let words = crate::solve::axis_words(&alt.axes);
        de.push_str(&format!(". Die andere Lösung ({}) wäre kollisionsfrei: {words}", alt.word));
        en.push_str(&format!(". The other solution ({}) would be collision-free: {words}", alt.word));
    }
    t(de, en)
}

impl Collision {
    /// The two bodies as the control's message names them: "Werkzeug – Rundtisch C".
    #[must_use]
    pub fn pair(&self) -> Text {
        t(format!("{} – {}", self.a.de, self.b.de), format!("{} – {}", self.a.en, self.b.en))
    }

    /// The why panel's note when the other solution's swivel is free: "Die gewählte Lösung
    /// kollidiert (Werkzeug – Rundtisch C); die andere Lösung SEQ+ (A+30 C+180) wäre
    /// kollisionsfrei."
    #[must_use]
    pub fn alternative_note(&self) -> Option<Text> {
        let alt = self.alternative.as_ref()?;
        let (pair, words) = (self.pair(), crate::solve::axis_words(&alt.axes));
        Some(t(
            format!(
                "Die gewählte Lösung kollidiert ({}); die andere Lösung {} ({words}) wäre kollisionsfrei.",
                pair.de, alt.word
            ),
            format!(
                "The chosen solution collides ({}); the other solution {} ({words}) would be collision-free.",
                pair.en, alt.word
            ),
        ))
    }
}
