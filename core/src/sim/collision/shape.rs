//! The shapes of the bodies as placed and the tests between them: separating axes for boxes,
//! exact segment distances for capsules (the module doc of [`super`] says which and why).

use glam::{DMat3, DVec3};
use serde::Serialize;

use super::RESOLUTION;

/// An oriented box: centre, unit axes (columns), half edge lengths.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Obb {
    pub center: DVec3,
    pub axes: DMat3,
    pub half: DVec3,
}

/// The points within `radius` of the segment `a`–`b`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Capsule {
    pub a: DVec3,
    pub b: DVec3,
    pub radius: f64,
}

/// A body placed in M-CS.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "shape", rename_all = "snake_case")]
pub enum Placed {
    Box(Obb),
    /// A cylinder as its capsule and its bounding box (module doc).
    Cylinder {
        capsule: Capsule,
        bound: Obb,
    },
}

impl Placed {
    /// The box that holds it: itself, or a cylinder's bounding box.
    #[must_use]
    pub fn bound(&self) -> Obb {
        match *self {
            Placed::Box(o) | Placed::Cylinder { bound: o, .. } => o,
        }
    }

    /// A cylinder from the centre of one end face, the unit direction to the other, radius and
    /// height.
    #[must_use]
    pub fn cylinder(base: DVec3, direction: DVec3, radius: f64, height: f64) -> Placed {
        let (e1, e2) = direction.any_orthonormal_pair();
        Placed::Cylinder {
            capsule: Capsule { a: base, b: base + direction * height, radius },
            bound: Obb {
                center: base + direction * (0.5 * height),
                axes: DMat3::from_cols(e1, e2, direction),
                half: DVec3::new(radius, radius, 0.5 * height),
            },
        }
    }
}

/// `true` if `a` and `b` come within `margin` (mm) of each other (conservatively: module doc).
#[must_use]
pub fn touch(a: &Placed, b: &Placed, margin: f64) -> bool {
    match (a, b) {
        (Placed::Box(x), Placed::Box(y)) => obb_obb(x, y, margin),
        (Placed::Box(o), Placed::Cylinder { capsule, bound })
        | (Placed::Cylinder { capsule, bound }, Placed::Box(o)) => {
            obb_obb(o, bound, margin)
                && segment_obb_distance(capsule.a, capsule.b, o) <= capsule.radius + margin
        }
        (Placed::Cylinder { capsule: c, bound: o }, Placed::Cylinder { capsule: d, bound: p }) => {
            obb_obb(o, p, margin)
                && segment_segment_distance(c.a, c.b, d.a, d.b) <= c.radius + d.radius + margin
                && segment_obb_distance(c.a, c.b, p) <= c.radius + margin
                && segment_obb_distance(d.a, d.b, o) <= d.radius + margin
        }
    }
}

/// Separating-axis test of two boxes with a margin: `false` if some axis separates them by more
/// than `margin`.
fn obb_obb(a: &Obb, b: &Obb, margin: f64) -> bool {
    obb_gap(a, b) <= margin
}

/// The widest gap between the projections of two boxes on the 15 separating-axis candidates
/// (unit axes; Ericson §4.4.1), negative when they overlap on all. Projecting on a unit axis
/// shortens no distance, so it is a lower bound on the boxes' distance. A NaN gap counts as
/// none (the pair is then not called apart).
fn obb_gap(a: &Obb, b: &Obb) -> f64 {
    let t = b.center - a.center;
    let ax = [a.axes.x_axis, a.axes.y_axis, a.axes.z_axis];
    let bx = [b.axes.x_axis, b.axes.y_axis, b.axes.z_axis];
    let gap = |l: DVec3| {
        let ra =
            a.half.x * ax[0].dot(l).abs() + a.half.y * ax[1].dot(l).abs() + a.half.z * ax[2].dot(l).abs();
        let rb =
            b.half.x * bx[0].dot(l).abs() + b.half.y * bx[1].dot(l).abs() + b.half.z * bx[2].dot(l).abs();
        t.dot(l).abs() - ra - rb
    };
    let mut widest = f64::NEG_INFINITY;
    for k in 0..3 {
        widest = widest.max(gap(ax[k])).max(gap(bx[k]));
    }
    for u in ax {
        for v in bx {
            // Parallel edges give no new axis (the face axes cover them).
            if let Some(l) = u.cross(v).try_normalize() {
                widest = widest.max(gap(l));
            }
        }
    }
    widest
}

