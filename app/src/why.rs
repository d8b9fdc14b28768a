//! The "why" panel's content for the cursor block: what the block does, in one or two
//! sentences, and for a PLANE block the solver's explanation — both candidate axis positions,
//! limits, path lengths, the rule that decided, the symmetry point and the equivalent SPATIAL and
//! EULER angles. Pure: the component only renders the lines.

use glam::DMat3;
use schwenkbar_core::BlockBody;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::format::plane_angles;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::number::{localise, prose, prose_vec};
use schwenkbar_core::plane::{PlaneBlock, PlaneDef, RotaryAxis};
use schwenkbar_core::sim::{Simulation, State};
use schwenkbar_core::solve::{Explanation, SolveOptions, axis_words, fmt_deg, solve_block};

use crate::i18n::Lang;

/// One PLANE solve as the panel shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneWhy {
    /// What the machine does, in plain words first ("Keine B-Achse: C dreht auf +90°, dann
    /// kippt A auf +15°"); empty when it cannot position.
    pub plain: String,
    pub spatial: String,
    pub euler: String,
    pub tool_axis: String,
    /// One line per candidate: axis words, limits, path, chosen or why not.
    pub candidates: Vec<(String, bool)>,
    /// The candidates' axis values (hovering one shows it as the ghost in the 3D view).
    pub candidate_axes: Vec<AxisValues>,
    pub rule: String,
    pub symmetry: String,
    /// The control's message if it refuses the block.
    pub error: Option<String>,
    /// The block's swivel collides and the other solution's would not: says so (the view
    /// shows that solution as the ghost).
    pub safe_alternative: Option<String>,
    /// The UNCONFIRMED assumptions that influenced the result.
    pub assumptions: Vec<String>,
}

/// Explains a PLANE block on `machine`, with the rotary axes starting at `opts.start` and the
/// tilt active before it `active` (identity when nothing is tilted).
#[must_use]
pub fn explain_plane(
    block: &PlaneBlock,
    machine: &Machine,
    active: DMat3,
    opts: &SolveOptions,
    l: Lang,
) -> PlaneWhy {
    let Ok(block) = block.numbers() else {
        return PlaneWhy {
            error: Some(
                l.t(
                    "Der Satz enthält Q-Parameter: ihre Werte kennt erst der Programmlauf.",
                    "The block uses Q parameters: their values are known only when the program runs.",
                )
                .to_owned(),
            ),
            ..PlaneWhy::empty()
        };
    };
    match solve_block(machine, &block, active, opts) {
        Ok(e) => from_explanation(&e, l),
        Err(err) => PlaneWhy { error: Some(err.message().get(l).to_owned()), ..PlaneWhy::empty() },
    }
}

impl PlaneWhy {
    fn empty() -> PlaneWhy {
        PlaneWhy {
            plain: String::new(),
            spatial: String::new(),
            euler: String::new(),
            tool_axis: String::new(),
            candidates: Vec::new(),
            candidate_axes: Vec::new(),
            rule: String::new(),
            symmetry: String::new(),
            error: None,
            safe_alternative: None,
            assumptions: Vec::new(),
        }
    }
}

/// The panel for block `index`: from the simulation (real start positions, the active plane
/// before it), where the control stopped if it stopped there, else solved on its own from A0 C0.
#[must_use]
pub fn for_block(
    program: &schwenkbar_core::Program,
    sim: Option<&Simulation>,
    shown: Option<&State>,
    index: usize,
    machine: &Machine,
    l: Lang,
) -> Option<PlaneWhy> {
    let BlockBody::Plane(block) = program.blocks.get(index)?.stored_body()? else { return None };
    if let Some(e) = sim.and_then(|s| s.error.as_ref()).filter(|e| e.block == index) {
        let note = sim.and_then(Simulation::collision).and_then(|c| c.alternative_note());
        return Some(PlaneWhy {
            error: Some(format!("{} — {}", e.message.get(l), e.detail.get(l))),
            safe_alternative: note.map(|n| n.get(l).to_owned()),
            ..PlaneWhy::empty()
        });
    }
    let from_sim = shown.filter(|s| s.block == index).cloned().or_else(|| {
        let sim = sim?;
        let step = sim.step_of_block(index)?;
        sim.state_at(program, step)
    });
    match from_sim.and_then(|s| s.explanation) {
        Some(e) => Some(from_explanation(&e, l)),
        None => Some(explain_plane(block, machine, DMat3::IDENTITY, &SolveOptions::default(), l)),
    }
}

