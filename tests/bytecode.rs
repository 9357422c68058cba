//! Compiled shaders: the reader, the writer, the listing and the constant
//! table.
//!
//! Why: ps30 reads bytecode that comes from elsewhere — fxc, games, captured
//! frames — and writes bytecode others load, so two things must hold. What
//! it writes and reads back must be the same program, to the byte: every
//! shader of `asm/` and every random program of the generators goes text →
//! tokens → listing → tokens and must come back identical, and load to the
//! same program with the same costs. And a stream that lies must never hurt:
//! each case of the malformed corpus below (truncations, lengths past the
//! end, a comment claiming 32,767 tokens, a constant table claiming 2^30
//! constants, offsets out of range, cycles, unknown opcodes) is refused with
//! a message and the byte offset of the token at fault — worked out by hand
//! from the layout, not copied from the output — without a panic and
//! without allocating more than a small multiple of the input (a counting
//! allocator watches); every truncation and every single-byte change of a
//! real stream is refused cleanly or read back byte for byte; and through
//! the binary each refusal is exit 2 with the token and byte named.
//! Constant tables are built by hand (`common/ctab.rs`, from D3DX's
//! structure definitions) with several kinds of constants, arrays, a struct
//! and defaults, and decoded field by field.

use crate::common::bin;
use crate::common::ctab as ctab_builder;
use crate::common::program_gen;

use ctab_builder::{comment, comment_lines, table, Const, Ty};
use proptest::prelude::*;
use ps30::core::bytecode::ctab::{self, Class, RegisterSet};
use ps30::core::bytecode::{listing, read, write};
use ps30::core::cost::{self, Environment, Profile};
use ps30::core::front::print::write_program;
use ps30::core::load::{self, Options};
use std::path::Path;
use std::time::{Duration, Instant};

use crate::common::counting;
use counting::allocated_by;

// ---------------------------------------------------------------------------
// Helpers.

const V: u32 = 0xffff_0300;
const E: u32 = 0x0000_ffff;

fn bytes(tokens: &[u32]) -> Vec<u8> {
    write::to_bytes(tokens)
}

/// Text → tokens the way `ps30 asm` makes them (load, validate, write).
fn assemble(name: &str, text: &[u8], options: &Options) -> (load::Loaded, Vec<u32>) {
    let file = load::source_file(name, text.to_vec(), options).unwrap_or_else(|e| panic!("{e}"));
    load::assemble(file, options).unwrap_or_else(|e| panic!("{}", e.diagnostics.render(&e.file)))
}

/// The round trip: text → tokens → listing → tokens, and the two loads
/// (from the text, from the tokens) give the same program and costs.
fn round_trip(name: &str, text: &str, options: &Options) -> Result<(), String> {
    let (from_text, tokens) = assemble(name, text.as_bytes(), options);
    let (from_tokens, again) = assemble(name, &bytes(&tokens), options);
    if again != tokens {
        return Err(format!(
            "{name}: tokens → listing → tokens differ\n{}",
            from_tokens.file.text
        ));
    }
    let (a, b) = (
        write_program(from_text.shader.program()),
        write_program(from_tokens.shader.program()),
    );
    if a != b {
        return Err(format!(
            "{name}: the tokens load to another program:\n{a}\n---\n{b}"
        ));
    }
    let env = Environment::default();
    let cost = |l: &load::Loaded| {
        cost::analyse(&l.shader, &l.file, &env, &Profile::ps_3_0()).map(|a| (a.slots, a.executed))
    };
    match (cost(&from_text), cost(&from_tokens)) {
        (Ok(x), Ok(y)) if x == y => Ok(()),
        (x, y) => Err(format!("{name}: costs differ: {x:?} vs {y:?}")),
    }
}

fn asm_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            asm_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "psh") {
            out.push(path);
        }
    }
}

// ---------------------------------------------------------------------------
// Round trips.

