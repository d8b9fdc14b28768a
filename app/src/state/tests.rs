//! The trainer's reducer, action by action.

use super::*;
use crate::dialog::PosKind;
use crate::persist::{self, Prefs, Stored};
use schwenkbar_core::plane::PlaneKind;

fn keys(mut s: AppState, text: &str) -> AppState {
    for c in text.chars() {
        s = s.then(Action::DialogKey(Key::Char(c)));
    }
    s.then(Action::DialogKey(Key::Ent))
}

#[test]
fn spatial_dialog_inserts_the_block_after_the_cursor_with_the_next_number() {
    let mut s = AppState::default()
        .then(Action::SetText("0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91\n2 END PGM T MM\n".into()));
    s = s.then(Action::CursorTo(1));
    s = s.then(Action::SpecFct).then(Action::TiltPlane).then(Action::Function(PlaneKind::Spatial));
    s = keys(keys(keys(s, "0"), "15"), "0");
    s = s.then(Action::DialogKey(Key::Positioning(PosKind::Turn)));
    s = s.then(Action::DialogKey(Key::NoEnt)).then(Action::DialogKey(Key::FMax));
    s = s.then(Action::DialogKey(Key::NoEnt)).then(Action::DialogKey(Key::NoEnt));
    assert!(s.dialog.is_none());
    assert_eq!(
        s.doc.text,
        "0 BEGIN PGM T MM\n1 L Z+0 R0 FMAX M91\n2 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX\n3 END PGM T MM\n"
    );
    assert_eq!(s.cursor, 2);
    assert!(s.doc.diagnostics.is_empty());
}

#[test]
fn abort_keeps_the_program_and_ent_reopens_a_plane_block() {
    let s = AppState::default();
    let before = s.doc.text.clone();
    let s = s.then(Action::Function(PlaneKind::Euler));
    let s = keys(s, "45").then(Action::Abort);
    assert!(s.dialog.is_none());
    assert_eq!(s.doc.text, before);
    // Musterprogramm 1, block 10 is the PLANE SPATIAL block.
    let s = s.then(Action::CursorTo(10)).then(Action::Open);
    let (d, editing) = s.dialog.as_ref().expect("dialog reopened");
    assert_eq!((d.function, *editing), (PlaneKind::Spatial, Some(10)));
    let s = s.then(Action::CursorTo(9));
    assert_eq!(s.cursor, 10, "the cursor stays while the dialog is open");
    let s = s.then(Action::Abort).then(Action::CursorTo(9)).then(Action::Open);
    assert!(s.dialog.is_none());
    assert!(s.message.is_some(), "ENT on a non-PLANE block says why nothing opens");
}

#[test]
fn samples_select_their_machine_and_unknown_ids_are_reported() {
    let s = AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into()));
    assert_eq!(s.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));
    let t = s.then(Action::SelectMachine("no-such".into()));
    assert_eq!(t.machine, s.machine);
    assert!(t.message.is_some());
}

