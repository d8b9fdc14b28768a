//! The course's exercises (issue 8). Each exercise is generated from a variant number, so a
//! trainee who asks for a fresh one gets new numbers, and each answer is checked by the core's
//! own maths, never by comparing strings:
//! - a PLANE block is parsed and its orientation compared as a rotation matrix with the target
//!   (`orientation`), so SPATIAL, EULER, VECTOR, … all count when they mean the same; the same
//!   block with one or more angle signs flipped is recognised as a sign error (right-hand rule);
//! - "which axis position will the control choose?" is compared with the solver (`solve`);
//! - "what does the display show after block N?" is compared with the simulator (`sim`).
//!
//! Variant 0 of every exercise is fixed (it is the one the lesson text and the tests talk
//! about); variants 1, 2, … are drawn from a small deterministic generator.

mod answer;
mod expected;
mod orientation;
mod programs;

use std::hash::{Hash, Hasher};

use glam::DMat3;

use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::Machine;
use crate::plane::{Feed, PlaneBlock, PlaneDef, Positioning};
use crate::solve::Explanation;

pub use answer::Answer;
pub use programs::{SeedRow, seed_rows};

/// Two rotation matrices are the same orientation when every entry agrees to this (a VECTOR
/// block typed with 4 decimals is off by ~1e-4).
const ORIENTATION_TOL: f64 = 5e-4;
/// Axis positions and run values agree to a thousandth (the display shows three decimals).
const VALUE_TOL: f64 = 0.001_5;

/// What an exercise asks; the lesson table in the web crate lists these per lesson.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Spec {
    /// Tilt the tool towards +X, −X, +Y or −Y (one spatial angle): a PLANE block, any form.
    Lean,
    /// Turn the working plane about Z (SPC): a PLANE block, any form.
    TurnAboutZ,
    /// A lean and a turn about Z together (two spatial angles): a PLANE block, any form.
    LeanAndTurn,
    /// Like [`Spec::Lean`], and the block must position with `TURN` at `FMAX` (dialog lesson).
    DialogTurn,
    /// Like [`Spec::Lean`], and the block must position with `MOVE` at a given DIST and F.
    DialogMove,
    /// Like [`Spec::Lean`]; variant 0 is the plane of Musterprogramm 1 (lesson 8), so it has its
    /// own variant 0 instead of repeating lesson 2's.
    ProgramLean,
    /// An orientation given as `PLANE EULER`: the same one in another form.
    EulerToOther,
    /// One of the four chamfers (EULNU 45): the PLANE block for it, any form.
    Chamfer,
    /// Which axis positions the control chooses: machine, start, limits and option given.
    Choose(ChooseKind),
    /// A value the program run shows after a block.
    Run(RunKind),
}

/// The set-ups of [`Spec::Choose`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ChooseKind {
    /// The same spatial angles on another machine (B/C head-table): other axes, same tilt.
    OtherMachine,
    /// A/C table, no option: the shorter path from a start position.
    ShortestPath,
    /// A/C table with SEQ± or SYM±.
    Option,
    /// A/C table with the seed's limit switch −90 < A < +10: an option may have no solution.
    Limits,
    /// Only SPC non-zero with `TABLE ROT`: the free C axis turns.
    TableRot,
    /// Only SPC non-zero with `COORD ROT`: the table stays.
    CoordRot,
}

/// The programs of [`Spec::Run`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RunKind {
    /// PLANE … TURN: where the master axis stands after the block.
    Turn,
    /// PLANE … STAY: the rotary axes don't move.
    Stay,
    /// PLANE … STAY: what Q120 holds for the later `L A+Q120 C+Q122`.
    StayQ120,
    /// PLANE RESET STAY after a tilt: the axes stay tilted.
    ResetStay,
    /// PLANE RESET TURN after a tilt: the axes go home.
    ResetTurn,
    /// Musterprogramm 1: the axes at a block.
    Musterprogramm1,
    /// TRANS DATUM, then a tilt: the tool tip in W-CS.
    DatumThenPlane,
    /// TRANS DATUM, then TRANS MIRROR: the tool tip in W-CS.
    DatumThenMirror,
}

/// What the answer field expects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AnswerKind {
    /// A PLANE block, e.g. `PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX`.
    PlaneBlock,
    /// Rotary axis positions, e.g. `A+45 C+90` (also `PLANE AXIAL A+45 C+90`), or the control's
    /// error message.
    Axes,
    /// One number, e.g. `+45` or `X+12,5`.
    Number,
}

/// Why a wrong answer is wrong; each has its hint text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hint {
    /// The right orientation or value with a sign flipped: the right-hand rule.
    RightHand,
    /// The right tool axis, but the working plane turned about it.
    TurnedAboutToolAxis,
    /// The block positions differently from what the task asks (TURN/MOVE, DIST, F).
    Positioning,
    /// The task asks for another PLANE form than the one given.
    SameForm,
    /// The other of the two machine solutions of the same orientation.
    OtherSolution,
    /// What `STAY` (or `PLANE RESET STAY`) does: only the coordinate system, no axis moves.
    Stay,
    /// What `COORD ROT` or `TABLE ROT` does with the free table axis.
    Transform,
    /// The control refuses this block, but the answer gives positions.
    ControlRefuses,
    /// The control finds a position, but the answer says it refuses.
    ControlFinds,
    /// Just not it: the hint says how to work it out.
    Wrong,
}

