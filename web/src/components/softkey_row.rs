//! The row of eight softkeys at the bottom of the screen.

use yew::prelude::*;

use crate::i18n::Lang;
use crate::softkeys::Row;
use crate::state::Action;

#[derive(Properties, PartialEq)]
pub struct SoftkeyRowProps {
    pub row: Row,
    pub lang: Lang,
    pub on_action: Callback<Action>,
}

#[function_component(SoftkeyRow)]
pub fn softkey_row(props: &SoftkeyRowProps) -> Html {
    let keys = props.row.iter().map(|slot| match slot {
        Some(key) => {
            let action = key.action.clone();
            let onclick = props.on_action.reform(move |_: MouseEvent| action.clone());
            let label = props.lang.t(key.de, key.en);
            html! {
                <button class="softkey" data-key={key.id} {onclick}>
                    { for label.split('\n').map(|part| html! { <span>{ part }</span> }) }
                </button>
            }
        }
        None => html! { <button class="softkey blank" disabled=true aria-hidden="true"></button> },
    });
    html! { <nav class="softkeys" aria-label="Softkeys">{ for keys }</nav> }
}
