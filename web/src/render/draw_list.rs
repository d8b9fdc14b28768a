//! The renderer's input after scene interpretation: instances of a few unit meshes, each with a
//! model transform, a colour and a pass. Building it is pure (tested natively); the GPU side
//! only uploads uniforms and draws.

use glam::{DAffine3, DMat3, DQuat, DVec3};

/// The unit meshes uploaded once per GL context.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Cube from −0.5 to +0.5.
    Cube,
    /// Radius 1, from z = 0 to z = 1.
    Cylinder,
    /// Base radius 1 at z = 0, apex at z = 1.
    Cone,
    /// Three quarters of a ring of radius 1 about +Z (tube radius 0.06), from +X turning
    /// counter-clockwise seen from +Z, i.e. positively about +Z.
    CurlArc,
    /// Square of side 1 in the XY plane.
    Square,
    /// A finger of the stylised hand: like [`Shape::CurlArc`] but with a thick tube (0.33).
    Finger,
}

impl Shape {
    /// Every shape, in discriminant order (the renderer's mesh table is indexed by `shape as usize`).
    pub const ALL: [Shape; 6] =
        [Shape::Cube, Shape::Cylinder, Shape::Cone, Shape::CurlArc, Shape::Square, Shape::Finger];
    /// Sweep of [`Shape::CurlArc`] in radians.
    pub const CURL_SWEEP: f32 = 1.5 * std::f32::consts::PI;
    pub const CURL_TUBE: f32 = 0.06;
    pub const FINGER_TUBE: f32 = 0.33;
}

/// How an instance is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pass {
    /// Depth-tested, opaque.
    Opaque,
    /// Translucent after the opaque parts, no depth writes (ghost, working plane).
    Translucent,
    /// Translucent after [`Pass::Translucent`] without the depth test (the colliding pair): a
    /// body inside a drawn part, e.g. the rotary table's body in the table, still shows.
    XRay,
    /// On top of everything (triads), so a coordinate system is never hidden inside the blank.
    Overlay,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Instance {
    pub shape: Shape,
    pub model: DAffine3,
    /// Linear RGB and alpha.
    pub colour: [f32; 4],
    pub pass: Pass,
}

/// A screen label anchored at a world point.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub text: &'static str,
    pub at: DVec3,
    /// CSS colour class suffix (`x`, `y`, `z`, `frame`).
    pub kind: &'static str,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct DrawList {
    pub instances: Vec<Instance>,
    pub labels: Vec<Label>,
}

impl DrawList {
    pub fn push(&mut self, shape: Shape, model: DAffine3, colour: [f32; 4], pass: Pass) {
        self.instances.push(Instance { shape, model, colour, pass });
    }
}

/// The rotation taking +Z to the unit vector `dir` (shortest arc).
#[must_use]
pub fn z_to(dir: DVec3) -> DMat3 {
    DMat3::from_quat(DQuat::from_rotation_arc(DVec3::Z, dir.normalize_or(DVec3::Z)))
}

/// A cylinder of `radius` from `a` to `b`.
#[must_use]
pub fn rod(a: DVec3, b: DVec3, radius: f64) -> DAffine3 {
    let d = b - a;
    let len = d.length().max(1e-6);
    DAffine3::from_mat3_translation(z_to(d) * DMat3::from_diagonal(DVec3::new(radius, radius, len)), a)
}

/// A box of cross-section `w × h` from `a` to `b` (its width along the component of `across`
/// perpendicular to `a → b`).
#[must_use]
pub fn beam(a: DVec3, b: DVec3, w: f64, h: f64, across: DVec3) -> DAffine3 {
    let d = b - a;
    let len = d.length().max(1e-6);
    let z = d / len;
    let x = (across - z * across.dot(z)).try_normalize().unwrap_or_else(|| z.any_orthonormal_vector());
    let y = z.cross(x);
    let rot = DMat3::from_cols(x * w, y * h, z * len);
    DAffine3::from_mat3_translation(rot, (a + b) / 2.0)
}

/// An axis-aligned box (in the frame of `pose`) from `min` to `max`.
#[must_use]
pub fn cuboid(pose: DAffine3, min: DVec3, max: DVec3) -> DAffine3 {
    pose * DAffine3::from_scale_rotation_translation(max - min, glam::DQuat::IDENTITY, (min + max) / 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_lists_every_shape_at_its_discriminant() {
        for (i, s) in Shape::ALL.iter().enumerate() {
            assert_eq!(*s as usize, i, "{s:?}");
        }
    }

    #[test]
    fn rod_maps_the_unit_cylinder_between_its_end_points() {
        let (a, b) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 12.0, 3.0));
        let m = rod(a, b, 2.0);
        assert!((m.transform_point3(DVec3::ZERO) - a).length() < 1e-9);
        assert!((m.transform_point3(DVec3::Z) - b).length() < 1e-9);
        assert!((m.transform_vector3(DVec3::X).length() - 2.0).abs() < 1e-9);
    }

    #[test]
    fn beam_spans_its_end_points_with_its_cross_section() {
        let m = beam(DVec3::ZERO, DVec3::new(0.0, 0.0, 10.0), 4.0, 2.0, DVec3::X);
        assert!((m.transform_point3(DVec3::new(0.0, 0.0, 0.5)) - DVec3::new(0.0, 0.0, 10.0)).length() < 1e-9);
        assert!((m.transform_vector3(DVec3::X) - DVec3::new(4.0, 0.0, 0.0)).length() < 1e-9);
        let skew = beam(DVec3::ZERO, DVec3::X, 1.0, 1.0, DVec3::X);
        assert!(skew.matrix3.determinant().abs() > 0.5, "a degenerate `across` still gives a box");
    }

    #[test]
    fn cuboid_maps_the_unit_cube_to_min_max() {
        let m = cuboid(DAffine3::IDENTITY, DVec3::new(0.0, 0.0, -40.0), DVec3::new(100.0, 100.0, 0.0));
        assert!((m.transform_point3(DVec3::splat(-0.5)) - DVec3::new(0.0, 0.0, -40.0)).length() < 1e-9);
        assert!((m.transform_point3(DVec3::splat(0.5)) - DVec3::new(100.0, 100.0, 0.0)).length() < 1e-9);
    }
}