fn from_explanation(e: &Explanation, l: Lang) -> PlaneWhy {
    let [a, b, c] = e.spatial();
    let [pr, nu, rot] = e.euler();
    let [tx, ty, tz] = e.tool_axis;
    let candidates = e
        .candidates
        .iter()
        .enumerate()
        .map(|(i, cand)| {
            let axes = axis_words(&cand.axes);
            let limits = if cand.in_limits {
                l.t("in den Endschaltern", "inside the limits")
            } else {
                l.t("außerhalb der Endschalter", "outside the limits")
            };
            let chosen = e.chosen == Some(i);
            let verdict =
                if chosen { l.t("gewählt", "chosen") } else { l.t("nicht gewählt", "not chosen") };
            let path = prose(cand.path, Some(1), l);
            (format!("{} · {limits} · {} {path}° · {verdict}", axes, l.t("Weg", "path")), chosen)
        })
        .collect();
    PlaneWhy {
        plain: plain_words(e, l),
        candidate_axes: e.candidates.iter().map(|c| c.axes).collect(),
        spatial: plane_angles(PlaneDef::Spatial { spa: a, spb: b, spc: c }),
        euler: plane_angles(PlaneDef::Euler { eulpr: pr, eulnu: nu, eulrot: rot }),
        tool_axis: prose_vec([tx, ty, tz], 4, l),
        candidates,
        rule: e.rule.text().get(l).to_owned(),
        symmetry: format!(
            "{} {}: {}",
            l.t("Symmetriepunkt der Master-Achse", "Symmetry point of the master axis"),
            e.master.letter(),
            fmt_deg(e.symmetry_point)
        ),
        error: e.error_message.map(|m| m.0.message().get(l).to_owned()),
        safe_alternative: None,
        assumptions: e.decisions.iter().map(|d| d.text().get(l).to_owned()).collect(),
    }
}

/// The chosen positioning in plain words: the slave axis turns, then the master axis tilts
/// (the order in which the solution is built: the slave brings the tilt direction round, the
/// master tilts; on the machine both move together). A single tilt about X or Y that the
/// machine has no axis for is named first: "Keine B-Achse: C dreht auf +90°, dann kippt A
/// auf +15°."
fn plain_words(e: &Explanation, l: Lang) -> String {
    let Some(chosen) = e.chosen_axes() else { return String::new() };
    let [spa, spb, _] = e.spatial();
    let on_machine = |axis: RotaryAxis| e.master == axis || e.slave == axis;
    let missing = match (spa.abs() > 1e-9, spb.abs() > 1e-9) {
        (true, false) if !on_machine(RotaryAxis::A) => Some('A'),
        (false, true) if !on_machine(RotaryAxis::B) => Some('B'),
        _ => None,
    };
    let prefix = missing.map_or_else(String::new, |axis| match l {
        Lang::De => format!("Keine {axis}-Achse: "),
        Lang::En => format!("No {axis} axis: "),
    });
    // (axis letter, verb, preposition, target) of an axis: "dreht", "auf", "+90°".
    let part = |axis: RotaryAxis, verb_de: &'static str, verb_en: &'static str| {
        let value = chosen.get(axis).unwrap_or(0.0);
        let stays = (value - e.start.get(axis).unwrap_or(0.0)).abs() < 1e-9;
        let (verb, prep) = match (stays, l) {
            (true, Lang::De) => ("bleibt", "auf"),
            (true, Lang::En) => ("stays", "at"),
            (false, Lang::De) => (verb_de, "auf"),
            (false, Lang::En) => (verb_en, "to"),
        };
        (axis.letter(), verb, prep, format!("{}°", localise(fmt_deg(value), l)))
    };
    let (s_axis, s_verb, s_prep, s_to) = part(e.slave, "dreht", "turns");
    let (m_axis, m_verb, m_prep, m_to) = part(e.master, "kippt", "tilts");
    let first = format!("{prefix}{s_axis} {s_verb} {s_prep} {s_to}");
    match l {
        // German puts the verb second after "dann".
        Lang::De => format!("{first}, dann {m_verb} {m_axis} {m_prep} {m_to}."),
        Lang::En => format!("{first}, then {m_axis} {m_verb} {m_prep} {m_to}."),
    }
}

