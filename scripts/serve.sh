#!/usr/bin/env bash
# Sets up what is missing, builds the app and serves it on http://127.0.0.1:8080/ (offline).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# shellcheck source=scripts/env.sh
source scripts/env.sh
echo
echo "Schwenkbar: http://127.0.0.1:8080/   (Ctrl+C stops the server)"
echo
bundle_env trunk serve --release --offline --address 127.0.0.1 --port 8080
