//! The machine drawn from its definition: bed and column, the rotary table and tilting cradle
//! (or a fixed table), the swivel head, spindle, tool and the clamped blank. Every part is placed
//! in the frame of the link that carries it (see `pose.rs`), so it turns about the real pivot
//! and axis direction of `static/machines/*.json`. Sizes that the definition does not give
//! (table radius, housings) are illustrative and derived from the blank.

use glam::{DAffine3, DMat3, DVec3};
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::{Carrier, Machine, RotaryJoint};
use schwenkbar_core::sim::collision::Placed;

use super::draw_list::{DrawList, Pass, Shape, beam, cuboid, rod};
use schwenkbar_app::scene::pose::{Poses, head_pivot, poses};
use schwenkbar_app::scene::{Blank, Frame, SceneState, Tool};

pub const BED: [f32; 3] = [0.36, 0.39, 0.44];
pub const FIXED: [f32; 3] = [0.52, 0.55, 0.60];
pub const CRADLE: [f32; 3] = [0.26, 0.45, 0.72];
pub const ROTARY: [f32; 3] = [0.66, 0.70, 0.76];
pub const MARK: [f32; 3] = [0.10, 0.10, 0.12];
pub const HEAD: [f32; 3] = [0.86, 0.87, 0.89];
pub const SPINDLE: [f32; 3] = [0.58, 0.61, 0.66];
pub const TOOL: [f32; 3] = [0.80, 0.82, 0.86];
pub const FLUTE: [f32; 3] = [0.95, 0.78, 0.20];
/// The blank: amber, a colour no machine part has (the pixel tests look for it).
pub const BLANK: [f32; 3] = [0.93, 0.55, 0.18];
/// Colour of the translucent ghost of the other candidate: a bright cyan, opaque enough to
/// stand out from the background on a washed-out classroom projector (trial II found the old
/// 30 % light cyan hard to see; the test asks for WCAG's 3:1 of graphics).
pub const GHOST: [f32; 4] = [0.35, 0.85, 1.0, 0.55];

/// The two bodies of a collision: translucent red over the parts they stand for.
pub const CONTACT: [f32; 4] = [0.95, 0.10, 0.08, 0.60];
/// Every collision body in the machine editor's preview: translucent violet.
pub const BODY: [f32; 4] = [0.62, 0.40, 0.95, 0.35];

/// Rotary-table thickness and spindle dimensions (illustrative, mm).
const DISC: f64 = 30.0;
const SPINDLE_R: f64 = 55.0;
const SPINDLE_LEN: f64 = 120.0;
const HOLDER_LEN: f64 = 50.0;
/// Where the column stands (behind the table, +Y).
const COLUMN_Y: f64 = 330.0;

/// How one copy of the machine is drawn.
#[derive(Debug, Clone, Copy)]
struct Style {
    pass: Pass,
    /// `Some` = every part in this colour (the ghost).
    tint: Option<[f32; 4]>,
}

impl Style {
    fn colour(&self, c: [f32; 3]) -> [f32; 4] {
        self.tint.unwrap_or([c[0], c[1], c[2], 1.0])
    }
}

/// The head's housing, ram, spindle and holder seen from above: a veil, so that the view from
/// the top shows the part under the spindle (classroom trial II: "Oben" showed only the
/// spindle). The cutting tool stays solid.
pub const HEAD_VEIL: [f32; 4] = [0.86, 0.87, 0.89, 0.22];

/// A view looks down this steeply (degrees above the XY plane) or more: the head is veiled.
pub const FROM_ABOVE: f32 = 60.0;

/// The whole machine in its current state, the blank included; `from_above`: the head but its
/// cutting tool veiled ([`HEAD_VEIL`]).
pub fn machine(list: &mut DrawList, m: &Machine, s: &SceneState, from_above: bool) -> Poses {
    let p = poses(m, &s.axes.rotary, s.axes.linear, s.tool.length);
    let style = Style { pass: Pass::Opaque, tint: None };
    let layout = Layout::new(m, s);
    fixed_parts(list, m, &layout, &p, style, s.tool.length.max(1.0));
    moving_parts(list, m, s, &layout, &p, style, Sides { table: true, head: false });
    let housing = if from_above { Style { pass: Pass::Translucent, tint: Some(HEAD_VEIL) } } else { style };
    head(list, m, &s.tool, &p, style, housing);
    p
}