/// What a block does, in one or two sentences.
#[must_use]
pub fn describe(body: &BlockBody, l: Lang) -> &'static str {
    match body {
        BlockBody::BeginPgm { .. } => l.t("Programmanfang: Name und Maßeinheit.", "Program start: name and unit."),
        BlockBody::EndPgm { .. } => l.t("Programmende.", "End of program."),
        BlockBody::Empty | BlockBody::Structure { .. } => {
            l.t("Leersatz oder Gliederung: die Steuerung tut hier nichts.", "Empty block or structure item: nothing happens.")
        }
        BlockBody::BlkForm(_) => l.t(
            "Rohteil-Definition für die Grafik: MIN- und MAX-Punkt im Werkstück-Koordinatensystem.",
            "Blank form for the graphics: MIN and MAX point in the workpiece coordinate system.",
        ),
        BlockBody::ToolCall(_) => l.t(
            "Werkzeugaufruf: Werkzeug, Werkzeugachse, Drehzahl und Vorschub.",
            "Tool call: tool, tool axis, spindle speed and feed.",
        ),
        BlockBody::L(_) => l.t(
            "Gerade: fährt auf die programmierten Koordinaten (Eingabe-KS I-CS; mit M91 Maschinen-Koordinaten).",
            "Straight line to the programmed coordinates (input CS I-CS; with M91 machine coordinates).",
        ),
        BlockBody::Plane(p) if matches!(p.def, schwenkbar_core::plane::PlaneDef::Reset) => l.t(
            "PLANE RESET setzt die Schwenkung zurück; mit MOVE/TURN schwenken auch die Drehachsen zurück, mit STAY bleiben sie stehen.",
            "PLANE RESET cancels the tilt; with MOVE/TURN the rotary axes return too, with STAY they stay tilted.",
        ),
        BlockBody::Plane(_) => l.t(
            "Schwenkt die Bearbeitungsebene: die Steuerung rechnet die Raumlage in Achswinkel der Maschine um und wählt eine der möglichen Lösungen.",
            "Tilts the working plane: the control converts the orientation into the machine's axis angles and picks one of the possible solutions.",
        ),
        BlockBody::CycleDef(_) | BlockBody::CycleDefOld(_) => l.t(
            "Zyklusdefinition: wirkt erst beim Aufruf (M99 oder CYCL CALL), außer bei Koordinatentransformationen.",
            "Cycle definition: acts only when called (M99 or CYCL CALL), except coordinate transformations.",
        ),
        BlockBody::CyclCall { .. } | BlockBody::CyclCallPat { .. } | BlockBody::CyclCallPos(_) => {
            l.t("Ruft den zuletzt definierten Zyklus auf.", "Calls the last defined cycle.")
        }
        BlockBody::PatternDef(_) => l.t(
            "Musterdefinition: Bearbeitungspositionen für CYCL CALL PAT in der Bearbeitungsebene.",
            "Pattern definition: machining positions for CYCL CALL PAT in the working plane.",
        ),
        BlockBody::Appr(_) | BlockBody::Dep(_) => l.t(
            "Anfahren oder Verlassen der Kontur auf einer Geraden oder einem Kreisbogen.",
            "Approaching or departing the contour on a straight line or an arc.",
        ),
        BlockBody::FnJump(_) => l.t(
            "Bedingter Sprung: ist die Bedingung erfüllt, geht es bei der Marke LBL weiter.",
            "Conditional jump: if the condition holds, the program continues at the label LBL.",
        ),
        BlockBody::TransDatum { .. } | BlockBody::TransDatumReset => l.t(
            "Nullpunktverschiebung: vor dem Schwenken verschiebt sie den Ursprung der Bearbeitungsebene (WPL-CS).",
            "Datum shift: before tilting it moves the origin of the working plane (WPL-CS).",
        ),
        BlockBody::TransMirror { .. } | BlockBody::TransMirrorReset => l.t(
            "Spiegelung: vor dem Schwenken spiegelt sie auch die Raumwinkel.",
            "Mirroring: before tilting it mirrors the spatial angles too.",
        ),
        BlockBody::TransRotation { .. } | BlockBody::TransRotationReset => l.t(
            "Drehung in der Bearbeitungsebene (um die Werkzeugachse).",
            "Rotation in the working plane (about the tool axis).",
        ),
        BlockBody::FunctionTcpm(_) | BlockBody::FunctionResetTcpm => l.t(
            "TCPM: die Werkzeugspitze bleibt auf dem programmierten Punkt, während die Drehachsen drehen; FUNCTION RESET TCPM schaltet es aus.",
            "TCPM: the tool tip stays on the programmed point while the rotary axes turn; FUNCTION RESET TCPM switches it off.",
        ),
        BlockBody::Lbl(_) | BlockBody::CallLbl { .. } | BlockBody::CallPgm { .. } => {
            l.t("Unterprogramm: Marke oder Aufruf.", "Subprogram: label or call.")
        }
        BlockBody::QAssign { .. } | BlockBody::FnMath(_) => l.t("Weist einem Q-Parameter einen Wert zu.", "Assigns a value to a Q parameter."),
        BlockBody::MFunctions(..) => l.t("Zusatzfunktionen (M).", "Miscellaneous functions (M)."),
        BlockBody::Unknown { .. } => l.t(
            "Ein Satz, den dieser Trainer nicht nachbildet: er wird angezeigt, aber nicht ausgeführt.",
            "A block this trainer does not model: shown, not executed.",
        ),
        BlockBody::Invalid { .. } => l.t("Dieser Satz ist fehlerhaft (siehe Meldung).", "This block is invalid (see the message)."),
        _ => l.t("Bahnfunktion.", "Path function."),
    }
}

