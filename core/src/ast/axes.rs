//! The axes a path block names and its axis words (`X+10`, `IX-5`, `A+Q120`).

use std::fmt;

use serde::Serialize;

use crate::plane::Value;

/// Linear and rotary axis letters as written in path blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum Axis {
    X,
    Y,
    Z,
    A,
    B,
    C,
    U,
    V,
    W,
}

impl Axis {
    /// All axes in the order the control writes them.
    pub const ALL: [Axis; 9] =
        [Axis::X, Axis::Y, Axis::Z, Axis::A, Axis::B, Axis::C, Axis::U, Axis::V, Axis::W];

    #[must_use]
    pub fn from_byte(b: u8) -> Option<Axis> {
        Some(match b {
            b'X' => Axis::X,
            b'Y' => Axis::Y,
            b'Z' => Axis::Z,
            b'A' => Axis::A,
            b'B' => Axis::B,
            b'C' => Axis::C,
            b'U' => Axis::U,
            b'V' => Axis::V,
            b'W' => Axis::W,
            _ => return None,
        })
    }

    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Axis::X => "X",
            Axis::Y => "Y",
            Axis::Z => "Z",
            Axis::A => "A",
            Axis::B => "B",
            Axis::C => "C",
            Axis::U => "U",
            Axis::V => "V",
            Axis::W => "W",
        }
    }
}

/// `X+10`, `IX-5`, `A+Q120`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxisWord {
    pub axis: Axis,
    pub value: Value,
    /// Written with a leading `I` (incremental).
    pub incremental: bool,
}

/// The axis words of a path block: up to three inline (a straight line is usually `X Y Z`), more
/// on the heap. Reads as a slice.
#[derive(Clone)]
pub struct AxisWords(Words);

#[derive(Clone)]
enum Words {
    Inline { len: u8, words: [AxisWord; 3] },
    Heap(Box<[AxisWord]>),
}

impl Default for AxisWords {
    fn default() -> Self {
        let none = AxisWord { axis: Axis::X, value: Value::Number(0.0), incremental: false };
        AxisWords(Words::Inline { len: 0, words: [none; 3] })
    }
}

impl AxisWords {
    /// Appends inline; only called with room left (at most three words).
    pub(super) fn push(&mut self, word: AxisWord) {
        if let Words::Inline { len, words } = &mut self.0
            && let Some(slot) = words.get_mut(usize::from(*len))
        {
            *slot = word;
            *len += 1;
        }
    }
}

impl From<&[AxisWord]> for AxisWords {
    fn from(words: &[AxisWord]) -> Self {
        if words.len() <= 3 {
            let mut inline = AxisWords::default();
            words.iter().for_each(|&w| inline.push(w));
            inline
        } else {
            AxisWords(Words::Heap(words.into()))
        }
    }
}

impl From<Vec<AxisWord>> for AxisWords {
    fn from(words: Vec<AxisWord>) -> Self {
        AxisWords::from(&words[..])
    }
}

impl std::ops::Deref for AxisWords {
    type Target = [AxisWord];

    fn deref(&self) -> &[AxisWord] {
        match &self.0 {
            Words::Inline { len, words } => &words[..usize::from(*len)],
            Words::Heap(words) => words,
        }
    }
}

impl PartialEq for AxisWords {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl fmt::Debug for AxisWords {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        (**self).fmt(f)
    }
}

impl Serialize for AxisWords {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        (**self).serialize(ser)
    }
}