/// The result of checking an answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    Correct(Text),
    Wrong {
        hint: Hint,
        text: Text,
    },
    /// The answer cannot be read (a broken block, a letter in a number): the control's message.
    Unreadable(Text),
}

impl Verdict {
    #[must_use]
    pub fn is_correct(&self) -> bool {
        matches!(self, Verdict::Correct(_))
    }
}

/// One generated exercise.
#[derive(Debug, Clone)]
pub struct Exercise {
    pub spec: Spec,
    pub variant: u32,
    pub prompt: Text,
    pub answer_kind: AnswerKind,
    /// The answer the solution shows, per UI language: NC words read the same in both, the
    /// control's refusal is its message in that language.
    pub solution: Text,
    /// The same answer in another form (another PLANE form, or another way to write it).
    pub equivalent: Text,
    /// A wrong answer and the hint it gets (for the tests, and as "typical mistake").
    pub typical_mistake: (Answer, Hint),
    /// The program this exercise is about, to open in the lesson's trainer, and its machine.
    pub program: Option<(String, &'static str)>,
    check: Check,
}

#[derive(Debug, Clone)]
enum Check {
    Orientation {
        target: DMat3,
        spatial: [f64; 3],
        require: orientation::Require,
        not_euler: bool,
    },
    /// `other_mode`: for a block with COORD ROT or TABLE ROT, where the axes would go with the
    /// other of the two (the solver's answer), so its hint can tell the two apart.
    Axes {
        machine: Box<Machine>,
        explanation: Box<Explanation>,
        other_mode: Option<AxisValues>,
    },
    Value(expected::ValueCheck),
}

/// A small deterministic generator (SplitMix64): the same variant always gives the same numbers.
struct Rng(u64);

impl Rng {
    fn new(spec: Spec, variant: u32) -> Rng {
        // Mix the spec in so two exercises of one lesson don't share numbers.
        let mut h = std::collections::hash_map::DefaultHasher::new();
        spec.hash(&mut h);
        Rng(h.finish() ^ u64::from(variant).wrapping_mul(0x9e37_79b9_7f4a_7c15))
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// One of `items` (every call passes a non-empty literal list).
    fn pick<T: Copy, const N: usize>(&mut self, items: &[T; N]) -> T {
        items[usize::try_from(self.next() % N as u64).unwrap_or(0)]
    }
}

/// `TURN FMAX`: how the exercises' blocks position unless the task asks otherwise.
const TURN_FMAX: Positioning<f64> = Positioning::Turn { move_back: None, feed: Some(Feed::Max) };

/// A PLANE block without SEQ/SYM and COORD/TABLE ROT.
fn plane(def: PlaneDef<f64>, positioning: Option<Positioning<f64>>) -> PlaneBlock<f64> {
    PlaneBlock { def, positioning, selection: None, transform: None }
}

fn spatial_def([spa, spb, spc]: [f64; 3]) -> PlaneDef<f64> {
    PlaneDef::Spatial { spa, spb, spc }
}

fn euler_def([eulpr, eulnu, eulrot]: [f64; 3]) -> PlaneDef<f64> {
    PlaneDef::Euler { eulpr, eulnu, eulrot }
}

impl Exercise {
    /// Generates variant `variant` of an exercise.
    #[must_use]
    pub fn generate(spec: Spec, variant: u32) -> Exercise {
        let mut rng = Rng::new(spec, variant);
        match spec {
            Spec::Lean | Spec::DialogTurn | Spec::DialogMove | Spec::ProgramLean => {
                orientation::lean(spec, variant, &mut rng)
            }
            Spec::TurnAboutZ => orientation::turn_about_z(variant, &mut rng),
            Spec::LeanAndTurn => orientation::lean_and_turn(variant, &mut rng),
            Spec::EulerToOther => orientation::euler_to_other(variant, &mut rng),
            Spec::Chamfer => orientation::chamfer(variant, &mut rng),
            Spec::Choose(kind) => programs::choose(kind, variant, &mut rng),
            Spec::Run(kind) => programs::run(kind, variant, &mut rng),
        }
    }

    /// Checks an answer.
    #[must_use]
    pub fn check(&self, answer: &Answer) -> Verdict {
        match &self.check {
            Check::Orientation { target, spatial, require, not_euler } => {
                orientation::check(answer, target, *spatial, *require, *not_euler)
            }
            Check::Axes { machine, explanation, other_mode } => {
                answer::check_axes(answer, machine, explanation, other_mode.as_ref())
            }
            Check::Value(v) => answer::check_value(answer, v),
        }
    }
}

#[cfg(test)]
mod tests;
