//! The course pages: the overview and a lesson (text, live view, exercises), the instructor
//! view (projector type, presenter-remote keys, solutions only on request) and the progress
//! kept in the browser. State in [`schwenkbar_app::course::state::CourseState`].

use std::rc::Rc;

use yew::prelude::*;

use super::exercise_card::ExerciseCard;
use super::positioning::PositioningCompare;
use super::right_hand_demo::RightHandDemo;
use super::solve_lab::SolveLab;
use crate::app::{App, Embed};
use crate::browser;
use crate::effects::{Course, Shell, use_effects};
use schwenkbar_app::course::Route;
use schwenkbar_app::course::lessons::{self, COUNT, Widget};
use schwenkbar_app::course::state::{CourseAction, CourseKey, CourseState};
use schwenkbar_app::course::texts::LESSONS;

const STYLE: &str = include_str!("course.css");

#[derive(Properties, PartialEq)]
pub struct CourseAppProps {
    pub route: Route,
}

fn go(route: Route) {
    // The fragment drives the page (`Root` follows it), so Back in the browser works too.
    let _ = browser::set_fragment(&route.fragment());
}

#[function_component(CourseApp)]
pub fn course_app(props: &CourseAppProps) -> Html {
    let route = props.route;
    let state = use_reducer(|| {
        let (progress, prefs) = browser::load_course();
        Course::new(CourseState::start(progress.as_deref(), prefs.as_deref(), route))
    });
    {
        let state = state.clone();
        use_effect_with(route, move |r| state.dispatch(CourseAction::Go(*r)));
    }
    let root = use_node_ref();
    {
        let notice = {
            let state = state.clone();
            Callback::from(move |t| state.dispatch(CourseAction::Notice(t)))
        };
        use_effects(&state.pending, Shell::saving(notice, root.clone()));
    }
    // The page's keys from the load on, wherever the focus is; keys pressed inside a lesson's
    // embedded trainer stay with the trainer (PageDown there does not leave the lesson). The
    // listener reads the state of the latest render.
    let current = use_mut_ref(|| state.clone());
    *current.borrow_mut() = state.clone();
    // Shown as `data-keys="on"` once the listener is there (the browser tests wait for it).
    let keys_on = use_state_eq(|| false);
    {
        let root = root.clone();
        let keys_on = keys_on.clone();
        use_effect_with((), move |()| {
            keys_on.set(true);
            let listener = browser::on_page_keys(
                move || root.cast::<web_sys::Element>(),
                false,
                move |e| {
                    let state = current.borrow().clone();
                    match state.key(&e.key()) {
                        Some(CourseKey::Go(r)) => go(r),
                        Some(CourseKey::Act(a)) => state.dispatch(a),
                        None => return false,
                    }
                    true
                },
            );
            move || drop(listener)
        });
    }
    let l = state.lang();
    let dispatch = {
        let state = state.clone();
        Callback::from(move |a: CourseAction| state.dispatch(a))
    };
    let class = classes!("course", state.instructor().then_some("projector"));
    let page = match state.lesson_index() {
        Some(i) => lesson_page(&state, i, &dispatch),
        None => overview(&state),
    };
    let toggle_lang = dispatch.reform(|_: MouseEvent| CourseAction::ToggleLang);
    let toggle_instructor = dispatch.reform(|_: MouseEvent| CourseAction::ToggleInstructor);
    html! {
        <div {class} lang={l.code()} tabindex="-1" data-testid="course" ref={root} data-keys={keys_on.then_some("on")}>
            <style>{ STYLE }</style>
            <header class="course-head">
                <a href="#kurs" class="course-title">{ l.t("Schwenkbar – Kurs", "Schwenkbar – course") }</a>
                <span class="course-where" data-testid="course-where">{ match state.lesson_index() {
                    Some(i) => format!("{} {}/{COUNT}", l.t("Lektion", "Lesson"), i + 1),
                    None => l.t("Übersicht", "Overview").to_owned(),
                } }</span>
                <button onclick={toggle_instructor} aria-pressed={state.instructor().to_string()} data-testid="instructor">
                    { l.t("Lehreransicht (I)", "Instructor view (I)") }
                </button>
                <button onclick={toggle_lang} data-testid="course-lang">{ l.t("English", "Deutsch") }</button>
                <a href="index.html" class="to-trainer">{ l.t("Zum Trainer", "To the trainer") }</a>
            </header>
            if let Some(n) = &state.notice {
                <p class="course-notice" role="status" data-testid="course-notice">{ n.get(l) }</p>
            }
            { page }
        </div>
    }
}

