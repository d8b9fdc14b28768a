//! Headless-Chromium tests of the course (issue 8): every lesson opens; every exercise accepts
//! its solution and an equivalent answer in another form and rejects the typical mistake with
//! its hint; the seed tables' rows on lesson 5's bench give the seed's results; the instructor
//! view, the presenter-remote keys and the progress.
#![cfg(target_arch = "wasm32")]

use schwenkbar_app::course::lessons::{self, COUNT};
use schwenkbar_core::course::{Answer, Exercise, Hint};
use schwenkbar_tests::browser::{
    clear_storage, click, eventually, key_on, mount, mount_at, query, settle, text, type_into, unmount,
    wait_for,
};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::Element;

wasm_bindgen_test_configure!(run_in_browser);

async fn verdict(root: &Element, n: usize) -> (String, String) {
    let found = wait_for(root, &format!("[data-testid=verdict-{n}]"), 3_000).await;
    let el = found.unwrap_or_else(|| {
        let page = query(root, "[data-testid=lesson]").and_then(|p| p.get_attribute("data-lesson"));
        let card = query(root, &format!("[data-testid=exercise-{n}]")).map(|c| c.inner_html());
        panic!("lesson {page:?}: no verdict {n}; card: {card:?}")
    });
    (el.get_attribute("data-verdict").unwrap_or_default(), el.text_content().unwrap_or_default())
}

async fn answer(root: &Element, n: usize, a: &Answer) {
    match a {
        Answer::Text(t) => {
            type_into(root, &format!("[data-testid=answer-{n}]"), t).await;
            click(root, &format!("[data-testid=check-{n}]")).await;
        }
        Answer::ControlError => click(root, &format!("[data-testid=refuse-{n}]")).await,
    }
}

#[wasm_bindgen_test]
async fn every_lesson_opens_and_its_exercises_accept_right_and_equivalent_answers_and_reject_wrong_ones() {
    clear_storage();
    for i in 0..COUNT {
        let root = mount_at(&format!("#kurs/{}", i + 1)).await;
        let page = wait_for(&root, "[data-testid=lesson]", 5_000).await.expect("the lesson page");
        assert_eq!(page.get_attribute("data-lesson"), Some((i + 1).to_string()));
        assert!(text(&root, "[data-testid=lesson-title]").starts_with(&format!("{}. ", i + 1)));
        assert!(
            query(&root, "[data-testid=course-notice]").is_none(),
            "lesson {} opens without a message",
            i + 1
        );
        let lesson = lessons::lesson(i).expect("lesson");
        for (n, &spec) in lesson.exercises.iter().enumerate() {
            let ex = Exercise::generate(spec, 0);
            assert_eq!(text(&root, &format!("[data-testid=prompt-{n}]")), ex.prompt.de);
            for good in [&ex.solution.de, &ex.equivalent.de] {
                answer(&root, n, &Answer::typed(good)).await;
                assert_eq!(verdict(&root, n).await.0, "correct", "lesson {} exercise {n}: {good}", i + 1);
            }
            let (wrong, hint) = &ex.typical_mistake;
            answer(&root, n, wrong).await;
            let (class, message) = verdict(&root, n).await;
            assert_eq!(class, "wrong", "lesson {} exercise {n}: {wrong:?}", i + 1);
            if *hint == Hint::RightHand {
                assert!(message.contains("Rechte-Hand-Regel"), "{message}");
            }
            // What was typed stays for correction.
            if let Answer::Text(t) = wrong {
                let input = query(&root, &format!("[data-testid=answer-{n}]")).expect("input");
                assert_eq!(
                    input.dyn_ref::<web_sys::HtmlInputElement>().map(|i| i.value()).as_deref(),
                    Some(t.as_str())
                );
            }
        }
        unmount(&root);
    }
}

use wasm_bindgen::JsCast;