#[test]
fn state_survives_a_reload_and_a_corrupt_one_falls_back_with_a_message() {
    let s = AppState::default()
        .then(Action::LoadSample("stay_q120".into()))
        .then(Action::CursorTo(7))
        .then(Action::ToggleLang);
    let stored = Stored {
        state: Some(s.saved().to_record()),
        prefs: Some(s.prefs().to_record()),
        program: Some(s.doc.text.clone()),
        machines: None,
        replaced: None,
        tools: None,
    };
    let (back, _) = AppState::start(stored, None);
    assert_eq!((back.doc.text.as_str(), back.cursor, back.lang), (s.doc.text.as_str(), 7, Lang::En));
    assert_eq!(back.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table"));
    assert_eq!(back.message, None);
    let sim = back.sim.as_ref().expect("simulated");
    assert_eq!(
        sim.0.first_step.len(),
        back.doc.program.blocks.len(),
        "the restored program is the one simulated"
    );

    let stored =
        Stored { state: Some("s2;cursor=".into()), program: Some("0 L X+1".into()), ..Stored::default() };
    let (broken, fx) = AppState::start(stored, None);
    assert_eq!(broken.doc.text, "0 L X+1", "the program typed is kept");
    assert_eq!(
        broken.message.as_ref().map(|m| m.get(Lang::En)),
        Some("The saved state was corrupt: cursor and machine reset, program kept")
    );
    assert!(
        fx.contains(&Effect::Save { key: persist::STATE_KEY, value: broken.saved().to_record() }),
        "the corrupt record is replaced"
    );
    let stored = Stored {
        state: Some(r#"{"version":1,"cursor":3,"machine":"ac-table","lang":"En","projector":false}"#.into()),
        prefs: Some("p1;lang=xx".into()),
        program: None,
        machines: None,
        replaced: None,
        tools: None,
    };
    let (old, _) = AppState::start(stored, None);
    assert_eq!(
        old.message.as_ref().map(|m| m.get(Lang::En)),
        Some("The saved state is from an older version: cursor and machine reset, program kept")
    );
    assert_eq!(old.prefs(), Prefs::default(), "unreadable preferences are the defaults");
}

#[test]
fn share_link_opens_the_same_program_at_the_same_block_and_machine() {
    let s =
        AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into())).then(Action::CursorTo(8));
    let (opened, _) = AppState::start(Stored::default(), Some(&format!("#{}", s.share_fragment())));
    assert_eq!(opened.doc.text, s.doc.text);
    assert_eq!(opened.cursor, 8);
    assert_eq!(opened.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));
    assert_eq!(s.file_name(), "WINKEL.h");
    assert!(opened.run.is_none());
    let running = AppState::default().then(Action::CursorTo(10)).then(Action::StartRun);
    let (opened, _) = AppState::start(Stored::default(), Some(&running.share_fragment()));
    let shown = opened.run.as_ref().and_then(|r| r.state.as_ref()).map(|s| s.block);
    assert_eq!(shown, Some(10), "the link opens the run at block 10");
}

/// The trainer's own start shows the program before it simulates (the simulator's code comes
/// after the first screen): SIMULATE, or any key before it, makes the same run a start that
/// simulates at once makes; the start's message and a link preview stay; a link that opens a
/// run simulates at once.
#[test]
fn the_first_screen_waits_for_its_simulation_and_any_key_makes_it() {
    let (eager, eager_fx) = AppState::start(Stored::default(), None);
    assert!(!eager_fx.contains(&Effect::Simulate));
    let (lazy, fx) = AppState::start_unsimulated(Stored::default(), None);
    assert!(lazy.sim_pending && lazy.sim.is_none() && !eager.sim_pending);
    assert!(!fx.contains(&Effect::BuildStock) && fx.contains(&Effect::Simulate));
    let (simulated, _) = lazy.apply(Action::Simulate);
    assert!(!simulated.sim_pending);
    let (a, b) = (simulated.sim.as_ref().expect("run"), eager.sim.as_ref().expect("run"));
    assert_eq!((a.0.len(), a.0.error.clone()), (b.0.len(), b.0.error.clone()));
    assert!(a.0.len() > 30, "Musterprogramm 1 runs");
    // Twice is once.
    assert_eq!(simulated.apply(Action::Simulate).0.sim, simulated.sim);
    // A key first: it acts on the simulated program.
    let started = lazy.then(Action::StartRun);
    assert!(!started.sim_pending && started.run.as_ref().is_some_and(|r| r.state.is_some()));

    // A link over own work: SIMULATE keeps the preview and its question.
    let own = "0 BEGIN PGM MEIN MM\n1 L Z+0 R0 FMAX M91\n2 END PGM MEIN MM\n".to_owned();
    let link = AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into())).share_fragment();
    let stored = Stored { program: Some(own), ..Stored::default() };
    let (preview, _) = AppState::start_unsimulated(stored, Some(&link));
    let question = preview.message.clone();
    let (preview, _) = preview.apply(Action::Simulate);
    assert!(preview.link.is_some() && preview.sim.is_some());
    assert_eq!(preview.message, question);
    // A link that opens a run: simulated at once.
    let running = AppState::default().then(Action::CursorTo(10)).then(Action::StartRun);
    let (opened, _) = AppState::start_unsimulated(Stored::default(), Some(&running.share_fragment()));
    assert!(!opened.sim_pending && opened.run.is_some());
}

