//! Why a run stopped: the control's message (German and English) with the numbers.

use crate::Lang;
use crate::number::prose;
use serde::Serialize;

use crate::lang::Text;
use crate::orientation::PlaneError;
use crate::solve::SolveError;

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
    /// `M99`/`CYCL CALL` with no cycle defined.
    NoCycle,
    /// The cycle was defined with its parameters left out (as printed in the seed).
    CycleParamsMissing { cycle: u32 },
    /// A cycle parameter the simulated cycle needs is missing.
    CycleParamMissing { cycle: u32, param: u32 },
    /// Cycle 200 with a positive depth Q201.
    DepthSign { value: f64 },
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

fn t(de: impl Into<std::borrow::Cow<'static, str>>, en: impl Into<std::borrow::Cow<'static, str>>) -> Text {
    Text { de: de.into(), en: en.into() }
}

impl SimErrorCode {
    /// The control's message (wordings not found in a source are marked in
    /// [`crate::unconfirmed::SIM_MESSAGES_UNCONFIRMED`]).
    #[must_use]
    pub fn message(&self) -> Text {
        match self {
            SimErrorCode::Solve { error } => error.message(),
            SimErrorCode::Plane { error } => error.message(),
            SimErrorCode::UndefinedQ { .. } => t("Q-Parameter nicht definiert", "Q parameter not defined"),
            SimErrorCode::Arithmetic { .. } => t("Rechenfehler", "Arithmetical error"),
            SimErrorCode::NoCycle => t("Zyklus nicht definiert", "Cycle not defined"),
            SimErrorCode::CycleParamsMissing { .. } | SimErrorCode::CycleParamMissing { .. } => {
                t("Zyklusparameter fehlt", "Cycle parameter missing")
            }
            SimErrorCode::DepthSign { .. } => t("Vorzeichen Tiefe falsch", "Depth sign wrong"),
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
        }
    }

    /// The detail with the numbers.
    #[must_use]
    pub fn detail(&self) -> Text {
        match self {
            SimErrorCode::Solve { error } => error.detail(),
            SimErrorCode::Plane { error } => error.message(),
            SimErrorCode::UndefinedQ { index } => {
                t(format!("Q{index} wurde noch kein Wert zugewiesen"), format!("Q{index} has no value yet"))
            }
            SimErrorCode::Arithmetic { index } => t(
                format!(
                    "Q{index}: das Ergebnis ist keine Zahl (Division durch 0, Wurzel aus negativer Zahl …)"
                ),
                format!("Q{index}: the result is not a number (division by 0, root of a negative number, …)"),
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
            SimErrorCode::DepthSign { value } => t(
                format!("Zyklus 200: Tiefe Q201 = {value} ist positiv"),
                format!("Cycle 200: depth Q201 = {value} is positive"),
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
        }
    }
}
