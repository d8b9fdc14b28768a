//! The 3D view's renderer: WebGL2 through web-sys, meshes built in code, no engine.
//!
//! Pure parts (camera, poses, draw lists, the right-hand demo's maths) are tested natively; the
//! GL parts (`gpu`, `renderer`, `context`) are tested in headless Chromium (tests/browser_render.rs).

pub mod camera;
pub mod draw_list;
pub mod from_sim;
pub mod machine_parts;
pub mod mesh;
pub mod plane_scene;
pub mod pose;
pub mod right_hand;
pub mod scene;
pub mod toolpath;
pub mod triads;

pub mod context;
pub mod gpu;
pub mod renderer;
