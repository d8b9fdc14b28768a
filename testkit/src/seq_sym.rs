//! The seed's two SEQ/SYM tables (seed 002, DOMAIN.md §10 oracles 13–27), written once as
//! `tests/fixtures/oracles/seq_sym.tsv` and read here for the core, cli and course tests.
//!
//! Columns (tab-separated, a header line first, `-` for "nothing"):
//!
//! | column | example | meaning |
//! |---|---|---|
//! | `oracle` | `14` | the oracle's number in DOMAIN.md |
//! | `source` | `seed 002 table 1 row 2` | where the row stands in the seed |
//! | `machine` | `ac-table` | built-in machine id |
//! | `block` | `PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX` | the PLANE block without SEQ/SYM |
//! | `selection` | `SYM+`, `SEQ-`, `SYM=SEQ+`, `-` | the word appended; `SYM=SEQ±` is the first table's column: either word, the tests run both |
//! | `start` | `A+0 C-105` | rotary axes before the block |
//! | `limit` | `A=-90..10` | a narrowed travel range, or `-` |
//! | `chosen` | `A+45 C+90` | the control's choice, or `-` when it refuses |
//! | `error` | `Winkel nicht erlaubt` | the control's message when it refuses, else `-` |
//!
//! The file is compiled in (`include_str!`), so a browser test can read it as well as a native one.

/// The table as written in `tests/fixtures/oracles/seq_sym.tsv`.
pub const TSV: &str = include_str!("../../tests/fixtures/oracles/seq_sym.tsv");

const HEADER: [&str; 9] =
    ["oracle", "source", "machine", "block", "selection", "start", "limit", "chosen", "error"];

/// One case of the table, its cells as written (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub oracle: u8,
    pub source: String,
    pub machine: String,
    /// The PLANE block without its SEQ/SYM word.
    pub block: String,
    /// The selection words to run the block with, in the table's order (`SYM=SEQ+` gives
    /// `["SYM+", "SEQ+"]`); empty when the block has none.
    pub selections: Vec<String>,
    /// Start position as axis words, `"A+0 C-105"` (the CLI's `--start` takes it as is).
    pub start: String,
    /// `"A=-90..10"` (the CLI's `--limit`), or `None`.
    pub limit: Option<String>,
    /// What the control does: the chosen axes or its refusal.
    pub expect: Expect,
}

/// The control's answer to one row.
#[derive(Debug, Clone, PartialEq)]
pub enum Expect {
    /// The chosen rotary axes, `[('A', 45.0), ('C', 90.0)]`.
    Chosen(Vec<(char, f64)>),
    /// The control's (German) error message.
    Refused(String),
}

impl Row {
    /// Every block text this row stands for: the block with each selection word appended, or
    /// the block alone.
    #[must_use]
    pub fn blocks(&self) -> Vec<String> {
        if self.selections.is_empty() {
            return vec![self.block.clone()];
        }
        self.selections.iter().map(|s| format!("{} {s}", self.block)).collect()
    }

    /// The start position as (axis letter, degrees).
    #[must_use]
    pub fn start_axes(&self) -> Vec<(char, f64)> {
        axis_words(&self.start).unwrap_or_else(|e| panic!("oracle {}: start: {e}", self.oracle))
    }

    /// The narrowed travel range as (axis letter, min, max).
    #[must_use]
    pub fn limit_range(&self) -> Option<(char, f64, f64)> {
        self.limit
            .as_deref()
            .map(|l| limit(l).unwrap_or_else(|e| panic!("oracle {}: limit: {e}", self.oracle)))
    }
}

/// The rows of [`TSV`], in the file's order.
///
/// # Panics
/// When the file breaks the format of the module docs: the tests it feeds would otherwise check
/// less than they say.
#[must_use]
pub fn rows() -> Vec<Row> {
    parse(TSV).unwrap_or_else(|e| panic!("tests/fixtures/oracles/seq_sym.tsv: {e}"))
}

/// Reads a table in the format of the module docs.
///
/// # Errors
/// The first line that breaks it, with its 1-based number.
pub fn parse(text: &str) -> Result<Vec<Row>, String> {
    let mut lines = text.lines().enumerate();
    let header: Vec<&str> = lines.next().map(|(_, l)| l.split('\t').collect()).unwrap_or_default();
    if header != HEADER {
        return Err(format!("line 1: header must be {HEADER:?}, is {header:?}"));
    }
    let mut rows = Vec::new();
    for (i, line) in lines {
        let at = |e: String| format!("line {}: {e}", i + 1);
        let cells: Vec<&str> = line.split('\t').collect();
        let [oracle, source, machine, block, selection, start, limit_cell, chosen, error] = cells[..] else {
            return Err(at(format!("{} cells, expected {}", cells.len(), HEADER.len())));
        };
        let oracle = oracle.parse().map_err(|_| at(format!("oracle {oracle:?} is not a number")))?;
        let selections = selection_words(selection).map_err(at)?;
        axis_words(start).map_err(at)?;
        let limit_text = dash(limit_cell).map(str::to_owned);
        if let Some(l) = &limit_text {
            limit(l).map_err(at)?;
        }
        let expect = match (dash(chosen), dash(error)) {
            (Some(c), None) => Expect::Chosen(axis_words(c).map_err(at)?),
            (None, Some(e)) => Expect::Refused(e.to_owned()),
            _ => return Err(at("exactly one of `chosen` and `error` must be given".into())),
        };
        rows.push(Row {
            oracle,
            source: source.to_owned(),
            machine: machine.to_owned(),
            block: block.to_owned(),
            selections,
            start: start.to_owned(),
            limit: limit_text,
            expect,
        });
    }
    Ok(rows)
}

