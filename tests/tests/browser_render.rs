//! Headless-Chromium tests of the 3D renderer on a real WebGL2 context (SwiftShader): pixels
//! where they must be, the direction a PLANE turn moves the picture, the colliding pair of a
//! stopped run in red, context loss and restore, the right-hand demo's block, and the
//! frame-time budget.
#![cfg(target_arch = "wasm32")]

use std::cell::Cell;
use std::rc::Rc;
use std::time::Duration;

use glam::{DVec3, Vec3};
use schwenkbar_app::effect::Reducer;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::scene::{Scene, SceneState, Triads};
use schwenkbar_app::state::{Action, AppState};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation::spatial;
use schwenkbar_core::plane::RotaryAxis;
use schwenkbar_core::sim::collision::{Obb, Placed};
use schwenkbar_core::solve::{SolveOptions, solve};
use schwenkbar_tests::browser::{settle, settled_attribute, wait_attribute};
use schwenkbar_web::components::right_hand_demo::{RightHandDemo, RightHandDemoProps};
use schwenkbar_web::components::scene_pane::scene_at;
use schwenkbar_web::components::view3d::{View3d, View3dProps};
use schwenkbar_web::render::camera::{Camera, Preset, project_to_css};
use schwenkbar_web::render::context::ContextWatch;
use schwenkbar_web::render::gpu::RenderError;
use schwenkbar_web::render::renderer::{Renderer, renderer_name, software_renderer};
use schwenkbar_web::render::toolpath::PathPoint;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{console_log, wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{Element, HtmlCanvasElement, WebGl2RenderingContext as Gl, WebglLoseContext};

wasm_bindgen_test_configure!(run_in_browser);

const NO_TRIADS: Triads = Triads { mcs: false, wcs: false, wpl: false, tcs: false };

fn document() -> web_sys::Document {
    web_sys::window().and_then(|w| w.document()).expect("a browser document")
}

/// A canvas of `w × h` CSS pixels in the page.
fn canvas(w: u32, h: u32) -> HtmlCanvasElement {
    let c: HtmlCanvasElement =
        document().create_element("canvas").expect("canvas").dyn_into().expect("a canvas");
    c.set_attribute("style", &format!("width:{w}px;height:{h}px;display:block")).expect("style");
    document().body().expect("body").append_child(&c).expect("append");
    c
}

async fn sleep(ms: u64) {
    yew::platform::time::sleep(Duration::from_millis(ms)).await;
}

/// The whole drawing buffer, rows bottom-up (GL order), RGBA.
fn pixels(gl: &Gl) -> (Vec<u8>, i32, i32) {
    let (w, h) = (gl.drawing_buffer_width(), gl.drawing_buffer_height());
    let mut buf = vec![0u8; (w * h * 4) as usize];
    gl.read_pixels_with_opt_u8_array(0, 0, w, h, Gl::RGBA, Gl::UNSIGNED_BYTE, Some(&mut buf))
        .expect("readPixels");
    (buf, w, h)
}

fn at(buf: &[u8], w: i32, x: i32, y_from_top: i32, h: i32) -> [u8; 3] {
    let i = (((h - 1 - y_from_top) * w + x) * 4) as usize;
    [buf[i], buf[i + 1], buf[i + 2]]
}

/// The blank's amber, lit: red dominates, blue is low (no machine part has this hue).
fn is_blank(c: [u8; 3]) -> bool {
    let [r, g, b] = c.map(i32::from);
    r > 110 && r > g + 25 && g > b + 25 && b < r / 2
}

/// Centroid (x right, y down, CSS pixels) of the pixels that pass `pick`, and their count.
fn centroid(buf: &[u8], w: i32, h: i32, pick: impl Fn([u8; 3]) -> bool) -> Option<(f32, f32, usize)> {
    let (mut sx, mut sy, mut n) = (0.0f64, 0.0f64, 0usize);
    for y in 0..h {
        for x in 0..w {
            if pick(at(buf, w, x, y, h)) {
                sx += f64::from(x);
                sy += f64::from(y);
                n += 1;
            }
        }
    }
    (n > 20).then(|| ((sx / n as f64) as f32, (sy / n as f64) as f32, n))
}

fn red(c: [u8; 3]) -> bool {
    c[0] > 150 && c[1] < 90 && c[2] < 90
}

fn green(c: [u8; 3]) -> bool {
    c[1] > 130 && c[0] < 110 && c[2] < 120
}

fn ac_table() -> Machine {
    Machine::builtin("ac-table").expect("ac-table ships")
}

#[wasm_bindgen_test]
async fn the_renderer_draws_the_blank_where_the_camera_looks() {
    let c = canvas(400, 300);
    let mut r = Renderer::new(&c).expect("WebGL2 in headless Chromium");
    let m = ac_table();
    let state = SceneState::default();
    // The default camera looks at the blank's centre (M-CS 0, 0, −20 with the centred preset).
    let labels =
        r.paint(&Scene { machine: &m, state: &state, triads: NO_TRIADS }, &Camera::default()).expect("paint");
    assert!(labels.is_empty(), "no triads, no labels");
    let (buf, w, h) = pixels(r.gl());
    let centre = at(&buf, w, w / 2, h / 2, h);
    assert!(is_blank(centre), "blank colour at the centre, got {centre:?}");
    let corner = at(&buf, w, 2, 2, h);
    assert!(!is_blank(corner), "background in the corner, got {corner:?}");
    c.remove();
}

/// Multisampling only where a GPU draws: on a CPU rasteriser (headless Chromium's SwiftShader,
/// a classroom PC without a usable GPU) it made every frame's paint the slowest part of a step.
#[wasm_bindgen_test]
fn multisampling_is_asked_for_only_when_a_gpu_draws() {
    let c = canvas(50, 50);
    let r = Renderer::new(&c).expect("WebGL2 in headless Chromium");
    let name = renderer_name(r.gl());
    let attributes = js_sys::Reflect::get(r.gl(), &"getContextAttributes".into())
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
        .and_then(|f| f.call0(r.gl()).ok())
        .expect("context attributes");
    let antialias = js_sys::Reflect::get(&attributes, &"antialias".into()).ok().and_then(|v| v.as_bool());
    assert_eq!(antialias, Some(!software_renderer(&name)), "renderer {name:?}");
    c.remove();
}

#[wasm_bindgen_test]
fn a_canvas_without_webgl2_gives_an_error_not_a_panic() {
    // A canvas that already has a 2D context cannot give WebGL2: the same answer as a browser
    // without WebGL2.
    let c = canvas(50, 50);
    assert!(c.get_context("2d").expect("getContext").is_some());
    assert_eq!(Renderer::new(&c).err(), Some(RenderError::NoWebGl2));
    c.remove();
}

#[wasm_bindgen_test]
async fn plane_spatial_spb45_on_the_ac_table_turns_the_workpiece_x_axis_towards_the_operator() {
    let m = ac_table();
    // Solve with core, as the control does (DOMAIN.md §10 oracle 13).
    let e = solve(&m, &spatial(0.0, 45.0, 0.0), &SolveOptions::default());
    let axes = e.chosen_axes().expect("a solution");
    assert_eq!((axes.a, axes.c), (Some(45.0), Some(90.0)), "A+45 C+90 from A0 C0");

    let c = canvas(400, 400);
    let mut r = Renderer::new(&c).expect("WebGL2");
    let mut cam = Camera { target: Vec3::new(0.0, 0.0, 0.0), distance: 900.0, ..Camera::default() };
    cam.set_preset(Preset::Top);
    let only_wcs = Triads { wcs: true, ..NO_TRIADS };
    let mut state = SceneState::default();

    r.paint(&Scene { machine: &m, state: &state, triads: only_wcs }, &cam).expect("paint home");
    let (buf, w, h) = pixels(r.gl());
    let (rx0, ry0, _) = centroid(&buf, w, h, red).expect("W-CS X arrow visible at home");
    let (gx0, gy0, _) = centroid(&buf, w, h, green).expect("W-CS Y arrow visible at home");
    // Top view, X right, Y up: at home the X arrow lies right of and below the Y arrow.
    assert!(rx0 > gx0 + 15.0 && ry0 > gy0 + 15.0, "home: X ({rx0},{ry0}) vs Y ({gx0},{gy0})");

    state.axes.rotary = axes;
    state.wpl.rot = spatial(0.0, 45.0, 0.0);
    r.paint(&Scene { machine: &m, state: &state, triads: only_wcs }, &cam).expect("paint tilted");
    let (buf, w, h) = pixels(r.gl());
    let (rx1, ry1, _) = centroid(&buf, w, h, red).expect("X arrow after the turn");
    let (gx1, gy1, _) = centroid(&buf, w, h, green).expect("Y arrow after the turn");
    // A+45 C+90 turns the workpiece so that its +X points towards the operator (−Y, screen
    // down) and rises, and its +Y points along machine +X (screen right): X is now left of and
    // below Y. The tool tilted towards +X relative to the workpiece, as positive SPB must.
    assert!(rx1 + 15.0 < gx1, "tilted: X ({rx1},{ry1}) left of Y ({gx1},{gy1})");
    assert!(ry1 > gy1 + 15.0, "tilted: X below Y on screen (towards the operator)");
    c.remove();
}

#[wasm_bindgen_test]
async fn context_loss_and_restore_leave_a_working_view() {
    let c = canvas(300, 200);
    let renderer = Rc::new(std::cell::RefCell::new(Renderer::new(&c).expect("WebGL2")));
    let (lost, restored) = (Rc::new(Cell::new(false)), Rc::new(Cell::new(false)));
    let (l2, r2, rr) = (lost.clone(), restored.clone(), renderer.clone());
    let _watch = ContextWatch::new(
        &c,
        move || l2.set(true),
        move || {
            r2.set(rr.borrow_mut().restore().is_ok());
        },
    );
    let m = ac_table();
    let state = SceneState::default();
    let scene = Scene { machine: &m, state: &state, triads: NO_TRIADS };
    renderer.borrow_mut().paint(&scene, &Camera::default()).expect("first frame");

    let gl = renderer.borrow().gl().clone();
    let ext: WebglLoseContext = gl
        .get_extension("WEBGL_lose_context")
        .expect("getExtension")
        .expect("WEBGL_lose_context in Chromium")
        .unchecked_into();
    ext.lose_context();
    for _ in 0..50 {
        if lost.get() {
            break;
        }
        sleep(20).await;
    }
    assert!(lost.get(), "webglcontextlost fired");
    renderer.borrow_mut().lost();
    assert_eq!(renderer.borrow_mut().paint(&scene, &Camera::default()), Err(RenderError::ContextLost));

    ext.restore_context();
    for _ in 0..50 {
        if restored.get() {
            break;
        }
        sleep(20).await;
    }
    assert!(restored.get(), "webglcontextrestored fired and the GL objects were rebuilt");
    renderer.borrow_mut().paint(&scene, &Camera::default()).expect("a frame after the restore");
    let (buf, w, h) = pixels(&gl);
    assert!(is_blank(at(&buf, w, w / 2, h / 2, h)), "the blank is back");
    c.remove();
}

#[wasm_bindgen_test]
async fn every_shipped_machine_renders_and_the_ghost_shows_the_other_candidate() {
    let c = canvas(320, 240);
    let mut r = Renderer::new(&c).expect("WebGL2");
    for id in Machine::builtin_ids() {
        let m = Machine::builtin(id).expect("shipped machine");
        let e = solve(&m, &spatial(0.0, 30.0, 0.0), &SolveOptions::default());
        let mut state = SceneState::default();
        state.axes.rotary = e.chosen_axes().unwrap_or_default();
        state.ghost = e.candidates.iter().find(|c| Some(c.axes) != e.chosen_axes()).map(|c| c.axes);
        let labels = r
            .paint(&Scene { machine: &m, state: &state, triads: Triads::default() }, &Camera::default())
            .unwrap_or_else(|err| panic!("{id}: {err}"));
        assert!(labels.iter().any(|l| l.text == "WPL-CS"), "{id}: labels");
        let (buf, w, h) = pixels(r.gl());
        let drawn = buf.chunks_exact(4).filter(|p| p[0] > 60 || p[1] > 60).count();
        assert!(drawn > (w * h) as usize / 20, "{id}: the machine fills part of the view");
    }
    c.remove();
}

/// The contact's translucent red over whatever it covers: red more than twice green and blue.
/// No machine part, the blank's amber, the ghost or the background passes (the X triad would:
/// these frames have none).
fn contact_red(c: [u8; 3]) -> bool {
    let [r, g, b] = c.map(i32::from);
    r > 90 && r > 2 * g && r > 2 * b
}

/// The corners of a placed collision body's box (a cylinder's bounding box), M-CS.
fn corners_of(p: &Placed) -> [Vec3; 8] {
    let o: &Obb = match p {
        Placed::Box(o) | Placed::Cylinder { bound: o, .. } => o,
    };
    std::array::from_fn(|i| {
        let s = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
        (o.center + o.axes * (o.half * DVec3::new(s(1), s(2), s(4)))).as_vec3()
    })
}

/// The trainer on `ac-table` run until it stops on the shared collision scene
/// ([`schwenkbar_testkit::collision`]).
fn run_into_a_collision() -> AppState {
    let text = schwenkbar_testkit::collision::program(schwenkbar_testkit::collision::SEQ_MINUS_SWIVEL);
    let then = |s: &AppState, a: Action| s.apply(a).0;
    let mut s = then(&AppState::default(), Action::SelectMachine("ac-table".into()));
    s = then(&s, Action::SetText(text));
    s = then(&then(&s, Action::StartRun), Action::RunPlay);
    for _ in 0..20 {
        let step = s.run.as_ref().map_or(0, |r| r.step);
        s = then(&s, Action::RunTick(step));
    }
    s
}

#[wasm_bindgen_test]
async fn a_run_stopped_by_a_collision_draws_the_colliding_pair_red_and_only_there() {
    let s = run_into_a_collision();
    let c = s.shown_collision().expect("the run stopped on a collision").clone();
    let m = s.machine.clone().expect("machine");
    let before = s.shown_state().expect("the last finished step");
    // The scene as the scene pane builds it for a stopped run.
    let mut with = scene_at(&m, &before, 1.0);
    with.at_collision(&m, &before, &c);
    let pair = with.contact.expect("the pair is placed");
    let without = SceneState { contact: None, ..with.clone() };

    // The camera framed on the pair, the default (iso) direction.
    let (cw, ch) = (400.0f32, 300.0f32);
    let cv = canvas(cw as u32, ch as u32);
    let mut r = Renderer::new(&cv).expect("WebGL2");
    let points: Vec<Vec3> = pair.iter().flat_map(corners_of).collect();
    let mut cam = Camera::default();
    cam.frame(&points, cw / ch, 1.4);

    r.paint(&Scene { machine: &m, state: &without, triads: NO_TRIADS }, &cam).expect("paint without");
    let (plain, w, h) = pixels(r.gl());
    r.paint(&Scene { machine: &m, state: &with, triads: NO_TRIADS }, &cam).expect("paint with");
    let (marked, w2, h2) = pixels(r.gl());
    assert_eq!((w, h), (w2, h2));
    let count = |buf: &[u8]| {
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .filter(|&(x, y)| contact_red(at(buf, w, x, y, h)))
            .count()
    };
    let (n_plain, n_marked) = (count(&plain), count(&marked));
    console_log!(
        "contact {} – {}: red pixels {n_plain} without, {n_marked} with the contact",
        c.a.en,
        c.b.en
    );
    assert_eq!(n_plain, 0, "nothing else in the frame is contact red");
    assert!(n_marked >= 100, "the pair is drawn red: {n_marked} pixels of {}", w * h);
    // Both bodies show, even where they lie inside a drawn part (the C table's body, r 50, in the
    // drawn table, r ≥ 80; the tool's body in the tool's own cylinder): red round the projected
    // centre of each.
    let (sx, sy) = (w as f32 / cw, h as f32 / ch);
    let vp = cam.view_proj(cw / ch);
    for (body, name) in pair.iter().zip([&c.a.en, &c.b.en]) {
        let corners = corners_of(body);
        let centre = corners.iter().copied().sum::<Vec3>() / corners.len() as f32;
        let (x, y) = project_to_css(&vp, centre, cw, ch).expect("in front of the eye");
        let (px, py) = ((x * sx) as i32, (y * sy) as i32);
        let red_near = (-2..=2)
            .flat_map(|dy| (-2..=2).map(move |dx| (px + dx, py + dy)))
            .filter(|&(x, y)| contact_red(at(&marked, w, x, y, h)))
            .count();
        assert!(red_near >= 20, "{name} is red at its centre ({px}, {py}): {red_near} of 25 pixels");
    }

    // Where the red is: on the screen rectangles of the pair's bodies (their projected bounding
    // boxes, 4 px of slack), nowhere else.
    let rects: Vec<[f32; 4]> = pair
        .iter()
        .map(|body| {
            corners_of(body).iter().fold([f32::MAX, f32::MAX, f32::MIN, f32::MIN], |r, p| {
                let (x, y) = project_to_css(&vp, *p, cw, ch).expect("in front of the eye");
                [
                    r[0].min(x * sx - 4.0),
                    r[1].min(y * sy - 4.0),
                    r[2].max(x * sx + 4.0),
                    r[3].max(y * sy + 4.0),
                ]
            })
        })
        .collect();
    let inside = |r: &[f32; 4], x: i32, y: i32| {
        (r[0]..=r[2]).contains(&(x as f32)) && (r[1]..=r[3]).contains(&(y as f32))
    };
    let stray = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| contact_red(at(&marked, w, x, y, h)) && !rects.iter().any(|r| inside(r, x, y)))
        .count();
    assert_eq!(stray, 0, "red outside the pair's screen rectangles {rects:?}");
    cv.remove();
}

