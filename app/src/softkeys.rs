//! The eight softkeys for the current state, as data (tested natively). A slot without a key is
//! a blank softkey, as the control shows where a level has fewer than eight functions.

use schwenkbar_core::machine::Machine;

use schwenkbar_core::plane::PlaneKind;

use crate::dialog::{Dialog, Key};
use crate::i18n::{Lang, Text};
use crate::run::Run;
use crate::samples::SAMPLES;
use crate::state::{Action, AppState, SoftkeyLevel};

#[derive(Debug, Clone, PartialEq)]
pub struct Softkey {
    /// Stable id for tests.
    pub id: String,
    /// Label as on the control; `\n` breaks lines like the control's multi-line labels.
    pub label: String,
    pub action: Action,
    /// Shown pressed (the chosen SEQ/SYM, the selected machine, projector on).
    pub active: bool,
}

/// Exactly eight slots, left to right.
pub type Row = [Option<Softkey>; 8];

fn key(id: &str, label: &str, action: Action) -> Option<Softkey> {
    Some(Softkey { id: id.to_owned(), label: label.to_owned(), action, active: false })
}

fn text_key(id: &str, text: Text, lang: Lang, action: Action) -> Option<Softkey> {
    key(id, text.get(lang), action)
}

/// A softkey shown pressed while what it switches is on (or chosen).
fn toggle_key(id: &str, text: Text, lang: Lang, action: Action, active: bool) -> Option<Softkey> {
    Some(Softkey { id: id.to_owned(), label: text.get(lang).to_owned(), action, active })
}

fn back(lang: Lang) -> Option<Softkey> {
    text_key("back", Text::new("ENDE", "END"), lang, Action::Back)
}

/// The label of a PLANE function softkey (DOMAIN.md §7; labels other than SPATIAL/RESET
/// UNCONFIRMED).
#[must_use]
pub fn function_label(f: PlaneKind) -> &'static str {
    match f {
        PlaneKind::Spatial => "SPATIAL",
        PlaneKind::Projected => "PROJECTED",
        PlaneKind::Euler => "EULER",
        PlaneKind::Vector => "VECTOR",
        PlaneKind::Points => "POINTS",
        PlaneKind::Relativ => "REL. SPA.",
        PlaneKind::Axial => "AXIAL",
        PlaneKind::Reset => "RESET",
    }
}

/// A machine's softkey: its name in softkey lines, pressed when it is the selected one.
fn machine_key(state: &AppState, m: &Machine) -> Softkey {
    Softkey {
        id: format!("machine-{}", m.id),
        label: softkey_lines(state.lang.t(&m.name.de, &m.name.en), LABEL_WIDTH),
        action: Action::SelectMachine(m.id.clone()),
        active: state.machine.as_ref().is_some_and(|s| s.id == m.id),
    }
}

/// Characters a softkey line holds at the smallest screen (1280×720 projector).
const LABEL_WIDTH: usize = 14;

/// A long name broken at blanks into softkey lines of at most `width` characters (a longer
/// word stands alone on its line).
fn softkey_lines(name: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line_len = 0;
    for word in name.split_whitespace() {
        let n = word.chars().count();
        if line_len > 0 && line_len + 1 + n > width {
            out.push('\n');
            line_len = 0;
        } else if line_len > 0 {
            out.push(' ');
            line_len += 1;
        }
        out.push_str(word);
        line_len += n;
    }
    out
}

/// The row the control shows in `state`.
#[must_use]
pub fn row(state: &AppState) -> Row {
    if let Some((dialog, _)) = &state.dialog {
        return dialog_row(dialog);
    }
    if let Some(run) = &state.run {
        return run_row(state, run);
    }
    if state.link.is_some() {
        return link_row(state.lang);
    }
    if state.replace.is_some() {
        return replace_row(state.lang);
    }
    if state.machine_offer.is_some() {
        return offer_row(state.lang);
    }
    match state.level {
        SoftkeyLevel::Main => main_row(state),
        SoftkeyLevel::SpecFct => spec_fct_row(state.lang),
        SoftkeyLevel::TiltPlane => tilt_plane_row(),
        SoftkeyLevel::Machines => machines_row(state),
        SoftkeyLevel::OwnMachines => own_machines_row(state),
        SoftkeyLevel::Files => files_row(state),
        SoftkeyLevel::Samples => samples_row(state.lang),
    }
}