/// The machine under the why panel: its name and rotary axes, master first, with their limit
/// switches (`A/C-Schwenktisch · Master zuerst: A (-120…120), C (endlos)`).
#[must_use]
pub fn machine_line(m: &Machine, l: Lang) -> String {
    let axes: Vec<String> = m
        .joints()
        .iter()
        .rev()
        .map(|j| {
            let limits = match (j.endless, j.limits) {
                (true, _) => l.t("endlos", "endless").to_owned(),
                (false, Some(lim)) => format!("{}…{}", lim.min, lim.max),
                (false, None) => l.t("ohne Endschalter", "no limits").to_owned(),
            };
            format!("{} ({limits})", j.axis.letter())
        })
        .collect();
    format!("{} · {}: {}", l.t(&m.name.de, &m.name.en), l.t("Master zuerst", "master first"), axes.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(text: &str) -> PlaneBlock {
        schwenkbar_core::parse::plane_block(text).expect("a PLANE block")
    }

    #[test]
    fn the_machine_line_names_the_rotary_axes_master_first_with_their_limits() {
        // static/machines/ba-table.json: B endless on A −100…180; ac-table has no limits.
        let m = Machine::builtin("ba-table").expect("shipped");
        assert_eq!(
            machine_line(&m, Lang::De),
            "B-Rundtisch auf A-Schwenktisch · Master zuerst: A (-100…180), B (endlos)"
        );
        let m = Machine::builtin("ac-table").expect("shipped");
        assert_eq!(
            machine_line(&m, Lang::En),
            "C rotary table on A tilting table · master first: A (no limits), C (no limits)"
        );
    }

    #[test]
    fn seed_table_row_shows_both_candidates_and_the_rule() {
        let m = Machine::builtin("ac-table").expect("shipped");
        let why = explain_plane(
            &plane("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SEQ-"),
            &m,
            DMat3::IDENTITY,
            &SolveOptions::default(),
            Lang::De,
        );
        assert_eq!(why.error, None);
        assert_eq!(why.candidates.len(), 2);
        let chosen: Vec<_> = why.candidates.iter().filter(|c| c.1).collect();
        assert_eq!(chosen.len(), 1);
        assert!(chosen[0].0.contains("A-45") && chosen[0].0.contains("C-90"), "{chosen:?}");
        assert!(why.rule.contains("SEQ"), "{}", why.rule);
        assert_eq!(why.spatial, "PLANE SPATIAL SPA+0 SPB+45 SPC+0");
    }

    #[test]
    fn plain_words_come_first_and_name_the_missing_axis() {
        let m = Machine::builtin("ac-table").expect("shipped");
        let why = |text: &str, l: Lang| {
            explain_plane(&plane(text), &m, DMat3::IDENTITY, &SolveOptions::default(), l).plain
        };
        // Musterprogramm 1, block 10: a tilt about Y on a machine with A and C only.
        assert_eq!(
            why("PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX", Lang::De),
            "Keine B-Achse: C dreht auf +90°, dann kippt A auf +15°."
        );
        assert_eq!(
            why("PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX", Lang::En),
            "No B axis: C turns to +90°, then A tilts to +15°."
        );
        // A tilt about X needs no turn of C: the machine has the A axis.
        assert_eq!(
            why("PLANE SPATIAL SPA+12.5 SPB+0 SPC+0 STAY", Lang::De),
            "C bleibt auf +0°, dann kippt A auf +12,5°."
        );
        let both = explain_plane(
            &plane("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX"),
            &m,
            DMat3::IDENTITY,
            &SolveOptions::default(),
            Lang::De,
        );
        assert_eq!(
            both.candidate_axes.len(),
            both.candidates.len(),
            "each candidate can be shown as the ghost"
        );
    }

    #[test]
    fn refused_block_says_winkel_nicht_erlaubt() {
        let m = Machine::builtin("ba-table").expect("shipped");
        let why = explain_plane(
            &plane("PLANE SPATIAL SPA-45 SPB+0 SPC+0 TURN FMAX SYM-"),
            &m,
            DMat3::IDENTITY,
            &SolveOptions::default(),
            Lang::De,
        );
        assert!(why.error.as_deref().is_some_and(|e| e.starts_with("Winkel nicht erlaubt")), "{why:?}");
    }

    #[test]
    fn q_parameters_are_explained_not_guessed() {
        let m = Machine::builtin("ac-table").expect("shipped");
        let why = explain_plane(
            &plane("PLANE SPATIAL SPA+0 SPB+Q27 SPC+0 STAY"),
            &m,
            DMat3::IDENTITY,
            &SolveOptions::default(),
            Lang::En,
        );
        assert!(why.error.as_deref().is_some_and(|e| e.contains("Q parameters")));
    }
}
