#!/usr/bin/env bash
# Writes a 1920×1080 screenshot of the built app (dist/, from scripts/bundle.sh) to PATH
# (default target/screenshot.png). Serves dist/ on 127.0.0.1 with python3's http.server for the
# duration and stops it again. Usage: scripts/screenshot.sh [PATH] [QUERY]
#   QUERY is appended to the URL (e.g. "?demo=…" once the app reads one).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/screenshot.png}"
query="${2:-}"
[ -f dist/index.html ] || { echo "no dist/index.html: run scripts/bundle.sh first" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
port="${SCREENSHOT_PORT:-8765}"
python3 -m http.server "$port" --bind 127.0.0.1 --directory dist >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import socket,sys; s=socket.socket(); sys.exit(s.connect_ex(('127.0.0.1', $port)))" && break
  sleep 0.1
done
profile=$(mktemp -d)
chromium --headless=new --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --user-data-dir="$profile" \
  --virtual-time-budget=4000 --window-size=1920,1080 --screenshot="$(realpath -m "$out")" \
  "http://127.0.0.1:$port/$query" 2>/dev/null
rm -rf "$profile"
echo "screenshot: $out"
