//! DOMAIN.md §10, oracles 1–30, through the public API. Tolerances: 1e-4 for the oracle numbers
//! (printed to 4 decimals), 1e-9 where two computations must agree exactly.

// The oracle numbers are DOMAIN.md's 4-decimal values (0.7071 etc.), kept as printed there.
#![allow(clippy::approx_constant)]

use crate::support;

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation::{self, Context};
use schwenkbar_core::plane::{PlaneDef, RelAxis, RotaryAxis, TransformMode};
use schwenkbar_core::solve::{self, Exclusion, Explanation, KinematicCase, Realisation, Rule, SolveOptions};
use schwenkbar_testkit::assert_close;
use schwenkbar_testkit::seq_sym::{self, Expect};
use support::{axis_values, block, limits, plane_block, rotary, spatial};

const ORACLE: f64 = 1e-4;
const EXACT: f64 = 1e-9;

fn r_of(def: PlaneDef<f64>) -> DMat3 {
    orientation::orientation(&def, &Context::default()).expect("valid oracle input")
}

// ------------------------------------------------------------------------------------------
// Oracles 1–12: rotation matrices
// ------------------------------------------------------------------------------------------

#[test]
fn oracles_01_to_04_spatial_matrices() {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let rows: [(u8, [f64; 3], [[f64; 3]; 3]); 4] = [
        (1, [0.0, 15.0, 0.0], [[0.9659, 0.0, 0.2588], [0.0, 1.0, 0.0], [-0.2588, 0.0, 0.9659]]),
        (2, [0.0, 45.0, 0.0], [[s, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, s]]),
        (3, [45.0, 0.0, 90.0], [[0.0, -s, s], [1.0, 0.0, 0.0], [0.0, s, s]]),
        (
            4,
            [10.0, 20.0, 30.0],
            [[0.8138, -0.4410, 0.3785], [0.4698, 0.8826, 0.0180], [-0.3420, 0.1632, 0.9254]],
        ),
    ];
    for (id, [a, b, c], expected) in rows {
        let r = r_of(spatial(a, b, c));
        assert_close!(orientation::rows(&r), expected, ORACLE, "oracle {id}");
        assert_close!(
            orientation::tool_axis(&r).to_array(),
            [expected[0][2], expected[1][2], expected[2][2]],
            ORACLE
        );
    }
    // Oracle 1: t = (0.2588, 0, 0.9659); oracle 3: equals Rz(90)·Rx(45).
    assert_close!(orientation::tool_axis(&r_of(spatial(0.0, 15.0, 0.0))), [0.2588, 0.0, 0.9659], ORACLE);
    let rz_rx = DMat3::from_rotation_z(90f64.to_radians()) * DMat3::from_rotation_x(45f64.to_radians());
    assert_close!(r_of(spatial(45.0, 0.0, 90.0)), rz_rx, EXACT, "oracle 3");
    // Oracle 4: inverse and Euler equivalent.
    let r4 = r_of(spatial(10.0, 20.0, 30.0));
    assert_close!(orientation::to_spatial(&r4), [10.0, 20.0, 30.0], EXACT, "oracle 4 inverse");
    assert_close!(orientation::to_euler(&r4), [92.7268, 22.2687, 295.5056], ORACLE, "oracle 4 Euler");
    let e = orientation::to_euler(&r4);
    assert_close!(
        r_of(PlaneDef::Euler { eulpr: e[0], eulnu: e[1], eulrot: e[2] }),
        r4,
        EXACT,
        "oracle 4 round trip"
    );
}

