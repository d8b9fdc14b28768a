//! The blocks that set the machine up rather than move it: `BLK FORM` and a setup sheet's
//! blank, `TOOL CALL` and `TOOL DEF`, the datum shift, mirroring and rotation, the collision
//! bodies the blank and the tool change, and the blocks that only say what the control would do
//! (`STOP`, `QS…`, `TCH PROBE`).

use super::*;

impl Interp {
    /// The collision bodies for the machine, the active tool and the blank.
    pub(super) fn rebuild_bodies(&mut self, machine: &Machine) {
        if self.check.replay {
            return;
        }
        self.check.bodies =
            Bodies::new(machine, &self.kin, self.tool.radius, self.blank.as_ref()).map(Arc::new);
        self.check.clearances.forget();
    }

    /// This interpreter for re-running steps of a run that executed them (a state, a listing,
    /// the stock's plan): they ran once without a collision and run the same again (the
    /// interpreter is deterministic), so their motions are not checked a second time.
    pub(crate) fn replaying(mut self) -> Interp {
        self.check.replay = true;
        self.check.bodies = None;
        self
    }

    /// The collision error of `seg` if two bodies touch along it (`clear`: what is known from
    /// the motions before).
    pub(super) fn collided(&self, seg: &Segment, clear: &mut Clearances) -> Option<Collision> {
        let bodies = self.check.bodies.as_deref()?;
        let c = bodies.first_contact(seg, clear)?;
        Some(Collision {
            a: bodies.name(c.a),
            b: bodies.name(c.b),
            kind: seg.kind,
            fraction: c.fraction,
            axes: seg.axes_at(c.fraction),
            alternative: None,
        })
    }

    pub(super) fn blk_form(&mut self, cx: &Cx<'_>, b: &BlkForm) -> R<()> {
        let base = if b.part == 2 { self.blank_min.unwrap_or(DVec3::ZERO) } else { DVec3::ZERO };
        let mut p = if b.part == 2 { base } else { DVec3::ZERO };
        for w in b.axes.iter() {
            if let Some(i) = linear_index(w.axis) {
                let v = self.length(&w.value)?;
                p[i] = if w.incremental { base[i] + v } else { v };
            }
        }
        if b.part == 2 {
            let min = self.blank_min.unwrap_or(DVec3::ZERO);
            self.blank = Some(Blank { min: min.min(p), max: min.max(p) });
            self.rebuild_bodies(cx.machine);
        } else {
            self.blank_min = Some(p);
        }
        Ok(())
    }

    /// The spindle speed of `TOOL CALL … S…`, or of an `S…` in a path block (read leniently,
    /// `diag::Lenient::SpeedInPath`): the spindle turns at it from this block on.
    pub(super) fn speed_word(&mut self, s: Option<&Value>) -> R<()> {
        if let Some(s) = s {
            self.spindle.speed = self.value(s)?;
        }
        Ok(())
    }

