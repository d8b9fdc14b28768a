//! The orbit camera: a target point, azimuth and elevation about the machine's Z axis, and a
//! distance. Pure maths (no browser), so the mapping from gestures to views is unit-tested.
//!
//! The world is the machine coordinate system M-CS, Z up, millimetres.

use glam::{Mat4, Vec3, Vec4};

/// The four preset views.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// From the operator's side (−Y) looking along +Y: X to the right, Z up.
    Front,
    /// From +X looking along −X: Y to the right, Z up.
    Side,
    /// From above looking down −Z: X to the right, Y up.
    Top,
    /// Isometric from front right above.
    Iso,
}

impl Preset {
    /// `(azimuth, elevation)` in degrees. The azimuth is measured from +X towards +Y to the eye.
    #[must_use]
    pub fn angles(self) -> (f32, f32) {
        match self {
            Preset::Front => (-90.0, 0.0),
            Preset::Side => (0.0, 0.0),
            // Not quite 90°: look_at needs an up vector that is not parallel to the view.
            Preset::Top => (-90.0, MAX_ELEVATION),
            // The isometric elevation atan(1/√2) = 35.26° (equal foreshortening of all axes).
            Preset::Iso => (-45.0, 35.264_39),
        }
    }

    /// The preset for a key (1–4 or F/S/T/I, either case), if any.
    #[must_use]
    pub fn from_key(key: &str) -> Option<Preset> {
        match key {
            "1" | "f" | "F" => Some(Preset::Front),
            "2" | "s" | "S" => Some(Preset::Side),
            "3" | "t" | "T" => Some(Preset::Top),
            "4" | "i" | "I" => Some(Preset::Iso),
            _ => None,
        }
    }
}

/// Elevation limit in degrees (keeps the up vector well defined).
pub const MAX_ELEVATION: f32 = 89.5;
const MIN_DISTANCE: f32 = 50.0;
const MAX_DISTANCE: f32 = 20_000.0;

/// An orbit camera looking at `target`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub target: Vec3,
    /// Degrees, from +X towards +Y.
    pub azimuth: f32,
    /// Degrees above the XY plane.
    pub elevation: f32,
    /// Eye to target, mm.
    pub distance: f32,
    /// Vertical field of view, degrees.
    pub fov_y: f32,
}

impl Default for Camera {
    fn default() -> Self {
        let (azimuth, elevation) = Preset::Iso.angles();
        Camera { target: Vec3::new(0.0, 0.0, -20.0), azimuth, elevation, distance: 1500.0, fov_y: 35.0 }
    }
}

