//! The control's tool table file `TOOL.T`, read and written.
//!
//! The layout is the one of the control's tables (`.T`, `.D`, `.TCH`): a first line
//! `BEGIN TOOL .T MM` (or `INCH`), a header line naming the columns, one line per tool, and
//! `[END]`. A column starts where its name starts in the header and ends where the next one
//! starts, so values stand in fixed columns (a public shop's `TOOL.T` was read to learn the
//! layout: `T`, `NAME`, `L`, `R`, `DL`, `DR`, … with a decimal comma, names cut to the column's
//! width). Columns used here (TNC user's manuals, "Tool data"; point angle as FN 18 ID50 lists
//! it): `T` number, `NAME`, `L`, `R` (required), `R2` (corner radius: 0 end mill, R ball,
//! between toroid), `DL`, `DR` (deltas the control adds to those of the TOOL CALL), `TYP`
//! (or `TYPE`; `DRILL`, `CENT`, `CSINK` are drills) and `T-ANGLE` (their point angle). Other
//! columns are read past.

use std::fmt::Write as _;

use crate::lang::Text;
use crate::number::{parse_f64, signed};

use super::{ShapeKind, ToolEntry};

/// The largest tool number (TNC user's manuals: "a number between 0 and 32767").
pub const MAX_TOOL_NUMBER: u32 = 32_767;

/// Why a tool table file was not read: the line (1-based, 0 for the whole file) and what.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolTableError {
    pub line: usize,
    pub code: ToolTableErrorCode,
}

#[derive(Debug, Clone, PartialEq)]
pub enum ToolTableErrorCode {
    /// No `BEGIN … .T` line first.
    NoBegin,
    /// No header line after `BEGIN`.
    NoHeader,
    /// A required column (`T`, `L`, `R`) is not in the header.
    MissingColumn(&'static str),
    /// A value that is not a number (column, text).
    NotANumber(String, String),
    /// A value that runs across the start of a column (column): not a table in fixed columns.
    Misaligned(String),
    /// A tool number outside 0…32767, or written twice.
    BadNumber(String),
    Duplicate(u32),
}

impl ToolTableError {
    /// The message in both languages, with the line.
    #[must_use]
    pub fn text(&self) -> Text {
        let (de, en) = match &self.code {
            ToolTableErrorCode::NoBegin => (
                "keine Werkzeugtabelle: die erste Zeile muss „BEGIN … .T MM“ lauten".to_owned(),
                "not a tool table: the first line must read \"BEGIN … .T MM\"".to_owned(),
            ),
            ToolTableErrorCode::NoHeader => {
                ("Spaltenüberschrift fehlt".to_owned(), "the line of column names is missing".to_owned())
            }
            ToolTableErrorCode::MissingColumn(c) => {
                (format!("Spalte {c} fehlt"), format!("column {c} is missing"))
            }
            ToolTableErrorCode::NotANumber(c, v) => {
                (format!("{c}: „{v}“ ist keine Zahl"), format!("{c}: \"{v}\" is not a number"))
            }
            ToolTableErrorCode::Misaligned(c) => (
                format!(
                    "Wert über den Spaltenanfang von {c} hinaus: die Werte müssen unter ihren Spaltennamen stehen"
                ),
                format!("a value runs into column {c}: values must stand under their column names"),
            ),
            ToolTableErrorCode::BadNumber(v) => (
                format!("Werkzeugnummer „{v}“ falsch (0 … {MAX_TOOL_NUMBER})"),
                format!("tool number \"{v}\" is wrong (0 … {MAX_TOOL_NUMBER})"),
            ),
            ToolTableErrorCode::Duplicate(t) => (
                format!("Werkzeug {t} steht zweimal in der Tabelle"),
                format!("tool {t} is in the table twice"),
            ),
        };
        if self.line == 0 {
            Text::owned(de, en)
        } else {
            let l = self.line;
            Text::owned(format!("Zeile {l}: {de}"), format!("line {l}: {en}"))
        }
    }
}

/// A column of the header: its name and where it starts (in characters: a table the control
/// wrote in Latin-1 has one byte per character, its UTF-8 reading not).
struct Column<'a> {
    name: &'a str,
    start: usize,
}