#[test]
fn run_steps_to_the_swivel_and_stops_on_the_refused_block() {
    let mut s = AppState::default().then(Action::StartRun);
    assert_eq!(s.cursor, 0);
    while s.cursor < 10 {
        s = s.then(Action::RunNext);
    }
    let shown = s.run.as_ref().and_then(|r| r.state.clone()).expect("state");
    let (axis, a) = shown.axes.named()[3];
    assert!(axis == 'A' && (a - 15.0).abs() < 1e-9, "{axis}{a}");
    assert_eq!(s.then(Action::CursorTo(25)).cursor, 25, "a click jumps there");
    let s = s.then(Action::Back);
    assert!(s.run.is_none());

    let mut s =
        AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into())).then(Action::StartRun);
    s = s.then(Action::RunPlay);
    for step in 0..20 {
        s = s.then(Action::RunTick(s.run.as_ref().map_or(step, |r| r.step)));
    }
    let run = s.run.as_ref().expect("run");
    assert!(run.stopped_by_error && !run.playing);
    assert_eq!(s.cursor, 8, "the cursor stands on the refused block");
    assert_eq!(s.dialog_line(), "Winkel nicht erlaubt");
}

#[test]
fn language_switch_changes_the_dialog_line_and_keeps_the_program() {
    let s = AppState::default().then(Action::SpecFct);
    assert_eq!(s.dialog_text().get(s.lang), "Sonderfunktionen: Bereich wählen");
    let en = s.then(Action::ToggleLang);
    assert_eq!(en.dialog_text().get(en.lang), "Special functions: select an area");
    assert_eq!(en.doc, s.doc);
}

#[test]
fn a_link_over_own_work_is_a_preview_until_the_trainee_decides() {
    let own = "0 BEGIN PGM MEIN MM\n1 L Z+0 R0 FMAX M91\n2 END PGM MEIN MM\n".to_owned();
    let saved = Some(AppState::default().saved().to_record());
    let link = AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into())).share_fragment();
    let stored = |program: &str| Stored {
        state: saved.clone(),
        program: Some(program.to_owned()),
        ..Stored::default()
    };
    let (s, fx) = AppState::start(stored(&own), Some(&link));
    assert!(s.link.is_some());
    assert_ne!(s.doc.text, own, "the link's program is shown");
    assert_eq!(fx, [Effect::ConsumeFragment], "the fragment is read once, nothing is saved in the preview");
    assert!(s.dialog_text().de.contains("übernehmen?"));
    // Editing is held back; looking and running are not.
    let held = s.then(Action::SetText("0 L X+1".into()));
    assert_eq!(held.doc, s.doc);
    assert!(held.message.is_some_and(|m| m.de.contains("LINK ÜBERNEHMEN")));
    assert!(s.then(Action::StartRun).run.is_some());
    let (kept, fx) = s.then(Action::StartRun).apply(Action::KeepOwn);
    assert!(fx.contains(&Effect::Save { key: persist::PROGRAM_KEY, value: own.clone() }), "{fx:?}");
    assert_eq!((kept.doc.text.as_str(), kept.link.is_none(), kept.run.is_none()), (own.as_str(), true, true));
    assert_eq!(kept.machine.as_ref().map(|m| m.id.as_str()), Some("ac-table"));
    assert_eq!(kept.sim.as_ref().map(|s| s.0.first_step.len()), Some(3), "the own program is simulated");
    let taken = s.then(Action::TakeLink);
    assert_eq!((taken.doc.text.as_str(), taken.link.is_none()), (s.doc.text.as_str(), true));
    assert_eq!(taken.machine.as_ref().map(|m| m.id.as_str()), Some("ba-table"));

    // No own work, or the same program: nothing to ask.
    assert!(AppState::start(Stored::default(), Some(&link)).0.link.is_none());
    let (same, _) = AppState::start(stored(&s.doc.text), Some(&link));
    assert!(same.link.is_none());
}

