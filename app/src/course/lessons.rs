//! What each lesson shows and asks: its live view and its exercises (the words are in
//! [`super::texts`]). The programs ship in `static/course/` and `static/programs/`.

use schwenkbar_core::course::{ChooseKind, RunKind, Spec};

use super::texts::{LESSONS, LessonText};

pub const COUNT: usize = 11;

/// The live view next to a lesson's text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Widget {
    /// The TNC screen with this program on this machine (not saved as the trainee's work).
    Trainer { program: &'static str, machine: &'static str },
    /// The rotatable plane with the right hand.
    RightHand,
    /// The same PLANE block with MOVE, TURN and STAY in three 3D views; `block` is its number.
    Positioning { programs: [&'static str; 3], block: u32 },
    /// The SEQ/SYM experiment bench with the seed's table rows.
    SolveLab,
}

/// One lesson.
pub struct Lesson {
    pub text: &'static LessonText,
    pub widget: Widget,
    pub exercises: &'static [Spec],
}

const fn trainer(program: &'static str) -> Widget {
    Widget::Trainer { program, machine: "ac-table" }
}

/// Lesson `index` (0-based), if there is one.
#[must_use]
pub fn lesson(index: usize) -> Option<Lesson> {
    let (widget, exercises): (Widget, &'static [Spec]) = match index {
        0 => (
            trainer(include_str!("../../../static/course/l01_raumwinkel.h")),
            &[Spec::LeanAndTurn, Spec::Choose(ChooseKind::OtherMachine)],
        ),
        1 => (Widget::RightHand, &[Spec::Lean, Spec::TurnAboutZ]),
        2 => (
            trainer(
                "0 BEGIN PGM DIALOG MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 16 Z S5000\n4 END PGM DIALOG MM\n",
            ),
            &[Spec::DialogTurn, Spec::DialogMove],
        ),
        3 => (
            Widget::Positioning {
                programs: [
                    include_str!("../../../static/course/l04_move.h"),
                    include_str!("../../../static/course/l04_turn.h"),
                    include_str!("../../../static/course/l04_stay.h"),
                ],
                block: 8,
            },
            &[Spec::Run(RunKind::Turn), Spec::Run(RunKind::Stay), Spec::Run(RunKind::StayQ120)],
        ),
        4 => (
            Widget::SolveLab,
            &[
                Spec::Choose(ChooseKind::ShortestPath),
                Spec::Choose(ChooseKind::Option),
                Spec::Choose(ChooseKind::Limits),
            ],
        ),
        5 => (
            trainer(include_str!("../../../static/course/l06_table_rot.h")),
            &[Spec::Choose(ChooseKind::TableRot), Spec::Choose(ChooseKind::CoordRot)],
        ),
        6 => (
            trainer(include_str!("../../../static/course/l07_reset.h")),
            &[Spec::Run(RunKind::ResetStay), Spec::Run(RunKind::ResetTurn)],
        ),
        7 => (
            trainer(include_str!("../../../static/programs/musterprogramm1.h")),
            &[Spec::Run(RunKind::Musterprogramm1), Spec::ProgramLean],
        ),
        8 => (
            trainer(include_str!("../../../static/programs/musterprogramm2.h")),
            &[Spec::Run(RunKind::DatumThenPlane), Spec::Run(RunKind::Turn)],
        ),
        9 => (
            trainer(include_str!("../../../static/programs/euler_fasen.h")),
            &[Spec::Chamfer, Spec::EulerToOther],
        ),
        10 => (
            trainer(include_str!("../../../static/course/l11_reihenfolge.h")),
            &[Spec::Run(RunKind::DatumThenMirror), Spec::Run(RunKind::DatumThenPlane)],
        ),
        _ => return None,
    };
    Some(Lesson { text: LESSONS.get(index)?, widget, exercises })
}

#[cfg(test)]
mod tests {
    use schwenkbar_core::machine::Machine;
    use schwenkbar_core::sim::{SimOptions, simulate};

    use super::*;

    #[test]
    fn every_lesson_has_words_a_view_and_programs_that_parse_and_run_to_the_end() {
        for i in 0..COUNT {
            let lesson = lesson(i).unwrap();
            assert!(!lesson.text.paragraphs.is_empty() && !lesson.text.title.de.is_empty());
            let programs: Vec<(&str, &str)> = match lesson.widget {
                Widget::Trainer { program, machine } => vec![(program, machine)],
                Widget::Positioning { programs, .. } => programs.iter().map(|p| (*p, "ac-table")).collect(),
                Widget::RightHand | Widget::SolveLab => vec![],
            };
            for (text, machine) in programs {
                let (program, diags) = schwenkbar_core::parse(text);
                assert!(diags.is_empty(), "lesson {}: {diags:?}", i + 1);
                let sim = simulate(&program, &Machine::builtin(machine).unwrap(), &SimOptions::default());
                assert!(sim.error.is_none(), "lesson {}: {:?}", i + 1, sim.error);
            }
        }
        assert!(lesson(COUNT).is_none());
    }
}
