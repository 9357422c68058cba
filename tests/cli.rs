//! Drives the real `ps30` binary: exit codes, the article's figures as a user
//! sees them, JSON fields, over-limit messages, bad input.

use std::path::Path;
use std::process::{Command, Output};

fn ps30(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run ps30")
}

fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn check_prints_the_articles_loop_figures() {
    let o = ps30(
        &[
            "check",
            "asm/article/lum_pass1_loop.psh",
            "--int",
            "i1=128",
            "--int",
            "i2=56",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("64,853 / 65,535"), "{out}");
    // The loop table: rep i2 own cost 6 per line, rep i1 9 per pixel.
    let row = |header: &str| {
        out.lines()
            .filter(|l| l.split_whitespace().count() >= 8)
            .find(|l| l.contains(header))
            .unwrap_or_else(|| panic!("no loop row for {header} in\n{out}"))
            .split_whitespace()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    let outer = row("rep i2");
    let inner = row("rep i1");
    // columns: line, rep, iN, iterations, entries, per-iteration, own, total
    assert_eq!(&outer[3..8], ["56", "1", "1,158", "6", "64,848"]);
    assert_eq!(&inner[3..8], ["128", "56", "9", "9", "64,512"]);
    assert!(out.contains("verdict: within limits"));
}

#[test]
fn check_json_has_the_documented_fields() {
    let o = ps30(
        &[
            "check",
            "asm/article/lum_pass1_unrolled.psh",
            "--int",
            "i2=128",
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["slots"], 511);
    assert_eq!(v["executed"], 64_773);
    assert_eq!(v["executed_min"], 64_773);
    assert_eq!(v["executed_max"], 64_773);
    assert_eq!(v["max_slots"], 512);
    assert_eq!(v["max_executed"], 65_535);
    assert_eq!(v["within_limits"], true);
    let loops = v["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 1);
    assert_eq!(loops[0]["iterations"], 128);
    assert_eq!(loops[0]["cost_per_iteration"], 506);
    assert_eq!(loops[0]["total"], 128 * 506);
    assert_eq!(loops[0]["line"], 32);
}

#[test]
fn over_the_executed_limit_exits_1_and_says_by_how_much() {
    // 130 lines of 506 plus 5: 65,785, which is 250 over 65,535.
    let o = ps30(
        &[
            "check",
            "asm/article/lum_pass1_unrolled.psh",
            "--int",
            "i2=130",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(out.contains("65,785 / 65,535"), "{out}");
    assert!(out.contains("OVER by 250"), "{out}");
    assert!(out.contains("EXCEEDS"), "{out}");
}

#[test]
fn over_the_slot_limit_exits_1() {
    let o = ps30(
        &[
            "check",
            "asm/article/lum_pass1_unrolled.psh",
            "--int",
            "i2=1",
            "--max-slots",
            "500",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("511 / 500"), "{}", stdout(&o));
    assert!(stdout(&o).contains("OVER by 11"), "{}", stdout(&o));
}

#[test]
fn data_dependent_counts_are_reported_as_ranges() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("d.psh"),
        "ps_3_0\ndcl_texcoord0 v0\nif_gt v0.x, v0.y\n  add r0, v0, v0\n  add r0, r0, r0\nelse\n  mov r0, v0\nendif\nmov oC0, r0\n",
    )
    .unwrap();
    let o = ps30(&["check", "d.psh", "--json"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["executed"].is_null());
    // if 3 + else 1 + endif 1 + mov oC0 1 = 6 on both paths, plus 2 or 1.
    assert_eq!(v["executed_min"], 7);
    assert_eq!(v["executed_max"], 8);
    assert_eq!(v["data_dependent"], true);
}

#[test]
fn expand_round_trips_through_check() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("pass2.psh");
    let o = ps30(
        &[
            "expand",
            "asm/article/lum_pass2.psh",
            "-D",
            "xsize=11",
            "-D",
            "ysize=8",
            "-o",
            out.to_str().unwrap(),
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(!text.to_ascii_uppercase().contains("REPEAT"));
    assert_eq!(text.matches("texld").count(), 88);
    let o = ps30(&["check", out.to_str().unwrap(), "--json"], repo());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["slots"], 190);
}

#[test]
fn verify_reproduces_every_claim_and_writes_the_report() {
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(
        &[
            "verify",
            "--reports",
            dir.path().to_str().unwrap(),
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["all_agree"], true);
    let claims = v["claims"].as_array().unwrap();
    assert!(claims.len() >= 12);
    let md = std::fs::read_to_string(dir.path().join("article-claims.md")).unwrap();
    assert!(md.contains("| 64,853 | 64,853 | yes |"));
    assert!(md.contains("| 64,773 | 64,773 | yes |"));
}

#[test]
fn bad_input_exits_2_with_file_line_col() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bad.psh"),
        "ps_3_0\nmov r0, r1\nfoo r0, r1\n",
    )
    .unwrap();
    let o = ps30(&["check", "bad.psh"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("bad.psh:3:1"), "{err}");
    assert!(err.contains("unknown instruction `foo`"), "{err}");
    assert!(err.contains('^'), "{err}");
}

#[test]
fn missing_file_invalid_utf8_and_bad_flags_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(&["check", "nope.psh"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("nope.psh"));
    std::fs::write(dir.path().join("bin.psh"), b"ps_3_0\n\xff\xfe mov").unwrap();
    let o = ps30(&["check", "bin.psh"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("not UTF-8"), "{}", stderr(&o));
    let o = ps30(
        &["check", "asm/article/lum_pass1_loop.psh", "--int", "i99=3"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    let o = ps30(
        &["check", "asm/article/lum_pass1_loop.psh", "--int", "i1=300"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("0..=255"), "{}", stderr(&o));
    let o = ps30(
        &[
            "check",
            "asm/article/lum_pass1_loop.psh",
            "--max-slots",
            "-3",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    let o = ps30(
        &["check", "asm/article/lum_pass2.psh", "-D", "xsize"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn undefined_repeat_name_names_the_flag() {
    let o = ps30(&["check", "asm/article/lum_pass2.psh"], repo());
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("`ysize` is not defined"), "{err}");
    assert!(err.contains("-D ysize="), "{err}");
}

#[test]
fn luminance_json_has_the_documented_fields() {
    let o = ps30(&["luminance", "assets/hdr/sunset.pfm", "--json"], repo());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for key in [
        "log_average",
        "reference_log_average",
        "relative_error",
        "agree",
        "target_format",
        "block",
        "targets",
        "executed_per_pixel",
        "blocks",
    ] {
        assert!(!v[key].is_null(), "missing {key}");
    }
    assert_eq!(v["agree"], true);
    assert_eq!(v["block"], serde_json::json!([125, 128]));
    // 1024×512 image: ⌈1024/125⌉ × ⌈512/128⌉.
    assert_eq!(v["targets"], serde_json::json!([9, 4]));
    // 5 set-up instructions and the output mov, 128 lines of rep 3 + 125·4 + mad 1 + endrep 2.
    assert_eq!(
        v["executed_per_pixel"]["pass1"],
        6 + 128 * (3 + 500 + 1 + 2)
    );
    let b = &v["blocks"][0];
    for key in ["x", "y", "emulated", "reference", "agree"] {
        assert!(!b[key].is_null(), "block missing {key}");
    }
}

#[test]
fn luminance_with_the_articles_shaders_exits_1_and_names_the_blocks() {
    let o = ps30(
        &[
            "luminance",
            "assets/hdr/forest.exr",
            "--pass1",
            "article:loop",
            "--pass2",
            "article:pass2",
            "--block",
            "128x56",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("disagreeing blocks"), "{out}");
    assert!(out.contains("DISAGREE"), "{out}");
}

#[test]
fn luminance_refuses_bad_images_and_values_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("junk.exr"), b"not an image at all").unwrap();
    let o = ps30(&["luminance", "junk.exr"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("junk.exr"), "{}", stderr(&o));
    let o = ps30(&["luminance", "missing.hdr"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    for args in [
        ["--block", "0x5"],
        ["--delta", "-1"],
        ["--delta", "nan"],
        ["--target-format", "f64"],
        ["--pass1", "nope.psh"],
    ] {
        let mut all = vec!["luminance", "assets/hdr/sunset.exr"];
        all.extend(args);
        let o = ps30(&all, repo());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    }
    let o = ps30(
        &["luminance", "assets/hdr/sunset.exr", "--max-pixels", "1000"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--max-pixels"), "{}", stderr(&o));
}

#[test]
fn run_writes_a_target_that_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sums.exr");
    let o = ps30(
        &[
            "run",
            "corrected:loop",
            "--image",
            "assets/hdr/forest.hdr",
            "--target",
            "8x10",
            "--int",
            "i1=128",
            "--int",
            "i2=52",
            "--const",
            "c1=0.0009765625,0.001953125,0,1",
            "--const",
            "c3=0.27,0.67,0.06,0.01",
            "-o",
            out.to_str().unwrap(),
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // 5 set-up + 52 lines of (3 + 128·9 + 1 + 2) + 1.
    assert_eq!(v["executed_per_pixel"], 6 + 52 * (3 + 128 * 9 + 1 + 2));
    let img = ps30::image::load(&out, &ps30::image::ImageLimits::default()).unwrap();
    assert_eq!((img.width, img.height), (8, 10));
    let texels = v["texels"].as_array().unwrap();
    for (t, p) in texels.iter().zip(&img.pixels) {
        assert_eq!(t.as_f64().unwrap() as f32, p[0]);
    }
}

#[test]
fn run_reports_shader_errors_with_a_caret() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bad.psh"),
        "ps_3_0\ndcl_2d s0\ntexld r0, r1, s9\n",
    )
    .unwrap();
    let o = ps30(
        &[
            "run",
            "bad.psh",
            "--image",
            &format!("{}/assets/hdr/sunset.exr", repo().display()),
            "--target",
            "2x2",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("bad.psh:3:"), "{err}");
    assert!(err.contains('^'), "{err}");
}
