//! `ps30 decompile` over the project's own corpus: every ps_3_0 shader of
//! `asm/` and every HLSL shader of `tests/oracle/corpus/hlsl/` that
//! Microsoft's compiler accepted (its bytecode fixture) is decompiled; the
//! HLSL is committed under `tests/oracle/corpus/hlsl/decompiled/` (the
//! test fails when it is not what the decompiler writes today:
//! `PS30_WRITE_DECOMPILED=1 cargo test --test suite decompile::` rewrites
//! it), so `tools/oracle/regen` records Microsoft's compilation of it as
//! fixtures like any corpus file; and the recompiled bytecode of each
//! fixture runs in the emulator against the original on the same inputs,
//! which must agree bit for bit.
//!
//! Shaders the decompiler refuses, and shaders whose recompilation is not
//! identical, are listed below with the reason, so that a change in either
//! direction fails the test.

use ps30::core::decompile::{decompile, DecompileError, Decompiled};
use ps30::core::load;
use ps30::jobs::decompile::{equivalence_of_bytes, Kind};
use std::path::{Path, PathBuf};

/// Shaders the decompiler refuses today, with the reason.
const REFUSED: &[(&str, &str)] = &[(
    "hlsl/listing/loop-input-array.hlsl",
    "v[aL + n]: an input array indexed by the loop counter",
)];

/// Recompiled shaders that do not run identically: in each, Microsoft's
/// compiler made different instructions of the HLSL than the original has
/// (it adds a range reduction, `frc` and `mad`, in front of every `sincos`
/// of `sin`/`cos`, splits or fuses `mad`s, and optimises shaders that were
/// compiled with optimisation off), so the rounding differs; the largest
/// difference seen and the instruction counts that changed
/// (original → recompiled) are the reason. `ps30 decompile --verify`
/// reports these as differences (exit 1).
const NOT_IDENTICAL: &[(&str, &str)] = &[
    ("hlsl/flags/gen_blinn_phong__skipopt.hlsl", "max 61 ulp; the compiler changed add: 6 → 1, cmp: 3 → 1, dp3: 5 → 3, exp: 1 → 0, log: 1 → 0, mad: 0 → 2, mov: 2 → 1, mul: 8 → 3, nrm: 0 → 2, pow: 0 → 1, rsq: 3 → 1"),
    ("hlsl/flags/gen_blinn_phong__skipopt_pp.hlsl", "max 61 ulp; the compiler changed add: 6 → 1, cmp: 3 → 1, dp3: 5 → 3, exp: 1 → 0, log: 1 → 0, mad: 0 → 2, mov: 2 → 1, mul: 8 → 3, nrm: 0 → 2, pow: 0 → 1, rsq: 3 → 1"),
    ("hlsl/conformance/nonfinite.hlsl", "max 1 ulp; the compiler changed rcp: 5 → 1"),
    ("hlsl/flags_debug/dbg_targets.hlsl", "max 240 ulp; the compiler changed mov: 13 → 5"),
    ("hlsl/gen_flow/loop_nested_none.hlsl", "max 5 ulp; the compiler changed mad: 6 → 3, mul: 4 → 5"),
    ("hlsl/gen_flow/loop_nested_unroll.hlsl", "max 5 ulp; the compiler changed mad: 6 → 3, mul: 4 → 5"),
    ("hlsl/gen_flow/loop_nested_unroll3.hlsl", "max 796917760 ulp; the compiler changed mad: 4 → 2, mul: 3 → 4 (a sum of products near 1 that cancels to 2e-10: an ulp of the terms)"),
    ("hlsl/lighting/oren_nayar.hlsl", "max 4 ulp; the compiler changed cmp: 2 → 3, max: 3 → 2, mov: 1 → 2"),
    ("hlsl/surface/water_gerstner_normal.hlsl", "max 2 ulp; the compiler changed add: 2 → 3, mad: 12 → 11, mov: 2 → 1, mul: 25 → 26"),
];

/// Decompiled shaders Microsoft's compiler refuses: the unrolled article
/// shaders and the generated ones read more values at once than its
/// register allocator fits in 32 temporaries (X4505, maximum temp register
/// index exceeded), which the original's hand allocation does.
const REFUSED_BY_COMPILER: &[&str] = &[
    "asm/article/lum_pass1_unrolled.psh",
    "asm/corrected/lum_pass1_unrolled.psh",
    "asm/generated/1024x768/pass1_last_unrolled_112x128.psh",
    "asm/generated/1024x768/pass1_unrolled_114x128.psh",
    "asm/generated/1024x768/pass1_unrolled_125x128.psh",
    "asm/generated/1280x1024/pass1_last_unrolled_110x128.psh",
    "asm/generated/1280x1024/pass1_unrolled_117x128.psh",
    "asm/generated/1280x1024/pass1_unrolled_125x128.psh",
    "asm/generated/1920x1080/pass1_unrolled_120x120.psh",
    "asm/generated/1920x1080/pass1_unrolled_125x120.psh",
    "asm/generated/2560x1440/pass1_last_unrolled_120x131.psh",
    "asm/generated/2560x1440/pass1_unrolled_122x131.psh",
    "asm/generated/2560x1440/pass1_unrolled_125x120.psh",
    "asm/generated/3840x2160/pass1_last_unrolled_111x135.psh",
    "asm/generated/3840x2160/pass1_last_unrolled_90x128.psh",
    "asm/generated/3840x2160/pass1_unrolled_113x135.psh",
    "asm/generated/3840x2160/pass1_unrolled_125x128.psh",
    "asm/generated/640x480/pass1_last_unrolled_105x120.psh",
    "asm/generated/640x480/pass1_unrolled_107x120.psh",
    "asm/generated/640x480/pass1_unrolled_125x120.psh",
];

