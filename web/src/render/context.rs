//! Watches a canvas for WebGL context loss and restore. A lost context comes back only if the
//! page calls `preventDefault()` on `webglcontextlost` (WebGL 1.0 spec §5.15.2), which this does;
//! the owner then rebuilds its GL objects on `webglcontextrestored`.

use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;
use web_sys::{Event, HtmlCanvasElement};

/// The two listeners; removed when dropped.
pub struct ContextWatch {
    canvas: HtmlCanvasElement,
    lost: Closure<dyn FnMut(Event)>,
    restored: Closure<dyn FnMut(Event)>,
}

impl ContextWatch {
    pub fn new(
        canvas: &HtmlCanvasElement,
        mut on_lost: impl FnMut() + 'static,
        mut on_restored: impl FnMut() + 'static,
    ) -> ContextWatch {
        let lost = Closure::<dyn FnMut(Event)>::new(move |e: Event| {
            e.prevent_default();
            on_lost();
        });
        let restored = Closure::<dyn FnMut(Event)>::new(move |_e: Event| on_restored());
        // Adding a listener fails only for a detached, exotic target; the view then simply
        // does not recover from a loss, which it reports like a missing WebGL2.
        let _ = canvas.add_event_listener_with_callback("webglcontextlost", lost.as_ref().unchecked_ref());
        let _ = canvas
            .add_event_listener_with_callback("webglcontextrestored", restored.as_ref().unchecked_ref());
        ContextWatch { canvas: canvas.clone(), lost, restored }
    }
}

impl Drop for ContextWatch {
    fn drop(&mut self) {
        let _ = self
            .canvas
            .remove_event_listener_with_callback("webglcontextlost", self.lost.as_ref().unchecked_ref());
        let _ = self.canvas.remove_event_listener_with_callback(
            "webglcontextrestored",
            self.restored.as_ref().unchecked_ref(),
        );
    }
}
