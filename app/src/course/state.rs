//! The course's one reducer: the open lesson's exercises, the progress and the instructor view.
//! Pure; it asks for saving the progress and the preferences as [`Effect`]s, which the web
//! shell carries out.

use std::rc::Rc;

use schwenkbar_core::course::{Answer, AnswerKind, Exercise, Spec, Verdict};

use super::Route;
use super::lessons::{self, COUNT};
use super::progress::Progress;
use crate::effect::{Effect, Reducer};
use crate::i18n::{Lang, Text};
use crate::persist::{self, Prefs};

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
    /// Language and instructor view (`classroom`), shared with the trainer.
    pub prefs: Prefs,
    /// The open lesson's exercises (empty on the overview).
    pub exercises: Vec<ExerciseState>,
    /// A program an exercise opened in the lesson's trainer, instead of the lesson's own.
    pub trainer_program: Option<(Rc<str>, &'static str)>,
    /// Counts the programs opened in the trainer: the trainer is rebuilt when it changes.
    pub trainer_generation: u32,
    /// The PLANE block under the trainer's cursor, for "take the block from the program".
    pub trainer_block: Option<String>,
    pub notice: Option<Text>,
    /// The answer field the keyboard is in: it keeps the focus through the check, the verdict
    /// and every re-render (classroom trial II: a keyboard-only instructor lost it at Enter).
    pub keyboard: Option<usize>,
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
    /// The keyboard went into an answer field, or to another element (`None`).
    FocusAnswer(Option<usize>),
    /// A message from a side effect (e.g. the progress could not be saved).
    Notice(Text),
}

impl Reducer for CourseState {
    type Action = CourseAction;

    /// The pure transition: the next state and what to save.
    fn apply(&self, action: CourseAction) -> (CourseState, Vec<Effect>) {
        let next = self.transition(action);
        let mut fx = Vec::new();
        next.follow_ups(Some(self), &mut fx);
        (next, fx)
    }

    /// The embedded trainer reports its cursor block after every render of its own; an
    /// unchanged one changes nothing.
    fn ignores(&self, action: &CourseAction) -> bool {
        match action {
            CourseAction::TrainerBlock(b) => *b == self.trainer_block,
            CourseAction::FocusAnswer(i) => *i == self.keyboard,
            _ => false,
        }
    }
}

/// What a key does on the course page: the presenter remote's keys and the instructor view.
#[derive(Debug, Clone, PartialEq)]
pub enum CourseKey {
    /// Open this route (through the URL fragment, so the browser's Back works too).
    Go(Route),
    Act(CourseAction),
}

impl CourseState {
    /// The course's keymap: → / Bild↓ next lesson, ← / Bild↑ previous, Pos1 the overview, I the
    /// instructor view; `None` for any other key (left to the page).
    #[must_use]
    pub fn key(&self, key: &str) -> Option<CourseKey> {
        Some(match key {
            "ArrowRight" | "PageDown" => CourseKey::Go(self.route.next()),
            "ArrowLeft" | "PageUp" => CourseKey::Go(self.route.prev()),
            "Home" => CourseKey::Go(Route::Overview),
            "i" | "I" => CourseKey::Act(CourseAction::ToggleInstructor),
            _ => return None,
        })
    }

    /// The course at start-up from the saved progress and preference records (a bad one is
    /// reported and replaced).
    #[must_use]
    pub fn start(saved: Option<&str>, prefs: Option<&str>, route: Route) -> (CourseState, Vec<Effect>) {
        let (prefs, prefs_notice) = Prefs::load(prefs);
        let (progress, notice) = match saved.map(Progress::from_text) {
            None => (Progress::default(), prefs_notice),
            Some(Ok(p)) => (p, prefs_notice),
            Some(Err(t)) => (Progress::default(), Some(t)),
        };
        let state = CourseState {
            route: Route::Overview,
            progress,
            prefs,
            exercises: Vec::new(),
            trainer_program: None,
            trainer_generation: 0,
            trainer_block: None,
            keyboard: None,
            notice,
        };
        let state = state.transition(CourseAction::Go(route));
        let mut fx = Vec::new();
        state.follow_ups(None, &mut fx);
        (state, fx)
    }

