//! Exercises answered with a PLANE block: the target is a rotation R, and an answer counts when
//! its block (any PLANE form) gives the same R. The same block with angle signs flipped, or the
//! tool tilted the mirrored way, is a sign error and gets the right-hand rule (seed 000 §2.2).

use glam::DMat3;

use super::{
    Answer, AnswerKind, Check, Exercise, Hint, ORIENTATION_TOL, Rng, Spec, TURN_FMAX, VALUE_TOL, Verdict,
    euler_def, plane, spatial_def,
};
use crate::format::plane_rounded;
use crate::lang::Text;
use crate::orientation::{self, Context};
use crate::plane::{Feed, PlaneBlock, PlaneDef, Positioning};
use crate::solve::fmt_deg;

/// What an orientation answer must also get right.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Require {
    Nothing,
    TurnFmax,
    Move { dist: f64, feed: f64 },
}

impl Require {
    /// The positioning the solution writes.
    fn positioning(self) -> Positioning<f64> {
        match self {
            Require::Nothing | Require::TurnFmax => TURN_FMAX,
            Require::Move { dist, feed } => {
                Positioning::Move { dist: Some(dist), feed: Some(Feed::Value(feed)) }
            }
        }
    }
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
pub(super) const TILTS: [f64; 10] = [10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 60.0];

fn orientation_exercise(
    spec: Spec,
    variant: u32,
    prompt: Text,
    spatial: [f64; 3],
    require: Require,
    not_euler: bool,
) -> Exercise {
    let target = orientation::spatial(spatial[0], spatial[1], spatial[2]);
    let positioning = Some(require.positioning());
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
        solution: Text::same(plane_rounded(&plane(spatial_def(spatial), positioning))),
        equivalent: Text::same(plane_rounded(&plane(euler_def(orientation::to_euler(&target)), positioning))),
        typical_mistake: (
            Answer::Text(plane_rounded(&plane(spatial_def(flipped), positioning))),
            Hint::RightHand,
        ),
        program: None,
        check: Check::Orientation { target, spatial, require, not_euler },
    }
}

pub(super) fn lean(spec: Spec, variant: u32, rng: &mut Rng) -> Exercise {
    // Variant 0 differs per exercise, so the course does not ask the same lean four times.
    // DialogTurn's is the block lesson 3's steps enter, ProgramLean's the plane of Musterprogramm 1
    // (block 10, lesson 8); the lesson texts rely on those two.
    let (toward, theta) = match (spec, variant) {
        (Spec::Lean, 0) => (Toward::MinusY, 20.0),
        (Spec::DialogTurn, 0) => (Toward::PlusX, 25.0),
        (Spec::DialogMove, 0) => (Toward::MinusX, 30.0),
        (_, 0) => (Toward::PlusX, 15.0),
        _ => (rng.pick(&DIRECTIONS), rng.pick(&TILTS)),
    };
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
    let prompt = Text::owned(
        format!(
            "Die Fläche ist so geneigt, dass das Werkzeug senkrecht auf ihr um {t}° in Richtung {d} gekippt steht (die Ebene wird nicht zusätzlich um Z gedreht). Geben Sie den PLANE-Satz ein.{de_tail}"
        ),
        format!(
            "The face is inclined so that a tool perpendicular to it leans {t}° towards {d} (the plane is not turned about Z as well). Enter the PLANE block.{en_tail}"
        ),
    );
    orientation_exercise(spec, variant, prompt, toward.spatial(theta), require, false)
}

