//! Driving the real app in headless Chromium: mount, click, type, read. Panics here are test
//! failures (this code never ships).

use std::time::Duration;

use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlElement, KeyboardEvent, KeyboardEventInit};

#[must_use]
pub fn document() -> web_sys::Document {
    web_sys::window().and_then(|w| w.document()).expect("a browser document")
}

/// Clears what an earlier test saved, so every test starts like a first visit.
/// Keeps a trainer state (cursor, machine) and the shared preferences the way the app saves
/// them, before [`mount`].
pub fn save_trainer_state(cursor: usize, machine: &str, lang: schwenkbar_app::i18n::Lang, projector: bool) {
    use schwenkbar_app::persist::{PREFS_KEY, Prefs, STATE_KEY, Saved};
    let storage = web_sys::window().and_then(|w| w.local_storage().ok().flatten()).expect("localStorage");
    let state = Saved { cursor, machine: machine.to_owned(), unexported: false };
    storage.set_item(STATE_KEY, &state.to_record()).expect("save state");
    storage.set_item(PREFS_KEY, &Prefs { lang, classroom: projector }.to_record()).expect("save prefs");
}

/// Clears what an earlier test saved, so every test starts like a first visit in a German
/// browser (the language a first visit takes from the browser is tested on its own).
pub fn clear_storage() {
    use schwenkbar_app::persist::{PREFS_KEY, Prefs};
    if let Some(s) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) {
        s.clear().expect("clear localStorage");
        s.set_item(PREFS_KEY, &Prefs::default().to_record()).expect("German first");
    }
}

/// Sets the saved state a "reload" will find.
pub fn set_saved(record: &str) {
    let s = web_sys::window().and_then(|w| w.local_storage().ok().flatten()).expect("localStorage");
    s.set_item(schwenkbar_app::persist::STATE_KEY, record).expect("set item");
    s.set_item("schwenkbar.program", "0 BEGIN PGM X MM\n1 END PGM X MM\n").expect("set item");
}

/// Mounts a fresh app into its own element and lets yew render. Earlier apps stay in the page;
/// every query goes through the returned root.
pub async fn mount() -> Element {
    let root = document().create_element("div").expect("create div");
    document().body().expect("body").append_child(&root).expect("append root");
    yew::Renderer::<schwenkbar_web::App>::with_root(root.clone()).render();
    settle().await;
    // The app takes keys once its first render's effects ran; a loaded page can take longer.
    assert!(wait_for(&root, "[data-keys]", 10_000).await.is_some(), "the app takes keys");
    root
}

/// Waits until yew has rendered what the last event changed and run the effects after it
/// (`yew::scheduler::flush`: its scheduler works through the microtask queue and wakes this when
/// the queue is drained). No timer: what takes longer (an animation frame, a worker, WebGL
/// start-up) is waited for on its DOM condition ([`eventually`], [`wait_for`]).
pub async fn settle() {
    yew::scheduler::flush().await;
}

#[must_use]
pub fn query(root: &Element, selector: &str) -> Option<Element> {
    root.query_selector(selector).expect("valid selector")
}

#[must_use]
pub fn text(root: &Element, selector: &str) -> String {
    query(root, selector).and_then(|e| e.text_content()).unwrap_or_default()
}

pub async fn click(root: &Element, selector: &str) {
    let el = query(root, selector).unwrap_or_else(|| panic!("no element {selector}"));
    el.dyn_into::<HtmlElement>().expect("an HTML element").click();
    settle().await;
}

/// A key pressed with the app focused (`KeyboardEvent.key` names: "Enter", "F3", "5").
pub async fn key(root: &Element, key: &str, shift: bool) {
    let init = KeyboardEventInit::new();
    init.set_key(key);
    init.set_shift_key(shift);
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("keyboard event");
    let target = query(root, ".tnc").expect("the app");
    target.dispatch_event(&event).expect("dispatch");
    settle().await;
}

/// Ctrl + `key` pressed with the app focused (undo, redo).
pub async fn key_ctrl(root: &Element, key: &str) {
    let init = KeyboardEventInit::new();
    init.set_key(key);
    init.set_ctrl_key(true);
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("keyboard event");
    query(root, ".tnc").expect("the app").dispatch_event(&event).expect("dispatch");
    settle().await;
}

