//! Issue 16: a text edit parsed again only where it changed, and the run resumed from a
//! checkpoint, give exactly what parsing and simulating the new text from scratch gives.

use std::sync::Arc;

use proptest::prelude::*;
use schwenkbar_app::document::Document;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, Simulation, simulate};

/// Programs with cycles and their `~` lines, labels, calls and jumps, contours with RND/CHF and
/// radius compensation (look-ahead), a missing END PGM, blank and unnumbered lines, comments
/// wrapped with `~` and written against their number (`2;…`).
const PROGRAMS: [&str; 7] = [
    include_str!("../../tests/fixtures/sim/contour_rl.h"),
    include_str!("../../tests/fixtures/sim/cycle_calls.h"),
    include_str!("../../tests/fixtures/sim/fn_jump_loop.h"),
    include_str!("../../tests/fixtures/sim/call_lbl.h"),
    include_str!("../../static/programs/musterprogramm1.h"),
    "0 BEGIN PGM K MM\n\n1 TOOL CALL 1 Z S1000\nL X+0 Y+0 R0 FMAX\n2 CYCL DEF 200 BOHREN ~\n\n  Q200=+2 ~\n3 L X+10 RND R2\n",
    "0 BEGIN PGM W MM\n1 ;a comment~\n  wrapped over~\n  three lines\n2;against its number\n3 L X+1 R0 FMAX ;a move~\n there\n4 END PGM W MM\n",
];

/// What is typed or pasted: parts of blocks, line breaks, `~`, numbers, labels, corners, junk.
const PIECES: [&str; 19] = [
    "",
    "\n",
    "~",
    " ~\n",
    "  Q201=-5 ;TIEFE",
    "1",
    "9 ",
    "/",
    "LBL 1\n",
    "CALL LBL 1 REP 2\n",
    "RND R3\n",
    "CHF 2\n",
    "L X+5 Y+5 RL F100\n",
    "Ü",
    "\r\n",
    ";x",
    "5;",
    "END PGM K MM\n",
    "7 FN 12: IF +Q1 LT +3 GOTO LBL 1\n",
];

/// A run bounded far below the default budget: an edit can make an endless loop (`LBL 1` and
/// `FN 12: … GOTO LBL 1` are among the pieces), which then stops here with the same error in the
/// fresh run and the resumed one instead of running to a million blocks with a checkpoint each.
fn bounded(interval: usize) -> SimOptions {
    SimOptions { checkpoint_interval: interval, max_steps: Some(5_000), ..SimOptions::default() }
}

fn edit(text: &str, at: usize, cut: usize, piece: &str) -> String {
    let mut at = at % (text.len() + 1);
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let mut end = (at + cut).min(text.len());
    while !text.is_char_boundary(end) {
        end += 1;
    }
    format!("{}{piece}{}", &text[..at], &text[end..])
}

fn assert_same(got: &Document, want: &Document) {
    assert_eq!(got.text, want.text);
    assert_eq!(got.program, want.program);
    let place =
        |d: &Document| d.program.blocks.iter().map(|b| (b.span(), b.line(), b.column())).collect::<Vec<_>>();
    assert_eq!(place(got), place(want), "spans and lines");
    assert_eq!(got.diagnostics, want.diagnostics);
    assert_eq!(got.line_count(), want.line_count());
    for i in 0..=want.line_count() {
        assert_eq!(got.line(i), want.line(i));
        assert_eq!(got.block_at_line(i), want.block_at_line(i));
    }
    for b in 0..want.program.blocks.len() {
        assert_eq!(got.block_lines(b), want.block_lines(b));
    }
}

/// The blocks outside `changed` are the old ones: the same before it, the old last ones after
/// it (moved in the text).
fn assert_kept(old: &Document, new: &Document, changed: &std::ops::Range<usize>) {
    let (old, new) = (&old.program.blocks, &new.program.blocks);
    assert!(changed.start <= changed.end && changed.end <= new.len());
    assert!(new[..changed.start] == old[..changed.start]);
    let tail = new.len() - changed.end;
    assert!(tail <= old.len());
    for (a, b) in new[changed.end..].iter().zip(&old[old.len() - tail..]) {
        assert_eq!(a.body(), b.body());
    }
}

fn assert_same_run(got: &Simulation, want: &Simulation, doc: &Document) {
    assert_eq!(got.records, want.records);
    assert_eq!(got.first_step, want.first_step);
    assert_eq!(got.error, want.error);
    let states = |s: &Simulation| s.states(&doc.program).collect::<Vec<_>>();
    assert_eq!(states(got), states(want));
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(400))]

    #[test]
    fn an_edit_parsed_and_run_again_in_part_equals_a_fresh_parse_and_run(
        program in 0..PROGRAMS.len(),
        edits in prop::collection::vec((any::<usize>(), 0usize..40, 0..PIECES.len()), 1..4),
        interval in 1usize..6,
    ) {
        let machine = Machine::builtin("ac-table").expect("shipped");
        let options = bounded(interval);
        let mut doc = Document::new(PROGRAMS[program].to_owned());
        let mut sim = Arc::new(simulate(&doc.program, &machine, &options));
        for (at, cut, piece) in edits {
            let text = edit(&doc.text, at, cut, PIECES[piece]);
            let (next, changed) = doc.edited(text.clone());
            let fresh = Document::new(text);
            assert_same(&next, &fresh);
            assert_kept(&doc, &next, &changed);
            let resumed = sim.resumed(&next.program, changed);
            assert_same_run(&resumed, &simulate(&fresh.program, &machine, &options), &fresh);
            (doc, sim) = (next, Arc::new(resumed));
        }
    }
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(300))]

    /// Typing breaks a block and the next keys heal it: edits, then the same edits undone one by
    /// one, each run resumed (joining an earlier run, also the one before the run stopped at a
    /// broken block) equal to a fresh parse and run.
    #[test]
    fn edits_undone_one_by_one_resume_to_a_fresh_parse_and_run(
        program in 0..PROGRAMS.len(),
        edits in prop::collection::vec((any::<usize>(), 0usize..8, 0..PIECES.len()), 1..4),
        interval in 1usize..6,
    ) {
        let machine = Machine::builtin("ac-table").expect("shipped");
        let options = bounded(interval);
        let mut doc = Document::new(PROGRAMS[program].to_owned());
        let mut sim = Arc::new(simulate(&doc.program, &machine, &options));
        let mut texts = vec![doc.text.clone()];
        for (at, cut, piece) in edits {
            texts.push(edit(&doc.text, at, cut, PIECES[piece]));
        }
        let back: Vec<String> = texts.iter().rev().skip(1).cloned().collect();
        for text in texts.into_iter().skip(1).chain(back) {
            let (next, changed) = doc.edited(text.clone());
            let fresh = Document::new(text);
            assert_kept(&doc, &next, &changed);
            let resumed = sim.resumed(&next.program, changed);
            assert_same_run(&resumed, &simulate(&fresh.program, &machine, &options), &fresh);
            (doc, sim) = (next, Arc::new(resumed));
        }
    }
}