#[test]
fn oracles_05_06_euler() {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let r5 = r_of(PlaneDef::Euler { eulpr: 0.0, eulnu: 45.0, eulrot: 0.0 });
    assert_close!(r5.z_axis, [0.0, -s, s], ORACLE, "oracle 5 t");
    assert_close!(r5.x_axis, [1.0, 0.0, 0.0], ORACLE, "oracle 5 X'");
    assert_close!(r5, r_of(spatial(45.0, 0.0, 0.0)), EXACT, "oracle 5 = SPATIAL SPA+45");
    for (pr, t) in [(90.0, [s, 0.0, s]), (180.0, [0.0, s, s]), (-90.0, [-s, 0.0, s])] {
        let r = r_of(PlaneDef::Euler { eulpr: pr, eulnu: 45.0, eulrot: 0.0 });
        assert_close!(r.z_axis, t, ORACLE, "oracle 6 EULPR {pr}");
    }
    // The seed's EULPR+270 is outside the input range (unconfirmed::EULPR_LIMIT) but the formula
    // gives the same plane as EULPR-90.
    assert_close!(
        orientation::euler(270.0, 45.0, 0.0),
        r_of(PlaneDef::Euler { eulpr: -90.0, eulnu: 45.0, eulrot: 0.0 }),
        EXACT,
        "oracle 6 EULPR 270 = -90"
    );
}

#[test]
fn oracles_07_08_relativ() {
    // 7: SPATIAL SPB+45, then RELATIV SPC+90 = SPATIAL SPA+45 SPB0 SPC+90.
    let active = r_of(spatial(0.0, 45.0, 0.0));
    let ctx = Context { active, ..Context::default() };
    let r7 = orientation::orientation(&PlaneDef::Relativ { axis: RelAxis::Spc, angle: 90.0 }, &ctx).unwrap();
    assert_close!(r7, r_of(spatial(45.0, 0.0, 90.0)), EXACT, "oracle 7");
    // 8: from untilted, RELATIV SPA+45 then RELATIV SPB+45.
    let mut r = Context::default().active;
    for (axis, angle) in [(RelAxis::Spa, 45.0), (RelAxis::Spb, 45.0)] {
        let ctx = Context { active: r, ..Context::default() };
        r = orientation::orientation(&PlaneDef::Relativ { axis, angle }, &ctx).unwrap();
    }
    assert_close!(orientation::to_spatial(&r), [54.7356, 30.0, 35.2644], ORACLE, "oracle 8 spatial");
    assert_close!(r.z_axis, [0.7071, -0.5, 0.5], ORACLE, "oracle 8 t");
}

#[test]
fn oracles_09_to_12_points_vector_projected() {
    let cases: [(&str, PlaneDef<f64>, [f64; 3]); 5] = [
        (
            "9a",
            PlaneDef::Points { p1: [0.0; 3], p2: [100.0, 0.0, 0.0], p3: [0.0, 100.0, 100.0] },
            [45.0, 0.0, 0.0],
        ),
        (
            "9b",
            PlaneDef::Points { p1: [0.0; 3], p2: [0.0, 100.0, 0.0], p3: [-100.0, 0.0, 0.0] },
            [0.0, 0.0, 90.0],
        ),
        ("10", PlaneDef::Vector { base: [1.0, 0.0, -1.0], normal: [1.0, 0.0, 1.0] }, [0.0, 45.0, 0.0]),
        ("12a", PlaneDef::Projected { propr: 30.0, promin: 0.0, rot: 0.0 }, [0.0, 30.0, 0.0]),
        ("12b", PlaneDef::Projected { propr: 0.0, promin: 30.0, rot: 0.0 }, [30.0, 0.0, 0.0]),
    ];
    for (id, def, sp) in cases {
        let r = r_of(def);
        assert_close!(orientation::to_spatial(&r), sp, ORACLE, "oracle {id}");
        assert_close!(r, r_of(spatial(sp[0], sp[1], sp[2])), EXACT, "oracle {id} matrix");
    }
    let r11 = r_of(PlaneDef::Vector { base: [0.8, -0.4, -0.4472], normal: [0.2, 0.2, 0.9592] });
    assert_close!(r11.x_axis, [0.9281, -0.3524, -0.1201], ORACLE, "oracle 11 X'");
    assert_close!(r11.z_axis, [0.2, 0.2, 0.9592], ORACLE, "oracle 11 t");
    // The result is a proper rotation even though B·N ≠ 0 in the input.
    assert_close!(r11.transpose() * r11, DMat3::IDENTITY, EXACT, "oracle 11 orthonormal");
    assert_close!(r11.determinant(), 1.0, EXACT);
}

