//! Schwenkbar's browser shell: a thin Yew UI over `schwenkbar-core`.
//! State lives in one reducer ([`state::AppState`]); components only render.

pub mod app;
pub mod browser;
pub mod components;
pub mod course;
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

use yew::prelude::*;

use crate::components::course::CourseApp;
use crate::course::Route;

/// The page the URL fragment names: the course (`#kurs…`) or the trainer (anything else,
/// including a share link). Follows the fragment as it changes.
#[function_component(Root)]
pub fn root() -> Html {
    let fragment = use_state(|| browser::fragment().unwrap_or_default());
    {
        let fragment = fragment.clone();
        use_effect_with((), move |()| {
            let listener = browser::on_hash_change(move |f| fragment.set(f));
            move || drop(listener)
        });
    }
    match Route::parse(&fragment) {
        Some(route) => html! { <CourseApp {route} /> },
        None => html! { <App /> },
    }
}

/// Mounts the app on the document body (the trunk entry point).
pub fn start() {
    yew::Renderer::<Root>::new().render();
}