#[test]
fn every_shader_in_asm_round_trips_through_bytecode() {
    let mut files = Vec::new();
    asm_files(&bin::repo().join("asm"), &mut files);
    assert!(files.len() >= 50, "found only {} shaders", files.len());
    let mut options = Options::default();
    // The pass-2 listings take their frame from -D.
    options.defines.insert("xsize".into(), 11);
    options.defines.insert("ysize".into(), 8);
    // lights/select_texld.psh is the bundled example of texld under dynamic
    // flow control: Microsoft's assembler refuses it (X6077), so ps30 asm
    // writes no bytecode for it.
    let (refused, files): (Vec<_>, Vec<_>) = files
        .into_iter()
        .partition(|f| f.ends_with("lights/select_texld.psh"));
    assert_eq!(refused.len(), 1);
    let text = std::fs::read(&refused[0]).unwrap();
    let file = load::source_file("select_texld.psh", text, &options).unwrap();
    let e = load::assemble(file, &options).expect_err("X6077");
    assert_eq!(e.diagnostics.errors().next().unwrap().code, Some("X6077"));
    let problems: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            round_trip(&f.display().to_string(), &text, &options).err()
        })
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Random programs with loops, ifs, calls and predication (the
    /// generator the cost-model property tests use).
    #[test]
    fn random_programs_round_trip_through_bytecode(seed in prop::collection::vec(any::<u8>(), 0..256)) {
        let text = program_gen::random_program(&seed);
        let r = round_trip("random.psh", &text, &Options::default());
        prop_assert!(r.is_ok(), "{}\n{:?}", text, r);
    }
}

/// Every constant the listing can spell reads back to its bits; NaNs with
/// other payloads are read as they are and listed as Microsoft lists them.
#[test]
fn constants_round_trip_by_their_bits() {
    for bits in [
        0x8000_0000u32, // -0.0
        0x0000_0001,    // the smallest denormal
        0x7f7f_ffff,    // the largest finite float
        0x3dcc_cccd,    // 0.1
        0x3e38_51ec,    // 0.18
        0xcb80_0001,    // -16777218 (odd mantissa at 2^24)
        0x7f80_0000,    // 1.#INF
        0xff80_0000,    // -1.#INF
        0x7fe0_0000,    // 1.#QNAN
        0xffe0_0000,    // -1.#QNAN
        0xffc0_0000,    // 1.#IND
        0x7fc0_0000,    // -1.#IND
    ] {
        let tokens = [
            V,
            0x0500_0051,
            0xa00f_0000,
            bits,
            0,
            0,
            0,
            0x0200_0001,
            0x800f_0800,
            0xa0e4_0000,
            E,
        ];
        let module = read::read(&bytes(&tokens), 100).unwrap();
        let text = listing::listing(&module).text;
        let (_, again) = assemble("c.fxo", text.as_bytes(), &Options::default());
        assert_eq!(again, tokens, "{bits:#x}:\n{text}");
    }
    // Any other NaN (a payload, a signalling NaN) is read with its bits and
    // listed as D3DDisassemble lists it (tests/oracle/corpus/dis/def-bits).
    for (bits, text) in [
        (0x7fc0_0001u32, "1.#QNAN"),
        (0x7f80_0001, "1.#QNAN"),
        (0xff80_0001, "-1.#IND"),
    ] {
        let module = read::read(
            &bytes(&[V, 0x0500_0051, 0xa00f_0000, bits, 0, 0, 0, E]),
            100,
        )
        .unwrap();
        let listed = listing::listing(&module).text;
        assert!(
            listed.contains(&format!("def c0, {text}, 0, 0, 0")),
            "{bits:#x}:\n{listed}"
        );
    }
}

// ---------------------------------------------------------------------------
// The constant table.

