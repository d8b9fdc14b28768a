//! A run that stops on a collision (issue 17): the view shows the moment of contact with the
//! pair marked, the collision-free other solution as the ghost, and the why panel says so.

use schwenkbar_app::effect::Reducer;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::persist::{Shared, Stored, share_fragment};
use schwenkbar_app::scene::{MachineAxes, SceneState};
use schwenkbar_app::state::{Action, AppState};
use schwenkbar_app::why::for_block;
use schwenkbar_core::sim::collision::{RESOLUTION, touch};
use schwenkbar_testkit::collision::{SEQ_MINUS_SWIVEL, program};

fn then(s: &AppState, a: Action) -> AppState {
    s.apply(a).0
}

/// The trainer on `ac-table` with `swivel`, the run played until it stops.
fn run_to_the_end(swivel: &str) -> AppState {
    let mut s = then(&AppState::default(), Action::SelectMachine("ac-table".into()));
    s = then(&s, Action::SetText(program(swivel)));
    s = then(&then(&s, Action::StartRun), Action::RunPlay);
    for _ in 0..20 {
        let step = s.run.as_ref().map_or(0, |r| r.step);
        s = then(&s, Action::RunTick(step));
    }
    s
}

#[test]
fn a_run_stopped_by_a_collision_shows_the_moment_of_contact_with_the_pair_and_the_free_solution() {
    let s = run_to_the_end(SEQ_MINUS_SWIVEL);
    assert!(s.run.as_ref().is_some_and(|r| r.stopped_by_error), "{:?}", s.sim.as_ref().map(|x| &x.0.error));
    let c = s.shown_collision().expect("the run stopped on a collision").clone();
    let machine = s.machine.clone().expect("machine");
    let before = s.shown_state().expect("the last finished step");
    let mut scene = SceneState::default();
    scene.at_collision(&machine, &before, &c);
    // At the contact, not at the block's end (A−30) nor its start (A+0).
    assert_eq!(scene.axes, MachineAxes { linear: c.axes.linear, rotary: c.axes.rotary_values() });
    let a = scene.axes.rotary.a.expect("A");
    assert!(a < 0.0 && a > -30.0, "A{a}");
    // The pair, placed there, touches (within the check's resolution).
    let [x, y] = scene.contact.expect("the pair is marked");
    assert!(touch(&x, &y, 2.0 * RESOLUTION), "{x:?} {y:?}");
    // The collision-free SEQ+ solution is the ghost.
    let alt = c.alternative.as_ref().expect("alternative");
    assert_eq!(scene.ghost, Some(alt.axes));

    // The why panel of the refused block names it, German first.
    let sim = s.sim.as_ref().map(|x| x.0.as_ref());
    let why =
        |l| for_block(&s.doc.program, sim, Some(&before), s.cursor, &machine, l).expect("a PLANE block");
    let de = why(Lang::De).safe_alternative.expect("the note");
    assert!(de.starts_with(&format!("Die gewählte Lösung kollidiert ({} – {})", c.a.de, c.b.de)), "{de}");
    assert!(de.contains("die andere Lösung SEQ+ (A+30") && de.ends_with("wäre kollisionsfrei."), "{de}");
    let en = why(Lang::En).safe_alternative.expect("the note");
    assert!(en.starts_with("The chosen solution collides (") && en.contains("SEQ+ (A+30"), "{en}");
}

/// The position display at the stop: REF where the machine stopped (the contact), not the last
/// finished block; IST in the plane still active then. TURN moves only the rotary axes and no
/// tilt is active yet, so the control leaves X, Y, Z where they were (3-axis behaviour).
#[test]
fn the_position_display_at_the_stop_shows_where_the_machine_stands() {
    let s = run_to_the_end(SEQ_MINUS_SWIVEL);
    let c = s.shown_collision().expect("the run stopped on a collision").clone();
    let before = s.shown_state().expect("the last finished step");
    let (axes, ist) = s.stop_position().expect("stands at the stop");
    assert_eq!(axes, c.axes, "REF at the contact");
    assert_ne!(axes, before.axes);
    assert_eq!(axes.linear, before.axes.linear, "TURN: the linear axes stand");
    assert!((ist - before.tip_ics).length() < 1e-9, "{ist} vs {}", before.tip_ics);
    // Before the stop the display shows the run's step itself.
    let mut running = then(&AppState::default(), Action::SelectMachine("ac-table".into()));
    running = then(&running, Action::SetText(program(SEQ_MINUS_SWIVEL)));
    running = then(&running, Action::StartRun);
    assert!(running.run.as_ref().is_some_and(|r| r.state.is_some()));
    assert!(running.shown_collision().is_none() && running.stop_position().is_none());
}

