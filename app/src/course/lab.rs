//! The SEQ/SYM experiment bench of lesson 5: machine, limit switch of the master axis, start
//! position and option as the trainee sets them, solved by the core; the seed's table rows
//! (seed 002, DOMAIN.md oracles 13–27) load as set-ups.

use glam::DMat3;
use schwenkbar_core::course::SeedRow;
use schwenkbar_core::machine::{Limits, Machine};
use schwenkbar_core::number::parse_input;
use schwenkbar_core::parse::{PlaneTextError, plane_block};
use schwenkbar_core::plane::PlaneBlock;
use schwenkbar_core::plane::{Selection, Sign, Value};
use schwenkbar_core::solve::{Explanation, SolveOptions, fmt_deg, solve_block};

use crate::i18n::{Lang, Text};
use crate::why::{PlaneWhy, explain_plane};

/// The bench's fields as typed (strings, so nothing the trainee types is lost).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LabForm {
    pub machine: String,
    /// The PLANE block without SEQ/SYM.
    pub block: String,
    /// Start values of the machine's [slave, master] axes.
    pub start: [String; 2],
    /// The master axis' limit switches; empty = the machine's own.
    pub min: String,
    pub max: String,
    /// `""`, `SEQ+`, `SEQ-`, `SYM+`, `SYM-`.
    pub option: String,
}

impl Default for LabForm {
    fn default() -> LabForm {
        LabForm {
            machine: "ac-table".into(),
            block: "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX".into(),
            start: ["0".into(), "0".into()],
            min: String::new(),
            max: String::new(),
            option: String::new(),
        }
    }
}

pub const OPTIONS: [&str; 5] = ["", "SEQ+", "SEQ-", "SYM+", "SYM-"];

pub(crate) fn option_word(s: Option<Selection>) -> &'static str {
    match s {
        None => "",
        Some(Selection::Seq(Sign::Plus)) => "SEQ+",
        Some(Selection::Seq(Sign::Minus)) => "SEQ-",
        Some(Selection::Sym(Sign::Plus)) => "SYM+",
        Some(Selection::Sym(Sign::Minus)) => "SYM-",
    }
}

impl LabForm {
    /// A seed table row as a set-up.
    #[must_use]
    pub fn from_row(row: &SeedRow) -> LabForm {
        let machine = Machine::builtin(row.machine).ok();
        let mut block = row.block.clone();
        let option = option_word(block.selection.take()).to_owned();
        let block = match block.try_map(|v| Ok::<_, std::convert::Infallible>(Value::Number(*v))) {
            Ok(b) => b,
            Err(never) => match never {},
        };
        let text = schwenkbar_core::format::plane_text(&block);
        let axes = machine.as_ref().map(|m| [m.joints()[0].axis, m.joints()[1].axis]);
        let start = axes.map_or_else(
            || ["0".into(), "0".into()],
            |a| a.map(|ax| row.start.get(ax).map_or_else(|| "0".to_owned(), fmt_deg)),
        );
        let limit =
            machine.as_ref().and_then(|m| row.limits.iter().rev().find(|(ax, _)| *ax == m.master().axis));
        LabForm {
            machine: row.machine.to_owned(),
            block: text,
            start,
            min: limit.map_or_else(String::new, |(_, l)| fmt_deg(l.min)),
            max: limit.map_or_else(String::new, |(_, l)| fmt_deg(l.max)),
            option,
        }
    }

    /// The control's choice for this set-up, or the message why the set-up cannot be read.
    pub fn solve(&self, l: Lang) -> Result<PlaneWhy, String> {
        self.bench(l).map(|b| b.why)
    }

