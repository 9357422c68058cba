//! Links the release binary with its relative relocations packed (`-z
//! pack-relative-relocs`, the ELF `DT_RELR` table): ps30 is a position-
//! independent executable whose vtables and tables of string slices need
//! 12,500 pointers fixed up at load, which a plain `.rela.dyn` spends 24
//! bytes each on (300 KB of the binary) and `DT_RELR` a bitmap on. The
//! binary's size goal (docs/speed.md) counts them.
//!
//! Only release builds on Linux with the GNU C library ask for it, and only
//! when a probe shows that the linker takes the option without a warning and
//! that a program linked with it runs here (the C library reads `DT_RELR`
//! from 2.36 on); anywhere else the binary links as before.

use std::env;
use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let var = |k: &str| env::var(k).unwrap_or_default();
    let native = var("HOST") == var("TARGET");
    let linux_gnu = var("CARGO_CFG_TARGET_OS") == "linux" && var("CARGO_CFG_TARGET_ENV") == "gnu";
    if var("PROFILE") == "release" && native && linux_gnu && relr_links_and_runs() {
        println!("cargo:rustc-link-arg-bins=-Wl,-z,pack-relative-relocs");
    }
}

/// Links an empty C program with the option (warnings fatal, so a linker
/// that ignores it says no) and runs it.
fn relr_links_and_runs() -> bool {
    let Some(out) = env::var_os("OUT_DIR").map(PathBuf::from) else {
        return false;
    };
    let probe = out.join("relr-probe");
    let linker = env::var("RUSTC_LINKER").unwrap_or_else(|_| "cc".into());
    let child = Command::new(linker)
        .args(["-x", "c", "-", "-o"])
        .arg(&probe)
        .args(["-Wl,-z,pack-relative-relocs", "-Wl,--fatal-warnings"])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn();
    let Ok(mut child) = child else {
        return false;
    };
    let wrote = child
        .stdin
        .take()
        .is_some_and(|mut s| s.write_all(b"int main(void) { return 0; }\n").is_ok());
    let linked = child.wait().is_ok_and(|s| s.success());
    wrote && linked && Command::new(&probe).status().is_ok_and(|s| s.success())
}
