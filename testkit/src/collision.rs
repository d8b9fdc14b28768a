//! The collision scene the tests of issue 17 share: on `ac-table`, a tool 100 mm long (tool 1,
//! L80 R5, DL+20) with its tip 5 mm above the rotary table's face, beside the 100 × 100 × 40
//! blank (centred on the C axis) at M-CS Y+60, then a swivel. Tilting A− lifts the +Y side of
//! the table: its rim swings through the tool (`SPA-30 … SEQ-`, `PLANE AXIAL A-30` collide;
//! `SEQ+` lowers it and runs free; core/tests/collision.rs works the geometry by hand).

/// The blocks before the swivel (numbered from 1 by [`program`]).
pub const LOW_TOOL: [&str; 6] = [
    "BLK FORM 0.1 Z X+0 Y+0 Z-40",
    "BLK FORM 0.2 X+100 Y+100 Z+0",
    "TOOL CALL 1 Z S3000 DL+20",
    "L Z+0 R0 FMAX M91",
    "L X+50 Y+110 R0 FMAX",
    "L Z-45 R0 FMAX",
];

/// The swivel of the scene whose chosen solution collides while the other one is free.
pub const SEQ_MINUS_SWIVEL: &str = "PLANE SPATIAL SPA-30 SPB+0 SPC+0 TURN FMAX SEQ-";

/// The whole program: `BEGIN PGM T MM`, [`LOW_TOOL`], `swivel` as block 7, `END PGM T MM`.
#[must_use]
pub fn program(swivel: &str) -> String {
    let mut text = String::from("0 BEGIN PGM T MM\n");
    for (i, b) in LOW_TOOL.iter().chain([&swivel]).enumerate() {
        text.push_str(&format!("{} {b}\n", i + 1));
    }
    text.push_str("8 END PGM T MM\n");
    text
}
