//! 2×2 quads, gradients, mip selection and what divergence costs: the
//! semantics of the ps_3_0 instructions that depend on them, through the
//! public API (front end → validator → emulator), against values worked out
//! by hand in the comments.

use ps30::core::emu::{
    self, Address, Compiled, Draw, DrawOutput, Filter, LinearInput, MipChain, MipFilter,
    SamplerState, Texture,
};
use ps30::core::load::{load_str, Loaded, Options};

fn load(body: &str) -> Loaded {
    let src = format!("ps_3_0\n{body}\n");
    load_str("t.psh", &src, &Options::default())
        .unwrap_or_else(|e| panic!("{}", e.diagnostics.render(&e.file)))
}

fn compile(body: &str) -> Compiled {
    emu::compile(&load(body).shader).unwrap()
}

fn run(c: &Compiled, d: &Draw) -> DrawOutput {
    emu::run_with_threads(c, d, 1).unwrap()
}

fn red(out: &DrawOutput, i: usize) -> f32 {
    out.color[0].as_ref().unwrap()[i][0]
}

/// A 256×256 chain whose level i is filled with the value i (so a sample
/// tells which level it read), 9 levels.
fn numbered_levels() -> MipChain {
    let mut levels = Vec::new();
    let mut n = 256u32;
    let mut i = 0.0f32;
    loop {
        levels.push((n, n, vec![[i, 0.0, 0.0, 1.0]; (n * n) as usize]));
        if n == 1 {
            break;
        }
        n /= 2;
        i += 1.0;
    }
    MipChain::from_levels(levels).unwrap()
}

/// v0 = (x·sx + y·syx, x·sxy + y·sy, 0, w) in texture coordinates of a
/// 256-texel texture: sx texels per pixel along x, and so on.
fn stepping(sx: f32, sy: f32, w: f32) -> LinearInput {
    LinearInput {
        base: [0.5 / 256.0, 0.5 / 256.0, 0.0, w],
        ddx: [sx / 256.0, 0.0, 0.0, 0.0],
        ddy: [0.0, sy / 256.0, 0.0, 0.0],
    }
}

fn mips(mip: MipFilter) -> SamplerState {
    SamplerState {
        mip_filter: mip,
        address_u: Address::Wrap,
        address_v: Address::Wrap,
        address_w: Address::Wrap,
        ..SamplerState::filtered(Filter::Point)
    }
}

const TEXLD: &str = "dcl_texcoord0 v0
dcl_2d s0
texld r0, v0, s0
mov oC0, r0";

/// Runs a one-texture shader over an 8×8 target and returns every pixel's
/// red channel and the draw output.
fn sample_with(
    body: &str,
    chain: &MipChain,
    input: LinearInput,
    state: SamplerState,
    consts: Vec<[f32; 4]>,
) -> (Vec<f32>, DrawOutput) {
    let c = compile(body);
    let mut d = Draw::new(8, 8);
    if body.contains("dcl_texcoord0 v0") {
        d.inputs.push((0, input));
    }
    d.constants.float = consts;
    d.samplers.push((0, chain.into(), state));
    d.record_lod = true;
    let out = run(&c, &d);
    let reds = out.color[0]
        .as_ref()
        .unwrap()
        .iter()
        .map(|p| p[0])
        .collect();
    (reds, out)
}

// ----- level of detail --------------------------------------------------------

