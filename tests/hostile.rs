//! Hostile inputs through the real binary, each run as a child process
//! under hard limits: 1 GiB of address space and 20 s of CPU time
//! (`setrlimit`), and a wall-clock deadline after which it is killed. A
//! regression that hangs, recurses without bound or allocates gigabytes
//! fails here by hitting a limit, not by a timed assertion on a fast path.
//! Large inputs are generated in the test.
#![cfg(unix)]

use std::fs;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common::bin;

/// What a bounded run left: exit code (None when killed by a signal or the
/// deadline), stdout, stderr.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Address space the child may map: the binary, rayon's threads and their
/// malloc arenas take about 200 MB of it before any work.
const MEMORY: u64 = 1 << 30;
/// CPU seconds the child may use.
const CPU_SECONDS: u64 = 20;
/// Wall-clock deadline (the machine may be shared).
const DEADLINE: Duration = Duration::from_secs(90);

fn run_in(dir: &Path, args: &[&str]) -> Run {
    let out = dir.join(".stdout");
    let err = dir.join(".stderr");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_ps30"));
    cmd.args(args)
        .current_dir(dir)
        .env_remove("NO_COLOR")
        .stdin(Stdio::null())
        .stdout(fs::File::create(&out).unwrap())
        .stderr(fs::File::create(&err).unwrap());
    // SAFETY: only async-signal-safe calls (setrlimit) between fork and exec.
    unsafe {
        cmd.pre_exec(|| {
            let limit = |resource, value: u64| {
                let l = libc::rlimit {
                    rlim_cur: value as libc::rlim_t,
                    rlim_max: value as libc::rlim_t,
                };
                if libc::setrlimit(resource, &l) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            };
            limit(libc::RLIMIT_AS, MEMORY)?;
            limit(libc::RLIMIT_CPU, CPU_SECONDS)
        });
    }
    let mut child = cmd.spawn().expect("start ps30");
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break Some(s);
        }
        if start.elapsed() > DEADLINE {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let read = |p: &Path| String::from_utf8_lossy(&fs::read(p).unwrap()).into_owned();
    let run = Run {
        code: status.and_then(|s| s.code()),
        stdout: read(&out),
        stderr: read(&err),
    };
    let _ = fs::remove_file(out);
    let _ = fs::remove_file(err);
    run
}

/// Runs `args` in `dir` and checks the exit code and that stderr (or
/// stdout) says `says`.
#[track_caller]
fn expect(dir: &Path, args: &[&str], code: i32, says: &str) -> Run {
    let r = run_in(dir, args);
    assert_eq!(
        r.code,
        Some(code),
        "ps30 {args:?}: exit {:?} (None: killed by a limit)\nstderr: {}",
        r.code,
        &r.stderr[..r.stderr.len().min(3000)]
    );
    assert!(
        r.stderr.contains(says) || r.stdout.contains(says),
        "ps30 {args:?} does not say {says:?}:\nstderr: {}\nstdout: {}",
        &r.stderr[..r.stderr.len().min(3000)],
        &r.stdout[..r.stdout.len().min(3000)]
    );
    r
}

fn write(dir: &Path, name: &str, text: &str) {
    fs::write(dir.join(name), text).unwrap();
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with(".std"))
        .collect();
    v.sort();
    v
}

#[test]
fn repeat_blocks_that_produce_nothing_cost_nothing() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write(
        d,
        "empty.psh",
        "ps_3_0\nBEGIN_REPEAT_BLOCK(4294967295)\nEND_REPEAT_BLOCK\nmov oC0, c0\n",
    );
    expect(d, &["check", "empty.psh"], 0, "within limits");
    write(
        d,
        "nested.psh",
        "ps_3_0\nBEGIN_REPEAT_BLOCK(4294967295)\nBEGIN_REPEAT_BLOCK(4294967295)\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nmov oC0, c0\n",
    );
    expect(d, &["check", "nested.psh"], 0, "within limits");
}

#[test]
fn deep_repeat_nesting_is_refused_where_it_starts() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let deep = |n: usize, body: &str| {
        format!(
            "ps_3_0\n{}{body}{}mov oC0, c0\n",
            "BEGIN_REPEAT_BLOCK(1)\n".repeat(n),
            "END_REPEAT_BLOCK\n".repeat(n)
        )
    };
    // 70,000 levels once overflowed the stack (exit 134).
    write(d, "deep.psh", &deep(70_000, "mov r0, c0\n"));
    expect(
        d,
        &["check", "deep.psh", "--max-input-bytes", "4000000"],
        2,
        "deep.psh:66:1",
    );
    // 50,000 statements 2,000 deep once took 4.6 GB.
    write(d, "wide.psh", &deep(2_000, &"mov r0, c0\n".repeat(50_000)));
    expect(d, &["check", "wide.psh"], 2, "nested more than 64 deep");
    // At the depth limit the expansion is one chain per repetition: 50,000
    // statements 64 deep are measured (over 512 slots: exit 1).
    write(d, "ok.psh", &deep(64, &"mov r0, c0\n".repeat(50_000)));
    expect(d, &["check", "ok.psh"], 1, "EXCEEDS");
    // Repetitions are bounded as well as statements: 99,990 repetitions of
    // a chain of 63 blocks around one statement.
    let src = format!(
        "ps_3_0\nBEGIN_REPEAT_BLOCK(99990)\n{}nop\n{}END_REPEAT_BLOCK\nmov oC0, c0\n",
        "BEGIN_REPEAT_BLOCK(1)\n".repeat(63),
        "END_REPEAT_BLOCK\n".repeat(63)
    );
    write(d, "reps.psh", &src);
    expect(
        d,
        &["check", "reps.psh"],
        2,
        "repetitions, over the cap of 100000",
    );
}

