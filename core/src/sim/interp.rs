//! The interpreter: one executed block at a time. Cloneable, so a clone is a checkpoint.

use std::collections::BTreeMap;
use std::sync::Arc;

use glam::{DMat3, DVec3};

use crate::angle::short_delta;
use crate::ast::{
    Axis, AxisWord, BinOp, BlkForm, BlockBody, CycleDef, CycleDefOld, Expr, FnJump, FnMath, FnOp, Func,
    Label, Line, OldCycleData, OldCycleWord, Program, RadiusComp, SysRead, ToolCall, ToolRef, Unit,
};
use crate::axes::AxisValues;
use crate::machine::{Carrier, Machine};
use crate::orientation::{self, Context};
use crate::plane::{Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, RotaryAxis, Value};
use crate::solve::{self, Explanation, SolveError, SolveOptions};
use crate::unconfirmed;

use super::collision::{Bodies, Clearances, Collision, SafeAlternative};
use super::cycles::{self, CycleMove};
use super::error::SimErrorCode;
use super::geometry::{Affine, Kin};
use super::note::Note;
use super::segment::{ArcPath, MachineAxes, MovePath, Segment, SegmentKind, SegmentPath, move_linear};
use super::tools;
use super::transform::{Level, Transforms};
mod compensation;
mod contour;
mod cycle_calls;
mod labels;
mod motion;
mod parameters;
mod setup;
mod snapshot;
mod tcpm;
mod tilt;

pub(super) use setup::header_blank;

use super::{
    ActivePlane, Blank, Frame, Frames, LabelKey, Pivot, SimOptions, Spindle, SpindleDir, State, StepMotion,
    TiltSource, ToolState,
};

/// What the run needs besides the interpreter state.
pub(crate) struct Cx<'a> {
    pub program: &'a Program,
    pub machine: &'a Machine,
    pub options: &'a SimOptions,
    pub labels: &'a BTreeMap<LabelKey, usize>,
}

/// What a full-detail step records (segments, message, explanation). The fast run passes none.
#[derive(Debug, Default)]
pub(crate) struct Rec {
    pub segments: Vec<Segment>,
    pub note: Option<Note>,
    pub explanation: Option<Arc<Explanation>>,
}

/// What the parts of one step share: the run's context, the record a full-detail step fills
/// (none in the fast run) and the block being executed.
pub(crate) struct At<'s, 'r> {
    pub cx: &'s Cx<'s>,
    pub rec: Option<&'r mut Rec>,
    pub block: usize,
    /// Whether the step made a positioning motion ([`SegmentKind::is_positioning`]).
    pub positioned: bool,
}

impl At<'_, '_> {
    /// The step's note, made only when a full-detail step records it.
    pub fn note(&mut self, note: impl FnOnce() -> Note) {
        if let Some(r) = self.rec.as_deref_mut() {
            r.note = Some(note());
        }
    }

    /// Whether a full-detail step has no note yet (a cycle call's own note stays).
    pub fn unnoted(&self) -> bool {
        self.rec.as_ref().is_some_and(|r| r.note.is_none())
    }
}

/// What one step did: whether it executed its block (not only listed it) and whether it made a
/// positioning motion (the material check looks at those steps only).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Stepped {
    pub executed: bool,
    pub positioned: bool,
}

/// A stored cycle definition.
#[derive(Debug, Clone, Copy, PartialEq)]
enum StoredCycle {
    /// New-style `CYCL DEF n …` at this block.
    New(usize),
    /// Old-style machining cycle `CYCL DEF n.0`.
    Old(u32),
}

/// Feed of one motion.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Rate {
    Rapid,
    Feed(f64),
}