/// A table with one of each kind: float with a default, float4, column- and
/// row-major matrices, int4, bool array, sampler2D, samplerCUBE, a struct
/// array and a float array with a default.
fn sample_table() -> Vec<u32> {
    let one = 1.0f32.to_bits();
    table(
        "ps30 tests",
        "ps_3_0",
        V,
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
                name: "g_vTint",
                set: 2,
                index: 1,
                count: 1,
                ty: Ty::numeric(1, 3, 1, 4, 1),
                default: None,
            },
            Const {
                name: "g_mView",
                set: 2,
                index: 2,
                count: 4,
                ty: Ty::numeric(3, 3, 4, 4, 1),
                default: None,
            },
            Const {
                name: "g_mRows",
                set: 2,
                index: 6,
                count: 3,
                ty: Ty::numeric(2, 3, 3, 4, 1),
                default: None,
            },
            Const {
                name: "g_iSteps",
                set: 1,
                index: 0,
                count: 1,
                ty: Ty::numeric(1, 2, 1, 4, 1),
                default: Some(vec![16, 0, 1, 0]),
            },
            Const {
                name: "g_bOn",
                set: 0,
                index: 2,
                count: 3,
                ty: Ty::numeric(0, 1, 1, 1, 3),
                default: Some(vec![1, 0, 1]),
            },
            Const {
                name: "g_tex",
                set: 3,
                index: 0,
                count: 1,
                ty: Ty::object(12),
                default: None,
            },
            Const {
                name: "g_env",
                set: 3,
                index: 1,
                count: 1,
                ty: Ty::object(14),
                default: None,
            },
            Const {
                name: "g_lights",
                set: 2,
                index: 9,
                count: 4,
                ty: Ty::structure(
                    2,
                    vec![
                        ("pos", Ty::numeric(1, 3, 1, 3, 1)),
                        ("range", Ty::numeric(0, 3, 1, 1, 1)),
                    ],
                ),
                default: None,
            },
            Const {
                name: "g_weights",
                set: 2,
                index: 13,
                count: 2,
                ty: Ty::numeric(0, 3, 1, 1, 2),
                default: Some(vec![one, 0, 0, 0, 0.5f32.to_bits(), 0, 0, 0]),
            },
        ],
    )
}

#[test]
fn hand_built_constant_tables_decode_field_by_field() {
    let body = sample_table();
    let t = ctab::decode(&body[1..]).unwrap();
    assert_eq!(
        (t.creator.as_str(), t.target.as_str(), t.version),
        ("ps30 tests", "ps_3_0", V)
    );
    let rows: Vec<(String, RegisterSet, u16, u16, String)> = t
        .constants
        .iter()
        .map(|c| {
            (
                c.name.clone(),
                c.set,
                c.index,
                c.count,
                format!("{}{}", c.ty.hlsl(), c.ty.array()),
            )
        })
        .collect();
    let want: Vec<(String, RegisterSet, u16, u16, String)> = [
        ("g_fKey", RegisterSet::Float4, 0, 1, "float"),
        ("g_vTint", RegisterSet::Float4, 1, 1, "float4"),
        ("g_mView", RegisterSet::Float4, 2, 4, "float4x4"),
        ("g_mRows", RegisterSet::Float4, 6, 3, "row_major float3x4"),
        ("g_iSteps", RegisterSet::Int4, 0, 1, "int4"),
        ("g_bOn", RegisterSet::Bool, 2, 3, "bool[3]"),
        ("g_tex", RegisterSet::Sampler, 0, 1, "sampler2D"),
        ("g_env", RegisterSet::Sampler, 1, 1, "samplerCUBE"),
        (
            "g_lights",
            RegisterSet::Float4,
            9,
            4,
            "struct { float3 pos; float range; }[2]",
        ),
        ("g_weights", RegisterSet::Float4, 13, 2, "float[2]"),
    ]
    .iter()
    .map(|&(n, s, i, c, h)| (n.to_string(), s, i, c, h.to_string()))
    .collect();
    assert_eq!(rows, want);
    let c = |name: &str| t.constants.iter().find(|c| c.name == name).unwrap();
    assert_eq!(
        c("g_fKey").register_defaults(),
        vec![vec![0.18f32.to_bits(), 0, 0, 0]]
    );
    assert_eq!(c("g_iSteps").register_defaults(), vec![vec![16, 0, 1, 0]]);
    assert_eq!(
        c("g_bOn").register_defaults(),
        vec![vec![1], vec![0], vec![1]]
    );
    assert_eq!(
        c("g_weights").register_defaults()[1],
        vec![0.5f32.to_bits(), 0, 0, 0]
    );
    assert_eq!(c("g_vTint").default, None);
    let lights = &c("g_lights").ty;
    assert_eq!(
        (lights.class, lights.elements, lights.members.len()),
        (Class::Struct, 2, 2)
    );
    assert_eq!(lights.members[1].name, "range");
    // D3DX's layout of a default: 4 words per register row for floats, one
    // per element for booleans.
    assert_eq!(c("g_mView").ty.default_words(RegisterSet::Float4), 16);
    assert_eq!(c("g_bOn").ty.default_words(RegisterSet::Bool), 3);
    assert_eq!(lights.default_words(RegisterSet::Float4), 2 * (4 + 4));
}

