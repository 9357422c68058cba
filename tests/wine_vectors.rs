//! Wine's assembler test vectors (dlls/d3dcompiler_43/tests/asm.c, LGPL-2.1):
//! shaders Microsoft's assembler accepts, with the exact token stream it
//! produces, and shaders it refuses.
//!
//! Why: they are the closest thing to an independent oracle for both the
//! syntax ps30 reads and the bytecode it writes. Every ps_3_0 vector goes
//! through the product's own writer (`core::bytecode::write`) and must come
//! out as Microsoft's tokens, byte for byte; Microsoft's tokens go through
//! the reader and the listing it prints and must come back the same. Wine
//! runs these vectors with validation off, so some are not valid programs
//! (`mov r0, vFace`, a texldd whose sampler operand is `r2`): those are
//! written and read byte for byte all the same, and refused by validation
//! for the reason given — from the text and from the tokens alike; where a
//! declaration or a first write of a temporary is all that is missing, the
//! repaired text must encode to the same instructions after its additions. The ps_2_0 / ps_2_x vectors are written and read
//! byte for byte under their own version line. Wine's failure vectors must all be refused by `ps30 asm`'s
//! path (load, validate, write).
//!
//! The texts and tokens are copied in as literals.

use ps30::core::bytecode::{listing, read, write};
use ps30::core::front::{parse, print::write_program, repeat};
use ps30::core::load::{self, Options};

