//! Step through a program: the machine state after every executed block, the motion of every
//! block as segments the 3D view can evaluate at any fraction, the transformation chain, and
//! the control's errors (issue 5).
//!
//! # The machine model (M-CS)
//!
//! * **Linear axes** `L = (X, Y, Z)` are the position of the tool tip in M-CS with every *head*
//!   axis at 0° (tool-length compensated, as the position display shows it). `L Z+0 M91` is
//!   therefore the tool tip at machine Z 0, the top of the travel in the shipped machines.
//! * **Table axes** turn the workpiece by −θ about their axis through their pivot (DOMAIN.md
//!   §3.1). Workpiece coordinates are M-CS coordinates at rotary zero; the workpiece pose is
//!   `W = T_n ∘ … ∘ T_1` over the table joints in chain order (the joint nearest the workpiece
//!   acts first because the next one carries it), `T_j(x) = p_j + Rot(u_j, −θ_j)·(x − p_j)`
//!   with the home direction `u_j` and pivot `p_j` from the machine JSON (M-CS).
//! * **Head axes** turn the tool by +θ about their axis. The head pose is
//!   `H = T_h1 ∘ T_h2` (the axis nearest the tool acts first), `T_h(x) = q + Rot(u, θ)·(x − q)`
//!   with `q = (0, 0, tool length) + pivot`: a head pivot in the JSON is given relative to the
//!   spindle gauge point, which sits one tool length above the tip. The physical tool tip is
//!   `L + H(0)`, the tool axis (tip → spindle) `H·ez`.
//! * Together the tool orientation relative to the workpiece is `Wᵀ·H = R_machine` of
//!   [`crate::machine::Machine::forward`] (derived; the kinematics' convention).
//! * **W-CS** = workpiece coordinates shifted by the preset `geometry.preset` (no basic
//!   rotation). A point `p` (W-CS) is under the tool tip when `L = W(preset + p) − H(0)`
//!   ([`geometry::Kin::wcs_to_linear`]); the control uses this kinematic transformation while a
//!   tilt is active ([`crate::unconfirmed::COMPENSATION_ONLY_WHEN_TILTED`]), otherwise `L = preset + p`.
//! * **Transformations**: `p_W = d_W + R·M_W·(d_I + M_I·Rz(rot)·p_I)` ([`transform`]).
//!   Programmed coordinates are I-CS values (DOMAIN.md §1).
//! * **Frames** in [`State::frames`] are the control's W-CS, WPL-CS and I-CS in M-CS.
//!
//! # Positioning behaviour (DOMAIN.md §4, seed S0)
//!
//! * `TURN`: optional `MB d` / `MB MAX` retract along the tool axis (MB MAX: up to the first
//!   linear software limit), then only the rotary axes move, linear in time.
//! * `MOVE`: the rotary axes move linear in time; the centre of rotation
//!   `c = tip_W − DIST·t_W(θ_start)` stays fixed on the workpiece and the tip follows
//!   `c + DIST·t_W(θ)`; the linear axes are `L(θ) = W_θ(preset + c + DIST·t_W(θ)) − H_θ(0)`
//!   (derived from the seed's "Relativposition bleibt unverändert" and DIST = "Abstand zwischen
//!   Drehpunkt und Werkzeugspitze"; DIST 0 or left out keeps the tool tip itself fixed).
//! * `STAY`: nothing moves; Q120–Q122 hold the axis angles for a later `L A+Q120 C+Q122`. The
//!   block still gets a [`SegmentKind::SwivelStay`] segment (axes constant, the plane's turn in
//!   [`SegmentPath::Stay`]) so the view can show the coordinate system turning.
//! * TCPM (`M128` … `M129`, `FUNCTION TCPM … AXIS POS|AXIS SPAT` … `FUNCTION RESET TCPM`, issue
//!   17): a block with rotary axes keeps the tool tip on the programmed point; the linear axes
//!   are `L(θ) = W_θ(preset + p(f)) − H_θ(0)` with the rotary axes linear in time and the tip
//!   `p(f)` straight from the start to the programmed end (W-CS) ([`SegmentPath::Tcpm`]); timing
//!   in [`crate::unconfirmed::TCPM_FROM_BLOCK_START`]. With `AXIS SPAT`, `A`, `B`, `C` are spatial
//!   angles in the active coordinate system, solved to axis positions as a PLANE block without
//!   SEQ ([`crate::unconfirmed::Decision::TcpmAxisSpat`]); `TOOL CALL`, `M91`, `M92` with TCPM on
//!   in [`crate::unconfirmed::TCPM_REFUSES_TOOL_CALL_M91_M92`].
//!
//! # Contour (issue 15)
//! `CC`, `C`, `CR`, `CT`, polar `LP`/`CP` (helix with `IZ`), `RND` and `CHF` run in the main
//! plane of the TOOL CALL's tool axis (Z → XY, Y → ZX, X → YZ; DR+ counter-clockwise seen
//! against the tool axis) of the I-CS, so after a PLANE they lie in the tilted plane
//! ([`arc`], `interp/contour.rs`). An arc is one [`SegmentKind::Feed`] (or rapid) segment with
//! [`SegmentPath::Arc`]: the I-CS arc carried into the linear axes, exact at every fraction. The
//! element before a `RND`/`CHF` looks ahead to the element after it, ends at the first tangent
//! point and leaves the rounding to the `RND`/`CHF` block; the element after starts at the
//! second. Geometry errors (no CC, CR radius too small, CT without a preceding element, a
//! rounding that does not fit) stop the run at their block. The radius compensation RL/RR and the
//! `APPR`/`DEP` approach and departure paths run in `interp/compensation.rs`.
//!
//! # Programs
//! Labels, `CALL LBL n [REP m]`, `FN 0`, formulas, `FN 1–5` and `FN 9–12` jumps run; `M30`/`M2` end the
//! run and the rest of the program is listed as not executed
//! ([`crate::unconfirmed::LIST_BLOCKS_AFTER_END`]); a `CYCL DEF` acts at `M99`/`CYCL CALL`
//! (the cycles `sim/cycles.rs` models move — drilling, face milling, pockets, patterns; any other
//! runs with a note on its call that it is not simulated).
//!
//! # Durations
//! Linear share = distance / F (mm/min); `FMAX` = `geometry.rapid_linear`; rotary share =
//! travel / F (°/min) or `geometry.rapid_rotary` ([`crate::unconfirmed::ROTARY_FEED_DEG_PER_MIN`]);
//! `F AUTO` = the feed of the last TOOL CALL. A segment lasts the longer of both shares.
//!
//! # Budget and stepping
//! [`simulate`] keeps one compact [`Record`] per executed block and a full checkpoint of the
//! interpreter every [`SimOptions::checkpoint_interval`] blocks; [`Simulation::state_at`]
//! re-runs from the nearest checkpoint, so any step is at most one interval away.