#[wasm_bindgen_test]
async fn the_3d_view_component_paints_labels_and_the_right_hand_demo_writes_the_block() {
    let root = mount_view(800, 500, Lang::De).await;
    let canvas = query(&root, "canvas.view3d");
    assert_eq!(canvas.get_attribute("data-webgl").as_deref(), Some("ready"));
    // Labels follow the first painted frame.
    let mut labels: Vec<String> = Vec::new();
    for _ in 0..200 {
        labels = (0..root.query_selector_all(".gl-labels .lbl").expect("selector").length())
            .filter_map(|i| root.query_selector_all(".gl-labels .lbl").ok()?.item(i)?.text_content())
            .collect();
        if ["M-CS", "W-CS", "WPL-CS", "T-CS"].iter().all(|n| labels.iter().any(|l| l == n)) {
            break;
        }
        sleep(25).await;
    }
    for name in ["M-CS", "W-CS", "WPL-CS", "T-CS"] {
        assert!(labels.iter().any(|l| l == name), "label {name} in {labels:?}");
    }
    root.remove();

    let demo = mount_demo().await;
    assert_eq!(
        query(&demo, ".rh-block").text_content().as_deref(),
        Some("PLANE SPATIAL SPA+0 SPB+15 SPC+0"),
        "a +15° turn about Y"
    );
    assert_eq!(query(&demo, ".rh-angle").text_content().as_deref(), Some("SPB+15°"));
    demo.remove();
}

