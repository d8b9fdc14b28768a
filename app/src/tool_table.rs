//! The shop's tool table on the machine editor page: the rows of the control's `TOOL.T` (T,
//! NAME, L, R, R2, DL, DR, TYP, T-ANGLE) as the trainee types them, checked cell by cell,
//! imported from and exported as `TOOL.T`, and kept in the browser under [`TOOLS_KEY`] as that
//! same file's text, which the trainer reads ([`read_saved`]) and a share link carries.
//! Until a table is kept the shipped one applies.

use std::sync::Arc;

use schwenkbar_core::number::parse_f64;
use schwenkbar_core::sim::tools::{
    Columns, MAX_TOOL_NUMBER, ToolEntry, read_tool_table, tool_table, write_tool_table,
};

use crate::effect::Effect;
use crate::i18n::Text;

/// The localStorage key of the shop's tool table (the `TOOL.T` text; none or empty: the
/// shipped table).
pub const TOOLS_KEY: &str = "schwenkbar.tools";

/// A tool table file larger than this is refused on import: 32,768 rows of 120 characters
/// (the most tools the control numbers) fit.
pub const MAX_TABLE_BYTES: usize = 4 * 1024 * 1024;

/// The columns as the page shows them, in the file's order.
pub const COLUMNS: [&str; 9] = ["T", "NAME", "L", "R", "R2", "DL", "DR", "TYP", "T-ANGLE"];

/// A column's heading: the control's abbreviation and what it means.
#[must_use]
pub fn heading(column: usize) -> Text {
    let [de, en] = [
        ["Werkzeugnummer", "tool number"],
        ["Name", "name"],
        ["Länge, mm", "length, mm"],
        ["Radius, mm", "radius, mm"],
        ["Eckenradius R2, mm", "corner radius R2, mm"],
        ["Aufmaß Länge, mm", "delta length, mm"],
        ["Aufmaß Radius, mm", "delta radius, mm"],
        ["Werkzeugtyp (MILL, DRILL …)", "tool type (MILL, DRILL …)"],
        ["Spitzenwinkel, °", "point angle, °"],
    ][column.min(COLUMNS.len() - 1)];
    Text::new(de, en)
}

/// A column's index in [`COLUMNS`].
const T: usize = 0;
const NAME: usize = 1;
const L: usize = 2;
const R: usize = 3;
const R2: usize = 4;
const DL: usize = 5;
const DR: usize = 6;
const TYP: usize = 7;
const ANGLE: usize = 8;

/// One row as typed.
pub type Row = [String; 9];

/// A cell's problem.
#[derive(Debug, Clone, PartialEq)]
pub struct CellIssue {
    pub row: usize,
    pub column: usize,
    pub message: Text,
}

/// The tool table's part of the page.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolTableState {
    pub rows: Vec<Row>,
    /// The rows' problems ([`check`]); the table is kept only without any.
    pub issues: Vec<CellIssue>,
    /// The shop's table is kept (else the shipped one applies and the rows show it).
    pub own: bool,
    /// What the last action did, or why an import was refused.
    pub message: Option<Text>,
}

/// What the tool table can be asked to do.
#[derive(Debug, Clone, PartialEq)]
pub enum ToolAction {
    /// A cell's new text.
    Set {
        row: usize,
        column: usize,
        text: String,
    },
    /// A new row with the next free number.
    AddRow,
    RemoveRow(usize),
    /// A `TOOL.T` file's bytes.
    Import(Vec<u8>),
    /// Offer the table as `TOOL.T`.
    Export,
    /// Drop the shop's table: the shipped one applies again.
    UseShipped,
}

/// The shop's table kept under [`TOOLS_KEY`]: `Ok(None)` when there is none (the shipped table
/// applies), the reason when the text cannot be read.
///
/// # Errors
/// The stored text is not a tool table.
pub fn read_saved(text: Option<&str>) -> Result<Option<Arc<[ToolEntry]>>, Text> {
    match text.filter(|t| !t.trim().is_empty()) {
        None => Ok(None),
        Some(t) => read_tool_table(t).map(|e| Some(e.into())).map_err(|e| {
            let why = e.text();
            Text::owned(
                format!("Gespeicherte Werkzeugtabelle unlesbar ({}): die mitgelieferte gilt", why.de),
                format!("The saved tool table cannot be read ({}): the shipped one applies", why.en),
            )
        }),
    }
}