pub mod arc;
pub mod collision;
mod cycles;
mod error;
pub mod geometry;
mod interp;
mod note;
mod pick;
mod placed;
pub mod segment;
mod state;
pub mod tools;
pub mod transform;

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::ops::Range;
use std::sync::Arc;

use serde::Serialize;

use crate::ast::{BlockBody, Label, Program};
use crate::machine::Machine;

pub use collision::{Collision, SafeAlternative};
pub use error::{ApprDepReason, SimError, SimErrorCode};
pub use geometry::{Affine, Kin};
pub use note::Note;
pub use pick::{Pick, pick_machine, programmed_rotary_axes};
pub use placed::{placed, written_blank};
pub use segment::{ArcPath, MachineAxes, MovePath, Segment, SegmentKind, SegmentPath, TcpmPath};
pub use state::{
    ActivePlane, Blank, Frame, Frames, ListingRow, Pivot, Spindle, SpindleDir, State, StepMotion, TiltSource,
    ToolState,
};
pub use transform::{ActiveTransform, Level, Transforms};

use interp::{Interp, Rec};

/// Options of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct SimOptions {
    /// Stop with an error after this many executed blocks (endless loops). `None` = the default
    /// budget: 1,000,000 + 20 × the number of blocks.
    pub max_steps: Option<usize>,
    /// Skip blocks written with a leading `/` (the control's block-skip switch).
    pub block_skip: bool,
    /// A full checkpoint every this many executed blocks (at least 1).
    pub checkpoint_interval: usize,
    /// The shop's tool table (read from `TOOL.T`); `None`: the shipped one ([`tools::tool_table`]).
    pub tools: Option<Arc<[tools::ToolEntry]>>,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions { max_steps: None, block_skip: false, checkpoint_interval: 1024, tools: None }
    }
}

impl SimOptions {
    /// The tool table of the run.
    #[must_use]
    pub fn tool_table(&self) -> &[tools::ToolEntry] {
        self.tools.as_deref().unwrap_or_else(|| tools::tool_table())
    }
}

