//! The stock in the 3D view (issue 14): the run's cuts ([`Cutting`]) made once per simulation
//! when the stock is shown, and the stock's mesh at any step and fraction of that step's motion.
//! Each animation frame cuts at most [`FRAME_RAYS`] rays towards the tool's position (a cut may
//! stop between rows and go on in the next frame) and meshes again only the tiles that changed,
//! so a frame's cost is bounded however big the cut; the view asks for more frames while the
//! stock is behind. A step back is cut from a checkpoint aside and shown once it is there, so
//! the view never flashes an older stock.

use std::cell::RefCell;
use std::rc::Rc;

use glam::DVec3;
use schwenkbar_core::number::{localise, tidy};
use schwenkbar_core::stock::{Cutting, StockCursor, StockOptions, TiledMesh};

use crate::document::Document;
use crate::i18n::{Lang, Text};
use crate::run::SimRef;

/// The cutting work of one animation frame, in rays ([`schwenkbar_core::stock::Removal::work`],
/// meshing included): about 1.5 ms natively and 3 ms in a release wasm build, well inside the issue's
/// 8 ms frame (`scripts/bench.sh`).
pub const FRAME_RAYS: usize = 4_000;

/// Cut tiles of the stock's mesh made again in one frame at most ([`TiledMesh::update_within`]):
/// about 3.5 ms natively. A frame's own cut changes a few; when frames are slow, several of
/// the first pass's lent shares land between two of them and changed up to about 80 tiles
/// (11 ms natively), meshed in one frame. The rest follow in the next frames.
pub const FRAME_TILES: usize = 24;

/// The first pass's share of one [`crate::state::Action::PassStock`] (it cuts the whole run
/// once for the notes): about 10 ms in a release wasm build, a paint between two of them.
pub const PASS_RAYS: usize = 3 * FRAME_RAYS;

/// Steps planned per share of the first pass or per frame that needs them: half a checkpoint
/// interval of the simulation, about 1 ms natively (planning a 100,000-block run at once took
/// 0.2 s natively, a long task in the browser).
pub const PLAN_STEPS: usize = 512;

/// What the view shows and where it is going.
#[derive(Default)]
struct Shown {
    /// The stock shown.
    cursor: StockCursor,
    /// A step back, cut forward from a checkpoint; shown when it gets there.
    pending: Option<StockCursor>,
    tiles: TiledMesh,
    mesh: Option<Rc<TiledMesh>>,
    /// The figures of `cursor`'s stock and the version they were worked out for.
    figures: Option<(u64, StockFigures)>,
    /// The stock asked for last (step, fraction) while the view has not got there yet.
    behind: Option<(usize, f64)>,
}

impl Shown {
    /// Cuts about `budget` rays towards the stock after `fraction` of step `step`: forward on
    /// the shown stock, or a step back on a pending one (shown once it gets there); whether
    /// the shown stock is that stock.
    fn cut_toward(&mut self, cutting: &Cutting, step: usize, fraction: f64, budget: usize) -> bool {
        let done = if cutting.is_past(&self.cursor, step, fraction) {
            let pending = self.pending.get_or_insert_with(StockCursor::default);
            let done = cutting.advance(pending, step, fraction, budget);
            if done {
                self.cursor = self.pending.take().unwrap_or_default();
                self.figures = None;
            }
            done
        } else {
            // Forward again (or still): a step back under way is no longer wanted.
            self.pending = None;
            cutting.advance(&mut self.cursor, step, fraction, budget)
        };
        self.behind = (!done).then_some((step, fraction));
        done
    }
}

/// What the stock shown has lost (issue 32: "how deep is this hole?"): the volume removed from
/// the blank, mm³, and the box around the material left (W-CS, mm; `None`: nothing left).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StockFigures {
    pub removed: f64,
    pub left: Option<(DVec3, DVec3)>,
}

/// A signed length as the figures write it: `+100`, `−2,5` (German decimal comma).
fn signed_mm(v: f64, lang: Lang) -> String {
    localise(format!("{:+}", tidy(v, 1)), lang).replace('-', "−")
}

