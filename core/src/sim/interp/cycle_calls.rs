//! Cycle definitions (`CYCL DEF n`, the old form `CYCL DEF 7.x`, `19.x` …) and cycle calls
//! (`CYCL CALL`, `M99`, modal `M89`, `CYCL CALL PAT` with `PATTERN DEF`, `CYCL CALL POS`, the
//! DEF-active patterns 220 and 221): what each called cycle moves ([`cycles`]), recorded as
//! segments in the I-CS, arcs and helices as [`SegmentPath::Arc`].

use super::*;
use crate::ast::{CycleParam, CycleValue, PatternItem, PatternKey};
use crate::sim::cycles::{ArcTo, CycleRun, Params, PatternValues, rapid};

impl Interp {
    #[inline(never)]
    pub(super) fn old_cycle(&mut self, at: &mut At<'_, '_>, d: &CycleDefOld) -> R<()> {
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
                        let v = self.length(&a.value)?;
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
            (11, _) => at.note(|| Note::Cycle11NotSimulated),
            (19, 0) => at.note(|| Note::Cycle19AnglesFollow),
            (19, _) => self.cycle19(at, words)?,
            (n, 0) => {
                self.calls_cycle.cycle = Some(StoredCycle::Old(n));
                at.note(|| Note::OldCycleDefined { cycle: n });
            }
            _ => {}
        }
        Ok(())
    }

    /// `CYCL DEF n …`: a machining cycle is stored for its calls; 220 and 221 are DEF-active and
    /// call the stored one at once.
    pub(super) fn cycle_def(&mut self, at: &mut At<'_, '_>, d: &CycleDef) -> R<()> {
        if matches!(d.number, 220 | 221) {
            return self.pattern_cycle(at, d);
        }
        self.calls_cycle.cycle = Some(StoredCycle::New(at.block));
        if d.params.is_empty() {
            at.note(|| Note::CycleDefinedParamsFromQ { cycle: d.number });
        } else {
            at.note(|| Note::CycleDefined { cycle: d.number });
        }
        Ok(())
    }

    /// The evaluated parameters of a definition. A definition without its parameter lines
    /// (`CYCL DEF 200 BOHREN`, then `Q200 = 2`, `Q201 = -15` as blocks of their own, as a
    /// training simulator's examples write it) takes them from the Q parameters Q200…Q1199 at
    /// the call: the range the cycles' parameters live in, "globally effective" (TNC 320/620,
    /// iTNC 530 user's manuals, Q parameters: principle and overview;
    /// `unconfirmed::CYCLE_PARAMS_FROM_GLOBAL_Q`). None of them set: the parameters were left
    /// out (a textbook's elision), the "parameter missing" stop.
    fn params_of(&self, d: &CycleDef) -> R<Params> {
        if d.params.is_empty() {
            if !unconfirmed::CYCLE_PARAMS_FROM_GLOBAL_Q {
                return Err(SimErrorCode::CycleParamsMissing { cycle: d.number });
            }
            let set: Vec<CycleParam> = self
                .q
                .range(200..1200)
                .map(|(&index, _)| CycleParam {
                    index,
                    value: CycleValue::Value(Value::Param { index, negate: false }),
                    label: None,
                })
                .collect();
            if set.is_empty() {
                return Err(SimErrorCode::CycleParamsMissing { cycle: d.number });
            }
            return self.params_of(&CycleDef { number: d.number, name: String::new(), params: set });
        }
        let word = |p: &CycleParam| SimErrorCode::CycleWordUnknown {
            cycle: d.number,
            param: p.index,
            word: p.value.word().unwrap_or_default(),
        };
        let values = d
            .params
            .iter()
            .filter_map(|p| {
                let quantity = cycles::quantity(p.index);
                let v = match &p.value {
                    CycleValue::Value(v) => match quantity {
                        Some(cycles::Quantity::Length) => self.length(v),
                        Some(cycles::Quantity::Feed) => self.feed_rate(v),
                        _ => self.value(v),
                    },
                    // The cycle dialog offers FMAX and FAUTO for feed rates only (TNC 640 cycle
                    // manual, e.g. "Q253 … alternatively FMAX, FAUTO").
                    CycleValue::Fmax | CycleValue::Fauto
                        if matches!(quantity, Some(cycles::Quantity::Length | cycles::Quantity::Other)) =>
                    {
                        Err(SimErrorCode::CycleWordNotFeed {
                            cycle: d.number,
                            param: p.index,
                            word: p.value.word().unwrap_or_default(),
                        })
                    }
                    CycleValue::Fmax => Ok(unconfirmed::CYCLE_FMAX_FEED),
                    CycleValue::Fauto => match [self.tool.feed, self.feed].into_iter().find(|&f| f > 0.0) {
                        Some(f) => Ok(f),
                        // A parameter no simulated cycle reads (cycle 22's Q11): its value is not
                        // needed, so an unknown feed stops nothing.
                        None if quantity.is_none() => return None,
                        None => Err(word(p)),
                    },
                    CycleValue::Predef => unconfirmed::predef(p.index).ok_or_else(|| word(p)),
                    // A string parameter (cycle 225's text) is no number: no simulated cycle reads one.
                    CycleValue::Text(_) | CycleValue::TextOf(_) => return None,
                };
                Some(v.map(|v| (p.index, v)))
            })
            .collect::<R<Vec<_>>>()?;
        Ok(Params::new(d.number, values))
    }

    /// The stored machining cycle's parameters; `None` (with a note) for an old-style cycle,
    /// which is not simulated.
    fn stored_params(&self, at: &mut At<'_, '_>) -> R<Option<Params>> {
        match self.calls_cycle.cycle {
            None => Err(SimErrorCode::NoCycle),
            Some(StoredCycle::Old(n)) => {
                at.note(|| Note::CycleNotSimulated { cycle: n });
                Ok(None)
            }
            Some(StoredCycle::New(b)) => {
                match at.cx.program.blocks.get(b).and_then(crate::Block::stored_body) {
                    Some(BlockBody::CycleDef(d)) => self.params_of(d).map(Some),
                    _ => Err(SimErrorCode::NoCycle),
                }
            }
        }
    }

    /// Runs the stored cycle at the current position with its parameters adjusted by `adjust`;
    /// the number of moves, or `None` when it is not simulated (said in the block's message).
    fn run_stored(&mut self, at: &mut At<'_, '_>, adjust: impl Fn(&mut Params)) -> R<Option<(u32, usize)>> {
        let Some(mut p) = self.stored_params(at)? else { return Ok(None) };
        adjust(&mut p);
        let n = p.cycle;
        let Some(CycleRun { moves, note: simplified }) = cycles::run(&p, self.pos_i, self.tool.radius)?
        else {
            at.note(|| Note::CycleNotSimulated { cycle: n });
            return Ok(None);
        };
        if let Some(note) = simplified {
            at.note(|| note);
        }
        self.run_moves(at, &moves)?;
        Ok(Some((n, moves.len())))
    }

    /// `M99`, `CYCL CALL` and each block of a modal `M89` call: the stored cycle here.
    pub(super) fn call_cycle(&mut self, at: &mut At<'_, '_>) -> R<()> {
        if let Some((cycle, moves)) = self.run_stored(at, |_| {})?
            && at.unnoted()
        {
            at.note(|| Note::CycleExecuted { cycle, moves });
        }
        Ok(())
    }

    /// After an `L` block: `M89` starts the modal cycle call ([`unconfirmed::M89_CALLS_AT_ITS_BLOCK`]):
    /// "for every following positioning block there will be a call of the last-programmed
    /// machining cycle" (HEIDENHAIN TNC 306/406 technical manual, "M-function M89"); it ends with
    /// `M99` (which calls once more, in [`Self::line`]) or a new `CYCL DEF` (iTNC 530 cycle
    /// manual, DOMAIN.md §11).
    pub(super) fn modal_call(&mut self, at: &mut At<'_, '_>, line: &Line) -> R<()> {
        if line.m.contains(&99) {
            self.calls_cycle.m89 = false;
            return Ok(());
        }
        if line.m.contains(&89) {
            self.calls_cycle.m89 = true;
            if !unconfirmed::M89_CALLS_AT_ITS_BLOCK {
                return Ok(());
            }
        }
        if self.calls_cycle.m89 && !self.ended && line.axes.iter().any(|w| linear_index(w.axis).is_some()) {
            self.call_cycle(at)?;
        }
        Ok(())
    }

    /// The moves of a cycle, each recorded as a segment (arcs and helices exact at any fraction).
    fn run_moves(&mut self, at: &mut At<'_, '_>, moves: &[CycleMove]) -> R<()> {
        for m in moves {
            let l = self.map.apply(m.target);
            self.check_linear(at.cx, l)?;
            let (kind, rate) = match m.feed {
                None => (SegmentKind::Rapid, Rate::Rapid),
                Some(f) => (SegmentKind::CycleFeed, Rate::Feed(f)),
            };
            let target = MachineAxes { linear: l, ..self.axes };
            match m.arc {
                None => self.go(at, kind, target, [0.0; 2], rate, || SegmentPath::Linear)?,
                Some(ArcTo { centre, sweep }) => {
                    // The I-CS arc about the tool axis (Z) carried through the I-CS → axes map,
                    // which only turns, mirrors and shifts (as the contour's arcs).
                    let start = self.pos_i;
                    let c = centre.extend(start.z);
                    let u = start - c;
                    let rise = m.target.z - start.z;
                    let mm = self.map.m;
                    let path = SegmentPath::Arc(Box::new(ArcPath {
                        centre: self.map.apply(c),
                        u: mm * u,
                        v: mm * DVec3::Z.cross(u),
                        sweep,
                        lead: mm * DVec3::new(0.0, 0.0, rise),
                    }));
                    let length = (u.length() * sweep).hypot(rise);
                    self.go_along(at, kind, target, rate, length, path)?;
                }
            }
            self.pos_i = m.target;
        }
        Ok(())
    }

    /// The words of a `PATTERN DEF` item as numbers (a word left out, which the parser reports,
    /// counts as 0, a count as 1).
    fn pattern_values(&self, item: &PatternItem) -> R<PatternValues> {
        // Positions, diameters and spacings are lengths; counts and angles stay as written.
        let get = |k: PatternKey, default: f64| {
            item.get(k).map_or(Ok(default), |v| match k {
                PatternKey::X
                | PatternKey::Y
                | PatternKey::Z
                | PatternKey::D
                | PatternKey::Dx
                | PatternKey::Dy => self.length(&v),
                _ => self.value(&v),
            })
        };
        Ok(PatternValues {
            kind: item.kind,
            x: get(PatternKey::X, 0.0)?,
            y: get(PatternKey::Y, 0.0)?,
            z: get(PatternKey::Z, 0.0)?,
            d: get(PatternKey::D, 0.0)?,
            dx: get(PatternKey::Dx, 0.0)?,
            dy: get(PatternKey::Dy, 0.0)?,
            num: get(PatternKey::Num, 1.0)?,
            numx: get(PatternKey::NumX, 1.0)?,
            numy: get(PatternKey::NumY, 1.0)?,
            rot: get(PatternKey::Rot, 0.0)?,
            rotx: get(PatternKey::RotX, 0.0)?,
            roty: get(PatternKey::RotY, 0.0)?,
            start: get(PatternKey::Start, 0.0)?,
            step: get(PatternKey::Step, 0.0)?,
        })
    }

    /// `CYCL CALL PAT`: the stored cycle at every point of the last `PATTERN DEF`, the point's Z
    /// added to the cycle's surface Q203. Between the points the tool travels at the clearance
    /// height, "the spindle axis coordinate at the cycle call or Q204, whichever is greater"
    /// (manual, "Calling a cycle with CYCL CALL PAT"), at the block's feed
    /// ([`unconfirmed::CYCL_CALL_PAT_FEED_BETWEEN_POINTS`]).
    #[inline(never)]
    pub(super) fn call_pattern(
        &mut self,
        at: &mut At<'_, '_>,

        feed: Option<&Feed<Value>>,
        m: &[u32],
    ) -> R<()> {
        self.m_functions(at, m);
        let items = match self
            .calls_cycle
            .pattern
            .and_then(|b| at.cx.program.blocks.get(b))
            .and_then(crate::Block::stored_body)
        {
            Some(BlockBody::PatternDef(items)) => items,
            _ => return Err(SimErrorCode::NoPattern),
        };
        let mut points = Vec::new();
        for item in items.iter() {
            points.extend(cycles::pattern_points(&self.pattern_values(item)?));
        }
        points.truncate(MAX_PATTERN_POINTS);
        let Some(p) = self.stored_params(at)? else {
            self.end_m(m);
            return Ok(());
        };
        let rate = match feed {
            Some(Feed::Value(v)) if unconfirmed::CYCL_CALL_PAT_FEED_BETWEEN_POINTS => {
                Some(self.feed_rate(v)?)
            }
            _ => None,
        };
        let z_call = self.pos_i.z;
        let (surface, clear2) = (p.or(203, 0.0), p.or(204, 0.0));
        let mut moves = 0;
        for &(xy, z) in &points {
            let height = z_call.max(surface + z + clear2);
            let mut pre = Vec::new();
            if self.pos_i.z < height {
                pre.push(rapid(self.pos_i.truncate().extend(height)));
            }
            pre.push(CycleMove { target: xy.extend(self.pos_i.z.max(height)), feed: rate, arc: None });
            self.run_moves(at, &pre)?;
            moves += pre.len() + self.run_stored(at, |q| shift_surface(q, z))?.map_or(0, |(_, n)| n);
        }
        if at.unnoted() {
            at.note(|| Note::PatternCall { cycle: p.cycle, points: points.len(), moves });
        }
        self.end_m(m);
        Ok(())
    }

    /// `CYCL CALL POS X… Y… Z…`: the stored cycle at that position, its Z "an additional datum
    /// shift" of the surface Q203. Above the surface the tool moves first in the plane, then in
    /// the tool axis; below it first up to the clearance height
    /// ([`unconfirmed::CYCL_CALL_POS_CLEARANCE`]), then in the plane (manual, "Calling a cycle
    /// with CYCL CALL POS"). The block's feed acts only on these moves.
    #[inline(never)]
    pub(super) fn call_pos(&mut self, at: &mut At<'_, '_>, l: &Line) -> R<()> {
        self.m_functions(at, &l.m);
        let Some(p) = self.stored_params(at)? else {
            self.end_m(&l.m);
            return Ok(());
        };
        let mut target = self.pos_i;
        for w in l.axes.iter() {
            let Some(i) = linear_index(w.axis) else {
                return Err(SimErrorCode::AxisNotOnMachine { axis: letter(w.axis) });
            };
            let v = self.length(&w.value)?;
            target[i] = if w.incremental { target[i] + v } else { v };
        }
        let rate = match l.feed.as_ref() {
            Some(Feed::Value(v)) => Some(self.feed_rate(v)?),
            Some(Feed::Max) => None,
            Some(Feed::Auto) => (self.tool.feed > 0.0).then_some(self.tool.feed),
            None => (self.feed > 0.0).then_some(self.feed),
        };
        let surface = p.or(203, 0.0) + target.z;
        let here = self.pos_i;
        let go = |v: DVec3| CycleMove { target: v, feed: rate, arc: None };
        let pre = if here.z > surface || !unconfirmed::CYCL_CALL_POS_CLEARANCE {
            vec![go(target.truncate().extend(here.z)), go(target)]
        } else {
            let h = surface + p.or(204, 0.0);
            vec![go(here.truncate().extend(h)), go(target.truncate().extend(h)), go(target)]
        };
        self.run_moves(at, &pre)?;
        let shift = target.z;
        if let Some((cycle, moves)) = self.run_stored(at, |q| shift_surface(q, shift))?
            && at.unnoted()
        {
            at.note(|| Note::PosCall { cycle, moves });
        }
        self.end_m(&l.m);
        Ok(())
    }

    /// Cycles 220 MUSTER KREIS and 221 MUSTER LINIEN (DEF-active): the stored cycle at every
    /// point, with this cycle's Q200, Q203 and Q204 (manual: "the set-up clearance, workpiece
    /// surface and 2nd set-up clearance that you defined in cycle 220 are effective for the
    /// selected fixed cycle"). To the first point: up to Q204, in the plane, (the cycle) down to
    /// Q200; between the points at Q200 (Q301 = 0) or Q204 (Q301 = 1), on a straight line or,
    /// for 220 with Q365 = 1, on the circle; at the end to Q204 ([`unconfirmed::PATTERN_CYCLE_END`]).
    fn pattern_cycle(&mut self, at: &mut At<'_, '_>, d: &CycleDef) -> R<()> {
        let p = self.params_of(d)?;
        let (points, circle) = if d.number == 220 {
            let (points, centre, step) = cycles::circle_220(&p)?;
            (points, (p.or(365, 0.0) == 1.0).then_some((centre, step)))
        } else {
            (cycles::grid_221(&p)?, None)
        };
        let (clear, surface, clear2, q301) = (p.get(200)?, p.get(203)?, p.get(204)?, p.get(301)?);
        let between = if q301 == 0.0 { clear } else { clear2 };
        let high = surface + clear2;
        let mut moves = 0;
        let mut called = None;
        for (k, &xy) in points.iter().take(MAX_PATTERN_POINTS).enumerate() {
            let here = self.pos_i;
            let pre = if k == 0 {
                let mut v = Vec::new();
                if here.z < high {
                    v.push(rapid(here.truncate().extend(high)));
                }
                v.push(rapid(xy.extend(here.z.max(high))));
                v
            } else {
                let on_circle = circle
                    .filter(|(c, _)| ((here.truncate() - *c).length() - (xy - *c).length()).abs() < 1e-6);
                let arc = on_circle.map(|(centre, step)| ArcTo { centre, sweep: step.to_radians() });
                vec![CycleMove { target: xy.extend(here.z), feed: None, arc }]
            };
            self.run_moves(at, &pre)?;
            let Some((n, count)) = self.run_stored(at, |q| {
                q.set(200, clear);
                q.set(203, surface);
                q.set(204, between);
            })?
            else {
                return Ok(());
            };
            called = Some(n);
            moves += pre.len() + count;
        }
        if unconfirmed::PATTERN_CYCLE_END && self.pos_i.z < high {
            moves += 1;
            self.run_moves(at, &[rapid(self.pos_i.truncate().extend(high))])?;
        }
        if at.unnoted() {
            let points = points.len().min(MAX_PATTERN_POINTS);
            at.note(|| Note::PatternCycle { cycle: d.number, called, points, moves });
        }
        Ok(())
    }
}

/// Upper bound of the positions of one pattern call.
const MAX_PATTERN_POINTS: usize = 10_000;

/// The surface Q203 of a called cycle moved by `z` (the pattern point's or `CYCL CALL POS`'s Z).
fn shift_surface(p: &mut Params, z: f64) {
    if z != 0.0
        && let Ok(s) = p.get(203)
    {
        p.set(203, s + z);
    }
}
