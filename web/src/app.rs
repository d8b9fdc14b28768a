//! The root component: one reducer, the TNC screen layout, the keyboard.

use std::rc::Rc;

use yew::prelude::*;

use schwenkbar_app::run::StateRef;

use crate::browser;
use crate::components::dialog_area::DialogArea;
use crate::components::header::Header;
use crate::components::position::PositionDisplay;
use crate::components::program_pane::ProgramPane;
use crate::components::right_hand_demo::RightHandDemo;
use crate::components::scene_pane::ScenePane;
use crate::components::softkey_row::SoftkeyRow;
use crate::components::why_panel::WhyPanel;
use crate::effects::{Shell, Trainer, use_effects};
use schwenkbar_app::document::DocRef;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::keymap::{self, KeyPress};
use schwenkbar_app::softkeys;
use schwenkbar_app::state::{Action, AppState};

/// A lesson's program shown in the trainer instead of the trainee's own work.
#[derive(Debug, Clone, PartialEq)]
pub struct Embed {
    pub program: Rc<str>,
    pub machine: &'static str,
    pub lang: Lang,
    /// The course's instructor view: projector mode with the classroom's question.
    pub classroom: bool,
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
    let state = use_reducer(|| {
        Trainer::new(match &embed {
            Some(e) => AppState::embedded(&e.program, e.machine, e.lang, e.classroom),
            None => AppState::start_unsimulated(browser::load_stored(), browser::fragment().as_deref()),
        })
    });
    let root = use_node_ref();
    let on_action = {
        let state = state.clone();
        Callback::from(move |a: Action| state.dispatch(a))
    };
    // What the reducer asked for: saving, downloads, the share link, the Satzfolge timer, the
    // lesson's "which PLANE block".
    use_effects(
        &state.pending,
        Shell {
            notice: on_action.reform(Action::Notice),
            tick: on_action.reform(Action::RunTick),
            build_stock: on_action.reform(|()| Action::BuildStock),
            pass_stock: on_action.reform(|()| Action::PassStock),
            simulate: on_action.reform(|()| Action::Simulate),
            root: root.clone(),
            tell_course: props.embed.as_ref().map(|e| e.on_plane_block.clone()),
        },
    );
    let on_import = {
        let state = state.clone();
        Callback::from(move |file: web_sys::File| {
            let state = state.clone();
            yew::platform::spawn_local(async move {
                match browser::read_file(file).await {
                    Ok(bytes) => state.dispatch(Action::Import(bytes)),
                    Err(message) => state.dispatch(Action::Notice(message)),
                }
            });
        })
    };
    // The keyboard belongs to the page from the load on, wherever the focus is; a lesson's
    // trainer takes only the keys pressed inside it. The listener reads the state of the
    // latest render.
    let current = use_mut_ref(|| state.clone());
    *current.borrow_mut() = state.clone();
    // Shown as `data-keys="on"` once the listener is there (the browser tests wait for it).
    let keys_on = use_state_eq(|| false);
    {
        let root = root.clone();
        let embedded = props.embed.is_some();
        let keys_on = keys_on.clone();
        use_effect_with((), move |()| {
            // The root element is looked up per key: it is bound once the first render is in
            // the document.
            let own = move || root.cast::<web_sys::Element>();
            keys_on.set(true);
            let listener = browser::on_page_keys(own, embedded, move |e| {
                let state = current.borrow().clone();
                let key = e.key();
                let press =
                    KeyPress { key: &key, shift: e.shift_key(), ctrl_or_alt: e.ctrl_key() || e.meta_key() };
                let action = keymap::action(&state, &press);
                action.map(|a| state.dispatch(a)).is_some()
            });
            move || drop(listener)
        });
    }
    let on_select = on_action.reform(Action::CursorTo);
    let on_edit = on_action.reform(|(at, text)| Action::EditText { at, text });
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
    let scene_state = state.shown_state().map(StateRef);
    let fraction = use_state_eq(|| 1.0_f64);
    // The candidate hovered in the why panel, drawn as the ghost; forgotten when the cursor moves.
    let hovered = use_state_eq(|| None::<(usize, schwenkbar_core::axes::AxisValues)>);
    let on_hover = {
        let hovered = hovered.clone();
        let cursor = state.cursor;
        Callback::from(move |axes: Option<schwenkbar_core::axes::AxisValues>| {
            hovered.set(axes.map(|a| (cursor, a)))
        })
    };
    let ghost = hovered.filter(|(at, _)| *at == state.cursor).map(|(_, axes)| axes);
    let on_fraction = {
        let fraction = fraction.clone();
        Callback::from(move |f: f64| fraction.set(f))
    };
    let shown = state.run.as_ref().and_then(|r| r.state.clone()).map(StateRef);
    let class = classes!("tnc", state.projector.then_some("projector"));
    html! {
            <div {class} lang={l.code()} tabindex="-1" ref={root} data-keys={keys_on.then_some("on")}>
                <Header lang={l} machine={machine_name} mode={mode} course_link={props.embed.is_none()} />
                <main class="panes">
                    <ProgramPane doc={DocRef(state.doc.clone())} cursor={state.cursor} lang={l}
                        text_editing={state.text_editing} wrap={state.projector} {on_select} {on_edit} />
    if state.right_hand {
                        <RightHandDemo lang={l} block={state.cursor_plane_text().map(AttrValue::from)} />
                    } else {
                        <ScenePane lang={l} machine={state.machine.clone()} sim={state.sim.clone()} doc={DocRef(state.doc.clone())}
                        state={scene_state} animate={state.run.as_ref().is_some_and(|r| r.playing)} speed={speed} {on_fraction} in_run={state.run.is_some()} {ghost} stock={state.shown_stock()}
                        collision={state.shown_collision().cloned().map(Rc::new)}
                        typing={state.text_editing} />
                    }
                    <div class="side">
                        if let Some(shown) = shown.clone() {
                            <PositionDisplay state={shown} stopped={state.stop_position()} lang={l} machine={state.machine.clone()} fraction={*fraction} />
                        }
                        <WhyPanel doc={DocRef(state.doc.clone())} cursor={state.cursor} machine={state.machine.clone()}
                            sim={state.sim.clone()} shown={shown} lang={l} {on_hover}
                            collision={state.material_note().map(|t| t.get(l).to_owned())} />
                    </div>
                </main>
                <DialogArea {dialog} text={state.dialog_line()} lang={l} on_action={on_action.clone()} />
                <SoftkeyRow row={softkeys::row(&state)} name={AttrValue::from(softkeys::row_name(&state).get(l).to_owned())} {on_action} {on_import} />
            </div>
        }
}
