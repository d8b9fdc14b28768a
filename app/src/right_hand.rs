//! The right-hand rule exercise (seed 000 §2.2): the axis and angle the demo shows, the PLANE
//! block it opened on, the "try it" task and its verdict. A pure reducer without effects; the
//! component `web/src/components/right_hand_demo.rs` renders it and sends its actions, the scene
//! is drawn by `web/src/render/right_hand.rs`.

use schwenkbar_core::plane::RelAxis;
use schwenkbar_core::solve::fmt_deg;

use crate::i18n::Lang;

/// The practice tasks of "try it": axis and signed angle, both signs on every axis.
pub const TASKS: [(RelAxis, f64); 6] = [
    (RelAxis::Spb, 30.0),
    (RelAxis::Spa, -45.0),
    (RelAxis::Spc, 60.0),
    (RelAxis::Spb, -20.0),
    (RelAxis::Spa, 30.0),
    (RelAxis::Spc, -90.0),
];

/// Tolerance of a trainee's turn, degrees (a drag cannot be exact).
pub const TOLERANCE: f64 = 5.0;

/// How a trainee's turn compares with the task.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    Right,
    /// Right size, wrong direction: the classic mistake the demo is for.
    WrongSign,
    /// Wrong axis or size.
    Off,
}

/// The verdict on turning `angle` about `axis` for `task`.
#[must_use]
pub fn check(task: (RelAxis, f64), axis: RelAxis, angle: f64) -> Verdict {
    if axis == task.0 && (angle - task.1).abs() <= TOLERANCE {
        Verdict::Right
    } else if axis == task.0 && (angle + task.1).abs() <= TOLERANCE {
        Verdict::WrongSign
    } else {
        Verdict::Off
    }
}

/// The first turn the control makes for `angles` (about X, then Y, then Z): the axis the demo
/// opens on for a block.
#[must_use]
pub fn first_turn(angles: [f64; 3]) -> RelAxis {
    RelAxis::ALL.into_iter().zip(angles).find(|(_, a)| a.abs() > 1e-9).map_or(RelAxis::Spc, |(t, _)| t)
}

/// What the demo shows and asks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RightHand {
    /// The axis the plane turns about.
    pub axis: RelAxis,
    /// The signed turn, whole degrees in −180…+180.
    pub angle: f64,
    /// The index into [`TASKS`] of the task asked, if "try it" was pressed.
    pub task: Option<usize>,
    /// The verdict on the last "check"; cleared by any turn or pick.
    pub verdict: Option<Verdict>,
    /// The turns about X, Y and Z (SPA, SPB, SPC) of the PLANE block the demo shows, if any.
    pub block_turns: Option<[f64; 3]>,
}

impl Default for RightHand {
    /// Musterprogramm 1's turn (`PLANE SPATIAL SPA+0 SPB+15 SPC+0`, block 10).
    fn default() -> Self {
        RightHand { axis: RelAxis::Spb, angle: 15.0, task: None, verdict: None, block_turns: None }
    }
}

/// What the trainee does in the demo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RightHandAction {
    /// The trainer's cursor is on this PLANE block (its turns about X, Y, Z), or on none: a new
    /// block shows its first turn.
    Block(Option<[f64; 3]>),
    /// An axis button: with a block its turn about that axis, without one the flat plane.
    Pick(RelAxis),
    /// A drag or the slider: the plane turned to this angle (rounded to whole degrees).
    Turn(f64),
    /// "Ausprobieren" / "Nächste Aufgabe": the next task, from the untilted plane about Y.
    NextTask,
    /// "Prüfen": the verdict on the current turn.
    Check,
}