#[test]
fn texld_lod_is_log2_of_the_quad_gradient_in_texels() {
    let chain = numbered_levels();
    // 4 texels per pixel: |dX| = |dY| = 4, λ = log2 4 = 2 → level 2.
    let (reds, out) = sample_with(
        TEXLD,
        &chain,
        stepping(4.0, 4.0, 0.0),
        mips(MipFilter::Point),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 2.0), "{reds:?}");
    assert_eq!(out.gradients[0].lod, Some((2.0, 2.0)));
    // Isotropic: the larger of |dX| = 8 and |dY| = 1 decides: λ = 3.
    let (reds, out) = sample_with(
        TEXLD,
        &chain,
        stepping(8.0, 1.0, 0.0),
        mips(MipFilter::Point),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 3.0));
    assert_eq!(out.gradients[0].lod, Some((3.0, 3.0)));
    // Euclidean length: dX = (3, 4) texels is 5 long, λ = log2 5 = 2.32 → round → 2.
    let input = LinearInput {
        base: [0.0, 0.0, 0.0, 0.0],
        ddx: [3.0 / 256.0, 4.0 / 256.0, 0.0, 0.0],
        ddy: [0.0; 4],
    };
    let (reds, out) = sample_with(TEXLD, &chain, input, mips(MipFilter::Point), vec![]);
    assert!(reds.iter().all(|&r| r == 2.0));
    let (lo, hi) = out.gradients[0].lod.unwrap();
    assert_eq!(lo, hi);
    assert!((lo as f64 - 5f64.log2()).abs() < 1e-6, "{lo}");
    // Linear mip filter blends levels 2 and 3 by frac(λ): 2 + 0.3219.
    let (reds, _) = sample_with(TEXLD, &chain, input, mips(MipFilter::Linear), vec![]);
    for r in reds {
        assert!((r as f64 - 5f64.log2()).abs() < 1e-6, "{r}");
    }
    // 3 texels per pixel: λ = 1.585 → mip point rounds to 2.
    let (reds, _) = sample_with(
        TEXLD,
        &chain,
        stepping(3.0, 3.0, 0.0),
        mips(MipFilter::Point),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 2.0));
    // One texel per pixel or less: λ ≤ 0, magnification on level 0.
    let (reds, out) = sample_with(
        TEXLD,
        &chain,
        stepping(0.5, 1.0, 0.0),
        mips(MipFilter::Linear),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 0.0));
    assert_eq!(out.gradients[0].lod, Some((0.0, 0.0)));
}

#[test]
fn mip_filter_none_and_a_single_level_read_the_base_level() {
    let chain = numbered_levels();
    let (reds, out) = sample_with(
        TEXLD,
        &chain,
        stepping(16.0, 16.0, 0.0),
        mips(MipFilter::None),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 0.0));
    // The LOD is still what the gradients give.
    assert_eq!(out.gradients[0].lod, Some((4.0, 4.0)));
    let one = MipChain::from_levels(vec![(2, 2, vec![[5.0, 0.0, 0.0, 1.0]; 4])]).unwrap();
    let (reds, _) = sample_with(
        TEXLD,
        &one,
        stepping(16.0, 16.0, 0.0),
        mips(MipFilter::Point),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 5.0));
}

#[test]
fn texldb_adds_its_w_and_the_sampler_bias() {
    let chain = numbered_levels();
    let body = "dcl_texcoord0 v0
dcl_2d s0
texldb r0, v0, s0
mov oC0, r0";
    // λ = 2 from the gradients, w = -1: level 1.
    let (reds, out) = sample_with(
        body,
        &chain,
        stepping(4.0, 4.0, -1.0),
        mips(MipFilter::Point),
        vec![],
    );
    assert!(reds.iter().all(|&r| r == 1.0));
    assert_eq!(out.gradients[0].lod, Some((1.0, 1.0)));
    // ... and MIPMAPLODBIAS 1.5 on top: λ = 2.5, round(2.5) = 3.
    let state = SamplerState {
        mip_lod_bias: 1.5,
        ..mips(MipFilter::Point)
    };
    let (reds, out) = sample_with(body, &chain, stepping(4.0, 4.0, -1.0), state, vec![]);
    assert!(reds.iter().all(|&r| r == 3.0));
    assert_eq!(out.gradients[0].lod, Some((2.5, 2.5)));
}