/// The interpreter state between blocks. Equal states run on alike over the same blocks (a
/// resumed run joins an earlier one where they are equal, [`crate::sim::Simulation::resumed`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Interp {
    /// Index of the next block.
    pub pc: usize,
    /// Executed steps so far.
    pub step_count: usize,
    /// The block of the step just executed.
    pub last: usize,
    /// M30/M2 reached: the rest is listed, not executed.
    ended: bool,
    pub axes: MachineAxes,
    /// The control's position in the I-CS.
    pos_i: DVec3,
    tool: ToolState,
    spindle: Spindle,
    feed: f64,
    blank_min: Option<DVec3>,
    blank: Option<Blank>,
    tf: Transforms,
    pub plane: Option<Arc<ActivePlane>>,
    q: BTreeMap<u32, f64>,
    /// `TOOL DEF n L… R…` of the program: length and radius (each if written) for `TOOL CALL n`.
    tool_defs: Vec<(ToolRef, Option<f64>, Option<f64>)>,
    /// The label calls under way ([`LabelCalls`]).
    labels: LabelCalls,
    kin: Kin,
    /// I-CS → linear axes as the control computes it, for the current rotary axes.
    map: Affine,
    m126: bool,
    /// The cycle 7 definition being read: the shift before its `7.0` header, the words so far.
    c7: Option<Cycle7>,
    /// The contour between its elements ([`Contour`]).
    contour: Contour,
    /// What calls the stored cycle ([`CycleCalls`]).
    calls_cycle: CycleCalls,
    /// TCPM and how it reads rotary words ([`Tcpm`]).
    tcpm: Tcpm,
    /// The collision check's state ([`Checking`]).
    check: Checking,
    /// The unit of `BEGIN PGM`: lengths and feeds are converted to mm where a block uses them.
    unit: Unit,
    /// The last touch-probe cycle run (not simulated: its results are not set).
    probed: Option<u32>,
}

/// The contour's state between its elements: what the next `C`/`CP`, `RND`/`CHF` and the
/// radius compensation take from the blocks before.
#[derive(Debug, Clone, Default, PartialEq)]
struct Contour {
    /// The circle centre / pole of the last `CC` (I-CS).
    pole: Option<contour::Pole>,
    /// The last programmed direction of rotation (+1 = DR+).
    last_dr: Option<f64>,
    /// Direction of travel (in the working plane) at the end of the last contour element.
    tangent: Option<Travel>,
    /// The rounding/chamfer the element just run prepared for the RND/CHF block after it.
    corner: Option<Result<contour::PendingCorner, SimErrorCode>>,
    /// The corner point a RND/CHF cut off: where the next element starts geometrically.
    geom_start: Option<DVec3>,
    /// The tool radius compensation RL/RR (`None`: R0).
    comp: Option<compensation::Comp>,
}

/// A direction of travel in the working plane ([`Contour::tangent`]): a unit vector, or a
/// straight line's travel, made one when a `CT` or a `DEP` asks (a straight line ends almost
/// every block of a program; its direction is asked for by few).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Travel {
    Unit(DVec3),
    Line(DVec3),
}

impl Travel {
    fn unit(self) -> DVec3 {
        match self {
            Travel::Unit(t) => t,
            Travel::Line(t) => t.normalize(),
        }
    }
}

/// What the collision check ([`super::collision`]) carries from block to block.
#[derive(Debug, Clone, Default, PartialEq)]
struct Checking {
    /// The bodies every motion is checked against, for this tool and blank.
    bodies: Option<Arc<Bodies>>,
    /// What the check knows from the motions before ([`Clearances`]).
    clearances: Clearances,
    /// Re-running steps that ran once without a collision ([`Interp::replaying`]): no bodies.
    replay: bool,
}

/// `CALL LBL` under way: where each call returns to, and the repeats (`CALL LBL … REP`) left
/// per calling block.
#[derive(Debug, Clone, Default, PartialEq)]
struct LabelCalls {
    calls: Vec<usize>,
    reps: Vec<(usize, u32)>,
}

/// The tool centre point management.
#[derive(Debug, Clone, Default, PartialEq)]
struct Tcpm {
    /// `M128` is active (TCPM): the tool tip keeps the programmed point while rotary axes move.
    on: bool,
    /// `FUNCTION TCPM … AXIS SPAT` is active: `A`, `B`, `C` in positioning blocks are the spatial
    /// angles SPA, SPB, SPC (modal; `None` before the first positioning block since it was switched on).
    spat: Option<[Option<f64>; 3]>,
}

/// The stored cycle and what calls it.
#[derive(Debug, Clone, Default, PartialEq)]
struct CycleCalls {
    /// The last `CYCL DEF` (with its parameters).
    cycle: Option<StoredCycle>,
    /// The block of the last `PATTERN DEF` (for `CYCL CALL PAT`).
    pattern: Option<usize>,
    /// `M89` is active: every positioning block calls the cycle.
    m89: bool,
}

