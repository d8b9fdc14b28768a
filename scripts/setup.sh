#!/usr/bin/env bash
# Makes sure every tool the build and the tests need is present, installing only what is
# missing or at the wrong version. Idempotent: a second run only checks.
# Recipe and versions: ../shared/TOOLCHAIN.md (offline machines; crates.io, npm and Debian only).
#
# Steps: 1 wasm32 std (+ std source), 2 wasm-bindgen-cli, 3 trunk, 4 wasm-opt (binaryen),
# 5 Chromium + ChromeDriver, then the crates std depends on.
# Prints each step; on failure names the step and exits non-zero.
set -euo pipefail

WASM_BINDGEN_VERSION=0.2.130
TRUNK_VERSION=0.21.14
BINARYEN_VERSION=132
TERSER_VERSION=5.51.2
TOOLS_DIR="${SCHWENKBAR_TOOLS:-$HOME/.cache/schwenkbar-tools}"

step() { printf '\n==> setup step %s\n' "$*"; }
fail() { printf '\nsetup FAILED in step %s\n' "$*" >&2; exit 1; }
ok() { printf '    ok: %s\n' "$*"; }

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
APT_UPDATED=0
apt_install() {
  if [ "$APT_UPDATED" = 0 ]; then
    as_root apt-get update -qq || return 1
    APT_UPDATED=1
  fi
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"
}

# A cargo for native host tools: rustup's if there is one, else Debian's.
HOST_CARGO=$(command -v cargo || true)

# --- 1: a standard library for wasm32-unknown-unknown -------------------------------------
step "1/5: wasm32 standard library"
rustup_sysroot=""
if command -v rustc >/dev/null; then rustup_sysroot=$(rustc --print sysroot 2>/dev/null || true); fi
# The rustup route needs the prebuilt wasm32 std and the std source (the bundle rebuilds std for
# size). SCHWENKBAR_BUILD_STD=1 forces the Debian route (to test it where rustup works).
rustup_ready() {
  [ -n "$rustup_sysroot" ] && [ -d "$rustup_sysroot/lib/rustlib/wasm32-unknown-unknown" ] \
    && [ -d "$rustup_sysroot/lib/rustlib/src/rust/library" ]
}
if [ -z "${SCHWENKBAR_BUILD_STD:-}" ] && rustup_ready; then
  ok "prebuilt wasm32 std and std source in $rustup_sysroot"
elif [ -z "${SCHWENKBAR_BUILD_STD:-}" ] && command -v rustup >/dev/null \
   && timeout 60 rustup target add wasm32-unknown-unknown >/dev/null 2>&1 \
   && timeout 60 rustup component add rust-src >/dev/null 2>&1 && rustup_ready; then
  ok "rustup target add wasm32-unknown-unknown, component rust-src"
elif [ -x /usr/bin/rustc ] && [ -d /usr/lib/rustlib/src/rust/library ] && command -v wasm-ld >/dev/null; then
  ok "Debian rustc-web $(/usr/bin/rustc --version | cut -d' ' -f2) with std source (-Zbuild-std)"
else
  echo "    rustup cannot download here; installing Debian's rustc-web + rust-web-src + lld"
  apt_install rustc-web cargo-web rust-web-src lld || fail "1/5 (apt-get install rustc-web cargo-web rust-web-src lld)"
  [ -d /usr/lib/rustlib/src/rust/library ] || fail "1/5 (std source missing under /usr/lib/rustlib/src/rust)"
  ok "Debian rustc-web installed"
fi
[ -n "$HOST_CARGO" ] || HOST_CARGO=/usr/bin/cargo

# --- 2: wasm-bindgen-cli (must equal the wasm-bindgen crate pinned in Cargo.toml) -----------
step "2/5: wasm-bindgen-cli $WASM_BINDGEN_VERSION"
if command -v wasm-bindgen >/dev/null && [ "$(wasm-bindgen --version | cut -d' ' -f2)" = "$WASM_BINDGEN_VERSION" ] \
   && command -v wasm-bindgen-test-runner >/dev/null; then
  ok "$(wasm-bindgen --version)"
else
  # No --locked: the registry lacks a pinned sub-dependency of its lock file (TOOLCHAIN.md).
  "$HOST_CARGO" install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --force \
    || fail "2/5 (cargo install wasm-bindgen-cli)"
  ok "$(wasm-bindgen --version)"
fi

# --- 3: trunk ------------------------------------------------------------------------------
step "3/5: trunk $TRUNK_VERSION"
if command -v trunk >/dev/null && [ "$(trunk --version | cut -d' ' -f2)" = "$TRUNK_VERSION" ]; then
  ok "$(trunk --version)"
else
  echo "    building trunk from crates.io (about 10 minutes on 2 cores)"
  "$HOST_CARGO" install trunk --version "$TRUNK_VERSION" --locked --force || fail "3/5 (cargo install trunk)"
  ok "$(trunk --version)"
fi

# --- 4: wasm-opt from binaryen (Debian's 108 cannot read what rustc emits) ------------------
step "4/5: wasm-opt (binaryen $BINARYEN_VERSION)"
# Installs an npm package into $TOOLS_DIR unless its command already reports `version`.
npm_tool() {
  local command=$1 package=$2 version=$3
  local bin="$TOOLS_DIR/node_modules/.bin/$command"
  if [ -x "$bin" ] && "$bin" --version | grep -q "$version"; then
    ok "$("$bin" --version)"
    return
  fi
  command -v npm >/dev/null || apt_install nodejs npm || fail "4/5 (apt-get install nodejs npm)"
  mkdir -p "$TOOLS_DIR"
  [ -f "$TOOLS_DIR/package.json" ] || echo '{"name":"schwenkbar-tools","private":true}' >"$TOOLS_DIR/package.json"
  (cd "$TOOLS_DIR" && npm install --no-audit --no-fund --silent "$package@$version") \
    || fail "4/5 (npm install $package@$version)"
  ok "$("$bin" --version)"
}
npm_tool wasm-opt binaryen "$BINARYEN_VERSION"
# terser minifies wasm-bindgen's JS glue (trunk 0.21's own minifier cannot parse it).
npm_tool terser terser "$TERSER_VERSION"

# --- 5: Chromium and ChromeDriver for the headless browser tests ---------------------------
step "5/5: Chromium + ChromeDriver"
if [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; then
  ok "$(/usr/bin/chromium --version 2>/dev/null | head -1); $(/usr/bin/chromedriver --version | cut -d' ' -f1-2)"
else
  apt_install chromium chromium-driver || fail "5/5 (apt-get install chromium chromium-driver)"
  ok "$(/usr/bin/chromium --version 2>/dev/null | head -1)"
fi
# python3 serves the built pages (scripts/serve.sh) and drives the screenshot.
command -v python3 >/dev/null || apt_install python3 || fail "5/5 (apt-get install python3)"

# --- the crates std itself depends on, so that `trunk build --offline` can rebuild std -------
step "std's own dependencies (for building std offline)"
# shellcheck source=scripts/env.sh
source "$(dirname "$0")/env.sh"
(cd "$WASM_STD_SRC" && RUSTC_BOOTSTRAP=1 cargo fetch --quiet) || fail "std dependencies (cargo fetch in $WASM_STD_SRC)"
ok "fetched for $WASM_ROUTE"

printf '\nsetup complete\n'
