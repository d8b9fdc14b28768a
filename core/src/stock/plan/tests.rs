//! The merge of short cuts on one line ([`Cutting::push_event`]), step by step as `plan_on`
//! pushes them.

use glam::DVec3;

use super::{Action, Cutting, Event, MERGE_STEPS, Motion, StockOptions};

/// A cutting that has planned nothing, at 0.25 mm (merged cuts at most 0.125 mm long, their points
/// within 0.0039 mm of the chord).
fn cutting() -> Cutting {
    let mut c = Cutting::unplanned(StockOptions { resolution: 0.25, checkpoints: 0 });
    c.step_events.clear();
    c
}

/// Step `step` of a plan: one cut from `from` to `to`.
fn step(c: &mut Cutting, step: usize, from: [f64; 3], to: [f64; 3], motion: Motion, axis: DVec3) {
    c.step_events.push(c.events.len());
    let (from, to) = (DVec3::from_array(from), DVec3::from_array(to));
    c.push_event(Event {
        step,
        block: step,
        end: 1.0,
        action: Action::Cut { cutter: 0, axis, from, to, motion },
    });
}

fn cut(c: &Cutting, k: usize) -> (DVec3, DVec3) {
    match c.events[k].action {
        Action::Cut { from, to, .. } => (from, to),
        Action::Blank(_) => panic!("event {k} is a blank"),
    }
}

#[test]
fn short_cuts_on_a_line_merge_into_the_last_steps_cut_up_to_half_the_resolution() {
    let mut c = cutting();
    // Five moves of 0.03 mm along X: four make 0.12 mm (≤ 0.125), the fifth starts a new cut.
    for k in 0..5 {
        let x = 0.03 * k as f64;
        step(&mut c, k, [x, 0.0, 0.0], [x + 0.03, 0.0, 0.0], Motion::Cut, DVec3::Z);
    }
    assert_eq!(c.events.len(), 2);
    assert_eq!(cut(&c, 0), (DVec3::ZERO, DVec3::new(0.12, 0.0, 0.0)));
    assert_eq!(c.events[0].step, 3, "the merged cut belongs to its last piece's step");
    // Steps 0…3 start where the merged cut is: their stock lags until step 3 is done.
    assert_eq!(c.step_events, [0, 0, 0, 0, 1]);
}

#[test]
fn a_corner_another_axis_or_a_rapid_never_merges() {
    let mut c = cutting();
    step(&mut c, 0, [0.0; 3], [0.03, 0.0, 0.0], Motion::Cut, DVec3::Z);
    // 90° turn: the corner is 0.021 mm off the chord (more than 1/64 of the resolution).
    step(&mut c, 1, [0.03, 0.0, 0.0], [0.03, 0.03, 0.0], Motion::Cut, DVec3::Z);
    assert_eq!(c.events.len(), 2);
    // A slight bend within the deviation merges: 0.003 mm off the line.
    step(&mut c, 2, [0.03, 0.03, 0.0], [0.033, 0.06, 0.0], Motion::Cut, DVec3::Z);
    assert_eq!(c.events.len(), 2);
    let tilted = DVec3::new(0.0, 0.6, 0.8);
    step(&mut c, 3, [0.033, 0.06, 0.0], [0.033, 0.09, 0.0], Motion::Cut, tilted);
    step(&mut c, 4, [0.033, 0.09, 0.0], [0.033, 0.12, 0.0], Motion::Rapid, tilted);
    step(&mut c, 5, [0.033, 0.12, 0.0], [0.033, 0.15, 0.0], Motion::Cut, tilted);
    // A gap between two cuts (the next starts elsewhere) is not bridged.
    step(&mut c, 6, [0.033, 0.16, 0.0], [0.033, 0.18, 0.0], Motion::Cut, tilted);
    assert_eq!(c.events.len(), 6);
}

#[test]
fn no_merge_crosses_a_multiple_of_merge_steps() {
    let mut c = cutting();
    let first = MERGE_STEPS - 1;
    for k in 0..3 {
        let x = 0.01 * k as f64;
        step(&mut c, first + k, [x, 0.0, 0.0], [x + 0.01, 0.0, 0.0], Motion::Cut, DVec3::Z);
    }
    assert_eq!(c.events.len(), 2, "step {first} alone, steps {MERGE_STEPS} and after merged");
    assert_eq!(cut(&c, 1), (DVec3::new(0.01, 0.0, 0.0), DVec3::new(0.03, 0.0, 0.0)));
}