    pub(super) fn tool_call(&mut self, at: &mut At<'_, '_>, t: &ToolCall) -> R<()> {
        self.tcpm_reset_before("TOOL CALL")?;
        let mut dl = t.dl.as_ref().map(|v| self.length(v)).transpose()?.unwrap_or(0.0);
        let mut dr = t.dr.as_ref().map(|v| self.length(v)).transpose()?.unwrap_or(0.0);
        let mut written_length = None;
        if let Some(tool) = &t.tool {
            let (entry, known) = self.tool_entry(at.cx, &self.tool_of(tool)?);
            // The control adds the table's deltas to those of the TOOL CALL.
            dl += entry.dl;
            dr += entry.dr;
            self.tool.shape = entry.shape(entry.radius + dr);
            self.tool.number = entry.number;
            self.tool.name = entry.name;
            // The control's L (Q114); the simulated tool may be longer (a zero-tool difference).
            written_length = Some(entry.length + dl);
            self.tool.length = unconfirmed::physical_tool_length(entry.length) + dl;
            self.tool.radius = entry.radius + dr;
            self.tool.known = known;
            if self.tool.length != entry.length + dl {
                let (written, simulated) = (entry.length, self.tool.length);
                at.note(|| Note::ZeroToolLength { written, simulated });
            }
            if !known {
                let t = &self.tool;
                at.note(|| Note::ToolNotInTable {
                    number: t.number,
                    name: t.name.to_string(),
                    length: t.length,
                    radius: t.radius,
                });
            }
        }
        if let Some(a) = t.axis {
            self.tool.axis = letter(a);
            if a != Axis::Z {
                let axis = self.tool.axis;
                at.note(|| Note::ToolAxis { axis });
            }
        }
        self.speed_word(t.speed.as_ref())?;
        if let Some(f) = &t.feed {
            let f = self.feed_rate(f)?;
            self.tool.feed = f;
            self.feed = f;
        }
        // Q108 the active tool radius, Q114 the tool length (preassigned Q parameters, iTNC 530
        // and TNC 410 user's manuals), in the program's unit.
        self.q.insert(108, self.in_program_unit(self.tool.radius));
        let written_length = written_length.unwrap_or(self.tool.length);
        self.q.insert(114, self.in_program_unit(written_length));
        self.kin.tool_length = self.tool.length;
        self.rebuild_bodies(at.cx.machine);
        self.sync_pos();
        Ok(())
    }

    /// The tool a `TOOL CALL`/`TOOL DEF` names: the number a numeric parameter holds (its
    /// integer part; a tool number is ≥ 0), anything else as written. A string parameter's
    /// text is not simulated: the tool stays unknown and the block says so.
    /// The data of `tool` as a TOOL CALL loads it: the tool table's entry with the length and
    /// radius of a `TOOL DEF` in the program over it; `false` when neither gives the tool's
    /// radius (it is then the stated default tool's: a `TOOL DEF 7` that only preselects the
    /// tool, as CAM posts write it, gives none).
    pub(super) fn tool_entry(&self, cx: &Cx<'_>, tool: &ToolRef) -> (tools::ToolEntry, bool) {
        let (mut entry, mut known) = tools::lookup_in(cx.options.tool_table(), tool);
        if let Some((_, l, r)) = self.tool_defs.iter().find(|(t, ..)| t == tool) {
            entry.length = l.unwrap_or(entry.length);
            entry.radius = r.unwrap_or(entry.radius);
            known |= r.is_some();
        }
        (entry, known)
    }

    pub(super) fn tool_of(&self, tool: &ToolRef) -> R<ToolRef> {
        let ToolRef::Param(q) = *tool else { return Ok(tool.clone()) };
        let v = self.value(&Value::Param { index: q, negate: false })?;
        if !(0.0..=f64::from(u32::MAX)).contains(&v) {
            return Err(SimErrorCode::ToolNumber { index: q, value: v });
        }
        Ok(ToolRef::Number(v.trunc() as u32))
    }

    /// The new datum shift from the written components ([`unconfirmed::DATUM_ABSOLUTE_REPLACES`]):
    /// with an absolute word the axes not written are 0, with only incremental words they keep
    /// the base.
    pub(super) fn datum_of(base: DVec3, written: [Option<f64>; 3], any_absolute: bool) -> DVec3 {
        let keep = !(any_absolute && unconfirmed::DATUM_ABSOLUTE_REPLACES);
        DVec3::from_array(std::array::from_fn(|i| written[i].unwrap_or(if keep { base[i] } else { 0.0 })))
    }

