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
const REFUSED: &[(&str, &str)] = &[];

/// Recompiled shaders whose values differ beyond the rounding bound
/// derived from both shaders' arithmetic (`jobs/decompile/bound.rs`), with
/// the reason: failures the decompiler still has. A shader whose values
/// differ within the bound passes (the compiler regrouped a sum, split a
/// `mad`); one beyond it that is not listed here fails the test, and so
/// does a listed one that passes.
///
/// None today. The last two, `lighting/oren_nayar` (4 ulp where `tan` as
/// `sin·rcp(cos)` is near `cos = 0`, whose bound is unbounded) and
/// `surface/water_gerstner_normal` (2 ulp in a cube map's coordinate), differed
/// because the compiler regrouped the decompiled products and sums around
/// literals; declared `precise`, the HLSL keeps the original's order and both
/// run bit-identical.
const BEYOND_BOUND: &[(&str, &str)] = &[];

/// Decompiled shaders Microsoft's compiler refuses, with none today: the
/// unrolled luminance shaders, refused while their 125 copies of one block
/// were straight code (X4505: the compiler read every texture first and
/// held the results past 32 temporaries), are written as `[loop]`s
/// (`core/decompile/repeat.rs`).
const REFUSED_BY_COMPILER: &[&str] = &[];

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
    let mut within = Vec::new();
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
        let listed = BEYOND_BOUND.iter().any(|(n, _)| *n == s.name);
        match v.kind {
            Kind::Identical => identical += 1,
            Kind::WithinBound => {
                within.push(format!(
                    "{}: {} of {} values differ, max {} ulp, within the bound ({})",
                    s.name,
                    v.differing,
                    v.values,
                    v.max_ulp,
                    v.explained_by.join("; ")
                ));
            }
            _ => {
                seen.push(s.name.clone());
                if !listed {
                    problems.push(format!(
                        "{}: {:?}: {} of {} values differ ({} beyond the bound), max {} ulp, \
                         first beyond {:?}; changed: {}",
                        s.name,
                        v.kind,
                        v.differing,
                        v.values,
                        v.unexplained,
                        v.max_ulp,
                        v.first_unexplained,
                        v.changed_instructions.join(", ")
                    ));
                }
            }
        }
        if listed && v.equivalent {
            problems.push(format!(
                "{} is listed as beyond the bound but is not",
                s.name
            ));
        }
    }
    for w in &within {
        eprintln!("{w}");
    }
    eprintln!(
        "{identical} recompiled shaders run identically, {} within the derived bound, {} beyond it, \
         {compiler_refused} do not compile",
        within.len(),
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
fn a_shader_the_hlsl_cannot_express_is_refused_naming_what() {
    let dir = root().join("target/decompile-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("packed.psh");
    std::fs::write(
        &path,
        "ps_3_0\ndcl_texcoord0 v0.xy\ndcl_texcoord1 v0.zw\nmov oC0, v0\n",
    )
    .unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(["decompile", path.to_str().unwrap()])
        .current_dir(root())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("cannot decompile") && err.contains("packed"),
        "{err}"
    );
    assert!(o.stdout.is_empty());
}

/// `v[aL + n]` reads the run of declarations around `v#n` as one array
/// parameter indexed by the loop counter.
#[test]
fn inputs_read_by_the_loop_counter_are_an_array_parameter() {
    let options = load::Options::default();
    let fxo = root().join("tests/oracle/fixtures/hlsl/listing/loop-input-array.hlsl.fxo");
    let file = load::source_file("a.fxo", std::fs::read(fxo).unwrap(), &options).unwrap();
    let loaded = load::load(file, &options).unwrap();
    let hlsl = decompile(&loaded.shader, loaded.constants.as_ref())
        .unwrap()
        .hlsl;
    assert!(hlsl.contains("float4 texcoord[4] : TEXCOORD0"), "{hlsl}");
    assert!(hlsl.contains("abs(texcoord[i].x)"), "{hlsl}");
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

fn assembled(text: &str) -> ps30::core::ir::Shader {
    let options = load::Options::default();
    let file = load::source_file("t.psh", text.as_bytes().to_vec(), &options).unwrap();
    load::load(file, &options).unwrap().shader
}

/// The derived bound tells a regrouped sum (the same function, rounded
/// differently) from a different function: `(v0 + v1) + v2` against
/// `(v1 + v2) + v0` differs in the last bits of some pixels, within the
/// bound `u·(|v0 + v1| + |Σ|)` of each; scaling one term by 1 + 2⁻¹⁰ is a
/// difference of up to 2⁻¹⁰·2 at inputs of magnitude 2, far beyond it.
#[test]
fn a_regrouped_sum_is_within_the_derived_bound_and_a_changed_term_is_not() {
    let head = "ps_3_0\ndcl_texcoord v0\ndcl_texcoord1 v1\ndcl_texcoord2 v2\n";
    let original = assembled(&format!(
        "{head}mov r1, v1\nadd r0, v0, r1\nadd oC0, r0, v2\n"
    ));
    let regrouped = assembled(&format!(
        "{head}mov r1, v2\nadd r0, v1, r1\nadd oC0, r0, v0\n"
    ));
    let scaled = assembled(&format!(
        "{head}def c0, 1.0009765625, 0, 0, 0\nmov r1, v2\nadd r0, v1, r1\nmad oC0, v0, c0.x, r0\n"
    ));
    let v = ps30::jobs::decompile::equivalence(&original, &regrouped, 32).unwrap();
    assert_eq!(v.kind, Kind::WithinBound, "{v:?}");
    assert!(
        v.equivalent && v.differing > 0 && v.unexplained == 0,
        "{v:?}"
    );
    let v = ps30::jobs::decompile::equivalence(&original, &scaled, 32).unwrap();
    assert_eq!(v.kind, Kind::Different, "{v:?}");
    let first = v.first_unexplained.expect("a value beyond the bound");
    assert!(first
        .bound
        .is_some_and(|e| (first.original - first.recompiled).abs() > e));
}

/// A block written out four or more times in a row is one `[loop]` around
/// a copy (`core/decompile/repeat.rs`); three copies stay straight code,
/// and the code around the loop keeps its order.
#[test]
fn a_block_written_out_four_times_is_a_loop() {
    let shader = |copies: usize| {
        let block = "texld r1, r0, s0\nadd r2, r2, r1\nadd r0.x, r0.x, c0.x\n".repeat(copies);
        let text = format!(
            "ps_3_0\ndcl_texcoord v0\ndcl_2d s0\nmov r0, v0\nmov r2, c1\n{block}mul oC0, r2, c2\n"
        );
        decompile(&assembled(&text), None).unwrap().hlsl
    };
    let four = shader(4);
    assert!(
        four.contains("[loop] for (int n0 = 0; n0 < 4; n0++) {"),
        "{four}"
    );
    assert_eq!(four.matches("tex2D").count(), 1, "{four}");
    let before = four.find("r2 = c1;").unwrap();
    let after = four.find("oC0 = r2 * c2;").unwrap();
    let looped = four.find("[loop]").unwrap();
    assert!(before < looped && looped < after, "{four}");
    let three = shader(3);
    assert!(!three.contains("for"), "{three}");
    assert_eq!(three.matches("tex2D").count(), 3, "{three}");
}
