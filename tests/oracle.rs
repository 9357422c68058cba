//! ps30 against Microsoft's own compiler, without Wine: the corpus of
//! `tests/oracle/corpus/` (assembly probes and HLSL shaders written for the
//! project) and what `d3dcompiler_47.dll` answered for each file, committed in
//! `tests/oracle/fixtures/` by `tools/oracle/regen` (never by hand, never from
//! ps30's output; `.ci/run` regenerates them and fails on any difference).
//!
//! For a corpus file `corpus/SET/REL` (SET is `asm`, assembled with
//! `D3DAssemble`, or `hlsl`, compiled with `D3DCompile` for `ps_3_0`, entry
//! `main`) the fixtures are `fixtures/SET/REL.rc` (the HRESULT, eight hex
//! digits; `00000000` is accepted), `REL.err` (Microsoft's messages, when it
//! wrote any), `REL.fxo` (the bytecode, when accepted) and `REL.dis`
//! (`D3DDisassemble`'s listing of that bytecode), and for the round trip
//! `REL.dis.rc` / `REL.dis.fxo`: `D3DAssemble` of that listing. The third set,
//! `dis`, is bytecode made by hand (`tools/oracle/def_bits.py`): Microsoft
//! only lists it, so its `fxo` is the corpus file itself.
//!
//! Each aspect is a module: acceptance and error codes (`accept`), bytecode
//! and round trips (`bytes`), listing text (`listing`), slot counts (`slots`),
//! and the shader profiles besides ps_3_0 (`profiles`, `parity`; ps_1_x's
//! instruction set and listings read back: `ps1x`).

mod accept;
mod bytes;
mod listing;
mod parity;
mod profiles;
mod ps1x;
mod slots;

use std::path::{Path, PathBuf};

/// One corpus file and Microsoft's answers for it.
pub struct Fixture {
    /// `asm`, `hlsl` or `dis`.
    pub set: &'static str,
    /// The path below `corpus/SET/`, with `/` separators (`ops/add.psh`).
    pub rel: String,
    /// The corpus file's bytes.
    pub source: Vec<u8>,
    /// Microsoft's HRESULT: 0 when it accepted the file.
    pub rc: u32,
    /// Microsoft's messages (errors and warnings), if it wrote any.
    pub err: Option<String>,
    /// The bytecode Microsoft wrote, when it accepted the file.
    pub fxo: Option<Vec<u8>>,
    /// `D3DDisassemble`'s listing of `fxo`.
    pub dis: Option<String>,
    /// `D3DAssemble` of `dis`: its HRESULT and bytecode.
    pub redis: Option<(u32, Option<Vec<u8>>)>,
}

impl Fixture {
    /// Whether Microsoft accepted the file.
    pub fn accepted(&self) -> bool {
        self.rc == 0
    }

    /// `SET/REL`, for messages.
    pub fn name(&self) -> String {
        format!("{}/{}", self.set, self.rel)
    }

    /// The first `X####` code in Microsoft's messages that belongs to an
    /// error (not a warning), if any.
    pub fn error_code(&self) -> Option<String> {
        let err = self.err.as_deref()?;
        err.lines().find_map(|l| {
            let at = l.find("error X")?;
            let code: String = l[at + 6..].chars().take(5).collect();
            Some(code)
        })
    }
}

/// The corpus files on which ps30 still disagrees with Microsoft, each with
/// the reason: the tests hold everything else to Microsoft's answer, and
/// each of these to still disagreeing (a fix removes its line here).
pub const KNOWN_GAPS: &[(&str, &str)] = &[];

/// Whether `SET/REL` is one of [`KNOWN_GAPS`].
pub fn known_gap(name: &str) -> bool {
    KNOWN_GAPS.iter().any(|(n, _)| *n == name)
}

/// The oracle folder, `tests/oracle/`.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/oracle")
}

fn read_opt(path: &Path) -> Option<Vec<u8>> {
    std::fs::read(path).ok()
}

