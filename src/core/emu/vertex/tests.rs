//! Each vertex instruction against values worked out by hand (the
//! derivation beside each). Every expected value is exact in f32, so the
//! comparisons are exact.

use super::*;
use crate::core::emu::SamplerState;
use crate::core::load::{self, Options};

/// Runs assembly `text` over `vertices` (position0 values) with float
/// constants `consts` (from c0).
fn run_text(text: &str, consts: &[[f32; 4]], positions: &[[f32; 4]]) -> VertexOutput {
    let options = Options::default();
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options).unwrap();
    let shader = load::load(file, &options)
        .map_err(|e| format!("{:?}", e.diagnostics))
        .unwrap()
        .shader;
    let draw = VertexDraw {
        constants: Constants {
            float: consts.to_vec(),
            ..Constants::default()
        },
        ..VertexDraw::default()
    };
    let vertices = Vertices {
        count: positions.len(),
        attributes: vec![(
            Attribute {
                usage: "position".into(),
                index: 0,
            },
            positions.to_vec(),
        )],
    };
    run(&shader, &draw, &vertices).unwrap()
}

/// The first output of every vertex.
fn first(out: &VertexOutput) -> Vec<[f32; 4]> {
    out.values.iter().map(|v| v[0]).collect()
}

#[test]
fn mova_rounds_halves_to_even_and_indexes_constants() {
    // c_k = (k, 0, 0, 0): reading c[a0.x + 2] gives a0.x + 2.
    let consts: Vec<[f32; 4]> = (0..8).map(|k| [k as f32, 0.0, 0.0, 1.0]).collect();
    let text = "vs_2_0\ndcl_position v0\nmova a0.x, v0.x\nmov oPos, c[a0.x + 2]\n";
    let xs = [0.5, 1.49, 2.5, -1.5, 1.5, -0.5, -2.5, 3.5];
    let rows: Vec<[f32; 4]> = xs.iter().map(|&x| [x, 0.0, 0.0, 1.0]).collect();
    let out = run_text(text, &consts, &rows);
    // Halves to even: 0.5 → 0, 1.49 → 1, 2.5 → 2, −1.5 → −2, 1.5 → 2,
    // −0.5 → 0, −2.5 → −2, 3.5 → 4; each + 2.
    let got: Vec<f32> = first(&out).iter().map(|v| v[0]).collect();
    assert_eq!(got, [2.0, 3.0, 4.0, 0.0, 4.0, 2.0, 0.0, 6.0]);
}

#[test]
fn mova_rule_at_exact_halves() {
    use crate::core::emu::math::mova;
    let cases = [
        (0.5, 0),
        (-0.5, 0),
        (1.5, 2),
        (-1.5, -2),
        (2.5, 2),
        (-2.5, -2),
        (0.49999997, 0),
        (2.5000002, 3),
        (f32::NAN, 0),
        (3e9, i32::MAX),
        (-3e9, i32::MIN),
    ];
    for (x, want) in cases {
        assert_eq!(mova(x), want, "mova({x})");
    }
}

#[test]
fn relative_reads_outside_the_constants_read_zero() {
    let consts = [[7.0, 7.0, 7.0, 7.0]; 4];
    let text = "vs_2_0\ndcl_position v0\nmova a0.x, v0.x\nmov oPos, c[a0.x + 1]\n";
    // a0.x = -2 reads c-1, a0.x = 300 reads c301: both outside c0-c255.
    let out = run_text(
        text,
        &consts,
        &[[-2.0, 0.0, 0.0, 0.0], [300.0, 0.0, 0.0, 0.0], [0.0; 4]],
    );
    assert_eq!(first(&out), [[0.0; 4], [0.0; 4], [7.0; 4]]);
}

