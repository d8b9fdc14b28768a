//! `schwenkbar machines [FILE.json…] [--json]`: the shipped machines (issue 4), or the given
//! machine descriptions checked (issue 17: an instructor tries a file before a class).

use std::process::ExitCode;

use schwenkbar_core::machine::Machine;

#[derive(clap::Args)]
pub(crate) struct Args {
    /// Machine descriptions to check instead of the shipped machines; every problem of a
    /// broken one is printed (German, then English) and the exit code is 2.
    files: Vec<String>,
    /// Print the full validated machine descriptions as a JSON array.
    #[arg(long)]
    json: bool,
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let mut machines = Vec::new();
    if args.files.is_empty() {
        for id in Machine::builtin_ids() {
            match Machine::builtin(id) {
                Ok(m) => machines.push(m),
                Err(e) => {
                    eprintln!("schwenkbar machines: {id}: {e}");
                    return ExitCode::from(2);
                }
            }
        }
    }
    let mut broken = false;
    for file in &args.files {
        match crate::machine_arg::load(file) {
            Ok(m) => machines.push(m),
            Err(e) => {
                eprintln!("{e}");
                broken = true;
            }
        }
    }
    if broken {
        return ExitCode::from(2);
    }
    if args.json {
        match serde_json::to_string_pretty(&machines) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("schwenkbar machines: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        for m in &machines {
            println!("{}", m.id);
        }
    }
    ExitCode::SUCCESS
}