impl Camera {
    /// The eye position.
    #[must_use]
    pub fn eye(&self) -> Vec3 {
        // f64 trigonometry: shares the wasm code of the kinematics' sine and cosine.
        let (az, el) = (f64::from(self.azimuth).to_radians(), f64::from(self.elevation).to_radians());
        let dir = glam::DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin()).as_vec3();
        self.target + self.distance * dir
    }

    #[must_use]
    pub fn view(&self) -> Mat4 {
        look_at(self.eye(), self.target, Vec3::Z)
    }

    /// Perspective projection for WebGL's clip space (z in −1…1); near/far follow the distance
    /// so the depth buffer keeps its precision at every zoom.
    #[must_use]
    pub fn projection(&self, aspect: f32) -> Mat4 {
        let near = (self.distance * 0.05).max(1.0);
        let far = self.distance * 6.0 + 4000.0;
        perspective(self.fov_y.to_radians(), aspect.max(1e-3), near, far)
    }

    #[must_use]
    pub fn view_proj(&self, aspect: f32) -> Mat4 {
        self.projection(aspect) * self.view()
    }

    /// Jumps to a preset view, keeping target and distance.
    pub fn set_preset(&mut self, preset: Preset) {
        (self.azimuth, self.elevation) = preset.angles();
    }

    /// Orbits by a drag of `(dx, dy)` CSS pixels: right drag turns the scene right (the eye
    /// moves left), up drag shows it from higher.
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        const DEG_PER_PX: f32 = 0.4;
        // Wrapped into −180…180 in f64 (one remainder routine in the bundle, the kinematics' one).
        self.azimuth = schwenkbar_core::angle::wrap180(f64::from(self.azimuth - dx * DEG_PER_PX)) as f32;
        self.elevation = (self.elevation + dy * DEG_PER_PX).clamp(-MAX_ELEVATION, MAX_ELEVATION);
    }

    /// Zooms by `factor` (> 1 moves away).
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(MIN_DISTANCE, MAX_DISTANCE);
        }
    }

    /// Zooms by `factor` towards the point under the pointer at `(x, y)` CSS pixels of a view
    /// `width_px × height_px`: that point, at the target's depth, stays under the pointer (the
    /// blank under it does not drift out of view, classroom trial II). Under the pointer lies
    /// `target + (dx·right − dy·up)·s` (`s` mm a pixel, proportional to the distance); keeping
    /// it while `s` becomes `s·k` moves the target by that offset times `1 − k`.
    pub fn zoom_at(&mut self, factor: f32, x: f32, y: f32, width_px: f32, height_px: f32) {
        let offset = self.at_target_depth(x, y, width_px, height_px) - self.target;
        let before = self.distance;
        self.zoom(factor);
        self.target += offset * (1.0 - self.distance / before);
    }

    /// The point under the pointer at `(x, y)` CSS pixels of a view `width_px × height_px`, at
    /// the target's depth: `target + (dx·right − dy·up)·s`, `s` mm a pixel there.
    fn at_target_depth(&self, x: f32, y: f32, width_px: f32, height_px: f32) -> Vec3 {
        let view = self.view();
        // Rows of the view matrix are the camera's right and up axes in world coordinates.
        let right = Vec3::new(view.x_axis.x, view.y_axis.x, view.z_axis.x);
        let up = Vec3::new(view.x_axis.y, view.y_axis.y, view.z_axis.y);
        let mm_per_px = 2.0 * self.distance * half_tan(self.fov_y.to_radians()) / height_px.max(1.0);
        let (dx, dy) = (x - width_px / 2.0, y - height_px / 2.0);
        self.target + (dx * right - dy * up) * mm_per_px
    }

    /// The ray from the eye through the pointer at `(x, y)` CSS pixels of a view `width_px ×
    /// height_px`: `(eye, direction)`, world mm (what lies under the pointer).
    #[must_use]
    pub fn ray(&self, x: f32, y: f32, width_px: f32, height_px: f32) -> (Vec3, Vec3) {
        let eye = self.eye();
        (eye, self.at_target_depth(x, y, width_px, height_px) - eye)
    }

    /// Frames `points` (mm): the target at the centre of their box, the distance at which a
    /// sphere around them fits both the height and the width of a view of `aspect` (width /
    /// height), times `margin` (> 1 leaves the machine around them in view). The view
    /// direction stays. Sphere in a cone of half-angle θ: distance = r / sin θ.
    pub fn frame(&mut self, points: &[Vec3], aspect: f32, margin: f32) {
        let Some(first) = points.first() else { return };
        let (min, max) = points.iter().fold((*first, *first), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let centre = (min + max) / 2.0;
        let radius = points.iter().map(|p| p.distance(centre)).fold(10.0_f32, f32::max);
        let half_v = f64::from(self.fov_y.to_radians()) / 2.0;
        let half_h = (half_v.tan() * f64::from(aspect.max(1e-3))).atan();
        let half = half_v.min(half_h);
        self.target = centre;
        self.distance = ((f64::from(radius * margin) / half.sin()) as f32).clamp(MIN_DISTANCE, MAX_DISTANCE);
    }

    /// Pans so that the scene follows a drag of `(dx, dy)` CSS pixels in a view `height_px` tall.
    pub fn pan(&mut self, dx: f32, dy: f32, height_px: f32) {
        let view = self.view();
        // Rows of the view matrix are the camera's right and up axes in world coordinates.
        let right = Vec3::new(view.x_axis.x, view.y_axis.x, view.z_axis.x);
        let up = Vec3::new(view.x_axis.y, view.y_axis.y, view.z_axis.y);
        // World size of one pixel at the target's depth.
        let mm_per_px = 2.0 * self.distance * half_tan(self.fov_y.to_radians()) / height_px.max(1.0);
        self.target += (-dx * right + dy * up) * mm_per_px;
    }
}

/// tan(angle / 2), in f64 (see [`Camera::eye`]).
fn half_tan(angle: f32) -> f32 {
    let (s, c) = (f64::from(angle) / 2.0).sin_cos();
    (s / c) as f32
}

/// Right-handed view matrix (the matrix of `gluLookAt`, OpenGL 2.1 reference pages): rows are
/// the camera's right, up and backward axes.
#[must_use]
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let f = (target - eye).normalize();
    let s = f.cross(up).normalize();
    let u = s.cross(f);
    Mat4::from_cols(
        Vec4::new(s.x, u.x, -f.x, 0.0),
        Vec4::new(s.y, u.y, -f.y, 0.0),
        Vec4::new(s.z, u.z, -f.z, 0.0),
        Vec4::new(-s.dot(eye), -u.dot(eye), f.dot(eye), 1.0),
    )
}

