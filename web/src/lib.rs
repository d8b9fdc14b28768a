//! Schwenkbar's browser shell: a thin Yew UI over `schwenkbar-core`.
//! State lives in one reducer ([`schwenkbar_app::state::AppState`]); components only render.

pub mod app;
pub mod browser;
pub mod components;
pub mod effects;
pub mod render;

pub use app::App;

use yew::prelude::*;

use crate::components::course::CourseApp;
use schwenkbar_app::course::Route;

/// The course page (`kurs.html`): the lesson the URL fragment names (`#kurs/3`), else the
/// overview; follows the fragment as it changes.
#[function_component(CourseRoot)]
pub fn course_root() -> Html {
    let fragment = use_state(|| browser::fragment().unwrap_or_default());
    {
        let fragment = fragment.clone();
        use_effect_with((), move |()| {
            let listener = browser::on_hash_change(move |f| fragment.set(f));
            move || drop(listener)
        });
    }
    let route = Route::parse(&fragment).unwrap_or(Route::Overview);
    html! { <CourseApp {route} /> }
}

/// Mounts the trainer on the document body (the entry point of `index.html`). The course is a
/// page of its own (`kurs.html`, [`start_course`]) so that its code and texts stay out of the
/// trainer's bundle.
pub fn start() {
    yew::Renderer::<App>::new().render();
}

/// Mounts the course on the document body (the entry point of `kurs.html`).
pub fn start_course() {
    yew::Renderer::<CourseRoot>::new().render();
}

/// Mounts the machine editor on the document body (the entry point of `maschine.html`, bin
/// `maschine`: its form, checks and JSON stay out of the trainer's bundle).
pub fn start_editor() {
    yew::Renderer::<components::machine_editor::EditorRoot>::new().render();
}
