//! The malformed-input corpus, through the real binary: assembly, images and
//! command-line arguments. Every case must end with the documented exit code
//! (2 for bad input or usage, 1 where the input is well-formed but the check
//! finds a problem), print an error that names the place (file:line:col for
//! assembly, the file for images, the flag for arguments), never panic, and
//! finish within a second — a hang guard with a wide margin: each case takes
//! milliseconds.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::common::bin;
use crate::common::malformed_asm;

struct Outcome {
    code: Option<i32>,
    stderr: String,
    stdout: String,
    elapsed: Duration,
}

fn ps30(args: &[&str], dir: &Path) -> Outcome {
    let start = Instant::now();
    let o = bin::ps30(args, dir);
    Outcome {
        code: o.status.code(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        elapsed: start.elapsed(),
    }
}

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The checks every case shares.
fn expect(case: &str, o: &Outcome, code: i32, needle: &str) {
    assert!(
        !o.stderr.contains("panicked"),
        "{case}: panicked\n{}",
        o.stderr
    );
    assert_eq!(
        o.code,
        Some(code),
        "{case}: exit code\n{}{}",
        o.stdout,
        o.stderr
    );
    assert!(
        o.stderr.contains(needle) || o.stdout.contains(needle),
        "{case}: output lacks `{needle}`\n{}{}",
        o.stdout,
        o.stderr
    );
    assert!(
        o.elapsed < Duration::from_secs(1),
        "{case}: took {:?}",
        o.elapsed
    );
}

#[test]
fn every_malformed_shader_exits_2_at_its_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("case.psh");
    for (i, &(src, message, line, col)) in malformed_asm::CASES.iter().enumerate() {
        std::fs::write(&path, src).unwrap();
        let o = ps30(&["check", "case.psh", "-D", "n=3"], dir.path());
        let case = format!("asm case {i}: {src:?}");
        expect(&case, &o, 2, &format!("case.psh:{line}:{col}"));
        assert!(
            o.stderr.contains(message),
            "{case}: lacks `{message}`\n{}",
            o.stderr
        );
    }
}

/// Writes `bytes` to a file named `name` in `dir`.
fn file(dir: &Path, name: &str, bytes: &[u8]) {
    std::fs::write(dir.join(name), bytes).unwrap();
}

fn pfm(width: &str, height: &str, scale: &str, data: &[f32]) -> Vec<u8> {
    let mut v = format!("PF\n{width} {height}\n{scale}\n").into_bytes();
    for x in data {
        v.extend_from_slice(&x.to_le_bytes());
    }
    v
}

