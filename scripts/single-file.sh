#!/usr/bin/env bash
# Builds the pages (build_pages, as scripts/bundle.sh) and packs each into ONE HTML file:
# dist-single/index.html (the trainer) and dist-single/kurs.html (the course), with the CSS, the
# JS glue and the wasm inside. Copy dist-single/ to a USB stick and open index.html: it runs
# from file://, no server, no network (and no service worker: that needs http(s)).
# Usage: scripts/single-file.sh [--from-dist]   (--from-dist: pack the existing dist/, no build)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" != "--from-dist" ]; then
  bash scripts/setup.sh
  # shellcheck source=scripts/env.sh
  source scripts/env.sh
  build_pages
fi
[ -f dist/index.html ] && [ -f dist/kurs.html ] && [ -f dist/maschine.html ] || { echo "no dist/index.html, dist/kurs.html and dist/maschine.html: run without --from-dist" >&2; exit 1; }
python3 scripts/single_file.py dist dist-single
