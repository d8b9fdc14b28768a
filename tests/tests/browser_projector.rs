//! Issue 12, defect 6: the classroom projector layout at a projector's 1280 pixels, with the
//! real styles (static/app.css put into the page as the built pages link it): the type of the
//! dialog, header and keys scales, the hidden "why" panel leaves no empty column, PLANE blocks
//! wrap instead of being cut and the cursor block is in sight, NO ENT stays in its key, three
//! softkey lines fit, the focus ring is there, and the course's instructor view does not
//! overflow and shows its trainer in projector type. Headless Chromium (scripts/test.sh).
#![cfg(target_arch = "wasm32")]

use schwenkbar_app::i18n::Lang;
use schwenkbar_tests::browser::{
    clear_storage, click, inject_app_css, mount, mount_at, query, save_trainer_state, settle, unmount,
    wait_for,
};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{Element, HtmlElement};

wasm_bindgen_test_configure!(run_in_browser);

fn prop(el: &Element, name: &str) -> String {
    web_sys::window()
        .and_then(|w| w.get_computed_style(el).ok().flatten())
        .and_then(|s| s.get_property_value(name).ok())
        .unwrap_or_default()
}

fn px(el: &Element, name: &str) -> f64 {
    prop(el, name).trim_end_matches("px").parse().unwrap_or(f64::NAN)
}

fn all(root: &Element, selector: &str) -> Vec<Element> {
    let list = root.query_selector_all(selector).expect("selector");
    (0..list.length()).filter_map(|i| list.item(i)).filter_map(|n| n.dyn_into::<Element>().ok()).collect()
}

/// Text that does not fit its box (wider or taller than the box shows).
fn cut(el: &Element) -> bool {
    el.scroll_width() > el.client_width() + 1 || el.scroll_height() > el.client_height() + 1
}

/// Every drawn program line wraps inside the program pane: not cut by its own box nor by the
/// pane (classroom trial II: "10 PLANE SPATIAL SPA+0 SPB+15 SP").
fn lines_fit_the_pane(root: &Element) {
    let lines = query(root, ".program-pane .lines").expect("lines");
    let visible_right = lines.get_bounding_client_rect().left() + f64::from(lines.client_width());
    for line in all(root, ".program-pane .line") {
        assert!(!cut(&line), "cut: {:?}", line.text_content());
        let r = line.get_bounding_client_rect();
        assert!(
            r.right() <= visible_right + 1.0,
            "beyond the pane: {:?} {} > {visible_right}",
            line.text_content(),
            r.right()
        );
    }
}

/// The app in projector mode, 1280 px wide, the cursor on Musterprogramm 1's block 10.
async fn projector_app() -> Element {
    clear_storage();
    save_trainer_state(10, "ac-table", Lang::De, true);
    let root = mount().await;
    root.set_attribute("style", "width: 1280px").expect("style");
    settle().await;
    assert!(query(&root, ".tnc.projector").is_some(), "projector mode");
    root
}

