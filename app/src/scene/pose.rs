//! Where every moving part of the machine is, as rigid transforms in M-CS, from the
//! simulator's rigid-body model ([`schwenkbar_core::sim::Kin`]; formulas and sources in the
//! `core::sim` module doc): the workpiece pose W (table axes turn the workpiece by −θ about their
//! pivot, DOMAIN.md §3.1), the head pose H (head axes turn the tool by +θ about their pivot,
//! which hangs from the spindle gauge point one tool length above the tip), and the linear axes
//! L = the tool tip with the head at home, so the tip is L + H(0).
//!
//! The view also needs each link on its own (the cradle turns with the master only, the rotary
//! table with both): a link's pose is `Kin`'s pose with the joints it does not ride on held at
//! 0°. The test below checks that W and H together give exactly `Machine::forward`.

use glam::{DAffine3, DMat3, DVec3};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::{Carrier, Machine, RotaryJoint};
use schwenkbar_core::sim::{Affine, Kin};

/// A head axis' pivot in home coordinates with the linear axes at 0 (tool tip at the origin):
/// the gauge point `(0, 0, tool_length)` plus the machine's pivot (as in `Kin::head_pose`).
#[must_use]
pub fn head_pivot(j: &RotaryJoint, tool_length: f64) -> DVec3 {
    DVec3::new(0.0, 0.0, tool_length) + j.pivot
}

/// Poses (link → M-CS) of everything that moves.
#[derive(Debug, Clone, PartialEq)]
pub struct Poses {
    /// For each joint in chain order (workpiece → tool): the pose of the part it turns.
    pub joints: [DAffine3; 2],
    /// The workpiece (blank, W-CS, WPL-CS, toolpath): the innermost table link.
    pub workpiece: DAffine3,
    /// The head carriage (moved by X/Y/Z only): the outermost fixed-orientation head part.
    pub carriage: DAffine3,
    /// The tool, origin at the tool tip, +Z from the tip into the spindle.
    pub tool: DAffine3,
}

fn affine(a: Affine) -> DAffine3 {
    DAffine3::from_mat3_translation(a.m, a.v)
}

/// Forward kinematics for axis values (missing rotary axes at 0°), the linear axes and the
/// active tool length (it places the head axes, which hang from the gauge point).
#[must_use]
pub fn poses(machine: &Machine, rotary: &AxisValues, linear: DVec3, tool_length: f64) -> Poses {
    let kin = Kin::new(machine, tool_length);
    let chain = machine.joints();
    let values: [f64; 2] = std::array::from_fn(|i| rotary.get(chain[i].axis).unwrap_or(0.0));
    let carriage = DAffine3::from_translation(linear);
    // Joint i's link rides on the table joints from the bed down to i (indices ≥ i) or on the
    // head joints from the carriage out to i (indices ≤ i); the others are held at 0°.
    let joints = std::array::from_fn(|i| match chain[i].carrier {
        Carrier::Table => {
            affine(kin.workpiece_pose(std::array::from_fn(|k| if k >= i { values[k] } else { 0.0 })))
        }
        Carrier::Head => {
            carriage * affine(kin.head_pose(std::array::from_fn(|k| if k <= i { values[k] } else { 0.0 })))
        }
    });
    Poses {
        joints,
        workpiece: affine(kin.workpiece_pose(values)),
        carriage,
        tool: carriage * affine(kin.head_pose(values)),
    }
}

/// The tool's orientation relative to the workpiece (its third column is the tool axis in the
/// workpiece's coordinates).
#[must_use]
pub fn relative_orientation(p: &Poses) -> DMat3 {
    p.workpiece.matrix3.transpose() * p.tool.matrix3
}

/// What the "Werkstück" camera keeps in view, in M-CS, as the machine stands: the blank's eight
/// corners and, while the tool works near the part, its cutting end: the tip and the point up its
/// axis as far as the blank's half diagonal (at most the tool's length). A tip farther from the
/// blank than its half diagonal (retracted, at the tool change) is left out: framing the whole
/// tool up there made the part small (issue 32).
#[must_use]
pub fn work_points(machine: &Machine, s: &super::SceneState) -> Vec<glam::Vec3> {
    let p = poses(machine, &s.axes.rotary, s.axes.linear, s.tool.length);
    let on_table = p.workpiece * DAffine3::from_mat3_translation(s.wcs.rot, s.wcs.origin);
    let (lo, hi) = (s.blank.min, s.blank.max);
    let mut points: Vec<DVec3> = (0..8)
        .map(|i| {
            let pick = |bit: u32, a: f64, b: f64| if i & (1 << bit) == 0 { a } else { b };
            on_table.transform_point3(DVec3::new(
                pick(0, lo.x, hi.x),
                pick(1, lo.y, hi.y),
                pick(2, lo.z, hi.z),
            ))
        })
        .collect();
    let reach = (hi - lo).length() / 2.0;
    let tip = on_table.inverse().transform_point3(p.tool.transform_point3(DVec3::ZERO));
    if tip.distance(tip.clamp(lo, hi)) <= reach {
        let up = reach.min(s.tool.length.max(0.0));
        points.extend([DVec3::ZERO, DVec3::new(0.0, 0.0, up)].map(|q| p.tool.transform_point3(q)));
    }
    points.into_iter().map(|q| q.as_vec3()).collect()
}