#[test]
fn a_binary_file_is_not_imported_and_the_program_stays() {
    let s = AppState::default().then(Action::ShowFiles);
    let png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0\0\0\x01\0".to_vec();
    let refused = s.then(Action::Import(png));
    assert_eq!(refused.doc, s.doc);
    assert!(refused.message.is_some_and(|m| m.de.contains("kein NC-Programm")));
    let imported = s.then(Action::Import(b"0 BEGIN PGM I MM\r\n1 END PGM I MM\r\n".to_vec()));
    assert_eq!(imported.doc.program.blocks.len(), 2);
    assert!(imported.message.as_ref().is_some_and(|m| m.get(Lang::En).starts_with("Imported file opened")));
}

#[test]
fn text_editing_asks_for_the_focus_in_the_editor() {
    let (s, fx) = AppState::default().apply(Action::ToggleTextEditing);
    assert_eq!(fx, [Effect::FocusEditor]);
    assert!(s.apply(Action::ToggleTextEditing).1.is_empty());
}

#[test]
fn the_classroom_run_asks_before_a_swivel_and_reveals_on_nc_start() {
    let to_block_9 = |projector: bool| {
        let mut s = AppState { projector, ..AppState::default() }.then(Action::StartRun);
        while s.cursor < 9 {
            s = s.then(Action::RunNext);
        }
        s
    };
    // Musterprogramm 1, block 10: PLANE SPATIAL … TURN on the A/C table.
    let s = to_block_9(true).then(Action::RunNext);
    let run = s.run.as_ref().expect("run");
    assert!(run.asking);
    assert_eq!(run.state.as_ref().map(|st| st.block), Some(9), "block 10 has not run yet");
    assert_eq!(
        s.dialog_line(),
        "Vorhersage: Wohin schwenkt der Tisch? Welche Werte haben A und C? NC-Start zeigt es."
    );
    let revealed = s.then(Action::RunNext);
    let run = revealed.run.as_ref().expect("run");
    assert!(!run.asking);
    assert_eq!(run.state.as_ref().map(|st| st.block), Some(10), "NC start reveals block 10");
    // The other solution is there to be shown as the ghost.
    assert!(
        run.state.as_ref().and_then(|st| st.explanation.as_ref()).is_some_and(|e| e.candidates.len() == 2)
    );
    // Outside the classroom the run does not stop to ask.
    let plain = to_block_9(false).then(Action::RunNext);
    assert_eq!(plain.run.as_ref().and_then(|r| r.state.as_ref()).map(|st| st.block), Some(10));
    // In a full sequence the run stops at the question and NC start goes on after it.
    let mut playing = to_block_9(true).then(Action::RunPlay);
    let step = playing.run.as_ref().map_or(0, |r| r.step);
    playing = playing.then(Action::RunTick(step));
    let run = playing.run.as_ref().expect("run");
    assert!(run.asking && !run.playing);
    let on = playing.then(Action::RunPlay);
    let run = on.run.as_ref().expect("run");
    assert!(run.playing && !run.asking);
    assert_eq!(run.state.as_ref().map(|st| st.block), Some(10));
}

#[test]
fn what_changed_is_saved_and_a_lessons_trainer_saves_nothing() {
    let s = AppState::default();
    let (s, fx) = s.apply(Action::CursorTo(10));
    assert_eq!(
        fx,
        [Effect::Save {
            key: persist::STATE_KEY,
            value: "s3;cursor=10;machine=ac-table;unexported=0".into()
        }]
    );
    let (s, fx) = s.apply(Action::ToggleProjector);
    assert_eq!(fx, [Effect::Save { key: persist::PREFS_KEY, value: "p1;lang=de;classroom=1".into() }]);
    let (s, fx) = s.apply(Action::SetText("0 BEGIN PGM X MM\n1 END PGM X MM\n".into()));
    assert_eq!(
        fx,
        [
            Effect::Save { key: persist::PROGRAM_KEY, value: s.doc.text.clone() },
            Effect::Save {
                key: persist::STATE_KEY,
                value: "s3;cursor=1;machine=ac-table;unexported=1".into()
            },
        ]
    );
    assert!(s.apply(Action::ShowFiles).1.is_empty(), "a softkey level is not saved");

    let (lesson, fx) = AppState::embedded(samples::DEFAULT.text, "ac-table", Lang::De, false);
    // Shown first, simulated once the simulator's code is there (or at the first key).
    assert_eq!(fx, [Effect::Simulate, Effect::TellCourse(lesson.cursor_plane_text())]);
    assert!(lesson.sim_pending && lesson.sim.is_none());
    assert!(lesson.apply(Action::Simulate).0.sim.is_some());
    assert!(lesson.cursor_plane_text().is_some_and(|t| t.contains("PLANE")));
    let (_, fx) = lesson.apply(Action::CursorTo(0));
    assert_eq!(fx, [Effect::TellCourse(None)], "a lesson's trainer saves nothing");
}

