//! Degree helpers shared by the orientation maths, the kinematics and the solver.
//!
//! The control works in degrees throughout (DOMAIN.md §2: "all right-handed, degrees"); glam
//! works in radians, so every conversion goes through here.

/// Below this (relative) length a vector counts as zero, and below this sine two directions
/// count as parallel. Numerical choice (derived): NC input has at most 7 decimals.
pub const PARALLEL_EPS: f64 = 1e-9;

/// Wraps an angle in degrees into (−180, +180], the way the seed writes axis positions
/// (`C-90`, never `C+270`; DOMAIN.md §10 oracles 13–27).
#[must_use]
pub fn wrap180(deg: f64) -> f64 {
    let r = rem360(deg);
    if r > 180.0 { r - 360.0 } else { r }
}

/// Wraps an angle in degrees into [0, 360), the range of `EULROT` and `ROT` (DOMAIN.md §5).
#[must_use]
pub fn wrap360(deg: f64) -> f64 {
    let r = rem360(deg);
    // rem_euclid can round up to exactly 360.0 for tiny negative inputs.
    if r >= 360.0 { 0.0 } else { r }
}

/// `deg.rem_euclid(360.0)` bit for bit, without its `fmod` for |deg| < 360, where `fmod` returns
/// `deg` exactly: every solve wraps a dozen angles, and `fmod` was 4 % of its time.
fn rem360(deg: f64) -> f64 {
    if (0.0..360.0).contains(&deg) {
        deg
    } else if deg < 0.0 && deg > -360.0 {
        deg + 360.0
    } else {
        deg.rem_euclid(360.0)
    }
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

    /// The shortcut is `rem_euclid` itself, to the bit (signed zeros, the edges, tiny and huge
    /// values, NaN and infinities included).
    #[test]
    fn rem360_is_rem_euclid_to_the_bit() {
        let same = |x: f64| {
            let (a, b) = (rem360(x), x.rem_euclid(360.0));
            assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()), "{x:e}: {a:e} vs {b:e}");
        };
        let edges =
            [0.0, -0.0, 360.0, -360.0, 180.0, -180.0, 1e-300, -1e-300, 1e-20, -1e-20, 5e-324, -5e-324];
        for x in edges.into_iter().chain([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300]) {
            same(x);
            // The neighbouring doubles (one step of the bit pattern each way, same sign).
            same(f64::from_bits(x.to_bits().wrapping_add(1)));
            same(f64::from_bits(x.to_bits().wrapping_sub(1)));
        }
        // Deterministic spread over ±1e6 and over ±720 (xorshift).
        let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
        for k in 0..200_000 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let u = (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
            same(u * if k % 2 == 0 { 720.0 } else { 1e6 });
        }
    }
}
