#!/usr/bin/env bash
# Issue 16: `schwenkbar run` and `check` on the generated 100,000-block CAM program, timed side by
# side with the public JavaScript peer tnc-sim's parser (`parseProgram` of its
# core/parser-engine.js: it parses, expands and builds the 3-axis toolpath; no 5-axis, a
# 2000-line limit in its own validator, at most 200,000 expanded blocks). Whole processes, one
# hyperfine call (or the same in Python without it), medians. Prints figures; skipped unless TNC_SIM_DIR names a checkout of the
# peer (nothing of it is in this repository and nothing is built: it is plain browser JS, loaded
# into a node:vm context with the few globals its app defines, as its own tests load it).
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ -z ${TNC_SIM_DIR:-} || ! -f ${TNC_SIM_DIR}/core/parser-engine.js ]]; then
  echo "peer: TNC_SIM_DIR is not a tnc-sim checkout — skipped"; exit 0
fi
command -v node >/dev/null || { echo "peer: needs node — skipped"; exit 0; }
cargo build --release -q -p schwenkbar
# The 100,000-block programs as the command line's own benchmark writes them (bench_cli): the
# CAM program (issue 16) and 100,000 moves inside a blank (issue 32).
file=target/release/bench_cam_100000.h
blank=target/release/bench_blank_100000.h
[ -f "$file" ] && [ -f "$blank" ] || cargo run --release -q -p schwenkbar --example bench_cli >/dev/null
driver=target/tnc-sim-parse.js
cat >"$driver" <<'JS'
// Runs the peer's parser on a file: node tnc-sim-parse.js TNC_SIM_DIR FILE
const fs = require("fs"), path = require("path"), vm = require("vm");
const [dir, file] = process.argv.slice(2);
const tools = [{T: 1, TYPE: "MILL", R: 5, R2: 0, DL: 0, DR: 0, DR2: 0}, {T: 12, TYPE: "MILL", R: 5, R2: 0, DL: 0, DR: 0, DR2: 0}];
const ctx = {console, window: {}, probs: [], DEFAULT_FEED: 500, lastDefinedFeed: 500, TOOL_R: 5,
  _WORKPIECE_TOP_Z: 20, TOOL_TYPES: ["MILL", "DRILL", "COUNTERSINK"], toolLibrary: tools,
  pFloat: v => parseFloat((v + "").replace(",", ".")), inferToolType: t => (t && t.TYPE) || "MILL",
  getToolByNum: n => tools.find(t => t.T === n) || null};
vm.createContext(ctx);
vm.runInContext(fs.readFileSync(path.join(dir, "core", "parser-engine.js"), "utf8"), ctx);
const p = ctx.parseProgram(fs.readFileSync(file, "utf8"));
console.log("tnc-sim parseProgram: " + p.sub.length + " segments");
JS
node "$driver" "$TNC_SIM_DIR" "$file"
# Medians of whole processes, output to /dev/null: hyperfine where it is installed, else the
# same timing in Python (no warm-up statistics, the same medians).
commands=(
  peer "node $driver $TNC_SIM_DIR $file"
  run "target/release/schwenkbar run --machine ac-table $file"
  run-json "target/release/schwenkbar run --json --machine ac-table $file"
  check "target/release/schwenkbar check $file"
  peer-blank "node $driver $TNC_SIM_DIR $blank"
  run-blank "target/release/schwenkbar run --machine bc-head-table $blank"
)
json=$(mktemp)
if command -v hyperfine >/dev/null; then
  args=()
  for ((i = 0; i < ${#commands[@]}; i += 2)); do args+=(-n "${commands[i]}" "${commands[i + 1]}"); done
  hyperfine -N -i --warmup 1 --runs "${PEER_RUNS:-7}" --export-json "$json" "${args[@]}" >/dev/null
else
  python3 - "$json" "${PEER_RUNS:-7}" "${commands[@]}" <<'PY'
import json, shlex, statistics, subprocess, sys, time
out, runs, pairs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
results = []
for name, cmd in zip(pairs[::2], pairs[1::2]):
    times = []
    for _ in range(runs + 1):
        t = time.perf_counter()
        subprocess.run(shlex.split(cmd), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - t)
    results.append({"command": name, "median": statistics.median(times[1:])})
json.dump({"results": results}, open(out, "w"))
PY
fi
python3 - "$json" <<'PY'
import json, sys
r = {x["command"]: x["median"] for x in json.load(open(sys.argv[1]))["results"]}
p = r["peer"]
for k in ("run", "run-json", "check"):
    print(f"peer: {k} 100,000 blocks {r[k]*1e3:.0f} ms = {r[k]/p:.3f}x tnc-sim's parser ({p*1e3:.0f} ms), medians (budget for run: 0.05x)")
b = r["peer-blank"]
print(f"peer: run 100,000 moves inside a blank {r['run-blank']*1e3:.0f} ms = {r['run-blank']/b:.3f}x tnc-sim's parser ({b*1e3:.0f} ms), medians (budget: 0.05x)")
PY
rm -f "$json"
