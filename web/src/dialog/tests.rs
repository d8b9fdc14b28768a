//! The dialog, key by key, against the blocks the control would write.

use schwenkbar_core::plane::PlaneDef;

use super::*;

/// Types `text` and presses ENT.
fn enter(d: &mut Dialog, text: &str) -> Outcome {
    for c in text.chars() {
        d.key(Key::Char(c));
    }
    d.key(Key::Ent)
}

fn finished(o: Outcome) -> String {
    match o {
        Outcome::Finished(text) => text,
        Outcome::Continue => panic!("dialog not finished"),
    }
}

/// SPATIAL with the given angles up to the positioning softkeys.
fn spatial(a: &str, b: &str, c: &str) -> Dialog {
    let mut d = Dialog::new(Function::Spatial);
    for v in [a, b, c] {
        assert_eq!(enter(&mut d, v), Outcome::Continue);
        assert_eq!(d.message, None, "{v}");
    }
    assert_eq!(d.step, Step::Positioning);
    d
}

#[test]
fn spatial_turn_fmax_as_in_musterprogramm_1() {
    let mut d = spatial("0", "15", "0");
    d.key(Key::Positioning(PosKind::Turn));
    assert_eq!(d.step, Step::MoveBack);
    d.key(Key::NoEnt);
    assert_eq!(d.step, Step::Feed);
    d.key(Key::FMax);
    assert_eq!(d.step, Step::Selection);
    d.key(Key::NoEnt);
    assert_eq!(d.step, Step::Transform);
    assert_eq!(finished(d.key(Key::NoEnt)), "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX");
}

#[test]
fn spatial_variants_move_dist_f_mb_max_seq_table_rot() {
    let mut d = spatial("0", "15", "0");
    d.key(Key::Positioning(PosKind::Move));
    assert_eq!(d.word(), "DIST");
    enter(&mut d, "50");
    assert_eq!(d.word(), "F");
    enter(&mut d, "500");
    d.key(Key::Selection(Selection::Seq(Sign::Minus)));
    d.key(Key::Ent);
    assert_eq!(
        finished(d.key(Key::Transform(TransformMode::TableRot))),
        "PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST+50 F500 SEQ- TABLE ROT"
    );

    let mut d = spatial("0", "15", "0");
    d.key(Key::Positioning(PosKind::Turn));
    d.key(Key::MbMax);
    d.key(Key::FMax);
    assert_eq!(finished(d.key(Key::End)), "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX");
}

#[test]
fn euler_as_in_the_manual_example() {
    let mut d = Dialog::new(Function::Euler);
    enter(&mut d, "0");
    enter(&mut d, "45");
    enter(&mut d, "0");
    d.key(Key::Positioning(PosKind::Turn));
    d.key(Key::MbMax);
    d.key(Key::FMax);
    d.key(Key::Selection(Selection::Sym(Sign::Minus)));
    d.key(Key::Ent);
    assert_eq!(
        finished(d.key(Key::Transform(TransformMode::TableRot))),
        "PLANE EULER EULPR+0 EULNU+45 EULROT+0 TURN MB MAX FMAX SYM- TABLE ROT"
    );
}

#[test]
fn reset_asks_only_for_positioning() {
    let mut d = Dialog::new(Function::Reset);
    assert_eq!(d.step, Step::Positioning);
    assert_eq!(finished(d.key(Key::Positioning(PosKind::Stay))), "PLANE RESET STAY");
    let mut d = Dialog::new(Function::Reset);
    d.key(Key::Positioning(PosKind::Turn));
    d.key(Key::NoEnt);
    assert_eq!(finished(d.key(Key::FMax)), "PLANE RESET TURN FMAX");
}