#[test]
fn many_diagnostics_are_reported_in_linear_time_and_capped() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // 99,990 different errors: the first 50 are shown.
    let distinct: String = (0..99_990).map(|i| format!("foo{i} r0, r1\n")).collect();
    write(d, "errors.psh", &format!("ps_3_0\n{distinct}"));
    let r = expect(
        d,
        &["check", "errors.psh", "--max-input-bytes", "2000000"],
        2,
        "99,940 more errors not shown",
    );
    assert_eq!(r.stderr.matches("unknown instruction").count(), 50);
    // 99,990 times the same error: one report with its count and lines.
    write(
        d,
        "same.psh",
        &format!("ps_3_0\n{}", "foo r0, r1\n".repeat(99_990)),
    );
    let r = expect(
        d,
        &["check", "same.psh", "--max-input-bytes", "2000000"],
        2,
        "the same error at 99989 more places (lines 2–99991 in all)",
    );
    assert_eq!(r.stderr.matches("unknown instruction").count(), 1);
    // 20,000 warnings on a shader that validates.
    let body = "if_gt v0.x, c0.x\ntexld r0, r1, s0\nendif\n".repeat(20_000);
    write(
        d,
        "warnings.psh",
        &format!("ps_3_0\ndcl_2d s0\ndcl_texcoord0 v0.xy\nmov r1, c0\n{body}mov oC0, r0\n"),
    );
    expect(
        d,
        &["check", "warnings.psh", "--max-input-bytes", "2000000"],
        1,
        "the same warning at 19999 more places",
    );
    // A 10 MB line with one error: not echoed, the token cut short.
    write(
        d,
        "long.psh",
        &format!("ps_3_0\n{}\n", "a".repeat(10_000_000)),
    );
    let r = expect(
        d,
        &["check", "long.psh", "--max-input-bytes", "20000000"],
        2,
        "(10000000 characters)",
    );
    assert!(r.stderr.len() < 2_000, "{} bytes of stderr", r.stderr.len());
}

#[test]
fn input_size_is_capped() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    expect(d, &["check", "/dev/zero"], 2, "--max-input-bytes");
    write(
        d,
        "lines.psh",
        &format!("ps_3_0\n{}", "nop\n".repeat(1_000_000)),
    );
    expect(
        d,
        &["check", "lines.psh"],
        2,
        "larger than the cap of 1,048,576 bytes",
    );
    // Within the byte cap, a file without macros past the statement cap
    // says so in its own words.
    write(
        d,
        "plain.psh",
        &format!("ps_3_0\n{}mov oC0, c0\n", "nop\n".repeat(100_000)),
    );
    expect(
        d,
        &["check", "plain.psh"],
        2,
        "the file has 100002 statements",
    );
}

#[test]
fn default_bounds_stop_huge_draws() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let img = bin::repo().join("assets/hdr/forest.hdr");
    let img = img.to_str().unwrap();
    // 585,000 slots per pixel over 4 Mpixel: hours of work without a bound.
    expect(
        d,
        &[
            &[
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2048x2048",
                "--int",
                "i1=255",
                "--int",
                "i2=255",
            ][..],
            &bin::LOOP_FLOATS,
        ]
        .concat(),
        2,
        "--max-executed-total",
    );
    // A 64 GiB target asked for by raising the bound fails, not aborts.
    expect(
        d,
        &[
            &[
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "65536x65536",
                "--max-target-pixels",
                "99999999999",
                "--int",
                "i1=1",
                "--int",
                "i2=1",
            ][..],
            &bin::LOOP_FLOATS,
        ]
        .concat(),
        2,
        "more than this machine can give",
    );
    // profile has the same bound flags, and checks its G-buffer against them.
    expect(
        d,
        &["profile", "lights:select", "--gbuffer", "65536x65536"],
        2,
        "--max-target-pixels",
    );
    expect(d, &["profile", "--help"], 0, "--max-executed-total");
}

