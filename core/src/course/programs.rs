//! The set-ups behind the machine exercises: solver questions ([`choose`]), small programs run
//! through the simulator ([`run`]), and the seed's two SEQ/SYM tables as experiments
//! ([`seed_rows`], seed 002 / DOMAIN.md oracles 13–27).

use glam::DMat3;

use super::expected::{axes_exercise, value_exercise};
use super::orientation::TILTS;
use super::{ChooseKind, Exercise, Rng, RunKind, Spec, TURN_FMAX, plane, spatial_def};
use crate::axes::AxisValues;
use crate::format::{plane_angles, plane_rounded};
use crate::lang::Text;
use crate::machine::{Limits, Machine};
use crate::number::signed;
use crate::plane::{PlaneBlock, PlaneDef, RotaryAxis, Selection, Sign, TransformMode};
use crate::solve::{SolveError, SolveOptions, axis_words, fmt_deg, solve_block};

const SELECTIONS: [Selection; 4] = [
    Selection::Seq(Sign::Plus),
    Selection::Seq(Sign::Minus),
    Selection::Sym(Sign::Plus),
    Selection::Sym(Sign::Minus),
];
/// Start positions of C that never tie (a tie is decided by an unconfirmed rule).
const STARTS_C: [f64; 10] = [-150.0, -120.0, -105.0, -60.0, -30.0, 30.0, 60.0, 105.0, 120.0, 150.0];

/// One row of the seed's tables: the set-up; what the control does is the solver's business
/// (the expected results are in the tests, from DOMAIN.md).
#[derive(Debug, Clone, PartialEq)]
pub struct SeedRow {
    /// The oracle's number in DOMAIN.md.
    pub number: u8,
    pub machine: &'static str,
    pub block: PlaneBlock<f64>,
    pub start: AxisValues,
    pub limits: Vec<(RotaryAxis, Limits)>,
}

fn spatial_block(spa: f64, spb: f64, spc: f64, selection: Option<Selection>) -> PlaneBlock<f64> {
    PlaneBlock { selection, ..plane(spatial_def([spa, spb, spc]), Some(TURN_FMAX)) }
}

fn limit_a(min: f64, max: f64) -> (RotaryAxis, Limits) {
    (RotaryAxis::A, Limits { min, max })
}

/// The seed's two tables (seed 002): C table on A tilting table with `SPB+45`, rows 13–22;
/// B table on A tilting table (A −100…+180) with `SPA-45`, rows 23–27.
#[must_use]
pub fn seed_rows() -> Vec<SeedRow> {
    let ac = |number, c: f64, limit: bool, selection| SeedRow {
        number,
        machine: "ac-table",
        block: spatial_block(0.0, 45.0, 0.0, selection),
        start: AxisValues::default().with(RotaryAxis::A, 0.0).with(RotaryAxis::C, c),
        limits: if limit { vec![limit_a(-90.0, 10.0)] } else { Vec::new() },
    };
    let ba = |number, selection| SeedRow {
        number,
        machine: "ba-table",
        block: spatial_block(-45.0, 0.0, 0.0, selection),
        start: AxisValues::default().with(RotaryAxis::A, 0.0).with(RotaryAxis::B, 0.0),
        limits: Vec::new(),
    };
    let (seq, sym) = (|s| Some(Selection::Seq(s)), |s| Some(Selection::Sym(s)));
    // The first table's "SYM=SEQ" column: on the A/C table the symmetry point is A0, so SYM and
    // SEQ choose alike; the rows use SYM as the seed's table heads them.
    vec![
        ac(13, 0.0, false, None),
        ac(14, 0.0, false, sym(Sign::Plus)),
        ac(15, 0.0, false, sym(Sign::Minus)),
        ac(16, -105.0, false, None),
        ac(17, -105.0, false, sym(Sign::Plus)),
        ac(18, -105.0, false, sym(Sign::Minus)),
        ac(19, 0.0, true, None),
        ac(20, 0.0, true, sym(Sign::Plus)),
        ac(21, 0.0, true, sym(Sign::Minus)),
        ac(22, -135.0, false, seq(Sign::Plus)),
        ba(23, sym(Sign::Plus)),
        ba(24, sym(Sign::Minus)),
        ba(25, seq(Sign::Plus)),
        ba(26, seq(Sign::Minus)),
        ba(27, None),
    ]
}