fn dash(cell: &str) -> Option<&str> {
    (cell != "-").then_some(cell)
}

/// `-` → none, `SYM+` → one word, `SYM=SEQ+` → both words, SYM first.
fn selection_words(cell: &str) -> Result<Vec<String>, String> {
    let word = |w: &str| {
        let ok = matches!(w.get(..3), Some("SEQ" | "SYM")) && matches!(w.get(3..), Some("+" | "-"));
        if ok {
            Ok(w.to_owned())
        } else {
            Err(format!("selection {cell:?}: expected SEQ±, SYM±, SYM=SEQ± or -"))
        }
    };
    match cell {
        "-" => Ok(Vec::new()),
        _ => match cell.strip_prefix("SYM=SEQ") {
            Some(sign) => Ok(vec![word(&format!("SYM{sign}"))?, word(&format!("SEQ{sign}"))?]),
            None => Ok(vec![word(cell)?]),
        },
    }
}

/// `"A+0 C-105"` → `[('A', 0.0), ('C', -105.0)]`.
fn axis_words(text: &str) -> Result<Vec<(char, f64)>, String> {
    text.split_whitespace()
        .map(|w| {
            let mut chars = w.chars();
            let letter = chars.next().filter(char::is_ascii_uppercase);
            let value = chars.as_str().parse::<f64>().ok().filter(|v| v.is_finite());
            letter.zip(value).ok_or_else(|| format!("{w:?} is not an axis word like A+45"))
        })
        .collect()
}

/// `"A=-90..10"` → `('A', -90.0, 10.0)`.
fn limit(text: &str) -> Result<(char, f64, f64), String> {
    let err = || format!("{text:?} is not a limit like A=-90..10");
    let (axis, range) = text.split_once('=').ok_or_else(err)?;
    let (min, max) = range.split_once("..").ok_or_else(err)?;
    let mut letters = axis.chars();
    let (Some(letter), None) = (letters.next(), letters.next()) else { return Err(err()) };
    let (min, max): (f64, f64) = (min.parse().map_err(|_| err())?, max.parse().map_err(|_| err())?);
    if min < max { Ok((letter, min, max)) } else { Err(err()) }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &str = "oracle\tsource\tmachine\tblock\tselection\tstart\tlimit\tchosen\terror\n";

    #[test]
    fn the_table_holds_oracles_13_to_27_in_order() {
        let numbers: Vec<u8> = rows().iter().map(|r| r.oracle).collect();
        assert_eq!(numbers, (13..=27).collect::<Vec<_>>());
    }

    #[test]
    fn a_row_reads_into_its_cells() {
        let text = format!(
            "{HEAD}20\tseed 002 table 1 row 8\tac-table\tPLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX\tSYM=SEQ+\tA+0 C+0\tA=-90..10\t-\tWinkel nicht erlaubt\n"
        );
        let rows = parse(&text).unwrap();
        let row = &rows[0];
        assert_eq!(
            (row.oracle, row.machine.as_str(), row.source.as_str()),
            (20, "ac-table", "seed 002 table 1 row 8")
        );
        assert_eq!(
            row.blocks(),
            [
                "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SYM+",
                "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SEQ+"
            ]
        );
        assert_eq!(row.start_axes(), [('A', 0.0), ('C', 0.0)]);
        assert_eq!(row.limit_range(), Some(('A', -90.0, 10.0)));
        assert_eq!(row.expect, Expect::Refused("Winkel nicht erlaubt".into()));
    }

    #[test]
    fn without_selection_the_block_stands_alone() {
        let text = format!("{HEAD}27\ts\tba-table\tPLANE RESET STAY\t-\tA+0 B+0\t-\tA-45 B+0\t-\n");
        let row = &parse(&text).unwrap()[0];
        assert_eq!(row.blocks(), ["PLANE RESET STAY"]);
        assert_eq!(row.limit_range(), None);
        assert_eq!(row.expect, Expect::Chosen(vec![('A', -45.0), ('B', 0.0)]));
    }

    #[test]
    fn broken_rows_are_reported_with_their_line() {
        let cases = [
            ("13\ts\tm\tb\t-\tA+0\t-\tA+1\n", "line 2: 8 cells"),
            ("x\ts\tm\tb\t-\tA+0\t-\tA+1\t-\n", "line 2: oracle \"x\""),
            ("13\ts\tm\tb\tSYM\tA+0\t-\tA+1\t-\n", "line 2: selection \"SYM\""),
            ("13\ts\tm\tb\tSYM=SEQ*\tA+0\t-\tA+1\t-\n", "line 2: selection \"SYM=SEQ*\""),
            ("13\ts\tm\tb\t-\tA+zero\t-\tA+1\t-\n", "line 2: \"A+zero\""),
            ("13\ts\tm\tb\t-\tA+0\tA=10..-90\tA+1\t-\n", "line 2: \"A=10..-90\""),
            ("13\ts\tm\tb\t-\tA+0\t-\tA+1\tWinkel\n", "line 2: exactly one"),
            ("13\ts\tm\tb\t-\tA+0\t-\t-\t-\n", "line 2: exactly one"),
        ];
        for (row, want) in cases {
            let err = parse(&format!("{HEAD}{row}")).unwrap_err();
            assert!(err.starts_with(want), "{row:?}: {err}");
        }
        assert!(parse("oracle\tsource\n").unwrap_err().starts_with("line 1: header"));
    }
}
