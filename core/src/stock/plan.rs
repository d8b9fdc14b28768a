//! The cuts of a whole run, in order, and the stock after any step: [`Cutting`] turns every
//! motion segment of the simulation into straight sweeps in the W-CS once, cuts them all once
//! (for the notes and a few checkpoints) and replays them from the nearest checkpoint on demand.

use glam::DVec3;

use crate::Text;
use crate::ast::Program;
use crate::sim::collision::segment_segment_distance;
use crate::sim::{Blank, Kin, Segment, SegmentKind, SegmentPath, Simulation, StepMotion, ToolState};

use super::{Cutter, Part, Removal, RowAt, Stamp, Stock, StockError};

mod collisions;

pub use collisions::Collisions;

/// A positioning motion that removes more than this from one ray (mm) has entered the material;
/// less is grazing or roundoff (1 µm, the control's display resolution).
const ENTERS_MATERIAL: f64 = 1e-3;

/// Rays between two checkpoints at first (about 20 ms of cutting in a release build).
const FIRST_CHECKPOINT_RAYS: usize = 200_000;

/// Copying a checkpoint (a few MB) costs about as much as computing this many rays: a cursor
/// behind a checkpoint by less work cuts its way there instead.
const CHECKPOINT_COPY_RAYS: usize = 50_000;

/// Consecutive cuts with the same cutter and tool axis along one straight line are cut as one
/// sweep while it is at most this share of the resolution long: a CAM program's moves of a few
/// hundredths of a millimetre each cost a whole cut of the tool's footprint (the 592 KB CAM class:
/// 48.5 million rays for 14,000 moves, issue 32), while their union is the sweep of the chord.
/// The stock after a step then lags its tool by less than half the ray spacing (the merged cut
/// belongs to its last step), which the grid does not show.
const MERGE_LENGTH: f64 = 0.5;

/// Merged cuts never cross a multiple of this many steps, and the plan goes in shares of
/// multiples of it ([`Cutting::plan_on`]): which cuts merge depends on the run alone, not on how
/// its planning was shared out (a merge across two shares would grow a cut a cursor may have
/// made already).
const MERGE_STEPS: usize = 8;

/// The points of merged cuts lie within this share of the resolution of their chord: the sweep
/// of the chord and the sweeps of the pieces differ by at most that (a Hausdorff distance of
/// 1/64 of the spacing, far inside the quarter the arcs' chords allow).
const MERGE_DEVIATION: f64 = 1.0 / 64.0;

/// Most sub-moves of one turning motion (a swivel of 180° of a 100 mm tool at 0.25 mm needs
/// about 5,000): bounds the work of absurd programs.
const MAX_SUB_MOVES: usize = 10_000;

/// Options of the stock.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StockOptions {
    /// Ray spacing, mm.
    pub resolution: f64,
    /// Stocks kept along the run besides the blank, spaced evenly over the work of the cuts
    /// (rays computed): stepping back re-cuts at most the work between two of them. With any,
    /// the final stock is kept too.
    pub checkpoints: usize,
}

impl Default for StockOptions {
    /// 0.25 mm, the resolution the issue asks for on Musterprogramm 1's blank; three checkpoints
    /// keep four stocks of that blank at about 7 MB each.
    fn default() -> Self {
        StockOptions { resolution: 0.25, checkpoints: 3 }
    }
}

/// What the stock reports about a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StockNoteKind {
    /// A rapid (FMAX, or an MB retract) removed material: the tool ran into the blank at rapid
    /// traverse, a collision.
    RapidIntoMaterial,
    /// The swivel of a PLANE … MOVE/TURN removed material: the tool was turned while in the
    /// material, a collision that retracting first (`MB MAX`) avoids.
    SwivelInMaterial,
    /// The blank needs more rays than [`super::MAX_RAYS`] at the resolution asked for.
    ResolutionCapped { asked: f64, used: f64 },
    /// The blank has no volume or is not finite: no stock.
    InvalidBlank,
}

/// A note on one executed step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StockNote {
    pub step: usize,
    /// Index of the block in the program.
    pub block: usize,
    pub kind: StockNoteKind,
}

impl StockNote {
    /// Whether the note is a collision of the tool with the material.
    #[must_use]
    pub fn is_collision(&self) -> bool {
        matches!(self.kind, StockNoteKind::RapidIntoMaterial | StockNoteKind::SwivelInMaterial)
    }

