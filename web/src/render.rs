//! The 3D view's renderer: WebGL2 through web-sys, meshes built in code, no engine.
//!
//! Pure parts (camera, poses, draw lists, the right-hand demo's maths) are tested natively; the
//! GL parts (`gpu`, `renderer`, `context`) are tested in headless Chromium (tests/browser_render.rs).
//!
//! Feeding the view from the simulator (`components::view3d::View3d` takes `machine`, `state`,
//! `toolpath`; every prop has a default):
//! ```text
//! let sim = schwenkbar_app::run::SimRef::of(&program, &machine).0;  // app simulates
//! let run = from_sim::toolpath(&sim, &program);                  // once per run
//! let st = sim.state_at(&program, step)?;                         // the block shown
//! let mut state = from_sim::scene_state(&machine, &st);           // or, while animating a
//! // segment: from_sim::scene_during(&machine, &st, &st.segments[k], fraction)
//! state.toolpath_drawn = run.segments_after.get(step).copied();
//! html! { <View3d lang={l} machine={Some(machine_rc)} state={Some(Rc::new(state))}
//!                 toolpath={SharedPath(run.points.into())} /> }
//! ```
//! Keep the `Rc<[PathPoint]>` of a run and pass the same one again: the view compares it by
//! pointer and uploads a new path only when it changes.

pub mod camera;
pub mod draw_list;
pub mod from_sim;
pub mod machine_parts;
pub mod mesh;
pub mod right_hand;
pub mod stock;
pub mod toolpath;
pub mod triads;

pub mod context;
pub mod gpu;
pub mod renderer;
