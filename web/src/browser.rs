//! The browser side of the app's side effects: localStorage, the URL fragment, downloads and
//! file import. Every failure becomes a message for the dialog line, never a panic.

use js_sys::{Array, Uint8Array};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_futures::JsFuture;
use web_sys::{Blob, BlobPropertyBag, File, HtmlAnchorElement, Url};

use crate::i18n::Text;
use crate::persist::{PROGRAM_KEY, STATE_KEY};

fn storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok()?
}

/// The saved state's JSON and program text, if there are.
#[must_use]
pub fn load_saved() -> (Option<String>, Option<String>) {
    let Some(s) = storage() else { return (None, None) };
    (s.get_item(STATE_KEY).ok().flatten(), s.get_item(PROGRAM_KEY).ok().flatten())
}

const REFUSED: Text = Text::new(
    "Programm kann im Browser nicht gespeichert werden (Speicher voll oder gesperrt)",
    "The program cannot be kept in the browser (storage full or blocked)",
);

/// Saves the small state (cursor, machine, language); a blocked storage is reported.
pub fn save_state(json: &str) -> Result<(), Text> {
    storage().ok_or(REFUSED)?.set_item(STATE_KEY, json).map_err(|_| REFUSED)
}

/// Saves the program text; a full storage (programs of several MB) is reported.
pub fn save_program(text: &str) -> Result<(), Text> {
    storage().ok_or(REFUSED)?.set_item(PROGRAM_KEY, text).map_err(|_| REFUSED)
}

/// The URL fragment (`#…`), if any.
#[must_use]
pub fn fragment() -> Option<String> {
    web_sys::window()?.location().hash().ok().filter(|h| h.len() > 1)
}

/// Puts the share link into the address bar.
pub fn set_fragment(fragment: &str) -> Result<(), Text> {
    let failed = Text::new("Link konnte nicht gesetzt werden", "The link could not be set");
    let location = web_sys::window().ok_or(failed)?.location();
    location.set_hash(fragment).map_err(|_| failed)
}

/// Offers `bytes` as a file download named `name`.
pub fn download(name: &str, bytes: &[u8]) -> Result<(), Text> {
    let failed = Text::new("Herunterladen nicht möglich", "Download not possible");
    let parts = Array::of1(&Uint8Array::from(bytes).into());
    let options = BlobPropertyBag::new();
    options.set_type("text/plain");
    let blob = Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(|_| failed)?;
    let url = Url::create_object_url_with_blob(&blob).map_err(|_| failed)?;
    let document = web_sys::window().and_then(|w| w.document()).ok_or(failed)?;
    let anchor: HtmlAnchorElement =
        document.create_element("a").map_err(|_| failed)?.dyn_into().map_err(|_| failed)?;
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

/// The saved course progress record, if there is one.
#[must_use]
pub fn load_course() -> Option<String> {
    storage()?.get_item(crate::course::progress::KEY).ok().flatten()
}

/// Saves the course progress; a blocked storage is reported.
pub fn save_course(text: &str) -> Result<(), Text> {
    storage().ok_or(REFUSED)?.set_item(crate::course::progress::KEY, text).map_err(|_| REFUSED)
}

/// Calls `f` with the new URL fragment whenever it changes, until the guard is dropped.
pub struct HashListener {
    closure: Option<wasm_bindgen::closure::Closure<dyn FnMut()>>,
}

impl Drop for HashListener {
    fn drop(&mut self) {
        if let (Some(window), Some(c)) = (web_sys::window(), self.closure.take()) {
            // Removing can only fail for a listener never added: nothing left to do then.
            let _ = window.remove_event_listener_with_callback("hashchange", c.as_ref().unchecked_ref());
        }
    }
}

/// Listens to `hashchange`; without a window (never in a browser) the guard does nothing.
#[must_use]
pub fn on_hash_change(mut f: impl FnMut(String) + 'static) -> HashListener {
    let closure =
        wasm_bindgen::closure::Closure::<dyn FnMut()>::new(move || f(fragment().unwrap_or_default()));
    let added = web_sys::window().is_some_and(|w| {
        w.add_event_listener_with_callback("hashchange", closure.as_ref().unchecked_ref()).is_ok()
    });
    HashListener { closure: added.then_some(closure) }
}