pub(super) fn choose(kind: ChooseKind, variant: u32, rng: &mut Rng) -> Exercise {
    let fixed = variant == 0;
    let tilt = |rng: &mut Rng| if fixed { 45.0 } else { rng.pick(&TILTS) * rng.pick(&[1.0, -1.0]) };
    let start_c = |rng: &mut Rng, seed: f64| if fixed { seed } else { rng.pick(&STARTS_C) };
    let (machine_id, block, start, limits) = match kind {
        ChooseKind::OtherMachine => {
            let b = if fixed { 30.0 } else { rng.pick(&TILTS) };
            (
                "bc-head-table",
                spatial_block(0.0, b, 0.0, None),
                [(RotaryAxis::B, 0.0), (RotaryAxis::C, 0.0)],
                vec![],
            )
        }
        ChooseKind::ShortestPath => {
            let b = tilt(rng);
            let c = start_c(rng, -105.0);
            ("ac-table", spatial_block(0.0, b, 0.0, None), [(RotaryAxis::A, 0.0), (RotaryAxis::C, c)], vec![])
        }
        ChooseKind::Option => {
            let b = tilt(rng);
            let sel = if fixed { Selection::Seq(Sign::Minus) } else { rng.pick(&SELECTIONS) };
            let c = start_c(rng, 0.0);
            (
                "ac-table",
                spatial_block(0.0, b, 0.0, Some(sel)),
                [(RotaryAxis::A, 0.0), (RotaryAxis::C, c)],
                vec![],
            )
        }
        ChooseKind::Limits => {
            let b = tilt(rng);
            let sel = if fixed {
                Some(Selection::Sym(Sign::Plus))
            } else {
                rng.pick(&[None, Some(Selection::Seq(Sign::Plus)), Some(Selection::Seq(Sign::Minus))])
            };
            let c = start_c(rng, 0.0);
            (
                "ac-table",
                spatial_block(0.0, b, 0.0, sel),
                [(RotaryAxis::A, 0.0), (RotaryAxis::C, c)],
                vec![limit_a(-90.0, 10.0)],
            )
        }
        ChooseKind::TableRot | ChooseKind::CoordRot => {
            let spc = if fixed { 30.0 } else { rng.pick(&[15.0, 30.0, 45.0, 60.0, -30.0, -45.0, 90.0]) };
            let c = if fixed { 0.0 } else { rng.pick(&[0.0, 10.0, -20.0, 45.0]) };
            let mut block = spatial_block(0.0, 0.0, spc, None);
            block.transform = Some(if kind == ChooseKind::TableRot {
                TransformMode::TableRot
            } else {
                TransformMode::CoordRot
            });
            ("ac-table", block, [(RotaryAxis::A, 0.0), (RotaryAxis::C, c)], vec![])
        }
    };
    let machine = match Machine::builtin(machine_id) {
        Ok(m) => m,
        // The ids above are the shipped machines (tested); a missing one is a build error.
        Err(_) => return super::Exercise::generate(Spec::Lean, variant),
    };
    let start = start.iter().fold(AxisValues::default(), |a, &(ax, v)| a.with(ax, v));
    let limit_text = limits
        .iter()
        .map(|(ax, l)| format!(", Endschalter {}{} … {}", ax, fmt_deg(l.min), fmt_deg(l.max)))
        .collect::<String>();
    let limit_text_en = limit_text.replace("Endschalter", "limit switches");
    let text = plane_rounded(&block);
    // The control's refusal as the solver words it, in each language.
    let refuse = SolveError::NoSolutionInLimits { candidates: 0 }.message();
    let prompt = Text::owned(
        format!(
            "Maschine: {}. Die Drehachsen stehen auf {}{limit_text}. Welche Achspositionen fährt die Steuerung bei „{text}“ an? (z. B. {}, oder „{}“)",
            machine.name.de,
            axis_words(&start),
            example(&machine),
            refuse.de
        ),
        format!(
            "Machine: {}. The rotary axes stand at {}{limit_text_en}. Which axis positions does the control move to for \"{text}\"? (e.g. {}, or \"{}\")",
            machine.name.en,
            axis_words(&start),
            example(&machine),
            refuse.en
        ),
    );
    let opts = SolveOptions { start, limits, ..SolveOptions::default() };
    // COORD ROT and TABLE ROT: where the axes go with the other mode (the solver's answer), so a
    // trainee who mixes the two up gets told so.
    let other_mode = block.transform.and_then(|mode| {
        let other =
            if mode == TransformMode::TableRot { TransformMode::CoordRot } else { TransformMode::TableRot };
        let block = PlaneBlock { transform: Some(other), ..block.clone() };
        solve_block(&machine, &block, DMat3::IDENTITY, &opts).ok()?.chosen_axes()
    });
    let mut ex = axes_exercise(Spec::Choose(kind), variant, machine, &block, &opts, prompt, other_mode);
    let program = format!(
        "0 BEGIN PGM AUFGABE MM\n1 L {} R0 FMAX\n2 {text}\n3 END PGM AUFGABE MM\n",
        axis_words(&opts.start)
    );
    ex.program = Some((program, machine_id));
    ex
}

