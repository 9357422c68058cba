//! Malformed ps_3_0 sources: every one must be rejected, without a panic,
//! with its first error at the right line and column and a message that says
//! what is wrong.
//!
//! Why: the front end is the part of ps30 people meet first, and a wrong
//! column or a vague message costs them time. Each case is one line of a
//! table (source, expected message substring, line, column), so a new rule
//! or a new regression is a one-line addition. The expected positions were
//! worked out by hand from the text (columns count characters from 1), not
//! copied from the program's output.
//!
//! Besides the table: the help texts the user relies on (did-you-mean, `-D`),
//! REPEAT_BLOCK macro bombs (refused quickly and without allocating the
//! expansion), errors inside repetitions (named in a note), files with
//! several errors (all reported), and the ps_3_0 failure vectors of Wine's
//! assembler tests (dlls/d3dcompiler_43/tests/asm.c), copied in as literals.

// Loading results carry the whole source error (diagnostics and file) on
// purpose, as in the library; here they pass through `catch_unwind`.
#![allow(clippy::result_large_err)]

use ps30::core::diag::{Diagnostic, SourceError};
use ps30::core::load::{self, Options};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use crate::common::counting;
use counting::allocated_by;

// ---------------------------------------------------------------------------
// Helpers.

const NAME: &str = "case.psh";

/// Loads `src`, catching panics; `Err(text)` describes what went wrong when
/// the source was not rejected cleanly.
fn reject(src: &str, options: &Options) -> Result<SourceError, String> {
    let result = std::panic::catch_unwind(|| load::load_str(NAME, src, options));
    match result {
        Err(_) => Err(format!("PANIC on {src:?}")),
        Ok(Ok(_)) => Err(format!("ACCEPTED {src:?}")),
        Ok(Err(e)) => Ok(e),
    }
}

fn first_error(e: &SourceError) -> &Diagnostic {
    e.diagnostics
        .errors()
        .next()
        .expect("a rejected source has at least one error")
}

/// Checks one table row; returns a description of every mismatch.
fn check(src: &str, msg: &str, line: usize, col: usize, options: &Options) -> Vec<String> {
    let e = match reject(src, options) {
        Ok(e) => e,
        Err(why) => return vec![why],
    };
    let mut problems = Vec::new();
    let d = first_error(&e);
    let at = e.file.line_col(d.span.start);
    if at != (line, col) {
        problems.push(format!(
            "{src:?}: first error `{}` at {}:{}, expected {line}:{col}",
            d.message, at.0, at.1
        ));
    }
    if !d.message.contains(msg) {
        problems.push(format!(
            "{src:?}: first error is `{}`, expected it to contain `{msg}`",
            d.message
        ));
    }
    let rendered = e.diagnostics.render(&e.file);
    let loc = format!("{NAME}:{line}:{col}");
    if !rendered.contains(&loc) {
        problems.push(format!("{src:?}: rendering lacks `{loc}`:\n{rendered}"));
    }
    if !rendered.contains('^') {
        problems.push(format!("{src:?}: rendering has no caret:\n{rendered}"));
    }
    problems
}

