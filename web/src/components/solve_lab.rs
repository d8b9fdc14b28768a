//! Lesson 5's experiment bench: set machine, limit switches, start position and option, see the
//! control's choice and the reason, the master axis' gauge (limit switches, symmetry point, start,
//! both candidates) and the machine in 3D (chosen solution, the other as the ghost); the seed's
//! table rows load as set-ups, each named by what it shows.

use std::rc::Rc;

use schwenkbar_core::course::seed_rows;
use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use super::view3d::View3d;
use schwenkbar_app::course::bench::{Gauge, bench_caption, bench_scene, row_name};
use schwenkbar_app::course::lab::{Bench, LabForm, OPTIONS};
use schwenkbar_app::i18n::Lang;

/// The bench's CSS, shipped with the component.
const STYLE: &str = include_str!("solve_lab.css");

#[derive(Properties, PartialEq)]
pub struct SolveLabProps {
    pub lang: Lang,
}

#[derive(Clone, Copy)]
enum Field {
    Machine,
    Block,
    Start(usize),
    Min,
    Max,
    Option,
}

fn set(form: &UseStateHandle<LabForm>, field: Field, value: String) {
    let mut f = (**form).clone();
    match field {
        Field::Machine => {
            f.machine = value;
            f.start = ["0".into(), "0".into()];
        }
        Field::Block => f.block = value,
        Field::Start(i) => f.start[i.min(1)] = value,
        Field::Min => f.min = value,
        Field::Max => f.max = value,
        Field::Option => f.option = value,
    }
    form.set(f);
}

