//! The machinery shared by the 3D view and the right-hand demo: a canvas with a renderer, the
//! animation loop (cancelled on unmount), context loss and restore, wheel zoom, pointer and key
//! gestures, and the label layer. The parent hands in a shared [`Viewer`] and fills its content.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;
use web_sys::{HtmlCanvasElement, HtmlElement, KeyboardEvent, PointerEvent, WheelEvent};
use yew::prelude::*;

use super::viewer::{FrameOutcome, Viewer};
use crate::render::camera::Preset;
use crate::render::context::ContextWatch;
use crate::render::gpu::RenderError;
use crate::render::renderer::Renderer;
use schwenkbar_app::i18n::Lang;

/// The canvas' and labels' CSS, shipped with the component (each component brings its own rules,
/// so a page pays only for what it mounts; 3D labels are HTML so they stay crisp at any
/// devicePixelRatio).
const STYLE: &str = include_str!("gl_canvas.css");

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GlStatus {
    Pending,
    Ready,
    Lost,
    Missing,
    Failed,
}

impl GlStatus {
    #[must_use]
    pub fn attr(self) -> &'static str {
        match self {
            GlStatus::Pending => "pending",
            GlStatus::Ready => "ready",
            GlStatus::Lost => "lost",
            GlStatus::Missing => "missing",
            GlStatus::Failed => "failed",
        }
    }
}

/// A shared viewer compared by identity (it never changes for a mounted component).
#[derive(Clone)]
pub struct SharedViewer(pub Rc<RefCell<Viewer>>);

impl PartialEq for SharedViewer {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0)
    }
}