/// The widest separating-axis gap between box `a` swept by the translation `d` (every point of
/// `a + f·d`, 0 ≤ f ≤ 1) and box `b`; a lower bound on their distance all along the sweep.
/// The swept box is the zonotope of `a`'s three edges and `d`, so the candidate axes are the
/// face normals of both (`a`'s axes, `a`'s axes × `d`, `b`'s axes) and the cross products of
/// their edge directions (`a`'s axes × `b`'s axes, `d` × `b`'s axes): the separating-axis theorem
/// for convex polyhedra (Ericson §4.4.1, §5.5.7 on moving boxes) makes the test exact. `d` adds
/// `|d·l|/2` to the projected radius of `a`, whose centre moves to the middle of the sweep.
/// Stops at the face axes when they already part the two by more than [`RESOLUTION`].
#[must_use]
pub fn swept_obb_gap(a: &Obb, d: DVec3, b: &Obb) -> f64 {
    // In `b`'s frame (its axes the unit vectors): `a`'s axes are the columns of r, its centre
    // at the middle of the sweep t, half the sweep h.
    let bt = b.axes.transpose();
    let r = bt * a.axes;
    let t = bt * (a.center + 0.5 * d - b.center);
    let h = bt * (0.5 * d);
    let ax = [r.x_axis, r.y_axis, r.z_axis];
    let gap = |l: DVec3| {
        let ra = a.half.x * ax[0].dot(l).abs()
            + a.half.y * ax[1].dot(l).abs()
            + a.half.z * ax[2].dot(l).abs()
            + h.dot(l).abs();
        t.dot(l).abs() - ra - b.half.dot(l.abs())
    };
    // `b`'s face axes: the unit vectors, each projection one component.
    let abs_r = [ax[0].abs(), ax[1].abs(), ax[2].abs()];
    let reach = abs_r[0] * a.half.x + abs_r[1] * a.half.y + abs_r[2] * a.half.z + h.abs();
    let mut widest = (t.abs() - reach - b.half).max_element();
    for u in ax {
        widest = widest.max(gap(u));
    }
    // Machine parts mostly stand apart along a face axis: then the other axes are not needed
    // (any separating axis gives a lower bound).
    if widest > RESOLUTION {
        return widest;
    }
    let dl = bt * d;
    for v in [DVec3::X, DVec3::Y, DVec3::Z] {
        for u in ax.into_iter().chain([dl]) {
            if let Some(l) = u.cross(v).try_normalize() {
                widest = widest.max(gap(l));
            }
        }
    }
    for u in ax {
        if let Some(l) = u.cross(dl).try_normalize() {
            widest = widest.max(gap(l));
        }
    }
    widest
}

/// A lower bound on the distance of two placed bodies (0 or less when they may touch): the
/// widest separating-axis gap of their boxes (a cylinder's bounding box), and for two cylinders
/// also their capsules' distance. Each shape lies inside what is measured, so no bound exceeds
/// the true distance.
#[must_use]
pub fn separation(a: &Placed, b: &Placed) -> f64 {
    let sat = obb_gap(&a.bound(), &b.bound());
    match (a, b) {
        (Placed::Cylinder { capsule: c, .. }, Placed::Cylinder { capsule: d, .. }) => {
            sat.max(segment_segment_distance(c.a, c.b, d.a, d.b) - c.radius - d.radius)
        }
        _ => sat,
    }
}

/// Distance between the segments p1–q1 and p2–q2 (Ericson §5.1.9, clamped closest points).
#[must_use]
pub fn segment_segment_distance(p1: DVec3, q1: DVec3, p2: DVec3, q2: DVec3) -> f64 {
    const EPS: f64 = 1e-12;
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (s, t) = if a <= EPS && e <= EPS {
        (0.0, 0.0)
    } else if a <= EPS {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(r);
        if e <= EPS {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(d2);
            let denom = a * e - b * b;
            let mut s = if denom > EPS { ((b * f - c * e) / denom).clamp(0.0, 1.0) } else { 0.0 };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    ((p1 + d1 * s) - (p2 + d2 * t)).length()
}

/// Distance of a point from a box.
#[must_use]
pub fn point_obb_distance(p: DVec3, o: &Obb) -> f64 {
    let local = o.axes.transpose() * (p - o.center);
    (local.abs() - o.half).max(DVec3::ZERO).length()
}

/// Distance of the segment a–b from a box: the distance of a point from a convex set is convex
/// along a segment, so golden-section search finds its minimum (60 steps shrink the bracket to
/// 1e-12 of the segment; the small slack keeps the result a lower bound).
#[must_use]
pub fn segment_obb_distance(a: DVec3, b: DVec3, o: &Obb) -> f64 {
    let m = o.axes.transpose();
    let (la, lb) = (m * (a - o.center), m * (b - o.center));
    let dist = |t: f64| (la.lerp(lb, t).abs() - o.half).max(DVec3::ZERO).length();
    const G: f64 = 0.618_033_988_749_894_8;
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    let mut best = dist(0.0).min(dist(1.0));
    let (mut x1, mut x2) = (hi - G * (hi - lo), lo + G * (hi - lo));
    let (mut f1, mut f2) = (dist(x1), dist(x2));
    for _ in 0..60 {
        if best == 0.0 {
            break;
        }
        if f1 <= f2 {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = hi - G * (hi - lo);
            f1 = dist(x1);
        } else {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = lo + G * (hi - lo);
            f2 = dist(x2);
        }
        best = best.min(f1).min(f2);
    }
    (best - 1e-9 * (lb - la).length()).max(0.0)
}