fn run_table(table: &[(&str, &str, usize, usize)]) {
    let mut problems = Vec::new();
    for &(src, msg, line, col) in table {
        problems.extend(check(src, msg, line, col, &Options::default()));
    }
    assert!(
        problems.is_empty(),
        "{} problem(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

fn load_err(src: &str) -> SourceError {
    reject(src, &Options::default()).unwrap_or_else(|why| panic!("{why}"))
}

// ---------------------------------------------------------------------------
// The table: (source, expected substring of the first error, line, column).

use crate::common::malformed_asm;
use malformed_asm::CASES;

#[test]
fn table_of_malformed_sources() {
    assert!(CASES.len() >= 45, "only {} cases", CASES.len());
    run_table(CASES);
}

// ---------------------------------------------------------------------------
// Help texts.

#[test]
fn unknown_instruction_suggests_the_nearest_mnemonic() {
    for (src, want) in [
        ("ps_3_0\nmovv r0, c0", "did you mean `mov`?"),
        ("ps_3_0\nmull r0, r1, r2", "did you mean `mul`?"),
        (
            "ps_3_0\ndcl_2d s0\ntexldll r0, r1, s0",
            "did you mean `texldl`?",
        ),
        ("ps_3_0\nendreep", "did you mean `endrep`?"),
    ] {
        let e = load_err(src);
        let d = first_error(&e);
        assert_eq!(d.help.as_deref(), Some(want), "{src:?}");
        assert!(e.diagnostics.render(&e.file).contains(want));
    }
    // Nothing close: no suggestion, a pointer to the list instead.
    let e = load_err("ps_3_0\nfrobnicate r0");
    let help = first_error(&e).help.clone().unwrap_or_default();
    assert!(!help.contains("did you mean"), "{help}");
}

#[test]
fn foreign_instructions_and_registers_explain_themselves() {
    for (src, want) in [
        ("ps_3_0\nlit r0, c0", "vertex-shader instruction"),
        ("ps_3_0\nslt r0, c0, c1", "vertex-shader instruction"),
        ("ps_3_0\nmov r0, t0", "dcl_texcoord0 v0"),
        ("ps_3_0\nmov r0, a0", "aL"),
        ("ps_3_0\nmov o0, r0", "oC0"),
        (
            "ps_3_0\nloop aL, i0\nmov r0, v[a0 + 1]\nendloop",
            "vertex shaders",
        ),
        ("ps_3_0\nmov r0, r1_bx2", "ps_1_x only"),
    ] {
        let e = load_err(src);
        let help = first_error(&e).help.clone().unwrap_or_default();
        assert!(help.contains(want), "{src:?}: help {help:?} lacks {want:?}");
    }
}

#[test]
fn undefined_repeat_count_tells_how_to_define_it() {
    let e = load_err("ps_3_0\nBEGIN_REPEAT_BLOCK(ysize)\nmov r0, c0\nEND_REPEAT_BLOCK");
    let d = first_error(&e);
    let help = d.help.as_deref().unwrap_or_default();
    assert!(help.contains("-D ysize="), "{help}");
    assert!(e.diagnostics.render(&e.file).contains("-D ysize="));

    // With the name bound, the same text loads.
    let mut options = Options::default();
    options.defines.insert("ysize".to_string(), 3);
    let loaded = load::load_str(
        NAME,
        "ps_3_0\nBEGIN_REPEAT_BLOCK(ysize)\nmov r0, c0\nEND_REPEAT_BLOCK",
        &options,
    )
    .expect("loads with -D ysize=3");
    assert_eq!(loaded.shader.instructions().len(), 3);
}

// ---------------------------------------------------------------------------
// REPEAT_BLOCK bombs and repetitions.

#[test]
fn nested_repeat_bomb_is_refused_quickly_without_allocating_it() {
    let src = "ps_3_0\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               mov r0, c0\n\
               END_REPEAT_BLOCK\n\
               END_REPEAT_BLOCK\n\
               END_REPEAT_BLOCK\n";
    let start = Instant::now();
    let (result, bytes) = allocated_by(|| reject(src, &Options::default()));
    let elapsed = start.elapsed();
    let e = result.unwrap_or_else(|why| panic!("{why}"));
    let d = first_error(&e);
    assert!(
        d.message
            .contains("would produce 1000000001 statements, over the cap of 100000"),
        "{}",
        d.message
    );
    assert_eq!(e.file.line_col(d.span.start), (2, 1));
    assert!(d
        .help
        .as_deref()
        .unwrap_or_default()
        .contains("--max-expanded"));
    // A billion expanded statements would be gigabytes; the refusal costs
    // the parse and a few messages.
    assert!(bytes < 1 << 20, "allocated {bytes} bytes");
    assert!(elapsed < Duration::from_secs(5), "took {elapsed:?}");

    // The count saturates instead of wrapping: 2^32 - 1 cubed is refused too.
    let src = "ps_3_0\n\
               BEGIN_REPEAT_BLOCK(4294967295)\nBEGIN_REPEAT_BLOCK(4294967295)\n\
               BEGIN_REPEAT_BLOCK(4294967295)\nBEGIN_REPEAT_BLOCK(4294967295)\n\
               mov r0, c0\n\
               END_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\n";
    let (result, bytes) = allocated_by(|| reject(src, &Options::default()));
    let e = result.unwrap_or_else(|why| panic!("{why}"));
    assert!(first_error(&e).message.contains("over the cap"));
    assert!(bytes < 1 << 20, "allocated {bytes} bytes");
}

#[test]
fn the_expansion_cap_is_an_option() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(10)\nmov r0, c0\nEND_REPEAT_BLOCK\n";
    let tight = Options {
        max_expanded: 10,
        ..Options::default()
    };
    // 10 movs plus the version line: 11 statements.
    let problems = check(
        src,
        "would produce 11 statements, over the cap of 10",
        2,
        1,
        &tight,
    );
    assert!(problems.is_empty(), "{problems:?}");
    let roomy = Options {
        max_expanded: 11,
        ..Options::default()
    };
    assert!(load::load_str(NAME, src, &roomy).is_ok());
}

#[test]
fn an_error_inside_a_repetition_names_the_repetition() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(3)\nmov r0, v0\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    let errors: Vec<_> = e.diagnostics.errors().collect();
    // The same problem in three repetitions is reported once.
    assert_eq!(errors.len(), 1, "{}", e.diagnostics.render(&e.file));
    let d = errors[0];
    assert_eq!(e.file.line_col(d.span.start), (3, 1));
    assert!(d.message.contains("input v0 is used but never declared"));
    assert!(
        d.notes
            .iter()
            .any(|n| n.contains("in repetition 1 of 3") && n.contains("line 2")),
        "{:?}",
        d.notes
    );
    assert!(e
        .diagnostics
        .render(&e.file)
        .contains("in repetition 1 of 3"));

    // Nested: both levels are named, outermost first.
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(2)\nBEGIN_REPEAT_BLOCK(5)\nmov r0, q0\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    let d = first_error(&e);
    assert_eq!(e.file.line_col(d.span.start), (4, 9));
    assert_eq!(d.notes.len(), 2, "{:?}", d.notes);
    assert!(d.notes[0].contains("repetition 1 of 2") && d.notes[0].contains("line 2"));
    assert!(d.notes[1].contains("repetition 1 of 5") && d.notes[1].contains("line 3"));

    // A count of 0 drops the body: nothing inside is checked or reported.
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(0)\nmov r0, v0\nEND_REPEAT_BLOCK\nmov oC0, c0\n";
    assert!(load::load_str(NAME, src, &Options::default()).is_ok());
}