/// The shown row's name with the way back, above the softkeys: after a PLANE dialog the
/// control keeps the function row up (F6 is REL. SPA. there, not PGM-LAUF), which surprises a
/// trainee who does not see which row is up.
#[must_use]
pub fn row_name(state: &AppState) -> Text {
    let back = |de: &str, en: &str| {
        Text::owned(format!("Softkeys: {de} · END = zurück"), format!("Softkeys: {en} · END = back"))
    };
    if let Some((dialog, _)) = &state.dialog {
        let f = function_label(dialog.function);
        return Text::owned(
            format!("Softkeys: Dialog PLANE {f} · Esc = abbrechen"),
            format!("Softkeys: dialog PLANE {f} · Esc = abort"),
        );
    }
    if state.run.is_some() {
        return back("PGM-LAUF", "PGM RUN");
    }
    if state.link.is_some() {
        return Text::new("Softkeys: Programm aus dem Link", "Softkeys: program from the link");
    }
    if state.replace.is_some() {
        return Text::new("Softkeys: Programm ersetzen?", "Softkeys: replace the program?");
    }
    if state.machine_offer.is_some() {
        return Text::new("Softkeys: Maschine für das Programm?", "Softkeys: a machine for the program?");
    }
    match state.level {
        SoftkeyLevel::Main => {
            Text::new("Softkeys: Programmieren (Hauptleiste)", "Softkeys: programming (main row)")
        }
        SoftkeyLevel::SpecFct => back("SPEC FCT", "SPEC FCT"),
        SoftkeyLevel::TiltPlane => back("BEARB.-EBENE SCHWENKEN", "TILT MACHINING PLANE"),
        SoftkeyLevel::Machines => back("MASCHINE WÄHLEN", "SELECT MACHINE"),
        SoftkeyLevel::OwnMachines => back("EIGENE MASCHINEN", "OWN MACHINES"),
        SoftkeyLevel::Samples => back("BEISPIEL ÖFFNEN", "OPEN SAMPLE"),
        SoftkeyLevel::Files => back("DATEI", "FILE"),
    }
}

fn main_row(state: &AppState) -> Row {
    let l = state.lang;
    [
        key("spec-fct", "SPEC\nFCT", Action::SpecFct),
        text_key("machines", Text::new("MASCHINE\nWÄHLEN", "SELECT\nMACHINE"), l, Action::ShowMachines),
        text_key("samples", Text::new("BEISPIEL\nÖFFNEN", "OPEN\nSAMPLE"), l, Action::ShowSamples),
        toggle_key(
            "text-edit",
            Text::new("TEXT\nEDITIEREN", "EDIT\nAS TEXT"),
            l,
            Action::ToggleTextEditing,
            state.text_editing,
        ),
        text_key("files", Text::new("DATEI", "FILE"), l, Action::ShowFiles),
        text_key("run", Text::new("PGM-LAUF", "PGM RUN"), l, Action::StartRun),
        toggle_key(
            "projector",
            Text::new("PROJEKTOR", "PROJECTOR"),
            l,
            Action::ToggleProjector,
            state.projector,
        ),
        text_key("lang", Text::new("SPRACHE\nENGLISH", "LANGUAGE\nDEUTSCH"), l, Action::ToggleLang),
    ]
}

// The other rows out of line: the page split (scripts/split_pages.py) can then leave them, with
// their labels, to the wasm loaded after the first screen, which shows the main row only.
#[inline(never)]
fn dialog_row(dialog: &Dialog) -> Row {
    let mut row: Row = Default::default();
    for (slot, (k, label)) in row.iter_mut().zip(dialog.softkeys()) {
        let active = matches!((&k, dialog.selection), (Key::Selection(s), Some(sel)) if *s == sel);
        let id = format!("dlg-{}", label.to_ascii_lowercase().replace([' ', '.'], "-"));
        *slot = Some(Softkey { id, label: label.replace(' ', "\n"), action: Action::DialogKey(k), active });
    }
    row
}

#[inline(never)]
fn run_row(state: &AppState, run: &Run) -> Row {
    let l = state.lang;
    let speed = format!("{}\n×{}", Text::new("SCHNELLER", "FASTER").get(l), run.speed_factor());
    [
        Some(Softkey {
            id: "run-play".to_owned(),
            label: if run.playing {
                Text::new("NC-STOPP", "NC STOP")
            } else {
                Text::new("NC-START\nSATZFOLGE", "NC START\nSEQUENCE")
            }
            .get(l)
            .to_owned(),
            action: Action::RunPlay,
            active: run.playing,
        }),
        if run.asking {
            // The class has answered: show it.
            text_key("run-next", Text::new("ZEIGEN ▶", "SHOW ▶"), l, Action::RunNext)
        } else {
            text_key("run-next", Text::new("EINZEL-\nSATZ ▶", "SINGLE\nBLOCK ▶"), l, Action::RunNext)
        },
        text_key("run-prev", Text::new("◀ SATZ\nZURÜCK", "◀ BLOCK\nBACK"), l, Action::RunPrev),
        text_key("run-start", Text::new("ZUM\nANFANG", "TO\nSTART"), l, Action::RunToStart),
        text_key("run-slower", Text::new("LANG-\nSAMER", "SLOWER"), l, Action::RunSlower),
        key("run-faster", &speed, Action::RunFaster),
        toggle_key("stock", Text::new("ROHTEIL", "STOCK"), l, Action::ToggleStock, state.stock_shown),
        back(l),
    ]
}

