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
mod programs;

use glam::DMat3;

use crate::axes::AxisValues;
use crate::machine::{Limits, Machine, Texts};
use crate::orientation::{self, Context};
use crate::plane::{Feed, PlaneBlock, PlaneDef, Positioning, RotaryAxis, Selection, Sign, TransformMode};
use crate::sim::{SimOptions, simulate};
use crate::solve::{Explanation, SolveOptions, axis_word, fmt_deg, solve, solve_block};
use crate::{BlockBody, parse};

pub use answer::Answer;
pub use programs::{SeedRow, seed_rows};

/// Two rotation matrices are the same orientation when every entry agrees to this (a VECTOR
/// block typed with 4 decimals is off by ~1e-4).
const ORIENTATION_TOL: f64 = 5e-4;
/// Axis positions and run values agree to a thousandth (the display shows three decimals).
const VALUE_TOL: f64 = 0.001_5;

/// What an exercise asks; the lesson table in the web crate lists these per lesson.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
    /// The other of the two machine solutions.
    OtherSolution,
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
    Correct(Texts),
    Wrong {
        hint: Hint,
        text: Texts,
    },
    /// The answer cannot be read (a broken block, a letter in a number): the control's message.
    Unreadable(Texts),
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
    pub prompt: Texts,
    pub answer_kind: AnswerKind,
    /// The answer the solution shows.
    pub solution: String,
    /// The same answer in another form (another PLANE form, or another way to write it).
    pub equivalent: String,
    /// A wrong answer and the hint it gets (for the tests, and as "typical mistake").
    pub typical_mistake: (Answer, Hint),
    /// The program this exercise is about, to open in the lesson's trainer, and its machine.
    pub program: Option<(String, &'static str)>,
    check: Check,
}

#[derive(Debug, Clone)]
enum Check {
    Orientation { target: DMat3, spatial: [f64; 3], require: Require, not_euler: bool },
    Axes { machine: Box<Machine>, explanation: Box<Explanation> },
    Value { value: f64, letter: char },
}

/// What an orientation answer must also get right.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Require {
    Nothing,
    TurnFmax,
    Move { dist: f64, feed: f64 },
}

/// A small deterministic generator (SplitMix64): the same variant always gives the same numbers.
struct Rng(u64);

impl Rng {
    fn new(spec: Spec, variant: u32) -> Rng {
        // Mix the spec in so two exercises of one lesson don't share numbers.
        let tag = format!("{spec:?}")
            .bytes()
            .fold(0xcbf2_9ce4_8422_2325_u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
        Rng(tag ^ u64::from(variant).wrapping_mul(0x9e37_79b9_7f4a_7c15))
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        // `items` is never empty here: every call passes a literal list.
        let i = usize::try_from(self.next() % items.len().max(1) as u64).unwrap_or(0);
        items[i.min(items.len() - 1)]
    }
}

fn texts(de: impl Into<String>, en: impl Into<String>) -> Texts {
    Texts { de: de.into(), en: en.into() }
}

/// The four directions a tool can lean in, with the spatial angles that do it:
/// Ry(+θ)·ez = (sin θ, 0, cos θ), Rx(+θ)·ez = (0, −sin θ, cos θ) (DOMAIN.md §2.1).
#[derive(Debug, Clone, Copy)]
enum Toward {
    PlusX,
    MinusX,
    PlusY,
    MinusY,
}

impl Toward {
    fn name(self) -> &'static str {
        match self {
            Toward::PlusX => "+X",
            Toward::MinusX => "−X",
            Toward::PlusY => "+Y",
            Toward::MinusY => "−Y",
        }
    }

    /// `[SPA, SPB, SPC]` that lean the tool by `theta` towards this direction.
    fn spatial(self, theta: f64) -> [f64; 3] {
        match self {
            Toward::PlusX => [0.0, theta, 0.0],
            Toward::MinusX => [0.0, -theta, 0.0],
            Toward::PlusY => [-theta, 0.0, 0.0],
            Toward::MinusY => [theta, 0.0, 0.0],
        }
    }
}

