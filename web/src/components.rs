//! Small presentational components: each gets data and callbacks as props.

pub mod dialog_area;
pub mod header;
pub mod position;
pub mod program_pane;
pub mod softkey_row;
pub mod view3d;
pub mod why_panel;
