//! Core's integration tests, one binary: each file is a module (one idea per file, its oracle
//! said at its top). One binary links core once instead of once per file, which was most of the
//! native tests' build time.

mod support;

mod arcs;
mod collision;
mod compensation;
mod cycles;
mod errors;
mod fast_path;
mod kinematics;
mod lenient;
mod machine_def;
mod notes;
mod oracles;
mod parse_stops;
mod plane_oracles;
mod properties;
mod proptest_parse;
mod real_programs;
mod sim;
mod sim_properties;
mod stock;
mod tcpm;
