//! The translation of every bundled and generated shader to every target:
//! each module passes naga's validator, every writer succeeds, and the
//! WGSL parses back through naga's WGSL front end and validates again.

use ps30::core::float_rules::FloatRules;
use ps30::core::load::{load_str, Options};
use ps30::core::translate::{self, header, Entry, Target, Written};

fn load(name: &str, text: &str) -> ps30::core::ir::Shader {
    let mut opts = Options::default();
    opts.defines.insert("xsize".into(), 11);
    opts.defines.insert("ysize".into(), 8);
    load_str(name, text, &opts)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .shader
}

/// Translates to every target and reads the WGSL back.
fn check(name: &str, shader: &ps30::core::ir::Shader, rules: FloatRules, entry: Entry) {
    let t = translate::translate(shader, rules, entry)
        .unwrap_or_else(|e| panic!("{name} ({rules}): {e}"));
    for target in Target::ALL {
        let h = header::comment(name, &t, target);
        match translate::write(&t, target, &h)
            .unwrap_or_else(|e| panic!("{name} → {target:?}: {e}"))
        {
            Written::Text(text) => {
                assert!(
                    text.contains(name),
                    "{name} → {target:?}: the header names the source"
                );
                if target == Target::Wgsl {
                    let back = naga::front::wgsl::parse_str(&text).unwrap_or_else(|e| {
                        panic!(
                            "{name}: WGSL does not parse back: {}\n{text}",
                            e.emit_to_string(&text)
                        )
                    });
                    naga::valid::Validator::new(
                        naga::valid::ValidationFlags::all(),
                        naga::valid::Capabilities::default(),
                    )
                    .validate(&back)
                    .unwrap_or_else(|e| panic!("{name}: WGSL read back fails validation: {e:?}"));
                }
            }
            Written::Binary(words) => {
                assert_eq!(&words[..4], &0x0723_0203u32.to_le_bytes(), "SPIR-V magic");
            }
        }
    }
}

#[test]
fn every_bundled_shader_translates_to_every_target() {
    for b in ps30::jobs::bundled::ALL {
        let shader = load(b.path, b.text);
        for rules in FloatRules::ALL {
            check(b.path, &shader, rules, Entry::Application);
        }
        check(b.path, &shader, FloatRules::D3d9, Entry::Draw);
    }
}
