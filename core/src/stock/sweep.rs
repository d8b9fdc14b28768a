//! The cutting solid of a tool and where a ray crosses the volume it sweeps on a straight move
//! with a fixed orientation, in closed form.
//!
//! # The tool as pieces of revolution
//! In the tool frame (tip at the origin, tool axis = +z) every shape is a union of convex pieces
//! of revolution, each one quadric inequality plus a slab `z0 ≤ z ≤ z1`:
//! * a frustum `x² + y² ≤ (a + b·z)²` (b = 0: cylinder; a = 0: cone from the tip),
//! * a ball `x² + y² + (z − c)² ≤ r²`.
//!
//! Flat end mill: one cylinder `R`, `0 ≤ z ≤ L`. Ball nose: a ball of radius `R` centred `R`
//! above the tip and the cylinder above it. Drill: the point cone `r = z·tan(φ/2)` up to
//! `h = R / tan(φ/2)` and the cylinder above. Bull nose: the corner arc
//! `r(z) = R − rc + √(rc² − (rc − z)²)`, `0 ≤ z ≤ rc`, as frustums between points on the arc
//! (inscribed: the chords lie inside the exact profile, the radial error is at most the sagitta
//! `rc·(1 − cos(Δ/2))` of the arc step Δ, chosen below a quarter of the stock's resolution;
//! no closed form of a ray against a *swept* torus exists, its quartic grows to degree 8), and
//! the cylinder above. The whole tool length cuts: the model has no shank or holder.
//!
//! # A ray against a swept piece
//! Moving the piece `T` from `p0` to `p1` sweeps `⋃_{t∈[0,1]} (T + t·(p1 − p0))`, the Minkowski
//! sum of `T` and the segment, which is convex because `T` is. A ray point `r0 + λ·r` is inside
//! when some `t ∈ [0,1]` puts it in `T`; in the tool frame that is the point
//! `P(λ, t) = o + λ·u + t·w` (`o` = ray origin − `p0`, `u` = ray direction, `w` = −(p1 − p0),
//! all rotated into the tool frame). The set of `(λ, t)` is convex and bounded by one conic
//! `Q(λ, t) = Aλ² + Bλt + Ct² + Dλ + Et + F ≤ 0` (the quadric restricted to the plane) and four
//! lines (the slab and `0 ≤ t ≤ 1`). The smallest and largest λ of a compact convex set lie on
//! its boundary where either two boundary curves meet or the conic's tangent is parallel to the
//! t axis (∂Q/∂t = 0); so the extremes are among: the line–line vertices, the line–conic
//! intersections and the conic's two λ-extreme points, each kept if it satisfies every other
//! constraint (the standard Karush–Kuhn–Tucker enumeration of a 2D convex program, e.g.
//! Boyd & Vandenberghe, *Convex Optimization*, 2004, §5.5.3). Pieces of one tool overlap, and
//! the sweep of the whole (convex) tool is convex, so the pieces' intervals on one ray join to
//! one interval. Motion along the ray, a standing tool or a ray along the axis need no special
//! case: the enumeration covers degenerate conics (a quadratic in one unknown turning linear).
//!
//! # Less work, the same result
//! A ball's sweep is a capsule, met in closed form ([`capsule_interval`]; the enumeration is its
//! test oracle). The other pieces are enumerated only on rays whose material their sweep can
//! reach: a cheap bound (the slab, [`Piece::slab`], met with the 2D capsule of the axis's
//! shadow, [`Piece::radial`])
//! that holds no material skips the piece, which changes nothing, since the pieces' intervals
//! join to one and a part without material removes none ([`Cutter::material_interval`]).

use glam::DVec3;

use crate::sim::tools::ToolShape;

/// Points within this distance of a line constraint count as on it (mm): f64 roundoff of
/// coordinates up to 10⁴ mm stays far below it.
const TOL_LINE: f64 = 1e-7;
/// The same for the conic (mm², about `2·radius·TOL_LINE` for radii up to a few mm).
const TOL_QUAD: f64 = 1e-6;

