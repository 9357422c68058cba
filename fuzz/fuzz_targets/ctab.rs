//! Any tokens as a constant table (the body of a `CTAB` comment block, the
//! hostile part of a compiled shader). It is refused with an offset inside
//! the table, or it decodes to constants whose registers all exist in
//! ps_3_0's register files. Nothing may panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::bytecode::ctab::{self, RegisterSet};

fuzz_target!(|data: &[u8]| {
    let words: Vec<u32> = data
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    match ctab::decode(&words) {
        Err(e) => assert!(e.offset <= words.len() * 4, "{}", e.message),
        Ok(table) => {
            for c in &table.constants {
                let last = u32::from(c.index) + u32::from(c.count);
                let available = match c.set {
                    RegisterSet::Float4 => 224,
                    RegisterSet::Int4 | RegisterSet::Bool | RegisterSet::Sampler => 16,
                };
                assert!(last <= available, "{}: {last}", c.name);
            }
        }
    }
});