#[test]
fn texldp_takes_gradients_of_the_projected_coordinate() {
    let chain = numbered_levels();
    let body = "dcl_texcoord0 v0
dcl_2d s0
texldp r0, v0, s0
mov oC0, r0";
    // v0 = 2·(u, v) with w = 2: after the division the step is 4 texels: λ = 2.
    let input = LinearInput {
        base: [1.0 / 256.0, 1.0 / 256.0, 0.0, 2.0],
        ddx: [8.0 / 256.0, 0.0, 0.0, 0.0],
        ddy: [0.0, 8.0 / 256.0, 0.0, 0.0],
    };
    let (reds, out) = sample_with(body, &chain, input, mips(MipFilter::Point), vec![]);
    assert!(reds.iter().all(|&r| r == 2.0));
    assert_eq!(out.gradients[0].lod, Some((2.0, 2.0)));
    // The same v0 through texld (no division): 8 texels, λ = 3.
    let (reds, _) = sample_with(TEXLD, &chain, input, mips(MipFilter::Point), vec![]);
    assert!(reds.iter().all(|&r| r == 3.0));
}

#[test]
fn texldd_uses_the_given_gradients_not_the_quads() {
    let chain = numbered_levels();
    let body = "dcl_texcoord0 v0
dcl_2d s0
texldd r0, v0, s0, c0, c0.zwzw
mov oC0, r0";
    // The quad steps 4 texels (λ 2), but ddx = c0.xy = 8 texels and
    // ddy = c0.zw = 2: λ = 3.
    let consts = vec![[8.0 / 256.0, 0.0, 0.0, 2.0 / 256.0]];
    let (reds, out) = sample_with(
        body,
        &chain,
        stepping(4.0, 4.0, 0.0),
        mips(MipFilter::Point),
        consts,
    );
    assert!(reds.iter().all(|&r| r == 3.0));
    assert!(
        out.gradients.is_empty(),
        "texldd takes no implicit gradients"
    );
}

#[test]
fn texldl_uses_w_and_honours_max_mip_level() {
    let chain = numbered_levels();
    let body = "dcl_2d s0
texldl r0, c0, s0
mov oC0, r0";
    let at = |w: f32, state: SamplerState| -> f32 {
        let (reds, out) = sample_with(
            body,
            &chain,
            stepping(1.0, 1.0, 0.0),
            state,
            vec![[0.3, 0.3, 0.0, w]],
        );
        assert!(out.gradients.is_empty(), "texldl takes no gradients");
        assert!(reds.iter().all(|&r| r == reds[0]));
        reds[0]
    };
    assert_eq!(at(2.7, mips(MipFilter::Point)), 3.0);
    assert_eq!(at(2.2, mips(MipFilter::Point)), 2.0);
    // Linear: levels 2 and 3 blended by frac(2.7) (f32 arithmetic of the rule).
    let t = 2.7f32 - 2.0;
    assert_eq!(at(2.7, mips(MipFilter::Linear)), 2.0 * (1.0 - t) + 3.0 * t);
    // Negative LOD: level 0; beyond the chain: the last level (8).
    assert_eq!(at(-3.0, mips(MipFilter::Linear)), 0.0);
    assert_eq!(at(100.0, mips(MipFilter::Linear)), 8.0);
    assert_eq!(at(f32::NAN, mips(MipFilter::Linear)), 0.0);
    // MAXMIPLEVEL 2: nothing more detailed than level 2.
    let clamp = |mip| SamplerState {
        max_mip_level: 2,
        ..mips(mip)
    };
    assert_eq!(at(0.0, clamp(MipFilter::Point)), 2.0);
    assert_eq!(at(1.0, clamp(MipFilter::Point)), 2.0);
    assert_eq!(at(3.2, clamp(MipFilter::Point)), 3.0);
    assert_eq!(at(5.0, clamp(MipFilter::None)), 2.0);
    // MAXMIPLEVEL beyond the chain: the last level.
    let far = SamplerState {
        max_mip_level: 40,
        ..mips(MipFilter::Point)
    };
    assert_eq!(at(0.0, far), 8.0);
}

