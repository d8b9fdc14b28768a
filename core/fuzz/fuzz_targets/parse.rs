//! Fuzzes `parse` (must never panic, diagnostics must point into the input) and the formatter
//! (formatting what was read is stable). Input bytes are decoded like the CLI does: UTF-8, or
//! Latin-1 when not valid UTF-8.
#![no_main]

use libfuzzer_sys::fuzz_target;
use schwenkbar_core::{format_program, parse};

fuzz_target!(|data: &[u8]| {
    let src = match std::str::from_utf8(data) {
        Ok(s) => s.to_owned(),
        Err(_) => data.iter().map(|&b| char::from(b)).collect(),
    };
    let (program, diags) = parse(&src);
    for d in &diags {
        assert!(d.span.start <= d.span.end && d.span.end <= src.len());
        assert!(d.line >= 1 && d.column >= 1);
    }
    let once = format_program(&program);
    assert_eq!(format_program(&parse(&once).0), once);
});