/// Pixels on a side of each verification draw.
const SIZE: u32 = 32;

/// One shader of the corpus: its name (`hlsl/REL` or `asm/REL`) and the
/// loaded shader with its constant table.
struct Source {
    name: String,
    loaded: load::Loaded,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn decompiled_dir() -> PathBuf {
    root().join("tests/oracle/corpus/hlsl/decompiled")
}

fn walk(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.unwrap().path();
        if p.is_dir() {
            walk(&p, ext, out);
        } else if p.extension().is_some_and(|e| e == ext) {
            out.push(p);
        }
    }
}

/// Every ps_3_0 shader of the corpus.
fn sources() -> Vec<Source> {
    let options = load::Options::default();
    let mut out = Vec::new();
    for f in crate::oracle::fixtures("hlsl") {
        if f.rel.starts_with("decompiled/") || !f.accepted() {
            continue;
        }
        let Some(fxo) = f.fxo else { continue };
        let file = load::source_file(&f.rel, fxo, &options).expect("a fixture's bytecode reads");
        let loaded = load::load(file, &options).unwrap_or_else(|e| panic!("{}: {e}", f.rel));
        // The decompiler writes ps_3_0 (the ps_2_0 conformance shaders and the vertex
        // shaders of `hlsl/vertex/` are not its input).
        if loaded.shader.program().profile != ps30::core::profile::Profile::Ps3_0 {
            continue;
        }
        out.push(Source {
            name: format!("hlsl/{}", f.rel),
            loaded,
        });
    }
    let mut asm = Vec::new();
    walk(&root().join("asm"), "psh", &mut asm);
    asm.sort();
    for p in asm {
        let rel = p
            .strip_prefix(root().join("asm"))
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        let file = load::source_file(&rel, std::fs::read(&p).unwrap(), &options).unwrap();
        match load::load(file, &options) {
            // decompile writes HLSL for ps_3_0; ps_1_x has no HLSL target left
            // (Microsoft's compiler refuses it, X3539).
            Ok(loaded) if loaded.shader.program().profile.is_ps1() => {}
            Ok(loaded) => out.push(Source {
                name: format!("asm/{rel}"),
                loaded,
            }),
            // shaders that need `-D` counts (REPEAT_BLOCK sizes) are not one shader
            Err(e) if e.to_string().contains("is not defined") => {}
            Err(e) => panic!("asm/{rel} does not load: {e}"),
        }
    }
    out
}

fn decompiled(s: &Source) -> Result<Decompiled, DecompileError> {
    decompile(&s.loaded.shader, s.loaded.constants.as_ref())
}

/// The committed file of a source's HLSL.
fn committed(name: &str) -> PathBuf {
    let rel = name.strip_suffix(".hlsl").unwrap_or(name);
    decompiled_dir().join(format!("{rel}.hlsl"))
}