/// A cycle 7 definition spread over sub-blocks `7.1 X…`, `7.2 Y…`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cycle7 {
    base: DVec3,
    written: [Option<f64>; 3],
    any_absolute: bool,
}

type R<T> = Result<T, SimErrorCode>;

/// The M functions whose effect the run models (HEIDENHAIN's M function overview, DOMAIN.md §8
/// [M:helman-M]): M0/M1 program stop (said: the trainer runs on), M2/M30 end, M3/M4/M5 and
/// M13/M14 the spindle, M89/M99 cycle calls, M91 and M92 machine coordinates
/// ([`unconfirmed::M92_AT_MACHINE_DATUM`]), M126/M127 the rotary axes' shortest path, M128/M129
/// TCPM. Every other one is said on its block as not simulated, so that no block passes
/// silently: coolant, M90, M94,
/// M109/M110/M116/M136 (feeds: the run's times take F in mm/min on the path), M120, M197, M140
/// without MB (with MB the retraction says itself), M6 (the trainer changes tools at TOOL
/// CALL) and the machine makers' own numbers.
const MODELED_M: [u32; 17] = [0, 1, 2, 3, 4, 5, 13, 14, 30, 89, 91, 92, 99, 126, 127, 128, 129];

/// Animation time of a STAY swivel, seconds: nothing moves on the machine, so no feed gives a
/// duration; one second lets the view show the coordinate system turning (derived, display only).
pub const STAY_SECONDS: f64 = 1.0;

/// What a block's M functions tell the trainee: TCPM switched on or off, a program stop, M92's
/// assumed datum, or the functions the simulator does not model.
fn m_note(at: &mut At<'_, '_>, m: &[u32]) {
    if m.contains(&128) {
        at.note(|| Note::TcpmOn { word: "M128", spatial: false });
    } else if m.contains(&129) {
        at.note(|| Note::TcpmOff { word: "M129" });
    } else if m.contains(&0) {
        at.note(|| Note::Halt { word: "M0" });
    } else if m.contains(&1) {
        at.note(|| Note::OptionalStop);
    } else if m.contains(&92) {
        at.note(|| Note::Assumed { decision: unconfirmed::Decision::M92Datum });
    } else if m.iter().any(|f| !MODELED_M.contains(f)) {
        at.note(|| Note::MNotSimulated { m: m.iter().copied().filter(|f| !MODELED_M.contains(f)).collect() });
    }
}

fn rotary_of(axis: Axis) -> Option<RotaryAxis> {
    match axis {
        Axis::A => Some(RotaryAxis::A),
        Axis::B => Some(RotaryAxis::B),
        Axis::C => Some(RotaryAxis::C),
        _ => None,
    }
}

pub(super) fn linear_index(axis: Axis) -> Option<usize> {
    match axis {
        Axis::X => Some(0),
        Axis::Y => Some(1),
        Axis::Z => Some(2),
        _ => None,
    }
}

fn letter(axis: Axis) -> char {
    axis.as_str().chars().next().unwrap_or('?')
}

impl Interp {
    pub fn new(machine: &Machine) -> Interp {
        let j = machine.joints();
        let (entry, _) = tools::lookup(&ToolRef::Number(0));
        let tool = ToolState {
            number: 0,
            name: String::new(),
            axis: 'Z',
            length: entry.length,
            radius: entry.radius,
            shape: entry.shape(entry.radius),
            known: false,
            feed: 0.0,
        };
        let kin = Kin::new(machine, tool.length);
        let axes = MachineAxes {
            linear: machine.geometry.start,
            rotary: [0.0, 0.0],
            letters: [j[0].axis, j[1].axis],
        };
        let mut it = Interp {
            pc: 0,
            step_count: 0,
            last: 0,
            ended: false,
            axes,
            pos_i: DVec3::ZERO,
            tool,
            spindle: Spindle { speed: 0.0, dir: SpindleDir::Off },
            feed: 0.0,
            blank_min: None,
            blank: None,
            tf: Transforms::default(),
            plane: None,
            q: BTreeMap::new(),
            tool_defs: Vec::new(),
            labels: LabelCalls::default(),
            kin,
            map: Affine::IDENTITY,
            m126: false,
            c7: None,
            contour: Contour::default(),
            calls_cycle: CycleCalls::default(),
            tcpm: Tcpm::default(),
            check: Checking::default(),
            unit: Unit::Mm,
            probed: None,
        };
        it.rebuild_bodies(machine);
        it.refresh();
        it.pos_i = it.map.inverse_orthogonal().apply(it.axes.linear);
        it
    }