fn number_text(v: f64) -> String {
    schwenkbar_core::number::signed(v, 4)
}

/// The row of a tool.
#[must_use]
pub fn row_of(t: &ToolEntry) -> Row {
    let (r2, kind, angle) = t.columns();
    [
        t.number.to_string(),
        t.name.clone(),
        number_text(t.length),
        number_text(t.radius),
        number_text(r2),
        number_text(t.dl),
        number_text(t.dr),
        kind.to_owned(),
        angle.map(number_text).unwrap_or_default(),
    ]
}

/// A cell read as a number (a decimal comma too; empty is 0), or its problem.
fn cell_number(row: &Row, column: usize) -> Result<f64, Text> {
    let text = row[column].trim();
    if text.is_empty() {
        return Ok(0.0);
    }
    parse_f64(&text.replace(',', "."))
        .filter(|v| v.is_finite() && v.abs() <= 99_999.999_9)
        .ok_or_else(|| Text::owned(format!("„{text}“ ist keine Zahl"), format!("\"{text}\" is not a number")))
}

/// The tools of `rows`, or every cell's problem.
///
/// # Errors
/// The cells that are not a tool table's (numbers, T unique 0…32767, R ≥ 0, 0 ≤ R2 ≤ R, the
/// name without blanks and at most 32 characters, T-ANGLE 0…180).
pub fn check(rows: &[Row]) -> Result<Vec<ToolEntry>, Vec<CellIssue>> {
    let mut issues = Vec::new();
    let mut out = Vec::new();
    // The numbers seen so far: a table of 32,768 tools is checked at every key press.
    let mut seen = std::collections::BTreeSet::new();
    for (i, row) in rows.iter().enumerate() {
        let mut bad = |column: usize, message: Text| issues.push(CellIssue { row: i, column, message });
        let t = row[T].trim();
        let number = t.parse::<u32>().ok().filter(|n| *n <= MAX_TOOL_NUMBER);
        match number {
            None => bad(
                T,
                Text::owned(
                    format!("Werkzeugnummer „{t}“ falsch (0 … {MAX_TOOL_NUMBER})"),
                    format!("tool number \"{t}\" is wrong (0 … {MAX_TOOL_NUMBER})"),
                ),
            ),
            Some(n) if !seen.insert(n) => bad(
                T,
                Text::owned(
                    format!("Werkzeug {n} steht zweimal in der Tabelle"),
                    format!("tool {n} is in the table twice"),
                ),
            ),
            Some(_) => {}
        }
        let name = row[NAME].trim();
        if name.chars().any(char::is_whitespace) || name.chars().count() > 32 {
            bad(
                NAME,
                Text::new(
                    "Name ohne Leerzeichen, höchstens 32 Zeichen",
                    "a name without blanks, at most 32 characters",
                ),
            );
        }
        let mut value = |column: usize| cell_number(row, column).map_err(|m| bad(column, m)).ok();
        let [l, r, r2, dl, dr, angle] = [L, R, R2, DL, DR, ANGLE].map(&mut value);
        if r.is_some_and(|r| r < 0.0) {
            bad(R, Text::new("Radius R kleiner 0", "radius R below 0"));
        }
        if let (Some(r), Some(r2)) = (r, r2)
            && !(0.0..=r.max(0.0)).contains(&r2)
        {
            bad(R2, Text::new("R2 muss zwischen 0 und R liegen", "R2 must lie between 0 and R"));
        }
        if angle.is_some_and(|a| !(0.0..180.0).contains(&a)) {
            bad(ANGLE, Text::new("Spitzenwinkel 0 … 180°", "point angle 0 … 180°"));
        }
        let kind = row[TYP].trim();
        if kind.chars().any(char::is_whitespace) {
            bad(
                TYP,
                Text::new("Typ ohne Leerzeichen (MILL, DRILL …)", "a type without blanks (MILL, DRILL …)"),
            );
        }
        if let (Some(number), Some(length), Some(radius), Some(r2), Some(dl), Some(dr), Some(point_angle)) =
            (number, l, r, r2, dl, dr, angle)
        {
            out.push(ToolEntry::from_columns(Columns {
                number,
                name: name.to_owned(),
                length,
                radius,
                r2,
                dl,
                dr,
                kind,
                point_angle,
            }));
        }
    }
    if issues.is_empty() { Ok(out) } else { Err(issues) }
}

