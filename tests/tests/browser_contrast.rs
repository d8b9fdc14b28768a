//! Issue 12, defect 7: every text reaches a contrast of at least 4.5:1 (WCAG 2 AA) against
//! what is behind it, in the trainer (normal and projector mode, German and English, with the
//! dialog, a softkey row with an active key, the "why" panel and a program run open) and in the
//! course (overview, a bench lesson, a lesson with the trainer, the instructor view).
//!
//! Walks every rendered element with a text of its own, takes its computed `color` and its
//! effective background: the ancestors' `background-color`s up to the first opaque one,
//! composited (semi-transparent ones over what is below; white under all, as the canvas). An
//! element's and its ancestors' `opacity` fades its text. The real styles are checked:
//! static/app.css is put into the page as the built pages link it (the components bring their
//! own CSS). Headless Chromium (scripts/test.sh).
#![cfg(target_arch = "wasm32")]

use schwenkbar_app::i18n::Lang;
use schwenkbar_tests::browser::{
    clear_storage, click, eventually, inject_app_css, key, mount, mount_at, query, save_trainer_state,
    unmount, wait_for,
};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::Element;

wasm_bindgen_test_configure!(run_in_browser);

const MIN_RATIO: f64 = 4.5;

fn window() -> web_sys::Window {
    web_sys::window().expect("window")
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Rgba(f64, f64, f64, f64);

impl std::fmt::Display for Rgba {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let c = |v: f64| (v * 255.0).round() as u8;
        write!(f, "#{:02x}{:02x}{:02x}", c(self.0), c(self.1), c(self.2))?;
        if self.3 < 1.0 {
            write!(f, " (alpha {:.2})", self.3)?;
        }
        Ok(())
    }
}

/// A computed colour: `rgb(r, g, b)`, `rgba(r, g, b, a)` or `rgb(r g b / a)`.
fn parse_color(s: &str) -> Option<Rgba> {
    let inner =
        s.trim().strip_prefix("rgba(").or_else(|| s.trim().strip_prefix("rgb("))?.strip_suffix(')')?;
    let parts: Vec<f64> = inner
        .split([',', ' ', '/'])
        .filter(|p| !p.is_empty())
        .map(|p| p.trim().parse().ok())
        .collect::<Option<_>>()?;
    match parts[..] {
        [r, g, b] => Some(Rgba(r / 255.0, g / 255.0, b / 255.0, 1.0)),
        [r, g, b, a] => Some(Rgba(r / 255.0, g / 255.0, b / 255.0, a)),
        _ => None,
    }
}

/// `top` painted over the opaque `bottom`.
fn over(top: Rgba, bottom: Rgba) -> Rgba {
    let a = top.3;
    Rgba(
        top.0 * a + bottom.0 * (1.0 - a),
        top.1 * a + bottom.1 * (1.0 - a),
        top.2 * a + bottom.2 * (1.0 - a),
        1.0,
    )
}

fn luminance(c: Rgba) -> f64 {
    let lin = |v: f64| if v <= 0.039_28 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) };
    0.2126 * lin(c.0) + 0.7152 * lin(c.1) + 0.0722 * lin(c.2)
}

fn ratio(a: Rgba, b: Rgba) -> f64 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

fn style(el: &Element) -> web_sys::CssStyleDeclaration {
    window().get_computed_style(el).ok().flatten().expect("computed style")
}

fn prop(el: &Element, name: &str) -> String {
    style(el).get_property_value(name).unwrap_or_default()
}

/// The effective background of `el`, the element whose background made it opaque (for the
/// message) and the opacity its text is shown with.
fn background(el: &Element) -> (Rgba, String, f64) {
    let mut layers = Vec::new();
    let mut opacity = 1.0;
    let mut from = "the page (white)".to_owned();
    let mut node = Some(el.clone());
    while let Some(e) = node {
        opacity *= prop(&e, "opacity").parse::<f64>().unwrap_or(1.0);
        if let Some(c) = parse_color(&prop(&e, "background-color")).filter(|c| c.3 > 0.0) {
            layers.push(c);
            if c.3 >= 1.0 {
                from = describe(&e);
                break;
            }
        }
        node = e.parent_element();
    }
    let bg = layers.iter().rev().fold(Rgba(1.0, 1.0, 1.0, 1.0), |below, &layer| over(layer, below));
    (bg, from, opacity)
}

