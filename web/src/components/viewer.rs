//! The mutable side of the 3D view, shared by the animation loop and the event handlers: the
//! renderer, the camera, the copy of the scene it draws, pointer tracking and the label pool.
//! Painting happens in the animation frame and only when something changed.

use std::rc::Rc;

use schwenkbar_core::machine::Machine;
use wasm_bindgen::JsCast;
use web_sys::{HtmlElement, PointerEvent};

use crate::render::camera::Camera;
use crate::render::draw_list::DrawList;
use crate::render::gpu::RenderError;
use crate::render::renderer::{Renderer, ScreenLabel};
use crate::render::scene::{Scene, SceneState, Triads};
use crate::render::toolpath::PathPoint;

/// What the viewer draws each frame it is dirty.
pub enum Content {
    Machine {
        machine: Rc<Machine>,
        state: Box<SceneState>,
        triads: Triads,
    },
    /// A prepared draw list (the right-hand demo).
    List(DrawList),
}

/// Result of a frame, for the component's status.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FrameOutcome {
    Idle,
    Painted,
    Failed(RenderError),
}

pub struct Viewer {
    pub renderer: Option<Renderer>,
    pub camera: Camera,
    pub content: Option<Content>,
    pub dirty: bool,
    pub lost: bool,
    size: (f32, f32),
    pointers: Vec<(i32, f32, f32)>,
    pan_drag: bool,
    labels: Option<HtmlElement>,
    pool: Vec<web_sys::Element>,
    /// Milliseconds the last paint took (`performance.now()` around it).
    pub last_paint_ms: f64,
    pub paints: u64,
    /// A toolpath to upload at the next frame.
    pub pending_path: Option<Rc<[PathPoint]>>,
    /// The toolpath shown (compared by pointer to notice a new run).
    pub path: Option<Rc<[PathPoint]>>,
    /// The machine shown, to notice a change of machine.
    pub machine_id: Option<String>,
    fallback: Option<Rc<Machine>>,
}

impl Viewer {
    #[must_use]
    pub fn new(camera: Camera) -> Viewer {
        Viewer {
            renderer: None,
            camera,
            content: None,
            dirty: true,
            lost: false,
            size: (0.0, 0.0),
            pointers: Vec::new(),
            pan_drag: false,
            labels: None,
            pool: Vec::new(),
            last_paint_ms: 0.0,
            paints: 0,
            pending_path: None,
            path: None,
            machine_id: None,
            fallback: None,
        }
    }

    /// The machine drawn when the parent gives none: the built-in `ac-table`, parsed once.
    pub fn fallback_machine(&mut self) -> Option<Rc<Machine>> {
        if self.fallback.is_none() {
            self.fallback = Machine::builtin("ac-table").ok().map(Rc::new);
        }
        self.fallback.clone()
    }

    pub fn set_label_layer(&mut self, el: Option<HtmlElement>) {
        self.labels = el;
        self.pool.clear();
    }

    /// One animation frame: repaint if the content, the camera or the canvas size changed.
    pub fn frame(&mut self) -> FrameOutcome {
        if self.lost {
            return FrameOutcome::Idle;
        }
        let Some(renderer) = &mut self.renderer else { return FrameOutcome::Idle };
        if let Some(path) = self.pending_path.take() {
            // An upload failure keeps the old path; the view itself keeps working.
            let _ = renderer.set_toolpath(&path);
        }
        let size = renderer.fit();
        if size != self.size {
            self.size = size;
            self.dirty = true;
        }
        if !self.dirty {
            return FrameOutcome::Idle;
        }
        let Some(content) = &self.content else { return FrameOutcome::Idle };
        let t0 = now();
        let result = match content {
            Content::Machine { machine, state, triads } => {
                renderer.paint(&Scene { machine, state, triads: *triads }, &self.camera)
            }
            Content::List(list) => renderer.paint_list(list, &self.camera, None),
        };
        let spent = now() - t0;
        match result {
            Ok(labels) => {
                self.dirty = false;
                self.paints += 1;
                self.last_paint_ms = spent;
                self.place_labels(&labels);
                FrameOutcome::Painted
            }
            Err(RenderError::ContextLost) => {
                self.lost = true;
                FrameOutcome::Failed(RenderError::ContextLost)
            }
            Err(e) => FrameOutcome::Failed(e),
        }
    }

    fn place_labels(&mut self, labels: &[ScreenLabel]) {
        let Some(layer) = &self.labels else { return };
        let Some(doc) = web_sys::window().and_then(|w| w.document()) else { return };
        while self.pool.len() < labels.len() {
            let Ok(el) = doc.create_element("span") else { return };
            if layer.append_child(&el).is_err() {
                return;
            }
            self.pool.push(el);
        }
        for (i, el) in self.pool.iter().enumerate() {
            // One attribute write per label and frame: the style as a whole.
            let style = match labels.get(i) {
                Some(l) => {
                    el.set_text_content(Some(l.text));
                    el.set_class_name(&format!("lbl lbl-{}", l.kind));
                    format!("transform:translate({:.1}px,{:.1}px)", f64::from(l.x), f64::from(l.y))
                }
                None => "display:none".to_string(),
            };
            let _ = el.set_attribute("style", &style);
        }
    }

    // ---- pointer gestures -------------------------------------------------------------------

    pub fn pointer_down(&mut self, e: &PointerEvent) {
        if let Some(t) = e.target().and_then(|t| t.dyn_into::<web_sys::Element>().ok()) {
            let _ = t.set_pointer_capture(e.pointer_id());
        }
        self.pointers.retain(|p| p.0 != e.pointer_id());
        self.pointers.push((e.pointer_id(), e.client_x() as f32, e.client_y() as f32));
        // Right button, or shift with the left: pan.
        self.pan_drag = e.button() == 2 || e.shift_key();
    }

    pub fn pointer_move(&mut self, e: &PointerEvent) {
        let id = e.pointer_id();
        let (x, y) = (e.client_x() as f32, e.client_y() as f32);
        let Some(i) = self.pointers.iter().position(|p| p.0 == id) else { return };
        let (_, px, py) = self.pointers[i];
        let h = self.size.1;
        if self.pointers.len() >= 2 {
            // Two fingers: the midpoint pans, the spread zooms.
            let other = self.pointers[if i == 0 { 1 } else { 0 }];
            let before = ((px - other.1).hypot(py - other.2)).max(1.0);
            let after = ((x - other.1).hypot(y - other.2)).max(1.0);
            self.camera.zoom(before / after);
            self.camera.pan((x - px) / 2.0, (y - py) / 2.0, h);
        } else if self.pan_drag || e.shift_key() {
            self.camera.pan(x - px, y - py, h);
        } else {
            self.camera.orbit(x - px, y - py);
        }
        self.pointers[i] = (id, x, y);
        self.dirty = true;
    }

    pub fn pointer_up(&mut self, e: &PointerEvent) {
        self.pointers.retain(|p| p.0 != e.pointer_id());
    }
}

/// `performance.now()` in milliseconds (0 without a window, e.g. in a worker).
#[must_use]
pub fn now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}
