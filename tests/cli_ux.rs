//! What every command offers a person: `--help` with examples, `--json`,
//! `--quiet`, and no colour codes or progress bars when the output is not a
//! terminal.

use std::path::Path;

use crate::common::bin;
use bin::in_repo as ps30;

const COMMANDS: [&str; 10] = [
    "check",
    "expand",
    "asm",
    "disasm",
    "run",
    "luminance",
    "tonemap",
    "render",
    "study",
    "verify",
];

#[test]
fn every_command_has_help_with_an_example() {
    for c in COMMANDS {
        let o = ps30(&[c, "--help"]);
        assert_eq!(o.status.code(), Some(0), "{c}");
        let help = String::from_utf8(o.stdout).unwrap();
        assert!(
            help.contains("Example"),
            "{c} --help has no example:\n{help}"
        );
        assert!(help.contains(&format!("ps30 {c} ")), "{c}: {help}");
        assert!(help.contains("--json"), "{c} has no --json");
        assert!(help.contains("--quiet"), "{c} has no --quiet");
    }
}

#[test]
fn expand_json_gives_the_source_and_slots() {
    let o = ps30(&[
        "expand",
        "asm/article/lum_pass2.psh",
        "-D",
        "xsize=11",
        "-D",
        "ysize=8",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["shader"], "asm/article/lum_pass2.psh");
    assert_eq!(v["slots"], 190);
    assert!(v["output"].is_null());
    assert_eq!(v["assembly"].as_str().unwrap().matches("texld").count(), 88);
}

#[test]
fn quiet_keeps_results_and_drops_notes() {
    // check: the result stays; the warning that defi overrides --int goes.
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("d.psh");
    std::fs::write(
        &f,
        "ps_3_0\ndefi i0, 4, 0, 0, 0\nmov r0, c0\nrep i0\nadd r0, r0, r0\nendrep\nmov oC0, r0\n",
    )
    .unwrap();
    let f = f.to_str().unwrap();
    let loud = ps30(&["check", f, "--int", "i0=3"]);
    assert!(String::from_utf8_lossy(&loud.stderr).contains("--int i0=… has no effect"));
    let quiet = ps30(&["check", f, "--int", "i0=3", "--quiet"]);
    assert_eq!(quiet.status.code(), Some(0));
    assert!(quiet.stderr.is_empty());
    assert!(String::from_utf8_lossy(&quiet.stdout).contains("verdict: within limits"));
    // verify: nothing at all when everything agrees.
    let o = ps30(&[
        "verify",
        "--reports",
        dir.path().join("r").to_str().unwrap(),
        "-q",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
    assert!(dir.path().join("r/README.md").exists());
}

#[test]
fn no_colour_or_progress_codes_outside_a_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(&["verify", "--reports", dir.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("tone mapping"), "{out}");
    assert!(!out.contains('\x1b'));
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(Path::new(&dir.path().join("figures/budgets.png")).exists());
}
