//! `f64` → text with a fixed number of decimals, the same bytes as `format!("{:.d$}")` and
//! `format!("{:+.d$}")`, without the standard library's exact formatter on the common path.
//!
//! The standard formatter works on big integers (`flt2dec`, Dragon) whenever the precision is
//! given: a 100,000-block `schwenkbar run` spent a third of its time there. Here the value is
//! scaled by 10^d once; `mul_add` gives the multiplication's exact error, so value × 10^d is
//! known exactly as the sum `r + err` of two doubles, which decides the rounding — including
//! an exact tie, rounded half to even as the standard library does (it rounds the exact binary
//! value). Values whose scaled magnitude is not below 2^52, and more than 15 decimals, take
//! the standard formatter.

use std::fmt::Write;

/// Largest scaled magnitude handled here: below 2^52 `floor` and the fraction are exact.
const LIMIT: f64 = 4_503_599_627_370_496.0;

/// Appends `value` with exactly `decimals` places, as `write!(out, "{value:.decimals$}")`
/// (with `plus`: `{value:+.decimals$}`) would. A negative value that rounds to zero keeps its
/// sign (`-0.0000`), as the standard library writes it.
pub fn write_fixed(out: &mut String, value: f64, decimals: usize, plus: bool) {
    let mut buf = [0; FIXED_MAX];
    match fixed_ascii(&mut buf, value, decimals, plus) {
        Some(text) => out.extend(text.iter().map(|&b| char::from(b))),
        // NaN, infinities, huge values, many decimals: rare, and the standard formatter is exact.
        None => {
            let _ = if plus { write!(out, "{value:+.decimals$}") } else { write!(out, "{value:.decimals$}") };
        }
    }
}

/// Room for the longest text [`fixed_ascii`] writes: 16 integer digits (n < 2^53), 15
/// decimals, the point and the sign.
pub const FIXED_MAX: usize = 34;

/// [`write_fixed`]'s text as ASCII bytes at the end of `buf`, or `None` where the standard
/// formatter must write it (NaN, infinities, a scaled magnitude of 2^52 or more, more than 15
/// decimals). For a writer that pads the number (a table column) without a second pass.
pub fn fixed_ascii(buf: &mut [u8; FIXED_MAX], value: f64, decimals: usize, plus: bool) -> Option<&[u8]> {
    let scale = match decimals {
        0..=15 => 10f64.powi(decimals as i32),
        _ => f64::INFINITY,
    };
    let a = value.abs();
    let r = a * scale;
    if r.is_nan() || r >= LIMIT {
        return None;
    }
    // a × scale = r + err exactly (scale = 10^d ≤ 10^15 is exact, and so is an FMA's residue).
    let err = a.mul_add(scale, -r);
    // 0 ≤ r < 2^52: the cast truncates to floor(r) exactly, without a call to libm's `floor`.
    let whole = r as u64;
    // frac − 0.5 is exact for frac ∈ [0.25, 1) (Sterbenz); below that it is far from 0 anyway.
    let above_half = (r - whole as f64) - 0.5;
    let up = above_half > -err || (above_half == -err && whole % 2 == 1);
    // Below 2^52 + 1: fits u64 exactly.
    let n = whole + u64::from(up);
    // Written backwards: the decimals, the point, then the integer digits (at least one).
    let (mut i, mut m, mut k) = (buf.len(), n, 0);
    loop {
        if k == decimals && decimals > 0 {
            i -= 1;
            buf[i] = b'.';
        }
        i -= 1;
        buf[i] = b'0' + (m % 10) as u8;
        m /= 10;
        k += 1;
        if k > decimals && m == 0 {
            break;
        }
    }
    if value.is_sign_negative() {
        i -= 1;
        buf[i] = b'-';
    } else if plus {
        i -= 1;
        buf[i] = b'+';
    }
    Some(&buf[i..])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(value: f64, decimals: usize) {
        for plus in [false, true] {
            let mut ours = String::new();
            write_fixed(&mut ours, value, decimals, plus);
            let std = if plus { format!("{value:+.decimals$}") } else { format!("{value:.decimals$}") };
            assert_eq!(ours, std, "{value:e} ({:#x}) with {decimals} decimals", value.to_bits());
        }
    }

    /// A small deterministic generator (xorshift), so a failure names its case.
    fn xorshift(state: &mut u64) -> u64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        *state
    }

    #[test]
    fn edge_values_are_written_as_the_standard_library_writes_them() {
        let values = [
            0.0,
            -0.0,
            0.5,
            1.5,
            2.5,
            -2.5,
            0.125,
            0.375,
            -0.625,
            1.03125,
            0.05,
            0.15,
            0.25,
            0.35,
            0.45,
            1e-5,
            -1e-5,
            0.000_05,
            -0.000_05,
            0.000_15,
            0.999_95,
            9.999_95,
            99.999_949_999,
            359.999_99,
            -359.999_99,
            123_456_789.123_45,
            4.5e15,
            4.503_599_627_370_495e15,
            9.007_199_254_740_993e15,
            1e16,
            1e300,
            5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for v in values {
            for d in 0..=17 {
                check(v, d);
            }
        }
    }

    #[test]
    fn exact_ties_round_half_to_even_like_the_standard_library() {
        // k / 2^m is exact in binary; with m ≤ d its decimal expansion ends at the d-th place,
        // with m = d + 1 … it sits exactly or nearly on a half.
        for d in 0..=6usize {
            for m in 1..=12 {
                for k in 0..2000u32 {
                    let v = f64::from(k) / f64::from(1u32 << m);
                    check(v, d);
                    check(-v, d);
                }
            }
        }
    }

    #[test]
    fn random_values_and_decimals_match_the_standard_library() {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..300_000 {
            let bits = xorshift(&mut s);
            // Magnitudes 1e-8 … 1e12 (most of them), and any bit pattern now and then.
            let v = if bits % 16 == 0 {
                f64::from_bits(bits)
            } else {
                let mantissa = (bits >> 11) as f64 / (1u64 << 53) as f64;
                let exp = (bits % 21) as i32 - 8;
                let v = mantissa * 10f64.powi(exp);
                if bits & 1 == 1 { -v } else { v }
            };
            check(v, (xorshift(&mut s) % 10) as usize);
        }
    }

    #[test]
    fn decimals_of_nc_figures_match_the_standard_library() {
        // What programs and the display hold: up to 4 decimals, typed, then scaled and summed.
        for i in -200_000..200_000i64 {
            let v = i as f64 / 10_000.0;
            for d in [0, 1, 2, 3, 4, 5] {
                check(v, d);
            }
            check(v * 0.1 + 1e-9, 4);
            check(v * 3.0, 3);
        }
    }
}