impl RightHand {
    /// The state after `action` (no effects: the demo saves nothing).
    #[must_use]
    pub fn apply(&self, action: RightHandAction) -> RightHand {
        let mut next = *self;
        match action {
            RightHandAction::Block(turns) => {
                next.block_turns = turns;
                if let Some(turns) = turns.filter(|&t| Some(t) != self.block_turns) {
                    next.axis = first_turn(turns);
                    next.angle = turns[next.axis as usize];
                    next.verdict = None;
                }
            }
            RightHandAction::Pick(axis) => {
                next.axis = axis;
                next.angle = self.block_turns.map_or(0.0, |t| t[axis as usize]);
                next.verdict = None;
            }
            RightHandAction::Turn(angle) => {
                if angle.is_finite() {
                    next.angle = angle.round().clamp(-180.0, 180.0);
                    next.verdict = None;
                }
            }
            RightHandAction::NextTask => {
                next.task = Some(self.task.map_or(0, |i| (i + 1) % TASKS.len()));
                next.axis = RelAxis::Spb;
                next.angle = 0.0;
                next.verdict = None;
            }
            RightHandAction::Check => {
                next.verdict = self.task.map(|i| check(TASKS[i], self.axis, self.angle));
            }
        }
        next
    }

    /// During a task the angle and the block would give the sign away: hidden until checked.
    #[must_use]
    pub fn hidden(&self) -> bool {
        self.task.is_some() && self.verdict.is_none()
    }

    /// The task prompt ("Drehen Sie die Ebene um +30° um Y"), if a task is asked.
    #[must_use]
    pub fn task_text(&self, lang: Lang) -> Option<String> {
        let (axis, angle) = TASKS[self.task?];
        let angle = fmt_deg(angle);
        Some(match lang {
            Lang::De => format!("Drehen Sie die Ebene um {angle}° um {}", axis.about()),
            Lang::En => format!("Turn the plane by {angle}° about {}", axis.about()),
        })
    }

