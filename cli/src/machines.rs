//! `schwenkbar machines [--json]`: the shipped machines (issue 4).

use std::process::ExitCode;

use schwenkbar_core::machine::Machine;

#[derive(clap::Args)]
pub(crate) struct Args {
    /// Print the full validated machine descriptions as a JSON array.
    #[arg(long)]
    json: bool,
}

pub(crate) fn run(args: &Args) -> ExitCode {
    let mut machines = Vec::new();
    for id in Machine::builtin_ids() {
        match Machine::builtin(id) {
            Ok(m) => machines.push(m),
            Err(e) => {
                eprintln!("schwenkbar machines: {id}: {e}");
                return ExitCode::from(2);
            }
        }
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