#[test]
fn every_broken_image_exits_2_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let exr_magic = [0x76u8, 0x2f, 0x31, 0x01];
    let real = std::fs::read(repo().join("assets/hdr/sunset.exr")).unwrap();
    let real_hdr = std::fs::read(repo().join("assets/hdr/forest.hdr")).unwrap();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("empty.exr", vec![], "empty.exr"),
        ("one_byte.pfm", vec![b'P'], "one_byte.pfm"),
        ("text.hdr", b"hello, world".to_vec(), "text.hdr"),
        ("zeros.exr", vec![0; 64], "zeros.exr"),
        (
            "exr_magic_only.exr",
            exr_magic.to_vec(),
            "exr_magic_only.exr",
        ),
        (
            "exr_magic_garbage.exr",
            [&exr_magic[..], &[0xff; 200][..]].concat(),
            "exr_magic_garbage.exr",
        ),
        (
            "exr_header_cut.exr",
            real[..300].to_vec(),
            "exr_header_cut.exr",
        ),
        (
            "exr_half.exr",
            real[..real.len() / 2].to_vec(),
            "exr_half.exr",
        ),
        (
            "exr_flipped.exr",
            {
                let mut v = real.clone();
                for b in v.iter_mut().skip(400).step_by(97) {
                    *b ^= 0x5a;
                }
                v
            },
            "exr_flipped.exr",
        ),
        (
            "hdr_header_only.hdr",
            b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n".to_vec(),
            "hdr_header_only.hdr",
        ),
        (
            "hdr_bad_res.hdr",
            b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y two +X 2\n".to_vec(),
            "hdr_bad_res.hdr",
        ),
        (
            "hdr_huge.hdr",
            b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n".to_vec(),
            "hdr_huge.hdr",
        ),
        (
            "hdr_cut.hdr",
            real_hdr[..real_hdr.len() / 3].to_vec(),
            "hdr_cut.hdr",
        ),
        (
            "pfm_bad_magic.pfm",
            b"PX\n2 2\n-1\n".to_vec(),
            "pfm_bad_magic.pfm",
        ),
        ("pfm_no_dims.pfm", b"PF\n\n".to_vec(), "pfm_no_dims.pfm"),
        (
            "pfm_neg_width.pfm",
            pfm("-2", "2", "-1.0", &[0.0; 12]),
            "pfm_neg_width.pfm",
        ),
        ("pfm_zero.pfm", pfm("0", "0", "-1.0", &[]), "pfm_zero.pfm"),
        (
            "pfm_huge.pfm",
            pfm("100000", "100000", "-1.0", &[1.0; 3]),
            "pfm_huge.pfm",
        ),
        (
            "pfm_text_dims.pfm",
            pfm("two", "2", "-1.0", &[0.0; 12]),
            "pfm_text_dims.pfm",
        ),
        (
            "pfm_bad_scale.pfm",
            pfm("2", "2", "abc", &[0.0; 12]),
            "pfm_bad_scale.pfm",
        ),
        (
            "pfm_zero_scale.pfm",
            pfm("2", "2", "0", &[0.0; 12]),
            "pfm_zero_scale.pfm",
        ),
        (
            "pfm_short.pfm",
            pfm("2", "2", "-1.0", &[0.0; 11]),
            "pfm_short.pfm",
        ),
        (
            "pfm_long.pfm",
            pfm("2", "2", "-1.0", &[0.0; 13]),
            "pfm_long.pfm",
        ),
        (
            "pfm_overflow_dims.pfm",
            pfm("99999999999", "2", "-1.0", &[0.0; 12]),
            "pfm_overflow_dims.pfm",
        ),
    ];
    for (name, bytes, needle) in &cases {
        file(d, name, bytes);
        let o = ps30(&["luminance", name], d);
        expect(&format!("image {name}"), &o, 2, needle);
    }
    // A directory, a missing file.
    std::fs::create_dir(d.join("folder.exr")).unwrap();
    expect(
        "a directory",
        &ps30(&["luminance", "folder.exr"], d),
        2,
        "folder.exr",
    );
    expect(
        "a missing file",
        &ps30(&["luminance", "gone.pfm"], d),
        2,
        "gone.pfm",
    );
}

#[test]
fn nan_inf_and_negative_pixels_are_reported_not_fatal() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // 8×8 grey with one NaN, one +inf and one negative pixel.
    let mut data = vec![0.5f32; 8 * 8 * 3];
    data[(3 * 8 + 3) * 3..(3 * 8 + 3) * 3 + 3].fill(f32::NAN);
    data[(4 * 8 + 4) * 3..(4 * 8 + 4) * 3 + 3].fill(f32::INFINITY);
    file(d, "special.pfm", &pfm("8", "8", "-1.0", &data));
    let o = ps30(
        &[
            "luminance",
            "special.pfm",
            "--pass1",
            "corrected:loop",
            "--block",
            "4x4",
        ],
        d,
    );
    // Well-formed input whose L̄w is not finite: the check's problem, exit 1.
    expect("NaN and inf pixels", &o, 1, "2 pixels are NaN or infinite");
    // Negative pixels alone are fine: log takes |δ + L|.
    let mut data = vec![0.5f32; 8 * 8 * 3];
    data[..3].fill(-2.0);
    file(d, "negative.pfm", &pfm("8", "8", "-1.0", &data));
    let o = ps30(
        &[
            "luminance",
            "negative.pfm",
            "--pass1",
            "corrected:loop",
            "--block",
            "4x4",
        ],
        d,
    );
    expect("a negative pixel", &o, 0, "agree");
}