#[test]
fn magnification_and_minification_filters_follow_the_lod() {
    // A 2×1 texture [0, 1]: at u = 0.5, linear filtering gives 0.5, point 1.
    let chain = MipChain::from_levels(vec![(
        2,
        1,
        vec![[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]],
    )])
    .unwrap();
    let state = SamplerState {
        mag_filter: Filter::Linear,
        min_filter: Filter::Point,
        address_u: Address::Clamp,
        address_v: Address::Clamp,
        address_w: Address::Clamp,
        ..SamplerState::default()
    };
    let at = |texels_per_pixel: f32| -> f32 {
        let input = LinearInput {
            base: [0.5, 0.5, 0.0, 0.0],
            ddx: [texels_per_pixel / 2.0, 0.0, 0.0, 0.0],
            ddy: [0.0; 4],
        };
        let (_, out) = sample_with(TEXLD, &chain, input, state, vec![]);
        red(&out, 0)
    };
    assert_eq!(at(0.5), 0.5, "λ = -1: MAGFILTER (linear)");
    assert_eq!(at(4.0), 1.0, "λ = 2: MINFILTER (point)");
}

#[test]
fn box_filtered_chains_average_what_they_cover() {
    // 4×4 texture, texel (x, y) = x + 4y; level 1 = 2×2 averages, level 2 = mean.
    let base: Vec<[f32; 4]> = (0..16).map(|i| [i as f32, 0.0, 0.0, 1.0]).collect();
    let chain = MipChain::build(
        Texture {
            width: 4,
            height: 4,
            texels: &base,
        },
        None,
    )
    .unwrap();
    let body = "dcl_2d s0
texldl r0, c0, s0
mov oC0, r0";
    let at = |u: f32, v: f32, lod: f32| {
        let (_, out) = sample_with(
            body,
            &chain,
            stepping(1.0, 1.0, 0.0),
            mips(MipFilter::Point),
            vec![[u, v, 0.0, lod]],
        );
        red(&out, 0)
    };
    assert_eq!(at(0.1, 0.1, 1.0), 2.5); // (0 + 1 + 4 + 5) / 4
    assert_eq!(at(0.9, 0.9, 1.0), 12.5); // (10 + 11 + 14 + 15) / 4
    assert_eq!(at(0.5, 0.5, 2.0), 7.5);
}

// ----- quads and divergence -----------------------------------------------------

/// v0 = (x, y, 0, 1) at pixel (x, y).
fn position() -> LinearInput {
    LinearInput {
        base: [0.0, 0.0, 0.0, 1.0],
        ddx: [1.0, 0.0, 0.0, 0.0],
        ddy: [0.0, 1.0, 0.0, 0.0],
    }
}

#[test]
fn gradients_in_divergent_quads_are_counted_per_source_line() {
    let l = load(
        "dcl_texcoord0 v0
dcl_2d s0
def c0, 0.5, 0, 0, 0
defi i0, 3, 0, 0, 0
mov r0, v0
if_lt v0.x, c0.x
  dsx r1, r0
  rep i0
    texld r2, r0, s0
  endrep
endif
dsx r3, r0
add r1, r1, r3
mov oC0, r1",
    );
    // The validator warns about the two under the if, not the one after it.
    let warned: Vec<usize> = l
        .warnings
        .items
        .iter()
        .map(|w| l.file.line_of(w.span.start))
        .collect();
    assert_eq!(warned, [8, 10]);
    let c = emu::compile(&l.shader).unwrap();
    let texels = [[1.0f32; 4]; 4];
    let mut d = Draw::new(4, 2);
    d.inputs.push((0, position()));
    d.samplers.push((
        0,
        Texture {
            width: 2,
            height: 2,
            texels: &texels,
        }
        .into(),
        SamplerState::default(),
    ));
    let out = run(&c, &d);
    // Quad 0 (x = 0, 1): only x = 0 takes the branch: divergent. Quad 1
    // (x = 2, 3): nobody does.
    let sites: Vec<(u64, u64, u64, u64, bool)> = out
        .gradients
        .iter()
        .map(|g| {
            (
                g.quads,
                g.divergent_quads,
                g.executions,
                g.divergent_executions,
                g.temp_source,
            )
        })
        .collect();
    assert_eq!(
        sites,
        [
            (1, 1, 1, 1, true), // dsx r1 under the if
            (1, 1, 3, 3, true), // texld, three iterations
            (2, 0, 2, 0, true), // dsx r3 after endif
        ]
    );
    assert_eq!(out.gradients[1].op, ps30::core::isa::Opcode::TexLd);
    assert_eq!(l.file.line_of(out.gradients[1].span.start), 10);
    // Inside the branch the inactive neighbour still holds r0 = v0 (written
    // before the if): dsx = 1 at the pixels that ran it; 1 + 1 there.
    assert_eq!(red(&out, 0), 2.0);
    assert_eq!(out.quad_divergent, [true, false]);
}