#[inline(never)]
fn link_row(l: Lang) -> Row {
    [
        text_key("take-link", Text::new("LINK\nÜBER-\nNEHMEN", "TAKE\nLINK"), l, Action::TakeLink),
        text_key("keep-own", Text::new("EIGENES\nBEHALTEN", "KEEP\nMINE"), l, Action::KeepOwn),
        None,
        None,
        None,
        text_key("run", Text::new("PGM-LAUF", "PGM RUN"), l, Action::StartRun),
        None,
        text_key("lang", Text::new("SPRACHE\nENGLISH", "LANGUAGE\nDEUTSCH"), l, Action::ToggleLang),
    ]
}

#[inline(never)]
fn spec_fct_row(l: Lang) -> Row {
    [
        None,
        None,
        text_key(
            "tilt-plane",
            Text::new("BEARB.-\nEBENE\nSCHWENKEN", "TILT\nMACHINING\nPLANE"),
            l,
            Action::TiltPlane,
        ),
        None,
        None,
        None,
        None,
        back(l),
    ]
}

#[inline(never)]
fn tilt_plane_row() -> Row {
    PlaneKind::ALL.map(|f| {
        let label = function_label(f);
        key(&format!("fn-{}", label.to_ascii_lowercase().replace([' ', '.'], "")), label, Action::Function(f))
    })
}

#[inline(never)]
fn machines_row(state: &AppState) -> Row {
    let l = state.lang;
    let mut row: Row = Default::default();
    for (slot, id) in row.iter_mut().zip(Machine::builtin_ids()) {
        *slot = Machine::builtin(id).ok().map(|m| machine_key(state, &m));
    }
    if !state.own_machines.is_empty() {
        let own = state.machine.as_ref().is_some_and(|m| state.own_machines.iter().any(|o| o.id == m.id));
        row[5] = toggle_key(
            "own-machines",
            Text::new("EIGENE\nMASCHINEN", "OWN\nMACHINES"),
            l,
            Action::ShowOwnMachines,
            own,
        );
    }
    row[6] = text_key("edit-machine", Text::new("EDITIEREN", "EDIT"), l, Action::EditMachine);
    row[7] = back(l);
    row
}

#[inline(never)]
fn own_machines_row(state: &AppState) -> Row {
    let mut row: Row = Default::default();
    for (slot, m) in row.iter_mut().zip(state.own_machines.iter()) {
        *slot = Some(machine_key(state, m));
    }
    row[7] = back(state.lang);
    row
}

/// A question with two answers: yes on F1, no on F2 and at END (F8), so a key pressed again by
/// a slip chooses nothing new.
fn question_row(l: Lang, yes: Option<Softkey>, no: Option<Softkey>) -> Row {
    [yes, no, None, None, None, None, None, back(l)]
}

/// "Take the machine that has the program's rotary axes?" — take first, keep second and at END.
#[inline(never)]
fn offer_row(l: Lang) -> Row {
    question_row(
        l,
        text_key(
            "take-machine",
            Text::new("MASCHINE\nÜBERNEHMEN", "TAKE\nMACHINE"),
            l,
            Action::TakeMachineOffer,
        ),
        text_key("keep-machine", Text::new("MASCHINE\nBEHALTEN", "KEEP\nMACHINE"), l, Action::KeepMachine),
    )
}

/// "Replace the own, unexported program?" — the answer "replace" first, "keep" second and at
/// END, so the key that chose the sample, pressed again by a slip, replaces nothing.
#[inline(never)]
fn replace_row(l: Lang) -> Row {
    question_row(
        l,
        text_key(
            "confirm-replace",
            Text::new("PROGRAMM\nERSETZEN", "REPLACE\nPROGRAM"),
            l,
            Action::ConfirmReplace,
        ),
        text_key("keep-own", Text::new("EIGENES\nBEHALTEN", "KEEP\nMINE"), l, Action::KeepOwn),
    )
}

