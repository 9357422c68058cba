//! Shared by the integration tests that read the bundled HDR images.

use std::path::PathBuf;

/// Every image in `assets/hdr` (tests/reference_values.rs checks the list
/// against the folder and reference.json): the library's own list.
// Not every test crate that includes this module reads the list.
#[allow(unused_imports)]
pub use ps30::present::report::IMAGES;

/// Path of a bundled image or of `reference.json`.
pub fn asset(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("assets/hdr")
        .join(name)
}