#[test]
fn texkill_in_a_divergent_quad_marks_pixels_that_keep_running() {
    let c = compile(
        "dcl_texcoord0 v0
def c0, 0.5, -1, 0, 0
mov r1, c0.y
if_lt v0.x, c0.x
  texkill r1
endif
mov r0, v0
dsx r2, r0
mov r0.z, r2.x
mov oC0, r0",
    );
    let mut d = Draw::new(4, 2);
    d.inputs.push((0, position()));
    let out = run(&c, &d);
    // x = 0 is discarded (both rows); everybody else survives.
    assert_eq!(
        out.killed,
        [true, false, false, false, true, false, false, false]
    );
    let c0 = out.color[0].as_ref().unwrap();
    assert_eq!(c0[0], [0.0; 4], "a discarded pixel reports zeros");
    // The killed lane kept running: its neighbour's dsx still sees it.
    assert_eq!(c0[1], [1.0, 0.0, 1.0, 1.0]);
    // Pixel costs (Microsoft's count): mov 1, if 3, texkill 1, endif 1,
    // then 4 × 1 and dsx 2.
    let killed = 1 + 3 + 1 + 1 + 1 + 2 + 1 + 1;
    let skipped = 1 + 3 + 1 + 1 + 2 + 1 + 1;
    assert_eq!(
        out.executed,
        [killed, skipped, skipped, skipped, killed, skipped, skipped, skipped]
    );
    // Quad 0 pays for texkill once (any lane ran it); quad 1 does not.
    assert_eq!(out.quad_executed, [killed, skipped]);
    assert_eq!(out.quad_divergent, [true, false]);
}

#[test]
fn a_quad_pays_for_every_path_its_pixels_take() {
    // Per pixel the cost model's counts; per quad the union of its paths.
    let c = compile(
        "dcl_texcoord0 v0
def c0, 1, 2, 0, 0
mov r0, c0.z
if_lt v0.x, c0.x
  add r0, r0, c0.x
  add r0, r0, c0.x
else
  if_lt v0.y, c0.x
    mul r0, r0, c0.y
  endif
endif
mov oC0, r0",
    );
    let mut d = Draw::new(2, 2);
    d.inputs.push((0, position()));
    let out = run(&c, &d);
    // (0,0): mov 1, if 3, add 2, else 1, endif 1, mov 1 = 9.
    // (1,0): mov 1, if 3, else 1, if 3, mul 1, endif 1, endif 1, mov 1 = 12.
    // (0,1): 9.   (1,1): like (1,0) without mul = 11.
    assert_eq!(out.executed, [9, 12, 9, 11]);
    // The quad: mov 1, if 3, add 2, else 1, if 3, mul 1, endif 1, endif 1, mov 1.
    assert_eq!(out.quad_executed, [14]);
    assert_eq!(out.quad_divergent, [true]);
    // A uniform quad pays what each pixel pays.
    let mut d = Draw::new(2, 2);
    d.inputs
        .push((0, LinearInput::constant([5.0, 5.0, 0.0, 0.0])));
    let out = run(&c, &d);
    assert_eq!(out.executed, [11; 4]);
    assert_eq!(out.quad_executed, [11]);
    assert_eq!(out.quad_divergent, [false]);
}

