//! Contour geometry in the working plane: straight lines, circular arcs and helices, and the
//! rounded (RND) or chamfered (CHF) corner between two elements. Everything is in the I-CS:
//! arcs lie in the main plane of the tool axis there, so after a PLANE they tilt with it.
//!
//! Sources: TNC 620 Klartext user's manual, "Path contours — Cartesian coordinates" and
//! "— polar coordinates" (C around CC, CR with R± choosing the arc, CT tangential, RND, CHF,
//! LP/CP around the pole, helix as CP with IZ) and "Fundamentals of path functions" (DR+ is
//! counter-clockwise; the working plane of tool axis Z is XY, of Y it is ZX, of X it is YZ).
//! DR+ counter-clockwise seen against the tool axis is a positive rotation about +tool axis.

use glam::DVec3;

/// Angles closer than this (radians) count as equal: an arc from a point back to itself is a
/// full circle, not a zero-length arc (derived, well above f64 roundoff of atan2).
const ANGLE_EPS: f64 = 1e-9;

/// Lengths below this (mm) are zero: far below the control's display resolution of 1 µm.
const LENGTH_EPS: f64 = 1e-9;

/// The main plane of the tool axis: the two axes that span it and its normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorkPlane {
    /// Unit normal (the tool axis in the I-CS).
    pub normal: DVec3,
    /// Index of the angle reference axis (PA = 0°) and of the second axis (PA = +90°).
    pub first: usize,
    pub second: usize,
}

impl WorkPlane {
    /// Tool axis Z → plane XY (reference axis X), Y → ZX (reference Z), X → YZ (reference Y)
    /// (manual: "Fundamentals of path functions", the angle reference axis of polar coordinates).
    #[must_use]
    pub fn of_tool_axis(axis: char) -> WorkPlane {
        match axis {
            'X' => WorkPlane { normal: DVec3::X, first: 1, second: 2 },
            'Y' => WorkPlane { normal: DVec3::Y, first: 2, second: 0 },
            _ => WorkPlane { normal: DVec3::Z, first: 0, second: 1 },
        }
    }

    /// The part of `v` in the plane.
    #[must_use]
    pub fn planar(&self, v: DVec3) -> DVec3 {
        v - v.dot(self.normal) * self.normal
    }

    /// The coordinate along the tool axis.
    #[must_use]
    pub fn axial(&self, v: DVec3) -> f64 {
        v.dot(self.normal)
    }

    /// `p` with its tool-axis coordinate replaced by `axial`.
    #[must_use]
    pub fn with_axial(&self, p: DVec3, axial: f64) -> DVec3 {
        self.planar(p) + axial * self.normal
    }

    /// Signed angle from `a` to `b` about the normal, in (−π, π] (both taken in the plane).
    #[must_use]
    pub fn angle(&self, a: DVec3, b: DVec3) -> f64 {
        let (a, b) = (self.planar(a), self.planar(b));
        a.cross(b).dot(self.normal).atan2(a.dot(b))
    }

    /// `v` (in the plane) turned by `angle` about the normal (Rodrigues for v ⟂ n).
    #[must_use]
    pub fn rotate(&self, v: DVec3, angle: f64) -> DVec3 {
        let (s, c) = angle.sin_cos();
        v * c + self.normal.cross(v) * s
    }

    /// The unit vector at polar angle `deg` from the reference axis.
    #[must_use]
    pub fn direction(&self, deg: f64) -> DVec3 {
        let (s, c) = deg.to_radians().sin_cos();
        let mut v = DVec3::ZERO;
        v[self.first] = c;
        v[self.second] = s;
        v
    }

    /// Polar angle (degrees) of `v` from the reference axis.
    #[must_use]
    pub fn polar_angle(&self, v: DVec3) -> f64 {
        v[self.second].atan2(v[self.first]).to_degrees()
    }
}

/// The angle from `a` to `b` travelled in direction `dir` (+1 counter-clockwise, −1 clockwise):
/// in (0, 2π] for +1 and [−2π, 0) for −1, so a point back to itself is a full circle.
#[must_use]
pub fn directed(plane: &WorkPlane, a: DVec3, b: DVec3, dir: f64) -> f64 {
    let mut t = plane.angle(a, b);
    if dir >= 0.0 {
        if t <= ANGLE_EPS {
            t += std::f64::consts::TAU;
        }
    } else if t >= -ANGLE_EPS {
        t -= std::f64::consts::TAU;
    }
    t
}

