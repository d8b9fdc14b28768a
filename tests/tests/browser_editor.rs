//! Headless-Chromium test of the machine editor page (issue 17) and the trainer's side of it: a
//! direction typed as 0 0 0 is said in German at that field, fixed, saved; the trainer then
//! offers the saved machine under MASCHINE WÄHLEN → EIGENE MASCHINEN and runs on it.
#![cfg(target_arch = "wasm32")]

use schwenkbar_app::saved_machines::MACHINES_KEY;
use schwenkbar_tests::browser::{
    clear_storage, click, eventually, mount, mount_editor, query, text, type_into, wait_for,
};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

fn stored(key: &str) -> Option<String> {
    web_sys::window()?.local_storage().ok()??.get_item(key).ok()?
}

#[wasm_bindgen_test]
async fn a_zero_direction_is_said_at_its_field_then_fixed_saved_and_offered_by_the_trainer() {
    clear_storage();
    let editor = mount_editor("#ac-table").await;
    assert_eq!(
        query(&editor, ".editor .status").and_then(|s| s.get_attribute("data-valid")).as_deref(),
        Some("true")
    );
    let c_direction = r#"input[data-field="Direction(0, 2)"]"#;
    let at_field = r#"[data-path="chain[0].direction"] .ed-issue"#;
    // C's direction (0 0 1) typed as 0 0 0.
    type_into(&editor, c_direction, "0").await;
    assert!(wait_for(&editor, at_field, 3_000).await.is_some(), "a message at the direction");
    assert_eq!(text(&editor, at_field), "Richtung ist der Nullvektor");
    assert_eq!(
        query(&editor, ".editor .status").and_then(|s| s.get_attribute("data-valid")).as_deref(),
        Some("false")
    );
    assert!(query(&editor, "canvas.view3d").is_some(), "the preview stays (the last valid machine)");
    click(&editor, "[data-action=save]").await;
    assert!(text(&editor, ".message").starts_with("Nicht gespeichert"), "{}", text(&editor, ".message"));
    assert_eq!(stored(MACHINES_KEY), None);
    // Fixed: the message goes, the machine saves.
    type_into(&editor, c_direction, "1").await;
    assert!(eventually(|| query(&editor, at_field).is_none()).await, "the message went");
    click(&editor, "[data-action=save]").await;
    assert!(text(&editor, ".message").starts_with("Gespeichert"), "{}", text(&editor, ".message"));
    assert!(stored(MACHINES_KEY).is_some_and(|r| r.starts_with("m2;id=ac-table-eigen;")));
    editor.remove();
    web_sys::window().expect("window").location().set_hash("").expect("clear hash");

    // The trainer, loaded afterwards, offers it.
    let trainer = mount().await;
    click(&trainer, "[data-key=machines]").await;
    assert!(query(&trainer, "[data-key=edit-machine]").is_some(), "EDITIEREN");
    click(&trainer, "[data-key=own-machines]").await;
    let own = "[data-key=machine-ac-table-eigen]";
    assert!(wait_for(&trainer, own, 3_000).await.is_some(), "the saved machine is offered");
    assert!(text(&trainer, own).contains("(eigene)"), "{}", text(&trainer, own));
    click(&trainer, own).await;
    click(&trainer, "[data-key=machines]").await;
    click(&trainer, "[data-key=own-machines]").await;
    assert_eq!(query(&trainer, own).and_then(|k| k.get_attribute("aria-pressed")).as_deref(), Some("true"));
}

#[wasm_bindgen_test]
async fn a_collision_body_is_checked_at_its_field_added_and_removed() {
    clear_storage();
    let editor = mount_editor("#ac-table").await;
    // The machine bed's height (760 × 760 × 60) typed as 0.
    let size = r#"input[data-field="BodySize(0, 2)"]"#;
    let at_field = r#"[data-path="collision[0].box.size"] .ed-issue"#;
    type_into(&editor, size, "0").await;
    assert!(wait_for(&editor, at_field, 3_000).await.is_some(), "a message at the size");
    assert!(text(&editor, at_field).contains("muss größer als 0 sein (0)"), "{}", text(&editor, at_field));
    type_into(&editor, size, "60").await;
    assert!(eventually(|| query(&editor, at_field).is_none()).await, "the message went");
    // ac-table has 9 bodies: a tenth is added, then the first removed.
    let tenth = r#"input[data-field="BodyName(9, 0)"]"#;
    assert!(query(&editor, tenth).is_none());
    click(&editor, "[data-action=add-body]").await;
    assert!(wait_for(&editor, tenth, 3_000).await.is_some(), "the new body's fields");
    click(&editor, "[data-action=remove-body]").await;
    assert!(eventually(|| query(&editor, tenth).is_none()).await, "nine again");
    assert_eq!(
        query(&editor, ".editor .status").and_then(|s| s.get_attribute("data-valid")).as_deref(),
        Some("true")
    );
    editor.remove();
    web_sys::window().expect("window").location().set_hash("").expect("clear hash");
}

/// The shop's tool table beside the machine: the shipped table shown, a wrong cell said at its
/// row and not kept, fixed and kept as a `TOOL.T` text (which the trainer reads), a new row,
/// and back to the shipped table.
#[wasm_bindgen_test]
async fn the_tool_table_is_checked_at_its_cell_and_kept_as_tool_t() {
    use schwenkbar_app::tool_table::TOOLS_KEY;
    clear_storage();
    let editor = mount_editor("#ac-table").await;
    let own = || query(&editor, ".tools .status").and_then(|s| s.get_attribute("data-own"));
    assert_eq!(own().as_deref(), Some("false"), "the shipped table until one is kept");
    // Row 1 (tool 1, SCHAFTFRAESER_D10), column R.
    let radius = r#"input[data-cell="0:3"]"#;
    type_into(&editor, radius, "5x").await;
    let said = ".tools tr.issues .ed-issue";
    assert!(wait_for(&editor, said, 3_000).await.is_some(), "said under the row");
    assert_eq!(text(&editor, said), "R: „5x“ ist keine Zahl");
    assert_eq!(stored(TOOLS_KEY), None, "not kept while wrong");
    type_into(&editor, radius, "6").await;
    assert!(eventually(|| query(&editor, said).is_none()).await, "the message went");
    // Kept by the effect after the render that took the message away: waited for, not assumed
    // (it failed once with a release build beside the tests).
    assert!(eventually(|| stored(TOOLS_KEY).is_some()).await, "kept");
    let kept = stored(TOOLS_KEY).expect("kept");
    assert!(kept.starts_with("BEGIN TOOL") && kept.contains("SCHAFTFRAESER_D10"), "{kept}");
    assert_eq!(own().as_deref(), Some("true"));
    click(&editor, "[data-action=add-tool]").await;
    assert!(
        eventually(|| stored(TOOLS_KEY).is_some_and(|t| t.contains("WERKZEUG_0"))).await,
        "the new row kept"
    );
    click(&editor, "[data-action=shipped-tools]").await;
    assert!(eventually(|| stored(TOOLS_KEY).as_deref() == Some("")).await, "the own table dropped");
    assert_eq!(own().as_deref(), Some("false"));
    editor.remove();
    web_sys::window().expect("window").location().set_hash("").expect("clear hash");
}
