//! Schwenkbar's browser shell: a thin Yew UI over `schwenkbar-core`.
//! State lives in one reducer ([`state::AppState`]); components only render.

pub mod app;
pub mod browser;
pub mod components;
pub mod dialog;
pub mod document;
pub mod i18n;
pub mod keymap;
pub mod persist;
pub mod preview;
pub mod render;
pub mod run;
pub mod samples;
pub mod softkeys;
pub mod state;
pub mod syntax;
pub mod why;

pub use app::App;

/// Mounts the app on the document body (the trunk entry point).
pub fn start() {
    yew::Renderer::<App>::new().render();
}
