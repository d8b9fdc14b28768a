//! The control's choice of axis angles for a tilted working plane, with an explanation record
//! the UI shows as "why the machine does this" (DOMAIN.md §3.3, §3.4, seed S2).
//!
//! Order of the rules (seed S2, "Schwenklösungen"):
//! * `SEQ±`: master axis on the ± side of its home position 0°; both on that side → the nearer;
//!   none → "Winkel nicht erlaubt"; the selected one outside the limits → "Winkel nicht erlaubt".
//! * `SYM±`: the same, relative to the master's symmetry point.
//! * neither: drop solutions outside the limits; two left → shortest path from the current
//!   positions; one → take it; none → "Winkel nicht erlaubt".
//!
//! Every UNCONFIRMED choice comes from [`crate::unconfirmed`] and is listed in
//! [`Explanation::decisions`] when it influenced the result.

use glam::DMat3;

use crate::angle::{clean, short_delta, wrap180};
use crate::axes::AxisValues;
use crate::kinematics::{self, AxisPair, ToolAxisSolution};
use crate::machine::{Carrier, Limits, Machine, RotaryJoint};
use crate::orientation::{self, Context, PlaneError};
use crate::plane::{PlaneBlock, PlaneDef, RotaryAxis, Selection, Sign, TransformMode};
use crate::unconfirmed::{self, Decision};

mod explanation;
mod words;

pub use explanation::{
    Candidate, ErrorMessage, Exclusion, Explanation, KinematicCase, LimitViolation, QValues, Realisation,
    Reason, Residual, Rule, SolveError, SolveOptions,
};
pub use words::{axis_word, axis_words, fmt_deg};

/// Solves one PLANE block: its orientation (RELATIV composed on `active`), then the choice.
/// PLANE AXIAL and PLANE RESET position the axes directly.
pub fn solve_block(
    machine: &Machine,
    block: &PlaneBlock<f64>,
    active: DMat3,
    opts: &SolveOptions,
) -> Result<Explanation, PlaneError> {
    let selection = block.selection.or(opts.selection);
    let transform = block.transform.or(opts.transform);
    match &block.def {
        PlaneDef::Axial { axes } => {
            orientation::validate(&block.def)?;
            let targets = orientation::axial_targets(axes, machine, &opts.start)?;
            Ok(fixed(machine, &targets, opts, KinematicCase::Axial, Rule::Axial, Vec::new()))
        }
        PlaneDef::Reset => {
            let mut targets = AxisValues::default();
            for j in machine.joints() {
                targets.set(j.axis, unconfirmed::RESET_TARGET_DEG);
            }
            Ok(fixed(machine, &targets, opts, KinematicCase::Reset, Rule::Reset, vec![Decision::ResetTarget]))
        }
        def => {
            let ctx = Context { active, machine: Some(machine), current: opts.start };
            let r = orientation::orientation(def, &ctx)?;
            let mut decisions = Vec::new();
            match def {
                PlaneDef::Projected { .. } => decisions.push(Decision::ProjectedSign),
                PlaneDef::Vector { .. } => decisions.push(Decision::VectorGramSchmidt),
                PlaneDef::Relativ { .. } if active == DMat3::IDENTITY => {
                    decisions.push(Decision::RelativUntilted)
                }
                _ => {}
            }
            Ok(solve_inner(machine, &r, opts, selection, transform, decisions))
        }
    }
}

/// Solves an orientation R: candidates, the control's choice and the explanation.
#[must_use]
pub fn solve(machine: &Machine, r: &DMat3, opts: &SolveOptions) -> Explanation {
    solve_inner(machine, r, opts, opts.selection, opts.transform, Vec::new())
}

/// Per-axis data the candidates need.
struct AxisCtx {
    axis: RotaryAxis,
    start: f64,
    limits: Option<Limits>,
    endless: bool,
    table: bool,
}

impl AxisCtx {
    fn new(joint: &RotaryJoint, machine: &Machine, opts: &SolveOptions) -> AxisCtx {
        AxisCtx {
            axis: joint.axis,
            start: opts.start.get(joint.axis).unwrap_or(0.0),
            limits: machine.limits_of(joint.axis, &opts.limits),
            endless: joint.endless,
            table: joint.carrier == Carrier::Table,
        }
    }

    /// How the axis writes a solution known modulo 360 ([`unconfirmed::PREFER_CANONICAL_VALUE`]).
    fn represent(&self, deg: f64) -> f64 {
        let canonical = wrap180(deg);
        let Some(l) = self.limits.filter(|_| !self.endless) else { return canonical };
        if unconfirmed::PREFER_CANONICAL_VALUE && l.contains(canonical) {
            return canonical;
        }
        // canonical + 360·k inside the limits, k nearest to the start position.
        let kmin = ((l.min - Limits::EPS - canonical) / 360.0).ceil();
        let kmax = ((l.max + Limits::EPS - canonical) / 360.0).floor();
        if kmin > kmax {
            return canonical;
        }
        let k = ((self.start - canonical) / 360.0).round().clamp(kmin, kmax);
        canonical + 360.0 * k
    }

