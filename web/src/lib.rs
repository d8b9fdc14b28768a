//! Schwenkbar's browser shell: a thin Yew UI over `schwenkbar-core`.
//! State lives in one reducer ([`state::AppState`]); components only render.

pub mod app;
pub mod components;
pub mod i18n;
pub mod render;
pub mod softkeys;
pub mod state;

pub use app::App;

/// Mounts the app on the document body (the trunk entry point). A URL fragment naming a 3D
/// preview page (`#3d:…`, `#rechte-hand`; see `components::preview`) mounts that page instead.
pub fn start() {
    let fragment = web_sys::window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
    let fragment = fragment.trim_start_matches('#');
    if components::preview::is_preview(fragment) {
        let props = components::preview::PreviewProps { fragment: fragment.to_string().into() };
        yew::Renderer::<components::preview::Preview>::with_props(props).render();
    } else {
        yew::Renderer::<App>::new().render();
    }
}