/// Which sides of the chain to draw.
#[derive(Debug, Clone, Copy)]
struct Sides {
    table: bool,
    head: bool,
}

/// The moving parts at the other candidate's rotary values, translucent, with the tool tip on the
/// same point of the workpiece as in the real state (so the two postures compare like for like;
/// with the real X/Y/Z a head ghost would swing the tool away from the part).
pub fn ghost(list: &mut DrawList, m: &Machine, s: &SceneState, rotary: &AxisValues) {
    let p = poses(m, rotary, ghost_linear(m, s, rotary), s.tool.length);
    let layout = Layout::new(m, s);
    // Only the side that rotary axes move: a ghost over parts that stand still would only veil
    // them.
    let has = |c: Carrier| m.joints().iter().any(|j| j.carrier == c);
    let sides = Sides { table: has(Carrier::Table), head: has(Carrier::Head) };
    moving_parts(list, m, s, &layout, &p, Style { pass: Pass::Translucent, tint: Some(GHOST) }, sides);
}

/// The collision bodies `placed` (M-CS, from the simulator's own shapes) in `colour`, drawn in `pass`.
pub fn bodies<'a>(
    list: &mut DrawList,
    placed: impl IntoIterator<Item = &'a Placed>,
    colour: [f32; 4],
    pass: Pass,
) {
    for p in placed {
        match p {
            Placed::Box(o) => {
                let m =
                    DAffine3::from_mat3_translation(o.axes * DMat3::from_diagonal(2.0 * o.half), o.center);
                list.push(Shape::Cube, m, colour, pass);
            }
            Placed::Cylinder { capsule, .. } => {
                list.push(Shape::Cylinder, rod(capsule.a, capsule.b, capsule.radius), colour, pass);
            }
        }
    }
}

/// Linear axes that put the tool tip, with the rotary axes at `rotary`, on the workpiece point
/// where it is in the state `s`: L = W'(W⁻¹(tip)) − H'(0) (the inverse of tip = L + H(0) for
/// fixed rotary axes).
#[must_use]
pub fn ghost_linear(m: &Machine, s: &SceneState, rotary: &AxisValues) -> DVec3 {
    let now = poses(m, &s.axes.rotary, s.axes.linear, s.tool.length);
    let on_part = now.workpiece.inverse().transform_point3(now.tool.translation);
    let other = poses(m, rotary, DVec3::ZERO, s.tool.length);
    other.workpiece.transform_point3(on_part) - other.tool.translation
}

/// Sizes derived once per state from the machine and the blank (all in home coordinates).
struct Layout {
    /// Blank corners on the table at home.
    corners: [DVec3; 8],
    table_r: f64,
    bed_top: f64,
}

fn frame_affine(f: &Frame) -> DAffine3 {
    DAffine3::from_mat3_translation(f.rot, f.origin)
}

fn corners(b: &Blank, wcs: &Frame) -> [DVec3; 8] {
    let w = frame_affine(wcs);
    std::array::from_fn(|i| {
        let pick = |bit: usize, lo: f64, hi: f64| if i & bit == 0 { lo } else { hi };
        w.transform_point3(DVec3::new(
            pick(1, b.min.x, b.max.x),
            pick(2, b.min.y, b.max.y),
            pick(4, b.min.z, b.max.z),
        ))
    })
}

impl Layout {
    fn new(m: &Machine, s: &SceneState) -> Layout {
        let corners = corners(&s.blank, &s.wcs);
        let slave = m.slave();
        let table_r = if slave.carrier == Carrier::Table {
            let r = corners.iter().map(|c| distance_to_axis(*c, slave)).fold(0.0, f64::max);
            (r * 1.1).max(80.0)
        } else {
            80.0
        };
        let low_blank = corners.iter().map(|c| c.z).fold(f64::INFINITY, f64::min);
        let low_pivot = m
            .joints()
            .iter()
            .filter(|j| j.carrier == Carrier::Table)
            .map(|j| j.pivot.z - table_r * 0.6)
            .fold(f64::INFINITY, f64::min);
        Layout { corners, table_r, bed_top: low_blank.min(low_pivot) - 80.0 }
    }
}

fn distance_to_axis(p: DVec3, j: &RotaryJoint) -> f64 {
    let v = p - j.pivot;
    (v - j.direction * v.dot(j.direction)).length()
}

