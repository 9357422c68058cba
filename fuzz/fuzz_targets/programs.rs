//! Random *valid* programs (the generator of tests/cost.rs: rep/loop nests,
//! static ifs, breaks, REPEAT_BLOCKs, subroutines) through the cost model
//! and the emulator: the emulator's per-pixel executed count must equal the
//! symbolic count, and nothing may panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::cost::{analyse, Environment, Profile};
use ps30::core::emu::{self, Draw, LinearInput, SamplerState, Texture};
use ps30::core::load::{load_str, Options};

#[path = "../../tests/common/program_gen.rs"]
mod program_gen;

fuzz_target!(|data: &[u8]| {
    let src = program_gen::random_program(data);
    let loaded =
        load_str("random.psh", &src, &Options::default()).expect("generated programs are valid");
    let a = analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &Profile::ps_3_0(),
    )
    .expect("defi constants are in range");
    if a.executed.max > 1_000_000 {
        return;
    }
    let compiled = emu::compile(&loaded.shader).expect("valid programs compile");
    let mut draw = Draw::new(2, 2);
    for d in &loaded.shader.program().inputs {
        if d.reg.file == ps30::core::isa::RegFile::Input {
            draw.inputs
                .push((d.reg.index, LinearInput::constant([0.25, 0.5, 0.75, 1.0])));
        }
    }
    let texels = [[0.5f32; 4]; 4];
    for s in &loaded.shader.program().samplers {
        if s.ty == ps30::core::isa::SamplerType::Tex2d {
            draw.samplers.push((
                s.index,
                Texture {
                    width: 2,
                    height: 2,
                    texels: &texels,
                }
                .into(),
                SamplerState::default(),
            ));
        }
    }
    let out = emu::run_with_threads(&compiled, &draw, 1).expect("draw runs");
    for c in out.executed {
        assert!(
            a.executed.min <= c && c <= a.executed.max,
            "emulator {c}, cost model {:?}\n{src}",
            a.executed
        );
        if a.executed.is_exact() {
            assert_eq!(c, a.executed.min, "\n{src}");
        }
    }
});
