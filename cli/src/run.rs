//! `schwenkbar run FILE.h --machine ID|FILE.json [--tools TOOL.T] [--json] [--lang de|en] [--stock-stl OUT.stl]`: one row
//! per executed block; with `--stock-stl` also the stock after the run as binary STL. A rapid or
//! a swivel that runs the tool into the blank's material is a collision, said on stderr as
//! `FILE:LINE: message` (and in the JSON on its state) whether or not the stock is written.

use std::collections::BTreeMap;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use schwenkbar_core::Lang;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::number::{FIXED_MAX, fixed_ascii, tidy, write_fixed};
use schwenkbar_core::sim::{
    ListingRow, Note, SimOptions, Simulation, State, pick_machine, simulate, simulate_listed,
    tools::read_tool_table,
};
use schwenkbar_core::stock::{Collisions, Cutting, StockMesh, StockNote, StockOptions};
use schwenkbar_core::{Program, Text, parse};
use serde::Serialize;

use crate::LangArg;

#[derive(clap::Args)]
pub(crate) struct Args {
    /// The NC program (`.h`, UTF-8 or Latin-1).
    file: PathBuf,
    /// Machine id (ac-table, ba-table, bc-head-table, ca-head, b45-nutating), `auto` (the shipped
    /// machine with the program's rotary axes on which the run gets furthest, said on stderr) or a machine
    /// description `.json` file.
    #[arg(long)]
    machine: String,
    /// Print `{"machine", "states": […], "error": null | {"line", "message"}}`.
    #[arg(long)]
    json: bool,
    /// Language of the messages.
    #[arg(long, value_enum, default_value = "de")]
    lang: LangArg,
    /// Stop after this many executed blocks (endless loops); default: the simulator's budget.
    #[arg(long)]
    max_blocks: Option<usize>,
    /// Cut the BLK FORM blank with every motion and write the stock after the run (binary STL,
    /// W-CS, mm).
    #[arg(long, value_name = "OUT.stl")]
    stock_stl: Option<PathBuf>,
    /// The shop's tool table, the control's `TOOL.T` file: it replaces the shipped table (a tool
    /// it lacks runs with the default tool, said on its TOOL CALL).
    #[arg(long, value_name = "TOOL.T")]
    tools: Option<PathBuf>,
    /// Ray spacing of the stock, mm.
    #[arg(long, default_value_t = StockOptions::default().resolution, value_name = "MM")]
    stock_resolution: f64,
}

/// Rounds away float noise (1e-9) and `-0` for printing.
fn num(x: f64) -> f64 {
    tidy(x, 9)
}

/// The first line of a block's source text.
fn block_text<'a>(src: &'a str, program: &Program, block: usize) -> &'a str {
    program
        .blocks
        .get(block)
        .and_then(|b| src.get(b.span().start..b.span().end))
        .and_then(|t| t.lines().next())
        .unwrap_or("")
        .trim()
}

#[derive(Serialize)]
struct JsonPlane {
    spatial: [f64; 3],
    tool_axis: [f64; 3],
}

#[derive(Serialize)]
struct JsonState<'a> {
    line: u32,
    number: Option<u32>,
    block: &'a str,
    axes: Axes,
    tool_tip_wcs: [f64; 3],
    plane: Option<JsonPlane>,
    q: BTreeMap<String, f64>,
    message: Option<String>,
    /// The tool ran into the material (a rapid or a swivel): the collision's message.
    #[serde(skip_serializing_if = "Option::is_none")]
    collision: Option<&'a str>,
}

#[derive(Serialize)]
struct JsonError<'a> {
    line: u32,
    message: &'a str,
    detail: &'a str,
}

/// `{"X": …, "Y": …, "Z": …, "A": …, "C": …}` in the control's display order.
struct Axes(Vec<(char, f64)>);

impl Serialize for Axes {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = ser.serialize_map(Some(self.0.len()))?;
        for (c, v) in &self.0 {
            m.serialize_entry(&c.to_string(), v)?;
        }
        m.end()
    }
}

