//! The browser side of the app's side effects: localStorage, the URL fragment, downloads and
//! file import. Every failure becomes a message for the dialog line, never a panic.

use js_sys::{Array, Uint8Array};
use wasm_bindgen::closure::Closure;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_futures::JsFuture;
use web_sys::{Blob, BlobPropertyBag, Element, File, HtmlAnchorElement, HtmlElement, KeyboardEvent, Url};

use schwenkbar_app::i18n::Text;
use schwenkbar_app::persist::{COURSE_KEY, PREFS_KEY, PROGRAM_KEY, Prefs, REPLACED_KEY, STATE_KEY, Stored};
use schwenkbar_app::saved_machines::MACHINES_KEY;
use schwenkbar_app::tool_table::TOOLS_KEY;

fn storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok()?
}

fn load(key: &str) -> Option<String> {
    storage()?.get_item(key).ok().flatten()
}

/// What the trainer kept: its small state, the shared preferences, the program text and the
/// machine editor's own machines.
#[must_use]
pub fn load_stored() -> Stored {
    Stored {
        state: load(STATE_KEY),
        prefs: load_prefs(),
        program: load(PROGRAM_KEY),
        machines: load(MACHINES_KEY),
        replaced: load(REPLACED_KEY),
        tools: load(TOOLS_KEY),
    }
}

/// The machine editor's own machines, the shared preferences and the shop's tool table.
#[must_use]
pub fn load_editor() -> (Option<String>, Option<String>, Option<String>) {
    (load(MACHINES_KEY), load_prefs(), load(TOOLS_KEY))
}

/// Goes to another page of the app (relative `url`); without a window nothing happens.
pub fn open_page(url: &str) {
    if let Some(window) = web_sys::window() {
        // Failing leaves the trainer as it is; the trainee can open the page by its address.
        let _ = window.location().assign(url);
    }
}

/// The course's progress record and the shared preferences.
#[must_use]
pub fn load_course() -> (Option<String>, Option<String>) {
    (load(COURSE_KEY), load_prefs())
}

/// The shared preferences; on a first visit (none saved) the browser's language, which the
/// page then saves, so a choice made later stays.
fn load_prefs() -> Option<String> {
    load(PREFS_KEY).or_else(|| {
        let language = web_sys::window()?.navigator().language()?;
        Some(Prefs::first_visit(&language).to_record())
    })
}

const REFUSED: Text = Text::new(
    "Programm im Browser nicht gespeichert (zu groß, Speicher voll oder gesperrt): es bleibt geöffnet, mit HERUNTERLADEN sichern",
    "The program is not kept in the browser (too large, storage full or blocked): it stays open, keep it with DOWNLOAD",
);

/// Keeps `value` under `key`; a full (programs of several MB) or blocked storage is reported.
pub fn save(key: &str, value: &str) -> Result<(), Text> {
    storage().ok_or(REFUSED)?.set_item(key, value).map_err(|_| REFUSED)
}

/// The URL fragment (`#…`), if any.
#[must_use]
pub fn fragment() -> Option<String> {
    web_sys::window()?.location().hash().ok().filter(|h| h.len() > 1)
}

/// Puts the share link into the address bar.
pub fn set_fragment(fragment: &str) -> Result<(), Text> {
    const FAILED: Text = Text::new("Link konnte nicht gesetzt werden", "The link could not be set");
    let location = web_sys::window().ok_or(FAILED)?.location();
    location.set_hash(fragment).map_err(|_| FAILED)
}

/// Offers `bytes` as a file download named `name`.
pub fn download(name: &str, bytes: &[u8]) -> Result<(), Text> {
    const FAILED: Text = Text::new("Herunterladen nicht möglich", "Download not possible");
    let parts = Array::of1(&Uint8Array::from(bytes).into());
    let options = BlobPropertyBag::new();
    options.set_type("text/plain");
    let blob = Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(|_| FAILED)?;
    let url = Url::create_object_url_with_blob(&blob).map_err(|_| FAILED)?;
    let document = web_sys::window().and_then(|w| w.document()).ok_or(FAILED)?;
    let anchor: HtmlAnchorElement =
        document.create_element("a").map_err(|_| FAILED)?.dyn_into().map_err(|_| FAILED)?;
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.click();
    // The click has handed the data to the browser; the URL is not needed any more.
    let _ = Url::revoke_object_url(&url);
    Ok(())
}