/// Per executed block: which block, and every axis after it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Record {
    pub block: u32,
    /// `false` for a block only listed (after M30/M2, or skipped with `/`).
    pub executed: bool,
    /// Whether the step made a positioning motion (a rapid, an MB retract, the swivel of
    /// MOVE/TURN): the steps [`crate::stock::Cutting::collisions`] looks at.
    #[serde(skip)]
    pub positioned: bool,
    pub axes: MachineAxes,
}

/// Key of the label table.
/// Ordered (a BTreeMap, not a HashMap): the wasm then carries no hasher of its own for it.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum LabelKey {
    Num(u32),
    Name(String),
}

impl From<&Label> for LabelKey {
    fn from(l: &Label) -> Self {
        match l {
            Label::Number(n) => LabelKey::Num(*n),
            Label::Name(s) => LabelKey::Name(s.clone()),
        }
    }
}

/// The result of a run.
#[derive(Debug, Clone)]
pub struct Simulation {
    pub machine: Machine,
    pub options: SimOptions,
    /// One per executed block, in execution order.
    pub records: Vec<Record>,
    /// Where the run stopped with the control's message, if it did.
    pub error: Option<SimError>,
    /// For each block of the program, the first step that executed it.
    pub first_step: Vec<Option<u32>>,
    checkpoints: Vec<Interp>,
    labels: Arc<BTreeMap<LabelKey, usize>>,
    blocks: usize,
    /// After an edit stopped the run early (a block broken while typing): the longer run before
    /// it and the blocks where that run's program may differ from this one, so the run after
    /// the next edit (the block healed) can join it instead of running to the end again.
    spare: Option<(Arc<Simulation>, Range<usize>)>,
}

/// An earlier run a resumed run may join ([`Simulation::resumed`]).
struct Join<'a> {
    run: &'a Simulation,
    /// Blocks of the new program that may differ from the earlier run's program, or whose
    /// running looked ahead to such a block.
    dirty: Range<usize>,
    /// The earlier run's last step that ran a block of `dirty` (or stopped at one).
    last_dirty: Option<usize>,
}

