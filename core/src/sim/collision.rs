//! Collision checking along every motion (issue 17): the machine's bodies
//! ([`crate::machine::Body`]), the tool, its holder and the blank, placed by the rigid-body model
//! ([`Kin`]) for the axes at any fraction of a [`Segment`].
//!
//! # Which pairs are checked
//! Every body on the **head side** (the tool, the holder, the machine's `head` bodies: they move
//! with the linear axes and the head axes) against every body on the **table side** (`bed`
//! bodies, the bodies of the table axes, the blank of `BLK FORM`). Bodies on the same side are
//! built to stay apart (a spindle in its head, a rotary table on its cradle) and are not checked
//! against each other. The tool's cutting part against the blank is cutting, not a collision, at
//! any feed: the blank is the raw `BLK FORM` box, not the cut stock, and cycles retract at rapid
//! out of what they have cut (a rapid into material is the stock model's note, [`crate::stock`]).
//! The holder or the head touching the blank, or the tool touching a table part or the bed, is a
//! collision. A pair is only checked during a motion that moves one of its bodies.
//!
//! # Shapes and the static test
//! A box is an oriented box (OBB), tested against another by the separating-axis theorem over
//! the 15 candidate axes (Ericson, *Real-Time Collision Detection*, §4.4.1), each axis
//! normalised so that a margin is in millimetres. A cylinder is held as its capsule (the segment
//! of its axis, swept by its radius) *and* its bounding box; it touches another shape only if
//! both do (each contains the cylinder, so neither test can miss a contact; the pair of them
//! leaves only the corner regions where capsule and box overlap the other shape apart). The
//! capsule tests use exact segment–segment distances (Ericson §5.1.9) and the segment–box
//! distance, a convex function along the segment minimised by golden-section search. The
//! separating-axis test with a margin is conservative (it may call a pair within `margin` when
//! the true distance is slightly larger, never the other way round).
//!
//! # Along the motion: the guarantee
//! Between two fractions f₀ < f₁ of a segment no point of a body moves more than
//! `(f₁ − f₀)·(S_L + Σⱼ ρⱼ·|Δθⱼ|)` (`Solid::rate`): `S_L` bounds the speed of the linear
//! axes per unit fraction (linear move: the chord; arc: radius·sweep + lead; MOVE and TCPM: the
//! tool tip's and the workpiece point's travel, see `linear_rate`), `Δθⱼ` is the travel of
//! rotary axis j (radians) and `ρⱼ` bounds the distance of the body from that axis
//! (derived: a point at distance d from an axis moves at most d·|Δθ| when turned by Δθ; a joint
//! carried by another is at most the distance between their pivots further out). Each pair is
//! tested at the middle of an interval with the margin `(rate_a + rate_b)·(f₁ − f₀)/2`; a clear
//! test clears the whole interval, otherwise it is halved, until the margin is at most
//! [`RESOLUTION`]. So **no contact along the motion is missed**, and a reported collision has the
//! two bodies within [`RESOLUTION`] mm of each other at the reported fraction.
//!
//! # Broad phase
//! With the rotary axes standing still a motion translates the head side by the linear axes'
//! travel and leaves the table side standing. Each head-side body's axis-parallel box, swept
//! along the travel, is tested against each table-side body's box first: a gap along one axis
//! is a lower bound on the distance, so a pair apart by more than [`RESOLUTION`] is clear along
//! the whole motion. The boxes at a motion's end are carried to the next one ([`Clearances`]),
//! so a run of translations (CAM output, moves inside a blank) places no body at all. What a
//! motion before has shown to be far apart is not tested again until the motions since could
//! have closed that gap.

use glam::DVec3;
use serde::Serialize;

use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::{BodyCarrier, BodyShape, Carrier, Machine};
use crate::unconfirmed;

use super::Blank;
use super::geometry::{Affine, Kin};
use super::segment::{MachineAxes, Segment, SegmentKind, SegmentPath};