/// Reads a file the trainee picked, as bytes.
pub async fn read_file(file: File) -> Result<Vec<u8>, Text> {
    let buffer: JsValue = JsFuture::from(file.array_buffer())
        .await
        .map_err(|_| Text::new("Datei konnte nicht gelesen werden", "The file could not be read"))?;
    Ok(Uint8Array::new(&buffer).to_vec())
}

/// An event listener on the window, removed when the guard is dropped (a component's effect
/// returns it as its destructor).
pub struct Listener {
    event: &'static str,
    closure: Option<Closure<dyn FnMut(web_sys::Event)>>,
}

impl Drop for Listener {
    fn drop(&mut self) {
        if let (Some(window), Some(c)) = (web_sys::window(), self.closure.take()) {
            // Removing can only fail for a listener never added: nothing left to do then.
            let _ = window.remove_event_listener_with_callback(self.event, c.as_ref().unchecked_ref());
        }
    }
}

/// Listens to `event` on the window; without a window (never in a browser) the guard does
/// nothing.
#[must_use]
pub fn on_window(event: &'static str, f: impl FnMut(web_sys::Event) + 'static) -> Listener {
    let closure = Closure::<dyn FnMut(web_sys::Event)>::new(f);
    let added = web_sys::window()
        .is_some_and(|w| w.add_event_listener_with_callback(event, closure.as_ref().unchecked_ref()).is_ok());
    Listener { event, closure: added.then_some(closure) }
}

/// Calls `f` with the new URL fragment whenever it changes, until the guard is dropped.
#[must_use]
pub fn on_hash_change(mut f: impl FnMut(String) + 'static) -> Listener {
    on_window("hashchange", move |_| f(fragment().unwrap_or_default()))
}

/// The elements that own keys: the trainer (also a lesson's embedded one) and the course page.
const KEY_OWNERS: &str = ".tnc, [data-testid=course]";

/// Keys for the whole page, wherever the focus is (on BODY after a load or after the focused
/// softkey was re-rendered, on a view's checkbox or slider after a click), as long as the page
/// lives: `f` gets every keydown that no text field, focused button or canvas has taken and
/// that was pressed in `own` (the app's root element) or, unless `only_inside`, outside every
/// app — not inside another one, so a lesson's embedded trainer keeps its keys from the course
/// around it. Of the combinations with Ctrl only undo and redo (Ctrl+Z, Ctrl+Y, Ctrl+Shift+Z)
/// come through, also from the program's text area (its history is the trainer's). `f`
/// returns whether it used the key.
#[must_use]
pub fn on_page_keys(
    own: impl Fn() -> Option<Element> + 'static,
    only_inside: bool,
    mut f: impl FnMut(&KeyboardEvent) -> bool + 'static,
) -> Listener {
    on_window("keydown", move |e| {
        let Some(e) = e.dyn_ref::<KeyboardEvent>() else { return };
        let target = e.target().and_then(|t| t.dyn_into::<Element>().ok());
        let app = target.as_ref().and_then(|t| t.closest(KEY_OWNERS).ok().flatten());
        let key = e.key();
        let undo = (e.ctrl_key() || e.meta_key()) && matches!(key.as_str(), "z" | "Z" | "y" | "Y");
        // Inside an app, a key some element already used (a canvas's view keys, an answer
        // field's Enter) is not used twice; a key pressed outside every app is offered to each.
        if (app.is_some() && e.default_prevented())
            || e.alt_key()
            || ((e.ctrl_key() || e.meta_key()) && !undo)
        {
            return;
        }
        let mine = match (&own(), &app) {
            (Some(own), Some(app)) => own == app,
            (_, None) => !only_inside,
            (None, Some(_)) => false,
        };
        if !mine {
            return;
        }
        let tag = target.as_ref().map(Element::tag_name).unwrap_or_default();
        // Typing in a field belongs to the field, except the softkeys F1–F8 (and undo in the
        // program's text area). A checkbox, a slider or a button takes no letters: the page's
        // keys work there, as USAGE says.
        let function_key =
            key.len() >= 2 && key.starts_with('F') && key[1..].bytes().all(|b| b.is_ascii_digit());
        let types = match tag.as_str() {
            "TEXTAREA" | "SELECT" => true,
            "INPUT" => !matches!(
                target.as_ref().and_then(|t| t.get_attribute("type")).as_deref(),
                Some("checkbox" | "radio" | "range" | "button" | "submit" | "reset" | "color" | "file")
            ),
            _ => false,
        };
        let program_undo =
            undo && target.as_ref().is_some_and(|t| t.matches(".program-text").unwrap_or(false));
        if types && !function_key && !program_undo {
            return;
        }
        // Enter and Space on a focused button press that button, as everywhere on the web.
        if matches!(tag.as_str(), "BUTTON" | "A") && matches!(key.as_str(), "Enter" | " ") {
            return;
        }
        if f(e) {
            e.prevent_default();
        }
    })
}