#[test]
fn helper_lanes_make_edge_quads_pay_for_their_paths() {
    // A 3×1 target: quad 1 holds pixel (2, 0) and three helpers; the
    // helper at x = 3 takes the branch, so the quad pays for it.
    let c = compile(
        "dcl_texcoord0 v0
def c0, 2.5, 1, 0, 0
mov r0, c0.z
if_gt v0.x, c0.x
  add r0, r0, c0.y
endif
mov oC0, r0",
    );
    let mut d = Draw::new(3, 1);
    d.inputs.push((0, position()));
    let out = run(&c, &d);
    assert_eq!(out.executed, [6, 6, 6]);
    assert_eq!(out.quads_x, 2);
    assert_eq!(out.quad_executed, [6, 7]);
    assert_eq!(out.quad_divergent, [false, true]);
}

// ----- flow control and predication -------------------------------------------------

#[test]
fn break_out_of_a_nested_rep_under_divergence() {
    // Pixel x leaves the inner rep after x + 1 iterations, three times.
    let c = compile(
        "dcl_texcoord0 v0
def c0, 1, 0, 0, 0
defi i0, 3, 0, 0, 0
defi i1, 4, 0, 0, 0
mov r0, c0.y
rep i0
  mov r1, c0.y
  rep i1
    add r1.x, r1.x, c0.x
    add r0.x, r0.x, c0.x
    break_ge r1.x, v0.x
  endrep
  add r0.y, r0.y, c0.x
endrep
mov oC0, r0",
    );
    let mut d = Draw::new(4, 1);
    d.inputs.push((
        0,
        LinearInput {
            base: [1.0, 0.0, 0.0, 0.0],
            ddx: [1.0, 0.0, 0.0, 0.0],
            ddy: [0.0; 4],
        },
    ));
    let out = run(&c, &d);
    let c0 = out.color[0].as_ref().unwrap();
    for (x, p) in c0.iter().enumerate() {
        assert_eq!(p[0], 3.0 * (x as f32 + 1.0), "x = {x}");
        assert_eq!(p[1], 3.0, "the outer rep goes on after each break");
    }
    // Inner: T = x + 1 iterations of rep 3 + add 1 + add 1 + break_ge 3, the
    // last one leaving before its endrep (2): 8T + 2(T - 1). Outer iteration:
    // rep 3 + mov 1 + inner + add 1 + endrep 2. Plus mov r0 and mov oC0.
    let expect = |t: u64| 1 + 3 * (3 + 1 + 8 * t + 2 * (t - 1) + 1 + 2) + 1;
    assert_eq!(out.executed, [expect(1), expect(2), expect(3), expect(4)]);
    // Each quad runs the inner loop until its slower pixel leaves: it pays
    // that pixel's path.
    assert_eq!(out.quad_executed, [expect(2), expect(4)]);
    assert_eq!(out.quad_divergent, [true, true]);
}

#[test]
fn loop_al_counts_down_through_relative_inputs() {
    let c = compile(
        "dcl_texcoord0 v0
dcl_texcoord1 v1
dcl_texcoord2 v2
defi i0, 3, 2, -1, 0
defi i1, 3, 1, -1, 0
def c0, 0, 10, 0, 0
mov r0, c0.x
mov r1, c0.x
loop aL, i0
  add r0.x, r0.x, v[aL].x
  mad r0.y, r0.y, c0.y, v[aL].y
endloop
loop aL, i1
  add r1.x, r1.x, v[aL].x
endloop
mov r0.z, r1.x
mov oC0, r0",
    );
    let mut d = Draw::new(1, 1);
    // v#.x = 1, 10, 100 and v#.y = # for v0, v1, v2.
    for (v, x) in [(0u32, 1.0f32), (1, 10.0), (2, 100.0)] {
        d.inputs
            .push((v, LinearInput::constant([x, v as f32, 0.0, 0.0])));
    }
    let out = run(&c, &d);
    let p = out.color[0].as_ref().unwrap()[0];
    // aL = 2, 1, 0: v2 + v1 + v0; the order shows in r0.y = ((0·10 + 2)·10 + 1)·10 + 0.
    assert_eq!(p[0], 111.0);
    assert_eq!(p[1], 210.0);
    // aL = 1, 0, -1: v[-1] is outside v0..v9 and reads 0 (ps30's choice;
    // Direct3D leaves it undefined).
    assert_eq!(p[2], 11.0);
}