    /// The set-up as the solver reads it: machine, PLANE block (with the option) and options.
    fn setup(&self, l: Lang) -> Result<(Machine, PlaneBlock, SolveOptions), String> {
        let unreadable =
            |what: &str| format!("{}: {what}", l.t("Eingabe nicht lesbar", "Cannot read the entry"));
        let machine = Machine::builtin(&self.machine).map_err(|_| unreadable(&self.machine))?;
        let text = format!("{} {}", self.block.trim(), self.option);
        let block = plane_block(text.trim()).map_err(|e| match e {
            PlaneTextError::NoPlane => {
                l.t("Bitte einen PLANE-Satz eingeben", "Please enter a PLANE block").to_owned()
            }
            e => e.message(l).to_owned(),
        })?;
        let mut opts = SolveOptions::default();
        for (joint, value) in machine.joints().iter().zip(&self.start) {
            opts.start.set(joint.axis, parse_input(value).ok_or_else(|| unreadable(value))?);
        }
        if !(self.min.trim().is_empty() && self.max.trim().is_empty()) {
            let (min, max) = (parse_input(&self.min), parse_input(&self.max));
            match (min, max) {
                (Some(min), Some(max)) if min < max => {
                    opts.limits.push((machine.master().axis, Limits { min, max }));
                }
                _ => {
                    return Err(Text::new(
                        "Endschalter: min < max eingeben",
                        "Limit switches: enter min < max",
                    )
                    .get(l)
                    .to_owned());
                }
            }
        }
        Ok((machine, block, opts))
    }

    /// Everything the bench shows for this set-up: the "why" texts, and for the 3D view and the
    /// limit gauge the machine, the solver's explanation (`None` when the block has Q
    /// parameters or cannot be solved) and the options (start, limit switches).
    pub fn bench(&self, l: Lang) -> Result<Bench, String> {
        let (machine, block, opts) = self.setup(l)?;
        let why = explain_plane(&block, &machine, DMat3::IDENTITY, &opts, l);
        let explanation =
            block.numbers().ok().and_then(|b| solve_block(&machine, &b, DMat3::IDENTITY, &opts).ok());
        Ok(Bench { why, machine, explanation, opts })
    }
}

/// What the bench shows for one set-up ([`LabForm::bench`]).
#[derive(Debug, Clone)]
pub struct Bench {
    pub why: PlaneWhy,
    pub machine: Machine,
    pub explanation: Option<Explanation>,
    pub opts: SolveOptions,
}

#[cfg(test)]
mod tests {
    use schwenkbar_core::course::seed_rows;
    use schwenkbar_core::solve::solve_block;

    use super::*;

    /// The bench must show what the solver says for the row itself (the rows' results against
    /// DOMAIN.md are checked in core's course tests and, end to end, in the browser tests).
    #[test]
    fn seed_rows_set_up_on_the_bench_give_the_solvers_choice() {
        for row in seed_rows() {
            let machine = Machine::builtin(row.machine).unwrap();
            let opts =
                SolveOptions { start: row.start, limits: row.limits.clone(), ..SolveOptions::default() };
            let e = solve_block(&machine, &row.block, DMat3::IDENTITY, &opts).unwrap();
            let why = LabForm::from_row(&row).solve(Lang::De).unwrap();
            let chosen = why.candidates.iter().find(|(_, c)| *c).map(|(t, _)| t.clone());
            match e.chosen_axes() {
                Some(axes) => {
                    let words = schwenkbar_core::solve::axis_words(&axes);
                    assert!(chosen.is_some_and(|t| t.starts_with(&words)), "row {}", row.number);
                }
                None => {
                    assert_eq!(chosen, None, "row {}", row.number);
                    assert_eq!(
                        why.error.as_deref(),
                        e.error_message.map(|m| m.0.message().de.into_owned()).as_deref(),
                        "row {}",
                        row.number
                    );
                }
            }
        }
    }

    #[test]
    fn bad_entries_are_answered_not_swallowed() {
        let mut f = LabForm::default();
        f.start[1] = "x".into();
        assert!(f.solve(Lang::De).unwrap_err().contains("nicht lesbar"));
        let f = LabForm { min: "10".into(), max: "-90".into(), ..LabForm::default() };
        assert!(f.solve(Lang::En).unwrap_err().contains("min < max"));
        let f = LabForm { block: "PLANE SPATIAL SPA+0 SPB+45".into(), ..LabForm::default() };
        assert!(f.solve(Lang::De).is_err());
        let f = LabForm { option: "SYM-".into(), ..LabForm::default() };
        assert!(f.solve(Lang::De).unwrap().candidates.iter().any(|(t, c)| *c && t.starts_with("A-45")));
    }
}
