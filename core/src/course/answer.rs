//! Reading a trainee's answer the way the control reads input: axis words (`A+45 C+90`, also
//! inside `PLANE AXIAL …` or `L …`), numbers with a decimal point or comma, and "the control
//! refuses" as its own answer.

use super::expected::ValueCheck;
use super::{Hint, RunKind, VALUE_TOL, Verdict};
use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::Machine;
use crate::number::parse_input;
use crate::plane::{RotaryAxis, TransformMode};
use crate::solve::{Explanation, axis_words};

/// A trainee's answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Answer {
    /// What was typed.
    Text(String),
    /// "The control refuses this block" (the softkey for it, or typed as the control's message).
    ControlError,
}

impl Answer {
    /// Typed text; the control's refusal typed out (`Winkel nicht erlaubt`, `Fehler`) counts as
    /// [`Answer::ControlError`].
    #[must_use]
    pub fn typed(text: &str) -> Answer {
        let lower = text.to_lowercase();
        let refusal = ["nicht erlaubt", "nicht berechenbar", "fehler", "not permitted", "error"];
        if refusal.iter().any(|w| lower.contains(w)) {
            Answer::ControlError
        } else {
            Answer::Text(text.to_owned())
        }
    }
}

/// The axis words of an answer; `Err` names the first word that looks like one but isn't.
fn typed_axes(text: &str) -> Result<AxisValues, Text> {
    let mut out = AxisValues::default();
    for word in text.split_whitespace() {
        let mut chars = word.chars();
        let (Some(letter), rest) = (chars.next(), chars.as_str()) else { continue };
        let Some(axis) = RotaryAxis::from_letter(&letter.to_ascii_uppercase().to_string()) else { continue };
        // "AXIAL" and the like are words, not axis values.
        if !rest.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | ',')) {
            continue;
        }
        let Some(v) = parse_input(rest) else {
            return Err(Text::owned(
                format!("Eingabe nicht lesbar: {word}"),
                format!("Cannot read the entry: {word}"),
            ));
        };
        out.set(axis, v);
    }
    Ok(out)
}

pub(super) fn same(a: &AxisValues, b: &AxisValues) -> bool {
    a.iter().all(|(axis, v)| b.get(axis).is_some_and(|w| (v - w).abs() <= VALUE_TOL))
}

pub(super) fn check_axes(
    answer: &Answer,
    machine: &Machine,
    e: &Explanation,
    other_mode: Option<&AxisValues>,
) -> Verdict {
    let reason = e.rule.text();
    let Some(chosen) = e.chosen_axes() else {
        return match answer {
            Answer::ControlError => {
                let detail = e.error.map_or_else(|| Text::new("", ""), |err| err.detail());
                let m = super::expected::refusal(e);
                Verdict::Correct(Text::owned(
                    format!("Richtig: die Steuerung meldet „{}“. {}", m.de, detail.de),
                    format!("Correct: the control reports \"{}\". {}", m.en, detail.en),
                ))
            }
            Answer::Text(_) => Verdict::Wrong {
                hint: Hint::ControlRefuses,
                text: Text::new(
                    "Prüfen Sie jede Lösung gegen die Endschalter und die Option (SEQ/SYM): bleibt keine übrig, meldet die Steuerung einen Fehler",
                    "Check each solution against the limit switches and the option (SEQ/SYM): if none is left, the control reports an error",
                ),
            },
        };
    };
    let Answer::Text(text) = answer else {
        // With COORD ROT/TABLE ROT there are no limits or options to check: say what the mode does.
        let text = match other_mode {
            Some(_) => {
                let t = transform_hint(e, false);
                Text::owned(
                    format!("Die Steuerung findet hier eine Stellung. {}", t.de),
                    format!("The control finds a position here. {}", t.en),
                )
            }
            None => Text::new(
                "Die Steuerung findet hier eine erlaubte Lösung. Prüfen Sie beide Lösungen noch einmal gegen Endschalter und Option",
                "The control finds a permitted solution here. Check both solutions against the limit switches and the option again",
            ),
        };
        return Verdict::Wrong { hint: Hint::ControlFinds, text };
    };
    let given = match typed_axes(text) {
        Ok(g) => g,
        Err(t) => return Verdict::Unreadable(t),
    };
    let missing: Vec<char> =
        machine.joints().iter().filter(|j| given.get(j.axis).is_none()).map(|j| j.axis.letter()).collect();
    if !missing.is_empty() {
        let list = missing.iter().map(char::to_string).collect::<Vec<_>>().join(", ");
        return Verdict::Unreadable(Text::owned(
            format!("Bitte beide Drehachsen angeben, es fehlt: {list}"),
            format!("Please give both rotary axes, missing: {list}"),
        ));
    }
    if same(&chosen, &given) {
        return Verdict::Correct(Text::owned(
            format!("Richtig: {}. Grund: {}", axis_words(&chosen), reason.de),
            format!("Correct: {}. Reason: {}", axis_words(&chosen), reason.en),
        ));
    }
    if e.candidates.iter().any(|c| same(&c.axes, &given)) {
        return Verdict::Wrong {
            hint: Hint::OtherSolution,
            text: Text::owned(
                format!(
                    "Das ist die andere der beiden Lösungen. Welche Regel gilt hier? {}",
                    rule_hint(e).de
                ),
                format!(
                    "That is the other of the two solutions. Which rule applies here? {}",
                    rule_hint(e).en
                ),
            ),
        };
    }
    let (m, s) = (e.master, e.slave);
    if let Some(other) = other_mode {
        return Verdict::Wrong { hint: Hint::Transform, text: transform_hint(e, same(other, &given)) };
    }
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: Text::owned(
            format!(
                "Das ist keine der beiden Lösungen für diese Lage. Die Master-Achse {m} stellt den Kippwinkel ein, die Slave-Achse {s} die Richtung; die zweite Lösung hat {m} gespiegelt am Symmetriepunkt und {s} um 180° versetzt."
            ),
            format!(
                "That is neither of the two solutions for this orientation. The master axis {m} sets the tilt, the slave axis {s} the direction; the second solution has {m} mirrored at the symmetry point and {s} 180° apart."
            ),
        ),
    }
}