/// One convex piece of revolution in the tool frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    /// A ball: its sweep is a capsule, cut in closed form ([`capsule_interval`]).
    ball: bool,
    /// Quadric `x² + y² + s·z² + 2·g·z + h ≤ 0`.
    s: f64,
    g: f64,
    h: f64,
    z0: f64,
    z1: f64,
}

impl Piece {
    /// Frustum of radius `a + b·z` for `z0 ≤ z ≤ z1` (radius ≥ 0 there).
    fn frustum(a: f64, b: f64, z0: f64, z1: f64) -> Piece {
        // x² + y² − (a + b·z)² = x² + y² − b²z² − 2ab·z − a².
        Piece { ball: false, s: -b * b, g: -a * b, h: -a * a, z0, z1 }
    }

    /// The λ range where the line `o + λ·u` lies within this piece's slab `z0 ≤ z ≤ z1` for
    /// some t in [0, 1] (the piece swept by `−w`, see [`piece_interval`]): it holds where the
    /// line meets the sweep, and costs no root. `None`: the line misses the slab's sweep.
    fn slab(&self, o: DVec3, u: DVec3, w: DVec3) -> Option<(f64, f64)> {
        // z0 ≤ o.z + λ·u.z + t·w.z ≤ z1.
        let (wl, wh) = (w.z.min(0.0), w.z.max(0.0));
        if u.z.abs() > 1e-12 {
            let (x, y) = ((self.z0 - o.z - wh) / u.z, (self.z1 - o.z - wl) / u.z);
            Some((x.min(y), x.max(y)))
        } else if o.z + wh < self.z0 || o.z + wl > self.z1 {
            None
        } else {
            Some((f64::NEG_INFINITY, f64::INFINITY))
        }
    }

    /// `range` narrowed to where the line lies within the piece's largest radius of the axis
    /// for some t (seen along the axis, a 2D capsule): with [`Piece::slab`] a bound of the
    /// sweep cheaper than the exact one. `None`: the line misses the sweep.
    fn radial(&self, o: DVec3, u: DVec3, w: DVec3, range: (f64, f64)) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = range;
        let r = self.widest() * (1.0 + 1e-9) + 1e-9;
        if let Some(range) = shadow(o, u, w, r, 1e-12) {
            let (a, b) = range?;
            lo = lo.max(a);
            hi = hi.min(b);
        } else {
            // Along the axis: within the radius for every λ or for none. The nearest point of
            // the segment from 0 to m2 (the axis's shadow moving).
            let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
            let (o2, m2) = (flat(o), -flat(w));
            let mm = m2.length_squared();
            let along = if mm > 0.0 { (o2.dot(m2) / mm).clamp(0.0, 1.0) } else { 0.0 };
            if (o2 - along * m2).length() > r {
                return None;
            }
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// The piece's largest radius: a ball's own, √(g² − h); a frustum's, √(−(s·z² + 2g·z + h)),
    /// at either end of the slab (its radius is linear in z).
    fn widest(&self) -> f64 {
        if self.ball {
            return (self.g * self.g - self.h).max(0.0).sqrt();
        }
        let radius = |z: f64| (-(self.s * z * z + 2.0 * self.g * z + self.h)).max(0.0).sqrt();
        radius(self.z0).max(radius(self.z1))
    }

    /// What a cylinder's sweep removes from a line holding material where `touches` says:
    /// seen along the axis the line runs within the radius of the axis's moving shadow over a
    /// λ range (a 2D capsule), which with the slab range `slab` bounds the sweep. When the slab
    /// holds the line over that range for every t (its height is linear in λ and t, so the
    /// range's ends and t = 0, 1 suffice), the range is the sweep's exactly; else an end binds
    /// and [`piece_interval`] decides. `None`: not a cylinder, or a line along its axis (then
    /// [`Piece::radial`] and the enumeration); `Some(None)`: nothing to remove.
    #[allow(clippy::option_option)]
    fn swept_cylinder(
        &self,
        o: DVec3,
        u: DVec3,
        w: DVec3,
        slab: (f64, f64),
        touches: impl Fn((f64, f64)) -> bool,
    ) -> Option<Option<(f64, f64)>> {
        if self.s != 0.0 || self.g != 0.0 {
            return None;
        }
        let Some((a, b)) = shadow(o, u, w, (-self.h).max(0.0).sqrt(), 1e-9)? else { return Some(None) };
        if !touches((a.max(slab.0), b.min(slab.1))) {
            return Some(None);
        }
        let (wl, wh) = (w.z.min(0.0), w.z.max(0.0));
        let free = |l: f64| {
            let z = o.z + l * u.z;
            z + wl >= self.z0 && z + wh <= self.z1
        };
        Some(if free(a) && free(b) { Some((a, b)) } else { piece_interval(self, o, u, w) })
    }

    /// A ball's sweep: a capsule ([`capsule_interval`]); centre at z = −g, radius² = g² − h.
    fn swept_ball(&self, o: DVec3, u: DVec3, w: DVec3) -> Option<(f64, f64)> {
        let c = -self.g;
        capsule_interval(o - DVec3::new(0.0, 0.0, c), u, -w, (c * c - self.h).max(0.0).sqrt())
    }

    /// Ball of radius `r` centred at `z = c`.
    fn ball(c: f64, r: f64) -> Piece {
        // x² + y² + (z − c)² − r² = x² + y² + z² − 2c·z + c² − r².
        Piece { ball: true, s: 1.0, g: -c, h: c * c - r * r, z0: c - r, z1: c + r }
    }
}

/// A tool as the stock cuts it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Cutter {
    pub pieces: Vec<Piece>,
    pub radius: f64,
    pub length: f64,
}