#[test]
fn saturated_counts_say_more_than() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let sub = |n: usize, next: &str| {
        format!("label l{n}\nrep i0\nrep i0\nrep i0\nrep i0\n{next}\nendrep\nendrep\nendrep\nendrep\nret\n")
    };
    let src = format!(
        "ps_3_0\ndefi i0, 255, 0, 1, 0\ndef c0, 1, 1, 1, 1\ncall l0\nmov oC0, c0\nret\n{}{}{}{}",
        sub(0, "call l1"),
        sub(1, "call l2"),
        sub(2, "call l3"),
        sub(3, "nop")
    );
    write(d, "sat.psh", &src);
    // Counts past u64 need loops nested deeper than Microsoft's validator
    // allows once the loops around each call are counted (X5827, "Depth of
    // loop nesting exceeds limit of 4"): refused, so no shader reaches them.
    expect(d, &["check", "sat.psh"], 2, "error[X5827]");
    // The deepest nesting allowed: four loops of 255 around a chain of
    // calls, a count past u32 that is still exact.
    let src = "ps_3_0\ndefi i0, 255, 0, 1, 0\ndef c0, 1, 1, 1, 1\nrep i0\nrep i0\nrep i0\nrep i0\ncall l0\nendrep\nendrep\nendrep\nendrep\nmov oC0, c0\nret\nlabel l0\ncall l1\nret\nlabel l1\nnop\nret\n";
    write(d, "deep.psh", src);
    let r = expect(d, &["check", "deep.psh"], 1, "executed");
    assert!(!r.stdout.contains("more than"), "{}", r.stdout);
}

#[test]
fn outputs_never_replace_links_devices_fifos_or_inputs() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let src = bin::repo().join("asm/article/lum_pass2.psh");
    fs::copy(&src, d.join("src.psh")).unwrap();
    let expand = |out: &str| {
        run_in(
            d,
            &[
                "expand", "src.psh", "-D", "xsize=2", "-D", "ysize=2", "-o", out,
            ],
        )
    };
    // A link is followed: the file it points to is written, the link stays.
    write(d, "target.psh", "old");
    std::os::unix::fs::symlink("target.psh", d.join("link.psh")).unwrap();
    assert_eq!(expand("link.psh").code, Some(0));
    assert!(fs::symlink_metadata(d.join("link.psh"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(fs::read_to_string(d.join("target.psh"))
        .unwrap()
        .contains("ps_3_0"));
    // A FIFO is refused (writing to it would block, replacing it destroys it).
    let fifo = std::ffi::CString::new(d.join("fifo.psh").to_str().unwrap()).unwrap();
    assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o644) }, 0);
    let r = expand("fifo.psh");
    assert_eq!(r.code, Some(2));
    assert!(r.stderr.contains("is a FIFO"), "{}", r.stderr);
    // A device, a dangling link, a directory, the input itself.
    for (out, says) in [
        ("/dev/null", "is a character device"),
        (".", "names a directory"),
        ("/", "names a directory"),
        ("src.psh", "is also the input"),
    ] {
        let r = expand(out);
        assert_eq!(r.code, Some(2), "{out}: {}", r.stderr);
        assert!(r.stderr.contains(says), "{out}: {}", r.stderr);
    }
    std::os::unix::fs::symlink("nowhere", d.join("dangling.psh")).unwrap();
    assert!(expand("dangling.psh").stderr.contains("does not exist"));
    // Images: the input as the output, directly or through a link.
    fs::copy(bin::repo().join("assets/hdr/sunset.pfm"), d.join("img.pfm")).unwrap();
    std::os::unix::fs::symlink("img.pfm", d.join("alias.pfm")).unwrap();
    let before = fs::read(d.join("img.pfm")).unwrap();
    expect(
        d,
        &["tonemap", "img.pfm", "-o", "img.pfm"],
        2,
        "is also the input img.pfm",
    );
    expect(
        d,
        &[
            "run",
            "corrected:loop",
            "--image",
            "img.pfm",
            "--target",
            "2x2",
            "--int",
            "i1=1",
            "--int",
            "i2=1",
            "-o",
            "alias.pfm",
        ],
        2,
        "is also the input img.pfm",
    );
    assert_eq!(fs::read(d.join("img.pfm")).unwrap(), before);
    assert!(
        !names(d).iter().any(|n| n.ends_with(".tmp")),
        "{:?}",
        names(d)
    );
}

