//! The dialog line with what is being typed, the one-line help, the message, the hard keys
//! (ENT, NO ENT, END, DEL, digits, −/+) and the live preview of the plane.

use glam::DMat3;
use yew::prelude::*;

use schwenkbar_app::dialog::{Dialog, Key};
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::preview::{orientation_of, strokes};
use schwenkbar_app::state::Action;
use schwenkbar_core::plane::Word;

#[derive(Properties, PartialEq)]
pub struct DialogAreaProps {
    pub dialog: Option<Dialog>,
    /// The dialog line (the dialog's prompt or message, or what the control reports).
    pub text: AttrValue,
    pub lang: Lang,
    pub on_action: Callback<Action>,
}

#[function_component(DialogArea)]
pub fn dialog_area(props: &DialogAreaProps) -> Html {
    let act = |a: Action| props.on_action.reform(move |_: MouseEvent| a.clone());
    let in_dialog = props.dialog.is_some();
    let (ent, noent, end) = if in_dialog {
        (Action::DialogKey(Key::Ent), Action::DialogKey(Key::NoEnt), Action::DialogKey(Key::End))
    } else {
        (Action::Open, Action::Back, Action::Back)
    };
    let hard_keys = html! {
        <div class="hard-keys">
            <button class="hard-key" data-key="ent" onclick={act(ent)}>{ "ENT" }</button>
            <button class="hard-key" data-key="noent" disabled={!in_dialog} onclick={act(noent)}>{ "NO ENT" }</button>
            <button class="hard-key" data-key="end" onclick={act(end)}>{ "END" }</button>
            <button class="hard-key" data-key="del" disabled={!in_dialog} onclick={act(Action::Abort)}>{ "DEL" }</button>
        </div>
    };
    match &props.dialog {
        None => html! {
            <div class="dialog-area">
                <div class="dialog-line" role="status" aria-live="polite">{ props.text.clone() }</div>
                { hard_keys }
            </div>
        },
        Some(d) => open_dialog(props, d, hard_keys),
    }
}

/// The area with a dialog open. Out of line: the first screen has no dialog open, so the page
/// split (scripts/split_pages.py) leaves this to the wasm loaded after it.
#[inline(never)]
fn open_dialog(props: &DialogAreaProps, d: &Dialog, hard_keys: Html) -> Html {
    let l = props.lang;
    let act = |a: Action| props.on_action.reform(move |_: MouseEvent| a.clone());
    let keypad = "789456123".chars().chain(['0', '.']).map(|c| {
        html! { <button class="pad-key" data-key={format!("pad-{c}")} onclick={act(Action::DialogKey(Key::Char(c)))}>{ c }</button> }
    });
    let preview = d.preview().and_then(|def| orientation_of(&def, DMat3::IDENTITY)).map(|r| {
        html! {
            <svg class="plane-preview" viewBox="-100 -100 200 200" role="img"
                aria-label={l.t("Vorschau der Ebene", "Preview of the plane")}>
                { for strokes(&r).into_iter().map(|s| html! {
                    <line class={s.class} x1={fmt(s.from.0)} y1={fmt(s.from.1)} x2={fmt(s.to.0)} y2={fmt(s.to.1)} />
                }) }
            </svg>
        }
    });
    html! {
        <div class="dialog-area open">
            <div class="dialog-main">
                <div class={classes!("dialog-line", d.message.is_some().then_some("error"))} role="status" aria-live="polite">
                    { props.text.clone() }
                </div>
                if d.takes_value() {
                    <div class="dialog-input">
                        <span class="word">{ d.word().map_or("", Word::as_str) }</span>
                        <span class="value" data-testid="dialog-input">{ d.input.clone() }</span>
                        <span class="caret" aria-hidden="true">{ "▏" }</span>
                    </div>
                }
                // Only the German wording can be unconfirmed (the English prompts are the
                // manual's): said on hover, not on every prompt a trainee reads.
                <div class="dialog-help" title={d.wording().filter(|_| l == Lang::De).map(|w| w.text().get(l).to_owned())}>
                    { d.help().get(l) }
                </div>
                <div class="keys-hint">
                    { l.t("Tastatur: Enter = ENT · Umschalt+Enter = NO ENT · Ende = END · Esc = DEL · F1–F8 = Softkeys",
                          "Keyboard: Enter = ENT · Shift+Enter = NO ENT · End = END · Esc = DEL · F1–F8 = softkeys") }
                </div>
            </div>
            if d.takes_value() {
                <div class="keypad">
                    { for keypad }
                    <button class="pad-key" data-key="pad-sign" onclick={act(Action::DialogKey(Key::ToggleSign))}>{ "−/+" }</button>
                    <button class="pad-key" data-key="pad-q" onclick={act(Action::DialogKey(Key::Char('Q')))}>{ "Q" }</button>
                    <button class="pad-key" data-key="pad-back" onclick={act(Action::DialogKey(Key::Backspace))}>{ "⌫" }</button>
                </div>
            }
            { for preview }
            { hard_keys }
        </div>
    }
}

fn fmt(x: f64) -> String {
    format!("{x:.2}")
}
