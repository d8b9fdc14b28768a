//! Reading a trainee's answer the way the control reads input: axis words (`A+45 C+90`, also
//! inside `PLANE AXIAL …` or `L …`), numbers with a decimal point or comma, and "the control
//! refuses" as its own answer.

use super::{Hint, VALUE_TOL, Verdict, texts};
use crate::axes::AxisValues;
use crate::machine::{Machine, Texts};
use crate::number::parse_input;
use crate::plane::RotaryAxis;
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
fn typed_axes(text: &str) -> Result<AxisValues, Texts> {
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
            return Err(texts(
                format!("Eingabe nicht lesbar: {word}"),
                format!("Cannot read the entry: {word}"),
            ));
        };
        out.set(axis, v);
    }
    Ok(out)
}

fn same(a: &AxisValues, b: &AxisValues) -> bool {
    a.iter().all(|(axis, v)| b.get(axis).is_some_and(|w| (v - w).abs() <= VALUE_TOL))
}

pub(super) fn check_axes(answer: &Answer, machine: &Machine, e: &Explanation) -> Verdict {
    let reason = texts(e.reason.de(), e.reason.en());
    let Some(chosen) = e.chosen_axes() else {
        return match answer {
            Answer::ControlError => {
                let (de, en) = e.error.map_or((String::new(), String::new()), |err| err.details());
                let m = e
                    .error_message
                    .map_or(("Winkel nicht erlaubt", "Angle not permitted"), |m| (m.de(), m.en()));
                Verdict::Correct(texts(
                    format!("Richtig: die Steuerung meldet „{}“. {de}", m.0),
                    format!("Correct: the control reports \"{}\". {en}", m.1),
                ))
            }
            Answer::Text(_) => Verdict::Wrong {
                hint: Hint::ControlRefuses,
                text: texts(
                    "Prüfe jede Lösung gegen die Endschalter und die Option (SEQ/SYM): bleibt keine übrig, meldet die Steuerung einen Fehler",
                    "Check each solution against the limit switches and the option (SEQ/SYM): if none is left, the control reports an error",
                ),
            },
        };
    };
    let Answer::Text(text) = answer else {
        return Verdict::Wrong {
            hint: Hint::ControlFinds,
            text: texts(
                "Die Steuerung findet hier eine erlaubte Lösung. Prüfe beide Lösungen noch einmal gegen Endschalter und Option",
                "The control finds a permitted solution here. Check both solutions against the limit switches and the option again",
            ),
        };
    };
    let given = match typed_axes(text) {
        Ok(g) => g,
        Err(t) => return Verdict::Unreadable(t),
    };
    let missing: Vec<char> =
        machine.joints().iter().filter(|j| given.get(j.axis).is_none()).map(|j| j.axis.letter()).collect();
    if !missing.is_empty() {
        let list = missing.iter().map(char::to_string).collect::<Vec<_>>().join(", ");
        return Verdict::Unreadable(texts(
            format!("Bitte beide Drehachsen angeben, es fehlt: {list}"),
            format!("Please give both rotary axes, missing: {list}"),
        ));
    }
    if same(&chosen, &given) {
        return Verdict::Correct(texts(
            format!("Richtig: {}. Grund: {}", axis_words(&chosen), reason.de),
            format!("Correct: {}. Reason: {}", axis_words(&chosen), reason.en),
        ));
    }
    if e.candidates.iter().any(|c| same(&c.axes, &given)) {
        return Verdict::Wrong {
            hint: Hint::OtherSolution,
            text: texts(
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
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: texts(
            format!(
                "Das ist keine der beiden Lösungen für diese Lage. Die Master-Achse {m} stellt den Kippwinkel ein, die Slave-Achse {s} die Richtung; die zweite Lösung hat {m} gespiegelt am Symmetriepunkt und {s} um 180° versetzt."
            ),
            format!(
                "That is neither of the two solutions for this orientation. The master axis {m} sets the tilt, the slave axis {s} the direction; the second solution has {m} mirrored at the symmetry point and {s} 180° apart."
            ),
        ),
    }
}

/// Which rule decides, without giving the numbers away.
fn rule_hint(e: &Explanation) -> Texts {
    if e.selection.is_some() {
        texts(
            "Mit SEQ/SYM entscheidet das Vorzeichen der Master-Achse (SEQ: ab 0°, SYM: ab dem Symmetriepunkt).",
            "With SEQ/SYM the master axis' sign decides (SEQ: from 0°, SYM: from the symmetry point).",
        )
    } else {
        texts(
            "Ohne SEQ/SYM nimmt die Steuerung die Lösung im Verfahrbereich mit dem kürzeren Weg von der Startposition.",
            "Without SEQ/SYM the control takes the solution inside the travel with the shorter path from the start position.",
        )
    }
}

/// `letter` is the asked quantity: A/B/C, X/Y/Z, or `Q` for Q120.
pub(super) fn check_value(answer: &Answer, value: f64, letter: char) -> Verdict {
    let Answer::Text(text) = answer else {
        return Verdict::Wrong {
            hint: Hint::ControlFinds,
            text: texts("Die Steuerung arbeitet diesen Satz ab", "The control executes this block"),
        };
    };
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let upper = compact.to_uppercase();
    let prefix = if letter == 'Q' { "Q120" } else { "" };
    let rest = upper.strip_prefix(prefix).unwrap_or(&upper);
    let rest = rest.strip_prefix(letter).unwrap_or(rest);
    let rest = rest.strip_prefix('=').unwrap_or(rest);
    let Some(v) = parse_input(rest) else {
        return Verdict::Unreadable(texts(
            format!(
                "Eingabe nicht lesbar: „{}“ – bitte eine Zahl eingeben, z. B. +45 oder 12,5",
                text.trim()
            ),
            format!("Cannot read \"{}\" – please enter a number, e.g. +45 or 12.5", text.trim()),
        ));
    };
    let shown = if letter == 'Q' { "Q120".to_owned() } else { letter.to_string() };
    if (v - value).abs() <= VALUE_TOL {
        return Verdict::Correct(texts(
            format!("Richtig: {shown} = {}", super::expected::fmt_value(value)),
            format!("Correct: {shown} = {}", super::expected::fmt_value(value)),
        ));
    }
    if value.abs() > VALUE_TOL && (v + value).abs() <= VALUE_TOL {
        return Verdict::Wrong { hint: Hint::RightHand, text: super::orientation::right_hand_hint() };
    }
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: texts(
            "Noch nicht. Öffne das Programm im Trainer und lass es Satz für Satz bis zu diesem Satz laufen: die Positionsanzeige zeigt den Wert",
            "Not yet. Open the program in the trainer and run it block by block up to this block: the position display shows the value",
        ),
    }
}