#[test]
fn a_multi_file_output_that_fails_writes_nothing() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // The last file of `unroll --fit` cannot be written (a directory is in
    // its way): the run fails and leaves neither the other files nor the
    // directory it created nor a temporary file.
    let out = d.join("out");
    let r = run_in(d, &["unroll", "--fit", "-o", "out/none"]);
    assert_eq!(r.code, Some(2), "{}", r.stderr);
    fs::create_dir(&out).unwrap();
    fs::create_dir(out.join("pass2_11x8.psh")).unwrap();
    let r = run_in(d, &["unroll", "--fit", "-o", "out"]);
    assert_eq!(r.code, Some(2), "{}", r.stderr);
    assert!(r.stderr.contains("pass2_11x8.psh"), "{}", r.stderr);
    assert_eq!(names(&out), vec!["pass2_11x8.psh".to_string()]);
    // A new directory is created, and removed again on failure.
    let r = run_in(d, &["unroll", "--fit", "-o", "fresh"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert_eq!(names(&d.join("fresh")).len(), 6);
}

#[test]
fn regeneration_removes_only_what_the_generator_wrote() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let gen = d.join("gen");
    let elsewhere = d.join("elsewhere");
    fs::create_dir_all(gen.join("640x480")).unwrap();
    fs::create_dir_all(&elsewhere).unwrap();
    // Foreign files next to the generated ones, a subfolder the generator
    // does not write, and a link into another directory.
    write(&gen, "640x480/mine.psh", "ps_3_0\n// my own shader\n");
    fs::create_dir(gen.join("mine")).unwrap();
    write(&gen, "mine/other.psh", "// ps30 unroll: looks generated\n");
    write(&elsewhere, "keep.psh", "// ps30 unroll: looks generated\n");
    std::os::unix::fs::symlink(&elsewhere, gen.join("linked")).unwrap();
    write(
        &gen,
        "640x480/old.psh",
        "// ps30 unroll: an older shader\nps_3_0\n",
    );
    let reports = d.join("reports");
    let r = run_in(
        d,
        &[
            "verify",
            "--regenerate",
            "--generated",
            "gen",
            "--reports",
            "reports",
            "-q",
        ],
    );
    // Exit 1: the foreign file is still there, and named.
    assert_eq!(r.code, Some(1), "{}{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("mine.psh"), "{}", r.stdout);
    assert!(gen.join("640x480/mine.psh").exists());
    assert!(gen.join("mine/other.psh").exists());
    assert!(elsewhere.join("keep.psh").exists());
    assert!(!gen.join("640x480/old.psh").exists());
    assert!(reports.join("README.md").exists());
}

/// A small OpenEXR file (ZIP, 16 lines per chunk: 3 chunks for 40 lines)
/// and where its chunk offset table starts.
fn small_exr(path: &Path) -> (Vec<u8>, usize) {
    use ps30::core::image::{write_exr, RenderTarget, TargetFormat};
    let target = RenderTarget::new(4, 40, TargetFormat::R32F);
    write_exr(path, &target).unwrap();
    let b = fs::read(path).unwrap();
    // Header: magic and version, then name\0 type\0 size value… until \0.
    let mut pos = 8;
    while b[pos] != 0 {
        for _ in 0..2 {
            pos += b[pos..].iter().position(|&c| c == 0).unwrap() + 1;
        }
        let size = i32::from_le_bytes(b[pos..pos + 4].try_into().unwrap()) as usize;
        pos += 4 + size;
    }
    (b, pos + 1)
}

#[test]
fn corrupt_exr_chunk_tables_are_refused() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let (b, table) = small_exr(&d.join("ok.exr"));
    let offset = |b: &[u8], i: usize| {
        u64::from_le_bytes(b[table + 8 * i..table + 8 * i + 8].try_into().unwrap()) as usize
    };
    // Two table entries pointing at the first chunk.
    let mut dup = b.clone();
    let first = offset(&b, 0) as u64;
    dup[table + 8..table + 16].copy_from_slice(&first.to_le_bytes());
    fs::write(d.join("dup.exr"), dup).unwrap();
    // Every chunk claiming y = 0.
    let mut y0 = b.clone();
    for i in 0..3 {
        let at = offset(&b, i);
        y0[at..at + 4].copy_from_slice(&0i32.to_le_bytes());
    }
    fs::write(d.join("y0.exr"), y0).unwrap();
    for f in ["dup.exr", "y0.exr"] {
        expect(
            d,
            &[
                "luminance",
                f,
                "--block",
                "2x8",
                "--pass1",
                "corrected:loop",
            ],
            2,
            "chunk table",
        );
    }
    expect(
        d,
        &[
            "luminance",
            "ok.exr",
            "--block",
            "2x8",
            "--pass1",
            "corrected:loop",
        ],
        0,
        "agree",
    );
}

#[test]
fn odd_characters_are_named_where_they_stand() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    for (bytes, says) in [
        // A byte-order mark at the start is refused as Microsoft's
        // assembler refuses it; anywhere else it is an invisible character.
        (
            &b"\xef\xbb\xbfps_3_0\nmov oC0, c0\n"[..],
            "U+FEFF: a UTF-8 byte-order mark starts the file",
        ),
        (
            &b"ps_3_0\nmov \xef\xbb\xbfoC0, c0\n"[..],
            "U+FEFF: an invisible zero-width character",
        ),
        (b"ps_3_0\nmov \x01oC0, c0\n", "U+0001: a control character"),
        (b"ps_3_0\nmov\xc2\xa0oC0, c0\n", "U+00A0: a no-break space"),
        (b"ps_3_0\nmov\xe2\x80\x8b oC0, c0\n", "U+200B"),
        (
            b"ps_3_0\nm\xd0\xbev oC0, c0\n",
            "U+043E: the Cyrillic letter",
        ),
    ] {
        fs::write(d.join("odd.psh"), bytes).unwrap();
        expect(d, &["check", "odd.psh"], 2, says);
    }
    // What Microsoft's assembler reads as text, ps30 reads too: the text
    // ends at the first NUL (dumping tools end files with one, and what
    // follows is ignored), lone CRs end lines, a vertical tab is a space.
    for bytes in [
        &b"ps_3_0\nmov oC0, c0\n\x00\xff\xfe anything\n"[..],
        b"ps_3_0\rmov oC0, c0\r",
        b"ps_3_0\nmov\x0boC0, c0\n",
    ] {
        fs::write(d.join("odd.psh"), bytes).unwrap();
        expect(d, &["check", "odd.psh"], 0, "within limits");
    }
}