/// Right-handed perspective projection to OpenGL clip space, z in −1…1 (the matrix of
/// `gluPerspective`, OpenGL 2.1 reference pages).
#[must_use]
pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / half_tan(fov_y);
    let nf = 1.0 / (near - far);
    Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, (far + near) * nf, -1.0),
        Vec4::new(0.0, 0.0, 2.0 * far * near * nf, 0.0),
    )
}

/// A world point projected to CSS pixels of a `width × height` view (origin top left, y down),
/// or `None` behind the eye.
#[must_use]
pub fn project_to_css(view_proj: &Mat4, p: Vec3, width: f32, height: f32) -> Option<(f32, f32)> {
    let clip = *view_proj * Vec4::new(p.x, p.y, p.z, 1.0);
    if clip.w <= 1e-6 {
        return None;
    }
    let ndc = clip.truncate() / clip.w;
    Some(((ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn screen(cam: &Camera, p: Vec3) -> (f32, f32) {
        project_to_css(&cam.view_proj(1.0), p, 100.0, 100.0).expect("in front of the eye")
    }

    fn camera(preset: Preset) -> Camera {
        let mut c = Camera { target: Vec3::ZERO, ..Camera::default() };
        c.set_preset(preset);
        c
    }

    /// The pointer's ray, projected back, lands under the pointer (a second way: the view's
    /// own projection), and the centre's ray passes through the target.
    #[test]
    fn the_ray_under_the_pointer_projects_back_to_it() {
        let mut c = Camera { target: Vec3::new(10.0, -20.0, 5.0), distance: 800.0, ..Camera::default() };
        c.orbit(37.0, -12.0);
        let (w, h) = (640.0, 360.0);
        let view_proj = c.view_proj(w / h);
        for (x, y) in [(320.0, 180.0), (50.0, 300.0), (600.0, 20.0)] {
            let (eye, dir) = c.ray(x, y, w, h);
            for s in [0.5, 1.0, 2.0] {
                let (px, py) = project_to_css(&view_proj, eye + s * dir, w, h).expect("in front");
                assert!((px - x).abs() < 0.05 && (py - y).abs() < 0.05, "({x}, {y}) → ({px}, {py})");
            }
        }
        let (eye, dir) = c.ray(320.0, 180.0, w, h);
        assert!((eye + dir - c.target).length() < 1e-3);
    }

    #[test]
    fn front_view_shows_x_right_and_z_up() {
        let c = camera(Preset::Front);
        assert!(c.eye().y < -1000.0, "the operator stands at −Y: {}", c.eye());
        let (cx, cy) = screen(&c, Vec3::ZERO);
        assert!((cx - 50.0).abs() < 1e-3 && (cy - 50.0).abs() < 1e-3);
        assert!(screen(&c, Vec3::X * 100.0).0 > 55.0, "+X to the right");
        assert!(screen(&c, Vec3::Z * 100.0).1 < 45.0, "+Z up (smaller y)");
    }

    #[test]
    fn side_view_shows_y_right_and_top_view_y_up() {
        let s = camera(Preset::Side);
        assert!(screen(&s, Vec3::Y * 100.0).0 > 55.0, "side: +Y to the right");
        let t = camera(Preset::Top);
        assert!(screen(&t, Vec3::X * 100.0).0 > 55.0, "top: +X to the right");
        assert!(screen(&t, Vec3::Y * 100.0).1 < 45.0, "top: +Y up");
    }

    #[test]
    fn iso_view_sees_x_towards_the_viewer_and_z_up() {
        let c = camera(Preset::Iso);
        let e = c.eye();
        assert!(e.x > 0.0 && e.y < 0.0 && e.z > 0.0, "front right above: {e}");
        assert!(screen(&c, Vec3::Z * 100.0).1 < 45.0);
    }

    #[test]
    fn perspective_maps_near_and_far_to_the_clip_range() {
        let p = perspective(1.0, 1.5, 2.0, 100.0);
        let near = p * Vec4::new(0.0, 0.0, -2.0, 1.0);
        let far = p * Vec4::new(0.0, 0.0, -100.0, 1.0);
        assert!((near.z / near.w + 1.0).abs() < 1e-5 && (far.z / far.w - 1.0).abs() < 1e-5);
    }

    #[test]
    fn keys_map_to_presets() {
        assert_eq!(Preset::from_key("1"), Some(Preset::Front));
        assert_eq!(Preset::from_key("s"), Some(Preset::Side));
        assert_eq!(Preset::from_key("T"), Some(Preset::Top));
        assert_eq!(Preset::from_key("4"), Some(Preset::Iso));
        assert_eq!(Preset::from_key("x"), None);
    }

    #[test]
    fn orbit_clamps_elevation_and_wraps_azimuth() {
        let mut c = camera(Preset::Front);
        c.orbit(0.0, 10_000.0);
        assert_eq!(c.elevation, MAX_ELEVATION);
        c.orbit(900.0, 0.0);
        assert!((-180.0..=180.0).contains(&c.azimuth), "{}", c.azimuth);
    }

    #[test]
    fn pan_moves_the_scene_with_the_pointer() {
        let mut c = camera(Preset::Front);
        let before = screen(&c, Vec3::ZERO);
        c.pan(10.0, 0.0, 100.0);
        let after = screen(&c, Vec3::ZERO);
        assert!(
            (after.0 - before.0 - 10.0).abs() < 0.05,
            "the origin follows the drag: {before:?} → {after:?}"
        );
        c.pan(0.0, 10.0, 100.0);
        assert!((screen(&c, Vec3::ZERO).1 - after.1 - 10.0).abs() < 0.05);
    }

    #[test]
    fn the_wheel_zooms_towards_the_point_under_the_pointer() {
        for preset in [Preset::Iso, Preset::Front, Preset::Top] {
            let mut c = camera(preset);
            c.distance = 1000.0;
            let (w, h) = (160.0, 100.0);
            let vp = |c: &Camera| c.view_proj(w / h);
            // The world point under the pointer at (120, 30), on the plane through the target
            // facing the eye: found by projecting candidates (a second method, not the formula).
            let (px, py) = (120.0_f32, 30.0_f32);
            let view = c.view();
            let (right, up) = (
                Vec3::new(view.x_axis.x, view.y_axis.x, view.z_axis.x),
                Vec3::new(view.x_axis.y, view.y_axis.y, view.z_axis.y),
            );
            let mut p = c.target;
            for _ in 0..50 {
                let (sx, sy) = project_to_css(&vp(&c), p, w, h).expect("in view");
                p += (right * (px - sx) - up * (py - sy)) * 2.0;
            }
            for factor in [0.5_f32, 0.8, 1.25, 2.0] {
                let mut z = c;
                z.zoom_at(factor, px, py, w, h);
                assert!((z.distance - 1000.0 * factor).abs() < 1e-2);
                let (sx, sy) = project_to_css(&vp(&z), p, w, h).expect("in view");
                assert!(
                    (sx - px).abs() < 0.05 && (sy - py).abs() < 0.05,
                    "{preset:?} ×{factor}: ({sx}, {sy})"
                );
            }
            // At the centre it is the plain zoom.
            let mut z = c;
            z.zoom_at(0.5, w / 2.0, h / 2.0, w, h);
            assert!(z.target.distance(c.target) < 1e-3);
        }
    }

    #[test]
    fn zoom_stays_in_range_and_ignores_nonsense() {
        let mut c = Camera::default();
        c.zoom(1e-9);
        assert_eq!(c.distance, MIN_DISTANCE);
        c.zoom(f32::NAN);
        assert_eq!(c.distance, MIN_DISTANCE);
        c.zoom(1e12);
        assert_eq!(c.distance, MAX_DISTANCE);
    }

    #[test]
    fn framing_puts_every_point_inside_the_view_at_any_aspect() {
        // Musterprogramm 1 at block 10: the blank near the table centre, the tool at
        // X-600 Y+500 M91 far away from it (the case that left the tool out of view).
        let points = [
            Vec3::new(-50.0, -50.0, -40.0),
            Vec3::new(50.0, 50.0, 0.0),
            Vec3::new(-600.0, 500.0, 300.0),
            Vec3::new(-600.0, 500.0, 420.0),
        ];
        for (w, h) in [(1920.0, 1080.0), (800.0, 900.0), (400.0, 300.0)] {
            for preset in [Preset::Iso, Preset::Front, Preset::Top] {
                let mut cam = camera(preset);
                cam.frame(&points, w / h, 1.0);
                for p in points {
                    let (x, y) = project_to_css(&cam.view_proj(w / h), p, w, h).expect("in front of the eye");
                    assert!((0.0..=w).contains(&x) && (0.0..=h).contains(&y), "{p} at ({x}, {y}) in {w}×{h}");
                }
            }
        }
        let mut cam = camera(Preset::Iso);
        cam.frame(&[], 1.0, 1.0);
        assert_eq!(cam, camera(Preset::Iso), "nothing to frame: the camera stays");
    }

    #[test]
    fn points_behind_the_eye_are_not_projected() {
        let c = camera(Preset::Front);
        assert!(project_to_css(&c.view_proj(1.0), c.eye() * 2.0, 100.0, 100.0).is_none());
    }
}