    /// What the run assumed or left out that led to the stop `code`: the size of a tool the
    /// table does not have (the default tool's, as its TOOL CALL said:
    /// [`Note::ToolNotInTable`]) or of no tool called (T0), a touch-probe cycle's result never
    /// measured.
    pub fn because(&self, code: &SimErrorCode) -> Option<crate::lang::Text> {
        let t = &self.tool;
        if code.depends_on_tool_size() && !t.known {
            if t.number == 0 && t.name.is_empty() {
                return Some(super::error::no_tool(t.length, t.radius));
            }
            let assumed = Note::ToolNotInTable {
                number: t.number,
                name: t.name.clone(),
                length: t.length,
                radius: t.radius,
            };
            return Some(assumed.text());
        }
        self.probed.filter(|_| code.is_probe_result()).map(super::error::unprobed)
    }

    pub fn done(&self, program: &Program) -> bool {
        self.pc >= program.blocks.len()
    }

    /// Whether a later step may read one of `blocks` through this state without running it:
    /// the stored cycle's definition, the last `PATTERN DEF`.
    pub fn refers_into(&self, blocks: &std::ops::Range<usize>) -> bool {
        matches!(self.calls_cycle.cycle, Some(StoredCycle::New(b)) if blocks.contains(&b))
            || self.calls_cycle.pattern.is_some_and(|b| blocks.contains(&b))
    }

    /// The linear axes follow the rotary axes: with a tilt, and always with TCPM (M128), which
    /// is the kinematic transformation itself (DOMAIN.md §6).
    fn compensating(&self) -> bool {
        self.tcpm.on || self.tf.tilt.is_some() || !unconfirmed::COMPENSATION_ONLY_WHEN_TILTED
    }

    /// W-CS → linear axes as the control computes it for rotary axes `rotary`.
    fn wcs_to_linear(&self, rotary: [f64; 2]) -> Affine {
        if self.compensating() {
            self.kin.wcs_to_linear(rotary)
        } else {
            Affine { m: DMat3::IDENTITY, v: self.kin.preset }
        }
    }

    fn refresh(&mut self) {
        self.map = self.wcs_to_linear(self.axes.rotary).after(&self.tf.ics_to_wcs());
    }

    fn sync_pos(&mut self) {
        self.refresh();
        self.pos_i = self.map.inverse_orthogonal().apply(self.axes.linear);
    }

    /// A programmed length in mm (`INCH` programs: × 25.4).
    fn length(&self, v: &Value) -> R<f64> {
        Ok(self.value(v)? * self.unit.mm())
    }

    /// A programmed feed F in mm/min ([`Unit::feed_mm_per_min`]).
    fn feed_rate(&self, v: &Value) -> R<f64> {
        Ok(self.value(v)? * self.unit.feed_mm_per_min())
    }

    /// A length in mm as the program writes it (what Q108, Q114 and SYSREAD give an `INCH`
    /// program).
    fn in_program_unit(&self, mm: f64) -> f64 {
        mm / self.unit.mm()
    }

    /// Executes the next block; `Ok(false)` if it was only listed (after M30, or skipped).
    pub fn step(&mut self, cx: &Cx<'_>, rec: Option<&mut Rec>) -> R<Stepped> {
        let mut at = At { cx, rec, block: self.pc, positioned: false };
        let executed = self.step_at(&mut at)?;
        Ok(Stepped { executed, positioned: at.positioned })
    }