#[test]
fn a_subroutine_must_end_with_ret() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write(
        d,
        "noret.psh",
        "ps_3_0\ncall l0\nmov oC0, c0\nret\nlabel l0\nnop\n",
    );
    expect(
        d,
        &["check", "noret.psh"],
        2,
        "subroutine l0 does not end with ret",
    );
}

/// Subroutines are analysed once each, not once per call path: the
/// call-depth check on a graph with exponentially many paths, the cost
/// model on one whose call sites multiply, and the longest chain the
/// labels allow (l0…l2047).
#[test]
fn call_graphs_are_analysed_once_per_subroutine() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // 45 subroutines, each calling the next two: about 1.8e9 call paths
    // from main to the last one.
    let mut fib = String::from("ps_3_0\ndef c0, 1, 1, 1, 1\ncall l0\nmov oC0, c0\nret\n");
    for k in 0..45 {
        fib.push_str(&format!("label l{k}\n"));
        for next in [k + 1, k + 2].into_iter().filter(|&n| n < 45) {
            fib.push_str(&format!("call l{next}\n"));
        }
        fib.push_str("ret\n");
    }
    write(d, "fib.psh", &fib);
    expect(d, &["check", "fib.psh"], 2, "calls nest 45 deep");

    // 2,048 subroutines in one chain: main's call and 2,047 more.
    let mut chain = String::from("ps_3_0\ndef c0, 1, 1, 1, 1\ncall l0\nmov oC0, c0\nret\n");
    for k in 0..2047 {
        chain.push_str(&format!("label l{k}\ncall l{}\nret\n", k + 1));
    }
    chain.push_str("label l2047\nret\n");
    write(d, "chain.psh", &chain);
    expect(d, &["check", "chain.psh"], 2, "calls nest 2048 deep");

    // Four levels (the ps_3_0 limit) of 1,000 calls each: 10^12 entries of
    // the innermost subroutine. Executed count, from the inside out, with
    // Microsoft's slot counts call = 2, ret = mov = 1, nop = 0: l3 runs
    // nop + ret = 1; each level above runs 1,000 × (2 + the level below) +
    // its ret; main the same plus mov, without a label's ret counted twice.
    let mut wide = String::from("ps_3_0\ndef c0, 1, 1, 1, 1\n");
    wide.push_str(&"call l0\n".repeat(1000));
    wide.push_str("mov oC0, c0\nret\n");
    for k in 0..3 {
        wide.push_str(&format!("label l{k}\n"));
        wide.push_str(&format!("call l{}\n", k + 1).repeat(1000));
        wide.push_str("ret\n");
    }
    wide.push_str("label l3\nnop\nret\n");
    let mut executed: u64 = 1;
    for _ in 0..3 {
        executed = 1000 * (2 + executed) + 1;
    }
    executed = 1000 * (2 + executed) + 2;
    assert_eq!(executed, 3_003_003_003_002);
    write(d, "wide.psh", &wide);
    let r = expect(d, &["check", "wide.psh", "--json"], 1, "\"executed\"");
    let json: serde_json::Value = serde_json::from_str(&r.stdout).unwrap();
    assert_eq!(
        json["executed"],
        serde_json::json!({"min": executed, "max": executed}),
        "{}",
        r.stdout
    );
}

/// Compiled shaders at the bounds: a megabyte of one-token instructions
/// stops at the statement cap (raised, it loads and is merely over the slot
/// limit of the documented table — Microsoft's tools count `nop` 0), and
/// comment blocks at their largest (32,767 tokens each, almost a
/// megabyte) are listed, loaded and written back within the limits.
#[test]
fn compiled_shaders_at_the_bounds() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let bytes =
        |tokens: &[u32]| -> Vec<u8> { tokens.iter().flat_map(|t| t.to_le_bytes()).collect() };
    let mut nops = vec![0xffff_0300u32];
    nops.extend(std::iter::repeat_n(0, 262_000));
    nops.push(0xffff);
    fs::write(d.join("nops.fxo"), bytes(&nops)).unwrap();
    expect(
        d,
        &["check", "nops.fxo"],
        2,
        "more than 100000 instructions and comments",
    );
    expect(
        d,
        &[
            "check",
            "nops.fxo",
            "--max-expanded",
            "300000",
            "--slots",
            "documented",
        ],
        1,
        "262,000 / 512",
    );
    let mut comments = vec![0xffff_0300u32];
    for _ in 0..7 {
        comments.push(0x7fff_fffe);
        comments.extend(std::iter::repeat_n(0xabab_abab, 0x7fff));
    }
    comments.extend([0x0200_0001, 0x800f_0800, 0xa0e4_0000, 0xffff]);
    fs::write(d.join("comments.fxo"), bytes(&comments)).unwrap();
    expect(d, &["check", "comments.fxo"], 0, "verdict: within limits");
    // version 1 + 7 × (comment token 1 + 32,767) + mov 3 + end 1 = 229,381
    expect(
        d,
        &["asm", "comments.fxo", "-o", "again.fxo"],
        0,
        "229,381 tokens",
    );
    assert_eq!(fs::read(d.join("again.fxo")).unwrap(), bytes(&comments));
}