    /// The message, German and English.
    #[must_use]
    pub fn message(&self) -> Text {
        match self.kind {
            StockNoteKind::RapidIntoMaterial => Text::new(
                "Eilgang ins Material: Kollision Werkzeug – Rohteil",
                "Rapid traverse into the material: collision of the tool with the blank",
            ),
            StockNoteKind::SwivelInMaterial => Text::new(
                "Schwenken mit dem Werkzeug im Material: Kollision – vorher freifahren (MB MAX)",
                "Swivelling with the tool in the material: collision – retract first (MB MAX)",
            ),
            StockNoteKind::ResolutionCapped { asked, used } => Text::owned(
                format!("Rohteil zu groß für {asked:.2} mm Auflösung: {used:.2} mm verwendet"),
                format!("Blank too large for a resolution of {asked:.2} mm: using {used:.2} mm"),
            ),
            StockNoteKind::InvalidBlank => Text::new(
                "Rohteil ohne Volumen: kein Materialabtrag",
                "Blank without volume: no material removal",
            ),
        }
    }
}

/// One thing that happens to the stock.
#[derive(Debug, Clone, PartialEq)]
enum Action {
    /// A BLK FORM took effect: the stock starts over from this blank.
    Blank(Blank),
    /// A straight sweep (W-CS) with a fixed tool axis; `motion` says whether the tool may cut.
    Cut { cutter: usize, axis: DVec3, from: DVec3, to: DVec3, motion: Motion },
}

/// What a sweep is for: a cut, or a positioning that must not touch the material.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Motion {
    Cut,
    /// FMAX, or the MB retract before a swivel (the control moves it at rapid).
    Rapid,
    /// The turn of PLANE … MOVE/TURN: a positioning of the rotary axes, never a cut.
    Swivel,
}

impl Motion {
    fn of(kind: SegmentKind) -> Motion {
        match kind {
            SegmentKind::Rapid | SegmentKind::Retract => Motion::Rapid,
            SegmentKind::SwivelMove | SegmentKind::SwivelTurn => Motion::Swivel,
            SegmentKind::Feed | SegmentKind::SwivelStay | SegmentKind::CycleFeed => Motion::Cut,
        }
    }