const DIRECTIONS: [Toward; 4] = [Toward::PlusX, Toward::MinusX, Toward::PlusY, Toward::MinusY];
const TILTS: [f64; 10] = [10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 60.0];

fn spatial_text(s: [f64; 3]) -> String {
    format!("PLANE SPATIAL SPA{} SPB{} SPC{}", fmt_deg(s[0]), fmt_deg(s[1]), fmt_deg(s[2]))
}

fn euler_text(e: [f64; 3]) -> String {
    format!("PLANE EULER EULPR{} EULNU{} EULROT{}", fmt_deg(e[0]), fmt_deg(e[1]), fmt_deg(e[2]))
}

impl Exercise {
    /// Generates variant `variant` of an exercise.
    #[must_use]
    pub fn generate(spec: Spec, variant: u32) -> Exercise {
        let mut rng = Rng::new(spec, variant);
        match spec {
            Spec::Lean | Spec::DialogTurn | Spec::DialogMove => lean(spec, variant, &mut rng),
            Spec::TurnAboutZ => turn_about_z(variant, &mut rng),
            Spec::LeanAndTurn => lean_and_turn(variant, &mut rng),
            Spec::EulerToOther => euler_to_other(variant, &mut rng),
            Spec::Chamfer => chamfer(variant, &mut rng),
            Spec::Choose(kind) => programs::choose(kind, variant, &mut rng),
            Spec::Run(kind) => programs::run(kind, variant, &mut rng),
        }
    }

    /// Checks an answer.
    #[must_use]
    pub fn check(&self, answer: &Answer) -> Verdict {
        match &self.check {
            Check::Orientation { target, spatial, require, not_euler } => {
                check_orientation(answer, target, *spatial, *require, *not_euler)
            }
            Check::Axes { machine, explanation } => answer::check_axes(answer, machine, explanation),
            Check::Value { value, letter } => answer::check_value(answer, *value, *letter),
        }
    }
}

fn orientation_exercise(
    spec: Spec,
    variant: u32,
    prompt: Texts,
    spatial: [f64; 3],
    require: Require,
    not_euler: bool,
) -> Exercise {
    let target = orientation::spatial(spatial[0], spatial[1], spatial[2]);
    let tail = match require {
        Require::Nothing | Require::TurnFmax => " TURN FMAX".to_owned(),
        Require::Move { dist, feed } => format!(" MOVE DIST{} F{}", fmt_deg(dist), fmt_deg(feed)),
    };
    let euler = format!("{}{tail}", euler_text(orientation::to_euler(&target)));
    let spatial_block = format!("{}{tail}", spatial_text(spatial));
    // The typical mistake: the first non-zero angle with the wrong sign.
    let mut flipped = spatial;
    if let Some(v) = flipped.iter_mut().find(|v| v.abs() > 1e-9) {
        *v = -*v;
    }
    Exercise {
        spec,
        variant,
        prompt,
        answer_kind: AnswerKind::PlaneBlock,
        solution: spatial_block,
        equivalent: euler,
        typical_mistake: (Answer::Text(format!("{}{tail}", spatial_text(flipped))), Hint::RightHand),
        program: None,
        check: Check::Orientation { target, spatial, require, not_euler },
    }
}

