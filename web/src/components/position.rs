//! Position display as on the control: every axis in machine coordinates (REF) and in the
//! active working plane (IST; English screens write ACTL.), the tool, feed and spindle, and a status line with the active
//! transformations and the active PLANE.

use std::rc::Rc;

use glam::DVec3;
use schwenkbar_core::ast::Unit;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{ActiveTransform, Level, MachineAxes, SpindleDir, State};
use yew::prelude::*;

use schwenkbar_app::run::StateRef;

use schwenkbar_app::i18n::Lang;

#[derive(Properties, PartialEq)]
pub struct PositionProps {
    pub state: StateRef,
    pub lang: Lang,
    /// The machine, for the tool tip during the block's motion.
    pub machine: Option<Rc<Machine>>,
    /// Where in the block's motion the 3D view stands (1 = its end).
    #[prop_or(1.0)]
    pub fraction: f64,
    /// REF and IST where a collision stopped the machine ([`AppState::stop_position`]).
    ///
    /// [`AppState::stop_position`]: schwenkbar_app::state::AppState::stop_position
    #[prop_or_default]
    pub stopped: Option<(MachineAxes, DVec3)>,
}

fn signed(x: f64) -> String {
    schwenkbar_core::number::signed_fixed(x, 3)
}

/// The status line's entries.
#[must_use]
pub fn status(state: &State, l: Lang) -> Vec<String> {
    let level = |lv: Level| match lv {
        Level::Wcs => "W-CS",
        Level::Wpl => "WPL-CS",
    };
    let axes = |m: [bool; 3]| {
        ["X", "Y", "Z"].iter().zip(m).filter(|(_, on)| *on).map(|(a, _)| *a).collect::<String>()
    };
    state
        .transforms
        .iter()
        .map(|t| match t {
            // The shift in the program's unit, as the program wrote it.
            ActiveTransform::Datum { level: lv, offset } => format!(
                "{} ({}) X{} Y{} Z{}",
                l.t("Nullpunkt", "Datum"),
                level(*lv),
                signed(state.shown(offset[0])),
                signed(state.shown(offset[1])),
                signed(state.shown(offset[2]))
            ),
            ActiveTransform::Mirror { level: lv, axes: m } => {
                format!("{} ({}) {}", l.t("Spiegeln", "Mirror"), level(*lv), axes(*m))
            }
            ActiveTransform::Rotation { deg } => format!("ROT {}", signed(*deg)),
            ActiveTransform::Tilt { spatial, tool_axis } => format!(
                "PLANE SPA{} SPB{} SPC{} · {} ({:.4}, {:.4}, {:.4})",
                signed(spatial[0]),
                signed(spatial[1]),
                signed(spatial[2]),
                l.t("WZ-Achse", "tool axis"),
                tool_axis[0],
                tool_axis[1],
                tool_axis[2]
            ),
        })
        .collect()
}

#[function_component(PositionDisplay)]
pub fn position_display(props: &PositionProps) -> Html {
    let l = props.lang;
    let s = &props.state;
    // During the block's motion (animation or the scrub slider) both columns follow it.
    let (axes, tip) = match (props.stopped, &props.machine) {
        (Some(stop), _) => stop,
        (None, Some(m)) if props.fraction < 1.0 => {
            (s.axes_at(props.fraction), s.tip_ics_at(m, props.fraction))
        }
        _ => (s.axes, s.tip_ics),
    };
    // Lengths in the program's unit (an INCH program shows inches, to 4 decimals as the
    // control writes them); rotary axes in degrees.
    let shown = |v: f64| schwenkbar_core::number::signed_fixed(v, if s.unit == Unit::Inch { 4 } else { 3 });
    let ist = [tip.x, tip.y, tip.z].map(|v| s.shown(v));
    let rows = axes.named().into_iter().enumerate().map(|(i, (axis, reference))| {
        let reference = if i < 3 { s.shown(reference) } else { reference };
        let actual = ist.get(i).copied().unwrap_or(reference);
        html! {
            <tr data-axis={axis.to_string()}>
                <th>{ axis }</th>
                <td class="ref">{ shown(reference) }</td>
                <td class="ist">{ shown(actual) }</td>
            </tr>
        }
    });
    let spindle = match s.spindle.dir {
        SpindleDir::Off => "M5",
        SpindleDir::Cw => "M3",
        SpindleDir::Ccw => "M4",
    };
    let tool =
        if s.tool.name.is_empty() { format!("T{}", s.tool.number) } else { format!("T \"{}\"", s.tool.name) };
    let status = status(s, l);
    let decimals = if s.unit == Unit::Inch { 3 } else { 1 };
    html! {
        <section class="position" aria-label={l.t("Positionsanzeige", "Position display")}>
            <table>
                <thead><tr><th>{ if s.unit == Unit::Inch { "INCH" } else { "" } }</th><th>{ "REF" }</th><th>{ l.t("IST", "ACTL.") }</th></tr></thead>
                <tbody>{ for rows }</tbody>
            </table>
            <p class="tool">{ format!("{tool} {axis} L{length:.prec$} R{radius:.prec$} · F{feed:.0} · S{speed:.0} {spindle}", axis = s.tool.axis, length = s.shown(s.tool.length), radius = s.shown(s.tool.radius), feed = s.shown_feed(s.feed), speed = s.spindle.speed, prec = decimals) }</p>
            <p class="status-line" data-testid="status-line">
                if status.is_empty() { { l.t("keine Transformation aktiv", "no transformation active") } }
                else { { status.join(" · ") } }
            </p>
            if let Some(m) = s.message() {
                <p class="block-message">{ l.t(&m.de, &m.en) }</p>
            }
        </section>
    }
}
