#!/usr/bin/env bash
# Issue 16: `schwenkbar run` and `check` on the generated 100,000-block CAM program, timed side by
# side with the public JavaScript peer tnc-sim's parser (`parseProgram` of its
# core/parser-engine.js: it parses, expands and builds the 3-axis toolpath; no 5-axis, a
# 2000-line limit in its own validator, at most 200,000 expanded blocks). Whole processes, one
# hyperfine call, medians. Prints figures; skipped unless TNC_SIM_DIR names a checkout of the
# peer (nothing of it is in this repository and nothing is built: it is plain browser JS, loaded
# into a node:vm context with the few globals its app defines, as its own tests load it).
set -euo pipefail
cd "$(dirname "$0")/.."
blocks=${PEER_BLOCKS:-100000}
if [[ -z ${TNC_SIM_DIR:-} || ! -f ${TNC_SIM_DIR}/core/parser-engine.js ]]; then
  echo "peer: TNC_SIM_DIR is not a tnc-sim checkout — skipped"; exit 0
fi
for tool in node hyperfine; do
  command -v "$tool" >/dev/null || { echo "peer: needs $tool — skipped"; exit 0; }
done
cargo build --release -q -p schwenkbar
file=target/cam${blocks}.h
cargo run --release -q -p schwenkbar-core --example cam_program -- "$blocks" >"$file"
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
json=$(mktemp)
hyperfine -N --warmup 1 --runs "${PEER_RUNS:-7}" --export-json "$json" \
  -n peer "node $driver $TNC_SIM_DIR $file" \
  -n run "target/release/schwenkbar run --machine ac-table $file" \
  -n run-json "target/release/schwenkbar run --json --machine ac-table $file" \
  -n check "target/release/schwenkbar check $file" >/dev/null
python3 - "$json" "$blocks" <<'PY'
import json, sys
r = {x["command"]: x["median"] for x in json.load(open(sys.argv[1]))["results"]}
p = r["peer"]
for k in ("run", "run-json", "check"):
    print(f"peer: {k} {int(sys.argv[2]):,} blocks {r[k]*1e3:.0f} ms = {r[k]/p:.3f}x tnc-sim's parser ({p*1e3:.0f} ms), medians (budget for run: 0.05x)")
PY
rm -f "$json"
