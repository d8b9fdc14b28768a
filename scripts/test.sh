#!/usr/bin/env bash
# Sets up what is missing, then runs every test: formatting and lints, the native workspace
# tests, the browser suite in headless Chromium, the wasm splitter, the release bundle with its
# size, and the tests of the built pages (split wasm, service worker, single-file pages).
# Ends with one summary line "tests: N passed, N failed".
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# shellcheck source=scripts/env.sh
source scripts/env.sh
mkdir -p target
log=target/test-output.log
# The snapshot tests (insta) fail on a changed or missing snapshot and write nothing: accepting one
# is a reviewed step (`cargo insta review`), never a side effect of running the tests.
export INSTA_UPDATE=no
unset INSTA_FORCE_PASS
: >"$log"
# Each phase says when it started (seconds since the command began): where the time goes.
phase() { printf '\n==> [%ds] %s\n' "$SECONDS" "$*"; }

phase "rustfmt --check"
cargo fmt --all -- --check

phase "crate boundaries (scripts/boundary.sh)"
bash scripts/boundary.sh
phase "every path the docs name exists (scripts/doc_paths.py)"
python3 scripts/doc_paths.py
phase "core has no import circle (scripts/core_layers.py)"
python3 scripts/core_layers.py

phase "clippy (warnings are errors)"
cargo clippy --workspace --all-targets --quiet -- -D warnings
# The docs as cargo doc reads them (a citation `[S2]` read as a link, a link to a private item):
# after clippy it reuses its checked dependencies, about 15 s.
phase "cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --workspace --quiet

phase "native tests: cargo test --workspace"
cargo test --workspace 2>&1 | tee -a "$log"

# The release bundle is built beside the browser tests: most of it keeps one core busy (the
# link-time optimisation with one codegen unit, wasm-opt) and so do the tests (Chromium). Started
# beside clippy and the native tests instead, which keep both cores busy, the whole took longer
# (621 s against 612 s). It has its own cargo target folder so neither waits on the other's lock,
# and its own process group so a failure stops it too.
bundle_target=target/bundle
rm -f target/bundle.rc
phase "release bundle, beside the browser tests: trunk build --release --offline, each page's wasm split by web/first_screen/, checked in Chromium (scripts/split_pages.py)"
CARGO_TARGET_DIR=$bundle_target SCHWENKBAR_SPLIT=check \
  setsid bash -c 'bash scripts/bundle.sh >target/bundle.out 2>&1; rc=$?
    echo "(the bundle took ${SECONDS}s beside the tests)" >>target/bundle.out; echo $rc >target/bundle.rc' &
bundle_pid=$!
trap 'kill -- -"$bundle_pid" 2>/dev/null || true' EXIT

phase "browser tests: headless Chromium via wasm-bindgen-test-runner ($WASM_ROUTE)"
wasm_env cargo test --target wasm32-unknown-unknown -p schwenkbar-tests 2>&1 | tee -a "$log"

phase "the wasm splitter (tools/wasm-split, by scripts/wasm_split_test.py: a module run whole and split in node)"
python3 scripts/wasm_split_test.py --log "$log"

phase "release bundle: waiting for it"
wait "$bundle_pid" || true
trap - EXIT
cat target/bundle.out
[ "$(cat target/bundle.rc 2>/dev/null)" = 0 ] || { echo "release bundle failed (target/bundle.out)" >&2; exit 1; }

phase "the same bytes again: the steps after trunk rerun on its output (scripts/same_bytes.sh)"
CARGO_TARGET_DIR=$bundle_target bash scripts/same_bytes.sh | tee -a "$log"

phase "single-file pages: dist-single/ from dist/ (scripts/single-file.sh --from-dist)"
bash scripts/single-file.sh --from-dist

phase "offline: service worker and manifest (dist/), single-file pages (dist-single/)"
offline_rc=0
python3 scripts/offline_test.py --log "$log" || offline_rc=$?

phase "screenshot: Musterprogramm 1 after block 10 on ac-table, 1920x1080"
# The app's share link opens the program run at a block (`app/src/persist.rs`, `share_fragment`).
fragment=$(python3 -c 'import sys, urllib.parse
text = open(sys.argv[1], encoding="utf-8").read()
print("pgm=" + urllib.parse.quote(text, safe="-_.~") + "&block=10&machine=ac-table&run=1")' static/programs/musterprogramm1.h)
bash scripts/screenshot.sh target/screenshots/musterprogramm1-block10.png "#$fragment"
phase "screenshot: the course page, lesson 5 (SEQ/SYM bench)"
bash scripts/screenshot.sh target/screenshots/kurs-lektion-5.png "kurs.html#kurs/5"
phase "screenshot: the machine editor page on ba-table"
bash scripts/screenshot.sh target/screenshots/maschinen-editor.png "maschine.html#ba-table"
phase "screenshots: the classroom projector, 1280x720 (trainer in projector mode, course instructor view)"
SCREENSHOT_SIZE=1280,720 SCREENSHOT_PROJECTOR=1 \
  bash scripts/screenshot.sh target/screenshots/projektor-1280x720-musterprogramm1-block10.png "#$fragment"
SCREENSHOT_SIZE=1280,720 SCREENSHOT_PROJECTOR=1 \
  bash scripts/screenshot.sh target/screenshots/projektor-1280x720-kurs-lektion-5.png "kurs.html#kurs/5"

passed=$(grep -oE 'test result: [a-zA-Z]+\. [0-9]+ passed' "$log" | awk '{s+=$4} END {print s+0}')
failed=$(grep -oE '[0-9]+ failed' "$log" | awk '{s+=$1} END {print s+0}')
echo
echo "time: ${SECONDS}s"
echo "tests: $passed passed, $failed failed"
[ "$failed" = 0 ] && [ "$offline_rc" = 0 ]
