//! Degree helpers shared by the orientation maths, the kinematics and the solver.
//!
//! The control works in degrees throughout (DOMAIN.md §2: "all right-handed, degrees"); glam
//! works in radians, so every conversion goes through here.

/// Wraps an angle in degrees into (−180, +180], the way the seed writes axis positions
/// (`C-90`, never `C+270`; DOMAIN.md §10 oracles 13–27).
#[must_use]
pub fn wrap180(deg: f64) -> f64 {
    let r = deg.rem_euclid(360.0);
    if r > 180.0 { r - 360.0 } else { r }
}

/// Wraps an angle in degrees into [0, 360), the range of `EULROT` and `ROT` (DOMAIN.md §5).
#[must_use]
pub fn wrap360(deg: f64) -> f64 {
    let r = deg.rem_euclid(360.0);
    // rem_euclid can round up to exactly 360.0 for tiny negative inputs.
    if r >= 360.0 { 0.0 } else { r }
}

/// Signed shortest difference `to − from` in degrees, in (−180, +180] (derived: modulo travel).
#[must_use]
pub fn short_delta(from: f64, to: f64) -> f64 {
    wrap180(to - from)
}

/// `atan2` in degrees.
#[must_use]
pub fn atan2d(y: f64, x: f64) -> f64 {
    y.atan2(x).to_degrees()
}

/// `acos` in degrees with the argument clamped to [−1, 1] so rounding never yields NaN.
#[must_use]
pub fn acosd(x: f64) -> f64 {
    x.clamp(-1.0, 1.0).acos().to_degrees()
}

/// Snaps values within 1e-12 of zero to +0.0 so `-0` never reaches the JSON or the UI.
#[must_use]
pub fn clean(x: f64) -> f64 {
    if x.abs() < 1e-12 { 0.0 } else { x }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps() {
        assert_eq!(wrap180(270.0), -90.0);
        assert_eq!(wrap180(-180.0), 180.0);
        assert_eq!(wrap180(180.0), 180.0);
        assert_eq!(wrap180(-190.0), 170.0);
        assert_eq!(wrap360(-90.0), 270.0);
        assert_eq!(wrap360(360.0), 0.0);
        assert_eq!(short_delta(-105.0, 90.0), -165.0);
        assert_eq!(clean(-1e-15), 0.0);
    }
}
