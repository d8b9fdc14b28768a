//! Program run in the browser (issue 6): the position display after block 10 of
//! Musterprogramm 1 shows what the simulator computes, and the error sample stops at the refused
//! block with the control's message; a swivel that collides (issue 17) names the free solution.
#![cfg(target_arch = "wasm32")]

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, simulate};
use schwenkbar_tests::browser::{clear_storage, click, mount, paste_program, query, text};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

fn cursor_text(root: &web_sys::Element) -> String {
    query(root, ".program-pane .line.cursor").and_then(|l| l.text_content()).unwrap_or_default()
}

#[wasm_bindgen_test]
async fn musterprogramm_1_block_10_shows_the_simulated_axes() {
    clear_storage();
    let root = mount().await;
    click(&root, "[data-key=run]").await;
    assert_eq!(text(&root, "[data-testid=mode]"), "Programmlauf Einzelsatz");
    for _ in 0..20 {
        if cursor_text(&root).starts_with("10 PLANE") {
            break;
        }
        click(&root, "[data-key=run-next]").await;
    }
    assert!(cursor_text(&root).starts_with("10 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX"));

    // The same numbers straight from the simulator.
    let (program, _) = schwenkbar_core::parse(schwenkbar_app::samples::MUSTERPROGRAMM_1.text);
    let machine = Machine::builtin("ac-table").expect("shipped");
    let sim = simulate(&program, &machine, &SimOptions::default());
    let step = sim.first_step[10].expect("block 10 runs") as usize;
    let state = sim.state_at(&program, step).expect("state");
    for (axis, value) in state.axes.named() {
        let shown = text(&root, &format!(".position tr[data-axis='{axis}'] .ref"));
        assert_eq!(shown, format!("{value:+.3}"), "axis {axis}");
    }
    assert_eq!(text(&root, ".position tr[data-axis='A'] .ref"), "+15.000");
    assert_eq!(text(&root, ".position tr[data-axis='C'] .ref"), "+90.000");
    assert!(text(&root, "[data-testid=status-line]").contains("SPB+15.000"));
}

#[wasm_bindgen_test]
async fn the_error_sample_stops_at_the_refused_block_with_the_controls_message() {
    clear_storage();
    let root = mount().await;
    click(&root, "[data-key=samples]").await;
    click(&root, "[data-key=sample-winkel_nicht_erlaubt]").await;
    assert_eq!(text(&root, "[data-testid=machine-name]"), "B-Rundtisch auf A-Schwenktisch");
    click(&root, "[data-key=run]").await;
    for _ in 0..15 {
        click(&root, "[data-key=run-next]").await;
    }
    assert_eq!(text(&root, ".dialog-line"), "Winkel nicht erlaubt");
    assert!(
        cursor_text(&root).starts_with("8 PLANE SPATIAL SPA-45 SPB+0 SPC+0 TURN FMAX SYM-"),
        "{}",
        cursor_text(&root)
    );
    assert!(text(&root, "[data-testid=why-error]").starts_with("Winkel nicht erlaubt"));
}

#[wasm_bindgen_test]
async fn a_colliding_swivel_stops_the_run_and_the_why_panel_names_the_free_solution() {
    clear_storage();
    let root = mount().await;
    // On ac-table: a long tool low beside the blank; SEQ− lifts the table's rim into it
    // (core/tests/collision.rs), SEQ+ would lower it.
    let collision = schwenkbar_testkit::collision::program(schwenkbar_testkit::collision::SEQ_MINUS_SWIVEL);
    paste_program(&root, &collision).await;
    click(&root, "[data-key=run]").await;
    for _ in 0..10 {
        click(&root, "[data-key=run-next]").await;
    }
    assert!(text(&root, ".dialog-line").starts_with("Kollision: "), "{}", text(&root, ".dialog-line"));
    let note = text(&root, "[data-testid=why-alternative]");
    assert!(note.starts_with("Die gewählte Lösung kollidiert (") && note.contains("SEQ+ (A+30"), "{note}");
    // The position display stands where the machine stopped, on the way from A+0 to A−30.
    let a = text(&root, ".position [data-axis=A] .ref");
    let a: f64 = a.parse().unwrap_or_else(|_| panic!("REF A {a:?}"));
    assert!(a < 0.0 && a > -30.0, "REF A{a}");
}

/// An INCH program (issue 30): the position display shows the program's inches, to 4 decimals,
/// with `INCH` over the axes; the tool line gives L and R in inches and F as written.
#[wasm_bindgen_test]
async fn an_inch_program_shows_inches_in_the_position_display() {
    clear_storage();
    let root = mount().await;
    let program = "0 BEGIN PGM IN INCH\n1 TOOL CALL 1 Z S3000 F100\n2 L X+1 Y+0.5 Z+2 R0 F200\n\
                   3 M30\n4 END PGM IN INCH\n";
    paste_program(&root, program).await;
    click(&root, "[data-key=run]").await;
    for _ in 0..10 {
        if cursor_text(&root).starts_with("2 L") {
            break;
        }
        click(&root, "[data-key=run-next]").await;
    }
    assert!(cursor_text(&root).starts_with("2 L X+1"), "{}", cursor_text(&root));
    assert_eq!(text(&root, ".position thead th"), "INCH");
    assert_eq!(text(&root, ".position tr[data-axis='X'] .ist"), "+1.0000");
    assert_eq!(text(&root, ".position tr[data-axis='Y'] .ist"), "+0.5000");
    // Tool 1 of the shipped table: L80 R5 mm = L3.150 R0.197 inch; F200 as written.
    let tool = text(&root, ".position .tool");
    assert!(tool.contains("L3.150 R0.197") && tool.contains("F200"), "{tool}");
}
