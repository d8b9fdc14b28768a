# Sourced by the build and test scripts after scripts/setup.sh: puts the tools on PATH and
# decides how wasm32 is compiled (TOOLCHAIN.md).
#   - rustup's prebuilt wasm32 std if it is installed (unless SCHWENKBAR_BUILD_STD=1);
#   - else Debian's rustc-web, building std from source with -Zbuild-std.
# `wasm_env CMD…` runs CMD with the settings for wasm32 builds.
TOOLS_DIR="${SCHWENKBAR_TOOLS:-$HOME/.cache/schwenkbar-tools}"
export PATH="$TOOLS_DIR/node_modules/.bin:$HOME/.cargo/bin:$PATH"
export CHROMEDRIVER="${CHROMEDRIVER:-/usr/bin/chromedriver}"

# The bundle is size-first; the native release profile stays speed-first (Cargo.toml).
_size_first() { CARGO_PROFILE_RELEASE_OPT_LEVEL=z CARGO_PROFILE_RELEASE_PANIC=abort "$@"; }

_sysroot=$(rustc --print sysroot 2>/dev/null || true)
if [ -z "${SCHWENKBAR_BUILD_STD:-}" ] && [ -n "$_sysroot" ] && [ -d "$_sysroot/lib/rustlib/wasm32-unknown-unknown" ]; then
  WASM_ROUTE="rustup (prebuilt wasm32 std)"
  wasm_env() { _size_first "$@"; }
else
  WASM_ROUTE="Debian rustc-web with -Zbuild-std"
  # Debian's cargo/rustc first; lets the stable compiler take -Z flags for the std build.
  export PATH="$TOOLS_DIR/node_modules/.bin:/usr/bin:$PATH"
  wasm_env() {
    RUSTC_BOOTSTRAP=1 CARGO_UNSTABLE_BUILD_STD=std,panic_abort \
      CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld _size_first "$@"
  }
fi
unset _sysroot