/// What COORD ROT or TABLE ROT does when only SPC is non-zero (seed 000 §2.3.3, DOMAIN.md
/// §3.4): the tool stays vertical, so the master axis does not tilt and the free slave axis is
/// either left standing (COORD ROT) or turned (TABLE ROT). `other_mode`: the answer is where the
/// axes go with the other one.
fn transform_hint(e: &Explanation, other_mode: bool) -> Text {
    let (m, s) = (e.master, e.slave);
    let (mixed_de, mixed_en, de, en) = match e.transform {
        TransformMode::TableRot => (
            "Das ist die Stellung mit COORD ROT. ",
            "That is the position with COORD ROT. ",
            format!(
                "TABLE ROT: Der Tisch dreht mit – die freie Drehachse {s} stellt die Drehung um SPC ein. Die Werkzeugachse bleibt senkrecht (nur SPC ist ungleich 0), {m} kippt also nicht."
            ),
            format!(
                "TABLE ROT: the table turns – the free rotary axis {s} realises the turn by SPC. The tool axis stays vertical (only SPC is non-zero), so {m} does not tilt."
            ),
        ),
        TransformMode::CoordRot => (
            "Das ist die Stellung mit TABLE ROT. ",
            "That is the position with TABLE ROT. ",
            format!(
                "COORD ROT: Der Tisch bleibt stehen – {s} behält seine Stellung, die Drehung um SPC rechnet die Steuerung nur ins Koordinatensystem ein. Die Werkzeugachse bleibt senkrecht (nur SPC ist ungleich 0), {m} kippt also nicht."
            ),
            format!(
                "COORD ROT: the table stays – {s} keeps its position, the control applies the turn by SPC to the coordinate system only. The tool axis stays vertical (only SPC is non-zero), so {m} does not tilt."
            ),
        ),
    };
    if other_mode {
        Text::owned(format!("{mixed_de}{de}"), format!("{mixed_en}{en}"))
    } else {
        Text::owned(de, en)
    }
}

/// The hint for the other solution of the same orientation in a run: both axis positions give
/// the same plane, and the rule the solver applied says why the control takes the other one.
fn other_solution_hint(e: &Explanation) -> Text {
    let reason = e.rule.text();
    Text::owned(
        format!(
            "Das ist die andere Lösung derselben Lage: Beide Achsstellungen schwenken die Ebene gleich, die Maschine könnte beide anfahren. Die Steuerung wählt die andere. Grund: {}.",
            reason.de
        ),
        format!(
            "That is the other solution of the same orientation: both axis positions tilt the plane alike, the machine could reach either. The control chooses the other one. Reason: {}.",
            reason.en
        ),
    )
}

/// Which rule decides, without giving the numbers away.
fn rule_hint(e: &Explanation) -> Text {
    if e.selection.is_some() {
        Text::new(
            "Mit SEQ/SYM entscheidet das Vorzeichen der Master-Achse (SEQ: ab 0°, SYM: ab dem Symmetriepunkt).",
            "With SEQ/SYM the master axis' sign decides (SEQ: from 0°, SYM: from the symmetry point).",
        )
    } else {
        Text::new(
            "Ohne SEQ/SYM nimmt die Steuerung die Lösung im Verfahrbereich mit dem kürzeren Weg von der Startposition.",
            "Without SEQ/SYM the control takes the solution inside the travel with the shorter path from the start position.",
        )
    }
}

