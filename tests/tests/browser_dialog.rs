//! The PLANE softkey dialog in the browser, by clicks and by keys (issue 6), and keeping the
//! trainee's work across a reload.
#![cfg(target_arch = "wasm32")]

use schwenkbar_tests::browser::{
    clear_storage, click, key, mount, program_lines, query, set_saved, text, type_ent,
};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

const SPATIAL_BLOCK: &str = "1 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX";

#[wasm_bindgen_test]
async fn spatial_dialog_by_clicks_inserts_the_block_after_the_cursor() {
    clear_storage();
    let root = mount().await;
    click(&root, "[data-key=spec-fct]").await;
    click(&root, "[data-key=tilt-plane]").await;
    click(&root, "[data-key=fn-spatial]").await;
    assert_eq!(text(&root, ".dialog-line"), "Raumwinkel A?");
    for value in ["0", "15", "0"] {
        for c in value.chars() {
            click(&root, &format!("[data-key=pad-{c}]")).await;
        }
        click(&root, "[data-key=ent]").await;
    }
    assert_eq!(text(&root, ".dialog-line"), "Positionierverhalten?");
    click(&root, "[data-key=dlg-turn]").await;
    click(&root, "[data-key=noent]").await; // no MB
    click(&root, "[data-key=dlg-fmax]").await;
    click(&root, "[data-key=noent]").await; // no SEQ/SYM
    click(&root, "[data-key=noent]").await; // no COORD/TABLE ROT
    let lines = program_lines(&root);
    assert_eq!(lines.get(1).map(String::as_str), Some(SPATIAL_BLOCK), "{lines:?}");
    assert!(lines.get(2).is_some_and(|l| l.starts_with("2 ;")), "following blocks renumbered: {lines:?}");
}

#[wasm_bindgen_test]
async fn spatial_dialog_by_keys_with_seq_and_table_rot() {
    clear_storage();
    let root = mount().await;
    key(&root, "F1", false).await; // SPEC FCT
    key(&root, "F3", false).await; // BEARB.-EBENE SCHWENKEN
    key(&root, "F1", false).await; // SPATIAL
    type_ent(&root, "0").await;
    type_ent(&root, "15").await;
    type_ent(&root, "0").await;
    key(&root, "F1", false).await; // MOVE
    type_ent(&root, "50").await; // DIST
    type_ent(&root, "500").await; // F
    key(&root, "F2", false).await; // SEQ-
    key(&root, "Enter", false).await;
    key(&root, "F2", false).await; // TABLE ROT
    let lines = program_lines(&root);
    assert_eq!(
        lines.get(1).map(String::as_str),
        Some("1 PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST+50 F500 SEQ- TABLE ROT"),
        "{lines:?}"
    );
}

#[wasm_bindgen_test]
async fn euler_and_reset_by_keys() {
    clear_storage();
    let root = mount().await;
    for k in ["F1", "F3", "F3"] {
        key(&root, k, false).await; // SPEC FCT, tilt, EULER
    }
    type_ent(&root, "0").await;
    type_ent(&root, "45").await;
    type_ent(&root, "0").await;
    key(&root, "F2", false).await; // TURN
    key(&root, "F1", false).await; // MB MAX
    key(&root, "F2", false).await; // FMAX
    key(&root, "F4", false).await; // SYM-
    key(&root, "Enter", false).await;
    key(&root, "F2", false).await; // TABLE ROT
    key(&root, "F8", false).await; // RESET (the tilt row is still shown)
    key(&root, "F2", false).await; // TURN
    key(&root, "Enter", true).await; // NO ENT: no MB
    key(&root, "F2", false).await; // FMAX
    let lines = program_lines(&root);
    assert_eq!(
        lines.get(1).map(String::as_str),
        Some("1 PLANE EULER EULPR+0 EULNU+45 EULROT+0 TURN MB MAX FMAX SYM- TABLE ROT")
    );
    assert_eq!(lines.get(2).map(String::as_str), Some("2 PLANE RESET TURN FMAX"), "{lines:?}");
}

#[wasm_bindgen_test]
async fn a_wrong_entry_shows_its_message_and_can_be_corrected() {
    clear_storage();
    let root = mount().await;
    for k in ["F1", "F3", "F1"] {
        key(&root, k, false).await;
    }
    type_ent(&root, "1a").await;
    assert_eq!(text(&root, ".dialog-line"), "Eingabewert falsch: Zahl oder Q-Parameter erwartet");
    assert_eq!(text(&root, "[data-testid=dialog-input]"), "1a", "the value stays for correction");
    key(&root, "Backspace", false).await;
    key(&root, "Enter", false).await;
    type_ent(&root, "400").await;
    assert_eq!(text(&root, ".dialog-line"), "Winkel nicht erlaubt");
    key(&root, "Escape", false).await;
    assert_eq!(text(&root, ".dialog-line"), "Dialog abgebrochen");
    assert!(program_lines(&root).iter().all(|l| !l.contains("PLANE SPATIAL SPA+1 ")), "nothing inserted");
}

#[wasm_bindgen_test]
async fn state_survives_a_reload_and_a_corrupt_saved_state_falls_back() {
    clear_storage();
    let root = mount().await;
    click(&root, "[data-key=samples]").await;
    click(&root, "[data-key=sample-stay_q120]").await;
    click(&root, "[data-key=lang]").await;
    click(&root, ".program-pane .line[data-line='8']").await;
    // A second app in the same page reads what the first one saved: a reload.
    let again = mount().await;
    assert_eq!(query(&again, ".tnc").and_then(|t| t.get_attribute("lang")).as_deref(), Some("en"));
    let cursor =
        query(&again, ".program-pane .line.cursor").and_then(|l| l.text_content()).unwrap_or_default();
    assert!(cursor.starts_with("7 PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY"), "{cursor}");

    // The language is a preference of its own (shared with the course): it survives a broken
    // state record.
    set_saved("s2;cursor=");
    let broken = mount().await;
    assert_eq!(
        text(&broken, ".dialog-line"),
        "The saved state was corrupt: cursor and machine reset, program kept"
    );
    assert!(
        program_lines(&broken).first().is_some_and(|l| l.contains("BEGIN PGM X MM")),
        "the saved program is kept beside a corrupt state"
    );
    // The JSON the builds before records wrote is recognised as old, not as corrupt.
    set_saved("{\"version\":1,\"cursor\":3,\"machine\":\"ac-table\",\"lang\":\"De\",\"projector\":false}");
    let old = mount().await;
    assert_eq!(
        text(&old, ".dialog-line"),
        "The saved state is from an older version: cursor and machine reset, program kept"
    );
}