    fn step_at(&mut self, at: &mut At<'_, '_>) -> R<bool> {
        let (cx, idx) = (at.cx, self.pc);
        let Some(block) = cx.program.blocks.get(idx) else {
            self.pc = cx.program.blocks.len();
            return Ok(false);
        };
        self.pc += 1;
        self.step_count += 1;
        self.last = idx;
        let body = block.body();
        if self.ended {
            if matches!(*body, BlockBody::EndPgm { .. }) {
                self.pc = cx.program.blocks.len();
            }
            at.note(|| Note::AfterEnd);
            return Ok(false);
        }
        if block.skip() && cx.options.block_skip {
            at.note(|| Note::BlockSkipped);
            return Ok(false);
        }
        if !matches!(&*body, BlockBody::CycleDefOld(d) if d.number == 7) {
            self.c7 = None;
        }
        // A prepared rounding belongs to the block right after the element that prepared it.
        let pending_corner = self.contour.corner.take();
        match &*body {
            BlockBody::BeginPgm { unit, .. } => {
                // Q113: the unit of the program (preassigned, TNC 410 user's manual "Preassigned
                // Q parameters": 0 mm, 1 inch).
                self.q.insert(113, if *unit == Unit::Inch { 1.0 } else { 0.0 });
                self.unit = *unit;
                if *unit == Unit::Inch {
                    at.note(|| Note::Inch);
                }
            }
            BlockBody::Empty | BlockBody::Structure { .. } => {}
            BlockBody::EndPgm { .. } => {
                self.ended = true;
                self.pc = cx.program.blocks.len();
            }
            BlockBody::BlkForm(b) => self.blk_form(cx, b)?,
            BlockBody::ToolCall(t) => self.tool_call(at, t)?,
            BlockBody::L(line) => {
                self.line(at, line)?;
                if let Some(mb) = line.m_words.mb {
                    self.m140(at, mb, line.m_words.mb_feed)?;
                }
                self.modal_call(at, line)?;
            }
            BlockBody::MFunctions(m, w) => {
                self.m_functions(at, m);
                if let Some(mb) = w.mb {
                    self.m140(at, mb, w.mb_feed)?;
                }
                if m.contains(&99) {
                    self.call_cycle(at)?;
                }
                self.calls_cycle.m89 = m.contains(&89) || (self.calls_cycle.m89 && !m.contains(&99));
                self.end_m(m);
            }
            // A new cycle definition ends a modal M89 call (iTNC 530 cycle manual: "define a new
            // cycle with CYCL DEF"; DOMAIN.md §11); a CYCL CALL does not (the TNC 306/406 rule).
            BlockBody::CycleDef(d) => {
                self.calls_cycle.m89 = false;
                self.cycle_def(at, d)?;
            }
            BlockBody::CyclCall { m } => {
                self.m_functions(at, m);
                self.call_cycle(at)?;
                self.end_m(m);
            }
            BlockBody::Plane(p) => self.plane(at, p)?,
            BlockBody::Invalid { .. } => return Err(SimErrorCode::InvalidBlock),
            _ => self.other_block(at, &body, pending_corner)?,
        }
        Ok(true)
    }