/// A line or an arc (helix when the tool-axis coordinate changes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Line,
    /// `centre` has the start's tool-axis coordinate; `sweep` in radians, positive = DR+.
    Arc {
        centre: DVec3,
        sweep: f64,
    },
}

/// One contour element from `start` to `end` (I-CS).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elem {
    pub start: DVec3,
    pub end: DVec3,
    pub shape: Shape,
}

/// Why an element or a corner cannot be built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GeoError {
    /// C: the end point is not on the circle through the start (radii at start and end).
    EndNotOnCircle { start_radius: f64, end_radius: f64 },
    /// CR: the chord is longer than the diameter.
    RadiusTooSmall { radius: f64, chord: f64 },
    /// CR/C/CP: start and end (or centre) coincide where an arc needs them apart.
    Degenerate,
    /// CT: the end point lies on the tangent (no arc touches it there).
    EndOnTangent,
    /// RND/CHF: the two elements are tangent already or one has no length.
    NoCorner,
    /// RND/CHF: the rounding or chamfer does not fit on the elements.
    CornerTooLarge,
    /// CHF: a chamfer joins two straight lines only.
    ChamferNeedsLines,
}

impl Elem {
    #[must_use]
    pub fn line(start: DVec3, end: DVec3) -> Elem {
        Elem { start, end, shape: Shape::Line }
    }

    /// The point at `f` (0…1) of the element: arcs turn uniformly, the tool-axis coordinate
    /// moves linearly (helix).
    #[must_use]
    pub fn at(&self, plane: &WorkPlane, f: f64) -> DVec3 {
        match self.shape {
            Shape::Line => self.start.lerp(self.end, f),
            Shape::Arc { centre, sweep } => {
                let rise = plane.axial(self.end) - plane.axial(self.start);
                centre + plane.rotate(plane.planar(self.start - centre), f * sweep) + f * rise * plane.normal
            }
        }
    }

    /// Radius of an arc (0 for a line).
    #[must_use]
    pub fn radius(&self, plane: &WorkPlane) -> f64 {
        match self.shape {
            Shape::Line => 0.0,
            Shape::Arc { centre, .. } => plane.planar(self.start - centre).length(),
        }
    }

    /// Path length (a helix: its unrolled length).
    #[must_use]
    pub fn length(&self, plane: &WorkPlane) -> f64 {
        match self.shape {
            Shape::Line => self.start.distance(self.end),
            Shape::Arc { sweep, .. } => {
                let rise = plane.axial(self.end) - plane.axial(self.start);
                (self.radius(plane) * sweep).hypot(rise)
            }
        }
    }

    /// Unit direction of travel in the plane at `f` = 0 or 1; `None` for a move along the tool
    /// axis only.
    #[must_use]
    pub fn tangent(&self, plane: &WorkPlane, at_end: bool) -> Option<DVec3> {
        let t = match self.shape {
            Shape::Line => plane.planar(self.end - self.start),
            Shape::Arc { centre, sweep } => {
                let p = if at_end { self.end } else { self.start };
                sweep.signum() * plane.normal.cross(plane.planar(p - centre))
            }
        };
        (t.length() > LENGTH_EPS).then(|| t.normalize())
    }

    /// A straight element's travel in the plane, unnormalised, where [`Elem::tangent`] has a
    /// direction (its length over `LENGTH_EPS`); `None` for an arc. The same direction
    /// without its square root and division: a straight line ends almost every block, and its
    /// direction is asked for by few.
    #[must_use]
    pub fn line_travel(&self, plane: &WorkPlane) -> Option<DVec3> {
        let Shape::Line = self.shape else { return None };
        let t = plane.planar(self.end - self.start);
        (t.length_squared() > LENGTH_EPS * LENGTH_EPS).then_some(t)
    }

    /// Where `p` (a point on the element) lies, as a fraction of the element (line: along the
    /// line; arc: the turned angle over the sweep).
    #[must_use]
    pub fn fraction_of(&self, plane: &WorkPlane, p: DVec3) -> f64 {
        match self.shape {
            Shape::Line => {
                let d = plane.planar(self.end - self.start);
                let len2 = d.length_squared();
                if len2 > LENGTH_EPS * LENGTH_EPS { plane.planar(p - self.start).dot(d) / len2 } else { 0.0 }
            }
            Shape::Arc { centre, sweep } => {
                let turned = plane.angle(self.start - centre, p - centre);
                // Measured in the direction of travel, in [0, 2π).
                let turned = if sweep >= 0.0 { turned } else { -turned };
                let turned = turned.rem_euclid(std::f64::consts::TAU);
                let full = sweep.abs();
                // A point just before the start reads as almost a full turn: it is the start.
                if turned > full + ANGLE_EPS && turned > std::f64::consts::PI { 0.0 } else { turned / full }
            }
        }
    }