    /// Travel from the start, endless axes the short way round (DOMAIN.md §3.3).
    fn travel(&self, value: f64) -> f64 {
        if self.endless { short_delta(self.start, value).abs() } else { (value - self.start).abs() }
    }

    fn violation(&self, value: f64) -> Option<LimitViolation> {
        let l = self.limits.filter(|_| !self.endless)?;
        (!l.contains(value)).then_some(LimitViolation { axis: self.axis, value, min: l.min, max: l.max })
    }
}

fn candidate(s: &AxisCtx, m: &AxisCtx, slave: f64, master: f64, residual: f64) -> Candidate {
    let violation = s.violation(slave).or_else(|| m.violation(master));
    Candidate {
        axes: AxisValues::default().with(s.axis, clean(slave)).with(m.axis, clean(master)),
        master: clean(master),
        slave: clean(slave),
        in_limits: violation.is_none(),
        violation,
        path: unconfirmed::path_length([s.travel(slave), m.travel(master)]),
        residual: clean(residual),
        excluded: None,
    }
}

fn header(machine: &Machine, r: &DMat3, opts: &SolveOptions, case: KinematicCase) -> Explanation {
    let t = orientation::tool_axis(r);
    Explanation {
        orientation: orientation::rows(r),
        tool_axis: t.to_array().map(clean),
        master: machine.master().axis,
        slave: machine.slave().axis,
        symmetry_point: kinematics::symmetry_point(machine),
        case,
        selection: opts.selection,
        transform: opts.transform.unwrap_or(TransformMode::unprogrammed()),
        start: opts.start,
        candidates: Vec::new(),
        chosen: None,
        rule: Rule::Unreachable,
        reason: Reason(Rule::Unreachable),
        error: None,
        error_message: None,
        residual: None,
        q: QValues::default(),
        decisions: Vec::new(),
        rotation: *r,
    }
}

/// Fills rule, texts, error, chosen and Q values.
fn finish(mut e: Explanation, rule: Rule, chosen: Option<usize>, error: Option<SolveError>) -> Explanation {
    e.reason = Reason(rule);
    e.rule = rule;
    e.error_message = error.map(ErrorMessage);
    e.error = error;
    e.chosen = if error.is_none() { chosen } else { None };
    if let Some(axes) = e.chosen_axes() {
        e.q = QValues { q120: axes.a, q121: axes.b, q122: axes.c };
    }
    if let Some(c) = e.chosen.and_then(|i| e.candidates.get(i))
        && e.residual.is_none()
    {
        e.residual = Some(Residual { gamma: c.residual, realised_by: Realisation::Mathematical });
    }
    e
}

/// PLANE AXIAL / RESET: one candidate, the given axis values.
fn fixed(
    machine: &Machine,
    targets: &AxisValues,
    opts: &SolveOptions,
    case: KinematicCase,
    rule: Rule,
    decisions: Vec<Decision>,
) -> Explanation {
    let r = machine.forward(targets);
    let mut e = header(machine, &r, opts, case);
    e.decisions = decisions;
    let [sj, mj] = machine.joints();
    let (s, m) = (AxisCtx::new(sj, machine, opts), AxisCtx::new(mj, machine, opts));
    let c = candidate(&s, &m, targets.get(s.axis).unwrap_or(0.0), targets.get(m.axis).unwrap_or(0.0), 0.0);
    let error = c.violation.map(out_of_limit);
    if let Some(v) = c.violation {
        e.candidates.push(Candidate { excluded: Some(Exclusion::OutOfLimits(v)), ..c });
    } else {
        e.candidates.push(c);
    }
    finish(e, rule, Some(0), error)
}

fn out_of_limit(v: LimitViolation) -> SolveError {
    SolveError::AxisOutOfLimit { axis: v.axis, value: v.value, min: v.min, max: v.max }
}

fn first_not_finite(r: &DMat3, opts: &SolveOptions) -> Option<SolveError> {
    if let Some(&value) = r.to_cols_array().iter().find(|x| !x.is_finite()) {
        return Some(SolveError::NotFinite { what: "orientation", value });
    }
    if let Some((_, value)) = opts.start.iter().find(|(_, v)| !v.is_finite()) {
        return Some(SolveError::NotFinite { what: "start position", value });
    }
    if let Some((_, l)) = opts.limits.iter().find(|(_, l)| !(l.min.is_finite() && l.max.is_finite())) {
        let value = if l.min.is_finite() { l.max } else { l.min };
        return Some(SolveError::NotFinite { what: "limit", value });
    }
    None
}