    /// The verdict as the demo says it: its CSS class and its text.
    #[must_use]
    pub fn feedback(&self, lang: Lang) -> Option<(&'static str, &'static str)> {
        Some(match self.verdict? {
            Verdict::Right => (
                "right",
                lang.t(
                    "Richtig! Daumen in Plus-Richtung, die Finger zeigen die positive Drehung.",
                    "Right! Thumb along plus, the fingers show the positive turn.",
                ),
            ),
            Verdict::WrongSign => (
                "wrong-sign",
                lang.t(
                    "Falsches Vorzeichen: richtig gedreht, aber andersherum. Daumen in Plus-Richtung der Achse – die Finger zeigen Plus.",
                    "Wrong sign: the right amount, the other way round. Thumb along the plus axis – the fingers show plus.",
                ),
            ),
            Verdict::Off => {
                ("off", lang.t("Noch nicht: Achse und Winkel prüfen.", "Not yet: check the axis and the angle."))
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use RightHandAction::{Block, Check, NextTask, Pick, Turn};

    fn after(actions: &[RightHandAction]) -> RightHand {
        actions.iter().fold(RightHand::default(), |s, &a| s.apply(a))
    }

    #[test]
    fn try_it_tells_a_wrong_sign_from_a_wrong_turn() {
        let task = (RelAxis::Spb, 30.0);
        assert_eq!(check(task, RelAxis::Spb, 28.0), Verdict::Right);
        assert_eq!(check(task, RelAxis::Spb, -31.0), Verdict::WrongSign);
        assert_eq!(check(task, RelAxis::Spa, 30.0), Verdict::Off);
        assert_eq!(check(task, RelAxis::Spb, 60.0), Verdict::Off);
        assert!(TASKS.iter().any(|t| t.1 < 0.0) && TASKS.iter().any(|t| t.1 > 0.0));
    }

    #[test]
    fn a_task_hides_the_sign_until_checked_and_a_turn_asks_again() {
        let s = after(&[NextTask]);
        assert_eq!((s.task, s.axis, s.angle), (Some(0), RelAxis::Spb, 0.0));
        assert!(s.hidden());
        assert_eq!(s.task_text(Lang::De).as_deref(), Some("Drehen Sie die Ebene um +30° um Y"));
        // The first task is +30° about Y: turned the other way round, the sign is wrong.
        let s = after(&[NextTask, Turn(-29.6), Check]);
        assert_eq!((s.angle, s.verdict), (-30.0, Some(Verdict::WrongSign)));
        assert!(!s.hidden());
        assert_eq!(s.feedback(Lang::En).map(|f| f.0), Some("wrong-sign"));
        let s = s.apply(Turn(31.0));
        assert_eq!(s.verdict, None, "a new turn needs a new check");
        assert_eq!(s.apply(Check).verdict, Some(Verdict::Right));
        // The second task is about X: a turn about Y is off.
        let s = after(&[NextTask, NextTask, Turn(-45.0), Check]);
        assert_eq!(s.task_text(Lang::En).as_deref(), Some("Turn the plane by -45° about X"));
        assert_eq!(s.verdict, Some(Verdict::Off));
        assert_eq!(s.apply(Pick(RelAxis::Spa)).apply(Turn(-45.0)).apply(Check).verdict, Some(Verdict::Right));
        // The tasks go round; without a task "check" says nothing.
        assert_eq!(after(&[NextTask; 7]).task, Some(0));
        assert_eq!(after(&[Turn(30.0), Check]).verdict, None);
    }

    #[test]
    fn a_block_opens_on_its_first_turn_and_each_axis_shows_its_turn() {
        // PLANE SPATIAL SPA+0 SPB+30 SPC+90: the control turns about Y first.
        let turns = [0.0, 30.0, 90.0];
        let s = after(&[Block(Some(turns))]);
        assert_eq!((s.axis, s.angle), (RelAxis::Spb, 30.0));
        assert_eq!(s.apply(Pick(RelAxis::Spc)).angle, 90.0);
        // The same block again (a re-render) keeps what the trainee turned.
        let turned = s.apply(Turn(12.0));
        assert_eq!(turned.apply(Block(Some(turns))).angle, 12.0);
        // Without a block an axis starts from the flat plane.
        let s = s.apply(Block(None)).apply(Pick(RelAxis::Spc));
        assert_eq!(s.angle, 0.0);
    }

    #[test]
    fn a_plane_block_gives_its_spatial_angles_and_the_first_turn() {
        let a = crate::preview::block_angles("7 PLANE SPATIAL SPA+0 SPB+30 SPC+90 TURN FMAX").unwrap();
        assert!((a[1] - 30.0).abs() < 1e-9 && (a[2] - 90.0).abs() < 1e-9 && a[0].abs() < 1e-9, "{a:?}");
        assert_eq!(first_turn(a), RelAxis::Spb);
        // EULER (90, 45, 0) = SPATIAL (45, 0, 90) (DOMAIN.md oracle 3): the same orientation.
        let e = crate::preview::block_angles("PLANE EULER EULPR+90 EULNU+45 EULROT+0 STAY").unwrap();
        let (r, s) = (
            schwenkbar_core::orientation::spatial(e[0], e[1], e[2]),
            schwenkbar_core::orientation::spatial(45.0, 0.0, 90.0),
        );
        assert!(r.abs_diff_eq(s, 1e-6), "{e:?}");
        assert_eq!(first_turn(e), RelAxis::Spa);
        assert_eq!(crate::preview::block_angles("PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 TURN FMAX"), None);
        assert_eq!(crate::preview::block_angles("L X+10 R0 FMAX"), None);
    }

    #[test]
    fn a_turn_is_whole_degrees_within_half_a_turn() {
        assert_eq!(after(&[Turn(12.4)]).angle, 12.0);
        assert_eq!(after(&[Turn(250.0)]).angle, 180.0);
        assert_eq!(after(&[Turn(-999.0)]).angle, -180.0);
        assert_eq!(after(&[Turn(f64::NAN)]).angle, RightHand::default().angle);
    }
}