    /// The element from `f` to its end (`from` = the point there).
    #[must_use]
    pub fn tail_from(&self, plane: &WorkPlane, f: f64, from: DVec3) -> Elem {
        match self.shape {
            Shape::Line => Elem::line(from, self.end),
            Shape::Arc { centre, sweep } => Elem {
                start: from,
                end: self.end,
                shape: Shape::Arc {
                    centre: plane.with_axial(centre, plane.axial(from)),
                    sweep: sweep * (1.0 - f),
                },
            },
        }
    }

    /// The element from its start to `f` (`to` = the point there).
    #[must_use]
    pub fn head_to(&self, f: f64, to: DVec3) -> Elem {
        match self.shape {
            Shape::Line => Elem::line(self.start, to),
            Shape::Arc { centre, sweep } => {
                Elem { start: self.start, end: to, shape: Shape::Arc { centre, sweep: sweep * f } }
            }
        }
    }
}

/// `C`: the arc around `cc` from `start` to `end` in direction `dir` (+1 = DR+). The end must be
/// on the circle within `tolerance` (mm); end = start is a full circle.
///
/// # Errors
/// [`GeoError::EndNotOnCircle`], [`GeoError::Degenerate`] (start on the centre).
pub fn arc_c(
    plane: &WorkPlane,
    start: DVec3,
    end: DVec3,
    cc: DVec3,
    dir: f64,
    tolerance: f64,
) -> Result<Elem, GeoError> {
    let centre = plane.with_axial(cc, plane.axial(start));
    let (rs, re) = (plane.planar(start - centre).length(), plane.planar(end - centre).length());
    if rs < LENGTH_EPS {
        return Err(GeoError::Degenerate);
    }
    if (rs - re).abs() > tolerance {
        return Err(GeoError::EndNotOnCircle { start_radius: rs, end_radius: re });
    }
    let sweep = directed(plane, start - centre, end - centre, dir);
    Ok(Elem { start, end, shape: Shape::Arc { centre, sweep } })
}

/// `CR`: the arc of radius |`r`| from `start` to `end`; R+ the arc up to 180°, R− the one over
/// 180° (manual: "The algebraic sign determines the size of the arc"); `dir` +1 = DR+.
/// The centre lies on the chord's perpendicular bisector, h = √(R² − (d/2)²) from the middle,
/// on the left of the chord for DR+ with R+ (a counter-clockwise arc curves to the left).
///
/// # Errors
/// [`GeoError::RadiusTooSmall`] when d > 2R (beyond `tolerance`), [`GeoError::Degenerate`] when
/// start = end.
pub fn arc_cr(
    plane: &WorkPlane,
    start: DVec3,
    end: DVec3,
    r: f64,
    dir: f64,
    tolerance: f64,
) -> Result<Elem, GeoError> {
    let chord = plane.planar(end - start);
    let d = chord.length();
    let radius = r.abs();
    if d < LENGTH_EPS || radius < LENGTH_EPS {
        return Err(GeoError::Degenerate);
    }
    if d > 2.0 * radius + tolerance {
        return Err(GeoError::RadiusTooSmall { radius, chord: d });
    }
    let h = (radius * radius - d * d / 4.0).max(0.0).sqrt();
    let left = plane.normal.cross(chord / d);
    let side = if (dir >= 0.0) == (r >= 0.0) { 1.0 } else { -1.0 };
    let middle = plane.with_axial(start + 0.5 * chord, plane.axial(start));
    let centre = middle + side * h * left;
    let small = 2.0 * (d / (2.0 * radius)).min(1.0).asin();
    let size = if r >= 0.0 { small } else { std::f64::consts::TAU - small };
    Ok(Elem { start, end, shape: Shape::Arc { centre, sweep: dir.signum() * size } })
}