fn describe(el: &Element) -> String {
    let class =
        el.get_attribute("class").map(|c| format!(".{}", c.split_whitespace().collect::<Vec<_>>().join(".")));
    let key = el.get_attribute("data-key").map(|k| format!("[data-key={k}]"));
    format!("<{}{}{}>", el.tag_name().to_lowercase(), class.unwrap_or_default(), key.unwrap_or_default())
}

/// The element's own text (its text nodes, not its children's).
fn own_text(el: &Element) -> String {
    let nodes = el.child_nodes();
    (0..nodes.length())
        .filter_map(|i| nodes.item(i))
        .filter(|n| n.node_type() == web_sys::Node::TEXT_NODE)
        .filter_map(|n| n.text_content())
        .collect::<String>()
        .trim()
        .to_owned()
}

/// Every rendered text under `root` below 4.5:1, one line each; `context` names the screen.
fn low_contrast(root: &Element, context: &str) -> Vec<String> {
    let all = root.query_selector_all("*").expect("selector");
    let mut checked = 0;
    let mut out = Vec::new();
    for el in (0..all.length()).filter_map(|i| all.item(i)).filter_map(|n| n.dyn_into::<Element>().ok()) {
        let text = own_text(&el);
        if text.is_empty() || matches!(el.tag_name().as_str(), "STYLE" | "SCRIPT" | "OPTION") {
            continue;
        }
        if el.get_client_rects().length() == 0 || prop(&el, "visibility") != "visible" {
            continue; // not rendered
        }
        let Some(fg) = parse_color(&prop(&el, "color")) else {
            out.push(format!(
                "{context}: {} has a colour this test cannot read: {}",
                describe(&el),
                prop(&el, "color")
            ));
            continue;
        };
        let (bg, from, opacity) = background(&el);
        let shown = over(Rgba(fg.0, fg.1, fg.2, fg.3 * opacity), bg);
        let r = ratio(shown, bg);
        checked += 1;
        if r < MIN_RATIO {
            let short: String = text.chars().take(40).collect();
            out.push(format!(
                "{context}: {} \"{short}\": text {fg} (shown as {shown}) on {bg} (background of {from}): {r:.2}:1",
                describe(&el)
            ));
        }
    }
    assert!(checked > 5, "{context}: only {checked} texts found: is the page rendered?");
    out
}

fn assert_none(failures: &[String]) {
    assert!(failures.is_empty(), "texts below {MIN_RATIO}:1 ({}):\n{}", failures.len(), failures.join("\n"));
}

#[wasm_bindgen_test]
fn the_contrast_maths_matches_wcag() {
    let (black, white) = (Rgba(0.0, 0.0, 0.0, 1.0), Rgba(1.0, 1.0, 1.0, 1.0));
    assert!((ratio(black, white) - 21.0).abs() < 1e-9);
    assert!((ratio(white, white) - 1.0).abs() < 1e-9);
    // #767676 on white is the classic 4.54:1.
    let grey = parse_color("rgb(118, 118, 118)").expect("grey");
    assert!((ratio(grey, white) - 4.54).abs() < 0.01);
    assert_eq!(
        parse_color("rgba(10, 20, 30, 0.5)"),
        Some(Rgba(10.0 / 255.0, 20.0 / 255.0, 30.0 / 255.0, 0.5))
    );
    assert_eq!(over(Rgba(0.0, 0.0, 0.0, 0.5), white), Rgba(0.5, 0.5, 0.5, 1.0));
}

