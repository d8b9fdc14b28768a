//! Small presentational components: each gets data and callbacks as props.

pub mod course;
pub mod dialog_area;
pub mod exercise_card;
pub mod gl_canvas;
pub mod header;
pub mod machine_editor;
pub mod position;
pub mod positioning;
pub mod program_pane;
pub mod right_hand_demo;
pub mod scene_pane;
pub mod softkey_row;
pub mod solve_lab;
pub mod tool_table;
pub mod view3d;
pub mod viewer;
pub mod why_panel;