#[function_component(SolveLab)]
pub fn solve_lab(props: &SolveLabProps) -> Html {
    let l = props.lang;
    let form = use_state(LabForm::default);
    let on = |field: Field| {
        let form = form.clone();
        Callback::from(move |e: Event| {
            let value = e
                .target_dyn_into::<web_sys::HtmlInputElement>()
                .map(|i| i.value())
                .or_else(|| e.target_dyn_into::<web_sys::HtmlSelectElement>().map(|s| s.value()))
                .unwrap_or_default();
            set(&form, field, value);
        })
    };
    let machine = Machine::builtin(&form.machine).ok();
    let axes =
        machine.as_ref().map_or(['?', '?'], |m| [m.joints()[0].axis.letter(), m.joints()[1].axis.letter()]);
    let master = machine.as_ref().map_or('?', |m| m.master().axis.letter());
    let bench = form.bench(l);
    let result = match &bench {
        Ok(Bench { why, .. }) => html! {
            <div class="lab-result" data-testid="lab-result">
                { for why.candidates.iter().map(|(t, chosen)| html! {
                    <p class={classes!("candidate", chosen.then_some("chosen"))} data-chosen={chosen.to_string()}>{ t }</p>
                }) }
                <p class="rule">{ why.rule.clone() }</p>
                if let Some(err) = &why.error { <p class="error" data-testid="lab-error">{ err }</p> }
                <p class="symmetry">{ why.symmetry.clone() }</p>
            </div>
        },
        Err(message) => html! { <p class="error" data-testid="lab-error">{ message }</p> },
    };
    let figures = match &bench {
        Ok(b) => figures(b, l),
        // An entry the bench cannot read: the machine at home, and the message above says why.
        Err(_) => {
            let machine = Machine::builtin(&form.machine).ok().map(Rc::new);
            html! {
                <div class="bench-figures">
                    <figure class="bench-view" data-testid="bench-view">
                        <View3d lang={l} {machine} />
                        <figcaption>{ l.t("Grundstellung: die Eingabe ist nicht lesbar.", "Home position: the entry cannot be read.") }</figcaption>
                    </figure>
                </div>
            }
        }
    };
    let rows = seed_rows().into_iter().map(|row| {
        let form = form.clone();
        let number = row.number;
        let set_up = LabForm::from_row(&row);
        let pressed = if *form == set_up { "true" } else { "false" };
        let name = row_name(&row, l);
        let load = Callback::from(move |_: MouseEvent| form.set(set_up.clone()));
        html! {
            <li><button onclick={load} data-testid={format!("seed-row-{number}")} aria-pressed={pressed}
                title={format!("{} {number}", l.t("Handbuch-Tabelle, Zeile", "Manual table, row"))}>
                { name }<small class="row-no">{ format!("{} {number}", l.t("Zeile", "Row")) }</small>
            </button></li>
        }
    });
    html! {
        <div class="solve-lab" data-testid="solve-lab">
            <style>{ STYLE }</style>
            <div class="lab-fields">
                <label>{ l.t("Maschine", "Machine") }
                    <select onchange={on(Field::Machine)} data-testid="lab-machine">
                        { for Machine::builtin_ids().iter().map(|id| html! {
                            <option value={*id} selected={form.machine == *id}>{ *id }</option>
                        }) }
                    </select>
                </label>
                <label class="wide">{ l.t("PLANE-Satz", "PLANE block") }
                    <input value={form.block.clone()} onchange={on(Field::Block)} data-testid="lab-block" />
                </label>
                { for (0..2).map(|i| html! {
                    <label>{ format!("{} {}", l.t("Start", "Start"), axes[i]) }
                        <input value={form.start[i].clone()} onchange={on(Field::Start(i))} data-testid={format!("lab-start-{i}")} />
                    </label>
                }) }
                <label>{ format!("{} {master} min", l.t("Endschalter", "Limit")) }
                    <input value={form.min.clone()} onchange={on(Field::Min)} data-testid="lab-min" />
                </label>
                <label>{ format!("{} {master} max", l.t("Endschalter", "Limit")) }
                    <input value={form.max.clone()} onchange={on(Field::Max)} data-testid="lab-max" />
                </label>
                <label>{ "SEQ/SYM" }
                    <select onchange={on(Field::Option)} data-testid="lab-option">
                        { for OPTIONS.iter().map(|o| html! {
                            <option value={*o} selected={form.option == *o}>{ if o.is_empty() { l.t("ohne", "none") } else { o } }</option>
                        }) }
                    </select>
                </label>
            </div>
            <div class="seed-rows" data-testid="seed-rows">
                <span>{ l.t("Zeilen der Tabellen aus dem Handbuch:", "Rows of the manual's tables:") }</span>
                <ul>{ for rows }</ul>
            </div>
            { result }
            { figures }
        </div>
    }
}

/// The gauge and the 3D view of a set-up the bench could read.
fn figures(b: &Bench, l: Lang) -> Html {
    let scene = bench_scene(&b.machine, b.explanation.as_ref(), &b.opts.start);
    let chosen = b.explanation.as_ref().and_then(|e| e.chosen_axes());
    let caption = bench_caption(b, &scene, l);
    html! {
        <div class="bench-figures">
            { gauge(&Gauge::of_bench(b), l) }
            <figure class="bench-view" data-testid="bench-view" data-solved={chosen.is_some().to_string()}>
                <View3d lang={l} machine={Rc::new(b.machine.clone())} state={Rc::new(scene)} />
                <figcaption data-testid="bench-view-caption">{ caption }</figcaption>
            </figure>
        </div>
    }
}

/// The master axis gauge ([`Gauge::svg`]) and its key.
fn gauge(g: &Gauge, l: Lang) -> Html {
    let limits_text = g.limits_text(l);
    html! {
        <figure class="bench-gauge" data-testid="gauge">
            { Html::from_html_unchecked(g.svg(l).into()) }
            <figcaption>
                <span class="limits">{ limits_text }</span>
                <span class="key-chosen">{ l.t("● gewählt", "● chosen") }</span>
                <span class="key-other">{ l.t("○ andere Lösung", "○ other solution") }</span>
                <span class="key-out">{ l.t("✕ hinter dem Endschalter", "✕ beyond a limit switch") }</span>
            </figcaption>
        </figure>
    }
}