/// What lies under the pointer in the 3D view (issue 32: "how deep is this hole?"): the height
/// of the first material there, W-CS, and how far below the blank's top `top` it lies —
/// `Unter dem Zeiger Z−20 mm, 20 mm unter der Rohteil-Oberkante`.
#[must_use]
pub fn pointer_line(hit: DVec3, top: f64, lang: Lang) -> String {
    let depth = localise(format!("{}", tidy((top - hit.z).max(0.0), 1)), lang);
    let z = signed_mm(hit.z, lang);
    match lang {
        Lang::De => format!("Unter dem Zeiger Z{z} mm, {depth} mm unter der Rohteil-Oberkante"),
        Lang::En => format!("Under the pointer Z{z} mm, {depth} mm below the blank's top"),
    }
}

impl StockFigures {
    /// The line under the 3D view: `Abgetragen 785,4 mm³ · Rest X+0…+100 Y+0…+100 Z−40…−2 mm`.
    #[must_use]
    pub fn line(&self, lang: Lang) -> String {
        let mm = |v: f64| signed_mm(v, lang);
        let removed = localise(format!("{:.1}", self.removed.max(0.0)), lang);
        let left = match self.left {
            Some((lo, hi)) => {
                let axes = ["X", "Y", "Z"]
                    .iter()
                    .enumerate()
                    .map(|(k, a)| format!("{a}{}…{}", mm(lo[k]), mm(hi[k])));
                format!("{} {} mm", lang.t("Rest", "left"), axes.collect::<Vec<_>>().join(" "))
            }
            None => lang.t("nichts übrig", "nothing left").to_owned(),
        };
        format!("{} {removed} mm³ · {left}", lang.t("Abgetragen", "Removed"))
    }
}

/// The cuts of one simulation and where the view stands in them.
pub struct StockView {
    sim: SimRef,
    /// The program `sim` ran, for planning its steps.
    doc: Rc<Document>,
    /// Its first pass (the notes) goes on in shares, [`StockRef::pass_on`].
    cutting: RefCell<Cutting>,
    at: RefCell<Shown>,
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
    /// The cuts of `sim` (the run of `doc`'s program), none planned or made yet: planning and
    /// the first pass, which cuts the whole run once for the notes and the checkpoints, go on
    /// in shares ([`StockRef::pass_on`]), so that starting a run with the stock is no long task
    /// (classroom trial II: 0.85 s in one). The view plans and cuts what it shows on its own
    /// meanwhile.
    #[must_use]
    pub fn of(sim: &SimRef, doc: &Rc<Document>) -> StockRef {
        let cutting = RefCell::new(Cutting::unplanned(StockOptions::default()));
        StockRef(Rc::new(StockView {
            sim: sim.clone(),
            doc: doc.clone(),
            cutting,
            at: RefCell::new(Shown::default()),
        }))
    }

    /// Plans up to `steps` more steps; whether all are planned.
    fn plan_on(&self, steps: usize) -> bool {
        self.0.cutting.borrow_mut().plan_on(&self.0.doc.program, &self.0.sim.0, steps)
    }

    /// Plans [`PLAN_STEPS`] more steps, then goes on with the first pass by about `rays`;
    /// whether it is done (every step planned, every note known). While the view has not cut
    /// its way to the stock it shows, two thirds of the share go to the view: a run opened at a
    /// late block (a share link, a jump) shows its part about four times as soon. The pass
    /// keeps a third, so that its notes (a rapid into the material) still come while a running
    /// program keeps the view behind.
    pub fn pass_on(&self, rays: usize) -> bool {
        let planned = self.plan_on(PLAN_STEPS);
        let mut own = rays;
        {
            let mut at = self.0.at.borrow_mut();
            if let Some((step, fraction)) = at.behind {
                own = rays / 3;
                at.cut_toward(&self.0.cutting.borrow(), step, fraction, rays - own);
            }
        }
        self.0.cutting.borrow_mut().pass_on(own) && planned
    }

    /// Whether this is the stock of `sim`.
    #[must_use]
    pub fn is_for(&self, sim: &SimRef) -> bool {
        self.0.sim == *sim
    }