mod shape;

pub use shape::{
    Capsule, Obb, Placed, point_obb_distance, segment_obb_distance, segment_segment_distance, separation,
    swept_obb_gap, touch,
};

/// How close two bodies may come before the check calls it a collision, mm (derived: far below
/// what the 3D view can show, and it bounds the halving of a motion at about 20 steps).
pub const RESOLUTION: f64 = 0.05;

/// Where a body is fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Frame {
    /// Turned by the table joints with index ≥ `from` (2: none, the bed); home M-CS coordinates.
    Table { from: usize },
    /// Tool coordinates (tip at the origin, tool along +Z, head at home), placed at L + H(x).
    Tool,
}

/// What a body is, for the pair rules (module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Role {
    Tool,
    Holder,
    Head,
    Table,
    Blank,
}

impl Role {
    fn head_side(self) -> bool {
        matches!(self, Role::Tool | Role::Holder | Role::Head)
    }
}

/// A shape in its frame.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Local {
    Box { center: DVec3, half: DVec3 },
    Cylinder { base: DVec3, direction: DVec3, radius: f64, height: f64 },
}

impl Local {
    fn placed(&self, pose: &Affine) -> Placed {
        match *self {
            Local::Box { center, half } => {
                Placed::Box(Obb { center: pose.apply(center), axes: pose.m, half })
            }
            Local::Cylinder { base, direction, radius, height } => {
                Placed::cylinder(pose.apply(base), pose.m * direction, radius, height)
            }
        }
    }

    /// A bounding sphere (centre, radius) in the frame.
    fn sphere(&self) -> (DVec3, f64) {
        match *self {
            Local::Box { center, half } => (center, half.length()),
            Local::Cylinder { base, direction, radius, height } => {
                (base + direction * (0.5 * height), (radius * radius + 0.25 * height * height).sqrt())
            }
        }
    }
}

/// A body ready to be placed: its frame, shape, bounding sphere and reach from each joint.
#[derive(Debug, Clone, PartialEq)]
struct Solid {
    name: Text,
    role: Role,
    frame: Frame,
    shape: Local,
    centre: DVec3,
    radius: f64,
    /// ρⱼ: a bound on the distance of every point from rotary axis j while it moves the body
    /// (0 when axis j does not move it), mm.
    reach: [f64; 2],
}

impl Solid {
    fn new(kin: &Kin, name: Text, role: Role, frame: Frame, shape: Local) -> Solid {
        let (centre, radius) = shape.sphere();
        Solid { name, role, frame, shape, centre, radius, reach: reach(kin, frame, centre, radius) }
    }

    /// How far (mm) any point may move per unit fraction of a segment with linear rate `lin`
    /// and rotary travel `rot` (radians) (module doc).
    fn rate(&self, lin: f64, rot: [f64; 2]) -> f64 {
        let own = if self.frame == Frame::Tool { lin } else { 0.0 };
        own + self.reach[0] * rot[0] + self.reach[1] * rot[1]
    }
}

/// ρⱼ of a sphere in `frame` (derived, module doc): the joints moving the frame in the order
/// they act, each one's pivot in the same home coordinates; the first is bounded by the sphere's
/// distance from its pivot, each further one adds the distance between consecutive pivots.
fn reach(kin: &Kin, frame: Frame, centre: DVec3, radius: f64) -> [f64; 2] {
    let gauge = DVec3::new(0.0, 0.0, kin.tool_length);
    let order: Vec<(usize, DVec3)> = match frame {
        Frame::Table { from } => (from..2)
            .filter(|&k| kin.joints[k].carrier == Carrier::Table)
            .map(|k| (k, kin.joints[k].pivot))
            .collect(),
        Frame::Tool => (0..2)
            .rev()
            .filter(|&k| kin.joints[k].carrier == Carrier::Head)
            .map(|k| (k, gauge + kin.joints[k].pivot))
            .collect(),
    };
    let mut out = [0.0; 2];
    let mut prev: Option<(f64, DVec3)> = None;
    for (k, pivot) in order {
        let rho = match prev {
            None => (centre - pivot).length() + radius,
            Some((rho, p)) => rho + (p - pivot).length(),
        };
        out[k] = rho;
        prev = Some((rho, pivot));
    }
    out
}

