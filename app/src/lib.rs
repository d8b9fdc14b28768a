//! Schwenkbar's behaviour with no browser in it: the trainer's state ([`state::AppState`]) and
//! the course's ([`course::state::CourseState`]), each one pure transition
//! `apply(&self, action) -> (Self, Vec<Effect>)` that asks for its side effects as data; the
//! PLANE dialog, softkey rows and keymaps as data, the why panel's content, the 3D view's state
//! as data (`scene`) and the saved-state codecs. `schwenkbar-web` renders it and carries the
//! effects out; everything here runs and is tested natively.

pub mod course;
pub mod dialog;
pub mod document;
pub mod editor;
pub mod effect;
pub mod i18n;
pub mod keymap;
pub mod persist;
pub mod preview;
pub mod right_hand;
pub mod run;
pub mod samples;
pub mod saved_machines;
pub mod scene;
pub mod softkeys;
pub mod state;
pub mod stock;
pub mod syntax;
pub mod tool_table;
pub mod why;
