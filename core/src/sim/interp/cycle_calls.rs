//! Cycle definitions in the old form (`CYCL DEF 7.x`, `19.x` …) and cycle calls (`CYCL CALL`,
//! `M99`): what each called cycle moves.

use super::*;

impl Interp {
    pub(super) fn old_cycle(
        &mut self,
        cx: &Cx<'_>,
        rec: &mut Option<&mut Rec>,
        idx: usize,
        d: &CycleDefOld,
    ) -> R<()> {
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
                Text::new("Zyklus 11 (Maßfaktor) nicht simuliert", "Cycle 11 (scaling) not simulated")
            }),
            (19, 0) => note(rec, || {
                Text::new(
                    "Zyklus 19: die Winkel folgen im Satz 19.1",
                    "Cycle 19: the angles follow in block 19.1",
                )
            }),
            (19, _) => self.cycle19(cx, rec, idx, words)?,
            (n, 0) => {
                self.cycle = Some(StoredCycle::Old(n));
                note(rec, || {
                    Text::owned(
                        format!("Zyklus {n} (alte Form) definiert"),
                        format!("Cycle {n} (old form) defined"),
                    )
                });
            }
            _ => {}
        }
        Ok(())
    }

    /// `CYCL CALL PAT`/`CYCL CALL POS`: the M functions act, the call is reported.
    pub(super) fn call_not_simulated(&mut self, rec: &mut Option<&mut Rec>, word: &'static str, m: &[u32]) {
        self.spindle_m(m);
        note(rec, || {
            Text::owned(
                format!("CYCL CALL {word} nicht simuliert"),
                format!("CYCL CALL {word} not simulated"),
            )
        });
        self.end_m(m);
    }

    pub(super) fn call_cycle(&mut self, cx: &Cx<'_>, rec: &mut Option<&mut Rec>, idx: usize) -> R<()> {
        let Some(c) = self.cycle else { return Err(SimErrorCode::NoCycle) };
        let def = match c {
            StoredCycle::Old(n) => {
                note(rec, || {
                    Text::owned(format!("Zyklus {n} nicht simuliert"), format!("Cycle {n} not simulated"))
                });
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
                        Text::owned(
                            format!("Zyklus 232: Strategie Q389={strategy} als Mäander simuliert"),
                            format!("Cycle 232: strategy Q389={strategy} simulated as a meander"),
                        )
                    });
                }
                m
            }
            n => {
                note(rec, || {
                    Text::owned(format!("Zyklus {n} nicht simuliert"), format!("Cycle {n} not simulated"))
                });
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
                Text::owned(
                    format!("Zyklus {number} ausgeführt ({n} Bewegungen in der Bearbeitungsebene)"),
                    format!("Cycle {number} executed ({n} moves in the working plane)"),
                )
            });
        }
        Ok(())
    }
}
