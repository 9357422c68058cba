//! What several test modules share: the bundled images' paths (here), running
//! the binary (`bin`), a counting allocator (`counting`), constant-table
//! builders (`ctab`), a random valid-program generator (`program_gen`), the
//! malformed-assembly cases (`malformed_asm`) and the GPU adapter check
//! (`gpu`).

pub mod bin;
pub mod counting;
pub mod ctab;
pub mod gpu;
pub mod malformed_asm;
pub mod program_gen;

use std::path::PathBuf;

/// Every image in `assets/hdr` (tests/reference_values.rs checks the list
/// against the folder and reference.json): the library's own list.
pub use ps30::present::report::IMAGES;

/// Path of a bundled image or of `reference.json`.
pub fn asset(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("assets/hdr")
        .join(name)
}