/// `A+0 C+0`: the machine's axes in the control's order A, B, C.
fn example(machine: &Machine) -> String {
    axis_words(&machine.joints().iter().fold(AxisValues::default(), |a, j| a.with(j.axis, 0.0)))
}

const HEADER: &str = "0 BEGIN PGM KURS MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-40
2 BLK FORM 0.2 X+100 Y+100 Z+0
3 TOOL CALL 8 Z S4000 F800
4 L Z+0 R0 FMAX M91 M3
5 L X-600 Y+500 R0 FMAX M91
";

fn program(body: &[String]) -> String {
    let mut text = HEADER.to_owned();
    let mut n = 6;
    for line in body {
        text.push_str(&format!("{n} {line}\n"));
        n += 1;
    }
    text.push_str(&format!("{n} M30\n{} END PGM KURS MM\n", n + 1));
    text
}

/// `6 (PLANE SPATIAL … TURN FMAX)`: the block number with the block's words.
fn block_line(text: &str, number: u32) -> String {
    let prefix = format!("{number} ");
    text.lines().find_map(|l| l.strip_prefix(&prefix)).map_or_else(
        || number.to_string(),
        |words| format!("{number} ({})", words.split(';').next().unwrap_or("").trim()),
    )
}

const MUSTERPROGRAMM_1: &str = include_str!("../../../static/programs/musterprogramm1.h");

