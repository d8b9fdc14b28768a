//! Headless-Chromium test of the stock in the 3D view (issue 14): Musterprogramm 1 on the A/C
//! table, the view before and after block 13 (cycle 232 mills the face tilted by 15°): the milled
//! face appears in the cut colour where the amber blank was, nothing panics, and one frame's CPU
//! time with the whole stock is printed.
#![cfg(target_arch = "wasm32")]

use schwenkbar_app::document::Document;
use schwenkbar_app::run::SimRef;
use schwenkbar_app::scene::{Scene, StockShape, Triads};
use schwenkbar_app::stock::StockRef;
use schwenkbar_core::machine::Machine;
use schwenkbar_web::components::view3d::work_points;
use schwenkbar_web::render::camera::Camera;
use schwenkbar_web::render::from_sim::scene_state;
use schwenkbar_web::render::renderer::Renderer;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{console_log, wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{HtmlCanvasElement, WebGl2RenderingContext as Gl};

wasm_bindgen_test_configure!(run_in_browser);

const NO_TRIADS: Triads = Triads { mcs: false, wcs: false, wpl: false, tcs: false };

fn canvas(w: u32, h: u32) -> HtmlCanvasElement {
    let d = web_sys::window().and_then(|w| w.document()).expect("document");
    let c: HtmlCanvasElement = d.create_element("canvas").expect("canvas").dyn_into().expect("a canvas");
    c.set_attribute("style", &format!("width:{w}px;height:{h}px;display:block")).expect("style");
    d.body().expect("body").append_child(&c).expect("append");
    c
}

/// Pixels of the cut colour (light steel blue, lit) and of the blank's amber.
fn count(gl: &Gl) -> (usize, usize) {
    let (w, h) = (gl.drawing_buffer_width(), gl.drawing_buffer_height());
    let mut buf = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels_with_opt_u8_array(0, 0, w, h, Gl::RGBA, Gl::UNSIGNED_BYTE, Some(&mut buf))
        .expect("readPixels");
    let (mut cut, mut blank) = (0, 0);
    for p in buf.chunks_exact(4) {
        let [r, g, b] = [p[0], p[1], p[2]].map(i32::from);
        if b > 90 && b > r + 10 && g > r {
            cut += 1;
        }
        if r > 110 && r > g + 25 && g > b + 25 && b < r / 2 {
            blank += 1;
        }
    }
    (cut, blank)
}

#[wasm_bindgen_test]
async fn the_stock_is_drawn_and_block_13_shows_the_milled_face_in_the_cut_colour() {
    let doc = Document::new(schwenkbar_app::samples::MUSTERPROGRAMM_1.text.to_owned());
    let machine = Machine::builtin("ac-table").expect("machine");
    let sim = SimRef::of(&doc.program, &machine);
    let perf = web_sys::window().and_then(|w| w.performance()).expect("performance");
    let t0 = perf.now();
    let stock = StockRef::of(&sim, &doc.program);
    let cut_ms = perf.now() - t0;
    let block = doc.program.blocks.iter().position(|b| b.number == Some(13)).expect("block 13");
    let after = sim.0.step_of_block(block).expect("executed");
    let c = canvas(640, 480);
    let mut r = Renderer::new(&c).expect("WebGL2");
    let mut camera = Camera::default();
    let mut shot = |step: usize, camera: &mut Camera, frame: bool| {
        let st = sim.0.state_at(&doc.program, step).expect("state");
        let mut s = scene_state(&machine, &st);
        s.ghost = None;
        let t0 = perf.now();
        s.stock = stock.mesh_at(step, 1.0).map(StockShape);
        let mesh_ms = perf.now() - t0;
        if frame {
            camera.frame(&work_points(&machine, &s), 640.0 / 480.0, 1.35);
        }
        let t0 = perf.now();
        r.paint(&Scene { machine: &machine, state: &s, triads: NO_TRIADS }, camera).expect("paint");
        let paint_ms = perf.now() - t0;
        let t0 = perf.now();
        r.paint(&Scene { machine: &machine, state: &s, triads: NO_TRIADS }, camera).expect("paint");
        (count(r.gl()), mesh_ms, paint_ms, perf.now() - t0)
    };
    let ((cut_before, blank_before), ..) = shot(after - 1, &mut camera, true);
    let ((cut_after, blank_after), mesh_ms, upload_ms, frame_ms) = shot(after, &mut camera, false);
    console_log!(
        "BENCH stock in wasm: Musterprogramm 1 cut {cut_ms:.0} ms; block 13's stock meshed {mesh_ms:.0} ms, first paint with upload {upload_ms:.1} ms, next frame {frame_ms:.2} ms (640x480)"
    );
    console_log!("amber {blank_before} → {blank_after}, cut colour {cut_before} → {cut_after}");
    assert!(blank_before > 1000, "the raw blank is drawn in amber before block 13: {blank_before}");
    assert!(
        cut_after > cut_before + 500,
        "the milled face is drawn in the cut colour after block 13: {cut_before} → {cut_after}"
    );
    assert!(
        blank_after + 500 < blank_before,
        "where the face is milled, amber gives way: {blank_before} → {blank_after}"
    );
    c.remove();
}