#[test]
fn every_bad_argument_exits_2_naming_the_flag() {
    let r = repo();
    let img = "assets/hdr/sunset.exr";
    let shader = "asm/article/lum_pass1_loop.psh";
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec![], "Usage"),
        (vec!["frobnicate"], "frobnicate"),
        (vec!["check"], "SHADER"),
        (vec!["check", shader, "--bogus"], "--bogus"),
        (vec!["check", shader, "-D", "=3"], "-D"),
        (vec!["check", shader, "-D", "1a=3"], "-D"),
        (vec!["check", shader, "-D", "a=-1"], "-D"),
        (vec!["check", shader, "-D", "a=x"], "-D"),
        (vec!["check", shader, "-D", "a"], "-D"),
        (vec!["check", shader, "--int", "i16=1"], "--int"),
        (vec!["check", shader, "--int", "x=1"], "--int"),
        (vec!["check", shader, "--int", "i1=1,2,3,4,5"], "--int"),
        (vec!["check", shader, "--int", "i1=abc"], "--int"),
        (vec!["check", shader, "--int", "i1=99999999999"], "--int"),
        (vec!["check", shader, "--bool", "b0=maybe"], "--bool"),
        (vec!["check", shader, "--bool", "b16=true"], "--bool"),
        (vec!["check", shader, "--max-slots", "0"], "--max-slots"),
        (vec!["check", shader, "--max-slots", "-3"], "-3"),
        (
            vec!["check", shader, "--max-executed", "lots"],
            "--max-executed",
        ),
        (
            vec!["check", shader, "--max-expanded", "abc"],
            "--max-expanded",
        ),
        (
            vec!["check", shader, "--int", "i1=300", "--int", "i2=1"],
            "0..=255",
        ),
        (
            vec!["check", shader, "--int", "i1=-1", "--int", "i2=1"],
            "0..=255",
        ),
        (vec!["expand"], "SHADER"),
        (vec!["luminance"], "IMAGE"),
        (vec!["luminance", img, "--block", "0x5"], "--block"),
        (vec!["luminance", img, "--block", "5x0"], "--block"),
        (vec!["luminance", img, "--block", "x"], "--block"),
        (vec!["luminance", img, "--block", "99999999x1"], "--block"),
        (vec!["luminance", img, "--block", "-1x5"], "-1"),
        (vec!["luminance", img, "--delta", "0"], "--delta"),
        (vec!["luminance", img, "--delta", "-1"], "-1"),
        (vec!["luminance", img, "--delta", "nan"], "--delta"),
        (vec!["luminance", img, "--delta", "inf"], "--delta"),
        (
            vec!["luminance", img, "--target-format", "f64"],
            "--target-format",
        ),
        (vec!["luminance", img, "--negative", "ignore"], "--negative"),
        (vec!["luminance", img, "--threads", "0"], "--threads"),
        (vec!["luminance", img, "--threads", "1000"], "--threads"),
        (
            vec!["luminance", img, "--max-pixels", "abc"],
            "--max-pixels",
        ),
        (vec!["luminance", img, "--max-pixels", "0"], "--max-pixels"),
        (
            vec!["luminance", img, "--pass1", "article:nothing"],
            "article:nothing",
        ),
        (
            vec![
                "luminance",
                img,
                "--pass1",
                "corrected:unrolled",
                "--block",
                "128x56",
            ],
            "REPEAT_BLOCK count",
        ),
        (vec!["luminance", img, "--block", "128x56"], "--pass1"),
        (
            vec!["run", "corrected:loop", "--image", img, "--target", "0x0"],
            "--target",
        ),
        (vec!["run", "corrected:loop", "--target", "2x2"], "--image"),
        (vec!["run", "corrected:loop", "--image", img], "--target"),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--const",
                "c224=1",
            ],
            "--const",
        ),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--const",
                "c0=nan",
            ],
            "--const",
        ),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--const",
                "c0=1,2,3,4,5",
            ],
            "--const",
        ),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--filter",
                "cubic",
            ],
            "--filter",
        ),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--address",
                "repeat",
            ],
            "--address",
        ),
        (
            vec![
                "run",
                "corrected:loop",
                "--image",
                img,
                "--target",
                "2x2",
                "--border",
                "1,2,x",
            ],
            "--border",
        ),
        (vec!["verify", "--reports"], "--reports"),
    ];
    for (args, needle) in &cases {
        let o = ps30(args, &r);
        expect(&format!("args {args:?}"), &o, 2, needle);
    }
}