    #[must_use]
    pub fn lang(&self) -> Lang {
        self.prefs.lang
    }

    /// The instructor view (the classroom projector).
    #[must_use]
    pub fn instructor(&self) -> bool {
        self.prefs.classroom
    }

    /// Saving what changed since `before` (`None`: at start-up, where opening a lesson marks
    /// it visited and a replaced record is written anew).
    fn follow_ups(&self, before: Option<&CourseState>, fx: &mut Vec<Effect>) {
        if before.is_none_or(|b| b.progress != self.progress) {
            fx.push(Effect::Save { key: persist::COURSE_KEY, value: self.progress.to_text() });
        }
        if before.is_none_or(|b| b.prefs != self.prefs) {
            fx.push(Effect::Save { key: persist::PREFS_KEY, value: self.prefs.to_record() });
        }
    }

    #[must_use]
    pub fn lesson_index(&self) -> Option<usize> {
        match self.route {
            Route::Lesson(i) if i < COUNT => Some(i),
            _ => None,
        }
    }

    fn transition(&self, action: CourseAction) -> CourseState {
        let mut s = self.clone();
        match action {
            CourseAction::Go(route) if route != s.route || s.exercises.is_empty() => s.open(route),
            CourseAction::Go(_) => {}
            CourseAction::ToggleInstructor => s.prefs.classroom = !s.prefs.classroom,
            CourseAction::ToggleLang => s.prefs.lang = s.prefs.lang.other(),
            CourseAction::FocusAnswer(i) => s.keyboard = i.filter(|i| *i < s.exercises.len()),
            CourseAction::Input(i, text) => {
                s.keyboard = Some(i);
                // Editing the answer clears the old verdict: it spoke of the old text.
                if let Some(e) = s.exercises.get_mut(i) {
                    e.input = text;
                    e.verdict = None;
                }
            }
            CourseAction::Check(i) => {
                // Checked by Enter or by the button: the next keys correct the answer.
                s.keyboard = Some(i);
                let answer = s.exercises.get(i).map(|e| Answer::typed(&e.input));
                if let Some(answer) = answer {
                    s.check(i, &answer);
                }
            }
            CourseAction::Refuse(i) => s.check(i, &Answer::ControlError),
            CourseAction::ShowSolution(i) => {
                let instructor = s.prefs.classroom;
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
        self.keyboard = None;
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

#[cfg(test)]
mod tests {
    use schwenkbar_core::course::{Answer, Hint};

    use super::*;

    /// One transition, its effects dropped (they are tested on their own).
    trait Then {
        fn then(&self, a: CourseAction) -> CourseState;
    }
    impl Then for CourseState {
        fn then(&self, a: CourseAction) -> CourseState {
            self.apply(a).0
        }
    }

    fn lesson(i: usize) -> CourseState {
        CourseState::start(None, None, Route::Lesson(i)).0
    }

    fn answer(s: &CourseState, i: usize, a: &Answer) -> CourseState {
        match a {
            Answer::Text(t) => s.then(CourseAction::Input(i, t.clone())).then(CourseAction::Check(i)),
            Answer::ControlError => s.then(CourseAction::Refuse(i)),
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
        let s = lesson(1).then(CourseAction::Input(0, "PLANE SPATIAL SPA-20 SPB+0 SPC+0".into()));
        // A trainee has no solution button before a first try.
        assert!(!s.exercises[0].solution_offered(false));
        assert!(!s.then(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
        let s = s.then(CourseAction::Check(0));
        assert!(matches!(s.exercises[0].verdict, Some(Verdict::Wrong { hint: Hint::RightHand, .. })));
        assert_eq!(s.exercises[0].input, "PLANE SPATIAL SPA-20 SPB+0 SPC+0");
        assert!(!s.exercises[0].solution_shown);
        assert!(s.then(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
        // The instructor may reveal at once, but only when asked.
        let i = lesson(1).then(CourseAction::ToggleInstructor);
        assert!(!i.exercises[0].solution_shown);
        assert!(i.then(CourseAction::ShowSolution(0)).exercises[0].solution_shown);
    }

    #[test]
    fn fresh_variant_changes_the_exercise_and_clears_the_answer() {
        let s = lesson(4).then(CourseAction::Input(0, "A+1 C+1".into()));
        let f = s.then(CourseAction::Fresh(0));
        assert_eq!(f.exercises[0].exercise.variant, 1);
        assert_ne!(f.exercises[0].exercise.prompt, s.exercises[0].exercise.prompt);
        assert!(f.exercises[0].input.is_empty());
    }

    #[test]
    fn progress_survives_a_reload_and_a_corrupt_record_is_reported() {
        let s = lesson(0);
        let sol = s.exercises[0].exercise.solution.de.clone();
        let s = answer(&s, 0, &Answer::typed(&sol)).then(CourseAction::ToggleLang);
        let saved = s.progress.to_text();
        let back = CourseState::start(Some(&saved), Some(&s.prefs.to_record()), Route::Overview).0;
        assert_eq!(back.progress, s.progress);
        assert_eq!(back.lang(), Lang::En);
        let (bad, _) = CourseState::start(Some("{not progress"), None, Route::Lesson(2));
        assert_eq!(bad.notice, Some(super::super::progress::UNREADABLE));
        assert_eq!(bad.route, Route::Lesson(2));
    }

    #[test]
    fn exercise_programs_open_in_the_trainer_and_the_block_can_be_taken_over() {
        let s = lesson(3).then(CourseAction::OpenInTrainer(0));
        assert!(
            s.trainer_program.as_ref().is_some_and(|(p, m)| p.contains("PLANE SPATIAL") && *m == "ac-table")
        );
        let s = lesson(2).then(CourseAction::TakeBlock(0));
        assert!(s.notice.is_some());
        let s = s
            .then(CourseAction::TrainerBlock(Some("5 PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN FMAX".into())))
            .then(CourseAction::TakeBlock(0))
            .then(CourseAction::Check(0));
        assert!(s.exercises[0].verdict.as_ref().is_some_and(Verdict::is_correct));
    }

    #[test]
    fn the_presenter_remotes_keys_page_through_the_lessons() {
        let s = lesson(0);
        assert_eq!(s.key("PageDown"), Some(CourseKey::Go(Route::Lesson(1))));
        assert_eq!(s.key("ArrowLeft"), Some(CourseKey::Go(Route::Overview)));
        assert_eq!(s.key("Home"), Some(CourseKey::Go(Route::Overview)));
        assert_eq!(s.key("I"), Some(CourseKey::Act(CourseAction::ToggleInstructor)));
        assert_eq!(s.key("x"), None);
    }

    #[test]
    fn progress_and_preferences_are_saved_when_they_change_and_only_then() {
        let s = lesson(0);
        let (same, fx) = s.apply(CourseAction::Input(0, "x".into()));
        assert!(fx.is_empty(), "typing saves nothing: {fx:?}");
        let sol = same.exercises[0].exercise.solution.de.to_string();
        let (solved, fx) = same.then(CourseAction::Input(0, sol)).apply(CourseAction::Check(0));
        assert_eq!(fx, [Effect::Save { key: persist::COURSE_KEY, value: solved.progress.to_text() }]);
        let (_, fx) = solved.apply(CourseAction::ToggleInstructor);
        assert_eq!(
            fx,
            [Effect::Save { key: persist::PREFS_KEY, value: "p1;lang=de;classroom=1".into() }],
            "the instructor view is the shared classroom preference"
        );
        assert!(solved.ignores(&CourseAction::TrainerBlock(None)));
        assert!(solved.ignores(&CourseAction::FocusAnswer(solved.keyboard)));
        assert!(!solved.ignores(&CourseAction::TrainerBlock(Some("1 PLANE RESET STAY".into()))));
    }
}
