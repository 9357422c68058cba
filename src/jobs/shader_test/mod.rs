//! `ps30 shader-test`: vkd3d's `.shader_test` files run the way vkd3d's
//! Direct3D 9 runner (`tests/shader_runner_d3d9.c`) runs them, on ps30's
//! emulator instead of a Windows device, so that the expected pixels vkd3d
//! recorded on native Direct3D 9 check ps30's whole draw.
//!
//! The Direct3D 9 runner runs a file once, at the lowest shader model its
//! `[require]` section allows within 2.0–3.0: every HLSL section is
//! compiled by Microsoft's compiler (`D3DCompile`, entry `main`, profile
//! `ps_2_0`/`vs_2_0` or `ps_3_0`/`vs_3_0`) when a draw needs it — here
//! through the oracle of `tools/oracle/`, every source of every file in one
//! run of the harness. Uniforms are raw 32-bit words set as `c#` of both
//! shaders (`SetVertexShaderConstantF` and `SetPixelShaderConstantF` from
//! register 0); `draw quad` is one triangle (−2, −2), (−2, 4), (4, −2)
//! through the file's vertex shader or `return pos;`; render targets are
//! A32B32G32R32F (640 × 480 unless the file names its own) or R32F; the
//! alpha test is always on (ALWAYS unless `alpha test` says otherwise);
//! culling is off. Native Windows ignores `todo` and `bug`, so every probe
//! must hold; `if(…)` lines for other shader models are skipped, as are
//! the test lines after a shader marked `fail` for the model.
//!
//! [`parse`] splits a file into sections and scans their lines; `runner`
//! walks the sections as vkd3d's state machine does (first to learn what to
//! compile, then to run); `draw` turns the runner's state into a draw list
//! of [`crate::jobs::render`] (geometry through the vertex shader,
//! textures, samplers, targets) and reads probes back. What the draw list
//! cannot express is reported as unsupported, by name.

mod draw;
pub mod parse;
mod probe;
mod resource;
mod runner;
mod state;

use serde::Serialize;
use std::collections::{BTreeMap, HashMap};

/// One shader to compile: its HLSL, profile and compile flags.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CompileJob {
    /// The HLSL (entry point `main`).
    pub source: String,
    /// `ps_2_0`, `vs_3_0`, …
    pub profile: String,
    /// D3DCOMPILE_* names without the prefix, from `[require] options:`.
    pub flags: Vec<&'static str>,
}

/// Compiles every job at once: the bytecode, or the compiler's refusal in
/// words. `Err`: the compiler could not run at all.
pub type CompileAll<'a> =
    &'a mut dyn FnMut(&[CompileJob]) -> Result<Vec<Result<Vec<u8>, String>>, String>;

/// What became of one probe.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "verdict", rename_all = "lowercase")]
pub enum Verdict {
    /// Every pixel of the probe matched within its tolerance.
    Pass,
    /// A pixel did not match, or the draw before it failed.
    Fail {
        /// What differed (got, expected, where), or why the draw failed.
        detail: String,
    },
    /// ps30 cannot run what the probe checks.
    Unsupported {
        /// The section or test line ps30 cannot express, by name.
        reason: String,
    },
}

/// One probe line's result.
#[derive(Clone, Debug, Serialize)]
pub struct Probe {
    /// 1-based line in the file.
    pub line: usize,
    /// The line as written (qualifiers included).
    pub text: String,
    /// What became of it.
    #[serde(flatten)]
    pub verdict: Verdict,
}

/// One file's run.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FileReport {
    /// The path as given.
    pub path: String,
    /// Whether any test line ran at shader model 2 or 3 (a file for
    /// shader model 4 and above only has none).
    pub ran: bool,
    /// The shader model the last test section ran at (`2.0`, `3.0`).
    pub model: Option<&'static str>,
    /// Every probe that ran, in order.
    pub probes: Vec<Probe>,
    /// Draws that failed, unsupported lines, and where the file stopped:
    /// `(line, what)`.
    pub notes: Vec<(usize, String)>,
    /// Why the file could not be read or stopped early (a line vkd3d's
    /// runner refuses too: its `fatal_error`).
    pub stopped: Option<String>,
    /// Whether it stopped at a malformed line (bad input) rather than at
    /// one the Direct3D 9 runner refuses.
    pub malformed: bool,
}

impl FileReport {
    /// Probes by verdict: passed, failed, unsupported.
    pub fn counts(&self) -> (usize, usize, usize) {
        let mut c = (0, 0, 0);
        for p in &self.probes {
            match p.verdict {
                Verdict::Pass => c.0 += 1,
                Verdict::Fail { .. } => c.1 += 1,
                Verdict::Unsupported { .. } => c.2 += 1,
            }
        }
        c
    }
}

/// Every file's run and the totals.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// One per file, in the order given.
    pub files: Vec<FileReport>,
    /// Files given.
    pub total_files: usize,
    /// Files with test lines that ran at shader model 2 or 3.
    pub files_run: usize,
    /// Probes that passed.
    pub passed: usize,
    /// Probes that failed.
    pub failed: usize,
    /// Probes ps30 cannot run.
    pub unsupported: usize,
    /// Unsupported probes by reason, most first.
    pub unsupported_reasons: Vec<(String, usize)>,
}

impl Report {
    /// Whether every probe that ran passed (unsupported ones aside).
    pub fn ok(&self) -> bool {
        self.failed == 0
    }
}

/// How the draws run.
#[derive(Clone, Debug, Default)]
pub struct Settings {
    /// The draw lists' settings (threads, limits, float rules).
    pub render: crate::jobs::render::Settings,
}

/// Runs every file: `(path, text)` each. All shaders of all files are
/// compiled in one call of `compile`.
pub fn run_files(
    files: &[(String, String)],
    settings: &Settings,
    compile: CompileAll<'_>,
) -> Result<Report, String> {
    let mut jobs = Vec::new();
    for (_, text) in files {
        jobs.extend(runner::plan(text));
    }
    jobs.sort_unstable();
    jobs.dedup();
    let answers = if jobs.is_empty() {
        Vec::new()
    } else {
        compile(&jobs)?
    };
    let compiled: HashMap<CompileJob, Result<Vec<u8>, String>> =
        jobs.into_iter().zip(answers).collect();
    let reports: Vec<FileReport> = files
        .iter()
        .map(|(path, text)| runner::run(path, text, &compiled, settings))
        .collect();
    Ok(summarise(reports))
}

fn summarise(files: Vec<FileReport>) -> Report {
    let mut reasons: BTreeMap<String, usize> = BTreeMap::new();
    let (mut passed, mut failed, mut unsupported) = (0, 0, 0);
    for f in &files {
        let (p, x, u) = f.counts();
        passed += p;
        failed += x;
        unsupported += u;
        for probe in &f.probes {
            if let Verdict::Unsupported { reason } = &probe.verdict {
                *reasons.entry(reason.clone()).or_default() += 1;
            }
        }
    }
    let mut unsupported_reasons: Vec<(String, usize)> = reasons.into_iter().collect();
    unsupported_reasons.sort_unstable_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    Report {
        total_files: files.len(),
        files_run: files.iter().filter(|f| f.ran).count(),
        files,
        passed,
        failed,
        unsupported,
        unsupported_reasons,
    }
}
