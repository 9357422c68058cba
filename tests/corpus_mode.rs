//! Corpus mode: `check`, `asm`, `disasm` and `translate` over many files and
//! directories — one line per file in the order found, the summary, the exit
//! code for mixed results, JSON Lines, and `-o DIR` as a mirror of the input
//! tree that never replaces an input.

use crate::common::bin::{ps30, stdout};
use std::fs;
use std::path::Path;

/// A small corpus: two good shaders (one in a subfolder), one over the slot
/// limit with `--max-slots 4`, one refused, and a file that is no shader by
/// its extension.
fn corpus(dir: &Path) {
    let good = "ps_3_0\nmov oC0, c0\n";
    let long = "ps_3_0\nmov r0, c0\nadd r0, r0, c0\nadd r0, r0, c0\nadd r0, r0, c0\nadd r0, r0, c0\nmov oC0, r0\n";
    fs::create_dir_all(dir.join("in/sub")).unwrap();
    fs::write(dir.join("in/a.psh"), good).unwrap();
    fs::write(dir.join("in/sub/b.asm"), good).unwrap();
    fs::write(dir.join("in/c.psh"), long).unwrap();
    fs::write(dir.join("in/d.psh"), "ps_3_0\nmov oC0, q0\n").unwrap();
    fs::write(dir.join("in/notes.txt"), "not a shader").unwrap();
}

#[test]
fn check_streams_lines_and_a_summary() {
    let t = tempfile::tempdir().unwrap();
    corpus(t.path());
    let o = ps30(
        &["check", "in", "--max-slots", "4", "--threads", "2"],
        t.path(),
    );
    let out = stdout(&o);
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("ok      in/a.psh"), "{out}");
    assert!(
        lines[1].starts_with("over    in/c.psh") && lines[1].contains("over slots"),
        "{out}"
    );
    assert!(
        lines[2].starts_with("X2005   in/d.psh  in/d.psh:2:"),
        "{out}"
    );
    assert!(lines[3].starts_with("ok      in/sub/b.asm"), "{out}");
    assert_eq!(lines[4], "4 files: 2 accepted, 1 over a limit, 1 refused");
    assert!(
        out.contains("refused by code: X2005 1\nover the limit of: slots 1\n"),
        "{out}"
    );
    // Mixed results with a refusal: exit 2; without one, an over-limit file: 1.
    assert_eq!(o.status.code(), Some(2));
    let o = ps30(
        &["check", "in/a.psh", "in/c.psh", "--max-slots", "4"],
        t.path(),
    );
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let o = ps30(&["check", "in/a.psh", "in/sub"], t.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
}

#[test]
fn json_lines_end_with_the_summary() {
    let t = tempfile::tempdir().unwrap();
    corpus(t.path());
    let o = ps30(&["check", "in", "--json"], t.path());
    let out = stdout(&o);
    let values: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("one JSON value per line"))
        .collect();
    assert_eq!(values.len(), 5);
    assert_eq!(values[0]["status"], "accepted");
    assert_eq!(values[0]["slots"], 1);
    assert_eq!(
        values[0]["executed"],
        serde_json::json!({"min": 1, "max": 1})
    );
    assert_eq!(values[2]["code"], "X2005");
    let s = &values[4]["summary"];
    assert_eq!(
        (s["files"].as_u64(), s["refused"].as_u64()),
        (Some(4), Some(1))
    );
    assert_eq!(s["refused_by_code"]["X2005"], 1);
}

#[test]
fn asm_mirrors_the_tree_and_disasm_reads_it_back() {
    let t = tempfile::tempdir().unwrap();
    corpus(t.path());
    let o = ps30(&["asm", "in", "-o", "out"], t.path());
    assert_eq!(o.status.code(), Some(2), "d.psh is refused");
    let one = fs::read(t.path().join("out/a.psh.fxo")).unwrap();
    assert_eq!(one, fs::read(t.path().join("out/sub/b.asm.fxo")).unwrap());
    assert!(!t.path().join("out/d.psh.fxo").exists());
    // The outputs are shaders again: listed, and the output folder inside
    // the input is never read back as input.
    let o = ps30(&["disasm", "out", "-o", "out/listings"], t.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("3 files: 3 accepted"), "{}", stdout(&o));
    let listing = fs::read_to_string(t.path().join("out/listings/sub/b.asm.fxo.dis")).unwrap();
    assert!(listing.contains("mov oC0, c0"), "{listing}");
    let o = ps30(
        &["translate", "--to", "wgsl", "in/a.psh", "in/sub", "-o", "w"],
        t.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(t.path().join("w/b.asm.wgsl").is_file());
}