/// Types a value and presses Enter (ENT).
pub async fn type_ent(root: &Element, value: &str) {
    for c in value.chars() {
        key(root, &c.to_string(), false).await;
    }
    key(root, "Enter", false).await;
}

/// The program pane's lines as text.
#[must_use]
pub fn program_lines(root: &Element) -> Vec<String> {
    let list = root.query_selector_all(".program-pane .line").expect("selector");
    (0..list.length()).filter_map(|i| list.item(i)).filter_map(|n| n.text_content()).collect()
}

/// Replaces the program through the text editor, as a paste would.
pub async fn paste_program(root: &Element, program: &str) {
    click(root, "[data-key=text-edit]").await;
    let area: web_sys::HtmlTextAreaElement =
        query(root, ".program-text").expect("text area").dyn_into().expect("a text area");
    area.set_value(program);
    let init = web_sys::InputEventInit::new();
    init.set_bubbles(true);
    let event = web_sys::InputEvent::new_with_event_init_dict("input", &init).expect("input event");
    area.dispatch_event(&event).expect("dispatch");
    settle().await;
    click(root, "[data-key=text-edit]").await;
}

/// Milliseconds since page load.
#[must_use]
pub fn now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// Presses `key` and waits for the screen to update; the time from the key to the updated DOM
/// in milliseconds (yew renders before the 0 ms timer fires, so this bounds it from above).
pub async fn timed_key(root: &Element, key_name: &str) -> f64 {
    let init = KeyboardEventInit::new();
    init.set_key(key_name);
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("keyboard event");
    let target = query(root, ".tnc").expect("the app");
    let t0 = now();
    target.dispatch_event(&event).expect("dispatch");
    yew::platform::time::sleep(std::time::Duration::from_millis(0)).await;
    now() - t0
}

/// Waits for the browser's next animation frame; its time stamp (ms since page load). Frames
/// the app's 3D view asked for before run first, so the view has painted when this returns.
pub async fn next_frame() -> f64 {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Some(w) = web_sys::window() {
            let _ = w.request_animation_frame(&resolve);
        }
    });
    wasm_bindgen_futures::JsFuture::from(promise).await.ok().and_then(|t| t.as_f64()).unwrap_or_else(now)
}

/// The median of `samples`.
#[must_use]
pub fn median(mut samples: Vec<f64>) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples.get(samples.len() / 2).copied().unwrap_or(f64::NAN)
}

/// Waits (up to `ms`) until `selector`'s attribute `name` is something other than `pending`,
/// and returns it: WebGL start-up (shader compilation in software) can take a while on a loaded
/// machine.
pub async fn settled_attribute(root: &Element, selector: &str, name: &str, ms: u64) -> Option<String> {
    let mut waited = 0;
    loop {
        let value = query(root, selector).and_then(|e| e.get_attribute(name));
        if value.as_deref() != Some("pending") || waited >= ms {
            return value;
        }
        yew::platform::time::sleep(Duration::from_millis(25)).await;
        waited += 25;
    }
}

/// Waits (up to `ms`) until `el`'s attribute `name` equals `expected`; returns the last value.
pub async fn wait_attribute(el: &Element, name: &str, expected: &str, ms: u64) -> Option<String> {
    let mut waited = 0;
    loop {
        let value = el.get_attribute(name);
        if value.as_deref() == Some(expected) || waited >= ms {
            return value;
        }
        yew::platform::time::sleep(Duration::from_millis(25)).await;
        waited += 25;
    }
}

/// Mounts the course page at the URL fragment (`#kurs/3` = lesson 3), as a visit of
/// `kurs.html#kurs/3` would.
pub async fn mount_at(fragment: &str) -> Element {
    web_sys::window().expect("window").location().set_hash(fragment).expect("set hash");
    let root = document().create_element("div").expect("create div");
    document().body().expect("body").append_child(&root).expect("append root");
    let handle = yew::Renderer::<schwenkbar_web::CourseRoot>::with_root(root.clone()).render();
    MOUNTED.with(|m| m.borrow_mut().push((root.clone(), handle)));
    settle().await;
    // The page takes keys once its first render's effects ran; a loaded page can take longer.
    assert!(
        wait_for(&root, "[data-testid=course][data-keys]", 10_000).await.is_some(),
        "the course takes keys"
    );
    root
}

