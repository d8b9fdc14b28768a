//! The right-hand rule demonstrated (seed 000 §2.2, DOMAIN.md §2): a plane turned about X, Y or
//! Z, the thumb along the positive axis, the fingers curling in the positive turning direction,
//! and the `PLANE SPATIAL` block that produces the same turn. Pure maths and text; the component
//! `components/right_hand_demo.rs` draws it.

use glam::{DAffine3, DMat3, DVec3, Vec3};
use schwenkbar_core::format::plane_angles;
use schwenkbar_core::orientation::spatial;
use schwenkbar_core::plane::{PlaneDef, RelAxis};

use super::camera::project_to_css;
use super::draw_list::{DrawList, Label, Pass, Shape, rod, z_to};
use super::triads::{PLANE, X, Y, Z, arrow, triad};

/// The colour of the axis a spatial angle turns about (the triads' X, Y, Z).
fn colour(axis: RelAxis) -> [f32; 4] {
    match axis {
        RelAxis::Spa => X,
        RelAxis::Spb => Y,
        RelAxis::Spc => Z,
    }
}

/// `(SPA, SPB, SPC)` for a single turn.
#[must_use]
pub fn spatial_angles(axis: RelAxis, angle: f64) -> [f64; 3] {
    let mut a = [0.0; 3];
    a[axis as usize] = angle;
    a
}

/// The block as the control writes it: every angle with its sign (`PLANE SPATIAL SPA+0 SPB+15
/// SPC+0`; seed 000, Musterprogramm 1 block 10).
#[must_use]
pub fn block_text(axis: RelAxis, angle: f64) -> String {
    let [spa, spb, spc] = spatial_angles(axis, angle);
    plane_angles(PlaneDef::Spatial { spa, spb, spc })
}

/// The plane's orientation after the turn: the same matrix `core` computes for the block.
#[must_use]
pub fn orientation(axis: RelAxis, angle: f64) -> DMat3 {
    let [a, b, c] = spatial_angles(axis, angle);
    spatial(a, b, c)
}

/// Near the pivot the pointer's bearing is ill-defined: a few pixels there would swing the
/// plane by tens of degrees, so within this radius (CSS pixels) the bearing is held.
pub const DEAD_ZONE: f32 = 20.0;

/// A drag of the plane: one turn of the pointer around the pivot (the axis' origin on screen) is
/// one turn of the plane, i.e. the angle follows the pointer's bearing (atan2) around the pivot.
/// Counter-clockwise on screen is positive when the axis points towards the viewer: the
/// right-hand rule seen from the thumb's tip is counter-clockwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DragTurn {
    pivot: (f32, f32),
    towards_viewer: bool,
    /// The pointer's last bearing (degrees, counter-clockwise); `None` inside [`DEAD_ZONE`].
    bearing: Option<f64>,
    /// The plane's angle, −180…+180.
    pub angle: f64,
}

/// The bearing of `at` around `pivot`, counter-clockwise from 3 o'clock (y is down on screen).
fn bearing(pivot: (f32, f32), at: (f32, f32)) -> Option<f64> {
    let (x, y) = (f64::from(at.0 - pivot.0), f64::from(pivot.1 - at.1));
    (x.hypot(y) >= f64::from(DEAD_ZONE)).then(|| y.atan2(x).to_degrees())
}

impl DragTurn {
    /// A drag that starts at `at` with the plane at `angle`.
    #[must_use]
    pub fn start(pivot: (f32, f32), at: (f32, f32), angle: f64, towards_viewer: bool) -> DragTurn {
        DragTurn { pivot, towards_viewer, bearing: bearing(pivot, at), angle }
    }

    /// The drag after the pointer moved to `at`. The step between two bearings is taken the
    /// short way round, so crossing 9 o'clock (atan2's ±180°) does not jump; the angle stops at
    /// ±180° like the slider.
    #[must_use]
    pub fn moved(self, at: (f32, f32)) -> DragTurn {
        let Some(now) = bearing(self.pivot, at) else { return self };
        let Some(before) = self.bearing else { return DragTurn { bearing: Some(now), ..self } };
        let step = (now - before + 540.0).rem_euclid(360.0) - 180.0;
        let step = if self.towards_viewer { step } else { -step };
        DragTurn { bearing: Some(now), angle: (self.angle + step).clamp(-180.0, 180.0), ..self }
    }
}

