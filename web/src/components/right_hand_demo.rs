//! The right-hand rule, demonstrated (seed 000 §2.2): pick X, Y or Z, turn the plane by dragging
//! round the axis or with the slider, and watch the thumb arrow, the curled arrow, the hand, the
//! signed angle and the matching `PLANE SPATIAL` block. "Try it" asks for a signed turn and
//! checks the trainee's answer; the angle and the block stay hidden until "Prüfen", they would
//! give the sign away. In the trainer the demo opens on the cursor's PLANE block (`block`).

use std::rc::Rc;

use wasm_bindgen::JsCast;
use web_sys::{HtmlElement, HtmlInputElement, PointerEvent};
use yew::prelude::*;

use super::gl_canvas::{GlCanvas, SharedViewer};
use super::viewer::{Content, Viewer};
use crate::render::camera::Camera;
use crate::render::right_hand::{DragTurn, block_text, draw_list, pivot_on_screen, points_towards};
use glam::Vec3;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::preview::block_angles;
use schwenkbar_app::right_hand::{RightHand, RightHandAction};
use schwenkbar_core::number::parse_f64;
use schwenkbar_core::plane::RelAxis;
use schwenkbar_core::solve::fmt_deg;

/// The demo's CSS, shipped with the component (in the bundle only where the demo is mounted).
const STYLE: &str = include_str!("right_hand_demo.css");

#[derive(Properties, PartialEq)]
pub struct RightHandDemoProps {
    pub lang: Lang,
    /// A PLANE block (its text, as in the program): the demo shows its turns about X, Y and Z
    /// (SPA, SPB, SPC of the same orientation), starting with the first the control makes.
    #[prop_or_default]
    pub block: Option<AttrValue>,
}

/// The demo's fixed camera: front right above, so every axis points partly at the viewer.
fn demo_camera() -> Camera {
    Camera {
        target: Vec3::new(0.0, 20.0, 40.0),
        azimuth: -55.0,
        elevation: 24.0,
        distance: 640.0,
        fov_y: 35.0,
    }
}

/// A drag in progress: the pointer's id and the unrounded drag (so small moves are not lost to
/// the whole-degree rounding of the display).
#[derive(Default)]
struct Drag {
    active: Option<(i32, DragTurn)>,
}

/// The demo's state in yew: the app's reducer ([`RightHand`]), so that drag events between two
/// renders each act on the state the one before left.
#[derive(PartialEq, Default)]
struct Demo(RightHand);

impl Reducible for Demo {
    type Action = RightHandAction;

    fn reduce(self: Rc<Self>, action: RightHandAction) -> Rc<Self> {
        Rc::new(Demo(self.0.apply(action)))
    }
}