#[test]
fn a_table_travels_with_its_shader_and_is_listed_the_way_fxc_lists_it() {
    let body = sample_table();
    let mut tokens = vec![V];
    tokens.extend(comment(&body));
    tokens.extend([0x0200_001f, 0x9000_0000, 0xa00f_0800]); // dcl_2d s0
    tokens.extend([0x0200_0001, 0x800f_0800, 0xa000_0000]); // mov oC0, c0.x
    tokens.push(E);
    let (loaded, again) = assemble("t.fxo", &bytes(&tokens), &Options::default());
    assert_eq!(again, tokens, "the table is written back where it stood");
    let t = loaded.constants.expect("a constant table");
    assert_eq!(t.constants.len(), 10);
    let text = &loaded.file.text;
    for line in [
        "// Generated by ps30 tests",
        "//   float g_fKey;",
        "//   struct\n//   {\n//       float3 pos;\n//       float range;\n//\n//   } g_lights[2];",
        "//   g_mRows      c6       3",
        "//   g_tex        s0       1",
        "    ps_3_0",
        "// the constant table above (CTAB), 160 tokens, kept as written:",
        "//#comment 42415443 0000001c",
        "    mov oC0, c0.x",
        "// approximately 1 instruction slots used (0 texture, 1 arithmetic)",
    ] {
        assert!(text.contains(line), "`{line}` missing from\n{text}");
    }
    // The table's size by hand: header 28 + 10 constant infos × 20, then
    // names padded to 4 with types (16) and defaults — g_fKey 8+16+16,
    // g_vTint 8+16, g_mView 8+16, g_mRows 8+16, g_iSteps 12+16+16, g_bOn
    // 8+16+12, g_tex 8+16, g_env 8+16, g_lights 12+16 + members 2×8 + "pos"
    // 4+16 + "range" 8+16, g_weights 12+16+32 — then creator 12 and target 8:
    // 636 bytes, 159 tokens, and `CTAB`.
    assert_eq!(body.len(), 160);
    // A text shader may carry the table as //#comment lines too.
    let src = format!("ps_3_0\n{}dcl_2d s0\nmov oC0, c0.x\n", comment_lines(&body));
    let (from_text, text_tokens) = assemble("t.psh", src.as_bytes(), &Options::default());
    assert_eq!(text_tokens, tokens);
    assert_eq!(from_text.constants.unwrap().constants.len(), 10);
}

// ---------------------------------------------------------------------------
// The malformed corpus.

/// A table with one float constant, the byte at `offset` of the table
/// replaced by the dword `value`; in a shader: version, comment, end. The
/// table starts at byte 12 (version, comment token, `CTAB`).
fn bad_table(offset: usize, value: u32) -> Vec<u32> {
    let mut body = table(
        "c",
        "ps_3_0",
        V,
        &[Const {
            name: "k",
            set: 2,
            index: 0,
            count: 1,
            ty: Ty::numeric(0, 3, 1, 1, 1),
            default: None,
        }],
    );
    body[1 + offset / 4] = value;
    let mut t = vec![V];
    t.extend(comment(&body));
    t.push(E);
    t
}

/// The bytes of a malformed case.
enum Input {
    Tokens(Vec<u32>),
    Bytes(Vec<u8>),
}