#[derive(Properties, PartialEq)]
pub struct GlCanvasProps {
    pub lang: Lang,
    pub viewer: SharedViewer,
    /// CSS class of the canvas besides `gl` (`view3d` for the machine view).
    pub class: AttrValue,
    /// Accessible name of the canvas.
    pub label: AttrValue,
    /// Camera gestures (orbit, pan, zoom, preset keys); off for a view that uses drags itself.
    #[prop_or(true)]
    pub gestures: bool,
    /// Pointer events for a parent that uses drags itself (the right-hand demo).
    #[prop_or_default]
    pub on_pointer: Option<Callback<(&'static str, PointerEvent)>>,
}

/// The animation-frame callback, reachable from itself to schedule the next frame.
type FrameSlot = Rc<RefCell<Option<Closure<dyn FnMut(f64)>>>>;

/// Starts the loop: paints dirty frames until the returned guard is dropped.
fn start_loop(viewer: Rc<RefCell<Viewer>>, status: UseStateHandle<GlStatus>) -> impl FnOnce() {
    let handle = Rc::new(Cell::new(None::<i32>));
    let closure: FrameSlot = Rc::new(RefCell::new(None));
    let (h, c) = (handle.clone(), closure.clone());
    // The handle's value is a snapshot; remember what was reported to set the state only on a
    // change (every set re-renders).
    let reported = Cell::new(*status);
    *closure.borrow_mut() = Some(Closure::new(move |_t: f64| {
        let outcome = viewer.borrow_mut().frame();
        let next = match outcome {
            FrameOutcome::Failed(RenderError::ContextLost) => Some(GlStatus::Lost),
            FrameOutcome::Failed(_) => Some(GlStatus::Failed),
            FrameOutcome::Painted => Some(GlStatus::Ready),
            FrameOutcome::Idle => None,
        };
        if let Some(next) = next.filter(|n| *n != reported.get()) {
            reported.set(next);
            status.set(next);
        }
        if let (Some(w), Some(cb)) = (web_sys::window(), c.borrow().as_ref()) {
            h.set(w.request_animation_frame(cb.as_ref().unchecked_ref()).ok());
        }
    }));
    if let (Some(w), Some(cb)) = (web_sys::window(), closure.borrow().as_ref()) {
        handle.set(w.request_animation_frame(cb.as_ref().unchecked_ref()).ok());
    }
    move || {
        if let (Some(w), Some(id)) = (web_sys::window(), handle.get()) {
            let _ = w.cancel_animation_frame(id);
        }
        // Dropping the closure breaks its reference cycle with itself.
        closure.borrow_mut().take();
    }
}

/// Wheel zoom needs a non-passive listener so the page does not scroll at the same time.
fn wheel_listener(canvas: &HtmlCanvasElement, viewer: Rc<RefCell<Viewer>>) -> impl FnOnce() + use<> {
    let canvas_css = canvas.clone();
    let cb = Closure::<dyn FnMut(WheelEvent)>::new(move |e: WheelEvent| {
        e.prevent_default();
        // deltaMode 1 = lines (Firefox); a line is about 16 px.
        let dy = if e.delta_mode() == 1 { e.delta_y() * 16.0 } else { e.delta_y() };
        let mut v = viewer.borrow_mut();
        // 0.15 % per pixel of scroll, the same in and out (no exp(): keeps libm out of the bundle).
        let step = (1.0 + dy.abs() * 0.0015).min(2.0) as f32;
        let factor = if dy > 0.0 { step } else { 1.0 / step };
        // Towards the pointer (offset_x/y: CSS pixels in the canvas).
        let (w, h) = (canvas_css.client_width() as f32, canvas_css.client_height() as f32);
        if w > 0.0 && h > 0.0 {
            v.camera.zoom_at(factor, e.offset_x() as f32, e.offset_y() as f32, w, h);
        } else {
            v.camera.zoom(factor);
        }
        v.follow = false;
        v.dirty = true;
    });
    let opts = web_sys::AddEventListenerOptions::new();
    opts.set_passive(false);
    let _ = canvas.add_event_listener_with_callback_and_add_event_listener_options(
        "wheel",
        cb.as_ref().unchecked_ref(),
        &opts,
    );
    let canvas = canvas.clone();
    move || {
        let _ = canvas.remove_event_listener_with_callback("wheel", cb.as_ref().unchecked_ref());
    }
}

#[function_component(GlCanvas)]
pub fn gl_canvas(props: &GlCanvasProps) -> Html {
    let canvas_ref = use_node_ref();
    let labels_ref = use_node_ref();
    let status = use_state(|| GlStatus::Pending);
    {
        let (canvas_ref, labels_ref, status) = (canvas_ref.clone(), labels_ref.clone(), status.clone());
        let viewer = props.viewer.0.clone();
        let gestures = props.gestures;
        use_effect_with((), move |_| {
            let mut cleanup: Vec<Box<dyn FnOnce()>> = Vec::new();
            match canvas_ref.cast::<HtmlCanvasElement>() {
                Some(canvas) => match Renderer::new(&canvas) {
                    Ok(r) => {
                        {
                            let mut v = viewer.borrow_mut();
                            v.renderer = Some(r);
                            v.dirty = true;
                            v.set_label_layer(labels_ref.cast::<HtmlElement>());
                        }
                        let (v1, v2) = (viewer.clone(), viewer.clone());
                        let (s1, s2) = (status.clone(), status.clone());
                        let watch = ContextWatch::new(
                            &canvas,
                            move || {
                                let mut v = v1.borrow_mut();
                                v.lost = true;
                                if let Some(r) = &mut v.renderer {
                                    r.lost();
                                }
                                s1.set(GlStatus::Lost);
                            },
                            move || {
                                let mut v = v2.borrow_mut();
                                let ok = v.renderer.as_mut().is_some_and(|r| r.restore().is_ok());
                                v.lost = !ok;
                                v.dirty = true;
                                s2.set(if ok { GlStatus::Ready } else { GlStatus::Failed });
                            },
                        );
                        cleanup.push(Box::new(move || drop(watch)));
                        if gestures {
                            cleanup.push(Box::new(wheel_listener(&canvas, viewer.clone())));
                        }
                        cleanup.push(Box::new(start_loop(viewer.clone(), status.clone())));
                    }
                    Err(RenderError::NoWebGl2) => status.set(GlStatus::Missing),
                    Err(_) => status.set(GlStatus::Failed),
                },
                None => status.set(GlStatus::Missing),
            }
            move || {
                for c in cleanup {
                    c();
                }
                let mut v = viewer.borrow_mut();
                v.renderer = None;
                v.set_label_layer(None);
            }
        });
    }

    let pointer = |kind: &'static str| {
        let viewer = props.viewer.0.clone();
        let gestures = props.gestures;
        let forward = props.on_pointer.clone();
        Callback::from(move |e: PointerEvent| {
            if let Some(f) = &forward {
                f.emit((kind, e.clone()));
            }
            if !gestures {
                return;
            }
            let mut v = viewer.borrow_mut();
            match kind {
                "down" => v.pointer_down(&e),
                "move" => v.pointer_move(&e),
                "leave" => v.pointer_leave(),
                _ => v.pointer_up(&e),
            }
        })
    };
    let onkeydown = {
        let viewer = props.viewer.0.clone();
        let gestures = props.gestures;
        Callback::from(move |e: KeyboardEvent| {
            if !gestures || e.ctrl_key() || e.meta_key() || e.alt_key() {
                return;
            }
            if let Some(p) = Preset::from_key(&e.key()) {
                e.prevent_default();
                let mut v = viewer.borrow_mut();
                v.camera.set_preset(p);
                v.dirty = true;
            } else if e.key().eq_ignore_ascii_case("s") {
                // "Schnitt"/"section": the stock cut open through the tool.
                e.prevent_default();
                let mut v = viewer.borrow_mut();
                v.section = !v.section;
                v.dirty = true;
            }
        })
    };
    let l = props.lang;
    html! {
        <>
            <style>{ STYLE }</style>
            <canvas ref={canvas_ref} class={classes!("gl", props.class.clone())} data-webgl={status.attr()} tabindex="0"
                aria-label={props.label.clone()}
                onpointerdown={pointer("down")} onpointermove={pointer("move")}
                onpointerup={pointer("up")} onpointercancel={pointer("up")} onpointerleave={pointer("leave")}
                oncontextmenu={Callback::from(|e: MouseEvent| e.prevent_default())}
                {onkeydown}></canvas>
            <div ref={labels_ref} class="gl-labels" aria-hidden="true"></div>
            // One message for both ways the view cannot start (no WebGL2, or the GPU refused
            // the shaders): the trainee can do nothing about either; `data-webgl` tells which.
            if matches!(*status, GlStatus::Missing | GlStatus::Failed) {
                <p class="no-webgl">
                    { l.t("Die 3D-Ansicht ist in diesem Browser nicht verfügbar (WebGL2 fehlt). Alles andere funktioniert.",
                          "The 3D view is not available in this browser (no WebGL2). Everything else works.") }
                </p>
            }
        </>
    }
}
