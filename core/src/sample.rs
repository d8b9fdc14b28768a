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

/// `moves` straight moves `L X… Y… Z… F1000` to pseudo-random points inside a 200×200×50 blank
/// (tool tip 5 mm above its floor at the lowest), the collision check's worst case: every move
/// crosses the part near the table (issue 32's comparison with the peer). Deterministic
/// (xorshift64*, a fixed seed), so every machine runs the same program.
#[must_use]
pub fn moves_in_blank(moves: usize) -> String {
    let mut out = String::with_capacity(moves.saturating_mul(44) + 256);
    out.push_str(
        "0 BEGIN PGM BLANK100K MM\n1 BLK FORM 0.1 Z X-100 Y-100 Z-50\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n\
         3 TOOL CALL 1 Z S5000\n4 L Z+10 R0 FMAX M3\n",
    );
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let mut next = |lo: f64, hi: f64| {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        let r = state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
        lo + (hi - lo) * (r as f64 / (1u64 << 53) as f64)
    };
    for k in 0..moves {
        let (x, y, z) = (next(-100.0, 100.0), next(-100.0, 100.0), next(-45.0, 0.0));
        let _ = writeln!(out, "{} L X{x:+.3} Y{y:+.3} Z{z:+.3} F1000", k + 5);
    }
    let _ = writeln!(out, "{} L Z+50 R0 FMAX M30\n{} END PGM BLANK100K MM", moves + 5, moves + 6);
    out
}
