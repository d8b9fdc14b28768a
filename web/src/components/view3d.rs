//! The 3D view pane: the machine in its current state, the coordinate systems, the working plane,
//! the toolpath and the ghost of the other PLANE solution; preset views and triad switches.
//! Without WebGL2 it says so plainly and the rest of the app keeps working.
//!
//! The parent owns time: for an animation it passes the state at the current fraction
//! (`MachineAxes::lerp` or the simulator's `axes_at`); the view repaints when the state changes.

use std::rc::Rc;

use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use super::gl_canvas::{GlCanvas, SharedViewer};
use super::viewer::{Content, Viewer};
use crate::render::camera::{Camera, Preset};
use crate::render::toolpath::PathPoint;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::scene::pose::{blank_centre, work_points};
use schwenkbar_app::scene::{SceneState, Triads};

/// The toolpath, shared and compared by identity (a run's path has up to 100,000 segments;
/// comparing it point by point on every render would cost more than drawing it).
#[derive(Clone, Default)]
pub struct SharedPath(pub Rc<[PathPoint]>);

impl PartialEq for SharedPath {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0)
    }
}

#[derive(Properties, PartialEq)]
pub struct View3dProps {
    pub lang: Lang,
    /// The machine; `None` = the built-in `ac-table`.
    #[prop_or_default]
    pub machine: Option<Rc<Machine>>,
    /// The state to draw (axes at the current animation fraction, frames, tool, blank, ghost);
    /// `None` = the machine before a program runs ([`SceneState::for_machine`]).
    #[prop_or_default]
    pub state: Option<Rc<SceneState>>,
    /// The tool tip's path of the run, W-CS on the table at home.
    #[prop_or_default]
    pub toolpath: SharedPath,
    /// A program run is shown: the "Werkstück" camera is on until the trainee moves the view.
    #[prop_or_default]
    pub in_run: bool,
    /// The trainee is typing in the text editor: a changed scene is painted once typing pauses
    /// (`TYPING_PAUSE_FRAMES`).
    #[prop_or_default]
    pub typing: bool,
}

/// Frames without a new scene that count as a pause in typing (about 150 ms).
const TYPING_PAUSE_FRAMES: u32 = 9;

/// Whether two contents draw the same scene (the machine compared by identity).
fn same_content(a: Option<&Content>, b: Option<&Content>) -> bool {
    match (a, b) {
        (
            Some(Content::Machine { machine: m0, state: s0, triads: t0 }),
            Some(Content::Machine { machine: m1, state: s1, triads: t1 }),
        ) => Rc::ptr_eq(m0, m1) && s0 == s1 && t0 == t1,
        (None, None) => true,
        _ => false,
    }
}

/// The toolbar's CSS, shipped with the component.
const STYLE: &str = include_str!("view3d.css");

/// The preset buttons: view, `data-view`, German and English label.
const VIEWS: [(Preset, &str, &str, &str); 4] = [
    (Preset::Front, "front", "Vorne", "Front"),
    (Preset::Side, "side", "Seite", "Side"),
    (Preset::Top, "top", "Oben", "Top"),
    (Preset::Iso, "iso", "Iso", "Iso"),
];

/// The triad switches in [`Triads::get`] order: `data-triad`, German and English label.
const TRIAD_SWITCHES: [(&str, &str, &str); 4] = [
    ("mcs", "Maschine M-CS", "Machine M-CS"),
    ("wcs", "Werkstück W-CS", "Workpiece W-CS"),
    ("wpl", "Bearbeitungsebene WPL-CS", "Working plane WPL-CS"),
    ("tcs", "Werkzeug T-CS", "Tool T-CS"),
];