impl Cutter {
    /// The pieces of a tool of `radius` and `length` (mm); `tolerance` bounds the bull nose's
    /// profile error. A radius or length ≤ 0 (or not finite) cuts nothing.
    pub fn new(shape: ToolShape, radius: f64, length: f64, tolerance: f64) -> Cutter {
        let (r, l) = (radius, length);
        if !(r.is_finite() && l.is_finite() && r > 0.0 && l > 0.0) {
            return Cutter { pieces: Vec::new(), radius: 0.0, length: 0.0 };
        }
        let mut pieces = Vec::new();
        // Height where the cylinder starts; below it the shape's own tip.
        let base = match shape {
            ToolShape::Flat => 0.0,
            ToolShape::Ball => {
                pieces.push(Piece::ball(r, r));
                r
            }
            ToolShape::Drill { point_angle } => {
                let k = (point_angle.to_radians() / 2.0).tan();
                let h = r / k;
                pieces.push(Piece::frustum(0.0, k, 0.0, h.min(l)));
                h
            }
            ToolShape::Bull { corner_radius } => {
                let rc = corner_radius.min(r);
                if rc > 0.0 {
                    // Arc step Δ with rc·(1 − cos(Δ/2)) ≤ tolerance; the quarter arc in n steps.
                    let tol = tolerance.max(1e-6);
                    let max_step = 2.0 * (1.0 - (tol / rc).min(1.0)).acos();
                    let n = ((std::f64::consts::FRAC_PI_2 / max_step).ceil() as usize).clamp(1, 256);
                    // Arc point at angle θ from the bottom: z = rc − rc·cos θ, r = R − rc + rc·sin θ.
                    let at = |i: usize| {
                        let th = std::f64::consts::FRAC_PI_2 * i as f64 / n as f64;
                        (rc - rc * th.cos(), r - rc + rc * th.sin())
                    };
                    for i in 0..n {
                        let ((za, ra), (zb, rb)) = (at(i), at(i + 1));
                        let b = (rb - ra) / (zb - za);
                        pieces.push(Piece::frustum(ra - b * za, b, za, zb));
                    }
                }
                rc
            }
        };
        if base < l {
            pieces.push(Piece::frustum(r, 0.0, base, l));
        }
        Cutter { pieces, radius: r, length: l }
    }