impl ToolTableState {
    /// The page's table from what is kept: the shop's table, or the shipped one shown (and not
    /// kept) when there is none; a kept text that cannot be read is said and left in storage,
    /// so nothing is lost until the trainee imports or edits a table.
    #[must_use]
    pub fn start(saved: Option<&str>) -> ToolTableState {
        let (tools, own, message) = match read_saved(saved) {
            Ok(Some(t)) => (t.to_vec(), true, None),
            Ok(None) => (tool_table().to_vec(), false, None),
            Err(why) => (tool_table().to_vec(), false, Some(why)),
        };
        ToolTableState { rows: tools.iter().map(row_of).collect(), issues: Vec::new(), own, message }
    }

    /// The problem of a cell, if any.
    pub fn issue_at(&self, row: usize, column: usize) -> Option<&Text> {
        self.issues.iter().find(|i| i.row == row && i.column == column).map(|i| &i.message)
    }

    /// Checks the rows and keeps the table when it is valid.
    fn keep(&mut self, fx: &mut Vec<Effect>) {
        match check(&self.rows) {
            Ok(tools) => {
                self.issues.clear();
                self.own = true;
                fx.push(Effect::Save { key: TOOLS_KEY, value: write_tool_table(&tools) });
            }
            Err(issues) => self.issues = issues,
        }
    }

    fn import(&mut self, bytes: Vec<u8>, fx: &mut Vec<Effect>) {
        if bytes.len() > MAX_TABLE_BYTES {
            self.message = Some(Text::owned(
                format!("Datei zu groß ({} KB): nicht importiert", bytes.len() / 1024),
                format!("File too large ({} KB): not imported", bytes.len() / 1024),
            ));
            return;
        }
        match read_tool_table(&schwenkbar_core::text::decode(bytes)) {
            Ok(tools) => {
                let n = tools.len();
                self.rows = tools.iter().map(row_of).collect();
                self.keep(fx);
                self.message = Some(Text::owned(
                    format!("Werkzeugtabelle mit {n} Werkzeugen importiert und gespeichert"),
                    format!("Tool table with {n} tools imported and saved"),
                ));
            }
            Err(e) => {
                let why = e.text();
                self.message = Some(Text::owned(
                    format!("Nicht importiert: {}", why.de),
                    format!("Not imported: {}", why.en),
                ));
            }
        }
    }

