//! The dialog line: what the control asks or reports.

use yew::prelude::*;

#[derive(Properties, PartialEq)]
pub struct DialogLineProps {
    pub text: AttrValue,
}

#[function_component(DialogLine)]
pub fn dialog_line(props: &DialogLineProps) -> Html {
    html! { <div class="dialog-line" role="status" aria-live="polite">{ props.text.clone() }</div> }
}
