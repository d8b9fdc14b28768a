//! One exercise: the task, an answer field (kept as typed), check, the verdict with its hint,
//! a fresh variant, and the solution only when asked for.

use schwenkbar_core::course::{AnswerKind, Verdict};
use wasm_bindgen::JsCast;
use yew::prelude::*;

use schwenkbar_app::course::state::{CourseAction, ExerciseState};
use schwenkbar_app::i18n::Lang;

#[derive(Properties)]
pub struct ExerciseCardProps {
    pub index: usize,
    pub exercise: ExerciseState,
    pub lang: Lang,
    pub instructor: bool,
    /// Offer "the control refuses" as an answer.
    pub refusal: bool,
    /// The lesson shows a trainer: offer "open in the trainer" and "take the block".
    pub in_trainer: bool,
    /// The keyboard is in this exercise's answer field: it gets the focus back after a render.
    pub keyboard: bool,
    pub on_action: Callback<CourseAction>,
}

impl PartialEq for ExerciseCardProps {
    fn eq(&self, o: &Self) -> bool {
        self.index == o.index
            && std::rc::Rc::ptr_eq(&self.exercise.exercise, &o.exercise.exercise)
            && self.exercise.input == o.exercise.input
            && self.exercise.verdict == o.exercise.verdict
            && self.exercise.solution_shown == o.exercise.solution_shown
            && self.exercise.tries == o.exercise.tries
            && (self.lang, self.instructor, self.refusal, self.in_trainer, self.keyboard)
                == (o.lang, o.instructor, o.refusal, o.in_trainer, o.keyboard)
    }
}

#[function_component(ExerciseCard)]
pub fn exercise_card(props: &ExerciseCardProps) -> Html {
    let (i, l, e) = (props.index, props.lang, &props.exercise);
    let ex = &e.exercise;
    let act = |a: CourseAction| props.on_action.reform(move |_: MouseEvent| a.clone());
    let oninput = props.on_action.reform(move |ev: InputEvent| {
        let value =
            ev.target_dyn_into::<web_sys::HtmlInputElement>().map(|el| el.value()).unwrap_or_default();
        CourseAction::Input(i, value)
    });
    let onkeydown = {
        let on_action = props.on_action.clone();
        Callback::from(move |ev: KeyboardEvent| {
            if ev.key() == "Enter" {
                ev.prevent_default();
                on_action.emit(CourseAction::Check(i));
            }
        })
    };
    // The field keeps the keyboard through the check, the verdict and any re-render: a focus
    // lost to the page would hand the next letters to its shortcuts.
    let field = use_node_ref();
    {
        let field = field.clone();
        let keyboard = props.keyboard;
        use_effect(move || {
            let active = web_sys::window().and_then(|w| w.document()).and_then(|d| d.active_element());
            if let Some(input) = field.cast::<web_sys::HtmlElement>().filter(|_| keyboard)
                && active.as_ref() != Some(input.as_ref())
            {
                let _ = input.focus();
            }
        });
    }
    let onfocus = props.on_action.reform(move |_: FocusEvent| CourseAction::FocusAnswer(Some(i)));
    // Focus moved on to another element (not lost to a re-render, which has no such target):
    // the keyboard left the field. Its own buttons keep it (checking hands it back).
    let onblur = {
        let on_action = props.on_action.clone();
        Callback::from(move |ev: FocusEvent| {
            let to = ev.related_target().and_then(|t| t.dyn_into::<web_sys::Element>().ok());
            let own =
                to.as_ref().and_then(|t| t.closest(&format!("[data-testid=exercise-{i}]")).ok().flatten());
            if to.is_some() && own.is_none() {
                on_action.emit(CourseAction::FocusAnswer(None));
            }
        })
    };
    let placeholder = match ex.answer_kind {
        AnswerKind::PlaneBlock => "PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN FMAX",
        AnswerKind::Axes => "A+0 C+0",
        AnswerKind::Number => "+0",
    };
    let verdict = e.verdict.as_ref().map(|v| {
        let (class, text) = match v {
            Verdict::Correct(t) => ("correct", l.t(&t.de, &t.en).to_owned()),
            Verdict::Wrong { text, .. } => ("wrong", l.t(&text.de, &text.en).to_owned()),
            Verdict::Unreadable(t) => ("unreadable", l.t(&t.de, &t.en).to_owned()),
        };
        html! { <p class={classes!("verdict", class)} role="status" data-testid={format!("verdict-{i}")} data-verdict={class}>{ text }</p> }
    });
    html! {
        <article class="exercise" data-testid={format!("exercise-{i}")} data-variant={ex.variant.to_string()}>
            <h3>{ format!("{} {}", l.t("Aufgabe", "Exercise"), i + 1) }</h3>
            <p class="prompt" data-testid={format!("prompt-{i}")}>{ l.t(&ex.prompt.de, &ex.prompt.en) }</p>
            <div class="answer">
                <input type="text" ref={field} value={e.input.clone()} {placeholder} {oninput} {onkeydown} {onfocus} {onblur} spellcheck="false"
                    aria-label={l.t("Antwort", "Answer")} data-testid={format!("answer-{i}")} />
                <button onclick={act(CourseAction::Check(i))} data-testid={format!("check-{i}")}>{ l.t("Prüfen", "Check") }</button>
                if props.refusal {
                    <button onclick={act(CourseAction::Refuse(i))} data-testid={format!("refuse-{i}")}>
                        { l.t("Steuerung meldet Fehler", "Control reports an error") }
                    </button>
                }
                if props.in_trainer && ex.answer_kind == AnswerKind::PlaneBlock {
                    <button onclick={act(CourseAction::TakeBlock(i))} data-testid={format!("take-{i}")}>
                        { l.t("Satz aus dem Programm übernehmen", "Take the block from the program") }
                    </button>
                }
            </div>
            { for verdict }
            <div class="exercise-tools">
                <button onclick={act(CourseAction::Fresh(i))} data-testid={format!("fresh-{i}")}>{ l.t("Neue Aufgabe", "New exercise") }</button>
                if props.in_trainer && ex.program.is_some() {
                    <button onclick={act(CourseAction::OpenInTrainer(i))} data-testid={format!("open-{i}")}>
                        { l.t("Im Trainer öffnen", "Open in the trainer") }
                    </button>
                }
                if e.solution_offered(props.instructor) && !e.solution_shown {
                    <button onclick={act(CourseAction::ShowSolution(i))} data-testid={format!("solution-button-{i}")}>
                        { l.t("Lösung zeigen", "Show solution") }
                    </button>
                }
            </div>
            if e.solution_shown {
                <p class="solution" data-testid={format!("solution-{i}")}>
                    { l.t("Lösung: ", "Solution: ") }<code>{ l.t(&ex.solution.de, &ex.solution.en) }</code>
                    { l.t(" – gleichwertig: ", " – equivalent: ") }<code>{ l.t(&ex.equivalent.de, &ex.equivalent.en) }</code>
                </p>
            }
        </article>
    }
}
