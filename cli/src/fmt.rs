//! `schwenkbar fmt FILE.h [--check]`.

use std::path::PathBuf;
use std::process::ExitCode;

use schwenkbar_core::{format_program, parse};

#[derive(clap::Args)]
pub(crate) struct Args {
    /// The NC program (`.h`, UTF-8 or Latin-1).
    file: PathBuf,
    /// Print nothing; exit 1 if the file is not in canonical form.
    #[arg(long)]
    check: bool,
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let src = match crate::input::read_or_report(&args.file) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let formatted = format_program(&parse(&src).0);
    if args.check {
        if formatted == src {
            return ExitCode::SUCCESS;
        }
        eprintln!("{}: not in canonical form", args.file.display());
        return ExitCode::from(1);
    }
    print!("{formatted}");
    ExitCode::SUCCESS
}