#[test]
fn the_corpus_decompiles_and_the_committed_hlsl_is_current() {
    let write = std::env::var_os("PS30_WRITE_DECOMPILED").is_some();
    let (mut ok, mut refused, mut problems) = (0, Vec::new(), Vec::new());
    let mut expected = Vec::new();
    for s in sources() {
        let path = committed(&s.name);
        match decompiled(&s) {
            Ok(d) => {
                ok += 1;
                expected.push(path.clone());
                if write {
                    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
                    std::fs::write(&path, &d.hlsl).unwrap();
                } else if std::fs::read_to_string(&path).ok().as_deref() != Some(d.hlsl.as_str()) {
                    problems.push(format!(
                        "{}: {} is not today's output",
                        s.name,
                        path.display()
                    ));
                }
            }
            Err(e) => {
                if !REFUSED.iter().any(|(n, _)| *n == s.name) {
                    problems.push(format!("{}: refused: {e}", s.name));
                }
                refused.push(s.name.clone());
            }
        }
    }
    for (n, why) in REFUSED {
        if !refused.iter().any(|r| r == n) {
            problems.push(format!("{n} is listed as refused ({why}) but decompiles"));
        }
    }
    let mut on_disk = Vec::new();
    walk(&decompiled_dir(), "hlsl", &mut on_disk);
    for p in on_disk {
        if !expected.contains(&p) {
            if write {
                std::fs::remove_file(&p).unwrap();
            } else {
                problems.push(format!("{} has no source any more", p.display()));
            }
        }
    }
    eprintln!("decompiled {ok} shaders, {} refused", refused.len());
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_recompiled_corpus_runs_identically() {
    let fixtures = root().join("tests/oracle/fixtures/hlsl/decompiled");
    let (mut identical, mut problems, mut seen) = (0, Vec::new(), Vec::new());
    let mut compiler_refused = 0;
    for s in sources() {
        let path = committed(&s.name);
        if !path.is_file() {
            continue;
        }
        let rel = path.strip_prefix(decompiled_dir()).unwrap();
        let base = fixtures.join(rel);
        let rc = std::fs::read_to_string(format!("{}.rc", base.display()));
        let Ok(rc) = rc else {
            problems.push(format!(
                "{}: no fixture for {}: run tools/oracle/regen",
                s.name,
                rel.display()
            ));
            continue;
        };
        let listed_refused = REFUSED_BY_COMPILER.contains(&s.name.as_str());
        if rc.trim() != "00000000" {
            let err =
                std::fs::read_to_string(format!("{}.err", base.display())).unwrap_or_default();
            if !listed_refused {
                problems.push(format!(
                    "{}: Microsoft's compiler refused the HLSL: {err}",
                    s.name
                ));
            }
            compiler_refused += 1;
            continue;
        }
        if listed_refused {
            problems.push(format!(
                "{} is listed as refused by the compiler but compiles",
                s.name
            ));
        }
        let fxo = std::fs::read(format!("{}.fxo", base.display())).unwrap();
        let v = equivalence_of_bytes(&s.loaded.shader, &fxo, SIZE)
            .unwrap_or_else(|e| panic!("{}: {e}", s.name));
        let listed = NOT_IDENTICAL.iter().any(|(n, _)| *n == s.name);
        if v.kind == Kind::Identical {
            identical += 1;
            if listed {
                problems.push(format!("{} is listed as not identical but is", s.name));
            }
        } else {
            seen.push(s.name.clone());
            if !listed {
                problems.push(format!(
                    "{}: {:?}: {} of {} values differ, max {} ulp, worst {:?}; changed: {}",
                    s.name,
                    v.kind,
                    v.differing,
                    v.values,
                    v.max_ulp,
                    v.worst,
                    v.changed_instructions.join(", ")
                ));
            }
        }
    }
    eprintln!(
        "{identical} recompiled shaders run identically, {} do not, {compiler_refused} do not compile",
        seen.len()
    );
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn verify_without_the_oracle_says_what_is_missing_and_exits_3() {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args([
            "decompile",
            "tests/oracle/fixtures/hlsl/lighting/blinn_phong.hlsl.fxo",
            "--verify",
        ])
        .current_dir(root())
        .env("PS30_ORACLE", root().join("target/no-such-oracle"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(3), "{err}");
    assert!(
        err.contains("Microsoft's compiler is not installed"),
        "{err}"
    );
    assert!(err.contains("tools/oracle/setup.sh"), "{err}");
}

#[test]
fn a_shader_the_hlsl_cannot_express_is_refused_naming_the_instruction() {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args([
            "decompile",
            "tests/oracle/fixtures/hlsl/listing/loop-input-array.hlsl.fxo",
        ])
        .current_dir(root())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("cannot decompile instruction") && err.contains("v[aL + n]"),
        "{err}"
    );
    assert!(o.stdout.is_empty());
}

/// The compiler's range reduction before `sincos` is read back as the
/// angle itself only where nothing but `sincos` reads the reduced value:
/// here once as the compiler writes it, once with the reduced angle also
/// written to `oC0.z`, where the arithmetic must stay.
#[test]
fn the_range_reduction_of_sin_is_read_back_only_where_sincos_alone_reads_it() {
    let shader = |extra: &str| {
        let text = format!(
            "ps_3_0\ndef c0, 0.159154937, 0.5, 6.28318548, -3.14159274\ndcl_texcoord v0.x\n\
             mad r0.x, v0.x, c0.x, c0.y\nfrc r0.x, r0.x\nmad r0.x, r0.x, c0.z, c0.w\n\
             sincos r1.xy, r0.x\n{extra}mov oC0.xy, r1\nmov oC0.zw, c0.y\n"
        );
        let loaded = load::load(
            load::source_file("t.psh", text.into_bytes(), &load::Options::default()).unwrap(),
            &load::Options::default(),
        )
        .unwrap();
        decompile(&loaded.shader, None).unwrap().hlsl
    };
    let alone = shader("");
    assert!(alone.contains("r0.x = texcoord0.x;"), "{alone}");
    assert!(!alone.contains("frac"), "{alone}");
    let shared = shader("mov oC0.z, r0.x\n");
    assert!(shared.contains("frac"), "{shared}");
    assert!(shared.contains("6.2831855"), "{shared}");
}