    /// The blocks Musterprogramm 1 (the first screen's program) does not have: out of line, so
    /// that `step` stays small and the page split leaves their code to the wasm loaded after
    /// the first screen.
    #[inline(never)]
    fn other_block(
        &mut self,
        at: &mut At<'_, '_>,

        body: &BlockBody,
        pending_corner: Option<Result<contour::PendingCorner, SimErrorCode>>,
    ) -> R<()> {
        match body {
            BlockBody::Header { text } => self.header(at, text),
            BlockBody::ToolDef { .. }
            | BlockBody::Stop { .. }
            | BlockBody::QsAssign { .. }
            | BlockBody::TouchProbe(_) => self.program_data(at, body)?,
            BlockBody::Cc(m) => {
                let last = self.contour.geom_start.unwrap_or(self.programmed());
                self.contour.pole = Some(self.pole_of(&m.axes, last)?);
                at.note(|| Note::CircleCentre);
            }
            BlockBody::C(m) | BlockBody::Cr(m) | BlockBody::Ct(m) | BlockBody::Lp(m) | BlockBody::Cp(m) => {
                self.contour(at, body, m)?;
            }
            BlockBody::Rnd { feed, .. } => {
                self.corner_block(at, "RND", feed.as_ref(), pending_corner)?;
            }
            BlockBody::Chf { feed, .. } => {
                self.corner_block(at, "CHF", feed.as_ref(), pending_corner)?;
            }
            BlockBody::Appr(a) => self.approach(at, a)?,
            BlockBody::Dep(a) => self.depart(at, a)?,
            BlockBody::CyclCallPat { feed, m } => self.call_pattern(at, feed.as_ref(), m)?,
            BlockBody::CyclCallPos(l) => self.call_pos(at, l)?,
            BlockBody::PatternDef(items) => {
                self.calls_cycle.pattern = Some(at.block);
                at.note(|| Note::PatternDef { items: items.len() });
            }
            BlockBody::FnMath(f) => self.fn_math(f)?,
            BlockBody::FnJump(j) => self.fn_jump(at.cx, j)?,
            BlockBody::CycleDefOld(d) => {
                self.calls_cycle.m89 &= d.sub != 0;
                self.old_cycle(at, d)?;
            }
            BlockBody::TransDatum { axes } => self.datum(axes)?,
            BlockBody::TransDatumReset => {
                self.tf.datum_w = DVec3::ZERO;
                self.tf.datum_i = DVec3::ZERO;
                self.sync_pos();
            }
            BlockBody::TransMirror { axes } => self.mirror(axes),
            BlockBody::TransMirrorReset => {
                self.tf.mirror_w = [false; 3];
                self.tf.mirror_i = [false; 3];
                self.sync_pos();
            }
            BlockBody::TransRotation { rot, incremental } => self.rotation(rot, *incremental)?,
            BlockBody::TransRotationReset => {
                self.tf.rotation = 0.0;
                self.sync_pos();
            }
            BlockBody::FunctionTcpm(t) => self.function_tcpm(at, *t),
            BlockBody::FunctionResetTcpm => self.function_reset_tcpm(at),
            BlockBody::Lbl(l) => {
                if *l == Label::Number(0)
                    && let Some(ret) = self.labels.calls.pop()
                {
                    self.pc = ret;
                }
            }
            BlockBody::CallLbl { label, rep } => {
                let rep = rep.map(|v| self.repeats(&v)).transpose()?;
                self.call_lbl(at.cx, at.block, label, rep)?;
            }
            BlockBody::CallPgm { path } => at.note(|| Note::CallPgm { path: path.clone() }),
            BlockBody::QAssign { target, expr, .. } => self.q_assign(*target, expr)?,
            BlockBody::SysRead(r) => self.sysread(at, r)?,
            BlockBody::FnOther { number, text } => self.fn_other(at, *number, text)?,
            BlockBody::Unknown { text } => at.note(|| Note::BlockNotSimulated { text: text.clone() }),
            // Run by `step` itself; listed so that a new block kind needs a decision here.
            BlockBody::BeginPgm { .. }
            | BlockBody::Empty
            | BlockBody::Structure { .. }
            | BlockBody::EndPgm { .. }
            | BlockBody::BlkForm(_)
            | BlockBody::ToolCall(_)
            | BlockBody::L(_)
            | BlockBody::MFunctions(..)
            | BlockBody::CycleDef(_)
            | BlockBody::CyclCall { .. }
            | BlockBody::Plane(_)
            | BlockBody::Invalid { .. } => {}
        }
        Ok(())
    }

    /// A block's M functions: their effect on the state, and what they tell the trainee.
    fn m_functions(&mut self, at: &mut At<'_, '_>, m: &[u32]) {
        self.spindle_m(m);
        m_note(at, m);
    }

    /// The M functions' effect on the spindle and the modal switches.
    fn spindle_m(&mut self, m: &[u32]) {
        for &f in m {
            match f {
                // M13/M14: the spindle with coolant; M0 and M6 stop the spindle (the overview
                // above MODELED_M).
                3 | 13 => self.spindle.dir = SpindleDir::Cw,
                4 | 14 => self.spindle.dir = SpindleDir::Ccw,
                0 | 5 | 6 => self.spindle.dir = SpindleDir::Off,
                126 => self.m126 = true,
                127 => self.m126 = false,
                // From the block's start (unconfirmed::TCPM_FROM_BLOCK_START); the programmed
                // position is taken anew from where the tool tip is.
                128 if unconfirmed::TCPM_FROM_BLOCK_START => self.set_tcpm(true),
                _ => {}
            }
        }
    }

    fn end_m(&mut self, m: &[u32]) {
        self.tcpm_at_block_end(m);
        if m.iter().any(|&f| f == 30 || f == 2) {
            self.spindle.dir = SpindleDir::Off;
            self.ended = true;
            if !unconfirmed::LIST_BLOCKS_AFTER_END {
                self.pc = usize::MAX;
            }
        }
    }
}
