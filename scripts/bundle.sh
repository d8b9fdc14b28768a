#!/usr/bin/env bash
# Builds the release pages into dist/ and prints their sizes: each page's HTML + JS + wasm + CSS,
# gzip -9, summed. The trainer (index.html) against the issues' budget (BUNDLE_BUDGET_KB: a
# figure to report, not a test); the course page (kurs.html) and the machine editor
# (maschine.html), each its own bundle, are reported too.
# Fails only above the regression ceilings, so that a size blow-up stops CI.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/env.sh
source scripts/env.sh
BUNDLE_BUDGET_KB="${BUNDLE_BUDGET_KB:-240}"
# The ceilings were raised when issue 15 landed (arcs, compensation, 15 cycles: +37 KB gzip on
# the trainer), with issue 16 (typed edits re-parsed and re-run in part, the windowed text editor,
# the virtualised program list, the toolpath made in parts: +19 KB) and TCPM, and again with issue
# 17's collision check and machine editor (collision bodies of five machines, the swept check, the
# saved machines' record and the EDITIEREN softkeys: the trainer 291.7 -> 313.1 KB, the course
# 366.1 -> 387.2 KB). The trainer is far over its 240 KB budget (see the session notes: only
# splitting the wasm can bring it back). The ceilings stop a blow-up; the budget line reports the overrun.
BUNDLE_LIMIT_KB="${BUNDLE_LIMIT_KB:-320}"
COURSE_LIMIT_KB="${COURSE_LIMIT_KB:-395}"
# The machine editor (maschine.html): the renderer, the form and serde_json's export and import.
EDITOR_LIMIT_KB="${EDITOR_LIMIT_KB:-300}"
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
kb() { awk -v t="$1" 'BEGIN {printf "%.1f", t/1024}'; }
total=$(page_size index.html)
printf "bundle: %d bytes gzip -9 (%s KB; budget %d KB) — the trainer, index.html\n" "$total" "$(kb "$total")" "$BUNDLE_BUDGET_KB"
if [ "$total" -le $((BUNDLE_BUDGET_KB * 1024)) ]; then
  echo "bundle within the budget of $BUNDLE_BUDGET_KB KB"
else
  echo "bundle OVER the budget of $BUNDLE_BUDGET_KB KB by $(( (total - BUNDLE_BUDGET_KB * 1024 + 1023) / 1024 )) KB"
fi
course=$(page_size kurs.html)
printf "course page: %d bytes gzip -9 (%s KB; loaded only when the course is opened; ceiling %d KB)\n" "$course" "$(kb "$course")" "$COURSE_LIMIT_KB"
editor=$(page_size maschine.html)
printf "machine editor page: %d bytes gzip -9 (%s KB; loaded only when the editor is opened; ceiling %d KB)\n" "$editor" "$(kb "$editor")" "$EDITOR_LIMIT_KB"
# Offline (issue 12): fetched once by the browser and the service worker, not by the page's start.
extras=0
for f in dist/sw.js dist/manifest.webmanifest dist/icons/*; do
  if [ -f "$f" ]; then extras=$((extras + $(gzip -9 -c "$f" | wc -c))); fi
done
printf "offline extras: %d bytes gzip -9 (%s KB: sw.js, manifest, icons; not in the pages' figures)\n" "$extras" "$(kb "$extras")"
[ "$total" -le $((BUNDLE_LIMIT_KB * 1024)) ] || { echo "bundle above the regression ceiling of $BUNDLE_LIMIT_KB KB" >&2; exit 1; }
[ "$course" -le $((COURSE_LIMIT_KB * 1024)) ] || { echo "course page above its ceiling of $COURSE_LIMIT_KB KB" >&2; exit 1; }
[ "$editor" -le $((EDITOR_LIMIT_KB * 1024)) ] || { echo "machine editor page above its ceiling of $EDITOR_LIMIT_KB KB" >&2; exit 1; }