    // Out of line: the page split can leave it to the wasm loaded after the first screen.
    #[inline(never)]
    pub(super) fn datum(&mut self, axes: &[AxisWord]) -> R<()> {
        let level = self.tf.level_now();
        let base = match level {
            Level::Wcs => self.tf.datum_w,
            Level::Wpl => self.tf.datum_i,
        };
        let mut written = [None; 3];
        let mut any_absolute = false;
        for w in axes {
            if let Some(i) = linear_index(w.axis) {
                let v = self.length(&w.value)?;
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

    pub(super) fn set_mirror(&mut self, set: [bool; 3]) {
        match self.tf.level_now() {
            Level::Wcs => self.tf.mirror_w = set,
            Level::Wpl => self.tf.mirror_i = set,
        }
        self.sync_pos();
    }

    /// `TOOL DEF`, `STOP`, `QS…`, `TCH PROBE`: blocks that store data for later blocks or say
    /// what the control would do. Out of line, like the other rare kinds: the page split leaves
    /// them to the wasm loaded after the first screen.
    #[inline(never)]
    pub(super) fn program_data(&mut self, at: &mut At<'_, '_>, body: &BlockBody) -> R<()> {
        match body {
            BlockBody::ToolDef { tool, length, radius } => {
                let l = length.map(|v| self.length(&v)).transpose()?;
                let r = radius.map(|v| self.length(&v)).transpose()?;
                let tool = self.tool_of(tool)?;
                self.tool_defs.retain(|(t, ..)| *t != tool);
                self.tool_defs.push((tool, l, r));
                at.note(|| Note::ToolDef);
            }
            BlockBody::Stop { m } => {
                self.spindle_m(m);
                at.note(|| Note::Halt { word: "STOP" });
                self.end_m(m);
            }
            BlockBody::QsAssign { index, .. } => {
                at.note(|| Note::QsNotSimulated { index: *index });
            }
            BlockBody::TouchProbe(d) => {
                self.probed = Some(d.number);
                at.note(|| Note::TouchProbe { cycle: d.number });
            }
            _ => {}
        }
        Ok(())
    }

    /// A setup-sheet header line before `BEGIN PGM`, as a training simulator exports it: a
    /// cuboid blank `Quader: QX100 QY90 QZ20` is the program's blank when the program has no
    /// BLK FORM ([`unconfirmed::HEADER_BLANK_AT_DATUM`]); any other header line is shown as
    /// written.
    #[inline(never)]
    pub(super) fn header(&mut self, at: &mut At<'_, '_>, text: &str) {
        // The first cuboid of the header applies (and a later line does not scan the program
        // for a BLK FORM again).
        let Some(size) =
            header_blank(text).filter(|_| unconfirmed::HEADER_BLANK_AT_DATUM && self.blank.is_none())
        else {
            return;
        };
        let (x, y, z) = (size.x, size.y, size.z);
        if at.cx.program.blocks.iter().any(|b| matches!(b.stored_body(), Some(BlockBody::BlkForm(_)))) {
            at.note(|| Note::HeaderBlankIgnored);
            return;
        }
        self.blank = Some(Blank { min: DVec3::new(0.0, 0.0, -z), max: DVec3::new(x, y, 0.0) });
        self.rebuild_bodies(at.cx.machine);
        at.note(|| Note::HeaderBlank { size: [x, y, z] });
    }

    #[inline(never)]
    pub(super) fn mirror(&mut self, axes: &[Axis]) {
        let mut set = [false; 3];
        for a in axes {
            if let Some(i) = linear_index(*a) {
                set[i] = true;
            }
        }
        self.set_mirror(set);
    }

    #[inline(never)]
    pub(super) fn rotation(&mut self, rot: &Value, incremental: bool) -> R<()> {
        let v = self.value(rot)?;
        self.tf.rotation = if incremental { self.tf.rotation + v } else { v };
        self.sync_pos();
        Ok(())
    }
}

/// The cuboid of a setup-sheet header line: `QX…`, `QY…` and `QZ…` (each a positive number,
/// a decimal comma read as a point), as in `(Quader: QX100 QY90 QZ20)`.
pub(in crate::sim) fn header_blank(text: &str) -> Option<DVec3> {
    let size = |key: &str| -> Option<f64> {
        let at = text.find(key)? + key.len();
        let digits: String = text[at..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | ','))
            .map(|c| if c == ',' { '.' } else { c })
            .collect();
        crate::number::parse_f64(&digits).filter(|v| *v > 0.0 && v.is_finite())
    };
    Some(DVec3::new(size("QX")?, size("QY")?, size("QZ")?))
}
