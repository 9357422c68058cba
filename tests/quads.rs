//! 2×2 quads, gradients, mip selection and what divergence costs: the
//! semantics of the ps_3_0 instructions that depend on them, through the
//! public API (front end → validator → emulator), against values worked out
//! by hand in the comments.

use ps30::front::{load_str, Loaded, Options};

fn load(body: &str) -> Loaded {
    let src = format!("ps_3_0\n{body}\n");
    load_str("t.psh", &src, &Options::default())
        .unwrap_or_else(|e| panic!("{}", e.diagnostics.render(&e.file)))
}

// ----- static diagnostics -----------------------------------------------------

fn warned_lines(body: &str) -> Vec<usize> {
    let l = load(body);
    l.warnings
        .items
        .iter()
        .map(|w| l.file.line_of(w.span.start) - 1)
        .collect()
}

#[test]
fn gradients_under_dynamic_flow_control_are_warned_about_statically() {
    let head = "dcl_texcoord0 v0\ndcl_2d s0\ndef c0, 0.5, 0, 0, 0\ndefi i0, 4, 0, 0, 0\ndefb b0, true\nmov r0, v0\n";
    // Lines below are numbered from 1 after the six header lines.
    let at = |body: &str| -> Vec<usize> {
        warned_lines(&format!("{head}{body}"))
            .into_iter()
            .map(|l| l - 6)
            .collect()
    };
    // Predicated.
    assert_eq!(
        at("setp_gt p0, v0, c0\n(p0) texld r1, r0, s0\nmov oC0, r1"),
        [2]
    );
    // Inside if_comp and if p0 (both sides), not inside if b#.
    assert_eq!(
        at("if_gt v0.x, c0.x\ntexld r1, r0, s0\nelse\ndsy r1, r0\nendif\nif b0\ntexldb r2, r0, s0\nendif\nmov oC0, r1"),
        [2, 4]
    );
    // A loop that pixels leave at different iterations: its whole body.
    assert_eq!(
        at("rep i0\ntexldp r1, r0, s0\nbreak_gt r1.x, c0.x\nendrep\nrep i0\ntexld r2, r0, s0\nif b0\nbreak\nendif\nendrep\nmov oC0, r1"),
        [2]
    );
    // A plain break under a dynamic if makes the loop dynamic too.
    assert_eq!(
        at("rep i0\ndsx r1, r0\nif_lt r0.x, c0.x\nbreak\nendif\nendrep\nmov oC0, r1"),
        [2]
    );
    // In a subroutine called by callnz p0, and in what it calls.
    assert_eq!(
        at("setp_gt p0, v0, c0\ncallnz l1, p0.x\ncall l2\nmov oC0, r0\nret\nlabel l1\ntexld r2, r0, s0\ncall l3\nret\nlabel l2\ntexld r2, r0, s0\nret\nlabel l3\ndsx r3, r0\nret"),
        [7, 14]
    );
    // Legal everywhere: texldl, texldd, input coordinates, dsx of an input.
    assert_eq!(
        at("if_gt v0.x, c0.x\ntexldl r1, r0, s0\ntexldd r2, r0, s0, c0, c0\ntexld r3, v0, s0\ndsx r4, v0\nendif\nmov oC0, r1"),
        Vec::<usize>::new()
    );
}

#[test]
fn the_static_warning_names_the_branch_and_the_fix() {
    let l = load(
        "dcl_texcoord0 v0
dcl_2d s0
def c0, 0.5, 0, 0, 0
mov r0, v0
if_lt v0.x, c0.x
  texld r1, r0, s0
endif
mov oC0, r1",
    );
    let text = l.warnings.render(&l.file);
    assert!(
        text.contains("warning: `texld` with a temporary coordinate under dynamic flow control")
    );
    assert!(text.contains("t.psh:7:3"), "{text}");
    assert!(text.contains("the pixels of a quad can go different ways here"));
    assert!(text.contains("texldl"));
    assert_eq!(l.warnings.errors().count(), 0);
}