pub(super) fn run(kind: RunKind, variant: u32, rng: &mut Rng) -> Exercise {
    let fixed = variant == 0;
    let b = if fixed { 45.0 } else { rng.pick(&TILTS) * rng.pick(&[1.0, -1.0]) };
    let spatial = plane_angles(PlaneDef::Spatial { spa: 0.0, spb: b, spc: 0.0 });
    // The prompt quotes the block asked about, so a fresh variant shows its new numbers.
    let ask = |text: &str, block: u32, what_de: &str, what_en: &str| {
        let line = block_line(text, block);
        Text::owned(
            format!(
                "Welchen Wert zeigt die Steuerung für {what_de} nach Satz {line}? (z. B. +45 oder -12,5)"
            ),
            format!("What value does the control show for {what_en} after block {line}? (e.g. +45 or -12.5)"),
        )
    };
    match kind {
        RunKind::Turn => {
            let text = program(&[format!("{spatial} TURN FMAX")]);
            let letter = if fixed { 'A' } else { rng.pick(&['A', 'C']) };
            let prompt = ask(&text, 6, &format!("die Drehachse {letter}"), &format!("rotary axis {letter}"));
            value_exercise(kind, variant, text, None, "ac-table", (6, letter), prompt)
        }
        RunKind::Stay | RunKind::StayQ120 => {
            let text = program(&[format!("{spatial} STAY"), "L A+Q120 C+Q122 R0 FMAX".to_owned()]);
            let (letter, de, en) = if kind == RunKind::StayQ120 {
                ('Q', "Q120 (den berechneten A-Wert)".to_owned(), "Q120 (the computed A value)".to_owned())
            } else {
                let l = if fixed { 'A' } else { rng.pick(&['A', 'C']) };
                (l, format!("die Drehachse {l}"), format!("rotary axis {l}"))
            };
            let prompt = ask(&text, 6, &de, &en);
            value_exercise(kind, variant, text, None, "ac-table", (6, letter), prompt)
        }
        RunKind::ResetStay | RunKind::ResetTurn => {
            let reset = if kind == RunKind::ResetStay { "PLANE RESET STAY" } else { "PLANE RESET TURN FMAX" };
            let text =
                program(&[format!("{spatial} TURN FMAX"), reset.to_owned(), "L A+0 C+0 R0 FMAX".to_owned()]);
            let tilt = block_line(&text, 6);
            let prompt = ask(
                &text,
                7,
                &format!("die Drehachse A (vorher Satz {tilt})"),
                &format!("rotary axis A (block {tilt} came before)"),
            );
            value_exercise(kind, variant, text, None, "ac-table", (7, 'A'), prompt)
        }
        RunKind::Musterprogramm1 => {
            let (block, letter) =
                if fixed { (10, 'A') } else { rng.pick(&[(10, 'A'), (10, 'C'), (18, 'A'), (25, 'C')]) };
            let prompt = ask(
                MUSTERPROGRAMM_1,
                block,
                &format!("die Drehachse {letter}"),
                &format!("rotary axis {letter}"),
            );
            value_exercise(
                kind,
                variant,
                MUSTERPROGRAMM_1.to_owned(),
                None,
                "ac-table",
                (block, letter),
                prompt,
            )
        }
        RunKind::DatumThenPlane => {
            let (dx, z) = if fixed {
                (40.0, 10.0)
            } else {
                (rng.pick(&[20.0, 30.0, 40.0, 50.0, 60.0]), rng.pick(&[10.0, 20.0]))
            };
            let b = if fixed { 30.0 } else { b };
            let with_tilt = |b: f64| {
                program(&[
                    format!("TRANS DATUM AXIS X{} Y+50 Z+0", signed(dx, 3)),
                    format!("{} TURN FMAX", plane_angles(PlaneDef::Spatial { spa: 0.0, spb: b, spc: 0.0 })),
                    format!("L X+0 Y+0 Z{} R0 FMAX", signed(z, 3)),
                ])
            };
            let (text, flipped) = (with_tilt(b), with_tilt(-b));
            let blocks = (6..=8).map(|n| block_line(&text, n)).collect::<Vec<_>>().join(", ");
            let prompt = Text::owned(
                format!(
                    "Sätze {blocks}: Wo steht die Werkzeugspitze nach Satz 8 im Werkstück-Koordinatensystem (W-CS, vor der Verschiebung)? Geben Sie X ein (z. B. +45 oder 12,5)."
                ),
                format!(
                    "Blocks {blocks}: where is the tool tip after block 8 in the workpiece coordinate system (W-CS, before the shift)? Enter X (e.g. +45 or 12.5)."
                ),
            );
            value_exercise(kind, variant, text, Some(&flipped), "ac-table", (8, 'X'), prompt)
        }
        RunKind::DatumThenMirror => {
            let (dx, x) = if fixed {
                (50.0, 20.0)
            } else {
                (rng.pick(&[30.0, 40.0, 50.0, 60.0]), rng.pick(&[10.0, 15.0, 20.0, 25.0]))
            };
            let text = program(&[
                format!("TRANS DATUM AXIS X{} Y+50 Z+0", signed(dx, 3)),
                "TRANS MIRROR AXIS X".to_owned(),
                format!("L X{} Y+10 Z+10 R0 FMAX", signed(x, 3)),
            ]);
            let blocks = (6..=8).map(|n| block_line(&text, n)).collect::<Vec<_>>().join(", ");
            let prompt = Text::owned(
                format!(
                    "Sätze {blocks}: Wo steht die Werkzeugspitze nach Satz 8 im Werkstück-Koordinatensystem (W-CS, vor Verschiebung und Spiegelung)? Geben Sie X ein."
                ),
                format!(
                    "Blocks {blocks}: where is the tool tip after block 8 in the workpiece coordinate system (W-CS, before shift and mirror)? Enter X."
                ),
            );
            value_exercise(kind, variant, text, None, "ac-table", (8, 'X'), prompt)
        }
    }
}
