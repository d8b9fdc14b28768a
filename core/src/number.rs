//! Decimal text → `f64`, correctly rounded, without the standard library's tables.
//!
//! `str::parse::<f64>` (Eisel–Lemire with a 10 KB table of powers of five, plus a slow path
//! with tables of its own) was about 13 KB gzip of the wasm bundle, as much as the whole
//! parser; the tables are random bits that do not compress. [`parse_f64`] accepts exactly the
//! same text and returns bit-for-bit the same value (round to nearest, ties to even), which a
//! native test checks against the standard library on a million generated inputs and on the
//! hard cases (exact halfway points, subnormals, overflow, thousands of digits). It is fast for
//! what NC programs hold (up to 15 significant digits and 22 decimals, one exact division) and
//! exact but slower (big-integer long division) for anything else.

use std::cmp::Ordering;

mod fixed;

pub use fixed::{FIXED_MAX, fixed_ascii, write_fixed};

/// A number as the control writes it in an NC word (`SPB+45`, `A-12.5`, `X+0.001`): the sign
/// always, at most `decimals` places, trailing zeros dropped, never `-0`. Angles take 4
/// places ([`crate::solve::fmt_deg`]), course values 3. The canonical program formatter
/// ([`crate::format`]) writes the shortest exact form instead, so a program reads back
/// unchanged.
#[must_use]
pub fn signed(value: f64, decimals: usize) -> String {
    let scale = 10f64.powi(i32::try_from(decimals).unwrap_or(i32::MAX));
    // `+ 0.0` turns a rounded `-0` into `+0`.
    let s = format!("{:+.*}", decimals, (value * scale).round() / scale + 0.0);
    let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.') } else { &s };
    if s == "-0" { "+0".to_owned() } else { s.to_owned() }
}

/// A signed number with exactly `decimals` places (`+12.500`, `-0.100`), for columns of
/// figures (the position display); rounds first, so never `-0.000`.
#[must_use]
pub fn signed_fixed(value: f64, decimals: usize) -> String {
    let scale = 10f64.powi(i32::try_from(decimals).unwrap_or(i32::MAX));
    format!("{:+.*}", decimals, (value * scale).round() / scale + 0.0)
}

/// `value` rounded to `decimals` places, `-0` as `+0`: takes float noise (44.99999999999999)
/// out of figures written to JSON or compared as text.
#[must_use]
pub fn tidy(value: f64, decimals: i32) -> f64 {
    let scale = 10f64.powi(decimals);
    (value * scale).round() / scale + 0.0
}

/// A number in running text (a message, the why panel), not in an NC word: with a decimal
/// comma in German ("Weg 105,0°") and a point in English. `decimals` fixes the places; `None`
/// writes the shortest form that reads back exactly (`359.9999`, `-180`). NC words keep the
/// point: that is the control's syntax in both languages.
#[must_use]
pub fn prose(value: f64, decimals: Option<usize>, lang: crate::Lang) -> String {
    let text = match decimals {
        Some(d) => format!("{value:.d$}"),
        None => format!("{value}"),
    };
    localise(text, lang)
}

/// A number already written with a decimal point (`+12.5`), for running text in `lang`.
#[must_use]
pub fn localise(text: String, lang: crate::Lang) -> String {
    match lang {
        crate::Lang::De => text.replace('.', ","),
        crate::Lang::En => text,
    }
}

/// A vector in running text: `(0,2588; 0,0000; 0,9659)` in German (the comma is taken by the
/// decimals), `(0.2588, 0.0000, 0.9659)` in English.
#[must_use]
pub fn prose_vec(v: [f64; 3], decimals: usize, lang: crate::Lang) -> String {
    let sep = match lang {
        crate::Lang::De => "; ",
        crate::Lang::En => ", ",
    };
    let parts: Vec<String> = v.iter().map(|&x| prose(x, Some(decimals), lang)).collect();
    format!("({})", parts.join(sep))
}

/// A number as a person types it into a field: blanks around it, a decimal point or comma
/// (`-12,5`); finite values only.
#[must_use]
pub fn parse_input(text: &str) -> Option<f64> {
    parse_f64(&text.trim().replace(',', ".")).filter(|v| v.is_finite())
}

