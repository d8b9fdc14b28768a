//! `schwenkbar`: the command-line face of `schwenkbar-core`. A thin dispatcher: one module per
//! subcommand.

mod check;
mod fmt;
mod input;
mod machine_arg;
mod machines;
mod run;
mod solve;

use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

#[derive(Parser)]
#[command(
    name = "schwenkbar",
    version,
    about = "HEIDENHAIN Klartext tools: check and format NC programs, solve PLANE blocks"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Language of the diagnostic messages.
#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum LangArg {
    De,
    En,
}

impl From<LangArg> for schwenkbar_core::Lang {
    fn from(l: LangArg) -> Self {
        match l {
            LangArg::De => schwenkbar_core::Lang::De,
            LangArg::En => schwenkbar_core::Lang::En,
        }
    }
}

#[derive(Subcommand)]
enum Command {
    /// Parse a program and print `FILE:LINE:COL: error|warning: message`; exit 1 on errors.
    Check(check::Args),
    /// Print the program in canonical form (`--check`: exit 1 if it is not).
    Fmt(fmt::Args),
    /// Run a program on a machine block by block: axes, tool tip, active plane, messages.
    Run(run::Args),
    /// Solve one PLANE block for a machine: candidates, the control's choice and why, as JSON.
    Solve(solve::Args),
    /// List the shipped machine ids (`--json`: full descriptions).
    Machines(machines::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Check(a) => check::run(&a),
        Command::Fmt(a) => fmt::run(&a),
        Command::Run(a) => run::run(&a),
        Command::Solve(a) => solve::run(&a),
        Command::Machines(a) => machines::run(&a),
    }
}
