//! Load a shader and check it against the ps_3_0 budgets, as `ps30 check`
//! does: the instruction slots, the executed instructions per pixel and the
//! verdict, with any warnings of validation.
//!
//! ```text
//! cargo run --example check_shader                  # the article's loop listing
//! cargo run --example check_shader -- my.psh        # a file of your own
//! ```

use ps30::core::{cost, load};
use ps30::jobs::bundled;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A file named on the command line, or a listing bundled in the library.
    let (name, text) = match std::env::args().nth(1) {
        Some(path) => {
            let text = std::fs::read_to_string(&path)?;
            (path, text)
        }
        None => {
            let b = bundled::find("article:loop").expect("a bundled listing");
            (b.path.to_string(), b.text.to_string())
        }
    };
    // The front end: parse, expand REPEAT_BLOCK, validate. An error carries
    // compiler-style diagnostics that render against the source.
    let loaded = match load::load_str(&name, &text, &load::Options::default()) {
        Ok(l) => l,
        Err(e) => {
            eprint!("{}", e.diagnostics.render(&e.file));
            std::process::exit(2);
        }
    };
    if !loaded.warnings.items.is_empty() {
        eprint!("{}", loaded.warnings.render(&loaded.file));
    }
    // The cost model: exact slots and the range of executed instructions.
    // The loop listing reads its counts from i1 and i2, which the article
    // sets to a 128 × 56 block; without them the loops run 0 times.
    let mut env = cost::Environment::default();
    env.ints.insert(1, [128, 0, 0, 0]);
    env.ints.insert(2, [56, 0, 0, 0]);
    let profile = cost::Profile::ps_3_0();
    let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
    println!(
        "{name}: {} slots of {}, {}..{} executed of {}: {:?}",
        a.slots, profile.max_slots, a.executed.min, a.executed.max, profile.max_executed, a.verdict
    );
    Ok(())
}
