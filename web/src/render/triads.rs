//! Coordinate triads (X red, Y green, Z blue) for M-CS, W-CS, WPL-CS and T-CS, the tilted
//! working plane as a translucent square, and the screen labels that name them.

use glam::{DAffine3, DMat3, DVec3};

use super::draw_list::{DrawList, Label, Pass, Shape, rod};
use super::machine_parts;
use schwenkbar_app::scene::{Frame, Scene};

pub const X: [f32; 4] = [0.92, 0.16, 0.12, 1.0];
pub const Y: [f32; 4] = [0.10, 0.72, 0.20, 1.0];
pub const Z: [f32; 4] = [0.18, 0.38, 0.98, 1.0];
/// The working plane: translucent light blue.
pub const PLANE: [f32; 4] = [0.40, 0.78, 1.0, 0.26];

/// One arrow along `axis` (unit) from `origin`: shaft and head.
pub fn arrow(
    list: &mut DrawList,
    origin: DVec3,
    axis: DVec3,
    length: f64,
    radius: f64,
    colour: [f32; 4],
    pass: Pass,
) {
    let head = length * 0.22;
    let neck = origin + axis * (length - head);
    list.push(Shape::Cylinder, rod(origin, neck, radius), colour, pass);
    list.push(Shape::Cone, rod(neck, origin + axis * length, radius * 2.6), colour, pass);
}

/// A triad with its axis letters and its name as labels (`kind` styles the name label, so names
/// of frames that share an origin, such as W-CS and WPL-CS, do not overprint each other).
pub fn triad(
    list: &mut DrawList,
    origin: DVec3,
    rot: DMat3,
    length: f64,
    name: &'static str,
    kind: &'static str,
) {
    let radius = length * 0.028;
    for (i, (colour, letter, kind)) in [(X, "X", "x"), (Y, "Y", "y"), (Z, "Z", "z")].into_iter().enumerate() {
        let axis = rot.col(i).normalize_or(DVec3::Z);
        arrow(list, origin, axis, length, radius, colour, Pass::Overlay);
        list.labels.push(Label { text: letter, at: origin + axis * (length * 1.12), kind });
    }
    list.labels.push(Label { text: name, at: origin, kind });
}

fn compose(pose: DAffine3, f: &Frame) -> (DVec3, DMat3) {
    (pose.transform_point3(f.origin), pose.matrix3 * f.rot)
}

/// Builds the whole draw list of a scene: machine, ghost, working plane, triads; `from_above`:
/// seen from above, the head veiled ([`machine_parts::HEAD_VEIL`]).
#[must_use]
pub fn scene(s: &Scene<'_>, from_above: bool) -> DrawList {
    let mut list = DrawList::default();
    let p = machine_parts::machine(&mut list, s.machine, s.state, from_above);
    if let Some(g) = &s.state.ghost {
        machine_parts::ghost(&mut list, s.machine, s.state, g);
    }
    machine_parts::bodies(&mut list, &s.state.bodies, machine_parts::BODY, Pass::Translucent);
    if let Some(pair) = &s.state.contact {
        machine_parts::bodies(&mut list, pair, machine_parts::CONTACT, Pass::XRay);
    }
    let (w_origin, w_rot) = compose(p.workpiece, &s.state.wcs);
    let wcs_pose = DAffine3::from_mat3_translation(w_rot, w_origin);
    let (wpl_origin, wpl_rot) = compose(wcs_pose, &s.state.wpl);
    let b = &s.state.blank;
    let size = (b.max.x - b.min.x).abs().max((b.max.y - b.min.y).abs()).max(40.0);

    if s.triads.wpl {
        let side = size * 1.6;
        let m = DAffine3::from_mat3_translation(
            wpl_rot * DMat3::from_diagonal(DVec3::new(side, side, 1.0)),
            wpl_origin,
        );
        list.push(Shape::Square, m, PLANE, Pass::Translucent);
        triad(&mut list, wpl_origin, wpl_rot, size * 0.75, "WPL-CS", "frame-wpl");
    }
    if s.triads.mcs {
        triad(&mut list, DVec3::ZERO, DMat3::IDENTITY, size * 1.3, "M-CS", "frame-mcs");
    }
    if s.triads.wcs {
        triad(&mut list, w_origin, w_rot, size * 1.0, "W-CS", "frame-wcs");
    }
    if s.triads.tcs {
        triad(&mut list, p.tool.translation, p.tool.matrix3, size * 0.6, "T-CS", "frame-tcs");
    }
    list
}