/// `CT`: the arc leaving `start` along the unit tangent `t` and ending at `end`. The centre is
/// `start + ρ·(n × t)` with |centre − end| = |ρ|, i.e. ρ = |w|² / (2 (n×t)·w), w = end − start
/// (derived); ρ > 0 turns counter-clockwise.
///
/// # Errors
/// [`GeoError::EndOnTangent`] when `end` lies on the tangent line, [`GeoError::Degenerate`] when
/// end = start.
pub fn arc_ct(plane: &WorkPlane, start: DVec3, end: DVec3, t: DVec3) -> Result<Elem, GeoError> {
    let w = plane.planar(end - start);
    if w.length() < LENGTH_EPS {
        return Err(GeoError::Degenerate);
    }
    let left = plane.normal.cross(t);
    let k = left.dot(w);
    if k.abs() < 1e-12 * w.length() {
        return Err(GeoError::EndOnTangent);
    }
    let rho = w.length_squared() / (2.0 * k);
    let centre = start + rho * left;
    let sweep = directed(plane, start - centre, end - centre, rho.signum());
    Ok(Elem { start, end, shape: Shape::Arc { centre, sweep } })
}

/// `CP`: around the pole from `start` by `sweep` radians, ending at tool-axis coordinate
/// `axial_end` (helix when it differs from the start's).
///
/// # Errors
/// [`GeoError::Degenerate`] when the start is on the pole.
pub fn arc_cp(
    plane: &WorkPlane,
    start: DVec3,
    pole: DVec3,
    sweep: f64,
    axial_end: f64,
) -> Result<Elem, GeoError> {
    let centre = plane.with_axial(pole, plane.axial(start));
    let r = plane.planar(start - centre);
    if r.length() < LENGTH_EPS || sweep.abs() < ANGLE_EPS {
        return Err(GeoError::Degenerate);
    }
    let end = plane.with_axial(centre + plane.rotate(r, sweep), axial_end);
    Ok(Elem { start, end, shape: Shape::Arc { centre, sweep } })
}

/// What joins two elements at their common point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CornerKind {
    /// `RND R…`: an arc of this radius tangent to both.
    Round(f64),
    /// `CHF …`: a straight line cutting this length off each line.
    Chamfer(f64),
}

/// A curve through the corner, for the offset construction of a rounding.
#[derive(Debug, Clone, Copy)]
enum Curve {
    /// Through `p` along unit `d`.
    Line { p: DVec3, d: DVec3 },
    /// Centre, radius, direction of travel (+1 counter-clockwise).
    Circle { c: DVec3, r: f64, dir: f64 },
}

impl Curve {
    fn of(plane: &WorkPlane, e: &Elem, corner: DVec3) -> Option<Curve> {
        match e.shape {
            Shape::Line => Some(Curve::Line { p: plane.planar(corner), d: e.tangent(plane, true)? }),
            Shape::Arc { centre, sweep } => {
                Some(Curve::Circle { c: plane.planar(centre), r: e.radius(plane), dir: sweep.signum() })
            }
        }
    }

    /// The curve moved by `r` to the left (`side` +1) or right (−1) of the direction of travel.
    /// A counter-clockwise circle has its centre on the left, so its left offset shrinks it.
    fn offset(self, plane: &WorkPlane, side: f64, r: f64) -> Option<Curve> {
        match self {
            Curve::Line { p, d } => Some(Curve::Line { p: p + side * r * plane.normal.cross(d), d }),
            Curve::Circle { c, r: big, dir } => {
                let nr = big - dir * side * r;
                (nr > LENGTH_EPS).then_some(Curve::Circle { c, r: nr, dir })
            }
        }
    }

    /// The point of the curve nearest to `q` (the foot of the perpendicular).
    fn foot(self, plane: &WorkPlane, q: DVec3) -> DVec3 {
        match self {
            Curve::Line { p, d } => p + (q - p).dot(d) * d,
            Curve::Circle { c, r, .. } => {
                let v = plane.planar(q - c);
                c + r * v.normalize_or_zero()
            }
        }
    }
}

/// Why an element has no offset path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OffsetError {
    /// The element moves along the tool axis only: no side to offset to.
    NoDirection,
    /// An arc whose offset radius would be < 0 (its radius, mm): the tool does not fit inside.
    RadiusGone { radius: f64 },
}

