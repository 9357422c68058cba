//! The validation faults found when ps30 was compared with an independent
//! assembler, each pinned in both directions: what Microsoft's validator
//! refuses is refused (with the place and a message that says why), and
//! what it accepts still loads.
//!
//! Why: a validator that accepts too much lets a shader through that
//! Direct3D will refuse at `CreatePixelShader`; one that refuses too much
//! stops a user with a working shader. The rules and their sources:
//!
//! * reads of temporaries: "If a temporary register uses components that
//!   are not defined in previous code, shader validation will fail"
//!   (Microsoft's ps_3_0 temporary-register page), per component, counted
//!   in program order (`core::valid::init` says how);
//! * `v[aL + n]`: input registers need a declaration (Microsoft's ps_3_0
//!   register table), so every register the loop's aL reaches is checked;
//! * `vFace` is the operand of `setp_comp`, `if_comp` and `break_comp`
//!   (same table), a scalar that needs no replicate swizzle;
//! * `dcl_2d_centroid s0`, `dcl_2d_pp s0`: Microsoft's assembler refuses
//!   both (X5969), though Wine's vectors ps_3_0 #13 and #14 hold their
//!   tokens;
//! * the documented rules Microsoft's assembler does not enforce (reads of
//!   unwritten temporaries, undeclared inputs read through aL, oC# written
//!   in branches, mixed `_abs` constant reads) are warnings that `--strict`
//!   makes errors.

use crate::common::bin;

use ps30::core::load::{self, Options};

fn loads(src: &str) -> Result<load::Loaded, String> {
    load::load_str("v.psh", src, &Options::default()).map_err(|e| e.diagnostics.render(&e.file))
}

/// The first error under `--strict` (which also refuses the documented
/// rules Microsoft's assembler lets through): its message, and its line
/// and column.
fn refusal(src: &str) -> (String, (usize, usize)) {
    let strict = Options {
        strict: true,
        ..Options::default()
    };
    let e = load::load_str("v.psh", src, &strict).expect_err(src);
    let d = e.diagnostics.errors().next().expect("an error");
    (d.message.clone(), e.file.line_col(d.span.start))
}

#[test]
fn temporaries_are_written_before_they_are_read() {
    // (source, first error, line) — each refused where the read is.
    let refused = [
        (
            "ps_3_0\nmov oC0, r5\n",
            "r5 is read, but no earlier instruction writes it",
            2,
        ),
        (
            "ps_3_0\nmov r0.xy, c0\nmov oC0, r0\n",
            "r0.zw is read, but earlier instructions write only r0.xy",
            3,
        ),
        // An accumulator read in the loop before the loop writes it.
        (
            "ps_3_0\ndefi i0, 4, 0, 0, 0\nrep i0\n  add r0, r0, c0\nendrep\nmov oC0, r0\n",
            "r0 is read, but no earlier instruction writes it",
            4,
        ),
        // Three components for dp3, the replicated one for rcp.
        (
            "ps_3_0\nmov r1.xy, c0\ndp3 r0.x, r1, c0\nmov oC0, r0.x\n",
            "r1.z is read",
            3,
        ),
        (
            "ps_3_0\nmov r1.xyz, c0\nrcp r0.x, r1.w\nmov oC0, r0.x\n",
            "r1.w is read",
            3,
        ),
        // Every row register of a matrix.
        (
            "ps_3_0\nmov r1, c0\nmov r2, c0\nm3x3 r0.xyz, c0, r1\nmov oC0, r0.xyzz\n",
            "r3 is read, but no earlier instruction writes it",
            4,
        ),
        // texkill tests xyz of its operand.
        ("ps_3_0\nmov r0.xy, c0\ntexkill r0\n", "r0.z is read", 3),
        // A subroutine called only after the read writes nothing before it.
        (
            "ps_3_0\nmov oC0, r0\ncall l0\nret\nlabel l0\nmov r0, c0\nret\n",
            "r0 is read, but no earlier instruction writes it",
            2,
        ),
    ];
    for (src, message, line) in refused {
        // Microsoft's assembler accepts each: by default a warning that
        // --strict makes an error.
        let loaded = loads(src).unwrap_or_else(|e| panic!("{src}: {e}"));
        let w = loaded.warnings.warnings().next().expect("a warning");
        assert!(w.strict && w.message.contains(message), "{src}: {w:?}");
        let (got, at) = refusal(src);
        assert!(
            got.contains(message),
            "{src}: `{got}`, expected `{message}`"
        );
        assert_eq!(at.0, line, "{src}: {got}");
    }
    // What is read is exactly what the operation reads.
    let accepted = [
        // A 2D sampler reads xy of its coordinate; texldl reads w too.
        "ps_3_0\ndcl_2d s0\nmov r1.xy, c0\ntexld r0, r1, s0\nmov oC0, r0\n",
        "ps_3_0\ndcl_2d s0\nmov r1.xyw, c0\ntexldl r0, r1, s0\nmov oC0, r0\n",
        // A write mask selects source components through the swizzle.
        "ps_3_0\nmov r1.y, c0\nmov r0.xz, r1.yyyy\nmov r0.yw, c0\nmov oC0, r0\n",
        "ps_3_0\nmov r1.xyz, c0\ndp3 r0, r1, c0\nmov oC0, r0\n",
        // Writes inside an if, under a predicate, or in a called subroutine
        // count as earlier code.
        "ps_3_0\ndefb b0, true\nif b0\n  mov r0, c0\nendif\nmov oC0, r0\n",
        "ps_3_0\n(p0.x) mov r0, c0\nmov oC0, r0\n",
        "ps_3_0\ncall l0\nmov oC0, r0\nret\nlabel l0\ncall l1\nret\nlabel l1\nmov r0, c0\nret\n",
    ];
    for src in accepted {
        if let Err(e) = loads(src) {
            panic!("{src} refused:\n{e}");
        }
    }
}

