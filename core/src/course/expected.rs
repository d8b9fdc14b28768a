//! Exercises whose answer the solver or the simulator gives: which axis positions the control
//! chooses for a set-up, and what the display shows after a block of a program.

use glam::DMat3;

use super::{Answer, AnswerKind, Check, Exercise, Hint, RunKind, Spec};
use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::Machine;
use crate::plane::{PlaneBlock, RotaryAxis};
use crate::sim::{SimOptions, simulate};
use crate::solve::{Explanation, SolveError, SolveOptions, axis_words, solve, solve_block};
use crate::{BlockBody, parse};

/// The control's refusal for an explanation without a chosen position: its own message, or the
/// solver's "none inside the limits" wording when it names none.
pub(super) fn refusal(e: &Explanation) -> Text {
    e.error_message.map_or_else(
        || SolveError::NoSolutionInLimits { candidates: e.candidates.len() }.message(),
        |m| m.0.message(),
    )
}

/// The solver's answer for a set-up, as an [`Exercise`] check.
pub(super) fn axes_exercise(
    spec: Spec,
    variant: u32,
    machine: Machine,
    block: &PlaneBlock<f64>,
    opts: &SolveOptions,
    prompt: Text,
    other_mode: Option<AxisValues>,
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
            Text::same(axis_words(&a)),
            Text::same(format!("PLANE AXIAL {}", axis_words(&a))),
            // With COORD ROT/TABLE ROT the typical mistake is the other mode's position (unless
            // the table already stands where TABLE ROT turns it).
            match (other_mode.filter(|m| !super::answer::same(m, &a)), other) {
                (Some(m), _) => (Answer::Text(axis_words(&m)), Hint::Transform),
                (None, Some(o)) => (Answer::Text(axis_words(&o)), Hint::OtherSolution),
                (None, None) => (Answer::ControlError, Hint::ControlFinds),
            },
        ),
        None => {
            let refusal = refusal(&explanation);
            (
                refusal.clone(),
                refusal,
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
        check: Check::Axes { machine: Box::new(machine), explanation: Box::new(explanation), other_mode },
    }
}

/// What a value answer is checked against: the simulator's value, and what the hints need.
#[derive(Debug, Clone)]
pub(super) struct ValueCheck {
    pub value: f64,
    /// The asked quantity: A/B/C, X/Y/Z, or `Q` for Q120.
    pub letter: char,
    pub kind: RunKind,
    /// The solver's explanation of the last PLANE block up to the asked one that had two
    /// solutions: the other solution and the rule that chose come from it.
    pub decider: Option<Box<Explanation>>,
    /// The value the same program gives with the PLANE block's angle signs flipped (a sign
    /// error), where the exercise has one.
    pub sign_flipped: Option<f64>,
}

impl ValueCheck {
    /// The questions about STAY: what it does is their hint.
    pub fn is_stay(&self) -> bool {
        matches!(self.kind, RunKind::Stay | RunKind::StayQ120 | RunKind::ResetStay)
    }

    /// The rotary axis the asked value belongs to (Q120 holds the A axis' angle).
    pub fn axis(&self) -> Option<RotaryAxis> {
        match self.letter {
            'Q' => Some(RotaryAxis::A),
            l => RotaryAxis::from_letter(&l.to_string()),
        }
    }

    /// The other solution's value of the asked axis, when the axis stands at the chosen
    /// solution's value (a STAY block computes a position the axis does not take).
    pub fn other_solution(&self) -> Option<f64> {
        let (e, axis) = (self.decider.as_deref()?, self.axis()?);
        let chosen = e.chosen_axes()?.get(axis)?;
        if (chosen - self.value).abs() > super::VALUE_TOL {
            return None;
        }
        let other = e.candidates.iter().enumerate().find(|(i, _)| Some(*i) != e.chosen)?;
        other.1.axes.get(axis)
    }

    /// The position the decider computed for the asked axis (what STAY stores in Q120–Q122).
    pub fn computed(&self) -> Option<f64> {
        self.decider.as_deref()?.chosen_axes()?.get(self.axis()?)
    }
}

/// The value the simulator shows for `letter` after the first execution of block `number`
/// (`asked`); `flipped` is the same program with the PLANE angles' signs flipped, for the sign
/// hint.
pub(super) fn value_exercise(
    kind: RunKind,
    variant: u32,
    program: String,
    flipped: Option<&str>,
    machine: &'static str,
    (number, letter): (u32, char),
    prompt: Text,
) -> Exercise {
    let (value, decider) = run_value(&program, machine, number, letter).unwrap_or((f64::NAN, None));
    let sign_flipped = flipped.and_then(|p| run_value(p, machine, number, letter)).map(|(v, _)| v);
    let check = ValueCheck { value, letter, kind, decider: decider.map(Box::new), sign_flipped };
    let word = |v: f64| format!("{letter}{}", crate::number::signed(v, 3));
    let differs = |v: &f64| (v - value).abs() > super::VALUE_TOL;
    let mistake = if check.is_stay() {
        // The position the block computed, taken for one the axes moved to; or (Q120, RESET
        // STAY) the axes taken as untilted.
        let v = [check.computed().unwrap_or(0.0), 0.0].into_iter().find(differs).unwrap_or(value + 10.0);
        (Answer::Text(word(v)), Hint::Stay)
    } else if let Some(o) = check.other_solution() {
        (Answer::Text(word(o)), Hint::OtherSolution)
    } else if let Some(f) = check.sign_flipped.filter(differs) {
        (Answer::Text(word(f)), Hint::RightHand)
    } else {
        (Answer::Text(word(value + 10.0)), Hint::Wrong)
    };
    Exercise {
        spec: Spec::Run(kind),
        variant,
        prompt,
        answer_kind: AnswerKind::Number,
        solution: Text::same(word(value)),
        equivalent: Text::same(crate::number::signed(value, 3).replace('.', ",")),
        typical_mistake: mistake,
        program: Some((program, machine)),
        check: Check::Value(check),
    }
}

/// Runs `program` on `machine` and reads `letter` after the first execution of block `number`:
/// a rotary axis (A/B/C), the tool tip in W-CS (X/Y/Z) or Q120–Q122 (`1`, `2`, `3` stand for
/// Q120, Q121, Q122), with the explanation of the last PLANE block up to it that had two
/// solutions.
fn run_value(program: &str, machine: &str, number: u32, letter: char) -> Option<(f64, Option<Explanation>)> {
    let machine = Machine::builtin(machine).ok()?;
    let (program, _) = parse(program);
    let sim = simulate(&program, &machine, &SimOptions::default());
    let index = program.blocks.iter().position(|b| b.number() == Some(number))?;
    let state_of = |i: usize| sim.state_at(&program, sim.step_of_block(i)?);
    let decider = (0..=index)
        .rev()
        .filter(|&i| {
            matches!(program.blocks.get(i).and_then(crate::Block::stored_body), Some(BlockBody::Plane(_)))
        })
        .filter_map(|i| state_of(i)?.explanation)
        .find(|e| e.candidates.len() >= 2 && e.chosen.is_some())
        .map(|e| (*e).clone());
    let state = state_of(index)?;
    let value = match letter {
        'A' | 'B' | 'C' => {
            let axis = RotaryAxis::from_letter(&letter.to_string())?;
            state.axes.rotary_axis(axis)
        }
        'X' => Some(state.tip_wcs.x),
        'Y' => Some(state.tip_wcs.y),
        'Z' => Some(state.tip_wcs.z),
        'Q' => state.q.get(&120).copied(),
        _ => None,
    }?;
    Some((value, decider))
}