type Vector = (&'static str, &'static str, &'static [u32]);

// ---------------------------------------------------------------------------
// The vectors.

/// ps_3_0 vectors that are valid ps_3_0 programs.
#[rustfmt::skip]
const PS30_VALID: &[Vector] = &[
    ("ps_3_0 shader 0", "ps_3_0\nmov r0, c0\n", &[0xffff0300, 0x02000001, 0x800f0000, 0xa0e40000, 0x0000ffff]),
    ("ps_3_0 shader 1", "ps_3_0\ndcl_normal5 v0\n", &[0xffff0300, 0x0200001f, 0x80050003, 0x900f0000, 0x0000ffff]),
    ("ps_3_0 shader 12", "ps_3_0\ndcl_texcoord0_centroid v0\n", &[0xffff0300, 0x0200001f, 0x80000005, 0x904f0000, 0x0000ffff]),
];

/// A vector that is not a valid program, why, and (when only a declaration
/// or a first write is missing) the text with it added.
struct Rejected {
    vector: Vector,
    reason: &'static str,
    /// Substring of the first error ps30 reports.
    message: &'static str,
    repaired: Option<&'static str>,
}

#[rustfmt::skip]
const PS30_INVALID: &[Rejected] = &[
    // Wine's vectors hold these tokens, but d3dcompiler_47's D3DAssemble
    // refuses both (X5969, "dcl for s register does not support any
    // modifiers"), and the tools win.
    Rejected {
        vector: ("ps_3_0 shader 13", "ps_3_0\ndcl_2d_centroid s0\n", &[0xffff0300, 0x0200001f, 0x90000000, 0xa04f0800, 0x0000ffff]),
        reason: "Microsoft's assembler refuses modifiers on sampler declarations (X5969)",
        message: "a sampler declaration takes no modifier",
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 14", "ps.3.0\ndcl_2d_pp s0\n", &[0xffff0300, 0x0200001f, 0x90000000, 0xa02f0800, 0x0000ffff]),
        reason: "Microsoft's assembler refuses modifiers on sampler declarations (X5969)",
        message: "a sampler declaration takes no modifier",
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 2", "ps_3_0\nmov r0, vPos\n", &[0xffff0300, 0x02000001, 0x800f0000, 0x90e41000, 0x0000ffff]),
        reason: "vPos must be declared before use (Microsoft's ps_3_0 register page)",
        message: "input vPos is used but never declared",
        // Declared, the read of .zw is still refused (X6063): no repair
        // keeps Wine's instruction.
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 3", "ps_3_0\nmov r0, vFace\n", &[0xffff0300, 0x02000001, 0x800f0000, 0x90e41001, 0x0000ffff]),
        reason: "vFace is used without a declaration",
        message: "input vFace is used but never declared",
        // Declared, vFace read as a value is still refused (X5692).
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 4", "ps_3_0\nmov r0, v[ aL + 12 ]\n", &[0xffff0300, 0x03000001, 0x800f0000, 0x90e4200c, 0xf0e40800, 0x0000ffff]),
        reason: "aL is read outside a loop (v12 as a base is Microsoft's `v12[aL]`)",
        message: "v[aL + n] used outside a loop",
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 5", "ps_3_0\nloop aL, i0\nmov r0, v0[aL]\nendloop\n", &[0xffff0300, 0x0200001b, 0xf0e40800, 0xf0e40000, 0x03000001, 0x800f0000, 0x90e42000, 0xf0e40800, 0x0000001d, 0x0000ffff]),
        reason: "v0[aL] reads v0 (aL = 0 when i0 is not defined), which is not declared",
        message: "input v0 is used but never declared",
        repaired: Some("ps_3_0\ndcl_texcoord0 v0\nloop aL, i0\nmov r0, v0[aL]\nendloop\n"),
    },
    Rejected {
        vector: ("ps_3_0 shader 6", "ps_3_0\ntexldl r0, v0, s0\n", &[0xffff0300, 0x0300005f, 0x800f0000, 0x90e40000, 0xa0e40800, 0x0000ffff]),
        reason: "v0 and s0 are used without declarations",
        message: "input v0 is used but never declared",
        repaired: Some("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ntexldl r0, v0, s0\n"),
    },
    Rejected {
        vector: ("ps_3_0 shader 7", "ps_3_0\nadd_pp r0, r0, r1\n", &[0xffff0300, 0x03000002, 0x802f0000, 0x80e40000, 0x80e40001, 0x0000ffff]),
        reason: "r0 and r1 are read before anything writes them (Microsoft's temporary-register page)",
        message: "r0 is read, but no earlier instruction writes it",
        repaired: Some("ps_3_0\nmov r0, c0\nmov r1, c0\nadd_pp r0, r0, r1\n"),
    },
    Rejected {
        vector: ("ps_3_0 shader 8", "ps_3_0\ndsx_sat r0, r1\n", &[0xffff0300, 0x0200005b, 0x801f0000, 0x80e40001, 0x0000ffff]),
        reason: "r1 is read before anything writes it",
        message: "r1 is read, but no earlier instruction writes it",
        repaired: Some("ps_3_0\nmov r1, c0\ndsx_sat r0, r1\n"),
    },
    Rejected {
        vector: ("ps_3_0 shader 9", "ps_3_0\ntexldd_pp r0, r1, r2, r3, r4\n", &[0xffff0300, 0x0500005d, 0x802f0000, 0x80e40001, 0x80e40002, 0x80e40003, 0x80e40004, 0x0000ffff]),
        reason: "the sampler operand of texldd is the temporary r2",
        message: "operand 3 of `texldd` must be a sampler s#",
        repaired: None,
    },
    Rejected {
        vector: ("ps_3_0 shader 10", "ps_3_0\ntexkill v0\n", &[0xffff0300, 0x01000041, 0x900f0000, 0x0000ffff]),
        reason: "v0 is used without a declaration",
        message: "input v0 is used but never declared",
        repaired: Some("ps_3_0\ndcl_texcoord0 v0\ntexkill v0\n"),
    },
    Rejected {
        vector: ("ps_3_0 shader 11", "ps_3_0\nadd oC3, r0, r1\n", &[0xffff0300, 0x03000002, 0x800f0803, 0x80e40000, 0x80e40001, 0x0000ffff]),
        reason: "r0 and r1 are read before anything writes them",
        message: "r0 is read, but no earlier instruction writes it",
        repaired: Some("ps_3_0\nmov r0, c0\nmov r1, c0\nadd oC3, r0, r1\n"),
    },
];

/// Wine's ps_2_0 and ps_2_x vectors: name, text, tokens.
#[rustfmt::skip]
const OLDER: &[Vector] = &[
    ("ps_2_0 shader 0", "ps_2_0\ndcl_2d s0\n", &[0xffff0200, 0x0200001f, 0x90000000, 0xa00f0800, 0x0000ffff]),
    ("ps_2_0 shader 1", "ps_2_0\ndcl_cube s0\n", &[0xffff0200, 0x0200001f, 0x98000000, 0xa00f0800, 0x0000ffff]),
    ("ps_2_0 shader 2", "ps_2_0\ndcl_volume s0\n", &[0xffff0200, 0x0200001f, 0xa0000000, 0xa00f0800, 0x0000ffff]),
    ("ps_2_0 shader 3", "ps_2_0\ndcl_volume s0\ndcl_cube s1\ndcl_2d s2\n", &[0xffff0200, 0x0200001f, 0xa0000000, 0xa00f0800, 0x0200001f, 0x98000000, 0xa00f0801, 0x0200001f, 0x90000000, 0xa00f0802, 0x0000ffff]),
    ("ps_2_0 shader 4", "ps_2_0\nmov r0, t0\n", &[0xffff0200, 0x02000001, 0x800f0000, 0xb0e40000, 0x0000ffff]),
    ("ps_2_0 shader 5", "ps_2_0\ndcl_2d s2\ntexld r0, t1, s2\n", &[0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03000042, 0x800f0000, 0xb0e40001, 0xa0e40802, 0x0000ffff]),
    ("ps_2_0 shader 6", "ps_2_0\ntexkill t0\n", &[0xffff0200, 0x01000041, 0xb00f0000, 0x0000ffff]),
    ("ps_2_0 shader 7", "ps_2_0\nmov oC0, c0\nmov oC1, c1\n", &[0xffff0200, 0x02000001, 0x800f0800, 0xa0e40000, 0x02000001, 0x800f0801, 0xa0e40001, 0x0000ffff]),
    ("ps_2_0 shader 8", "ps_2_0\nmov oDepth, c0.x\n", &[0xffff0200, 0x02000001, 0x900f0800, 0xa0000000, 0x0000ffff]),
    ("ps_2_0 shader 9", "ps_2_0\ndcl_2d s2\ntexldp r0, t1, s2\n", &[0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03010042, 0x800f0000, 0xb0e40001, 0xa0e40802, 0x0000ffff]),
    ("ps_2_0 shader 10", "ps.2.0\ndcl_2d s2\ntexldb r0, t1, s2\n", &[0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03020042, 0x800f0000, 0xb0e40001, 0xa0e40802, 0x0000ffff]),
    ("ps_2_x shader 0", "ps_2_x\ndefb b0, true\ndefb b1, false\n", &[0xffff0201, 0x0200002f, 0xe00f0800, 0x00000001, 0x0200002f, 0xe00f0801, 0x00000000, 0x0000ffff]),
    ("ps_2_x shader 1", "ps_2_x\ndefi i0, -1, 1, 10, 0\ndefi i1, 0, 40, 30, 10\n", &[0xffff0201, 0x05000030, 0xf00f0000, 0xffffffff, 0x00000001, 0x0000000a, 0x00000000, 0x05000030, 0xf00f0001, 0x00000000, 0x00000028, 0x0000001e, 0x0000000a, 0x0000ffff]),
    ("ps_2_x shader 2", "ps_2_x\ndsx r0, r0\n", &[0xffff0201, 0x0200005b, 0x800f0000, 0x80e40000, 0x0000ffff]),
    ("ps_2_x shader 3", "ps_2_x\ndsy r0, r0\n", &[0xffff0201, 0x0200005c, 0x800f0000, 0x80e40000, 0x0000ffff]),
    ("ps_2_x shader 4", "ps_2_x\ndcl_2d s2\ntexldd r0, v1, s2, r3, r4\n", &[0xffff0201, 0x0200001f, 0x90000000, 0xa00f0802, 0x0500005d, 0x800f0000, 0x90e40001, 0xa0e40802, 0x80e40003, 0x80e40004, 0x0000ffff]),
    ("ps_2_x shader 5", "ps_2_x\ncall l0\nret\nlabel l0\nret\n", &[0xffff0201, 0x01000019, 0xa0e41000, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c, 0x0000ffff]),
    ("ps_2_x shader 6", "ps_2_x\ncallnz l0, b0\nret\nlabel l0\nret\n", &[0xffff0201, 0x0200001a, 0xa0e41000, 0xe0e40800, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c, 0x0000ffff]),
    ("ps_2_x shader 7", "ps_2_x\ncallnz l0, !b0\nret\nlabel l0\nret\n", &[0xffff0201, 0x0200001a, 0xa0e41000, 0xede40800, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c, 0x0000ffff]),
    ("ps_2_x shader 8", "ps_2_x\nif !b0\nelse\nendif\n", &[0xffff0201, 0x01000028, 0xede40800, 0x0000002a, 0x0000002b, 0x0000ffff]),
    ("ps_2_x shader 9", "ps_2_x\nrep i0\nbreak\nendrep\n", &[0xffff0201, 0x01000026, 0xf0e40000, 0x0000002c, 0x00000027, 0x0000ffff]),
    ("ps_2_x shader 10", "ps_2_x\nif_ge r0, r1\nendif\n", &[0xffff0201, 0x02030029, 0x80e40000, 0x80e40001, 0x0000002b, 0x0000ffff]),
    ("ps_2_x shader 11", "ps_2_x\nrep i0\nbreak_ne r0, r1\nendrep", &[0xffff0201, 0x01000026, 0xf0e40000, 0x0205002d, 0x80e40000, 0x80e40001, 0x00000027, 0x0000ffff]),
    ("ps_2_x shader 12", "ps_2_x\nsetp_gt p0, r0, r1\n(!p0) add r2, r2, r3\n", &[0xffff0201, 0x0301005e, 0xb00f1000, 0x80e40000, 0x80e40001, 0x14000002, 0x800f0002, 0xbde41000, 0x80e40002, 0x80e40003, 0x0000ffff]),
    ("ps_2_x shader 13", "ps_2_x\nif p0.x\nelse\nendif\n", &[0xffff0201, 0x01000028, 0xb0001000, 0x0000002a, 0x0000002b, 0x0000ffff]),
    ("ps_2_x shader 14", "ps_2_x\ncallnz l0, !p0.z\nret\nlabel l0\nret\n", &[0xffff0201, 0x0200001a, 0xa0e41000, 0xbdaa1000, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c, 0x0000ffff]),
    ("ps_2_x shader 15", "ps_2_x\nrep i0\nbreakp p0.w\nendrep\n", &[0xffff0201, 0x01000026, 0xf0e40000, 0x01000060, 0xb0ff1000, 0x00000027, 0x0000ffff]),
    ("ps_2_x shader 16", "ps.2.x\ncall l2047\nret\nlabel l2047\nret\n", &[0xffff0201, 0x01000019, 0xa0e417ff, 0x0000001c, 0x0100001e, 0xa0e417ff, 0x0000001c, 0x0000ffff]),
];

/// The ps_3_0 vectors of Wine's failure tests (reason in the name), and
/// its ps_2_0 ones: `ps30 asm` refuses all of them.
#[rustfmt::skip]
const FAILURES: &[(&str, &str)] = &[
    ("0: instruction modifier not allowed", "ps_3_0\ndcl_2d s2\ntexldd_x2 r0, v1, s2, v3, v4\n"),
    ("2: coissue not supported in pixel shader version >= 2.0", "ps_2_0\ntexld r0, t0, s0\nadd r0.rgb, r0, r1\n+add r0.a, r0, v1\n"),
    ("4: register a0 doesn't exist in pixel shaders", "ps_3_0\nmov r0, v[ a0 + 12 ]\n"),
    ("6: aL is a scalar register, no swizzles allowed", "ps_3_0\nmov r0, v[ aL.x + 12 ]\n"),
    ("7: tn doesn't exist in ps_3_0", "ps_3_0\ndcl_2d s2\ntexldd r0, t1, s2, v3, v4\n"),
    ("11: complement modifier not allowed in >= PS 2", "ps_2_0\nmov r2, 1 - r0\n"),
    ("17: _x2 modifier not available in >= PS 2.0", "ps_2_0\nmov r0, r1_x2\n"),
    ("23: can't declare output registers in a pixel shader", "ps_3_0\ndcl_positiont o0\n"),
    ("25: _x4 instruction modified not allowed in > ps_1_x", "ps_3_0\nadd_x4 r0, r0, r1\n"),
    ("27: oC3 is the max in >= ps_2_0", "ps_3_0\nadd oC4, r0, r1\n"),
    ("31: s20 register does not exist", "ps_3_0\ntexld r0, r1, s20\n"),
    ("35: no aL register in ps_2_0", "ps_2_0\nadd r0, v[ aL ], r1\n"),
    ("36: no relative addressing in ps_2_0", "ps_2_0\nadd r0, v[ r0 ], r1\n"),
    ("37: no a0 register in ps_3_0", "ps_3_0\nadd r0, v[ a0.x ], r1\n"),
    ("39: invalid modifier for dcl instruction", "ps_3_0\ndcl_texcoord0_sat v0\n"),
    ("40: shift not allowed", "ps_3_0\ndcl_texcoord0_x2 v0\n"),
    ("43: (ps_1_x instruction)", "ps_2_0\ntexm3x3vspec t3, t0\n"),
];

// ---------------------------------------------------------------------------
// The writer and the reader, as the product runs them.

/// Text → tokens through the product's writer alone (parse, expand,
/// encode; no validation, as Wine runs Microsoft's assembler).
fn write_text(text: &str) -> Result<Vec<u32>, String> {
    let (stmts, diags) = parse::parse(text);
    if let Some(d) = diags.errors().next() {
        return Err(d.message.clone());
    }
    let expanded = repeat::expand(&stmts, &Default::default(), 1000)
        .map_err(|d| d.items[0].message.clone())?;
    write::assemble(&stmts, &expanded)
        .map(|m| write::encode(&m))
        .map_err(|d| d.items[0].message.clone())
}

/// Tokens → module → tokens, and → listing → tokens: the reader, the
/// disassembler and the writer. Returns the listing.
fn read_back(name: &str, tokens: &[u32], problems: &mut Vec<String>) -> Option<String> {
    let bytes = write::to_bytes(tokens);
    let module = match read::read(&bytes, 1000) {
        Ok(m) => m,
        Err(e) => {
            problems.push(format!("{name}: the reader refused Wine's tokens: {e}"));
            return None;
        }
    };
    let direct = write::encode(&module);
    if direct != tokens {
        problems.push(format!(
            "{name}: read + encode:\n  Wine: {}\n  ps30: {}",
            hex(tokens),
            hex(&direct)
        ));
    }
    let l = listing::listing(&module);
    match write_text(&l.text) {
        Ok(again) if again == tokens => {}
        Ok(again) => problems.push(format!(
            "{name}: listing + writer:\n  Wine: {}\n  ps30: {}\nlisting:\n{}",
            hex(tokens),
            hex(&again),
            l.text
        )),
        Err(e) => problems.push(format!(
            "{name}: its listing does not write: {e}\n{}",
            l.text
        )),
    }
    Some(l.text)
}

/// The instruction tokens of a stream: without version, end, dcl and def*.
fn instruction_tokens(tokens: &[u32]) -> Vec<u32> {
    let body = &tokens[1..tokens.len() - 1];
    let mut out = Vec::new();
    let mut i = 0;
    while i < body.len() {
        let len = ((body[i] >> 24) & 0xf) as usize;
        let op = body[i] & 0xffff;
        if !matches!(op, 0x1f | 0x2f | 0x30 | 0x51) {
            out.extend_from_slice(&body[i..=i + len]);
        }
        i += len + 1;
    }
    out
}

fn hex(tokens: &[u32]) -> String {
    let t: Vec<String> = tokens.iter().map(|t| format!("{t:08x}")).collect();
    t.join(" ")
}

/// The first error of loading bytes through the path every command takes.
/// `--strict`: the documented rules Microsoft's assembler lets through
/// (reads of unwritten temporaries, undeclared inputs read through aL) are
/// errors, as the vectors' reasons expect.
fn strict() -> Options {
    Options {
        strict: true,
        ..Options::default()
    }
}

fn load_bytes(name: &str, tokens: &[u32]) -> Result<load::Loaded, String> {
    let file =
        load::source_file(name, write::to_bytes(tokens), &strict()).map_err(|e| e.to_string())?;
    load::load(file, &strict()).map_err(|e| {
        let d = e.diagnostics.errors().next().expect("an error");
        format!("{}\n{}", d.message, d.render(&e.file))
    })
}

// ---------------------------------------------------------------------------
// The tests.

#[test]
fn every_ps_3_0_vector_is_written_and_read_byte_for_byte() {
    let mut problems = Vec::new();
    let all = PS30_VALID
        .iter()
        .chain(PS30_INVALID.iter().map(|r| &r.vector));
    for &(name, text, tokens) in all {
        match write_text(text) {
            Ok(ours) if ours == tokens => {}
            Ok(ours) => problems.push(format!(
                "{name}: writer:\n  Wine: {}\n  ps30: {}",
                hex(tokens),
                hex(&ours)
            )),
            Err(e) => problems.push(format!("{name}: the writer refused the text: {e}")),
        }
        read_back(name, tokens, &mut problems);
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn valid_vectors_assemble_and_their_tokens_load_to_the_same_program() {
    let mut problems = Vec::new();
    for &(name, text, tokens) in PS30_VALID {
        let file = load::source_file(name, text.as_bytes().to_vec(), &Options::default()).unwrap();
        match load::assemble(file, &Options::default()) {
            Ok((_, ours)) if ours == tokens => {}
            Ok((_, ours)) => problems.push(format!(
                "{name}: asm:\n  Wine: {}\n  ps30: {}",
                hex(tokens),
                hex(&ours)
            )),
            Err(e) => problems.push(format!(
                "{name}: asm refused it:\n{}",
                e.diagnostics.render(&e.file)
            )),
        }
        let from_text = load::load_str(name, text, &Options::default())
            .map(|l| write_program(l.shader.program()))
            .map_err(|e| e.to_string());
        let from_tokens = load_bytes(name, tokens).map(|l| write_program(l.shader.program()));
        if from_text != from_tokens {
            problems.push(format!(
                "{name}: text and tokens load differently:\n{from_text:?}\n{from_tokens:?}"
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn invalid_vectors_are_refused_for_their_reason_as_text_and_as_tokens() {
    let mut problems = Vec::new();
    for r in PS30_INVALID {
        let (name, text, tokens) = r.vector;
        let from_text = load::load_str(name, text, &strict())
            .map(|_| ())
            .map_err(|e| {
                e.diagnostics
                    .errors()
                    .next()
                    .expect("an error")
                    .message
                    .clone()
            });
        match from_text {
            Ok(()) => problems.push(format!("{name} accepted; expected: {}", r.reason)),
            Err(m) if !m.contains(r.message) => problems.push(format!(
                "{name}: first error `{m}`, expected `{}` ({})",
                r.message, r.reason
            )),
            Err(_) => {}
        }
        // The same program as tokens: the same verdict, placed by token.
        match load_bytes(name, tokens) {
            Ok(_) => problems.push(format!("{name}: its tokens were accepted")),
            Err(m)
                if !m.contains(r.message) || !m.contains("token ") || !m.contains("(byte 0x") =>
            {
                problems.push(format!("{name}: from tokens: {m}"))
            }
            Err(_) => {}
        }
        if let Some(repaired) = r.repaired {
            match write_text(repaired) {
                // The repair adds declarations, or writes before Wine's
                // instructions: those come out unchanged at the end.
                Ok(ours) if instruction_tokens(&ours).ends_with(&instruction_tokens(tokens)) => {}
                other => {
                    problems.push(format!("{name} repaired: {other:?}, Wine: {}", hex(tokens)))
                }
            }
            if let Err(e) = load::load_str(name, repaired, &Options::default()) {
                problems.push(format!(
                    "{name} repaired does not load:\n{}",
                    e.diagnostics.render(&e.file)
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn vface_is_read_only_as_a_condition() {
    // Microsoft's assembler refuses vFace read as a value (X5692) and
    // accepts it as the operand of setp_comp, if_comp, break_comp and as
    // cmp's condition (what Wine's visual.c vface_register_test draws).
    let e = load::load_str(
        "v.psh",
        "ps_3_0\ndcl vFace\nmov r0, vFace\n",
        &Options::default(),
    )
    .expect_err("vFace as a value");
    assert_eq!(e.diagnostics.errors().next().unwrap().code, Some("X5692"));
    for src in [
        "ps_3_0\ndcl vFace\nsetp_lt p0.x, vFace, c0.x\n",
        "ps_3_0\ndcl vFace\nmov r1, c1\ncmp oC0, vFace, c0, r1\n",
    ] {
        let loaded = load::load_str("v.psh", src, &Options::default()).expect(src);
        assert_eq!(loaded.warnings.warnings().count(), 0, "{src}");
    }
}

#[test]
fn older_vectors_are_written_and_read_byte_for_byte_under_their_own_version() {
    let mut problems = Vec::new();
    for &(name, text, tokens) in OLDER {
        // The writer alone, as Wine runs Microsoft's assembler.
        match write_text(text) {
            Ok(ours) if ours == tokens => {}
            other => problems.push(format!(
                "{name} through the writer: {other:?}, Wine: {}",
                hex(tokens)
            )),
        }
        // The reader, and the writer on what it read.
        let bytes = write::to_bytes(tokens);
        match read::read(&bytes, 1000) {
            Ok(m) if write::encode(&m) == tokens => {}
            Ok(m) => problems.push(format!(
                "{name}: read and written back as {}",
                hex(&write::encode(&m))
            )),
            Err(e) => problems.push(format!("{name}: not read: {e}")),
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn failure_vectors_are_refused_by_asm() {
    let mut problems = Vec::new();
    for (name, text) in FAILURES {
        let file = load::source_file(name, text.as_bytes().to_vec(), &Options::default()).unwrap();
        if let Ok((_, tokens)) = load::assemble(file, &Options::default()) {
            problems.push(format!(
                "failure_test shader {name}: written as {}",
                hex(&tokens)
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn every_vector_is_classified() {
    // Wine's lists: 15 ps_3_0 vectors, 28 older ones, 17 failures.
    assert_eq!(PS30_VALID.len() + PS30_INVALID.len(), 15);
    assert_eq!(OLDER.len(), 28);
    assert_eq!(FAILURES.len(), 17);
}

// ---------------------------------------------------------------------------
// ps_1_x: Wine's ps_1_1, ps_1_3 and ps_1_4 vectors. Wine assembles them with
// validation skipped (several break a rule: `cnd r0, r1, …` before ps_1_4,
// `texcrd r0, t0` with a full mask, shifts on texture instructions), so they
// are held to ps_1_x's grammar and tokens alone: the text parsed by
// `core::ps1::text` and written by `core::ps1::tokens` must be Wine's tokens,
// and the tokens read back and listed must parse to the same tokens.

#[rustfmt::skip]
const PS1: &[(&str, &str, &[u32])] = &[
    ("ps_1_1 shader 0", "ps.1.1\r\ntex t0\r\nadd r0.rgb, r0, r1\r\n+mov r0.a, t0\r\n", &[0xffff0101, 0x00000042, 0xb00f0000, 0x00000002, 0x80070000, 0x80e40000, 0x80e40001, 0x40000001, 0x80080000, 0xb0e40000, 0x0000ffff]),
    ("ps_1_1 shader 1", "ps.1.1\nmov_d4 r0, r1\n", &[0xffff0101, 0x00000001, 0x8e0f0000, 0x80e40001, 0x0000ffff]),
    ("ps_1_1 shader 2", "ps_1_1\ndef c2, 0, 0., 0, 0.\n", &[0xffff0101, 0x00000051, 0xa00f0002, 0x00000000, 0x00000000, 0x00000000, 0x00000000, 0x0000ffff]),
    ("ps_1_3 shader 0", "ps_1_3\nmov r0, r1\n", &[0xffff0103, 0x00000001, 0x800f0000, 0x80e40001, 0x0000ffff]),
    ("ps_1_3 shader 1", "ps_1_3\nadd r0, r1, r0\n", &[0xffff0103, 0x00000002, 0x800f0000, 0x80e40001, 0x80e40000, 0x0000ffff]),
    ("ps_1_3 shader 2", "ps_1_3\nmov r0, v0\n", &[0xffff0103, 0x00000001, 0x800f0000, 0x90e40000, 0x0000ffff]),
    ("ps_1_3 shader 3", "ps_1_3\nmov r0, v1\n", &[0xffff0103, 0x00000001, 0x800f0000, 0x90e40001, 0x0000ffff]),
    ("ps_1_3 shader 4", "ps_1_3\ntex t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x0000ffff]),
    ("ps_1_3 shader 5", "ps_1_3\ntex t0\ntexreg2ar t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000045, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 6", "ps_1_3\ntex t0\ntexreg2gb t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000046, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 7", "ps_1_3\ntex t0\ntexreg2rgb t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000052, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 8", "ps_1_3\ncnd r0, r1, r0, v0\n", &[0xffff0103, 0x00000050, 0x800f0000, 0x80e40001, 0x80e40000, 0x90e40000, 0x0000ffff]),
    ("ps_1_3 shader 9", "ps_1_3\ncmp r0, r1, r0, v0\n", &[0xffff0103, 0x00000058, 0x800f0000, 0x80e40001, 0x80e40000, 0x90e40000, 0x0000ffff]),
    ("ps_1_3 shader 10", "ps_1_3\ntexkill t0\n", &[0xffff0103, 0x00000041, 0xb00f0000, 0x0000ffff]),
    ("ps_1_3 shader 11", "ps_1_3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000047, 0xb00f0001, 0xb0e40000, 0x00000048, 0xb00f0002, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 12", "ps_1_3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000047, 0xb00f0001, 0xb0e40000, 0x00000054, 0xb00f0002, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 13", "ps_1_3\ntex t0\ntexbem t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000043, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 14", "ps_1_3\ntex t0\ntexbeml t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000044, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 15", "ps_1_3\ntex t0\ntexdp3tex t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000053, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 16", "ps_1_3\ntex t0\ntexdp3 t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000055, 0xb00f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 17", "ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049, 0xb00f0002, 0xb0e40000, 0x0000004a, 0xb00f0003, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 18", "ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049, 0xb00f0002, 0xb0e40000, 0x00000056, 0xb00f0003, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 19", "ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049, 0xb00f0002, 0xb0e40000, 0x0000004c, 0xb00f0003, 0xb0e40000, 0xa0e40000, 0x0000ffff]),
    ("ps_1_3 shader 20", "ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049, 0xb00f0002, 0xb0e40000, 0x0000004d, 0xb00f0003, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 21", "ps_1_3\ntexcoord t0\n", &[0xffff0103, 0x00000040, 0xb00f0000, 0x0000ffff]),
    ("ps_1_3 shader 22", "ps_1_3\nmov_x2_sat r0, 1 - r1\n", &[0xffff0103, 0x00000001, 0x811f0000, 0x86e40001, 0x0000ffff]),
    ("ps_1_3 shader 23", "ps_1_3\nmov_d8 r0, -r1\n", &[0xffff0103, 0x00000001, 0x8d0f0000, 0x81e40001, 0x0000ffff]),
    ("ps_1_3 shader 24", "ps_1_3\nmov_sat r0, r1_bx2\n", &[0xffff0103, 0x00000001, 0x801f0000, 0x84e40001, 0x0000ffff]),
    ("ps_1_3 shader 25", "ps_1_3\nmov_sat r0, r1_bias\n", &[0xffff0103, 0x00000001, 0x801f0000, 0x82e40001, 0x0000ffff]),
    ("ps_1_3 shader 26", "ps_1_3\nmov_sat r0, -r1_bias\n", &[0xffff0103, 0x00000001, 0x801f0000, 0x83e40001, 0x0000ffff]),
    ("ps_1_3 shader 27", "ps_1_3\nmov_sat r0, -r1_bx2\n", &[0xffff0103, 0x00000001, 0x801f0000, 0x85e40001, 0x0000ffff]),
    ("ps_1_3 shader 28", "ps_1_3\nmov_sat r0, -r1_x2\n", &[0xffff0103, 0x00000001, 0x801f0000, 0x88e40001, 0x0000ffff]),
    ("ps_1_3 shader 29", "ps_1_3\nmov_x4_sat r0.a, -r1_bx2.a\n", &[0xffff0103, 0x00000001, 0x82180000, 0x85ff0001, 0x0000ffff]),
    ("ps_1_3 shader 30", "ps_1_3\ntexcoord_x2 t0\n", &[0xffff0103, 0x00000040, 0xb10f0000, 0x0000ffff]),
    ("ps_1_3 shader 31", "ps_1_3\ntex_x2 t0\n", &[0xffff0103, 0x00000042, 0xb10f0000, 0x0000ffff]),
    ("ps_1_3 shader 32", "ps_1_3\ntexreg2ar_x4 t0, t1\n", &[0xffff0103, 0x00000045, 0xb20f0000, 0xb0e40001, 0x0000ffff]),
    ("ps_1_3 shader 33", "ps_1_3\ntexbem_d4 t1, t0\n", &[0xffff0103, 0x00000043, 0xbe0f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 34", "ps_1_3\ntex t0\ntexm3x3pad_x2 t1, t0\ntexm3x3pad_x2 t2, t0\ntexm3x3tex_x2 t3, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb10f0001, 0xb0e40000, 0x00000049, 0xb10f0002, 0xb0e40000, 0x0000004a, 0xb10f0003, 0xb0e40000, 0x0000ffff]),
    ("ps_1_3 shader 35", "ps.1.3\ntex t0\ntexdp3tex_x8 t1, t0\n", &[0xffff0103, 0x00000042, 0xb00f0000, 0x00000053, 0xb30f0001, 0xb0e40000, 0x0000ffff]),
    ("ps_1_4 shader 0", "ps_1_4\nmov r0, r1\n", &[0xffff0104, 0x00000001, 0x800f0000, 0x80e40001, 0x0000ffff]),
    ("ps_1_4 shader 1", "ps_1_4\nmov r0, r5\n", &[0xffff0104, 0x00000001, 0x800f0000, 0x80e40005, 0x0000ffff]),
    ("ps_1_4 shader 2", "ps_1_4\nmov r0, c7\n", &[0xffff0104, 0x00000001, 0x800f0000, 0xa0e40007, 0x0000ffff]),
    ("ps_1_4 shader 3", "ps_1_4\nmov r0, v1\n", &[0xffff0104, 0x00000001, 0x800f0000, 0x90e40001, 0x0000ffff]),
    ("ps_1_4 shader 4", "ps_1_4\nphase\n", &[0xffff0104, 0x0000fffd, 0x0000ffff]),
    ("ps_1_4 shader 5", "ps_1_4\ntexcrd r0, t0\n", &[0xffff0104, 0x00000040, 0x800f0000, 0xb0e40000, 0x0000ffff]),
    ("ps_1_4 shader 6", "ps_1_4\ntexcrd r4, t3\n", &[0xffff0104, 0x00000040, 0x800f0004, 0xb0e40003, 0x0000ffff]),
    ("ps_1_4 shader 7", "ps_1_4\ntexcrd_sat r4, t3\n", &[0xffff0104, 0x00000040, 0x801f0004, 0xb0e40003, 0x0000ffff]),
    ("ps_1_4 shader 8", "ps_1_4\ntexld r0, t0\n", &[0xffff0104, 0x00000042, 0x800f0000, 0xb0e40000, 0x0000ffff]),
    ("ps_1_4 shader 9", "ps_1_4\ntexld r1, t4\n", &[0xffff0104, 0x00000042, 0x800f0001, 0xb0e40004, 0x0000ffff]),
    ("ps_1_4 shader 10", "ps_1_4\ntexld r5, r0\n", &[0xffff0104, 0x00000042, 0x800f0005, 0x80e40000, 0x0000ffff]),
    ("ps_1_4 shader 11", "ps_1_4\ntexld r5, c0\n", &[0xffff0104, 0x00000042, 0x800f0005, 0xa0e40000, 0x0000ffff]),
    ("ps_1_4 shader 12", "ps_1_4\ntexld r5, r2_dz\n", &[0xffff0104, 0x00000042, 0x800f0005, 0x89e40002, 0x0000ffff]),
    ("ps_1_4 shader 13", "ps_1_4\nbem r1.rg, c0, r0\n", &[0xffff0104, 0x00000059, 0x80030001, 0xa0e40000, 0x80e40000, 0x0000ffff]),
    ("ps_1_4 shader 14", "ps_1_4\ntexdepth r5\n", &[0xffff0104, 0x00000057, 0x800f0005, 0x0000ffff]),
    ("ps_1_4 shader 15", "ps_1_4\nadd r0, r1, r2_bx2\n", &[0xffff0104, 0x00000002, 0x800f0000, 0x80e40001, 0x84e40002, 0x0000ffff]),
    ("ps_1_4 shader 16", "ps_1_4\nadd_x4 r0, r1, r2\n", &[0xffff0104, 0x00000002, 0x820f0000, 0x80e40001, 0x80e40002, 0x0000ffff]),
    ("ps_1_4 shader 17", "ps_1_4\nadd r0.rgb, r1, r2\n+add r0.a, r1, r2\n", &[0xffff0104, 0x00000002, 0x80070000, 0x80e40001, 0x80e40002, 0x40000002, 0x80080000, 0x80e40001, 0x80e40002, 0x0000ffff]),
    ("ps_1_4 shader 18", "ps_1_4\ntexdepth_x2 r5\n", &[0xffff0104, 0x00000057, 0x810f0005, 0x0000ffff]),
    ("ps_1_4 shader 19", "ps.1.4\nbem_d2 r1, c0, r0\n", &[0xffff0104, 0x00000059, 0x8f0f0001, 0xa0e40000, 0x80e40000, 0x0000ffff]),
];

#[test]
fn ps_1_x_vectors_are_written_and_read_as_wines_tokens() {
    use ps30::core::profile::Profile;
    use ps30::core::ps1::{listing as ps1_listing, text, tokens};
    let mut problems = Vec::new();
    for (name, source, want) in PS1 {
        let version = source.lines().next().unwrap_or_default().trim();
        let profile = Profile::from_version_line(version).expect("a ps_1_x version");
        match text::parse(source, profile) {
            Ok(p) if tokens::encode(&p) == *want => {}
            Ok(p) => problems.push(format!("{name}: written as {}", hex(&tokens::encode(&p)))),
            Err(e) => problems.push(format!("{name}: not parsed: {:?}", e.items.first())),
        }
        match tokens::decode(&write::to_bytes(want), 1000) {
            Ok(p) => {
                let listed = ps1_listing::listing(&p);
                match text::parse(&listed, profile) {
                    Ok(again) if tokens::encode(&again) == *want => {}
                    _ => {
                        problems.push(format!("{name}: its listing does not read back:\n{listed}"))
                    }
                }
            }
            Err(e) => problems.push(format!("{name}: not read: {e}")),
        }
    }
    assert_eq!(
        PS1.len(),
        59,
        "Wine's 3 ps_1_1, 36 ps_1_3 and 20 ps_1_4 vectors"
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