fn lean(spec: Spec, variant: u32, rng: &mut Rng) -> Exercise {
    let (toward, theta) =
        if variant == 0 { (Toward::PlusX, 15.0) } else { (rng.pick(&DIRECTIONS), rng.pick(&TILTS)) };
    let t = fmt_deg(theta).trim_start_matches('+').to_owned();
    let d = toward.name();
    let (require, de_tail, en_tail) = match spec {
        Spec::DialogTurn => (
            Require::TurnFmax,
            " Die Drehachsen sollen mit TURN im Eilgang (FMAX) schwenken.",
            " The rotary axes are to swivel with TURN at rapid traverse (FMAX).",
        ),
        Spec::DialogMove => (
            Require::Move { dist: 50.0, feed: 1000.0 },
            " Schwenken mit MOVE, Drehpunkt 50 mm über der Werkzeugspitze (DIST 50), F 1000.",
            " Swivel with MOVE, centre of rotation 50 mm above the tool tip (DIST 50), F 1000.",
        ),
        _ => (Require::Nothing, "", ""),
    };
    let prompt = texts(
        format!(
            "Die Fläche ist so geneigt, dass das Werkzeug senkrecht auf ihr um {t}° in Richtung {d} gekippt steht (die Ebene wird nicht zusätzlich um Z gedreht). Gib den PLANE-Satz ein.{de_tail}"
        ),
        format!(
            "The face is inclined so that a tool perpendicular to it leans {t}° towards {d} (the plane is not turned about Z as well). Enter the PLANE block.{en_tail}"
        ),
    );
    orientation_exercise(spec, variant, prompt, toward.spatial(theta), require, false)
}

fn turn_about_z(variant: u32, rng: &mut Rng) -> Exercise {
    let phi = if variant == 0 { 30.0 } else { rng.pick(&[15.0, 20.0, 30.0, 45.0, 60.0, 90.0]) };
    let toward_plus_y = variant == 0 || rng.pick(&[true, false]);
    let (dir, spc) = if toward_plus_y { ("+Y", phi) } else { ("−Y", -phi) };
    let t = fmt_deg(phi).trim_start_matches('+').to_owned();
    let prompt = texts(
        format!(
            "Das Werkzeug bleibt senkrecht (Z). Nur die Bearbeitungsebene soll um {t}° um die Z-Achse gedreht werden, so dass ihre X-Achse in Richtung {dir} dreht. Gib den PLANE-Satz ein."
        ),
        format!(
            "The tool stays vertical (Z). Only the working plane is to turn {t}° about the Z axis, so that its X axis turns towards {dir}. Enter the PLANE block."
        ),
    );
    orientation_exercise(Spec::TurnAboutZ, variant, prompt, [0.0, 0.0, spc], Require::Nothing, false)
}

fn lean_and_turn(variant: u32, rng: &mut Rng) -> Exercise {
    let (theta, phi) = if variant == 0 {
        (30.0, 90.0)
    } else {
        (rng.pick(&TILTS), rng.pick(&[30.0, 45.0, 60.0, 90.0, -90.0]))
    };
    let spatial = [0.0, theta, phi];
    let r = orientation::spatial(0.0, theta, phi);
    let t = orientation::tool_axis(&r);
    let prompt = texts(
        format!(
            "Erst um Y um {} kippen (SPB), dann um Z um {} drehen (SPC). Die Werkzeugachse zeigt danach in Richtung ({:.4}, {:.4}, {:.4}). Gib den PLANE-Satz ein – SPATIAL oder eine andere Form.",
            fmt_deg(theta),
            fmt_deg(phi),
            t.x + 0.0,
            t.y + 0.0,
            t.z + 0.0
        ),
        format!(
            "First tilt {} about Y (SPB), then turn {} about Z (SPC). The tool axis then points along ({:.4}, {:.4}, {:.4}). Enter the PLANE block – SPATIAL or another form.",
            fmt_deg(theta),
            fmt_deg(phi),
            t.x + 0.0,
            t.y + 0.0,
            t.z + 0.0
        ),
    );
    orientation_exercise(Spec::LeanAndTurn, variant, prompt, spatial, Require::Nothing, false)
}