/// The section through the part (issue 32: a hole or a pocket seen without orbiting): the
/// plane normal to the W-CS's X or Y axis, whichever faces the viewer at `eye` (M-CS) more,
/// through the tool tip held inside the blank (a tool above the part cuts through what it has
/// just made), or through the blank's middle when the tool is beside it along that axis.
/// Returns a point of it and its normal towards the viewer, W-CS: the half on the viewer's
/// side is not drawn.
#[must_use]
pub fn section_plane(machine: &Machine, s: &super::SceneState, eye: DVec3) -> (DVec3, DVec3) {
    let p = poses(machine, &s.axes.rotary, s.axes.linear, s.tool.length);
    let to_wcs = (p.workpiece * DAffine3::from_mat3_translation(s.wcs.rot, s.wcs.origin)).inverse();
    let tip = to_wcs.transform_point3(p.tool.transform_point3(DVec3::ZERO));
    let (lo, hi) = (s.blank.min, s.blank.max.max(s.blank.min));
    let mut point = tip.clamp(lo, hi);
    let look = to_wcs.transform_point3(eye) - point;
    let k = usize::from(look.x.abs() < look.y.abs());
    if !(lo[k] < tip[k] && tip[k] < hi[k]) {
        point[k] = 0.5 * (lo[k] + hi[k]);
    }
    let mut normal = DVec3::ZERO;
    normal[k] = look[k].signum();
    (point, normal)
}

