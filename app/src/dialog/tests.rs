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
    let mut d = Dialog::new(PlaneKind::Spatial);
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
    assert_eq!(d.word(), Some(Word::Dist));
    enter(&mut d, "50");
    assert_eq!(d.word(), Some(Word::F));
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
    let mut d = Dialog::new(PlaneKind::Euler);
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
    let mut d = Dialog::new(PlaneKind::Reset);
    assert_eq!(d.step, Step::Positioning);
    assert_eq!(finished(d.key(Key::Positioning(PosKind::Stay))), "PLANE RESET STAY");
    let mut d = Dialog::new(PlaneKind::Reset);
    d.key(Key::Positioning(PosKind::Turn));
    d.key(Key::NoEnt);
    assert_eq!(finished(d.key(Key::FMax)), "PLANE RESET TURN FMAX");
}

#[test]
fn wrong_entries_are_answered_and_kept_for_correction() {
    let mut d = Dialog::new(PlaneKind::Spatial);
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
    assert_eq!(d.message.as_ref().map(|m| &*m.de), Some("Winkel nicht erlaubt"));
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
    let mut d = Dialog::new(PlaneKind::Spatial);
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
    let mut d = Dialog::new(PlaneKind::Relativ);
    d.key(Key::RelAxis(RelAxis::Spb));
    assert_eq!(d.word(), Some(Word::Spb));
    enter(&mut d, "30");
    d.key(Key::Positioning(PosKind::Stay));
    assert_eq!(finished(d.key(Key::End)), "PLANE RELATIV SPB+30 STAY");

    let mut d = Dialog::new(PlaneKind::Axial);
    d.key(Key::NoEnt);
    d.key(Key::NoEnt);
    d.key(Key::NoEnt);
    assert_eq!(d.message, Some(MSG_AXIAL_EMPTY));
    d.key(Key::NoEnt);
    enter(&mut d, "-45");
    d.key(Key::NoEnt);
    assert_eq!(finished(d.key(Key::Positioning(PosKind::Stay))), "PLANE AXIAL B-45 STAY");

    let mut d = Dialog::new(PlaneKind::Points);
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
    let block =
        match schwenkbar_core::parse(text).0.blocks.into_iter().next().map(schwenkbar_core::Block::into_body)
        {
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
    let mut d = Dialog::new(PlaneKind::Spatial);
    d.key(Key::Ent); // required: refused, nothing changes
    enter(&mut d, "0");
    d.key(Key::Char('3'));
    d.key(Key::Char('0'));
    assert_eq!(d.preview(), Some(PlaneDef::Spatial { spa: 0.0, spb: 30.0, spc: 0.0 }));
}

/// The block of a one-line PLANE text, as the parser reads it.
fn parsed(text: &str) -> schwenkbar_core::plane::PlaneBlock {
    match schwenkbar_core::parse(text).0.blocks.into_iter().next().map(schwenkbar_core::Block::into_body) {
        Some(schwenkbar_core::BlockBody::Plane(p)) => *p,
        other => panic!("{text}: {other:?}"),
    }
}

/// The block written by reopening `text` and pressing END at once.
fn reopened_end(text: &str) -> String {
    finished(Dialog::reopen(&parsed(text)).key(Key::End))
}

/// The block written by reopening `text` and walking through every prompt with ENT.
fn reopened_ent(text: &str) -> String {
    let mut d = Dialog::reopen(&parsed(text));
    for _ in 0..40 {
        if let Outcome::Finished(t) = d.key(Key::Ent) {
            return t;
        }
        assert_eq!(d.message, None, "{text}: ENT at {:?}", d.step);
    }
    panic!("{text}: ENT never finished the block")
}

#[test]
fn reopening_keeps_fmax_mb_max_f_auto_and_the_options() {
    // Issue 12, defect 1: these words were dropped on ENT … END.
    for text in [
        "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX",
        "PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB+50 FMAX SYM+ COORD ROT",
        "PLANE EULER EULPR+0 EULNU+45 EULROT+0 TURN MB MAX F AUTO SEQ- TABLE ROT",
        "PLANE RESET MOVE DIST+20 F AUTO",
        "PLANE AXIAL IA+10 C-90 TURN FMAX",
    ] {
        assert_eq!(parsed(&reopened_end(text)), parsed(text), "END after reopening {text}");
        assert_eq!(parsed(&reopened_ent(text)), parsed(text), "ENT through {text}");
    }
}

#[test]
fn softkey_choices_can_be_typed_and_are_shown_by_name() {
    let mut d = Dialog::reopen(&parsed("PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX"));
    for _ in 0..4 {
        d.key(Key::Ent);
    }
    assert_eq!((d.step, d.input.as_str()), (Step::MoveBack, "MAX"));
    d.key(Key::Ent);
    assert_eq!((d.step, d.input.as_str()), (Step::Feed, "MAX"));
    d.key(Key::NoEnt);
    assert_eq!(d.feed, None, "NO ENT takes the feed out");
}

#[test]
fn decimal_comma_is_accepted_like_a_point() {
    let mut d = Dialog::new(PlaneKind::Spatial);
    enter(&mut d, "12,5");
    assert_eq!(d.message, None);
    assert_eq!(d.values.first().copied().flatten(), Some(Value::Number(12.5)));
    d.key(Key::Char('7'));
    d.key(Key::Char(','));
    d.key(Key::Char('5'));
    assert_eq!(d.preview(), Some(PlaneDef::Spatial { spa: 12.5, spb: 7.5, spc: 0.0 }));
}

mod round_trip {
    use proptest::prelude::*;
    use schwenkbar_core::format::plane_text;
    use schwenkbar_core::plane::{
        AxialAngle, Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, RelAxis, RotaryAxis, Selection, Sign,
        TransformMode, Value, input_range,
    };

    use super::{parsed, reopened_end, reopened_ent};

    /// A value the dialog accepts for `word`: a number inside its input range (4 decimals, as
    /// the control writes them) or a Q parameter.
    fn value(word: &'static str) -> BoxedStrategy<Value> {
        let r = input_range(word).expect("a word with a range");
        let (lo, hi) = ((r.min * 10_000.0) as i64, (r.max * 10_000.0) as i64);
        prop_oneof![
            4 => (lo..=hi).prop_map(|n| Value::Number(n as f64 / 10_000.0)),
            1 => (1u32..2000, any::<bool>()).prop_map(|(index, negate)| Value::Param { index, negate }),
        ]
        .boxed()
    }

    fn three(words: [&'static str; 3]) -> impl Strategy<Value = [Value; 3]> {
        (value(words[0]), value(words[1]), value(words[2])).prop_map(|(a, b, c)| [a, b, c])
    }

    fn def() -> impl Strategy<Value = PlaneDef> {
        let axis = prop::sample::select(vec![RelAxis::Spa, RelAxis::Spb, RelAxis::Spc]);
        let axial = prop::collection::btree_map(
            prop::sample::select(vec![RotaryAxis::A, RotaryAxis::B, RotaryAxis::C]),
            (value("A"), any::<bool>()),
            1..=3,
        )
        .prop_map(|m| PlaneDef::Axial {
            axes: m
                .into_iter()
                .map(|(axis, (value, incremental))| AxialAngle { axis, value, incremental })
                .collect(),
        });
        prop_oneof![
            three(["SPA", "SPB", "SPC"]).prop_map(|[spa, spb, spc]| PlaneDef::Spatial { spa, spb, spc }),
            three(["PROPR", "PROMIN", "ROT"]).prop_map(|[propr, promin, rot]| PlaneDef::Projected {
                propr,
                promin,
                rot
            }),
            three(["EULPR", "EULNU", "EULROT"]).prop_map(|[eulpr, eulnu, eulrot]| PlaneDef::Euler {
                eulpr,
                eulnu,
                eulrot
            }),
            (three(["BX", "BY", "BZ"]), three(["NX", "NY", "NZ"]))
                .prop_map(|(base, normal)| PlaneDef::Vector { base, normal }),
            (three(["P1X", "P1Y", "P1Z"]), three(["P2X", "P2Y", "P2Z"]), three(["P3X", "P3Y", "P3Z"]))
                .prop_map(|(p1, p2, p3)| PlaneDef::Points { p1, p2, p3 }),
            (axis, value("SPA")).prop_map(|(axis, angle)| PlaneDef::Relativ { axis, angle }),
            axial,
            Just(PlaneDef::Reset),
        ]
    }

    /// DIST, MB and F are lengths and feeds: the dialog takes no negative ones.
    fn amount() -> impl Strategy<Value = Value> {
        prop_oneof![
            (0i64..=5_000_000).prop_map(|n| Value::Number(n as f64 / 10_000.0)),
            (1u32..2000).prop_map(|index| Value::Param { index, negate: false }),
        ]
    }

    fn positioning() -> impl Strategy<Value = Positioning> {
        let feed =
            prop::option::of(prop_oneof![Just(Feed::Max), Just(Feed::Auto), amount().prop_map(Feed::Value)]);
        let move_back = prop::option::of(prop_oneof![Just(MoveBack::Max), amount().prop_map(MoveBack::Dist)]);
        prop_oneof![
            Just(Positioning::Stay),
            (prop::option::of(amount()), feed.clone())
                .prop_map(|(dist, feed)| Positioning::Move { dist, feed }),
            (move_back, feed).prop_map(|(move_back, feed)| Positioning::Turn { move_back, feed }),
        ]
    }

    fn block() -> impl Strategy<Value = PlaneBlock> {
        let sign = prop::sample::select(vec![Sign::Plus, Sign::Minus]);
        let selection = prop::option::of(prop_oneof![
            sign.clone().prop_map(Selection::Seq),
            sign.prop_map(Selection::Sym)
        ]);
        let transform =
            prop::option::of(prop::sample::select(vec![TransformMode::CoordRot, TransformMode::TableRot]));
        (def(), positioning(), selection, transform).prop_map(|(def, p, selection, transform)| {
            // AXIAL and RESET have no SEQ/SYM and no COORD ROT/TABLE ROT (DOMAIN.md §2.7).
            let options = !matches!(def, PlaneDef::Axial { .. } | PlaneDef::Reset);
            PlaneBlock {
                def,
                positioning: Some(p),
                selection: selection.filter(|_| options),
                transform: transform.filter(|_| options),
            }
        })
    }

    proptest! {
        #![proptest_config(schwenkbar_testkit::proptest_cases(512))]

        /// Reopening a block and closing it without changes — at once with END, or prompt by
        /// prompt with ENT — writes a block the parser reads as the same block.
        #[test]
        fn reopen_then_close_gives_back_an_equivalent_block(b in block()) {
            let text = plane_text(&b);
            let original = parsed(&text);
            prop_assert_eq!(&original, &b, "the generated block is what its text says");
            prop_assert_eq!(parsed(&reopened_end(&text)), original.clone(), "END: {}", text);
            prop_assert_eq!(parsed(&reopened_ent(&text)), original, "ENT: {}", text);
        }
    }
}

#[test]
fn euler_prompts_are_the_manuals() {
    // iTNC 530 user manual, PLANE EULER, input parameters (German and English editions).
    let mut d = Dialog::new(PlaneKind::Euler);
    let mut prompts = Vec::new();
    for v in ["0", "45", "0"] {
        prompts.push(d.prompt());
        enter(&mut d, v);
    }
    assert_eq!(
        prompts.iter().map(|p| &*p.de).collect::<Vec<_>>(),
        ["Drehw. Haupt-Koordinatenebene?", "Schwenkwinkel Werkzeug-Achse?", "ROT-Winkel der geschw. Ebene?"]
    );
    assert_eq!(
        prompts.iter().map(|p| &*p.en).collect::<Vec<_>>(),
        ["Rot. angle main coordinate plane?", "Tilting angle tool axis?", "ROT angle of the tilted plane?"]
    );
}

/// The dialog and the parser read a value by the same rule (`plane::check`): whatever the
/// dialog refuses at a prompt, the parser refuses in a block, and the other way round.
#[test]
fn the_dialog_refuses_exactly_what_the_parser_refuses() {
    for (typed, dist_ok) in [("-5", false), ("0", true), ("50", true), ("100000", false)] {
        let mut d = spatial("0", "15", "0");
        d.key(Key::Positioning(PosKind::Move));
        enter(&mut d, typed);
        let dialog_ok = d.step != Step::Dist;
        let (_, diags) =
            schwenkbar_core::parse(&format!("1 PLANE SPATIAL SPA+0 SPB+15 SPC+0 MOVE DIST{typed} F500\n"));
        assert_eq!(dialog_ok, dist_ok, "dialog, DIST {typed}: {:?}", d.message);
        assert_eq!(diags.is_empty(), dist_ok, "parser, DIST {typed}: {diags:?}");
    }
    let mut d = spatial("0", "15", "0");
    d.key(Key::Positioning(PosKind::Move));
    enter(&mut d, "-5");
    assert_eq!(d.message.as_ref().map(|m| &*m.de), Some("Eingabewert außerhalb des Bereichs"));
    let mut d = Dialog::new(PlaneKind::Spatial);
    enter(&mut d, "400");
    assert_eq!(d.message.as_ref().map(|m| &*m.de), Some("Winkel nicht erlaubt"));
}

#[test]
fn only_the_manuals_german_prompts_count_as_confirmed() {
    let euler = Dialog::new(PlaneKind::Euler);
    assert_eq!(euler.prompt().de, "Drehw. Haupt-Koordinatenebene?");
    assert_eq!(euler.wording(), None);
    assert_eq!(Dialog::new(PlaneKind::Vector).wording(), None);
    assert_eq!(Dialog::new(PlaneKind::Spatial).wording(), Some(Decision::DialogWording));
    let mut d = spatial("0", "15", "0");
    d.key(Key::Positioning(PosKind::Move));
    assert_eq!(d.wording(), Some(Decision::DialogWording), "DIST's prompt is ours");
}
