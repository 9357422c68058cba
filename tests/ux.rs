//! What a new user meets, through the real binary: the mistakes of the
//! user-experience issue, each of which once gave a wrong answer with exit 0
//! or an unreadable one, and now gives a clear message and the documented
//! exit code.

use std::path::Path;
use std::process::Output;

use crate::common::bin;
use bin::{in_repo as ps30, stderr as err, stdout as out};

fn ps30_in(dir: &Path, args: &[&str]) -> Output {
    bin::ps30(args, dir)
}

/// A `w × h` PFM (colour) whose pixels vary smoothly, written to `path`.
fn pfm(path: &Path, w: u32, h: u32) {
    let mut bytes = format!("PF\n{w} {h}\n-1\n").into_bytes();
    for y in 0..h {
        for x in 0..w {
            let v = 0.05 + 0.3 * (x as f32 + 1.0) * (y as f32 + 2.0) / (w * h) as f32;
            for c in [v, 0.8 * v, 1.3 * v] {
                bytes.extend_from_slice(&c.to_le_bytes());
            }
        }
    }
    std::fs::write(path, bytes).unwrap();
}

#[test]
fn a_run_on_constants_nobody_set_is_refused_naming_them() {
    for args in [
        &[
            "run",
            "corrected:loop",
            "--image",
            "assets/hdr/forest.hdr",
            "--target",
            "8x10",
        ][..],
        &[
            "profile",
            "corrected:loop",
            "--image",
            "assets/hdr/forest.hdr",
            "--target",
            "8x8",
        ],
    ] {
        let o = ps30(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", err(&o));
        assert!(
            o.stdout.is_empty(),
            "{args:?}: nothing is reported as a result"
        );
        let e = err(&o);
        assert!(e.contains("reads c0, c1, c3, i1 and i2"), "{e}");
        assert!(
            e.contains("lum_pass1_loop.psh:24:1"),
            "the first read is pointed at: {e}"
        );
        assert!(e.contains("--int i1=N"), "the fix is spelled out: {e}");
    }
    // With them set, the same run works.
    let o = bin::run_loop_example(&[]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(err(&o).is_empty(), "{}", err(&o));
}

#[test]
fn overridden_unread_and_unused_values_are_warnings() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("d.psh"),
        "ps_3_0\ndefi i0, 4, 0, 0, 0\ndef c0, 1, 1, 1, 1\nmov r0, c0\nrep i0\nadd r0, r0, c0\nendrep\nmov oC0, r0\n",
    )
    .unwrap();
    let o = ps30_in(
        dir.path(),
        &[
            "check", "d.psh", "--int", "i0=3", "--const", "c5=1", "-D", "xsiz=11",
        ],
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "warnings do not change the exit code"
    );
    let e = err(&o);
    assert!(
        e.contains("--int i0=… has no effect: the shader's own `defi` sets i0"),
        "{e}"
    );
    assert!(e.contains("d.psh:2:1"), "the defi is pointed at: {e}");
    assert!(e.contains("--const c5=… is never read"), "{e}");
    assert!(e.contains("the shader reads c0"), "{e}");
    assert!(e.contains("-D xsiz=… is never used"), "{e}");
    // --quiet drops the warnings, keeps the verdict.
    let o = ps30_in(
        dir.path(),
        &["check", "d.psh", "--int", "i0=3", "--const", "c5=1", "-q"],
    );
    assert!(o.stderr.is_empty(), "{}", err(&o));
    assert_eq!(out(&o).lines().count(), 3, "{}", out(&o));
}