    /// This tool moving straight from tip `p0` to tip `p1` with tool axis `frame[2]` (`frame`
    /// orthonormal, columns x, y, axis), ready for its rays.
    pub fn sweep(&self, frame: [DVec3; 3], p0: DVec3, p1: DVec3) -> Sweep<'_> {
        let local = |v: DVec3| DVec3::new(frame[0].dot(v), frame[1].dot(v), frame[2].dot(v));
        let t = frame[2];
        // Each piece lies within its widest radius of its stretch of the axis; a disc of radius
        // r square to t reaches r·√(1 − t_k²) along axis k.
        let disc = DVec3::ONE - t * t;
        let disc = DVec3::new(disc.x.max(0.0).sqrt(), disc.y.max(0.0).sqrt(), disc.z.max(0.0).sqrt());
        let boxes = self
            .pieces
            .iter()
            .map(|piece| {
                let (lo, hi) = if piece.ball {
                    // The centre's segment grown by the radius.
                    let c = -piece.g * t;
                    let r = DVec3::splat(piece.widest());
                    ((p0 + c).min(p1 + c) - r, (p0 + c).max(p1 + c) + r)
                } else {
                    let ends = [p0 + piece.z0 * t, p0 + piece.z1 * t, p1 + piece.z0 * t, p1 + piece.z1 * t];
                    let grow = piece.widest() * disc;
                    let lo = ends.iter().fold(DVec3::INFINITY, |a, e| a.min(*e));
                    let hi = ends.iter().fold(DVec3::NEG_INFINITY, |a, e| a.max(*e));
                    (lo - grow, hi + grow)
                };
                // A hair wider: roundoff must not drop a ray the piece touches.
                let hair = DVec3::splat(1e-9 * (1.0 + lo.abs().max(hi.abs()).max_element()));
                (lo - hair, hi + hair)
            })
            .collect();
        Sweep { cutter: self, frame, p0, w: -local(p1 - p0), boxes }
    }

    /// Where the ray `r0 + λ·dir` crosses the volume swept by this tool moving from tip `p0` to
    /// tip `p1` with tool axis `frame[2]`: `(λmin, λmax)`, or `None` if it misses;
    /// [`Sweep::material_interval`] of a ray in material all along.
    #[cfg(test)]
    pub fn ray_interval(
        &self,
        frame: &[DVec3; 3],
        p0: DVec3,
        p1: DVec3,
        r0: DVec3,
        dir: DVec3,
    ) -> Option<(f64, f64)> {
        let all = super::Span { lo: f64::NEG_INFINITY, hi: f64::INFINITY };
        self.sweep(*frame, p0, p1).material_interval(r0, dir, &[all])
    }
}

/// A tool's straight sweep ([`Cutter::sweep`]): what every ray of one cut shares.
pub(crate) struct Sweep<'a> {
    cutter: &'a Cutter,
    frame: [DVec3; 3],
    p0: DVec3,
    /// −(p1 − p0) in the tool frame.
    w: DVec3,
    /// Per piece, the box its sweep lies in (W-CS).
    boxes: Vec<(DVec3, DVec3)>,
}

impl Sweep<'_> {
    /// What the whole sweep would remove from the ray `r0 + λ·dir` holding `material`: the same
    /// material, with less work. A piece whose sweep cannot reach the material is skipped: the
    /// ray passes its box (along an axis the ray does not move on), or the material lies
    /// outside its cheap bounds ([`Piece::slab`], [`Piece::radial`]). The pieces' intervals
    /// join to the sweep's one interval, and leaving out a part without material removes the
    /// same material. `None`: nothing to remove.
    pub fn material_interval(&self, r0: DVec3, dir: DVec3, material: &[super::Span]) -> Option<(f64, f64)> {
        let frame = &self.frame;
        let local = |v: DVec3| DVec3::new(frame[0].dot(v), frame[1].dot(v), frame[2].dot(v));
        let (o, u, w) = (local(r0 - self.p0), local(dir), self.w);
        let mut out: Option<(f64, f64)> = None;
        let touches = |(lo, hi): (f64, f64)| material.iter().any(|s| s.hi > lo && s.lo < hi);
        let passes =
            |(lo, hi): &(DVec3, DVec3)| (0..3).any(|k| dir[k] == 0.0 && (r0[k] < lo[k] || r0[k] > hi[k]));
        for (piece, bounds) in self.cutter.pieces.iter().zip(&self.boxes) {
            // The cheap bounds first: most rays' material lies beyond most pieces' reach.
            if passes(bounds) {
                continue;
            }
            let Some(slab) = piece.slab(o, u, w).filter(|&b| touches(b)) else { continue };
            let hit = if piece.ball {
                piece.swept_ball(o, u, w)
            } else if let Some(hit) = piece.swept_cylinder(o, u, w, slab, touches) {
                hit
            } else {
                match piece.radial(o, u, w, slab) {
                    Some(b) if touches(b) => piece_interval(piece, o, u, w),
                    _ => None,
                }
            };
            if let Some((a, b)) = hit {
                out = Some(out.map_or((a, b), |(lo, hi)| (lo.min(a), hi.max(b))));
            }
        }
        out
    }
}

