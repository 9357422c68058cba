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
    use rayon::prelude::*;
    // Shader by shader on the pool: naga is unoptimised in the test profile
    // (Cargo.toml), and this is the suite's longest test.
    ps30::jobs::bundled::ALL.par_iter().for_each(|b| {
        let shader = load(b.path, b.text);
        for rules in FloatRules::ALL {
            check(b.path, &shader, rules, Entry::Application);
        }
        check(b.path, &shader, FloatRules::D3d9, Entry::Draw);
    });
}

/// The constant block's layout, as the WGSL output declares it (WGSL
/// computes offsets from its own alignment rules), is the one
/// `interface.rs` documents and `core/gpu` fills.
#[test]
fn the_constant_block_layout_is_the_documented_one() {
    use ps30::core::translate::interface;
    let shader = load("tonemap", ps30::jobs::bundled::TONEMAP_REINHARD.text);
    let t = translate::translate(&shader, FloatRules::D3d9, Entry::Application).unwrap();
    let Written::Text(wgsl) = translate::write(&t, Target::Wgsl, "").unwrap() else {
        panic!("WGSL is text");
    };
    let back = naga::front::wgsl::parse_str(&wgsl).unwrap();
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(back.to_ctx()).unwrap();
    let (handle, ty) = back
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some("Ps30Constants"))
        .expect("Ps30Constants");
    let naga::TypeInner::Struct { members, .. } = &ty.inner else {
        panic!("a struct");
    };
    let offsets: Vec<(String, u32)> = members
        .iter()
        .map(|m| (m.name.clone().unwrap(), m.offset))
        .collect();
    assert_eq!(
        offsets,
        [
            ("c".to_string(), interface::FLOATS_OFFSET),
            ("i".to_string(), interface::INTS_OFFSET),
            ("b".to_string(), interface::BOOLS_OFFSET),
            ("s".to_string(), interface::SAMPLERS_OFFSET),
        ]
    );
    assert_eq!(layouter[handle].size, interface::CONSTANTS_SIZE);
}

/// The header names the source, the rules, and where the shader's
/// constants, sampler, input and output are bound.
#[test]
fn the_header_says_what_an_application_binds() {
    let b = ps30::jobs::bundled::CORRECTED_LOOP;
    let shader = load(b.path, b.text);
    let t = translate::translate(&shader, FloatRules::Ieee, Entry::Application).unwrap();
    let h = header::comment(b.path, &t, Target::Glsl);
    for want in [
        "asm/corrected/lum_pass1_loop.psh: Direct3D 9 ps_3_0, translated by ps30 to GLSL 4.50 core",
        "float rules: ieee",
        "this shader reads c0, c1, c3",
        "reads i1, i2",
        "binding 1: s0's texture (2D), binding 2: its sampler",
        "@location(0): v0 (dcl_texcoord0)",
        "@location(0) out: oC0",
    ] {
        assert!(h.contains(want), "missing `{want}` in\n{h}");
    }
    assert!(h.lines().all(|l| l.is_empty() || l.starts_with("//")));
}

/// The translation writes the extra code a rule needs only under that
/// rule: `-FLT_MAX` for log(0) appears in d3d9's WGSL, not in ieee's.
#[test]
fn rules_add_code_only_where_they_differ() {
    let shader = load(
        "log",
        "ps_3_0\ndcl_texcoord0 v0\nlog r0, v0.x\nmov oC0, r0\n",
    );
    let wgsl = |rules| {
        let t = translate::translate(&shader, rules, Entry::Application).unwrap();
        match translate::write(&t, Target::Wgsl, "").unwrap() {
            Written::Text(s) => s,
            Written::Binary(_) => unreachable!(),
        }
    };
    let flt_max = "-340282350000000000000000000000000000000f";
    assert!(wgsl(FloatRules::D3d9).contains(flt_max));
    assert!(!wgsl(FloatRules::Ieee).contains(flt_max));
    assert!(wgsl(FloatRules::Ieee).contains("log2("));
}

/// Every generated shader (asm/generated/, six frame sizes) translates too.
#[test]
fn every_generated_shader_translates() {
    let set = ps30::jobs::gen::set::generated_set().unwrap();
    for (path, text) in &set.files {
        let shader = load(path, text);
        let t = translate::translate(&shader, FloatRules::D3d9, Entry::Application)
            .unwrap_or_else(|e| panic!("{path}: {e}"));
        translate::write(&t, Target::SpirV, "").unwrap_or_else(|e| panic!("{path}: {e}"));
    }
}

/// Implicit derivatives in flow control that may differ between a quad's
/// pixels turn WGSL's `derivative_uniformity` off and say where; the same
/// sampling under a constant `if b#` or in straight-line code does not.
#[test]
fn derivatives_under_divergent_flow_are_named() {
    let translate = |name: &str, body: &str| {
        let text = format!("ps_3_0\ndcl_texcoord0 v0.xy\ndcl_2d s0\n{body}mov oC0, r0\n");
        let shader = load(name, &text);
        translate::translate(&shader, FloatRules::D3d9, Entry::Application)
            .unwrap_or_else(|e| panic!("{name}: {e}"))
    };
    let divergent = translate(
        "divergent",
        "mov r0, c0\nif_gt v0.x, c0.x\ntexld r0, v0, s0\nendif\n",
    );
    assert!(divergent.derivative_uniformity_off);
    assert!(
        divergent
            .notes
            .iter()
            .any(|n| n.contains("instruction 3, `texld`")),
        "{:?}",
        divergent.notes
    );
    let Written::Text(wgsl) = translate::write(&divergent, Target::Wgsl, "").unwrap() else {
        panic!("WGSL is text")
    };
    assert!(
        wgsl.contains("diagnostic(off, derivative_uniformity)"),
        "{wgsl}"
    );

    let by_constant = translate("constant", "mov r0, c0\nif b0\ntexld r0, v0, s0\nendif\n");
    assert!(
        !by_constant.derivative_uniformity_off,
        "{:?}",
        by_constant.notes
    );
    let straight = translate("straight", "texld r0, v0, s0\n");
    assert!(!straight.derivative_uniformity_off, "{:?}", straight.notes);
}