/// Where the rotary table's face sits on its axis: touching the blank from behind.
fn disc_centre(layout: &Layout, j: &RotaryJoint) -> DVec3 {
    let t = layout.corners.iter().map(|c| (*c - j.pivot).dot(j.direction)).fold(f64::INFINITY, f64::min);
    j.pivot + j.direction * t
}

/// A unit vector perpendicular to `d`, preferring +X (the zero mark of a rotary table).
fn perpendicular(d: DVec3) -> DVec3 {
    let x = DVec3::X - d * d.x;
    x.try_normalize().unwrap_or_else(|| (DVec3::Y - d * d.y).normalize_or(DVec3::Z))
}

/// The two trunnion points of a tilting cradle (on its axis, beside the rotary table).
fn trunnions(layout: &Layout, slave: &RotaryJoint, master: &RotaryJoint) -> (DVec3, DVec3, DVec3) {
    let under = disc_centre(layout, slave) - slave.direction * (DISC + 12.0);
    let d = master.direction;
    let q0 = master.pivot + d * (under - master.pivot).dot(d);
    let half = layout.table_r + 25.0;
    (under, q0 - d * half, q0 + d * half)
}

fn fixed_parts(list: &mut DrawList, m: &Machine, layout: &Layout, p: &Poses, style: Style, tool_length: f64) {
    let bed_top = layout.bed_top;
    let pass = style.pass;
    list.push(
        Shape::Cube,
        cuboid(
            DAffine3::IDENTITY,
            DVec3::new(-380.0, -320.0, bed_top - 60.0),
            DVec3::new(380.0, 440.0, bed_top),
        ),
        style.colour(BED),
        pass,
    );
    let [slave, master] = m.joints();
    match (slave.carrier, master.carrier) {
        (Carrier::Table, Carrier::Table) => {
            // Bearing blocks under the trunnions: they do not turn with the cradle.
            let (_, qa, qb) = trunnions(layout, slave, master);
            for (q, out) in [(qa, -master.direction), (qb, master.direction)] {
                let o = q + out * 80.0;
                if o.z - bed_top > 1.0 {
                    list.push(
                        Shape::Cube,
                        beam(o, DVec3::new(o.x, o.y, bed_top), 60.0, 130.0, master.direction),
                        style.colour(FIXED),
                        pass,
                    );
                }
            }
        }
        (Carrier::Table, Carrier::Head) => {
            let base = disc_centre(layout, slave) - slave.direction * DISC;
            if base.z - bed_top > 1.0 {
                list.push(
                    Shape::Cylinder,
                    rod(DVec3::new(base.x, base.y, bed_top), base, layout.table_r * 0.55),
                    style.colour(FIXED),
                    pass,
                );
            }
        }
        _ => {
            // No table axis: a fixed machine table under the blank.
            let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            for c in layout.corners {
                lo = lo.min(c);
                hi = hi.max(c);
            }
            let top = lo.z;
            list.push(
                Shape::Cube,
                cuboid(
                    DAffine3::IDENTITY,
                    DVec3::new(lo.x - 60.0, lo.y - 60.0, bed_top),
                    DVec3::new(hi.x + 60.0, hi.y + 60.0, top.max(bed_top + 1.0)),
                ),
                style.colour(ROTARY),
                pass,
            );
        }
    }
    // Column and the Y ram to the head carriage (moved by the linear axes only).
    let ram_end = p.carriage.transform_point3(DVec3::new(0.0, 0.0, carriage_top(m, tool_length)));
    let column_top = (bed_top + 900.0).max(ram_end.z + 90.0);
    list.push(
        Shape::Cube,
        cuboid(
            DAffine3::IDENTITY,
            DVec3::new(-120.0, COLUMN_Y, bed_top),
            DVec3::new(120.0, COLUMN_Y + 110.0, column_top),
        ),
        style.colour(FIXED),
        pass,
    );
    let at_column = DVec3::new(ram_end.x, COLUMN_Y, ram_end.z);
    if (at_column - ram_end).length() > 1.0 {
        list.push(Shape::Cube, beam(ram_end, at_column, 120.0, 110.0, DVec3::X), style.colour(FIXED), pass);
    }
}

/// Height (home coordinates, linear axes at 0, tool tip at the origin) where the carriage's
/// vertical ram ends. The head hangs from the gauge point, one tool length above the tip, so
/// everything above the tool moves up with a longer tool.
fn carriage_top(m: &Machine, tool_length: f64) -> f64 {
    let pivots = m.joints().iter().filter(|j| j.carrier == Carrier::Head).map(|j| j.pivot.z);
    tool_length + pivots.fold(SPINDLE_LEN, f64::max) + 220.0
}

