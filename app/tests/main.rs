//! The app's integration tests, one binary (each file a module): the app is linked once.

mod collision_view;
mod edit_properties;
mod machine_editor;