fn axes_map(s: &State) -> Axes {
    Axes(s.axes.named().into_iter().map(|(c, v)| (c, num(v))).collect())
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let src = match crate::input::read_or_report(&args.file) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let (program, _) = parse(&src);
    let lang = Lang::from(args.lang);
    let tools = match &args.tools {
        None => None,
        Some(path) => match crate::input::read(path).and_then(|t| {
            read_tool_table(&t).map_err(|e| format!("{}: {}", path.display(), e.text().get(lang)))
        }) {
            Ok(t) => Some(t.into()),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        },
    };
    let opts = SimOptions { max_steps: args.max_blocks, tools, ..SimOptions::default() };
    // `auto` has run the program on its machine already: the JSON output takes that run.
    let mut picked: Option<Simulation> = None;
    let machine = if args.machine == "auto" {
        // Every shipped machine is a candidate; which one and why goes to stderr, so the table
        // and the JSON stay what they are for a named machine.
        let all: Vec<Machine> =
            Machine::builtin_ids().iter().filter_map(|id| Machine::builtin(id).ok()).collect();
        if all.is_empty() {
            eprintln!("error: no shipped machine");
            return ExitCode::from(2);
        }
        let pick = pick_machine(&program, &all, &opts);
        eprintln!("note: {}", pick.reason.get(lang));
        let machine = all.into_iter().nth(pick.index).unwrap_or_else(|| pick.simulation.machine.clone());
        picked = Some(pick.simulation);
        machine
    } else {
        match crate::machine_arg::load(&args.machine) {
            Ok(m) => m,
            Err(e) => {
                e.lines().for_each(|line| eprintln!("error: {line}"));
                return ExitCode::from(2);
            }
        }
    };

    let stock_options = StockOptions {
        resolution: args.stock_resolution.max(COLLISION_RESOLUTION),
        ..StockOptions::default()
    };
    let (sim, written, collisions) = if args.json {
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        let sim = picked.unwrap_or_else(|| simulate(&program, &machine, &opts));
        let collisions = Cutting::collisions(&program, &sim, stock_options, COLLISION_WORK);
        let written = write_json(&mut out, &src, &program, &machine, &sim, &collisions.notes, lang)
            .and_then(|()| out.flush());
        (sim, written, collisions)
    } else {
        let (sim, written) =
            write_table(std::io::stdout(), &src, &program, &machine, &opts, lang, &args.file);
        // `--stock-stl` cuts the whole run and says its notes, these among them.
        let collisions = if args.stock_stl.is_none() {
            Cutting::collisions(&program, &sim, stock_options, COLLISION_WORK)
        } else {
            Collisions::default()
        };
        (sim, written, collisions)
    };
    if let Err(e) = written {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    if args.stock_stl.is_none() {
        say_notes(&args.file, &program, &collisions.notes, lang);
        if let (Some((_, block)), Some(text)) = (collisions.unchecked, collisions.unchecked_message()) {
            let line = program.blocks.get(block).map_or(0, |b| b.line());
            eprintln!("{}:{line}: {} (--stock-stl)", args.file.display(), text.get(lang));
        }
    }
    if let Some(path) = &args.stock_stl
        && let Err(e) = write_stock(path, args, &program, &sim)
    {
        eprintln!("error: {}: {e}", path.display());
        return ExitCode::from(2);
    }
    if sim.error.is_some() { ExitCode::from(1) } else { ExitCode::SUCCESS }
}

/// A length with its sign, at most 3 decimals (`+0`, `-40`, `+12.5`).
fn signed(v: f64) -> String {
    format!("{:+}", tidy(v, 3))
}

/// Rays the material check may cut when the stock is not written (about a second): a run that
/// rapids into its blank early is checked in full, a long CAM program as far as this reaches,
/// and where it stopped is said. `--stock-stl` cuts everything.
const COLLISION_WORK: usize = 3_000_000;

/// The material check's ray spacing when the stock is not written (mm), unless
/// `--stock-resolution` asks for a coarser one: a tool that runs into the material meets rays
/// 1 mm apart as surely as 0.25 mm apart, at a sixteenth of the rays and a quarter of the
/// swivel's sub-moves; only a graze of less than a millimetre between two rays goes unseen.
const COLLISION_RESOLUTION: f64 = 1.0;

/// Rows in one message from the simulation to the table writer: few enough to start writing
/// at once, enough that the channel costs nothing per row.
const BATCH: usize = 1024;

/// The table of a run. The simulation goes on while a second thread formats and writes the
/// rows it has listed (a third of a 100,000-block run's time is the table), in the program's
/// order: one writer, one queue. The first write error is kept; the run goes on (its result
/// decides the exit code).
fn write_table<W: Write + Send>(
    out: W,
    src: &str,
    program: &Program,
    machine: &Machine,
    opts: &SimOptions,
    lang: Lang,
    file: &std::path::Path,
) -> (Simulation, std::io::Result<()>) {
    std::thread::scope(|scope| {
        let (rows, queue) = std::sync::mpsc::sync_channel::<Vec<ListingRow>>(8);
        let writer = scope.spawn(move || {
            let mut out = std::io::BufWriter::new(out);
            let mut table = Table::new(&mut out, src, lang);
            let mut written = Ok(());
            for row in queue.iter().flatten() {
                if written.is_ok() {
                    written = table.write(program, &row);
                }
            }
            let head_written = table.head_written;
            (out, head_written, written)
        });
        let mut batch = Vec::with_capacity(BATCH);
        let sim = simulate_listed(
            program,
            machine,
            opts,
            Some(&mut |row: ListingRow| {
                batch.push(row);
                if batch.len() == BATCH {
                    // Only fails when the writer is gone, which the join below reports.
                    let _ = rows.send(std::mem::replace(&mut batch, Vec::with_capacity(BATCH)));
                }
            }),
        );
        let _ = rows.send(batch);
        drop(rows);
        let (mut out, head_written, written) =
            writer.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        let written = written.and_then(|()| {
            let mut table = Table { head_written, ..Table::new(&mut out, src, lang) };
            table.finish(&sim, file)?;
            out.flush()
        });
        (sim, written)
    })
}

/// Cuts the run's blank and writes the final stock as a closed STL mesh (every edge in two
/// triangles: [`StockMesh::closed`]); the stock's notes go to stderr as
/// `FILE:LINE: message`, then one summary line.
fn write_stock(
    path: &std::path::Path,
    args: &Args,
    program: &Program,
    sim: &Simulation,
) -> std::io::Result<()> {
    let options = StockOptions { resolution: args.stock_resolution, ..StockOptions::default() };
    let cutting = Cutting::new(program, sim, options);
    say_notes(&args.file, program, &cutting.notes, Lang::from(args.lang));
    let Some(stock) = cutting.final_stock() else {
        return Err(std::io::Error::other("no BLK FORM blank with a volume: no stock to write"));
    };
    let mesh = StockMesh::closed(&stock);
    std::fs::write(path, mesh.to_stl())?;
    let (min, max) = stock.bounds();
    let blank = (max - min).element_product();
    // The box around what is left (W-CS, mm): how deep the part was cut, where it was cut away.
    let left = stock.material_bounds().map_or_else(
        || "nothing left".to_owned(),
        |(lo, hi)| {
            let range = |k: usize| format!("{}…{}", signed(lo[k]), signed(hi[k]));
            format!("material left X{} Y{} Z{}", range(0), range(1), range(2))
        },
    );
    eprintln!(
        "stock: {:.0} mm³ of {:.0} mm³ removed, {left}, {} mm rays, {} triangles",
        blank - stock.volume(),
        blank,
        tidy(stock.resolution(), 4),
        mesh.triangles()
    );
    Ok(())
}

/// The stock's notes on stderr, `FILE:LINE: message`, as a compiler says its warnings.
fn say_notes(file: &std::path::Path, program: &Program, notes: &[StockNote], lang: Lang) {
    for note in notes {
        let line = program.blocks.get(note.block).map_or(0, |b| b.line());
        eprintln!("{}:{line}: {}", file.display(), note.message().get(lang));
    }
}

fn json_state<'a>(
    src: &'a str,
    program: &Program,
    s: &'a State,
    collision: Option<&'a str>,
    lang: Lang,
) -> JsonState<'a> {
    JsonState {
        line: s.line,
        number: program.blocks.get(s.block).and_then(|b| b.number()),
        block: block_text(src, program, s.block),
        axes: axes_map(s),
        tool_tip_wcs: s.tip_wcs.to_array().map(num),
        plane: s
            .plane
            .as_ref()
            .map(|p| JsonPlane { spatial: p.spatial.map(num), tool_axis: p.tool_axis.map(num) }),
        q: s.q.iter().map(|(k, v)| (k.to_string(), num(*v))).collect(),
        message: s.message().map(|m| m.get(lang).to_owned()),
        collision,
    }
}