fn overview(state: &CourseState) -> Html {
    let l = state.lang();
    html! {
        <main class="course-overview" data-testid="course-overview">
            <h1>{ l.t("Bearbeitungsebene schwenken – der Kurs", "Tilting the working plane – the course") }</h1>
            <p>{ l.t(
                "Elf Lektionen, jede mit Erklärung, einer Live-Ansicht und Aufgaben, die das Programm nachrechnet. Weiter mit → oder Bild↓, zurück mit ← oder Bild↑.",
                "Eleven lessons, each with an explanation, a live view and exercises the program checks. Next with → or Page Down, back with ← or Page Up.",
            ) }</p>
            <ol class="lesson-list">
                { for LESSONS.iter().enumerate().map(|(i, t)| {
                    let p = state.progress.lessons[i];
                    let total = lessons::lesson(i).map_or(0, |x| x.exercises.len());
                    let status = format!("{}/{total} {}", p.solved_count(), l.t("gelöst", "solved"));
                    html! {
                        <li class={classes!(p.visited.then_some("visited"))}>
                            <a href={format!("#{}", Route::Lesson(i).fragment())} data-testid={format!("lesson-link-{}", i + 1)}>
                                { t.title.get(l) }
                            </a>
                            <span class="lesson-goal">{ t.goal.get(l) }</span>
                            <span class="lesson-status" data-testid={format!("lesson-status-{}", i + 1)}>{ status }</span>
                        </li>
                    }
                }) }
            </ol>
        </main>
    }
}

fn lesson_page(state: &CourseState, i: usize, dispatch: &Callback<CourseAction>) -> Html {
    let (Some(lesson), l) = (lessons::lesson(i), state.lang()) else { return overview(state) };
    let t = lesson.text;
    let widget = match lesson.widget {
        Widget::RightHand => html! { <RightHandDemo lang={l} /> },
        Widget::SolveLab => html! { <SolveLab lang={l} /> },
        Widget::Positioning { programs, block } => {
            html! { <PositioningCompare lang={l} {programs} {block} /> }
        }
        Widget::Trainer { program, machine } => {
            let (program, machine): (Rc<str>, &'static str) =
                state.trainer_program.clone().unwrap_or_else(|| (program.into(), machine));
            // Rebuilt only for another lesson, another opened program or language (a key that
            // changed on every render would remount it endlessly).
            // The instructor view shows the trainer in projector mode, with the classroom's
            // question before each swivel (a new key: the trainer starts again in that mode).
            let classroom = state.instructor();
            let key = format!("{i}-{}-{}-{classroom}", state.trainer_generation, l.code());
            let on_plane_block = dispatch.reform(CourseAction::TrainerBlock);
            let embed = Embed { program, machine, lang: l, classroom, on_plane_block };
            html! { <div class="lesson-trainer" {key}><App embed={Some(embed)} /></div> }
        }
    };
    let prev = Route::Lesson(i).prev();
    let next = Route::Lesson(i).next();
    html! {
        <main class="lesson" data-testid="lesson" data-lesson={(i + 1).to_string()}>
            <section class="lesson-text">
                <h1 data-testid="lesson-title">{ format!("{}. {}", i + 1, t.title.get(l)) }</h1>
                <p class="lesson-goal">{ t.goal.get(l) }</p>
                { for t.paragraphs.iter().map(|p| html! { <p>{ p.get(l) }</p> }) }
                if !t.steps.is_empty() {
                    <ol class="lesson-steps">{ for t.steps.iter().map(|s| html! { <li>{ s.get(l) }</li> }) }</ol>
                }
                <p class="lesson-summary"><strong>{ l.t("Merksatz: ", "Remember: ") }</strong>{ t.summary.get(l) }</p>
            </section>
            <section class="lesson-widget">
                <p class="widget-caption">{ t.widget_caption.get(l) }</p>
                { widget }
            </section>
            <section class="lesson-exercises">
                <h2>{ l.t("Aufgaben", "Exercises") }</h2>
                { for state.exercises.iter().enumerate().map(|(n, e)| html! {
                    <ExerciseCard index={n} exercise={e.clone()} lang={l} instructor={state.instructor()}
                        refusal={state.offers_refusal(n)} in_trainer={matches!(lesson.widget, Widget::Trainer { .. })}
                        keyboard={state.keyboard == Some(n)}
                        on_action={dispatch.clone()} />
                }) }
            </section>
            <nav class="lesson-nav">
                <a href={format!("#{}", prev.fragment())} data-testid="lesson-prev">{ l.t("← Zurück", "← Back") }</a>
                <a href="#kurs">{ l.t("Übersicht", "Overview") }</a>
                if i + 1 < COUNT {
                    <a href={format!("#{}", next.fragment())} data-testid="lesson-next">{ l.t("Weiter →", "Next →") }</a>
                }
            </nav>
        </main>
    }
}