/// Mounts the machine editor page at the URL fragment (`#ba-table`: start from that machine),
/// as a visit of `maschine.html#ba-table` would.
pub async fn mount_editor(fragment: &str) -> Element {
    web_sys::window().expect("window").location().set_hash(fragment).expect("set hash");
    let root = document().create_element("div").expect("create div");
    document().body().expect("body").append_child(&root).expect("append root");
    yew::Renderer::<schwenkbar_web::components::machine_editor::EditorRoot>::with_root(root.clone()).render();
    settle().await;
    assert!(wait_for(&root, ".editor .status", 10_000).await.is_some(), "the editor renders");
    root
}

thread_local! {
    /// Pages mounted with [`mount_at`], so [`unmount`] can end them: a page left running would
    /// still follow the URL fragment and save the course progress of earlier tests.
    static MOUNTED: std::cell::RefCell<Vec<(Element, yew::AppHandle<schwenkbar_web::CourseRoot>)>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// Ends a page mounted with [`mount_at`] (or only takes it out of the document).
pub fn unmount(root: &Element) {
    let handle = MOUNTED.with(|m| {
        let mut m = m.borrow_mut();
        let i = m.iter().position(|(r, _)| r == root)?;
        Some(m.remove(i).1)
    });
    if let Some(h) = handle {
        h.destroy();
    }
    root.remove();
}

/// Types `value` into the input `selector` as a user would (one input event).
pub async fn type_into(root: &Element, selector: &str, value: &str) {
    let input: web_sys::HtmlInputElement =
        query(root, selector).unwrap_or_else(|| panic!("no input {selector}")).dyn_into().expect("an input");
    input.set_value(value);
    let init = web_sys::InputEventInit::new();
    init.set_bubbles(true);
    let event = web_sys::InputEvent::new_with_event_init_dict("input", &init).expect("input event");
    input.dispatch_event(&event).expect("dispatch");
    settle().await;
}

/// A key pressed on the element `selector` (bubbling like a real key press).
pub async fn key_on(root: &Element, selector: &str, key: &str) {
    let init = KeyboardEventInit::new();
    init.set_key(key);
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("keyboard event");
    query(root, selector)
        .unwrap_or_else(|| panic!("no element {selector}"))
        .dispatch_event(&event)
        .expect("dispatch");
    settle().await;
}

/// Waits (up to `ms`) until `selector` exists under `root`.
pub async fn wait_for(root: &Element, selector: &str, ms: u64) -> Option<Element> {
    let mut waited = 0;
    loop {
        if let Some(el) = query(root, selector) {
            return Some(el);
        }
        if waited >= ms {
            return None;
        }
        yew::platform::time::sleep(Duration::from_millis(25)).await;
        waited += 25;
    }
}

/// Waits (up to 3 s) until `check` holds: for what an effect starts and finishes later (an
/// animation frame, a timer, a worker), checked after each render and every 20 ms.
pub async fn eventually(mut check: impl FnMut() -> bool) -> bool {
    for _ in 0..150 {
        settle().await;
        if check() {
            return true;
        }
        yew::platform::time::sleep(Duration::from_millis(20)).await;
    }
    check()
}

/// Reads `probe` until `done` holds of what it read (up to 3 s, as [`eventually`]); the last
/// reading, for the assertion's message.
pub async fn until<T>(mut probe: impl FnMut() -> T, done: impl Fn(&T) -> bool) -> T {
    let mut last = probe();
    let _ = eventually(|| {
        last = probe();
        done(&last)
    })
    .await;
    last
}

/// A key pressed where nothing has the focus (BODY), as after a load or a re-rendered button.
pub async fn key_on_body(key: &str) {
    if let Some(el) = document().active_element().and_then(|e| e.dyn_into::<HtmlElement>().ok()) {
        el.blur().expect("blur");
    }
    let init = KeyboardEventInit::new();
    init.set_key(key);
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("event");
    document().body().expect("body").dispatch_event(&event).expect("dispatch");
    settle().await;
}

/// The shipped stylesheet, static/app.css, in the page's head (once): the browser tests mount
/// the components without the page that links it.
pub fn inject_app_css() {
    if document().get_element_by_id("app-css").is_some() {
        return;
    }
    let style = document().create_element("style").expect("style");
    style.set_id("app-css");
    style.set_text_content(Some(include_str!("../../static/app.css")));
    document().head().expect("head").append_child(&style).expect("append style");
}