/// The columns of a header line, each from its name to the next name.
fn columns(header: &str) -> Vec<Column<'_>> {
    let mut out = Vec::new();
    let mut start = None;
    let mut offsets = header.char_indices().map(|(i, _)| i).chain(std::iter::once(header.len()));
    for (at, c) in header.chars().chain(std::iter::once(' ')).enumerate() {
        let byte = offsets.next().unwrap_or(header.len());
        match (c.is_whitespace(), start) {
            (false, None) => start = Some((at, byte)),
            (true, Some((s, b))) => {
                out.push(Column { name: &header[b..byte], start: s });
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// The text of column `i` in `line` (trimmed; empty past the line's end).
fn field(line: &[char], cols: &[Column<'_>], i: usize) -> String {
    let from = cols[i].start.min(line.len());
    let to = cols.get(i + 1).map_or(line.len(), |c| c.start.min(line.len()));
    line[from..to.max(from)].iter().collect::<String>().trim().to_owned()
}

/// A tool as the table's columns give it (mm, degrees).
#[derive(Debug, Clone, PartialEq)]
pub struct Columns<'a> {
    pub number: u32,
    pub name: String,
    pub length: f64,
    pub radius: f64,
    /// `R2`: 0 end mill, `R` ball, between: toroid (TNC 640 user's manual, "Permitted tool
    /// shapes").
    pub r2: f64,
    pub dl: f64,
    pub dr: f64,
    /// `TYP`: `DRILL`, `CENT` and `CSINK` have a point (`T-ANGLE`); any other is a mill.
    pub kind: &'a str,
    /// `T-ANGLE`, 0 for none.
    pub point_angle: f64,
}

/// The tool types with a point angle (`T-ANGLE` "for DRILL and CSINK", FN 18 ID50; a centring
/// drill `CENT` too).
const POINTED: [&str; 3] = ["DRILL", "CENT", "CSINK"];

impl ToolEntry {
    /// The tool the table's columns describe.
    #[must_use]
    pub fn from_columns(c: Columns<'_>) -> ToolEntry {
        let drill = POINTED.iter().any(|d| c.kind.eq_ignore_ascii_case(d));
        let (shape, corner_radius, point_angle) = if drill {
            (ShapeKind::Drill, None, (c.point_angle > 0.0).then_some(c.point_angle))
        } else if c.r2 > 0.0 && c.r2 >= c.radius {
            (ShapeKind::Ball, None, None)
        } else if c.r2 > 0.0 {
            (ShapeKind::Bull, Some(c.r2), None)
        } else {
            (ShapeKind::Flat, None, None)
        };
        ToolEntry {
            number: c.number,
            name: c.name,
            length: c.length,
            radius: c.radius,
            shape,
            corner_radius,
            point_angle,
            dl: c.dl,
            dr: c.dr,
        }
    }

    /// `R2`, `TYP` and `T-ANGLE` (none: the drill's default) of the tool, as the table writes them.
    #[must_use]
    pub fn columns(&self) -> (f64, &'static str, Option<f64>) {
        match self.shape {
            ShapeKind::Flat => (0.0, "MILL", None),
            ShapeKind::Ball => (self.radius, "MILL", None),
            ShapeKind::Bull => (self.corner_radius.unwrap_or(0.0), "MILL", None),
            ShapeKind::Drill => (0.0, "DRILL", self.point_angle),
        }
    }
}

/// Reads a `TOOL.T` file. Lengths of an `INCH` table are converted to mm. Rows keep the file's
/// order.
///
/// # Errors
/// The first line that cannot be read, with what is wrong in it.
// Out of line: the page split (scripts/split_pages.py) can leave it to the wasm loaded after the
// first screen, which only asks whether a table is kept.
#[inline(never)]
pub fn read_tool_table(text: &str) -> Result<Vec<ToolEntry>, ToolTableError> {
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let err = |line: usize, code| ToolTableError { line, code };
    let (_, begin) = lines.next().ok_or(err(0, ToolTableErrorCode::NoBegin))?;
    let words: Vec<String> = begin.split_whitespace().map(str::to_ascii_uppercase).collect();
    if words.first().map(String::as_str) != Some("BEGIN") || !words.iter().any(|w| w.ends_with(".T")) {
        return Err(err(1, ToolTableErrorCode::NoBegin));
    }
    let scale = if words.iter().any(|w| w == "INCH") { 25.4 } else { 1.0 };
    let (_, header) = lines.next().ok_or(err(0, ToolTableErrorCode::NoHeader))?;
    let cols = columns(header);
    let find =
        |names: &[&str]| cols.iter().position(|c| names.iter().any(|n| c.name.eq_ignore_ascii_case(n)));
    let [t, l, r] = [("T", &["T"]), ("L", &["L"]), ("R", &["R"])]
        .map(|(name, names)| find(names).ok_or(err(2, ToolTableErrorCode::MissingColumn(name))));
    let (t, l, r) = (t?, l?, r?);
    let (name, r2, dl, dr) = (find(&["NAME"]), find(&["R2"]), find(&["DL"]), find(&["DR"]));
    let (kind, angle) = (find(&["TYP", "TYPE"]), find(&["T-ANGLE"]));
    let mut out: Vec<ToolEntry> = Vec::new();
    for (i, line) in lines {
        let n = i + 1;
        if line.trim_start().starts_with('[') {
            break; // [END]
        }
        let line: Vec<char> = line.chars().collect();
        // Fixed columns: a value may not run across the start of the next column.
        if let Some(c) = cols.iter().skip(1).find(|c| {
            c.start < line.len() && !line[c.start].is_whitespace() && !line[c.start - 1].is_whitespace()
        }) {
            return Err(err(n, ToolTableErrorCode::Misaligned(c.name.to_owned())));
        }
        let number_text = field(&line, &cols, t);
        let number = number_text
            .parse::<u32>()
            .ok()
            .filter(|v| *v <= MAX_TOOL_NUMBER)
            .ok_or_else(|| err(n, ToolTableErrorCode::BadNumber(number_text.clone())))?;
        if out.iter().any(|e| e.number == number) {
            return Err(err(n, ToolTableErrorCode::Duplicate(number)));
        }
        let value = |col: Option<usize>| -> Result<f64, ToolTableError> {
            let Some(c) = col else { return Ok(0.0) };
            let v = field(&line, &cols, c);
            if v.is_empty() {
                return Ok(0.0);
            }
            parse_f64(&v.replace(',', "."))
                .filter(|x| x.is_finite())
                .ok_or_else(|| err(n, ToolTableErrorCode::NotANumber(cols[c].name.to_owned(), v.clone())))
        };
        let kind_text = kind.map(|k| field(&line, &cols, k)).unwrap_or_default();
        out.push(ToolEntry::from_columns(Columns {
            number,
            name: name.map_or_else(String::new, |c| field(&line, &cols, c)),
            length: value(Some(l))? * scale,
            radius: value(Some(r))? * scale,
            r2: value(r2)? * scale,
            dl: value(dl)? * scale,
            dr: value(dr)? * scale,
            kind: &kind_text,
            point_angle: value(angle)?,
        }));
    }
    Ok(out)
}

/// Writes `tools` as a `TOOL.T` file in mm, in fixed columns wide enough for every value
/// (names up to 32 characters, as the control allows), read back by [`read_tool_table`].
#[must_use]
pub fn write_tool_table(tools: &[ToolEntry]) -> String {
    const HEAD: [(&str, usize); 9] = [
        ("T", 6),
        ("NAME", 33),
        ("L", 12),
        ("R", 12),
        ("R2", 12),
        ("DL", 10),
        ("DR", 10),
        ("TYP", 7),
        ("T-ANGLE", 0),
    ];
    let mut out = String::from("BEGIN TOOL    .T    MM\n");
    for (name, width) in HEAD {
        let _ = write!(out, "{name:<width$}");
    }
    out.push('\n');
    let num = |v: f64| signed(v, 4);
    for t in tools {
        let (r2, kind, angle) = t.columns();
        let angle = angle.map(num).unwrap_or_default();
        // Names are cut to the column (32 characters): the control's limit.
        let name: String = t.name.chars().filter(|c| !c.is_whitespace()).take(32).collect();
        let cells = [
            t.number.to_string(),
            name,
            num(t.length),
            num(t.radius),
            num(r2),
            num(t.dl),
            num(t.dr),
            kind.to_owned(),
            angle,
        ];
        for ((_, width), cell) in HEAD.iter().zip(cells) {
            let _ = write!(out, "{cell:<width$}");
        }
        let end = out.trim_end_matches(' ').len();
        out.truncate(end);
        out.push('\n');
    }
    out.push_str("[END]\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A table written here by hand in the control's layout: numbers with a decimal comma, an
    /// unknown column, a drill, a ball and a toroid cutter, an empty slot.
    const TABLE: &str = "BEGIN TOOL    .T       MM\n\
T    NAME             L          R          R2         DL      DR      TL TYP   T-ANGLE CUR.TIME\n\
0                     +0,000     +0,000     +0,000     +0,000  +0,000     MILL  +0      0\n\
3    SCHRUPP_D20      +95,5      +10        +2         +0,1    -0,05      MILL          12\n\
8    BOHRER_D8        +120       +4         +0         +0      +0         DRILL +140    0\n\
12   FRÄSER_D6        +80        +3         +3         +0      +0         MILL          0\n\
14                    -4,686     +7,000\n\
[END]\n";

    #[test]
    fn a_table_in_fixed_columns_is_read() {
        let t = read_tool_table(TABLE).expect("read");
        assert_eq!(t.iter().map(|e| e.number).collect::<Vec<_>>(), [0, 3, 8, 12, 14]);
        let rough = &t[1];
        assert_eq!((rough.name.as_str(), rough.length, rough.radius), ("SCHRUPP_D20", 95.5, 10.0));
        assert_eq!(
            (rough.shape, rough.corner_radius, rough.dl, rough.dr),
            (ShapeKind::Bull, Some(2.0), 0.1, -0.05)
        );
        assert_eq!((t[2].shape, t[2].point_angle), (ShapeKind::Drill, Some(140.0)));
        assert_eq!((t[3].name.as_str(), t[3].length, t[3].shape), ("FRÄSER_D6", 80.0, ShapeKind::Ball));
        assert_eq!(
            (t[4].name.as_str(), t[4].length, t[4].radius, t[4].shape),
            ("", -4.686, 7.0, ShapeKind::Flat)
        );
    }

    #[test]
    fn written_tables_read_back_the_same() {
        let t = read_tool_table(TABLE).expect("read");
        let again = read_tool_table(&write_tool_table(&t)).expect("read back");
        assert_eq!(again, t);
        let shipped = super::super::tool_table();
        assert_eq!(read_tool_table(&write_tool_table(shipped)).expect("shipped"), shipped);
    }

    #[test]
    fn an_inch_table_is_converted_to_mm() {
        let t = read_tool_table("BEGIN TOOL.T INCH\nT NAME L  R\n1 A    +4 +0,25\n").expect("read");
        assert_eq!((t[0].length, t[0].radius), (101.6, 6.35));
    }

    #[test]
    fn broken_tables_say_the_line_and_what() {
        let e = |s: &str| read_tool_table(s).expect_err(s).text();
        assert_eq!(
            e("L X+10\n").de,
            "Zeile 1: keine Werkzeugtabelle: die erste Zeile muss „BEGIN … .T MM“ lauten"
        );
        assert_eq!(e("").en, "not a tool table: the first line must read \"BEGIN … .T MM\"");
        assert_eq!(e("BEGIN TOOL .T MM\nT NAME R\n").en, "line 2: column L is missing");
        assert_eq!(e("BEGIN TOOL .T MM\nT L  R\n1 +1 x\n").de, "Zeile 3: R: „x“ ist keine Zahl");
        assert_eq!(e("BEGIN TOOL .T MM\nT L  R\n1 inf +1\n").en, "line 3: L: \"inf\" is not a number");
        assert_eq!(
            e("BEGIN TOOL .T MM\nT     L  R\n40000 +1 +1\n").de,
            "Zeile 3: Werkzeugnummer „40000“ falsch (0 … 32767)"
        );
        assert_eq!(
            e("BEGIN TOOL .T MM\nT L  R\n1 +1 +1\n1 +2 +2\n").en,
            "line 4: tool 1 is in the table twice"
        );
        assert_eq!(
            e("BEGIN TOOL .T MM\nT L R\n1 +10 +5\n").en,
            "line 3: a value runs into column R: values must stand under their column names"
        );
    }
}
