//! Axis motion: limit checks, the rotary path, feed rates and `L` blocks, each move recorded
//! as segments the 3D view animates.

use super::*;
use crate::sim::arc::Elem;
use crate::sim::segment::TcpmPath;

/// `M91`, and `M92` whose datum is taken as the machine datum
/// ([`unconfirmed::M92_AT_MACHINE_DATUM`]): the block's coordinates are machine coordinates.
pub(super) fn in_machine_coordinates(line: &Line) -> bool {
    line.m.contains(&91) || (unconfirmed::M92_AT_MACHINE_DATUM && line.m.contains(&92))
}

/// Duration (s) = distance / (feed per minute) · 60; the longer of the linear (`lin`, mm) and
/// rotary (`rot`, °) shares wins (sim.rs doc). The rotary share takes F as written in °/min:
/// `unit` undoes the mm/min conversion of an `INCH` program's F.
fn duration(cx: &Cx<'_>, unit: Unit, rate: Rate, lin: f64, rot: f64) -> f64 {
    let g = &cx.machine.geometry;
    let (lin_rate, rot_rate) = match rate {
        Rate::Feed(f) if f > 0.0 => (f, f / unit.feed_mm_per_min()),
        _ => (g.rapid_linear, g.rapid_rotary),
    };
    let d = (lin / lin_rate).max(rot / rot_rate) * 60.0;
    if d.is_finite() { d } else { 0.0 }
}