#[test]
fn absurd_work_is_refused_quickly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Four nested rep 255 around 1,000 slots: about 4.2 × 10^12 executed,
    // 64 million times the limit. The cost model says so at once.
    let mut src =
        String::from("ps_3_0\ndefi i0, 255, 0, 0, 0\nmov r0, c0\nrep i0\nrep i0\nrep i0\nrep i0\n");
    src.push_str("BEGIN_REPEAT_BLOCK(1000)\nadd r0, r0, r0\nEND_REPEAT_BLOCK\n");
    src.push_str("endrep\nendrep\nendrep\nendrep\nmov oC0, r0\n");
    file(d, "huge_loop.psh", src.as_bytes());
    let o = ps30(&["check", "huge_loop.psh"], d);
    expect("a loop a million times over the limit", &o, 1, "OVER by");
    // A REPEAT_BLOCK bomb: 10^15 statements, refused before expansion.
    file(
        d,
        "bomb.psh",
        b"ps_3_0\nBEGIN_REPEAT_BLOCK(100000)\nBEGIN_REPEAT_BLOCK(100000)\nBEGIN_REPEAT_BLOCK(100000)\nmov r0, r0\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\n",
    );
    let o = ps30(&["check", "bomb.psh"], d);
    expect("a REPEAT_BLOCK bomb", &o, 2, "--max-expanded");
    // UTF-16 text, and a huge literal.
    file(d, "utf16.psh", b"\xff\xfep\x00s\x00_\x003\x00_\x000\x00");
    expect(
        "UTF-16 text",
        &ps30(&["check", "utf16.psh"], d),
        2,
        "a UTF-16 byte-order mark",
    );
    file(d, "big_literal.psh", b"ps_3_0\ndef c0, 1e999, 0, 0, 0\n");
    // Infinity, as Microsoft's assembler writes it (`1.#INF`).
    expect(
        "a huge literal",
        &ps30(&["check", "big_literal.psh"], d),
        0,
        "within limits",
    );
    file(
        d,
        "big_count.psh",
        b"ps_3_0\nBEGIN_REPEAT_BLOCK(99999999999999999999999)\nEND_REPEAT_BLOCK\n",
    );
    expect(
        "a huge count",
        &ps30(&["check", "big_count.psh"], d),
        2,
        "big_count.psh:2:",
    );
    file(
        d,
        "open.psh",
        b"ps_3_0\nBEGIN_REPEAT_BLOCK(3)\nmov r0, r1\n",
    );
    expect(
        "an unterminated block",
        &ps30(&["check", "open.psh"], d),
        2,
        "open.psh:2:1",
    );
}