/// Parses a decimal number as `str::parse::<f64>` does: `[+-]` then `inf`, `infinity` or `nan`
/// (any case), or digits with an optional `.` (at least one digit on either side) and an
/// optional exponent `e`/`E` `[+-]` digits. Overflow gives ±∞, underflow ±0. `None` where the
/// standard library returns an error.
#[must_use]
pub fn parse_f64(s: &str) -> Option<f64> {
    let b = s.as_bytes();
    let (negative, b) = match b.first() {
        Some(b'-') => (true, &b[1..]),
        Some(b'+') => (false, &b[1..]),
        _ => (false, b),
    };
    let v = unsigned(b)?;
    Some(if negative { -v } else { v })
}

/// At most this many significant digits are kept; a longer number keeps a nonzero digit after
/// them for its nonzero rest. Exact, because a point halfway between two f64 has at most 767
/// significant digits, so no rounding boundary lies between the kept digits and the true value.
const MAX_DIGITS: usize = 800;

fn unsigned(b: &[u8]) -> Option<f64> {
    if b.eq_ignore_ascii_case(b"inf") || b.eq_ignore_ascii_case(b"infinity") {
        return Some(f64::INFINITY);
    }
    if b.eq_ignore_ascii_case(b"nan") {
        return Some(f64::NAN);
    }
    // value = D × 10^exp10, where D is the n significant digits (leading zeros dropped) and
    // `d` holds the first 19 of them; nothing is allocated unless the slow path needs it.
    let (mut d, mut n, mut exp10) = (0u64, 0i64, 0i64);
    let (mut any_digit, mut dot) = (false, false);
    let mut i = 0;
    while let Some(&c) = b.get(i) {
        match c {
            b'0'..=b'9' => {
                any_digit = true;
                exp10 -= i64::from(dot);
                if n > 0 || c != b'0' {
                    if n < 19 {
                        d = d * 10 + u64::from(c - b'0');
                    }
                    n += 1;
                }
            }
            b'.' if !dot => dot = true,
            _ => break,
        }
        i += 1;
    }
    if !any_digit {
        return None;
    }
    let mantissa = &b[..i];
    if i < b.len() {
        if b[i] | 0x20 != b'e' {
            return None;
        }
        let rest = &b[i + 1..];
        let (negative, rest) = match rest.first() {
            Some(b'-') => (true, &rest[1..]),
            Some(b'+') => (false, &rest[1..]),
            _ => (false, rest),
        };
        if rest.is_empty() || !rest.iter().all(u8::is_ascii_digit) {
            return None;
        }
        // Saturated: beyond a million the result is 0 or ∞ either way.
        let e = rest.iter().fold(0i64, |e, &d| (e * 10 + i64::from(d - b'0')).min(1_000_000));
        exp10 += if negative { -e } else { e };
    }
    if n == 0 {
        return Some(0.0);
    }
    if n - 1 + exp10 >= 309 {
        // ≥ 1e309 > f64::MAX.
        return Some(f64::INFINITY);
    }
    if n + exp10 < -324 {
        // < 1e-325, below half the smallest subnormal (2.5e-324).
        return Some(0.0);
    }
    if n <= 19 && d <= 1 << 53 && exp10.abs() <= 22 {
        // Clinger's fast path: both operands exact, so the one IEEE operation rounds correctly.
        let p = (0..exp10.abs()).fold(1.0, |p, _| p * 10.0);
        return Some(if exp10 < 0 { d as f64 / p } else { d as f64 * p });
    }
    // The significant digits, at most MAX_DIGITS of them and a 1 for a nonzero rest.
    let mut digits: Vec<u8> =
        mantissa.iter().filter(|c| c.is_ascii_digit()).map(|c| c - b'0').skip_while(|&c| c == 0).collect();
    if digits.len() > MAX_DIGITS {
        let rest_nonzero = digits[MAX_DIGITS..].iter().any(|&c| c != 0);
        exp10 += (digits.len() - MAX_DIGITS) as i64;
        digits.truncate(MAX_DIGITS);
        if rest_nonzero {
            digits.push(1);
            exp10 -= 1;
        }
    }
    while digits.last() == Some(&0) {
        digits.pop();
        exp10 += 1;
    }
    Some(slow(&digits, exp10))
}