/// The poses of the four frames for the axes: `Table { from: 0, 1, 2 }` and `Tool`.
fn frame_poses(kin: &Kin, axes: &MachineAxes) -> [Affine; 4] {
    let [t0, t1, t2] = kin.table_poses(axes.rotary);
    let h = kin.head_pose(axes.rotary);
    [t0, t1, t2, Affine { m: h.m, v: h.v + axes.linear }]
}

impl Frame {
    /// Its index into [`frame_poses`].
    fn index(self) -> usize {
        match self {
            Frame::Table { from } => from.min(2),
            Frame::Tool => 3,
        }
    }
}

/// A bound on the speed of the linear axes per unit fraction of `seg` (module doc).
fn linear_rate(seg: &Segment, rot: [f64; 2]) -> f64 {
    let turn = rot[0] + rot[1];
    // The tool tip turned by the head axes: H(0) in the rigid-body model.
    let tip = |kin: &Kin| {
        let r = reach(kin, Frame::Tool, DVec3::ZERO, 0.0);
        r[0] * rot[0] + r[1] * rot[1]
    };
    // A workpiece point in the sphere (centre, radius), carried by the table axes.
    let point = |kin: &Kin, centre: DVec3, radius: f64| {
        let r = reach(kin, Frame::Table { from: 0 }, centre, radius);
        r[0] * rot[0] + r[1] * rot[1]
    };
    match &seg.path {
        SegmentPath::Linear | SegmentPath::Stay { .. } => (seg.end.linear - seg.start.linear).length(),
        SegmentPath::Arc(a) => a.sweep.abs() * a.radius() + a.lead.length(),
        // L = W(preset + c + DIST·t(θ)) − H(0): the point turns with the table, t turns by at most
        // the sum of the rotary travels.
        SegmentPath::Move(m) => {
            let d = m.dist.abs();
            point(&m.kin, m.kin.preset + m.centre, d) + d * turn + tip(&m.kin)
        }
        // L = W(preset + p(f)) − H(0), p straight from `from` to `to`.
        SegmentPath::Tcpm(t) => {
            let half = 0.5 * (t.to - t.from).length();
            point(&t.kin, t.kin.preset + 0.5 * (t.from + t.to), half) + 2.0 * half + tip(&t.kin)
        }
    }
}

/// Two bodies that touched, at a fraction of a segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// The head-side body and the table-side body, indices into [`Bodies`].
    pub a: usize,
    pub b: usize,
    pub fraction: f64,
}

/// Every body of a run for the current machine, tool and blank, with the pairs to check.
#[derive(Debug, Clone, PartialEq)]
pub struct Bodies {
    kin: Kin,
    solids: Vec<Solid>,
    pairs: Vec<(usize, usize)>,
    /// Per side (head, table): whether a body moves with the linear axes, and the largest ρⱼ —
    /// a bound on [`Solid::rate`] of every body on that side.
    sides: [(bool, [f64; 2]); 2],
}

