//! TCPM: `M128`/`M129` and `FUNCTION TCPM`/`FUNCTION RESET TCPM` (DOMAIN.md §6). While it is on,
//! the tool tip keeps the programmed point and the linear axes compensate the rotary axes
//! (the motion itself is in `motion.rs`).

use crate::ast::{Tcpm, TcpmAxis};
use crate::solve::axis_words;

use super::*;

impl Interp {
    /// TCPM on or off; the programmed position is taken anew from where the tool tip is.
    /// Off also ends `AXIS SPAT`.
    pub(super) fn set_tcpm(&mut self, on: bool) {
        if !on {
            self.tcpm.spat = None;
        }
        if on != self.tcpm.on {
            self.tcpm.on = on;
            self.sync_pos();
        }
    }

    /// At the block's end `M129` switches TCPM off and `M128` on (if it was not already on from
    /// the block's start, unconfirmed::TCPM_FROM_BLOCK_START); `M129` wins over `M128`.
    pub(super) fn tcpm_at_block_end(&mut self, m: &[u32]) {
        if m.contains(&129) {
            self.set_tcpm(false);
        } else if m.contains(&128) {
            self.set_tcpm(true);
        }
    }

    /// `FUNCTION TCPM`: on as `M128`; the feed and path modes are not told apart
    /// (unconfirmed::Decision::TcpmFunction). `AXIS POS` takes `A`, `B`, `C` as axis angles,
    /// `AXIS SPAT` as spatial angles ([`Self::spatial_tool_axis`]), each block's anew.
    pub(super) fn function_tcpm(&mut self, at: &mut At<'_, '_>, t: Tcpm) {
        self.set_tcpm(true);
        self.tcpm.spat = (t.axis == TcpmAxis::Spat).then_some([None; 3]);
        at.note(|| Note::TcpmOn { word: "FUNCTION TCPM", spatial: t.axis == TcpmAxis::Spat });
    }

    /// `AXIS SPAT`: the rotary axis positions for the spatial angles `written` in a positioning
    /// block (A, B, C = SPA, SPB, SPC; `None` = not in the block), which stay for the next
    /// blocks. The iTNC 530 manual ("Interpretation of the programmed rotary axis coordinates"):
    /// the angles are "given with respect to the currently active (perhaps tilted) coordinate
    /// system", and the first block after switching on should program all three. So the tool
    /// orientation is R = R_active·Rz(C)·Ry(B)·Rx(A) (mirrored as a PLANE block's, tilt.rs),
    /// and the machine takes it as a PLANE block without SEQ would (solve.rs: within the
    /// limits, the shorter path) — unconfirmed::Decision::TcpmAxisSpat.
    pub(super) fn spatial_tool_axis(
        &mut self,
        at: &mut At<'_, '_>,
        written: [Option<(f64, bool)>; 3],
    ) -> R<[f64; 2]> {
        let Some(modal) = self.tcpm.spat.as_mut() else { return Ok(self.axes.rotary) };
        let missing = (0..3).filter(|&k| modal[k].is_none() && written[k].is_none()).count();
        for (slot, w) in modal.iter_mut().zip(written) {
            if let Some((v, incremental)) = w {
                *slot = Some(if incremental { slot.unwrap_or(0.0) + v } else { v });
            }
        }
        // A missing angle is told once, in the first block, and is 0° from then on.
        let [a, b, c] = modal.map(|v| v.unwrap_or(0.0));
        *modal = [Some(a), Some(b), Some(c)];
        // As a PLANE block's R = M_W·(M_W·R_active·M_W·R_prog)·M_W (tilt.rs), with M_W² = 1.
        let mw = self.tf.mirror_w_matrix();
        let r = self.tf.r() * mw * orientation::spatial(a, b, c) * mw;
        let start = self.axes.rotary_values();
        let mut expl = Self::solved(solve::solve(
            at.cx.machine,
            &r,
            &SolveOptions { start, ..SolveOptions::default() },
        ))?;
        expl.decisions.push(unconfirmed::Decision::TcpmAxisSpat);
        let expl = Arc::new(expl);
        let axes = expl.chosen_axes().unwrap_or_default();
        at.note(|| Note::AxisSpat { spatial: [a, b, c], chosen: axis_words(&axes), missing: missing > 0 });
        if let Some(r) = at.rec.as_deref_mut() {
            r.explanation = Some(expl);
        }
        Ok(self.target_rotary(&axes))
    }

    /// `FUNCTION RESET TCPM`: off, whichever way it was switched on.
    pub(super) fn function_reset_tcpm(&mut self, at: &mut At<'_, '_>) {
        self.set_tcpm(false);
        at.note(|| Note::TcpmOff { word: "FUNCTION RESET TCPM" });
    }

    /// Before `TOOL CALL`, `M91` and `M92` (`word`) TCPM must be off
    /// (unconfirmed::TCPM_REFUSES_TOOL_CALL_M91_M92).
    pub(super) fn tcpm_reset_before(&mut self, word: &'static str) -> R<()> {
        if self.tcpm.on && unconfirmed::TCPM_REFUSES_TOOL_CALL_M91_M92 {
            return Err(SimErrorCode::TcpmActive { word });
        }
        self.set_tcpm(false);
        Ok(())
    }
}
