//! The row of eight softkeys at the bottom of the screen; F1–F8 press them too (keymap.rs).
//! The IMPORT softkey is a file picker: a browser opens one only on the user's own click.

use web_sys::{File, HtmlInputElement};
use yew::prelude::*;

use schwenkbar_app::softkeys::Row;
use schwenkbar_app::state::Action;

#[derive(Properties, PartialEq)]
pub struct SoftkeyRowProps {
    pub row: Row,
    /// The row's name and the way back ([`schwenkbar_app::softkeys::row_name`]).
    pub name: AttrValue,
    pub on_action: Callback<Action>,
    pub on_import: Callback<File>,
}

#[function_component(SoftkeyRow)]
pub fn softkey_row(props: &SoftkeyRowProps) -> Html {
    let keys = props.row.iter().enumerate().map(|(i, slot)| match slot {
        Some(key) if key.action == Action::PickFile => {
            let on_import = props.on_import.clone();
            let onchange = Callback::from(move |e: Event| {
                let file =
                    e.target_dyn_into::<HtmlInputElement>().and_then(|i| i.files()).and_then(|f| f.get(0));
                if let Some(file) = file {
                    on_import.emit(file);
                }
            });
            html! {
                <label class="softkey" data-key={key.id.clone()} title={format!("F{}", i + 1)}>
                    { for key.label.split('\n').map(|part| html! { <span>{ part.to_owned() }</span> }) }
                    <input type="file" accept=".h,.H,.nc,text/plain" class="file-input" {onchange} />
                </label>
            }
        }
        Some(key) => {
            let action = key.action.clone();
            let onclick = props.on_action.reform(move |_: MouseEvent| action.clone());
            let class = classes!("softkey", key.active.then_some("active"));
            html! {
                <button {class} data-key={key.id.clone()} {onclick} title={format!("F{}", i + 1)}
                    aria-pressed={key.active.then_some("true")}>
                    { for key.label.split('\n').map(|part| html! { <span>{ part.to_owned() }</span> }) }
                </button>
            }
        }
        None => {
            html! { <button class="softkey blank" disabled=true aria-hidden="true" tabindex="-1"></button> }
        }
    });
    html! {
        <div class="softkey-bar">
            <div class="softkey-row-name" data-testid="row-name">{ props.name.clone() }</div>
            <nav class="softkeys" aria-label="Softkeys">{ for keys }</nav>
        </div>
    }
}