impl Bodies {
    /// The machine's bodies, the tool (`tool_radius`, the length of `kin`) and its holder
    /// ([`unconfirmed::holder`]), and the blank (W-CS) if the program has one; `None` when no pair
    /// is left to check.
    #[must_use]
    pub fn new(machine: &Machine, kin: &Kin, tool_radius: f64, blank: Option<&Blank>) -> Option<Bodies> {
        let gauge = DVec3::new(0.0, 0.0, kin.tool_length);
        let mut solids = Vec::new();
        for b in &machine.bodies {
            let (role, frame, offset) = match b.carrier {
                BodyCarrier::Bed => (Role::Table, Frame::Table { from: 2 }, DVec3::ZERO),
                BodyCarrier::Table { joint } => (Role::Table, Frame::Table { from: joint }, DVec3::ZERO),
                BodyCarrier::Head => (Role::Head, Frame::Tool, gauge),
            };
            let shape = match b.shape {
                BodyShape::Box { center, half } => Local::Box { center: center + offset, half },
                BodyShape::Cylinder { base, direction, radius, height } => {
                    Local::Cylinder { base: base + offset, direction, radius, height }
                }
            };
            solids.push(Solid::new(kin, b.name.clone(), role, frame, shape));
        }
        let length = kin.tool_length.max(0.0);
        let holder = unconfirmed::holder(length, tool_radius);
        let cut = length - holder.length;
        if cut > 0.0 && tool_radius > 0.0 {
            let shape =
                Local::Cylinder { base: DVec3::ZERO, direction: DVec3::Z, radius: tool_radius, height: cut };
            solids.push(Solid::new(kin, Text::new("Werkzeug", "tool"), Role::Tool, Frame::Tool, shape));
        }
        if holder.length > 0.0 {
            let shape = Local::Cylinder {
                base: DVec3::new(0.0, 0.0, cut),
                direction: DVec3::Z,
                radius: holder.radius,
                height: holder.length,
            };
            let name = Text::new("Werkzeughalter", "tool holder");
            solids.push(Solid::new(kin, name, Role::Holder, Frame::Tool, shape));
        }
        if let Some(b) = blank.filter(|b| (b.max - b.min).min_element() > 0.0) {
            let shape =
                Local::Box { center: kin.preset + 0.5 * (b.min + b.max), half: 0.5 * (b.max - b.min) };
            let name = Text::new("Rohteil", "blank");
            solids.push(Solid::new(kin, name, Role::Blank, Frame::Table { from: 0 }, shape));
        }
        let mut pairs = Vec::new();
        for (i, a) in solids.iter().enumerate() {
            for (j, b) in solids.iter().enumerate() {
                if a.role.head_side()
                    && !b.role.head_side()
                    && !(a.role == Role::Tool && b.role == Role::Blank)
                {
                    pairs.push((i, j));
                }
            }
        }
        let mut sides = [(false, [0.0_f64; 2]); 2];
        for b in &solids {
            let (own, reach) = &mut sides[usize::from(!b.role.head_side())];
            *own |= b.frame == Frame::Tool;
            *reach = [reach[0].max(b.reach[0]), reach[1].max(b.reach[1])];
        }
        (!pairs.is_empty()).then_some(Bodies { kin: *kin, solids, pairs, sides })
    }

    /// The name of body `i`.
    #[must_use]
    pub fn name(&self, i: usize) -> Text {
        self.solids.get(i).map_or(Text::new("?", "?"), |s| s.name.clone())
    }

    /// Every body placed for `axes`, with its name.
    #[must_use]
    pub fn placed(&self, axes: &MachineAxes) -> Vec<(Text, Placed)> {
        let poses = frame_poses(&self.kin, axes);
        self.solids.iter().map(|s| (s.name.clone(), s.shape.placed(&poses[s.frame.index()]))).collect()
    }

