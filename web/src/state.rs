//! All UI state in one reducer (yew `Reducible`), pure and tested natively.
//!
//! The softkey row works like the control's: a key such as `SPEC FCT` replaces the row with the
//! softkeys of that area, `END`/the back softkey returns one level.

use std::rc::Rc;

use yew::Reducible;

use crate::i18n::Lang;

/// Which softkey row is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SoftkeyLevel {
    /// Programming mode, top level.
    #[default]
    Main,
    /// After the `SPEC FCT` key: special functions.
    SpecFct,
    /// After `BEARB.-EBENE SCHWENKEN`: the PLANE functions.
    TiltPlane,
}

#[derive(Debug, Clone, PartialEq)]
pub struct AppState {
    pub lang: Lang,
    pub level: SoftkeyLevel,
    /// The NC program as text.
    pub program: String,
}

impl Default for AppState {
    fn default() -> Self {
        AppState { lang: Lang::default(), level: SoftkeyLevel::Main, program: DEFAULT_PROGRAM.to_owned() }
    }
}

/// What the empty program looks like when a new one is started on the control.
pub const DEFAULT_PROGRAM: &str = "0 BEGIN PGM NEU MM\n1 END PGM NEU MM\n";

#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// The `SPEC FCT` key.
    SpecFct,
    /// Softkey `BEARB.-EBENE SCHWENKEN`.
    TiltPlane,
    /// The `END` key or the back softkey: one softkey level up.
    Back,
    ToggleLang,
}

impl AppState {
    /// The pure transition; `Reducible::reduce` only wraps it.
    #[must_use]
    pub fn apply(&self, action: Action) -> AppState {
        let mut next = self.clone();
        match action {
            Action::SpecFct => next.level = SoftkeyLevel::SpecFct,
            Action::TiltPlane => {
                if self.level == SoftkeyLevel::SpecFct {
                    next.level = SoftkeyLevel::TiltPlane;
                }
            }
            Action::Back => {
                next.level = match self.level {
                    SoftkeyLevel::Main | SoftkeyLevel::SpecFct => SoftkeyLevel::Main,
                    SoftkeyLevel::TiltPlane => SoftkeyLevel::SpecFct,
                }
            }
            Action::ToggleLang => next.lang = self.lang.other(),
        }
        next
    }

    /// The dialog line shows what the control expects next.
    #[must_use]
    pub fn dialog_text(&self) -> &'static str {
        let l = self.lang;
        match self.level {
            SoftkeyLevel::Main => l.t("Programm-Einspeichern/Editieren", "Programming"),
            SoftkeyLevel::SpecFct => {
                l.t("Sonderfunktionen: Bereich wählen", "Special functions: select an area")
            }
            SoftkeyLevel::TiltPlane => l.t(
                "Bearbeitungsebene schwenken: Funktion wählen",
                "Tilt the working plane: select a function",
            ),
        }
    }
}

impl Reducible for AppState {
    type Action = Action;

    fn reduce(self: Rc<Self>, action: Action) -> Rc<Self> {
        Rc::new(self.apply(action))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_fct_then_tilt_then_back_walks_the_softkey_levels() {
        let s = AppState::default();
        assert_eq!(s.level, SoftkeyLevel::Main);
        let s = s.apply(Action::SpecFct);
        assert_eq!(s.level, SoftkeyLevel::SpecFct);
        let s = s.apply(Action::TiltPlane);
        assert_eq!(s.level, SoftkeyLevel::TiltPlane);
        let s = s.apply(Action::Back);
        assert_eq!(s.level, SoftkeyLevel::SpecFct);
        let s = s.apply(Action::Back);
        assert_eq!(s.level, SoftkeyLevel::Main);
    }

    #[test]
    fn tilt_softkey_only_exists_in_the_special_functions_row() {
        let s = AppState::default().apply(Action::TiltPlane);
        assert_eq!(s.level, SoftkeyLevel::Main);
    }

    #[test]
    fn language_switch_changes_the_dialog_line_and_keeps_the_program() {
        let s = AppState::default().apply(Action::SpecFct);
        assert_eq!(s.dialog_text(), "Sonderfunktionen: Bereich wählen");
        let en = s.apply(Action::ToggleLang);
        assert_eq!(en.dialog_text(), "Special functions: select an area");
        assert_eq!(en.program, s.program);
    }
}
