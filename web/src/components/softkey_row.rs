//! The row of eight softkeys at the bottom of the screen; F1–F8 press them too (keymap.rs).

use yew::prelude::*;

use crate::softkeys::Row;
use crate::state::Action;

#[derive(Properties, PartialEq)]
pub struct SoftkeyRowProps {
    pub row: Row,
    pub on_action: Callback<Action>,
}

#[function_component(SoftkeyRow)]
pub fn softkey_row(props: &SoftkeyRowProps) -> Html {
    let keys = props.row.iter().enumerate().map(|(i, slot)| match slot {
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
    html! { <nav class="softkeys" aria-label="Softkeys">{ for keys }</nav> }
}
