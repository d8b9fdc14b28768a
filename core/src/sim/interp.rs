//! The interpreter: one executed block at a time. Cloneable, so a clone is a checkpoint.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use glam::{DMat3, DVec3};

use crate::angle::short_delta;
use crate::ast::{
    Axis, AxisWord, BinOp, BlkForm, BlockBody, CycleDefOld, Expr, Func, Label, Line, OldCycleData,
    OldCycleWord, Program, RadiusComp, ToolCall, ToolRef,
};
use crate::axes::AxisValues;
use crate::machine::{Carrier, Machine, Texts};
use crate::orientation::{self, Context};
use crate::plane::{Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, RotaryAxis, Value};
use crate::solve::{self, Explanation, SolveError, SolveOptions};
use crate::unconfirmed;

use super::cycles::{self, CycleMove};
use super::error::SimErrorCode;
use super::geometry::{Affine, Kin};
use super::jumps;
use super::segment::{MachineAxes, MovePath, Segment, SegmentKind, SegmentPath, move_linear};
use super::tools;
use super::transform::{Level, Transforms};
use super::{
    ActivePlane, Blank, Frame, Frames, LabelKey, Pivot, SimOptions, Spindle, SpindleDir, State, TiltSource,
    ToolState,
};

/// What the run needs besides the interpreter state.
pub(crate) struct Cx<'a> {
    pub program: &'a Program,
    pub machine: &'a Machine,
    pub options: &'a SimOptions,
    pub labels: &'a HashMap<LabelKey, usize>,
}

/// What a full-detail step records (segments, message, explanation). The fast run passes none.
#[derive(Debug, Default)]
pub(crate) struct Rec {
    pub segments: Vec<Segment>,
    pub message: Option<Texts>,
    pub explanation: Option<Arc<Explanation>>,
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

/// The interpreter state between blocks.
#[derive(Debug, Clone)]
pub(crate) struct Interp {
    /// Index of the next block.
    pub pc: usize,
    /// Executed steps so far.
    pub step_count: usize,
    /// The block of the step just executed.
    last: usize,
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
    plane: Option<Arc<ActivePlane>>,
    q: BTreeMap<u32, f64>,
    cycle: Option<StoredCycle>,
    calls: Vec<usize>,
    reps: Vec<(usize, u32)>,
    kin: Kin,
    /// I-CS → linear axes as the control computes it, for the current rotary axes.
    map: Affine,
    m126: bool,
    /// The cycle 7 definition being read: the shift before its `7.0` header, the words so far.
    c7: Option<Cycle7>,
}

/// A cycle 7 definition spread over sub-blocks `7.1 X…`, `7.2 Y…`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cycle7 {
    base: DVec3,
    written: [Option<f64>; 3],
    any_absolute: bool,
}

type R<T> = Result<T, SimErrorCode>;

/// M functions with a motion meaning the simulator does not model (M92 OEM position, M128/M129
/// TCPM, M140 retract); a block with one of them says so (DOMAIN.md §8).
const NOT_SIMULATED_M: [u32; 4] = [92, 128, 129, 140];

/// Animation time of a STAY swivel, seconds: nothing moves on the machine, so no feed gives a
/// duration; one second lets the view show the coordinate system turning (derived, display only).
pub const STAY_SECONDS: f64 = 1.0;

