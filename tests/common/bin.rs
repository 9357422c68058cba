//! Running the real `ps30` binary from integration tests: one way, so every
//! test sees the same environment (no NO_COLOR, stdout and stderr captured).

use std::path::Path;
use std::process::{Command, Output};

/// Runs `ps30 ARGS` in `dir`.
pub fn ps30(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(args)
        .current_dir(dir)
        .env_remove("NO_COLOR")
        .output()
        .expect("run ps30")
}

/// The repository root (where `asm/` and `assets/` are).
pub fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `ps30 ARGS` in the repository root.
pub fn in_repo(args: &[&str]) -> Output {
    ps30(args, repo())
}

/// A run's standard output, as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A run's standard error, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Runs `ps30 ARGS` in `dir` with `input` on standard input.
pub fn ps30_with_stdin(args: &[&str], dir: &Path, input: &[u8]) -> Output {
    use std::io::Write;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(args)
        .current_dir(dir)
        .env_remove("NO_COLOR")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run ps30");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(input)
        .expect("write stdin");
    child.wait_with_output().expect("wait for ps30")
}

/// The loop counts `corrected:loop` reads, as the README's `run` example
/// sets them for forest.hdr: 128 × 52 texels of a 1024 × 512 image.
pub const LOOP_INTS: [&str; 4] = ["--int", "i1=128", "--int", "i2=52"];

/// The float constants `corrected:loop` reads (c0.z = 0 clears the
/// accumulator; c1 is one texel of a 1024 × 512 image; c3 the luminance
/// weights and δ).
pub const LOOP_FLOATS: [&str; 6] = [
    "--const",
    "c0=0,0,0,0",
    "--const",
    "c1=0.0009765625,0.001953125,0,1",
    "--const",
    "c3=0.27,0.67,0.06,0.01",
];

/// The README's `run` example on `image`: `corrected:loop` into an 8 × 10
/// target with [`LOOP_INTS`] and [`LOOP_FLOATS`], then `extra`.
pub fn loop_args<'a>(image: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "run",
        "corrected:loop",
        "--image",
        image,
        "--target",
        "8x10",
    ];
    args.extend(LOOP_INTS);
    args.extend(LOOP_FLOATS);
    args.extend(extra);
    args
}

/// Runs the README's `run` example over forest.hdr ([`loop_args`]) with
/// `extra` flags, in the repository root.
pub fn run_loop_example(extra: &[&str]) -> Output {
    ps30(&loop_args("assets/hdr/forest.hdr", extra), repo())
}