/// The JSON report, streamed state by state (a million-block run never sits in memory twice).
fn write_json(
    out: &mut impl Write,
    src: &str,
    program: &Program,
    machine: &Machine,
    sim: &Simulation,
    collisions: &[StockNote],
    lang: Lang,
) -> std::io::Result<()> {
    write!(out, "{{\"machine\":{},\"states\":[", serde_json::to_string(&machine.id)?)?;
    let texts: Vec<(usize, Text)> = collisions.iter().map(|n| (n.step, n.message())).collect();
    for (i, s) in sim.states(program).enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        let collision = texts.iter().find(|(step, _)| *step == s.step).map(|(_, t)| t.get(lang));
        serde_json::to_writer(&mut *out, &json_state(src, program, &s, collision, lang))?;
    }
    let error = sim.error.as_ref().map(|e| JsonError {
        line: e.line,
        message: e.message.get(lang),
        detail: e.detail.get(lang),
    });
    writeln!(out, "],\"error\":{}}}", serde_json::to_string(&error)?)
}

/// One row per executed block, written as the run makes it (one pass: the run is not repeated
/// for the listing). Rows are written into one reused buffer with the exact fixed-point writer
/// (`write_fixed`, the same bytes as `{:.4}`): a 100,000-block run spent most of its time in
/// `format!` of floats and in per-row allocations.
struct Table<'a, W: Write> {
    out: &'a mut W,
    src: &'a str,
    lang: Lang,
    row: Vec<u8>,
    cell: String,
    head_written: bool,
}

