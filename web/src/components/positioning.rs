//! Lesson 4: the same PLANE block with MOVE, TURN and STAY in three 3D views side by side,
//! each animating that block's motion from the simulator.

use std::rc::Rc;

use yew::prelude::*;

use schwenkbar_app::run::StateRef;

use super::scene_pane::ScenePane;
use schwenkbar_app::course::positioning::{Pane, panes, unsimulated};
use schwenkbar_app::document::DocRef;
use schwenkbar_app::i18n::Lang;

#[derive(Properties, PartialEq)]
pub struct PositioningProps {
    pub lang: Lang,
    pub programs: [&'static str; 3],
    /// Number of the PLANE block.
    pub block: u32,
}

#[function_component(PositioningCompare)]
pub fn positioning_compare(props: &PositioningProps) -> Html {
    let l = props.lang;
    // Each press of "again" hands new state pointers to the panes, which replays the motion.
    let replay = use_state(|| 0_u32);
    // The machine and the three programs at once, their simulations once the simulator's code
    // has loaded (the lesson's first screen does without it), once per set of programs.
    let shown = use_state(|| Rc::new(unsimulated(props.programs)));
    {
        let shown = shown.clone();
        use_effect_with((props.programs, props.block), move |&(programs, block)| {
            yew::platform::spawn_local(async move {
                crate::browser::deferred_code().await;
                shown.set(Rc::new(panes(programs, block)));
            });
        });
    }
    let machine = &shown.0;
    let again = {
        let replay = replay.clone();
        Callback::from(move |_: MouseEvent| replay.set(*replay + 1))
    };
    html! {
        <div class="positioning" data-testid="positioning">
            <button onclick={again} data-testid="replay">{ l.t("Schwenken noch einmal zeigen", "Show the swivel again") }</button>
            <div class="positioning-panes">
                { for shown.1.iter().map(|Pane { name, doc, sim, state }| {
                    html! {
                        <figure class="positioning-pane" key={format!("{name}-{}", *replay)} data-testid={format!("pane-{name}")}>
                            <figcaption>{ name }</figcaption>
                            <ScenePane lang={l} machine={machine.clone()} sim={sim.clone()} doc={DocRef(doc.clone())}
                                state={state.clone().map(StateRef)} animate={true} speed={1.0} />
                        </figure>
                    }
                }) }
            </div>
        </div>
    }
}