#[cfg(test)]
mod tests {
    use super::*;
    use schwenkbar_app::scene::{SceneState, Triads};
    use schwenkbar_core::axes::AxisValues;
    use schwenkbar_core::machine::Machine;
    use schwenkbar_core::orientation::spatial;
    use schwenkbar_core::plane::RotaryAxis;

    fn labels(list: &DrawList, name: &str) -> Option<DVec3> {
        list.labels.iter().find(|l| l.text == name).map(|l| l.at)
    }

    #[test]
    fn triads_are_switchable_and_labelled() {
        let m = Machine::builtin("ac-table").expect("machine");
        let state = SceneState::default();
        let all = scene(&Scene { machine: &m, state: &state, triads: Triads::default() }, false);
        for name in ["M-CS", "W-CS", "WPL-CS", "T-CS"] {
            assert!(labels(&all, name).is_some(), "{name}");
        }
        let none = scene(&Scene { machine: &m, state: &state, triads: Triads::NONE }, false);
        assert!(none.labels.is_empty());
        assert!(none.instances.iter().all(|i| i.pass != Pass::Overlay));
        assert_eq!(all.instances.iter().filter(|i| i.pass == Pass::Overlay).count(), 4 * 3 * 2);
    }

    #[test]
    fn the_colliding_pair_is_drawn_in_the_warning_colour_where_it_is_placed() {
        use schwenkbar_core::sim::collision::{Obb, Placed};
        let m = Machine::builtin("ac-table").expect("machine");
        let cube = Placed::Box(Obb {
            center: DVec3::new(10.0, 20.0, 30.0),
            axes: DMat3::IDENTITY,
            half: DVec3::new(1.0, 2.0, 3.0),
        });
        let rod = Placed::cylinder(DVec3::ZERO, DVec3::Z, 5.0, 40.0);
        let state = SceneState { contact: Some([cube, rod]), ..SceneState::default() };
        let list = scene(&Scene { machine: &m, state: &state, triads: Triads::default() }, false);
        let red: Vec<_> = list.instances.iter().filter(|i| i.colour == machine_parts::CONTACT).collect();
        assert_eq!(red.len(), 2);
        assert!(red.iter().all(|i| i.pass == Pass::XRay), "the pair shows through the parts it is in");
        let corner = red[0].model.transform_point3(DVec3::splat(0.5));
        assert!((corner - DVec3::new(11.0, 22.0, 33.0)).length() < 1e-9, "{corner}");
        assert!((red[1].model.transform_point3(DVec3::Z) - DVec3::new(0.0, 0.0, 40.0)).length() < 1e-9);
        let plain =
            scene(&Scene { machine: &m, state: &SceneState::default(), triads: Triads::default() }, false);
        assert!(plain.instances.iter().all(|i| i.colour != machine_parts::CONTACT));
    }

    #[test]
    fn the_wpl_triad_follows_the_plane_and_the_table() {
        // PLANE SPATIAL SPB+45 on the A/C table at A+45 C+90 (DOMAIN.md §10 oracle 13): the
        // tilted tool axis (WPL-CS Z) must point straight up in the machine.
        let m = Machine::builtin("ac-table").expect("machine");
        let mut state = SceneState::default();
        state.wpl.rot = spatial(0.0, 45.0, 0.0);
        state.axes.rotary = AxisValues::default().with(RotaryAxis::A, 45.0).with(RotaryAxis::C, 90.0);
        let list = scene(&Scene { machine: &m, state: &state, triads: Triads::default() }, false);
        let plane = list.instances.iter().find(|i| i.shape == Shape::Square).expect("plane");
        let normal = plane.model.matrix3.col(2).normalize();
        assert!((normal - DVec3::Z).length() < 1e-9, "working plane horizontal in the machine: {normal}");
        // Labels of the WPL-CS triad: X, Y, Z, then its name.
        let name = list.labels.iter().position(|l| l.text == "WPL-CS").expect("WPL-CS label");
        let z_label = &list.labels[name - 1];
        assert_eq!(z_label.text, "Z");
        let z_dir = (z_label.at - plane.model.translation).normalize();
        assert!((z_dir - DVec3::Z).length() < 1e-9, "WPL-CS Z = tool axis, vertical: {z_dir}");
    }
}