/// `e` moved by `r` to the left (`side` +1, RL) or right (−1, RR) of its direction of travel:
/// a line is shifted along its normal, an arc keeps its centre and sweep and its radius grows
/// or shrinks by `r` (a counter-clockwise arc has its centre on the left, so RL shrinks it;
/// manual "Tool radius compensation": the tool centre path runs at the distance of the tool
/// radius from the contour). The tool-axis coordinates stay.
///
/// # Errors
/// [`OffsetError::NoDirection`], [`OffsetError::RadiusGone`].
pub fn offset(plane: &WorkPlane, e: &Elem, side: f64, r: f64) -> Result<Elem, OffsetError> {
    match e.shape {
        Shape::Line => {
            let t = e.tangent(plane, true).ok_or(OffsetError::NoDirection)?;
            let shift = side * r * plane.normal.cross(t);
            Ok(Elem::line(e.start + shift, e.end + shift))
        }
        Shape::Arc { centre, sweep } => {
            let radius = e.radius(plane);
            // Radius 0 (an inside arc exactly the tool's size) leaves the tool standing at the
            // centre; only a negative one does not fit.
            let nr = radius - sweep.signum() * side * r;
            if nr < -LENGTH_EPS {
                return Err(OffsetError::RadiusGone { radius });
            }
            let nr = nr.max(0.0);
            let at = |p: DVec3| {
                let u = plane.planar(p - centre).normalize_or_zero();
                plane.with_axial(plane.planar(centre) + nr * u, plane.axial(p))
            };
            Ok(Elem { start: at(e.start), end: at(e.end), shape: e.shape })
        }
    }
}

/// Where the curves of `a` and `b` (lines taken infinite, arcs as full circles) meet, the
/// intersection nearest to `near`, with `near`'s tool-axis coordinate. For the inside corner of
/// two offset paths (manual: at inside corners the tool centre path ends at the intersection of
/// the two offset paths).
#[must_use]
pub fn meet(plane: &WorkPlane, a: &Elem, b: &Elem, near: DVec3) -> Option<DVec3> {
    let ca = Curve::of(plane, a, a.start)?;
    let cb = Curve::of(plane, b, b.start)?;
    let q = plane.planar(near);
    intersect(plane, ca, cb)
        .into_iter()
        .min_by(|x, y| x.distance_squared(q).total_cmp(&y.distance_squared(q)))
        .map(|x| plane.with_axial(x, plane.axial(near)))
}

/// `f` such that `e.at(f)` is `p`, when `p` lies on the curve of `e` within `tolerance` (mm).
#[must_use]
pub fn on_curve(plane: &WorkPlane, e: &Elem, p: DVec3, tolerance: f64) -> Option<f64> {
    let f = e.fraction_of(plane, p);
    (plane.planar(e.at(plane, f) - p).length() <= tolerance).then_some(f)
}

/// The point where a line through `q` touches the circle around `m` of radius `r` that is run
/// in direction `dir` (+1 counter-clockwise): `x = m + r·u` with `u·(q − m) = r` (the radius
/// is perpendicular to the tangent). `arrive`: the line runs from `q` into the circle (APPR
/// LCT), else from the circle out to `q` (DEP LCT); of the two tangent points the one where
/// the line and the circle run the same way. `None` when `q` lies inside the circle.
#[must_use]
pub fn tangent_point(plane: &WorkPlane, m: DVec3, r: f64, dir: f64, q: DVec3, arrive: bool) -> Option<DVec3> {
    let d = plane.planar(q - m);
    let dist = d.length();
    if dist < r + LENGTH_EPS || r < LENGTH_EPS {
        return None;
    }
    let phi = (r / dist).acos();
    [phi, -phi].into_iter().find_map(|a| {
        let u = plane.rotate(d / dist, a);
        let x = m + r * u;
        let run = dir * plane.normal.cross(u);
        let line = if arrive { plane.planar(x - q) } else { plane.planar(q - x) };
        (line.dot(run) > 0.0).then_some(x)
    })
}