impl Interp {
    pub(super) fn check_linear(&self, cx: &Cx<'_>, l: DVec3) -> R<()> {
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

    pub(super) fn check_rotary(&self, cx: &Cx<'_>, rot: [f64; 2]) -> R<()> {
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
    pub(super) fn rotary_delta(&self, cx: &Cx<'_>, end: [f64; 2], short: bool) -> [f64; 2] {
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

    /// Moves to `target`, checking the motion for collisions and recording a segment when a
    /// full record is asked for.
    pub(super) fn go(
        &mut self,
        at: &mut At<'_, '_>,

        kind: SegmentKind,
        target: MachineAxes,
        rotary_delta: [f64; 2],
        rate: Rate,
        path: impl FnOnce() -> SegmentPath,
    ) -> R<()> {
        let moves = target.linear != self.axes.linear || rotary_delta != [0.0; 2];
        at.positioned |= moves && kind.is_positioning();
        if moves && (at.rec.is_some() || self.check.bodies.is_some()) {
            let lin = (target.linear - self.axes.linear).length();
            let rot = rotary_delta[0].abs().max(rotary_delta[1].abs());
            let duration = duration(at.cx, self.unit, rate, lin, rot);
            let seg = self.segment(at.block, kind, target, rotary_delta, duration, path());
            self.record(at, seg)?;
        }
        self.axes = target;
        Ok(())
    }

    /// Checks `seg` for collisions, then records it when a full record is asked for.
    fn record(&mut self, at: &mut At<'_, '_>, seg: Segment) -> R<()> {
        let mut clear = std::mem::take(&mut self.check.clearances);
        let collided = self.collided(&seg, &mut clear);
        self.check.clearances = clear;
        if let Some(c) = collided {
            return Err(SimErrorCode::Collision(Box::new(c)));
        }
        if let Some(r) = at.rec.as_deref_mut() {
            r.segments.push(seg);
        }
        Ok(())
    }

    /// The segment of this step from the axes now to `target`.
    pub(super) fn segment(
        &self,
        block: usize,
        kind: SegmentKind,
        target: MachineAxes,
        rotary_delta: [f64; 2],
        duration: f64,
        path: SegmentPath,
    ) -> Segment {
        let step = self.step_count.saturating_sub(1);
        Segment { step, block, kind, start: self.axes, end: target, rotary_delta, duration, path }
    }

    /// Moves the linear axes to `target` along `path` of `length` mm (an arc may end where it
    /// started), checking it for collisions and recording a segment when a full record is asked
    /// for.
    pub(super) fn go_along(
        &mut self,
        at: &mut At<'_, '_>,

        kind: SegmentKind,
        target: MachineAxes,
        rate: Rate,
        length: f64,
        path: SegmentPath,
    ) -> R<()> {
        at.positioned |= length > 0.0 && kind.is_positioning();
        if length > 0.0 && (at.rec.is_some() || self.check.bodies.is_some()) {
            let duration = duration(at.cx, self.unit, rate, length, 0.0);
            let seg = self.segment(at.block, kind, target, [0.0; 2], duration, path);
            self.record(at, seg)?;
        }
        self.axes = target;
        Ok(())
    }

    pub(super) fn rate(&mut self, feed: Option<&Feed<Value>>) -> R<Rate> {
        Ok(match feed {
            None => {
                if self.feed > 0.0 {
                    Rate::Feed(self.feed)
                } else {
                    Rate::Rapid
                }
            }
            Some(Feed::Value(v)) => {
                let f = self.feed_rate(v)?;
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

    pub(super) fn line(&mut self, at: &mut At<'_, '_>, line: &Line) -> R<()> {
        self.m_functions(at, &line.m);
        self.speed_word(line.speed.as_ref())?;
        if let Some(&m) = line.m.iter().find(|&&m| m == 91 || m == 92) {
            self.tcpm_reset_before(if m == 91 { "M91" } else { "M92" })?;
        }
        let m91 = in_machine_coordinates(line);
        let rate = self.rate(line.feed.as_ref())?;
        let mut p = self.programmed();
        let mut l = self.axes.linear;
        let mut rot = self.axes.rotary;
        let (mut lin_prog, mut rot_prog) = (false, false);
        // AXIS SPAT: A, B, C are the spatial angles SPA, SPB, SPC, whatever axes the machine has.
        let mut spatial: [Option<(f64, bool)>; 3] = [None; 3];
        for w in line.axes.iter() {
            if let Some(i) = linear_index(w.axis) {
                let v = self.length(&w.value)?;
                lin_prog = true;
                let slot = if m91 { &mut l[i] } else { &mut p[i] };
                *slot = if w.incremental { *slot + v } else { v };
            } else if let Some(ra) = rotary_of(w.axis).filter(|_| self.tcpm.spat.is_some()) {
                // A, B, C in declaration order: SPA, SPB, SPC.
                spatial[ra as usize] = Some((self.value(&w.value)?, w.incremental));
                rot_prog = true;
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
        if rot_prog && self.tcpm.spat.is_some() {
            rot = self.spatial_tool_axis(at, spatial)?;
        }
        self.check_rotary(at.cx, rot)?;
        // A straight contour element in the working plane: it ends at the tangent point when a
        // RND/CHF follows, and leaves its direction for a CT.
        self.contour.geom_start = None;
        if lin_prog && !m91 && !rot_prog {
            let elem = self.before_corner(at.cx, at.block, Elem::line(self.programmed(), p))?;
            if self.active_comp().is_some() || matches!(line.comp, Some(RadiusComp::Rl | RadiusComp::Rr)) {
                // A contour element with the tool radius compensation on, switched on or off.
                self.run_element(at, elem, line.comp, rate)?;
                if line.m.contains(&99) {
                    self.call_cycle(at)?;
                }
                self.end_m(&line.m);
                return Ok(());
            }
            p = elem.end;
            if let Some(t) = elem.line_travel(&self.work_plane()) {
                self.contour.tangent = Some(Travel::Line(t));
            }
        }
        // Any other move ends the compensation.
        if lin_prog || rot_prog {
            self.contour.comp = None;
        }
        // TCPM: the tip keeps the programmed point while the rotary axes move, whether or not
        // the block also programs linear axes.
        let tcpm = self.tcpm.on && rot_prog && !m91;
        if (lin_prog && !m91) || tcpm {
            l = if rot_prog {
                self.wcs_to_linear(rot).after(&self.tf.ics_to_wcs()).apply(p)
            } else {
                self.map.apply(p)
            };
        }
        if lin_prog || rot_prog {
            self.check_linear(at.cx, l)?;
            let delta = self.rotary_delta(at.cx, rot, self.m126);
            let kind = if rate == Rate::Rapid { SegmentKind::Rapid } else { SegmentKind::Feed };
            let target = MachineAxes { linear: l, rotary: rot, letters: self.axes.letters };
            // Under TCPM: the tip on the straight line between the programmed points (W-CS).
            let tcpm_path = tcpm.then(|| {
                let ics_to_wcs = self.tf.ics_to_wcs();
                (self.kin, ics_to_wcs.apply(self.programmed()), ics_to_wcs.apply(p))
            });
            self.go(at, kind, target, delta, rate, || match tcpm_path {
                Some((kin, from, to)) => SegmentPath::Tcpm(Box::new(TcpmPath { kin, from, to })),
                None => SegmentPath::Linear,
            })?;
            if rot_prog {
                self.refresh();
            }
            if (lin_prog && !m91) || tcpm {
                self.pos_i = p;
            } else {
                self.pos_i = self.map.inverse_orthogonal().apply(self.axes.linear);
            }
        }
        if line.m.contains(&99) {
            self.call_cycle(at)?;
        }
        self.end_m(&line.m);
        Ok(())
    }
}