    /// The first checked pair that touches along `seg`, with the earliest fraction found (module
    /// doc: no contact is missed). `clear` carries lower bounds on each pair's distance from the
    /// end of the motion checked before: a pair that moves less than that along `seg` is clear
    /// without a test (derived: the distance shrinks at most by the motion), which keeps the long
    /// runs of tiny CAM moves cheap. While the motions since stay within the smallest of those
    /// gaps, even the loop over the pairs is skipped (a bound per side: the head-side and the
    /// table-side body that can move most).
    pub fn first_contact(&self, seg: &Segment, clear: &mut Clearances) -> Option<Contact> {
        let rot = seg.rotary_delta.map(|d| d.to_radians().abs());
        let lin = linear_rate(seg, rot);
        if !lin.is_finite() || !rot.iter().all(|r| r.is_finite()) {
            return None;
        }
        let rate_of = |i: usize| self.solids[i].rate(lin, rot);
        // Every body placed once at the middle, when a pair needs it: most are cleared there.
        let mut at_mid: Option<Vec<(Affine, Placed)>> = None;
        let mut best: Option<Contact> = None;
        // Intervals still to test, the earliest on top; halving ends at RESOLUTION, so the depth
        // stays far below the capacity (a rate of 1e12 mm per segment needs 45 levels).
        let mut stack = [(0.0_f64, 1.0_f64); 64];
        let known = clear.at == Some(seg.start) && clear.gaps.len() == self.pairs.len();
        if known {
            // No pair moves more than this: within the smallest gap, every pair is clear.
            let most: f64 = self
                .sides
                .iter()
                .map(|&(own, reach)| if own { lin } else { 0.0 } + reach[0] * rot[0] + reach[1] * rot[1])
                .sum();
            if most < clear.slack - clear.spent - RESOLUTION {
                clear.spent += most;
                clear.at = Some(seg.end);
                return None;
            }
            for g in &mut clear.gaps {
                *g -= clear.spent;
            }
        } else {
            clear.gaps.clear();
            clear.gaps.resize(self.pairs.len(), 0.0);
        }
        clear.spent = 0.0;
        clear.at = None;
        let mut at_end: Option<Vec<(Affine, Placed)>> = None;
        // With the rotary axes standing still the table frames stand still and the head-side
        // frame (L + H) only moves straight by the linear axes' travel: every pair's motion is
        // a translation, tested whole by the swept boxes (`swept_obb_gap`) before any halving.
        let straight = rot == [0.0, 0.0]
            && matches!(seg.path, SegmentPath::Linear | SegmentPath::Stay { .. } | SegmentPath::Tcpm(_));
        // Broad phase of a translation: each head-side body's box swept along it against each
        // table-side body's box; apart by more than the resolution, the pair is clear along the
        // whole motion by at least that much (a box holds its body, and a gap along one axis is
        // a lower bound on the distance). Computed once the first pair needs a test.
        // The boxes at the start are the last motion's at its end, moved along, while the run
        // goes from translation to translation: most motions place no body at all.
        let d = seg.end.linear - seg.start.linear;
        let mut start_boxes: Option<Vec<(DVec3, DVec3)>> = None;
        // The head side's boxes together, swept along the translation (made once per motion):
        // a table-side body apart from it is apart from each of them by at least as much, so a
        // pair passes on that one comparison before its own sweep is made (inside a blank most
        // pairs are near enough to be tested, and most pass this way).
        let mut head_sweep: Option<(DVec3, DVec3)> = None;
        for (k, &(a, b)) in self.pairs.iter().enumerate() {
            let rate = rate_of(a) + rate_of(b);
            if known && rate < clear.gaps[k] - RESOLUTION {
                clear.gaps[k] -= rate;
                continue;
            }
            if straight {
                let boxes = start_boxes.get_or_insert_with(|| match clear.boxes.take() {
                    Some((at, boxes)) if at == seg.start => boxes,
                    _ => self.boxes(at_end.get_or_insert_with(|| self.place_all(&seg.axes_at(1.0))), -d),
                });
                let (lh, hh) = *head_sweep.get_or_insert_with(|| {
                    let mut sweep = (DVec3::INFINITY, DVec3::NEG_INFINITY);
                    for (solid, (lo, hi)) in self.solids.iter().zip(boxes.iter()) {
                        if solid.role.head_side() {
                            sweep = (sweep.0.min(lo.min(*lo + d)), sweep.1.max(hi.max(*hi + d)));
                        }
                    }
                    sweep
                });
                let (lb, hb) = boxes[b];
                let apart = (lb - hh).max(lh - hb).max_element();
                if apart > RESOLUTION {
                    clear.gaps[k] = apart;
                    continue;
                }
                // `a` (head side) swept along the translation, `b` (table side) standing.
                let (la, ha) = boxes[a];
                let apart = (lb - ha.max(ha + d)).max(la.min(la + d) - hb).max_element();
                if apart > RESOLUTION {
                    clear.gaps[k] = apart;
                    continue;
                }
            }
            let end = at_end.get_or_insert_with(|| self.place_all(&seg.axes_at(1.0)));
            if straight {
                // Pairs are (head side, table side): `a` came to its place at the end along
                // the linear axes' travel, `b` stood still.
                let swept = self.swept_gap(a, &end[a], b, &end[b], seg.start.linear - seg.end.linear);
                if swept > RESOLUTION {
                    clear.gaps[k] = swept;
                    continue;
                }
            }
            let gap = self.gap(a, &end[a], b, &end[b]).max(separation(&end[a].1, &end[b].1));
            clear.gaps[k] = gap.max(0.0);
            // Clear along the whole motion when it moves them less than their gap at its end.
            if rate <= 0.0 || rate < gap - RESOLUTION {
                continue;
            }
            stack[0] = (0.0, 1.0);
            let mut len = 1;
            while len > 0 {
                len -= 1;
                let (f0, f1) = stack[len];
                if best.is_some_and(|c| c.fraction <= f0) {
                    break;
                }
                let fm = 0.5 * (f0 + f1);
                let margin = 0.5 * rate * (f1 - f0);
                let leaf = margin <= RESOLUTION || f1 - f0 < 1e-9 || len + 2 > stack.len();
                let margin = margin.max(RESOLUTION);
                let near = if len == 0 && f0 == 0.0 && f1 == 1.0 {
                    let mid = at_mid.get_or_insert_with(|| self.place_all(&seg.axes_at(0.5)));
                    self.near(a, &mid[a], b, &mid[b], margin)
                } else {
                    let placed = self.place_all(&seg.axes_at(fm));
                    self.near(a, &placed[a], b, &placed[b], margin)
                };
                if !near {
                    continue;
                }
                if leaf {
                    best = Some(Contact { a, b, fraction: fm });
                    break;
                }
                stack[len] = (fm, f1);
                stack[len + 1] = (f0, fm);
                len += 2;
            }
        }
        if best.is_none() {
            clear.at = Some(seg.end);
            clear.slack = clear.gaps.iter().copied().fold(f64::INFINITY, f64::min);
        }
        let boxes =
            start_boxes.or_else(|| clear.boxes.take().filter(|(at, _)| *at == seg.start).map(|(_, b)| b));
        clear.boxes = match boxes {
            Some(mut boxes) if straight && best.is_none() => {
                self.move_head_side(&mut boxes, d);
                Some((seg.end, boxes))
            }
            _ => None,
        };
        best
    }