/// A small valid draw list with one target named `name` and one step.
fn draw_list(name: &str, step: &str) -> String {
    let name = serde_json::to_string(name).unwrap();
    format!(
        r#"{{"targets": [{{"name": {name}, "size": "8x8", "format": "R32F"}}], "steps": [{step}]}}"#
    )
}

#[test]
fn draw_list_names_never_become_paths_outside_the_output_folder() {
    let d = tempfile::tempdir().unwrap();
    let work = d.path().join("work");
    fs::create_dir(&work).unwrap();
    let abs = d.path().join("abs").display().to_string();
    for name in [
        "../escape",
        abs.as_str(),
        "a/b",
        "..",
        ".",
        "",
        "bad\u{1b}]0;title\u{7}",
    ] {
        let list = draw_list(
            name,
            &format!(r#"{{"clear": {}}}"#, serde_json::to_string(name).unwrap()),
        );
        write(&work, "list.json", &list);
        let r = expect(
            &work,
            &["render", "list.json", "-o", "out"],
            2,
            "targets[0].name",
        );
        assert!(
            r.stderr.contains("cannot be a file name"),
            "{name:?}: {}",
            r.stderr
        );
        assert!(
            !r.stderr.contains('\u{1b}') && !r.stderr.contains('\u{7}'),
            "{:?}",
            r.stderr
        );
        assert_eq!(names(&work), ["list.json"], "{name:?} wrote something");
        assert_eq!(
            names(d.path()),
            ["work"],
            "{name:?} wrote outside the folder"
        );
    }
}

#[test]
fn files_a_draw_list_names_are_read_under_the_input_cap() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write(
        d,
        "list.json",
        &draw_list("t", r#"{"draw": "t", "shader": "/dev/zero"}"#),
    );
    expect(d, &["render", "list.json"], 2, "--max-input-bytes");
    write(d, "big.psh", &format!("ps_3_0\n{}", "nop\n".repeat(300)));
    write(
        d,
        "list.json",
        &draw_list("t", r#"{"draw": "t", "shader": "big.psh"}"#),
    );
    expect(
        d,
        &["render", "list.json", "--max-input-bytes", "1000"],
        2,
        "larger than the cap of 1,000 bytes",
    );
    // The list itself, too.
    expect(d, &["render", "/dev/zero"], 2, "--max-input-bytes");
}

#[test]
fn a_draw_list_may_start_with_a_byte_order_mark() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let list = format!(
        "\u{feff}{}",
        draw_list("t", r#"{"clear": "t", "color": [1, 0, 0, 0]}"#)
    );
    write(d, "list.json", &list);
    expect(d, &["render", "list.json"], 0, "1 target,");
}

#[test]
fn a_closed_pipe_keeps_the_verdict() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // 600 adds: over the 512-slot budget under either slot table.
    write(
        d,
        "over.psh",
        &format!(
            "ps_3_0\nmov r0, c0\n{}mov oC0, r0\n",
            "add r0, r0, c0\n".repeat(600)
        ),
    );
    for args in [&["check", "over.psh"][..], &["check", "over.psh", "--json"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_ps30"))
            .args(args)
            .current_dir(d)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        // The reader goes away before anything is written (`| head -0`).
        drop(child.stdout.take());
        let status = child.wait().unwrap();
        assert_eq!(
            status.code(),
            Some(1),
            "{args:?}: the over-budget verdict was lost"
        );
    }
}

#[test]
fn an_interrupted_render_removes_the_folder_it_created() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // Hundreds of mip reductions of a large target: seconds of work.
    let steps = vec![r#"{"mips": "t"}"#; 400].join(", ");
    let list = format!(
        r#"{{"targets": [{{"name": "t", "size": "2048x2048", "format": "A32B32G32R32F"}}], "steps": [{steps}]}}"#
    );
    write(d, "list.json", &list);
    let mut child = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args([
            "render",
            "list.json",
            "-o",
            "new",
            "--max-steps",
            "1000",
            "--max-list-pixels",
            "10000000000",
        ])
        .current_dir(d)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Wait until the run has made its output folder, then interrupt it.
    let start = Instant::now();
    while !d.join("new").exists() && start.elapsed() < DEADLINE {
        std::thread::sleep(Duration::from_millis(5));
    }
    assert!(
        d.join("new").exists(),
        "render never created its output folder"
    );
    // SAFETY: sending a signal to our own child.
    unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) };
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
    assert_eq!(
        names(d),
        ["list.json"],
        "the interrupted run left its folder"
    );
}

