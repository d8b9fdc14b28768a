//! Tilting the working plane: PLANE blocks (positioning with MOVE, TURN, STAY; MB; Q120–Q122)
//! and cycle 19.

use super::*;

impl Interp {
    /// Solves a target orientation R (already mirrored) or a PLANE block; returns the
    /// explanation or the control's error.
    pub(super) fn solved(e: Explanation) -> R<Explanation> {
        match e.error {
            Some(error) => Err(SimErrorCode::Solve { error }),
            None if e.chosen.is_none() => Err(SimErrorCode::Solve {
                error: SolveError::NoSolutionInLimits { candidates: e.candidates.len() },
            }),
            None => Ok(e),
        }
    }

    pub(super) fn set_q_from(&mut self, e: &Explanation) {
        for (i, v) in [(120, e.q.q120), (121, e.q.q121), (122, e.q.q122)] {
            if let Some(v) = v {
                self.q.insert(i, v);
            }
        }
    }

    pub(super) fn target_rotary(&self, axes: &AxisValues) -> [f64; 2] {
        let mut rot = self.axes.rotary;
        for (k, l) in self.axes.letters.iter().enumerate() {
            if let Some(v) = axes.get(*l) {
                rot[k] = v;
            }
        }
        rot
    }

    pub(super) fn plane(&mut self, at: &mut At<'_, '_>, pb: &PlaneBlock) -> R<()> {
        let pb = self.positioning_in_mm(pb.try_map(|v| self.value(v))?);
        let machine = at.cx.machine;
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
                block: at.block,
                source: TiltSource::Plane,
                orientation: r,
                spatial: orientation::to_spatial(&r),
                tool_axis: r.z_axis.to_array(),
                explanation: expl.clone(),
            })
        });
        if let Some(r) = at.rec.as_deref_mut() {
            r.explanation = Some(expl.clone());
        }
        match pb.positioning {
            None | Some(Positioning::Stay) => {
                if pb.positioning.is_none() {
                    at.note(|| Note::PositioningMissing);
                }
                self.stay_segment(at, before, self.tf.r());
            }
            Some(Positioning::Turn { move_back, feed }) => {
                if let Some(mb) = move_back {
                    let rate =
                        if unconfirmed::MB_RETRACT_AT_RAPID { Rate::Rapid } else { self.swivel_rate(feed) };
                    self.retract(at, mb, rate)?;
                }
                let rate = self.swivel_rate(feed);
                let plan = |it: &Self, target: [f64; 2]| {
                    let end = MachineAxes { rotary: target, ..it.axes };
                    (end, it.rotary_delta(at.cx, target, true), SegmentPath::Linear)
                };
                self.swivel(at, &expl, SegmentKind::SwivelTurn, rate, target, plan)?;
            }
            Some(Positioning::Move { dist, feed }) => {
                let dist = dist.unwrap_or(unconfirmed::MOVE_DEFAULT_DIST);
                let tip = self.kin.tip_wcs(&self.axes);
                let centre = tip - dist * self.kin.tool_axis_wcs(self.axes.rotary);
                let mp = MovePath { kin: self.kin, centre, dist };
                let delta = self.rotary_delta(at.cx, target, true);
                // Check the travel along the way (16 samples) and at the end.
                for k in 1..=16 {
                    let f = f64::from(k) / 16.0;
                    let rot = [self.axes.rotary[0] + f * delta[0], self.axes.rotary[1] + f * delta[1]];
                    self.check_linear(at.cx, move_linear(&mp, rot))?;
                }
                let rate = self.swivel_rate(feed);
                let plan = |it: &Self, target: [f64; 2]| {
                    let end = MachineAxes {
                        linear: move_linear(&mp, target),
                        rotary: target,
                        letters: it.axes.letters,
                    };
                    (end, it.rotary_delta(at.cx, target, true), SegmentPath::Move(Box::new(mp.clone())))
                };
                self.swivel(at, &expl, SegmentKind::SwivelMove, rate, target, plan)?;
            }
        }
        self.sync_pos();
        Ok(())
    }

    /// The swivel of a PLANE block to `target` as `plan` lays it out from the axes now. When it
    /// collides and the swivel to another permitted solution of `expl` would not, the error
    /// names that solution (the why panel's safe alternative, the view's ghost).
    fn swivel(
        &mut self,
        at: &mut At<'_, '_>,

        expl: &Explanation,
        kind: SegmentKind,
        rate: Rate,
        target: [f64; 2],
        plan: impl Fn(&Self, [f64; 2]) -> (MachineAxes, [f64; 2], SegmentPath),
    ) -> R<()> {
        let (end, delta, path) = plan(self, target);
        match self.go(at, kind, end, delta, rate, || path) {
            Err(SimErrorCode::Collision(mut c)) => {
                c.alternative = self.safe_alternative(at.cx, at.block, expl, kind, &plan);
                Err(SimErrorCode::Collision(c))
            }
            other => other,
        }
    }

    /// The first other permitted candidate of `expl` whose swivel from the axes now is inside
    /// the linear limits and collision-free.
    fn safe_alternative(
        &self,
        cx: &Cx<'_>,
        idx: usize,
        expl: &Explanation,
        kind: SegmentKind,
        plan: &impl Fn(&Self, [f64; 2]) -> (MachineAxes, [f64; 2], SegmentPath),
    ) -> Option<SafeAlternative> {
        let chosen = expl.chosen?;
        expl.candidates.iter().enumerate().filter(|(i, c)| *i != chosen && c.in_limits).find_map(|(_, c)| {
            let (end, delta, path) = plan(self, self.target_rotary(&c.axes));
            let seg = self.segment(idx, kind, end, delta, 0.0, path);
            let free = self.check_linear(cx, end.linear).is_ok()
                && self.collided(&seg, &mut Clearances::default()).is_none();
            // SEQ counts the master's sign ([`unconfirmed::ZERO_COUNTS_AS_PLUS`] at 0).
            let plus = c.master > 0.0 || (c.master == 0.0 && unconfirmed::ZERO_COUNTS_AS_PLUS);
            free.then(|| SafeAlternative {
                word: format!("SEQ{}", if plus { '+' } else { '−' }),
                axes: c.axes,
            })
        })
    }

    /// STAY: no axis moves; a segment of [`STAY_SECONDS`] lets the view turn the working plane
    /// from `from` to `to` (W-CS orientations).
    pub(super) fn stay_segment(&self, at: &mut At<'_, '_>, from: DMat3, to: DMat3) {
        if let Some(r) = at.rec.as_deref_mut() {
            r.segments.push(Segment {
                step: self.step_count.saturating_sub(1),
                block: at.block,
                kind: SegmentKind::SwivelStay,
                start: self.axes,
                end: self.axes,
                rotary_delta: [0.0; 2],
                duration: STAY_SECONDS,
                path: SegmentPath::Stay { from, to },
            });
        }
    }

    /// The PLANE block with its positioning's distance (DIST, MB) in mm and its F in mm/min;
    /// the angles stay as written, and so does PLANE POINTS: its plane does not depend on the
    /// unit.
    fn positioning_in_mm(&self, mut pb: PlaneBlock<f64>) -> PlaneBlock<f64> {
        let (mm, f_mm) = (self.unit.mm(), self.unit.feed_mm_per_min());
        let feed = |f: &mut Option<Feed<f64>>| {
            if let Some(Feed::Value(v)) = f {
                *v *= f_mm;
            }
        };
        match &mut pb.positioning {
            Some(Positioning::Move { dist, feed: f }) => {
                if let Some(d) = dist {
                    *d *= mm;
                }
                feed(f);
            }
            Some(Positioning::Turn { move_back, feed: f }) => {
                if let Some(MoveBack::Dist(d)) = move_back {
                    *d *= mm;
                }
                feed(f);
            }
            Some(Positioning::Stay) | None => {}
        }
        pb
    }

    pub(super) fn swivel_rate(&self, feed: Option<Feed<f64>>) -> Rate {
        match feed {
            Some(Feed::Value(f)) if f > 0.0 => Rate::Feed(f),
            Some(Feed::Auto) if self.tool.feed > 0.0 => Rate::Feed(self.tool.feed),
            _ => Rate::Rapid,
        }
    }

    /// The retract along the tool axis of `TURN MB…` and `M140 MB…`, by the distance or to
    /// just before the limits (`MB MAX`).
    pub(super) fn retract(&mut self, at: &mut At<'_, '_>, mb: MoveBack<f64>, rate: Rate) -> R<()> {
        let d = self.kin.tool_axis_mcs(self.axes.rotary);
        let s = match mb {
            MoveBack::Dist(v) => v,
            MoveBack::Max => self.mb_max(at.cx, d),
        };
        let l = self.axes.linear + s * d;
        self.check_linear(at.cx, l)?;
        let target = MachineAxes { linear: l, ..self.axes };
        self.go(at, SegmentKind::Retract, target, [0.0; 2], rate, || SegmentPath::Linear)
    }

    /// `M140 MB…` ("retraction in the tool axis direction", TNC 640 user's manual), after the
    /// block's own move: at rapid, or at the feed written after MB
    /// ([`unconfirmed::M140_FEED_AFTER_MB`]). Out of line: rare, so the page split defers it.
    #[inline(never)]
    pub(super) fn m140(&mut self, at: &mut At<'_, '_>, mb: MoveBack, feed: Option<Feed>) -> R<()> {
        let mb = match mb {
            MoveBack::Dist(v) => MoveBack::Dist(self.length(&v)?),
            MoveBack::Max => MoveBack::Max,
        };
        let feed = match feed {
            Some(Feed::Value(v)) if unconfirmed::M140_FEED_AFTER_MB => {
                Some(self.feed_rate(&v)?).filter(|&f| f > 0.0)
            }
            _ => None,
        };
        self.retract(at, mb, feed.map_or(Rate::Rapid, Rate::Feed))?;
        at.note(|| Note::Retract { feed });
        Ok(())
    }

    /// `MB MAX`: the longest retract along `d` that ends "just before the software limit
    /// switch" (DOMAIN.md §4): every linear axis stays `MB_MAX_CLEARANCE` inside its limits.
    pub(super) fn mb_max(&self, cx: &Cx<'_>, d: DVec3) -> f64 {
        let l = self.axes.linear;
        let margin = unconfirmed::MB_MAX_CLEARANCE;
        let mut s = f64::INFINITY;
        for (i, lim) in cx.machine.geometry.linear_limits.iter().enumerate() {
            if d[i] > 1e-12 {
                s = s.min((lim.max - margin - l[i]) / d[i]);
            } else if d[i] < -1e-12 {
                s = s.min((lim.min + margin - l[i]) / d[i]);
            }
        }
        if s.is_finite() { s.max(0.0) } else { 0.0 }
    }

    /// Cycle 19 WORKING PLANE (DOMAIN.md §6, [M:320cyc-p258]).
    pub(super) fn cycle19(&mut self, at: &mut At<'_, '_>, words: &[OldCycleWord]) -> R<()> {
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
            self.stay_segment(at, before, DMat3::IDENTITY);
            self.sync_pos();
            at.note(|| Note::Cycle19Reset);
            return Ok(());
        }
        let machine = at.cx.machine;
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
        self.stay_segment(at, before, r);
        self.plane = Some(Arc::new(ActivePlane {
            block: at.block,
            source: TiltSource::Cycle19,
            orientation: r,
            spatial: orientation::to_spatial(&r),
            tool_axis: r.z_axis.to_array(),
            explanation: e.clone(),
        }));
        if let Some(rr) = at.rec.as_deref_mut() {
            rr.explanation = Some(e);
        }
        if unconfirmed::CYCLE19_MOVES_AXES {
            // Not the chosen convention; kept so the switch in unconfirmed.rs stays meaningful.
            at.note(|| Note::Cycle19MovesAxes);
        } else {
            at.note(|| Note::Cycle19Active);
        }
        self.sync_pos();
        Ok(())
    }
}