fn euler_to_other(variant: u32, rng: &mut Rng) -> Exercise {
    let e = if variant == 0 {
        [90.0, 45.0, 0.0]
    } else {
        [
            rng.pick(&[-90.0, 0.0, 45.0, 90.0, 180.0]),
            rng.pick(&[20.0, 30.0, 45.0, 60.0]),
            rng.pick(&[0.0, 90.0, 270.0]),
        ]
    };
    let r = orientation::euler(e[0], e[1], e[2]);
    let spatial = orientation::to_spatial(&r);
    let given = euler_text(e);
    let prompt = texts(
        format!("Gegeben: {given}. Gib dieselbe Lage als anderen PLANE-Satz ein (z. B. PLANE SPATIAL)."),
        format!("Given: {given}. Enter the same orientation as another PLANE block (e.g. PLANE SPATIAL)."),
    );
    let mut ex = orientation_exercise(Spec::EulerToOther, variant, prompt, spatial, Require::Nothing, true);
    // The other equivalent form: VECTOR (base = tilted X, normal = tool axis), 4 decimals.
    let (x, z) = (r.x_axis, r.z_axis);
    let f = |v: f64| format!("{:+.4}", v + 0.0);
    ex.equivalent = format!(
        "PLANE VECTOR BX{} BY{} BZ{} NX{} NY{} NZ{} TURN FMAX",
        f(x.x),
        f(x.y),
        f(x.z),
        f(z.x),
        f(z.y),
        f(z.z)
    );
    ex
}

fn chamfer(variant: u32, rng: &mut Rng) -> Exercise {
    // Seed 001: chamfers with EULNU 45 at EULPR 0, 90, 180 and 270 (written −90, the input
    // range is −180…+180: unconfirmed::EULPR_RANGE).
    let pr = if variant == 0 { 0.0 } else { rng.pick(&[0.0, 90.0, 180.0, -90.0]) };
    let r = orientation::euler(pr, 45.0, 0.0);
    let t = orientation::tool_axis(&r);
    let side = if t.y < -0.5 {
        "−Y"
    } else if t.y > 0.5 {
        "+Y"
    } else if t.x > 0.5 {
        "+X"
    } else {
        "−X"
    };
    let prompt = texts(
        format!(
            "Fase unter 45° an der Seite {side} des Rohteils: das Werkzeug steht senkrecht auf der Fase und kippt 45° in Richtung {side}. Die X-Achse der Bearbeitungsebene liegt entlang der Kante (EULROT 0). Gib den PLANE-Satz ein – EULER oder eine andere Form."
        ),
        format!(
            "A 45° chamfer on the {side} side of the blank: the tool is perpendicular to the chamfer and leans 45° towards {side}. The working plane's X axis runs along the edge (EULROT 0). Enter the PLANE block – EULER or another form."
        ),
    );
    let spatial = orientation::to_spatial(&r);
    let mut ex = orientation_exercise(Spec::Chamfer, variant, prompt, spatial, Require::Nothing, false);
    // Here the EULER block is the natural answer; SPATIAL the equivalent one.
    ex.solution = format!("{} TURN FMAX", euler_text([pr, 45.0, 0.0]));
    ex.equivalent = format!("{} TURN FMAX", spatial_text(spatial));
    // The typical mistake: the chamfer on the opposite side (EULPR off by 180°). It tilts the
    // tool the other way, so it gets the right-hand hint.
    let wrong_pr = if pr > 0.0 { pr - 180.0 } else { pr + 180.0 };
    ex.typical_mistake =
        (Answer::Text(format!("{} TURN FMAX", euler_text([wrong_pr, 45.0, 0.0]))), Hint::RightHand);
    ex
}

fn close(a: &DMat3, b: &DMat3) -> bool {
    (0..3).all(|c| (a.col(c) - b.col(c)).abs().max_element() < ORIENTATION_TOL)
}

/// The single PLANE block of an answer, with numbers only.
fn answer_block(answer: &Answer) -> Result<PlaneBlock<f64>, Texts> {
    let Answer::Text(text) = answer else {
        return Err(texts("Hier ist ein PLANE-Satz gefragt", "A PLANE block is asked for here"));
    };
    let (program, diags) = parse(text.trim());
    if let Some(d) = diags.iter().find(|d| d.is_error()) {
        return Err(texts(d.message(crate::Lang::De), d.message(crate::Lang::En)));
    }
    let plane = program.blocks.iter().find_map(|b| match &b.body {
        BlockBody::Plane(p) => Some(p),
        _ => None,
    });
    let Some(plane) = plane else {
        return Err(texts(
            "Kein PLANE-Satz erkannt (er beginnt mit PLANE)",
            "No PLANE block found (it starts with PLANE)",
        ));
    };
    plane.try_map(|v| match v {
        crate::plane::Value::Number(x) => Ok(*x),
        crate::plane::Value::Param { index, .. } => Err(texts(
            format!("Q{index} hat hier keinen Wert: bitte Zahlen eingeben"),
            format!("Q{index} has no value here: please enter numbers"),
        )),
    })
}

