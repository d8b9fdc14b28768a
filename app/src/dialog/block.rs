//! Between the dialog and a PLANE block: a block's values reopened in the dialog, the block
//! as entered, and the plane typed so far for the live preview.

use schwenkbar_core::parse::parse_value;
use schwenkbar_core::plane::{PlaneBlock, PlaneDef, PlaneKind, PlaneSlots, Positioning, Value};

use super::{Dialog, MSG_AXIAL_EMPTY, MSG_CHOOSE_POS, MSG_REQUIRED, Message, PosKind, Step};

impl Dialog {
    /// Reopens an existing block (ENT on a PLANE block): every value filled in, positioned at the
    /// first prompt so the trainee can walk through with ENT.
    #[must_use]
    pub fn reopen(block: &PlaneBlock) -> Dialog {
        let slots = block.def.slots();
        let mut d = Dialog::new(slots.kind);
        d.values = slots.values;
        d.rel_axis = slots.rel_axis;
        d.incremental = slots.incremental;
        match block.positioning {
            Some(Positioning::Move { dist, feed }) => {
                d.positioning = Some(PosKind::Move);
                d.dist = dist;
                d.feed = feed;
            }
            Some(Positioning::Turn { move_back, feed }) => {
                d.positioning = Some(PosKind::Turn);
                d.move_back = move_back;
                d.feed = feed;
            }
            Some(Positioning::Stay) => d.positioning = Some(PosKind::Stay),
            None => {}
        }
        d.selection = block.selection;
        d.transform = block.transform;
        d.input = d.prefill();
        d
    }

    /// The block as entered so far, or what is still missing.
    pub fn block(&self) -> Result<PlaneBlock, Message> {
        let slots = PlaneSlots {
            kind: self.function,
            values: self.values.clone(),
            rel_axis: self.rel_axis,
            incremental: self.incremental,
        };
        let def = slots.def().ok_or(match self.function {
            PlaneKind::Axial => MSG_AXIAL_EMPTY,
            _ => MSG_REQUIRED,
        })?;
        let positioning = match self.positioning.ok_or(MSG_CHOOSE_POS)? {
            PosKind::Move => Positioning::Move { dist: self.dist, feed: self.feed },
            PosKind::Turn => Positioning::Turn { move_back: self.move_back, feed: self.feed },
            PosKind::Stay => Positioning::Stay,
        };
        Ok(PlaneBlock {
            def,
            positioning: Some(positioning),
            selection: self.selection,
            transform: self.transform,
        })
    }

    /// The angles as typed so far (missing ones 0, the current input included if readable):
    /// the live preview of the plane.
    #[must_use]
    pub fn preview(&self) -> Option<PlaneDef<f64>> {
        let number = |v: Option<Value>| match v {
            Some(Value::Number(x)) => x,
            _ => 0.0,
        };
        let typed = parse_value(&self.typed().0);
        let get = |i: usize| {
            if self.step == Step::Value(i) && typed.is_some() {
                number(typed)
            } else {
                number(self.values.get(i).copied().flatten())
            }
        };
        if matches!(self.function, PlaneKind::Axial | PlaneKind::Reset) {
            return None;
        }
        let mut slots = PlaneSlots::new(self.function, self.rel_axis);
        for (i, slot) in slots.values.iter_mut().enumerate() {
            *slot = Some(get(i));
        }
        slots.def()
    }
}