fn note(rec: &mut Option<&mut Rec>, text: impl FnOnce() -> (String, String)) {
    if let Some(r) = rec.as_deref_mut() {
        let (de, en) = text();
        r.message = Some(Texts { de, en });
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

fn linear_index(axis: Axis) -> Option<usize> {
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
            cycle: None,
            calls: Vec::new(),
            reps: Vec::new(),
            kin,
            map: Affine::IDENTITY,
            m126: false,
            c7: None,
        };
        it.refresh();
        it.pos_i = it.map.inverse_orthogonal().apply(it.axes.linear);
        it
    }

    pub fn done(&self, program: &Program) -> bool {
        self.pc >= program.blocks.len()
    }

    fn compensating(&self) -> bool {
        self.tf.tilt.is_some() || !unconfirmed::COMPENSATION_ONLY_WHEN_TILTED
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

    fn value(&self, v: &Value) -> R<f64> {
        match *v {
            Value::Number(x) => Ok(x),
            Value::Param { index, negate } => match self.q.get(&index) {
                Some(&x) => Ok(if negate { -x } else { x }),
                None => Err(SimErrorCode::UndefinedQ { index }),
            },
        }
    }

    fn eval(&self, e: &Expr) -> R<f64> {
        Ok(match e {
            Expr::Num(x) => *x,
            Expr::Param(i) => *self.q.get(i).ok_or(SimErrorCode::UndefinedQ { index: *i })?,
            Expr::Pi => std::f64::consts::PI,
            Expr::Neg(a) => -self.eval(a)?,
            // Angles of the Q formula functions are degrees (the control works in degrees,
            // DOMAIN.md §2).
            Expr::Func(f, a) => {
                let x = self.eval(a)?;
                match f {
                    Func::Sin => x.to_radians().sin(),
                    Func::Cos => x.to_radians().cos(),
                    Func::Tan => x.to_radians().tan(),
                    Func::Asin => x.asin().to_degrees(),
                    Func::Acos => x.acos().to_degrees(),
                    Func::Atan => x.atan().to_degrees(),
                    Func::Sqrt => x.sqrt(),
                    Func::Sq => x * x,
                    Func::Abs => x.abs(),
                    Func::Int => x.trunc(),
                    Func::Frac => x.fract(),
                    Func::Ln => x.ln(),
                    Func::Log => x.log10(),
                    Func::Exp => x.exp(),
                    Func::Sgn => {
                        if x == 0.0 {
                            0.0
                        } else {
                            x.signum()
                        }
                    }
                }
            }
            Expr::Bin(op, a, b) => {
                let (x, y) = (self.eval(a)?, self.eval(b)?);
                match op {
                    BinOp::Add => x + y,
                    BinOp::Sub => x - y,
                    BinOp::Mul => x * y,
                    BinOp::Div => x / y,
                    BinOp::Pow => x.powf(y),
                }
            }
        })
    }

    fn check_linear(&self, cx: &Cx<'_>, l: DVec3) -> R<()> {
        for (i, lim) in cx.machine.geometry.linear_limits.iter().enumerate() {
            let v = l[i];
            if !v.is_finite() || !lim.contains(v) {
                return Err(SimErrorCode::LimitSwitch {
                    axis: ['X', 'Y', 'Z'][i],
                    value: v,
                    min: lim.min,
                    max: lim.max,
                });
            }
        }
        Ok(())
    }

    fn check_rotary(&self, cx: &Cx<'_>, rot: [f64; 2]) -> R<()> {
        for (j, v) in cx.machine.joints().iter().zip(rot) {
            if let Some(l) = j.limits.filter(|_| !j.endless)
                && (!v.is_finite() || !l.contains(v))
            {
                return Err(SimErrorCode::RotaryLimit {
                    axis: j.axis.letter(),
                    value: v,
                    min: l.min,
                    max: l.max,
                });
            }
        }
        Ok(())
    }

    /// Rotary travel start → end: the short way for endless axes (solver swivels; `L` blocks
    /// only with M126).
    fn rotary_delta(&self, cx: &Cx<'_>, end: [f64; 2], short: bool) -> [f64; 2] {
        let j = cx.machine.joints();
        let d = |k: usize| {
            if short && j[k].endless {
                short_delta(self.axes.rotary[k], end[k])
            } else {
                end[k] - self.axes.rotary[k]
            }
        };
        [d(0), d(1)]
    }

    /// Moves to `target`, recording a segment when a full record is asked for.
    #[allow(clippy::too_many_arguments)]
    fn go(
        &mut self,
        cx: &Cx<'_>,
        rec: &mut Option<&mut Rec>,
        block: usize,
        kind: SegmentKind,
        target: MachineAxes,
        rotary_delta: [f64; 2],
        rate: Rate,
        path: impl FnOnce() -> SegmentPath,
    ) {
        let moves = target.linear != self.axes.linear || rotary_delta != [0.0; 2];
        if let Some(r) = rec.as_deref_mut().filter(|_| moves) {
            let g = &cx.machine.geometry;
            let (lin_rate, rot_rate) = match rate {
                Rate::Feed(f) if f > 0.0 => (f, f),
                _ => (g.rapid_linear, g.rapid_rotary),
            };
            let lin = (target.linear - self.axes.linear).length();
            let rot = rotary_delta[0].abs().max(rotary_delta[1].abs());
            // Duration (s) = distance / (feed per minute) · 60; the longer share wins (sim.rs doc).
            let duration = (lin / lin_rate).max(rot / rot_rate) * 60.0;
            r.segments.push(Segment {
                step: self.step_count.saturating_sub(1),
                block,
                kind,
                start: self.axes,
                end: target,
                rotary_delta,
                duration: if duration.is_finite() { duration } else { 0.0 },
                path: path(),
            });
        }
        self.axes = target;
    }

    fn rate(&mut self, feed: Option<&Feed<Value>>) -> R<Rate> {
        Ok(match feed {
            None => {
                if self.feed > 0.0 {
                    Rate::Feed(self.feed)
                } else {
                    Rate::Rapid
                }
            }
            Some(Feed::Value(v)) => {
                let f = self.value(v)?;
                self.feed = f;
                Rate::Feed(f)
            }
            Some(Feed::Max) => Rate::Rapid,
            Some(Feed::Auto) => {
                if self.tool.feed > 0.0 {
                    Rate::Feed(self.tool.feed)
                } else {
                    Rate::Rapid
                }
            }
        })
    }

    /// Executes the next block; `Ok(false)` if it was only listed (after M30, or skipped).
    pub fn step(&mut self, cx: &Cx<'_>, rec: Option<&mut Rec>) -> R<bool> {
        let mut rec = rec;
        let idx = self.pc;
        let Some(block) = cx.program.blocks.get(idx) else {
            self.pc = cx.program.blocks.len();
            return Ok(false);
        };
        self.pc += 1;
        self.step_count += 1;
        self.last = idx;
        if self.ended {
            if matches!(block.body, BlockBody::EndPgm { .. }) {
                self.pc = cx.program.blocks.len();
            }
            note(&mut rec, || {
                (
                    "Nach Programmende (M30/M2): nicht ausgeführt".into(),
                    "After program end (M30/M2): not executed".into(),
                )
            });
            return Ok(false);
        }
        if block.skip && cx.options.block_skip {
            note(&mut rec, || ("Satz ausgeblendet (/)".into(), "Block skipped (/)".into()));
            return Ok(false);
        }
        if !matches!(&block.body, BlockBody::CycleDefOld(d) if d.number == 7) {
            self.c7 = None;
        }
        match &block.body {
            BlockBody::BeginPgm { .. } | BlockBody::Empty | BlockBody::Structure { .. } => {}
            BlockBody::EndPgm { .. } => {
                self.ended = true;
                self.pc = cx.program.blocks.len();
            }
            BlockBody::BlkForm(b) => self.blk_form(b)?,
            BlockBody::ToolCall(t) => self.tool_call(t, &mut rec)?,
            BlockBody::L(line) => self.line(cx, &mut rec, idx, line)?,
            BlockBody::Cc(_) => note(&mut rec, || {
                ("CC: Kreismittelpunkt (keine Bewegung)".into(), "CC: circle centre (no motion)".into())
            }),
            BlockBody::C(m) | BlockBody::Cr(m) | BlockBody::Ct(m) => {
                let line = Line { axes: m.axes.clone(), comp: m.comp, feed: m.feed, m: m.m.clone() };
                self.line(cx, &mut rec, idx, &line)?;
                note(&mut rec, || {
                    (
                        "Kreisbahn nicht simuliert: Gerade zum Endpunkt".into(),
                        "Arc not simulated: straight line to its end point".into(),
                    )
                });
            }
            BlockBody::Lp(_) | BlockBody::Cp(_) | BlockBody::Rnd { .. } | BlockBody::Chf { .. } => {
                note(&mut rec, || {
                    (
                        "Polar-/Rundungs-/Fasensatz nicht simuliert".into(),
                        "Polar, rounding or chamfer block not simulated".into(),
                    )
                })
            }
            BlockBody::MFunctions(m) => {
                self.spindle_m(m);
                if let Some(&f) = m.iter().find(|&&f| NOT_SIMULATED_M.contains(&f)) {
                    note(&mut rec, || (format!("M{f} nicht simuliert"), format!("M{f} not simulated")));
                }
                if m.contains(&99) {
                    self.call_cycle(cx, &mut rec, idx)?;
                }
                self.end_m(m);
            }
            BlockBody::CycleDef(d) => {
                self.cycle = Some(StoredCycle::New(idx));
                let n = d.number;
                note(&mut rec, || {
                    (
                        format!("Zyklus {n} definiert, wirkt beim Aufruf"),
                        format!("Cycle {n} defined, acts when called"),
                    )
                });
            }
            BlockBody::CycleDefOld(d) => self.old_cycle(cx, &mut rec, idx, d)?,
            BlockBody::CyclCall { m } => {
                self.spindle_m(m);
                self.call_cycle(cx, &mut rec, idx)?;
                self.end_m(m);
            }
            BlockBody::Plane(p) => self.plane(cx, &mut rec, idx, p)?,
            BlockBody::TransDatum { axes } => self.datum(axes)?,
            BlockBody::TransDatumReset => {
                self.tf.datum_w = DVec3::ZERO;
                self.tf.datum_i = DVec3::ZERO;
                self.sync_pos();
            }
            BlockBody::TransMirror { axes } => {
                let mut set = [false; 3];
                for a in axes.iter() {
                    if let Some(i) = linear_index(*a) {
                        set[i] = true;
                    }
                }
                self.set_mirror(set);
            }
            BlockBody::TransMirrorReset => {
                self.tf.mirror_w = [false; 3];
                self.tf.mirror_i = [false; 3];
                self.sync_pos();
            }
            BlockBody::TransRotation { rot, incremental } => {
                let v = self.value(rot)?;
                self.tf.rotation = if *incremental { self.tf.rotation + v } else { v };
                self.sync_pos();
            }
            BlockBody::TransRotationReset => {
                self.tf.rotation = 0.0;
                self.sync_pos();
            }
            BlockBody::Lbl(l) => {
                if *l == Label::Number(0)
                    && let Some(ret) = self.calls.pop()
                {
                    self.pc = ret;
                }
            }
            BlockBody::CallLbl { label, rep } => self.call_lbl(cx, idx, label, *rep)?,
            BlockBody::CallPgm { path } => {
                let p = path.clone();
                note(&mut rec, || {
                    (format!("CALL PGM {p}: nicht simuliert"), format!("CALL PGM {p}: not simulated"))
                })
            }
            BlockBody::QAssign { target, expr, .. } => {
                let v = self.eval(expr)?;
                if !v.is_finite() {
                    return Err(SimErrorCode::Arithmetic { index: *target });
                }
                self.q.insert(*target, v);
            }
            BlockBody::Unknown { text } => match jumps::parse_jump(text) {
                Some(j) => {
                    let (a, b) = (self.value(&j.a)?, self.value(&j.b)?);
                    if j.holds(a, b) {
                        self.pc = self.label_index(cx, &j.label)?;
                    }
                }
                None => {
                    let t = text.clone();
                    note(&mut rec, || {
                        (format!("Satz nicht simuliert: {t}"), format!("Block not simulated: {t}"))
                    })
                }
            },
            BlockBody::Invalid { .. } => return Err(SimErrorCode::InvalidBlock),
        }
        Ok(true)
    }

    fn spindle_m(&mut self, m: &[u32]) {
        for &f in m {
            match f {
                3 => self.spindle.dir = SpindleDir::Cw,
                4 => self.spindle.dir = SpindleDir::Ccw,
                5 => self.spindle.dir = SpindleDir::Off,
                126 => self.m126 = true,
                127 => self.m126 = false,
                _ => {}
            }
        }
    }

    fn end_m(&mut self, m: &[u32]) {
        if m.iter().any(|&f| f == 30 || f == 2) {
            self.spindle.dir = SpindleDir::Off;
            self.ended = true;
            if !unconfirmed::LIST_BLOCKS_AFTER_END {
                self.pc = usize::MAX;
            }
        }
    }

    fn blk_form(&mut self, b: &BlkForm) -> R<()> {
        let base = if b.part == 2 { self.blank_min.unwrap_or(DVec3::ZERO) } else { DVec3::ZERO };
        let mut p = if b.part == 2 { base } else { DVec3::ZERO };
        for w in b.axes.iter() {
            if let Some(i) = linear_index(w.axis) {
                let v = self.value(&w.value)?;
                p[i] = if w.incremental { base[i] + v } else { v };
            }
        }
        if b.part == 2 {
            let min = self.blank_min.unwrap_or(DVec3::ZERO);
            self.blank = Some(Blank { min: min.min(p), max: min.max(p) });
        } else {
            self.blank_min = Some(p);
        }
        Ok(())
    }

    fn tool_call(&mut self, t: &ToolCall, rec: &mut Option<&mut Rec>) -> R<()> {
        let dl = t.dl.as_ref().map(|v| self.value(v)).transpose()?.unwrap_or(0.0);
        let dr = t.dr.as_ref().map(|v| self.value(v)).transpose()?.unwrap_or(0.0);
        if let Some(tool) = &t.tool {
            let (entry, known) = tools::lookup(tool);
            self.tool.number = entry.number;
            self.tool.name = entry.name;
            self.tool.length = entry.length + dl;
            self.tool.radius = entry.radius + dr;
            self.tool.known = known;
            if !known {
                let (n, l, r) = (self.tool.number, self.tool.length, self.tool.radius);
                note(rec, || {
                    (
                        format!("Werkzeug {n} nicht in der Werkzeugtabelle: L={l} R={r} angenommen"),
                        format!("Tool {n} not in the tool table: assuming L={l} R={r}"),
                    )
                });
            }
        }
        if let Some(a) = t.axis {
            self.tool.axis = letter(a);
            if a != Axis::Z {
                let c = self.tool.axis;
                note(rec, || {
                    (
                        format!("Werkzeugachse {c}: simuliert wird mit Werkzeugachse Z"),
                        format!("Tool axis {c}: simulated with tool axis Z"),
                    )
                });
            }
        }
        if let Some(s) = &t.speed {
            self.spindle.speed = self.value(s)?;
        }
        if let Some(f) = &t.feed {
            let f = self.value(f)?;
            self.tool.feed = f;
            self.feed = f;
        }
        self.kin.tool_length = self.tool.length;
        self.sync_pos();
        Ok(())
    }

    fn line(&mut self, cx: &Cx<'_>, rec: &mut Option<&mut Rec>, idx: usize, line: &Line) -> R<()> {
        self.spindle_m(&line.m);
        let m91 = line.m.contains(&91);
        let rate = self.rate(line.feed.as_ref())?;
        let mut p = self.pos_i;
        let mut l = self.axes.linear;
        let mut rot = self.axes.rotary;
        let (mut lin_prog, mut rot_prog) = (false, false);
        for w in line.axes.iter() {
            if let Some(i) = linear_index(w.axis) {
                let v = self.value(&w.value)?;
                lin_prog = true;
                let slot = if m91 { &mut l[i] } else { &mut p[i] };
                *slot = if w.incremental { *slot + v } else { v };
            } else if let Some(ra) = rotary_of(w.axis) {
                // The axis must exist before its value matters ("Achse nicht vorhanden" first).
                let Some(k) = self.axes.letters.iter().position(|&x| x == ra) else {
                    return Err(SimErrorCode::AxisNotOnMachine { axis: ra.letter() });
                };
                let v = self.value(&w.value)?;
                rot[k] = if w.incremental { rot[k] + v } else { v };
                rot_prog = true;
            } else {
                return Err(SimErrorCode::AxisNotOnMachine { axis: letter(w.axis) });
            }
        }
        if matches!(line.comp, Some(RadiusComp::Rl | RadiusComp::Rr)) {
            note(rec, || {
                (
                    "Radiuskorrektur RL/RR nicht simuliert: Werkzeugmittelpunkt auf der Kontur".into(),
                    "Radius compensation RL/RR not simulated: tool centre on the contour".into(),
                )
            });
        }
        if let Some(&m) = line.m.iter().find(|&&m| NOT_SIMULATED_M.contains(&m)) {
            note(rec, || (format!("M{m} nicht simuliert"), format!("M{m} not simulated")));
        }
        self.check_rotary(cx, rot)?;
        if lin_prog && !m91 {
            l = if rot_prog {
                self.wcs_to_linear(rot).after(&self.tf.ics_to_wcs()).apply(p)
            } else {
                self.map.apply(p)
            };
        }
        if lin_prog || rot_prog {
            self.check_linear(cx, l)?;
            let delta = self.rotary_delta(cx, rot, self.m126);
            let kind = if rate == Rate::Rapid { SegmentKind::Rapid } else { SegmentKind::Feed };
            let target = MachineAxes { linear: l, rotary: rot, letters: self.axes.letters };
            self.go(cx, rec, idx, kind, target, delta, rate, || SegmentPath::Linear);
            if rot_prog {
                self.refresh();
            }
            if lin_prog && !m91 {
                self.pos_i = p;
            } else {
                self.pos_i = self.map.inverse_orthogonal().apply(self.axes.linear);
            }
        }
        if line.m.contains(&99) {
            self.call_cycle(cx, rec, idx)?;
        }
        self.end_m(&line.m);
        Ok(())
    }

    /// The new datum shift from the written components ([`unconfirmed::DATUM_ABSOLUTE_REPLACES`]):
    /// with an absolute word the axes not written are 0, with only incremental words they keep
    /// the base.
    fn datum_of(base: DVec3, written: [Option<f64>; 3], any_absolute: bool) -> DVec3 {
        let keep = !(any_absolute && unconfirmed::DATUM_ABSOLUTE_REPLACES);
        DVec3::from_array(std::array::from_fn(|i| written[i].unwrap_or(if keep { base[i] } else { 0.0 })))
    }

    fn datum(&mut self, axes: &[AxisWord]) -> R<()> {
        let level = self.tf.level_now();
        let base = match level {
            Level::Wcs => self.tf.datum_w,
            Level::Wpl => self.tf.datum_i,
        };
        let mut written = [None; 3];
        let mut any_absolute = false;
        for w in axes {
            if let Some(i) = linear_index(w.axis) {
                let v = self.value(&w.value)?;
                written[i] = Some(if w.incremental { base[i] + v } else { v });
                any_absolute |= !w.incremental;
            }
        }
        let d = Self::datum_of(base, written, any_absolute);
        match level {
            Level::Wcs => self.tf.datum_w = d,
            Level::Wpl => self.tf.datum_i = d,
        }
        self.sync_pos();
        Ok(())
    }

    fn set_mirror(&mut self, set: [bool; 3]) {
        match self.tf.level_now() {
            Level::Wcs => self.tf.mirror_w = set,
            Level::Wpl => self.tf.mirror_i = set,
        }
        self.sync_pos();
    }

    fn label_index(&self, cx: &Cx<'_>, label: &Label) -> R<usize> {
        cx.labels.get(&LabelKey::from(label)).copied().ok_or_else(|| SimErrorCode::UndefinedLabel {
            label: match label {
                Label::Number(n) => n.to_string(),
                Label::Name(s) => format!("\"{s}\""),
            },
        })
    }

    fn call_lbl(&mut self, cx: &Cx<'_>, idx: usize, label: &Label, rep: Option<u32>) -> R<()> {
        let target = self.label_index(cx, label)?;
        match rep {
            Some(m) if unconfirmed::REP_IS_SECTION_REPEAT => {
                if let Some(k) = self.reps.iter().position(|(b, _)| *b == idx) {
                    if self.reps[k].1 > 0 {
                        self.reps[k].1 -= 1;
                        self.pc = target;
                    } else {
                        self.reps.remove(k);
                    }
                } else if m > 0 {
                    self.reps.push((idx, m - 1));
                    self.pc = target;
                }
            }
            _ => {
                if self.calls.len() >= unconfirmed::MAX_CALL_DEPTH {
                    return Err(SimErrorCode::CallDepth { depth: unconfirmed::MAX_CALL_DEPTH });
                }
                self.calls.push(idx + 1);
                self.pc = target;
            }
        }
        Ok(())
    }

    /// Solves a target orientation R (already mirrored) or a PLANE block; returns the
    /// explanation or the control's error.
    fn solved(e: Explanation) -> R<Explanation> {
        match e.error {
            Some(error) => Err(SimErrorCode::Solve { error }),
            None if e.chosen.is_none() => Err(SimErrorCode::Solve {
                error: SolveError::NoSolutionInLimits { candidates: e.candidates.len() },
            }),
            None => Ok(e),
        }
    }

    fn set_q_from(&mut self, e: &Explanation) {
        for (i, v) in [(120, e.q.q120), (121, e.q.q121), (122, e.q.q122)] {
            if let Some(v) = v {
                self.q.insert(i, v);
            }
        }
    }

    fn target_rotary(&self, axes: &AxisValues) -> [f64; 2] {
        let mut rot = self.axes.rotary;
        for (k, l) in self.axes.letters.iter().enumerate() {
            if let Some(v) = axes.get(*l) {
                rot[k] = v;
            }
        }
        rot
    }

    fn plane(&mut self, cx: &Cx<'_>, rec: &mut Option<&mut Rec>, idx: usize, pb: &PlaneBlock) -> R<()> {
        let pb: PlaneBlock<f64> = pb.try_map(|v| self.value(v))?;
        let machine = cx.machine;
        let start = self.axes.rotary_values();
        let opts = SolveOptions { start, ..SolveOptions::default() };
        let mw = self.tf.mirror_w_matrix();
        let mirrored = self.tf.mirror_w.iter().any(|&b| b);
        let before = self.tf.r();
        let plane_err = |error| SimErrorCode::Plane { error };
        let (expl, tilt) = match &pb.def {
            PlaneDef::Reset => {
                (solve::solve_block(machine, &pb, DMat3::IDENTITY, &opts).map_err(plane_err)?, None)
            }
            PlaneDef::Axial { .. } => {
                // Axis angles: a preceding mirror does not change the rotary axes (DOMAIN.md §6).
                let e =
                    Self::solved(solve::solve_block(machine, &pb, self.tf.r(), &opts).map_err(plane_err)?)?;
                let r = e.chosen_axes().map(|a| machine.forward(&a));
                (e, r)
            }
            def => {
                // Spatial-angle functions: R = M_W·R_prog·M_W (transform.rs doc, DOMAIN.md §6).
                let ctx = Context { active: mw * self.tf.r() * mw, machine: Some(machine), current: start };
                let r_prog = orientation::orientation(def, &ctx).map_err(plane_err)?;
                let r = mw * r_prog * mw;
                let e = if mirrored {
                    solve::solve(
                        machine,
                        &r,
                        &SolveOptions { selection: pb.selection, transform: pb.transform, ..opts.clone() },
                    )
                } else {
                    solve::solve_block(machine, &pb, self.tf.r(), &opts).map_err(plane_err)?
                };
                (e, Some(r))
            }
        };
        let expl = Arc::new(Self::solved(expl)?);
        let target = expl.chosen_axes().map(|a| self.target_rotary(&a)).unwrap_or(self.axes.rotary);
        if unconfirmed::Q120_ONLY_FOR_SPATIAL_TILTS
            && !matches!(pb.def, PlaneDef::Reset | PlaneDef::Axial { .. })
        {
            self.set_q_from(&expl);
        }
        self.tf.tilt = tilt;
        self.plane = tilt.map(|r| {
            Arc::new(ActivePlane {
                block: idx,
                source: TiltSource::Plane,
                orientation: r,
                spatial: orientation::to_spatial(&r),
                tool_axis: r.z_axis.to_array(),
                explanation: expl.clone(),
            })
        });
        if let Some(r) = rec.as_deref_mut() {
            r.explanation = Some(expl.clone());
        }
        match pb.positioning {
            None | Some(Positioning::Stay) => {
                if pb.positioning.is_none() {
                    note(rec, || {
                        (
                            "MOVE/TURN/STAY fehlt: wie STAY behandelt".into(),
                            "MOVE/TURN/STAY missing: treated as STAY".into(),
                        )
                    });
                }
                self.stay_segment(rec, idx, before, self.tf.r());
            }
            Some(Positioning::Turn { move_back, feed }) => {
                if let Some(mb) = move_back {
                    let d = self.kin.tool_axis_mcs(self.axes.rotary);
                    let s = match mb {
                        MoveBack::Dist(v) => v,
                        MoveBack::Max => self.mb_max(cx, d),
                    };
                    let l = self.axes.linear + s * d;
                    self.check_linear(cx, l)?;
                    let target = MachineAxes { linear: l, ..self.axes };
                    let rate =
                        if unconfirmed::MB_RETRACT_AT_RAPID { Rate::Rapid } else { self.swivel_rate(feed) };
                    self.go(cx, rec, idx, SegmentKind::Retract, target, [0.0; 2], rate, || {
                        SegmentPath::Linear
                    });
                }
                let rate = self.swivel_rate(feed);
                let delta = self.rotary_delta(cx, target, true);
                let t = MachineAxes { rotary: target, ..self.axes };
                self.go(cx, rec, idx, SegmentKind::SwivelTurn, t, delta, rate, || SegmentPath::Linear);
            }
            Some(Positioning::Move { dist, feed }) => {
                let dist = dist.unwrap_or(unconfirmed::MOVE_DEFAULT_DIST);
                let tip = self.kin.tip_wcs(&self.axes);
                let centre = tip - dist * self.kin.tool_axis_wcs(self.axes.rotary);
                let mp = MovePath { kin: self.kin, centre, dist };
                let delta = self.rotary_delta(cx, target, true);
                // Check the travel along the way (16 samples) and at the end.
                for k in 1..=16 {
                    let f = f64::from(k) / 16.0;
                    let rot = [self.axes.rotary[0] + f * delta[0], self.axes.rotary[1] + f * delta[1]];
                    self.check_linear(cx, move_linear(&mp, rot))?;
                }
                let end = MachineAxes {
                    linear: move_linear(&mp, target),
                    rotary: target,
                    letters: self.axes.letters,
                };
                let rate = self.swivel_rate(feed);
                self.go(cx, rec, idx, SegmentKind::SwivelMove, end, delta, rate, || {
                    SegmentPath::Move(Box::new(mp))
                });
            }
        }
        self.sync_pos();
        Ok(())
    }

    /// STAY: no axis moves; a segment of [`STAY_SECONDS`] lets the view turn the working plane
    /// from `from` to `to` (W-CS orientations).
    fn stay_segment(&self, rec: &mut Option<&mut Rec>, block: usize, from: DMat3, to: DMat3) {
        if let Some(r) = rec.as_deref_mut() {
            r.segments.push(Segment {
                step: self.step_count.saturating_sub(1),
                block,
                kind: SegmentKind::SwivelStay,
                start: self.axes,
                end: self.axes,
                rotary_delta: [0.0; 2],
                duration: STAY_SECONDS,
                path: SegmentPath::Stay { from, to },
            });
        }
    }

    fn swivel_rate(&self, feed: Option<Feed<f64>>) -> Rate {
        match feed {
            Some(Feed::Value(f)) if f > 0.0 => Rate::Feed(f),
            Some(Feed::Auto) if self.tool.feed > 0.0 => Rate::Feed(self.tool.feed),
            _ => Rate::Rapid,
        }
    }

    /// `MB MAX`: the longest retract along `d` that stays inside every linear limit (derived).
    fn mb_max(&self, cx: &Cx<'_>, d: DVec3) -> f64 {
        let l = self.axes.linear;
        let mut s = f64::INFINITY;
        for (i, lim) in cx.machine.geometry.linear_limits.iter().enumerate() {
            if d[i] > 1e-12 {
                s = s.min((lim.max - l[i]) / d[i]);
            } else if d[i] < -1e-12 {
                s = s.min((lim.min - l[i]) / d[i]);
            }
        }
        if s.is_finite() { s.max(0.0) } else { 0.0 }
    }

    fn old_cycle(&mut self, cx: &Cx<'_>, rec: &mut Option<&mut Rec>, idx: usize, d: &CycleDefOld) -> R<()> {
        let words: &[OldCycleWord] = match &d.data {
            OldCycleData::Words(w) => w,
            _ => &[],
        };
        match (d.number, d.sub) {
            (7, 0) => {
                let base = match self.tf.level_now() {
                    Level::Wcs => self.tf.datum_w,
                    Level::Wpl => self.tf.datum_i,
                };
                self.c7 = Some(Cycle7 { base, written: [None; 3], any_absolute: false });
            }
            (7, _) => {
                let level = self.tf.level_now();
                let cur = match level {
                    Level::Wcs => self.tf.datum_w,
                    Level::Wpl => self.tf.datum_i,
                };
                // A sub-block without its header continues from the active shift.
                let mut c7 = self.c7.unwrap_or(Cycle7 { base: cur, written: [None; 3], any_absolute: false });
                for w in words {
                    if let OldCycleWord::Axis(a) = w
                        && let Some(i) = linear_index(a.axis)
                    {
                        let v = self.value(&a.value)?;
                        c7.written[i] = Some(if a.incremental { c7.base[i] + v } else { v });
                        c7.any_absolute |= !a.incremental;
                    }
                }
                self.c7 = Some(c7);
                let d = Self::datum_of(c7.base, c7.written, c7.any_absolute);
                match level {
                    Level::Wcs => self.tf.datum_w = d,
                    Level::Wpl => self.tf.datum_i = d,
                }
                self.sync_pos();
            }
            (8, 0) => {}
            (8, _) => {
                let mut set = [false; 3];
                for w in words {
                    if let OldCycleWord::MirrorAxis(a) = w
                        && let Some(i) = linear_index(*a)
                    {
                        set[i] = true;
                    }
                }
                self.set_mirror(set);
            }
            (10, 0) => {}
            (10, _) => {
                for w in words {
                    if let OldCycleWord::Rot { value, incremental } = w {
                        let v = self.value(value)?;
                        self.tf.rotation = if *incremental { self.tf.rotation + v } else { v };
                    }
                }
                self.sync_pos();
            }
            (11, _) => note(rec, || {
                ("Zyklus 11 (Maßfaktor) nicht simuliert".into(), "Cycle 11 (scaling) not simulated".into())
            }),
            (19, 0) => note(rec, || {
                (
                    "Zyklus 19: die Winkel folgen im Satz 19.1".into(),
                    "Cycle 19: the angles follow in block 19.1".into(),
                )
            }),
            (19, _) => self.cycle19(cx, rec, idx, words)?,
            (n, 0) => {
                self.cycle = Some(StoredCycle::Old(n));
                note(rec, || {
                    (format!("Zyklus {n} (alte Form) definiert"), format!("Cycle {n} (old form) defined"))
                });
            }
            _ => {}
        }
        Ok(())
    }

    /// Cycle 19 WORKING PLANE (DOMAIN.md §6, [M:320cyc-p258]).
    fn cycle19(
        &mut self,
        cx: &Cx<'_>,
        rec: &mut Option<&mut Rec>,
        idx: usize,
        words: &[OldCycleWord],
    ) -> R<()> {
        let mut abc = [0.0_f64; 3];
        for w in words {
            if let OldCycleWord::Axis(a) = w
                && let Some(ra) = rotary_of(a.axis)
            {
                let k = match ra {
                    RotaryAxis::A => 0,
                    RotaryAxis::B => 1,
                    RotaryAxis::C => 2,
                };
                abc[k] = self.value(&a.value)?;
            }
        }
        let before = self.tf.r();
        if abc.iter().all(|&v| v == 0.0) {
            self.tf.tilt = None;
            self.plane = None;
            self.stay_segment(rec, idx, before, DMat3::IDENTITY);
            self.sync_pos();
            note(rec, || ("Zyklus 19 zurückgesetzt".into(), "Cycle 19 reset".into()));
            return Ok(());
        }
        let machine = cx.machine;
        let mw = self.tf.mirror_w_matrix();
        let r = if unconfirmed::CYCLE19_INPUT_SPATIAL {
            let def = PlaneDef::Spatial { spa: abc[0], spb: abc[1], spc: abc[2] };
            orientation::validate(&def).map_err(|error| SimErrorCode::Plane { error })?;
            mw * orientation::spatial(abc[0], abc[1], abc[2]) * mw
        } else {
            machine.forward(&AxisValues { a: Some(abc[0]), b: Some(abc[1]), c: Some(abc[2]) })
        };
        // Cycle 19 takes the shorter path from the rotary axes' zero position [M:320cyc-p258].
        let mut zero = AxisValues::default();
        for j in machine.joints() {
            zero.set(j.axis, 0.0);
        }
        let e = Arc::new(Self::solved(solve::solve(
            machine,
            &r,
            &SolveOptions { start: zero, ..SolveOptions::default() },
        ))?);
        self.set_q_from(&e);
        self.tf.tilt = Some(r);
        self.stay_segment(rec, idx, before, r);
        self.plane = Some(Arc::new(ActivePlane {
            block: idx,
            source: TiltSource::Cycle19,
            orientation: r,
            spatial: orientation::to_spatial(&r),
            tool_axis: r.z_axis.to_array(),
            explanation: e.clone(),
        }));
        if let Some(rr) = rec.as_deref_mut() {
            rr.explanation = Some(e);
        }
        if unconfirmed::CYCLE19_MOVES_AXES {
            // Not the chosen convention; kept so the switch in unconfirmed.rs stays meaningful.
            note(rec, || ("Zyklus 19 positioniert die Achsen".into(), "Cycle 19 positions the axes".into()));
        } else {
            note(rec, || {
                (
                    "Zyklus 19 aktiv: Drehachsen mit L A+Q120 … positionieren".into(),
                    "Cycle 19 active: position the rotary axes with L A+Q120 …".into(),
                )
            });
        }
        self.sync_pos();
        Ok(())
    }

    fn call_cycle(&mut self, cx: &Cx<'_>, rec: &mut Option<&mut Rec>, idx: usize) -> R<()> {
        let Some(c) = self.cycle else { return Err(SimErrorCode::NoCycle) };
        let def = match c {
            StoredCycle::Old(n) => {
                note(rec, || (format!("Zyklus {n} nicht simuliert"), format!("Cycle {n} not simulated")));
                return Ok(());
            }
            StoredCycle::New(b) => match cx.program.blocks.get(b).map(|b| &b.body) {
                Some(BlockBody::CycleDef(d)) => d,
                _ => return Err(SimErrorCode::NoCycle),
            },
        };
        let number = def.number;
        if def.params.is_empty() {
            return Err(SimErrorCode::CycleParamsMissing { cycle: number });
        }
        let q = |i: u32| -> R<f64> {
            match def.params.iter().rev().find(|p| p.index == i) {
                Some(p) => self.value(&p.value),
                None => Err(SimErrorCode::CycleParamMissing { cycle: number, param: i }),
            }
        };
        let moves: Vec<CycleMove> = match number {
            200 => cycles::drill_200(&q, self.pos_i)?,
            232 => {
                let strategy = q(389).unwrap_or(0.0);
                let m = cycles::face_mill_232(&q, self.pos_i, self.tool.radius)?;
                if strategy != 0.0 && unconfirmed::CYCLE232_STRATEGY {
                    note(rec, || {
                        (
                            format!("Zyklus 232: Strategie Q389={strategy} als Mäander simuliert"),
                            format!("Cycle 232: strategy Q389={strategy} simulated as a meander"),
                        )
                    });
                }
                m
            }
            n => {
                note(rec, || (format!("Zyklus {n} nicht simuliert"), format!("Cycle {n} not simulated")));
                return Ok(());
            }
        };
        for m in &moves {
            let l = self.map.apply(m.target);
            self.check_linear(cx, l)?;
            let (kind, rate) = match m.feed {
                None => (SegmentKind::Rapid, Rate::Rapid),
                Some(f) => (SegmentKind::CycleFeed, Rate::Feed(f)),
            };
            let target = MachineAxes { linear: l, ..self.axes };
            self.go(cx, rec, idx, kind, target, [0.0; 2], rate, || SegmentPath::Linear);
            self.pos_i = m.target;
        }
        if rec.as_ref().is_some_and(|r| r.message.is_none()) {
            let n = moves.len();
            note(rec, || {
                (
                    format!("Zyklus {number} ausgeführt ({n} Bewegungen in der Bearbeitungsebene)"),
                    format!("Cycle {number} executed ({n} moves in the working plane)"),
                )
            });
        }
        Ok(())
    }

    /// The full state after the step just executed.
    pub fn state(
        &self,
        program: &Program,
        machine: &Machine,
        step: usize,
        executed: bool,
        rec: Rec,
    ) -> State {
        let block = self.last;
        let line = program.blocks.get(block).map_or(0, |b| b.line);
        let rot = self.axes.rotary;
        let wpose = if self.compensating() { self.kin.workpiece_pose(rot) } else { Affine::IDENTITY };
        let preset = self.kin.preset;
        let ics = self.tf.ics_to_wcs();
        let frames = Frames {
            wcs: Frame { origin: wpose.apply(preset), axes: wpose.m },
            wpl: Frame { origin: wpose.apply(preset + self.tf.datum_w), axes: wpose.m * self.tf.r() },
            ics: Frame { origin: wpose.apply(preset + ics.v), axes: wpose.m * ics.m },
        };
        State {
            step,
            block,
            line,
            axes: self.axes,
            tool: self.tool.clone(),
            spindle: self.spindle,
            feed: self.feed,
            blank: self.blank,
            transforms: self.tf.list(self.plane.as_ref().map(|p| p.spatial)),
            frames,
            pivots: self.pivots(machine),
            tip_mcs: self.kin.tip_mcs(&self.axes),
            tip_wcs: self.kin.tip_wcs(&self.axes),
            tip_ics: self.pos_i,
            tool_axis_mcs: self.kin.tool_axis_mcs(rot),
            q: self.q.clone(),
            plane: self.plane.clone(),
            explanation: rec.explanation,
            message: rec.message,
            segments: rec.segments,
            ended: self.ended,
            executed,
        }
    }

    /// Where the rotary axes stand (3D view): table axes moved by the table axes that carry
    /// them, head axes by the head axes nearer the bed, plus the linear axes.
    fn pivots(&self, machine: &Machine) -> [Pivot; 2] {
        let j = self.kin.joints;
        let rot = self.axes.rotary;
        let gauge = DVec3::new(0.0, 0.0, self.kin.tool_length);
        let letters = [machine.joints()[0].axis, machine.joints()[1].axis];
        let one = |k: usize| -> Pivot {
            let mut outer = Affine::IDENTITY;
            let (point, base) = match j[k].carrier {
                Carrier::Table => {
                    for m in (k + 1)..2 {
                        if j[m].carrier == Carrier::Table {
                            outer = Affine::rotation_about(j[m].dir, j[m].pivot, -rot[m]).after(&outer);
                        }
                    }
                    (j[k].pivot, DVec3::ZERO)
                }
                Carrier::Head => {
                    for m in 0..k {
                        if j[m].carrier == Carrier::Head {
                            outer =
                                outer.after(&Affine::rotation_about(j[m].dir, gauge + j[m].pivot, rot[m]));
                        }
                    }
                    (gauge + j[k].pivot, self.axes.linear)
                }
            };
            Pivot { axis: letters[k], point: base + outer.apply(point), direction: outer.m * j[k].dir }
        };
        [one(0), one(1)]
    }
}
