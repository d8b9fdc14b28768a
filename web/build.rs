//! The pages' wasm is linked with its relocations kept (`--emit-relocs`): scripts/split_pages.py
//! reads them from cargo's output to find the read-only data (texts, tables) only the deferred
//! functions read, which then loads with them after the first screen (tools/wasm-split/src/data.rs,
//! plan_data). wasm-bindgen and wasm-opt carry the sections along (trunk's wasm-opt says so:
//! "linking section is present…"; the code it writes is the same) and
//! scripts/order_functions.py drops them from what the pages load. Native builds are not touched.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    if std::env::var("CARGO_CFG_TARGET_ARCH").as_deref() == Ok("wasm32") {
        println!("cargo:rustc-link-arg-bins=--emit-relocs");
    }
}
