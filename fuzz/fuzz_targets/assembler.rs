//! Arbitrary text through the whole front end (parse, REPEAT_BLOCK
//! expansion, validation), then the cost model and the writer's round trip
//! on whatever validates. Nothing may panic; expansion is capped small so a
//! macro bomb is refused, not run.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::cost::{analyse, Environment, Profile};
use ps30::core::load::{load_str, Options};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut options = Options {
        max_expanded: 4_096,
        ..Options::default()
    };
    options.defines.insert("n".into(), 3);
    let Ok(loaded) = load_str("fuzz.psh", text, &options) else {
        return;
    };
    if let Ok(a) = analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &Profile::ps_3_0(),
    ) {
        assert!(a.executed.min <= a.executed.max);
    }
    // What the writer prints must load back to the same instructions.
    let printed = ps30::core::front::print::write_program(loaded.shader.program());
    let again =
        load_str("printed.psh", &printed, &Options::default()).expect("writer output loads");
    assert_eq!(
        loaded.shader.instructions().len(),
        again.shader.instructions().len()
    );
});
