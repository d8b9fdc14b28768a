//! Between the dialog and a PLANE block: a block's values reopened in the dialog, the block
//! as entered, and the plane typed so far for the live preview.

use schwenkbar_core::parse::parse_value;
use schwenkbar_core::plane::{AxialAngle, PlaneBlock, PlaneDef, Positioning, RotaryAxis, Value};

use super::{Dialog, Function, MSG_AXIAL_EMPTY, MSG_CHOOSE_POS, MSG_REQUIRED, Message, PosKind, Step};

impl Dialog {
    /// Reopens an existing block (ENT on a PLANE block): every value filled in, positioned at the
    /// first prompt so the trainee can walk through with ENT.
    #[must_use]
    pub fn reopen(block: &PlaneBlock) -> Dialog {
        let function = function_of(&block.def);
        let mut d = Dialog::new(function);
        d.values = match &block.def {
            PlaneDef::Spatial { spa, spb, spc } => vec![Some(*spa), Some(*spb), Some(*spc)],
            PlaneDef::Projected { propr, promin, rot } => vec![Some(*propr), Some(*promin), Some(*rot)],
            PlaneDef::Euler { eulpr, eulnu, eulrot } => vec![Some(*eulpr), Some(*eulnu), Some(*eulrot)],
            PlaneDef::Vector { base, normal } => base.iter().chain(normal).map(|v| Some(*v)).collect(),
            PlaneDef::Points { p1, p2, p3 } => p1.iter().chain(p2).chain(p3).map(|v| Some(*v)).collect(),
            PlaneDef::Relativ { axis, angle } => {
                d.rel_axis = *axis;
                vec![Some(*angle)]
            }
            PlaneDef::Axial { axes } => [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]
                .iter()
                .enumerate()
                .map(|(i, letter)| {
                    let angle = axes.iter().find(|a| a.axis == *letter)?;
                    d.incremental[i] = angle.incremental;
                    Some(angle.value)
                })
                .collect(),
            PlaneDef::Reset => Vec::new(),
        };
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
        let v = |i: usize| self.values.get(i).copied().flatten().ok_or(MSG_REQUIRED);
        let def = match self.function {
            Function::Spatial => PlaneDef::Spatial { spa: v(0)?, spb: v(1)?, spc: v(2)? },
            Function::Projected => PlaneDef::Projected { propr: v(0)?, promin: v(1)?, rot: v(2)? },
            Function::Euler => PlaneDef::Euler { eulpr: v(0)?, eulnu: v(1)?, eulrot: v(2)? },
            Function::Vector => {
                PlaneDef::Vector { base: [v(0)?, v(1)?, v(2)?], normal: [v(3)?, v(4)?, v(5)?] }
            }
            Function::Points => PlaneDef::Points {
                p1: [v(0)?, v(1)?, v(2)?],
                p2: [v(3)?, v(4)?, v(5)?],
                p3: [v(6)?, v(7)?, v(8)?],
            },
            Function::Relativ => PlaneDef::Relativ { axis: self.rel_axis, angle: v(0)? },
            Function::Axial => {
                let axes: Vec<AxialAngle> = [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]
                    .into_iter()
                    .enumerate()
                    .filter_map(|(i, axis)| {
                        self.values.get(i).copied().flatten().map(|value| AxialAngle {
                            axis,
                            value,
                            incremental: self.incremental[i],
                        })
                    })
                    .collect();
                if axes.is_empty() {
                    return Err(MSG_AXIAL_EMPTY);
                }
                PlaneDef::Axial { axes }
            }
            Function::Reset => PlaneDef::Reset,
        };
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
        Some(match self.function {
            Function::Spatial => PlaneDef::Spatial { spa: get(0), spb: get(1), spc: get(2) },
            Function::Projected => PlaneDef::Projected { propr: get(0), promin: get(1), rot: get(2) },
            Function::Euler => PlaneDef::Euler { eulpr: get(0), eulnu: get(1), eulrot: get(2) },
            Function::Relativ => PlaneDef::Relativ { axis: self.rel_axis, angle: get(0) },
            Function::Vector => {
                PlaneDef::Vector { base: [get(0), get(1), get(2)], normal: [get(3), get(4), get(5)] }
            }
            Function::Points => PlaneDef::Points {
                p1: [get(0), get(1), get(2)],
                p2: [get(3), get(4), get(5)],
                p3: [get(6), get(7), get(8)],
            },
            Function::Axial | Function::Reset => return None,
        })
    }
}

fn function_of(def: &PlaneDef) -> Function {
    match def {
        PlaneDef::Spatial { .. } => Function::Spatial,
        PlaneDef::Projected { .. } => Function::Projected,
        PlaneDef::Euler { .. } => Function::Euler,
        PlaneDef::Vector { .. } => Function::Vector,
        PlaneDef::Points { .. } => Function::Points,
        PlaneDef::Relativ { .. } => Function::Relativ,
        PlaneDef::Axial { .. } => Function::Axial,
        PlaneDef::Reset => Function::Reset,
    }
}
