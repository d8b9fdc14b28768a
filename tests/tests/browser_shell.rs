//! Headless-Chromium tests of the app shell (run by `cargo test --target wasm32-unknown-unknown
//! -p schwenkbar-tests`, see scripts/test.sh). They mount the real root component.
#![cfg(target_arch = "wasm32")]

use std::time::Duration;

use wasm_bindgen::JsCast;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{Element, HtmlElement};

wasm_bindgen_test_configure!(run_in_browser);

/// Mounts a fresh app into its own element and lets yew render.
async fn mount() -> Element {
    let document = web_sys::window().and_then(|w| w.document()).expect("a browser document");
    let root = document.create_element("div").expect("create div");
    document.body().expect("body").append_child(&root).expect("append root");
    yew::Renderer::<schwenkbar_web::App>::with_root(root.clone()).render();
    settle().await;
    root
}

/// Gives yew's scheduler and the effects a moment to run.
async fn settle() {
    yew::platform::time::sleep(Duration::from_millis(30)).await;
}

fn query(root: &Element, selector: &str) -> Option<Element> {
    root.query_selector(selector).expect("valid selector")
}

#[wasm_bindgen_test]
async fn shell_shows_eight_softkeys_with_spec_fct_and_a_webgl2_canvas() {
    let root = mount().await;
    let keys = root.query_selector_all(".softkeys .softkey").expect("selector");
    assert_eq!(keys.length(), 8, "the control shows eight softkeys");
    assert!(query(&root, "[data-key=spec-fct]").is_some(), "SPEC FCT is on the main row");
    let canvas = query(&root, "canvas.view3d").expect("the 3D view's canvas");
    assert_eq!(canvas.get_attribute("data-webgl").as_deref(), Some("ready"), "headless Chromium has WebGL2");
    assert!(query(&root, ".no-webgl").is_none());
}

#[wasm_bindgen_test]
async fn spec_fct_opens_the_special_functions_row_and_end_returns() {
    let root = mount().await;
    let dialog = query(&root, ".dialog-line").expect("dialog line");
    assert_eq!(dialog.text_content().as_deref(), Some("Programm-Einspeichern/Editieren"));
    assert!(query(&root, "[data-key=tilt-plane]").is_none());

    click(&root, "[data-key=spec-fct]").await;
    let tilt = query(&root, "[data-key=tilt-plane]").expect("BEARB.-EBENE SCHWENKEN softkey");
    assert_eq!(tilt.text_content().as_deref(), Some("BEARB.-EBENESCHWENKEN"));
    assert_eq!(dialog.text_content().as_deref(), Some("Sonderfunktionen: Bereich wählen"));

    click(&root, "[data-key=back]").await;
    assert!(query(&root, "[data-key=spec-fct]").is_some(), "END returns to the main row");
}

#[wasm_bindgen_test]
async fn language_softkey_switches_to_english_and_back() {
    let root = mount().await;
    click(&root, "[data-key=lang]").await;
    let tnc = query(&root, ".tnc").expect("screen");
    assert_eq!(tnc.get_attribute("lang").as_deref(), Some("en"));
    assert_eq!(query(&root, ".dialog-line").and_then(|d| d.text_content()).as_deref(), Some("Programming"));
    click(&root, "[data-key=lang]").await;
    assert_eq!(tnc.get_attribute("lang").as_deref(), Some("de"));
}

async fn click(root: &Element, selector: &str) {
    let el = query(root, selector).unwrap_or_else(|| panic!("no element {selector}"));
    el.dyn_into::<HtmlElement>().expect("an HTML element").click();
    settle().await;
}
