#!/usr/bin/env bash
# Builds the release pages into dist/ and prints their sizes: each page's HTML + JS + wasm + CSS,
# gzip -9, summed — what the page loads before its first screen. Each page's wasm is split
# (scripts/split_pages.py) by the lists of web/first_screen/: the functions the first screen does
# not run are in X_deferred.wasm, fetched after it; its size is printed on its own line ("then").
# The trainer (index.html) must stay within its budget (BUNDLE_BUDGET_KB: the brief's 200 KB for
# the trainer's first screen); the course page (kurs.html) and the machine editor (maschine.html),
# each its own bundle, within regression ceilings. Fails above any of them.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/env.sh
source scripts/env.sh
BUNDLE_BUDGET_KB="${BUNDLE_BUDGET_KB:-200}"
# Unsplit, the trainer was 316.7 KB, the course 391.0 KB and the editor 176.2 KB; split, with
# the read-only data only the deferred code reads, 197, 309 (its lessons' first screens run most
# of the trainer too) and 123 KB. The ceilings stop a
# blow-up (or a page left whole by the split). The course's rose to 334 with the collision
# check's swept test and the stock's light replay (issue 32) and the old controls' empty words
# (issue 30): core code every page carries (330.7 KB measured with them). It rose to 338 with
# SYSREAD ID50, TABREAD and the nameless program frame (issue 30) and the depth under the
# pointer in the 3D view (issue 32): 334.3 KB measured. It rose to 346 with the block grammar
# as nom combinators (issue 30; the parser's code +25 % in wasm) and the stops that say what the
# run assumed (an unknown tool's size, an unprobed result): 343.8 KB measured, the trainer
# 174.2 → 178.0 KB. The trainer's went down from 216 to
# 172.9 KB when its start stopped simulating before the first screen (AppState::start_unsimulated).
COURSE_LIMIT_KB="${COURSE_LIMIT_KB:-346}"
EDITOR_LIMIT_KB="${EDITOR_LIMIT_KB:-160}"
build_pages
# The files a page loads: the page itself and what it references (trunk's hashed names).
page_size() {
  local page=$1 total=0 f raw gz
  for f in "dist/$page" $(grep -oE '/[A-Za-z0-9_.-]+\.(js|wasm|css)' "dist/$page" | sort -u | sed 's|^/|dist/|'); do
    [ -f "$f" ] || continue
    raw=$(stat -c %s "$f"); gz=$(gzip -9 -c "$f" | wc -c); total=$((total + gz))
    printf '    %-48s %8d bytes, gzip -9 %7d bytes\n' "$f" "$raw" "$gz" >&2
  done
  echo "$total"
}
# The deferred wasm a page's glue names (none if the page was left whole).
deferred_size() {
  local page=$1 glue name
  glue=$(grep -oE '/[A-Za-z0-9_.-]+\.js' "dist/$page" | head -1 | sed 's|^/|dist/|')
  name=$(grep -oE '[A-Za-z0-9_.-]+_deferred\.wasm' "$glue" | head -1 || true)
  if [ -n "$name" ] && [ -f "dist/$name" ]; then
    printf '%d gzip -9 bytes (%s)' "$(gzip -9 -c "dist/$name" | wc -c)" "$name"
  else
    printf 'none: the page was not split'
  fi
}
kb() { awk -v t="$1" 'BEGIN {printf "%.1f", t/1024}'; }
total=$(page_size index.html)
printf "bundle: %d bytes gzip -9 (%s KB; budget %d KB) — the trainer, index.html\n" "$total" "$(kb "$total")" "$BUNDLE_BUDGET_KB"
if [ "$total" -le $((BUNDLE_BUDGET_KB * 1024)) ]; then
  echo "bundle within the budget of $BUNDLE_BUDGET_KB KB"
else
  echo "bundle OVER the budget of $BUNDLE_BUDGET_KB KB by $(( (total - BUNDLE_BUDGET_KB * 1024 + 1023) / 1024 )) KB"
fi
echo "  then, after the first screen: $(deferred_size index.html)"
course=$(page_size kurs.html)
printf "course page: %d bytes gzip -9 (%s KB; loaded only when the course is opened; ceiling %d KB)\n" "$course" "$(kb "$course")" "$COURSE_LIMIT_KB"
echo "  then, after the first screen: $(deferred_size kurs.html)"
editor=$(page_size maschine.html)
printf "machine editor page: %d bytes gzip -9 (%s KB; loaded only when the editor is opened; ceiling %d KB)\n" "$editor" "$(kb "$editor")" "$EDITOR_LIMIT_KB"
echo "  then, after the first screen: $(deferred_size maschine.html)"
# Offline (issue 12): fetched once by the browser and the service worker, not by the page's start.
extras=0
for f in dist/sw.js dist/manifest.webmanifest dist/icons/*; do
  if [ -f "$f" ]; then extras=$((extras + $(gzip -9 -c "$f" | wc -c))); fi
done
printf "offline extras: %d bytes gzip -9 (%s KB: sw.js, manifest, icons; not in the pages' figures)\n" "$extras" "$(kb "$extras")"
[ "$total" -le $((BUNDLE_BUDGET_KB * 1024)) ] || { echo "the trainer's bundle is above its budget of $BUNDLE_BUDGET_KB KB" >&2; exit 1; }
[ "$course" -le $((COURSE_LIMIT_KB * 1024)) ] || { echo "course page above its ceiling of $COURSE_LIMIT_KB KB" >&2; exit 1; }
[ "$editor" -le $((EDITOR_LIMIT_KB * 1024)) ] || { echo "machine editor page above its ceiling of $EDITOR_LIMIT_KB KB" >&2; exit 1; }