/// The blank's centre in M-CS as the machine stands.
#[must_use]
pub fn blank_centre(machine: &Machine, s: &super::SceneState) -> DVec3 {
    let p = poses(machine, &s.axes.rotary, s.axes.linear, s.tool.length);
    let wcs = DAffine3::from_mat3_translation(s.wcs.rot, s.wcs.origin);
    (p.workpiece * wcs).transform_point3((s.blank.min + s.blank.max) / 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use schwenkbar_core::plane::RotaryAxis;

    fn close(a: DMat3, b: DMat3) -> bool {
        (a - b).to_cols_array().iter().all(|d| d.abs() < 1e-9)
    }

    #[test]
    fn relative_orientation_is_cores_forward_kinematics_on_every_machine() {
        let angles = [(0.0, 0.0), (45.0, 90.0), (-30.0, 17.0), (123.0, -75.5)];
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("shipped machine");
            for (s, t) in angles {
                let v = AxisValues::default().with(m.slave().axis, s).with(m.master().axis, t);
                let p = poses(&m, &v, DVec3::new(10.0, -20.0, 30.0), 80.0);
                assert!(close(relative_orientation(&p), m.forward_deg(s, t)), "{id} at {s}/{t}");
            }
        }
    }

    #[test]
    fn spb45_on_the_ac_table_brings_the_tilted_tool_axis_vertical() {
        // DOMAIN.md §10 oracle 13: PLANE SPATIAL SPB+45 from A0 C0 → A+45 C+90.
        let m = Machine::builtin("ac-table").expect("ac-table");
        let v = AxisValues::default().with(RotaryAxis::A, 45.0).with(RotaryAxis::C, 90.0);
        let p = poses(&m, &v, DVec3::ZERO, 100.0);
        let t = DVec3::new(45f64.to_radians().sin(), 0.0, 45f64.to_radians().cos());
        let up = p.workpiece.transform_vector3(t);
        assert!((up - DVec3::Z).length() < 1e-9, "the workpiece's tilted tool axis points up: {up}");
        // The workpiece's +X edge tips towards the operator (−Y) and rises.
        let x = p.workpiece.transform_vector3(DVec3::X);
        assert!(x.y < -0.7 && x.z > 0.7, "{x}");
        assert_eq!(p.tool.matrix3, DMat3::IDENTITY, "the head does not move on a table-table machine");
    }

    #[test]
    fn head_axes_turn_about_their_pivot_and_carry_the_tool_tip() {
        let m = Machine::builtin("bc-head-table").expect("bc-head-table");
        let v = AxisValues::default().with(RotaryAxis::B, 90.0);
        let p = poses(&m, &v, DVec3::new(0.0, 0.0, 0.0), 100.0);
        // The B pivot is 300 above the gauge point, which is 100 (the tool length) above the
        // tip: the tip hangs 400 below the pivot at home; +90° about +Y turns (0, 0, −400) into
        // Ry(90)·(0, 0, −400) = (−400, 0, 0), so the tip ends at the pivot plus that.
        let tip = p.tool.transform_point3(DVec3::ZERO);
        assert!((tip - DVec3::new(-400.0, 0.0, 400.0)).length() < 1e-9, "{tip}");
        // And the tool axis (tip → spindle) is Ry(90)·ez = +X.
        assert!((p.tool.transform_vector3(DVec3::Z) - DVec3::X).length() < 1e-9);
    }

    #[test]
    fn the_nutating_head_at_b180_lays_the_tool_horizontal_along_plus_y() {
        let m = Machine::builtin("b45-nutating").expect("b45-nutating");
        let v = AxisValues::default().with(RotaryAxis::B, 180.0);
        let p = poses(&m, &v, DVec3::ZERO, 100.0);
        let axis = p.tool.transform_vector3(DVec3::Z);
        assert!(
            (axis - DVec3::Y).length() < 1e-9,
            "machine description: B180 = tool horizontal (+Y): {axis}"
        );
    }

    #[test]
    fn linear_axes_move_the_carriage_only() {
        let m = Machine::builtin("ac-table").expect("ac-table");
        let p = poses(&m, &AxisValues::default(), DVec3::new(1.0, 2.0, 3.0), 100.0);
        assert_eq!(p.tool.translation, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(p.workpiece, DAffine3::IDENTITY);
    }

    /// The camera frames the blank's corners; the tool's cutting end only while its tip is
    /// within the blank's half diagonal of the blank (worked by hand on the A/C table at home:
    /// no rotary turn, so the tip is the linear axes' point).
    #[test]
    fn the_workpiece_camera_frames_the_blank_and_the_tool_only_near_it() {
        let machine = Machine::builtin("ac-table").expect("shipped machine");
        let mut s = crate::scene::SceneState::for_machine(&machine);
        let centre = blank_centre(&machine, &s);
        let half_diagonal = (s.blank.max - s.blank.min).length() / 2.0;
        let corners_ok = |points: &[glam::Vec3]| {
            points[..8].iter().all(|c| (f64::from(c.distance(centre.as_vec3())) - half_diagonal).abs() < 1e-3)
        };
        s.axes.linear = centre;
        let near = work_points(&machine, &s);
        assert_eq!(near.len(), 10, "eight corners, the tip and the cutting end");
        assert!(corners_ok(&near));
        assert!(near[8].distance(centre.as_vec3()) < 1e-3, "the tip at the blank's centre");
        let up = f64::from(near[9].distance(near[8]));
        assert!((up - half_diagonal.min(s.tool.length)).abs() < 1e-3, "{up}");
        s.axes.linear = centre + DVec3::new(0.0, 0.0, 3.0 * half_diagonal);
        let far = work_points(&machine, &s);
        assert_eq!(far.len(), 8, "a retracted tool is not framed");
        assert!(corners_ok(&far));
    }

    /// Worked by hand on the A/C table at rotary zero (W-CS axes along M-CS): a viewer in front
    /// (−Y, a little to the side) cuts the plane y = tip's y, facing −Y; one to the right (+X)
    /// the plane x = tip's x; a tip above the blank is brought down into it.
    #[test]
    fn the_section_goes_through_the_tool_and_faces_the_viewer() {
        let machine = Machine::builtin("ac-table").expect("shipped machine");
        let mut s = crate::scene::SceneState::for_machine(&machine);
        let centre = blank_centre(&machine, &s);
        s.axes.linear = centre + DVec3::new(10.0, 5.0, 500.0);
        let front = centre + DVec3::new(30.0, -900.0, 400.0);
        let (point, normal) = section_plane(&machine, &s, front);
        assert_eq!(normal, -DVec3::Y);
        let wcs_centre = (s.blank.min + s.blank.max) / 2.0;
        assert!(
            (point - DVec3::new(wcs_centre.x + 10.0, wcs_centre.y + 5.0, s.blank.max.z)).length() < 1e-9,
            "{point}"
        );
        let (_, normal) = section_plane(&machine, &s, centre + DVec3::new(900.0, 100.0, 400.0));
        assert_eq!(normal, DVec3::X);
        // A tool beside the blank along the normal: the plane goes through the blank's middle.
        s.axes.linear = centre + DVec3::new(10.0, -400.0, 500.0);
        let (point, normal) = section_plane(&machine, &s, front);
        assert_eq!(normal, -DVec3::Y);
        assert!(
            (point.y - wcs_centre.y).abs() < 1e-9 && (point.x - wcs_centre.x - 10.0).abs() < 1e-9,
            "{point}"
        );
    }
}