fn solve_inner(
    machine: &Machine,
    r: &DMat3,
    opts: &SolveOptions,
    selection: Option<Selection>,
    transform: Option<TransformMode>,
    decisions: Vec<Decision>,
) -> Explanation {
    let bad = first_not_finite(r, opts);
    let ik = if bad.is_some() {
        ToolAxisSolution::Unreachable
    } else {
        kinematics::solve_tool_axis(machine, orientation::tool_axis(r))
    };
    let case = match ik {
        ToolAxisSolution::Two { .. } => KinematicCase::Two,
        ToolAxisSolution::One { .. } => KinematicCase::One,
        ToolAxisSolution::SlaveFree { .. } => KinematicCase::SlaveFree,
        ToolAxisSolution::Unreachable => KinematicCase::Unreachable,
    };
    let mut e = header(machine, r, opts, case);
    e.selection = selection;
    e.transform = transform.unwrap_or(TransformMode::unprogrammed());
    e.decisions = decisions;
    if let Some(err) = bad {
        return finish(e, Rule::Unreachable, None, Some(err));
    }
    let [sj, mj] = machine.joints();
    let (s, m) = (AxisCtx::new(sj, machine, opts), AxisCtx::new(mj, machine, opts));
    let with_residual = |pair: AxisPair| {
        let (slave, master) = (s.represent(pair.slave), m.represent(pair.master));
        let g = kinematics::residual(machine, AxisPair { slave, master }, r);
        candidate(&s, &m, slave, master, g)
    };

    match ik {
        ToolAxisSolution::Unreachable => {
            e.decisions.push(Decision::UnreachableMessage);
            let err = SolveError::Unreachable { tool_axis: e.tool_axis };
            finish(e, Rule::Unreachable, None, Some(err))
        }
        ToolAxisSolution::One { solution } => {
            e.candidates.push(with_residual(solution));
            only_one(e, Rule::Unique { free: None })
        }
        ToolAxisSolution::SlaveFree { master } => {
            let (c, realised_by) = free_slave(machine, r, &s, &m, master, transform, &mut e.decisions);
            e.candidates.push(c);
            let gamma = e.candidates[0].residual;
            e.residual = Some(Residual { gamma, realised_by });
            only_one(e, Rule::Unique { free: Some(s.axis) })
        }
        ToolAxisSolution::Two { solutions } => {
            e.candidates = solutions.iter().map(|p| with_residual(*p)).collect();
            // Candidate 1 is the one on the SYM+ side of the symmetry point (stable order for the UI).
            if wrap180(e.candidates[0].master - e.symmetry_point) < 0.0 {
                e.candidates.swap(0, 1);
            }
            match selection {
                Some(sel) => choose_selected(e, sel),
                None => choose_free(e),
            }
        }
    }
}

/// The singular case: the master is fixed, the free slave follows COORD ROT or TABLE ROT.
fn free_slave(
    machine: &Machine,
    r: &DMat3,
    s: &AxisCtx,
    m: &AxisCtx,
    master_deg: f64,
    transform: Option<TransformMode>,
    decisions: &mut Vec<Decision>,
) -> (Candidate, Realisation) {
    if transform.is_none() {
        decisions.push(Decision::DefaultTransform);
    }
    let master = m.represent(master_deg);
    let turn_table = match transform.unwrap_or(TransformMode::unprogrammed()) {
        TransformMode::CoordRot => false,
        TransformMode::TableRot => {
            if !s.table {
                decisions.push(Decision::TableRotHeadAxis);
            }
            s.table || unconfirmed::TABLE_ROT_ON_HEAD_AXIS
        }
    };
    let slave = if turn_table {
        decisions.push(Decision::TableRotSign);
        s.represent(
            unconfirmed::TABLE_ROT_SIGN * kinematics::free_slave_for_zero_residual(machine, master, r),
        )
    } else {
        decisions.push(Decision::CoordRotFreeAxis);
        unconfirmed::coord_rot_free_axis(s.start)
    };
    let g = kinematics::residual(machine, AxisPair { slave, master }, r);
    let c = candidate(s, m, slave, master, g);
    let realised_by = if turn_table {
        Realisation::TableAxis { axis: s.axis, value: c.slave }
    } else {
        Realisation::Mathematical
    };
    (c, realised_by)
}

/// Exactly one candidate: take it if it is inside the limits.
fn only_one(mut e: Explanation, rule: Rule) -> Explanation {
    let violation = e.candidates[0].violation;
    if let Some(v) = violation {
        e.candidates[0].excluded = Some(Exclusion::OutOfLimits(v));
    }
    finish(e, rule, Some(0), violation.map(out_of_limit))
}