#[test]
fn emptied_and_refilled_text_and_an_edit_at_either_end() {
    let machine = Machine::builtin("ac-table").expect("shipped");
    let options = bounded(2);
    let mut doc = Document::new(PROGRAMS[0].to_owned());
    let mut sim = Arc::new(simulate(&doc.program, &machine, &options));
    for text in
        ["", PROGRAMS[1], &PROGRAMS[1].replace("0 BEGIN", "BEGIN"), &format!("{}21 L X+1\n", PROGRAMS[1])]
    {
        let (next, changed) = doc.edited(text.to_owned());
        let fresh = Document::new(text.to_owned());
        assert_same(&next, &fresh);
        assert_kept(&doc, &next, &changed);
        let resumed = sim.resumed(&next.program, changed);
        assert_same_run(&resumed, &simulate(&fresh.program, &machine, &options), &fresh);
        (doc, sim) = (next, Arc::new(resumed));
    }
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(300))]

    /// What the text editor does (issue 16): a window of the text typed in and put back in
    /// place is the same document as the whole text edited the same way.
    #[test]
    fn an_edit_in_the_window_equals_the_same_edit_of_the_whole_text(
        program in 0..PROGRAMS.len(),
        window in (any::<usize>(), any::<usize>()),
        edits in prop::collection::vec((any::<usize>(), 0usize..40, 0..PIECES.len()), 1..4),
    ) {
        let mut doc = Document::new(PROGRAMS[program].to_owned());
        for (at, cut, piece) in edits {
            // Any window of whole lines, as the editor's are.
            let lines = doc.line_count() + 1;
            let (a, b) = (window.0 % lines, window.1 % lines);
            let starts: Vec<usize> = (0..=lines).map(|l| doc.text.match_indices('\n').take(l).last().map_or(0, |(i, _)| i + 1)).collect();
            let w = starts[a.min(b)]..if a.max(b) + 1 >= lines { doc.text.len() } else { starts[a.max(b) + 1] };
            let typed = edit(&doc.text[w.clone()], at, cut, PIECES[piece]);
            let whole = format!("{}{typed}{}", &doc.text[..w.start], &doc.text[w.end..]);
            let (next, changed) = doc.replaced(w, &typed).expect("a window of the text");
            assert_same(&next, &Document::new(whole));
            assert_kept(&doc, &next, &changed);
            doc = next;
        }
    }
}

#[test]
fn a_window_that_is_not_in_the_text_is_refused() {
    let doc = Document::new("0 BEGIN PGM Ü MM\n".to_owned());
    assert!(doc.replaced(0..99, "x").is_none());
    assert!(doc.replaced(13..14, "x").is_none(), "not a char boundary");
}

/// Every one-character edit of the program with wrapped comments and a comment against its
/// number (a character cut, a `~`, a line break or a blank put in at each place): the spliced
/// document equals a fresh parse of the text.
#[test]
fn every_small_edit_of_wrapped_comments_equals_a_fresh_parse() {
    let text = PROGRAMS[6];
    let doc = Document::new(text.to_owned());
    for at in 0..=text.len() {
        for (cut, piece) in [(1, ""), (0, "~"), (0, "\n"), (0, " ")] {
            let t = edit(text, at, cut, piece);
            let (next, _) = doc.edited(t.clone());
            assert_same(&next, &Document::new(t));
        }
    }
}

/// Every one-character edit of a program whose transfer ended with ETX and SUB lines (a
/// character cut, an ETX or a line break put in at each place): the spliced document equals a
/// fresh parse, the transfer marks' warnings included (each is said on its own line).
#[test]
fn every_small_edit_around_transfer_marks_equals_a_fresh_parse() {
    let text = "0 BEGIN PGM T MM\n1 L X+1 R0 FMAX\n\u{3}\n2 L Y+2\n3 END PGM T MM\n\u{3}\n\u{1a}\n";
    let doc = Document::new(text.to_owned());
    let marks =
        doc.diagnostics.iter().filter(|d| d.code == schwenkbar_core::diag::DiagCode::TransferMark).count();
    assert_eq!(marks, 3, "{:?}", doc.diagnostics);
    for at in 0..=text.len() {
        for (cut, piece) in [(1, ""), (0, "\u{3}"), (0, "\n")] {
            let t = edit(text, at, cut, piece);
            let (next, _) = doc.edited(t.clone());
            assert_same(&next, &Document::new(t));
        }
    }
}