// ---------------------------------------------------------------------------
// Several errors in one file.

fn error_lines(e: &SourceError) -> Vec<(usize, usize)> {
    e.diagnostics
        .errors()
        .map(|d| e.file.line_col(d.span.start))
        .collect()
}

#[test]
fn every_syntax_error_is_reported() {
    let src = "ps_3_0\n\
               mov r0, r1_bx2\n\
               add r0 r1, r2\n\
               mov r0, c0\n\
               mov r0,\n\
               def c0, 1.2.3, 0, 0, 0\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        [(2, 11), (3, 8), (5, 8), (6, 12)],
        "{}",
        e.diagnostics.render(&e.file)
    );
    let rendered = e.diagnostics.render(&e.file);
    for loc in [
        "case.psh:2:11",
        "case.psh:3:8",
        "case.psh:5:8",
        "case.psh:6:12",
    ] {
        assert!(rendered.contains(loc), "{loc} missing:\n{rendered}");
    }
    assert!(e.to_string().contains("(4 errors in all)"), "{e}");
}

#[test]
fn every_validation_error_is_reported() {
    let src = "ps_3_0\n\
               dcl_2d s0\n\
               mov r0, q0\n\
               mul_x2 r0, r1, r2\n\
               texld r0, r1, s1\n\
               add r0, c0, c1\n\
               rcp r0, r1\n\
               break\n\
               mov r0, c0\n\
               dcl_texcoord0 v0\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        // Line 5 once: the undeclared sampler (r1 read before any
        // instruction writes it is a warning: Microsoft's assembler
        // accepts it).
        [(3, 9), (4, 4), (5, 1), (6, 1), (7, 9), (8, 1), (10, 1)],
        "{}",
        e.diagnostics.render(&e.file)
    );
}

#[test]
fn statement_errors_are_reported_alongside_syntax_errors() {
    // Line 3 does not parse, so the program as a whole cannot be checked,
    // but the lines that did parse still get their own checks.
    let src = "ps_3_0\n\
               mov r0, q0\n\
               add r0 r1, r2\n\
               frc_sat r0, r1\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        [(2, 9), (3, 8), (4, 4)],
        "{}",
        e.diagnostics.render(&e.file)
    );
}

#[test]
fn unknown_input_is_reported_once_per_statement_not_per_repetition() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(50)\nmov r0, q0\nmov r1, v3\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    assert_eq!(error_lines(&e), [(3, 9), (4, 1)]);
}

// ---------------------------------------------------------------------------
// Wine's failure vectors (dlls/d3dcompiler_43/tests/asm.c, LGPL-2.1): every
// ps_3_0 shader there must be rejected. The expected message and position
// are ps30's, for the reason Wine gives.