pub(super) fn turn_about_z(variant: u32, rng: &mut Rng) -> Exercise {
    let phi = if variant == 0 { 30.0 } else { rng.pick(&[15.0, 20.0, 30.0, 45.0, 60.0, 90.0]) };
    let toward_plus_y = variant == 0 || rng.pick(&[true, false]);
    let (dir, spc) = if toward_plus_y { ("+Y", phi) } else { ("−Y", -phi) };
    let t = fmt_deg(phi).trim_start_matches('+').to_owned();
    let prompt = Text::owned(
        format!(
            "Das Werkzeug bleibt senkrecht (Z). Nur die Bearbeitungsebene soll um {t}° um die Z-Achse gedreht werden, so dass ihre X-Achse in Richtung {dir} dreht. Geben Sie den PLANE-Satz ein."
        ),
        format!(
            "The tool stays vertical (Z). Only the working plane is to turn {t}° about the Z axis, so that its X axis turns towards {dir}. Enter the PLANE block."
        ),
    );
    orientation_exercise(Spec::TurnAboutZ, variant, prompt, [0.0, 0.0, spc], Require::Nothing, false)
}

pub(super) fn lean_and_turn(variant: u32, rng: &mut Rng) -> Exercise {
    let (theta, phi) = if variant == 0 {
        (30.0, 90.0)
    } else {
        (rng.pick(&TILTS), rng.pick(&[30.0, 45.0, 60.0, 90.0, -90.0]))
    };
    let spatial = [0.0, theta, phi];
    let r = orientation::spatial(0.0, theta, phi);
    let t = orientation::tool_axis(&r);
    let prompt = Text::owned(
        format!(
            "Erst um Y um {} kippen (SPB), dann um Z um {} drehen (SPC). Die Werkzeugachse zeigt danach in Richtung ({:.4}, {:.4}, {:.4}). Geben Sie den PLANE-Satz ein – SPATIAL oder eine andere Form.",
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

pub(super) fn euler_to_other(variant: u32, rng: &mut Rng) -> Exercise {
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
    let given = plane_rounded(&plane(euler_def(e), None));
    let prompt = Text::owned(
        format!(
            "Gegeben: {given}. Geben Sie dieselbe Lage als anderen PLANE-Satz ein (z. B. PLANE SPATIAL)."
        ),
        format!("Given: {given}. Enter the same orientation as another PLANE block (e.g. PLANE SPATIAL)."),
    );
    let mut ex = orientation_exercise(Spec::EulerToOther, variant, prompt, spatial, Require::Nothing, true);
    // The other equivalent form: VECTOR (base = tilted X, normal = tool axis).
    let vector = PlaneDef::Vector { base: r.x_axis.to_array(), normal: r.z_axis.to_array() };
    ex.equivalent = Text::same(plane_rounded(&plane(vector, Some(TURN_FMAX))));
    ex
}

pub(super) fn chamfer(variant: u32, rng: &mut Rng) -> Exercise {
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
    let prompt = Text::owned(
        format!(
            "Fase unter 45° an der Seite {side} des Rohteils: das Werkzeug steht senkrecht auf der Fase und kippt 45° in Richtung {side}. Die X-Achse der Bearbeitungsebene liegt entlang der Kante (EULROT 0). Geben Sie den PLANE-Satz ein – EULER oder eine andere Form."
        ),
        format!(
            "A 45° chamfer on the {side} side of the blank: the tool is perpendicular to the chamfer and leans 45° towards {side}. The working plane's X axis runs along the edge (EULROT 0). Enter the PLANE block – EULER or another form."
        ),
    );
    let spatial = orientation::to_spatial(&r);
    let mut ex = orientation_exercise(Spec::Chamfer, variant, prompt, spatial, Require::Nothing, false);
    // Here the EULER block is the natural answer; SPATIAL the equivalent one.
    ex.solution = Text::same(plane_rounded(&plane(euler_def([pr, 45.0, 0.0]), Some(TURN_FMAX))));
    ex.equivalent = Text::same(plane_rounded(&plane(spatial_def(spatial), Some(TURN_FMAX))));
    // The typical mistake: the chamfer on the opposite side (EULPR off by 180°). It tilts the
    // tool the other way, so it gets the right-hand hint.
    let wrong_pr = if pr > 0.0 { pr - 180.0 } else { pr + 180.0 };
    let mistake = plane_rounded(&plane(euler_def([wrong_pr, 45.0, 0.0]), Some(TURN_FMAX)));
    ex.typical_mistake = (Answer::Text(mistake), Hint::RightHand);
    ex
}

fn close(a: &DMat3, b: &DMat3) -> bool {
    (0..3).all(|c| (a.col(c) - b.col(c)).abs().max_element() < ORIENTATION_TOL)
}

/// The single PLANE block of an answer, with numbers only.
fn answer_block(answer: &Answer) -> Result<PlaneBlock<f64>, Text> {
    let Answer::Text(text) = answer else {
        return Err(Text::new("Hier ist ein PLANE-Satz gefragt", "A PLANE block is asked for here"));
    };
    let block = crate::parse::plane_block(text.trim())
        .map_err(|e| Text::owned(e.message(crate::Lang::De), e.message(crate::Lang::En)))?;
    block.numbers().map_err(|index| {
        Text::owned(
            format!("{} hat hier keinen Wert: bitte Zahlen eingeben", crate::ast::QName(index)),
            format!("{} has no value here: please enter numbers", crate::ast::QName(index)),
        )
    })
}

pub(super) fn check(
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
            text: Text::new(
                "Gefragt ist eine Lage im Raum: PLANE SPATIAL, EULER, PROJECTED, VECTOR oder POINTS",
                "An orientation in space is asked for: PLANE SPATIAL, EULER, PROJECTED, VECTOR or POINTS",
            ),
        };
    }
    if not_euler && matches!(block.def, PlaneDef::Euler { .. }) {
        return Verdict::Wrong {
            hint: Hint::SameForm,
            text: Text::new(
                "Das ist wieder PLANE EULER – gefragt ist eine andere Form, z. B. PLANE SPATIAL",
                "That is PLANE EULER again – another form is asked for, e.g. PLANE SPATIAL",
            ),
        };
    }
    let r = match orientation::orientation(&block.def, &Context::default()) {
        Ok(r) => r,
        Err(e) => {
            return Verdict::Unreadable(e.message());
        }
    };
    if close(&r, target) {
        return match positioning_problem(&block, require) {
            None => Verdict::Correct(Text::owned(
                format!(
                    "Richtig. Dieselbe Lage als SPATIAL: {}",
                    plane_rounded(&plane(spatial_def(spatial), None))
                ),
                format!(
                    "Correct. The same orientation as SPATIAL: {}",
                    plane_rounded(&plane(spatial_def(spatial), None))
                ),
            )),
            Some(text) => Verdict::Wrong { hint: Hint::Positioning, text },
        };
    }
    if let Some((_, flipped)) =
        sign_flips(spatial).find(|(s, _)| close(&r, &orientation::spatial(s[0], s[1], s[2])))
    {
        return Verdict::Wrong { hint: Hint::RightHand, text: right_hand_hint(flipped) };
    }
    let (t, want) = (orientation::tool_axis(&r), orientation::tool_axis(target));
    if (t - want).abs().max_element() < ORIENTATION_TOL {
        let gamma = target.x_axis.angle_between(r.x_axis).to_degrees();
        return Verdict::Wrong {
            hint: Hint::TurnedAboutToolAxis,
            text: Text::owned(
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
        return Verdict::Wrong { hint: Hint::RightHand, text: right_hand_hint(non_zero(spatial)) };
    }
    Verdict::Wrong {
        hint: Hint::Wrong,
        text: Text::new(
            "Noch nicht: Stellen Sie sich die Fläche vor und kippen Sie die Ebene Schritt für Schritt – erst um X (SPA), dann um Y (SPB), dann um Z (SPC)",
            "Not yet: picture the face and tilt the plane step by step – first about X (SPA), then about Y (SPB), then about Z (SPC)",
        ),
    }
}

/// Every variant of `spatial` with at least one non-zero angle's sign flipped, and which angles
/// it flips.
fn sign_flips(spatial: [f64; 3]) -> impl Iterator<Item = ([f64; 3], [bool; 3])> {
    (1_u8..8).filter_map(move |mask| {
        let mut s = spatial;
        let flipped = [0, 1, 2].map(|i| mask & (1 << i) != 0);
        for (v, _) in s.iter_mut().zip(flipped).filter(|(_, f)| *f) {
            if v.abs() < 1e-9 {
                return None;
            }
            *v = -*v;
        }
        Some((s, flipped))
    })
}

/// What a positive spatial angle does (seed 000 §2.2, DOMAIN.md §2.1), as data so the tests can
/// check every claim against the orientation maths: the angle's word, the column of R it moves
/// (2 = tool axis, 0 = the plane's X axis) and the direction that column turns towards.
pub(super) struct SignRule {
    pub word: &'static str,
    pub column: usize,
    pub towards: glam::DVec3,
}

impl SignRule {
    /// `+X`, `−Y`: the unit direction [`SignRule::towards`] as the lesson texts name it.
    fn towards_name(&self) -> String {
        let t = self.towards;
        let (name, v) = if t.x.abs() > 0.5 {
            ("X", t.x)
        } else if t.y.abs() > 0.5 {
            ("Y", t.y)
        } else {
            ("Z", t.z)
        };
        format!("{}{name}", if v < 0.0 { '−' } else { '+' })
    }
}

pub(super) const SIGN_RULES: [SignRule; 3] = [
    SignRule { word: "SPA", column: 2, towards: glam::DVec3::NEG_Y },
    SignRule { word: "SPB", column: 2, towards: glam::DVec3::X },
    SignRule { word: "SPC", column: 0, towards: glam::DVec3::Y },
];

/// The right-hand rule (seed 000 §2.2), with the sign rule of each angle in `about` (SPA, SPB,
/// SPC): only the angles the answer got wrong, so an SPC task does not talk about SPB.
pub(super) fn right_hand_hint(about: [bool; 3]) -> Text {
    let (mut de, mut en) = (
        "Vorzeichen prüfen – Rechte-Hand-Regel: Der Daumen zeigt in die positive Achsrichtung, die gekrümmten Finger zeigen die positive Drehrichtung.".to_owned(),
        "Check the sign – right-hand rule: the thumb points along the positive axis, the curled fingers show the positive direction of rotation.".to_owned(),
    );
    for rule in SIGN_RULES.iter().zip(about).filter_map(|(r, on)| on.then_some(r)) {
        let (w, to) = (rule.word, rule.towards_name());
        if rule.column == 2 {
            de.push_str(&format!(" {w}+ kippt die Werkzeugachse von +Z nach {to}."));
            en.push_str(&format!(" {w}+ tilts the tool axis from +Z towards {to}."));
        } else {
            de.push_str(&format!(" {w}+ dreht die X-Achse der Ebene von +X nach {to}."));
            en.push_str(&format!(" {w}+ turns the plane's X axis from +X towards {to}."));
        }
    }
    Text::owned(de, en)
}

/// The angles of `spatial` that are not zero (what a sign hint can be about).
pub(super) fn non_zero(spatial: [f64; 3]) -> [bool; 3] {
    spatial.map(|v| v.abs() > 1e-9)
}

fn positioning_problem(block: &PlaneBlock<f64>, require: Require) -> Option<Text> {
    match (require, block.positioning) {
        (Require::Nothing, _) => None,
        (Require::TurnFmax, Some(Positioning::Turn { feed: Some(Feed::Max), .. })) => None,
        (Require::TurnFmax, _) => Some(Text::new(
            "Die Lage stimmt. Es fehlt das Positionierverhalten: TURN, und als Vorschub FMAX",
            "The orientation is right. The positioning is missing: TURN, with FMAX as the feed",
        )),
        (
            Require::Move { dist, feed },
            Some(Positioning::Move { dist: Some(d), feed: Some(Feed::Value(f)) }),
        ) if (d - dist).abs() < VALUE_TOL && (f - feed).abs() < VALUE_TOL => None,
        (Require::Move { dist, feed }, _) => Some(Text::owned(
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
