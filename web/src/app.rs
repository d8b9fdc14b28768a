//! The root component: one reducer, the TNC screen layout, the keyboard.

use wasm_bindgen::JsCast;
use web_sys::HtmlElement;
use yew::prelude::*;

use crate::components::dialog_area::DialogArea;
use crate::components::header::Header;
use crate::components::program_pane::ProgramPane;
use crate::components::softkey_row::SoftkeyRow;
use crate::components::view3d::View3d;
use crate::components::why_panel::WhyPanel;
use crate::keymap::{self, KeyPress};
use crate::softkeys;
use crate::state::{Action, AppState};

#[function_component(App)]
pub fn app() -> Html {
    let state = use_reducer(AppState::default);
    let on_action = {
        let state = state.clone();
        Callback::from(move |a: Action| state.dispatch(a))
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
    let class = classes!("tnc", state.projector.then_some("projector"));
    html! {
        <div {class} lang={l.code()} tabindex="0" {onkeydown}>
            <Header lang={l} machine={machine_name} />
            <main class="panes">
                <ProgramPane doc={state.doc.clone()} cursor={state.cursor} lang={l}
                    text_editing={state.text_editing} {on_select} {on_text} />
                <View3d lang={l} />
                <WhyPanel doc={state.doc.clone()} cursor={state.cursor} machine={state.machine.clone()} lang={l} />
            </main>
            <DialogArea {dialog} text={state.dialog_text()} lang={l} on_action={on_action.clone()} />
            <SoftkeyRow row={softkeys::row(&state)} {on_action} />
        </div>
    }
}
