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
use crate::render::toolpath::PathPoint;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::scene::{Scene, SceneState, Triads};

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
    pub paints: u64,
    /// Frames to wait before painting a new scene: set while the trainee types in the text
    /// editor, so that the view is painted once typing pauses. A paint of a long run's toolpath
    /// costs tens of ms (far more in software WebGL) and would hold up the text on every key.
    pub hold: u32,
    /// A toolpath to upload at the next frame.
    pub pending_path: Option<Rc<[PathPoint]>>,
    /// The toolpath shown (compared by pointer to notice a new run).
    pub path: Option<Rc<[PathPoint]>>,
    /// The machine shown, to notice a change of machine.
    pub machine_id: Option<String>,
    /// The "Werkstück" camera: frame the blank and the tool at every new state. On by default
    /// in a program run; a pan or zoom of the trainee's own turns it off.
    pub follow: bool,
    /// Whether the last content was a program run (to switch `follow` on as a run starts).
    pub in_run: bool,
    /// What the "Werkstück" camera frames: the blank's corners and the tool, M-CS.
    pub work_points: Vec<glam::Vec3>,
    /// The "Schnitt" switch: the stock is drawn cut open through the tool.
    pub section: bool,
    /// Where the stock's figures are written (the 3D view's line under the picture), in the
    /// UI's language: filled here once the stock shown is cut, not by the component, whose
    /// renders stop while the frames go on cutting.
    pub figures: Option<(HtmlElement, Lang)>,
    /// The figures' text written last.
    figures_shown: String,
    /// Where the pointer hovers over the canvas (CSS px from its top left corner), for the
    /// depth under it; `None` off the canvas or while it drags.
    hover: Option<(f32, f32)>,
    /// The pointer moved since the line was written last.
    hover_moved: bool,
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
            paints: 0,
            hold: 0,
            pending_path: None,
            path: None,
            machine_id: None,
            follow: false,
            in_run: false,
            work_points: Vec::new(),
            section: false,
            figures: None,
            figures_shown: String::new(),
            hover: None,
            hover_moved: false,
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
            // Nothing to paint, but the pointer moved over the part: only the line changes.
            if std::mem::take(&mut self.hover_moved) {
                self.show_figures();
            }
            return FrameOutcome::Idle;
        }
        if self.hold > 0 {
            self.hold -= 1;
            return FrameOutcome::Idle;
        }
        if self.follow && self.size.1 > 0.0 {
            self.camera.frame(&self.work_points, self.size.0 / self.size.1, WORK_MARGIN);
        }
        let Some(content) = &self.content else { return FrameOutcome::Idle };
        renderer.section = self.section;
        let result = match content {
            Content::Machine { machine, state, triads } => {
                renderer.paint(&Scene { machine, state, triads: *triads }, &self.camera)
            }
            Content::List(list) => renderer.paint_list(list, &self.camera, None),
        };
        match result {
            Ok(mut labels) => {
                // The stock may still be cutting its way to this step: paint on until it is there.
                self.dirty = renderer.wants_frame();
                self.paints += 1;
                spread_labels(&mut labels);
                self.place_labels(&labels);
                if !self.dirty {
                    self.show_figures();
                }
                FrameOutcome::Painted
            }
            Err(RenderError::ContextLost) => {
                self.lost = true;
                FrameOutcome::Failed(RenderError::ContextLost)
            }
            Err(e) => FrameOutcome::Failed(e),
        }
    }

    /// Writes the figures of the stock shown (removed volume, the box left) and what lies
    /// under the pointer, or nothing when no stock is drawn.
    fn show_figures(&mut self) {
        let Some((el, lang)) = &self.figures else { return };
        let stock = match &self.content {
            Some(Content::Machine { state, .. }) => state.stock.as_ref(),
            _ => None,
        };
        let mut text = stock.and_then(|s| s.stock.figures()).map(|f| f.line(*lang)).unwrap_or_default();
        let model = self.renderer.as_ref().and_then(|r| r.stock_shown);
        if let (Some(stock), Some(model), Some((x, y))) = (stock, model, self.hover) {
            // The pointer's ray carried from the machine into the W-CS the stock is cut in.
            let (eye, dir) = self.camera.ray(x, y, self.size.0, self.size.1);
            let to_wcs = model.inverse();
            let (origin, dir) =
                (to_wcs.transform_point3(eye.as_dvec3()), to_wcs.transform_vector3(dir.as_dvec3()));
            if let Some((hit, top)) = stock.stock.under_pointer(origin, dir) {
                text = format!("{text} · {}", schwenkbar_app::stock::pointer_line(hit, top, *lang));
            }
        }
        if text != self.figures_shown {
            el.set_text_content(Some(&text));
            self.figures_shown = text;
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
        let Some(i) = self.pointers.iter().position(|p| p.0 == id) else {
            // Hovering: the depth under the pointer is written at the next frame.
            self.hover = Some((e.offset_x() as f32, e.offset_y() as f32));
            self.hover_moved = true;
            return;
        };
        self.hover = None;
        let (_, px, py) = self.pointers[i];
        let h = self.size.1;
        if self.pointers.len() >= 2 {
            // Two fingers: the midpoint pans, the spread zooms.
            let other = self.pointers[if i == 0 { 1 } else { 0 }];
            let before = ((px - other.1).hypot(py - other.2)).max(1.0);
            let after = ((x - other.1).hypot(y - other.2)).max(1.0);
            self.camera.zoom(before / after);
            self.camera.pan((x - px) / 2.0, (y - py) / 2.0, h);
            self.follow = false;
        } else if self.pan_drag || e.shift_key() {
            self.camera.pan(x - px, y - py, h);
            self.follow = false;
        } else {
            self.camera.orbit(x - px, y - py);
        }
        self.pointers[i] = (id, x, y);
        self.dirty = true;
    }

    pub fn pointer_up(&mut self, e: &PointerEvent) {
        self.pointers.retain(|p| p.0 != e.pointer_id());
    }

    /// The pointer left the canvas: nothing is under it.
    pub fn pointer_leave(&mut self) {
        self.hover = None;
        self.hover_moved = true;
    }
}

