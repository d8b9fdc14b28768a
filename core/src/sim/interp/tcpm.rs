//! TCPM: `M128`/`M129` and `FUNCTION TCPM`/`FUNCTION RESET TCPM` (DOMAIN.md §6). While it is on,
//! the tool tip keeps the programmed point and the linear axes compensate the rotary axes
//! (the motion itself is in `motion.rs`).

use crate::ast::{Tcpm, TcpmAxis};

use super::*;

/// What `M128` or `M129` in a block (`m`) tell the trainee.
pub(super) fn m_note(m: &[u32]) -> Option<Text> {
    if m.contains(&128) {
        Some(switched_on("M128"))
    } else if m.contains(&129) {
        Some(Text::new("M129: TCPM aus", "M129: TCPM off"))
    } else {
        None
    }
}

/// What `M128` and `FUNCTION TCPM` (`word`) tell the trainee.
fn switched_on(word: &str) -> Text {
    Text::owned(
        format!(
            "{word}: TCPM aktiv – die Werkzeugspitze bleibt auf dem programmierten Punkt, die Linearachsen gleichen die Drehachsen aus"
        ),
        format!(
            "{word}: TCPM on – the tool tip stays on the programmed point, the linear axes compensate the rotary axes"
        ),
    )
}

impl Interp {
    /// TCPM on or off; the programmed position is taken anew from where the tool tip is.
    pub(super) fn set_tcpm(&mut self, on: bool) {
        if on != self.tcpm {
            self.tcpm = on;
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

    /// `FUNCTION TCPM`: on as `M128` with `AXIS POS`; the feed and path modes are not told apart
    /// (unconfirmed::Decision::TcpmFunction). `AXIS SPAT` is refused rather than run as axis
    /// angles, which would move the machine elsewhere than the program means.
    pub(super) fn function_tcpm(&mut self, rec: &mut Option<&mut Rec>, t: Tcpm) -> R<()> {
        if t.axis == TcpmAxis::Spat {
            return Err(SimErrorCode::TcpmAxisSpat);
        }
        self.set_tcpm(true);
        note(rec, || switched_on("FUNCTION TCPM"));
        Ok(())
    }

    /// `FUNCTION RESET TCPM`: off, whichever way it was switched on.
    pub(super) fn function_reset_tcpm(&mut self, rec: &mut Option<&mut Rec>) {
        self.set_tcpm(false);
        note(rec, || Text::new("FUNCTION RESET TCPM: TCPM aus", "FUNCTION RESET TCPM: TCPM off"));
    }

    /// Before `TOOL CALL`, `M91` and `M92` (`word`) TCPM must be off
    /// (unconfirmed::TCPM_REFUSES_TOOL_CALL_M91_M92).
    pub(super) fn tcpm_reset_before(&mut self, word: &'static str) -> R<()> {
        if self.tcpm && unconfirmed::TCPM_REFUSES_TOOL_CALL_M91_M92 {
            return Err(SimErrorCode::TcpmActive { word });
        }
        self.set_tcpm(false);
        Ok(())
    }
}
