# Sourced by the build and test scripts after scripts/setup.sh: puts the tools on PATH and
# decides how wasm32 is compiled (TOOLCHAIN.md).
#   - rustup's prebuilt wasm32 std plus its std source (unless SCHWENKBAR_BUILD_STD=1);
#   - else Debian's rustc-web, building std from source with -Zbuild-std.
# `wasm_env CMD…` runs CMD with the settings for wasm32 builds (tests);
# `bundle_env CMD…` adds the size-first settings of the release bundle.
TOOLS_DIR="${SCHWENKBAR_TOOLS:-$HOME/.cache/schwenkbar-tools}"
export PATH="$TOOLS_DIR/node_modules/.bin:$HOME/.cargo/bin:$PATH"
export CHROMEDRIVER="${CHROMEDRIVER:-/usr/bin/chromedriver}"
# wasm-bindgen-test-runner gives a whole test binary 20 s by default; the WebGL suite (software
# rendering, a 100,000-segment toolpath) takes about 14 s on an idle 2-core machine.
export WASM_BINDGEN_TEST_TIMEOUT="${WASM_BINDGEN_TEST_TIMEOUT:-300}"

_sysroot=$(rustc --print sysroot 2>/dev/null || true)
if [ -z "${SCHWENKBAR_BUILD_STD:-}" ] && [ -n "$_sysroot" ] \
   && [ -d "$_sysroot/lib/rustlib/wasm32-unknown-unknown" ] && [ -d "$_sysroot/lib/rustlib/src/rust/library" ]; then
  WASM_ROUTE="rustup (prebuilt wasm32 std)"
  WASM_STD_SRC="$_sysroot/lib/rustlib/src/rust/library"
  _route_env() { "$@"; }
else
  WASM_ROUTE="Debian rustc-web with -Zbuild-std"
  WASM_STD_SRC=/usr/lib/rustlib/src/rust/library
  # Debian's cargo/rustc first; lets the stable compiler take -Z flags for the std build.
  export PATH="$TOOLS_DIR/node_modules/.bin:/usr/bin:$PATH"
  _route_env() {
    RUSTC_BOOTSTRAP=1 CARGO_UNSTABLE_BUILD_STD=std,panic_abort \
      CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld "$@"
  }
fi
unset _sysroot

wasm_env() { _route_env "$@"; }

# The bundle is size-first (the native release profile stays speed-first, Cargo.toml): std is
# rebuilt with optimize_for_size and panics abort at once, which drops the panic formatting
# machinery (about 21 KB gzip). The app never relies on a panic message: bad input is a message.
bundle_env() {
  RUSTC_BOOTSTRAP=1 CARGO_UNSTABLE_BUILD_STD=std,panic_abort CARGO_UNSTABLE_BUILD_STD_FEATURES=optimize_for_size \
    CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-Zunstable-options -Cpanic=immediate-abort" \
    CARGO_PROFILE_RELEASE_OPT_LEVEL=z _route_env "$@"
}

# Builds the release pages into dist/: the trainer (index.html), the course (kurs.html) and the
# machine editor (maschine.html), each its own bundle, so the course's and the editor's code and
# texts never weigh on the trainer. trunk builds one page per run and replaces its dist folder,
# so the other pages are built aside and copied in. The pages share the manifest and the icons
# (copied by trunk); dist/sw.js is written last.
build_pages() {
  bundle_env trunk build index.html --release --offline
  local page
  for page in kurs maschine; do
    rm -rf "target/$page-dist"
    bundle_env trunk build "$page.html" --release --offline --dist "target/$page-dist"
    cp "target/$page-dist/index.html" "dist/$page.html"
    find "target/$page-dist" -maxdepth 1 -type f ! -name index.html -exec cp {} dist/ \;
  done
  # What trunk built, kept to show that the steps after it give the same bytes again
  # (scripts/same_bytes.sh).
  rm -rf target/pages-trunk && cp -r dist target/pages-trunk
  finish_pages dist
}

# The steps after trunk, on the pages in $1.
finish_pages() {
  local dir=$1
  # Each page's wasm split into what its first screen runs (web/first_screen/) and the rest,
  # loaded after it (with the read-only data only the rest reads: cargo's linked wasm says
  # which, web/build.rs).
  python3 scripts/split_pages.py "$dir" "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release"
  # Each wasm's functions ordered for gzip (the names wasm-opt kept are stripped there).
  python3 scripts/order_functions.py "$dir"
  # wasm-bindgen's JS glue, minified with terser (trunk's minifier cannot parse it), and the
  # pages' integrity hashes of it written anew.
  python3 scripts/minify_glue.py "$dir"
  # The service worker (offline after one visit): its precache list and cache version come from
  # the files now in the folder, whose names trunk hashed.
  python3 scripts/precache.py "$dir"
}
