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
//! A ball's sweep is a capsule, met in closed form ([`Capsule`]; the enumeration is its test
//! oracle). The other pieces are enumerated only on rays whose material their sweep can
//! reach: a cheap bound (the slab, [`PieceRays::slab`], met with the 2D capsule of the axis's
//! shadow, [`PieceRays::radial`]) that holds no material skips the piece, which changes
//! nothing, since the pieces' intervals join to one and a part without material removes none
//! ([`Rays::material_interval`]); so does a bound that lies within what the pieces before it
//! reach. What all rays of one grid share (the direction in the tool frame, each piece's
//! constants) is worked out once per grid of a cut ([`Sweep::rays`]).

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
    /// A ball: its sweep is a capsule, cut in closed form ([`Capsule`]).
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

    /// The piece's largest radius: a ball's own, √(g² − h); a frustum's, √(−(s·z² + 2g·z + h)),
    /// at either end of the slab (its radius is linear in z).
    fn widest(&self) -> f64 {
        if self.ball {
            return (self.g * self.g - self.h).max(0.0).sqrt();
        }
        let radius = |z: f64| (-(self.s * z * z + 2.0 * self.g * z + self.h)).max(0.0).sqrt();
        radius(self.z0).max(radius(self.z1))
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
    /// [`Rays::material_interval`] of a ray in material all along.
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
        self.sweep(*frame, p0, p1).rays(dir).material_interval(r0, &[all])
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
    /// The sweep met by rays along the unit vector `dir` (W-CS): what those rays share, worked
    /// out once per grid of a cut instead of once per ray.
    pub fn rays(&self, dir: DVec3) -> Rays<'_> {
        let frame = &self.frame;
        let u = DVec3::new(frame[0].dot(dir), frame[1].dot(dir), frame[2].dot(dir));
        let pieces = self.cutter.pieces.iter().map(|p| PieceRays::new(p, u, self.w)).collect();
        Rays { sweep: self, dir, pieces }
    }
}

/// A sweep met by parallel rays ([`Sweep::rays`]).
pub(crate) struct Rays<'a> {
    sweep: &'a Sweep<'a>,
    /// The rays' direction, W-CS.
    dir: DVec3,
    pieces: Vec<PieceRays>,
}