    /// The stock's mesh (W-CS, in tiles) on its way to the stock after `fraction` (0…1) of step
    /// `step`'s motion, cutting about `budget` rays at most ([`FRAME_RAYS`] per frame, then
    /// meshing at most [`FRAME_TILES`] cut tiles; `usize::MAX` to get there at once); the same
    /// `Rc` as long as nothing changed. Also says whether the mesh shows that stock (`false`:
    /// call again next frame). `None` before a `BLK FORM`.
    pub fn mesh_toward(&self, step: usize, fraction: f64, budget: usize) -> (Option<Rc<TiledMesh>>, bool) {
        // The steps up to the shown one planned first: all at once without a budget, else a
        // share per frame.
        self.plan_on(if budget == usize::MAX { step.saturating_add(1) } else { PLAN_STEPS });
        let mut guard = self.0.at.borrow_mut();
        let at = &mut *guard;
        let done = at.cut_toward(&self.0.cutting.borrow(), step, fraction.clamp(0.0, 1.0), budget);
        let Some(stock) = &at.cursor.stock else {
            at.mesh = None;
            return (None, done);
        };
        let limit = if budget == usize::MAX { usize::MAX } else { FRAME_TILES };
        let (made, meshed) = at.tiles.update_within(stock, limit);
        if made > 0 || at.mesh.is_none() {
            at.mesh = Some(Rc::new(at.tiles.clone()));
        }
        (at.mesh.clone(), done && meshed)
    }

    /// The figures of the stock the view shows now (`None` before a `BLK FORM`), worked out
    /// again only when that stock changed.
    #[must_use]
    pub fn figures(&self) -> Option<StockFigures> {
        let mut at = self.0.at.borrow_mut();
        let version = at.cursor.version;
        if let Some((v, f)) = at.figures
            && v == version
        {
            return Some(f);
        }
        let stock = at.cursor.stock.as_ref()?;
        let (min, max) = stock.bounds();
        let f = StockFigures {
            removed: (max - min).element_product() - stock.volume(),
            left: stock.material_bounds(),
        };
        at.figures = Some((version, f));
        Some(f)
    }

    /// The first material along the ray `origin + λ·dir` (W-CS) in the stock the view shows
    /// now, and the blank's top (its highest Z); `None` before a `BLK FORM` or off the part.
    #[must_use]
    pub fn under_pointer(&self, origin: DVec3, dir: DVec3) -> Option<(DVec3, f64)> {
        let at = self.0.at.borrow();
        let stock = at.cursor.stock.as_ref()?;
        Some((stock.first_material(origin, dir)?, stock.bounds().1.z))
    }

    /// What the stock says about step `step` (a rapid into the material), German and English.
    #[must_use]
    pub fn notes_at(&self, step: usize) -> Option<Text> {
        let cutting = self.0.cutting.borrow();
        let mut notes = cutting.notes_at(step).map(|n| n.message());
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

    fn musterprogramm1() -> (Rc<Document>, SimRef) {
        let doc = Rc::new(Document::new(crate::samples::MUSTERPROGRAMM_1.text.to_owned()));
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine);
        (doc, sim)
    }

    fn step_of(doc: &Document, sim: &SimRef, number: u32) -> usize {
        let block = doc.program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
        sim.0.step_of_block(block).expect("executed")
    }

    /// Cut faces of a mesh (flag bit 3, `stock::mesh::flag::CUT`), as triangles.
    fn cut_triangles(m: &TiledMesh) -> usize {
        m.tiles().iter().flat_map(|t| t.1.flags.iter().step_by(3)).filter(|f| **f & 0b1000 != 0).count()
    }

    /// The mesh at once.
    fn mesh_at(stock: &StockRef, step: usize, fraction: f64) -> Option<Rc<TiledMesh>> {
        let (mesh, done) = stock.mesh_toward(step, fraction, usize::MAX);
        assert!(done, "without a budget the stock gets there at once");
        mesh
    }

    #[test]
    fn the_figures_line_says_the_volume_and_the_box_left_in_the_language() {
        let f = StockFigures {
            removed: 785.398,
            left: Some((DVec3::new(0.0, 0.0, -40.0), DVec3::new(100.0, 100.0, -2.04))),
        };
        assert_eq!(f.line(Lang::De), "Abgetragen 785,4 mm³ · Rest X+0…+100 Y+0…+100 Z−40…−2 mm");
        assert_eq!(f.line(Lang::En), "Removed 785.4 mm³ · left X+0…+100 Y+0…+100 Z−40…−2 mm");
        let gone = StockFigures { removed: 8000.0, left: None };
        assert_eq!(gone.line(Lang::De), "Abgetragen 8000,0 mm³ · nichts übrig");
    }

