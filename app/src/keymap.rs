//! The physical keyboard mapped onto the control's keys, so the whole app works by keyboard:
//! F1–F8 are the softkeys (left to right), Enter = ENT, Shift+Enter = NO ENT, End = END,
//! Esc = DEL (abort), digits/sign/point type into the dialog, arrows move the cursor, `p` the
//! projector mode, `h` the right-hand rule, Ctrl+Z/Ctrl+Y undo and redo a change of the program.

use crate::dialog::Key;
use crate::softkeys;
use crate::state::{Action, AppState};

/// A key event reduced to what matters.
#[derive(Debug, Clone, PartialEq)]
pub struct KeyPress<'a> {
    /// `KeyboardEvent.key`.
    pub key: &'a str,
    pub shift: bool,
    pub ctrl_or_alt: bool,
}

/// The action for a key press, or `None` to let the browser have it.
#[must_use]
pub fn action(state: &AppState, press: &KeyPress<'_>) -> Option<Action> {
    if press.ctrl_or_alt {
        // The editor's undo, wherever the focus is (the text editor's too: its history is this
        // one); every other combination stays the browser's.
        return match press.key {
            "z" | "Z" if press.shift => Some(Action::Redo),
            "z" | "Z" => Some(Action::Undo),
            "y" | "Y" => Some(Action::Redo),
            _ => None,
        }
        .filter(|_| state.dialog.is_none());
    }
    if let Some(n) = press.key.strip_prefix('F').and_then(|n| n.parse::<usize>().ok())
        && (1..=8).contains(&n)
    {
        return softkeys::row(state)[n - 1].as_ref().map(|k| k.action.clone());
    }
    if state.dialog.is_some() {
        return Some(match press.key {
            "Enter" if press.shift => Action::DialogKey(Key::NoEnt),
            "Enter" => Action::DialogKey(Key::Ent),
            "End" => Action::DialogKey(Key::End),
            "Escape" | "Delete" => Action::Abort,
            "Backspace" => Action::DialogKey(Key::Backspace),
            k => {
                let mut chars = k.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) if !c.is_whitespace() => Action::DialogKey(Key::Char(c)),
                    _ => return None,
                }
            }
        });
    }
    Some(match press.key {
        "ArrowUp" => Action::CursorUp,
        "ArrowDown" => Action::CursorDown,
        "Enter" => Action::Open,
        "Escape" | "End" => Action::Back,
        "p" | "P" => Action::ToggleProjector,
        // The right-hand rule on the cursor's PLANE block, in place of the machine view.
        "h" | "H" => Action::ToggleRightHand,
        // The ROHTEIL switch (the stock in the 3D view).
        "r" | "R" => Action::ToggleStock,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::state::Then;

    fn press(key: &str) -> KeyPress<'_> {
        KeyPress { key, shift: false, ctrl_or_alt: false }
    }

    #[test]
    fn function_keys_press_the_softkeys() {
        let s = AppState::default();
        assert_eq!(action(&s, &press("F1")), Some(Action::SpecFct));
        let s = s.then(Action::SpecFct);
        assert_eq!(action(&s, &press("F3")), Some(Action::TiltPlane));
        assert_eq!(action(&s, &press("F1")), None, "blank softkey");
    }

    #[test]
    fn dialog_keys_and_browser_shortcuts() {
        let s = AppState::default().then(Action::Function(schwenkbar_core::plane::PlaneKind::Spatial));
        assert_eq!(action(&s, &press("5")), Some(Action::DialogKey(Key::Char('5'))));
        assert_eq!(
            action(&s, &KeyPress { key: "Enter", shift: true, ctrl_or_alt: false }),
            Some(Action::DialogKey(Key::NoEnt))
        );
        assert_eq!(action(&s, &press("Escape")), Some(Action::Abort));
        assert_eq!(action(&s, &KeyPress { key: "r", shift: false, ctrl_or_alt: true }), None);
        assert_eq!(
            action(&s, &KeyPress { key: "z", shift: false, ctrl_or_alt: true }),
            None,
            "not in a dialog"
        );
        let s = AppState::default();
        assert_eq!(action(&s, &KeyPress { key: "z", shift: false, ctrl_or_alt: true }), Some(Action::Undo));
        assert_eq!(action(&s, &KeyPress { key: "Z", shift: true, ctrl_or_alt: true }), Some(Action::Redo));
        assert_eq!(action(&s, &KeyPress { key: "y", shift: false, ctrl_or_alt: true }), Some(Action::Redo));
        assert_eq!(action(&s, &press("Tab")), None, "Tab keeps moving the focus");
    }
}
