//! The machine editor page (`maschine.html`, its own bundle): the form of
//! [`schwenkbar_app::editor`] row by row with each row's messages under it, the 3D preview of the
//! last valid machine, and the page's commands (start from, save, delete, export, import,
//! language), and the shop's tool table below ([`super::tool_table`]). State and checks in
//! [`EditorState`]; this only renders and dispatches.

use std::rc::Rc;

use web_sys::{HtmlInputElement, HtmlSelectElement};
use yew::prelude::*;

use super::tool_table::ToolTable;
use super::view3d::View3d;
use crate::browser;
use crate::effects::{Shell, Shelled, use_effects};
use schwenkbar_app::editor::{EditorAction, EditorState, Field, SECTIONS, rows, section_title};
use schwenkbar_app::i18n::{Lang, Text};
use schwenkbar_app::scene::SceneState;
use schwenkbar_core::machine::Machine;

const STYLE: &str = include_str!("machine_editor.css");

/// The editor in yew.
pub type Editor = Shelled<EditorState>;

/// A choice among `options` (word, label) that sets `field`; a value not among them (from an
/// imported file) stays selectable, so the message next to it makes sense.
fn choice(state: &UseReducerHandle<Editor>, field: Field, options: Vec<(String, Text)>, l: Lang) -> Html {
    let value = state.form.value(field);
    let onchange = {
        let state = state.clone();
        Callback::from(move |e: Event| {
            if let Some(s) = e.target_dyn_into::<HtmlSelectElement>() {
                state.dispatch(EditorAction::Set(field, s.value()));
            }
        })
    };
    let known = options.iter().any(|(w, _)| *w == value);
    html! {
        <select data-field={format!("{field:?}")} {onchange}>
            { for options.into_iter().map(|(w, label)| {
                let selected = w == value;
                html! { <option {selected} value={w}>{ label.get(l).to_owned() }</option> }
            }) }
            if !known { <option value={value.clone()} selected=true>{ value.clone() }</option> }
        </select>
    }
}

/// One input of a row: a text field, a choice (carrier, shape) or the endless switch.
fn input(state: &UseReducerHandle<Editor>, field: Field, l: Lang) -> Html {
    let value = state.form.value(field);
    let name = format!("{field:?}");
    match field {
        Field::BodyCarrier(_) => choice(state, field, state.form.body_carriers(), l),
        Field::BodyShape(_) | Field::Carrier(_) => {
            let words = match field {
                Field::Carrier(_) => [
                    ("table", Text::new("Tisch (table)", "table")),
                    ("head", Text::new("Kopf (head)", "head")),
                ],
                _ => [
                    ("box", Text::new("Quader (box)", "box")),
                    ("cylinder", Text::new("Zylinder (cylinder)", "cylinder")),
                ],
            };
            choice(state, field, words.into_iter().map(|(w, t)| (w.to_owned(), t)).collect(), l)
        }
        Field::Endless(i) => {
            let onchange = {
                let state = state.clone();
                Callback::from(move |e: Event| {
                    if let Some(c) = e.target_dyn_into::<HtmlInputElement>() {
                        state.dispatch(EditorAction::SetEndless(i, c.checked()));
                    }
                })
            };
            html! { <input type="checkbox" data-field={name} checked={!value.is_empty()} {onchange} /> }
        }
        _ => {
            let oninput = {
                let state = state.clone();
                Callback::from(move |e: InputEvent| {
                    if let Some(i) = e.target_dyn_into::<HtmlInputElement>() {
                        state.dispatch(EditorAction::Set(field, i.value()));
                    }
                })
            };
            html! { <input type="text" data-field={name} {value} {oninput} spellcheck="false" /> }
        }
    }
}

/// A file input's change: the chosen file's bytes as `action`, or why it could not be read.
pub(super) fn on_file(
    state: &UseReducerHandle<Editor>,
    action: fn(Vec<u8>) -> EditorAction,
) -> Callback<Event> {
    let state = state.clone();
    Callback::from(move |e: Event| {
        let file = e.target_dyn_into::<HtmlInputElement>().and_then(|i| i.files()).and_then(|f| f.get(0));
        let Some(file) = file else { return };
        let state = state.clone();
        yew::platform::spawn_local(async move {
            match browser::read_file(file).await {
                Ok(bytes) => state.dispatch(action(bytes)),
                Err(message) => state.dispatch(EditorAction::Notice(message)),
            }
        });
    })
}