    /// A run opened at its last block (a share link): while the view is behind, the first
    /// pass's share after each frame cuts the view's way, so it gets there in about a quarter
    /// of the frames it needs alone; then the pass goes on to its end with every note.
    #[test]
    fn a_view_behind_gets_the_first_passs_share() {
        let (doc, sim) = musterprogramm1();
        let last = sim.0.len() - 1;
        let frames = |helped: bool| {
            let stock = StockRef::of(&sim, &doc);
            let mut frames = 0;
            while !stock.mesh_toward(last, 1.0, FRAME_RAYS).1 {
                if helped {
                    stock.pass_on(PASS_RAYS);
                }
                frames += 1;
                assert!(frames < 100_000, "the view never gets there");
            }
            (stock, frames)
        };
        let ((_, alone), (stock, helped)) = (frames(false), frames(true));
        assert!(helped * 3 <= alone, "{helped} frames helped, {alone} alone");
        let mut shares = 0;
        while !stock.pass_on(PASS_RAYS) {
            shares += 1;
            assert!(shares < 100_000, "the pass never ends");
        }
    }

    /// Slow frames: several of the first pass's lent shares land between two frames and change
    /// more tiles than one frame meshes. Each frame meshes at most [`FRAME_TILES`] cut tiles,
    /// the view says it is not there yet while tiles are stale, and it ends with the mesh the
    /// stock has at once.
    #[test]
    fn a_frame_meshes_at_most_its_share_of_tiles() {
        let (doc, sim) = musterprogramm1();
        let last = sim.0.len() - 1;
        let stock = StockRef::of(&sim, &doc);
        let (mut shown, _) = stock.mesh_toward(last, 1.0, FRAME_RAYS);
        let (mut frames, mut most) = (0, 0);
        loop {
            for _ in 0..8 {
                stock.pass_on(PASS_RAYS);
            }
            let (mesh, done) = stock.mesh_toward(last, 1.0, FRAME_RAYS);
            let (before, after) = (shown.as_deref(), mesh.as_deref().expect("a blank"));
            let remade = after
                .tiles()
                .iter()
                .enumerate()
                .filter(|(k, t)| {
                    before.and_then(|b| b.tiles().get(*k)).is_none_or(|b| !Rc::ptr_eq(&b.1, &t.1))
                })
                .filter(|(_, t)| t.1.flags.iter().any(|f| f & 0b1000 != 0))
                .count();
            assert!(remade <= FRAME_TILES, "{remade} cut tiles meshed in one frame");
            most = most.max(remade);
            shown = mesh;
            frames += 1;
            assert!(frames < 10_000, "the view never gets there");
            if done {
                break;
            }
        }
        assert_eq!(most, FRAME_TILES, "some frame had more tiles to mesh than its share");
        let at_once = mesh_at(&StockRef::of(&sim, &doc), last, 1.0).expect("a blank");
        let shown = shown.expect("a blank");
        assert_eq!(shown.tiles().len(), at_once.tiles().len());
        for (a, b) in shown.tiles().iter().zip(at_once.tiles()) {
            assert_eq!(*a.1, *b.1, "the same mesh in the end");
        }
    }