/// Every bound with a flag, on both sides of it.
#[test]
fn every_bound_is_tested_on_both_sides() {
    let r = repo();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // --max-expanded: the pass-2 listing for 11×8 expands to 193 statements:
    // the version line and two dcls, 3 + 8·(2·11 + 1) + 3 instructions.
    let pass2 = r.join("asm/article/lum_pass2.psh");
    let pass2 = pass2.to_str().unwrap();
    let args = |cap: &str| {
        ps30(
            &[
                "check",
                pass2,
                "-D",
                "xsize=11",
                "-D",
                "ysize=8",
                "--max-expanded",
                cap,
            ],
            d,
        )
    };
    expect("expansion at the cap", &args("193"), 0, "within limits");
    expect(
        "expansion one over the cap",
        &args("192"),
        2,
        "--max-expanded 193",
    );
    // --max-pixels: sunset.exr has 1024·512 = 524,288 pixels.
    let img = r.join("assets/hdr/sunset.exr");
    let img = img.to_str().unwrap();
    let lum = |extra: &[&str]| {
        let mut a = vec![
            "luminance",
            img,
            "--pass1",
            "corrected:loop",
            "--block",
            "128x56",
        ];
        a.extend_from_slice(extra);
        ps30(&a, d)
    };
    expect(
        "image at the pixel cap",
        &lum(&["--max-pixels", "524288"]),
        0,
        "agree",
    );
    expect(
        "image one pixel over the cap",
        &lum(&["--max-pixels", "524287"]),
        2,
        "--max-pixels",
    );
    // --max-executed-per-pixel: pass 1 with 128×56 blocks runs 6 + 56·(3 + 128·9 + 1 + 2) slots.
    let per_pixel = (6 + 56 * (3 + 128 * 9 + 1 + 2)).to_string();
    let below = (6 + 56 * (3 + 128 * 9 + 1 + 2) - 1).to_string();
    expect(
        "executed at the cap",
        &lum(&["--max-executed-per-pixel", &per_pixel]),
        0,
        "agree",
    );
    expect(
        "executed one over the cap",
        &lum(&["--max-executed-per-pixel", &below]),
        2,
        "--max-executed-per-pixel",
    );
    // --max-target-pixels: 8×10 blocks of 128×52 make an 8×10 = 80-pixel target.
    let run = |cap: &str| ps30(&bin::loop_args(img, &["--max-target-pixels", cap]), d);
    expect("target at the cap", &run("80"), 0, "8×10 target");
    expect(
        "target one over the cap",
        &run("79"),
        2,
        "--max-target-pixels",
    );
    // --max-slots / --max-executed of check: the loop listing needs 20 slots, 64,853 executed.
    let shader = r.join("asm/article/lum_pass1_loop.psh");
    let shader = shader.to_str().unwrap();
    let check = |flag: &str, v: &str| {
        ps30(
            &[
                "check", shader, "--int", "i1=128", "--int", "i2=56", flag, v,
            ],
            d,
        )
    };
    expect(
        "slots at the limit",
        &check("--max-slots", "20"),
        0,
        "within limits",
    );
    expect(
        "slots over the limit",
        &check("--max-slots", "19"),
        1,
        "OVER by 1",
    );
    expect(
        "executed at the limit",
        &check("--max-executed", "64853"),
        0,
        "within limits",
    );
    expect(
        "executed over the limit",
        &check("--max-executed", "64852"),
        1,
        "OVER by 1",
    );
}

#[test]
fn a_failed_run_leaves_no_file_behind() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = repo().join("assets/hdr/sunset.exr");
    // The draw fails (executed cap): no output file, not even a partial one.
    let o = ps30(
        &bin::loop_args(
            img.to_str().unwrap(),
            &["--max-executed-per-pixel", "100", "-o", "out.exr"],
        ),
        d,
    );
    expect("a failing draw", &o, 2, "--max-executed-per-pixel");
    let left: Vec<_> = std::fs::read_dir(d).unwrap().collect();
    assert!(left.is_empty(), "files left behind: {left:?}");
    // An unwritable destination (its "directory" is a file): an error
    // naming it, and nothing but the blocking file in the folder.
    std::fs::write(d.join("blocker"), b"a file").unwrap();
    let listing = repo().join("asm/article/lum_pass1_loop.psh");
    let o = ps30(
        &["expand", listing.to_str().unwrap(), "-o", "blocker/x.psh"],
        d,
    );
    expect("an unwritable destination", &o, 2, "blocker/x.psh");
    let left: Vec<_> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(
        left,
        vec![std::ffi::OsString::from("blocker")],
        "files left behind"
    );
}

#[test]
fn outputs_are_byte_identical_across_runs_and_thread_counts() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = repo().join("assets/hdr/forest.hdr");
    let mut exrs = Vec::new();
    let mut jsons = Vec::new();
    for (i, threads) in ["1", "2", "2"].iter().enumerate() {
        let out = format!("out{i}.exr");
        let o = ps30(
            &bin::loop_args(
                img.to_str().unwrap(),
                &["--threads", threads, "-o", &out, "--json"],
            ),
            d,
        );
        assert_eq!(o.code, Some(0), "{}", o.stderr);
        exrs.push(std::fs::read(d.join(&out)).unwrap());
        jsons.push(o.stdout);
    }
    assert!(exrs.windows(2).all(|w| w[0] == w[1]), "EXR bytes differ");
    assert!(jsons.windows(2).all(|w| w[0] == w[1]), "JSON differs");
    // verify's reports, figures included, are compared byte for byte across
    // runs and thread counts in tests/reports.rs.
}
