#!/usr/bin/env bash
# Writes a screenshot of the built app (dist/, from scripts/bundle.sh) to PATH (default
# target/screenshot.png). Serves dist/ on 127.0.0.1 with python3's http.server for the duration
# and stops it again. Usage: scripts/screenshot.sh [PATH] [QUERY]
#   QUERY is appended to the URL ("#pgm=…" a share link, "kurs.html#kurs/5" a lesson).
# Environment:
#   SCREENSHOT_SIZE=W,H         the window (default 1920,1080)
#   SCREENSHOT_PROJECTOR=1      the classroom view: the trainer in projector mode (saved state,
#                               web/src/persist.rs) and the course's instructor view (course
#                               progress, web/src/course/progress.rs), set in localStorage by a
#                               small page of the same origin before the app loads
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
url="http://127.0.0.1:$port/$query"
if [ -n "${SCREENSHOT_PROJECTOR:-}" ]; then
  lessons=$(printf '0:0,%.0s' $(seq 11)); lessons=${lessons%,}
  python3 - "$site/_screenshot-setup.html" "/$query" "k1;de;1;$lessons" <<'PY'
import json, sys
path, target, course = sys.argv[1:]
state = '{"version":1,"cursor":0,"machine":"ac-table","lang":"De","projector":true}'
with open(path, "w", encoding="utf-8") as f:
    f.write("<!doctype html><meta charset=utf-8><script>"
            f"localStorage.setItem('schwenkbar.state', {json.dumps(state)});"
            f"localStorage.setItem('schwenkbar.kurs', {json.dumps(course)});"
            f"location.replace({json.dumps(target)});</script>")
PY
  url="http://127.0.0.1:$port/_screenshot-setup.html"
fi
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
  --virtual-time-budget=4000 --window-size="$size" --screenshot="$(realpath -m "$out")" \
  "$url" 2>/dev/null
echo "screenshot: $out"