    /// The note of a positioning motion that removed material.
    fn note(self) -> Option<StockNoteKind> {
        match self {
            Motion::Cut => None,
            Motion::Rapid => Some(StockNoteKind::RapidIntoMaterial),
            Motion::Swivel => Some(StockNoteKind::SwivelInMaterial),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
struct Event {
    step: usize,
    /// Index of the block in the program.
    block: usize,
    /// Fraction of the step's motion time at which this event is complete.
    end: f64,
    action: Action,
}

/// The stock as it stands after some events; reusable, so stepping forward only cuts what is
/// new.
#[derive(Debug, Clone, Default)]
pub struct StockCursor {
    /// `None` before the first BLK FORM, or for a blank without volume.
    pub stock: Option<Stock>,
    /// Events applied.
    applied: usize,
    /// Where event `applied` stands when it is applied in part ([`Cutting::advance`]), and the
    /// stamps its parts gave so far.
    partial: Option<RowAt>,
    partial_stamps: Vec<Stamp>,
    /// Bumped whenever the stock changes (the view re-meshes when it differs).
    pub version: u64,
}

/// The cuts of a run.
#[derive(Debug, Clone)]
pub struct Cutting {
    options: StockOptions,
    events: Vec<Event>,
    /// `step_events[k]` = index of the first event of step `k` (one more entry at the end).
    step_events: Vec<usize>,
    cutters: Vec<Cutter>,
    /// `(events applied, stock)`, ascending.
    checkpoints: Vec<(usize, Option<Stock>)>,
    /// `work[k]`: the work ([`Removal::work`]) of the first `k` events (one more entry than
    /// events).
    work: Vec<usize>,
    /// Notes, by step (of the part the first pass has cut, [`Cutting::passed`]).
    pub notes: Vec<StockNote>,
    /// This run's number in the tiles' stamps.
    run: u64,
    /// The first pass under way (`None` once every event was cut once).
    pass: Option<FirstPass>,
    /// Where planning stands (`None` once every step is planned).
    planning: Option<Planning>,
    /// The last event's index and the points of the cuts merged into it ([`MERGE_LENGTH`]), while
    /// more may join it.
    chain: Option<(usize, Vec<DVec3>)>,
}

/// The next step to plan and what the steps before it left in effect.
#[derive(Debug, Clone, Default)]
struct Planning {
    next: usize,
    blank: Option<Blank>,
    tool: Option<(ToolState, usize)>,
}

/// Where the first pass stands: it cuts every event once, in parts, for the notes and the
/// checkpoints ([`Cutting::pass_on`]).
#[derive(Debug, Clone, Default)]
struct FirstPass {
    cursor: StockCursor,
    last_rapid_note: Option<usize>,
    /// Rays between two checkpoints; doubles when there would be too many.
    budget: usize,
    /// Rays since the last checkpoint.
    since: usize,
    /// The parts of a cut made so far (a cut may stop between two rows).
    removal: Removal,
}

impl Cutting {
    /// The cuts of `sim` (a run of `program`); cuts everything once to find the notes and to
    /// place the checkpoints.
    #[must_use]
    pub fn new(program: &Program, sim: &Simulation, options: StockOptions) -> Cutting {
        let mut c = Cutting::planned(program, sim, options);
        c.pass_on(usize::MAX);
        c
    }

    /// The cuts of `sim` planned, none cut yet: the first pass (notes, checkpoints) goes on a
    /// bounded share at a time with [`Cutting::pass_on`], so that switching the stock on in the
    /// browser never blocks a frame (classroom trial II: 0.85 s). Seeking works at once; it
    /// only has fewer checkpoints to start from until the pass is done.
    #[must_use]
    pub fn planned(program: &Program, sim: &Simulation, options: StockOptions) -> Cutting {
        let mut c = Cutting::unplanned(options);
        c.plan_on(program, sim, usize::MAX);
        c
    }

    /// The cuts of a run, none planned yet: [`Cutting::plan_on`] plans its steps a share at a
    /// time (planning a 100,000-block run at once took 0.2 s natively, a long task in the
    /// browser). Until a step is planned, seeking it does not get there
    /// ([`Cutting::advance`] says so) and the first pass is not done.
    #[must_use]
    pub fn unplanned(options: StockOptions) -> Cutting {
        Cutting {
            options,
            events: Vec::new(),
            step_events: vec![0],
            cutters: Vec::new(),
            checkpoints: vec![(0, None)],
            work: vec![0],
            notes: Vec::new(),
            run: Stamp::run(),
            pass: Some(FirstPass { budget: FIRST_CHECKPOINT_RAYS, ..FirstPass::default() }),
            planning: Some(Planning::default()),
            chain: None,
        }
    }

    /// Plans `steps` more steps of `sim` (the run of `program`), up to the next multiple of
    /// `MERGE_STEPS`; returns whether every step is planned. A share that starts on a multiple of the simulation's checkpoint
    /// interval re-simulates nothing twice ([`Simulation::states_from`]).
    pub fn plan_on(&mut self, program: &Program, sim: &Simulation, steps: usize) -> bool {
        let Some(mut p) = self.planning.take() else { return true };
        // Events planned before may have been cut already: none of them grows (a share ends on
        // a multiple of MERGE_STEPS, where no merge goes on anyway).
        self.chain = None;
        // The entry after the last planned step goes and comes back at the end.
        self.step_events.pop();
        let end = p.next.saturating_add(steps).checked_next_multiple_of(MERGE_STEPS).unwrap_or(usize::MAX);
        let wanted = (end - p.next).min(sim.len().saturating_sub(p.next));
        let mut got = 0;
        for state in sim.motions_from(program, p.next).take(wanted) {
            got += 1;
            self.step_events.push(self.events.len());
            if state.blank != p.blank {
                p.blank = state.blank;
                if let Some(b) = p.blank {
                    self.push_event(Event {
                        step: state.step,
                        block: state.block,
                        end: 0.0,
                        action: Action::Blank(b),
                    });
                }
            }
            if state.segments.is_empty() {
                continue;
            }
            let cutter = match &p.tool {
                Some((t, k)) if *t == state.tool => *k,
                _ => {
                    self.cutters.push(self.cutter(&state.tool));
                    p.tool = Some((state.tool.clone(), self.cutters.len() - 1));
                    self.cutters.len() - 1
                }
            };
            self.plan_step(sim, &state, cutter);
        }
        self.step_events.push(self.events.len());
        p.next += got;
        // A run whose states end early (it cannot be re-simulated) is planned as far as it goes.
        let done = got < wanted || p.next >= sim.len();
        if !done {
            self.planning = Some(p);
        }
        done
    }

    /// The cutter of `tool`; the bull nose's profile error is a quarter of the resolution
    /// (sweep.rs).
    fn cutter(&self, tool: &ToolState) -> Cutter {
        Cutter::new(tool.shape, tool.radius, tool.length, self.options.resolution / 4.0)
    }

    /// Whether step `step` is planned.
    fn is_planned(&self, step: usize) -> bool {
        self.planning.is_none() || step + 1 < self.step_events.len()
    }

    /// The sweeps of one step's segments (see the module doc of [`super`]).
    fn plan_step(&mut self, sim: &Simulation, state: &StepMotion, cutter: usize) {
        let kin = Kin::new(&sim.machine, state.tool.length);
        let total = state.duration();
        let (step, block) = (state.step, state.block);
        let (radius, length) = (self.cutters[cutter].radius, self.cutters[cutter].length);
        let mut elapsed = 0.0;
        for (k, seg) in state.segments.iter().enumerate() {
            let frac = |f: f64| {
                if total > 0.0 {
                    ((elapsed + f * seg.duration) / total).min(1.0)
                } else {
                    (k + 1) as f64 / state.segments.len() as f64
                }
            };
            let motion = Motion::of(seg.kind);
            let cut = |f: f64, axis: DVec3, from: DVec3, to: DVec3| Event {
                step,
                block,
                end: frac(f),
                action: Action::Cut { cutter, axis, from, to, motion },
            };
            match &seg.path {
                SegmentPath::Stay { .. } => {}
                SegmentPath::Linear if seg.rotary_delta == [0.0; 2] => {
                    // Fixed orientation: the tip moves on a straight line in the W-CS, one exact
                    // sweep; split into pieces of at least four diameters (each piece tests the
                    // rays of its box again) only so that an animated block shows the cut
                    // advancing.
                    let (from, to) = (kin.tip_wcs(&seg.start), kin.tip_wcs(&seg.end));
                    let axis = kin.tool_axis_wcs(seg.start.rotary);
                    let piece = (8.0 * radius).max(20.0);
                    let n = ((from.distance(to) / piece).ceil() as usize).clamp(1, 64);
                    for i in 0..n {
                        let (fa, fb) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                        self.push_event(cut(fb, axis, from.lerp(to, fa), from.lerp(to, fb)));
                    }
                }
                SegmentPath::Arc(arc) => {
                    // Straight pieces whose chord error, the sagitta r·(1 − cos(θ/2)) of a piece
                    // turning θ on radius r, stays below a quarter of the resolution:
                    // θ ≤ 2·acos(1 − (res/4)/r). A helix rises linearly, so its pieces deviate
                    // from it by the same sagitta.
                    let (r, tolerance) = (arc.radius(), self.options.resolution / 4.0);
                    let step =
                        if r > tolerance { 2.0 * (1.0 - tolerance / r).acos() } else { std::f64::consts::PI };
                    let n = ((arc.sweep.abs() / step).ceil() as usize).clamp(1, MAX_SUB_MOVES);
                    let axis = kin.tool_axis_wcs(seg.start.rotary);
                    for i in 0..n {
                        let (fa, fb) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                        let (from, to) = (kin.tip_wcs(&seg.axes_at(fa)), kin.tip_wcs(&seg.axes_at(fb)));
                        self.push_event(cut(fb, axis, from, to));
                    }
                }
                _ => {
                    let n = sub_moves(&kin, seg, radius + length, self.options.resolution);
                    for i in 0..n {
                        let (fa, fb) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                        let axis = kin.tool_axis_wcs(seg.axes_at(0.5 * (fa + fb)).rotary);
                        let (from, to) = (kin.tip_wcs(&seg.axes_at(fa)), kin.tip_wcs(&seg.axes_at(fb)));
                        self.push_event(cut(fb, axis, from, to));
                    }
                }
            }
            elapsed += seg.duration;
        }
    }

    /// Appends `event`, or merges a cut into the last event when both are cuts of the same
    /// cutter and tool axis whose points stay on one short straight line ([`MERGE_LENGTH`],
    /// [`MERGE_DEVIATION`]): the merged cut belongs to the step of its last piece.
    fn push_event(&mut self, event: Event) {
        let index = self.events.len();
        let Action::Cut { cutter, axis, from, to, motion: Motion::Cut } = event.action else {
            self.chain = None;
            self.events.push(event);
            return;
        };
        let res = self.options.resolution;
        let merged = match (&mut self.chain, self.events.last()) {
            (
                Some((at, points)),
                Some(Event {
                    step: s,
                    action: Action::Cut { cutter: c, axis: a, from: start, to: end, .. },
                    ..
                }),
            ) if *at + 1 == index
                && *s / MERGE_STEPS == event.step / MERGE_STEPS
                && *c == cutter
                && *a == axis
                && *end == from
                && start.distance(to) <= MERGE_LENGTH * res
                && points
                    .iter()
                    .all(|&q| segment_segment_distance(q, q, *start, to) <= MERGE_DEVIATION * res) =>
            {
                points.push(to);
                Some(*start)
            }
            _ => None,
        };
        match merged {
            Some(start) => {
                // The last event moves to this step: the steps after its own start behind it.
                let last = index - 1;
                for e in self.step_events.iter_mut().rev().take_while(|e| **e > last) {
                    *e = last;
                }
                self.events[last] = Event {
                    action: Action::Cut { cutter, axis, from: start, to, motion: Motion::Cut },
                    ..event
                };
            }
            None => {
                self.chain = Some((index, vec![from, to]));
                self.events.push(event);
            }
        }
    }

    /// Goes on with the first pass by about `rays` rays (a cut may stop between two rows and go
    /// on in the next call); returns whether it is done (never before every step is planned).
    /// It cuts every event once: the notes,
    /// the work up to each event, and the checkpoints evenly over the work. The total is known
    /// only at the end, so a checkpoint is taken after every `budget` rays; when there are too
    /// many, every other one goes and the budget doubles (so they stay within a factor of two of
    /// even).
    pub fn pass_on(&mut self, rays: usize) -> bool {
        let Some(mut pass) = self.pass.take() else { return true };
        let mut spent = 0usize;
        while pass.cursor.applied < self.events.len() && spent < rays {
            let k = pass.cursor.applied;
            // Checkpoints only between events: a part-cut stock is never kept.
            if pass.cursor.partial.is_none() && pass.since >= pass.budget && self.options.checkpoints > 0 {
                self.checkpoints.push((k, pass.cursor.stock.clone()));
                pass.since = 0;
                if self.checkpoints.len() > self.options.checkpoints + 1 {
                    let mut i = 0;
                    // Keep the blank (index 0) and every second checkpoint after it.
                    self.checkpoints.retain(|_| {
                        i += 1;
                        i == 1 || i % 2 == 1
                    });
                    pass.budget *= 2;
                }
            }
            let event = &self.events[k];
            let (step, block) = (event.step, event.block);
            let positioning = match event.action {
                Action::Cut { motion, .. } => motion.note(),
                Action::Blank(_) => None,
            };
            let applied = match (&event.action, pass.cursor.stock.as_mut()) {
                (Action::Cut { cutter, axis, from, to, .. }, Some(stock)) => {
                    // The whole cut's stamp on every part: no one sees the stock before it is
                    // done (the pass's cursor is its own).
                    let start = pass.cursor.partial.take().unwrap_or_default();
                    let part = Part { start, budget: rays - spent, stamp: Stamp::done(self.run, k) };
                    let (r, rest) = stock.cut_part(&self.cutters[*cutter], *axis, *from, *to, part);
                    spent += r.work().max(1);
                    if r.depth > 0.0 {
                        pass.cursor.version += 1;
                    }
                    let sum = &mut pass.removal;
                    sum.volume += r.volume;
                    sum.depth = sum.depth.max(r.depth);
                    (sum.rays, sum.visited, sum.tiles) =
                        (sum.rays + r.rays, sum.visited + r.visited, sum.tiles + r.tiles);
                    pass.cursor.partial = rest;
                    if rest.is_some() {
                        continue;
                    }
                    pass.cursor.applied += 1;
                    Applied::Removed(std::mem::take(&mut pass.removal))
                }
                _ => {
                    spent += 1;
                    self.apply(&mut pass.cursor, k)
                }
            };
            let mut work = 0;
            match applied {
                Applied::Removed(r) => {
                    pass.since += r.rays;
                    work = r.work();
                    if let Some(kind) = positioning
                        && r.depth > ENTERS_MATERIAL
                        && pass.last_rapid_note != Some(step)
                    {
                        pass.last_rapid_note = Some(step);
                        self.notes.push(StockNote { step, block, kind });
                    }
                }
                Applied::NewStock { asked, used } => {
                    if (used - asked).abs() > 1e-9 {
                        self.notes.push(StockNote {
                            step,
                            block,
                            kind: StockNoteKind::ResolutionCapped { asked, used },
                        });
                    }
                }
                Applied::NoStock => {
                    self.notes.push(StockNote { step, block, kind: StockNoteKind::InvalidBlank });
                }
            }
            let before = self.work.last().copied().unwrap_or(0);
            self.work.push(before + work);
        }
        let done = pass.cursor.applied >= self.events.len() && self.planning.is_none();
        if !done {
            self.pass = Some(pass);
        } else if self.options.checkpoints > 0
            && self.checkpoints.last().is_some_and(|(at, _)| *at < self.events.len())
        {
            // The pass's own stock is the final one: kept, the end (the CLI's STL, a jump to
            // the last block) needs no second cut.
            self.checkpoints.push((self.events.len(), pass.cursor.stock.take()));
        }
        done
    }

    /// The steps the first pass has cut (their notes are known): all of them once it is done.
    #[must_use]
    pub fn passed(&self) -> usize {
        match &self.pass {
            None => self.step_events.len().saturating_sub(1),
            Some(p) => self.step_events.partition_point(|&e| e <= p.cursor.applied).saturating_sub(1),
        }
    }

    /// Applies event `k` to `cursor`.
    fn apply(&self, cursor: &mut StockCursor, k: usize) -> Applied {
        cursor.applied = k + 1;
        cursor.partial = None;
        cursor.partial_stamps.clear();
        let Some(event) = self.events.get(k) else { return Applied::Removed(Removal::default()) };
        match &event.action {
            Action::Blank(b) => {
                cursor.version += 1;
                match Stock::new(b, self.options.resolution) {
                    Ok(mut s) => {
                        s.stamp_all(Stamp::done(self.run, k));
                        let used = s.resolution();
                        cursor.stock = Some(s);
                        Applied::NewStock { asked: self.options.resolution, used }
                    }
                    Err(StockError::InvalidBlank) => {
                        cursor.stock = None;
                        Applied::NoStock
                    }
                }
            }
            Action::Cut { cutter, axis, from, to, .. } => {
                let Some(stock) = cursor.stock.as_mut() else { return Applied::Removed(Removal::default()) };
                let whole = Part::whole(Stamp::done(self.run, k));
                let (r, _) = stock.cut_part(&self.cutters[*cutter], *axis, *from, *to, whole);
                if r.depth > 0.0 {
                    cursor.version += 1;
                }
                Applied::Removed(r)
            }
        }
    }

    /// The work of the events `from..to` in the first pass.
    fn work_between(&self, from: usize, to: usize) -> usize {
        let at = |k: usize| self.work.get(k).or(self.work.last()).copied().unwrap_or(0);
        at(to).saturating_sub(at(from))
    }

    /// Number of events up to the end of `step` (or up to `fraction` of its motion).
    fn events_until(&self, step: usize, fraction: f64) -> usize {
        let last = self.step_events.len().saturating_sub(1);
        let (start, end) = (self.step_events[step.min(last)], self.step_events[(step + 1).min(last)]);
        if fraction >= 1.0 || fraction.is_nan() {
            return end;
        }
        start + self.events[start..end].iter().take_while(|e| e.end <= fraction).count()
    }

    /// Moves `cursor` to the stock after `fraction` (0…1) of step `step`'s motion (1 = the whole
    /// step): forward by cutting only what is new, backward from the nearest checkpoint.
    pub fn seek(&self, cursor: &mut StockCursor, step: usize, fraction: f64) {
        self.advance(cursor, step, fraction, usize::MAX);
    }

    /// [`Cutting::seek`] that computes about `budget` rays at most (an animation frame's share;
    /// a cut may stop between two rows and go on in the next call): returns whether `cursor`
    /// reached the stock asked for (never for a step not planned yet). A cursor past the target starts over from the nearest
    /// checkpoint before it; so does a cursor so far behind a checkpoint that copying it is
    /// cheaper than cutting up to it, unless a budget is given (copying would blow the frame)
    /// and the cursor already holds a stock.
    pub fn advance(&self, cursor: &mut StockCursor, step: usize, fraction: f64, budget: usize) -> bool {
        let target = self.events_until(step, fraction);
        let past = self.is_past(cursor, step, fraction);
        let fresh = cursor.applied == 0 && cursor.stock.is_none();
        if let Some((at, stock)) = self.checkpoints.iter().rev().find(|(at, _)| *at <= target)
            && (past
                || ((budget == usize::MAX || fresh)
                    && *at > cursor.applied
                    && self.work_between(cursor.applied, *at) > CHECKPOINT_COPY_RAYS))
        {
            cursor.stock = stock.clone();
            cursor.applied = *at;
            cursor.partial = None;
            cursor.partial_stamps.clear();
            cursor.version += 1;
        }
        let mut spent = 0;
        while cursor.applied < target && spent < budget {
            let k = cursor.applied;
            match (&self.events[k].action, cursor.stock.as_mut()) {
                (Action::Cut { cutter, axis, from, to, .. }, Some(stock)) => {
                    let start = cursor.partial.unwrap_or_default();
                    // A part that may not finish the cut stamps afresh; the whole cut's stamp
                    // goes on every tile it changed once it is done.
                    let stamp = Stamp::fresh();
                    let part = Part { start, budget: budget - spent, stamp };
                    let (r, rest) = stock.cut_part(&self.cutters[*cutter], *axis, *from, *to, part);
                    spent += r.work().max(1);
                    if r.depth > 0.0 {
                        cursor.version += 1;
                    }
                    cursor.partial_stamps.push(stamp);
                    cursor.partial = rest;
                    if rest.is_none() {
                        stock.restamp(&cursor.partial_stamps, Stamp::done(self.run, k));
                        cursor.partial_stamps.clear();
                        cursor.applied += 1;
                    }
                }
                _ => {
                    self.apply(cursor, k);
                    spent += 1;
                }
            }
        }
        cursor.applied >= target && self.is_planned(step)
    }

    /// Whether `cursor` has cut more than the stock after `fraction` of step `step` holds (it
    /// has to go back to a checkpoint to get there).
    #[must_use]
    pub fn is_past(&self, cursor: &StockCursor, step: usize, fraction: f64) -> bool {
        let target = self.events_until(step, fraction);
        cursor.applied > target || (cursor.applied == target && cursor.partial.is_some())
    }

    /// The stock after step `step` (`None` before a BLK FORM or for a blank without volume).
    #[must_use]
    pub fn stock_at(&self, step: usize) -> Option<Stock> {
        let mut cursor = StockCursor::default();
        self.seek(&mut cursor, step, 1.0);
        cursor.stock
    }

    /// The stock at the end of the run.
    #[must_use]
    pub fn final_stock(&self) -> Option<Stock> {
        self.stock_at(self.step_events.len().saturating_sub(2))
    }

    /// The notes of one step.
    pub fn notes_at(&self, step: usize) -> impl Iterator<Item = &StockNote> {
        self.notes.iter().filter(move |n| n.step == step)
    }

    /// Bytes held by the checkpoints.
    #[must_use]
    pub fn checkpoint_bytes(&self) -> usize {
        self.checkpoints.iter().filter_map(|(_, s)| s.as_ref()).map(Stock::memory_bytes).sum()
    }
}

enum Applied {
    Removed(Removal),
    NewStock { asked: f64, used: f64 },
    NoStock,
}

/// Sub-moves of a motion that turns the tool: the turn (sum of the angles between the tool axes
/// at 16 points) times the tool's reach `reach` (radius + length) is the farthest a tool point
/// moves by turning; each sub-move keeps that within half the resolution, so evaluating the
/// orientation at its middle errs by at most a quarter.
fn sub_moves(kin: &Kin, seg: &Segment, reach: f64, resolution: f64) -> usize {
    const SAMPLES: usize = 16;
    let axis = |f: f64| kin.tool_axis_wcs(seg.axes_at(f).rotary);
    let mut turn = 0.0;
    let mut prev = axis(0.0);
    for i in 1..=SAMPLES {
        let next = axis(i as f64 / SAMPLES as f64);
        turn += prev.angle_between(next);
        prev = next;
    }
    let n = (turn * reach / (0.5 * resolution)).ceil();
    if n.is_finite() { (n as usize).clamp(1, MAX_SUB_MOVES) } else { 1 }
}

#[cfg(test)]
mod tests;