#[test]
fn satzfolge_asks_for_a_tick_per_step_and_none_when_paused() {
    let (s, fx) = AppState::default().then(Action::StartRun).apply(Action::RunPlay);
    let run = s.run.as_ref().expect("run");
    assert_eq!(fx, [Effect::Tick { step: run.step, ms: run.tick_ms() }]);
    let (s, fx) = s.apply(Action::RunTick(run.step));
    let next = s.run.as_ref().expect("run");
    assert!(fx.contains(&Effect::Tick { step: next.step, ms: next.tick_ms() }), "{fx:?}");
    assert_eq!(next.step, run.step + 1);
    let (_, fx) = s.apply(Action::RunPlay);
    assert!(fx.is_empty(), "paused: no timer");
}

#[test]
fn the_stock_is_cut_after_a_run_starts_never_while_typing_and_the_switch_hides_it() {
    let s = AppState::default().then(Action::SetText(crate::samples::MUSTERPROGRAMM_1.text.to_owned()));
    assert!(s.stock_shown, "on by default (issue 32)");
    let (typed, fx) = s.apply(Action::SetText(format!("{}\n", s.doc.text)));
    assert!(!fx.contains(&Effect::BuildStock) && typed.stock.is_none(), "typing cuts nothing");
    let (run, fx) = typed.apply(Action::StartRun);
    assert_eq!(
        fx.iter().filter(|e| **e == Effect::BuildStock).count(),
        1,
        "asked for once, after the render"
    );
    assert!(run.stock.is_none());
    let (_, fx) = run.apply(Action::RunNext);
    assert!(!fx.contains(&Effect::BuildStock), "asked for already");
    let (_, fx) = run.apply(Action::ToggleStock);
    assert!(!fx.contains(&Effect::BuildStock), "hiding it asks for nothing new");
    let (cut, fx) = run.apply(Action::BuildStock);
    assert!(!fx.contains(&Effect::BuildStock));
    assert_eq!(fx, [Effect::PassStock], "the first pass goes on after the next paint");
    let stock = cut.shown_stock().expect("the stock of this run");
    assert!(stock.is_for(cut.sim.as_ref().expect("sim")));
    let hidden = cut.then(Action::ToggleStock);
    assert!(hidden.shown_stock().is_none() && hidden.stock.is_some(), "hidden, kept for the switch back");
    assert_eq!(
        crate::keymap::action(&cut, &crate::keymap::KeyPress { key: "r", shift: false, ctrl_or_alt: false }),
        Some(Action::ToggleStock)
    );
    let row = crate::softkeys::row(&cut);
    assert!(
        row[6].as_ref().is_some_and(|k| k.label == "ROHTEIL" && k.active && k.action == Action::ToggleStock)
    );
    let other = cut.then(Action::SelectMachine("ba-table".into()));
    assert!(other.stock.is_none(), "a new simulation drops the old stock");
    // With the switch off a run still cuts: its collisions with the material are said.
    let (_, fx) = typed.then(Action::ToggleStock).apply(Action::StartRun);
    assert!(fx.contains(&Effect::BuildStock), "cut with the stock hidden too");
}