/// (what, input, message substring, byte offset of the token at fault).
fn corpus() -> Vec<(&'static str, Input, &'static str, usize)> {
    use Input::{Bytes, Tokens};
    // Layout of the sample table (common/ctab.rs): header 0..28, constant
    // info 28..48 (name at 28, set/index at 32, count at 36, type at 40,
    // default at 44), name "k" at 48, type at 52.
    let cycle = {
        // A struct whose only member's type is the struct itself.
        let mut body = table(
            "c",
            "ps_3_0",
            V,
            &[Const {
                name: "s",
                set: 2,
                index: 0,
                count: 1,
                ty: Ty::structure(1, vec![("m", Ty::numeric(0, 3, 1, 1, 1))]),
                default: None,
            }],
        );
        // Struct type at 52, its member info at 68 (name at 68, type at 72).
        body[1 + 72 / 4] = 52;
        let mut t = vec![V];
        t.extend(comment(&body));
        t.push(E);
        t
    };
    let shared = {
        // 300 constants sharing one struct of 100 members sharing one leaf:
        // a few kilobytes that would decode to megabytes.
        let mut body = table(
            "c",
            "ps_3_0",
            V,
            &[Const {
                name: "s",
                set: 2,
                index: 0,
                count: 1,
                ty: Ty::structure(1, vec![("m", Ty::numeric(0, 3, 1, 1, 1))]),
                default: None,
            }],
        );
        let n = 300;
        body[1 + 12 / 4] = n; // constant count
        let info_at = (body.len() - 1) * 4;
        // Struct: 100 members at the end, each naming the leaf at 80.
        let members_at = info_at + 20 * n as usize;
        body[1 + 60 / 4] = 100 << 16 | (body[1 + 60 / 4] & 0xffff); // rows/members word: members = 100
        body[1 + 64 / 4] = members_at as u32;
        body[1 + 16 / 4] = info_at as u32; // constant infos at the end
        for _ in 0..n {
            body.extend([48, 2, 1, 52, 0]);
        }
        for _ in 0..100 {
            body.extend([76, 80]); // the member's name "m" and the leaf type
        }
        let mut t = vec![V];
        t.extend(comment(&body));
        t.push(E);
        t
    };
    vec![
        ("empty", Bytes(vec![]), "empty: no version token", 0),
        (
            "a token cut off",
            Bytes(vec![0, 3, 0xff, 0xff, 1, 0]),
            "not a whole number of 4-byte tokens",
            4,
        ),
        (
            "no end token",
            Tokens(vec![V, 0x0200_0001, 0x800f_0000, 0xa0e4_0000]),
            "without an end token",
            16,
        ),
        (
            "bytes after the end",
            Tokens(vec![V, E, 0xdead_beef]),
            "4 bytes follow the end token",
            8,
        ),
        (
            "a length past the end",
            Tokens(vec![V, 0x0f00_0001, 0x800f_0000, E]),
            "claims 15 operand tokens, past the end",
            4,
        ),
        (
            "a zero-length mov",
            Tokens(vec![V, 0x0000_0001, E]),
            "says 0 operand tokens; its operands need more",
            4,
        ),
        (
            "a length too long",
            Tokens(vec![
                V,
                0x0300_0001,
                0x800f_0000,
                0xa0e4_0000,
                0xa0e4_0000,
                E,
            ]),
            "says 3 operand tokens; its operands take 2",
            4,
        ),
        (
            "an unknown opcode",
            Tokens(vec![V, 0x0200_1234, 0x800f_0000, 0xa0e4_0000, E]),
            "unknown opcode 0x1234",
            4,
        ),
        (
            "a vertex-shader opcode",
            Tokens(vec![V, 0x0200_0010, 0x800f_0000, 0xa0e4_0000, E]),
            "opcode 0x10 (lit) is not a ps_3_0 instruction",
            4,
        ),
        (
            "a ps_1_x opcode",
            Tokens(vec![V, 0x0100_0040, 0xb00f_0000, E]),
            "(texcoord) is not a ps_3_0",
            4,
        ),
        (
            "a comment claiming 32,767 tokens",
            Tokens(vec![V, 0x7fff_fffe, E]),
            "the comment claims 32767 tokens",
            4,
        ),
        // ps_1_x has its own reader (core::ps1): the ps_2_0-ps_3_0 reader
        // names the version, ps30's commands the opcode ps_1_4 lacks.
        (
            "a ps_1_4 stream with an opcode ps_1_4 lacks",
            Tokens(vec![0xffff_0104, 0x0000_1234, E]),
            "ps_1_4",
            0,
        ),
        (
            "a vs_1_1 stream",
            Tokens(vec![0xfffe_0101, E]),
            "a vs_1_1 shader",
            0,
        ),
        (
            "an effect",
            Tokens(vec![0xfeff_0901, E]),
            "a Direct3D effect (version token 0xfeff0901)",
            0,
        ),
        (
            "the co-issue bit",
            Tokens(vec![V, 0x4200_0001, 0x800f_0000, 0xa0e4_0000, E]),
            "co-issue",
            4,
        ),
        (
            "a comparison code of 7",
            Tokens(vec![V, 0x0207_0029, 0x8000_0000, 0x8000_0001, E]),
            "comparison code 7",
            4,
        ),
        (
            "a t# register",
            Tokens(vec![V, 0x0200_0001, 0x800f_0000, 0xb0e4_0000, E]),
            "register type 3",
            12,
        ),
        (
            "r40",
            Tokens(vec![V, 0x0200_0001, 0x800f_0028, 0xa0e4_0000, E]),
            "r40 does not exist: ps_3_0 has r0 to r31",
            8,
        ),
        (
            "a parameter with bit 31 clear",
            Tokens(vec![V, 0x0200_0001, 0x000f_0000, 0xa0e4_0000, E]),
            "bit 31 clear",
            8,
        ),
        (
            "a shift",
            Tokens(vec![V, 0x0200_0001, 0x810f_0000, 0xa0e4_0000, E]),
            "shift modifier",
            8,
        ),
        (
            "an empty write mask",
            Tokens(vec![V, 0x0200_0001, 0x8000_0000, 0xa0e4_0000, E]),
            "empty write mask",
            8,
        ),
        (
            "a _bx2 source",
            Tokens(vec![V, 0x0200_0001, 0x800f_0000, 0x84e4_0000, E]),
            "the modifier _bx2",
            12,
        ),
        (
            "relative through a0",
            Tokens(vec![
                V,
                0x0300_0001,
                0x800f_0000,
                0x90e4_2000,
                0xb000_0000,
                E,
            ]),
            "relative-address token 0xb0000000",
            16,
        ),
        (
            "a relative destination",
            Tokens(vec![V, 0x0200_0001, 0x800f_2000, 0xa0e4_0000, E]),
            "relatively addressed destination",
            8,
        ),
        (
            "defb 2",
            Tokens(vec![V, 0x0200_002f, 0xe00f_0800, 2, E]),
            "`defb` value 0x2",
            12,
        ),
        (
            "a dcl usage token with stray bits",
            Tokens(vec![V, 0x0200_001f, 0x8000_0105, 0x900f_0000, E]),
            "sets bits a declaration does not have",
            8,
        ),
        (
            "a table's header size",
            Tokens(bad_table(0, 27)),
            "the header says it is 27 bytes",
            12,
        ),
        (
            "a table claiming 2^30 constants",
            Tokens(bad_table(12, 1 << 30)),
            "1073741824 constants of 20 bytes",
            24,
        ),
        (
            "a name offset out of range",
            Tokens(bad_table(28, 0x10000)),
            "a constant's name is at offset 65536, past the end",
            40,
        ),
        (
            "a type offset out of range",
            Tokens(bad_table(40, 0x10000)),
            "a type at offset 65536 runs past the end",
            52,
        ),
        (
            "a default past the end",
            Tokens(bad_table(44, 72)),
            "the default value of `k` (4 words at offset 72) runs past the end",
            56,
        ),
        (
            "a register set of 7",
            Tokens(bad_table(32, 7)),
            "register set 7",
            44,
        ),
        (
            "a creator string without its zero",
            Tokens(bad_table(4, 79)),
            "the creator at offset 79 is not ended by a zero byte",
            91,
        ),
        (
            "a struct that contains itself",
            Tokens(cycle),
            "types nest more than 16 deep",
            84,
        ),
        (
            "types shared over and over",
            Tokens(shared),
            "more than 8 times its",
            0,
        ),
    ]
}

