//! `ps30 decompile` over the project's own corpus: every shader of `asm/`,
//! every HLSL shader of `tests/oracle/corpus/hlsl/` that Microsoft's
//! compiler accepted (its bytecode fixture) and the oracle's assembly of
//! the profiles other than ps_3_0 (`tests/oracle/corpus/asm/profiles/`,
//! `conformance_ps2x/`) is decompiled, ps_1_x too (as the program ps30
//! runs for it, `core/decompile/ps1.rs`; with `tests/ps1_run/`); the
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

use ps30::core::decompile::{decompile, DecompileError, Decompiled, Halves, HALVES};
use ps30::core::ir::Shader;
use ps30::core::load;
use ps30::jobs::decompile::{equivalence_of_bytes, Kind};
use std::path::{Path, PathBuf};

/// Shaders the decompiler refuses today: a name, or `*` and the end of
/// names (the same probe in each vertex profile's folder), with what the
/// refusal must name.
const REFUSED: &[(&str, &str)] = &[
    // `def c3000` (and a read of it): the emulator's 256 vertex constants
    // drop the def and read (0, 0, 0, 0); HLSL would write the literal
    ("*/const-3000.psh", "def c3000 is read"),
    // m4x4's rows reach c8193: the compiler binds c0–c8191 only (X4507)
    ("*/rel-c-m4x4-8190.psh", "past c8191"),
    // an output register chosen at run time: X3500 / X3531 in HLSL
    ("*/rel-o-aL.psh", "X3500"),
    ("*/rel-o-aL-2049.psh", "X3500"),
    ("*/rel-o-aL-mask.psh", "X3500"),
];

/// Whether `name` is one of `list`'s (exactly, or by a `*` entry's end).
fn listed(list: &[(&str, &str)], name: &str) -> bool {
    list.iter().any(|(n, _)| matches(n, name))
}

fn matches(entry: &str, name: &str) -> bool {
    match entry.strip_prefix('*') {
        Some(end) => name.ends_with(end),
        None => entry == name,
    }
}

/// Recompiled shaders whose values differ beyond the rounding bound
/// derived from both shaders' arithmetic (`jobs/decompile/bound.rs`), with
/// the reason: failures the decompiler still has. A shader whose values
/// differ within the bound passes (the compiler regrouped a sum, split a
/// `mad`); one beyond it that is not listed here fails the test, and so
/// does a listed one that passes.
///
/// None today. The pixel side's last two, `lighting/oren_nayar` (4 ulp
/// where `tan` as `sin·rcp(cos)` is near `cos = 0`, whose bound is
/// unbounded) and `surface/water_gerstner_normal` (2 ulp in a cube map's
/// coordinate), differed because the compiler regrouped the decompiled
/// products and sums around literals; declared `precise`, the HLSL keeps
/// the original's order and both run bit-identical. The vertex side's
/// five: `op-nrm` in vs_2_0, vs_2_x and vs_3_0 (1 ulp: `nrm`'s arithmetic
/// rounded otherwise) are within the bound derived for vertex shaders as
/// for pixel shaders, and `rel-v-aL`, `rel-v-aL-2048` (1 ulp: the
/// compiler had fused the unrolled loop's adds into a `mad`) run
/// bit-identical under `precise`.
const BEYOND_BOUND: &[(&str, &str)] = &[];

