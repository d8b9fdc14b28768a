//! Stand-alone pages for the 3D parts, opened by URL fragment (for teaching with a projector,
//! for screenshots and for checking every machine by eye):
//! `#3d:machine=b45-nutating;spb=45` = the machine after that PLANE SPATIAL (ghost = the other
//! candidate); `#rechte-hand` (`#right-hand` in English) = the right-hand demo.

use std::rc::Rc;

use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use super::right_hand_demo::RightHandDemo;
use super::view3d::{SharedPath, View3d};
use crate::i18n::Lang;
use crate::render::plane_scene::{PageQuery, demo_path, state_for};
use crate::render::toolpath::PathPoint;

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

/// Mounts the page the URL fragment names, if it names one (the app's entry point asks first).
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
    let Ok(machine) = Machine::builtin(&q.machine) else {
        return html! { <p class="page3d-error">{ format!("{}: {}", lang.t("Unbekannte Maschine", "Unknown machine"), q.machine) }</p> };
    };
    let (mut state, e) = state_for(&machine, q.orientation(), AxisValues::default());
    if !q.ghost {
        state.ghost = None;
    }
    let path: Rc<[PathPoint]> =
        if q.path { demo_path(&state.blank, &state.wpl).into() } else { Rc::from(Vec::new()) };
    let axes: Vec<String> =
        state.axes.rotary.iter().map(|(a, v)| schwenkbar_core::solve::axis_word(a, v)).collect();
    let pick = |t: &schwenkbar_core::machine::Texts| match lang {
        Lang::De => t.de.clone(),
        Lang::En => t.en.clone(),
    };
    let caption = match &e.error_message {
        Some(m) => lang.t(m.de(), m.en()).to_string(),
        None => axes.join(" "),
    };
    html! {
        <main class="page3d page3d-machine">
            <p class="page3d-caption">{ format!("{} · PLANE SPATIAL SPA{} SPB{} SPC{} → {caption}",
                pick(&machine.name),
                schwenkbar_core::solve::fmt_deg(q.spatial[0]),
                schwenkbar_core::solve::fmt_deg(q.spatial[1]),
                schwenkbar_core::solve::fmt_deg(q.spatial[2])) }</p>
            <View3d {lang} machine={Some(Rc::new(machine))} state={Rc::new(state)} toolpath={SharedPath(path)} />
        </main>
    }
}