/// The crash the trainer exists to prevent: the drill in its hole, then `PLANE … TURN` without
/// `MB MAX`. The run says so on the PLANE block, in the dialog line and the why panel, with the
/// stock shown or hidden.
#[test]
fn a_swivel_with_the_tool_in_the_material_is_said_on_its_plane_block_stock_shown_or_not() {
    let text = "0 BEGIN PGM S MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 1 Z S1000\n4 L X+50 Y+50 Z+10 R0 FMAX\n5 L Z-5 F100\n6 PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX\n7 END PGM S MM\n";
    for shown in [true, false] {
        let s = AppState::default().then(Action::SetText(text.into()));
        let s = if shown { s } else { s.then(Action::ToggleStock) };
        assert_eq!(s.stock_shown, shown);
        let mut state = s.then(Action::StartRun).then(Action::BuildStock);
        while state.apply(Action::PassStock).1.contains(&Effect::PassStock) {
            state = state.then(Action::PassStock);
        }
        let state = state.then(Action::PassStock);
        let block = state.doc.program.blocks.iter().position(|b| b.number() == Some(6)).expect("block 6");
        let step = state.sim.as_ref().expect("sim").0.step_of_block(block).expect("executed");
        let mut at = state.clone();
        while at.run.as_ref().is_some_and(|r| r.step < step) {
            at = at.then(Action::RunNext);
        }
        let note = at.material_note().expect("the collision on the PLANE block");
        assert!(note.de.contains("Schwenken mit dem Werkzeug im Material") && note.de.contains("MB MAX"));
        assert_eq!(at.dialog_text(), note);
        let before = state.run.as_ref().map(|r| r.step);
        assert!(before < Some(step) && state.material_note().is_none(), "said on its block only");
    }
}

/// Presses a key as the keyboard would (`F3`, `Enter`, `z` with Ctrl …).
fn press(s: &AppState, key: &str, ctrl: bool) -> AppState {
    use crate::keymap::{KeyPress, action};
    let press = KeyPress { key, shift: false, ctrl_or_alt: ctrl };
    match action(s, &press) {
        Some(a) => s.then(a),
        None => s.clone(),
    }
}

fn edited() -> AppState {
    let mut text = AppState::default().doc.text.clone();
    text = text.replacen("SPB+15", "SPB+20", 1);
    AppState::default().then(Action::SetText(text))
}

#[test]
fn the_classroom_slip_asks_before_a_sample_replaces_unexported_work() {
    // Classroom trial II: edit → F6 → F2 → F3 (◀ SATZ ZURÜCK) → F8 (END) → F3 F3.
    let own = edited();
    assert!(own.unexported);
    let mut s = own.clone();
    for k in ["F6", "F2", "F3", "F8", "F3", "F3"] {
        s = press(&s, k, false);
    }
    assert_eq!(s.doc.text, own.doc.text, "nothing replaced yet");
    let asked = s.replace.as_ref().expect("the question");
    assert_eq!(asked.what.de, crate::samples::SAMPLES[2].title.de);
    assert!(s.dialog_text().de.contains("nicht exportiert"), "{:?}", s.dialog_text());
    // The same key pressed once more by a slip does nothing; other keys wait for the answer.
    let again = press(&s, "F3", false);
    assert_eq!((again.doc.text.as_str(), again.replace.is_some()), (own.doc.text.as_str(), true));
    assert!(press(&s, "F6", false).replace.is_some());
    // END keeps the own program, F2 too.
    for k in ["End", "F2", "F8"] {
        let kept = press(&s, k, false);
        assert_eq!((kept.doc.text.as_str(), kept.replace.is_none()), (own.doc.text.as_str(), true), "{k}");
    }
    // F1 replaces; the own program is one undo step back, kept in the browser too.
    let (replaced, fx) = s.apply(Action::ConfirmReplace);
    assert_eq!(replaced.doc.text, crate::samples::SAMPLES[2].text);
    assert!(!replaced.unexported);
    assert!(fx.contains(&Effect::Save { key: persist::REPLACED_KEY, value: own.doc.text.clone() }), "{fx:?}");
    let back = press(&replaced, "z", true);
    assert_eq!(back.doc.text, own.doc.text, "Ctrl+Z brings the own program back");
    assert!(back.unexported);
    let forward = press(&back, "y", true);
    assert_eq!(forward.doc.text, replaced.doc.text, "Ctrl+Y replaces it again");
}

