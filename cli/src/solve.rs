//! `schwenkbar solve --machine ID|FILE.json [--start "A+0 C-105"] [--limit "A=-90..10"] "PLANE …"`:
//! the control's choice of rotary axis positions for one PLANE block, as JSON (issue 4).
//!
//! Exit code: 0 = a position was chosen, 1 = the control refuses ("Winkel nicht erlaubt"; the
//! JSON is printed all the same), 2 = the input cannot be read (message on stderr).

use std::process::ExitCode;

use glam::DMat3;
use schwenkbar_core::Lang;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::{Limits, Machine};
use schwenkbar_core::number::tidy;
use schwenkbar_core::parse::{self, PlaneTextError};
use schwenkbar_core::plane::{PlaneBlock, RotaryAxis};
use schwenkbar_core::solve::{Explanation, SolveOptions, solve_block};
use serde::Serialize;

use crate::LangArg;

#[derive(clap::Args)]
pub(crate) struct Args {
    /// Machine id (see `schwenkbar machines`) or a machine description `.json` file.
    #[arg(long)]
    machine: String,
    /// Current rotary axis positions, e.g. "A+0 C-105" (missing axes stand at 0).
    #[arg(long, default_value = "")]
    start: String,
    /// Override a limit switch, e.g. "A=-90..10" (repeatable).
    #[arg(long)]
    limit: Vec<String>,
    /// Language of `reason` and `error`.
    #[arg(long, value_enum, default_value = "de")]
    lang: LangArg,
    /// One PLANE block, e.g. "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SEQ-".
    block: String,
}

/// Exactly the JSON of issue 4.
#[derive(Serialize)]
struct Output {
    machine: String,
    orientation: [[f64; 3]; 3],
    tool_axis: [f64; 3],
    spatial: [f64; 3],
    euler: [f64; 3],
    candidates: Vec<CandidateOut>,
    chosen: Option<AxisValues>,
    error: Option<String>,
    reason: String,
}

#[derive(Serialize)]
struct CandidateOut {
    axes: AxisValues,
    in_limits: bool,
    path: f64,
}

/// Rounds away float noise (44.99999999999999 → 45) while keeping 10 decimals.
fn r(x: f64) -> f64 {
    tidy(x, 10)
}

fn r_axes(a: AxisValues) -> AxisValues {
    AxisValues { a: a.a.map(r), b: a.b.map(r), c: a.c.map(r) }
}

fn output(machine: &Machine, e: &Explanation, lang: Lang) -> Output {
    Output {
        machine: machine.id.clone(),
        orientation: e.orientation.map(|row| row.map(r)),
        tool_axis: e.tool_axis.map(r),
        spatial: e.spatial().map(r),
        euler: e.euler().map(r),
        candidates: e
            .candidates
            .iter()
            .map(|c| CandidateOut { axes: r_axes(c.axes), in_limits: c.in_limits, path: r(c.path) })
            .collect(),
        chosen: e.chosen_axes().map(r_axes),
        error: e.error_message.map(|m| m.0.message().get(lang).to_owned()),
        reason: e.rule.text().get(lang).to_owned(),
    }
}

/// `"A+0 C-105"` → axis values.
pub(crate) fn parse_start(s: &str) -> Result<AxisValues, String> {
    let mut out = AxisValues::default();
    for word in s.split_whitespace() {
        let (letter, num) = word.split_at(word.chars().next().map_or(0, char::len_utf8));
        let axis =
            RotaryAxis::from_letter(letter).ok_or_else(|| format!("--start: unknown axis in {word:?}"))?;
        let v: f64 = num.parse().map_err(|_| format!("--start: no number in {word:?}"))?;
        if !v.is_finite() {
            return Err(format!("--start: {word:?} is not a finite number"));
        }
        out.set(axis, v);
    }
    Ok(out)
}

/// `"A=-90..10"` → (A, −90…10).
pub(crate) fn parse_limit(s: &str) -> Result<(RotaryAxis, Limits), String> {
    let err = || format!("--limit: expected e.g. \"A=-90..10\", got {s:?}");
    let (letter, range) = s.split_once('=').ok_or_else(err)?;
    let axis = RotaryAxis::from_letter(letter.trim()).ok_or_else(err)?;
    let (lo, hi) = range.split_once("..").ok_or_else(err)?;
    let (min, max): (f64, f64) =
        (lo.trim().parse().map_err(|_| err())?, hi.trim().parse().map_err(|_| err())?);
    if !(min.is_finite() && max.is_finite() && min < max) {
        return Err(format!("--limit: need finite min < max, got {min} .. {max}"));
    }
    Ok((axis, Limits { min, max }))
}

/// The single PLANE block of `src`, numbers only.
fn plane_block(src: &str, lang: Lang) -> Result<PlaneBlock<f64>, String> {
    let block = parse::plane_block(src).map_err(|e| match e {
        PlaneTextError::Invalid(d) => format!("{}:{}: {}", d.line, d.column, d.message(lang)),
        PlaneTextError::NoPlane | PlaneTextError::SeveralPlanes => "expected exactly one PLANE block".into(),
    })?;
    block
        .numbers()
        .map_err(|index| format!("{}: Q parameters have no value here", schwenkbar_core::ast::QName(index)))
}

/// `msg` on stderr, each line marked (a machine file's problems are one a line).
fn fail(msg: &str) -> ExitCode {
    msg.lines().for_each(|line| eprintln!("schwenkbar solve: {line}"));
    ExitCode::from(2)
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let lang: Lang = args.lang.into();
    let machine = match crate::machine_arg::load(&args.machine) {
        Ok(m) => m,
        Err(e) => return fail(&e),
    };
    let start = match parse_start(&args.start) {
        Ok(s) => s,
        Err(e) => return fail(&e),
    };
    let limits = match args.limit.iter().map(|l| parse_limit(l)).collect::<Result<Vec<_>, _>>() {
        Ok(l) => l,
        Err(e) => return fail(&e),
    };
    let block = match plane_block(&args.block, lang) {
        Ok(b) => b,
        Err(e) => return fail(&e),
    };
    let opts = SolveOptions { start, limits, ..SolveOptions::default() };
    let e = match solve_block(&machine, &block, DMat3::IDENTITY, &opts) {
        Ok(e) => e,
        Err(pe) => return fail(pe.message().get(lang)),
    };
    match serde_json::to_string(&output(&machine, &e, lang)) {
        Ok(json) => println!("{json}"),
        Err(err) => return fail(&err.to_string()),
    }
    if e.error.is_some() { ExitCode::from(1) } else { ExitCode::SUCCESS }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_and_limit_words() {
        let s = parse_start("A+0 C-105").unwrap();
        assert_eq!((s.a, s.b, s.c), (Some(0.0), None, Some(-105.0)));
        assert!(parse_start("X+1").is_err());
        assert!(parse_start("Anan").is_err());
        assert_eq!(parse_limit("A=-90..10").unwrap(), (RotaryAxis::A, Limits { min: -90.0, max: 10.0 }));
        assert!(parse_limit("A=10..-90").is_err());
        assert!(parse_limit("A-90..10").is_err());
    }
}
