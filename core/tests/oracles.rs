//! Parser oracles from DOMAIN.md §10 (31–33) and the single-block contract of `solve`.

use schwenkbar_core::diag::DiagCode;
use schwenkbar_core::plane::{
    Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, Selection, Sign, TransformMode, Value,
};
use schwenkbar_core::{BlockBody, Severity, parse};

fn plane(src: &str) -> (PlaneBlock, Vec<schwenkbar_core::Diagnostic>) {
    let (p, d) = parse(src);
    assert_eq!(p.blocks.len(), 1, "{src}");
    match &*p.blocks[0].body() {
        BlockBody::Plane(b) => ((**b).clone(), d),
        other => panic!("{src}: {other:?}"),
    }
}

fn num(v: f64) -> Value {
    Value::Number(v)
}

#[test]
fn oracle_31_spatial_turn_fmax_with_comment() {
    let src = "10 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX ; Einschwenken";
    let (b, d) = plane(src);
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(b.def, PlaneDef::Spatial { spa: num(0.0), spb: num(15.0), spc: num(0.0) });
    assert_eq!(b.positioning, Some(Positioning::Turn { move_back: None, feed: Some(Feed::Max) }));
    let (p, _) = parse(src);
    assert_eq!(p.blocks[0].number(), Some(10));
    assert_eq!(p.blocks[0].comment(), Some("Einschwenken"));
}

#[test]
fn oracle_32_euler_with_all_options() {
    let (b, d) = plane("11 PLANE EULER EULPR+0 EULNU45 EULROT0 TURN MB MAX FMAX SYM- TABLE ROT");
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(b.def, PlaneDef::Euler { eulpr: num(0.0), eulnu: num(45.0), eulrot: num(0.0) });
    assert_eq!(
        b.positioning,
        Some(Positioning::Turn { move_back: Some(MoveBack::Max), feed: Some(Feed::Max) })
    );
    assert_eq!(b.selection, Some(Selection::Sym(Sign::Minus)));
    assert_eq!(b.transform, Some(TransformMode::TableRot));
}

#[test]
fn oracle_33_range_and_mandatory_word_errors() {
    let cases: [(&str, &str); 4] = [
        ("1 PLANE EULER EULPR+0 EULNU-5 EULROT0 TURN FMAX", "EULNU"),
        ("1 PLANE PROJECTED PROPR+90 PROMIN+0 ROT+0 TURN FMAX", "PROPR"),
        ("1 PLANE SPATIAL SPA+360 SPB+0 SPC+0 TURN FMAX", "SPA"),
        ("1 PLANE SPATIAL SPA+0 SPB+45 TURN FMAX", "SPC"),
    ];
    for (src, word) in cases {
        let (_, d) = parse(src);
        assert_eq!(d.len(), 1, "{src}: {d:?}");
        assert_eq!(d[0].severity, Severity::Error);
        let named = match &d[0].code {
            DiagCode::AngleNotPermitted { word, .. } | DiagCode::MissingWord { word } => *word,
            other => panic!("{src}: {other:?}"),
        };
        assert_eq!(named, word, "{src}");
    }
    // The bounds themselves are allowed (DOMAIN.md §5).
    let (_, d) = parse("1 PLANE SPATIAL SPA+359.9999 SPB-359.9999 SPC+0 TURN FMAX");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn single_block_without_number_parses_with_a_warning_only() {
    let (p, d) = parse("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX");
    assert_eq!(p.blocks.len(), 1);
    assert_eq!(p.blocks[0].number(), None);
    assert!(matches!(*p.blocks[0].body(), BlockBody::Plane(_)));
    assert!(d.iter().all(|d| d.severity == Severity::Warning), "{d:?}");
}

#[test]
fn q_parameters_stand_for_numbers() {
    let (b, d) = plane("5 PLANE SPATIAL SPA+0 SPB+Q27 SPC-Q28 STAY SEQ- TABLE ROT");
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(
        b.def,
        PlaneDef::Spatial {
            spa: num(0.0),
            spb: Value::Param { index: 27, negate: false },
            spc: Value::Param { index: 28, negate: true }
        }
    );
}

#[test]
fn diagnostics_point_at_the_word() {
    let src = "0 BEGIN PGM X MM\n1 PLANE SPATIAL SPA+400 SPB+0 SPC+0 TURN FMAX\n2 END PGM X MM\n";
    let (_, d) = parse(src);
    assert_eq!(d.len(), 1);
    assert_eq!((d[0].line, d[0].column), (2, 17));
    assert_eq!(&src[d[0].span.start..d[0].span.end], "SPA+400");
}