#[function_component(EditorRoot)]
pub fn editor_root() -> Html {
    let state = use_reducer(|| {
        let (machines, prefs, tools) = browser::load_editor();
        let (editor, fx) =
            EditorState::start(machines.as_deref(), prefs.as_deref(), browser::fragment().as_deref());
        Editor::new((editor.with_tools(tools.as_deref()), fx))
    });
    let root = use_node_ref();
    {
        let notice = {
            let state = state.clone();
            Callback::from(move |t| state.dispatch(EditorAction::Notice(t)))
        };
        use_effects(&state.pending, Shell::saving(notice, root.clone()));
    }
    let l = state.lang();
    let send = |a: EditorAction| {
        let state = state.clone();
        Callback::from(move |_: MouseEvent| state.dispatch(a.clone()))
    };
    let on_open = {
        let state = state.clone();
        Callback::from(move |e: Event| {
            if let Some(s) = e.target_dyn_into::<HtmlSelectElement>()
                && !s.value().is_empty()
            {
                state.dispatch(EditorAction::Open(s.value()));
            }
        })
    };
    let on_import = on_file(&state, EditorAction::Import);
    let shipped = Machine::builtin_ids().into_iter().filter_map(|id| Machine::builtin(id).ok());
    let starts: Vec<(String, String)> = shipped
        .map(|m| (m.id.clone(), format!("{} ({})", l.t(&m.name.de, &m.name.en), m.id)))
        .chain(state.saved.iter().map(|m| (m.id.clone(), format!("{} – {}", l.t("eigene", "own"), m.id))))
        .collect();
    let all_rows = rows(&state.form);
    let section = |s: usize| {
        let rows = all_rows.iter().filter(|r| r.section == s).map(|r| {
            let path = r.path();
            let issues: Vec<Html> = state
                .issues_at(path)
                .map(|i| html! { <p class="ed-issue" role="alert">{ i.message.get(l).to_owned() }</p> })
                .collect();
            let class = classes!("ed-row", (!issues.is_empty()).then_some("bad"));
            html! {
                <div {class} data-path={path.to_string()}>
                    <span>{ r.label.get(l).to_owned() }</span>
                    <span class="ed-inputs">{ for r.fields.iter().map(|f| input(&state, *f, l)) }</span>
                    { for issues }
                </div>
            }
        });
        // A collision body's section ends with its remove button.
        let remove = s.checked_sub(SECTIONS).map(|i| {
            html! {
                <button type="button" data-action="remove-body" onclick={send(EditorAction::RemoveBody(i))}>
                    { l.t("Körper entfernen", "Remove body") }
                </button>
            }
        });
        html! { <><h2>{ section_title(s, &state.form).get(l).to_owned() }</h2>{ for rows }{ for remove }</> }
    };
    let sections = SECTIONS + state.form.collision.len();
    let preview =
        use_memo(state.preview.clone(), |m| m.as_deref().map(|m| Rc::new(SceneState::with_bodies(m))));
    // Two literal elements: with `data-valid={valid.to_string()}` this page's first screen
    // called into its deferred wasm (offline_test.py's first_screen_the_same_without_the_deferred_data).
    let text = state.status().get(l).to_owned();
    let status = if state.valid {
        html! { <p class="status" data-valid="true">{ text }</p> }
    } else {
        html! { <p class="status bad" data-valid="false">{ text }</p> }
    };
    let top_issues = state
        .import_issues
        .iter()
        .cloned()
        .chain(state.unplaced().into_iter().map(|i| i.message.clone()))
        .map(|t| html! { <p class="ed-top-issue" role="alert">{ t.get(l).to_owned() }</p> });
    html! {
        <div class="editor" ref={root} lang={l.code()}>
            <style>{ STYLE }</style>
            <header>
                <h1>{ l.t("Maschinen-Editor", "Machine editor") }</h1>
                <select aria-label={l.t("Ausgehen von", "Start from")} data-action="open" onchange={on_open}>
                    <option value="" selected=true>{ l.t("Ausgehen von …", "Start from …") }</option>
                    { for starts.into_iter().map(|(id, label)| html! { <option value={id}>{ label }</option> }) }
                </select>
                <button type="button" data-action="save" onclick={send(EditorAction::Save)}>{ l.t("SPEICHERN", "SAVE") }</button>
                <button type="button" data-action="delete" onclick={send(EditorAction::Delete)}>{ l.t("LÖSCHEN", "DELETE") }</button>
                <button type="button" data-action="export" onclick={send(EditorAction::Export)}>{ l.t("EXPORT .JSON", "EXPORT .JSON") }</button>
                <label class="button" data-action="import">{ l.t("IMPORT .JSON", "IMPORT .JSON") }
                    <input type="file" accept=".json,application/json" class="file-input" onchange={on_import} />
                </label>
                <button type="button" data-action="lang" onclick={send(EditorAction::ToggleLang)}>{ l.t("ENGLISH", "DEUTSCH") }</button>
                <a href="index.html" data-action="trainer">{ l.t("Zum Trainer", "To the trainer") }</a>
            </header>
            <section class="form" aria-label={l.t("Maschinendaten", "Machine data")}>
                if let Some(m) = &state.message { <p class="message" role="status">{ m.get(l).to_owned() }</p> }
                { status }
                { for top_issues }
                { for (0..sections).map(section) }
                <button type="button" data-action="add-body" onclick={send(EditorAction::AddBody)}>
                    { l.t("Kollisionskörper hinzufügen", "Add collision body") }
                </button>
            </section>
            <section class="preview">
                <h2>{ l.t("Vorschau", "Preview") }</h2>
                <View3d lang={l} machine={state.preview.clone()} state={(*preview).clone()} />
            </section>
            <ToolTable state={state.clone()} lang={l} />
        </div>
    }
}