#[test]
fn inputs_read_relative_to_al_are_declared() {
    // i0 = 3 iterations from aL = 1, step 2: v[aL] reads v1, v3, v5.
    let head = "ps_3_0\ndefi i0, 3, 1, 2, 0\ndcl_texcoord1 v1\ndcl_texcoord3 v3\n";
    let body = "mov r0, c0\nloop aL, i0\n  add r0, r0, v[aL]\nendloop\nmov oC0, r0\n";
    // Microsoft's assembler does not check reads through aL: a warning,
    // an error under --strict.
    let loaded = loads(&format!("{head}{body}")).expect("a warning only");
    assert!(loaded.warnings.warnings().any(|w| w.strict));
    let (message, at) = refusal(&format!("{head}{body}"));
    assert_eq!(message, "input v5 is used but never declared");
    assert_eq!(at, (7, 3));
    loads(&format!("{head}dcl_texcoord5 v5\n{body}")).expect("all three declared");
    // An offset moves every register read: v0[aL + 1] with aL = 1, 3, 5
    // reads v2, v4, v6.
    let (message, _) = refusal(&format!(
        "{head}dcl_texcoord5 v5\nmov r0, c0\nloop aL, i0\n  add r0, r0, v[aL + 1]\nendloop\nmov oC0, r0\n"
    ));
    assert_eq!(message, "input v2 is used but never declared");
    // With i0 set by the application, the register named (aL = 0) is the
    // one checked.
    let (message, _) =
        refusal("ps_3_0\nmov r0, c0\nloop aL, i0\n  add r0, r0, v0[aL]\nendloop\nmov oC0, r0\n");
    assert_eq!(message, "input v0 is used but never declared");
    // Values of aL past v9 are undefined in Direct3D, not invalid: the
    // emulator reads 0 there (tests/quads.rs), validation lets them be.
    loads(
        "ps_3_0\ndefi i0, 3, 8, 1, 0\ndcl_texcoord8 v8\ndcl_texcoord9 v9\nmov r0, c0\n\
         loop aL, i0\n  add r0, r0, v[aL]\nendloop\nmov oC0, r0\n",
    )
    .expect("v8, v9 declared; v10 is out of range");
}

