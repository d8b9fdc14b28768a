//! Lesson 4: the same PLANE block with MOVE, TURN and STAY in three 3D views side by side,
//! each animating that block's motion from the simulator.

use std::rc::Rc;

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, simulate};
use yew::prelude::*;

use super::scene_pane::ScenePane;
use schwenkbar_app::document::Document;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::run::SimRef;

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
    // The machine and the three simulations, once per set of programs.
    let panes = use_memo(props.programs, |programs| {
        let machine = Machine::builtin("ac-table").ok().map(Rc::new);
        let runs = programs
            .iter()
            .map(|text| {
                let doc = Rc::new(Document::new((*text).to_owned()));
                let sim = machine
                    .as_ref()
                    .map(|m| SimRef(Rc::new(simulate(&doc.program, m, &SimOptions::default()))));
                (doc, sim)
            })
            .collect::<Vec<_>>();
        (machine, runs)
    });
    let machine = &panes.0;
    let again = {
        let replay = replay.clone();
        Callback::from(move |_: MouseEvent| replay.set(*replay + 1))
    };
    let names = ["MOVE", "TURN", "STAY"];
    html! {
        <div class="positioning" data-testid="positioning">
            <button onclick={again} data-testid="replay">{ l.t("Schwenken noch einmal zeigen", "Show the swivel again") }</button>
            <div class="positioning-panes">
                { for panes.1.iter().zip(names).map(|((doc, sim), name)| {
                    let index = doc.program.blocks.iter().position(|b| b.number == Some(props.block));
                    let state = sim.as_ref().zip(index).and_then(|(s, i)| {
                        let step = s.0.first_step.get(i).copied().flatten()?;
                        s.0.state_at(&doc.program, step as usize).map(Rc::new)
                    });
                    html! {
                        <figure class="positioning-pane" key={format!("{name}-{}", *replay)} data-testid={format!("pane-{name}")}>
                            <figcaption>{ name }</figcaption>
                            <ScenePane lang={l} machine={machine.clone()} sim={sim.clone()} doc={doc.clone()}
                                {state} animate={true} speed={1.0} />
                        </figure>
                    }
                }) }
            </div>
        </div>
    }
}