    /// A view that is behind (a running program whose next block comes before the view got to
    /// the last) does not hold up the first pass: it goes on with its third of every share.
    #[test]
    fn the_first_pass_goes_on_while_the_view_is_behind() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        let last = sim.0.len() - 1;
        assert!(!stock.mesh_toward(last, 1.0, 1).1, "one ray does not get there");
        let passed = || stock.0.cutting.borrow().passed();
        let mut shares = 0;
        while stock.0.at.borrow().behind.is_some() && !stock.pass_on(PASS_RAYS) {
            shares += 1;
            assert!(shares < 10_000, "the view never gets there");
        }
        assert!(shares > 10, "the view was behind for a while: {shares} shares");
        assert!(passed() > 0, "the pass went on meanwhile: {} steps", passed());
    }

    #[test]
    fn the_pointer_line_says_the_height_and_the_depth_below_the_top() {
        let hit = DVec3::new(50.0, 50.0, -20.0);
        assert_eq!(
            pointer_line(hit, 0.0, Lang::De),
            "Unter dem Zeiger Z−20 mm, 20 mm unter der Rohteil-Oberkante"
        );
        assert_eq!(
            pointer_line(hit, 0.0, Lang::En),
            "Under the pointer Z−20 mm, 20 mm below the blank's top"
        );
        let face = DVec3::new(10.0, 10.0, -2.54);
        assert_eq!(
            pointer_line(face, 0.0, Lang::De),
            "Unter dem Zeiger Z−2,5 mm, 2,5 mm unter der Rohteil-Oberkante"
        );
    }

    /// Under the pointer at the end of Musterprogramm 1: looking down the Ø8 hole of the tilted
    /// face along its axis (SPB+15 at I-CS (50, 50, 0), 20 mm deep along the tool axis), the
    /// first material is the hole's floor at the drill's tip, worked out from the tilt by hand,
    /// to a ray spacing; beside the part, nothing.
    #[test]
    fn under_the_pointer_is_the_floor_of_the_hole() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        let last = sim.0.len() - 1;
        mesh_at(&stock, last, 1.0);
        let (sin, cos) = 15f64.to_radians().sin_cos();
        // SPB+15 turns the plane about Y: I-CS X = (cos, 0, −sin), Z = (sin, 0, cos) in W-CS.
        let axis = DVec3::new(sin, 0.0, cos);
        let tip = DVec3::new(50.0 * cos, 50.0, -50.0 * sin) - 20.0 * axis;
        let (hit, top) = stock.under_pointer(tip + 100.0 * axis, -axis).expect("the floor");
        assert!((hit - tip).length() < 0.5, "floor at {hit} vs tip {tip}");
        assert!((top - 0.0).abs() < 1e-9, "{top}");
        assert_eq!(stock.under_pointer(DVec3::new(-50.0, 50.0, 100.0), DVec3::NEG_Z), None);
    }

    /// At the end of Musterprogramm 1 the view's figures are those of the whole run cut at once
    /// by core (`Cutting::new`, a second way to the same stock), and before any cut nothing is
    /// removed and the box is the blank.
    #[test]
    fn the_figures_are_the_shown_stocks() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        let before = step_of(&doc, &sim, 13) - 1;
        mesh_at(&stock, before, 1.0);
        let f0 = stock.figures().expect("a blank");
        let blank = sim.0.state_at(&doc.program, before).and_then(|s| s.blank).expect("blank");
        assert!(f0.removed.abs() < 1e-9 * (blank.max - blank.min).element_product(), "{f0:?}");
        assert_eq!(f0.left, Some((blank.min, blank.max)));
        let last = sim.0.len() - 1;
        mesh_at(&stock, last, 1.0);
        let f1 = stock.figures().expect("stock");
        let whole = Cutting::new(&doc.program, &sim.0, StockOptions::default()).final_stock().expect("stock");
        let (min, max) = whole.bounds();
        assert!((f1.removed - ((max - min).element_product() - whole.volume())).abs() < 1e-6, "{f1:?}");
        assert!(f1.removed > 1000.0, "{f1:?}");
        assert_eq!(f1.left, whole.material_bounds());
    }

    #[test]
    fn block_13_mills_the_face_and_the_mesh_is_made_again_only_when_the_stock_changed() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        assert!(stock.is_for(&sim));
        let (before, after) = (step_of(&doc, &sim, 13) - 1, step_of(&doc, &sim, 13));
        let m0 = mesh_at(&stock, before, 1.0).expect("a blank");
        assert_eq!(cut_triangles(&m0), 0, "nothing cut before block 13");
        assert!(Rc::ptr_eq(&m0, &mesh_at(&stock, before, 1.0).expect("same")), "no new mesh");
        let half = mesh_at(&stock, after, 0.5).expect("stock");
        let m1 = mesh_at(&stock, after, 1.0).expect("stock");
        assert!(cut_triangles(&half) > 0 && cut_triangles(&m1) > cut_triangles(&half) / 2);
        // Only the tiles the second half of the block cut are new meshes.
        let same = half.tiles().iter().zip(m1.tiles()).filter(|(a, b)| Rc::ptr_eq(&a.1, &b.1)).count();
        assert!(same > 0 && same < m1.tiles().len(), "{same} of {} tiles kept", m1.tiles().len());
        // Back again: the same stock as before.
        let back = mesh_at(&stock, before, 1.0).expect("stock");
        assert!(back.tiles().iter().zip(m0.tiles()).all(|(a, b)| a.1 == b.1));
    }

    /// An animation frame cuts a bounded share; the view is told to come back until the stock
    /// is there, and a step back keeps showing the stock it had until the older one is ready.
    #[test]
    fn frames_cut_a_bounded_share_and_a_step_back_shows_the_old_stock_until_the_new_is_ready() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        let step13 = step_of(&doc, &sim, 13);
        let mut frames = 0;
        let mut last = None;
        loop {
            let (mesh, done) = stock.mesh_toward(step13, 1.0, FRAME_RAYS);
            frames += 1;
            last = mesh.or(last);
            if done {
                break;
            }
            assert!(frames < 10_000);
        }
        assert!(frames > 5, "block 13 takes several frames at {FRAME_RAYS} rays: {frames}");
        let full = last.expect("stock");
        assert!(
            full.tiles()
                .iter()
                .zip(mesh_at(&stock, step13, 1.0).expect("same").tiles())
                .all(|(a, b)| a.1 == b.1)
        );
        // Step back to the middle of block 13: until the stock is cut there, the full one stays.
        let (first, done) = stock.mesh_toward(step13, 0.5, 2_000);
        if !done {
            let first = first.expect("stock");
            assert!(
                first.tiles().iter().zip(full.tiles()).all(|(a, b)| a.1 == b.1),
                "the old stock stays shown"
            );
        }
        while !stock.mesh_toward(step13, 0.5, 2_000).1 {}
        let half = mesh_at(&stock, step13, 0.5).expect("stock");
        assert!(cut_triangles(&half) < cut_triangles(&full));
    }

    #[test]
    fn the_stock_before_the_blk_form_is_none_and_notes_are_worded_in_both_languages() {
        let (doc, sim) = musterprogramm1();
        let stock = StockRef::of(&sim, &doc);
        assert!(mesh_at(&stock, 0, 1.0).is_none(), "BEGIN PGM: no blank yet");
        let doc = Rc::new(Document::new(
            "0 BEGIN PGM R MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 16 Z S5000\n4 L X+50 Y+50 Z+50 R0 FMAX\n5 L Z-5 R0 FMAX\n6 END PGM R MM\n"
                .to_owned(),
        ));
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine);
        let stock = StockRef::of(&sim, &doc);
        let step = sim.0.step_of_block(5).expect("executed");
        assert!(stock.notes_at(step).is_none(), "nothing cut yet when the stock is switched on");
        let mut shares = 0;
        while !stock.pass_on(PASS_RAYS) {
            shares += 1;
            assert!(shares < 10_000);
        }
        let note = stock.notes_at(step).expect("rapid into the material");
        assert_eq!(note.de, "Eilgang ins Material: Kollision Werkzeug – Rohteil");
        assert!(note.en.starts_with("Rapid traverse into the material"));
        assert!(stock.notes_at(step - 1).is_none());
    }

    /// A long run is planned a share at a time: making the stock plans nothing, each share of
    /// the first pass plans at most [`PLAN_STEPS`] steps, and a frame that shows a step far
    /// ahead gets there over several frames.
    #[test]
    fn a_long_run_is_planned_a_share_at_a_time() {
        let mut text =
            String::from("BEGIN PGM P MM\nBLK FORM 0.1 Z X+0 Y+0 Z-40\nBLK FORM 0.2 X+100 Y+100 Z+0\n");
        text.extend((0..2_000).map(|k| format!("Q1 = Q1 + {k}\n")));
        text.push_str("END PGM P MM\n");
        let doc = Rc::new(Document::new(text));
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine);
        let last = sim.0.len() - 1;
        let stock = StockRef::of(&sim, &doc);
        let mut frames = 1;
        while !stock.mesh_toward(last, 1.0, FRAME_RAYS).1 {
            frames += 1;
            assert!(frames < 1_000);
        }
        assert!(frames >= last.div_ceil(PLAN_STEPS), "{frames} frames to plan {last} steps");
        let mut shares = 1;
        while !stock.pass_on(PASS_RAYS) {
            shares += 1;
            assert!(shares < 1_000);
        }
        assert!(mesh_at(&stock, last, 1.0).is_some(), "the blank");
    }
}