/// The share link: this page's address with `fragment`.
#[must_use]
pub fn share_url(fragment: &str) -> Option<String> {
    let href = web_sys::window()?.location().href().ok()?;
    let base = href.split('#').next().unwrap_or(&href);
    Some(format!("{base}#{fragment}"))
}

/// Puts `text` on the clipboard. Fails where the browser has no clipboard API (a page not
/// served from a secure origin such as a classroom server's LAN address) or refuses it.
pub async fn copy_to_clipboard(text: &str) -> Result<(), ()> {
    let navigator = web_sys::window().ok_or(())?.navigator();
    // `navigator.clipboard` is undefined outside secure contexts: calling into it would throw.
    let api = js_sys::Reflect::get(&navigator, &JsValue::from_str("clipboard")).map_err(|_| ())?;
    if api.is_undefined() || api.is_null() {
        return Err(());
    }
    JsFuture::from(navigator.clipboard().write_text(text)).await.map(|_| ()).map_err(|_| ())
}

/// Resolves once the code the page loads after its first screen is there: the split page's
/// loader (`scripts/split_pages.py`) sets `__schwenkbarSplitReady` to a promise that resolves
/// when that code has arrived (never when its load failed: the first key then loads it, as any
/// action simulates first). A page built whole has no such promise: at once.
pub async fn deferred_code() {
    let ready = js_sys::Reflect::get(&js_sys::global(), &JsValue::from_str("__schwenkbarSplitReady"));
    if let Ok(promise) = ready.and_then(|r| r.dyn_into::<js_sys::Promise>()) {
        let _ = JsFuture::from(promise).await;
    }
}

/// Takes the fragment out of the address bar without a reload or a new history entry.
pub fn consume_fragment() {
    let Some(window) = web_sys::window() else { return };
    let location = window.location();
    let (Ok(path), Ok(search)) = (location.pathname(), location.search()) else { return };
    if let Ok(history) = window.history() {
        // Failing leaves the fragment in place; the trainee's own program is still kept, since
        // a link over it opens as a preview.
        let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&format!("{path}{search}")));
    }
}

/// Clicks the file input inside `root` (the IMPORT softkey), which opens the file picker; the
/// key press that asked for it counts as the user's gesture.
pub fn pick_file(root: &Element) {
    if let Ok(Some(input)) = root.query_selector("input.file-input")
        && let Ok(input) = input.dyn_into::<HtmlElement>()
    {
        input.click();
    }
}

/// Moves the keyboard focus to the first element matching `selector` inside `root`.
pub fn focus(root: &Element, selector: &str) {
    if let Ok(Some(el)) = root.query_selector(selector)
        && let Ok(el) = el.dyn_into::<HtmlElement>()
    {
        let _ = el.focus();
    }
}
