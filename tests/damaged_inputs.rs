//! Damaged copies of the real test images (truncated, or with bytes
//! overwritten) must give an `ImageError` naming the file, never a panic or
//! an abort, read whole or only for their header's size. The real files exercise the decoders' compressed paths (DWAB,
//! PIZ, RLE-RGBE) that small synthetic files in the unit tests do not reach.

use ps30::core::image::{load, load_beside, size, ImageLimits};

use crate::common;
use common::{asset, IMAGES};

fn original(name: &str) -> Vec<u8> {
    std::fs::read(asset(name)).unwrap()
}

#[test]
fn truncated_images_are_errors_that_name_the_file() {
    let dir = tempfile::tempdir().unwrap();
    for name in IMAGES {
        let full = original(name);
        let len = full.len();
        // Inside the magic, the header, the offset table or first scan
        // lines, the middle of the pixel data, and one byte short.
        for cut in [0, 3, 40, 1000, len / 3, len / 2, len - 1] {
            let path = dir.path().join(format!("cut{cut}_{name}"));
            std::fs::write(&path, &full[..cut]).unwrap();
            match load(&path, &ImageLimits::default()) {
                Ok(_) => panic!("{name} cut to {cut} of {len} bytes loaded"),
                Err(e) => {
                    let text = e.to_string();
                    assert!(text.contains(&path.display().to_string()), "{text}");
                    // Read beside other work (the header may be whole):
                    // the same error.
                    let beside = load_beside(&path, &ImageLimits::default(), |_, _| ());
                    assert_eq!(beside.unwrap_err().to_string(), text);
                }
            }
        }
    }
}

#[test]
fn overwritten_bytes_never_panic() {
    let dir = tempfile::tempdir().unwrap();
    // A fixed xorshift sequence: the same damaged files on every run.
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let (mut errors, mut loaded) = (0, 0);
    for name in IMAGES {
        let full = original(name);
        for case in 0..12 {
            let mut bytes = full.clone();
            for _ in 0..3 {
                // Half of the damage lands in the first 2 KB: headers, offset
                // tables and the first chunk's own header.
                let span = if next() % 2 == 0 {
                    2048.min(bytes.len())
                } else {
                    bytes.len()
                };
                let at = (next() % span as u64) as usize;
                bytes[at] = next() as u8;
            }
            let path = dir.path().join(format!("damaged{case}_{name}"));
            std::fs::write(&path, &bytes).unwrap();
            // Damage to pixel data can decode to other pixel values: Ok is
            // allowed, a panic (or abort) is not.
            let header = size(&path, &ImageLimits::default());
            match load(&path, &ImageLimits::default()) {
                Ok(image) => {
                    loaded += 1;
                    // What decodes, the header said.
                    assert_eq!(header.unwrap(), (image.width, image.height));
                }
                Err(_) => errors += 1,
            }
        }
    }
    assert_eq!(errors + loaded, IMAGES.len() * 12);
}
