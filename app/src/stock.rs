//! The stock in the 3D view (issue 14): the run's cuts ([`Cutting`]) made once per simulation
//! when the stock is shown, and the stock's mesh at any step and fraction of that step's motion.
//! A cursor moves forward by cutting only what is new (back from a checkpoint), and the mesh is
//! made again only when the stock changed, so an animation frame that cuts nothing costs nothing.

use std::cell::RefCell;
use std::rc::Rc;

use schwenkbar_core::Program;
use schwenkbar_core::stock::{Cutting, StockCursor, StockMesh, StockOptions};

use crate::i18n::Text;
use crate::run::SimRef;

/// Stages of a block's motion at which the animated stock is cut and meshed again: a new mesh of
/// Musterprogramm 1's milled face costs about 30 ms natively (320,000 triangles), far more than
/// a frame, so the stock follows the tool in quarters of the block, not every frame.
pub const STAGES: f64 = 4.0;

/// A mesh and the cursor version it shows.
type Meshed = (u64, Rc<StockMesh>);

/// The cuts of one simulation and where the view stands in them.
pub struct StockView {
    sim: SimRef,
    cutting: Cutting,
    /// The cursor and the mesh of its stock (with the cursor's version when it was made).
    at: RefCell<(StockCursor, Option<Meshed>)>,
}

/// The stock of the current simulation, shared and compared by identity.
#[derive(Clone)]
pub struct StockRef(pub Rc<StockView>);

impl PartialEq for StockRef {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0)
    }
}

impl std::fmt::Debug for StockRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("StockRef")
    }
}

impl StockRef {
    /// Cuts the whole run of `sim` once (about a second in the browser for Musterprogramm 1).
    #[must_use]
    pub fn of(sim: &SimRef, program: &Program) -> StockRef {
        let cutting = Cutting::new(program, &sim.0, StockOptions::default());
        StockRef(Rc::new(StockView {
            sim: sim.clone(),
            cutting,
            at: RefCell::new((StockCursor::default(), None)),
        }))
    }

    /// Whether this is the stock of `sim`.
    #[must_use]
    pub fn is_for(&self, sim: &SimRef) -> bool {
        self.0.sim == *sim
    }

    /// The stock's mesh (W-CS) after `fraction` (0…1) of step `step`'s motion, which it
    /// follows in [`STAGES`] steps; the same `Rc` as long as the stock did not change. `None`
    /// before a `BLK FORM`.
    #[must_use]
    pub fn mesh_at(&self, step: usize, fraction: f64) -> Option<Rc<StockMesh>> {
        let mut at = self.0.at.borrow_mut();
        let (cursor, mesh) = &mut *at;
        let staged = (fraction.clamp(0.0, 1.0) * STAGES).floor() / STAGES;
        self.0.cutting.seek(cursor, step, staged);
        let stock = cursor.stock.as_ref()?;
        match mesh {
            Some((version, m)) if *version == cursor.version => Some(m.clone()),
            _ => {
                let m = Rc::new(StockMesh::of(stock));
                *mesh = Some((cursor.version, m.clone()));
                Some(m)
            }
        }
    }

    /// What the stock says about step `step` (a rapid into the material), German and English.
    #[must_use]
    pub fn notes_at(&self, step: usize) -> Option<Text> {
        let mut notes = self.0.cutting.notes_at(step).map(|n| n.message());
        let first = notes.next()?;
        Some(
            notes.fold(first, |a, b| {
                Text::owned(format!("{}; {}", a.de, b.de), format!("{}; {}", a.en, b.en))
            }),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::document::Document;
    use schwenkbar_core::machine::Machine;

    fn musterprogramm1() -> (Document, SimRef) {
        let doc = Document::new(crate::samples::MUSTERPROGRAMM_1.text.to_owned());
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine);
        (doc, sim)
    }

    fn step_of(doc: &Document, sim: &SimRef, number: u32) -> usize {
        let block = doc.program.blocks.iter().position(|b| b.number == Some(number)).expect("block");
        sim.0.step_of_block(block).expect("executed")
    }

    /// Cut faces of a mesh (flag bit 3, `stock::mesh::flag::CUT`), as triangles.
    fn cut_triangles(m: &StockMesh) -> usize {
        m.flags.iter().step_by(3).filter(|f| **f & 0b1000 != 0).count()
    }

    #[test]
    fn block_13_mills_the_face_and_the_mesh_is_made_again_only_when_the_stock_changed() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc.program);
        assert!(stock.is_for(&sim));
        let (before, after) = (step_of(&doc, &sim, 13) - 1, step_of(&doc, &sim, 13));
        let m0 = stock.mesh_at(before, 1.0).expect("a blank");
        assert_eq!(cut_triangles(&m0), 0, "nothing cut before block 13");
        assert!(Rc::ptr_eq(&m0, &stock.mesh_at(before, 1.0).expect("same")), "no new mesh");
        let half = stock.mesh_at(after, 0.6).expect("stock");
        assert!(Rc::ptr_eq(&half, &stock.mesh_at(after, 0.7).expect("stock")), "same stage, same mesh");
        let m1 = stock.mesh_at(after, 1.0).expect("stock");
        assert!(cut_triangles(&half) > 0 && cut_triangles(&m1) > cut_triangles(&half) / 2);
        assert!(!Rc::ptr_eq(&m0, &m1));
        // Back again: the same stock as before.
        assert_eq!(*stock.mesh_at(before, 1.0).expect("stock"), *m0);
    }

    #[test]
    fn the_stock_before_the_blk_form_is_none_and_notes_are_worded_in_both_languages() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc.program);
        assert!(stock.mesh_at(0, 1.0).is_none(), "BEGIN PGM: no blank yet");
        let (p, _) = schwenkbar_core::parse(
            "0 BEGIN PGM R MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 16 Z S5000\n4 L X+50 Y+50 Z+50 R0 FMAX\n5 L Z-5 R0 FMAX\n6 END PGM R MM\n",
        );
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&p, &machine);
        let stock = StockRef::of(&sim, &p);
        let step = sim.0.step_of_block(5).expect("executed");
        let note = stock.notes_at(step).expect("rapid into the material");
        assert_eq!(note.de, "Eilgang ins Material");
        assert!(stock.notes_at(step - 1).is_none());
    }
}
