//! The live preview of a plane while its values are typed: the tilted square and its triad in
//! a fixed isometric view, as SVG line coordinates (pure; the component only draws them).

use glam::{DMat3, DVec3};
use schwenkbar_core::orientation::{Context, orientation, to_spatial};
use schwenkbar_core::parse::plane_block;
use schwenkbar_core::plane::PlaneDef;

/// A line in SVG user space with its CSS class.
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    pub from: (f64, f64),
    pub to: (f64, f64),
    pub class: &'static str,
}

/// Half the side of the drawn square, in the units of the view box (−100…100).
const HALF: f64 = 45.0;
const AXIS: f64 = 70.0;

/// Isometric projection of a W-CS point: X to the lower right, Y to the upper right, Z up
/// (the control's usual 3D view), screen y pointing down as in SVG.
#[must_use]
pub fn project(p: DVec3) -> (f64, f64) {
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    (c * (p.x + p.y), s * (p.x - p.y) - p.z)
}

/// The untilted square (faint), the tilted one and the tilted triad X' red, Y' green, Z' blue.
#[must_use]
pub fn strokes(r: &DMat3) -> Vec<Stroke> {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    let mut out = Vec::with_capacity(11);
    for (rot, class) in [(DMat3::IDENTITY, "plane-home"), (*r, "plane-tilted")] {
        for k in 0..4 {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            let pa = rot * DVec3::new(a.0 * HALF, a.1 * HALF, 0.0);
            let pb = rot * DVec3::new(b.0 * HALF, b.1 * HALF, 0.0);
            out.push(Stroke { from: project(pa), to: project(pb), class });
        }
    }
    for (col, class) in [(r.x_axis, "axis-x"), (r.y_axis, "axis-y"), (r.z_axis, "axis-z")] {
        out.push(Stroke { from: (0.0, 0.0), to: project(col * AXIS), class });
    }
    out
}

/// The orientation of what is typed so far, if it can be computed yet.
#[must_use]
pub fn orientation_of(def: &PlaneDef<f64>, active: DMat3) -> Option<DMat3> {
    orientation(def, &Context { active, ..Context::default() }).ok()
}

/// The spatial angles `[SPA, SPB, SPC]` of the PLANE block in `text` (any form the orientation
/// maths reads without a machine), rounded to the control's 4 decimals, or `None` when it has
/// none (not one readable PLANE block, a Q parameter, PLANE AXIAL).
#[must_use]
pub fn block_angles(text: &str) -> Option<[f64; 3]> {
    let block = plane_block(text).ok()?.numbers().ok()?;
    let r = orientation(&block.def, &Context::default()).ok()?;
    Some(to_spatial(&r).map(|a| (a * 1e4).round() / 1e4 + 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positive_spb_tips_the_drawn_tool_axis_towards_plus_x() {
        let r = orientation_of(&PlaneDef::Spatial { spa: 0.0, spb: 30.0, spc: 0.0 }, DMat3::IDENTITY);
        let r = r.expect("valid");
        let z = strokes(&r).into_iter().find(|s| s.class == "axis-z").expect("Z' axis");
        let x_dir = project(DVec3::X);
        // The Z' arrow leans the way +X points on screen (right) and still points up.
        assert!(z.to.0 * x_dir.0 > 0.0, "{z:?}");
        assert!(z.to.1 < 0.0);
    }

    #[test]
    fn out_of_range_values_give_no_preview_instead_of_a_panic() {
        assert!(
            orientation_of(&PlaneDef::Euler { eulpr: 0.0, eulnu: 200.0, eulrot: 0.0 }, DMat3::IDENTITY)
                .is_none()
        );
    }
}
