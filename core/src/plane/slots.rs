//! Which PLANE function a definition is and its values as the dialog holds them: one slot per
//! prompt ([`PlaneSlots`]), converted both ways with [`PlaneDef`], so the flattening is written once.

use serde::{Deserialize, Serialize};

use super::{AxialAngle, PlaneDef, RelAxis, RotaryAxis, Value, Word};

/// Which PLANE function a definition uses (the softkey of the dialog).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum PlaneKind {
    Spatial,
    Projected,
    Euler,
    Vector,
    Points,
    Relativ,
    Axial,
    Reset,
}

impl PlaneKind {
    /// The eight functions in the order of the control's softkey row.
    pub const ALL: [PlaneKind; 8] = [
        PlaneKind::Spatial,
        PlaneKind::Projected,
        PlaneKind::Euler,
        PlaneKind::Vector,
        PlaneKind::Points,
        PlaneKind::Relativ,
        PlaneKind::Axial,
        PlaneKind::Reset,
    ];

    /// The word after `PLANE` (`SPATIAL`, `RELATIV`).
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            PlaneKind::Spatial => "SPATIAL",
            PlaneKind::Projected => "PROJECTED",
            PlaneKind::Euler => "EULER",
            PlaneKind::Vector => "VECTOR",
            PlaneKind::Points => "POINTS",
            PlaneKind::Relativ => "RELATIV",
            PlaneKind::Axial => "AXIAL",
            PlaneKind::Reset => "RESET",
        }
    }

    /// The words the dialog asks for, in the control's order (one slot each, see
    /// [`PlaneSlots`]). RELATIV asks for one angle, written with the chosen axis (`rel_axis`);
    /// AXIAL has a slot for each of A, B, C.
    #[must_use]
    pub fn words(self, rel_axis: RelAxis) -> &'static [Word] {
        use Word::*;
        match self {
            PlaneKind::Spatial => &[Spa, Spb, Spc],
            PlaneKind::Projected => &[Propr, Promin, Rot],
            PlaneKind::Euler => &[Eulpr, Eulnu, Eulrot],
            PlaneKind::Vector => &[Bx, By, Bz, Nx, Ny, Nz],
            PlaneKind::Points => &[P1x, P1y, P1z, P2x, P2y, P2z, P3x, P3y, P3z],
            PlaneKind::Relativ => match rel_axis {
                RelAxis::Spa => &[Spa],
                RelAxis::Spb => &[Spb],
                RelAxis::Spc => &[Spc],
            },
            PlaneKind::Axial => &[A, B, C],
            PlaneKind::Reset => &[],
        }
    }
}

/// A PLANE definition as the dialog holds it: one optional value per prompt of its kind
/// ([`PlaneKind::words`]), the RELATIV axis and the AXIAL increments. [`PlaneDef::slots`] and
/// [`PlaneSlots::def`] convert both ways, so the flattening is written once.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneSlots<V = Value> {
    pub kind: PlaneKind,
    /// In the order of [`PlaneKind::words`]; AXIAL: A, B, C, `None` where not programmed.
    pub values: Vec<Option<V>>,
    /// RELATIV: its axis (`Spa` otherwise).
    pub rel_axis: RelAxis,
    /// AXIAL: `IA`, `IB`, `IC` (incremental) per slot.
    pub incremental: [bool; 3],
}

impl<V: Clone> PlaneSlots<V> {
    /// Empty slots of `kind`.
    #[must_use]
    pub fn new(kind: PlaneKind, rel_axis: RelAxis) -> Self {
        let values = vec![None; kind.words(rel_axis).len()];
        PlaneSlots { kind, values, rel_axis, incremental: [false; 3] }
    }

    /// The definition, or `None` while a mandatory value is missing (AXIAL: while all three are).
    #[must_use]
    pub fn def(&self) -> Option<PlaneDef<V>> {
        let v = |i: usize| self.values.get(i).cloned().flatten();
        let v3 = |i: usize| Some([v(i)?, v(i + 1)?, v(i + 2)?]);
        Some(match self.kind {
            PlaneKind::Spatial => PlaneDef::Spatial { spa: v(0)?, spb: v(1)?, spc: v(2)? },
            PlaneKind::Projected => PlaneDef::Projected { propr: v(0)?, promin: v(1)?, rot: v(2)? },
            PlaneKind::Euler => PlaneDef::Euler { eulpr: v(0)?, eulnu: v(1)?, eulrot: v(2)? },
            PlaneKind::Vector => PlaneDef::Vector { base: v3(0)?, normal: v3(3)? },
            PlaneKind::Points => PlaneDef::Points { p1: v3(0)?, p2: v3(3)?, p3: v3(6)? },
            PlaneKind::Relativ => PlaneDef::Relativ { axis: self.rel_axis, angle: v(0)? },
            PlaneKind::Axial => {
                let axes: Vec<AxialAngle<V>> = [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]
                    .into_iter()
                    .enumerate()
                    .filter_map(|(i, axis)| {
                        Some(AxialAngle { axis, value: v(i)?, incremental: self.incremental[i] })
                    })
                    .collect();
                if axes.is_empty() {
                    return None;
                }
                PlaneDef::Axial { axes }
            }
            PlaneKind::Reset => PlaneDef::Reset,
        })
    }
}