#[wasm_bindgen_test]
async fn seed_table_rows_on_the_lesson_5_bench_give_the_seed_results() {
    clear_storage();
    let root = mount_at("#kurs/5").await;
    wait_for(&root, "[data-testid=solve-lab]", 5_000).await.expect("the bench");
    // DOMAIN.md oracles 13–27.
    let expected: [(u8, Option<&str>); 15] = [
        (13, Some("A+45 C+90")),
        (14, Some("A+45 C+90")),
        (15, Some("A-45 C-90")),
        (16, Some("A-45 C-90")),
        (17, Some("A+45 C+90")),
        (18, Some("A-45 C-90")),
        (19, Some("A-45 C-90")),
        (20, None),
        (21, Some("A-45 C-90")),
        (22, Some("A+45 C+90")),
        (23, Some("A-45 B+0")),
        (24, None),
        (25, None),
        (26, Some("A-45 B+0")),
        (27, Some("A-45 B+0")),
    ];
    for (row, want) in expected {
        click(&root, &format!("[data-testid=seed-row-{row}]")).await;
        let chosen = text(&root, "[data-testid=lab-result] .chosen");
        match want {
            Some(axes) => assert!(chosen.starts_with(axes), "row {row}: {chosen:?}"),
            None => {
                assert_eq!(chosen, "", "row {row}");
                assert_eq!(text(&root, "[data-testid=lab-error]"), "Winkel nicht erlaubt", "row {row}");
            }
        }
    }
    unmount(&root);
}

/// The seed row button whose text starts with `name` (the row's name, not its number).
fn seed_button(root: &Element, name: &str) -> web_sys::HtmlElement {
    let buttons = root.query_selector_all("[data-testid=seed-rows] button").expect("selector");
    (0..buttons.length())
        .filter_map(|i| buttons.item(i)?.dyn_into::<web_sys::HtmlElement>().ok())
        .find(|b| b.text_content().is_some_and(|t| t.starts_with(name)))
        .unwrap_or_else(|| panic!("no seed row button named {name:?}"))
}

/// The gauge's candidates as (word, chosen, beyond a limit switch).
fn gauge_candidates(root: &Element) -> Vec<(String, bool, bool)> {
    let marks = root.query_selector_all("[data-testid=gauge-candidate]").expect("selector");
    (0..marks.length())
        .filter_map(|i| marks.item(i)?.dyn_into::<Element>().ok())
        .map(|m| {
            let attr = |n: &str| m.get_attribute(n).unwrap_or_default();
            (attr("data-word"), attr("data-chosen") == "true", attr("data-out") == "true")
        })
        .collect()
}

