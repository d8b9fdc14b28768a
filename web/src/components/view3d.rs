//! The 3D view pane. For now it owns a WebGL2 context that it clears to the background
//! colour; without WebGL2 it says so plainly and the rest of the app keeps working.

use wasm_bindgen::JsCast;
use web_sys::{HtmlCanvasElement, WebGl2RenderingContext as Gl};
use yew::prelude::*;

use crate::i18n::Lang;

/// Background of the view (the control's dark graphics area), linear RGB.
const BACKGROUND: [f32; 3] = [0.11, 0.15, 0.20];

#[derive(Properties, PartialEq)]
pub struct View3dProps {
    pub lang: Lang,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum GlStatus {
    Pending,
    Ready,
    Missing,
}

/// Sizes the drawing buffer to the element and clears it; `false` if there is no WebGL2.
fn init_and_clear(canvas: &HtmlCanvasElement) -> bool {
    let Ok(Some(ctx)) = canvas.get_context("webgl2") else { return false };
    let Ok(gl) = ctx.dyn_into::<Gl>() else { return false };
    let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
    let (w, h) = (f64::from(canvas.client_width()) * dpr, f64::from(canvas.client_height()) * dpr);
    if w >= 1.0 && h >= 1.0 {
        canvas.set_width(w as u32);
        canvas.set_height(h as u32);
    }
    gl.viewport(0, 0, canvas.width() as i32, canvas.height() as i32);
    gl.clear_color(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1.0);
    gl.clear(Gl::COLOR_BUFFER_BIT);
    true
}

#[function_component(View3d)]
pub fn view3d(props: &View3dProps) -> Html {
    let canvas_ref = use_node_ref();
    let status = use_state(|| GlStatus::Pending);
    {
        let canvas_ref = canvas_ref.clone();
        let status = status.clone();
        use_effect_with((), move |_| {
            let ok = canvas_ref.cast::<HtmlCanvasElement>().is_some_and(|c| init_and_clear(&c));
            status.set(if ok { GlStatus::Ready } else { GlStatus::Missing });
        });
    }
    let l = props.lang;
    let state = match *status {
        GlStatus::Pending => "pending",
        GlStatus::Ready => "ready",
        GlStatus::Missing => "missing",
    };
    html! {
        <section class="view-pane" aria-label={l.t("3D-Ansicht", "3D view")}>
            <canvas ref={canvas_ref} class="view3d" data-webgl={state}></canvas>
            if *status == GlStatus::Missing {
                <p class="no-webgl">
                    { l.t("Dieser Browser kann kein WebGL2: die 3D-Ansicht ist nicht verfügbar. Alles andere funktioniert.",
                          "This browser has no WebGL2: the 3D view is not available. Everything else works.") }
                </p>
            }
        </section>
    }
}
