//! Generated sample programs for benchmarks and tests.

use std::fmt::Write as _;

/// A CAM-style 5-axis finishing program with `blocks` blocks in total (at least the frame),
/// about 40 bytes per block: a frame, a tool call, `PLANE SPATIAL … STAY SEQ- TABLE ROT` with
/// the rotary axes positioned from Q120/Q122 (as hyperMILL writes it, DOMAIN.md §9.4), then
/// straight lines `L X… Y… Z… F…` along a deterministic zig-zag, with a tilt change every 5000
/// blocks. Deterministic (no randomness), so benchmark inputs are the same on every machine;
/// the parser reads it without any diagnostic.
///
/// The parser and simulator benchmarks share it (`core/examples/bench_parse.rs`).
#[must_use]
pub fn cam_program(blocks: usize) -> String {
    let mut out = String::with_capacity(blocks.saturating_mul(42) + 256);
    let mut n = 0usize;
    let mut push = |out: &mut String, line: std::fmt::Arguments<'_>| {
        let _ = writeln!(out, "{n} {line}");
        n += 1;
    };
    push(&mut out, format_args!("BEGIN PGM CAM5X MM"));
    push(&mut out, format_args!("BLK FORM 0.1 Z X-50 Y-50 Z-40"));
    push(&mut out, format_args!("BLK FORM 0.2 X+50 Y+50 Z+0"));
    push(&mut out, format_args!("TOOL CALL 12 Z S12000 F2500"));
    let body = blocks.saturating_sub(5);
    let mut k = 0usize;
    while k < body {
        if k % 5000 == 0 && k + 3 <= body {
            let spa = (k / 5000 % 7) as f64 * 7.5 - 22.5;
            // Out of the material before the table turns, as a CAM post writes it (turning
            // with the tool in the part is the collision the material check reports).
            push(&mut out, format_args!("L Z+50 R0 FMAX M3"));
            push(&mut out, format_args!("PLANE SPATIAL SPA{spa:+} SPB+0 SPC+90 STAY SEQ- TABLE ROT"));
            push(&mut out, format_args!("L A+Q120 C+Q122 R0 FMAX M126"));
            k += 3;
            continue;
        }
        // A zig-zag over the part with 4 decimals, like CAM output.
        let x = ((k * 37) % 100_000) as f64 / 1000.0 - 50.0;
        let y = ((k * 11) % 100_000) as f64 / 1000.0 - 50.0;
        let z = -(((k * 7) % 20_000) as f64) / 1000.0;
        push(&mut out, format_args!("L X{x:+.4} Y{y:+.4} Z{z:+.4} F2500"));
        k += 1;
    }
    if blocks > 4 {
        push(&mut out, format_args!("END PGM CAM5X MM"));
    }
    out
}
