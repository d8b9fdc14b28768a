//! "Warum?" — what the cursor block does and, for a PLANE block, why the machine positions its
//! axes the way it does.

use std::rc::Rc;

use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use yew::prelude::*;

use schwenkbar_app::document::DocRef;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::run::{SimRef, StateRef};
use schwenkbar_app::why::{PlaneWhy, describe, for_block, machine_line};

#[derive(Properties, PartialEq)]
pub struct WhyPanelProps {
    pub doc: DocRef,
    pub cursor: usize,
    pub machine: Option<Rc<Machine>>,
    pub sim: Option<SimRef>,
    /// The state shown in run mode.
    pub shown: Option<StateRef>,
    pub lang: Lang,
    /// A candidate hovered (its axes, shown as the ghost in the 3D view) or left (`None`).
    #[prop_or_default]
    pub on_hover: Callback<Option<AxisValues>>,
    /// The shown run step's collision with the material, in the UI language.
    #[prop_or_default]
    pub collision: Option<String>,
}

#[function_component(WhyPanel)]
pub fn why_panel(props: &WhyPanelProps) -> Html {
    let l = props.lang;
    let Some(block) = props.doc.program.blocks.get(props.cursor) else {
        return html! { <aside class="why-panel"></aside> };
    };
    let plane = props.machine.as_ref().and_then(|m| {
        for_block(
            &props.doc.program,
            props.sim.as_ref().map(|s| s.0.as_ref()),
            props.shown.as_deref(),
            props.cursor,
            m,
            l,
        )
    });
    let machine = props.machine.as_ref().map(|m| machine_line(m, l));
    html! {
        <aside class="why-panel" aria-label={l.t("Warum?", "Why?")}>
            <h2>{ l.t("Warum?", "Why?") }</h2>
            <p class="why-block">{ describe(&block.body(), l) }</p>
            if let Some(c) = &props.collision {
                <p class="why-collision" role="alert">{ c }</p>
            }
            if let Some(w) = plane {
                { plane_why(&w, &props.on_hover, l) }
            }
            if let Some(m) = machine {
                <p class="why-machine">{ m }</p>
            }
        </aside>
    }
}

/// What the panel says of a PLANE block. Out of line: the first screen's cursor is on BEGIN PGM,
/// so the page split (scripts/split_pages.py) leaves this to the wasm loaded after it.
#[inline(never)]
fn plane_why(w: &PlaneWhy, on_hover: &Callback<Option<AxisValues>>, l: Lang) -> Html {
    html! {
        <div class="why-plane">
            if let Some(e) = &w.error {
                <p class="why-error" data-testid="why-error">{ e }</p>
            }
            if let Some(a) = &w.safe_alternative {
                <p class="why-alternative" data-testid="why-alternative">{ a }</p>
            }
            if !w.plain.is_empty() {
                <p class="why-plain" data-testid="why-plain">{ &w.plain }</p>
            }
            if !w.candidates.is_empty() {
                <ul class="candidates">
                    { for w.candidates.iter().zip(&w.candidate_axes).map(|((text, chosen), axes)| {
                        let axes = *axes;
                        let enter = on_hover.reform(move |_: MouseEvent| Some(axes));
                        let leave = on_hover.reform(|_: MouseEvent| None);
                        html! {
                            <li class={classes!("candidate", chosen.then_some("chosen"))}
                                onmouseenter={enter} onmouseleave={leave}>{ text }</li>
                        }
                    }) }
                </ul>
                <p class="why-rule">{ &w.rule }</p>
                <p>{ &w.symmetry }</p>
                <p>{ l.t("Werkzeugachse", "Tool axis") }{ " " }{ &w.tool_axis }</p>
                <p class="equiv"><code>{ &w.spatial }</code><br/><code>{ &w.euler }</code></p>
            }
            if !w.assumptions.is_empty() {
                <details class="assumptions">
                    <summary>{ l.t("Annahmen (nicht bestätigt)", "Assumptions (unconfirmed)") }</summary>
                    <ul>{ for w.assumptions.iter().map(|a| html! { <li>{ a }</li> }) }</ul>
                </details>
            }
        </div>
    }
}
