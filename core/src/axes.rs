//! Rotary axis positions keyed by letter, as the control names them (`A+45 C+90`).

use serde::{Deserialize, Serialize};

use crate::plane::RotaryAxis;

/// A value per rotary axis letter; `None` = the axis is not part of it (not on the machine,
/// or not programmed). Serialises as `{"A": 45.0, "C": 90.0}` (absent axes left out).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct AxisValues {
    #[serde(rename = "A", default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    #[serde(rename = "B", default, skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(rename = "C", default, skip_serializing_if = "Option::is_none")]
    pub c: Option<f64>,
}

impl AxisValues {
    /// The value of one axis.
    #[must_use]
    pub fn get(&self, axis: RotaryAxis) -> Option<f64> {
        match axis {
            RotaryAxis::A => self.a,
            RotaryAxis::B => self.b,
            RotaryAxis::C => self.c,
        }
    }

    /// Sets one axis.
    pub fn set(&mut self, axis: RotaryAxis, value: f64) {
        *self.slot(axis) = Some(value);
    }

    /// Builder form of [`AxisValues::set`].
    #[must_use]
    pub fn with(mut self, axis: RotaryAxis, value: f64) -> Self {
        self.set(axis, value);
        self
    }

    fn slot(&mut self, axis: RotaryAxis) -> &mut Option<f64> {
        match axis {
            RotaryAxis::A => &mut self.a,
            RotaryAxis::B => &mut self.b,
            RotaryAxis::C => &mut self.c,
        }
    }

    /// `(axis, value)` for every axis present, in the order A, B, C.
    pub fn iter(&self) -> impl Iterator<Item = (RotaryAxis, f64)> + '_ {
        [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]
            .into_iter()
            .filter_map(|ax| self.get(ax).map(|v| (ax, v)))
    }
}

impl RotaryAxis {
    /// The letter as the control writes it.
    #[must_use]
    pub fn letter(self) -> char {
        match self {
            RotaryAxis::A => 'A',
            RotaryAxis::B => 'B',
            RotaryAxis::C => 'C',
        }
    }

    /// The letter back to an axis (upper or lower case).
    #[must_use]
    pub fn from_letter(letter: &str) -> Option<RotaryAxis> {
        match letter {
            "A" | "a" => Some(RotaryAxis::A),
            "B" | "b" => Some(RotaryAxis::B),
            "C" | "c" => Some(RotaryAxis::C),
            _ => None,
        }
    }
}

impl std::fmt::Display for RotaryAxis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.letter())
    }
}