    /// Every body placed for `axes`, with its frame's pose.
    fn place_all(&self, axes: &MachineAxes) -> Vec<(Affine, Placed)> {
        let poses = frame_poses(&self.kin, axes);
        self.solids
            .iter()
            .map(|s| {
                let p = poses[s.frame.index()];
                (p, s.shape.placed(&p))
            })
            .collect()
    }

    /// A lower bound on the distance of bodies `a` and `b` placed so: the bounding sphere of `a`
    /// against `b`'s box or bounding sphere.
    fn gap(&self, a: usize, (pa, _): &(Affine, Placed), b: usize, (pb, sb): &(Affine, Placed)) -> f64 {
        let (ka, kb) = (&self.solids[a], &self.solids[b]);
        let centre = pa.apply(ka.centre);
        match sb {
            Placed::Box(o) => point_obb_distance(centre, o) - ka.radius,
            Placed::Cylinder { .. } => (centre - pb.apply(kb.centre)).length() - ka.radius - kb.radius,
        }
    }

    /// Per body, the axis-parallel box it lies in where it is `placed`, the head side's moved by
    /// `d`.
    fn boxes(&self, placed: &[(Affine, Placed)], d: DVec3) -> Vec<(DVec3, DVec3)> {
        let mut boxes: Vec<(DVec3, DVec3)> = placed
            .iter()
            .map(|(_, p)| {
                let o = p.bound();
                let a = o.axes;
                let reach = DVec3::new(
                    a.row(0).abs().dot(o.half),
                    a.row(1).abs().dot(o.half),
                    a.row(2).abs().dot(o.half),
                );
                (o.center - reach, o.center + reach)
            })
            .collect();
        self.move_head_side(&mut boxes, d);
        boxes
    }