/// Exact rounding of digits × 10^exp10 by big-integer long division (|exp10| < 1200 here).
fn slow(digits: &[u8], exp10: i64) -> f64 {
    let mut num = Big::from_digits(digits);
    let mut den = Big(vec![1]);
    if exp10 >= 0 {
        num.mul_pow10(exp10);
    } else {
        den.mul_pow10(-exp10);
    }
    // Binary exponent e with num / (den·2^e) in [2^52, 2^54); not below the subnormal one.
    let mut e = (num.bits() - den.bits() - 53).max(-1074);
    if e < 0 {
        num.shl(-e);
    } else {
        den.shl(e);
    }
    // q = ⌊num / den⌋ < 2^54, bit by bit; `num` ends as the remainder.
    let mut q: u64 = 0;
    let mut d = den.clone();
    d.shl(54);
    for bit in (0..=54).rev() {
        if num.cmp(&d) != Ordering::Less {
            num.sub(&d);
            q |= 1 << bit;
        }
        d.shr1();
    }
    let up = if q >> 53 != 0 {
        // 54 bits: the last one is the halfway bit, the remainder the sticky rest.
        e += 1;
        let half = q & 1 == 1;
        q >>= 1;
        half && (!num.is_zero() || q & 1 == 1)
    } else {
        num.shl(1);
        match num.cmp(&den) {
            Ordering::Greater => true,
            Ordering::Equal => q & 1 == 1,
            Ordering::Less => false,
        }
    };
    q += u64::from(up);
    if q >> 53 != 0 {
        q >>= 1;
        e += 1;
    }
    if q < 1 << 52 {
        // Only at e = −1074: a subnormal (or zero), whose bits are the mantissa.
        return f64::from_bits(q);
    }
    let biased = e + 1075;
    if biased >= 2047 {
        return f64::INFINITY;
    }
    // `biased` is in 1..2047 here (e ≥ −1074), so the cast keeps it.
    f64::from_bits(((biased as u64) << 52) | (q & ((1 << 52) - 1)))
}

/// A natural number in base 2^32, least significant limb first, no leading zero limbs.
#[derive(Clone)]
struct Big(Vec<u32>);

impl Big {
    fn from_digits(digits: &[u8]) -> Big {
        let mut b = Big(Vec::new());
        for chunk in digits.chunks(9) {
            let v = chunk.iter().fold(0u32, |v, &d| v * 10 + u32::from(d));
            b.mul_add(10u32.pow(chunk.len() as u32), v);
        }
        b
    }