#[rustfmt::skip]
const WINE_PS30_FAILURES: &[(&str, &str, &str, usize, usize)] = &[
    // (Wine's name and reason, source, expected message, line, column)
    ("failure_test shader 0: instruction modifier not allowed",
     "ps_3_0\ndcl_2d s2\ntexldd_x2 r0, v1, s2, v3, v4\n", "shift modifier `_x2`", 3, 7),
    ("failure_test shader 4: register a0 doesn't exist in pixel shaders",
     "ps_3_0\nmov r0, v[ a0 + 12 ]\n", "`a0` cannot index registers", 2, 10),
    ("failure_test shader 6: aL is a scalar register, no swizzles allowed",
     "ps_3_0\nmov r0, v[ aL.x + 12 ]\n", "aL is a scalar register", 2, 14),
    ("failure_test shader 7: tn doesn't exist in ps_3_0",
     "ps_3_0\ndcl_2d s2\ntexldd r0, t1, s2, v3, v4\n", "unknown register `t1`", 3, 12),
    ("failure_test shader 23: can't declare output registers in a pixel shader",
     "ps_3_0\ndcl_positiont o0\n", "unknown register `o0`", 2, 15),
    ("failure_test shader 25: _x4 instruction modified not allowed in > ps_1_x",
     "ps_3_0\nadd_x4 r0, r0, r1\n", "shift modifier `_x4`", 2, 4),
    ("failure_test shader 27: oC3 is the max in >= ps_2_0",
     "ps_3_0\nadd oC4, r0, r1\n", "register `oC4` is out of range", 2, 5),
    ("failure_test shader 31: s20 register does not exist",
     "ps_3_0\ntexld r0, r1, s20\n", "register `s20` is out of range", 2, 15),
    ("failure_test shader 37: no a0 register in ps_3_0",
     "ps_3_0\nadd r0, v[ a0.x ], r1\n", "`a0` cannot index registers", 2, 10),
    ("failure_test shader 39: invalid modifier for dcl instruction",
     "ps_3_0\ndcl_texcoord0_sat v0\n", "`_sat` is not allowed on a declaration", 2, 14),
    ("failure_test shader 40: shift not allowed",
     "ps_3_0\ndcl_texcoord0_x2 v0\n", "unexpected `_x2` in declaration", 2, 14),
];

/// The ps_2_0 failures of the same list: rejected by ps30 under ps_2_0's
/// rules (co-issue, a literal operand, a shift, aL or r0 as an index, a
/// ps_1_x instruction).
const WINE_PS20_FAILURES: &[&str] = &[
    "ps_2_0\ntexld r0, t0, s0\nadd r0.rgb, r0, r1\n+add r0.a, r0, v1\n",
    "ps_2_0\nmov r2, 1 - r0\n",
    "ps_2_0\nmov r0, r1_x2\n",
    "ps_2_0\nadd r0, v[ aL ], r1\n",
    "ps_2_0\nadd r0, v[ r0 ], r1\n",
    "ps_2_0\ntexm3x3vspec t3, t0\n",
];

#[test]
fn wine_ps_3_0_failure_vectors_are_rejected() {
    let mut problems = Vec::new();
    for &(name, src, msg, line, col) in WINE_PS30_FAILURES {
        for p in check(src, msg, line, col, &Options::default()) {
            problems.push(format!("{name}: {p}"));
        }
    }
    for src in WINE_PS20_FAILURES {
        if let Err(why) = reject(src, &Options::default()) {
            problems.push(why);
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

// ---------------------------------------------------------------------------
// No input makes the front end panic: every prefix of every case, and every
// case with each line dropped in turn, is either accepted or rejected.

#[test]
fn truncated_and_mangled_cases_never_panic() {
    let mut sources: BTreeMap<String, ()> = BTreeMap::new();
    for &(src, ..) in CASES {
        for (i, _) in src.char_indices() {
            sources.insert(src[..i].to_string(), ());
        }
        let lines: Vec<&str> = src.lines().collect();
        for skip in 0..lines.len() {
            let s: Vec<&str> = lines
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != skip)
                .map(|(_, l)| *l)
                .collect();
            sources.insert(s.join("\n"), ());
        }
    }
    let mut panics = Vec::new();
    for src in sources.keys() {
        let r = std::panic::catch_unwind(|| load::load_str(NAME, src, &Options::default()));
        match r {
            Err(_) => panics.push(src.clone()),
            Ok(Err(e)) => {
                // Every rejection has at least one error with a location.
                let d = first_error(&e);
                let _ = e.file.line_col(d.span.start);
                let _ = e.diagnostics.render(&e.file);
            }
            Ok(Ok(_)) => {}
        }
    }
    assert!(panics.is_empty(), "panics on: {panics:#?}");
}