impl<'a, W: Write> Table<'a, W> {
    fn new(out: &'a mut W, src: &'a str, lang: Lang) -> Self {
        Table {
            out,
            src,
            lang,
            row: Vec::with_capacity(256),
            cell: String::with_capacity(32),
            head_written: false,
        }
    }

    /// The head line; the axis columns are the machine's axes in the first row.
    fn head(&mut self, letters: &[(char, f64)]) -> std::io::Result<()> {
        self.head_written = true;
        let mut head = format!("{:>5}  {:<44}", "line", "block");
        for (c, _) in letters {
            head.push_str(&format!(" {c:>10}"));
        }
        head.push_str(&format!("  {:<26}  message", "SPA/SPB/SPC"));
        writeln!(self.out, "{head}")
    }

    fn write(&mut self, program: &Program, s: &ListingRow) -> std::io::Result<()> {
        let axes = s.axes.named();
        if !self.head_written {
            self.head(&axes)?;
        }
        let Table { row, cell, .. } = self;
        row.clear();
        let line = itoa(cell, s.line).as_bytes();
        pad(row, 5usize.saturating_sub(line.len()));
        row.extend_from_slice(line);
        row.extend_from_slice(b"  ");
        let text = block_text(self.src, program, s.block);
        // Block text is ASCII but for comments: counted by bytes then, by chars otherwise.
        let (shown, width) = if text.is_ascii() {
            let shown = &text[..text.len().min(44)];
            (shown, shown.len())
        } else {
            let shown = text.char_indices().nth(44).map_or(text, |(i, _)| &text[..i]);
            (shown, shown.chars().count())
        };
        row.extend_from_slice(shown.as_bytes());
        pad(row, 44 - width);
        let mut digits = [0; FIXED_MAX];
        for (_, v) in axes {
            column(row, &mut digits, cell, v);
        }
        row.extend_from_slice(b"  ");
        let start = row.len();
        match s.spatial {
            Some(spatial) => {
                for (i, a) in spatial.iter().enumerate() {
                    if i > 0 {
                        row.push(b' ');
                    }
                    row.extend_from_slice(fixed4(&mut digits, cell, *a, true));
                }
            }
            None => row.push(b'-'),
        }
        // Numbers are ASCII: bytes are columns.
        pad(row, 26usize.saturating_sub(row.len() - start));
        if let Some(m) = s.note.as_ref().map(Note::text) {
            row.extend_from_slice(b"  ");
            row.extend_from_slice(m.get(self.lang).as_bytes());
        }
        self.out.write_all(row.trim_ascii_end())?;
        self.out.write_all(b"\n")
    }