#[test]
fn without_unexported_edits_a_sample_opens_at_once_and_undo_goes_back() {
    let s = AppState::default();
    let opened = s.then(Action::LoadSample("euler_fasen".into()));
    assert!(opened.replace.is_none());
    assert_ne!(opened.doc.text, s.doc.text);
    assert!(opened.message.as_ref().is_some_and(|m| m.de.contains("RÜCKGÄNGIG")));
    // The softkey on the DATEI row does what Ctrl+Z does.
    let files = opened.then(Action::ShowFiles);
    let undo = crate::softkeys::row(&files)[4].clone().expect("RÜCKGÄNGIG");
    assert_eq!(undo.action, Action::Undo);
    assert_eq!(files.then(undo.action).doc.text, s.doc.text);
    // Exporting ends "unexported": after a download a sample opens without a question.
    let downloaded = edited().then(Action::Download);
    assert!(!downloaded.unexported);
    assert!(downloaded.then(Action::LoadSample("euler_fasen".into())).replace.is_none());
}

#[test]
fn an_import_over_unexported_work_asks_and_a_taken_link_is_undone() {
    let own = edited();
    let asked = own.then(Action::Import(b"0 BEGIN PGM NEU MM\n1 END PGM NEU MM\n".to_vec()));
    assert_eq!(asked.doc.text, own.doc.text);
    let replaced = asked.then(Action::ConfirmReplace);
    assert_eq!(replaced.doc.text, "0 BEGIN PGM NEU MM\n1 END PGM NEU MM\n");
    assert_eq!(replaced.then(Action::Undo).doc.text, own.doc.text);

    let link = AppState::default().then(Action::LoadSample("winkel_nicht_erlaubt".into())).share_fragment();
    let stored = Stored { program: Some(own.doc.text.clone()), ..Stored::default() };
    let (preview, _) = AppState::start(stored, Some(&link));
    let (taken, fx) = preview.apply(Action::TakeLink);
    assert!(fx.contains(&Effect::Save { key: persist::REPLACED_KEY, value: own.doc.text.clone() }));
    assert_eq!(taken.then(Action::Undo).doc.text, own.doc.text, "the link taken is undone");
}

#[test]
fn typing_is_undone_a_line_at_a_time_and_the_replaced_program_survives_a_reload() {
    let s = AppState::default();
    let base = s.doc.text.clone();
    let typed = s
        .then(Action::SetText(format!("{base}; a")))
        .then(Action::SetText(format!("{base}; ab")))
        .then(Action::SetText(format!("{base}; ab\n")))
        .then(Action::SetText(format!("{base}; ab\n; c")));
    let one = typed.then(Action::Undo);
    assert_eq!(one.doc.text, format!("{base}; ab"));
    assert_eq!(one.then(Action::Undo).doc.text, base);
    assert!(one.then(Action::Undo).then(Action::Undo).message.is_some_and(|m| m.de.contains("Nichts")));

    let stored =
        Stored { program: Some("0 L X+1\n".into()), replaced: Some(base.clone()), ..Stored::default() };
    let (reloaded, _) = AppState::start(stored, None);
    assert_eq!(reloaded.then(Action::Undo).doc.text, base, "one step back after a reload");
}

/// Switching the stock on cuts nothing at once: the first pass goes on a bounded share per
/// `PassStock` (each after a paint) until it is done, and the note of a rapid into the material
/// shows on its block once the pass has got there (classroom trial II: 0.85 s in one task).
#[test]
fn the_stocks_first_pass_goes_on_in_bounded_shares_and_its_note_follows() {
    let text = "0 BEGIN PGM R MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 1 Z S1000\n4 L X+50 Y+50 Z+50 R0 FMAX\n5 L Z-5 R0 FMAX\n6 L X+90 F200\n7 END PGM R MM\n";
    let s = AppState::default().then(Action::SetText(text.into())).then(Action::StartRun);
    let s = s.then(Action::BuildStock);
    let block = s.doc.program.blocks.iter().position(|b| b.number() == Some(5)).expect("block 5");
    let rapid = s.sim.as_ref().expect("sim").0.step_of_block(block).expect("executed");
    let stock = s.stock.clone().expect("planned");
    assert!(stock.notes_at(rapid).is_none(), "nothing cut at the switch");
    let mut shares = 0;
    let mut state = s;
    loop {
        let (next, fx) = state.apply(Action::PassStock);
        state = next;
        shares += 1;
        if !fx.contains(&Effect::PassStock) {
            break;
        }
        assert!(shares < 1_000, "the pass ends");
    }
    assert!(stock.notes_at(rapid).is_some_and(|n| n.de.starts_with("Eilgang ins Material")));
    assert!(state.apply(Action::PassStock).1.is_empty(), "done: no more shares asked for");
}