/// Whether the axis (through the origin) points towards the eye at `eye`.
#[must_use]
pub fn points_towards(axis: RelAxis, eye: Vec3) -> bool {
    eye.as_dvec3().dot(axis.unit()) > 0.0
}

/// The axis' origin on screen (the pivot of a drag).
#[must_use]
pub fn pivot_on_screen(view_proj: &glam::Mat4, width: f32, height: f32) -> (f32, f32) {
    project_to_css(view_proj, Vec3::ZERO, width, height).unwrap_or((width / 2.0, height / 2.0))
}

/// Skin colour of the stylised hand, translucent so the arrows show through.
const SKIN: [f32; 4] = [0.96, 0.76, 0.60, 0.72];
const PLANE_SIDE: f64 = 200.0;

/// The demo scene (seen from `eye`): the turned plane and its triad, the fixed reference triad, the thumb arrow,
/// the curled arrow and a stylised right hand gripping the axis.
#[must_use]
pub fn draw_list(axis: RelAxis, angle: f64, eye: DVec3) -> DrawList {
    let mut list = DrawList::default();
    let r = orientation(axis, angle);
    let m = DAffine3::from_mat3_translation(
        r * DMat3::from_diagonal(DVec3::new(PLANE_SIDE, PLANE_SIDE, 1.0)),
        DVec3::ZERO,
    );
    list.push(Shape::Square, m, [PLANE[0], PLANE[1], PLANE[2], 0.45], Pass::Translucent);
    // The untilted axes, thin and grey, for reference.
    for u in [DVec3::X, DVec3::Y, DVec3::Z] {
        list.push(Shape::Cylinder, rod(DVec3::ZERO, u * 150.0, 1.2), [0.55, 0.58, 0.62, 1.0], Pass::Opaque);
    }
    triad(&mut list, DVec3::ZERO, r, 110.0, "", "frame");
    list.labels.retain(|l| !l.text.is_empty());

    // Thumb along +axis, the curl around it (rotation about the thumb = positive direction).
    let u = axis.unit();
    let frame = z_to(u);
    arrow(&mut list, DVec3::ZERO, u, 250.0, 3.5, colour(axis), Pass::Opaque);
    let curl_at = u * 205.0;
    let radius = 34.0;
    list.push(
        Shape::CurlArc,
        DAffine3::from_mat3_translation(frame * DMat3::from_diagonal(DVec3::splat(radius)), curl_at),
        [0.98, 0.62, 0.10, 1.0],
        Pass::Opaque,
    );
    // Arrow head at the end of the arc, pointing along the positive turning direction.
    let end = f64::from(super::draw_list::Shape::CURL_SWEEP);
    let (s, c) = end.sin_cos();
    let tip_at = curl_at + frame * DVec3::new(c, s, 0.0) * radius;
    let tangent = frame * DVec3::new(-s, c, 0.0);
    list.push(
        Shape::Cone,
        rod(tip_at - tangent * 2.0, tip_at + tangent * 16.0, 6.5),
        [0.98, 0.62, 0.10, 1.0],
        Pass::Opaque,
    );

    // Turn the hand about its axis so the palm and the thumb face the viewer.
    let e = frame.transpose() * eye;
    let facing = e.y.atan2(e.x) + std::f64::consts::PI;
    hand(&mut list, frame * DMat3::from_rotation_z(facing), u * 125.0);
    list.labels.push(Label { text: axis.about(), at: u * 268.0, kind: "axis" });
    list
}