#[function_component(RightHandDemo)]
pub fn right_hand_demo(props: &RightHandDemoProps) -> Html {
    let l = props.lang;
    let viewer = use_mut_ref(|| Viewer::new(demo_camera()));
    let demo = use_reducer(Demo::default);
    let state = demo.0;
    let drag = use_mut_ref(Drag::default);
    let block_turns = props.block.as_deref().and_then(block_angles);
    {
        // A new block (or none): the reducer shows a new block's first turn.
        let demo = demo.dispatcher();
        use_effect_with(block_turns.map(|a| a.map(f64::to_bits)), move |bits| {
            demo.dispatch(RightHandAction::Block(bits.map(|b| b.map(f64::from_bits))));
        });
    }
    {
        let viewer = viewer.clone();
        use_effect_with((state.axis, state.angle), move |(axis, angle)| {
            let mut v = viewer.borrow_mut();
            let eye = v.camera.eye().as_dvec3();
            v.content = Some(Content::List(draw_list(*axis, *angle, eye)));
            v.dirty = true;
        });
    }
    let on_pointer = {
        let (viewer, drag, axis, angle, demo) =
            (viewer.clone(), drag.clone(), state.axis, state.angle, demo.dispatcher());
        Callback::from(move |(kind, e): (&'static str, PointerEvent)| {
            let at = (e.offset_x() as f32, e.offset_y() as f32);
            let mut d = drag.borrow_mut();
            match kind {
                "down" => {
                    let Some(el) = e.target().and_then(|t| t.dyn_into::<HtmlElement>().ok()) else { return };
                    let _ = el.set_pointer_capture(e.pointer_id());
                    // The camera does not move while the demo is dragged: one pivot per drag.
                    let (w, h) = (el.client_width() as f32, el.client_height() as f32);
                    let cam = viewer.borrow().camera;
                    let pivot = pivot_on_screen(&cam.view_proj(w / h.max(1.0)), w, h);
                    // The axis runs through the origin: its sign towards the eye decides.
                    let towards = points_towards(axis, cam.eye());
                    d.active = Some((e.pointer_id(), DragTurn::start(pivot, at, angle, towards)));
                }
                "move" => {
                    let Some((id, turn)) = d.active else { return };
                    if id != e.pointer_id() {
                        return;
                    }
                    let turn = turn.moved(at);
                    d.active = Some((id, turn));
                    demo.dispatch(RightHandAction::Turn(turn.angle));
                }
                _ => d.active = None,
            }
        })
    };
    let send = |action: RightHandAction| {
        let demo = demo.dispatcher();
        Callback::from(move |_: MouseEvent| demo.dispatch(action))
    };
    let on_slider = {
        let demo = demo.dispatcher();
        Callback::from(move |e: InputEvent| {
            if let Some(v) = e.target_dyn_into::<HtmlInputElement>().and_then(|i| parse_f64(&i.value())) {
                demo.dispatch(RightHandAction::Turn(v));
            }
        })
    };
    let (axis, angle) = (state.axis, state.angle);
    let block = block_text(axis, angle);
    let hidden = state.hidden();
    let feedback = state.feedback(l);
    html! {
        <section class="right-hand" aria-label={l.t("Rechte-Hand-Regel", "Right-hand rule")}>
            <style>{ STYLE }</style>
            <div class="rh-view">
                <GlCanvas lang={l} viewer={SharedViewer(viewer)} class="rh-canvas" gestures={false} {on_pointer}
                    label={l.t("Ebene: um die Achse ziehen dreht sie", "Plane: drag round the axis to turn it")} />
            </div>
            <div class="rh-controls">
                <div role="group" aria-label={l.t("Drehachse", "Axis")}>
                    { for RelAxis::ALL.iter().map(|a| html! {
                        <button type="button" class="rh-axis" data-axis={a.about()} aria-pressed={(axis == *a).to_string()}
                            onclick={send(RightHandAction::Pick(*a))}>{ a.about() }</button>
                    }) }
                </div>
                <label class="rh-slider">{ l.t("Winkel", "Angle") }
                    <input type="range" min="-180" max="180" step="1" value={angle.to_string()} oninput={on_slider} />
                </label>
                if hidden {
                    <output class="rh-angle" data-hidden="true">{ format!("{} ?", axis.word()) }</output>
                    <p class="rh-hidden">{ l.t("Winkel und Satz erscheinen nach „Prüfen“.", "The angle and the block show after \"Check\".") }</p>
                } else {
                    <output class="rh-angle" data-angle={angle.to_string()}>{ format!("{}{}°", axis.word(), fmt_deg(angle)) }</output>
                    <code class="rh-block">{ block }</code>
                }
                if let Some(t) = block_turns {
                    <p class="rh-of-block">{ format!("{} SPA{} SPB{} SPC{} – {}", l.t("Raumwinkel des Satzes:", "The block's spatial angles:"),
                        fmt_deg(t[0]), fmt_deg(t[1]), fmt_deg(t[2]),
                        l.t("X, Y und Z zeigen je eine Drehung; die Steuerung dreht erst um X, dann um Y, dann um Z.",
                            "X, Y and Z show one turn each; the control turns about X first, then Y, then Z.")) }</p>
                }
                <p class="rh-rule">{ l.t("Rechte Hand: Daumen in Plus-Richtung der Achse, die gekrümmten Finger zeigen die positive Drehrichtung.",
                                         "Right hand: thumb along the plus axis, the curled fingers show the positive turning direction.") }</p>
                <div class="rh-try">
                    <button type="button" class="rh-start" onclick={send(RightHandAction::NextTask)}>
                        { if state.task.is_some() { l.t("Nächste Aufgabe", "Next task") } else { l.t("Ausprobieren", "Try it") } }</button>
                    if let Some(task) = state.task_text(l) {
                        <p class="rh-task">{ task }</p>
                        <button type="button" class="rh-check" onclick={send(RightHandAction::Check)}>{ l.t("Prüfen", "Check") }</button>
                    }
                    if let Some((kind, text)) = feedback {
                        <p class={classes!("rh-verdict", kind)}>{ text }</p>
                    }
                </div>
            </div>
        </section>
    }
}
