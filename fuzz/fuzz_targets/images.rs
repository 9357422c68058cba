//! Arbitrary bytes through the image loaders (OpenEXR, Radiance HDR, PFM,
//! chosen by magic bytes). Errors are fine; panics, aborts and allocations
//! beyond the pixel cap are not.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::image::{load, ImageLimits};
use std::io::Write;

fuzz_target!(|data: &[u8]| {
    let mut file = tempfile_in_target();
    file.1.write_all(data).unwrap();
    drop(file.1);
    let limits = ImageLimits {
        max_pixels: 1 << 20,
    };
    if let Ok(img) = load(&file.0, &limits) {
        assert_eq!(
            img.pixels.len() as u64,
            img.width as u64 * img.height as u64
        );
        assert!(img.width as u64 * img.height as u64 <= limits.max_pixels);
    }
    let _ = std::fs::remove_file(&file.0);
});

/// A scratch file per process (the loaders take paths).
fn tempfile_in_target() -> (std::path::PathBuf, std::fs::File) {
    let path = std::env::temp_dir().join(format!("ps30-fuzz-image-{}", std::process::id()));
    let f = std::fs::File::create(&path).unwrap();
    (path, f)
}