#[test]
fn a_repeated_comment_block_is_bounded_by_its_tokens() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // One kept comment block of 32,767 tokens (a token a word, 8 hex digits),
    // repeated 10,000 times: 1.3 GB of bytecode if it were expanded.
    let words: Vec<String> = (0..32_767u32)
        .map(|i| format!("{:08x}", 0x4000_0000 + i))
        .collect();
    let lines: Vec<String> = words.chunks(16).map(|c| c.join(" ")).collect();
    let text = format!(
        "ps_3_0\nBEGIN_REPEAT_BLOCK(10000)\n//#comment {}\n//#+ {}\nEND_REPEAT_BLOCK\nmov oC0, c0\n",
        lines[0],
        lines[1..].join("\n//#+ ")
    );
    write(d, "bomb.psh", &text);
    for cmd in ["asm", "check", "expand"] {
        let mut args = vec![cmd, "bomb.psh", "--max-input-bytes", "1000000"];
        if cmd == "asm" {
            args.extend(["-o", "bomb.fxo"]);
        }
        expand_refused(d, &args);
    }
    assert!(!d.join("bomb.fxo").exists());
}

#[track_caller]
fn expand_refused(d: &Path, args: &[&str]) {
    expect(d, args, 2, "counts one per 6 tokens");
}

/// A constant table with one float4 constant `name` at c`index`, `count`
/// registers, as `//#comment` lines.
fn table_lines(name: &'static str, index: u16, count: u16) -> String {
    use crate::common::ctab::{comment_lines, table, Const, Ty};
    let body = table(
        "t",
        "ps_3_0",
        0xffff_0300,
        &[Const {
            name,
            set: 2,
            index,
            count,
            ty: Ty::numeric(1, 3, 1, 4, count),
            default: None,
        }],
    );
    comment_lines(&body)
}

#[test]
fn constant_tables_are_checked_against_the_register_files() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // c220 … c227: four registers that do not exist.
    write(
        d,
        "past.psh",
        &format!("ps_3_0\n{}mov oC0, c0\n", table_lines("k", 220, 8)),
    );
    for cmd in ["check", "asm"] {
        let mut args = vec![cmd, "past.psh"];
        if cmd == "asm" {
            args.extend(["-o", "past.fxo"]);
        }
        expect(d, &args, 2, "past the last float4 register, c223");
    }
    // A second table that does not decode is refused as the bytecode reader
    // would refuse what asm wrote; a table in a block repeated zero times is
    // not written, so not listed either.
    let broken = table_lines("k", 0, 1).replacen(" 0000001c", " 0000ffff", 1);
    write(
        d,
        "two.psh",
        &format!("ps_3_0\n{}{broken}mov oC0, c0\n", table_lines("k", 0, 1)),
    );
    expect(
        d,
        &["asm", "two.psh", "-o", "two.fxo"],
        2,
        "the constant table does not decode",
    );
    assert!(!d.join("two.fxo").exists());
    write(
        d,
        "zero.psh",
        &format!(
            "ps_3_0\nBEGIN_REPEAT_BLOCK(0)\n{}END_REPEAT_BLOCK\nmov oC0, c0\n",
            table_lines("g_hidden", 0, 1)
        ),
    );
    let r = expect(d, &["check", "zero.psh"], 0, "");
    assert!(!r.stdout.contains("g_hidden"), "{}", r.stdout);
}

#[test]
fn names_from_a_file_are_escaped_in_messages() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write(
        d,
        "named.psh",
        &format!(
            "ps_3_0\n{}mov oC0, c0\n",
            table_lines("k\u{1b}]0;owned\u{7}\nfake: line", 0, 1)
        ),
    );
    let r = expect(
        d,
        &["check", "named.psh", "--const", "nosuch=1"],
        2,
        "has no `nosuch`",
    );
    assert!(
        !r.stderr.contains('\u{1b}')
            && !r.stderr.contains('\u{7}')
            && !r.stderr.contains("\nfake: line"),
        "{:?}",
        r.stderr
    );
}

#[test]
fn translating_a_long_shader_takes_time_linear_in_its_length() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // 40,000 instructions in one straight run (600 KB): naga's MSL writer
    // removed each block's value names one by one from an ordered map,
    // quadratic in a block's length (18 s in a release build); the
    // translation now cuts long runs into nested blocks. Under the child's
    // 20 s CPU limit the quadratic version does not finish.
    write(
        d,
        "long.psh",
        &format!(
            "ps_3_0\ndef c0, 1, 2, 3, 4\nmov r0, c0\n{}mov oC0, r0\n",
            "add r0, r0, c0\n".repeat(40_000)
        ),
    );
    for to in ["msl", "wgsl"] {
        let out = format!("long.{to}");
        expect(
            d,
            &[
                "translate",
                "long.psh",
                "--to",
                to,
                "--max-expanded",
                "100000",
                "-o",
                &out,
            ],
            0,
            "wrote",
        );
    }
}