#[wasm_bindgen_test]
async fn the_3d_view_component_survives_a_context_loss() {
    let root = mount_view(400, 300, Lang::En).await;
    let canvas: HtmlCanvasElement = query(&root, "canvas.view3d").dyn_into().expect("canvas");
    assert_eq!(canvas.get_attribute("data-webgl").as_deref(), Some("ready"));
    let gl: Gl = canvas.get_context("webgl2").expect("context").expect("the view's context").unchecked_into();
    let ext: WebglLoseContext =
        gl.get_extension("WEBGL_lose_context").expect("getExtension").expect("extension").unchecked_into();
    ext.lose_context();
    assert_eq!(wait_attribute(&canvas, "data-webgl", "lost", 5_000).await.as_deref(), Some("lost"));
    ext.restore_context();
    assert_eq!(
        wait_attribute(&canvas, "data-webgl", "ready", 10_000).await.as_deref(),
        Some("ready"),
        "restored and painting"
    );
    assert!(root.query_selector(".no-webgl").expect("selector").is_none(), "no failure message");
    root.remove();
}

#[wasm_bindgen_test]
async fn try_it_asks_for_a_signed_turn_and_tells_a_wrong_sign() {
    let demo = mount_demo().await;
    click(&demo, ".rh-start").await;
    assert_eq!(query(&demo, ".rh-task").text_content().as_deref(), Some("Drehen Sie die Ebene um +30° um Y"));
    set_slider(&demo, "-30").await;
    // The signed angle and the block would give the sign away: hidden until "Prüfen".
    assert!(demo.query_selector(".rh-block").expect("selector").is_none(), "no block before the check");
    assert_eq!(query(&demo, ".rh-angle").get_attribute("data-hidden").as_deref(), Some("true"));
    assert!(!query(&demo, ".rh-angle").text_content().unwrap_or_default().contains("30"));
    click(&demo, ".rh-check").await;
    assert_eq!(query(&demo, ".rh-block").text_content().as_deref(), Some("PLANE SPATIAL SPA+0 SPB-30 SPC+0"));
    assert!(query(&demo, ".rh-verdict").class_name().contains("wrong-sign"), "−30 for +30 is the wrong sign");
    set_slider(&demo, "30").await;
    click(&demo, ".rh-check").await;
    assert!(query(&demo, ".rh-verdict").class_name().contains("right"));
    demo.remove();
}

