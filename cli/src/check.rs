//! `schwenkbar check FILE.h [--json] [--lang de|en]`.

use std::path::PathBuf;
use std::process::ExitCode;

use schwenkbar_core::{Lang, parse};
use serde::Serialize;

use crate::LangArg;

#[derive(clap::Args)]
pub(crate) struct Args {
    /// The NC program (`.h`, UTF-8 or Latin-1).
    file: PathBuf,
    /// Print `{"blocks": N, "diagnostics": [{"line", "column", "severity", "message"}]}`.
    #[arg(long)]
    json: bool,
    /// Language of the messages.
    #[arg(long, value_enum, default_value = "de")]
    lang: LangArg,
}

#[derive(Serialize)]
struct JsonDiag {
    line: u32,
    column: u32,
    severity: &'static str,
    message: String,
}

#[derive(Serialize)]
struct JsonReport {
    blocks: usize,
    diagnostics: Vec<JsonDiag>,
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let src = match crate::input::read_or_report(&args.file) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let lang = Lang::from(args.lang);
    let (program, diags) = parse(&src);
    if args.json {
        let report = JsonReport {
            blocks: program.blocks.len(),
            diagnostics: diags
                .iter()
                .map(|d| JsonDiag {
                    line: d.line,
                    column: d.column,
                    severity: d.severity.as_str(),
                    message: d.message(lang),
                })
                .collect(),
        };
        match serde_json::to_string(&report) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        let name = args.file.display();
        for d in &diags {
            println!("{name}:{}:{}: {}: {}", d.line, d.column, d.severity.as_str(), d.message(lang));
        }
    }
    if diags.iter().any(schwenkbar_core::Diagnostic::is_error) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