#[test]
fn vface_is_a_comparison_operand_without_a_swizzle() {
    let loaded = loads(
        "ps_3_0\ndcl vFace\ndef c0, 0, 1, 0, 0\ndefi i0, 2, 0, 0, 0\nmov r0, c0\n\
         if_lt vFace, c0.x\n  mov r0, c0.y\nendif\n\
         rep i0\n  break_ge vFace, c0.x\n  add r0, r0, c0.y\nendrep\nmov oC0, r0\n",
    )
    .expect("vFace in if_comp and break_comp");
    assert_eq!(
        loaded.warnings.warnings().count(),
        0,
        "{:?}",
        loaded.warnings
    );
    // Other registers still need a replicate swizzle there.
    let (message, _) = refusal("ps_3_0\ndcl_texcoord0 v0\nif_lt v0, c0.x\nendif\nmov oC0, c0\n");
    assert!(message.contains("needs a replicate swizzle"), "{message}");
}

#[test]
fn sampler_declarations_take_no_centroid_or_pp() {
    // Microsoft's assembler refuses both (X5969, "dcl for s register does
    // not support any modifiers"), though the token has room for them.
    for src in [
        "ps_3_0\ndcl_2d_centroid s0\nmov oC0, c0\n",
        "ps_3_0\ndcl_cube_pp s1\nmov oC0, c0\n",
    ] {
        let e = load::load_str("v.psh", src, &Options::default()).expect_err(src);
        let d = e.diagnostics.errors().next().unwrap();
        assert_eq!(d.code, Some("X5969"), "{src}: {d:?}");
    }
    // And through the command: exit 2, the code beside the message.
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.psh");
    std::fs::write(&f, "ps_3_0\ndcl_2d_centroid s0\nmov oC0, c0\n").unwrap();
    let out = bin::ps30(&["expand", f.to_str().unwrap()], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let text = String::from_utf8(out.stderr).unwrap();
    assert!(text.contains("error[X5969]"), "{text}");
}

#[test]
fn strict_turns_the_documented_rules_into_errors() {
    // oC0 written in an if, mixed _abs reads, an unwritten temporary:
    // Microsoft's assembler accepts each, so ps30 warns; --strict refuses.
    let src = "ps_3_0\nif_gt c0.x, c0.y\n  mov oC0, c0_abs\nendif\nmov r1, c1\nmov oC1, r2\n";
    let loaded = loads(src).expect("warnings only");
    let strict: Vec<_> = loaded.warnings.warnings().filter(|w| w.strict).collect();
    assert_eq!(strict.len(), 3, "{:?}", loaded.warnings);
    let e = load::load_str(
        "v.psh",
        src,
        &Options {
            strict: true,
            ..Options::default()
        },
    )
    .expect_err("strict");
    assert_eq!(e.diagnostics.errors().count(), 3);
    // Through the command line, on every command that loads a shader.
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("w.psh");
    std::fs::write(&f, src).unwrap();
    let path = f.to_str().unwrap();
    let out = dir.path().join("w.bin");
    for args in [
        vec!["asm", path, "-o", out.to_str().unwrap()],
        vec!["check", path],
        vec!["expand", path],
    ] {
        let plain = bin::ps30(&args, dir.path());
        assert_eq!(plain.status.code(), Some(0), "{args:?}");
        let mut with = args.clone();
        with.push("--strict");
        let strict = bin::ps30(&with, dir.path());
        assert_eq!(strict.status.code(), Some(2), "{with:?}");
        let text = String::from_utf8(strict.stderr).unwrap();
        assert!(text.contains("an error under --strict"), "{text}");
    }
}

#[test]
fn the_gradient_rule_is_a_warning_when_measured_and_an_error_when_assembled() {
    // Microsoft's assembler refuses texld with a temporary coordinate in a
    // dynamic if (X6077): ps30 asm too; check and run may still load it.
    let src = "ps_3_0\ndcl_2d s0\ndcl_texcoord0 v0\nmov r0, c0\nif_gt v0.x, c0.x\n  add r1, v0, c0\n  texld r0, r1, s0\nendif\nmov oC0, r0\n";
    let loaded = loads(src).expect("a warning when measured");
    assert!(loaded.warnings.warnings().any(|w| w.code == Some("X6077")));
    let e = load::assemble(
        load::load_str("v.psh", src, &Options::default())
            .unwrap()
            .file,
        &Options::default(),
    )
    .expect_err("refused when assembled");
    assert_eq!(e.diagnostics.errors().next().unwrap().code, Some("X6077"));
}
