//! Headless-Chromium tests of the app shell (run by `cargo test --target wasm32-unknown-unknown
//! -p schwenkbar-tests`, see scripts/test.sh). They mount the real root component.
#![cfg(target_arch = "wasm32")]

use schwenkbar_tests::browser::{clear_storage, click, mount, query, settled_attribute, text};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
async fn shell_shows_eight_softkeys_with_spec_fct_and_a_webgl2_canvas() {
    clear_storage();
    let root = mount().await;
    let keys = root.query_selector_all(".softkeys .softkey").expect("selector");
    assert_eq!(keys.length(), 8, "the control shows eight softkeys");
    assert!(query(&root, "[data-key=spec-fct]").is_some(), "SPEC FCT is on the main row");
    assert!(query(&root, "canvas.view3d").is_some(), "the 3D view's canvas");
    let status = settled_attribute(&root, "canvas.view3d", "data-webgl", 10_000).await;
    assert_eq!(status.as_deref(), Some("ready"), "headless Chromium has WebGL2");
    assert!(query(&root, ".no-webgl").is_none());
}

#[wasm_bindgen_test]
async fn spec_fct_opens_the_special_functions_row_and_end_returns() {
    clear_storage();
    let root = mount().await;
    assert_eq!(text(&root, ".dialog-line"), "Programm-Einspeichern/Editieren");
    assert!(query(&root, "[data-key=tilt-plane]").is_none());

    click(&root, "[data-key=spec-fct]").await;
    let tilt = query(&root, "[data-key=tilt-plane]").expect("BEARB.-EBENE SCHWENKEN softkey");
    assert_eq!(tilt.text_content().as_deref(), Some("BEARB.-EBENESCHWENKEN"));
    assert_eq!(text(&root, ".dialog-line"), "Sonderfunktionen: Bereich wählen");

    click(&root, "[data-key=back]").await;
    assert!(query(&root, "[data-key=spec-fct]").is_some(), "END returns to the main row");
}

#[wasm_bindgen_test]
async fn language_softkey_switches_to_english_and_back() {
    clear_storage();
    let root = mount().await;
    click(&root, "[data-key=lang]").await;
    let tnc = query(&root, ".tnc").expect("screen");
    assert_eq!(tnc.get_attribute("lang").as_deref(), Some("en"));
    assert_eq!(text(&root, ".dialog-line"), "Programming");
    click(&root, "[data-key=lang]").await;
    assert_eq!(tnc.get_attribute("lang").as_deref(), Some("de"));
}