#[wasm_bindgen_test]
async fn the_lesson_5_bench_shows_the_machine_in_3d_the_master_axis_gauge_and_named_rows() {
    use schwenkbar_app::course::bench::row_name;
    use schwenkbar_core::course::seed_rows;
    clear_storage();
    let root = mount_at("#kurs/5").await;
    wait_for(&root, "[data-testid=solve-lab]", 5_000).await.expect("the bench");
    // The 3D view (or its plain no-WebGL message) and the gauge for the default set-up.
    assert!(query(&root, "[data-testid=bench-view] .view-pane").is_some(), "the 3D view");
    assert!(query(&root, "[data-testid=gauge] svg").is_some(), "the gauge");
    assert_eq!(gauge_candidates(&root).len(), 2, "both candidates on the gauge");
    // The rows are named by what they show; the number is only a small label.
    let rows = seed_rows();
    let row = |n: u8| rows.iter().find(|r| r.number == n).expect("row");
    let name = row_name(row(21), schwenkbar_core::Lang::De);
    assert!(name.starts_with("SYM-"), "{name}");
    let button = seed_button(&root, &name);
    assert_eq!(button.get_attribute("data-testid").as_deref(), Some("seed-row-21"));
    button.click();
    settle().await;
    assert!(text(&root, "[data-testid=lab-result] .chosen").starts_with("A-45 C-90"));
    assert_eq!(
        gauge_candidates(&root),
        [("A+45".to_owned(), false, true), ("A-45".to_owned(), true, false)],
        "SYM- with −90 < A < +10: A-45 chosen, A+45 beyond the limit switch"
    );
    let limits = root.query_selector_all("[data-testid=gauge-limit]").expect("selector");
    assert_eq!(limits.length(), 2, "both limit switches on the gauge");
    assert!(text(&root, "[data-testid=gauge] figcaption").contains("A-90 … A+10"));
    assert_eq!(
        query(&root, "[data-testid=seed-row-21]").and_then(|b| b.get_attribute("aria-pressed")).as_deref(),
        Some("true")
    );
    assert!(
        text(&root, "[data-testid=bench-view-caption]").contains("A+45 C+90"),
        "the other one as the ghost"
    );
    // A refused row: no candidate chosen, the machine stays at the start position and says so.
    seed_button(&root, &row_name(row(20), schwenkbar_core::Lang::De)).click();
    settle().await;
    assert!(gauge_candidates(&root).iter().all(|c| !c.1), "nothing chosen");
    assert!(text(&root, "[data-testid=bench-view-caption]").contains("Startstellung A+0 C+0"));
    assert_eq!(
        query(&root, "[data-testid=bench-view]").and_then(|v| v.get_attribute("data-solved")).as_deref(),
        Some("false")
    );
    // A letter in a field: the form's message, the view stays.
    let input: web_sys::HtmlInputElement =
        query(&root, "[data-testid=lab-start-1]").expect("start field").dyn_into().expect("input");
    input.set_value("x");
    input.dispatch_event(&web_sys::Event::new("change").expect("event")).expect("dispatch");
    settle().await;
    assert!(text(&root, "[data-testid=lab-error]").contains("nicht lesbar"));
    assert!(query(&root, "[data-testid=bench-view] .view-pane").is_some());
    // Q parameters: nothing to compute yet; the view says the machine stands at the start.
    for (field, value) in [("lab-start-1", "0"), ("lab-block", "PLANE SPATIAL SPA+Q1 SPB+45 SPC+0 TURN FMAX")]
    {
        let input: web_sys::HtmlInputElement =
            query(&root, &format!("[data-testid={field}]")).expect("field").dyn_into().expect("input");
        input.set_value(value);
        input.dispatch_event(&web_sys::Event::new("change").expect("event")).expect("dispatch");
        settle().await;
    }
    assert!(
        text(&root, "[data-testid=lab-error]").contains("Q-Parameter"),
        "{}",
        text(&root, "[data-testid=lab-error]")
    );
    assert!(text(&root, "[data-testid=bench-view-caption]").contains("Keine Achsstellung berechnet"));
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

#[wasm_bindgen_test]
async fn instructor_view_keys_of_a_presenter_remote_and_solution_only_on_request() {
    clear_storage();
    let root = mount_at("#kurs/2").await;
    wait_for(&root, "[data-lesson='2']", 5_000).await.expect("lesson 2");
    // A trainee gets the solution button only after trying.
    assert!(query(&root, "[data-testid=solution-button-0]").is_none());
    key_on(&root, "[data-testid=course]", "i").await;
    assert!(
        wait_for(&root, ".course.projector", 3_000).await.is_some(),
        "the instructor view enlarges for the projector"
    );
    assert!(query(&root, "[data-testid=solution-0]").is_none(), "the solution is held back");
    click(&root, "[data-testid=solution-button-0]").await;
    assert!(text(&root, "[data-testid=solution-0]").contains("PLANE SPATIAL"));
    key_on(&root, "[data-testid=course]", "PageDown").await;
    assert!(wait_for(&root, "[data-lesson='3']", 3_000).await.is_some(), "PageDown: next lesson");
    key_on(&root, "[data-testid=course]", "ArrowRight").await;
    assert!(wait_for(&root, "[data-lesson='4']", 3_000).await.is_some(), "→: next lesson");
    key_on(&root, "[data-testid=course]", "PageUp").await;
    assert!(wait_for(&root, "[data-lesson='3']", 3_000).await.is_some(), "PageUp: previous lesson");
    key_on(&root, "[data-testid=course]", "Home").await;
    assert!(wait_for(&root, "[data-testid=course-overview]", 3_000).await.is_some());
    unmount(&root);
    // Leave the fragment so later tests in this binary start in the trainer.
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

#[wasm_bindgen_test]
async fn progress_is_kept_and_a_corrupt_record_is_reported() {
    clear_storage();
    let root = mount_at("#kurs/1").await;
    wait_for(&root, "[data-lesson='1']", 5_000).await.expect("lesson 1");
    let ex = Exercise::generate(lessons::lesson(0).expect("lesson").exercises[0], 0);
    answer(&root, 0, &Answer::Text(ex.solution.de.to_string())).await;
    assert_eq!(verdict(&root, 0).await.0, "correct");
    // Kept by the effect after the render with the verdict: waited for, not assumed (it failed
    // once with the release bundle built beside the tests).
    let kept = || {
        web_sys::window()
            .and_then(|w| w.local_storage().ok().flatten())
            .and_then(|s| s.get_item(schwenkbar_app::persist::COURSE_KEY).ok().flatten())
            .is_some()
    };
    assert!(eventually(kept).await, "the progress kept");
    unmount(&root);
    let root = mount_at("#kurs").await;
    let status = wait_for(&root, "[data-testid=lesson-status-1]", 3_000).await.expect("overview");
    assert_eq!(status.text_content().as_deref(), Some("1/2 gelöst"));
    unmount(&root);
    web_sys::window()
        .and_then(|w| w.local_storage().ok().flatten())
        .expect("storage")
        .set_item("schwenkbar.kurs", "{kaputt")
        .expect("set");
    let root = mount_at("#kurs").await;
    assert!(text(&root, "[data-testid=course-notice]").contains("zurückgesetzt"));
    assert!(query(&root, "[data-testid=lesson-link-11]").is_some(), "the course works on");
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

#[wasm_bindgen_test]
async fn the_trainer_links_to_the_course() {
    clear_storage();
    let root = mount().await;
    let link = query(&root, "[data-testid=course-link]").expect("course link");
    assert_eq!(link.get_attribute("href").as_deref(), Some("kurs.html"));
    unmount(&root);
}

#[wasm_bindgen_test]
async fn lesson_2_try_it_hides_the_signed_angle_and_the_block_until_checked() {
    clear_storage();
    let root = mount_at("#kurs/2").await;
    wait_for(&root, ".right-hand", 5_000).await.expect("the right-hand demo");
    assert!(query(&root, ".rh-block").is_some(), "free play shows the block");
    click(&root, ".rh-start").await;
    assert!(query(&root, ".rh-task").is_some());
    assert!(query(&root, ".rh-block").is_none(), "the block would give the sign away");
    let angle = query(&root, ".rh-angle").expect("the angle readout");
    assert_eq!(angle.get_attribute("data-hidden").as_deref(), Some("true"));
    assert!(angle.get_attribute("data-angle").is_none());
    click(&root, ".rh-check").await;
    assert!(query(&root, ".rh-verdict").is_some());
    assert!(text(&root, ".rh-block").starts_with("PLANE SPATIAL"), "shown after Prüfen");
    assert!(query(&root, ".rh-angle[data-angle]").is_some());
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

/// The solver's other solution of the exercise program's block `number` from A+0 C+0.
fn other_solution(ex: &Exercise, number: u32) -> schwenkbar_core::axes::AxisValues {
    use schwenkbar_core::plane::Value;
    let (text, machine) = ex.program.clone().expect("a program");
    let (program, _) = schwenkbar_core::parse(&text);
    let block = program
        .blocks
        .iter()
        .find(|b| b.number() == Some(number))
        .and_then(|b| match b.stored_body()? {
            schwenkbar_core::BlockBody::Plane(p) => p
                .try_map(|v| match v {
                    Value::Number(x) => Ok(*x),
                    Value::Param { .. } => Err(()),
                })
                .ok(),
            _ => None,
        })
        .expect("a PLANE block");
    let machine = schwenkbar_core::machine::Machine::builtin(machine).expect("machine");
    let e = schwenkbar_core::solve::solve_block(
        &machine,
        &block,
        glam::DMat3::IDENTITY,
        &schwenkbar_core::solve::SolveOptions::default(),
    )
    .expect("solvable");
    let chosen = e.chosen.expect("a choice");
    e.candidates.iter().enumerate().find(|(i, _)| *i != chosen).map(|(_, c)| c.axes).expect("two solutions")
}

#[wasm_bindgen_test]
async fn the_other_solution_in_lessons_4_8_and_9_gets_its_own_hint_and_lesson_5_refuses_in_english() {
    use schwenkbar_core::course::{RunKind, Spec};
    use schwenkbar_core::plane::RotaryAxis;
    clear_storage();
    // Lesson 4 exercise 1 (TURN), lesson 8 exercise 1 (Musterprogramm 1 block 10), lesson 9
    // exercise 2 (TURN): the axis A at the solver's other solution.
    for (lesson, n, kind, block) in
        [(4, 0, RunKind::Turn, 6), (8, 0, RunKind::Musterprogramm1, 10), (9, 1, RunKind::Turn, 6)]
    {
        let root = mount_at(&format!("#kurs/{lesson}")).await;
        wait_for(&root, &format!("[data-lesson='{lesson}']"), 5_000).await.expect("the lesson");
        let ex = Exercise::generate(Spec::Run(kind), 0);
        let a = other_solution(&ex, block).get(RotaryAxis::A).expect("A");
        answer(&root, n, &Answer::Text(schwenkbar_core::solve::fmt_deg(a))).await;
        let (class, message) = verdict(&root, n).await;
        assert_eq!(class, "wrong", "lesson {lesson}");
        assert!(message.contains("andere Lösung derselben Lage"), "lesson {lesson}: {message}");
        assert!(!message.contains("Rechte-Hand-Regel"), "lesson {lesson}: {message}");
        unmount(&root);
    }
    // Lesson 5 exercise 3: the control refuses; the English view shows the English message.
    let root = mount_at("#kurs/5").await;
    wait_for(&root, "[data-lesson='5']", 5_000).await.expect("lesson 5");
    click(&root, "[data-testid=course-lang]").await;
    click(&root, "[data-testid=refuse-2]").await;
    assert_eq!(verdict(&root, 2).await.0, "correct");
    click(&root, "[data-testid=solution-button-2]").await;
    let shown = text(&root, "[data-testid=solution-2]");
    assert!(shown.contains("Entered angle not permitted") && !shown.contains("Winkel"), "{shown}");
    click(&root, "[data-testid=course-lang]").await;
    unmount(&root);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
}

/// Language and the classroom projector are one setting of both pages: chosen in the course,
/// the trainer opens the same way.
#[wasm_bindgen_test]
async fn the_language_and_instructor_view_chosen_in_the_course_are_the_trainers_too() {
    clear_storage();
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    let course = mount_at("#kurs").await;
    click(&course, "[data-testid=course-lang]").await;
    click(&course, "[data-testid=instructor]").await;
    let page = query(&course, "[data-testid=course]").expect("course page");
    assert_eq!(page.get_attribute("lang").as_deref(), Some("en"));
    unmount(&course);
    web_sys::window().expect("window").location().set_hash("").expect("hash");
    settle().await;
    let trainer = mount().await;
    let tnc = query(&trainer, ".tnc").expect("trainer");
    assert_eq!(tnc.get_attribute("lang").as_deref(), Some("en"), "the course's language");
    let class = tnc.get_attribute("class").unwrap_or_default();
    assert!(class.split(' ').any(|c| c == "projector"), "the instructor view is the projector mode: {class}");
    unmount(&trainer);
    clear_storage();
}
