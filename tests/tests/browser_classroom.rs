//! Issue 12's defects, driven as a trainee would: keys wherever the focus is, the DATEI row by
//! function keys, share links over own work, diagnostics by block, a binary import, the scrub
//! slider and the position display. Headless Chromium (scripts/test.sh).
#![cfg(target_arch = "wasm32")]

use std::cell::Cell;
use std::rc::Rc;

use schwenkbar_app::state::{Action, AppState, Reducer};
use schwenkbar_tests::browser::{
    clear_storage, click, document, eventually, key_on, key_on_body, mount, mount_at, paste_program,
    program_lines, query, settle, text, unmount, until, wait_for,
};
use wasm_bindgen::JsCast;
use wasm_bindgen::closure::Closure;
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{Element, HtmlElement};

wasm_bindgen_test_configure!(run_in_browser);

fn storage() -> web_sys::Storage {
    web_sys::window().and_then(|w| w.local_storage().ok().flatten()).expect("localStorage")
}

#[wasm_bindgen_test]
async fn keys_work_from_the_load_on_and_after_a_click_wherever_the_focus_is() {
    clear_storage();
    let root = mount().await;
    key_on_body("F1").await;
    assert!(eventually(|| query(&root, "[data-key=tilt-plane]").is_some()).await, "F1 = SPEC FCT on BODY");
    click(&root, "[data-key=tilt-plane]").await;
    key_on_body("F1").await;
    assert!(
        eventually(|| text(&root, ".dialog-line") == "Raumwinkel A?").await,
        "F1 = SPATIAL after a click"
    );
    key_on_body("Escape").await;
    key_on_body("End").await;
    key_on_body("End").await;
    // Enter on a focused softkey presses that softkey (the browser's own button action), it
    // does not open the cursor's PLANE block as ENT would.
    click(&root, ".program-pane .line[data-line='11']").await;
    let softkey = query(&root, "[data-key=samples]").expect("BEISPIEL ÖFFNEN");
    softkey.clone().dyn_into::<HtmlElement>().expect("button").focus().expect("focus");
    key_on(&root, "[data-key=samples]", "Enter").await;
    assert!(query(&root, ".dialog-area.open").is_none(), "Enter on a softkey is not ENT");
    key_on_body("p").await;
    assert!(eventually(|| query(&root, ".tnc.projector").is_some()).await, "p: projector mode from BODY");
    key_on_body("p").await;
}

#[wasm_bindgen_test]
async fn the_files_row_works_by_function_keys() {
    clear_storage();
    let root = mount().await;
    key_on(&root, ".tnc", "F5").await;
    assert!(eventually(|| query(&root, "input.file-input").is_some()).await, "F5 DATEI");
    // F1 IMPORT opens the file picker: the file input is clicked.
    let clicked = Rc::new(Cell::new(false));
    let flag = clicked.clone();
    let on_click = Closure::<dyn FnMut(web_sys::Event)>::new(move |e: web_sys::Event| {
        flag.set(true);
        e.prevent_default(); // no real picker in the test
    });
    let input = query(&root, "input.file-input").expect("the IMPORT softkey's file input");
    input.add_event_listener_with_callback("click", on_click.as_ref().unchecked_ref()).expect("listen");
    key_on(&root, ".tnc", "F1").await;
    assert!(eventually(|| clicked.get()).await, "F1 IMPORT opened the file picker");
    key_on(&root, ".tnc", "F2").await;
    assert!(
        eventually(|| text(&root, ".dialog-line") == "Programm wird als .h-Datei heruntergeladen").await,
        "F2 HERUNTERLADEN"
    );
    key_on(&root, ".tnc", "F3").await;
    // The clipboard answers later (a promise): waited for on the dialog line.
    let line = until(|| text(&root, ".dialog-line"), |l| l.starts_with("Link")).await;
    assert!(
        line == "Link in die Zwischenablage kopiert: einfügen und weitergeben"
            || line == "Link steht in der Adresszeile: kopieren und weitergeben",
        "{line}"
    );
    let location = web_sys::window().expect("window").location();
    if line.contains("Adresszeile") {
        assert!(
            location.hash().expect("hash").starts_with("#pgm="),
            "the fallback puts the link in the address bar"
        );
    }
    location.set_hash("").expect("clear the hash for later tests");
}