fn moving_parts(
    list: &mut DrawList,
    m: &Machine,
    s: &SceneState,
    layout: &Layout,
    p: &Poses,
    style: Style,
    sides: Sides,
) {
    let [slave, master] = m.joints();
    if sides.table {
        table_side(list, s, layout, p, style, slave, master);
    }
    if sides.head {
        head(list, m, &s.tool, p, style, style);
    }
}

fn table_side(
    list: &mut DrawList,
    s: &SceneState,
    layout: &Layout,
    p: &Poses,
    style: Style,
    slave: &RotaryJoint,
    master: &RotaryJoint,
) {
    let pass = style.pass;
    if slave.carrier == Carrier::Table {
        let pose = p.joints[0];
        let top = disc_centre(layout, slave);
        list.push(
            Shape::Cylinder,
            pose * rod(top - slave.direction * DISC, top, layout.table_r),
            style.colour(ROTARY),
            pass,
        );
        // Zero mark at the rim so a turn of a round table is visible.
        let e = perpendicular(slave.direction);
        let mark_at = top + e * (layout.table_r - 14.0);
        list.push(
            Shape::Cube,
            pose * beam(mark_at - e * 12.0, mark_at + e * 12.0, 10.0, 10.0, slave.direction),
            style.colour(MARK),
            pass,
        );
        if master.carrier == Carrier::Table {
            let pose = p.joints[1];
            let (under, qa, qb) = trunnions(layout, slave, master);
            let d = master.direction;
            let span = 2.0 * (layout.table_r + 25.0);
            list.push(
                Shape::Cube,
                pose * beam(
                    under + slave.direction * 12.0,
                    under - slave.direction * 12.0,
                    span,
                    layout.table_r * 1.6,
                    d,
                ),
                style.colour(CRADLE),
                pass,
            );
            for (q, out) in [(qa, -d), (qb, d)] {
                let plate_end = under + (q - master.pivot - d * (under - master.pivot).dot(d)).dot(d) * d;
                if (plate_end - q).length() > 1.0 {
                    list.push(
                        Shape::Cube,
                        pose * beam(plate_end, q, 30.0, 110.0, d),
                        style.colour(CRADLE),
                        pass,
                    );
                }
                list.push(
                    Shape::Cylinder,
                    pose * rod(q - out * 15.0, q + out * 80.0, 42.0),
                    style.colour(CRADLE),
                    pass,
                );
            }
        }
    }
    // The blank, clamped on the innermost table link (the renderer draws the cut stock in its
    // place when there is one; the ghost keeps the box).
    if s.stock.is_none() || style.tint.is_some() {
        list.push(
            Shape::Cube,
            cuboid(p.workpiece * frame_affine(&s.wcs), s.blank.min, s.blank.max),
            style.colour(BLANK),
            pass,
        );
    }
}