impl Rays<'_> {
    /// What the whole sweep would remove from the ray `r0 + λ·dir` holding `material`: the same
    /// material, with less work. A piece whose sweep cannot reach the material is skipped: the
    /// ray passes its box (along an axis the ray does not move on), or the material lies
    /// outside its cheap bounds ([`PieceRays::slab`], [`PieceRays::radial`]). The pieces'
    /// intervals join to the sweep's one interval, and leaving out a part without material
    /// removes the same material. `None`: nothing to remove.
    pub fn material_interval(&self, r0: DVec3, material: &[super::Span]) -> Option<(f64, f64)> {
        let (frame, dir) = (&self.sweep.frame, self.dir);
        let v = r0 - self.sweep.p0;
        let o = DVec3::new(frame[0].dot(v), frame[1].dot(v), frame[2].dot(v));
        let mut out: Option<(f64, f64)> = None;
        let touches = |(lo, hi): (f64, f64)| material.iter().any(|s| s.hi > lo && s.lo < hi);
        let passes =
            |(lo, hi): &(DVec3, DVec3)| (0..3).any(|k| dir[k] == 0.0 && (r0[k] < lo[k] || r0[k] > hi[k]));
        for (piece, bounds) in self.pieces.iter().zip(&self.sweep.boxes) {
            // The cheap bounds first: most rays' material lies beyond most pieces' reach.
            if passes(bounds) {
                continue;
            }
            let Some(slab) = piece.slab(o).filter(|&b| touches(b)) else { continue };
            let hit = if let Some(hit) = piece.swept_ball(o) {
                hit
            } else if let Some(hit) = piece.swept_cylinder(o, slab, touches, out) {
                hit
            } else {
                // A piece whose bound lies within what the pieces before it reach adds nothing.
                let within = |(lo, hi): (f64, f64)| out.is_some_and(|(a, b)| a <= lo && hi <= b);
                match piece.radial(o, slab) {
                    Some(b) if touches(b) && !within(b) => piece_interval(&piece.piece, o, piece.u, piece.w),
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

/// One piece swept by `−w` (tool frame), met by lines `o + λ·u` along one direction: what the
/// lines share.
struct PieceRays {
    piece: Piece,
    u: DVec3,
    w: DVec3,
    /// 1 / u.z; `None`: a line square to the axis.
    inv_uz: Option<f64>,
    /// A ball's sweep: the capsule of its centre's path ([`Capsule`]); centre at z = −g,
    /// radius² = g² − h.
    ball: Option<Capsule>,
    /// Seen along the axis, the widest radius's 2D capsule ([`PieceRays::radial`]).
    radial: Shadow,
    /// A cylinder's own radius's 2D capsule ([`PieceRays::swept_cylinder`]); `None`: not a
    /// cylinder.
    cylinder: Option<Shadow>,
}

impl PieceRays {
    fn new(piece: &Piece, u: DVec3, w: DVec3) -> PieceRays {
        let ball = piece.ball.then(|| {
            let c = -piece.g;
            Capsule::new(u, -w, (c * c - piece.h).max(0.0).sqrt())
        });
        let radial = Shadow::new(u, w, piece.widest() * (1.0 + 1e-9) + 1e-9, 1e-12);
        let cylinder = (piece.s == 0.0 && piece.g == 0.0 && !piece.ball)
            .then(|| Shadow::new(u, w, (-piece.h).max(0.0).sqrt(), 1e-9));
        PieceRays {
            piece: *piece,
            u,
            w,
            inv_uz: (u.z.abs() > 1e-12).then(|| 1.0 / u.z),
            ball,
            radial,
            cylinder,
        }
    }

    /// A ball's sweep met by the line; `None`: not a ball.
    #[allow(clippy::option_option)]
    fn swept_ball(&self, o: DVec3) -> Option<Option<(f64, f64)>> {
        let capsule = self.ball.as_ref()?;
        Some(capsule.interval(o - DVec3::new(0.0, 0.0, -self.piece.g)))
    }

    /// The λ range where the line `o + λ·u` lies within this piece's slab `z0 ≤ z ≤ z1` for
    /// some t in [0, 1] (the piece swept by `−w`, see [`piece_interval`]): it holds where the
    /// line meets the sweep, and costs no root. `None`: the line misses the slab's sweep.
    fn slab(&self, o: DVec3) -> Option<(f64, f64)> {
        let (p, w) = (&self.piece, self.w);
        // z0 ≤ o.z + λ·u.z + t·w.z ≤ z1.
        let (wl, wh) = (w.z.min(0.0), w.z.max(0.0));
        if let Some(inv) = self.inv_uz {
            let (x, y) = ((p.z0 - o.z - wh) * inv, (p.z1 - o.z - wl) * inv);
            Some((x.min(y), x.max(y)))
        } else if o.z + wh < p.z0 || o.z + wl > p.z1 {
            None
        } else {
            Some((f64::NEG_INFINITY, f64::INFINITY))
        }
    }

    /// `range` narrowed to where the line lies within the piece's largest radius of the axis
    /// for some t (seen along the axis, a 2D capsule): with [`PieceRays::slab`] a bound of the
    /// sweep cheaper than the exact one. `None`: the line misses the sweep.
    fn radial(&self, o: DVec3, range: (f64, f64)) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = range;
        if let Some(range) = self.radial.interval(o) {
            let (a, b) = range?;
            lo = lo.max(a);
            hi = hi.min(b);
        } else {
            // Along the axis: within the radius for every λ or for none. The nearest point of
            // the segment from 0 to m2 (the axis's shadow moving).
            let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
            let (o2, m2) = (flat(o), -flat(self.w));
            let mm = m2.length_squared();
            let along = if mm > 0.0 { (o2.dot(m2) / mm).clamp(0.0, 1.0) } else { 0.0 };
            if (o2 - along * m2).length() > self.radial.r {
                return None;
            }
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// What a cylinder's sweep removes from a line holding material where `touches` says,
    /// joined to `found` (the hull of the pieces before it, if any): seen along the axis the
    /// line runs within the radius of the axis's moving shadow over a λ range (a 2D capsule),
    /// which with the slab range `slab` bounds the sweep. Where the slab holds the line at an
    /// end of that range for every t (its height is linear in λ and t, so t = 0, 1 suffice),
    /// that end is the sweep's exactly. Where it does not, the slab binds and the end lies
    /// within the two ranges' overlap: if `found` reaches beyond that, the end changes nothing
    /// in the join (a pointed or ball tip below a cylinder holds its lower end), else
    /// [`piece_interval`] decides. `None`: not a cylinder, or a line along its axis (then
    /// [`PieceRays::radial`] and the enumeration); `Some(None)`: nothing to remove.
    #[allow(clippy::option_option)]
    fn swept_cylinder(
        &self,
        o: DVec3,
        slab: (f64, f64),
        touches: impl Fn((f64, f64)) -> bool,
        found: Option<(f64, f64)>,
    ) -> Option<Option<(f64, f64)>> {
        let Some((a, b)) = self.cylinder.as_ref()?.interval(o)? else { return Some(None) };
        let bound = (a.max(slab.0), b.min(slab.1));
        if !touches(bound) {
            return Some(None);
        }
        let (p, u, w) = (&self.piece, self.u, self.w);
        let (wl, wh) = (w.z.min(0.0), w.z.max(0.0));
        let free = |l: f64| {
            let z = o.z + l * u.z;
            z + wl >= p.z0 && z + wh <= p.z1
        };
        let lo = if free(a) {
            a
        } else {
            match found {
                Some((lo, _)) if lo <= bound.0 => lo,
                _ => return Some(piece_interval(p, o, u, w)),
            }
        };
        let hi = if free(b) {
            b
        } else {
            match found {
                Some((_, hi)) if hi >= bound.1 => hi,
                _ => return Some(piece_interval(p, o, u, w)),
            }
        };
        Some(Some((lo, hi)))
    }
}

/// Seen along the tool axis: the line `o + λ·u` against the axis's shadow swept by `−w`
/// grown by `r` (a 2D capsule). `None` when the line runs along the axis (its shadow moves
/// less than `min` per unit of λ): then its distance does not depend on λ.
struct Shadow {
    /// The 2D capsule met along the unit shadow of `u`, and 1 / that shadow's length.
    capsule: Option<(Capsule, f64)>,
    r: f64,
}

impl Shadow {
    fn new(u: DVec3, w: DVec3, r: f64, min: f64) -> Shadow {
        let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
        let k = flat(u).length();
        Shadow { capsule: (k > min).then(|| (Capsule::flat(flat(u) / k, -flat(w), r), 1.0 / k)), r }
    }

    /// The λ range within the radius (`Some(None)`: never; `None`: along the axis).
    #[allow(clippy::option_option)]
    #[inline(always)]
    fn interval(&self, o: DVec3) -> Option<Option<(f64, f64)>> {
        let (capsule, inv_k) = self.capsule.as_ref()?;
        Some(capsule.interval(DVec3::new(o.x, o.y, 0.0)).map(|(a, b)| (a * inv_k, b * inv_k)))
    }
}

/// λ range where the line `o + λ·u` (`u` a unit vector) runs within `r` of the segment from the
/// origin to `m`, all in the plane z = 0: a disc swept along a segment ([`Capsule::flat`]).
pub(crate) fn flat_capsule_interval(o: DVec3, u: DVec3, m: DVec3, r: f64) -> Option<(f64, f64)> {
    Capsule::flat(u, m, r).interval(o)
}

/// The points within `r` of the segment from the origin to `m`, met by lines along the unit
/// vector `u`: what the lines share. The capsule is the union of the two end balls and the
/// cylinder between their centres; it lies inside the infinite cylinder, so a line that
/// misses that misses it, and where the line enters (leaves) the infinite cylinder between
/// the centres' planes it enters (leaves) the capsule there; beyond a plane it enters (leaves)
/// through the ball on that side (the standard ray–capsule test, e.g. Quílez, "Intersectors",
/// iquilezles.org). So most lines need one or two roots, not three.
#[derive(Clone, Copy)]
struct Capsule {
    u: DVec3,
    m: DVec3,
    r2: f64,
    mm: f64,
    /// m·u: how fast the projection on m grows along the line.
    k: f64,
    /// mm − k².
    a: f64,
    /// 1 / (mm − k²), the line's quadratic coefficient against the infinite cylinder (times
    /// mm); `None`: a line along the segment or a ball standing (the cylinder adds nothing).
    inv_a: Option<f64>,
    /// In the plane (every vector's third component 0), the square root of that quadratic's
    /// discriminant: the same for every line (see [`Capsule::flat`]).
    flat_root: Option<f64>,
}

impl Capsule {
    fn new(u: DVec3, m: DVec3, r: f64) -> Capsule {
        let (mm, k) = (m.length_squared(), m.dot(u));
        let a = mm - k * k;
        let inv_a = (mm > 0.0 && a > 1e-12 * mm).then(|| 1.0 / a);
        Capsule { u, m, r2: r * r, mm, k, a, inv_a, flat_root: None }
    }

    /// A disc of radius `r` swept from the origin to `m`, met by lines along `u`, all in the
    /// plane z = 0 (the lines' points too). There the distance to the segment's line is linear
    /// along a line: with Lagrange's identity b = (u×m)·(o×m) and mm·|o|² − p² = (o×m)², the
    /// discriminant b² − a·c is (u×m)²·r²·mm whatever `o`, so its root is worked out once.
    fn flat(u: DVec3, m: DVec3, r: f64) -> Capsule {
        let c = Capsule::new(u, m, r);
        let cross = u.x * m.y - u.y * m.x;
        Capsule { flat_root: Some(cross.abs() * r * c.mm.sqrt()), ..c }
    }

    // Inlined into each caller: a call returning the pair through memory cost a sixth of a cut.
    #[inline(always)]
    fn interval(&self, o: DVec3) -> Option<(f64, f64)> {
        let Capsule { u, m, r2, mm, k, a, inv_a, flat_root } = *self;
        // A ball at centre c: |o − c + λu|² = r², λ² + 2λ·u·(o − c) + |o − c|² − r² = 0.
        let ball = |oc: DVec3| {
            let b = u.dot(oc);
            let h = b * b - (oc.length_squared() - r2);
            (h >= 0.0).then(|| {
                let s = h.sqrt();
                (-b - s, -b + s)
            })
        };
        let Some(inv_a) = inv_a else {
            return match (ball(o), ball(o - m)) {
                (Some((a, b)), Some((c, d))) => Some((a.min(c), b.max(d))),
                (one, other) => one.or(other),
            };
        };
        let p = m.dot(o);
        let b = mm * u.dot(o) - p * k;
        let s = match flat_root {
            Some(s) => s,
            None => {
                let c = mm * o.length_squared() - p * p - r2 * mm;
                let h = b * b - a * c;
                if h < 0.0 {
                    return None;
                }
                h.sqrt()
            }
        };
        let (from, to) = ((-b - s) * inv_a, (-b + s) * inv_a);
        let (at_from, at_to) = (p + from * k, p + to * k);
        let start = if at_from < 0.0 || at_to < 0.0 { Some(ball(o)?) } else { None };
        let finish = if at_from > mm || at_to > mm { Some(ball(o - m)?) } else { None };
        let lo = match (start, finish) {
            (Some((lo, _)), _) if at_from < 0.0 => lo,
            (_, Some((lo, _))) if at_from > mm => lo,
            _ => from,
        };
        let hi = match (start, finish) {
            (Some((_, hi)), _) if at_to < 0.0 => hi,
            (_, Some((_, hi))) if at_to > mm => hi,
            _ => to,
        };
        (lo <= hi).then_some((lo, hi))
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

/// An orthonormal frame with `axis` as its third column (tools are round, so any x works).
pub(crate) fn frame_of(axis: DVec3) -> [DVec3; 3] {
    let z = axis.normalize_or(DVec3::Z);
    let (x, y) = z.any_orthonormal_pair();
    [x, y, z]
}

#[cfg(test)]
mod tests;
