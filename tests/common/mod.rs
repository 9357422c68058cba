//! Shared by the integration tests that read the bundled HDR images.

use std::path::PathBuf;

/// Every image in `assets/hdr` (tests/reference_values.rs checks the list
/// against the folder and reference.json).
pub const IMAGES: [&str; 7] = [
    "city.exr",
    "courtyard.exr",
    "courtyard_1280x1024.exr",
    "forest.exr",
    "forest.hdr",
    "sunset.exr",
    "sunset.pfm",
];

/// Path of a bundled image or of `reference.json`.
pub fn asset(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("assets/hdr")
        .join(name)
}