async fn click(root: &Element, selector: &str) {
    query(root, selector).dyn_into::<web_sys::HtmlElement>().expect("an HTML element").click();
    settle().await;
}

async fn set_slider(root: &Element, value: &str) {
    let input: web_sys::HtmlInputElement = query(root, ".rh-slider input").dyn_into().expect("range input");
    input.set_value(value);
    // Bubbling, as a real input event does (yew listens at the root).
    let init = web_sys::EventInit::new();
    init.set_bubbles(true);
    let ev = web_sys::Event::new_with_event_init_dict("input", &init).expect("input event");
    input.dispatch_event(&ev).expect("dispatch");
    settle().await;
}

/// A fresh element of `style` in the page.
fn host(style: &str) -> Element {
    let root = document().create_element("div").expect("div");
    root.set_attribute("style", style).expect("style");
    document().body().expect("body").append_child(&root).expect("append");
    root
}

/// Mounts the 3D view (the default machine before a program runs) into a new `w × h` element.
async fn mount_view(w: u32, h: u32, lang: Lang) -> Element {
    let root = host(&format!("width:{w}px;height:{h}px;position:relative"));
    let props = View3dProps {
        lang,
        machine: None,
        state: None,
        toolpath: Default::default(),
        in_run: false,
        typing: false,
    };
    yew::Renderer::<View3d>::with_root_and_props(root.clone(), props).render();
    settle().await;
    // WebGL start-up (software rendering) can take a while on a loaded machine.
    settled_attribute(&root, "canvas.view3d", "data-webgl", 10_000).await;
    root
}