#[wasm_bindgen_test]
async fn every_text_of_the_trainer_reaches_4_5_to_1_normal_and_projector_german_and_english() {
    inject_app_css();
    let mut failures = Vec::new();
    for (lang, projector) in [(Lang::De, false), (Lang::En, false), (Lang::De, true), (Lang::En, true)] {
        clear_storage();
        // The cursor on Musterprogramm 1's PLANE block 10: the "why" panel has its explanation.
        save_trainer_state(10, "ac-table", lang, projector);
        let root = mount().await;
        let mode = if projector { "projector" } else { "normal" };
        assert_eq!(query(&root, ".tnc.projector").is_some(), projector, "{lang:?} {mode}: the saved mode");
        let ctx = |screen: &str| format!("{lang:?} {mode}, {screen}");
        failures.extend(low_contrast(&root, &ctx("program and why panel")));
        // The right-hand rule in place of the 3D view.
        key(&root, "h", false).await;
        assert!(
            eventually(|| query(&root, ".right-hand").is_some()).await,
            "{lang:?} {mode}: h, the right-hand rule"
        );
        failures.extend(low_contrast(&root, &ctx("right-hand rule")));
        key(&root, "h", false).await;
        // A softkey row with an active (highlighted) key.
        click(&root, "[data-key=machines]").await;
        failures.extend(low_contrast(&root, &ctx("machine softkeys")));
        click(&root, "[data-key=back]").await;
        // The PLANE dialog: prompt, input, help, keypad, hard keys, preview.
        click(&root, "[data-key=spec-fct]").await;
        click(&root, "[data-key=tilt-plane]").await;
        click(&root, "[data-key=fn-spatial]").await;
        assert!(
            eventually(|| query(&root, ".keypad").is_some()).await,
            "{lang:?} {mode}: the dialog is open"
        );
        failures.extend(low_contrast(&root, &ctx("PLANE dialog")));
        click(&root, "[data-key=del]").await;
        for _ in 0..3 {
            key(&root, "Escape", false).await;
        }
        // A program run: the position display and the run's status lines.
        click(&root, "[data-key=run]").await;
        click(&root, "[data-key=run-next]").await;
        click(&root, "[data-key=run-next]").await;
        assert!(
            eventually(|| query(&root, ".position").is_some()).await,
            "{lang:?} {mode}: the position display"
        );
        failures.extend(low_contrast(&root, &ctx("program run")));
        root.remove();
    }
    assert_none(&failures);
}

#[wasm_bindgen_test]
async fn every_text_of_the_course_reaches_4_5_to_1_overview_lessons_and_instructor_view() {
    inject_app_css();
    clear_storage();
    let mut failures = Vec::new();
    for instructor in [false, true] {
        let view = if instructor { "instructor view" } else { "normal view" };
        for (fragment, screen) in
            [("#kurs", "overview"), ("#kurs/5", "lesson 5 (bench)"), ("#kurs/3", "lesson 3 (trainer)")]
        {
            let root = mount_at(fragment).await;
            assert!(wait_for(&root, ".course-head", 5_000).await.is_some(), "{screen}: the course page");
            if fragment != "#kurs" {
                assert!(
                    wait_for(&root, "[data-testid=lesson]", 5_000).await.is_some(),
                    "{screen}: the lesson"
                );
            }
            let on = query(&root, ".course.projector").is_some();
            if on != instructor {
                click(&root, "[data-testid=instructor]").await;
            }
            assert!(
                eventually(|| query(&root, ".course.projector").is_some() == instructor).await,
                "{screen}: the {view}"
            );
            failures.extend(low_contrast(&root, &format!("course {view}, {screen}")));
            if fragment == "#kurs" {
                click(&root, "[data-testid=course-lang]").await;
                failures.extend(low_contrast(&root, &format!("course {view}, overview in English")));
                click(&root, "[data-testid=course-lang]").await;
            }
            unmount(&root);
        }
    }
    assert_none(&failures);
}