/// An imported program that moves B and C on the A/C table: the machine with B and C is offered;
/// F1 takes it, F2 or END keeps the machine. A program the machine can run gets no offer.
#[test]
fn an_import_offers_the_machine_with_the_programs_rotary_axes() {
    let bc = b"0 BEGIN PGM BC MM\n1 TOOL CALL 1 Z S1000\n2 L B+30 C+90 R0 FMAX\n3 END PGM BC MM\n".to_vec();
    let s = AppState::default().then(Action::ShowFiles).then(Action::Import(bc));
    assert_eq!(s.machine.as_ref().map(|m| m.id.as_str()), Some(DEFAULT_MACHINE));
    let offer = s.machine_offer.clone().expect("a machine is offered");
    assert_eq!(offer.axes, "B, C");
    let offered = Machine::builtin(offer.id).expect("shipped");
    for axis in [schwenkbar_core::plane::RotaryAxis::B, schwenkbar_core::plane::RotaryAxis::C] {
        assert!(offered.joints().iter().any(|j| j.axis == axis), "{} has {axis:?}", offer.id);
    }
    assert!(s.message.as_ref().is_some_and(|m| m.de.contains("Drehachsen B, C") && m.de.contains("F1")));
    assert_eq!(
        crate::softkeys::row(&s)[0].as_ref().map(|k| k.action.clone()),
        Some(Action::TakeMachineOffer)
    );

    let taken = press(&s, "F1", false);
    assert_eq!(taken.machine.as_ref().map(|m| m.id.as_str()), Some(offer.id));
    assert!(taken.machine_offer.is_none());
    assert!(taken.sim.as_ref().is_some_and(|sim| sim.0.error.is_none()), "it runs on the offered machine");

    for key in ["F2", "End"] {
        let kept = press(&s, key, false);
        assert_eq!(kept.machine.as_ref().map(|m| m.id.as_str()), Some(DEFAULT_MACHINE), "{key}");
        assert!(kept.machine_offer.is_none(), "{key}");
    }

    let ac = b"0 BEGIN PGM AC MM\n1 L A+10 C+90 R0 FMAX\n2 END PGM AC MM\n".to_vec();
    let s = AppState::default().then(Action::ShowFiles).then(Action::Import(ac));
    assert!(s.machine_offer.is_none(), "the A/C table has A and C");
}

/// The tool table kept by the machine editor page runs in the trainer, and a share link
/// carries it to a receiver who has none (for that visit).
#[test]
fn the_shops_tool_table_runs_in_the_trainer_and_travels_in_a_share_link() {
    let table = "BEGIN TOOL .T MM\nT L    R\n1 +42  +3\n[END]\n";
    let program = "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000\n2 END PGM T MM\n";
    let length_after_call = |s: &AppState| {
        let sim = &s.sim.as_ref().expect("simulated").0;
        let step = sim.first_step[1].expect("executed") as usize;
        sim.state_at(&s.doc.program, step).expect("state").tool.length
    };
    let stored = Stored { program: Some(program.into()), tools: Some(table.into()), ..Stored::default() };
    let (s, _) = AppState::start(stored, None);
    assert_eq!(length_after_call(&s), 42.0, "the shop's tool 1, not the shipped one (L=80)");
    let (received, _) = AppState::start(Stored::default(), Some(&format!("#{}", s.share_fragment())));
    assert_eq!(length_after_call(&received), 42.0);
    let (plain, _) = AppState::start(Stored { program: Some(program.into()), ..Stored::default() }, None);
    assert_eq!(length_after_call(&plain), 80.0, "the shipped table");
    let (broken, _) = AppState::start(Stored { tools: Some("kaputt".into()), ..Stored::default() }, None);
    assert!(broken.message.is_some_and(|m| m.de.starts_with("Gespeicherte Werkzeugtabelle unlesbar")));
}