/// Mounts the right-hand demo (German) into a new element.
async fn mount_demo() -> Element {
    let root = host("width:900px;height:500px");
    yew::Renderer::<RightHandDemo>::with_root_and_props(
        root.clone(),
        RightHandDemoProps { lang: Lang::De, block: None },
    )
    .render();
    settle().await;
    root
}

fn query(root: &Element, selector: &str) -> Element {
    root.query_selector(selector).expect("selector").unwrap_or_else(|| panic!("no {selector}"))
}

/// CPU time per frame with the machine and a 100,000-segment toolpath at 1920 × 1080 (budget:
/// 2 ms median, issue 7). GL calls are queued by the browser, so this is the wasm + JS side. A
/// benchmark: it prints the figure (scripts/bench.sh shows it) and checks only that every frame
/// painted.
#[wasm_bindgen_test]
async fn frame_time_with_a_100000_segment_toolpath() {
    let c = canvas(1920, 1080);
    let mut r = Renderer::new(&c).expect("WebGL2");
    let path: Vec<PathPoint> = (0..=100_000)
        .map(|i| {
            let t = f64::from(i) * 0.01;
            PathPoint {
                at: DVec3::new(50.0 + 45.0 * t.cos(), 50.0 + 45.0 * t.sin(), -(t * 0.03)),
                rapid: i % 50 == 0,
            }
        })
        .collect();
    r.set_toolpath(&path).expect("upload once");
    let m = ac_table();
    let mut state = SceneState::default();
    state.axes.rotary = AxisValues::default().with(RotaryAxis::A, 30.0).with(RotaryAxis::C, 45.0);
    state.ghost = Some(AxisValues::default().with(RotaryAxis::A, -30.0).with(RotaryAxis::C, -135.0));
    let perf = web_sys::window().and_then(|w| w.performance()).expect("performance");
    let mut cam = Camera::default();
    let mut times = Vec::with_capacity(100);
    for i in 0..110 {
        cam.orbit(1.0, 0.0);
        state.axes.linear.x = f64::from(i);
        let t0 = perf.now();
        r.paint(&Scene { machine: &m, state: &state, triads: Triads::default() }, &cam).expect("paint");
        let dt = perf.now() - t0;
        if i >= 10 {
            times.push(dt);
        }
        // Let the GPU process catch up between frames, as requestAnimationFrame would.
        if i % 10 == 0 {
            sleep(1).await;
        }
    }
    times.sort_by(f64::total_cmp);
    let median = times[times.len() / 2];
    console_log!(
        "BENCH paint CPU time at 1920x1080 with 100,000 segments: median {median:.3} ms, p90 {:.3} ms (budget 2 ms median)",
        times[times.len() * 9 / 10]
    );
    assert_eq!(times.len(), 100, "every frame painted");
    c.remove();
}
