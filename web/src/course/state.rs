//! The course's one reducer: the open lesson's exercises, the progress and the instructor view.
//! Pure; the components render it and the browser keeps `progress` (see `components::course`).

use std::rc::Rc;

use schwenkbar_core::course::{Answer, AnswerKind, Exercise, Spec, Verdict};
use yew::Reducible;

use super::Route;
use super::lessons::{self, COUNT};
use super::progress::Progress;
use crate::i18n::{Lang, Text};

/// One exercise as the trainee works on it.
#[derive(Debug, Clone)]
pub struct ExerciseState {
    pub exercise: Rc<Exercise>,
    /// What is in the answer field (kept through checks, so nothing typed is lost).
    pub input: String,
    pub verdict: Option<Verdict>,
    /// Wrong or unreadable answers so far.
    pub tries: u32,
    pub solution_shown: bool,
}

impl ExerciseState {
    fn new(spec: Spec, variant: u32) -> ExerciseState {
        ExerciseState {
            exercise: Rc::new(Exercise::generate(spec, variant)),
            input: String::new(),
            verdict: None,
            tries: 0,
            solution_shown: false,
        }
    }

    /// The solution button: in the instructor view always offered (shown only when pressed);
    /// a trainee gets it after a first try.
    #[must_use]
    pub fn solution_offered(&self, instructor: bool) -> bool {
        instructor || self.tries > 0 || self.verdict.as_ref().is_some_and(Verdict::is_correct)
    }
}

