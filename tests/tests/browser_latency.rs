//! Issue 6 budget, measured in the browser (a benchmark: it prints the figures and checks only
//! that the screen really followed the key): a key press to the updated screen for
//! Musterprogramm 1 and with a 100,000-block program loaded.
#![cfg(target_arch = "wasm32")]

use schwenkbar_tests::browser::{
    clear_storage, eventually, inject_app_css, key_on, median, mount, next_frame, now, paste_program, query,
    timed_key,
};
use wasm_bindgen_test::{console_log, wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

fn cursor_line(root: &web_sys::Element) -> String {
    query(root, ".program-pane .line.cursor").and_then(|l| l.get_attribute("data-line")).unwrap_or_default()
}

async fn measure(root: &web_sys::Element, presses: usize) -> f64 {
    let mut samples = Vec::with_capacity(presses);
    for _ in 0..presses {
        let before = cursor_line(root);
        samples.push(timed_key(root, "ArrowDown").await);
        // A slow machine (CI's debug build) may draw after the measured wait: the check waits.
        assert!(eventually(|| cursor_line(root) != before).await, "the cursor moved on screen");
    }
    median(samples)
}

#[wasm_bindgen_test]
async fn key_press_latency_musterprogramm_1_and_100000_blocks() {
    clear_storage();
    let root = mount().await;
    let small = measure(&root, 20).await;

    let big = schwenkbar_core::sample::cam_program(100_000);
    let t0 = now();
    paste_program(&root, &big).await;
    let load = now() - t0;
    let large = measure(&root, 20).await;
    console_log!(
        "BENCH key press → screen: Musterprogramm 1 median {small:.2} ms (budget 16); 100,000 blocks median {large:.2} ms (budget 100); pasting the 100,000-block program {load:.0} ms"
    );
    clear_storage();
}

/// Classroom trial II's figures with the stock on (Musterprogramm 1): the longest gap between two
/// animation frames while the stock is switched on and its first pass goes on (budget: no task
/// over 100 ms; it was one of 0.85 s), and a step key to the next frame (budget 50 ms median).
#[wasm_bindgen_test]
async fn the_stock_switched_on_and_a_step_with_it_musterprogramm_1() {
    clear_storage();
    inject_app_css();
    let root = mount().await;
    // The stock is on by default (issue 32): the run starts with it and cuts it.
    let t0 = now();
    key_on(&root, ".tnc", "F6").await;
    let (mut last, mut worst) = (next_frame().await, 0.0_f64);
    while now() - t0 < 4_000.0 {
        let t = next_frame().await;
        worst = worst.max(t - last);
        last = t;
    }
    assert!(query(&root, "[data-key=stock].active").is_some(), "ROHTEIL pressed");
    let mut steps = Vec::new();
    for _ in 0..20 {
        let before = cursor_line(&root);
        let t = now();
        timed_key(&root, "F2").await;
        next_frame().await;
        steps.push(now() - t);
        assert!(eventually(|| cursor_line(&root) != before).await, "the run stepped on");
    }
    console_log!(
        "BENCH stock on, Musterprogramm 1: the longest frame gap while it is switched on and cut {worst:.0} ms (budget: no task over 100 ms); step key → frame median {:.1} ms (budget 50)",
        median(steps)
    );
    clear_storage();
}

#[wasm_bindgen_test]
fn parser_throughput_in_wasm() {
    let program = schwenkbar_core::sample::cam_program(200_000);
    let mb = program.len() as f64 / 1e6;
    // V8 runs a wasm function in its baseline compiler until the optimising one has compiled it
    // in the background, and a call already running stays in the baseline code: the first parse
    // is the cold figure, the best of the later ones the steady one that native is compared with.
    let mut times = Vec::new();
    for _ in 0..8 {
        let t0 = now();
        let (parsed, diagnostics) = schwenkbar_core::parse(&program);
        times.push(now() - t0);
        assert_eq!(parsed.blocks.len(), 200_000);
        assert!(diagnostics.is_empty());
    }
    let best = times.iter().copied().fold(f64::INFINITY, f64::min);
    console_log!(
        "BENCH parser in wasm32 (Chromium): {mb:.1} MB, first parse {:.0} ms = {:.0} MB/s, best of 8 {best:.0} ms = {:.0} MB/s",
        times[0],
        mb / (times[0] / 1000.0),
        mb / (best / 1000.0)
    );
}