    fn mul_add(&mut self, m: u32, a: u32) {
        let mut carry = u64::from(a);
        for limb in &mut self.0 {
            let t = u64::from(*limb) * u64::from(m) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
        if carry != 0 {
            self.0.push(carry as u32);
        }
    }

    fn mul_pow10(&mut self, mut k: i64) {
        while k > 0 {
            let step = k.min(9);
            self.mul_add(10u32.pow(step as u32), 0);
            k -= step;
        }
    }

    fn bits(&self) -> i64 {
        self.0.last().map_or(0, |top| (self.0.len() as i64) * 32 - i64::from(top.leading_zeros()))
    }

    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    fn shl(&mut self, n: i64) {
        let (limbs, bits) = ((n / 32) as usize, (n % 32) as u32);
        if bits != 0 {
            let mut carry = 0;
            for limb in &mut self.0 {
                let t = (u64::from(*limb) << bits) | carry;
                *limb = t as u32;
                carry = t >> 32;
            }
            if carry != 0 {
                self.0.push(carry as u32);
            }
        }
        if !self.0.is_empty() {
            self.0.splice(0..0, std::iter::repeat_n(0, limbs));
        }
    }

    fn shr1(&mut self) {
        let mut carry = 0;
        for limb in self.0.iter_mut().rev() {
            let next = *limb & 1;
            *limb = (*limb >> 1) | (carry << 31);
            carry = next;
        }
        self.trim();
    }

    fn cmp(&self, other: &Big) -> Ordering {
        self.0.len().cmp(&other.0.len()).then_with(|| self.0.iter().rev().cmp(other.0.iter().rev()))
    }

    /// `self -= other`, for `self ≥ other`.
    fn sub(&mut self, other: &Big) {
        let mut borrow = false;
        for (i, limb) in self.0.iter_mut().enumerate() {
            let (t, b1) = limb.overflowing_sub(other.0.get(i).copied().unwrap_or(0));
            let (t, b2) = t.overflowing_sub(u32::from(borrow));
            *limb = t;
            borrow = b1 || b2;
        }
        self.trim();
    }

    fn trim(&mut self) {
        while self.0.last() == Some(&0) {
            self.0.pop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_numbers_are_written_as_the_control_writes_them() {
        assert_eq!(signed(45.0, 4), "+45");
        assert_eq!(signed(-12.5, 4), "-12.5");
        assert_eq!(signed(-0.00001, 4), "+0");
        assert_eq!(signed(0.0001, 3), "+0");
        assert_eq!(signed(359.99999, 4), "+360");
        assert_eq!(signed(1.23456, 3), "+1.235");
        assert_eq!(signed(7.0, 0), "+7");
        assert_eq!(signed_fixed(-0.0004, 3), "+0.000");
        assert_eq!(signed_fixed(12.5, 3), "+12.500");
        assert_eq!(tidy(44.999_999_999_999_99, 10), 45.0);
        assert!(tidy(-1e-12, 9).is_sign_positive());
    }

    #[test]
    fn prose_numbers_take_a_decimal_comma_in_german() {
        use crate::Lang::{De, En};
        assert_eq!(prose(105.0, Some(1), De), "105,0");
        assert_eq!(prose(105.0, Some(1), En), "105.0");
        assert_eq!(prose(-359.9999, None, De), "-359,9999");
        assert_eq!(prose(-180.0, None, En), "-180");
        assert_eq!(prose_vec([0.258_819, 0.0, 0.965_926], 4, De), "(0,2588; 0,0000; 0,9659)");
        assert_eq!(prose_vec([0.258_819, 0.0, 0.965_926], 4, En), "(0.2588, 0.0000, 0.9659)");
    }

    fn same(s: &str) {
        let ours = parse_f64(s);
        let std = s.parse::<f64>().ok();
        match (ours, std) {
            (Some(a), Some(b)) if a.is_nan() && b.is_nan() => {
                assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "{s:?}");
            }
            _ => assert_eq!(ours.map(f64::to_bits), std.map(f64::to_bits), "{s:?}: {ours:?} vs {std:?}"),
        }
    }

    use schwenkbar_testkit::Rng;

    /// Up to `max` random digits.
    fn digits(rng: &mut Rng, out: &mut String, max: u64) {
        for _ in 0..rng.below(max + 1) {
            out.push(char::from(b'0' + rng.below(10) as u8));
        }
    }

    #[test]
    fn grammar_and_special_values_match_the_standard_library() {
        for s in [
            "",
            "+",
            "-",
            ".",
            "+.",
            "-.",
            "e",
            "e5",
            ".e5",
            "1e",
            "1e+",
            "1e-",
            "1.e5",
            ".5",
            "5.",
            "-.5e-1",
            "+5.",
            "0",
            "-0",
            "+0",
            "0.0",
            "-0.000",
            "00",
            "007",
            "1..2",
            "1.2.3",
            "1e5.5",
            "1e5e5",
            " 1",
            "1 ",
            "1_0",
            "+-1",
            "-+1",
            "--1",
            "0x10",
            "1f",
            "inf",
            "-inf",
            "+INF",
            "Infinity",
            "-infinity",
            "infinit",
            "infx",
            "nan",
            "-NaN",
            "+nan",
            "nanx",
            "in",
            "１",
            "1e99999999999999999999",
            "1e-99999999999999999999",
            "0e99999999",
            "-0e-5",
            "1E3",
            "1e+0003",
            "12345678901234567890",
            "9007199254740993",
            "9007199254740992",
            "9007199254740994",
            "9007199254740995",
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "1.7976931348623159e308",
            "2.4703282292062327e-324",
            "2.4703282292062328e-324",
            "4.9406564584124654e-324",
            "2.2250738585072011e-308",
            "2.2250738585072014e-308",
            "1e22",
            "1e23",
            "123456789012345.6789",
            "0.1",
            "0.2",
            "0.3",
            "89.9999",
            "-359.9999",
            "99999.9999",
            "1e-400",
            "-1e400",
            "1e308",
            "1e309",
            "1e-323",
            "1e-324",
        ] {
            same(s);
        }
    }

    #[test]
    fn long_numbers_match_the_standard_library() {
        let ones = "1".repeat(5000);
        let zeros = "0".repeat(5000);
        for s in [
            ones.clone(),
            format!("0.{zeros}{ones}"),
            format!("{zeros}1.5"),
            format!("1.{zeros}1"),
            format!("1.{zeros}"),
            format!("9007199254740993.{zeros}1"),
            format!("9007199254740993.{zeros}"),
            format!("{}e-5000", "9".repeat(5000)),
            format!("{}e-4700", "1".repeat(5000)),
            format!("1{zeros}e-5000"),
        ] {
            same(&s);
        }
    }

    /// The exact decimal value of `(a + b) / 2` for two finite non-negative f64, from their
    /// exact expansions (Rust prints every digit when asked for enough).
    fn exact_mean(a: f64, b: f64) -> String {
        let (x, y) = (format!("{a:.1100}"), format!("{b:.1100}"));
        let (xi, xf) = x.split_once('.').expect("dot");
        let (yi, yf) = y.split_once('.').expect("dot");
        let width = xi.len().max(yi.len());
        let x: Vec<u8> = format!("{xi:0>width$}{xf}").bytes().collect();
        let y: Vec<u8> = format!("{yi:0>width$}{yf}").bytes().collect();
        let mut out = vec![b'0'; x.len()];
        let mut carry = 0;
        for i in (0..x.len()).rev() {
            let s = (x[i] - b'0') + (y[i] - b'0') + carry;
            out[i] = b'0' + s % 10;
            carry = s / 10;
        }
        // Halve, digit by digit from the left (the sum's carry is the first remainder).
        out.push(b'0');
        let mut rem = carry;
        for d in &mut out {
            let v = rem * 10 + (*d - b'0');
            *d = b'0' + v / 2;
            rem = v % 2;
        }
        let mut s = String::from_utf8(out).expect("digits");
        s.insert(width, '.');
        s
    }

    #[test]
    fn halfway_points_and_their_neighbours_match_the_standard_library() {
        let mut rng = Rng(0x5EED_00F6_4F64);
        for i in 0..400 {
            // Every binade, normal and subnormal, near the overflow and at ordinary sizes.
            let bits = match i % 4 {
                0 => rng.next_u64() & 0x7FEF_FFFF_FFFF_FFFF,
                1 => rng.below(1 << 52),
                2 => 0x7FEF_FFFF_FFFF_FFFF - rng.below(1 << 20),
                _ => (rng.below(80) + 1000) << 52 | rng.below(1 << 52),
            };
            let x = f64::from_bits(bits);
            let mid = exact_mean(x, f64::from_bits(bits + 1));
            let trimmed = mid.trim_end_matches('0');
            // Just below the halfway point: one unit less in the last of its 1100+ places.
            let mut below = mid.clone().into_bytes();
            for d in below.iter_mut().rev().filter(|d| **d != b'.') {
                if *d == b'0' {
                    *d = b'9';
                } else {
                    *d -= 1;
                    break;
                }
            }
            same(&format!("{x:.1100}"));
            same(trimmed);
            same(&format!("{trimmed}000001"));
            same(std::str::from_utf8(&below).expect("digits"));
            same(&format!("{x}"));
            same(&format!("{x:e}"));
        }
    }

    #[test]
    fn a_million_generated_numbers_match_the_standard_library() {
        let mut rng = Rng(0x0123_4567_89AB_CDEF);
        let mut s = String::new();
        for _ in 0..1_000_000 {
            s.clear();
            match rng.below(3) {
                0 => s.push('-'),
                1 => s.push('+'),
                _ => {}
            }
            let int = [0, 1, 3, 8, 16, 17, 19, 25][rng.below(8) as usize];
            digits(&mut rng, &mut s, int);
            if rng.below(3) != 0 {
                s.push('.');
                let frac = [0, 2, 4, 7, 15, 22, 30][rng.below(7) as usize];
                digits(&mut rng, &mut s, frac);
            }
            if rng.below(4) == 0 {
                s.push(if rng.below(2) == 0 { 'e' } else { 'E' });
                match rng.below(3) {
                    0 => s.push('-'),
                    1 => s.push('+'),
                    _ => {}
                }
                s.push_str(&rng.below(340).to_string());
            }
            if rng.below(50) == 0 {
                let at = rng.below(s.len() as u64 + 1) as usize;
                s.insert(at, ['x', ' ', '.', 'e', '-', '0'][rng.below(6) as usize]);
            }
            same(&s);
        }
    }
}