#[derive(Debug, Clone)]
pub struct CourseState {
    pub route: Route,
    pub progress: Progress,
    /// The open lesson's exercises (empty on the overview).
    pub exercises: Vec<ExerciseState>,
    /// A program an exercise opened in the lesson's trainer, instead of the lesson's own.
    pub trainer_program: Option<(Rc<str>, &'static str)>,
    /// Counts the programs opened in the trainer: the trainer is rebuilt when it changes.
    pub trainer_generation: u32,
    /// The PLANE block under the trainer's cursor, for "take the block from the program".
    pub trainer_block: Option<String>,
    pub notice: Option<Text>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum CourseAction {
    Go(Route),
    ToggleInstructor,
    ToggleLang,
    Input(usize, String),
    Check(usize),
    /// "The control refuses": the answer for exercises where that is an option.
    Refuse(usize),
    ShowSolution(usize),
    Fresh(usize),
    OpenInTrainer(usize),
    /// Fill the answer field with the trainer's cursor block.
    TakeBlock(usize),
    TrainerBlock(Option<String>),
    /// A message from a side effect (e.g. the progress could not be saved).
    Notice(Text),
}

impl CourseState {
    /// The course at start-up from the saved progress record (a bad one is reported and replaced).
    #[must_use]
    pub fn start(saved: Option<&str>, route: Route) -> CourseState {
        let (progress, notice) = match saved.map(Progress::from_text) {
            None => (Progress::default(), None),
            Some(Ok(p)) => (p, None),
            Some(Err(t)) => (Progress::default(), Some(t)),
        };
        let state = CourseState {
            route: Route::Overview,
            progress,
            exercises: Vec::new(),
            trainer_program: None,
            trainer_generation: 0,
            trainer_block: None,
            notice,
        };
        state.apply(CourseAction::Go(route))
    }

    #[must_use]
    pub fn lang(&self) -> Lang {
        self.progress.lang
    }

    #[must_use]
    pub fn lesson_index(&self) -> Option<usize> {
        match self.route {
            Route::Lesson(i) if i < COUNT => Some(i),
            _ => None,
        }
    }

    #[must_use]
    pub fn apply(&self, action: CourseAction) -> CourseState {
        let mut s = self.clone();
        match action {
            CourseAction::Go(route) if route != s.route || s.exercises.is_empty() => s.open(route),
            CourseAction::Go(_) => {}
            CourseAction::ToggleInstructor => s.progress.instructor = !s.progress.instructor,
            CourseAction::ToggleLang => s.progress.lang = s.progress.lang.other(),
            CourseAction::Input(i, text) => {
                // Editing the answer clears the old verdict: it spoke of the old text.
                if let Some(e) = s.exercises.get_mut(i) {
                    e.input = text;
                    e.verdict = None;
                }
            }
            CourseAction::Check(i) => {
                let answer = s.exercises.get(i).map(|e| Answer::typed(&e.input));
                if let Some(answer) = answer {
                    s.check(i, &answer);
                }
            }
            CourseAction::Refuse(i) => s.check(i, &Answer::ControlError),
            CourseAction::ShowSolution(i) => {
                let instructor = s.progress.instructor;
                if let Some(e) = s.exercises.get_mut(i).filter(|e| e.solution_offered(instructor)) {
                    e.solution_shown = true;
                }
            }
            CourseAction::Fresh(i) => {
                if let Some(e) = s.exercises.get_mut(i) {
                    *e = ExerciseState::new(e.exercise.spec, e.exercise.variant + 1);
                }
            }
            CourseAction::OpenInTrainer(i) => {
                if let Some((program, machine)) = s.exercises.get(i).and_then(|e| e.exercise.program.clone())
                {
                    s.trainer_program = Some((program.into(), machine));
                    s.trainer_generation += 1;
                }
            }
            CourseAction::TakeBlock(i) => match (s.trainer_block.clone(), s.exercises.get_mut(i)) {
                (Some(block), Some(e)) => e.input = block,
                _ => {
                    s.notice = Some(Text::new(
                        "Im Programm steht der Cursor auf keinem PLANE-Satz",
                        "The program's cursor is not on a PLANE block",
                    ));
                }
            },
            CourseAction::TrainerBlock(block) => s.trainer_block = block,
            CourseAction::Notice(t) => s.notice = Some(t),
        }
        s
    }

    fn open(&mut self, route: Route) {
        self.route = route;
        self.trainer_program = None;
        self.trainer_block = None;
        self.exercises.clear();
        if let Some(lesson) = self.lesson_index().and_then(lessons::lesson) {
            self.exercises = lesson.exercises.iter().map(|&spec| ExerciseState::new(spec, 0)).collect();
        }
        if let Some(p) = self.lesson_index().and_then(|i| self.progress.lessons.get_mut(i)) {
            p.visited = true;
        }
    }

    fn check(&mut self, i: usize, answer: &Answer) {
        let lesson = self.lesson_index();
        let Some(e) = self.exercises.get_mut(i) else { return };
        let verdict = e.exercise.check(answer);
        if verdict.is_correct() {
            if let Some(p) = lesson.and_then(|l| self.progress.lessons.get_mut(l)) {
                p.solved |= 1 << i.min(7);
            }
        } else {
            e.tries += 1;
        }
        e.verdict = Some(verdict);
        self.notice = None;
    }

    /// Whether the answer field of exercise `i` also offers "the control refuses".
    #[must_use]
    pub fn offers_refusal(&self, i: usize) -> bool {
        self.exercises.get(i).is_some_and(|e| e.exercise.answer_kind == AnswerKind::Axes)
    }
}

impl Reducible for CourseState {
    type Action = CourseAction;

    fn reduce(self: Rc<Self>, action: CourseAction) -> Rc<Self> {
        // The trainer reports its cursor block after every render of its own; an unchanged one
        // must not re-render the course.
        if let CourseAction::TrainerBlock(b) = &action
            && *b == self.trainer_block
        {
            return self;
        }
        Rc::new(self.apply(action))
    }
}

#[cfg(test)]
mod tests {
    use schwenkbar_core::course::{Answer, Hint};

    use super::*;

    fn lesson(i: usize) -> CourseState {
        CourseState::start(None, Route::Lesson(i))
    }

    fn answer(s: &CourseState, i: usize, a: &Answer) -> CourseState {
        match a {
            Answer::Text(t) => s.apply(CourseAction::Input(i, t.clone())).apply(CourseAction::Check(i)),
            Answer::ControlError => s.apply(CourseAction::Refuse(i)),
        }
    }

    #[test]
    fn every_lesson_opens_with_two_to_five_exercises_that_accept_solutions_and_reject_mistakes() {
        for l in 0..COUNT {
            let s = lesson(l);
            assert!((2..=5).contains(&s.exercises.len()), "lesson {}", l + 1);
            assert!(s.progress.lessons[l].visited);
            for (i, e) in s.exercises.iter().enumerate() {
                let ex = e.exercise.clone();
                for good in [&ex.solution.de, &ex.equivalent.de] {
                    let done = answer(&s, i, &Answer::typed(good));
                    assert!(
                        done.exercises[i].verdict.as_ref().is_some_and(Verdict::is_correct),
                        "lesson {} ex {i}: {good}",
                        l + 1
                    );
                    assert_ne!(done.progress.lessons[l].solved & (1 << i), 0);
                }
                let (wrong, hint) = &ex.typical_mistake;
                let done = answer(&s, i, wrong);
                assert!(
                    matches!(done.exercises[i].verdict, Some(Verdict::Wrong { hint: h, .. }) if h == *hint),
                    "lesson {} ex {i}: {wrong:?}",
                    l + 1
                );
                assert_eq!(done.exercises[i].tries, 1);
                assert_eq!(done.progress.lessons[l].solved, 0);
            }
        }
    }

    #[test]
    fn a_wrong_answer_keeps_the_input_and_the_solution_waits_until_asked() {
        let s = lesson(1).apply(CourseAction::Input(0, "PLANE SPATIAL SPA-20 SPB+0 SPC+0".into()));
        // A trainee has no solution button before a first try.
        assert!(!s.exercises[0].solution_offered(false));
        assert!(!s.apply(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
        let s = s.apply(CourseAction::Check(0));
        assert!(matches!(s.exercises[0].verdict, Some(Verdict::Wrong { hint: Hint::RightHand, .. })));
        assert_eq!(s.exercises[0].input, "PLANE SPATIAL SPA-20 SPB+0 SPC+0");
        assert!(!s.exercises[0].solution_shown);
        assert!(s.apply(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
        // The instructor may reveal at once, but only when asked.
        let i = lesson(1).apply(CourseAction::ToggleInstructor);
        assert!(!i.exercises[0].solution_shown);
        assert!(i.apply(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
    }

    #[test]
    fn fresh_variant_changes_the_exercise_and_clears_the_answer() {
        let s = lesson(4).apply(CourseAction::Input(0, "A+1 C+1".into()));
        let f = s.apply(CourseAction::Fresh(0));
        assert_eq!(f.exercises[0].exercise.variant, 1);
        assert_ne!(f.exercises[0].exercise.prompt, s.exercises[0].exercise.prompt);
        assert!(f.exercises[0].input.is_empty());
    }

    #[test]
    fn progress_survives_a_reload_and_a_corrupt_record_is_reported() {
        let s = lesson(0);
        let sol = s.exercises[0].exercise.solution.de.clone();
        let s = answer(&s, 0, &Answer::typed(&sol)).apply(CourseAction::ToggleLang);
        let saved = s.progress.to_text();
        let back = CourseState::start(Some(&saved), Route::Overview);
        assert_eq!(back.progress, s.progress);
        assert_eq!(back.lang(), Lang::En);
        let bad = CourseState::start(Some("{not progress"), Route::Lesson(2));
        assert_eq!(bad.notice, Some(super::super::progress::UNREADABLE));
        assert_eq!(bad.route, Route::Lesson(2));
    }

    #[test]
    fn exercise_programs_open_in_the_trainer_and_the_block_can_be_taken_over() {
        let s = lesson(3).apply(CourseAction::OpenInTrainer(0));
        assert!(
            s.trainer_program.as_ref().is_some_and(|(p, m)| p.contains("PLANE SPATIAL") && *m == "ac-table")
        );
        let s = lesson(2).apply(CourseAction::TakeBlock(0));
        assert!(s.notice.is_some());
        let s = s
            .apply(CourseAction::TrainerBlock(Some("5 PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN FMAX".into())))
            .apply(CourseAction::TakeBlock(0))
            .apply(CourseAction::Check(0));
        assert!(s.exercises[0].verdict.as_ref().is_some_and(Verdict::is_correct));
    }
}
