#!/usr/bin/env bash
# Sets up what is missing, builds the app (trainer and course pages) and serves it on
# http://127.0.0.1:8080/ (offline, only on this machine).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# shellcheck source=scripts/env.sh
source scripts/env.sh
build_pages
echo
echo "Schwenkbar: http://127.0.0.1:8080/   course: http://127.0.0.1:8080/kurs.html   machine editor: http://127.0.0.1:8080/maschine.html   (Ctrl+C stops the server)"
echo
exec python3 -m http.server 8080 --bind 127.0.0.1 --directory dist
