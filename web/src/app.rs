//! The root component: one reducer, the TNC screen layout.

use yew::prelude::*;

use crate::components::dialog_line::DialogLine;
use crate::components::header::Header;
use crate::components::program_pane::ProgramPane;
use crate::components::softkey_row::SoftkeyRow;
use crate::components::view3d::View3d;
use crate::softkeys;
use crate::state::{Action, AppState};

#[function_component(App)]
pub fn app() -> Html {
    let state = use_reducer(AppState::default);
    let on_action = {
        let state = state.clone();
        Callback::from(move |a: Action| state.dispatch(a))
    };
    let l = state.lang;
    html! {
        <div class="tnc" lang={l.code()}>
            <Header lang={l} />
            <main class="panes">
                <ProgramPane program={state.program.clone()} title={l.t("NC-Programm", "NC program")} />
                <View3d lang={l} />
            </main>
            <DialogLine text={state.dialog_text()} />
            <SoftkeyRow row={softkeys::row(state.level)} lang={l} {on_action} />
        </div>
    }
}
