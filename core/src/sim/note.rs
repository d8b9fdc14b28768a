//! What a block tells the trainee without stopping the run: a typed note with the numbers, worded
//! here in German and English (as [`super::SimErrorCode`] is for the stops). The simulator
//! records the code; the words are made only when a step is shown.

use serde::Serialize;

use crate::Lang;
use crate::ast::QName;
use crate::lang::Text;
use crate::number::{prose, signed};
use crate::unconfirmed::{self, Decision};

/// A block's note. Every variant carries the numbers its words need.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum Note {
    /// `M128` or `FUNCTION TCPM` (`word`); `spatial`: `AXIS SPAT`.
    TcpmOn { word: &'static str, spatial: bool },
    /// `M129` or `FUNCTION RESET TCPM` (`word`).
    TcpmOff { word: &'static str },
    /// `M0` or `STOP` (`word`): the control stops there, the trainer runs on.
    Halt { word: &'static str },
    /// `M1`: optional program stop.
    OptionalStop,
    /// A convention of [`crate::unconfirmed`] the block depends on (M92's datum).
    Assumed { decision: Decision },
    /// M functions the simulator does not model.
    MNotSimulated { m: Vec<u32> },
    /// A block after M30/M2, listed but not executed.
    AfterEnd,
    /// A `/` block with block skip on.
    BlockSkipped,
    /// `BEGIN PGM … INCH`.
    Inch,
    /// `CC`: circle centre or pole, no motion.
    CircleCentre,
    /// `PATTERN DEF` with its number of items.
    PatternDef { items: usize },
    /// `CALL PGM` (the called program is not loaded).
    CallPgm { path: String },
    /// A block the parser kept as written and the simulator does not model.
    BlockNotSimulated { text: String },
    /// A PLANE block without MOVE/TURN/STAY.
    PositioningMissing,
    /// `M140`, at rapid or at the feed (mm/min) written after MB.
    Retract { feed: Option<f64> },
    /// `CYCL DEF 19.0`: the angles follow.
    Cycle19AnglesFollow,
    /// Cycle 19 with all angles 0.
    Cycle19Reset,
    /// Cycle 19 positions the rotary axes itself ([`unconfirmed::CYCLE19_MOVES_AXES`]).
    Cycle19MovesAxes,
    /// Cycle 19 active; the program positions the rotary axes.
    Cycle19Active,
    /// `AXIS SPAT`: the spatial angles `spatial` (SPA, SPB, SPC) give the axis words `chosen`;
    /// `missing`: the first block after switching on left some out.
    AxisSpat { spatial: [f64; 3], chosen: String, missing: bool },
    /// A rotary axis in an arc block.
    ArcRotaryAxis,
    /// Cycle 11 (scaling).
    Cycle11NotSimulated,
    /// An old-style cycle `CYCL DEF n.0` stored for its call.
    OldCycleDefined { cycle: u32 },
    /// `CYCL DEF n …` stored for its call.
    CycleDefined { cycle: u32 },
    /// `CYCL DEF n` without its parameter lines: its call reads Q200… as set then.
    CycleDefinedParamsFromQ { cycle: u32 },
    /// A called cycle the simulator does not model.
    CycleNotSimulated { cycle: u32 },
    /// `M99`/`CYCL CALL`: the cycle ran with `moves` moves.
    CycleExecuted { cycle: u32, moves: usize },
    /// `CYCL CALL PAT`.
    PatternCall { cycle: u32, points: usize, moves: usize },
    /// `CYCL CALL POS`.
    PosCall { cycle: u32, moves: usize },
    /// Cycle 220/221 (`cycle`) calling the stored cycle `called` at its points.
    PatternCycle { cycle: u32, called: Option<u32>, points: usize, moves: usize },
    /// Q366=2 ([`unconfirmed::POCKET_RECIPROCATING_AS_VERTICAL`]).
    ReciprocatingPlunge { cycle: u32 },
    /// Q389 ([`unconfirmed::CYCLE232_STRATEGY`]).
    FaceStrategy { cycle: u32, strategy: f64 },
    /// Cycle 233 as 232 ([`unconfirmed::CYCLE233_AS_232`]).
    Cycle233AsMeander,
    /// An FN function the simulator does not model.
    FnNotSimulated { number: u32, text: String },
    /// `FN 28: TABREAD` without the table: each parameter kept (`Some`) or assumed 0 (`None`).
    Tabread { values: Vec<(u32, Option<f64>)> },
    /// `FN 18: SYSREAD ID…` read `value` into Q`target`; `default_tool`: of a tool the table does
    /// not have.
    SysRead { id: u32, target: u32, value: f64, default_tool: Option<u32> },
    /// `FN 18: SYSREAD` of an ID the simulator does not know.
    SysReadNotSimulated { id: u32, target: u32 },
    /// A tool length read as the difference to a zero tool ([`unconfirmed::physical_tool_length`]).
    ZeroToolLength { written: f64, simulated: f64 },
    /// A called tool the table does not have (named by `name` when it was called by it).
    ToolNotInTable { number: u32, name: String, length: f64, radius: f64 },
    /// A tool axis other than Z.
    ToolAxis { axis: char },
    /// `TOOL DEF`.
    ToolDef,
    /// `QS…` string parameters.
    QsNotSimulated { index: u32 },
    /// `TCH PROBE`.
    TouchProbe { cycle: u32 },
    /// A setup sheet's blank when the program has a BLK FORM of its own.
    HeaderBlankIgnored,
    /// A setup sheet's cuboid blank (X, Y, Z size) taken as the program's blank.
    HeaderBlank { size: [f64; 3] },
}

/// German and English owned.
fn t(de: String, en: String) -> Text {
    Text::owned(de, en)
}

impl Note {
    /// What the note says, in German and English.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            Note::TcpmOn { word, spatial } => {
                let mut de = format!(
                    "{word}: TCPM aktiv – die Werkzeugspitze bleibt auf dem programmierten Punkt, die Linearachsen gleichen die Drehachsen aus"
                );
                let mut en = format!(
                    "{word}: TCPM on – the tool tip stays on the programmed point, the linear axes compensate the rotary axes"
                );
                if *spatial {
                    de.push_str("; A, B, C sind Raumwinkel (AXIS SPAT)");
                    en.push_str("; A, B, C are spatial angles (AXIS SPAT)");
                }
                t(de, en)
            }
            Note::TcpmOff { word } => t(format!("{word}: TCPM aus"), format!("{word}: TCPM off")),
            Note::Halt { word } => t(
                format!("{word}: die Steuerung hält hier an (weiter mit NC-Start); der Trainer läuft weiter"),
                format!("{word}: the control stops here (continue with NC start); the trainer runs on"),
            ),
            Note::OptionalStop => Text::new(
                "M1: wahlweiser Programmhalt (nur mit Programmiertem Halt); der Trainer läuft weiter",
                "M1: optional program stop (only with optional stop on); the trainer runs on",
            ),
            Note::Assumed { decision } => decision.text(),
            Note::MNotSimulated { m } => {
                let words = m.iter().map(|f| format!("M{f}")).collect::<Vec<_>>().join(", ");
                t(format!("{words} nicht simuliert"), format!("{words} not simulated"))
            }
            Note::AfterEnd => Text::new(
                "Nach Programmende (M30/M2): nicht ausgeführt",
                "After program end (M30/M2): not executed",
            ),
            Note::BlockSkipped => Text::new("Satz ausgeblendet (/)", "Block skipped (/)"),
            Note::Inch => Text::new(
                "Programm in Inch: Längen in Zoll (× 25,4 mm), F in 1/10 inch/min",
                "Program in inches: lengths × 25.4 mm, F in 1/10 inch/min",
            ),
            Note::CircleCentre => {
                Text::new("CC: Kreismittelpunkt/Pol (keine Bewegung)", "CC: circle centre/pole (no motion)")
            }
            Note::PatternDef { items } => t(
                format!("PATTERN DEF: {items} Element(e) für CYCL CALL PAT"),
                format!("PATTERN DEF: {items} item(s) for CYCL CALL PAT"),
            ),
            Note::CallPgm { path } => {
                t(format!("CALL PGM {path}: nicht simuliert"), format!("CALL PGM {path}: not simulated"))
            }
            Note::BlockNotSimulated { text } => {
                t(format!("Satz nicht simuliert: {text}"), format!("Block not simulated: {text}"))
            }
            Note::PositioningMissing => Text::new(
                "MOVE/TURN/STAY fehlt: wie STAY behandelt",
                "MOVE/TURN/STAY missing: treated as STAY",
            ),
            Note::Retract { feed: None } => Text::new(
                "M140: Rückzug in Werkzeugachsrichtung (Eilgang)",
                "M140: retraction in the tool axis direction (rapid)",
            ),
            Note::Retract { feed: Some(f) } => {
                let assumed = Decision::M140Feed.text();
                t(
                    format!(
                        "M140: Rückzug in Werkzeugachsrichtung mit {} mm/min – {}",
                        prose(*f, None, Lang::De),
                        assumed.de
                    ),
                    format!(
                        "M140: retraction in the tool axis direction at {} mm/min – {}",
                        prose(*f, None, Lang::En),
                        assumed.en
                    ),
                )
            }
            Note::Cycle19AnglesFollow => Text::new(
                "Zyklus 19: die Winkel folgen im Satz 19.1",
                "Cycle 19: the angles follow in block 19.1",
            ),
            Note::Cycle19Reset => Text::new("Zyklus 19 zurückgesetzt", "Cycle 19 reset"),
            Note::Cycle19MovesAxes => {
                Text::new("Zyklus 19 positioniert die Achsen", "Cycle 19 positions the axes")
            }
            Note::Cycle19Active => Text::new(
                "Zyklus 19 aktiv: Drehachsen mit L A+Q120 … positionieren",
                "Cycle 19 active: position the rotary axes with L A+Q120 …",
            ),
            Note::AxisSpat { spatial: [a, b, c], chosen, missing } => {
                let deg = |v: &f64| signed(*v, 4);
                let words = format!("SPA{} SPB{} SPC{}", deg(a), deg(b), deg(c));
                if *missing {
                    t(
                        format!(
                            "AXIS SPAT: {words} → {chosen}; im ersten Satz alle drei Raumwinkel programmieren, fehlende gelten als 0°"
                        ),
                        format!(
                            "AXIS SPAT: {words} → {chosen}; program all three spatial angles in the first block, missing ones count as 0°"
                        ),
                    )
                } else {
                    let s = format!("AXIS SPAT: {words} → {chosen}");
                    t(s.clone(), s)
                }
            }
            Note::ArcRotaryAxis => Text::new(
                "Drehachse im Kreissatz nicht simuliert",
                "Rotary axis in an arc block not simulated",
            ),
            Note::Cycle11NotSimulated => {
                Text::new("Zyklus 11 (Maßfaktor) nicht simuliert", "Cycle 11 (scaling) not simulated")
            }
            Note::OldCycleDefined { cycle } => t(
                format!("Zyklus {cycle} (alte Form) definiert"),
                format!("Cycle {cycle} (old form) defined"),
            ),
            Note::CycleDefined { cycle } => t(
                format!("Zyklus {cycle} definiert, wirkt beim Aufruf"),
                format!("Cycle {cycle} defined, acts when called"),
            ),
            Note::CycleDefinedParamsFromQ { cycle } => t(
                format!(
                    "Zyklus {cycle} ohne Parameterzeilen definiert: beim Aufruf gelten die Q-Parameter Q200 … wie dann gesetzt"
                ),
                format!(
                    "Cycle {cycle} defined without parameter lines: its call uses the Q parameters Q200 … as set then"
                ),
            ),
            Note::CycleNotSimulated { cycle } => {
                t(format!("Zyklus {cycle} nicht simuliert"), format!("Cycle {cycle} not simulated"))
            }
            Note::CycleExecuted { cycle, moves } => t(
                format!("Zyklus {cycle} ausgeführt ({moves} Bewegungen in der Bearbeitungsebene)"),
                format!("Cycle {cycle} executed ({moves} moves in the working plane)"),
            ),
            Note::PatternCall { cycle, points, moves } => t(
                format!("CYCL CALL PAT: Zyklus {cycle} an {points} Punkten ausgeführt ({moves} Bewegungen)"),
                format!("CYCL CALL PAT: cycle {cycle} executed at {points} points ({moves} moves)"),
            ),
            Note::PosCall { cycle, moves } => t(
                format!("CYCL CALL POS: Zyklus {cycle} ausgeführt ({moves} Bewegungen)"),
                format!("CYCL CALL POS: cycle {cycle} executed ({moves} moves)"),
            ),
            Note::PatternCycle { cycle, called, points, moves } => {
                let called = called.map_or_else(String::new, |n| n.to_string());
                t(
                    format!(
                        "Zyklus {cycle}: Zyklus {called} an {points} Punkten ausgeführt ({moves} Bewegungen)"
                    ),
                    format!("Cycle {cycle}: cycle {called} executed at {points} points ({moves} moves)"),
                )
            }
            Note::ReciprocatingPlunge { cycle } => t(
                format!("Zyklus {cycle}: pendelndes Eintauchen (Q366=2) senkrecht simuliert"),
                format!("Cycle {cycle}: reciprocating plunge (Q366=2) simulated vertically"),
            ),
            Note::FaceStrategy { cycle, strategy } => t(
                format!("Zyklus {cycle}: Strategie Q389={strategy} als Mäander simuliert"),
                format!("Cycle {cycle}: strategy Q389={strategy} simulated as a meander"),
            ),
            Note::Cycle233AsMeander => Text::new(
                "Zyklus 233: als Mäander ohne Begrenzungen (Q347–Q349) simuliert",
                "Cycle 233: simulated as a meander without limits (Q347–Q349)",
            ),
            Note::FnNotSimulated { number, text } => t(
                format!("FN {number}: {text} – wird nicht simuliert"),
                format!("FN {number}: {text} – not simulated"),
            ),
            Note::Tabread { values } => {
                let said = |lang: Lang| {
                    let each = values.iter().map(|&(index, kept)| {
                        let name = QName(index);
                        match (kept, lang) {
                            (Some(v), Lang::De) => format!("{name} bleibt {}", prose(v, Some(4), lang)),
                            (Some(v), Lang::En) => format!("{name} stays {}", prose(v, Some(4), lang)),
                            (None, Lang::De) => format!("{name} = 0 angenommen"),
                            (None, Lang::En) => format!("{name} = 0 assumed"),
                        }
                    });
                    each.collect::<Vec<_>>().join(", ")
                };
                t(
                    format!("FN 28: TABREAD – die Tabelle wird nicht simuliert: {}", said(Lang::De)),
                    format!("FN 28: TABREAD – the table is not simulated: {}", said(Lang::En)),
                )
            }
            Note::SysRead { id, target, value, default_tool } => {
                let target = QName(*target);
                let (de, en) = match default_tool {
                    Some(n) => (
                        format!(" (Werkzeug {n} nicht in der Werkzeugtabelle: Standardwerkzeug)"),
                        format!(" (tool {n} not in the tool table: the default tool)"),
                    ),
                    None => Default::default(),
                };
                t(
                    format!("FN 18: ID{id} gelesen: {target} = {}{de}", prose(*value, Some(4), Lang::De)),
                    format!("FN 18: ID{id} read: {target} = {}{en}", prose(*value, Some(4), Lang::En)),
                )
            }
            Note::SysReadNotSimulated { id, target } => {
                let target = QName(*target);
                t(
                    format!("FN 18: ID{id} wird nicht simuliert, {target} bleibt unverändert"),
                    format!("FN 18: ID{id} is not simulated, {target} stays as it was"),
                )
            }
            Note::ZeroToolLength { written, simulated } => {
                let num = |v: f64| signed(v, 3);
                let (l, sim, l0) = (num(*written), num(*simulated), num(unconfirmed::ZERO_TOOL_LENGTH));
                t(
                    format!(
                        "L={l} gilt als Differenz zum Nullwerkzeug: simuliert mit L={sim} (Nullwerkzeug L={l0} angenommen)"
                    ),
                    format!(
                        "L={l} counts as the difference to a zero tool: simulated with L={sim} (zero tool L={l0} assumed)"
                    ),
                )
            }
            Note::ToolNotInTable { number, name, length: l, radius: r } => {
                // A tool called by name is named by it, not by the number 0 it gets.
                let n = if name.is_empty() { number.to_string() } else { format!("\"{name}\"") };
                t(
                    format!("Werkzeug {n} nicht in der Werkzeugtabelle: L={l} R={r} angenommen"),
                    format!("Tool {n} not in the tool table: assuming L={l} R={r}"),
                )
            }
            Note::ToolAxis { axis } => t(
                format!("Werkzeugachse {axis}: simuliert wird mit Werkzeugachse Z"),
                format!("Tool axis {axis}: simulated with tool axis Z"),
            ),
            Note::ToolDef => {
                Text::new("TOOL DEF: Werkzeug im Programm definiert", "TOOL DEF: tool defined in the program")
            }
            Note::QsNotSimulated { index } => t(
                format!("QS{index}: String-Parameter werden nicht simuliert"),
                format!("QS{index}: string parameters are not simulated"),
            ),
            Note::TouchProbe { cycle } => t(
                format!("TCH PROBE {cycle}: Tastsystemzyklus wird nicht simuliert"),
                format!("TCH PROBE {cycle}: touch-probe cycle not simulated"),
            ),
            Note::HeaderBlankIgnored => Text::new(
                "Rohteil des Einrichteblatts: das Programm hat eine BLK FORM, sie gilt",
                "Blank of the setup sheet: the program has a BLK FORM, which applies",
            ),
            Note::HeaderBlank { size: [x, y, z] } => {
                let sizes = |l| {
                    let n = |v: &f64| prose(*v, None, l);
                    (
                        format!("{} × {} × {} mm", n(x), n(y), n(z)),
                        format!("X0…{} Y0…{} Z−{}…0", n(x), n(y), n(z)),
                    )
                };
                let ((de, de_blk), (en, en_blk)) = (sizes(Lang::De), sizes(Lang::En));
                t(
                    format!("Rohteil des Einrichteblatts {de} als BLK FORM {de_blk}"),
                    format!("Blank of the setup sheet {en} as BLK FORM {en_blk}"),
                )
            }
        }
    }
}