/// The "Werkstück" camera leaves this much room around the blank and the tool, so the table
/// and the head around them stay in view.
const WORK_MARGIN: f32 = 1.35;

/// Axis letter boxes, CSS px: a letter this close to an earlier one would cover it.
const LABEL_W: f32 = 16.0;
const LABEL_H: f32 = 15.0;

/// Frame names (`lbl-frame-*`) sit beside their origin by CSS offsets of their own (one per
/// frame, gl_canvas.css), so only the axis letters are spread here.
fn is_frame_name(label: &ScreenLabel) -> bool {
    label.kind.starts_with("frame")
}

/// Moves each axis letter down until it no longer covers an earlier one, so the letters of
/// triads whose origins coincide (W-CS, WPL-CS and I-CS on the blank) stay readable.
fn spread_labels(labels: &mut [ScreenLabel]) {
    for i in 1..labels.len() {
        let (placed, rest) = labels.split_at_mut(i);
        let label = &mut rest[0];
        if is_frame_name(label) {
            continue;
        }
        // Below the letter it covers: y only grows and never comes back to a letter it left,
        // so it is free after at most one move per earlier letter.
        for _ in 0..=placed.len() {
            let covered = placed.iter().find(|p| {
                !is_frame_name(p) && (p.x - label.x).abs() < LABEL_W && (p.y - label.y).abs() < LABEL_H
            });
            match covered {
                Some(p) => label.y = p.y + LABEL_H,
                None => break,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_at_one_point_are_stacked_not_piled() {
        let at = |text, x, y| ScreenLabel { text, kind: "x", x, y };
        let mut labels =
            vec![at("X", 100.0, 100.0), at("X'", 102.0, 101.0), at("XW", 99.0, 99.0), at("Y", 300.0, 100.0)];
        spread_labels(&mut labels);
        for (i, a) in labels.iter().enumerate() {
            for b in &labels[..i] {
                assert!(
                    (a.x - b.x).abs() >= LABEL_W || (a.y - b.y).abs() >= LABEL_H,
                    "{} covers {}",
                    a.text,
                    b.text
                );
            }
        }
        assert_eq!((labels[3].x, labels[3].y), (300.0, 100.0), "a free label stays where it is");
        let mut mixed =
            vec![at("X", 100.0, 100.0), ScreenLabel { text: "W-CS", kind: "frame-wcs", x: 100.0, y: 100.0 }];
        spread_labels(&mut mixed);
        assert_eq!(mixed[1].y, 100.0, "a frame name keeps its own CSS offset");
    }
}