#[test]
fn wrong_entries_are_answered_and_kept_for_correction() {
    let mut d = Dialog::new(Function::Spatial);
    enter(&mut d, "1a5");
    assert_eq!(d.message, Some(MSG_INVALID));
    assert_eq!(d.input, "1a5", "nothing typed is lost");
    assert_eq!(d.step, Step::Value(0));
    d.key(Key::Backspace);
    d.key(Key::Backspace);
    d.key(Key::Char('5'));
    d.key(Key::Ent);
    assert_eq!(d.message, None);
    assert_eq!(d.step, Step::Value(1));

    enter(&mut d, "400");
    assert_eq!(d.message.map(|m| m.de), Some("Winkel nicht erlaubt"));
    assert_eq!(d.input, "400");
    d.input.clear();
    d.key(Key::Ent);
    assert_eq!(d.message, Some(MSG_REQUIRED), "SPB is required");
    d.key(Key::NoEnt);
    assert_eq!(d.message, Some(MSG_REQUIRED), "NO ENT cannot skip a required angle");
    assert_eq!(d.values.first().copied().flatten(), Some(Value::Number(15.0)), "SPA kept");
}

#[test]
fn seq_together_with_sym_is_refused() {
    let mut d = spatial("0", "45", "0");
    d.key(Key::Positioning(PosKind::Stay));
    d.key(Key::Selection(Selection::Seq(Sign::Plus)));
    d.key(Key::Selection(Selection::Sym(Sign::Minus)));
    assert_eq!(d.message, Some(MSG_SEQ_SYM));
    assert_eq!(d.selection, Some(Selection::Seq(Sign::Plus)), "the first choice stays");
    d.key(Key::Ent);
    assert_eq!(finished(d.key(Key::NoEnt)), "PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY SEQ+");
}

#[test]
fn negative_and_q_values_and_sign_key() {
    let mut d = Dialog::new(Function::Spatial);
    d.key(Key::Char('4'));
    d.key(Key::Char('5'));
    d.key(Key::ToggleSign);
    assert_eq!(d.input, "-45");
    d.key(Key::Ent);
    enter(&mut d, "Q27");
    enter(&mut d, "0");
    assert_eq!(
        finished({
            d.key(Key::Positioning(PosKind::Stay));
            d.key(Key::End)
        }),
        "PLANE SPATIAL SPA-45 SPB+Q27 SPC+0 STAY"
    );
}

#[test]
fn relativ_and_axial_and_points() {
    let mut d = Dialog::new(Function::Relativ);
    d.key(Key::RelAxis(RelAxis::Spb));
    assert_eq!(d.word(), "SPB");
    enter(&mut d, "30");
    d.key(Key::Positioning(PosKind::Stay));
    assert_eq!(finished(d.key(Key::End)), "PLANE RELATIV SPB+30 STAY");

    let mut d = Dialog::new(Function::Axial);
    d.key(Key::NoEnt);
    d.key(Key::NoEnt);
    d.key(Key::NoEnt);
    assert_eq!(d.message, Some(MSG_AXIAL_EMPTY));
    d.key(Key::NoEnt);
    enter(&mut d, "-45");
    d.key(Key::NoEnt);
    assert_eq!(finished(d.key(Key::Positioning(PosKind::Stay))), "PLANE AXIAL B-45 STAY");

    let mut d = Dialog::new(Function::Points);
    for v in ["0", "0", "0", "100", "0", "0", "0", "100", "100"] {
        enter(&mut d, v);
    }
    d.key(Key::Positioning(PosKind::Stay));
    assert_eq!(
        finished(d.key(Key::End)),
        "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+100 P2Y+0 P2Z+0 P3X+0 P3Y+100 P3Z+100 STAY"
    );
}

#[test]
fn reopened_block_shows_its_values_and_finishes_unchanged() {
    let text = "PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST+50 F500 SEQ- TABLE ROT";
    let block = match schwenkbar_core::parse(text).0.blocks.into_iter().next().map(|b| b.body) {
        Some(schwenkbar_core::BlockBody::Plane(p)) => *p,
        other => panic!("{other:?}"),
    };
    let mut d = Dialog::reopen(&block);
    assert_eq!(d.input, "0");
    d.key(Key::Ent);
    assert_eq!(d.input, "15");
    assert_eq!(finished(d.key(Key::End)), text);
}

#[test]
fn preview_follows_the_value_being_typed() {
    let mut d = Dialog::new(Function::Spatial);
    d.key(Key::Ent); // required: refused, nothing changes
    enter(&mut d, "0");
    d.key(Key::Char('3'));
    d.key(Key::Char('0'));
    assert_eq!(d.preview(), Some(PlaneDef::Spatial { spa: 0.0, spb: 30.0, spc: 0.0 }));
}