#[wasm_bindgen_test]
async fn projector_type_scales_and_the_program_and_view_take_the_why_panels_column() {
    inject_app_css();
    let root = projector_app().await;
    for selector in [".mode-header", ".dialog-line", ".hard-key", ".program-pane .line"] {
        let el = query(&root, selector).unwrap_or_else(|| panic!("{selector}"));
        assert_eq!(px(&el, "font-size"), 22.0, "{selector} in projector type");
    }
    // No empty column: the side column (only the hidden why panel outside a run) is gone and
    // the 3D view reaches the right edge of the panes.
    let panes = query(&root, ".panes").expect("panes").get_bounding_client_rect();
    let view = query(&root, ".scene-pane").expect("3D view").get_bounding_client_rect();
    let program = query(&root, ".program-pane").expect("program").get_bounding_client_rect();
    assert!(
        (panes.right() - view.right()).abs() <= 1.0,
        "the view ends at {} of {}",
        view.right(),
        panes.right()
    );
    assert!(program.width() > panes.width() * 0.35, "the program pane gets its share: {}", program.width());
    // Long blocks wrap, nothing is cut; the cursor block is in the pane.
    let pane = query(&root, ".program-pane").expect("pane").get_bounding_client_rect();
    lines_fit_the_pane(&root);
    let cursor = query(&root, ".line.cursor").expect("cursor line");
    assert!(cursor.text_content().unwrap_or_default().contains("PLANE SPATIAL"), "block 10");
    let c = cursor.get_bounding_client_rect();
    assert!(
        c.top() >= pane.top() && c.bottom() <= pane.bottom(),
        "block 10 in sight: {} {} in {} {}",
        c.top(),
        c.bottom(),
        pane.top(),
        pane.bottom()
    );
    // NO ENT on one line in its key.
    for key in all(&root, ".hard-key") {
        assert!(!cut(&key), "{:?} fits its key", key.text_content());
        assert!(key.get_client_rects().length() > 0);
    }
    // A program run keeps the position display in its own column.
    click(&root, "[data-key=run]").await;
    // The run row comes with the next render; on a loaded machine that can take a while.
    wait_for(&root, "[data-key=run-next]", 3_000).await.expect("the run row");
    click(&root, "[data-key=run-next]").await;
    let side = wait_for(&root, ".side .position", 3_000).await.expect("position display");
    assert!(side.get_bounding_client_rect().width() >= 250.0, "the position display is readable");
    // It fills its column: no empty black under it.
    let column = query(&root, ".side").expect("side").get_bounding_client_rect();
    let shown = side.get_bounding_client_rect();
    assert!(
        column.bottom() - shown.bottom() <= 2.0,
        "empty under the position display: {} < {}",
        shown.bottom(),
        column.bottom()
    );
    root.remove();
}

#[wasm_bindgen_test]
async fn three_softkey_lines_fit_and_the_focus_ring_shows() {
    inject_app_css();
    let root = projector_app().await;
    for row in ["[data-key=machines]", "[data-key=spec-fct]"] {
        click(&root, row).await;
        for key in all(&root, ".softkey") {
            assert!(!cut(&key), "softkey {:?} fits", key.text_content());
            for line in all(&key, "span") {
                assert_eq!(line.get_client_rects().length(), 1, "{:?} on one line", line.text_content());
            }
        }
        click(&root, "[data-key=back]").await;
    }
    let machines = all(&root, "[data-key^=machine-]");
    assert!(machines.is_empty(), "back on the main row");
    click(&root, "[data-key=machines]").await;
    assert!(all(&root, "[data-key^=machine-] span").len() >= 3, "machine names on several lines");
    // The ring: a black outline off the key and a yellow band between, for keys and buttons.
    let key: HtmlElement = query(&root, "[data-key^=machine-]").expect("softkey").dyn_into().expect("button");
    key.focus().expect("focus");
    settle().await;
    if key.matches(":focus-visible").unwrap_or(false) {
        assert_eq!(prop(&key, "outline-style"), "solid");
        assert!(px(&key, "outline-width") >= 3.0 && px(&key, "outline-offset") >= 3.0);
        assert!(prop(&key, "box-shadow").contains("rgb(255, 212, 0)"), "{}", prop(&key, "box-shadow"));
    }
    root.remove();
}

#[wasm_bindgen_test]
async fn the_instructor_view_fits_1366_pixels_and_its_trainer_has_projector_type() {
    inject_app_css();
    clear_storage();
    let root = mount_at("#kurs/3").await;
    root.set_attribute("style", "width: 1366px").expect("style");
    wait_for(&root, ".lesson-trainer .tnc", 5_000).await.expect("the lesson's trainer");
    click(&root, "[data-testid=instructor]").await;
    assert!(query(&root, ".course.projector").is_some(), "instructor view");
    settle().await;
    let course = query(&root, ".course").expect("course");
    assert!(
        course.scroll_width() <= course.client_width() + 1,
        "no overflow: {} > {}",
        course.scroll_width(),
        course.client_width()
    );
    let trainer = query(&root, ".lesson-trainer .tnc").expect("trainer");
    assert!(trainer.get_bounding_client_rect().right() <= course.get_bounding_client_rect().right() + 1.0);
    let line = query(&root, ".lesson-trainer .program-pane .line").expect("program line");
    assert_eq!(px(&line, "font-size"), 22.0, "the embedded program in projector type");
    lines_fit_the_pane(&query(&root, ".lesson-trainer").expect("trainer"));
    for key in all(&root, ".lesson-trainer .softkey, .lesson-trainer .hard-key") {
        assert!(!cut(&key), "{:?} fits", key.text_content());
    }
    unmount(&root);
}