/// `αλ + βt + γ ≥ 0`.
#[derive(Clone, Copy)]
struct Half {
    a: f64,
    b: f64,
    c: f64,
}

impl Half {
    fn at(&self, l: f64, t: f64) -> f64 {
        self.a * l + self.b * t + self.c
    }
}

/// The conic `Aλ² + Bλt + Ct² + Dλ + Et + F`.
struct Conic {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: f64,
    f: f64,
}

impl Conic {
    fn at(&self, l: f64, t: f64) -> f64 {
        self.a * l * l + self.b * l * t + self.c * t * t + self.d * l + self.e * t + self.f
    }
}

/// Real roots of `a·x² + b·x + c = 0` (a linear equation when `a` is negligible).
fn roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    let scale = b.abs().max(c.abs()).max(f64::MIN_POSITIVE);
    if a.abs() <= 1e-13 * scale {
        return if b.abs() > 0.0 { [Some(-c / b), None] } else { [None, None] };
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return [None, None];
    }
    // Numerically stable form (Press et al., Numerical Recipes, §5.6): q = −(b + sgn b·√disc)/2.
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return [Some(0.0), None];
    }
    [Some(q / a), Some(c / q)]
}

/// λ range of `{(λ, t): Q ≤ 0, slab, 0 ≤ t ≤ 1}` for one piece (see the module doc).
fn piece_interval(p: &Piece, o: DVec3, u: DVec3, w: DVec3) -> Option<(f64, f64)> {
    // Bilinear form of the quadric's matrix diag(1, 1, s).
    let sd = |x: DVec3, y: DVec3| x.x * y.x + x.y * y.y + p.s * x.z * y.z;
    let q = Conic {
        a: sd(u, u),
        b: 2.0 * sd(u, w),
        c: sd(w, w),
        d: 2.0 * (sd(o, u) + p.g * u.z),
        e: 2.0 * (sd(o, w) + p.g * w.z),
        f: sd(o, o) + 2.0 * p.g * o.z + p.h,
    };
    let lines = [
        Half { a: 0.0, b: 1.0, c: 0.0 },
        Half { a: 0.0, b: -1.0, c: 1.0 },
        Half { a: u.z, b: w.z, c: o.z - p.z0 },
        Half { a: -u.z, b: -w.z, c: p.z1 - o.z },
    ];
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut take = |l: f64, t: f64, skip: [usize; 2], check_q: bool| {
        if !l.is_finite() || !t.is_finite() {
            return;
        }
        if check_q && q.at(l, t) > TOL_QUAD {
            return;
        }
        for (k, h) in lines.iter().enumerate() {
            if !skip.contains(&k) && h.at(l, t) < -TOL_LINE {
                return;
            }
        }
        lo = lo.min(l);
        hi = hi.max(l);
    };
    // Line–line vertices.
    for i in 0..4 {
        for j in i + 1..4 {
            let (m, n) = (lines[i], lines[j]);
            let det = m.a * n.b - m.b * n.a;
            if det.abs() > 1e-12 {
                // Cramer's rule for m.a·λ + m.b·t = −m.c, n.a·λ + n.b·t = −n.c.
                let l = (-m.c * n.b + n.c * m.b) / det;
                let t = (-m.a * n.c + n.a * m.c) / det;
                take(l, t, [i, j], true);
            }
        }
    }
    // Line–conic intersections: the line as point + s·direction, Q along it a quadratic in s.
    for (k, h) in lines.iter().enumerate() {
        let nn = h.a * h.a + h.b * h.b;
        if nn <= 0.0 {
            continue;
        }
        let (l0, t0) = (-h.c * h.a / nn, -h.c * h.b / nn);
        let (dl, dt) = (-h.b, h.a);
        let a2 = q.a * dl * dl + q.b * dl * dt + q.c * dt * dt;
        let a1 = 2.0 * q.a * l0 * dl + q.b * (l0 * dt + t0 * dl) + 2.0 * q.c * t0 * dt + q.d * dl + q.e * dt;
        let a0 = q.at(l0, t0);
        for s in roots(a2, a1, a0).into_iter().flatten() {
            take(l0 + s * dl, t0 + s * dt, [k, k], false);
        }
    }
    // The conic's λ extremes: ∂Q/∂t = Bλ + 2Ct + E = 0, so t = −(Bλ + E)/(2C) on Q = 0.
    if q.c.abs() > 1e-12 {
        let a2 = q.a - q.b * q.b / (4.0 * q.c);
        let a1 = q.d - q.b * q.e / (2.0 * q.c);
        let a0 = q.f - q.e * q.e / (4.0 * q.c);
        for l in roots(a2, a1, a0).into_iter().flatten() {
            take(l, -(q.b * l + q.e) / (2.0 * q.c), [4, 4], false);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// λ range where the line `o + λ·u` (`u` a unit vector) runs within `r` of the segment from the
/// origin to `m`: a ray against a capsule, the sweep of a ball. The capsule is the union of the
/// two end balls and the cylinder between their centres, each met in one interval (a quadratic
/// in λ each, the cylinder's clipped to the slab between the centres); the capsule is convex,
/// so their union is one interval. In 2D (third components 0) the same for a disc swept along
/// a segment.
pub(crate) fn capsule_interval(o: DVec3, u: DVec3, m: DVec3, r: f64) -> Option<(f64, f64)> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    // A ball at centre c: |o − c + λu|² = r², λ² + 2λ·u·(o − c) + |o − c|² − r² = 0.
    let mut ball = |oc: DVec3| {
        let b = u.dot(oc);
        let h = b * b - (oc.length_squared() - r * r);
        if h >= 0.0 {
            let s = h.sqrt();
            lo = lo.min(-b - s);
            hi = hi.max(-b + s);
        }
    };
    ball(o);
    ball(o - m);
    let mm = m.length_squared();
    // The cylinder: the distance to the axis line ≤ r, with the projection on m in [0, mm]
    // (with k = m·u, p = m·o: |o + λu|²·mm − (p + λk)² ≤ r²·mm).
    let k = m.dot(u);
    let a = mm - k * k;
    if mm > 0.0 && a > 1e-12 * mm {
        let p = m.dot(o);
        let b = mm * u.dot(o) - p * k;
        let c = mm * o.length_squared() - p * p - r * r * mm;
        let h = b * b - a * c;
        if h >= 0.0 {
            let s = h.sqrt();
            let (mut from, mut to) = ((-b - s) / a, (-b + s) / a);
            // The slab 0 ≤ p + λk ≤ mm along the ray.
            if k.abs() > 0.0 {
                let (x, y) = (-p / k, (mm - p) / k);
                from = from.max(x.min(y));
                to = to.min(x.max(y));
            } else if p < 0.0 || p > mm {
                to = f64::NEG_INFINITY;
            }
            if from <= to {
                lo = lo.min(from);
                hi = hi.max(to);
            }
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// Seen along the tool axis: the λ range where the line `o + λ·u` runs within `r` of the axis's
/// shadow swept by `−w` (a 2D capsule; `Some(None)`: never). `None` when the line runs along
/// the axis (its shadow moves less than `min` per unit of λ): then its distance does not
/// depend on λ.
#[allow(clippy::option_option)]
fn shadow(o: DVec3, u: DVec3, w: DVec3, r: f64, min: f64) -> Option<Option<(f64, f64)>> {
    let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
    let k = flat(u).length();
    (k > min).then(|| capsule_interval(flat(o), flat(u) / k, -flat(w), r).map(|(a, b)| (a / k, b / k)))
}

/// An orthonormal frame with `axis` as its third column (tools are round, so any x works).
pub(crate) fn frame_of(axis: DVec3) -> [DVec3; 3] {
    let z = axis.normalize_or(DVec3::Z);
    let (x, y) = z.any_orthonormal_pair();
    [x, y, z]
}

#[cfg(test)]
mod tests;
