//! The full [`State`] a step shows: axes, frames, tool tip, pivots (checkpoints keep only the
//! interpreter; the state is built from it on demand).

use super::*;

impl Interp {
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
        let line = program.blocks.get(block).map_or(0, |b| b.line());
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
            compensating: self.compensating(),
            q: self.q.clone(),
            plane: self.plane.clone(),
            explanation: rec.explanation,
            note: rec.note,
            segments: rec.segments,
            ended: self.ended,
            executed,
            unit: self.unit,
        }
    }

    /// What the stock needs of the step just run ([`StepMotion`]).
    pub(crate) fn motion(&self, step: usize, rec: Rec) -> StepMotion {
        StepMotion {
            step,
            block: self.last,
            blank: self.blank,
            tool: self.tool.clone(),
            segments: rec.segments,
        }
    }

    /// Where the rotary axes stand (3D view): table axes moved by the table axes that carry
    /// them, head axes by the head axes nearer the bed, plus the linear axes.
    pub(super) fn pivots(&self, machine: &Machine) -> [Pivot; 2] {
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