/// Among `pool` (indices), the candidate with the shorter path; `true` if the tie rule decided.
/// Marks the loser. `pool` has one or two entries.
fn nearest(e: &mut Explanation, pool: &[usize]) -> (usize, bool) {
    let [a, b] = match *pool {
        [a, b] => [a, b],
        [a, ..] => return (a, false),
        [] => return (0, false),
    };
    e.decisions.push(Decision::PathMetric);
    let (pa, pb) = (e.candidates[a].path, e.candidates[b].path);
    let tie = (pa - pb).abs() < unconfirmed::TIE_TOLERANCE_DEG;
    let a_wins =
        if tie { unconfirmed::tie_prefers(e.candidates[a].master, e.candidates[b].master) } else { pa < pb };
    let (win, lose) = if a_wins { (a, b) } else { (b, a) };
    let chosen_path = e.candidates[win].path;
    let path = e.candidates[lose].path;
    e.candidates[lose].excluded =
        Some(if tie { Exclusion::LostTie { path } } else { Exclusion::LongerPath { path, chosen_path } });
    if tie {
        e.decisions.push(Decision::TieRule);
    }
    (win, tie)
}

/// `SEQ±` / `SYM±` with two candidates (DOMAIN.md §3.3, seed S2).
fn choose_selected(mut e: Explanation, sel: Selection) -> Explanation {
    let (sign, reference) = match sel {
        Selection::Seq(sign) => (sign, 0.0),
        Selection::Sym(sign) => {
            e.decisions.push(Decision::SymmetryPoint);
            (sign, e.symmetry_point)
        }
    };
    let side = |master: f64| {
        let d = match sel {
            Selection::Seq(_) => master - reference,
            Selection::Sym(_) => wrap180(master - reference),
        };
        (d > 0.0 || (d == 0.0 && unconfirmed::ZERO_COUNTS_AS_PLUS), d == 0.0)
    };
    // At most two candidates: the indices on the asked side, without a heap allocation.
    let (mut on_side, mut n) = ([0usize; 2], 0);
    for (i, c) in e.candidates.iter_mut().enumerate() {
        let (plus, zero) = side(c.master);
        if zero && !e.decisions.contains(&Decision::ZeroIsPlus) {
            e.decisions.push(Decision::ZeroIsPlus);
        }
        if plus == (sign == Sign::Plus) {
            on_side[n] = i;
            n += 1;
        } else {
            c.excluded = Some(Exclusion::WrongSide { selection: sel });
        }
    }
    let master = e.master;
    let rule_one = match sel {
        Selection::Seq(sign) => Rule::Seq { sign, master },
        Selection::Sym(sign) => Rule::Sym { sign, master, symmetry_point: e.symmetry_point },
    };
    if n == 0 {
        let values = [e.candidates[0].master, e.candidates[1].master];
        return finish(
            e,
            rule_one,
            None,
            Some(SolveError::NoSolutionOnSide { selection: sel, master, values }),
        );
    }
    let rule = match (sel, n) {
        (Selection::Seq(sign), 2) => {
            e.decisions.push(Decision::SeqSameSide);
            if !unconfirmed::SEQ_NEAREST_BEFORE_LIMITS {
                let both = on_side;
                n = 0;
                for i in both.into_iter().filter(|&i| e.candidates[i].in_limits) {
                    on_side[n] = i;
                    n += 1;
                }
            }
            Rule::SeqNearer { sign, master }
        }
        _ => rule_one,
    };
    if n == 0 {
        return finish(e, rule, None, Some(SolveError::NoSolutionInLimits { candidates: 2 }));
    }
    let (pick, _) = nearest(&mut e, &on_side[..n]);
    match e.candidates[pick].violation {
        Some(v) => {
            e.candidates[pick].excluded = Some(Exclusion::OutOfLimits(v));
            finish(e, rule, None, Some(out_of_limit(v)))
        }
        None => finish(e, rule, Some(pick), None),
    }
}

/// No selection: limits, then shortest path (DOMAIN.md §3.3 steps 1–4, seed S2).
fn choose_free(mut e: Explanation) -> Explanation {
    let (mut inside, mut n) = ([0usize; 2], 0);
    for (i, c) in e.candidates.iter_mut().enumerate() {
        match c.violation {
            Some(v) => c.excluded = Some(Exclusion::OutOfLimits(v)),
            None => {
                inside[n] = i;
                n += 1;
            }
        }
    }
    match n {
        0 => {
            let n = e.candidates.len();
            finish(e, Rule::NoneInLimits, None, Some(SolveError::NoSolutionInLimits { candidates: n }))
        }
        1 => finish(e, Rule::OnlyInLimits, Some(inside[0]), None),
        _ => {
            let (pick, tie) = nearest(&mut e, &inside[..n]);
            let rule = if tie { Rule::Tie { master: e.master } } else { Rule::ShortestPath };
            finish(e, rule, Some(pick), None)
        }
    }
}
