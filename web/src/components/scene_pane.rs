//! The 3D view fed by the simulation: while editing it shows the machine after the cursor
//! block; in a program run it animates the shown block's motion segment by segment (the
//! simulator's `axes_at`: MOVE keeps the tool tip on the workpiece, TURN moves it, STAY turns
//! only the frame) at the run's speed, and a slider scrubs through the block. The animation
//! state lives here so that only the 3D view re-renders per frame.

use std::cell::Cell;
use std::rc::Rc;
use std::time::Duration;

use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::number::parse_f64;
use schwenkbar_core::sim::{Collision, State};
use yew::prelude::*;

use super::view3d::{SharedPath, View3d};
use crate::render::from_sim::{RunPath, extend_path, scene_during, scene_state};
use schwenkbar_app::document::DocRef;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::run::{SimRef, StateRef};
use schwenkbar_app::scene::{SceneState, StockShape};
use schwenkbar_app::stock::StockRef;

#[derive(Properties, PartialEq)]
pub struct ScenePaneProps {
    pub lang: Lang,
    pub machine: Option<Rc<Machine>>,
    pub sim: Option<SimRef>,
    pub doc: DocRef,
    /// The state to show (after the cursor block, or the run's step).
    pub state: Option<StateRef>,
    /// Animate the block's motion (program run) instead of showing its end.
    pub animate: bool,
    /// Playback speed factor.
    pub speed: f64,
    /// A program run is shown (the view follows the workpiece by default).
    #[prop_or_default]
    pub in_run: bool,
    /// The trainee is typing in the text editor (the view is painted once typing pauses).
    #[prop_or_default]
    pub typing: bool,
    /// A PLANE candidate hovered in the why panel: drawn as the ghost instead of the other one.
    #[prop_or_default]
    pub ghost: Option<AxisValues>,
    /// The collision that stopped the run: shown at the moment of contact, the pair marked.
    #[prop_or_default]
    pub collision: Option<Rc<Collision>>,
    /// The cut stock of the run (the ROHTEIL switch on), drawn at the shown step and fraction.
    #[prop_or_default]
    pub stock: Option<StockRef>,
    /// Told where in the block's motion the view stands (animation or scrub), for the
    /// position display.
    #[prop_or_default]
    pub on_fraction: Callback<f64>,
}

/// How long one part of the toolpath may take before the browser gets a turn, ms.
const PART_MS: f64 = 4.0;

/// Steps of the toolpath made between two looks at the clock.
const PATH_SLICE: usize = 64;

/// The page's clock, ms (none outside a window: then one slice per part).
fn now_ms() -> Option<f64> {
    Some(web_sys::window()?.performance()?.now())
}

/// Frame interval of the animation, ms.
const FRAME_MS: u64 = 33;

/// The scene at `fraction` of the block's motion (by time over its segments).
#[must_use]
pub fn scene_at(machine: &Machine, state: &State, fraction: f64) -> SceneState {
    match state.segment_at(fraction) {
        Some((seg, f)) => scene_during(machine, state, seg, f),
        None => scene_state(machine, state),
    }
}

/// The run's toolpath, once per simulation, made in parts between frames (a run of
/// 1,000,000 steps takes seconds) and shown when all in; a new simulation ends the old work.
#[hook]
fn use_run_path(sim: Option<SimRef>, doc: DocRef) -> UseStateHandle<(SharedPath, Rc<RunPath>)> {
    let sim_ptr = sim.as_ref().map_or(0, |s| std::sync::Arc::as_ptr(&s.0) as usize);
    let path = use_state(|| (SharedPath::default(), Rc::new(RunPath::default())));
    let path_gen = use_mut_ref(|| Rc::new(Cell::new(0_u64)));
    {
        let path = path.clone();
        let generation = path_gen.borrow().clone();
        use_effect_with(sim_ptr, move |_| {
            let gen_now = generation.get() + 1;
            generation.set(gen_now);
            let Some(sim) = sim else {
                path.set((SharedPath::default(), Rc::default()));
                return;
            };
            yew::platform::spawn_local(async move {
                let mut p = RunPath::default();
                // One pass through the run (an iterator kept between the parts: nothing is run
                // twice), in parts of about PART_MS, every part after a turn of the browser, the
                // first too: a keystroke's screen update should not wait for it.
                let mut states = sim.0.states_from(&doc.program, 0);
                loop {
                    yew::platform::time::sleep(Duration::from_millis(0)).await;
                    if generation.get() != gen_now {
                        return;
                    }
                    let until = now_ms().map(|t| t + PART_MS);
                    let all_in = loop {
                        if extend_path(&sim.0.machine, &mut p, states.by_ref().take(PATH_SLICE)) < PATH_SLICE
                        {
                            break true;
                        }
                        if until.zip(now_ms()).is_none_or(|(until, now)| now >= until) {
                            break false;
                        }
                    };
                    if all_in {
                        break;
                    }
                }
                if generation.get() == gen_now {
                    path.set((SharedPath(p.points.clone().into()), Rc::new(p)));
                }
            });
        });
    }
    path
}