/// Intersections of two curves in the plane (planar points, 0, 1 or 2 of them).
fn intersect(plane: &WorkPlane, a: Curve, b: Curve) -> Vec<DVec3> {
    match (a, b) {
        (Curve::Line { p: p1, d: d1 }, Curve::Line { p: p2, d: d2 }) => {
            let den = d1.cross(d2).dot(plane.normal);
            if den.abs() < 1e-12 {
                return Vec::new();
            }
            let t = (p2 - p1).cross(d2).dot(plane.normal) / den;
            vec![p1 + t * d1]
        }
        (Curve::Line { p, d }, Curve::Circle { c, r, .. })
        | (Curve::Circle { c, r, .. }, Curve::Line { p, d }) => {
            // |p + t d − c|² = r²  →  t² + 2 t (d·(p−c)) + |p−c|² − r² = 0.
            let m = p - c;
            let b = d.dot(m);
            let disc = b * b - (m.length_squared() - r * r);
            if disc < 0.0 {
                return Vec::new();
            }
            let s = disc.sqrt();
            vec![p + (-b - s) * d, p + (-b + s) * d]
        }
        (Curve::Circle { c: c1, r: r1, .. }, Curve::Circle { c: c2, r: r2, .. }) => {
            // Two circles: the chord of intersection is perpendicular to c1c2 at distance a from c1,
            // a = (d² + r1² − r2²) / 2d.
            let v = plane.planar(c2 - c1);
            let d = v.length();
            if d < LENGTH_EPS {
                return Vec::new();
            }
            let a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
            let h2 = r1 * r1 - a * a;
            if h2 < 0.0 {
                return Vec::new();
            }
            let u = v / d;
            let m = c1 + a * u;
            let h = h2.sqrt() * plane.normal.cross(u);
            vec![m - h, m + h]
        }
    }
}

/// The corner between `e1` (ending at the corner) and `e2` (starting there): `e1` shortened to
/// the first tangent point, the rounding or chamfer, and `e2`'s fraction where it now starts.
///
/// RND: the arc of radius r touching both elements; its centre is where the two elements,
/// each moved by r towards the inside of the turn, meet (offset construction; for two lines it
/// gives the closed form T = P ∓ r·tan(α/2)·d). CHF: the line from P − L·d1 to P + L·d2, L the
/// programmed length on each line (manual: "Chamfer side length"). The corner keeps P's
/// tool-axis coordinate.
///
/// # Errors
/// [`GeoError::NoCorner`], [`GeoError::CornerTooLarge`], [`GeoError::ChamferNeedsLines`].
pub fn corner(
    plane: &WorkPlane,
    e1: &Elem,
    e2: &Elem,
    kind: CornerKind,
) -> Result<(Elem, Elem, f64), GeoError> {
    let p = e1.end;
    let axial = plane.axial(p);
    let (Some(t1), Some(t2)) = (e1.tangent(plane, true), e2.tangent(plane, false)) else {
        return Err(GeoError::NoCorner);
    };
    let turn = t1.cross(t2).dot(plane.normal);
    if turn.abs() < 1e-9 && t1.dot(t2) > 0.0 {
        return Err(GeoError::NoCorner);
    }
    let side = if turn >= 0.0 { 1.0 } else { -1.0 };
    let (a, b, piece) = match kind {
        CornerKind::Chamfer(len) => {
            if e1.shape != Shape::Line || e2.shape != Shape::Line {
                return Err(GeoError::ChamferNeedsLines);
            }
            if len <= 0.0 {
                return Err(GeoError::CornerTooLarge);
            }
            let (a, b) = (p - len * t1, p + len * t2);
            (a, b, Elem::line(a, b))
        }
        CornerKind::Round(r) => {
            let r = r.abs();
            let (Some(c1), Some(c2)) = (Curve::of(plane, e1, p), Curve::of(plane, e2, p)) else {
                return Err(GeoError::NoCorner);
            };
            let (Some(o1), Some(o2)) = (c1.offset(plane, side, r), c2.offset(plane, side, r)) else {
                return Err(GeoError::CornerTooLarge);
            };
            let pp = plane.planar(p);
            let centre = intersect(plane, o1, o2)
                .into_iter()
                .min_by(|x, y| x.distance_squared(pp).total_cmp(&y.distance_squared(pp)))
                .ok_or(GeoError::CornerTooLarge)?;
            let (a, b) = (
                plane.with_axial(c1.foot(plane, centre), axial),
                plane.with_axial(c2.foot(plane, centre), axial),
            );
            let centre = plane.with_axial(centre, axial);
            let sweep = side * plane.angle(a - centre, b - centre).abs();
            (a, b, Elem { start: a, end: b, shape: Shape::Arc { centre, sweep } })
        }
    };
    let (f1, f2) = (e1.fraction_of(plane, a), e2.fraction_of(plane, b));
    let inside = |f: f64| (-1e-9..=1.0 + 1e-9).contains(&f);
    if !inside(f1) || !inside(f2) {
        return Err(GeoError::CornerTooLarge);
    }
    Ok((e1.head_to(f1.clamp(0.0, 1.0), plane.with_axial(a, plane.axial(e1.end))), piece, f2.clamp(0.0, 1.0)))
}
