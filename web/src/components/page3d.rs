//! Stand-alone pages for the 3D parts, opened by URL fragment (for teaching with a projector,
//! for screenshots and for checking every machine by eye):
//! `#3d:machine=b45-nutating;spb=45` = the machine after that PLANE SPATIAL (ghost = the other
//! candidate); `#rechte-hand` (`#right-hand` in English) = the right-hand demo. Add `;lang=en`
//! for English. (A page that runs a sample program through the simulator was left out: it pulls
//! the simulator into the bundle, ~36 KB gzip, before the app itself uses it.)

use std::rc::Rc;

use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use super::right_hand_demo::RightHandDemo;
use super::view3d::{SharedPath, View3d};
use crate::i18n::Lang;
use crate::render::plane_scene::{PageQuery, demo_path, state_for};
use crate::render::scene::SceneState;
use crate::render::toolpath::PathPoint;
use schwenkbar_core::solve::{axis_word, fmt_deg};

#[derive(Properties, PartialEq)]
pub struct Page3dProps {
    /// The URL fragment without `#`.
    pub fragment: AttrValue,
}

/// Whether a fragment names one of these pages.
#[must_use]
pub fn is_page(fragment: &str) -> bool {
    fragment.starts_with("3d") || fragment.starts_with("rechte-hand") || fragment.starts_with("right-hand")
}

/// Mounts the page the URL fragment names, if it names one. Not called by the app's entry point
/// on purpose: the pages cost ~12 KB gzip of the 240 KB bundle budget. To have them, call it
/// first in `lib.rs` `start()`: `if components::page3d::mount_if_named() { return; }`.
#[must_use]
pub fn mount_if_named() -> bool {
    let fragment = web_sys::window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
    let fragment = fragment.trim_start_matches('#');
    if !is_page(fragment) {
        return false;
    }
    yew::Renderer::<Page3d>::with_props(Page3dProps { fragment: fragment.to_string().into() }).render();
    true
}

#[function_component(Page3d)]
pub fn page3d(props: &Page3dProps) -> Html {
    let f = props.fragment.as_str();
    let lang = if f.starts_with("right-hand") || f.contains("lang=en") { Lang::En } else { Lang::De };
    if !f.starts_with("3d") {
        return html! { <main class="page3d page3d-hand"><RightHandDemo {lang} /></main> };
    }
    let q = PageQuery::parse(f.trim_start_matches("3d"));
    match plane_page(&q, lang) {
        Ok((machine, state, path, caption)) => html! {
            <main class="page3d page3d-machine">
                <p class="page3d-caption">{ caption }</p>
                <View3d {lang} machine={Some(Rc::new(machine))} state={Some(Rc::new(state))} toolpath={SharedPath(path)} />
            </main>
        },
        Err(message) => html! { <p class="page3d-error">{ message }</p> },
    }
}

/// Machine, state, toolpath and caption of a page, or the message why there is none.
type Page = Result<(Machine, SceneState, Rc<[PathPoint]>, String), String>;

fn machine_named(id: &str, lang: Lang) -> Result<Machine, String> {
    Machine::builtin(id).map_err(|_| format!("{}: {id}", lang.t("Unbekannte Maschine", "Unknown machine")))
}

fn texts(lang: Lang, t: &schwenkbar_core::machine::Texts) -> String {
    match lang {
        Lang::De => t.de.clone(),
        Lang::En => t.en.clone(),
    }
}

/// One PLANE SPATIAL from the home position, solved by core.
fn plane_page(q: &PageQuery, lang: Lang) -> Page {
    let machine = machine_named(q.machine.as_deref().unwrap_or("ac-table"), lang)?;
    let (mut state, e) = state_for(&machine, q.orientation(), AxisValues::default());
    if !q.ghost {
        state.ghost = None;
    }
    let path: Rc<[PathPoint]> =
        if q.path { demo_path(&state.blank, &state.wpl).into() } else { Rc::from(Vec::new()) };
    let axes: Vec<String> = state.axes.rotary.iter().map(|(a, v)| axis_word(a, v)).collect();
    let result = match &e.error_message {
        Some(m) => lang.t(m.de(), m.en()).to_string(),
        None => axes.join(" "),
    };
    let [a, b, c] = q.spatial.map(fmt_deg);
    let caption = format!("{} · PLANE SPATIAL SPA{a} SPB{b} SPC{c} → {result}", texts(lang, &machine.name));
    Ok((machine, state, path, caption))
}
