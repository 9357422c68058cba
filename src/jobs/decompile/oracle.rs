//! Microsoft's compiler as `ps30 decompile --verify` calls it: the harness
//! of `tools/oracle/` (`harness.exe` beside `d3dcompiler_47.dll`, under
//! Wine), in its `hlsl` mode, the same call `tools/oracle/regen` makes for
//! the HLSL corpus, with Wine's own d3dcompiler never answering in
//! Microsoft's place.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder `tools/oracle/setup.sh` set up.
#[derive(Clone, Debug)]
pub struct Oracle {
    /// The folder holding `harness.exe`, `d3dcompiler_47.dll` and `prefix/`.
    pub dir: PathBuf,
}

/// The oracle is not installed (or not where it was looked for).
#[derive(Clone, Debug)]
pub struct Missing(pub String);

impl std::fmt::Display for Missing {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// What the compiler answered for one HLSL source.
#[derive(Clone, Debug)]
pub struct Compiled {
    /// `D3DCompile`'s HRESULT (0: accepted).
    pub hresult: u32,
    /// Its messages (errors and warnings), as it wrote them.
    pub messages: String,
    /// The bytecode, when it was accepted.
    pub bytecode: Option<Vec<u8>>,
}

impl Oracle {
    /// `$PS30_ORACLE`, else `target/oracle` below the current folder, else
    /// `../oracle` beside the running executable (`target/debug/ps30`).
    pub fn find() -> Result<Oracle, Missing> {
        let mut tried = Vec::new();
        let mut candidates = Vec::new();
        if let Some(d) = std::env::var_os("PS30_ORACLE") {
            candidates.push(PathBuf::from(d));
        } else {
            candidates.push(PathBuf::from("target/oracle"));
            if let Some(exe) = std::env::current_exe()
                .ok()
                .and_then(|e| e.parent().map(Path::to_path_buf))
            {
                candidates.push(exe.join("../oracle"));
            }
        }
        for dir in candidates {
            let need = ["harness.exe", "d3dcompiler_47.dll", "prefix/system.reg"];
            if need.iter().all(|n| dir.join(n).is_file()) {
                return Ok(Oracle { dir });
            }
            tried.push(dir.display().to_string());
        }
        Err(Missing(format!(
            "Microsoft's compiler is not installed (looked for harness.exe, d3dcompiler_47.dll and a Wine prefix in {}): run tools/oracle/setup.sh, or set PS30_ORACLE to its folder",
            tried.join(", ")
        )))
    }

    /// Compiles `hlsl` for `profile` with entry point `main` in a fresh
    /// folder under the system's temporary folder (removed afterwards).
    pub fn compile(&self, hlsl: &str, profile: &str) -> Result<Compiled, String> {
        let mut all = self.compile_all(&[Job {
            hlsl,
            profile,
            flags: &[],
        }])?;
        all.pop()
            .ok_or_else(|| "the oracle's harness gave no answer".to_string())
    }

    /// Compiles every job in one run of the harness (Wine starts once), in
    /// a fresh folder under the system's temporary folder (removed
    /// afterwards); the answers in the jobs' order.
    pub fn compile_all(&self, jobs: &[Job<'_>]) -> Result<Vec<Compiled>, String> {
        let dir = scratch()?;
        let result = self.compile_in(&dir, jobs);
        let _ = std::fs::remove_dir_all(&dir);
        result
    }

    fn compile_in(&self, dir: &Path, jobs: &[Job<'_>]) -> Result<Vec<Compiled>, String> {
        let mut list = String::new();
        for (n, job) in jobs.iter().enumerate() {
            let src = dir.join(format!("{n}.hlsl"));
            let flags = if job.flags.is_empty() {
                String::new()
            } else {
                format!(" flags={}", job.flags.join("|"))
            };
            let text = format!(
                "// oracle: target={} entry=main{flags}\n{}",
                job.profile, job.hlsl
            );
            std::fs::write(&src, text).map_err(|e| format!("{}: {e}", src.display()))?;
            // Each source answers into the folder under the name the
            // compiler's messages give it.
            list.push_str(&format!(
                "{}\t{}\tdecompiled.hlsl\r\n",
                windows(&src),
                windows(dir)
            ));
        }
        let list_path = dir.join("list.txt");
        std::fs::write(&list_path, list).map_err(|e| format!("{}: {e}", list_path.display()))?;
        let dll = self
            .dir
            .canonicalize()
            .map_err(|e| format!("{}: {e}", self.dir.display()))?;
        let out = Command::new("wine")
            .arg(dll.join("harness.exe"))
            .arg("hlsl")
            .arg(windows(&list_path))
            .arg(windows(dir))
            .env("WINEPREFIX", dll.join("prefix"))
            .env("WINEDEBUG", "-all")
            .env("WINEDLLOVERRIDES", "d3dcompiler_47=n")
            .output()
            .map_err(|e| format!("cannot run wine: {e} (tools/oracle/setup.sh installs it)"))?;
        (0..jobs.len())
            .map(|n| {
                let read = |ext: &str| std::fs::read(dir.join(format!("{n}.hlsl.{ext}"))).ok();
                let rc = read("rc").ok_or_else(|| {
                    format!(
                        "the oracle's harness gave no answer (exit {}): {}",
                        out.status,
                        String::from_utf8_lossy(&out.stderr).trim()
                    )
                })?;
                let hresult = u32::from_str_radix(String::from_utf8_lossy(&rc).trim(), 16)
                    .map_err(|_| "the harness wrote an unreadable .rc".to_string())?;
                Ok(Compiled {
                    hresult,
                    messages: read("err")
                        .map(|b| String::from_utf8_lossy(&b).into_owned())
                        .unwrap_or_default(),
                    bytecode: read("fxo"),
                })
            })
            .collect()
    }
}

/// One source for [`Oracle::compile_all`]: HLSL with entry point `main`.
#[derive(Clone, Copy, Debug)]
pub struct Job<'a> {
    /// The HLSL.
    pub hlsl: &'a str,
    /// The profile (`ps_3_0`, `vs_2_0`, …).
    pub profile: &'a str,
    /// D3DCOMPILE_* flag names without the prefix (`PACK_MATRIX_ROW_MAJOR`).
    pub flags: &'a [&'a str],
}

/// A Linux path as Wine's Z: drive names it.
fn windows(path: &Path) -> String {
    let abs = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    format!("Z:{}", abs.display().to_string().replace('/', "\\"))
}

/// A new private folder for one compilation.
fn scratch() -> Result<PathBuf, String> {
    let base = std::env::temp_dir();
    for n in 0..1000u32 {
        let dir = base.join(format!("ps30-decompile-{}-{n}", std::process::id()));
        match std::fs::create_dir(&dir) {
            Ok(()) => return Ok(dir),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(format!("{}: {e}", dir.display())),
        }
    }
    Err(format!("no free scratch folder in {}", base.display()))
}