#[test]
fn a_whole_draw_list_is_held_to_a_budget() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // 300 reductions of a 2048 × 2048 target: refused before any step runs.
    let mips = vec![r#"{"mips": "t"}"#; 300].join(", ");
    write(
        d,
        "mips.json",
        &format!(
            r#"{{"targets": [{{"name": "t", "size": "2048x2048", "format": "A32B32G32R32F"}}], "steps": [{mips}]}}"#
        ),
    );
    expect(d, &["render", "mips.json"], 2, "--max-list-pixels");
    // Every step written after it: an upper bound on the staged bytes, checked
    // before any step runs, and nothing left behind.
    let clears = vec![r#"{"clear": "t", "color": [1, 1, 1, 1]}"#; 100].join(", ");
    write(
        d,
        "clears.json",
        &format!(
            r#"{{"targets": [{{"name": "t", "size": "2048x2048", "format": "A32B32G32R32F"}}], "steps": [{clears}]}}"#
        ),
    );
    expect(
        d,
        &[
            "render",
            "clears.json",
            "-o",
            "out",
            "--every-step",
            "--max-list-pixels",
            "1000000000",
        ],
        2,
        "--max-staged-bytes",
    );
    assert!(!d.join("out").exists());
    // The instruction slots of all draws together: stopped at the draw that
    // passes the budget (each draw here executes 3 slots in each of 64 pixels).
    let draw = r#"{"draw": "t", "shader": "s.psh"}"#;
    write(
        d,
        "s.psh",
        "ps_3_0\ndef c0, 1, 2, 3, 4\nmov r0, c0\nadd r0, r0, c0\nmov oC0, r0\n",
    );
    write(
        d,
        "draws.json",
        &draw_list("t", &vec![draw; 20].join(", ")).replace("R32F", "A32B32G32R32F"),
    );
    expect(d, &["render", "draws.json"], 0, "20 steps");
    let r = expect(
        d,
        &["render", "draws.json", "--max-list-executed", "1000"],
        2,
        "--max-list-executed",
    );
    // 1,000 slots allow five draws of 192; the sixth passes the budget.
    assert!(r.stderr.contains("steps[5]"), "{}", r.stderr);
}

#[test]
fn vertex_buffers_are_checked_before_anything_is_allocated_from_them() {
    // A vertex list of raw buffers (docs/vertex-shaders.md): a stream file
    // missing, too short, a count far past it, stride 0, an offset past
    // any file, and /dev/zero (read up to the 64 MiB cap, then refused for
    // holding more vertices than a list may) — each refused naming its
    // field, with exit 2, inside the memory and CPU limits above.
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write(d, "vs.vsh", "vs_2_0\ndcl_position v0\nmov oPos, v0\n");
    fs::write(d.join("short.vb"), [0u8; 40]).unwrap();
    let list = |stream: &str, count: &str| {
        format!(
            r#"{{"declaration": [{{"offset": 0, "type": "FLOAT4", "usage": "position"}}],
               "streams": [{stream}]{count}}}"#
        )
    };
    let cases = [
        (
            list(r#"{"file": "missing.vb", "stride": 16}"#, ""),
            "streams[0].file: ",
        ),
        (
            list(r#"{"file": "short.vb", "stride": 16}"#, r#", "count": 3"#),
            "streams[0]: 40 bytes hold 2 vertices for declaration[0] (position0); count 3 needs 48",
        ),
        (
            list(
                r#"{"file": "short.vb", "stride": 16}"#,
                r#", "count": 1048576"#,
            ),
            "count 1048576 needs 16777216",
        ),
        (
            list(
                r#"{"file": "short.vb", "stride": 16}"#,
                r#", "count": 4294967296"#,
            ),
            "count: 4294967296 is not a whole number from 0 to 1048576",
        ),
        (
            list(r#"{"file": "short.vb", "stride": 0}"#, ""),
            "streams[0].stride: 0",
        ),
        (
            list(
                r#"{"file": "short.vb", "stride": 16, "offset": 18446744073709551615}"#,
                "",
            ),
            "streams[0].offset: 18446744073709551615 is not a whole number",
        ),
        (
            list(r#"{"file": "/dev/zero", "stride": 16}"#, ""),
            "a list holds at most 1048576 (give \"count\")",
        ),
    ];
    for (text, says) in &cases {
        write(d, "list.json", text);
        let r = expect(d, &["run", "vs.vsh", "--vertices", "list.json"], 2, says);
        assert!(r.stderr.contains("list.json"), "{}", r.stderr);
    }
    // The same list with a count the file holds runs.
    write(
        d,
        "list.json",
        &list(r#"{"file": "short.vb", "stride": 16}"#, ""),
    );
    expect(
        d,
        &["run", "vs.vsh", "--vertices", "list.json"],
        0,
        "2 vertices",
    );
}