/// Where in the shown block's motion the view stands, 0…1: with `animate`, run from 0 to 1 in
/// the motion's time at `speed`; else its end. Each new block ends the previous animation loop;
/// so does a scrub, which moves the generation (the second value) on.
#[hook]
fn use_motion(state: Option<StateRef>, animate: bool, speed: f64) -> (UseStateHandle<f64>, Rc<Cell<u64>>) {
    let fraction = use_state(|| 1.0_f64);
    let generation = use_mut_ref(|| Rc::new(Cell::new(0_u64)));
    let handle = generation.borrow().clone();
    {
        let fraction = fraction.clone();
        let generation = handle.clone();
        let deps = (state.as_ref().map(|s| (s.step, Rc::as_ptr(&s.0) as usize)), animate);
        let duration = state.as_ref().map_or(0.0, |s| s.duration());
        let speed = speed.max(0.01);
        use_effect_with(deps, move |(_, animate)| {
            let gen_now = generation.get() + 1;
            generation.set(gen_now);
            if !*animate || duration <= 0.0 {
                fraction.set(1.0);
                return;
            }
            fraction.set(0.0);
            // Long cycles are compressed to a few seconds so a lesson does not stall.
            let seconds = (duration / speed).clamp(0.3, 4.0);
            yew::platform::spawn_local(async move {
                let mut f = 0.0;
                while f < 1.0 && generation.get() == gen_now {
                    yew::platform::time::sleep(Duration::from_millis(FRAME_MS)).await;
                    f = (f + FRAME_MS as f64 / 1000.0 / seconds).min(1.0);
                    if generation.get() == gen_now {
                        fraction.set(f);
                    }
                }
            });
        });
    }
    (fraction, handle)
}

#[function_component(ScenePane)]
pub fn scene_pane(props: &ScenePaneProps) -> Html {
    let path = use_run_path(props.sim.clone(), props.doc.clone());
    let (fraction, generation) = use_motion(props.state.clone(), props.animate, props.speed);
    {
        let on_fraction = props.on_fraction.clone();
        use_effect_with(*fraction, move |f| on_fraction.emit(*f));
    }
    let scene = match (&props.machine, &props.state) {
        (Some(m), Some(s)) => {
            let mut scene = scene_at(m, s, *fraction);
            if let Some(c) = &props.collision {
                scene.at_collision(m, s, c);
            }
            scene.toolpath_drawn = path.1.segments_after.get(s.step).copied();
            if props.ghost.is_some() {
                scene.ghost = props.ghost;
            }
            scene.stock = props.stock.as_ref().map(|st| StockShape {
                stock: st.clone(),
                step: s.step,
                fraction: *fraction,
            });
            Some(Rc::new(scene))
        }
        _ => None,
    };
    let l = props.lang;
    let scrub = {
        let fraction = fraction.clone();
        Callback::from(move |e: InputEvent| {
            if let Some(input) = e.target_dyn_into::<web_sys::HtmlInputElement>() {
                generation.set(generation.get() + 1);
                fraction.set(parse_f64(&input.value()).map_or(1.0, |v| v / 1000.0));
            }
        })
    };
    html! {
        <div class="scene-pane">
            <View3d lang={l} machine={props.machine.clone()} state={scene} toolpath={path.0.clone()} in_run={props.in_run}
                typing={props.typing} />
            // Also before the start's simulation is there (disabled): the view keeps its size.
            if props.machine.is_some() {
                <label class="scrub">
                    { l.t("Satz-Bewegung", "Block motion") }
                    <input type="range" min="0" max="1000" value={((*fraction * 1000.0).round() as i64).to_string()}
                        oninput={scrub} data-testid="scrub" disabled={props.state.is_none()} />
                </label>
            }
        </div>
    }
}