    /// The next state and its effects.
    #[must_use]
    pub fn apply(&self, action: ToolAction) -> (ToolTableState, Vec<Effect>) {
        let mut next = self.clone();
        let mut fx = Vec::new();
        next.message = None;
        match action {
            ToolAction::Set { row, column, text } => {
                if let Some(cell) = next.rows.get_mut(row).and_then(|r| r.get_mut(column)) {
                    *cell = text;
                    next.keep(&mut fx);
                }
            }
            ToolAction::AddRow => {
                let used: std::collections::BTreeSet<u32> =
                    next.rows.iter().filter_map(|r| r[T].trim().parse().ok()).collect();
                let free = (0..=MAX_TOOL_NUMBER).find(|n| !used.contains(n)).unwrap_or(0);
                let mut row = row_of(&ToolEntry::from_columns(Columns {
                    number: free,
                    name: String::new(),
                    length: 100.0,
                    radius: 5.0,
                    r2: 0.0,
                    dl: 0.0,
                    dr: 0.0,
                    kind: "MILL",
                    point_angle: 0.0,
                }));
                row[NAME] = format!("WERKZEUG_{free}");
                next.rows.push(row);
                next.keep(&mut fx);
            }
            ToolAction::RemoveRow(i) => {
                if i < next.rows.len() {
                    next.rows.remove(i);
                    next.keep(&mut fx);
                }
            }
            ToolAction::Import(bytes) => next.import(bytes, &mut fx),
            ToolAction::Export => match check(&next.rows) {
                Ok(tools) => {
                    fx.push(Effect::SaveFile { name: "TOOL.T".to_owned(), text: write_tool_table(&tools) })
                }
                Err(issues) => {
                    let n = issues.len();
                    next.message = Some(Text::owned(
                        format!("Nicht exportiert: {n} Fehler in der Tabelle"),
                        format!("Not exported: {n} problem(s) in the table"),
                    ));
                }
            },
            ToolAction::UseShipped => {
                next = ToolTableState::start(None);
                fx.push(Effect::Save { key: TOOLS_KEY, value: String::new() });
                next.message = Some(Text::new(
                    "Eigene Werkzeugtabelle gelöscht: die mitgelieferte gilt",
                    "Own tool table deleted: the shipped one applies",
                ));
            }
        }
        (next, fx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn saved(fx: &[Effect]) -> Option<&str> {
        fx.iter().find_map(|e| match e {
            Effect::Save { key: TOOLS_KEY, value } => Some(value.as_str()),
            _ => None,
        })
    }

    #[test]
    fn without_a_kept_table_the_shipped_one_is_shown_and_not_kept() {
        let s = ToolTableState::start(None);
        assert!(!s.own);
        assert_eq!(s.rows.len(), tool_table().len());
        assert_eq!(check(&s.rows).expect("valid"), tool_table());
    }

    #[test]
    fn an_edit_is_kept_as_the_tool_t_text_the_trainer_reads() {
        let s = ToolTableState::start(None);
        let (s, fx) = s.apply(ToolAction::Set { row: 0, column: L, text: "82,5".into() });
        assert!(s.own && s.issues.is_empty());
        let kept = read_saved(saved(&fx)).expect("readable").expect("own table");
        assert_eq!(kept[0].length, 82.5);
        assert_eq!(kept.len(), tool_table().len());
    }

    #[test]
    fn a_wrong_cell_is_said_at_the_cell_and_nothing_is_kept_or_lost() {
        let s = ToolTableState::start(None);
        let (s, fx) = s.apply(ToolAction::Set { row: 1, column: R, text: "4x".into() });
        assert!(saved(&fx).is_none(), "not kept while wrong");
        assert_eq!(s.rows[1][R], "4x", "the typed text stays");
        assert_eq!(s.issue_at(1, R).expect("said").de, "„4x“ ist keine Zahl");
        let (s, _) = s.apply(ToolAction::Set { row: 2, column: T, text: s.rows[0][T].clone() });
        assert!(s.issue_at(2, T).expect("twice").en.contains("is in the table twice"));
        let (s, fx) = s.apply(ToolAction::Export);
        assert!(fx.is_empty() && s.message.is_some(), "not exported while wrong");
    }

    #[test]
    fn import_export_and_back_to_the_shipped_table() {
        let s = ToolTableState::start(None);
        let file = b"BEGIN TOOL .T MM\nT NAME    L    R\n7 SENKER  +60  +8\n[END]\n".to_vec();
        let (s, fx) = s.apply(ToolAction::Import(file));
        assert_eq!(s.rows.len(), 1);
        assert_eq!(s.rows[0][NAME], "SENKER");
        assert!(saved(&fx).is_some_and(|t| t.contains("SENKER")));
        let (s, fx) = s.apply(ToolAction::Export);
        let Some(Effect::SaveFile { name, text }) = fx.first() else { panic!("{fx:?}") };
        assert_eq!(name, "TOOL.T");
        assert_eq!(read_tool_table(text).expect("reads back")[0].radius, 8.0);
        let (broken, fx) = s.apply(ToolAction::Import(b"L X+1\n".to_vec()));
        assert!(fx.is_empty() && broken.rows == s.rows, "a broken file leaves the table");
        assert!(broken.message.expect("said").de.starts_with("Nicht importiert: Zeile 1"));
        let (s, fx) = s.apply(ToolAction::UseShipped);
        assert_eq!(saved(&fx), Some(""));
        assert!(!s.own && s.rows.len() == tool_table().len());
    }

    #[test]
    fn a_corrupt_kept_table_is_said_and_the_shipped_one_applies() {
        let why = read_saved(Some("kaputt")).expect_err("corrupt");
        assert!(why.de.starts_with("Gespeicherte Werkzeugtabelle unlesbar"));
        let s = ToolTableState::start(Some("kaputt"));
        assert!(!s.own && s.message.is_some());
    }

    #[test]
    fn a_new_row_takes_the_next_free_number() {
        let s = ToolTableState::start(None);
        let (s, _) = s.apply(ToolAction::AddRow);
        let numbers: Vec<&str> = s.rows.iter().map(|r| r[T].as_str()).collect();
        assert_eq!(numbers.last(), Some(&"0"), "{numbers:?}");
        assert!(s.issues.is_empty());
    }
}