#[function_component(View3d)]
pub fn view3d(props: &View3dProps) -> Html {
    let viewer = use_mut_ref(|| Viewer::new(Camera::default()));
    // Two sets of switches: the normal view's and the collision moment's (which starts with
    // none, so the red bodies are not hidden under triads).
    let collision = props.state.as_ref().is_some_and(|s| s.contact.is_some());
    let normal_triads = use_state(|| Triads::at_start(false));
    let contact_triads = use_state(|| Triads::at_start(true));
    let triads = if collision { contact_triads } else { normal_triads };
    // Renders the toolbar again when a button changed the viewer (the "Werkstück" switch).
    let redraw = use_state(|| false);
    // The stock's figures under the picture, written by the viewer's frames (`Viewer::figures`).
    let figures_ref = use_node_ref();
    {
        // One effect after every render (View3d renders only when its props or switches change)
        // instead of one per dependency: each `use_effect_with` costs bundle size, and the
        // comparisons here are by pointer, not by value.
        let viewer = viewer.clone();
        let (machine, state, path, triads) =
            (props.machine.clone(), props.state.clone(), props.toolpath.0.clone(), *triads);
        let (in_run, typing) = (props.in_run, props.typing);
        let (figures_ref, lang) = (figures_ref.clone(), props.lang);
        use_effect(move || {
            let mut v = viewer.borrow_mut();
            if v.figures.as_ref().map(|f| f.1) != Some(lang) {
                // A new language writes the line again at the next paint.
                v.dirty = true;
            }
            v.figures = figures_ref.cast::<web_sys::HtmlElement>().map(|el| (el, lang));
            let run_changed = in_run != v.in_run;
            if run_changed {
                v.in_run = in_run;
                v.follow = in_run;
            }
            let machine = machine.or_else(|| v.fallback_machine());
            let new_machine = machine.as_ref().map(|m| m.id.as_str()) != v.machine_id.as_deref();
            v.machine_id = machine.as_ref().map(|m| m.id.clone());
            let content = machine.map(|machine| {
                let state = match state {
                    Some(s) => (*s).clone(),
                    None => SceneState::for_machine(&machine),
                };
                Content::Machine { machine, state: Box::new(state), triads }
            });
            // A keystroke that leaves the scene as it was (most do) paints nothing.
            let changed = !same_content(v.content.as_ref(), content.as_ref());
            v.content = content;
            // Look at the blank when the machine changes (not on every state: a trainee's pan
            // stays while the program runs).
            if let Some(Content::Machine { machine, state, .. }) = &v.content {
                let (centre, points) = (blank_centre(machine, state).as_vec3(), work_points(machine, state));
                if new_machine {
                    v.camera.target = centre;
                }
                v.work_points = points;
            }
            let new_path = !v.path.as_ref().is_some_and(|p| Rc::ptr_eq(p, &path));
            if new_path {
                // Uploaded by the next frame (the renderer may not exist yet).
                v.pending_path = Some(path.clone());
                v.path = Some(path);
            }
            if changed && typing {
                v.hold = TYPING_PAUSE_FRAMES;
            }
            if changed || run_changed || new_path {
                v.dirty = true;
            }
        });
    }
    let l = props.lang;
    let preset = |p: Preset| {
        let viewer = viewer.clone();
        Callback::from(move |_: MouseEvent| {
            let mut v = viewer.borrow_mut();
            v.camera.set_preset(p);
            v.dirty = true;
        })
    };
    // The "Werkstück" camera: frames the blank and the tool, and keeps them framed.
    let follow = viewer.borrow().follow;
    // A switch of the viewer's: flips it, paints again and renders the toolbar again.
    let switch = |flag: fn(&mut Viewer) -> &mut bool| {
        let viewer = viewer.clone();
        let redraw = redraw.clone();
        Callback::from(move |_: MouseEvent| {
            let mut v = viewer.borrow_mut();
            let on = flag(&mut v);
            *on = !*on;
            v.dirty = true;
            redraw.set(!*redraw);
        })
    };
    let toggle_follow = switch(|v| &mut v.follow);
    // The "Schnitt" switch: the stock cut open through the tool, the half towards the viewer
    // left out (also the `s` key on the view).
    let section = viewer.borrow().section;
    let toggle_section = switch(|v| &mut v.section);
    let toggle = |i: usize| {
        let triads = triads.clone();
        Callback::from(move |_: Event| {
            let mut t = *triads;
            t.flip(i);
            triads.set(t);
        })
    };
    let t = *triads;
    // The translucent other solution, named for assistive technology and the browser tests.
    let ghost = props.state.as_ref().and_then(|s| s.ghost).map(|g| schwenkbar_core::solve::axis_words(&g));
    html! {
        <section class="view-pane" aria-label={l.t("3D-Ansicht", "3D view")} data-ghost={ghost}>
            <style>{ STYLE }</style>
            <GlCanvas lang={l} viewer={SharedViewer(viewer.clone())} class="view3d"
                label={l.t("Maschine in 3D (ziehen, Umschalt, Rad, 1–4, S Schnitt)", "Machine in 3D (drag, shift, wheel, 1–4, S section)")} />
            <div class="view-tools">
                <div class="view-presets" role="group" aria-label={l.t("Ansichten", "Views")}>
                    { for VIEWS.iter().map(|&(p, key, de, en)| html! {
                        <button type="button" data-view={key} onclick={preset(p)}>{ l.t(de, en) }</button>
                    }) }
                    <button type="button" data-view="work" aria-pressed={if follow { "true" } else { "false" }}
                        title={l.t("Rohteil und Werkzeug im Bild halten", "Keep the blank and the tool in view")}
                        onclick={toggle_follow}>{ l.t("Werkstück", "Workpiece") }</button>
                    <button type="button" data-view="section" aria-pressed={if section { "true" } else { "false" }}
                        title={l.t("Rohteil aufgeschnitten durch das Werkzeug (Taste S)", "The stock cut open through the tool (key S)")}
                        onclick={toggle_section}>{ l.t("Schnitt", "Section") }</button>
                </div>
                <div class="view-triads" role="group" aria-label={l.t("Koordinatensysteme", "Coordinate systems")}>
                    { for TRIAD_SWITCHES.iter().enumerate().map(|(i, &(key, de, en))| html! {
                        <label><input type="checkbox" data-triad={key} checked={t.get(i)} onchange={toggle(i)} />
                            { l.t(de, en) }</label>
                    }) }
                </div>
            </div>
            <output ref={figures_ref} class="stock-figures" data-testid="stock-figures" aria-live="polite"></output>
        </section>
    }
}