#[test]
fn runs_over_the_limits_exit_1_and_say_so() {
    // The loop listing with the unrolled listing's 125×128 block: 144,774
    // executed per pixel, twice the limit.
    let o = ps30(&[
        "luminance",
        "assets/hdr/forest.exr",
        "--pass1",
        "corrected:loop",
        "--block",
        "125x128",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    let text = out(&o);
    assert!(
        text.contains("144,774 executed per pixel, 65,535 allowed (79,239 over)"),
        "{text}"
    );
    assert!(text.contains("EXCEED the ps_3_0 limits"), "{text}");
    // Without --block the listing runs with the article's 128×56.
    let o = ps30(&[
        "luminance",
        "assets/hdr/forest.exr",
        "--pass1",
        "corrected:loop",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", out(&o));
    assert!(out(&o).contains("blocks 128×56"), "{}", out(&o));
    // run: over the slot limit of a custom shader.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("long.psh"),
        format!(
            "ps_3_0\ndef c0, 1, 1, 1, 1\nmov r0, c0\n{}mov oC0, r0\n",
            "add r0, r0, c0\n".repeat(600)
        ),
    )
    .unwrap();
    let img = bin::repo().join("assets/hdr/sunset.exr");
    let o = ps30_in(
        dir.path(),
        &[
            "run",
            "long.psh",
            "--image",
            img.to_str().unwrap(),
            "--target",
            "2x2",
        ],
    );
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    assert!(
        out(&o).contains("OVER the ps_3_0 limits: 602 slots, 512 allowed"),
        "{}",
        out(&o)
    );
}

#[test]
fn identical_findings_are_one_line_with_their_count() {
    let g = "asm/generated/1280x1024";
    let o = ps30(&[
        "luminance",
        "assets/hdr/courtyard_1280x1024.exr",
        "--pass1",
        &format!("{g}/pass1_unrolled_117x128.psh"),
        "--last-column",
        &format!("{g}/pass1_last_unrolled_110x128.psh"),
        "--pass2",
        &format!("{g}/pass2_11x8.psh"),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    let text = out(&o);
    let warnings: Vec<&str> = text.lines().filter(|l| l.contains("warning:")).collect();
    assert_eq!(warnings.len(), 2, "one per shader, not 117 + 110:\n{text}");
    assert!(
        warnings[0].contains("and 116 more places (117 in all, lines"),
        "{}",
        warnings[0]
    );
    assert!(
        text.contains("blocks 117×128"),
        "the block comes from the header: {text}"
    );
    assert!(text.lines().count() < 15, "{text}");
    let o = ps30(&[
        "luminance",
        "assets/hdr/courtyard_1280x1024.exr",
        "--pass1",
        &format!("{g}/pass1_unrolled_117x128.psh"),
        "--pass2",
        &format!("{g}/pass2_11x8.psh"),
        "--json",
    ]);
    assert!(o.stdout.len() < 40_000, "{} bytes of JSON", o.stdout.len());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let d = &v["passes"][0]["diagnostics"];
    assert_eq!(d.as_array().unwrap().len(), 1, "{d}");
    assert_eq!(d[0]["count"], 117);
    assert_eq!(d[0]["kind"], "lod_far_from_level0");
}

#[test]
fn quiet_is_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(&[
        "unroll",
        "--fit",
        "-o",
        dir.path().join("s").to_str().unwrap(),
        "-q",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(
        o.stdout.is_empty() && o.stderr.is_empty(),
        "{}{}",
        out(&o),
        err(&o)
    );
    assert!(dir.path().join("s/pass2_11x8.psh").exists());
    let o = ps30(&[
        "check",
        "article:loop",
        "--int",
        "i1=128",
        "--int",
        "i2=56",
        "-q",
    ]);
    assert_eq!(
        out(&o),
        "slots              20 / 512      ok (492 to spare), Microsoft's count (1 texture, 19 arithmetic)\nexecuted       64,853 / 65,535   ok (682 to spare)\nverdict: within limits\n"
    );
}

#[test]
fn the_output_format_follows_the_extension() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let img = bin::repo().join("assets/hdr/forest.hdr");
    let run = |name: &str| ps30_in(d, &bin::loop_args(img.to_str().unwrap(), &["-o", name]));
    for (name, magic) in [
        ("a.exr", &[0x76u8, 0x2f, 0x31, 0x01][..]),
        ("a.pfm", b"Pf"),
        ("a.png", &[0x89, b'P', b'N', b'G']),
    ] {
        let o = run(name);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", err(&o));
        assert!(
            std::fs::read(d.join(name)).unwrap().starts_with(magic),
            "{name}"
        );
    }
    // The sums are negative: PNG clamps them (and says how many), RGBE
    // cannot hold them at all.
    assert!(out(&run("b.png")).contains("80 values outside [0, 1] clamped"));
    let o = run("a.hdr");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err(&o).contains("Radiance RGBE holds only finite values ≥ 0"),
        "{}",
        err(&o)
    );
    let o = run("a.jpg");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err(&o).contains("cannot write a `.jpg` file"),
        "{}",
        err(&o)
    );
    assert!(!d.join("a.hdr").exists() && !d.join("a.jpg").exists());
    // Every channel the shader writes is reported; R32F keeps red only.
    assert!(out(&run("c.exr")).contains("oC0.r: min -"));
    // tonemap: .exr holds the linear result, .png the sRGB codes.
    let o = ps30_in(
        d,
        &[
            "tonemap",
            bin::repo().join("assets/hdr/sunset.exr").to_str().unwrap(),
            "-o",
            "t.exr",
            "-q",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(std::fs::read(d.join("t.exr"))
        .unwrap()
        .starts_with(&[0x76, 0x2f, 0x31, 0x01]));
}

#[test]
fn tiny_images_get_blocks_of_their_size_and_unfit_blocks_are_not_agree() {
    let dir = tempfile::tempdir().unwrap();
    let img = dir.path().join("tiny.pfm");
    pfm(&img, 3, 7);
    let img = img.to_str().unwrap();
    let o = ps30(&["luminance", img]);
    assert_eq!(o.status.code(), Some(0), "{}{}", out(&o), err(&o));
    let text = out(&o);
    assert!(text.contains("blocks 3×7 → 1×1"), "{text}");
    assert!(text.contains("planned for the image"), "{text}");
    assert!(text.contains(": agree"), "{text}");
    // The article's 125×128 block on it: the bound is too wide to tell
    // anything, so the run is unfit, exit 1, and never "agree".
    let o = ps30(&["luminance", img, "--pass1", "corrected:unrolled"]);
    assert_eq!(o.status.code(), Some(1), "{}", out(&o));
    let text = out(&o);
    assert!(text.contains("UNFIT for this image"), "{text}");
    assert!(
        !text
            .lines()
            .any(|l| l.starts_with("L̄w") && l.ends_with("agree")),
        "{text}"
    );
    // tonemap uses the planned blocks too.
    let o = ps30(&["tonemap", img, "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["block"], serde_json::json!([3, 7]));
}

#[test]
fn bundled_names_work_everywhere_and_typos_get_a_suggestion() {
    for args in [
        &["check", "article:loop", "--int", "i1=128", "--int", "i2=56"][..],
        &["expand", "article:pass2", "-D", "xsize=11", "-D", "ysize=8"],
        &["shaders", "article:loop"],
    ] {
        let o = ps30(args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", err(&o));
    }
    let o = ps30(&["shaders"]);
    for b in ps30::jobs::bundled::ALL {
        assert!(out(&o).contains(b.name), "{} not listed", b.name);
    }
    let o = ps30(&[
        "luminance",
        "assets/hdr/forest.exr",
        "--pass1",
        "article:loopp",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err(&o).contains("did you mean `article:loop`?"),
        "{}",
        err(&o)
    );
    assert!(!err(&o).contains("os error"), "{}", err(&o));
}

#[test]
fn streams_and_messages() {
    use std::process::{Command, Stdio};
    // A closed stderr (`2>&1 | head` that has gone) is not a panic.
    let mut child = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(["check", "Cargo.toml"])
        .current_dir(bin::repo())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    assert_eq!(child.wait().unwrap().code(), Some(2));
    // A file that is no shader (the manifest: plain text, no `#` at a line's
    // start, which would be a preprocessor directive): one error, not hundreds.
    let o = ps30(&["check", "Cargo.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(err(&o).matches("error[X2001]:").count(), 1, "{}", err(&o));
    assert!(err(&o).contains("missing version line"));
    // No doubled prefixes, no Rust debug output.
    for args in [
        &[
            "profile",
            "article:pass2",
            "--gbuffer",
            "8x8",
            "-D",
            "xsize=1",
            "-D",
            "ysize=1",
        ][..],
        &["profile", "tonemap:reinhard", "--gbuffer", "8x8"],
    ] {
        let e = err(&ps30(args));
        assert!(
            !e.contains("error: error:") && !e.contains("None") && !e.contains("Some("),
            "{e}"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    // A byte-order mark at the start is refused, as Microsoft's assembler
    // refuses it, with what to do.
    std::fs::write(
        dir.path().join("bom.psh"),
        b"\xef\xbb\xbfps_3_0\ndef c0, 1, 1, 1, 1\nmov oC0, c0\n",
    )
    .unwrap();
    let o = ps30_in(dir.path(), &["check", "bom.psh"]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(err(&o).contains("error[X2001]"), "{}", err(&o));
    assert!(err(&o).contains("without a byte-order mark"), "{}", err(&o));
    // A comment in a Windows code page (not UTF-8) is read as Microsoft's
    // assembler reads it.
    std::fs::write(
        dir.path().join("latin1.psh"),
        b"ps_3_0\n// caf\xe9\nmov oC0, c0\n",
    )
    .unwrap();
    let o = ps30_in(dir.path(), &["check", "latin1.psh"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    // The same output-path rules for every command.
    for args in [
        &[
            "expand",
            "article:pass2",
            "-D",
            "xsize=1",
            "-D",
            "ysize=1",
            "-o",
            "/nonexistent/x.psh",
        ][..],
        &[
            "run",
            "corrected:loop",
            "--image",
            "assets/hdr/forest.hdr",
            "--target",
            "1x1",
            "-o",
            "/nonexistent/x.exr",
        ],
        &[
            "tonemap",
            "assets/hdr/sunset.exr",
            "-o",
            "/nonexistent/x.png",
        ],
    ] {
        let o = ps30(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(err(&o).contains("/nonexistent"), "{args:?}: {}", err(&o));
        assert!(!Path::new("/nonexistent").exists());
    }
}

#[test]
fn colour_completions_man_page_and_help() {
    let o = ps30(&[
        "check",
        "article:loop",
        "--int",
        "i1=128",
        "--int",
        "i2=56",
        "--color",
        "always",
    ]);
    assert!(
        out(&o).contains("\x1b[32mwithin limits\x1b[0m"),
        "{}",
        out(&o)
    );
    let o = ps30(&[
        "check",
        "article:loop",
        "--int",
        "i1=128",
        "--int",
        "i2=56",
        "--color",
        "never",
    ]);
    assert!(!out(&o).contains('\x1b'));
    let o = ps30(&["completions", "bash"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        out(&o).contains("luminance") && out(&o).contains("--max-executed"),
        "bash script"
    );
    let o = ps30(&["man"]);
    assert!(
        out(&o).starts_with(".ie") || out(&o).contains(".TH ps30"),
        "{}",
        out(&o)
    );
    let o = ps30(&["man", "luminance"]);
    assert!(out(&o).contains(".TH ps30-luminance"), "{}", out(&o));
    // Every argument of every command has a description in --help.
    let top = out(&ps30(&["--help"]));
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| c != "help")
        .collect();
    assert!(commands.len() >= 12, "{commands:?}");
    for c in &commands {
        let help = out(&ps30(&[c, "--help"]));
        let mut lines = help.lines().peekable();
        let mut in_list = false;
        while let Some(l) = lines.next() {
            let t = l.trim_start();
            if !l.is_empty() && !l.starts_with(' ') {
                // A heading: the argument lists are under these two.
                in_list = l == "Arguments:" || l == "Options:";
                continue;
            }
            let indent = l.len() - t.len();
            let is_arg =
                in_list && (2..=6).contains(&indent) && (t.starts_with('-') || t.starts_with('<'));
            if !is_arg {
                continue;
            }
            // An argument line has its description on the same line (after
            // two spaces) or on the next, indented further.
            let described = t.contains("  ")
                || lines
                    .peek()
                    .is_some_and(|n| n.starts_with("          ") && !n.trim().is_empty());
            assert!(
                described,
                "ps30 {c} --help: `{}` has no description\n{help}",
                t
            );
        }
    }
}

/// An installed binary needs no source tree: a copy of the binary, run in an
/// empty directory, verifies the article (images and shaders compiled in),
/// says that it had no generated shaders to check, and runs a study.
#[test]
fn an_installed_binary_works_anywhere() {
    let install = tempfile::tempdir().unwrap();
    let work = tempfile::tempdir().unwrap();
    let exe = install.path().join("ps30");
    std::fs::copy(env!("CARGO_BIN_EXE_ps30"), &exe).unwrap();
    let run = |args: &[&str]| {
        std::process::Command::new(&exe)
            .args(args)
            .current_dir(work.path())
            .output()
            .unwrap()
    };
    let o = run(&["verify"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", out(&o), err(&o));
    let text = out(&o);
    assert!(text.contains("18 of 18 claims reproduced"), "{text}");
    assert!(
        text.contains("cross-check on assets/hdr/courtyard_1280x1024.exr"),
        "{text}"
    );
    assert!(text.contains("not checked (no asm/generated"), "{text}");
    assert!(work.path().join("reports/README.md").is_file());
    assert!(work.path().join("reports/figures/budgets.png").is_file());
    // No source tree appears: nothing under `asm/` was created.
    assert!(!work.path().join("asm").exists());
    let o = run(&["study", "log-lights", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(work.path().join("reports/log-lights.md").is_file());
}