#[test]
fn lit_dst_sgn_slt_sge() {
    let text = "vs_2_0\ndcl_position v0\ndef c0, 9, 2, 3, 9\ndef c1, 9, 4, 9, 5\n\
                lit oT0, v0\nmov r2, c0\ndst oT1, r2, c1\nmov r0, c0\nmov r1, c0\nsgn oT2, v0, r0, r1\nslt oT3, v0, c1\nsge oT4, v0, c1\nmov oPos, v0\n";
    let out = run_text(text, &[], &[[0.5, 0.25, -3.0, 3.0], [-1.0, 2.0, 0.0, 0.0]]);
    let row = |v: usize, reg: &str| {
        let k = out.slots.iter().position(|s| s.register == reg).unwrap();
        out.values[v][k]
    };
    // lit: x = 1, y = src.x = 0.5, z = 0.25^3 = 0.015625, w = 1.
    assert_eq!(row(0, "oT0"), [1.0, 0.5, 0.015625, 1.0]);
    // lit with src.x <= 0: y = z = 0.
    assert_eq!(row(1, "oT0"), [1.0, 0.0, 0.0, 1.0]);
    // dst of r2 = c0 and c1: (1, 2 * 4, c0.z = 3, c1.w = 5).
    assert_eq!(row(0, "oT1"), [1.0, 8.0, 3.0, 5.0]);
    // sgn of (0.5, 0.25, -3, 3) and of (-1, 2, 0, 0).
    assert_eq!(row(0, "oT2"), [1.0, 1.0, -1.0, 1.0]);
    assert_eq!(row(1, "oT2"), [-1.0, 1.0, 0.0, 0.0]);
    // slt against (9, 4, 9, 5): 0.5<9, 0.25<4, -3<9, 3<5 all hold; sge is the opposite.
    assert_eq!(row(0, "oT3"), [1.0; 4]);
    assert_eq!(row(0, "oT4"), [0.0; 4]);
}

#[test]
fn expp_logp_sincos_and_matrices() {
    let text = "vs_2_0\ndcl_position v0\ndef c4, 1, 2, 3, 4\ndef c5, 0, 1, 0, 0\ndef c6, 0, 0, 1, 0\ndef c7, 0, 0, 0, 1\n\
                expp oT0, v0.x\nlogp oT1, v0.y\nsincos r0.xy, v0.z, c0, c1\nmov oT2, r0\nm4x4 oPos, v0, c4\nm3x2 oT3.xy, v0, c4\n";
    let out = run_text(text, &[], &[[3.0, 8.0, 0.0, 1.0]]);
    let row = |reg: &str| out.values[0][out.slots.iter().position(|s| s.register == reg).unwrap()];
    // expp 3 = 2^3 = 8 (vs_2_0's form writes every component); logp 8 = 3.
    assert_eq!(row("oT0"), [8.0; 4]);
    assert_eq!(row("oT1"), [3.0; 4]);
    // sincos of 0: x = cos 0 = 1, y = sin 0 = 0; z, w untouched (0).
    assert_eq!(row("oT2"), [1.0, 0.0, 0.0, 0.0]);
    // m4x4 with rows (1,2,3,4), e_y, e_z, e_w: x = 3 + 16 + 0 + 4 = 23.
    assert_eq!(row("oPos"), [23.0, 8.0, 0.0, 1.0]);
    // m3x2: two dot3 products, z and w not written.
    assert_eq!(row("oT3"), [19.0, 8.0, 0.0, 0.0]);
}

#[test]
fn loops_index_constants_and_outputs_by_al() {
    // vs_3_0: aL = 1, 2 (start 1, step 1, 2 iterations): o[aL] = v0 + c[aL].
    let text = "vs_3_0\ndefi i0, 2, 1, 1, 0\ndcl_position v0\ndcl_position o0\ndcl_texcoord0 o1\ndcl_texcoord1 o2\n\
                mov o0, v0\nloop aL, i0\nadd o[aL], v0, c[aL]\nendloop\n";
    let consts = [[0.0; 4], [10.0, 0.0, 0.0, 0.0], [0.0, 20.0, 0.0, 0.0]];
    let out = run_text(text, &consts, &[[1.0, 1.0, 1.0, 1.0]]);
    let names: Vec<(String, String)> = out
        .slots
        .iter()
        .map(|s| (s.register.clone(), s.semantic.as_ref().unwrap().to_string()))
        .collect();
    assert_eq!(names[1], ("o1".to_string(), "texcoord0".to_string()));
    assert_eq!(
        out.values[0],
        [[1.0; 4], [11.0, 1.0, 1.0, 1.0], [1.0, 21.0, 1.0, 1.0]]
    );
    // executed (the cost model's rule): mov 1, loop + add + endloop per
    // iteration: 2 * (3 + 1 + 2) = 12, so 13.
    assert_eq!(out.executed, [13]);
}