#[inline(never)]
fn files_row(state: &AppState) -> Row {
    let l = state.lang;
    let undo = Softkey {
        id: "undo".to_owned(),
        label: Text::new("RÜCK-\nGÄNGIG", "UNDO").get(l).to_owned(),
        action: Action::Undo,
        active: false,
    };
    let redo = Softkey {
        id: "redo".to_owned(),
        label: Text::new("WIEDER-\nHERSTELLEN", "REDO").get(l).to_owned(),
        action: Action::Redo,
        active: false,
    };
    [
        // Rendered as a file picker by the softkey row; F1 opens it through Effect::PickFile.
        text_key("import", Text::new("IMPORT\n.H", "IMPORT\n.H"), l, Action::PickFile),
        text_key("download", Text::new("HERUNTER-\nLADEN .H", "DOWNLOAD\n.H"), l, Action::Download),
        text_key("share", Text::new("LINK\nTEILEN", "SHARE\nLINK"), l, Action::Share),
        None,
        state.history.can_undo().then_some(undo),
        state.history.can_redo().then_some(redo),
        None,
        back(l),
    ]
}

#[inline(never)]
fn samples_row(l: Lang) -> Row {
    let mut row: Row = Default::default();
    for (slot, s) in row.iter_mut().zip(&SAMPLES) {
        *slot = key(&format!("sample-{}", s.id), s.title.get(l), Action::LoadSample(s.id.to_owned()));
    }
    row[7] = back(l);
    row
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::state::{Reducer, Then};

    fn ids(state: &AppState) -> Vec<String> {
        row(state).iter().flatten().map(|k| k.id.clone()).collect()
    }

    #[test]
    fn every_level_has_a_way_out_and_spec_fct_is_on_the_main_row() {
        let s = AppState::default();
        assert!(ids(&s).contains(&"spec-fct".to_owned()));
        let s = s.then(Action::SpecFct);
        assert!(ids(&s).contains(&"back".to_owned()));
        let s = s.then(Action::TiltPlane);
        assert_eq!(
            ids(&s),
            [
                "fn-spatial",
                "fn-projected",
                "fn-euler",
                "fn-vector",
                "fn-points",
                "fn-relspa",
                "fn-axial",
                "fn-reset"
            ]
        );
    }

    #[test]
    fn the_row_name_says_the_function_row_is_still_up_after_a_plane_dialog() {
        use crate::dialog::Key;
        let s = AppState::default().then(Action::SpecFct).then(Action::TiltPlane);
        let s = s.then(Action::Function(PlaneKind::Reset));
        assert!(row_name(&s).de.contains("Dialog PLANE RESET"));
        let mut s = s.then(Action::DialogKey(Key::Positioning(crate::dialog::PosKind::Stay)));
        for _ in 0..4 {
            if s.dialog.is_none() {
                break;
            }
            s = s.then(Action::DialogKey(Key::End));
        }
        assert!(s.dialog.is_none(), "the dialog is finished");
        assert_eq!(row(&s)[5].as_ref().map(|k| k.id.as_str()), Some("fn-relspa"), "F6 is REL. SPA. here");
        assert_eq!(row_name(&s).de, "Softkeys: BEARB.-EBENE SCHWENKEN · END = zurück");
        assert_eq!(row_name(&s.then(Action::Back).then(Action::Back)).en, "Softkeys: programming (main row)");
    }

    #[test]
    fn machine_row_lists_every_shipped_machine_by_name_and_marks_the_selected_one() {
        let s = AppState::default().then(Action::ShowMachines);
        let r = row(&s);
        let machines: Vec<_> = r.iter().flatten().filter(|k| k.id.starts_with("machine-")).collect();
        assert_eq!(machines.len(), Machine::builtin_ids().len());
        let ac = machines.iter().find(|k| k.active && k.id == "machine-ac-table").expect("ac-table selected");
        assert_eq!(ac.label, "C-Rundtisch\nauf\nA-Schwenktisch");
        for k in &machines {
            assert!(k.label.lines().all(|line| line.chars().count() <= LABEL_WIDTH), "{:?}", k.label);
            assert!(
                !k.label.contains("TABLE") && !k.label.contains("HEAD"),
                "a name, not an id: {:?}",
                k.label
            );
        }
        let en = s.then(Action::ToggleLang);
        assert!(row(&en).iter().flatten().any(|k| k.label.starts_with("C rotary")));
    }

    #[test]
    fn files_row_by_function_keys_asks_the_shell_for_each_effect() {
        use crate::state::Effect;
        let s = AppState::default().then(Action::ShowFiles);
        let press = |n: usize| s.apply(row(&s)[n].as_ref().expect("a softkey").action.clone());
        assert_eq!(press(0).1, [Effect::PickFile]);
        assert!(matches!(&*press(1).1, [Effect::Download { name, text }]
            if name == "Musterprogramm1.h" && *text == s.doc.text));
        assert!(matches!(&*press(2).1, [Effect::Share { fragment }] if fragment.starts_with("pgm=")));
        assert!(
            !press(1).0.apply(Action::ToggleLang).1.iter().any(|e| matches!(e, Effect::Download { .. })),
            "an effect is asked for once"
        );
    }
}