#[test]
fn call_depth_is_four() {
    let nest = |depth: u32| {
        let mut s = String::from("def c0, 1, 0, 0, 0\nmov r0, c0.y\ncall l1\nmov oC0, r0\nret\n");
        for k in 1..=depth {
            s.push_str(&format!("label l{k}\nadd r0, r0, c0.x\n"));
            if k < depth {
                s.push_str(&format!("call l{}\n", k + 1));
            }
            s.push_str("ret\n");
        }
        s
    };
    let c = compile(&nest(4));
    let out = run(&c, &Draw::new(1, 1));
    assert_eq!(red(&out, 0), 4.0);
    // mov 1, four calls (2) with add 1 and ret 1 each, mov 1, ret 1.
    assert_eq!(out.executed, [1 + 4 * (2 + 1 + 1) + 1 + 1]);
    let src = format!("ps_3_0\n{}", nest(5));
    let e = load_str("deep.psh", &src, &Options::default()).unwrap_err();
    let text = e.diagnostics.render(&e.file);
    assert!(
        text.contains("calls nest 5 deep; ps_3_0 allows 4"),
        "{text}"
    );
}

#[test]
fn predicated_writes_follow_p0_per_component_and_per_pixel() {
    let c = compile(
        "dcl_texcoord0 v0
def c0, 1.5, 0, 0, 0
def c1, 7, 8, 9, 10
mov r0, c0.y
setp_gt p0, v0, c0.x
(p0) mov r0, c1
(!p0.x) add r0.y, r0.y, c1.x
mov oC0, r0",
    );
    let mut d = Draw::new(4, 1);
    // v0 = (x, 3 - x, 0, 2): p0 = (x > 1.5, x < 1.5, false, true).
    d.inputs.push((
        0,
        LinearInput {
            base: [0.0, 3.0, 0.0, 2.0],
            ddx: [1.0, -1.0, 0.0, 0.0],
            ddy: [0.0; 4],
        },
    ));
    let out = run(&c, &d);
    let c0 = out.color[0].as_ref().unwrap();
    assert_eq!(c0[0], [0.0, 15.0, 0.0, 10.0]);
    assert_eq!(c0[1], [0.0, 15.0, 0.0, 10.0]);
    assert_eq!(c0[2], [7.0, 0.0, 0.0, 10.0]);
    assert_eq!(c0[3], [7.0, 0.0, 0.0, 10.0]);
    // Predication masks writes, not execution: every pixel pays every
    // instruction, a predicated one 1 slot more; no quad diverges.
    assert_eq!(out.executed, [1 + 1 + 2 + 2 + 1; 4]);
    assert_eq!(out.quad_divergent, [false, false]);
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
    // Microsoft's validator counts a loop with a plain `break` (under a
    // static if) too (X6077), and so does ps30.
    assert_eq!(
        at("rep i0\ntexldp r1, r0, s0\nbreak_gt r1.x, c0.x\nendrep\nrep i0\ntexld r2, r0, s0\nif b0\nbreak\nendif\nendrep\nmov oC0, r1"),
        [2, 6]
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
    assert!(text.contains(
        "warning[X6077]: `texld` with a temporary coordinate under dynamic flow control"
    ));
    assert!(text.contains("t.psh:7:3"), "{text}");
    assert!(text.contains("the pixels of a quad can go different ways here"));
    assert!(text.contains("texldl"));
    assert_eq!(l.warnings.errors().count(), 0);
}