fn rc_of(path: &Path) -> Option<u32> {
    let text = std::fs::read_to_string(path).ok()?;
    Some(
        u32::from_str_radix(text.trim(), 16)
            .unwrap_or_else(|_| panic!("{}: {text:?}", path.display())),
    )
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.unwrap().path();
        if p.is_dir() {
            walk(&p, out);
        } else {
            out.push(p);
        }
    }
}

/// Every fixture of one set (`asm` or `hlsl`) that ps30 reads today, sorted by
/// path: the files of other profiles (`asm/profiles/<profile>/` and
/// `hlsl/gen_profiles/NAME__<target>.hlsl`, all but ps_3_0's) are
/// [`profile_fixtures`]'s and [`target_fixtures`]'. Panics if a corpus file
/// has no `.rc` fixture: the fixtures are out of date.
pub fn fixtures(set: &'static str) -> Vec<Fixture> {
    let mut all = every_fixture(set);
    all.retain(|f| {
        let other_asm = f.rel.starts_with("profiles/") && !f.rel.starts_with("profiles/ps_3_0/");
        let other_hlsl = f.rel.starts_with("gen_profiles/") && !f.rel.ends_with("__ps_3_0.hlsl");
        !(other_asm || other_hlsl)
    });
    all
}

/// The HLSL shaders compiled for other targets than ps_3_0
/// (`hlsl/gen_profiles/NAME__<target>.hlsl`), each with its target's name.
pub fn target_fixtures() -> Vec<(String, Fixture)> {
    every_fixture("hlsl")
        .into_iter()
        .filter_map(|f| {
            let name = f.rel.strip_prefix("gen_profiles/")?.strip_suffix(".hlsl")?;
            let target = name.rsplit_once("__")?.1.to_string();
            (target != "ps_3_0").then_some((target, f))
        })
        .collect()
}

/// The per-profile probes of one profile (`asm/profiles/<profile>/`).
pub fn profile_fixtures(profile: &str) -> Vec<Fixture> {
    let prefix = format!("profiles/{profile}/");
    let mut all = every_fixture("asm");
    all.retain(|f| f.rel.starts_with(&prefix));
    all
}

fn every_fixture(set: &'static str) -> Vec<Fixture> {
    let corpus = root().join("corpus").join(set);
    let fixtures = root().join("fixtures").join(set);
    let mut files = Vec::new();
    walk(&corpus, &mut files);
    files.retain(|p| {
        p.extension()
            .is_some_and(|e| e == "psh" || e == "hlsl" || e == "fxo")
    });
    files.sort();
    files
        .into_iter()
        .map(|path| {
            let rel = path
                .strip_prefix(&corpus)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            let base = fixtures.join(&rel);
            let with = |ext: &str| PathBuf::from(format!("{}.{ext}", base.display()));
            let rc = rc_of(&with("rc"))
                .unwrap_or_else(|| panic!("{set}/{rel} has no fixture: run tools/oracle/regen"));
            let redis = rc_of(&with("dis.rc")).map(|rc| (rc, read_opt(&with("dis.fxo"))));
            let source = std::fs::read(&path).unwrap();
            // hand-made bytecode is its own `fxo`: Microsoft only lists it
            let fxo = if set == "dis" {
                Some(source.clone())
            } else {
                read_opt(&with("fxo"))
            };
            Fixture {
                set,
                source,
                rc,
                err: read_opt(&with("err")).map(|b| String::from_utf8_lossy(&b).into_owned()),
                fxo,
                dis: read_opt(&with("dis")).map(|b| String::from_utf8_lossy(&b).into_owned()),
                redis,
                rel,
            }
        })
        .collect()
}

/// Every fixture of the three sets.
pub fn all() -> Vec<Fixture> {
    let mut v = fixtures("asm");
    v.extend(fixtures("hlsl"));
    v.extend(fixtures("dis"));
    v
}
