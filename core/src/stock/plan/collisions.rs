//! Whether a run's positioning motions run the tool into the material ([`Cutting::collisions`]),
//! stock shown or not: only the steps that position are looked at, and only the cuts up to the
//! last of them that reaches into a blank are made.

use glam::DVec3;

use crate::Text;
use crate::ast::Program;
use crate::sim::{Blank, Simulation};

use super::{Action, Cutter, Cutting, Motion, StockNote, StockOptions};

/// What [`Cutting::collisions`] found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Collisions {
    pub notes: Vec<StockNote>,
    /// `(step, block)` from which the work allowed did not reach: not checked from there on.
    pub unchecked: Option<(usize, usize)>,
}

impl Collisions {
    /// What to say on the block where the check stopped, if it did.
    #[must_use]
    pub fn unchecked_message(&self) -> Option<Text> {
        self.unchecked.map(|_| {
            Text::new(
                "Materialprüfung hier abgebrochen (Rechenaufwand): Kollisionen mit dem Material danach nicht geprüft",
                "Material check stopped here (work limit): collisions with the material after this are not checked",
            )
        })
    }
}

impl Cutting {
    /// The collisions of positioning motions with the material (a rapid into it, a swivel with
    /// the tool in it), whether or not the stock is shown, cutting about `work` rays at most
    /// (`Removal::work`). Only the cuts up to the last positioning sweep that reaches into a
    /// blank are made, and none when no such sweep exists, as in a run that rapids above its
    /// blank: most runs cost only the plan.
    #[must_use]
    pub fn collisions(program: &Program, sim: &Simulation, options: StockOptions, work: usize) -> Collisions {
        let options = StockOptions { checkpoints: 0, ..options };
        let Some(step) = Cutting::last_positioning_step_in_a_blank(program, sim, options) else {
            return Collisions::default();
        };
        let mut c = Cutting::unplanned(options);
        c.plan_on(program, sim, step + 1);
        let Some(last) = c.last_positioning_in_a_blank() else { return Collisions::default() };
        // This cutting is never sought: the events after the last one that can collide go.
        c.events.truncate(last + 1);
        let done = c.pass_on(work);
        let unchecked = match &c.pass {
            Some(pass) if !done => c.events.get(pass.cursor.applied).map(|e| (e.step, e.block)),
            _ => None,
        };
        c.notes.retain(StockNote::is_collision);
        Collisions { notes: c.notes, unchecked }
    }

    /// The last step whose positioning reaches into the blank in effect
    /// ([`Cutting::reaches_blank`]). Only the steps that position ([`crate::sim::Record`]) are
    /// planned, each stretch of them between two of the run's checkpoints re-simulated once, the
    /// last stretch first: a run whose rapids stay above its blank costs no plan of its cuts
    /// (100,000 moves inside a blank: the check took more than the run itself).
    fn last_positioning_step_in_a_blank(
        program: &Program,
        sim: &Simulation,
        options: StockOptions,
    ) -> Option<usize> {
        let steps: Vec<usize> = (0..sim.len()).filter(|&k| sim.records[k].positioned).collect();
        let n = sim.options.checkpoint_interval.max(1);
        // One plan reused for each step looked at.
        let mut scratch = Cutting::unplanned(options);
        for stretch in steps.chunk_by(|a, b| a / n == b / n).rev() {
            let (first, last) = (stretch[0], stretch[stretch.len() - 1]);
            let mut found = None;
            for state in sim.motions_from(program, first).take(last + 1 - first) {
                if stretch.binary_search(&state.step).is_err() || state.segments.is_empty() {
                    continue;
                }
                let Some(blank) = state.blank else { continue };
                scratch.events.clear();
                scratch.cutters.clear();
                scratch.cutters.push(scratch.cutter(&state.tool));
                scratch.plan_step(sim, &state, 0);
                if scratch.events.iter().any(|e| scratch.reaches_blank(&blank, &e.action)) {
                    found = Some(state.step);
                }
            }
            if found.is_some() {
                return found;
            }
        }
        None
    }

    /// The last positioning sweep that reaches into the blank in effect.
    fn last_positioning_in_a_blank(&self) -> Option<usize> {
        let mut blank: Option<&Blank> = None;
        let mut last = None;
        for (k, e) in self.events.iter().enumerate() {
            match &e.action {
                Action::Blank(b) => blank = Some(b),
                action => {
                    if blank.is_some_and(|b| self.reaches_blank(b, action)) {
                        last = Some(k);
                    }
                }
            }
        }
        last
    }

    /// Whether `action` is a positioning sweep whose tool (tip to shank end, in a box widened
    /// by the radius) overlaps the blank `b`.
    fn reaches_blank(&self, b: &Blank, action: &Action) -> bool {
        let Action::Cut { cutter, axis, from, to, motion } = action else { return false };
        if *motion == Motion::Cut {
            return false;
        }
        let Cutter { radius, length, .. } = self.cutters[*cutter];
        let (shank_from, shank_to) = (*from + *axis * length, *to + *axis * length);
        // Straight up its own axis (a retract) the tool only sweeps what is new above its
        // shank's end: where it stands is free, it has just cut there.
        let d = *to - *from;
        let (lo, hi) = if d.dot(*axis) >= d.length() * (1.0 - 1e-9) {
            (shank_from.min(shank_to), shank_from.max(shank_to))
        } else {
            (from.min(*to).min(shank_from).min(shank_to), from.max(*to).max(shank_from).max(shank_to))
        };
        let (lo, hi) = (lo - DVec3::splat(radius), hi + DVec3::splat(radius));
        lo.cmplt(b.max).all() && hi.cmpgt(b.min).all()
    }
}
