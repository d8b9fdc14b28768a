#!/usr/bin/env bash
# The crate boundaries ARCHITECTURE.md promises, checked (run by scripts/test.sh):
# - core and app have no browser in them: no yew, web-sys, js-sys, wasm-bindgen, gloo among
#   their dependencies (cargo tree, normal dependencies);
# - web renders and carries out effects only: it never parses, solves or simulates (those
#   calls belong to core, driven by app);
# - no str::parse::<f64> in the wasm crates but number.rs's own test (the tables it pulls in);
# - the simulator's notes are worded in one place (core/src/sim/note.rs), not where a block runs.
set -euo pipefail
cd "$(dirname "$0")/.."
fail=0
for crate in schwenkbar-core schwenkbar-app; do
  browser=$(cargo tree --offline -q -p "$crate" -e normal --prefix none 2>/dev/null \
    | grep -E '^(yew|web-sys|js-sys|wasm-bindgen|gloo)[ -]' | sort -u || true)
  if [ -n "$browser" ]; then
    echo "boundary: $crate depends on the browser: $browser"
    fail=1
  fi
done
# Calls of the core's parser, solver or simulator (not other functions of those modules, such
# as the formatters solve::axis_words or solve::fmt_deg).
calls=$(grep -rnE 'schwenkbar_core::parse\s*\(|schwenkbar_core::(parse|parse_value)\b\s*[,;}]|\b(simulate|solve|solve_block)\s*\(|schwenkbar_core::(sim::simulate|solve::(solve|solve_block))\b' web/src || true)
if [ -n "$calls" ]; then
  echo "boundary: web calls parse, solve or simulate (app's job):"
  echo "$calls"
  fail=1
fi
# The standard library's float parsing carries 13 KB gzip of tables into the wasm
# (core/src/number.rs): text becomes f64 through number::parse_f64 everywhere else.
floats=$(grep -rnE 'parse::<f(32|64)>' core/src app/src web/src | grep -v '^core/src/number.rs:' || true)
if [ -n "$floats" ]; then
  echo "boundary: str::parse::<f64> outside core/src/number.rs (use number::parse_f64):"
  echo "$floats"
  fail=1
fi
# The simulator records typed notes (core/src/sim/note.rs) and errors (error.rs); it words no
# sentence where it runs a block, so each wording is in one place.
words=$(grep -rnE 'Text::(new|owned|same)|Text \{' core/src/sim/interp.rs core/src/sim/interp \
  core/src/sim/cycles.rs core/src/sim/cycles || true)
if [ -n "$words" ]; then
  echo "boundary: the simulator words a sentence where it runs a block (a Note in core/src/sim/note.rs):"
  echo "$words"
  fail=1
fi
# The pages word nothing per language themselves: a sentence with numbers in it is made in app
# (or core) and tested there; web picks a label with Lang::t at most.
perlang=$(grep -rnE 'Lang::(De|En) *=>' web/src || true)
if [ -n "$perlang" ]; then
  echo "boundary: web words a sentence per language (make it in app, where it is tested):"
  echo "$perlang"
  fail=1
fi
# Every property test runs a fixed number of cases from a fixed seed (testkit's proptest_cases):
# no test's outcome, time or memory depends on chance.
configs=$(grep -rnE 'ProptestConfig(::with_cases|::default\(\)| \{)|proptest_config\((ProptestConfig|cases)' \
  core/src core/tests app/src app/tests cli tests/tests 2>/dev/null || true)
if [ -n "$configs" ]; then
  echo "boundary: a property test configured without schwenkbar_testkit::proptest_cases:"
  echo "$configs"
  fail=1
fi
[ "$fail" = 0 ] && echo "boundary: core and app without a browser; web without parse, solve, simulate; floats read by number::parse_f64; notes worded in sim/note.rs; no sentence per language in web; property tests from a fixed seed"
exit "$fail"