#[test]
fn malformed_streams_are_refused_at_their_byte_without_panic_or_large_allocation() {
    let mut problems = Vec::new();
    for (what, input, message, byte) in corpus() {
        let data = match input {
            Input::Tokens(t) => bytes(&t),
            Input::Bytes(b) => b,
        };
        let (result, allocated) =
            allocated_by(|| std::panic::catch_unwind(|| read::read(&data, 100_000)));
        let bound = 64 * 1024 + 64 * data.len() as u64;
        match result {
            Err(_) => problems.push(format!("{what}: PANIC")),
            Ok(Ok(_)) => problems.push(format!("{what}: accepted")),
            // The sharing bomb is found wherever the budget runs out.
            Ok(Err(e)) if !e.message.contains(message) || (byte != 0 && e.byte != byte) => problems
                .push(format!(
                    "{what}: `{e}`; expected `{message}` at byte {byte}"
                )),
            Ok(Err(_)) if allocated > bound => problems.push(format!(
                "{what}: allocated {allocated} bytes for {} bytes of input",
                data.len()
            )),
            Ok(Err(_)) => {}
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// A real stream (a table, declarations, a loop with relative addressing,
/// predication, a subroutine) cut at every length and with every byte
/// changed: each is refused cleanly with an offset inside the input, or read
/// and written back byte for byte.
#[test]
fn every_truncation_and_every_changed_byte_is_refused_or_read_back_exactly() {
    let src = format!(
        "ps_3_0\n{}dcl_texcoord0_centroid v0.xy\ndcl_texcoord1 v1\ndcl_2d s0\ndefi i0, 2, 0, 1, 0\ndef c5, 0.5, -0, 1e-20, 3\nmov r0, c5\nloop aL, i0\n  add r0, r0, v[aL]\nendloop\nsetp_gt p0.x, r0.x, c5.x\n(!p0.x) texldl r1, r0, s0\ncall l3\nmov oC0, -r1_abs.wzyx\nret\nlabel l3\nret\n",
        comment_lines(&sample_table())
    );
    let (_, tokens) = assemble("real.psh", src.as_bytes(), &Options::default());
    let data = bytes(&tokens);
    let check = |b: &[u8]| -> Result<(), String> {
        match std::panic::catch_unwind(|| read::read(b, 100_000)) {
            Err(_) => Err("PANIC".into()),
            Ok(Err(e)) if e.byte > b.len() => Err(format!(
                "offset {} past the input ({} bytes): {e}",
                e.byte,
                b.len()
            )),
            Ok(Err(_)) => Ok(()),
            Ok(Ok(m)) => {
                let direct = write::to_bytes(&write::encode(&m));
                // And through the listing, as every command reads it.
                let listed = std::panic::catch_unwind(|| -> Result<Vec<u8>, String> {
                    let file = load::source_file("x", b.to_vec(), &Options::default())
                        .map_err(|e| e.to_string())?;
                    let (stmts, _) = ps30::core::front::parse::parse(&file.text);
                    let expanded =
                        ps30::core::front::repeat::expand(&stmts, &Default::default(), 100_000)
                            .map_err(|d| d.items[0].message.clone())?;
                    write::assemble(&stmts, &expanded)
                        .map(|m| write::to_bytes(&write::encode(&m)))
                        .map_err(|d| format!("{}\n{}", d.items[0].message, file.text))
                })
                .map_err(|_| "PANIC in the listing".to_string())?;
                // Through text, `sub` is written as Microsoft's assembler
                // writes it (`add` with the second source negated).
                let mut spelled = m.clone();
                for item in &mut spelled.items {
                    if let ps30::core::bytecode::ItemKind::Instr(i) = &mut item.kind {
                        if i.op == ps30::core::isa::Opcode::Sub {
                            write::sub_as_add(i);
                        }
                    }
                }
                let as_text = write::to_bytes(&write::encode(&spelled));
                match (direct == b, listed) {
                    (true, Ok(l)) if l == as_text => Ok(()),
                    (ok, other) => Err(format!(
                        "read but not written back (direct: {ok}, listing: {other:?})"
                    )),
                }
            }
        }
    };
    let mut problems = Vec::new();
    for n in 0..data.len() {
        if let Err(e) = check(&data[..n]) {
            problems.push(format!("first {n} bytes: {e}"));
        }
    }
    for i in 0..data.len() {
        for v in [
            0x00,
            0xff,
            data[i] ^ 0x01,
            data[i] ^ 0x80,
            data[i].wrapping_add(4),
        ] {
            let mut b = data.clone();
            b[i] = v;
            if let Err(e) = check(&b) {
                problems.push(format!("byte {i} = {v:#04x}: {e}"));
            }
        }
    }
    problems.truncate(10);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_binary_refuses_malformed_streams_with_exit_2_naming_the_token() {
    let dir = tempfile::tempdir().unwrap();
    let mut problems = Vec::new();
    for (i, (what, input, message, _)) in corpus().into_iter().enumerate() {
        let data = match input {
            Input::Tokens(t) => bytes(&t),
            Input::Bytes(b) => b,
        };
        // `empty` and a cut-off token are not recognised as bytecode: text.
        if data.len() < 8 {
            continue;
        }
        let path = dir.path().join(format!("case{i}.fxo"));
        std::fs::write(&path, &data).unwrap();
        for cmd in ["check", "disasm"] {
            let start = Instant::now();
            let o = bin::ps30(&[cmd, path.to_str().unwrap()], dir.path());
            let err = String::from_utf8_lossy(&o.stderr);
            if o.status.code() != Some(2)
                || !err.contains(message)
                || !err.contains("(byte 0x")
                || err.contains("panicked")
                || start.elapsed() > Duration::from_secs(5)
            {
                problems.push(format!("{cmd} {what}: exit {:?}: {err}", o.status.code()));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