#[wasm_bindgen_test]
async fn text_editing_takes_the_focus_and_keeps_its_letters() {
    clear_storage();
    let root = mount().await;
    key_on(&root, ".tnc", "F4").await;
    let focused =
        || document().active_element().map(|e| e.class_name()).unwrap_or_default() == "program-text";
    assert!(eventually(focused).await, "F4 TEXT EDITIEREN focuses the editor");
    key_on(&root, ".program-text", "p").await;
    assert!(query(&root, ".tnc.projector").is_none(), "p typed in the editor is a letter");
    key_on(&root, ".program-text", "F4").await;
}

#[wasm_bindgen_test]
async fn a_share_link_over_own_work_asks_before_it_replaces_anything() {
    clear_storage();
    let own = "0 BEGIN PGM MEIN MM\n1 L Z+0 R0 FMAX M91\n2 END PGM MEIN MM\n";
    storage().set_item("schwenkbar.program", own).expect("save");
    let link = AppState::default().apply(Action::LoadSample("stay_q120".into())).0.share_fragment();
    let location = web_sys::window().expect("window").location();
    location.set_hash(&link).expect("open the link");
    let root = mount().await;
    assert!(eventually(|| query(&root, "[data-key=take-link]").is_some()).await, "Übernehmen?");
    assert!(location.hash().expect("hash").is_empty(), "the fragment is read once");
    assert!(program_lines(&root)[0].contains("STAY_Q120"), "the link's program is shown");
    assert_eq!(
        storage().get_item("schwenkbar.program").ok().flatten().as_deref(),
        Some(own),
        "nothing saved yet"
    );
    key_on(&root, ".tnc", "F2").await;
    assert!(eventually(|| program_lines(&root)[0].contains("MEIN")).await, "EIGENES BEHALTEN");
    let again = mount().await;
    assert!(program_lines(&again)[0].contains("MEIN"), "a reload shows the own program");
    assert!(query(&again, "[data-key=take-link]").is_none());

    location.set_hash(&link).expect("open the link again");
    let root = mount().await;
    assert!(eventually(|| query(&root, "[data-key=take-link]").is_some()).await);
    key_on(&root, ".tnc", "F1").await;
    assert!(eventually(|| query(&root, "[data-key=take-link]").is_none()).await, "LINK ÜBERNEHMEN");
    assert!(program_lines(&root)[0].contains("STAY_Q120"));
    let again = mount().await;
    assert!(program_lines(&again)[0].contains("STAY_Q120"), "the taken link is the own program now");
}

#[wasm_bindgen_test]
async fn diagnostics_name_the_block_and_an_error_is_not_hidden_by_a_warning() {
    clear_storage();
    let root = mount().await;
    paste_program(
        &root,
        "0 BEGIN PGM T MM\n1 PLANE SPATIAL SPA+400 SPB+0 SPC+0 STAY\nL X+1\n2 END PGM T MM\n",
    )
    .await;
    assert_eq!(text(&root, ".summary"), "1 Fehler · 1 Warnung");
    let inline = text(&root, ".line[data-line='2'] .diag-inline");
    assert!(inline.starts_with("Winkel nicht erlaubt"), "the error, not the warning: {inline}");
    click(&root, "[data-key=text-edit]").await;
    let list = text(&root, ".diag-list");
    assert!(list.contains("Satz 1: Winkel nicht erlaubt"), "{list}");
    click(&root, "[data-key=text-edit]").await;
}