fn check_orientation(
    answer: &Answer,
    target: &DMat3,
    spatial: [f64; 3],
    require: Require,
    not_euler: bool,
) -> Verdict {
    let block = match answer_block(answer) {
        Ok(b) => b,
        Err(t) => return Verdict::Unreadable(t),
    };
    if matches!(block.def, PlaneDef::Reset | PlaneDef::Axial { .. } | PlaneDef::Relativ { .. }) {
        return Verdict::Wrong {
            hint: Hint::Wrong,
            text: texts(
                "Gefragt ist eine Lage im Raum: PLANE SPATIAL, EULER, PROJECTED, VECTOR oder POINTS",
                "An orientation in space is asked for: PLANE SPATIAL, EULER, PROJECTED, VECTOR or POINTS",
            ),
        };
    }
    if not_euler && matches!(block.def, PlaneDef::Euler { .. }) {
        return Verdict::Wrong {
            hint: Hint::SameForm,
            text: texts(
                "Das ist wieder PLANE EULER – gefragt ist eine andere Form, z. B. PLANE SPATIAL",
                "That is PLANE EULER again – another form is asked for, e.g. PLANE SPATIAL",
            ),
        };
    }
    let r = match orientation::orientation(&block.def, &Context::default()) {
        Ok(r) => r,
        Err(e) => {
            let (de, en) = e.messages();
            return Verdict::Unreadable(texts(de, en));
        }
    };
    if close(&r, target) {
        return match positioning_problem(&block, require) {
            None => Verdict::Correct(texts(
                format!("Richtig. Dieselbe Lage als SPATIAL: {}", spatial_text(spatial)),
                format!("Correct. The same orientation as SPATIAL: {}", spatial_text(spatial)),
            )),
            Some(text) => Verdict::Wrong { hint: Hint::Positioning, text },
        };
    }
    if sign_flips(spatial).any(|s| close(&r, &orientation::spatial(s[0], s[1], s[2]))) {
        return Verdict::Wrong { hint: Hint::RightHand, text: right_hand_hint() };
    }
    let (t, want) = (orientation::tool_axis(&r), orientation::tool_axis(target));
    if (t - want).abs().max_element() < ORIENTATION_TOL {
        let gamma = target.x_axis.angle_between(r.x_axis).to_degrees();
        return Verdict::Wrong {
            hint: Hint::TurnedAboutToolAxis,
            text: texts(
                format!(
                    "Die Werkzeugachse stimmt, aber die Bearbeitungsebene ist um {gamma:.1}° um die Werkzeugachse verdreht"
                ),
                format!(
                    "The tool axis is right, but the working plane is turned {gamma:.1}° about the tool axis"
                ),
            ),
        };
    }
    // The tilt the other way round: the tool axis mirrored about Z (a sign or a side error).
    let mirrored = glam::DVec3::new(-want.x, -want.y, want.z);
    if (t - mirrored).abs().max_element() < ORIENTATION_TOL {
        return Verdict::Wrong { hint: Hint::RightHand, text: right_hand_hint() };
    }
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: texts(
            "Noch nicht: stell dir die Fläche vor und kippe die Ebene Schritt für Schritt – erst um X (SPA), dann um Y (SPB), dann um Z (SPC)",
            "Not yet: picture the face and tilt the plane step by step – first about X (SPA), then about Y (SPB), then about Z (SPC)",
        ),
    }
}

/// Every variant of `spatial` with at least one non-zero angle's sign flipped.
fn sign_flips(spatial: [f64; 3]) -> impl Iterator<Item = [f64; 3]> {
    (1_u8..8).filter_map(move |mask| {
        let mut s = spatial;
        for (i, v) in s.iter_mut().enumerate() {
            if mask & (1 << i) != 0 {
                if v.abs() < 1e-9 {
                    return None;
                }
                *v = -*v;
            }
        }
        Some(s)
    })
}

