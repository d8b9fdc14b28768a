//! The root component: one reducer, the TNC screen layout, the keyboard.

use std::rc::Rc;

use wasm_bindgen::JsCast;
use web_sys::HtmlElement;
use yew::prelude::*;

use crate::browser;
use crate::components::dialog_area::DialogArea;
use crate::components::header::Header;
use crate::components::position::PositionDisplay;
use crate::components::program_pane::ProgramPane;
use crate::components::right_hand_demo::RightHandDemo;
use crate::components::scene_pane::ScenePane;
use crate::components::softkey_row::SoftkeyRow;
use crate::components::why_panel::WhyPanel;
use crate::i18n::{Lang, Text};
use crate::keymap::{self, KeyPress};
use crate::persist;
use crate::softkeys;
use crate::state::{Action, AppState};

/// A lesson's program shown in the trainer instead of the trainee's own work.
#[derive(Debug, Clone, PartialEq)]
pub struct Embed {
    pub program: Rc<str>,
    pub machine: &'static str,
    pub lang: Lang,
    /// Told the cursor block's text whenever it is a PLANE block (`None` otherwise).
    pub on_plane_block: Callback<Option<String>>,
}

#[derive(Properties, PartialEq, Default)]
pub struct AppProps {
    /// Set inside a lesson: that program, nothing saved.
    #[prop_or_default]
    pub embed: Option<Embed>,
}

#[function_component(App)]
pub fn app(props: &AppProps) -> Html {
    let embed = props.embed.clone();
    let state = use_reducer(|| match &embed {
        Some(e) => AppState::embedded(&e.program, e.machine, e.lang),
        None => {
            let (saved, program) = browser::load_saved();
            AppState::start(saved.as_deref(), program, browser::fragment().as_deref())
        }
    });
    // Keep the trainee's work (not a lesson's program): the program when its text changed, the
    // small state when the cursor, machine, language or projector mode changed. In a lesson,
    // tell the course which PLANE block the cursor is on.
    let embedded = props.embed.clone();
    {
        let state = state.clone();
        let deps = (Rc::as_ptr(&state.doc) as usize, state.cursor);
        use_effect_with(deps, move |_| match embedded {
            Some(e) => e.on_plane_block.emit(state.cursor_plane_text()),
            None => {
                if let Err(message) = browser::save_program(&state.doc.text) {
                    state.dispatch(Action::Notice(message));
                }
            }
        });
    }
    {
        let deps = (state.cursor, state.machine.as_ref().map(|m| m.id.clone()), state.lang, state.projector);
        let state = state.clone();
        let embedded = props.embed.is_some();
        use_effect_with(deps, move |_| {
            if embedded {
                return;
            }
            if let Err(message) = browser::save_state(&persist::to_json(&state.saved())) {
                state.dispatch(Action::Notice(message));
            }
        });
    }
    let on_action = {
        let state = state.clone();
        Callback::from(move |a: Action| match a {
            Action::Download => {
                let bytes = schwenkbar_core::text::encode_latin1(&state.doc.text);
                if let Err(message) = browser::download(&state.file_name(), &bytes) {
                    state.dispatch(Action::Notice(message));
                }
            }
            Action::Share => {
                let notice = match browser::set_fragment(&state.share_fragment()) {
                    Ok(()) => Text::new(
                        "Link steht in der Adresszeile: kopieren und weitergeben",
                        "The link is in the address bar: copy and pass it on",
                    ),
                    Err(message) => message,
                };
                state.dispatch(Action::Notice(notice));
            }
            other => state.dispatch(other),
        })
    };
    // Satzfolge: the next block follows when this one's motion has had its time.
    {
        let run = state.run.as_ref().map(|r| (r.step, r.playing, r.tick_ms()));
        let state = state.clone();
        use_effect_with(run, move |run| {
            if let Some((step, true, ms)) = *run {
                yew::platform::spawn_local(async move {
                    yew::platform::time::sleep(std::time::Duration::from_millis(ms)).await;
                    state.dispatch(Action::RunTick(step));
                });
            }
        });
    }
    let on_import = {
        let state = state.clone();
        Callback::from(move |file: web_sys::File| {
            let state = state.clone();
            yew::platform::spawn_local(async move {
                match browser::read_file(file).await {
                    Ok(bytes) => state.dispatch(Action::Import(schwenkbar_core::text::decode(bytes))),
                    Err(message) => state.dispatch(Action::Notice(message)),
                }
            });
        })
    };
    let onkeydown = {
        let state = state.clone();
        Callback::from(move |e: KeyboardEvent| {
            // Typing in the program text belongs to the text area, except the function keys.
            let in_text = e
                .target()
                .and_then(|t| t.dyn_into::<HtmlElement>().ok())
                .is_some_and(|el| matches!(el.tag_name().as_str(), "TEXTAREA" | "INPUT"));
            let key = e.key();
            if in_text && !key.starts_with('F') {
                return;
            }
            let press = KeyPress {
                key: &key,
                shift: e.shift_key(),
                ctrl_or_alt: e.ctrl_key() || e.alt_key() || e.meta_key(),
            };
            if let Some(action) = keymap::action(&state, &press) {
                e.prevent_default();
                state.dispatch(action);
            }
        })
    };
    let on_select = on_action.reform(Action::CursorTo);
    let on_text = on_action.reform(Action::SetText);
    let l = state.lang;
    let machine_name = state.machine.as_ref().map_or_else(
        || l.t("keine Maschine", "no machine").to_owned(),
        |m| l.t(&m.name.de, &m.name.en).to_owned(),
    );
    let dialog = state.dialog.as_ref().map(|(d, _)| d.clone());
    let mode = match &state.run {
        None => l.t("Programmieren", "Programming"),
        Some(r) if r.playing => l.t("Programmlauf Satzfolge", "Program run, full sequence"),
        Some(_) => l.t("Programmlauf Einzelsatz", "Program run, single block"),
    };
    let speed = state.run.as_ref().map_or(1.0, |r| r.speed_factor());
    let scene_state = state.shown_state();
    let shown = state.run.as_ref().and_then(|r| r.state.clone());
    let class = classes!("tnc", state.projector.then_some("projector"));
    html! {
            <div {class} lang={l.code()} tabindex="0" {onkeydown}>
                <Header lang={l} machine={machine_name} mode={mode} course_link={props.embed.is_none()} />
                <main class="panes">
                    <ProgramPane doc={state.doc.clone()} cursor={state.cursor} lang={l}
                        text_editing={state.text_editing} {on_select} {on_text} />
    if state.right_hand {
                        <RightHandDemo lang={l} block={state.cursor_plane_text().map(AttrValue::from)} />
                    } else {
                        <ScenePane lang={l} machine={state.machine.clone()} sim={state.sim.clone()} doc={state.doc.clone()}
                        state={scene_state} animate={state.run.as_ref().is_some_and(|r| r.playing)} speed={speed} />
                    }
                    <div class="side">
                        if let Some(shown) = shown.clone() {
                            <PositionDisplay state={shown} lang={l} />
                        }
                        <WhyPanel doc={state.doc.clone()} cursor={state.cursor} machine={state.machine.clone()}
                            sim={state.sim.clone()} shown={shown} lang={l} />
                    </div>
                </main>
                <DialogArea {dialog} text={state.dialog_line()} lang={l} on_action={on_action.clone()} />
                <SoftkeyRow row={softkeys::row(&state)} {on_action} {on_import} />
            </div>
        }
}