#[test]
fn a_collision_without_a_free_solution_has_no_ghost_and_no_note() {
    // A plain rotary move has no other solution.
    let s = run_to_the_end("PLANE AXIAL A-30 TURN FMAX");
    let c = s.shown_collision().expect("collision").clone();
    assert!(c.alternative.is_none());
    let machine = s.machine.clone().expect("machine");
    let before = s.shown_state().expect("state");
    let mut scene = SceneState { ghost: Some(Default::default()), ..SceneState::default() };
    scene.at_collision(&machine, &before, &c);
    assert!(scene.ghost.is_none() && scene.contact.is_some());
    let sim = s.sim.as_ref().map(|x| x.0.as_ref());
    let why = for_block(&s.doc.program, sim, Some(&before), s.cursor, &machine, Lang::De).expect("PLANE");
    assert!(why.error.is_some() && why.safe_alternative.is_none());
}

#[test]
fn before_the_run_reaches_the_collision_nothing_is_marked() {
    let mut s = then(&AppState::default(), Action::SelectMachine("ac-table".into()));
    s = then(&s, Action::SetText(program(SEQ_MINUS_SWIVEL)));
    assert!(s.shown_collision().is_none(), "programming: the run has not stopped");
    let s = then(&s, Action::StartRun);
    assert!(s.shown_collision().is_none(), "the run stands at its first block");
    // The free solution runs through.
    let s = run_to_the_end("PLANE SPATIAL SPA-30 SPB+0 SPC+0 TURN FMAX SEQ+");
    assert!(s.shown_collision().is_none());
}

/// The instructor's link "run at block 7", where block 7's swivel collides: the trainee sees the
/// stop (the contact, the control's message), not the program's start. Block 8 (never reached)
/// gives the same; block 6 the state after it.
#[test]
fn a_link_to_a_run_that_stops_on_the_way_opens_at_the_stop() {
    let open = |block: usize| {
        let shared = Shared {
            program: program(SEQ_MINUS_SWIVEL),
            block,
            machine: Some("ac-table".into()),
            own_machine: None,
            run: true,
            tools: None,
        };
        AppState::start(Stored::default(), Some(&format!("#{}", share_fragment(&shared)))).0
    };
    for block in [7, 8] {
        let s = open(block);
        let run = s.run.as_ref().expect("in program run");
        assert!(run.stopped_by_error && !run.playing, "block {block}");
        assert_eq!(s.cursor, 7, "block {block}: the cursor on the refused block");
        assert!(s.shown_collision().is_some(), "block {block}: the contact is shown");
        let line = s.dialog_line();
        assert!(line.starts_with("Kollision: "), "block {block}: {line}");
    }
    let before = open(6);
    let run = before.run.as_ref().expect("in program run");
    assert!(!run.stopped_by_error && before.cursor == 6 && before.shown_collision().is_none());
    assert_eq!(before.dialog_line(), "Programm aus dem Link geöffnet");
}

/// NC-START with the cursor on the block the control refuses stands there too.
#[test]
fn nc_start_on_the_refused_block_stands_at_the_stop() {
    let s = then(&AppState::default(), Action::SelectMachine("ac-table".into()));
    let s = then(&s, Action::SetText(program(SEQ_MINUS_SWIVEL)));
    let at = |cursor: usize| then(&then(&s, Action::CursorTo(cursor)), Action::StartRun);
    let refused = at(7);
    assert!(refused.run.as_ref().is_some_and(|r| r.stopped_by_error) && refused.cursor == 7);
    assert!(refused.shown_collision().is_some());
    assert!(refused.dialog_line().starts_with("Kollision: "), "{}", refused.dialog_line());
    // Before the refused block the run starts there, as before.
    let before = at(5);
    assert!(before.run.as_ref().is_some_and(|r| !r.stopped_by_error) && before.cursor == 5);
}
