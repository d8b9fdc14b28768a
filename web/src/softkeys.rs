//! The eight softkeys of each level, as data (tested natively). A slot without an action is a
//! blank softkey, as the control shows where a level has fewer than eight functions.

use crate::state::{Action, SoftkeyLevel};

#[derive(Debug, Clone, PartialEq)]
pub struct Softkey {
    /// Stable id for tests and keyboard shortcuts.
    pub id: &'static str,
    /// Label as on the control; `\n` breaks lines on the key like the control's multi-line labels.
    pub de: &'static str,
    pub en: &'static str,
    pub action: Action,
}

/// Exactly eight slots, left to right.
pub type Row = [Option<Softkey>; 8];

const fn key(id: &'static str, de: &'static str, en: &'static str, action: Action) -> Option<Softkey> {
    Some(Softkey { id, de, en, action })
}

/// The row the control shows at `level`.
#[must_use]
pub fn row(level: SoftkeyLevel) -> Row {
    match level {
        SoftkeyLevel::Main => [
            key("spec-fct", "SPEC\nFCT", "SPEC\nFCT", Action::SpecFct),
            None,
            None,
            None,
            None,
            None,
            None,
            key("lang", "SPRACHE\nENGLISH", "LANGUAGE\nDEUTSCH", Action::ToggleLang),
        ],
        SoftkeyLevel::SpecFct => [
            None,
            None,
            key("tilt-plane", "BEARB.-\nEBENE\nSCHWENKEN", "TILT\nMACHINING\nPLANE", Action::TiltPlane),
            None,
            None,
            None,
            None,
            key("back", "ENDE", "END", Action::Back),
        ],
        SoftkeyLevel::TiltPlane => {
            [None, None, None, None, None, None, None, key("back", "ENDE", "END", Action::Back)]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_level_has_a_way_out_and_spec_fct_is_on_the_main_row() {
        assert!(row(SoftkeyLevel::Main).iter().flatten().any(|k| k.id == "spec-fct"));
        for level in [SoftkeyLevel::SpecFct, SoftkeyLevel::TiltPlane] {
            assert!(row(level).iter().flatten().any(|k| k.action == Action::Back), "{level:?}");
        }
    }
}
