#!/usr/bin/env bash
# Benchmarks (release builds; they print figures, they do not pass or fail on time).
#   Parser: MB/s, peak memory / file size, 10x scaling ratio (issue 3; budgets of issue 16:
#   >= 300 MB/s, peak <= 2x the file); 10,000,000 mutated inputs of every family, 0 panics
#   (issue 30). CLI (issue 16): `schwenkbar check` end to end on the 44 MB
#   program (>= 200 MB/s) and `schwenkbar run` on 100,000 blocks (table and --json), whole process.
#   Solver: solves/s from orientation to chosen axis positions, budget ≥ 1,000,000/s (issue 4).
#   Simulator: blocks/s on the 1,000,000-block program (≥ 1,000,000), state_at latency (issue 5).
#   Stock: time to cut Musterprogramm 1 at 0.25 mm (≤ 300 ms), its memory (≤ 64 MB) and the worst
#   animation frame's cutting and meshing natively; in the browser the whole cut (≤ 1 s) and block 13
#   animated at 1920×1080, worst and mean frame (≤ 8 ms) (issue 14). The real 5-axis CAM class cut
#   at 0.25 mm natively (≤ 1 s) and in the browser (≤ 2 s) (issue 32).
#   Command line: `run` and `check` on 100,000 blocks against the JS peer tnc-sim, when
#   TNC_SIM_DIR names a checkout of it (scripts/bench_peer.sh; issue 16).
#   Browser: key press → updated screen, Musterprogramm 1 and 100,000 blocks (issue 6); IMPORT of
#   1,000,000 blocks → first screen, stepping and jumping there, a keystroke in the 100,000-block
#   text editor (issue 16); the bundle size, and a cold load of the built trainer: first paint
#   and program shown (<= 800 ms, issue 29).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >/dev/null
# shellcheck source=scripts/env.sh
source scripts/env.sh
cargo run --release -p schwenkbar-core --example bench_parse
cargo run --release -p schwenkbar-core --example fuzz_parse
cargo build --release -p schwenkbar
cargo run --release -p schwenkbar --example bench_cli
cargo run --release -p schwenkbar-core --example bench_solve
cargo run --release -p schwenkbar-core --example bench_sim
cargo run --release -p schwenkbar-core --example bench_stock
cargo run --release -p schwenkbar-app --example bench_edit
bash scripts/bench_peer.sh
wasm_env cargo test --release --target wasm32-unknown-unknown -p schwenkbar-tests --test browser_latency --test browser_big --test browser_render --test browser_stock -- --nocapture \
  2>&1 | grep -E 'BENCH|test result'
bash scripts/bundle.sh 2>/dev/null | grep -E '^bundle|page:|then'
python3 scripts/cold_load.py
