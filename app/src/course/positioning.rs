//! Lesson 4's comparison: the same PLANE block with MOVE, TURN and STAY, each program simulated
//! on the A/C table, and the state just before that block (from where its swivel is animated).

use std::rc::Rc;

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::State;

use crate::document::Document;
use crate::run::SimRef;

/// The machine the three panes share.
pub const MACHINE: &str = "ac-table";

/// One pane: its program, simulation and the state after the PLANE block.
#[derive(Debug, Clone, PartialEq)]
pub struct Pane {
    pub name: &'static str,
    pub doc: Rc<Document>,
    pub sim: Option<SimRef>,
    pub state: Option<Rc<State>>,
}

/// The three panes for `programs` (MOVE, TURN, STAY) before their simulation: the programs
/// read, the machine standing at home (the lesson's first screen, shown before the
/// simulator's code has loaded).
#[must_use]
pub fn unsimulated(programs: [&str; 3]) -> (Option<Rc<Machine>>, Vec<Pane>) {
    let machine = Machine::builtin(MACHINE).ok().map(Rc::new);
    let panes = programs
        .iter()
        .zip(["MOVE", "TURN", "STAY"])
        .map(|(text, name)| Pane {
            name,
            doc: Rc::new(Document::new((*text).to_owned())),
            sim: None,
            state: None,
        })
        .collect();
    (machine, panes)
}

/// The three panes for `programs` (MOVE, TURN, STAY) at the block numbered `block`.
#[must_use]
pub fn panes(programs: [&str; 3], block: u32) -> (Option<Rc<Machine>>, Vec<Pane>) {
    let (machine, mut panes) = unsimulated(programs);
    for pane in &mut panes {
        let program = &pane.doc.program;
        pane.sim = machine.as_ref().map(|m| SimRef::of(program, m));
        let index = program.blocks.iter().position(|b| b.number() == Some(block));
        pane.state = pane
            .sim
            .as_ref()
            .zip(index)
            .and_then(|(s, i)| s.0.state_at(program, s.0.step_of_block(i)?).map(Rc::new));
    }
    (machine, panes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::course::lessons::{self, Widget};

    #[test]
    fn lesson_4s_panes_swivel_move_and_turn_but_stay_keeps_the_axes() {
        let lesson = lessons::lesson(3).expect("lesson 4");
        let Widget::Positioning { programs, block } = lesson.widget else {
            panic!("lesson 4 compares MOVE/TURN/STAY")
        };
        let (machine, panes) = panes(programs, block);
        assert!(machine.is_some());
        let rotary = |p: &Pane| p.state.as_ref().map(|s| s.axes.rotary).expect("state after the PLANE block");
        let names: Vec<_> = panes.iter().map(|p| p.name).collect();
        assert_eq!(names, ["MOVE", "TURN", "STAY"]);
        assert_eq!(rotary(&panes[0]), rotary(&panes[1]), "MOVE and TURN end on the same axes");
        assert_ne!(rotary(&panes[0]), [0.0, 0.0], "MOVE swivels");
        assert_eq!(rotary(&panes[2]), [0.0, 0.0], "STAY does not swivel");
        let (_, first) = unsimulated(programs);
        assert!(first.iter().all(|p| p.sim.is_none() && p.state.is_none()));
        assert!(first.iter().zip(&panes).all(|(a, b)| a.doc == b.doc && a.name == b.name));
    }
}