#[wasm_bindgen_test]
async fn a_binary_file_is_not_imported() {
    clear_storage();
    let root = mount().await;
    let before = program_lines(&root);
    key_on(&root, ".tnc", "F5").await;
    let bytes = js_sys::Uint8Array::from(&b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0"[..]);
    let parts = js_sys::Array::of1(&bytes.into());
    let file = web_sys::File::new_with_u8_array_sequence(&parts, "bild.png").expect("file");
    let transfer = web_sys::DataTransfer::new().expect("data transfer");
    transfer.items().add_with_file(&file).expect("add");
    let input: web_sys::HtmlInputElement =
        query(&root, "input.file-input").expect("file input").dyn_into().expect("input");
    input.set_files(transfer.files().as_ref());
    input.dispatch_event(&web_sys::Event::new("change").expect("event")).expect("dispatch");
    // The file is read later (a FileReader): waited for on the dialog line.
    let line = until(|| text(&root, ".dialog-line"), |l| l.contains("NC-Programm")).await;
    assert_eq!(line, "Datei ist kein NC-Programm (Binärdatei): nicht importiert");
    assert_eq!(program_lines(&root), before, "the program stays");
}

fn cell(root: &Element, axis: &str, column: &str) -> String {
    text(root, &format!(".position tr[data-axis='{axis}'] td.{column}"))
}

#[wasm_bindgen_test]
async fn the_position_display_follows_the_scrub_slider_and_machines_have_names() {
    clear_storage();
    let root = mount().await;
    paste_program(&root, "0 BEGIN PGM S MM\n1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+50 R0 FMAX\n3 L X+100 F1000\n4 END PGM S MM\n")
        .await;
    click(&root, ".program-pane .line[data-line='4']").await;
    click(&root, "[data-key=lang]").await;
    click(&root, "[data-key=run]").await;
    assert!(text(&root, ".position thead").contains("ACTL."), "English screens say ACTL.");
    click(&root, "[data-key=back]").await;
    click(&root, "[data-key=lang]").await;
    click(&root, "[data-key=run]").await;
    assert!(text(&root, ".position thead").contains("IST"));
    assert_eq!(cell(&root, "X", "ist"), "+100.000");
    let scrub: web_sys::HtmlInputElement =
        query(&root, "[data-testid=scrub]").expect("slider").dyn_into().expect("input");
    scrub.set_value("500");
    let init = web_sys::InputEventInit::new();
    init.set_bubbles(true);
    scrub
        .dispatch_event(&web_sys::InputEvent::new_with_event_init_dict("input", &init).expect("event"))
        .expect("dispatch");
    settle().await;
    assert_eq!(cell(&root, "X", "ist"), "+50.000", "halfway through L X+100");
    let work = "[data-view=work]";
    let pressed = |root: &Element| query(root, work).and_then(|b| b.get_attribute("aria-pressed"));
    assert_eq!(pressed(&root).as_deref(), Some("true"), "a run frames the workpiece by default");
    click(&root, work).await;
    assert_eq!(pressed(&root).as_deref(), Some("false"), "the switch turns it off");
    click(&root, work).await;
    click(&root, "[data-key=back]").await;
    click(&root, "[data-key=machines]").await;
    assert_eq!(text(&root, "[data-key=machine-ac-table]"), "C-RundtischaufA-Schwenktisch");
}

#[wasm_bindgen_test]
async fn the_why_panel_says_it_in_plain_words_first() {
    clear_storage();
    let root = mount().await;
    // Musterprogramm 1, block 10: PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN … on the A/C table.
    click(&root, ".program-pane .line[data-line='11']").await;
    assert_eq!(
        text(&root, "[data-testid=why-plain]"),
        "Keine B-Achse: C dreht auf +90°, dann kippt A auf +15°."
    );
    let why = query(&root, ".why-panel").and_then(|w| w.text_content()).unwrap_or_default();
    let plain_at = why.find("Keine B-Achse").expect("plain words");
    let vector_at = why.find("Werkzeugachse").expect("the tool axis vector");
    assert!(plain_at < vector_at, "plain words before the vector");
    assert!(why.contains("Weg ") && why.contains(",0°"), "German path with a decimal comma: {why}");
}

#[wasm_bindgen_test]
async fn in_projector_mode_the_run_asks_the_class_before_a_swivel() {
    clear_storage();
    let root = mount().await;
    key_on(&root, ".tnc", "p").await;
    // Musterprogramm 1: the cursor on block 9, then NC start steps towards block 10's swivel.
    click(&root, ".program-pane .line[data-line='10']").await;
    click(&root, "[data-key=run]").await;
    click(&root, "[data-key=run-next]").await;
    assert_eq!(
        text(&root, ".dialog-line"),
        "Vorhersage: Wohin schwenkt der Tisch? Welche Werte haben A und C? NC-Start zeigt es."
    );
    assert_eq!(text(&root, "[data-key=run-next]"), "ZEIGEN ▶");
    assert_eq!(cell(&root, "A", "ref"), "+0.000", "nothing has moved yet");
    click(&root, "[data-key=run-next]").await;
    assert!(eventually(|| cell(&root, "A", "ref") == "+15.000").await, "revealed: A+15");
    key_on(&root, ".tnc", "End").await;
    key_on(&root, ".tnc", "p").await;
}

#[wasm_bindgen_test]
async fn the_h_key_shows_the_right_hand_rule_on_the_cursor_plane_block() {
    clear_storage();
    let root = mount().await;
    click(&root, ".program-pane .line[data-line='11']").await;
    key_on(&root, ".tnc", "h").await;
    assert!(eventually(|| query(&root, ".rh-of-block").is_some()).await, "the demo on block 10");
    let of_block = text(&root, ".rh-of-block");
    assert!(of_block.contains("SPA+0 SPB+15 SPC+0"), "{of_block}");
    key_on(&root, ".tnc", "h").await;
    assert!(eventually(|| query(&root, "canvas.view3d").is_some()).await, "h again: the machine");
}

#[wasm_bindgen_test]
async fn the_course_takes_its_keys_from_the_load_and_an_embedded_trainer_keeps_its_own() {
    clear_storage();
    let root = mount_at("#kurs/3").await;
    wait_for(&root, "[data-lesson='3']", 5_000).await.expect("lesson 3");
    wait_for(&root, ".tnc[data-keys]", 5_000).await.expect("lesson 3 embeds the trainer");
    key_on(&root, ".tnc", "PageDown").await;
    settle().await;
    assert!(query(&root, "[data-lesson='3']").is_some(), "PageDown in the trainer stays in the lesson");
    key_on_body("i").await;
    assert!(eventually(|| query(&root, ".course.projector").is_some()).await, "I on BODY: instructor view");
    assert!(
        eventually(|| query(&root, ".tnc.projector[data-keys]").is_some()).await,
        "the instructor view shows the lesson's trainer in projector mode"
    );
    key_on_body("i").await;
    assert!(eventually(|| query(&root, ".course.projector").is_none()).await);
    key_on_body("PageDown").await;
    assert!(wait_for(&root, "[data-lesson='4']", 3_000).await.is_some(), "PageDown on BODY: next lesson");
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

#[wasm_bindgen_test]
async fn hovering_a_candidate_in_the_why_panel_shows_it_as_the_ghost() {
    clear_storage();
    let root = mount().await;
    click(&root, ".program-pane .line[data-line='11']").await;
    let ghost = |root: &Element| query(root, ".view-pane").and_then(|v| v.get_attribute("data-ghost"));
    assert_eq!(ghost(&root).as_deref(), Some("A-15 C-90"), "the other solution by default");
    let chosen = query(&root, ".candidate.chosen").expect("the chosen candidate");
    chosen.dispatch_event(&web_sys::MouseEvent::new("mouseenter").expect("event")).expect("hover");
    assert!(eventually(|| ghost(&root).as_deref() == Some("A+15 C+90")).await, "the hovered one");
    chosen.dispatch_event(&web_sys::MouseEvent::new("mouseleave").expect("event")).expect("leave");
    assert!(eventually(|| ghost(&root).as_deref() == Some("A-15 C-90")).await, "back to the other one");
}

// Classroom trial II.

#[wasm_bindgen_test]
async fn the_classroom_slip_never_loses_the_program_and_ctrl_z_brings_it_back() {
    use schwenkbar_tests::browser::key_ctrl;
    clear_storage();
    let root = mount().await;
    let own = "0 BEGIN PGM MEIN MM\n1 L Z+0 R0 FMAX M91\n2 END PGM MEIN MM\n";
    paste_program(&root, own).await;
    // edit → F6 → F2 → F3 (◀ SATZ ZURÜCK) → F8 (END) → F3 F3
    for k in ["F6", "F2", "F3", "F8", "F3", "F3"] {
        key_on(&root, ".tnc", k).await;
    }
    assert!(program_lines(&root)[0].contains("MEIN"), "the own program is still there");
    assert!(text(&root, ".dialog-line").contains("nicht exportiert"), "{}", text(&root, ".dialog-line"));
    assert!(query(&root, "[data-key=confirm-replace]").is_some());
    key_on(&root, ".tnc", "F1").await;
    assert!(eventually(|| !program_lines(&root)[0].contains("MEIN")).await, "PROGRAMM ERSETZEN");
    // The replaced program is kept by an effect after the render: waited for, not read at once.
    assert!(
        eventually(|| storage().get_item("schwenkbar.replaced").ok().flatten().as_deref() == Some(own)).await,
        "the replaced program is kept"
    );
    key_ctrl(&root, "z").await;
    assert!(eventually(|| program_lines(&root)[0].contains("MEIN")).await, "Ctrl+Z: the own program back");
    key_ctrl(&root, "y").await;
    assert!(eventually(|| !program_lines(&root)[0].contains("MEIN")).await, "Ctrl+Y: replaced again");
    // After a reload the replaced program is still one undo step away, by the softkey too.
    let again = mount().await;
    key_on(&again, ".tnc", "F5").await;
    click(&again, "[data-key=undo]").await;
    assert!(eventually(|| program_lines(&again)[0].contains("MEIN")).await, "RÜCKGÄNGIG after a reload");
    unmount(&again);
    unmount(&root);
}

#[wasm_bindgen_test]
async fn keys_work_after_a_click_on_a_view_checkbox_or_the_slider() {
    clear_storage();
    let root = mount().await;
    key_on(&root, ".tnc", "F6").await;
    let boxes =
        root.query_selector_all(".tnc input[type=checkbox], .tnc input[type=range]").expect("selector");
    assert!(boxes.length() > 0, "the run shows view switches or the slider");
    for i in 0..boxes.length() {
        let el: HtmlElement = boxes.item(i).expect("item").dyn_into().expect("element");
        el.focus().expect("focus");
        let before = query(&root, ".tnc.projector").is_some();
        let init = web_sys::KeyboardEventInit::new();
        init.set_key("p");
        init.set_bubbles(true);
        init.set_cancelable(true);
        let event =
            web_sys::KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("event");
        el.dispatch_event(&event).expect("dispatch");
        settle().await;
        assert_ne!(query(&root, ".tnc.projector").is_some(), before, "p from {:?}", el.outer_html());
    }
    unmount(&root);
}

#[wasm_bindgen_test]
async fn a_course_answer_field_keeps_the_keyboard_through_check_and_correction() {
    use schwenkbar_tests::browser::type_into;
    clear_storage();
    let root = mount_at("#kurs/2").await;
    wait_for(&root, "[data-lesson='2']", 5_000).await.expect("lesson 2");
    let field = "[data-testid=answer-0]";
    let input: HtmlElement = query(&root, field).expect("answer field").dyn_into().expect("input");
    input.focus().expect("focus");
    settle().await;
    type_into(&root, field, "falsch").await;
    key_on(&root, field, "Enter").await;
    let focused = || {
        document().active_element().and_then(|e| e.get_attribute("data-testid")).as_deref()
            == Some("answer-0")
    };
    assert!(wait_for(&root, "[data-testid=verdict-0]", 3_000).await.is_some(), "checked");
    assert!(eventually(focused).await, "the field keeps the focus after Enter");
    type_into(&root, field, "falsch2").await;
    assert!(eventually(focused).await, "and after the first edit of a wrong answer");
    // Letters and arrows typed there are the field's, not the page's shortcuts.
    for k in ["i", "p", "ArrowRight", "PageDown"] {
        let active = document().active_element().expect("active");
        let init = web_sys::KeyboardEventInit::new();
        init.set_key(k);
        init.set_bubbles(true);
        init.set_cancelable(true);
        let event =
            web_sys::KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init).expect("event");
        active.dispatch_event(&event).expect("dispatch");
        settle().await;
        assert!(query(&root, ".course.projector").is_none(), "{k} is no shortcut in the field");
        assert!(query(&root, "[data-lesson='2']").is_some(), "{k} leaves the lesson alone");
    }
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

#[wasm_bindgen_test]
async fn a_first_visit_follows_the_browsers_language_and_prompts_carry_no_internal_note() {
    if let Some(s) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) {
        s.clear().expect("clear");
    }
    let language = web_sys::window().expect("window").navigator().language().unwrap_or_default();
    let root = mount().await;
    let want = if language.to_ascii_lowercase().starts_with("de") { "de" } else { "en" };
    let lang = query(&root, ".tnc").and_then(|t| t.get_attribute("lang"));
    assert_eq!(lang.as_deref(), Some(want), "navigator.language = {language}");
    // The choice stays once made: the page saved it.
    assert!(
        eventually(|| storage()
            .get_item("schwenkbar.prefs")
            .ok()
            .flatten()
            .is_some_and(|p| p.contains(want)))
        .await
    );
    unmount(&root);
    clear_storage();
    let root = mount().await;
    key_on(&root, ".tnc", "F1").await;
    key_on(&root, ".tnc", "F3").await;
    key_on(&root, ".tnc", "F1").await;
    assert!(eventually(|| query(&root, ".dialog-area.open").is_some()).await, "the SPATIAL dialog");
    assert!(!text(&root, ".dialog-area").contains("unbestätigt"), "{}", text(&root, ".dialog-area"));
    unmount(&root);
}

#[wasm_bindgen_test]
async fn the_program_pane_stays_filled_when_the_run_reaches_the_end() {
    // The pane's scrolling comes with the shipped styles.
    schwenkbar_tests::browser::inject_app_css();
    clear_storage();
    let root = mount().await;
    root.set_attribute("style", "width: 1280px").expect("style");
    key_on(&root, ".tnc", "F6").await;
    // Screens of several heights: the last scroll asked for lies past the end on some.
    for height in [500, 800, 1000, 1300] {
        query(&root, ".tnc")
            .expect("app")
            .set_attribute("style", &format!("height: {height}px"))
            .expect("style");
        key_on(&root, ".tnc", "F4").await;
        let mut last = String::new();
        for _ in 0..200 {
            key_on(&root, ".tnc", "F2").await;
            let now = text(&root, ".program-pane .line.cursor");
            if now == last {
                break;
            }
            last = now;
        }
        assert!(last.contains("END PGM"), "the run reached the end: {last}");
        let scroller: HtmlElement =
            query(&root, ".program-pane .lines").expect("list").dyn_into().expect("element");
        let list: HtmlElement =
            query(&root, ".program-pane .blocks").expect("blocks").dyn_into().expect("element");
        let (top, height) = (scroller.scroll_top(), scroller.client_height());
        let (from, to) = (list.offset_top(), list.offset_top() + list.offset_height());
        let info =
            format!("{height} px: top {top} list {from}..{to} scroll height {}", scroller.scroll_height());
        assert!(from <= top, "the drawn lines start at or above the visible top: {info}");
        assert!(
            to >= top + height || to >= scroller.scroll_height() - 1,
            "the drawn lines reach the visible bottom: {info}"
        );
    }
    unmount(&root);
}

#[wasm_bindgen_test]
async fn the_collision_sample_stops_at_its_swivel_with_the_triads_out_of_the_way() {
    clear_storage();
    let root = mount().await;
    let checked = |root: &Element| {
        let list = root.query_selector_all("[data-triad]").expect("selector");
        (0..list.length())
            .filter_map(|i| list.item(i))
            .filter_map(|n| n.dyn_into::<web_sys::HtmlInputElement>().ok())
            .filter(|i| i.checked())
            .count()
    };
    key_on(&root, ".tnc", "F3").await;
    assert_eq!(text(&root, "[data-key=sample-kollision_schwenken]"), "Kollision beim Schwenken");
    click(&root, "[data-key=sample-kollision_schwenken]").await;
    assert!(eventually(|| program_lines(&root)[0].contains("KOLLISION")).await);
    key_on(&root, ".tnc", "F6").await;
    assert_eq!(checked(&root), 4, "a normal moment shows the four triads");
    for _ in 0..20 {
        key_on(&root, ".tnc", "F2").await;
    }
    assert!(
        eventually(|| text(&root, ".dialog-line").contains("Kollision")).await,
        "{}",
        text(&root, ".dialog-line")
    );
    assert!(text(&root, ".program-pane .line.cursor").contains("PLANE SPATIAL SPA-30"));
    assert!(eventually(|| checked(&root) == 0).await, "the collision moment hides the triads");
    unmount(&root);
}
