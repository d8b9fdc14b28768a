#!/usr/bin/env bash
# The same source builds the same bytes (issue 33): the steps after trunk (finish_pages in
# scripts/env.sh: the split by web/first_screen/, the function order, the minified glue, the
# service worker) run again on what trunk built for dist/ (target/pages-trunk, kept by
# build_pages) and must give every file of dist/ byte for byte. (cargo, wasm-bindgen and wasm-opt
# are deterministic for the same input; two whole builds of one commit were compared by hand.)
# Run after scripts/bundle.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/env.sh
source scripts/env.sh
[ -d target/pages-trunk ] || { echo "same bytes: no target/pages-trunk (run scripts/bundle.sh first)" >&2; exit 1; }
again=$(mktemp -d)
trap 'rm -rf "$again"' EXIT
cp -r target/pages-trunk/. "$again"
SCHWENKBAR_SPLIT='' finish_pages "$again" >/dev/null 2>&1
digests() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum); }
if diff <(digests dist) <(digests "$again") >/dev/null; then
  echo "test result: ok. 1 passed; 0 failed; same bytes: dist/ built again from trunk's output, $(find dist -type f | wc -l) files identical"
else
  diff <(digests dist) <(digests "$again") >&2 || true
  echo "test result: FAILED. 0 passed; 1 failed; same bytes: the steps after trunk gave other bytes the second time" >&2
  exit 1
fi