impl<'a> Join<'a> {
    fn new(run: &'a Simulation, dirty: Range<usize>) -> Join<'a> {
        let stop = run.error.as_ref().filter(|e| dirty.contains(&e.block)).map(|e| e.step);
        let last_dirty =
            stop.or_else(|| run.records.iter().rposition(|r| dirty.contains(&(r.block as usize))));
        Join { run, dirty, last_dirty }
    }

    /// Whether the earlier run from step `step` on is this run's: the interpreter is the same
    /// there, and no later step of the earlier run ran or reads a block that may differ.
    fn fits(&self, step: usize, it: &Interp) -> bool {
        self.last_dirty.is_none_or(|d| d < step)
            && self.run.checkpoints.get(step / self.run.options.checkpoint_interval) == Some(it)
            && !it.refers_into(&self.dirty)
    }
}

/// Runs a program on a machine.
#[must_use]
pub fn simulate(program: &Program, machine: &Machine, options: &SimOptions) -> Simulation {
    simulate_listed(program, machine, options, None)
}

/// [`simulate`], handing each executed step's [`ListingRow`] to `row` as it runs: a listing
/// (the CLI's table) in one pass instead of a run and a re-run of every step.
pub fn simulate_listed(
    program: &Program,
    machine: &Machine,
    options: &SimOptions,
    row: Option<&mut dyn FnMut(ListingRow)>,
) -> Simulation {
    let mut options = options.clone();
    options.checkpoint_interval = options.checkpoint_interval.max(1);
    // The blank on the table: the run's machine has the preset the program's blank gives.
    let machine = placed(machine, program).into_owned();
    let interp = Interp::new(&machine);
    Simulation {
        machine,
        options,
        records: Vec::with_capacity(program.blocks.len()),
        error: None,
        first_step: vec![None; program.blocks.len()],
        checkpoints: Vec::new(),
        labels: Arc::new(label_table(program)),
        blocks: program.blocks.len(),
        spare: None,
    }
    .run_on(program, interp, row, &[])
}

/// Blocks a contour element looks ahead over to the next element (`next_element`,
/// `before_corner` in `sim/interp/`): they do not move the tool.
fn looked_over(body: &BlockBody) -> bool {
    match body {
        BlockBody::Empty | BlockBody::Structure { .. } | BlockBody::CycleDef(_) | BlockBody::Cc(_) => true,
        BlockBody::MFunctions(m, _) => !m.contains(&99),
        BlockBody::L(l) => l.axes.is_empty() && !l.m.contains(&99),
        _ => false,
    }
}

fn make_error(program: &Program, step: usize, block: usize, code: SimErrorCode) -> SimError {
    let line = program.blocks.get(block).map_or(0, |b| b.line());
    SimError { step, block, line, message: code.message(), detail: code.detail(), code }
}

fn label_table(program: &Program) -> BTreeMap<LabelKey, usize> {
    let mut m = BTreeMap::new();
    for (i, b) in program.blocks.iter().enumerate() {
        if let Some(BlockBody::Lbl(l)) = b.stored_body()
            && *l != Label::Number(0)
        {
            m.entry(LabelKey::from(l)).or_insert(i);
        }
    }
    m
}

impl Simulation {
    /// Runs on from `it` (the state after `self.records`), recording and checkpointing as
    /// [`simulate`] does, and listing each step to `row` if given; at a checkpoint where one of
    /// `joins` fits, the rest is that run's.
    fn run_on(
        mut self,
        program: &Program,
        mut it: Interp,
        mut row: Option<&mut dyn FnMut(ListingRow)>,
        joins: &[Join<'_>],
    ) -> Simulation {
        let budget = self.options.max_steps.unwrap_or(1_000_000 + 20 * program.blocks.len());
        let Simulation { machine, options, records, error, first_step, checkpoints, labels, .. } = &mut self;
        let cx = interp::Cx { program, machine, options, labels };
        // One record reused for the listing: its segment list keeps its capacity.
        let mut rec = Rec::default();
        let mut joined = None;
        while !it.done(program) {
            let step = records.len();
            if step % options.checkpoint_interval == 0 {
                joined = joins.iter().find(|j| j.fits(step, &it));
                if joined.is_some() {
                    break;
                }
                checkpoints.push(it.clone());
            }
            let block = it.pc;
            if step >= budget {
                *error = Some(make_error(program, step, block, SimErrorCode::BlockBudget { steps: budget }));
                break;
            }
            rec.segments.clear();
            match it.step(&cx, row.is_some().then_some(&mut rec)) {
                Ok(stepped) => {
                    if let Some(row) = row.as_mut() {
                        row(ListingRow {
                            step,
                            block: it.last,
                            line: program.blocks.get(it.last).map_or(0, |b| b.line()),
                            axes: it.axes,
                            spatial: it.plane.as_ref().map(|p| p.spatial),
                            note: rec.note.take(),
                        });
                    }
                    if let Some(slot) = first_step.get_mut(block)
                        && slot.is_none()
                    {
                        *slot = u32::try_from(step).ok();
                    }
                    records.push(Record {
                        block: u32::try_from(block).unwrap_or(u32::MAX),
                        executed: stepped.executed,
                        positioned: stepped.positioned,
                        axes: it.axes,
                    });
                }
                Err(code) => {
                    let mut e = make_error(program, step, block, code);
                    // A stop that comes from what the trainer assumed or does not simulate says
                    // so, or a trainee looks for the fault in the program.
                    if let Some(because) = it.because(&e.code) {
                        e.detail = e.code.detail_because(&because);
                    }
                    *error = Some(e);
                    break;
                }
            }
        }
        if let Some(j) = joined {
            self.join(program, j.run);
        }
        self
    }

    /// Takes the rest of `run` from this run's end on (a checkpoint where both interpreters
    /// are equal): its steps, checkpoints and end, the first steps of the blocks first reached
    /// there.
    fn join(&mut self, program: &Program, run: &Simulation) {
        let step = self.records.len();
        self.records.extend_from_slice(&run.records[step..]);
        let n = self.options.checkpoint_interval;
        self.checkpoints.extend_from_slice(&run.checkpoints[step / n..]);
        for (s, r) in self.records.iter().enumerate().skip(step) {
            if let Some(slot @ None) = self.first_step.get_mut(r.block as usize) {
                *slot = u32::try_from(s).ok();
            }
        }
        // The same stop, at its block's line in this program.
        self.error = run
            .error
            .clone()
            .map(|e| SimError { line: program.blocks.get(e.block).map_or(0, |b| b.line()), ..e });
    }

    /// The run of `program` after an edit that kept the simulated program's blocks before
    /// `changed.start` and from `changed.end` on (its last blocks, moved by the change in
    /// number), equal to [`simulate`] of it: re-run from the last checkpoint before the first
    /// step that executed a changed block or looked ahead to one (a contour element looks over
    /// blocks that do not move to the next element), or jumped to one. The labels are read
    /// anew; the steps before never reached a changed block, so they stay. When the number of
    /// blocks and the labels are the same, the re-run ends at a checkpoint where its
    /// interpreter equals the old run's (or that of the run before an edit that stopped the run
    /// early) and the old run never again ran or reads a changed block: the rest is the old
    /// run's, as a run from there would make it again.
    #[must_use]
    pub fn resumed(self: &Arc<Simulation>, program: &Program, changed: Range<usize>) -> Simulation {
        // An edit that moved the blank moves the preset: a run from the start.
        if let Cow::Owned(moved) = placed(&self.machine, program) {
            return simulate(program, &moved, &self.options);
        }
        let blocks = &program.blocks;
        let mut from = changed.start.min(blocks.len()).min(self.blocks);
        while from > 0 && looked_over(&blocks[from - 1].body()) {
            from -= 1;
        }
        from = from.saturating_sub(1);
        if from > 0
            && matches!(blocks[from].stored_body(), Some(BlockBody::Rnd { .. } | BlockBody::Chf { .. }))
        {
            from -= 1;
        }
        let reached = self.first_step.get(from..).unwrap_or(&[]).iter().flatten().min();
        // The step before may have jumped there: its label look-up read the changed blocks.
        let until =
            reached.map_or(self.records.len(), |&s| (s as usize).saturating_sub(1)).min(self.records.len());
        let n = self.options.checkpoint_interval;
        let c = (until / n).min(self.checkpoints.len().saturating_sub(1));
        let Some(it) = self.checkpoints.get(c).cloned() else {
            return simulate(program, &self.machine, &self.options);
        };
        let start = c * n;
        let mut first_step = vec![None; blocks.len()];
        for (slot, old) in first_step.iter_mut().zip(&self.first_step).take(from) {
            *slot = old.filter(|&s| (s as usize) < start);
        }
        let mut records = Vec::with_capacity(blocks.len().max(start));
        records.extend_from_slice(&self.records[..start]);
        let labels = Arc::new(label_table(program));
        // Block indices in the interpreter and the records would have to move: only an edit
        // that kept the number of blocks joins an earlier run.
        let dirty = from..changed.end.max(from);
        let earlier = (blocks.len() == self.blocks).then(|| {
            let spare = self
                .spare
                .as_ref()
                .map(|(run, d)| (run.clone(), d.start.min(dirty.start)..d.end.max(dirty.end)));
            (spare, dirty)
        });
        let mut joins = Vec::new();
        if let Some((spare, dirty)) = &earlier {
            if self.labels == labels {
                joins.push(Join::new(self.as_ref(), dirty.clone()));
            }
            if let Some((run, d)) = spare.as_ref().filter(|(run, _)| run.labels == labels) {
                joins.push(Join::new(run, d.clone()));
            }
        }
        let mut sim = Simulation {
            machine: self.machine.clone(),
            options: self.options.clone(),
            records,
            error: None,
            first_step,
            checkpoints: self.checkpoints[..c].to_vec(),
            labels,
            blocks: blocks.len(),
            spare: None,
        }
        .run_on(program, it, None, &joins);
        // Stopped early by the edit: the longest earlier run is kept for the next edit.
        if sim.error.is_some()
            && let Some((spare, dirty)) = earlier
        {
            let own = (self.records.len() > sim.records.len()).then(|| (self.records.len(), dirty));
            let spare = spare.filter(|(run, _)| run.records.len() > sim.records.len());
            sim.spare = match (own, spare) {
                (Some((own, _)), Some(spare)) if spare.0.records.len() >= own => Some(spare),
                (Some((_, dirty)), _) => Some((Arc::clone(self), dirty)),
                (None, spare) => spare,
            };
        }
        sim
    }

    /// Number of executed blocks with a state.
    #[must_use]
    pub fn len(&self) -> usize {
        self.records.len()
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// The first step that executed block `block` (its index in the program), if it ran.
    #[must_use]
    pub fn step_of_block(&self, block: usize) -> Option<usize> {
        self.first_step.get(block).copied().flatten().and_then(|s| usize::try_from(s).ok())
    }

    /// The full state after step `step`, re-simulated from the nearest checkpoint. `program`
    /// must be the program that was simulated (`None` if the block count differs or the step
    /// does not exist).
    #[must_use]
    pub fn state_at(&self, program: &Program, step: usize) -> Option<State> {
        if program.blocks.len() != self.blocks || step >= self.records.len() {
            return None;
        }
        let n = self.options.checkpoint_interval;
        let mut it = self.checkpoints.get(step / n)?.clone().replaying();
        let cx = interp::Cx { program, machine: &self.machine, options: &self.options, labels: &self.labels };
        while it.step_count < step {
            it.step(&cx, None).ok()?;
        }
        let mut rec = Rec::default();
        let stepped = it.step(&cx, Some(&mut rec)).ok()?;
        Some(it.state(program, &self.machine, step, stepped.executed, rec))
    }

    /// Every state in order, re-simulated once from the start (for listings of a whole run).
    pub fn states<'a>(&'a self, program: &'a Program) -> impl Iterator<Item = State> + 'a {
        self.states_from(program, 0)
    }

    /// The states from step `first` on, in order, re-simulated once from the checkpoint before
    /// it (a long listing in parts).
    pub fn states_from<'a>(&'a self, program: &'a Program, first: usize) -> impl Iterator<Item = State> + 'a {
        self.replay_from(program, first, move |it, step, executed, rec| {
            it.state(program, &self.machine, step, executed, rec)
        })
    }

    /// What the stock needs of each step from `first` on ([`StepMotion`]), re-simulated as
    /// [`Simulation::states_from`] does without building the whole [`State`].
    pub fn motions_from<'a>(
        &'a self,
        program: &'a Program,
        first: usize,
    ) -> impl Iterator<Item = StepMotion> + 'a {
        self.replay_from(program, first, |it, step, _, rec| it.motion(step, rec))
    }

