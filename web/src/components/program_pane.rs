//! The NC program, one block per line.

use yew::prelude::*;

#[derive(Properties, PartialEq)]
pub struct ProgramPaneProps {
    pub program: AttrValue,
    pub title: AttrValue,
}

#[function_component(ProgramPane)]
pub fn program_pane(props: &ProgramPaneProps) -> Html {
    html! {
        <section class="program-pane" aria-label={props.title.clone()}>
            <ol class="blocks">
                { for props.program.lines().map(|line| html! { <li class="block">{ line }</li> }) }
            </ol>
        </section>
    }
}
