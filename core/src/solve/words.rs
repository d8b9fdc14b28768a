//! Axis values and options written as the control writes them (`A-45`, `C+90`, `SEQ−`).

use crate::axes::AxisValues;
use crate::plane::{RotaryAxis, Selection, Sign};

/// `A-45`, `C+90`, `A+12.5` (control style, up to 4 decimals).
#[must_use]
pub fn axis_word(axis: RotaryAxis, value: f64) -> String {
    format!("{axis}{}", fmt_deg(value))
}

/// `A+45 C+90`: every axis present, in the order A, B, C.
#[must_use]
pub fn axis_words(axes: &AxisValues) -> String {
    axes.iter().map(|(ax, v)| axis_word(ax, v)).collect::<Vec<_>>().join(" ")
}

/// A signed angle with up to 4 decimals, trailing zeros dropped: `+90`, `-45`, `+12.5`.
#[must_use]
pub fn fmt_deg(value: f64) -> String {
    crate::number::signed(value, 4)
}

pub(super) fn selection_word(sel: Selection) -> String {
    match sel {
        Selection::Seq(s) => format!("SEQ{}", sign_char(s)),
        Selection::Sym(s) => format!("SYM{}", sign_char(s)),
    }
}

pub(super) fn sign_char(s: Sign) -> char {
    match s {
        Sign::Plus => '+',
        Sign::Minus => '−',
    }
}