/// A right hand in the same pose: a fist round the axis, the thumb up along it, the four fingers
/// curling like the arrow (a palm block, a thumb rod and four thick finger arcs). `frame` maps
/// the hand's local +Z onto the axis; any turn about that axis keeps the hand a right hand.
fn hand(list: &mut DrawList, frame: DMat3, grip: DVec3) {
    let local = |p: DVec3| grip + frame * p;
    // The palm lies on the local −X side of the axis; the fingers leave it there (180°) and wrap
    // counter-clockwise about the thumb (+Z local) through −Y, +X to +Y: the positive direction.
    let from_palm = frame * DMat3::from_rotation_z(std::f64::consts::PI);
    list.push(
        Shape::Cube,
        DAffine3::from_mat3_translation(
            frame * DMat3::from_diagonal(DVec3::new(16.0, 54.0, 70.0)),
            local(DVec3::new(-32.0, 0.0, -26.0)),
        ),
        SKIN,
        Pass::Translucent,
    );
    // Thumbs up: the thumb lies along the axis, over the thumb arrow.
    list.push(
        Shape::Cylinder,
        rod(local(DVec3::new(-24.0, 0.0, -2.0)), local(DVec3::new(-17.0, 0.0, 50.0)), 9.0),
        SKIN,
        Pass::Translucent,
    );
    list.push(
        Shape::Cone,
        rod(local(DVec3::new(-17.0, 0.0, 50.0)), local(DVec3::new(-15.0, 0.0, 63.0)), 9.0),
        SKIN,
        Pass::Translucent,
    );
    for k in 0..4 {
        let z = -6.0 - 17.0 * f64::from(k);
        list.push(
            Shape::Finger,
            DAffine3::from_mat3_translation(
                from_palm * DMat3::from_diagonal(DVec3::splat(24.0)),
                local(DVec3::new(0.0, 0.0, z)),
            ),
            SKIN,
            Pass::Translucent,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_text_writes_every_sign_like_the_control() {
        assert_eq!(block_text(RelAxis::Spb, 15.0), "PLANE SPATIAL SPA+0 SPB+15 SPC+0");
        assert_eq!(block_text(RelAxis::Spa, -30.0), "PLANE SPATIAL SPA-30 SPB+0 SPC+0");
        assert_eq!(block_text(RelAxis::Spc, 12.5), "PLANE SPATIAL SPA+0 SPB+0 SPC+12.5");
    }

    #[test]
    fn positive_spb_tips_the_plane_normal_towards_plus_x() {
        // DOMAIN.md §2: Ry(b)·ez = (sin b, 0, cos b).
        let t = orientation(RelAxis::Spb, 15.0).col(2);
        assert!(t.x > 0.25 && t.y.abs() < 1e-12, "{t}");
        let t = orientation(RelAxis::Spa, 15.0).col(2);
        assert!(t.y < -0.25, "positive SPA tips the normal towards −Y: {t}");
    }

    /// The pointer `r` px from `pivot` at `deg` (counter-clockwise from 3 o'clock, y down).
    fn at(pivot: (f32, f32), r: f32, deg: f32) -> (f32, f32) {
        let (s, c) = deg.to_radians().sin_cos();
        (pivot.0 + r * c, pivot.1 - r * s)
    }

    /// Drags from bearing `from` to `to` in 1° steps, radius 60 px.
    fn drag(towards_viewer: bool, from: i32, to: i32, angle: f64) -> f64 {
        let pivot = (200.0, 150.0);
        let mut d = DragTurn::start(pivot, at(pivot, 60.0, from as f32), angle, towards_viewer);
        let step = if to >= from { 1 } else { -1 };
        let mut b = from;
        while b != to {
            b += step;
            d = d.moved(at(pivot, 60.0, b as f32));
        }
        d.angle
    }

    #[test]
    fn a_quarter_turn_of_the_pointer_round_the_pivot_turns_the_plane_90_degrees() {
        // Counter-clockwise seen with the axis towards the viewer: plus; clockwise: minus.
        assert!((drag(true, 0, 90, 0.0) - 90.0).abs() < 1e-3);
        assert!((drag(true, 0, -90, 0.0) + 90.0).abs() < 1e-3);
        // The axis pointing away: the same pointer turn is the other sign.
        assert!((drag(false, 0, 90, 0.0) + 90.0).abs() < 1e-3);
        // Across 9 o'clock (atan2's ±180°) without a jump, in both directions.
        assert!((drag(true, 135, 225, 10.0) - 100.0).abs() < 1e-3);
        assert!((drag(true, 225, 135, 10.0) + 80.0).abs() < 1e-3);
        // The same quarter turn further out or closer in is still 90°: not a matter of pixels.
        let pivot = (0.0, 0.0);
        let d = DragTurn::start(pivot, at(pivot, 300.0, 0.0), 0.0, true).moved(at(pivot, 30.0, 45.0));
        assert!((d.moved(at(pivot, 150.0, 90.0)).angle - 90.0).abs() < 1e-3);
    }

    #[test]
    fn a_drag_stops_at_half_a_turn_and_holds_near_the_pivot() {
        assert!((drag(true, 0, 270, 0.0) - 180.0).abs() < 1e-9);
        let pivot = (100.0, 100.0);
        let d = DragTurn::start(pivot, (160.0, 100.0), 0.0, true);
        // Through the dead zone: no swing, and the bearing picks up again outside it.
        let d = d.moved((105.0, 95.0)).moved((100.0, 40.0));
        assert!((d.angle - 90.0).abs() < 1e-3, "{}", d.angle);
    }

    #[test]
    fn the_curl_arc_mesh_turns_counter_clockwise_about_plus_z() {
        // The curled arrow means "positive about the thumb" only if the arc mesh runs from +X
        // towards +Y (counter-clockwise seen from +Z), as Shape::CurlArc promises.
        let m = super::super::mesh::torus_arc(1.0, Shape::CURL_TUBE, Shape::CURL_SWEEP, 48, 8);
        let ring = |seg: usize| {
            let per = 9 * 6; // (sides + 1) vertices of 6 floats per ring
            let v = &m.vertices[seg * per..(seg + 1) * per];
            let (mut x, mut y) = (0.0, 0.0);
            for p in v.chunks_exact(6).take(8) {
                x += p[0] / 8.0;
                y += p[1] / 8.0;
            }
            (x, y)
        };
        let (x0, y0) = ring(0);
        assert!((x0 - 1.0).abs() < 0.05 && y0.abs() < 0.05, "starts at +X: {x0},{y0}");
        assert!(ring(1).1 > 0.05, "then turns towards +Y");
        let (xe, ye) = ring(48);
        assert!(xe.abs() < 0.05 && (ye + 1.0).abs() < 0.05, "ends at 270°, i.e. −Y: {xe},{ye}");
    }

    #[test]
    fn the_demo_scene_shows_the_block_turn() {
        let list = draw_list(RelAxis::Spb, 15.0, DVec3::new(500.0, -500.0, 300.0));
        let plane = list.instances.iter().find(|i| i.shape == Shape::Square).expect("plane");
        let n = plane.model.matrix3.col(2).normalize();
        assert!((n - orientation(RelAxis::Spb, 15.0).col(2)).length() < 1e-12);
        assert!(list.labels.iter().any(|l| l.text == "Y" && l.kind == "axis"));
    }

    #[test]
    fn the_fingers_and_the_curl_arrow_turn_positively_about_the_thumb_from_any_eye() {
        // The arc meshes run counter-clockwise about their own +Z (mesh test above); they show
        // the positive direction only if their +Z is the +axis and nothing mirrors them.
        for axis in RelAxis::ALL {
            for eye in [DVec3::new(500.0, -500.0, 300.0), DVec3::new(-300.0, 200.0, -400.0)] {
                let list = draw_list(axis, -40.0, eye);
                let arcs: Vec<_> = list
                    .instances
                    .iter()
                    .filter(|i| matches!(i.shape, Shape::Finger | Shape::CurlArc))
                    .collect();
                assert_eq!(arcs.len(), 5, "four fingers and the arrow");
                for a in arcs {
                    let m = a.model.matrix3;
                    assert!(m.determinant() > 0.0, "{axis:?}: mirrored");
                    assert!(
                        m.col(2).normalize().dot(axis.unit()) > 0.999,
                        "{axis:?}: arc about {}",
                        m.col(2)
                    );
                }
            }
        }
    }
}
