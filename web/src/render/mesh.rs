//! Meshes built in code: box, cylinder, cone, torus arc, square plane and line sets.
//! Triangle meshes carry position + normal per vertex (interleaved, 6 floats) and u32 indices;
//! they are built once and uploaded once (see `gpu.rs`).

use glam::{Mat3, Vec3};

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// x, y, z, nx, ny, nz per vertex.
    pub vertices: Vec<f32>,
    pub indices: Vec<u32>,
}

impl Mesh {
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.vertices.len() / 6
    }

    fn push(&mut self, p: Vec3, n: Vec3) -> u32 {
        let i = self.vertex_count() as u32;
        self.vertices.extend_from_slice(&[p.x, p.y, p.z, n.x, n.y, n.z]);
        i
    }

    fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.indices.extend_from_slice(&[a, b, c, a, c, d]);
    }

    /// Appends `other` transformed by rotation `r` and translation `t`.
    pub fn append(&mut self, other: &Mesh, r: Mat3, t: Vec3) {
        let base = self.vertex_count() as u32;
        for v in other.vertices.chunks_exact(6) {
            let p = r * Vec3::new(v[0], v[1], v[2]) + t;
            let n = r * Vec3::new(v[3], v[4], v[5]);
            self.push(p, n);
        }
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }
}

/// Axis-aligned box from `min` to `max`, flat-shaded (24 vertices).
#[must_use]
pub fn cuboid(min: Vec3, max: Vec3) -> Mesh {
    let mut m = Mesh::default();
    let faces: [(Vec3, [Vec3; 4]); 6] = [
        (
            Vec3::X,
            [
                Vec3::new(max.x, min.y, min.z),
                Vec3::new(max.x, max.y, min.z),
                max,
                Vec3::new(max.x, min.y, max.z),
            ],
        ),
        (
            -Vec3::X,
            [
                min,
                Vec3::new(min.x, min.y, max.z),
                Vec3::new(min.x, max.y, max.z),
                Vec3::new(min.x, max.y, min.z),
            ],
        ),
        (
            Vec3::Y,
            [
                Vec3::new(min.x, max.y, min.z),
                Vec3::new(min.x, max.y, max.z),
                max,
                Vec3::new(max.x, max.y, min.z),
            ],
        ),
        (
            -Vec3::Y,
            [
                min,
                Vec3::new(max.x, min.y, min.z),
                Vec3::new(max.x, min.y, max.z),
                Vec3::new(min.x, min.y, max.z),
            ],
        ),
        (
            Vec3::Z,
            [
                Vec3::new(min.x, min.y, max.z),
                Vec3::new(max.x, min.y, max.z),
                max,
                Vec3::new(min.x, max.y, max.z),
            ],
        ),
        (
            -Vec3::Z,
            [
                min,
                Vec3::new(min.x, max.y, min.z),
                Vec3::new(max.x, max.y, min.z),
                Vec3::new(max.x, min.y, min.z),
            ],
        ),
    ];
    for (n, [a, b, c, d]) in faces {
        let (ia, ib, ic, id) = (m.push(a, n), m.push(b, n), m.push(c, n), m.push(d, n));
        m.quad(ia, ib, ic, id);
    }
    m
}

/// Cylinder along +Z from z = 0 to `height`, with caps; `segments` around.
#[must_use]
pub fn cylinder(radius: f32, height: f32, segments: u32) -> Mesh {
    cone_frustum(radius, radius, height, segments)
}

/// Cone along +Z: base radius at z = 0, apex at `height`.
#[must_use]
pub fn cone(radius: f32, height: f32, segments: u32) -> Mesh {
    cone_frustum(radius, 0.0, height, segments)
}

const TAU: f64 = std::f64::consts::TAU;

/// `(sin, cos)` of the angle `i / n · sweep`. Computed in f64 on purpose: the wasm bundle then
/// needs only the f64 sine and cosine the kinematics already use, not a second f32 set.
fn turn(i: u32, n: u32, sweep: f64) -> (f32, f32) {
    let (s, c) = (f64::from(i) / f64::from(n) * sweep).sin_cos();
    (s as f32, c as f32)
}

/// Frustum along +Z from radius `r0` at z = 0 to `r1` at `height`, with caps.
#[must_use]
pub fn cone_frustum(r0: f32, r1: f32, height: f32, segments: u32) -> Mesh {
    let segments = segments.max(3);
    let mut m = Mesh::default();
    // Side normal tilts by the slope of the mantle.
    let slope = (r0 - r1) / height.max(f32::EPSILON);
    for i in 0..=segments {
        let (s, c) = turn(i, segments, TAU);
        let n = Vec3::new(c, s, slope).normalize();
        m.push(Vec3::new(r0 * c, r0 * s, 0.0), n);
        m.push(Vec3::new(r1 * c, r1 * s, height), n);
    }
    for i in 0..segments {
        let k = 2 * i;
        m.quad(k, k + 2, k + 3, k + 1);
    }
    for (z, r, n) in [(0.0, r0, -Vec3::Z), (height, r1, Vec3::Z)] {
        if r <= 0.0 {
            continue;
        }
        let centre = m.push(Vec3::new(0.0, 0.0, z), n);
        let first = m.vertex_count() as u32;
        for i in 0..=segments {
            let (s, c) = turn(i, segments, TAU);
            m.push(Vec3::new(r * c, r * s, z), n);
        }
        for i in 0..segments {
            let (a, b) = (first + i, first + i + 1);
            // Counter-clockwise seen from outside.
            if n.z > 0.0 {
                m.indices.extend_from_slice(&[centre, a, b])
            } else {
                m.indices.extend_from_slice(&[centre, b, a])
            }
        }
    }
    m
}