pub(super) fn check_value(answer: &Answer, c: &ValueCheck) -> Verdict {
    let (value, letter) = (c.value, c.letter);
    let Answer::Text(text) = answer else {
        return Verdict::Wrong {
            hint: Hint::ControlFinds,
            text: Text::new("Die Steuerung arbeitet diesen Satz ab", "The control executes this block"),
        };
    };
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let upper = compact.to_uppercase();
    let prefix = if letter == 'Q' { "Q120" } else { "" };
    let rest = upper.strip_prefix(prefix).unwrap_or(&upper);
    let rest = rest.strip_prefix(letter).unwrap_or(rest);
    let rest = rest.strip_prefix('=').unwrap_or(rest);
    let Some(v) = parse_input(rest) else {
        return Verdict::Unreadable(Text::owned(
            format!(
                "Eingabe nicht lesbar: „{}“ – bitte eine Zahl eingeben, z. B. +45 oder 12,5",
                text.trim()
            ),
            format!("Cannot read \"{}\" – please enter a number, e.g. +45 or 12.5", text.trim()),
        ));
    };
    let shown = if letter == 'Q' { "Q120".to_owned() } else { letter.to_string() };
    let is = |w: f64| (v - w).abs() <= VALUE_TOL;
    if is(value) {
        return Verdict::Correct(Text::owned(
            format!("Richtig: {shown} = {}", crate::number::signed(value, 3)),
            format!("Correct: {shown} = {}", crate::number::signed(value, 3)),
        ));
    }
    if let (Some(e), Some(other)) = (c.decider.as_deref(), c.other_solution())
        && is(other)
    {
        return Verdict::Wrong { hint: Hint::OtherSolution, text: other_solution_hint(e) };
    }
    if c.is_stay() {
        return Verdict::Wrong { hint: Hint::Stay, text: stay_hint(c.kind, c.computed().is_some_and(is)) };
    }
    if c.sign_flipped.is_some_and(is) {
        let about = c.decider.as_deref().map_or([true; 3], |e| super::orientation::non_zero(e.spatial()));
        return Verdict::Wrong { hint: Hint::RightHand, text: super::orientation::right_hand_hint(about) };
    }
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: Text::new(
            "Noch nicht. Öffnen Sie das Programm im Trainer und lassen Sie es Satz für Satz bis zu diesem Satz laufen: die Positionsanzeige zeigt den Wert",
            "Not yet. Open the program in the trainer and run it block by block up to this block: the position display shows the value",
        ),
    }
}

/// What STAY does (seed 000 §2.3.3, §2.3.4; DOMAIN.md §4): only the coordinate system is
/// tilted, the axes do not move, the computed positions wait in Q120–Q122 for a later block.
/// `computed`: the answer is the position the block computed.
fn stay_hint(kind: RunKind, computed: bool) -> Text {
    match kind {
        RunKind::StayQ120 => Text::new(
            "Auch mit STAY rechnet die Steuerung die Achsstellung aus, als ob sie schwenken würde, und legt sie in Q120 bis Q122 ab (Q120 = A). Sie fährt sie nur nicht an: Das macht ein späterer Satz wie L A+Q120 C+Q122 R0 FMAX.",
            "With STAY, too, the control computes the axis position as if it swivelled and stores it in Q120 to Q122 (Q120 = A). It just does not move there: a later block such as L A+Q120 C+Q122 R0 FMAX does.",
        ),
        RunKind::ResetStay => Text::new(
            "PLANE RESET STAY setzt nur die Rechnung zurück: Die Drehachsen fahren nicht und bleiben geschwenkt stehen, bis ein späterer Satz sie zurückfährt (z. B. L A+0 C+0 R0 FMAX).",
            "PLANE RESET STAY only resets the calculation: the rotary axes do not move and stay tilted until a later block moves them back (e.g. L A+0 C+0 R0 FMAX).",
        ),
        _ => {
            let (de, en) = if computed {
                (
                    "Das ist die Stellung, die die Steuerung berechnet – angefahren wird sie mit STAY nicht. ",
                    "That is the position the control computes – with STAY it does not move there. ",
                )
            } else {
                ("", "")
            };
            Text::owned(
                format!(
                    "{de}STAY schwenkt nur das Koordinatensystem, keine Achse fährt: Die Drehachsen bleiben, wo sie vor dem Satz standen. Die berechneten Achswinkel stehen in Q120 bis Q122 für einen späteren Satz wie L A+Q120 C+Q122 R0 FMAX."
                ),
                format!(
                    "{en}STAY only tilts the coordinate system, no axis moves: the rotary axes stay where they were before the block. The computed axis angles are in Q120 to Q122, for a later block such as L A+Q120 C+Q122 R0 FMAX."
                ),
            )
        }
    }
}