impl<V> PlaneDef<V> {
    /// Which PLANE function this is.
    #[must_use]
    pub fn kind(&self) -> PlaneKind {
        match self {
            PlaneDef::Spatial { .. } => PlaneKind::Spatial,
            PlaneDef::Projected { .. } => PlaneKind::Projected,
            PlaneDef::Euler { .. } => PlaneKind::Euler,
            PlaneDef::Vector { .. } => PlaneKind::Vector,
            PlaneDef::Points { .. } => PlaneKind::Points,
            PlaneDef::Relativ { .. } => PlaneKind::Relativ,
            PlaneDef::Axial { .. } => PlaneKind::Axial,
            PlaneDef::Reset => PlaneKind::Reset,
        }
    }

    /// Every value with its word, in the order written (`SPA`, `SPB`, `SPC`; AXIAL: the axes
    /// programmed, as written).
    #[must_use]
    pub fn values(&self) -> Vec<(Word, &V)> {
        let rel = match self {
            PlaneDef::Relativ { axis, .. } => *axis,
            _ => RelAxis::Spa,
        };
        let words = self.kind().words(rel);
        let refs: Vec<&V> = match self {
            PlaneDef::Spatial { spa: a, spb: b, spc: c }
            | PlaneDef::Projected { propr: a, promin: b, rot: c }
            | PlaneDef::Euler { eulpr: a, eulnu: b, eulrot: c } => vec![a, b, c],
            PlaneDef::Vector { base, normal } => base.iter().chain(normal).collect(),
            PlaneDef::Points { p1, p2, p3 } => p1.iter().chain(p2).chain(p3).collect(),
            PlaneDef::Relativ { angle, .. } => vec![angle],
            PlaneDef::Axial { axes } => {
                return axes.iter().map(|a| (a.axis.plane_word(), &a.value)).collect();
            }
            PlaneDef::Reset => Vec::new(),
        };
        words.iter().copied().zip(refs).collect()
    }
}

impl<V: Clone> PlaneDef<V> {
    /// The definition as the dialog's slots (the inverse of [`PlaneSlots::def`]).
    #[must_use]
    pub fn slots(&self) -> PlaneSlots<V> {
        let rel_axis = match self {
            PlaneDef::Relativ { axis, .. } => *axis,
            _ => RelAxis::Spa,
        };
        let mut slots = PlaneSlots::new(self.kind(), rel_axis);
        if let PlaneDef::Axial { axes } = self {
            for a in axes {
                let i = a.axis as usize;
                slots.values[i] = Some(a.value.clone());
                slots.incremental[i] = a.incremental;
            }
        } else {
            slots.values = self.values().into_iter().map(|(_, v)| Some(v.clone())).collect();
        }
        slots
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::plane_block;

    #[test]
    fn slots_and_values_round_trip_every_kind() {
        for text in [
            "PLANE SPATIAL SPA+1 SPB+2 SPC+3 STAY",
            "PLANE PROJECTED PROPR+1 PROMIN+2 ROT+3 STAY",
            "PLANE EULER EULPR+1 EULNU+2 EULROT+3 STAY",
            "PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+1 STAY",
            "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+1 P2Y+0 P2Z+0 P3X+0 P3Y+1 P3Z+0 STAY",
            "PLANE RELATIV SPB+10 STAY",
            "PLANE AXIAL IC+5 A+10 STAY",
            "PLANE RESET STAY",
        ] {
            let def = plane_block(text).expect(text).def;
            let slots = def.slots();
            assert_eq!(slots.kind, def.kind());
            assert_eq!(slots.values.len(), slots.kind.words(slots.rel_axis).len(), "{text}");
            if def.kind() != PlaneKind::Axial {
                assert_eq!(slots.def().as_ref(), Some(&def), "{text}");
            }
            assert!(text.contains(def.kind().as_str()));
            for (word, _) in def.values() {
                assert!(text.contains(word.as_str()), "{text}: {word}");
            }
        }
        // AXIAL slots are A, B, C whatever the order written; `def` writes them in that order.
        let axial = plane_block("PLANE AXIAL IC+5 A+10 STAY").expect("axial").def;
        let slots = axial.slots();
        assert_eq!(slots.values, vec![Some(Value::Number(10.0)), None, Some(Value::Number(5.0))]);
        assert_eq!(slots.incremental, [false, false, true]);
        let again = slots.def().expect("two axes");
        assert_eq!(again.slots(), slots);
        assert_eq!(PlaneSlots::<f64>::new(PlaneKind::Axial, RelAxis::Spa).def(), None);
        assert_eq!(PlaneSlots::<f64>::new(PlaneKind::Spatial, RelAxis::Spa).def(), None);
    }
}