/// The tool in `style`, everything above its cutting part (holder, spindle, housings, ram) in
/// `housing`.
fn head(list: &mut DrawList, m: &Machine, tool: &Tool, p: &Poses, style: Style, housing: Style) {
    let pass = style.pass;
    let (len, r) = (tool.length.max(1.0), tool.radius.max(0.5));
    // Tool and holder ride on the tool link (tip at the origin at home) up to the gauge point at
    // the spindle nose, one tool length above the tip (the tool length includes the holder).
    let t = p.tool;
    let holder = (len * 0.35).min(HOLDER_LEN);
    let cut = len - holder;
    list.push(Shape::Cylinder, t * rod(DVec3::ZERO, DVec3::Z * (cut * 0.55), r), style.colour(FLUTE), pass);
    list.push(
        Shape::Cylinder,
        t * rod(DVec3::Z * (cut * 0.55), DVec3::Z * cut, r * 0.85),
        style.colour(TOOL),
        pass,
    );
    let holder_r = r.max(12.0) + 14.0;
    list.push(
        Shape::Cone,
        t * DAffine3::from_mat3_translation(
            glam::DMat3::from_diagonal(DVec3::new(holder_r, holder_r, -holder)),
            DVec3::Z * len,
        ),
        housing.colour(SPINDLE),
        housing.pass,
    );
    let spindle_top = DVec3::Z * (len + SPINDLE_LEN);
    list.push(
        Shape::Cylinder,
        t * rod(DVec3::Z * len, spindle_top, SPINDLE_R),
        housing.colour(SPINDLE),
        housing.pass,
    );

    // Head axes, from the tool outwards: each housing joins the part below to its own pivot.
    let heads: Vec<(usize, &RotaryJoint)> =
        m.joints().iter().enumerate().filter(|(_, j)| j.carrier == Carrier::Head).collect();
    let mut below = spindle_top;
    for &(i, j) in heads.iter().rev() {
        let pose = p.joints[i];
        let pivot = head_pivot(j, len);
        if (pivot - below).length() > 1.0 {
            list.push(
                Shape::Cube,
                pose * beam(below, pivot, 100.0, 100.0, j.direction),
                housing.colour(HEAD),
                housing.pass,
            );
        }
        list.push(
            Shape::Cylinder,
            pose * rod(pivot - j.direction * 75.0, pivot + j.direction * 75.0, 62.0),
            housing.colour(CRADLE),
            housing.pass,
        );
        below = pivot;
    }
    // The vertical ram of the carriage down to the first head axis (or the spindle).
    let top = DVec3::Z * carriage_top(m, len);
    if (top - below).length() > 1.0 {
        list.push(
            Shape::Cube,
            p.carriage * beam(below, top, 110.0, 110.0, DVec3::X),
            housing.colour(HEAD),
            housing.pass,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use schwenkbar_core::plane::RotaryAxis;

    /// WCAG 2's relative luminance of an sRGB colour.
    fn luminance(c: [f32; 3]) -> f32 {
        let lin = |v: f32| if v <= 0.040_45 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) };
        0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
    }

    #[test]
    fn from_above_the_head_is_veiled_and_the_cutting_tool_stays_solid() {
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("machine");
            let s = SceneState::default();
            let (mut side, mut top) = (DrawList::default(), DrawList::default());
            machine(&mut side, &m, &s, false);
            machine(&mut top, &m, &s, true);
            assert_eq!(side.instances.len(), top.instances.len(), "{id}: the same parts");
            let veiled = top.instances.iter().filter(|i| i.colour == HEAD_VEIL).count();
            assert!(veiled >= 3, "{id}: holder, spindle and ram veiled ({veiled})");
            assert!(top.instances.iter().all(|i| i.colour != HEAD_VEIL || i.pass == Pass::Translucent));
            let flute = [FLUTE[0], FLUTE[1], FLUTE[2], 1.0];
            assert!(
                top.instances.iter().any(|i| i.colour == flute && i.pass == Pass::Opaque),
                "{id}: the tool"
            );
            assert!(
                side.instances.iter().all(|i| i.colour != HEAD_VEIL),
                "{id}: from the side nothing veiled"
            );
        }
    }

    #[test]
    fn the_ghost_over_the_background_has_the_contrast_of_a_graphic() {
        use crate::render::renderer::BACKGROUND;
        // Blended as WebGL blends it (source alpha over the framebuffer's sRGB values).
        let a = GHOST[3];
        let over = |bg: [f32; 3]| std::array::from_fn(|i| a * GHOST[i] + (1.0 - a) * bg[i]);
        let ratio = |x: f32, y: f32| (x.max(y) + 0.05) / (x.min(y) + 0.05);
        let against_background = ratio(luminance(over(BACKGROUND)), luminance(BACKGROUND));
        assert!(against_background >= 3.0, "ghost vs background {against_background:.2}:1");
        // Over the grey machine parts it still reads as a tint, not as one more grey.
        let tinted = over(HEAD);
        assert!(tinted[2] - tinted[0] > 0.2, "ghost over a head part: {tinted:?}");
    }

    fn finite(list: &DrawList) -> bool {
        list.instances.iter().all(|i| i.model.to_cols_array().iter().all(|x| x.is_finite()))
    }

    #[test]
    fn every_shipped_machine_builds_finite_parts_with_the_blank_once() {
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("shipped machine");
            let mut list = DrawList::default();
            machine(&mut list, &m, &SceneState::default(), false);
            assert!(list.instances.len() >= 8, "{id}: {} parts", list.instances.len());
            assert!(finite(&list), "{id}");
            let blanks = list.instances.iter().filter(|i| i.colour[..3] == BLANK).count();
            assert_eq!(blanks, 1, "{id}");
        }
    }

    #[test]
    fn the_blank_sits_on_the_rotary_table_and_turns_with_it() {
        let m = Machine::builtin("ac-table").expect("ac-table");
        let mut s = SceneState::default();
        let mut list = DrawList::default();
        machine(&mut list, &m, &s, false);
        let blank = |l: &DrawList| l.instances.iter().find(|i| i.colour[..3] == BLANK).map(|i| i.model);
        let disc = |l: &DrawList| l.instances.iter().find(|i| i.colour[..3] == ROTARY).map(|i| i.model);
        let (b, d) = (blank(&list).expect("blank"), disc(&list).expect("disc"));
        // Blank bottom (unit cube z = −0.5) on the disc top (unit cylinder z = 1).
        let bottom = b.transform_point3(DVec3::new(0.0, 0.0, -0.5));
        let top = d.transform_point3(DVec3::Z);
        assert!((bottom - top).length() < 1e-9, "{bottom} vs {top}");

        s.axes.rotary = AxisValues::default().with(RotaryAxis::A, 45.0).with(RotaryAxis::C, 90.0);
        let mut turned = DrawList::default();
        machine(&mut turned, &m, &s, false);
        let (b2, d2) = (blank(&turned).expect("blank"), disc(&turned).expect("disc"));
        let bottom2 = b2.transform_point3(DVec3::new(0.0, 0.0, -0.5));
        assert!((bottom2 - d2.transform_point3(DVec3::Z)).length() < 1e-9, "still clamped after turning");
        assert!((bottom2 - bottom).length() > 1.0, "the table moved");
    }

    #[test]
    fn the_ghost_draws_only_moving_parts_translucent() {
        let m = Machine::builtin("bc-head-table").expect("machine");
        let mut list = DrawList::default();
        let v = AxisValues::default().with(RotaryAxis::B, -45.0).with(RotaryAxis::C, 180.0);
        ghost(&mut list, &m, &SceneState::default(), &v);
        assert!(!list.instances.is_empty());
        assert!(list.instances.iter().all(|i| i.pass == Pass::Translucent && i.colour == GHOST));
        let mut full = DrawList::default();
        machine(&mut full, &m, &SceneState::default(), false);
        assert!(list.instances.len() < full.instances.len(), "no bed, column or bearing in the ghost");
        // Table-table: the head stands still, so the ghost has no tool.
        let m = Machine::builtin("ac-table").expect("machine");
        let mut list = DrawList::default();
        ghost(&mut list, &m, &SceneState::default(), &AxisValues::default().with(RotaryAxis::A, -45.0));
        let tool_like = list.instances.iter().filter(|i| i.shape == Shape::Cone).count();
        assert_eq!(tool_like, 0, "no tool holder (cone) in a table-table ghost");
        assert!(list.instances.iter().any(|i| i.shape == Shape::Cylinder), "but the rotary table");
    }

    #[test]
    fn the_ghosts_tool_tip_touches_the_same_point_of_the_workpiece() {
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("machine");
            let mut s = SceneState::default();
            s.axes.rotary = AxisValues::default().with(m.slave().axis, 90.0).with(m.master().axis, 45.0);
            s.axes.linear = DVec3::new(12.0, -7.0, 60.0);
            let other = AxisValues::default().with(m.slave().axis, -90.0).with(m.master().axis, -45.0);
            let now = poses(&m, &s.axes.rotary, s.axes.linear, s.tool.length);
            let ghost = poses(&m, &other, ghost_linear(&m, &s, &other), s.tool.length);
            let on_part = |p: &Poses| p.workpiece.inverse().transform_point3(p.tool.translation);
            assert!((on_part(&now) - on_part(&ghost)).length() < 1e-9, "{id}");
        }
    }

    #[test]
    fn the_tool_tip_is_at_the_tool_links_origin() {
        let m = Machine::builtin("ca-head").expect("machine");
        let mut s = SceneState::default();
        s.axes.rotary = AxisValues::default().with(RotaryAxis::A, 30.0);
        let mut list = DrawList::default();
        let p = machine(&mut list, &m, &s, false);
        let flute = list.instances.iter().find(|i| i.colour[..3] == FLUTE).expect("flute");
        let tip = flute.model.transform_point3(DVec3::ZERO);
        assert!((tip - p.tool.transform_point3(DVec3::ZERO)).length() < 1e-9);
    }
}
