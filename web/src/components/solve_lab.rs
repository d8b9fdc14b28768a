//! Lesson 5's experiment bench: set machine, limit switches, start position and option, see the
//! control's choice and the reason; the seed's table rows load as set-ups.

use schwenkbar_core::course::seed_rows;
use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use crate::course::lab::{LabForm, OPTIONS};
use crate::i18n::Lang;

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
    let result = match form.solve(l) {
        Ok(why) => html! {
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
    let rows = seed_rows().into_iter().map(|row| {
        let form = form.clone();
        let number = row.number;
        let load = Callback::from(move |_: MouseEvent| form.set(LabForm::from_row(&row)));
        html! { <button onclick={load} data-testid={format!("seed-row-{number}")}>{ format!("{} {number}", l.t("Zeile", "Row")) }</button> }
    });
    html! {
        <div class="solve-lab" data-testid="solve-lab">
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
            <div class="seed-rows">
                <span>{ l.t("Zeilen der Tabellen aus dem Handbuch:", "Rows of the manual's tables:") }</span>
                { for rows }
            </div>
            { result }
        </div>
    }
}
