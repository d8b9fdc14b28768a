#!/usr/bin/env bash
# Writes a screenshot of the built app (dist/, from scripts/bundle.sh) to PATH (default
# target/screenshot.png). Serves dist/ on 127.0.0.1 with python3's http.server for the duration
# and stops it again. Usage: scripts/screenshot.sh [PATH] [QUERY]
#   QUERY is appended to the URL ("#pgm=…" a share link, "kurs.html#kurs/5" a lesson).
# Environment:
#   SCREENSHOT_SIZE=W,H         the window (default 1920,1080)
#   SCREENSHOT_BUDGET_MS=4000   the virtual time the page gets before the shot
#   SCREENSHOT_PROJECTOR=1      the classroom view: the trainer in projector mode and the course's
#                               instructor view (the shared preferences, app/src/persist.rs)
# Every screenshot is German (the preferences `p1;lang=de;…` in localStorage, set by a small
# page of the same origin before the app loads; a first visit would follow the browser's
# language).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/screenshot.png}"
query="${2:-}"
size="${SCREENSHOT_SIZE:-1920,1080}"
[ -f dist/index.html ] || { echo "no dist/index.html: run scripts/bundle.sh first" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
port="${SCREENSHOT_PORT:-8765}"
# dist/ as links plus the set-up page, so dist/ itself stays as built.
site=$(mktemp -d)
profile=$(mktemp -d)
cp -rs "$PWD/dist/." "$site/"
classroom=0
[ -n "${SCREENSHOT_PROJECTOR:-}" ] && classroom=1
python3 - "$site/_screenshot-setup.html" "/$query" "p1;lang=de;classroom=$classroom" <<'PY'
import json, sys
path, target, prefs = sys.argv[1:]
with open(path, "w", encoding="utf-8") as f:
    f.write("<!doctype html><meta charset=utf-8><script>"
            f"localStorage.setItem('schwenkbar.prefs', {json.dumps(prefs)});"
            f"location.replace({json.dumps(target)});</script>")
PY
url="http://127.0.0.1:$port/_screenshot-setup.html"
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site" >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -rf "$site" "$profile"' EXIT
for _ in $(seq 50); do
  python3 -c "import socket,sys; s=socket.socket(); sys.exit(s.connect_ex(('127.0.0.1', $port)))" && break
  sleep 0.1
done
# German, as a first visit in a German browser opens (the app follows the browser's language).
chromium --headless=new --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --lang=de-DE --user-data-dir="$profile" \
  --virtual-time-budget="${SCREENSHOT_BUDGET_MS:-4000}" --window-size="$size" --screenshot="$(realpath -m "$out")" \
  "$url" 2>/dev/null
echo "screenshot: $out"