/// Decompiled shaders Microsoft's compiler refuses. The unrolled luminance
/// shaders, refused while their 125 copies of one block were straight code
/// (X4505: the compiler read every texture first and held the results past
/// 32 temporaries), are written as `[loop]`s (`core/decompile/repeat.rs`).
const REFUSED_BY_COMPILER: &[&str] = &[
    // ps_2_x's `rep i1` over an int uniform: the ps_2_a and ps_2_b
    // compilers write no flow control (`[branch]` is X3528, a `[loop]` of
    // literal count comes back unrolled; measured) and cannot unroll a loop
    // of unknown count (X3511, with `[loop]` too); `[unroll(n)]` makes them
    // bind `i1` to a c register (X4509), which `rep` does not read
    "oracle-asm/conformance_ps2x/static.psh",
    // c[a0.x + 8191] with a0.x = 1 from a def: the compiler knows the
    // index, c8192, past the last register it binds (X3504, "array index
    // out of bounds"); at an index known only at run time it writes the
    // read back (`c8191[a0.x]`)
    "oracle-asm/profiles/vs_2_0/rel-c-a0-8191.psh",
    "oracle-asm/profiles/vs_2_x/rel-c-a0-8191.psh",
    "oracle-asm/profiles/vs_3_0/rel-c-a0-8191.psh",
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

/// Loads one fixture's bytecode, named `name`.
fn fixture_source(name: String, fxo: &[u8]) -> Source {
    let options = load::Options::default();
    let file =
        load::source_file(&name, fxo.to_vec(), &options).expect("a fixture's bytecode reads");
    let loaded = load::load(file, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
    Source { name, loaded }
}

/// Every shader of the corpus that the decompiler reads (every profile
/// but ps_1_x): the HLSL fixtures, the oracle's assembly of the profiles
/// other than ps_3_0 (`oracle-asm/`: `tests/oracle/corpus/asm/profiles/`
/// and `conformance_ps2x/`), and `asm/`.
fn sources() -> Vec<Source> {
    let options = load::Options::default();
    let mut out = Vec::new();
    let hlsl = crate::oracle::fixtures("hlsl")
        .into_iter()
        .chain(crate::oracle::target_fixtures().into_iter().map(|(_, f)| f));
    for f in hlsl {
        if f.rel.starts_with("decompiled/") || !f.accepted() {
            continue;
        }
        let Some(fxo) = &f.fxo else { continue };
        out.push(fixture_source(format!("hlsl/{}", f.rel), fxo));
    }
    let probes = [
        "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4", "ps_2_0", "ps_2_x", "vs_2_0", "vs_2_x", "vs_3_0",
    ]
    .into_iter()
    .flat_map(crate::oracle::profile_fixtures)
    .chain(
        crate::oracle::fixtures("asm")
            .into_iter()
            .filter(|f| f.rel.starts_with("conformance_ps2x/")),
    );
    for f in probes {
        if !f.accepted() {
            continue;
        }
        let Some(fxo) = &f.fxo else { continue };
        out.push(fixture_source(format!("oracle-asm/{}", f.rel), fxo));
    }
    let mut asm = Vec::new();
    walk(&root().join("asm"), "psh", &mut asm);
    walk(&root().join("asm"), "vsh", &mut asm);
    asm.sort();
    // the ps_1_x shaders the emulator's tests run
    let mut ps1_run = Vec::new();
    walk(&root().join("tests/ps1_run"), "psh", &mut ps1_run);
    ps1_run.sort();
    for p in asm.into_iter().chain(ps1_run) {
        let rel = match p.strip_prefix(root().join("asm")) {
            Ok(r) => format!("asm/{}", r.to_string_lossy()),
            Err(_) => p
                .strip_prefix(root())
                .unwrap()
                .to_string_lossy()
                .into_owned(),
        }
        .replace('\\', "/");
        let file = load::source_file(&rel, std::fs::read(&p).unwrap(), &options).unwrap();
        match load::load(file, &options) {
            Ok(loaded) => out.push(Source { name: rel, loaded }),
            // shaders that need `-D` counts (REPEAT_BLOCK sizes) are not one shader
            Err(e) if e.to_string().contains("is not defined") => {}
            Err(e) => panic!("{rel} does not load: {e}"),
        }
    }
    out
}

/// The profile a source's shader names (`ps_2_x`, `vs_3_0`).
fn profile(s: &Source) -> &'static str {
    s.loaded.shader.program().profile.name()
}

/// Counts per profile, printed as one line each.
#[derive(Default)]
struct Tally(std::collections::BTreeMap<&'static str, [usize; 6]>);

impl Tally {
    /// Column `k` of `profile` plus one.
    fn add(&mut self, profile: &'static str, k: usize) {
        self.0.entry(profile).or_default()[k] += 1;
    }

    fn print(&self, columns: &[&str]) {
        for (p, n) in &self.0 {
            let parts: Vec<String> = columns
                .iter()
                .enumerate()
                .map(|(k, c)| format!("{} {c}", n[k]))
                .collect();
            eprintln!("{p}: {}", parts.join(", "));
        }
    }
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
    let mut tally = Tally::default();
    let all = sources();
    for s in &all {
        let path = committed(&s.name);
        let result = decompiled(s);
        tally.add(profile(s), result.is_err() as usize);
        match result {
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
                let why = REFUSED.iter().find(|(n, _)| matches(n, &s.name));
                match why {
                    None => problems.push(format!("{}: refused: {e}", s.name)),
                    Some((_, w)) if !e.to_string().contains(w) => problems.push(format!(
                        "{}: refused, but not for what the list says ({w}): {e}",
                        s.name
                    )),
                    _ => {}
                }
                refused.push(s.name.clone());
            }
        }
    }
    for (n, why) in REFUSED {
        if !refused.iter().any(|r| matches(n, r)) {
            problems.push(format!("{n} is listed as refused ({why}) but decompiles"));
        }
    }
    for (n, _) in REFUSED.iter().filter(|(n, _)| n.starts_with('*')) {
        for s in all.iter().filter(|s| matches(n, &s.name)) {
            if !refused.contains(&s.name) {
                problems.push(format!(
                    "{} is listed as refused ({n}) but decompiles",
                    s.name
                ));
            }
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
    tally.print(&["decompiled", "refused"]);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_recompiled_corpus_runs_identically() {
    let fixtures = root().join("tests/oracle/fixtures/hlsl/decompiled");
    let (mut identical, mut problems, mut seen) = (0, Vec::new(), Vec::new());
    let mut within = Vec::new();
    let mut compiler_refused = 0;
    let mut tally = Tally::default();
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
            tally.add(profile(&s), 3);
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
        let listed = listed(BEYOND_BOUND, &s.name);
        let column = match v.kind {
            Kind::Identical => 0,
            Kind::WithinBound => 1,
            _ => 2,
        };
        tally.add(profile(&s), column);
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
    tally.print(&[
        "identical",
        "within the bound",
        "beyond it",
        "refused by the compiler",
    ]);
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

/// A relative read based at a `def` reads the literal where the index
/// names the def and the uniform elsewhere, through a function of the
/// array: a `[branch] if` where the profile branches, a sum of products by
/// 0 and 1 in vs_2_0, which does not. In a loop over an `int` uniform the
/// HLSL's counter counts from 0 while `aL` counts from `i#.y`, so there
/// the read is refused, naming why.
#[test]
fn a_relative_read_based_at_a_def_chooses_the_literal_by_the_index() {
    let body = "def c0, 1, 0.5, -0.25, 0\ndcl_position v0\nmov r0, v0\n\
                loop aL, i0\nadd r0, r0, c[aL]\nendloop\nmov oPos, r0\n";
    let hlsl = |profile: &str, defi: &str| {
        let text = format!("{profile}\n{defi}{body}");
        decompile(&assembled(&text), None)
    };
    let branch = hlsl("vs_2_x", "defi i0, 3, 0, 1, 0\n").unwrap().hlsl;
    assert!(branch.contains("r0 = r0 + c_at(i);"), "{branch}");
    assert!(
        branch.contains("    [branch] if (i == 0)\n        return float4(1.0, 0.5, -0.25, 0.0);\n    return c[i];"),
        "{branch}"
    );
    let products = hlsl("vs_2_0", "defi i0, 3, 0, 1, 0\n").unwrap().hlsl;
    assert!(
        products.contains("    float s0 = i == 0 ? 1 : 0;\n    v = v * (1 - s0) + float4(1.0, 0.5, -0.25, 0.0) * s0;"),
        "{products}"
    );
    assert!(!products.contains("[branch]"), "{products}");
    let refused = hlsl("vs_2_x", "").unwrap_err().to_string();
    assert!(refused.contains("counts from i#.y"), "{refused}");
}

fn assembled(text: &str) -> Shader {
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
    regrouped_sum_and_changed_term(head, "oC0");
}

/// The same for vertex shaders, whose bound shaders run in the vertex
/// stage (`jobs/decompile/vertex.rs`): the vertices' attributes take the
/// interpolants' place.
#[test]
fn a_vertex_shaders_regrouped_sum_is_within_the_derived_bound() {
    let head = "vs_2_0\ndcl_position v0\ndcl_texcoord v1\ndcl_texcoord1 v2\n";
    regrouped_sum_and_changed_term(head, "oPos");
}

/// `(v0 + v1) + v2` against `(v1 + v2) + v0` (within the bound) and
/// against `v0·(1 + 2⁻¹⁰) + (v1 + v2)` (beyond it), written to `out`.
fn regrouped_sum_and_changed_term(head: &str, out: &str) {
    let original = assembled(&format!(
        "{head}mov r1, v1\nadd r0, v0, r1\nadd {out}, r0, v2\n"
    ));
    let regrouped = assembled(&format!(
        "{head}mov r1, v2\nadd r0, v1, r1\nadd {out}, r0, v0\n"
    ));
    let scaled = assembled(&format!(
        "{head}def c0, 1.0009765625, 0, 0, 0\nmov r1, v2\nadd r0, v1, r1\nmad {out}, v0, c0.x, r0\n"
    ));
    within_and_beyond(&original, &regrouped, &scaled);
}

/// `regrouped` differs from `original` in some values, each within the
/// derived bound, and `wrong` differs beyond a bound that was derived (not
/// a value without one), so the rule in use can fail.
fn within_and_beyond(original: &Shader, regrouped: &Shader, wrong: &Shader) {
    let v = ps30::jobs::decompile::equivalence(original, regrouped, 32).unwrap();
    assert_eq!(v.kind, Kind::WithinBound, "{v:?}");
    assert!(
        v.equivalent && v.differing > 0 && v.unexplained == 0,
        "{v:?}"
    );
    let v = ps30::jobs::decompile::equivalence(original, wrong, 32).unwrap();
    assert_eq!(v.kind, Kind::Different, "{v:?}");
    let first = v.first_unexplained.expect("a value beyond the bound");
    assert!(
        first
            .bound
            .is_some_and(|e| (first.original - first.recompiled).abs() > e),
        "{first:?}"
    );
}

/// The vertex instructions with rules of their own (`jobs/decompile/
/// bound.rs`): each reads a sum `(v0 + v1) + v2`; against the same
/// instruction (or the compiler's expansion: `dp4`s for `m4x4`, `exp`/`log`
/// for `expp`/`logp`) of the regrouped sum `(v1 + v2) + v0` every
/// differing value is within its bound, and against a wrong expansion (one
/// result component scaled by 1 + 2⁻¹⁰, a relative change 2¹⁴ times the
/// unit roundoff) some value is beyond a bound that was derived; the same
/// for `m4x4` at a run-time index.
#[test]
fn lit_dst_expp_logp_and_m4x4_have_bounds_that_can_fail() {
    let head = "vs_2_0\ndef c8, 1.0009765625, 0, 0, 0\ndef c9, 1, 0.015625, 1, 0.0625\n\
                dcl_position v0\n\
                dcl_texcoord v1\ndcl_texcoord1 v2\n";
    let sum = "mov r2, v1\nadd r0, v0, r2\nadd r0, r0, v2\n";
    let regrouped_sum = "mov r2, v2\nadd r0, v1, r2\nadd r0, r0, v0\n";
    let rows = "dp4 r1.x, r0, c0\ndp4 r1.y, r0, c1\ndp4 r1.z, r0, c2\ndp4 r1.w, r0, c3\n";
    // lit's operand scaled (y by 2⁻⁶, w by 2⁻⁴) so that y^w stays far below
    // 2¹⁰⁰, where a bound would read as none
    let lit = "mul r0, r0, c9\nlit r1, r0\n";
    // expp's by 2⁻⁴, so that 2^x stays above 2⁻¹⁰⁰: the bound shader flushes
    // values below 2⁻¹²⁶, where a bound of a few ulp would read as 0
    let expp = "mul r0.x, r0.x, c9.w\nexpp r1, r0.x\n";
    // (the instruction into r1, its expansion into r1, the lane scaled)
    let cases = [
        ("m4x4 r1, r0, c0\n", rows, "y"),
        (
            "m3x3 r1.xyz, r0, c0\nmov r1.w, v0.w\n",
            "dp3 r1.x, r0, c0\ndp3 r1.y, r0, c1\ndp3 r1.z, r0, c2\nmov r1.w, v0.w\n",
            "z",
        ),
        ("dst r1, r0, v2\n", "dst r1, r0, v2\n", "y"),
        (lit, lit, "z"),
        (lit, lit, "y"),
        (expp, "mul r0.x, r0.x, c9.w\nexp r1, r0.x\n", "x"),
        ("logp r1, r0.x\n", "log r1, r0.x\n", "x"),
    ];
    for (op, expansion, lane) in cases {
        let shader = |body: &str| assembled(&format!("{head}{body}mov oPos, r1\n"));
        let original = shader(&format!("{sum}{op}"));
        let regrouped = shader(&format!("{regrouped_sum}{expansion}"));
        let wrong = shader(&format!("{sum}{expansion}mul r1.{lane}, r1.{lane}, c8.x\n"));
        within_and_beyond(&original, &regrouped, &wrong);
    }
    // rows read at a run-time index (`c[a0.x + k]`, `blendindices` 0–3):
    // the draws hold the bound shaders' literals where the index may land
    let shader = |body: &str| {
        assembled(&format!(
            "{head}dcl_blendindices v3\nmova a0.x, v3.x\n{body}mov oPos, r1\n"
        ))
    };
    let rows = rows.replace(", c", ", c[a0.x + ").replace('\n', "]\n");
    let rows = rows.replace("c[a0.x + 0]", "c[a0.x]");
    let original = shader(&format!("{sum}m4x4 r1, r0, c[a0.x]\n"));
    let regrouped = shader(&format!("{regrouped_sum}{rows}"));
    let wrong = shader(&format!("{sum}{rows}mul r1.w, r1.w, c8.x\n"));
    within_and_beyond(&original, &regrouped, &wrong);
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

/// `texbem` reads stage 1's bump-environment matrix from c13 in the
/// lowering (`core::ps1::run`: stage n's in c(12 + n)); the HLSL declares
/// that register and its header says which draw state feeds it.
#[test]
fn a_bump_shader_names_the_state_behind_its_constants() {
    let options = load::Options::default();
    let path = root().join("asm/ps1x/bump.psh");
    let file = load::source_file("bump.psh", std::fs::read(path).unwrap(), &options).unwrap();
    let loaded = load::load(file, &options).unwrap();
    let hlsl = decompile(&loaded.shader, None).unwrap().hlsl;
    assert!(hlsl.contains("float4 c13 : register(c13);"), "{hlsl}");
    assert!(
        hlsl.contains("// c12 + n: stage n's bump-environment matrix"),
        "{hlsl}"
    );
    // no texbeml here: the luminance constants are not named
    assert!(!hlsl.contains("// c18 + n"), "{hlsl}");
}

/// `mova` rounds to nearest; the HLSL writes the rounding itself
/// (`mova_round`) and indexes the constant array by `a0`, which the
/// compiler floors exactly.
#[test]
fn mova_is_written_as_its_rounding_and_a0_indexes_an_array() {
    let text = "vs_2_0\ndcl_position v0\ndcl_blendindices v1\nmova a0.x, v1.x\n\
                add r0, v0, c[a0.x + 3]\nmov oPos, r0\nmov oT0, c2\n";
    let options = load::Options::default();
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options).unwrap();
    let loaded = load::load(file, &options).unwrap();
    let hlsl = decompile(&loaded.shader, None).unwrap().hlsl;
    assert!(hlsl.starts_with("// oracle: target=vs_2_0\n"), "{hlsl}");
    assert!(
        hlsl.contains("a0.x = mova_round(blendindices0.x);"),
        "{hlsl}"
    );
    assert!(hlsl.contains("float mova_round(float x)\n"), "{hlsl}");
    // the array starts at the relative read's base and reaches to c224;
    // c2, below it, is a register of its own
    assert!(hlsl.contains("float4 cr[221] : register(c3);"), "{hlsl}");
    assert!(hlsl.contains("(position0 + cr[a0.x])"), "{hlsl}");
    assert!(hlsl.contains("float4 c2 : register(c2);"), "{hlsl}");
    assert!(hlsl.contains("float4 position0 : POSITION0;"), "{hlsl}");
    assert!(hlsl.contains("float4 texcoord0 : TEXCOORD0;"), "{hlsl}");
}

/// `mova_round` as the decompiled HLSL spells it (`core/decompile/vertex.rs`),
/// step by step in f32: `a = |x|`, `f = frac(a)` (`a − floor(a)`, the
/// emulator's `frc`), `r = a − f`, `r + 1` where `f > ½` or `f = ½` and the
/// tie goes up, with the sign of `x`.
fn mova_round(x: f32, halves: Halves) -> f32 {
    let frac = |v: f32| v - v.floor();
    let a = x.abs();
    let f = frac(a);
    let r = a - f;
    let up = match halves {
        Halves::AwayFromZero => f >= 0.5,
        Halves::ToEven => f > 0.5 || f == 0.5 && frac(r * 0.5) != 0.0,
    };
    let sign = if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    };
    sign * (r + if up { 1.0 } else { 0.0 })
}

/// The HLSL's rounding agrees with the emulator's `mova` at exact halves
/// (and at the float below ½, where `floor(x + ½)` does not): the emulator
/// runs `mova a0.x, c0.x` and reads `c[a0.x + 8]`, whose register holds
/// its own number; the HLSL's function, under the rule it spells
/// ([`HALVES`]), must give the same index. Both rules are spelled right
/// at the halves (0.5, 1.5, −0.5, 2.5), which the compiler folds the same
/// way (`asm/vs/mova_halves.vsh`, recompiled and verified in the corpus).
#[test]
fn mova_rounds_as_the_emulator_at_halves() {
    use ps30::core::emu::vertex::{run, VertexDraw, Vertices};
    use ps30::core::emu::Constants;
    let text = "vs_2_0\ndcl_position v0\nmova a0.x, c0.x\nmov oPos, c[a0.x + 8]\n";
    let options = load::Options::default();
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options).unwrap();
    let shader = load::load(file, &options).unwrap().shader;
    let xs = [
        0.5f32,
        1.5,
        -0.5,
        2.5,
        -1.5,
        3.5,
        0.499_999_97,
        -0.499_999_97,
        1.25,
        -2.75,
    ];
    for x in xs {
        let mut float: Vec<[f32; 4]> = (0..32).map(|k| [k as f32; 4]).collect();
        float[0] = [x; 4];
        let draw = VertexDraw {
            constants: Constants {
                float,
                ..Constants::default()
            },
            ..VertexDraw::default()
        };
        let vertices = Vertices {
            count: 1,
            attributes: vec![(
                ps30::core::emu::vertex::Attribute {
                    usage: "position".into(),
                    index: 0,
                },
                vec![[0.0; 4]],
            )],
        };
        let out = run(&shader, &draw, &vertices).unwrap();
        let emulator = out.values[0][0][0] - 8.0;
        assert_eq!(mova_round(x, HALVES), emulator, "mova of {x}");
    }
    let away = [1.0, 2.0, -1.0, 3.0];
    let even = [0.0, 2.0, 0.0, 2.0];
    for (k, x) in [0.5f32, 1.5, -0.5, 2.5].into_iter().enumerate() {
        assert_eq!(mova_round(x, Halves::AwayFromZero), away[k], "{x}");
        assert_eq!(mova_round(x, Halves::ToEven), even[k], "{x}");
    }
    // the old spelling, floor(|x| + 0.5) with the sign, reads 1 at the float below ½
    let x = 0.499_999_97f32;
    assert_eq!(x.signum() * (x.abs() + 0.5).floor(), 1.0);
    assert_eq!(mova_round(x, HALVES), 0.0);
}

fn loaded(text: &str) -> load::Loaded {
    let options = load::Options::default();
    let file = load::source_file("t.psh", text.as_bytes().to_vec(), &options).unwrap();
    load::load(file, &options).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// The ps_1_x proof can fail: a ps_2_0 or ps_3_0 shader that leaves out a
/// ps_1_x rule the decompiled HLSL writes is found different, and one that
/// keeps it identical. `mul r0, c0, c1` clamps both constants to [−1, 1]
/// first (the verifier's constants reach ±100); `sub r0, v0, c0` reads
/// `v0` in [0, 1], which a ps_3_0 shader receives unclamped (interpolants
/// in [−2, 2)). Every other step is exact, so "identical" is bit for bit.
#[test]
fn verify_finds_a_ps_1_x_clamp_left_out() {
    let kind = |ps1: &str, other: &str| {
        let (a, b) = (loaded(ps1), loaded(other));
        ps30::jobs::decompile::equivalence(&a.shader, &b.shader, 16)
            .unwrap()
            .kind
    };
    // one `c` register per instruction (X5213): the bounds go through r3
    let clamp_c = "def c8, -1, 1, 0, 0\nmov r3, c8\nmax r0, c0, r3.x\nmin r0, r0, r3.y\n\
                   max r1, c1, r3.x\nmin r1, r1, r3.y\n";
    let mul = "ps_1_1\nmul r0, c0, c1\n";
    let kept = format!("ps_2_0\n{clamp_c}mul_sat r0, r0, r1\nmov oC0, r0\n");
    assert_eq!(kind(mul, &kept), Kind::Identical);
    assert_eq!(
        kind(mul, "ps_2_0\nmov r0, c0\nmul_sat r0, r0, c1\nmov oC0, r0\n"),
        Kind::Different
    );
    let sub = "ps_1_1\nsub r0, v0, c0\n";
    let head = format!("ps_3_0\ndcl_color v0\n{clamp_c}");
    let kept = format!("{head}mov_sat r2, v0\nadd_sat oC0, r2, -r0\n");
    assert_eq!(kind(sub, &kept), Kind::Identical);
    let left_out = format!("{head}add_sat oC0, v0, -r0\n");
    assert_eq!(kind(sub, &left_out), Kind::Different);
}