/// The right-hand rule, seed 000 §2.2.
fn right_hand_hint() -> Texts {
    texts(
        "Vorzeichen prüfen – Rechte-Hand-Regel: Daumen zeigt in die positive Achsrichtung, die gekrümmten Finger zeigen die positive Drehrichtung. SPB+ kippt das Werkzeug nach +X, SPA+ nach −Y.",
        "Check the sign – right-hand rule: the thumb points along the positive axis, the curled fingers show the positive direction of rotation. SPB+ tilts the tool towards +X, SPA+ towards −Y.",
    )
}

fn positioning_problem(block: &PlaneBlock<f64>, require: Require) -> Option<Texts> {
    match (require, block.positioning) {
        (Require::Nothing, _) => None,
        (Require::TurnFmax, Some(Positioning::Turn { feed: Some(Feed::Max), .. })) => None,
        (Require::TurnFmax, _) => Some(texts(
            "Die Lage stimmt. Es fehlt das Positionierverhalten: TURN, und als Vorschub FMAX",
            "The orientation is right. The positioning is missing: TURN, with FMAX as the feed",
        )),
        (
            Require::Move { dist, feed },
            Some(Positioning::Move { dist: Some(d), feed: Some(Feed::Value(f)) }),
        ) if (d - dist).abs() < VALUE_TOL && (f - feed).abs() < VALUE_TOL => None,
        (Require::Move { dist, feed }, _) => Some(texts(
            format!(
                "Die Lage stimmt. Positionierverhalten prüfen: MOVE mit DIST{} und F{}",
                fmt_deg(dist),
                fmt_deg(feed)
            ),
            format!(
                "The orientation is right. Check the positioning: MOVE with DIST{} and F{}",
                fmt_deg(dist),
                fmt_deg(feed)
            ),
        )),
    }
}

/// The solver's answer for a set-up, as an [`Exercise`] check.
fn axes_exercise(
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
    let words = |a: &AxisValues| a.iter().map(|(ax, v)| axis_word(ax, v)).collect::<Vec<_>>().join(" ");
    let chosen = explanation.chosen_axes();
    let other = explanation
        .candidates
        .iter()
        .enumerate()
        .find(|(i, _)| Some(*i) != explanation.chosen)
        .map(|(_, c)| c.axes);
    let (solution, equivalent, mistake) = match chosen {
        Some(a) => (
            words(&a),
            format!("PLANE AXIAL {}", words(&a)),
            other.map_or((Answer::ControlError, Hint::ControlFinds), |o| {
                (Answer::Text(words(&o)), Hint::OtherSolution)
            }),
        ),
        None => {
            let m = explanation
                .error_message
                .map_or_else(|| "Winkel nicht erlaubt".to_owned(), |m| m.de().to_owned());
            (
                m.clone(),
                m,
                (Answer::Text(other.map_or_else(String::new, |o| words(&o))), Hint::ControlRefuses),
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
fn value_exercise(
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
fn fmt_value(v: f64) -> String {
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

fn limit_a(min: f64, max: f64) -> (RotaryAxis, Limits) {
    (RotaryAxis::A, Limits { min, max })
}

fn selection_text(sel: Option<Selection>) -> &'static str {
    match sel {
        None => "",
        Some(Selection::Seq(Sign::Plus)) => " SEQ+",
        Some(Selection::Seq(Sign::Minus)) => " SEQ-",
        Some(Selection::Sym(Sign::Plus)) => " SYM+",
        Some(Selection::Sym(Sign::Minus)) => " SYM-",
    }
}

fn transform_text(t: Option<TransformMode>) -> &'static str {
    match t {
        None => "",
        Some(TransformMode::CoordRot) => " COORD ROT",
        Some(TransformMode::TableRot) => " TABLE ROT",
    }
}

#[cfg(test)]
mod tests;
