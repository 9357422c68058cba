//! Drives the real `ps30` binary: exit codes, the article's figures as a user
//! sees them, JSON fields, over-limit messages, bad input.

use std::process::Output;

use crate::common::bin;
use bin::{ps30, repo, stderr, stdout};

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
    let exact = |n: u64| serde_json::json!({"min": n, "max": n});
    assert_eq!(v["slots"], 511);
    assert_eq!(v["executed"], exact(64_773));
    assert_eq!(v["limits"]["slots"], 512);
    assert_eq!(v["limits"]["executed"], 65_535);
    assert_eq!(v["within_limits"], true);
    let loops = v["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 1);
    assert_eq!(loops[0]["iterations"], exact(128));
    assert_eq!(loops[0]["cost_per_iteration"], exact(506));
    assert_eq!(loops[0]["total"], exact(128 * 506));
    assert_eq!(loops[0]["line"], 32);
    // The article's figures are the same under both slot tables.
    assert_eq!(v["documented_slots"], 511);
    assert_eq!(
        v["fxc_slots"],
        serde_json::json!({"total": 511, "texture": 125, "arithmetic": 386})
    );
}

#[test]
fn crc32_is_zlibs_of_the_bytecode() {
    // Independent values: python3 -c "import zlib; print('%08x' %
    // zlib.crc32(open(PATH, 'rb').read()))" on the committed file, and on the
    // bytecode `ps30 asm` writes for the article's loop shader (which is
    // D3DAssemble's, token for token).
    let o = ps30(
        &["check", "fuzz/seeds/bytecode/everything.fxo", "--json"],
        repo(),
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["crc32"], "31d289ce");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("loop.fxo");
    let out = out.to_str().unwrap();
    let o = ps30(
        &[
            "asm",
            "asm/article/lum_pass1_loop.psh",
            "-o",
            out,
            "--crc32",
            "-q",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(String::from_utf8_lossy(&o.stdout), "0a92b37c\n");
    let o = ps30(
        &["check", "asm/article/lum_pass1_loop.psh", "--json"],
        repo(),
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["crc32"], "0a92b37c");
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
    // if 3 + else 1 + endif 1 + mov oC0 1 = 6 on both paths, plus 2 or 1.
    assert_eq!(v["executed"], serde_json::json!({"min": 7, "max": 8}));
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
    // Read one byte a character, as Microsoft's assembler reads it: the
    // character is named where it stands, with Microsoft's code.
    assert!(
        stderr(&o).contains("error[X2000]: unexpected U+00FF"),
        "{}",
        stderr(&o)
    );
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
        "block_choice",
        "targets",
        "passes",
        "blocks",
    ] {
        assert!(!v[key].is_null(), "missing {key}");
    }
    assert_eq!(v["agree"], true);
    // No shader named: the plan's block for a 1024×512 image, 114×128
    // (9 columns of 114 = 1,026, 2 padded; 4 rows of 128), not the
    // article's 125×128.
    assert_eq!(v["block_choice"]["source"], "planned");
    assert_eq!(v["block"], serde_json::json!([114, 128]));
    assert_eq!(v["targets"], serde_json::json!([9, 4]));
    assert_eq!(v["padded_samples"], 2 * 512);
    // The article's set-up (5) and output (1)... as generated: 5 set-up
    // instructions, 128 lines of rep 3 + 114·4 + mad 1 + endrep 2.
    let pass1 = &v["passes"][0];
    assert_eq!(pass1["role"], "pass1");
    let executed = 5 + 128 * (3 + 114 * 4 + 1 + 2);
    assert_eq!(
        pass1["executed"],
        serde_json::json!({"min": executed, "max": executed})
    );
    assert_eq!(pass1["executed_emulated"], pass1["executed"]);
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
    let o = bin::run_loop_example(&["-o", out.to_str().unwrap(), "--json", "--texels"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // 5 set-up + 52 lines of (3 + 128·9 + 1 + 2) + 1.
    let executed = 6 + 52 * (3 + 128 * 9 + 1 + 2);
    assert_eq!(
        v["pass"]["executed_emulated"],
        serde_json::json!({"min": executed, "max": executed})
    );
    let img = ps30::core::image::load(&out, &ps30::core::image::ImageLimits::default()).unwrap();
    assert_eq!((img.width, img.height), (8, 10));
    let texels = v["texels"].as_array().unwrap();
    assert_eq!(texels.len(), 80);
    for (t, p) in texels.iter().zip(&img.pixels) {
        assert_eq!(t[0].as_f64().unwrap() as f32, p[0]);
    }
    // Without --texels, no per-pixel data.
    let o = bin::run_loop_example(&["--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v.get("texels").is_none());
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

#[test]
fn plan_shows_the_articles_choices_and_recommends_one() {
    let o = ps30(&["plan", "--frame", "1280x1024"], repo());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let row = |block: &str| {
        out.lines()
            .find(|l| l.split_whitespace().nth(2) == Some(block))
            .unwrap_or_else(|| panic!("no {block} row in\n{out}"))
            .to_string()
    };
    let loop_row = row("128×56");
    assert!(
        loop_row.contains("10×19") && loop_row.contains("64,853"),
        "{loop_row}"
    );
    assert!(loop_row.contains("the article's"));
    let unrolled_row = row("125×128");
    assert!(unrolled_row.contains("11×8") && unrolled_row.contains("64,773"));
    assert!(unrolled_row.contains("97,280") && unrolled_row.contains("× 0.5048"));
    assert!(out.contains("recommended (*): unrolled"), "{out}");
    assert!(out.contains("rule: among candidates that finish in two passes"));
    assert!(out.contains("why: "));
}

#[test]
fn plan_json_has_the_documented_fields() {
    let o = ps30(&["plan", "--frame", "1280x1024", "--json"], repo());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let cands = v["candidates"].as_array().unwrap();
    assert!(cands.len() >= 10);
    for c in cands {
        for field in [
            "name",
            "variant",
            "block",
            "targets",
            "passes",
            "slots",
            "executed_per_pixel",
            "total_executed",
            "padded_samples",
            "uncorrected_factor",
            "f16_safe",
        ] {
            assert!(c.get(field).is_some(), "{field} missing in {c}");
        }
        assert!(["loop", "unrolled"].contains(&c["variant"].as_str().unwrap()));
    }
    let art = cands
        .iter()
        .find(|c| c["variant"] == "loop" && c["block"] == serde_json::json!([128, 56]))
        .unwrap();
    assert_eq!(art["targets"], serde_json::json!([10, 19]));
    assert_eq!(art["executed_per_pixel"][0], 64_853);
    let rec = v["recommended"].as_str().unwrap();
    assert!(cands.iter().any(|c| c["name"] == rec));
    assert_eq!(v["profile"]["slots"], 512);
}

#[test]
fn plan_with_more_slots_changes_the_recommendation() {
    let rec = |extra: &[&str]| {
        let mut args = vec!["plan", "--frame", "1280x1024", "--json"];
        args.extend_from_slice(extra);
        let o = ps30(&args, repo());
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        v["recommended"].as_str().unwrap().to_string()
    };
    assert_ne!(rec(&[]), rec(&["--max-slots", "1024"]));
    // Loops nested at most once: no rep/rep loop form.
    let o = ps30(
        &["plan", "--frame", "1280x1024", "--max-nesting", "1"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    assert!(!out
        .lines()
        .any(|l| l.split_whitespace().nth(1) == Some("loop")));
    assert!(
        out.contains("the loop form does not fit this profile"),
        "{out}"
    );
}

#[test]
fn plan_bad_and_absurd_frames() {
    for bad in ["0x0", "1280x0", "70000x10", "1280", "axb"] {
        let o = ps30(&["plan", "--frame", bad], repo());
        assert_eq!(o.status.code(), Some(2), "{bad}: {}", stdout(&o));
    }
    for bad in [
        ["--max-slots", "0"],
        ["--max-rep-count", "256"],
        ["--max-nesting", "5"],
    ] {
        let mut args = vec!["plan", "--frame", "640x480"];
        args.extend_from_slice(&bad);
        assert_eq!(ps30(&args, repo()).status.code(), Some(2), "{bad:?}");
    }
    // The largest frame accepted: every plan needs a third pass; exit 1,
    // said in words, no panic.
    let o = ps30(&["plan", "--frame", "65536x65536"], repo());
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stdout(&o).contains("a third pass would be needed"));
    // A profile nothing fits.
    let o = ps30(&["plan", "--frame", "640x480", "--max-slots", "10"], repo());
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("does not fit this profile"));
}

#[test]
fn unroll_fit_reproduces_the_articles_125() {
    let o = ps30(&["unroll", "--fit"], repo());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains(
            "widest unroll: 125 texels per line, 511 slots of 512; 126 would take 515 slots"
        ),
        "{out}"
    );
    assert!(out.contains("so 128 lines"), "{out}");
    assert!(out.contains("pass1_unrolled_125x128.psh"));
    assert!(out.contains("pass2_11x8.psh"));
    assert!(out.contains("pass1_last_loop_30x128.psh"));
    // --only prints one plain file, no macros.
    let o = ps30(
        &["unroll", "--fit", "--form", "unrolled", "--only", "pass1"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.starts_with("// ps30 unroll: luminance pass 1"));
    let texlds = text
        .lines()
        .filter(|l| l.trim_start().starts_with("texld "))
        .count();
    assert_eq!(texlds, 125);
    assert!(!text.contains("REPEAT_BLOCK"));
    let o = ps30(
        &[
            "unroll", "--fit", "--form", "unrolled", "--only", "pass1", "--macro",
        ],
        repo(),
    );
    assert!(stdout(&o).contains("BEGIN_REPEAT_BLOCK(125)"));
    // With 1,024 slots the widest unroll is 253.
    let o = ps30(&["unroll", "--fit", "--max-slots", "1024"], repo());
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("widest unroll: 253 texels per line"));
}

#[test]
fn unroll_writes_files_that_check_passes() {
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(
        &[
            "unroll",
            "--fit",
            "--frame",
            "1920x1080",
            "-o",
            dir.path().to_str().unwrap(),
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let files: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert!(files.len() >= 4, "{files:?}");
    for f in files {
        let o = ps30(&["check", f.to_str().unwrap()], repo());
        assert_eq!(o.status.code(), Some(0), "{}: {}", f.display(), stdout(&o));
    }
    let o = ps30(
        &[
            "unroll", "--block", "125x128", "--form", "unrolled", "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let p1 = &v["shaders"][0];
    assert_eq!(p1["slots"], 511);
    assert_eq!(p1["executed"], 64_773);
    assert!(p1["text"].as_str().unwrap().contains("defi i2, 128"));
}

#[test]
fn unroll_blocks_that_cannot_fit_exit_1_with_numbers() {
    let o = ps30(&["unroll", "--block", "200x50"], repo());
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(
        out.contains("811 slots, over the limit of 512 by 299"),
        "{out}"
    );
    assert!(
        out.contains("90,305 executed per pixel, over the limit of 65,535"),
        "{out}"
    );
    let o = ps30(&["unroll", "--block", "300x10", "--form", "loop"], repo());
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("rep count of 300"));
    // Bad values and usage: exit 2.
    for args in [
        &["unroll"][..],
        &["unroll", "--block", "0x5"],
        &["unroll", "--block", "8x8", "--fit"],
        &["unroll", "--fit", "--frame", "0x0"],
        &["unroll", "--fit", "--delta", "-1"],
        &["unroll", "--fit", "--only", "pass1"],
    ] {
        let o = ps30(args, repo());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
    }
}

#[test]
fn verify_names_stale_generated_files() {
    let dir = tempfile::tempdir().unwrap();
    let gen = dir.path().join("gen");
    let reports = dir.path().join("reports");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "verify",
            "--reports",
            reports.to_str().unwrap(),
            "--generated",
            gen.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        ps30(&args, repo())
    };
    // Missing: exit 1, each file named.
    let o = run(&[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("1280x1024/pass1_unrolled_125x128.psh is missing"));
    // --regenerate writes them; then verify passes.
    assert_eq!(run(&["--regenerate"]).status.code(), Some(0));
    assert_eq!(run(&[]).status.code(), Some(0));
    let file = gen.join("640x480/pass2_6x4.psh");
    let text = std::fs::read_to_string(&file).unwrap();
    std::fs::write(&file, text.replace("c0.x", "c0.z")).unwrap();
    let o = run(&[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("640x480/pass2_6x4.psh is stale"));
    assert!(reports.join("generated-shaders.md").exists());
}

#[test]
fn luminance_runs_a_generated_set_with_its_last_column_shader() {
    let g = "asm/generated/1280x1024";
    let o = ps30(
        &[
            "luminance",
            "assets/hdr/courtyard_1280x1024.exr",
            "--pass1",
            &format!("{g}/pass1_unrolled_117x128.psh"),
            "--last-column",
            &format!("{g}/pass1_last_unrolled_110x128.psh"),
            "--pass2",
            &format!("{g}/pass2_11x8.psh"),
            "--block",
            "117x128",
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["agree"], true);
    assert_eq!(v["padded_samples"], 0);
    assert_eq!(v["passes"][1]["role"], "pass1_last");
    assert_eq!(
        v["passes"][1]["executed_emulated"],
        serde_json::json!({"min": 57_093, "max": 57_093})
    );
}

#[test]
fn a_closed_stdout_is_not_an_error() {
    use std::process::{Command, Stdio};
    // The reader goes away before ps30 has started writing (process start-up
    // takes milliseconds): every write then fails with EPIPE.
    let mut child = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(["expand", "asm/article/lum_pass1_unrolled.psh"])
        .current_dir(repo())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

// ---------------------------------------------------------------------------
// Compiled shaders: ps30 asm, ps30 disasm, and bytecode everywhere a shader
// is read.

use crate::common::ctab as ctab_builder;

/// `ps30 asm ARGS -o dir/NAME`, which must succeed; the path written.
fn asm(dir: &std::path::Path, args: &[&str], name: &str) -> std::path::PathBuf {
    let out = dir.join(name);
    let mut all = vec!["asm"];
    all.extend(args);
    all.extend(["-o", out.to_str().unwrap()]);
    let o = ps30(&all, repo());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    out
}

fn json(o: &Output) -> serde_json::Value {
    assert_eq!(o.status.code(), Some(0), "{}", stderr(o));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn asm_then_check_counts_as_the_text_and_disasm_assembles_to_the_same_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let d = ["-D", "xsize=11", "-D", "ysize=8"];
    let p2 = asm(
        dir.path(),
        &["asm/corrected/lum_pass2.psh", d[0], d[1], d[2], d[3]],
        "p2.fxo",
    );
    let text = json(&ps30(
        &[
            "check",
            "asm/corrected/lum_pass2.psh",
            d[0],
            d[1],
            d[2],
            d[3],
            "--json",
        ],
        repo(),
    ));
    let compiled = json(&ps30(&["check", p2.to_str().unwrap(), "--json"], repo()));
    for key in ["slots", "executed", "verdict"] {
        assert_eq!(text[key], compiled[key], "{key}");
    }
    assert_eq!(compiled["slots"], 191);
    let sum = |v: &serde_json::Value| -> u64 {
        v["lines"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| l["executed"]["max"].as_u64().unwrap())
            .sum()
    };
    assert_eq!(sum(&text), sum(&compiled));
    // disasm | asm - gives the same bytes.
    let listing = ps30(&["disasm", p2.to_str().unwrap()], repo());
    assert_eq!(listing.status.code(), Some(0), "{}", stderr(&listing));
    let again = dir.path().join("again.fxo");
    let o = bin::ps30_with_stdin(
        &["asm", "-", "-o", again.to_str().unwrap()],
        repo(),
        &listing.stdout,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(std::fs::read(&p2).unwrap(), std::fs::read(&again).unwrap());
    // And -o - writes the same bytes to a pipe.
    let piped = ps30(&["asm", p2.to_str().unwrap(), "-o", "-"], repo());
    assert_eq!(piped.status.code(), Some(0), "{}", stderr(&piped));
    assert_eq!(piped.stdout, std::fs::read(&p2).unwrap());
    let listed = stdout(&listing);
    assert!(listed.starts_with("    ps_3_0\n"), "{listed}");
    assert!(
        listed.ends_with(
            "// approximately 191 instruction slots used (88 texture, 103 arithmetic)\n"
        ),
        "{listed}"
    );
}

#[test]
fn every_command_that_reads_a_shader_takes_bytecode_and_gets_the_same_results() {
    let dir = tempfile::tempdir().unwrap();
    let p = |f: &std::path::PathBuf| f.to_str().unwrap().to_string();
    // sunset.pfm is 1024×512: 125×128 blocks make a 9×4 target.
    let pass1 = p(&asm(dir.path(), &["corrected:unrolled"], "p1.fxo"));
    let pass2 = p(&asm(
        dir.path(),
        &["corrected:pass2", "-D", "xsize=9", "-D", "ysize=4"],
        "p2.fxo",
    ));
    let tone = p(&asm(dir.path(), &["tonemap:reinhard"], "tone.fxo"));
    let select = p(&asm(dir.path(), &["lights:select"], "select.fxo"));
    let lum = |a: &str, b: &str| {
        json(&ps30(
            &[
                "luminance",
                "assets/hdr/sunset.pfm",
                "--pass1",
                a,
                "--pass2",
                b,
                // A compiled shader states no block: give the listing's.
                "--block",
                "125x128",
                "--json",
            ],
            repo(),
        ))
    };
    let (t, c) = (
        lum("corrected:unrolled", "corrected:pass2"),
        lum(&pass1, &pass2),
    );
    for key in ["log_average", "reference_log_average", "agree"] {
        assert_eq!(t[key], c[key], "luminance {key}");
    }
    for pass in 0..2 {
        let executed = |v: &serde_json::Value| v["passes"][pass]["executed"].clone();
        assert!(executed(&t)["max"].is_u64(), "{t}");
        assert_eq!(executed(&t), executed(&c), "pass {pass}");
    }
    let tm = |s: &str| {
        json(&ps30(
            &["tonemap", "assets/hdr/sunset.pfm", "--shader", s, "--json"],
            repo(),
        ))
    };
    let (t, c) = (tm("tonemap:reinhard"), tm(&tone));
    for key in [
        "log_average",
        "max_error",
        "mismatched_8bit_channels",
        "agree",
    ] {
        assert_eq!(t[key], c[key], "tonemap {key}");
    }
    let run = |s: &str| {
        json(&ps30(
            &[
                &[
                    "run",
                    s,
                    "--image",
                    "assets/hdr/sunset.pfm",
                    "--target",
                    "9x4",
                    "--int",
                    "i2=128",
                    "--json",
                ][..],
                &bin::LOOP_FLOATS,
            ]
            .concat(),
            repo(),
        ))
    };
    let (t, c) = (run("corrected:unrolled"), run(&pass1));
    assert_eq!(t["target"], c["target"], "run's target");
    let prof = |s: &str| {
        json(&ps30(
            &["profile", s, "--gbuffer", "16x16", "--json"],
            repo(),
        ))
    };
    let (t, c) = (prof("lights:select"), prof(&select));
    for key in ["per_pixel", "per_quad", "divergent_quads", "models"] {
        assert_eq!(t[key], c[key], "profile {key}");
    }
    let expanded = ps30(&["expand", &pass2], repo());
    assert_eq!(expanded.status.code(), Some(0), "{}", stderr(&expanded));
    assert!(stdout(&expanded).contains("texld r2.x, r0, s0"));
}

/// A shader whose constant table names c0 `g_fKey`, i0 `g_iSteps` and b0
/// `g_bOn`: as assembly with the table in `//#comment` lines.
fn shader_with_table(dir: &std::path::Path) -> std::path::PathBuf {
    use ctab_builder::{comment_lines, table, Const, Ty};
    let body = table(
        "tests",
        "ps_3_0",
        0xffff0300,
        &[
            Const {
                name: "g_fKey",
                set: 2,
                index: 0,
                count: 1,
                ty: Ty::numeric(0, 3, 1, 1, 1),
                default: Some(vec![0.18f32.to_bits(), 0, 0, 0]),
            },
            Const {
                name: "g_iSteps",
                set: 1,
                index: 0,
                count: 1,
                ty: Ty::numeric(1, 2, 1, 4, 1),
                default: None,
            },
            Const {
                name: "g_bOn",
                set: 0,
                index: 0,
                count: 1,
                ty: Ty::numeric(0, 1, 1, 1, 1),
                default: None,
            },
        ],
    );
    let src = format!(
        "ps_3_0\n{}dcl_texcoord0 v0.xy\ndcl_2d s0\ntexld r0, v0, s0\nrep i0\n  add r0, r0, c0.x\nendrep\nif b0\n  mul r0, r0, c0.x\nendif\nmov oC0, r0\n",
        comment_lines(&body)
    );
    let path = dir.join("named.psh");
    std::fs::write(&path, src).unwrap();
    asm(dir, &[path.to_str().unwrap()], "named.fxo")
}

#[test]
fn constants_are_given_by_their_names_in_the_constant_table() {
    let dir = tempfile::tempdir().unwrap();
    let fxo = shader_with_table(dir.path());
    let f = fxo.to_str().unwrap();
    let o = ps30(
        &["check", f, "--int", "g_iSteps=5", "--bool", "g_bOn=true"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    // texld 1, then 5 iterations of rep 3 + add 1 + endrep 2 (rep and endrep
    // are charged per iteration), if 3, mul 1, endif 1, mov 1: 37.
    assert!(out.contains("executed           37 / 65,535"), "{out}");
    for line in [
        "g_fKey    c0           1  float  (0.18, 0, 0, 0)",
        "g_iSteps  i0           1  int4",
        "g_bOn     b0           1  bool",
    ] {
        assert!(out.contains(line), "`{line}` missing from\n{out}");
    }
    let by_register = json(&ps30(
        &["check", f, "--int", "i0=5", "--bool", "b0=true", "--json"],
        repo(),
    ));
    assert_eq!(
        by_register["executed"],
        serde_json::json!({"min": 37, "max": 37})
    );
    assert_eq!(
        by_register["constant_table"]["constants"][0]["name"],
        "g_fKey"
    );
    let run = |c: &str| {
        json(&ps30(
            &[
                "run",
                f,
                "--image",
                "assets/hdr/sunset.pfm",
                "--target",
                "4x2",
                "--const",
                c,
                "--int",
                "g_iSteps=2",
                "--bool",
                "g_bOn=false",
                "--json",
            ],
            repo(),
        ))
    };
    assert_eq!(run("g_fKey=0.5")["target"], run("c0=0.5")["target"]);
    for (args, says) in [
        (
            vec!["check", f, "--int", "g_fKey=1"],
            "`g_fKey` is a float4 constant (c0); set it with --const",
        ),
        (
            vec!["check", f, "--int", "g_nope=1"],
            "has no `g_nope` (it has g_fKey, g_iSteps, g_bOn)",
        ),
        (
            vec!["check", "corrected:loop", "--int", "g_iSteps=1"],
            "has no constant table",
        ),
        (
            vec!["check", f, "--int", "g_iSteps=1,2,3,4,5"],
            "5 values, but the target takes 1 register of 4",
        ),
    ] {
        let o = ps30(&args, repo());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(says), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn disasm_lists_the_table_and_its_json_has_the_documented_fields() {
    let dir = tempfile::tempdir().unwrap();
    let fxo = shader_with_table(dir.path());
    let o = ps30(&["disasm", fxo.to_str().unwrap()], repo());
    let out = stdout(&o);
    for line in [
        "// Generated by tests",
        "//   float g_fKey;",
        "//   g_iSteps     i0       1",
        "      add r0, r0, c0.x",
    ] {
        assert!(out.contains(line), "`{line}` missing from\n{out}");
    }
    // Microsoft's listing drops comment blocks; the annotated one keeps them.
    assert!(!out.contains("//#comment"), "{out}");
    let o = ps30(&["disasm", fxo.to_str().unwrap(), "--annotated"], repo());
    let annotated = stdout(&o);
    for line in [
        "// Generated by tests",
        "//#comment 42415443 0000001c",
        "      add r0, r0, c0.x",
    ] {
        assert!(
            annotated.contains(line),
            "`{line}` missing from\n{annotated}"
        );
    }
    let v = json(&ps30(&["disasm", fxo.to_str().unwrap(), "--json"], repo()));
    for key in [
        "file",
        "version",
        "tokens",
        "bytes",
        "slots",
        "constant_table",
        "comments",
        "instructions",
        "listing",
        "annotated",
        "slots_documented",
    ] {
        assert!(!v[key].is_null(), "missing {key}");
    }
    assert_eq!(v["constant_table"]["constants"][1]["register"], "i0");
    let first = &v["instructions"][0];
    assert_eq!(first["text"], "dcl_texcoord v0.xy");
    assert_eq!(first["byte"], first["token"].as_u64().unwrap() * 4);
    assert_eq!(v["listing"], out);
    assert_eq!(v["annotated"], annotated);
}

#[test]
fn asm_refuses_invalid_programs_and_other_versions_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.fxo");
    for (src, says) in [
        (
            "ps_3_0\nmov oC0, r5.x\nfoo r0\n",
            "unknown instruction `foo`",
        ),
        (
            "vs_1_1\nmov oPos, c0\n",
            "this is a vs_1_1 shader; ps30 reads ps_2_0, ps_2_x, ps_3_0",
        ),
        ("ps_1_4\nmov r0, c8\n", "invalid register 'c8'"),
    ] {
        let path = dir.path().join("bad.psh");
        std::fs::write(&path, src).unwrap();
        let o = ps30(
            &["asm", path.to_str().unwrap(), "-o", out.to_str().unwrap()],
            repo(),
        );
        assert_eq!(o.status.code(), Some(2));
        assert!(stderr(&o).contains(says), "{}", stderr(&o));
        assert!(!out.exists(), "nothing is written");
    }
    let o = ps30(
        &["asm", "corrected:pass2", "-o", "/nonexistent/dir/x.fxo"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("does not exist"), "{}", stderr(&o));
}
