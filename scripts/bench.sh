#!/usr/bin/env bash
# Benchmarks (release build). Parser: MB/s, peak memory / file size, 10x scaling ratio (issue 3).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run --release -p schwenkbar-core --example bench_parse
# Simulator: blocks/s on the 1,000,000-block program (≥ 1,000,000), state_at for a late block (issue 5).
cargo run --release -p schwenkbar-core --example bench_sim
