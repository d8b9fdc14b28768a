#!/usr/bin/env bash
# Benchmarks (release build). Parser: MB/s, peak memory / file size, 10x scaling ratio (issue 3).
# Solver: solves/s from orientation to chosen axis positions, budget ≥ 1,000,000/s (issue 4).
# Simulator: blocks/s on the 1,000,000-block program (≥ 1,000,000), state_at latency (issue 5).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run --release -p schwenkbar-core --example bench_parse
cargo run --release -p schwenkbar-core --example bench_solve
cargo run --release -p schwenkbar-core --example bench_sim
