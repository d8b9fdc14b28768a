//! Exercises whose answer the solver or the simulator gives: which axis positions the control
//! chooses for a set-up, and what the display shows after a block of a program.

use glam::DMat3;

use super::{Answer, AnswerKind, Check, Exercise, Hint, Spec};
use crate::machine::{Machine, Texts};
use crate::parse;
use crate::plane::{PlaneBlock, RotaryAxis};
use crate::sim::{SimOptions, simulate};
use crate::solve::{SolveOptions, axis_words, solve, solve_block};

/// The solver's answer for a set-up, as an [`Exercise`] check.
pub(super) fn axes_exercise(
    spec: Spec,
    variant: u32,
    machine: Machine,
    block: &PlaneBlock<f64>,
    opts: &SolveOptions,
    prompt: Texts,
) -> Exercise {
    let explanation = match solve_block(&machine, block, DMat3::IDENTITY, opts) {
        Ok(e) => e,
        // Every generated block is a valid orientation; should one not be, the solver's own
        // explanation of the identity stands in (and the tests catch it).
        Err(_) => solve(&machine, &DMat3::IDENTITY, opts),
    };
    let chosen = explanation.chosen_axes();
    let other = explanation
        .candidates
        .iter()
        .enumerate()
        .find(|(i, _)| Some(*i) != explanation.chosen)
        .map(|(_, c)| c.axes);
    let (solution, equivalent, mistake) = match chosen {
        Some(a) => (
            axis_words(&a),
            format!("PLANE AXIAL {}", axis_words(&a)),
            other.map_or((Answer::ControlError, Hint::ControlFinds), |o| {
                (Answer::Text(axis_words(&o)), Hint::OtherSolution)
            }),
        ),
        None => {
            let m = explanation
                .error_message
                .map_or_else(|| "Winkel nicht erlaubt".to_owned(), |m| m.de().to_owned());
            (
                m.clone(),
                m,
                (Answer::Text(other.map_or_else(String::new, |o| axis_words(&o))), Hint::ControlRefuses),
            )
        }
    };
    Exercise {
        spec,
        variant,
        prompt,
        answer_kind: AnswerKind::Axes,
        solution,
        equivalent,
        typical_mistake: mistake,
        program: None,
        check: Check::Axes { machine: Box::new(machine), explanation: Box::new(explanation) },
    }
}

/// The value the simulator shows for `letter` after the first execution of block `number`.
pub(super) fn value_exercise(
    spec: Spec,
    variant: u32,
    program: String,
    machine: &'static str,
    number: u32,
    letter: char,
    prompt: Texts,
) -> Exercise {
    let value = run_value(&program, machine, number, letter).unwrap_or(f64::NAN);
    let word = format!("{letter}{}", fmt_value(value));
    let mistake = if value.abs() > 1e-6 {
        (Answer::Text(format!("{letter}{}", fmt_value(-value))), Hint::RightHand)
    } else {
        (Answer::Text(format!("{letter}+45")), Hint::Wrong)
    };
    Exercise {
        spec,
        variant,
        prompt,
        answer_kind: AnswerKind::Number,
        solution: word,
        equivalent: fmt_value(value).replace('.', ","),
        typical_mistake: mistake,
        program: Some((program, machine)),
        check: Check::Value { value, letter },
    }
}

/// `+12.5`, `-0.001` (three decimals at most, trailing zeros dropped).
pub(super) fn fmt_value(v: f64) -> String {
    let s = format!("{:+.3}", (v * 1e3).round() / 1e3 + 0.0);
    let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_owned() } else { s };
    if s == "-0" { "+0".to_owned() } else { s }
}

/// Runs `program` on `machine` and reads `letter` after the first execution of block `number`:
/// a rotary axis (A/B/C), the tool tip in W-CS (X/Y/Z) or Q120–Q122 (`1`, `2`, `3` stand for
/// Q120, Q121, Q122).
fn run_value(program: &str, machine: &str, number: u32, letter: char) -> Option<f64> {
    let machine = Machine::builtin(machine).ok()?;
    let (program, _) = parse(program);
    let sim = simulate(&program, &machine, &SimOptions::default());
    let index = program.blocks.iter().position(|b| b.number == Some(number))?;
    let step = sim.first_step.get(index).copied().flatten()?;
    let state = sim.state_at(&program, usize::try_from(step).ok()?)?;
    match letter {
        'A' | 'B' | 'C' => {
            let axis = RotaryAxis::from_letter(&letter.to_string())?;
            state.axes.rotary_axis(axis)
        }
        'X' => Some(state.tip_wcs.x),
        'Y' => Some(state.tip_wcs.y),
        'Z' => Some(state.tip_wcs.z),
        'Q' => state.q.get(&120).copied(),
        _ => None,
    }
}