    /// Moves the head side's boxes by `d` (the linear axes' travel).
    fn move_head_side(&self, boxes: &mut [(DVec3, DVec3)], d: DVec3) {
        for (solid, (lo, hi)) in self.solids.iter().zip(boxes) {
            if solid.role.head_side() {
                (*lo, *hi) = (*lo + d, *hi + d);
            }
        }
    }

    /// A lower bound on the distance of body `a`, swept from where it is placed by the
    /// translation `d`, from body `b` placed so: the bounding spheres first (the distance of
    /// `b`'s centre from the segment `a`'s centre runs along), then the swept boxes.
    fn swept_gap(&self, a: usize, pa: &(Affine, Placed), b: usize, pb: &(Affine, Placed), d: DVec3) -> f64 {
        let (ka, kb) = (&self.solids[a], &self.solids[b]);
        let (ca, cb) = (pa.0.apply(ka.centre), pb.0.apply(kb.centre));
        let spheres = segment_segment_distance(ca, ca + d, cb, cb) - ka.radius - kb.radius;
        if spheres > RESOLUTION {
            return spheres;
        }
        spheres.max(swept_obb_gap(&pa.1.bound(), d, &pb.1.bound()))
    }

    /// Whether bodies `a` and `b` placed so come within `margin`: [`Bodies::gap`] first, then the
    /// shapes.
    fn near(&self, a: usize, pa: &(Affine, Placed), b: usize, pb: &(Affine, Placed), margin: f64) -> bool {
        self.gap(a, pa, b, pb) <= margin && touch(&pa.1, &pb.1, margin)
    }
}

/// What [`Bodies::first_contact`] knows from the motion before: lower bounds on each pair's
/// distance with the axes at `at` (none: nothing known).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Clearances {
    at: Option<MachineAxes>,
    gaps: Vec<f64>,
    /// The smallest of `gaps` when they were last brought up to date…
    slack: f64,
    /// …and how far any pair may have moved since (`gaps` are that much too large).
    spent: f64,
    /// Each body's box (axis-parallel, M-CS) with the axes at the first of these.
    boxes: Option<(MachineAxes, Vec<(DVec3, DVec3)>)>,
}

impl Clearances {
    /// Nothing known (the bodies changed).
    pub fn forget(&mut self) {
        self.at = None;
        self.boxes = None;
    }
}

/// A collision that stopped the run: the two bodies, where in the block's motion, the axes at
/// that moment, and the other PLANE solution when its swivel would have been free.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Collision {
    /// The head-side body (tool, holder, head part).
    pub a: Text,
    /// The table-side body (bed, table part, blank).
    pub b: Text,
    pub kind: SegmentKind,
    /// Fraction (time) of the colliding segment.
    pub fraction: f64,
    /// Every axis at the moment of contact.
    pub axes: MachineAxes,
    /// The other solution of the PLANE block, when its swivel is collision-free.
    pub alternative: Option<SafeAlternative>,
}

/// The other SEQ solution of a swivel that collides, when it would not.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SafeAlternative {
    /// `SEQ+` or `SEQ−` (the master's side of zero, as the control's SEQ counts it).
    pub word: String,
    /// Its rotary axis values (for the view's ghost).
    pub axes: AxisValues,
}