// ------------------------------------------------------------------------------------------
// Oracles 13–27: the seed's two SYM/SEQ tables, read from tests/fixtures/oracles/seq_sym.tsv
// ------------------------------------------------------------------------------------------

/// The table's row of this oracle.
fn seed_row(oracle: u8) -> seq_sym::Row {
    seq_sym::rows().into_iter().find(|r| r.oracle == oracle).unwrap_or_else(|| panic!("oracle {oracle}"))
}

/// Solves one of the row's blocks (`row.blocks()`) on the row's machine, start and limit.
fn solve_row(row: &seq_sym::Row, block_text: &str) -> Explanation {
    let machine = Machine::builtin(&row.machine).unwrap();
    let start = axis_values(&row.start_axes());
    let limits = row.limit_range().map(limits).into_iter().collect();
    let opts = SolveOptions { start, limits, ..SolveOptions::default() };
    solve::solve_block(&machine, &plane_block(block_text), DMat3::IDENTITY, &opts).unwrap()
}

/// The explanation of oracle `n` with this selection word (`None`: the row has none).
fn explain(n: u8, selection: Option<&str>) -> Explanation {
    let row = seed_row(n);
    let text = row
        .blocks()
        .into_iter()
        .find(|b| selection.is_none_or(|s| b.ends_with(&format!(" {s}"))))
        .unwrap_or_else(|| panic!("oracle {n} has no block with {selection:?}"));
    assert_eq!(selection.is_none(), row.selections.is_empty(), "oracle {n}: {text}");
    solve_row(&row, &text)
}

/// Every block of the row gives the table's result; the "SYM=SEQ" rows are run with both words.
fn check(row: &seq_sym::Row) {
    for text in row.blocks() {
        let e = solve_row(row, &text);
        let id = format!("oracle {} ({}): {text}", row.oracle, row.source);
        match &row.expect {
            Expect::Chosen(axes) => {
                let chosen = e.chosen_axes().unwrap_or_else(|| panic!("{id}: no solution: {e:#?}"));
                assert!(e.error.is_none(), "{id}: {:?}", e.error);
                for &(letter, value) in axes {
                    let got = chosen.get(rotary(letter)).unwrap_or(f64::NAN);
                    assert_close!(got, value, ORACLE, "{id}, axis {letter}; rule {:?}", e.rule);
                }
            }
            Expect::Refused(msg) => {
                assert!(e.chosen.is_none(), "{id}: expected a refusal, chose {:?}", e.chosen_axes());
                let err = e.error.unwrap_or_else(|| panic!("{id}: no error"));
                assert_eq!(err.message().de, *msg, "{id}");
                assert_eq!(
                    e.error_message.map(|t| t.0.message().en),
                    Some("Entered angle not permitted".into()),
                    "{id}"
                );
            }
        }
    }
}

/// Checks every row of the table on `machine`; `count` guards against a table that lost rows.
fn check_table(machine: &str, count: usize) {
    let rows: Vec<_> = seq_sym::rows().into_iter().filter(|r| r.machine == machine).collect();
    assert_eq!(rows.len(), count, "{machine} rows in seq_sym.tsv");
    rows.iter().for_each(check);
}

use RotaryAxis::{A, C};

#[test]
fn oracles_13_to_22_c_table_on_a_tilting_table() {
    check_table("ac-table", 10);
}