/// Part of a torus around +Z: `major` radius of the ring, `minor` radius of the tube, from angle
/// 0 to `sweep` (radians, counter-clockwise seen from +Z). Used for the curled-finger arrow.
#[must_use]
pub fn torus_arc(major: f32, minor: f32, sweep: f32, segments: u32, sides: u32) -> Mesh {
    let (segments, sides) = (segments.max(2), sides.max(3));
    let mut m = Mesh::default();
    for i in 0..=segments {
        let (sa, ca) = turn(i, segments, f64::from(sweep));
        let ring = Vec3::new(ca, sa, 0.0);
        for j in 0..=sides {
            let (sb, cb) = turn(j, sides, TAU);
            let n = ring * cb + Vec3::Z * sb;
            m.push(ring * major + n * minor, n);
        }
    }
    let stride = sides + 1;
    for i in 0..segments {
        for j in 0..sides {
            let a = i * stride + j;
            m.quad(a, a + stride, a + stride + 1, a + 1);
        }
    }
    m
}

/// Square of side `size` in the XY plane centred on the origin, normal +Z, both sides visible
/// (the renderer draws it without culling).
#[must_use]
pub fn square(size: f32) -> Mesh {
    let h = size / 2.0;
    let mut m = Mesh::default();
    let c = [Vec3::new(-h, -h, 0.0), Vec3::new(h, -h, 0.0), Vec3::new(h, h, 0.0), Vec3::new(-h, h, 0.0)];
    let [a, b, cc, d] = c.map(|p| m.push(p, Vec3::Z));
    m.quad(a, b, cc, d);
    m
}

/// Line segments with a colour per vertex: x, y, z, r, g, b per vertex, two vertices a segment.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Lines {
    pub vertices: Vec<f32>,
}

impl Lines {
    pub fn segment(&mut self, a: Vec3, b: Vec3, colour: [f32; 3]) {
        for p in [a, b] {
            self.vertices.extend_from_slice(&[p.x, p.y, p.z, colour[0], colour[1], colour[2]]);
        }
    }

    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.vertices.len() / 6
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_indices(m: &Mesh) {
        assert_eq!(m.indices.len() % 3, 0);
        assert!(m.indices.iter().all(|&i| (i as usize) < m.vertex_count()));
        for v in m.vertices.chunks_exact(6) {
            let n = Vec3::new(v[3], v[4], v[5]);
            assert!((n.length() - 1.0).abs() < 1e-5, "normal {n} not unit");
        }
    }

    /// Each triangle's winding must agree with its vertex normals (front faces outwards).
    fn check_winding(m: &Mesh) {
        for t in m.indices.chunks_exact(3) {
            let p = |i: u32| {
                let v = &m.vertices[i as usize * 6..i as usize * 6 + 6];
                (Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]))
            };
            let ((a, na), (b, _), (c, _)) = (p(t[0]), p(t[1]), p(t[2]));
            let face = (b - a).cross(c - a);
            if face.length() > 1e-6 {
                assert!(face.dot(na) > 0.0, "triangle {t:?} winds against its normal");
            }
        }
    }

    #[test]
    fn cuboid_has_six_outward_faces() {
        let m = cuboid(Vec3::ZERO, Vec3::new(100.0, 100.0, 40.0));
        assert_eq!(m.vertex_count(), 24);
        assert_eq!(m.indices.len(), 36);
        check_indices(&m);
        check_winding(&m);
    }

    #[test]
    fn cylinder_cone_and_torus_are_well_formed() {
        for m in [cylinder(5.0, 50.0, 24), cone(2.0, 6.0, 16), torus_arc(20.0, 1.0, 4.7, 32, 8), square(10.0)]
        {
            check_indices(&m);
            check_winding(&m);
        }
    }

    #[test]
    fn append_transforms_positions_and_normals() {
        let mut m = Mesh::default();
        m.append(&square(2.0), Mat3::from_rotation_x(std::f32::consts::FRAC_PI_2), Vec3::new(0.0, 0.0, 5.0));
        let v = &m.vertices[0..6];
        assert!((v[2] - (5.0 - 1.0)).abs() < 1e-5, "corner (-1,-1,0) → z = 5 - 1, got {}", v[2]);
        assert!((Vec3::new(v[3], v[4], v[5]) - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-5);
    }
}