    /// After the last row: the head if there was no row, and the run's error.
    fn finish(&mut self, sim: &Simulation, file: &std::path::Path) -> std::io::Result<()> {
        if !self.head_written {
            self.head(&[])?;
        }
        if let Some(e) = &sim.error {
            let lang = self.lang;
            writeln!(
                self.out,
                "{}:{}: {}: {}",
                file.display(),
                e.line,
                e.message.get(lang),
                e.detail.get(lang)
            )?;
        }
        Ok(())
    }
}

/// `n` in decimal, written into `buf` (cleared first).
fn itoa(buf: &mut String, n: u32) -> &str {
    buf.clear();
    let _ = std::fmt::Write::write_fmt(buf, format_args!("{n}"));
    buf
}

/// `value` (float noise tidied) with 4 decimals, the bytes of `{:.4}` (`plus`: `{:+.4}`).
fn fixed4<'b>(digits: &'b mut [u8; FIXED_MAX], cell: &'b mut String, value: f64, plus: bool) -> &'b [u8] {
    let value = num(value);
    match fixed_ascii(digits, value, 4, plus) {
        Some(text) => text,
        None => {
            cell.clear();
            write_fixed(cell, value, 4, plus);
            cell.as_bytes()
        }
    }
}

/// An axis column: a blank and `value` as `{:>10.4}` writes it.
fn column(row: &mut Vec<u8>, digits: &mut [u8; FIXED_MAX], cell: &mut String, value: f64) {
    let text = fixed4(digits, cell, value, false);
    row.push(b' ');
    pad(row, 10usize.saturating_sub(text.len()));
    row.extend_from_slice(text);
}

/// `n` blanks.
fn pad(row: &mut Vec<u8>, n: usize) {
    const BLANKS: &[u8; 48] = b"                                                ";
    let mut n = n;
    while n > 0 {
        let k = n.min(BLANKS.len());
        row.extend_from_slice(&BLANKS[..k]);
        n -= k;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_columns_are_what_the_standard_formatter_writes() {
        let values = [
            0.0,
            -0.0,
            1e-12,
            -1e-12,
            0.00005,
            -0.00005,
            12.34565,
            359.99999,
            -1234.5678,
            123456.78915,
            -123456.78915,
            1e20,
            f64::NAN,
            f64::INFINITY,
        ];
        for v in values {
            let mut row = Vec::new();
            column(&mut row, &mut [0; FIXED_MAX], &mut String::new(), v);
            assert_eq!(String::from_utf8(row).unwrap(), format!(" {:>10.4}", num(v)), "{v:e}");
        }
    }
}