#[test]
fn oracles_13_to_22_explanations() {
    // Both solutions, checked with forward kinematics (DOMAIN.md §10 heading).
    let e = explain(13, None);
    assert_eq!(e.case, KinematicCase::Two);
    assert_close!(e.tool_axis, [0.7071, 0.0, 0.7071], ORACLE);
    assert_close!(e.symmetry_point, 0.0, EXACT, "A/C symmetry point");
    assert_eq!(e.master, A);
    let mut masters: Vec<f64> = e.candidates.iter().map(|c| c.master).collect();
    masters.sort_by(f64::total_cmp);
    assert_close!(masters, [-45.0, 45.0], ORACLE, "the two masters");
    let machine = Machine::builtin("ac-table").unwrap();
    for c in &e.candidates {
        assert_close!(machine.forward(&c.axes).z_axis, e.tool_axis, EXACT, "forward of {:?}", c.axes);
    }
    // 13: tie 45+90 each, decided by the tie rule.
    assert!(matches!(e.rule, Rule::Tie { master: A }), "{:?}", e.rule);
    let paths: Vec<f64> = e.candidates.iter().map(|c| c.path).collect();
    assert_close!(paths, [135.0, 135.0], ORACLE, "both paths");
    // 16: C travel 15 vs 195.
    let e = explain(16, None);
    assert_eq!(e.rule, Rule::ShortestPath);
    let mut paths: Vec<f64> = e.candidates.iter().map(|c| c.path).collect();
    paths.sort_by(f64::total_cmp);
    assert_close!([paths[0], paths[1]], [45.0 + 15.0, 45.0 + 195.0], ORACLE);
    // 19: A+45 outside the limits.
    let e = explain(19, None);
    assert_eq!(e.rule, Rule::OnlyInLimits);
    let out = e.candidates.iter().find(|c| !c.in_limits).unwrap();
    let Some(Exclusion::OutOfLimits(v)) = &out.excluded else { panic!("{:?}", out.excluded) };
    assert_eq!((v.axis, v.max), (A, 10.0));
    assert_close!(v.value, 45.0, ORACLE, "A of the excluded candidate");
    // 15: SEQ− text as the UI shows it.
    let e = explain(15, Some("SEQ-"));
    assert_eq!(e.rule.text().de, "SEQ−: Master-Achse A muss negativ sein (bezogen auf die Grundstellung 0°)");
    assert_eq!(e.q.q120.map(|a| a.round()), Some(-45.0));
    assert_eq!(e.q.q122.map(|c| c.round()), Some(-90.0));
    assert_eq!(e.q.q121, None);
}

#[test]
fn oracles_23_to_27_b_table_on_a_tilting_table() {
    check_table("ba-table", 5);
    let e = explain(27, None);
    assert_close!(e.tool_axis, [0.0, 0.7071, 0.7071], ORACLE);
    assert_close!(e.symmetry_point, -90.0, EXACT, "B/A symmetry point");
    let mut sols: Vec<[f64; 2]> = e.candidates.iter().map(|c| [c.master, c.slave.abs()]).collect();
    sols.sort_by(|a, b| b[0].total_cmp(&a[0]));
    assert_close!(sols, [[-45.0, 0.0], [-135.0, 180.0]].concat(), ORACLE);
    assert_eq!(e.rule, Rule::OnlyInLimits);
}

// ------------------------------------------------------------------------------------------
// Oracles 28–30: other kinematics
// ------------------------------------------------------------------------------------------

/// The candidates' `(master, slave)` pairs, master descending, slave wrapped to (−180, 180].
fn pairs(
    machine: &str,
    def: PlaneDef<f64>,
    transform: Option<TransformMode>,
) -> (Explanation, Vec<[f64; 2]>) {
    let m = Machine::builtin(machine).unwrap();
    let e = solve::solve_block(&m, &block(def, None, transform), DMat3::IDENTITY, &SolveOptions::default())
        .unwrap();
    let mut p: Vec<[f64; 2]> = e.candidates.iter().map(|c| [c.master, c.slave]).collect();
    p.sort_by(|a, b| b[0].total_cmp(&a[0]));
    (e, p)
}

#[test]
fn oracle_28_b_head_c_table() {
    // (B, C): SPB+45 → (B+45, C0) or (B−45, C180); SPA+45 → (B+45, C−90) or (B−45, C+90).
    let (_, p) = pairs("bc-head-table", spatial(0.0, 45.0, 0.0), None);
    assert_close!(p, [[45.0, 0.0], [-45.0, 180.0]].concat(), ORACLE, "SPB+45");
    let (_, p) = pairs("bc-head-table", spatial(45.0, 0.0, 0.0), None);
    assert_close!(p, [[45.0, -90.0], [-45.0, 90.0]].concat(), ORACLE, "SPA+45");
}