#[test]
fn predication_and_dynamic_branches_follow_each_vertex() {
    let text = "vs_2_x\ndcl_position v0\ndef c0, 0, 0, 0, 0\ndef c1, 5, 5, 5, 5\ndef c2, 7, 7, 7, 7\n\
                mov oPos, c0\nsetp_gt p0, v0, c0\n(p0) mov oPos, c1\nif_lt v0.y, c0.y\nmov oT0, c2\nelse\nmov oT0, c1\nendif\n";
    let out = run_text(text, &[], &[[1.0, -1.0, 1.0, -1.0], [-1.0, 1.0, -1.0, 1.0]]);
    // predicated per component: x, z > 0 for the first vertex, y, w for the second.
    assert_eq!(out.values[0][0], [5.0, 0.0, 5.0, 0.0]);
    assert_eq!(out.values[1][0], [0.0, 5.0, 0.0, 5.0]);
    assert_eq!(out.values[0][1], [7.0; 4]);
    assert_eq!(out.values[1][1], [5.0; 4]);
}

#[test]
fn inputs_are_bound_by_usage_and_index() {
    let options = Options::default();
    let text = "vs_2_0\ndcl_position v0\ndcl_texcoord2 v1\nmov oPos, v1\n";
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options).unwrap();
    let shader = load::load(file, &options).unwrap().shader;
    let attr = |usage: &str, index| Attribute {
        usage: usage.into(),
        index,
    };
    let mut vertices = Vertices {
        count: 1,
        attributes: vec![
            (attr("position", 0), vec![[1.0; 4]]),
            (attr("texcoord", 1), vec![[2.0; 4]]),
        ],
    };
    let e = run(&shader, &VertexDraw::default(), &vertices).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the shader reads v1 (dcl_texcoord2) and the vertex list has no texcoord2"
    );
    vertices
        .attributes
        .push((attr("texcoord", 2), vec![[3.0; 4]]));
    let out = run(&shader, &VertexDraw::default(), &vertices).unwrap();
    assert_eq!(out.values[0][0], [3.0; 4]);
}

#[test]
fn texldl_reads_the_level_its_w_names_through_the_sampler_swizzle() {
    use crate::core::emu::{MipChain, MipFilter};
    // Level 0 is 2×1: texel 0 = (1, 2, 3, 4), texel 1 = (5, 6, 7, 8);
    // level 1 is 1×1: (9, 10, 11, 12). Point filters, point mip filter.
    let chain = MipChain::from_levels(vec![
        (2, 1, vec![[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]]),
        (1, 1, vec![[9.0, 10.0, 11.0, 12.0]]),
    ])
    .unwrap();
    let state = SamplerState {
        mip_filter: MipFilter::Point,
        ..SamplerState::default()
    };
    let text = "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ndcl_texcoord0 o1\n\
                texldl o0, v0, s0\ntexldl o1, v0, s1\n";
    let options = Options::default();
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options);
    let loaded = load::load(file.unwrap(), &options);
    // s1 is not declared: Microsoft's assembler refuses that (X5577), so
    // the second read goes through s0 with a swizzle instead.
    assert!(loaded.is_err());
    let text = "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ndcl_texcoord0 o1\n\
                texldl o0, v0, s0\ntexldl o1, v0, s0.wzyx\n";
    let file = load::source_file("t.vsh", text.as_bytes().to_vec(), &options).unwrap();
    let shader = load::load(file, &options).unwrap().shader;
    let draw = VertexDraw {
        samplers: vec![(0, (&chain).into(), state)],
        ..VertexDraw::default()
    };
    let positions = vec![
        [0.25, 0.5, 0.0, 0.0],
        [0.75, 0.5, 0.0, 0.0],
        [0.75, 0.5, 0.0, 1.0],
    ];
    let vertices = Vertices {
        count: 3,
        attributes: vec![(
            Attribute {
                usage: "position".into(),
                index: 0,
            },
            positions,
        )],
    };
    let out = run(&shader, &draw, &vertices).unwrap();
    // u = 0.25 at LOD 0: texel 0; u = 0.75: texel 1; w = 1: level 1.
    assert_eq!(out.values[0][0], [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(out.values[1][0], [5.0, 6.0, 7.0, 8.0]);
    assert_eq!(out.values[2][0], [9.0, 10.0, 11.0, 12.0]);
    // the sampler's swizzle .wzyx reverses the texel
    assert_eq!(out.values[1][1], [8.0, 7.0, 6.0, 5.0]);
}
