//! Where every moving part of the machine is: forward kinematics of the chain in `core`'s
//! machine model, with pivots, as rigid transforms in M-CS.
//!
//! Composition (product of exponentials, Lynch & Park, *Modern Robotics* §4.1): with each axis
//! given by its direction and a pivot **at home**, the pose of a link is the product of the
//! rotations about those home axes from the fixed base outwards.
//! Sign (DOMAIN.md §3.1, `Machine::forward`): an axis value θ means "tool relative to the
//! workpiece turns by +θ about the axis direction"; a head axis turns the tool by +θ, a table
//! axis physically turns the workpiece by −θ. The test below checks that the relative
//! orientation of tool and workpiece is exactly `Machine::forward`.
//! Pivots (core/src/machine.rs): a table axis' pivot is in M-CS with every axis at home; a head
//! axis' pivot is relative to the spindle gauge point, one tool length above the tool tip. The
//! linear axes X/Y/Z are where the tool tip is with the head at home (the simulator's `Kin`
//! uses the same model: tip = L + H(0)).

use glam::{DAffine3, DMat3, DVec3};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::{Carrier, Machine, RotaryJoint};

/// The rigid motion of one joint's moving side: a turn by `angle_deg` about the joint's home
/// axis through its pivot.
#[must_use]
pub fn joint_motion(joint: &RotaryJoint, angle_deg: f64) -> DAffine3 {
    DAffine3::from_translation(joint.pivot)
        * DAffine3::from_axis_angle(joint.direction, angle_deg.to_radians())
        * DAffine3::from_translation(-joint.pivot)
}

/// A head axis' pivot in home coordinates with the linear axes at 0 (tool tip at the origin):
/// the gauge point `(0, 0, tool_length)` plus the machine's pivot.
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

/// Forward kinematics for axis values (missing rotary axes at 0°), the linear axes and the
/// active tool length (it places the head axes, which hang from the gauge point).
#[must_use]
pub fn poses(machine: &Machine, rotary: &AxisValues, linear: DVec3, tool_length: f64) -> Poses {
    let chain = machine.joints();
    let value = |j: &RotaryJoint| rotary.get(j.axis).unwrap_or(0.0);
    let mut joints = [DAffine3::IDENTITY; 2];

    // Table side: from the bed inwards (reverse chain order), each table axis turns by −θ.
    let mut table = DAffine3::IDENTITY;
    for (i, j) in chain.iter().enumerate().rev() {
        if j.carrier == Carrier::Table {
            table *= joint_motion(j, -value(j));
            joints[i] = table;
        }
    }
    // Head side: from the carriage outwards (chain order), each head axis turns by +θ.
    let carriage = DAffine3::from_translation(linear);
    let mut head = carriage;
    for (i, j) in chain.iter().enumerate() {
        if j.carrier == Carrier::Head {
            let at_home = RotaryJoint { pivot: head_pivot(j, tool_length), ..j.clone() };
            head *= joint_motion(&at_home, value(j));
            joints[i] = head;
        }
    }
    Poses { joints, workpiece: table, carriage, tool: head }
}

/// The tool's orientation relative to the workpiece (its third column is the tool axis in the
/// workpiece's coordinates).
#[must_use]
pub fn relative_orientation(p: &Poses) -> DMat3 {
    p.workpiece.matrix3.transpose() * p.tool.matrix3
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
}