#[test]
fn oracle_29_residual_rotation() {
    let (e, p) = pairs("ac-table", spatial(45.0, 0.0, 90.0), None);
    assert_close!(p[0], [45.0, 90.0], ORACLE);
    assert_close!(
        e.candidates.iter().find(|c| c.master > 0.0).unwrap().residual,
        0.0,
        ORACLE,
        "γ for SPA45 SPC90"
    );
    let (e, p) = pairs("ac-table", spatial(0.0, 45.0, 0.0), None);
    assert_close!(p[0], [45.0, 90.0], ORACLE);
    assert_close!(
        e.candidates.iter().find(|c| c.master > 0.0).unwrap().residual,
        -90.0,
        ORACLE,
        "γ for SPB45"
    );
    // For the A ≥ 0 solution, C = EULPR, A = EULNU, γ = EULROT (DOMAIN.md §3.2).
    let c = e.candidates.iter().find(|c| c.master > 0.0).unwrap();
    let eul = e.euler();
    assert_close!([c.slave, c.master, c.residual.rem_euclid(360.0)], eul, ORACLE);
}

#[test]
fn oracle_30_coord_rot_and_table_rot() {
    let start = AxisValues::default().with(A, 0.0).with(C, 12.0);
    let m = Machine::builtin("ac-table").unwrap();
    let opts = SolveOptions { start, ..SolveOptions::default() };
    let solve =
        |t| solve::solve_block(&m, &block(spatial(0.0, 0.0, 45.0), None, t), DMat3::IDENTITY, &opts).unwrap();

    let coord = solve(Some(TransformMode::CoordRot));
    assert_eq!(coord.case, KinematicCase::SlaveFree);
    assert_eq!(coord.rule, Rule::Unique { free: Some(C) });
    let axes = coord.chosen_axes().unwrap();
    assert_close!([axes.a.unwrap(), axes.c.unwrap()], [0.0, 12.0], EXACT, "COORD ROT: table stays");
    let res = coord.residual.unwrap();
    assert_eq!(res.realised_by, Realisation::Mathematical);
    assert_close!(res.gamma, 45.0 - 12.0, EXACT, "COORD ROT: the rest is mathematical");

    let table = solve(Some(TransformMode::TableRot));
    let axes = table.chosen_axes().unwrap();
    assert_close!([axes.a.unwrap(), axes.c.unwrap()], [0.0, 45.0], EXACT, "TABLE ROT: C+45");
    let res = table.residual.unwrap();
    assert_close!(res.gamma, 0.0, EXACT);
    assert!(
        matches!(res.realised_by, Realisation::TableAxis { axis: C, value } if (value - 45.0).abs() < EXACT)
    );

    // Either way the machine plus γ gives exactly the programmed orientation.
    for e in [&coord, &table] {
        let axes = e.chosen_axes().unwrap();
        let gamma = e.residual.unwrap().gamma.to_radians();
        let got = m.forward(&axes) * DMat3::from_rotation_z(gamma);
        assert_close!(got, spatial_r(0.0, 0.0, 45.0), EXACT);
    }
}

fn spatial_r(a: f64, b: f64, c: f64) -> DMat3 {
    orientation::spatial(a, b, c)
}

#[test]
fn tool_axis_along_x_is_the_spatial_singularity() {
    // SPB = ±90: the inverse picks SPA = 0 and still reproduces the matrix.
    for (a, b, c) in [(30.0, 90.0, 10.0), (-50.0, -90.0, 120.0)] {
        let r = orientation::spatial(a, b, c);
        let sp = orientation::to_spatial(&r);
        assert_close!(sp[0], 0.0, EXACT);
        assert_close!(orientation::spatial(sp[0], sp[1], sp[2]), r, EXACT, "({a}, {b}, {c}) → {sp:?}");
    }
    // EULNU 0 / 180: EULROT = 0.
    for (p, n, r) in [(30.0, 0.0, 50.0), (30.0, 180.0, 50.0)] {
        let m = orientation::euler(p, n, r);
        let e = orientation::to_euler(&m);
        assert_close!(e[2], 0.0, EXACT);
        assert_close!(orientation::euler(e[0], e[1], e[2]), m, EXACT, "({p}, {n}, {r}) → {e:?}");
    }
}
