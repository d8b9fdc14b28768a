//! Where the workpiece and the tool are in M-CS for given axis values: the rigid-body model of
//! [`crate::sim`] (see the module doc there for the formulas and their sources).

use glam::{DMat3, DVec3};
use serde::Serialize;

use crate::machine::{Carrier, Machine};

use super::segment::MachineAxes;

/// An affine map x ↦ m·x + v.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Affine {
    pub m: DMat3,
    pub v: DVec3,
}

impl Affine {
    pub const IDENTITY: Affine = Affine { m: DMat3::IDENTITY, v: DVec3::ZERO };

    #[must_use]
    pub fn apply(&self, x: DVec3) -> DVec3 {
        self.m * x + self.v
    }

    /// `self ∘ inner`: first `inner`, then `self`.
    #[must_use]
    pub fn after(&self, inner: &Affine) -> Affine {
        Affine { m: self.m * inner.m, v: self.m * inner.v + self.v }
    }

    /// Inverse of a rigid (orthogonal) map: mᵀ·(x − v). Every map built here is orthogonal
    /// (rotations and mirrors), so the transpose is the inverse.
    #[must_use]
    pub fn inverse_orthogonal(&self) -> Affine {
        let mt = self.m.transpose();
        Affine { m: mt, v: -(mt * self.v) }
    }

    /// Rotation by `deg` about the line through `pivot` with unit direction `dir`:
    /// x ↦ pivot + Rot(dir, deg)·(x − pivot).
    #[must_use]
    pub fn rotation_about(dir: DVec3, pivot: DVec3, deg: f64) -> Affine {
        let m = DMat3::from_axis_angle(dir, deg.to_radians());
        Affine { m, v: pivot - m * pivot }
    }
}

/// One rotary joint as the rigid-body model needs it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JointGeo {
    pub carrier: Carrier,
    /// Unit direction at home, M-CS.
    pub dir: DVec3,
    /// Table axis: a point on the axis in M-CS at home. Head axis: a point on the axis relative
    /// to the spindle gauge point with the head at home.
    pub pivot: DVec3,
}

/// The machine's rigid-body model: both joints in chain order workpiece → tool, the preset and
/// the active tool length. Small and `Copy`, so a MOVE segment carries its own copy.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Kin {
    pub joints: [JointGeo; 2],
    /// W-CS origin in M-CS at rotary zero.
    pub preset: DVec3,
    /// Active tool length (incl. DL), mm: the gauge point sits `tool_length` above the tip
    /// along the tool axis.
    pub tool_length: f64,
}

impl Kin {
    #[must_use]
    pub fn new(machine: &Machine, tool_length: f64) -> Kin {
        let j = machine.joints();
        let geo = |k: usize| JointGeo { carrier: j[k].carrier, dir: j[k].direction, pivot: j[k].pivot };
        Kin { joints: [geo(0), geo(1)], preset: machine.geometry.preset, tool_length }
    }

    /// Pose of the workpiece: maps workpiece coordinates (= M-CS at rotary zero) to M-CS.
    /// W = T_n ∘ … ∘ T_1 over the table joints in chain order, T_j = rotation by −θ_j about
    /// the joint's axis through its pivot (DOMAIN.md §3.1: a table axis turns the workpiece by −θ;
    /// derived: the joint nearest the workpiece is carried by the next one, so it acts first).
    #[must_use]
    pub fn workpiece_pose(&self, rotary: [f64; 2]) -> Affine {
        self.table_pose(0, rotary)
    }

    /// Pose of what table joint `from` carries (its home M-CS coordinates to M-CS): the product
    /// of [`Kin::workpiece_pose`] over the table joints from `from` on; `from` = 2 (none) is the
    /// bed, which never moves.
    #[must_use]
    pub fn table_pose(&self, from: usize, rotary: [f64; 2]) -> Affine {
        self.table_poses(rotary).get(from).copied().unwrap_or(Affine::IDENTITY)
    }

    /// [`Kin::table_pose`] for `from` = 0, 1, 2 at once (each turn computed once): the joint
    /// further from the workpiece carries the nearer one, so `pose[k] = pose[k + 1] ∘ T_k`.
    #[must_use]
    pub fn table_poses(&self, rotary: [f64; 2]) -> [Affine; 3] {
        let mut poses = [Affine::IDENTITY; 3];
        for k in (0..2).rev() {
            let j = &self.joints[k];
            poses[k] = if j.carrier == Carrier::Table {
                poses[k + 1].after(&Affine::rotation_about(j.dir, j.pivot, -rotary[k]))
            } else {
                poses[k + 1]
            };
        }
        poses
    }

    /// Pose of the head relative to the linear axes: maps tool coordinates (tip at the origin,
    /// tool along +Z, head at home) to an offset from the linear axis position.
    /// H = T_h1 ∘ T_h2 over the head joints in chain order (the one nearest the bed carries the
    /// next, so the one nearest the tool acts first), T_h = rotation by +θ about the axis through
    /// `(0, 0, tool_length) + pivot` (derived, DOMAIN.md §3.1: head axes turn the tool by +θ).
    #[must_use]
    pub fn head_pose(&self, rotary: [f64; 2]) -> Affine {
        let gauge = DVec3::new(0.0, 0.0, self.tool_length);
        let mut h = Affine::IDENTITY;
        for (j, theta) in self.joints.iter().zip(rotary).rev() {
            if j.carrier == Carrier::Head {
                h = Affine::rotation_about(j.dir, gauge + j.pivot, theta).after(&h);
            }
        }
        h
    }

    /// The physical tool tip in M-CS: L + H(0).
    #[must_use]
    pub fn tip_mcs(&self, axes: &MachineAxes) -> DVec3 {
        axes.linear + self.head_pose(axes.rotary).v
    }

    /// The physical tool tip in W-CS coordinates: W⁻¹(tip) − preset.
    #[must_use]
    pub fn tip_wcs(&self, axes: &MachineAxes) -> DVec3 {
        self.workpiece_pose(axes.rotary).inverse_orthogonal().apply(self.tip_mcs(axes)) - self.preset
    }

    /// The physical tool axis (tip → spindle) in W-CS coordinates.
    #[must_use]
    pub fn tool_axis_wcs(&self, rotary: [f64; 2]) -> DVec3 {
        self.workpiece_pose(rotary).m.transpose() * (self.head_pose(rotary).m * DVec3::Z)
    }

    /// The tool axis in M-CS (the direction of `MB` retracts).
    #[must_use]
    pub fn tool_axis_mcs(&self, rotary: [f64; 2]) -> DVec3 {
        self.head_pose(rotary).m * DVec3::Z
    }

    /// The map W-CS point → linear axis values that puts the physical tool tip on that point of
    /// the workpiece with the rotary axes at `rotary`: L = W(preset + p) − H(0)
    /// (derived: inverse of [`Kin::tip_wcs`] for fixed rotary axes).
    #[must_use]
    pub fn wcs_to_linear(&self, rotary: [f64; 2]) -> Affine {
        let w = self.workpiece_pose(rotary);
        let h = self.head_pose(rotary);
        Affine { m: w.m, v: w.apply(self.preset) - h.v }
    }
}
