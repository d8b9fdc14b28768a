//! Inverse kinematics for any machine with two rotary axes: which axis angles put the tool axis
//! t on the target, the singular case, the symmetry point and the residual rotation γ.
//!
//! Convention (DOMAIN.md §3.1): R_machine = Rot(u_slave, θs)·Rot(u_master, θm) with the home
//! directions u of the chain workpiece → tool ([`Machine::forward_deg`]), t = R_machine·ez.
//! Nothing here depends on the machine type: the geometry is Paden–Kahan subproblem 2
//! ("two rotations about intersecting axes map p to q") with p = ez, q = t.

use glam::{DMat3, DVec3};
use serde::Serialize;

use crate::angle::{atan2d, wrap180};
use crate::machine::Machine;
pub use crate::machine::symmetry_positions_of;

/// Below this sine the tool axis counts as parallel to the slave axis: the slave is free
/// (DOMAIN.md §3.4). Numerical choice (derived).
pub const SINGULAR_EPS: f64 = 1e-9;

/// Tolerance of the reachability test (the squared out-of-plane component γ² of Paden–Kahan
/// subproblem 2); between −EPS and +EPS the two solutions coincide. Numerical (derived).
pub const REACH_EPS: f64 = 1e-12;

/// Axis angles `(slave, master)` in degrees, each in (−180, 180].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxisPair {
    pub slave: f64,
    pub master: f64,
}

/// The answer of the inverse kinematics for a tool axis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "case", rename_all = "snake_case")]
pub enum ToolAxisSolution {
    /// Two distinct solutions, mirror images about the master's symmetry point.
    Two { solutions: [AxisPair; 2] },
    /// The two solutions coincide (tool axis at the edge of the reachable cone).
    One { solution: AxisPair },
    /// Tool axis parallel to the slave axis: the master is fixed, the slave is free.
    SlaveFree { master: f64 },
    /// No axis angles reach this tool axis.
    Unreachable,
}

/// Paden–Kahan subproblem 1: the angle θ (degrees) with Rot(u, θ)·p = q, for p and q with equal
/// components along the unit axis u. `None` if p or q lies on the axis (any θ works).
/// Source: derived, θ = atan2(u·(p'×q'), p'·q') with p', q' the parts perpendicular to u.
#[must_use]
pub fn rotation_angle(u: DVec3, p: DVec3, q: DVec3) -> Option<f64> {
    let pp = p - u * u.dot(p);
    let qp = q - u * u.dot(q);
    if pp.length() < SINGULAR_EPS || qp.length() < SINGULAR_EPS {
        return None;
    }
    Some(atan2d(u.dot(pp.cross(qp)), pp.dot(qp)))
}

/// All axis angles that turn the tool axis ez onto `t` (any length; normalised here).
///
/// Paden–Kahan subproblem 2 (derived): the intermediate c = Rot(u_m, θm)·ez = Rot(u_s, −θs)·t
/// satisfies u_m·c = u_m·ez, u_s·c = u_s·t and |c| = 1. Writing c = α u_s + β u_m + γ (u_s × u_m)
/// with w = u_s·u_m gives α = (w (u_m·ez) − u_s·t)/(w²−1), β = (w (u_s·t) − u_m·ez)/(w²−1) and
/// γ² = (1 − α² − β² − 2αβw)/|u_s × u_m|². γ² < 0: unreachable; γ = 0: one solution; else two.
/// Then θm = angle(u_m: ez → c) and θs = angle(u_s: c → t).
#[must_use]
pub fn solve_tool_axis(machine: &Machine, t: DVec3) -> ToolAxisSolution {
    let Some(t) = t.try_normalize() else { return ToolAxisSolution::Unreachable };
    let us = machine.slave().direction;
    let um = machine.master().direction;
    let ez = DVec3::Z;

    // Singular case (DOMAIN.md §3.4): t ∥ u_s, so c = t and only θm is determined.
    if t.cross(us).length() < SINGULAR_EPS {
        if (um.dot(ez) - um.dot(t)).abs() > 1e-9 {
            return ToolAxisSolution::Unreachable;
        }
        return match rotation_angle(um, ez, t) {
            Some(m) => ToolAxisSolution::SlaveFree { master: wrap180(m) },
            // ez ∥ u_m is excluded by the machine check (Problem::MasterAlongTool); t ∥ u_m ∥ … cannot
            // happen with u_s ∦ u_m. Report it as unreachable rather than guess.
            None => ToolAxisSolution::Unreachable,
        };
    }

    let w = us.dot(um);
    let n = us.cross(um);
    let den = w * w - 1.0; // = −|n|², nonzero because the axes are not parallel (validated)
    let (ust, ume) = (us.dot(t), um.dot(ez));
    let alpha = (w * ume - ust) / den;
    let beta = (w * ust - ume) / den;
    let g2 = (1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * w) / n.length_squared();
    if g2 < -REACH_EPS {
        return ToolAxisSolution::Unreachable;
    }
    let base = alpha * us + beta * um;
    let pair = |c: DVec3| -> Option<AxisPair> {
        let master = rotation_angle(um, ez, c)?;
        let slave = rotation_angle(us, c, t)?;
        Some(AxisPair { slave: wrap180(slave), master: wrap180(master) })
    };
    if g2 <= REACH_EPS {
        return match pair(base) {
            Some(solution) => ToolAxisSolution::One { solution },
            None => ToolAxisSolution::Unreachable,
        };
    }
    let g = g2.sqrt();
    match (pair(base + g * n), pair(base - g * n)) {
        (Some(a), Some(b)) => ToolAxisSolution::Two { solutions: [a, b] },
        (Some(solution), None) | (None, Some(solution)) => ToolAxisSolution::One { solution },
        (None, None) => ToolAxisSolution::Unreachable,
    }
}

/// The two symmetry positions of the master axis, 180° apart (DOMAIN.md §3.3, \[S2\]), with "the"
/// symmetry point first ([`crate::unconfirmed::SYMMETRY_POINT_CODIRECTIONAL`]). Computed once per
/// machine by [`Machine::from_json`]; see [`symmetry_positions_of`].
#[must_use]
pub fn symmetry_positions(machine: &Machine) -> [f64; 2] {
    machine.symmetry_positions()
}

/// "The" symmetry point of the master axis (first of [`symmetry_positions`]).
#[must_use]
pub fn symmetry_point(machine: &Machine) -> f64 {
    machine.symmetry_positions()[0]
}

/// Residual rotation γ (degrees) about the tool axis: Rz(γ) = R_machineᵀ·R (DOMAIN.md §3.2),
/// γ = atan2(M21, M11) of M = R_machineᵀ·R.
#[must_use]
pub fn residual(machine: &Machine, axes: AxisPair, r: &DMat3) -> f64 {
    let m = machine.forward_deg(axes.slave, axes.master).transpose() * *r;
    wrap180(atan2d(m.x_axis.y, m.x_axis.x))
}

/// Singular case: the slave value that leaves no residual rotation γ, given the master value.
///
/// Derived: with t = s·u_s (s = ±1), Rot(u_s, θs)·R_m = R_m·Rz(s·θs), so
/// γ(θs) = γ(0) − s·θs; γ = 0 for θs = s·γ(0).
#[must_use]
pub fn free_slave_for_zero_residual(machine: &Machine, master: f64, r: &DMat3) -> f64 {
    let s = r.z_axis.dot(machine.slave().direction).signum();
    let g0 = residual(machine, AxisPair { slave: 0.0, master }, r);
    wrap180(s * g0)
}