    /// The steps from `first` on, re-simulated once from the checkpoint before it, each made
    /// into a `T` by `make` from the interpreter after the step, the step, whether it executed
    /// its block and what it recorded.
    fn replay_from<'a, T: 'a>(
        &'a self,
        program: &'a Program,
        first: usize,
        make: impl Fn(&Interp, usize, bool, Rec) -> T + 'a,
    ) -> impl Iterator<Item = T> + 'a {
        let cx_ok = program.blocks.len() == self.blocks;
        let mut it =
            self.checkpoints.get(first / self.options.checkpoint_interval).cloned().map(Interp::replaying);
        let mut step = first;
        std::iter::from_fn(move || {
            if !cx_ok || step >= self.records.len() {
                return None;
            }
            let interp = it.as_mut()?;
            let cx =
                interp::Cx { program, machine: &self.machine, options: &self.options, labels: &self.labels };
            while interp.step_count < step {
                interp.step(&cx, None).ok()?;
            }
            let mut rec = Rec::default();
            let stepped = interp.step(&cx, Some(&mut rec)).ok()?;
            let made = make(interp, step, stepped.executed, rec);
            step += 1;
            Some(made)
        })
    }

    /// The collision that stopped the run, if one did: the two bodies, the axes at the moment
    /// of contact and the safe other solution, for the view to show.
    #[must_use]
    pub fn collision(&self) -> Option<&Collision> {
        match &self.error.as_ref()?.code {
            SimErrorCode::Collision(c) => Some(c),
            _ => None,
        }
    }

    /// The segments of one step (empty for blocks that do not move).
    #[must_use]
    pub fn segments_at(&self, program: &Program, step: usize) -> Vec<Segment> {
        self.state_at(program, step).map(|s| s.segments).unwrap_or_default()
    }
}

#[cfg(test)]
mod step_tests {
    use super::*;

    #[test]
    fn step_of_block_is_the_first_step_that_ran_it() {
        let (program, _) =
            crate::parse("1 L X+0 R0 FMAX\n2 LBL 1\n3 L X+1 R0 FMAX\n4 CALL LBL 1 REP 1\n5 M30\n");
        let machine = Machine::builtin("ac-table").expect("shipped");
        let sim = simulate(&program, &machine, &SimOptions::default());
        assert_eq!(sim.step_of_block(0), Some(0));
        assert_eq!(sim.step_of_block(2), Some(2));
        assert_eq!(sim.step_of_block(99), None);
        for b in 0..program.blocks.len() {
            assert_eq!(sim.step_of_block(b), sim.first_step[b].map(|s| s as usize));
        }
    }
}
