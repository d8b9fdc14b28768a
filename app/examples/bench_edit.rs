//! A keystroke in the text editor of a 100,000-block program, natively and stage by stage
//! (issue 16's budget "typing updates in ≤ 50 ms" is the browser's; this shows where the time
//! goes): the edit of the document (`Document::replaced`), the resumed run
//! (`Simulation::resumed`) and the whole `AppState::apply` of `Action::EditText`.
//! Run: `scripts/bench.sh` or `cargo run --release -p schwenkbar-app --example bench_edit`.

use std::rc::Rc;
use std::sync::Arc;
use std::time::Instant;

use schwenkbar_app::document::Document;
use schwenkbar_app::effect::Reducer;
use schwenkbar_app::state::{Action, AppState};
use schwenkbar_core::sample;

/// The median of `runs` timings of `f`, ms.
fn median_ms(runs: usize, mut f: impl FnMut(usize)) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|i| {
            let t0 = Instant::now();
            f(i);
            t0.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn main() {
    let blocks = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(100_000usize);
    let text = sample::cam_program(blocks);
    let t0 = Instant::now();
    let doc = Document::new(text);
    println!("Document::new: {:.1} ms", t0.elapsed().as_secs_f64() * 1e3);
    // The editor's window around the middle line; a character typed at its start and deleted.
    let line = doc.line_count() / 2;
    let window = doc.window_at(line);
    let at = doc.line_start(line) - window.start;
    let old = doc.text[window.clone()].to_owned();
    let typed = format!("{}Ü{}", &old[..at], &old[at..]);
    let texts = [typed.as_str(), old.as_str()];
    let state = AppState { doc: Rc::new(doc), ..AppState::default() };
    let state = state.apply(Action::SetText(state.doc.text.clone())).0;
    let doc = state.doc.clone();
    let sim = state.sim.clone().expect("a machine");
    let replaced = median_ms(20, |_| {
        let _ = doc.replaced(window.clone(), texts[0]);
    });
    let (next, changed) = doc.replaced(window.clone(), texts[0]).expect("a window of the text");
    let broken = Arc::new(sim.0.resumed(&next.program, changed.clone()));
    let resumed = median_ms(20, |_| {
        let _ = sim.0.resumed(&next.program, changed.clone());
    });
    // Deleting it again heals the block: the run goes on from there to the end.
    let (healed, same) = next.replaced(window.start..window.start + typed.len(), &old).expect("the window");
    let resumed_healed = median_ms(20, |_| {
        let _ = broken.resumed(&healed.program, same.clone());
    });
    let mut s = state.clone();
    let mut w = window.clone();
    let apply = median_ms(20, |i| {
        let text = texts[i % 2];
        s = s.apply(Action::EditText { at: w.clone(), text: text.to_owned() }).0;
        w = w.start..w.start + text.len();
    });
    // What the views make of it: the 3D view's state at the cursor block, and a part of the
    // toolpath (one checkpoint interval of states, as `web/src/components/scene_pane.rs` makes it).
    let shown = median_ms(20, |_| {
        let _ = s.shown_state();
    });
    let sim = s.sim.clone().expect("a machine");
    let path = median_ms(5, |_| {
        let _ = sim.0.states_from(&s.doc.program, 0).take(sim.0.options.checkpoint_interval).count();
    });
    println!(
        "keystroke in {blocks} blocks (median of 20): Document::replaced {replaced:.2} ms, Simulation::resumed {resumed:.2} ms (broken) {resumed_healed:.2} ms (healed), AppState::apply(EditText) {apply:.2} ms; views: shown_state {shown:.2} ms, a part of the toolpath {path:.2} ms"
    );
}
