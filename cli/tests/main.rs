//! The CLI's integration tests, one binary (each file a module): the CLI is linked once.

mod cli;
mod machine_file;
mod run;
mod run_fixtures;
mod solve;
