//! Any text as a draw list (`ps30 render`'s JSON). It is refused with a
//! message naming the place, or it loads within its limits: every target's
//! name is a plain file name (it becomes NAME.exr and NAME.png in the output
//! folder), and the whole list's pixel work and staged bytes are computed
//! without overflow. Nothing may panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::output::plain_name;
use ps30::jobs::render::{self, file};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let limits = file::FileLimits {
        max_pixels: 1 << 16,
        max_steps: 64,
        max_input_bytes: 1 << 16,
    };
    let dir = std::env::temp_dir();
    match file::parse(text, &dir.join("fuzz.json"), &limits) {
        Err(e) => assert!(!e.to_string().is_empty()),
        Ok(loaded) => {
            for t in &loaded.list.targets {
                assert!(plain_name(&t.name).is_ok(), "{:?}", t.name);
            }
            let _ = render::pixel_work(&loaded.list);
            let _ = render::staged_bytes_every_step(&loaded.list);
        }
    }
});
