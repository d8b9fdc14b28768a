#!/usr/bin/env bash
# Builds the release bundle into dist/ and prints its size: index.html + JS + wasm + CSS,
# each gzip -9, summed, against the issues' budget (BUNDLE_BUDGET_KB: a figure to report, not a
# test). Fails only above the regression ceiling BUNDLE_LIMIT_KB, so that a size blow-up stops CI.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/env.sh
source scripts/env.sh
BUNDLE_BUDGET_KB="${BUNDLE_BUDGET_KB:-240}"
BUNDLE_LIMIT_KB="${BUNDLE_LIMIT_KB:-260}"
bundle_env trunk build --release --offline
total=0
for f in dist/index.html dist/*.js dist/*.wasm dist/*.css; do
  [ -f "$f" ] || continue
  raw=$(stat -c %s "$f"); gz=$(gzip -9 -c "$f" | wc -c); total=$((total + gz))
  printf '    %-48s %8d bytes, gzip -9 %7d bytes\n' "$f" "$raw" "$gz"
done
printf "bundle: %d bytes gzip -9 (%s KB; budget %d KB)\n" "$total" "$(awk -v t="$total" "BEGIN {printf \"%.1f\", t/1024}")" "$BUNDLE_BUDGET_KB"
if [ "$total" -le $((BUNDLE_BUDGET_KB * 1024)) ]; then
  echo "bundle within the budget of $BUNDLE_BUDGET_KB KB"
else
  echo "bundle OVER the budget of $BUNDLE_BUDGET_KB KB by $(( (total - BUNDLE_BUDGET_KB * 1024 + 1023) / 1024 )) KB"
fi
[ "$total" -le $((BUNDLE_LIMIT_KB * 1024)) ] || { echo "bundle above the regression ceiling of $BUNDLE_LIMIT_KB KB" >&2; exit 1; }
