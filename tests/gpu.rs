//! The GPU backend against the emulator: the same draws on both, compared
//! bit for bit where the arithmetic is exact, within a derived bound where
//! the device is allowed to differ, and through `compare` on the luminance
//! and tone-mapping shaders. Every test draws on the adapter
//! `common/gpu.rs` opens; without one it says it was skipped (and fails
//! under `CI`).

use crate::common::gpu as gpu_device;

use gpu_device::gpu;
use ps30::core::emu::{
    self, Address, Draw, DrawOutput, Face, Filter, LinearInput, MipChain, MipFilter, SamplerState,
    Texture,
};
use ps30::core::float_rules::FloatRules;
use ps30::core::gpu::{self as backend, Gpu, GpuOutput, TargetKind};
use ps30::core::image::{unorm8_value, Encoding, TargetFormat};
use ps30::core::load::{load_str, Options};

fn shader(src: &str) -> ps30::core::ir::Shader {
    load_str("test.psh", src, &Options::default())
        .unwrap_or_else(|e| panic!("{e}"))
        .shader
}

fn both(
    g: &Gpu,
    s: &ps30::core::ir::Shader,
    d: &Draw,
    kind: TargetKind,
) -> (DrawOutput, GpuOutput) {
    let e = emu::run(&emu::compile(s).unwrap(), d).unwrap();
    let o = backend::run(g, s, d, kind).unwrap();
    (e, o)
}

/// Bit equality, any NaN equal to any NaN (payloads are not values).
fn same(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan()
}

/// [`same`], but +0 = −0: Vulkan does not promise the sign of a zero
/// result unless a shader asks for SignedZeroInfNanPreserve, which neither
/// WGSL nor naga's SPIR-V do (llvmpipe gives +0 for −0 × 0).
fn same_value(a: f32, b: f32) -> bool {
    same(a, b) || a == 0.0 && b == 0.0
}

fn assert_same(what: &str, e: &[[f32; 4]], g: &[[f32; 4]], width: u32) {
    for (i, (a, b)) in e.iter().zip(g).enumerate() {
        for c in 0..4 {
            assert!(
                same(a[c], b[c]),
                "{what}: pixel ({}, {}) channel {c}: emulator {:e}, GPU {:e}",
                i as u32 % width,
                i as u32 / width,
                a[c],
                b[c]
            );
        }
    }
}

#[test]
fn inputs_and_vpos_arrive_as_the_emulator_computes_them() {
    let Some(g) = gpu("inputs_and_vpos_arrive_as_the_emulator_computes_them") else {
        return;
    };
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl vPos.xy\nmov oC0, v0\nmov oC1, vPos.xyxy\n");
    let mut d = Draw::new(7, 5);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.1, 0.2, 0.3, 0.4],
            ddx: [1.0 / 3.0, 0.0, 1e-3, 2.0],
            ddy: [0.0, 1.0 / 7.0, 1e-3, -2.0],
        },
    ));
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    assert_same(
        "v0",
        e.color[0].as_ref().unwrap(),
        o.color[0].as_ref().unwrap(),
        7,
    );
    assert_same(
        "vPos",
        e.color[1].as_ref().unwrap(),
        o.color[1].as_ref().unwrap(),
        7,
    );
}

/// A draw of at least 4 MB of inputs has them made on the device from one
/// term per column and one per row (`core/gpu/inputs.rs`): they must still
/// arrive as the emulator computes them, bit for bit. v0's terms allow the
/// device's sum (finite, no −0, none below 2⁻¹⁰³ but zero); v1's row terms
/// include −0 (0 · −2) and its column terms a subnormal, so v1's draw is
/// evaluated on the CPU as before — both must agree with the emulator.
#[test]
fn large_inputs_made_on_the_device_are_the_cpus_bits() {
    let Some(g) = gpu("large_inputs_made_on_the_device_are_the_cpus_bits") else {
        return;
    };
    let s = shader("ps_3_0\ndcl_texcoord0 v0\nmov oC0, v0\n");
    let (w, h) = (1024, 1024);
    let inputs = [
        LinearInput {
            base: [0.5 / 1024.0, 0.3, -7.25, 1e3],
            ddx: [1.0 / 1024.0, 0.0, 1.0 / 3.0, -2.0],
            ddy: [0.0, 1.0 / 7.0, 1e-3, 2.0],
        },
        LinearInput {
            base: [1e-40, 0.3, -7.25, 1e3],
            ddx: [0.0, 0.0, 1.0 / 3.0, -2.0],
            ddy: [0.0, 1.0 / 7.0, 1e-3, -2.0],
        },
    ];
    for (k, input) in inputs.into_iter().enumerate() {
        let mut d = Draw::new(w, h);
        d.inputs.push((0, input));
        let (e, o) = both(&g, &s, &d, TargetKind::Raw);
        assert_same(
            &format!("input {k}"),
            e.color[0].as_ref().unwrap(),
            o.color[0].as_ref().unwrap(),
            w,
        );
    }
}

/// `run_in_bands` hands on the frame one band of rows at a time, top band
/// first, each the rows `run` gives for it (the killing draw without its
/// depth output: a depth target is read back whole).
#[test]
fn a_frame_read_back_in_bands_is_the_whole_frame() {
    let Some(g) = gpu("a_frame_read_back_in_bands_is_the_whole_frame") else {
        return;
    };
    let (_, d) = killing_draw();
    let s = shader(
        "ps_3_0
dcl_texcoord0 v0
def c0, 0.5, 0.25, 0, 1
add r0, v0, -c0.x
texkill r0.xy
mov oC0, v0
mov oC1, r0
",
    );
    let whole = backend::run(&g, &s, &d, TargetKind::Raw).unwrap();
    let (w, h) = (whole.width, whole.height);
    let mut next = 0;
    backend::run_in_bands(&g, &s, &d, TargetKind::Raw, 3, &mut |y0, band| {
        assert_eq!((y0, band.width), (next, w));
        assert_eq!(band.height, 3.min(h - y0));
        let rows = (y0 * w) as usize..((y0 + band.height) * w) as usize;
        assert_eq!(band.killed, whole.killed[rows.clone()]);
        for k in 0..2 {
            assert_same(
                &format!("rows from {y0}, oC{k}"),
                &whole.color[k].as_ref().unwrap()[rows.clone()],
                band.color[k].as_ref().unwrap(),
                w,
            );
        }
        next += band.height;
        true
    })
    .unwrap();
    assert_eq!(next, h);
    // With depth, one band: the whole frame.
    let (s, d) = killing_draw();
    let mut bands = 0;
    backend::run_in_bands(&g, &s, &d, TargetKind::Raw, 3, &mut |y0, band| {
        assert_eq!((y0, band.height), (0, 8));
        bands += 1;
        true
    })
    .unwrap();
    assert_eq!(bands, 1);
}

/// Flow control, relative addressing, subroutines, predication, modifiers,
/// masks and `_sat` on values where every operation is exact (small
/// integers and halves): any correct device gives the emulator's bits,
/// fused or not, in any order.
#[test]
fn flow_control_and_exact_arithmetic_are_bit_identical() {
    let Some(g) = gpu("flow_control_and_exact_arithmetic_are_bit_identical") else {
        return;
    };
    let s = shader(
        "ps_3_0
dcl_texcoord0 v0
dcl_texcoord1 v1
dcl_texcoord2 v2
defi i0, 3, 0, 1, 0
defi i1, 4, 0, 0, 0
def c0, 0.5, -1, 2, 0
def c1, 1, 0, 0, 0
mov r0, c0.w
loop aL, i0
  add r0, r0, v[aL]
  rep i1
    mad r0.xy, r0.yxzw, c0.x, -c0.y
    break_gt r0.x, c0.z
  endrep
endloop
setp_ge p0.xz, v0, c0.x
(p0.x) mov r1, -r0_abs
(!p0.z) mov r1.yw, c0.zzzz
call l1
if_lt r0.y, c0.z
  callnz l2, !b0
else
  mov r2, c1
endif
cmp oC0, r1, r2, -r2
mov_sat oC1, r0.wzyx
ret
label l1
mul r2, r0, c0.x
ret
label l2
add r2, r2, c0.yyyy
ret
",
    );
    let mut d = Draw::new(9, 7);
    for (v, step) in [(0u32, 0.5f32), (1, -1.0), (2, 2.0)] {
        d.inputs.push((
            v,
            LinearInput {
                base: [-2.0, 1.5, 0.5, -0.5],
                ddx: [step, 0.0, 0.5, 0.0],
                ddy: [0.0, step, 0.0, 1.0],
            },
        ));
    }
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    for k in 0..2 {
        assert_same(
            &format!("oC{k}"),
            e.color[k].as_ref().unwrap(),
            o.color[k].as_ref().unwrap(),
            9,
        );
    }
}

/// Vulkan's precision (the SPIR-V environment's table of precisions) for
/// the instruction behind each output channel of
/// `special_values_follow_each_float_rule_on_both_backends`, in ulp, for
/// ordinary inputs (±4 and 0.25 there), plus the emulator's own error
/// (1 ulp for log2, inversesqrt and exp2; division exact): oC0 = log2
/// (3 ulp outside [0.5, 2], where 4 and 0.25 lie: 3 + 1), inversesqrt
/// (2 ulp: 2 + 1), 1/x (2.5 ulp, 2 in whole ulp), exp2 (3 + 2·|x| ulp,
/// |x| ≤ 4: 11 + 1). oC1 and oC2 hold pow with a zero operand, frc, mul,
/// mad and dp3 by 0 and nrm of a zero vector: exact results, no allowance.
/// An H100 gives log2(0.25) = −1.9999999 (1 ulp), which this allows;
/// llvmpipe is exact there.
const VULKAN_ULP: [[u32; 4]; 3] = [[4, 3, 2, 12], [0; 4], [0; 4]];

/// Distance in units in the last place between two finite values of the
/// same sign (`u32::MAX` across signs, zeros excepted).
fn ulp_distance(a: f32, b: f32) -> u32 {
    if a == 0.0 && b == 0.0 {
        return 0;
    }
    if a.is_sign_negative() != b.is_sign_negative() {
        return u32::MAX;
    }
    a.to_bits().abs_diff(b.to_bits())
}

/// What every float rule says of the special values, on both backends.
/// Inputs come from a texture (column k holds input k); the shader writes
/// one instruction's result per output. Subnormal inputs are left out:
/// devices flush them (the probes of `ps30 compare` measure that).
#[test]
fn special_values_follow_each_float_rule_on_both_backends() {
    let Some(g) = gpu("special_values_follow_each_float_rule_on_both_backends") else {
        return;
    };
    let inputs = [
        0.0,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        -4.0,
        4.0,
        0.25,
    ];
    let texels: Vec<[f32; 4]> = inputs.iter().map(|&x| [x, 0.0, 0.0, x]).collect();
    let s = shader(
        "ps_3_0
dcl_texcoord0 v0.xy
dcl_2d s0
texld r0, v0, s0
log r1.x, r0.x
rsq r1.y, r0.x
rcp r1.z, r0.x
exp r1.w, r0.x
mov oC0, r1
pow r2.x, r0.x, c0.x
pow r2.y, c0.x, r0.x
frc r2.z, r0.x
mul r2.w, r0.x, c0.x
mov oC1, r2
nrm r3, r0.yyzx
mad r4, r0.x, c0.x, c0.y
mov r3.y, r4.x
dp3 r3.z, r0.x, c0.x
mov oC2, r3
",
    );
    for rules in FloatRules::ALL {
        let mut d = Draw::new(inputs.len() as u32, 1);
        d.float_rules = rules;
        // c0 comes from the application, not a `def`: a compiler that sees a
        // constant 0 may fold 0 × ∞ to 0 (Vulkan does not promise ∞ and NaN
        // survive; `ps30 compare`'s probes show llvmpipe doing it).
        d.constants.float = vec![[0.0, 1.0, 2.0, 0.5]];
        d.inputs.push((
            0,
            LinearInput {
                base: [0.5 / inputs.len() as f32, 0.5, 0.0, 0.0],
                ddx: [1.0 / inputs.len() as f32, 0.0, 0.0, 0.0],
                ddy: [0.0; 4],
            },
        ));
        d.samplers.push((
            0,
            Texture {
                width: inputs.len() as u32,
                height: 1,
                texels: &texels,
            }
            .into(),
            SamplerState {
                address_u: Address::Clamp,
                address_v: Address::Clamp,
                address_w: Address::Clamp,
                ..SamplerState::filtered(Filter::Point)
            },
        ));
        let (e, o) = both(&g, &s, &d, TargetKind::Raw);
        let (e0, g0) = (e.color[0].as_ref().unwrap(), o.color[0].as_ref().unwrap());
        // The rules' own statements, at x = 0 (column 0) and x = -4 (5).
        let log0 = e0[0][0];
        match rules {
            FloatRules::Ieee => {
                assert_eq!(log0, f32::NEG_INFINITY, "ieee log(0)");
                assert!(e0[5][0].is_nan(), "ieee log(-4)");
                assert!(e0[5][1].is_nan(), "ieee rsq(-4)");
            }
            _ => {
                assert_eq!(log0, -f32::MAX, "{rules} log(0)");
                assert_eq!(e0[5][0], 2.0, "{rules} log(-4) = log2 4");
                assert_eq!(e0[5][1], 0.5, "{rules} rsq(-4)");
            }
        }
        let e1 = e.color[1].as_ref().unwrap();
        let mul_inf_zero = e1[2][3];
        if rules.zero_mul() {
            assert_eq!(mul_inf_zero, 0.0, "0 × ∞ under {rules}");
        } else {
            assert!(mul_inf_zero.is_nan(), "{rules}: 0 × ∞ is NaN");
        }
        for (k, ulp) in VULKAN_ULP.iter().enumerate() {
            let (ec, gc) = (e.color[k].as_ref().unwrap(), o.color[k].as_ref().unwrap());
            for (i, (a, b)) in ec.iter().zip(gc).enumerate() {
                for c in 0..4 {
                    if inputs[i].is_nan() {
                        // Vulkan does not promise NaN survives either (no
                        // SignedZeroInfNanPreserve): llvmpipe gives
                        // pow(0, NaN) = 0. Shown, not judged.
                        if !same_value(a[c], b[c]) {
                            eprintln!(
                                "{rules} oC{k} channel {c} of NaN: emulator {:e}, GPU {:e}",
                                a[c], b[c]
                            );
                        }
                        continue;
                    }
                    // Ordinary inputs with finite results: the device's
                    // precision, which Vulkan bounds per instruction;
                    // everything else (the special values this test is
                    // about) bit for bit.
                    let ordinary = inputs[i].is_finite() && inputs[i] != 0.0;
                    let allowed = if ordinary && a[c].is_finite() && b[c].is_finite() {
                        ulp[c]
                    } else {
                        0
                    };
                    assert!(
                        same_value(a[c], b[c]) || ulp_distance(a[c], b[c]) <= allowed,
                        "{rules} oC{k}: input {:e}, channel {c}: emulator {:e}, GPU {:e} ({allowed} ulp allowed)",
                        inputs[i],
                        a[c],
                        b[c]
                    );
                }
            }
        }
        let _ = g0;
    }
}

/// A 4×4 texture sampled across [−1.3, 2.3] with every address mode and
/// both filters. Coordinates never fall on a texel edge, so point sampling
/// picks the same texel on both backends and must match bit for bit.
/// Linear filtering may differ by the device's weight precision: Vulkan
/// requires at least 4 bits of sub-texel precision, so each axis's weight
/// may be off by up to 2⁻⁵, and with texel values in [0, 1] a sample by at
/// most 2 · 2⁻⁵ = 1/16 (plus a few f32 roundings, covered by 2⁻²⁰).
#[test]
fn sampler_address_modes_and_filters_at_the_edges() {
    let Some(g) = gpu("sampler_address_modes_and_filters_at_the_edges") else {
        return;
    };
    let texels: Vec<[f32; 4]> = (0..16)
        .map(|i| {
            let f = i as f32 / 15.0;
            [f, 1.0 - f, (i % 4) as f32 / 3.0, 1.0]
        })
        .collect();
    let s = shader("ps_3_0\ndcl_texcoord0 v0.xy\ndcl_2d s0\ntexld r0, v0, s0\nmov oC0, r0\n");
    let modes = [
        (Address::Wrap, [0.0; 4]),
        (Address::Mirror, [0.0; 4]),
        (Address::Clamp, [0.0; 4]),
        (Address::Border, [0.0; 4]),
        (Address::Border, [1.0, 1.0, 1.0, 1.0]),
        (Address::Border, [0.25, 0.5, 0.75, 1.0]),
        (Address::MirrorOnce, [0.0; 4]),
    ];
    for (mode, border) in modes {
        for filter in [Filter::Point, Filter::Linear] {
            let mut d = Draw::new(24, 24);
            // u = −1.3 + 0.15·x: u·4 = −5.2 + 0.6·x is never an integer
            // (nor, for linear, u·4 − ½ — whose fraction is what matters).
            d.inputs.push((
                0,
                LinearInput {
                    base: [-1.3, -1.3, 0.0, 0.0],
                    ddx: [0.15, 0.0, 0.0, 0.0],
                    ddy: [0.0, 0.15, 0.0, 0.0],
                },
            ));
            d.samplers.push((
                0,
                Texture {
                    width: 4,
                    height: 4,
                    texels: &texels,
                }
                .into(),
                SamplerState {
                    address_u: mode,
                    address_v: mode,
                    address_w: mode,
                    border,
                    ..SamplerState::filtered(filter)
                },
            ));
            let (e, o) = both(&g, &s, &d, TargetKind::Raw);
            let (ec, gc) = (e.color[0].as_ref().unwrap(), o.color[0].as_ref().unwrap());
            let what = format!("{mode:?} {border:?} {filter:?}");
            match filter {
                Filter::Point => assert_same(&what, ec, gc, 24),
                Filter::Linear => {
                    for (i, (a, b)) in ec.iter().zip(gc).enumerate() {
                        for c in 0..4 {
                            assert!(
                                (a[c] - b[c]).abs() <= 1.0 / 16.0 + 2f32.powi(-20),
                                "{what}: pixel {i} channel {c}: emulator {}, GPU {}",
                                a[c],
                                b[c]
                            );
                        }
                    }
                }
            }
        }
    }
}

/// A mip chain read at explicit levels of detail (texldl) and with given
/// gradients (texldd along one axis, where every formula for the gradient's
/// length agrees): MIPFILTER NONE/POINT/LINEAR, MAXMIPLEVEL and
/// MIPMAPLODBIAS. λ avoids k + ½ (where Vulkan rounds down and D3D9 up).
/// Between levels the device may quantise frac(λ) (Vulkan: at least 4
/// bits), so linear mip filtering may be off by 2⁻⁵ of the two levels'
/// difference (texels in [0, 1]: ≤ 1/32, plus 2⁻²⁰ for roundings).
#[test]
fn mip_levels_bias_and_max_mip_level() {
    let Some(g) = gpu("mip_levels_bias_and_max_mip_level") else {
        return;
    };
    let texels: Vec<[f32; 4]> = (0..64)
        .map(|i| {
            let (x, y) = (i % 8, i / 8);
            [(x ^ y) as f32 / 7.0, x as f32 / 7.0, y as f32 / 7.0, 1.0]
        })
        .collect();
    let chain = MipChain::build(
        Texture {
            width: 8,
            height: 8,
            texels: &texels,
        },
        None,
    )
    .unwrap();
    let texldl = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ntexldl r0, v0, s0\nmov oC0, r0\n");
    let texldd = shader(
        "ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ndef c0, 0.3, 0, 0, 0\ndef c1, 0, 0, 0, 0\nmul r1, c0, v0.w\ntexldd r0, v0, s0, r1, c1\nmov oC0, r0\n",
    );
    for mip in [MipFilter::None, MipFilter::Point, MipFilter::Linear] {
        for (max_level, bias) in [(0, 0.0), (1, 0.0), (0, 0.35)] {
            for s in [&texldl, &texldd] {
                let mut d = Draw::new(16, 4);
                // w (the LOD, or the gradient's scale) from −0.8 in 0.3 steps.
                d.inputs.push((
                    0,
                    LinearInput {
                        base: [0.03, 0.07, 0.0, -0.8],
                        ddx: [0.061, 0.0, 0.0, 0.3],
                        ddy: [0.0, 0.23, 0.0, 0.0],
                    },
                ));
                d.samplers.push((
                    0,
                    (&chain).into(),
                    SamplerState {
                        mip_filter: mip,
                        max_mip_level: max_level,
                        mip_lod_bias: bias,
                        address_u: Address::Wrap,
                        address_v: Address::Wrap,
                        address_w: Address::Wrap,
                        ..SamplerState::filtered(Filter::Point)
                    },
                ));
                let (e, o) = both(&g, s, &d, TargetKind::Raw);
                let (ec, gc) = (e.color[0].as_ref().unwrap(), o.color[0].as_ref().unwrap());
                let what = format!("{mip:?} MAXMIPLEVEL {max_level} bias {bias}");
                for (i, (a, b)) in ec.iter().zip(gc).enumerate() {
                    for c in 0..4 {
                        let ok = match mip {
                            MipFilter::Linear => (a[c] - b[c]).abs() <= 1.0 / 32.0 + 2f32.powi(-20),
                            _ => same(a[c], b[c]),
                        };
                        assert!(
                            ok,
                            "{what}: pixel {i} channel {c}: emulator {}, GPU {}",
                            a[c], b[c]
                        );
                    }
                }
            }
        }
    }
}

/// texkill, two colour outputs and oDepth: the killed pixels, the colours
/// (zero where killed, as the emulator reports them) and the depth.
/// Two outputs and depth from a shader that kills the pixels left of or
/// above the middle of an 8×8 target.
fn killing_draw() -> (ps30::core::ir::Shader, Draw<'static>) {
    let s = shader(
        "ps_3_0
dcl_texcoord0 v0
def c0, 0.5, 0.25, 0, 1
add r0, v0, -c0.x
texkill r0.xy
mov oC0, v0
mov oC1, r0
mov oDepth, v0.y
",
    );
    let mut d = Draw::new(8, 8);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.0625, 0.0625, 0.0, 1.0],
            ddx: [0.125, 0.0, 0.0, 0.0],
            ddy: [0.0, 0.125, 0.0, 0.0],
        },
    ));
    (s, d)
}

#[test]
fn texkill_several_outputs_and_depth() {
    let Some(g) = gpu("texkill_several_outputs_and_depth") else {
        return;
    };
    let (s, d) = killing_draw();
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    assert_eq!(e.killed, o.killed);
    assert!(e.killed.iter().any(|&k| k) && e.killed.iter().any(|&k| !k));
    for k in 0..2 {
        assert_same(
            &format!("oC{k}"),
            e.color[k].as_ref().unwrap(),
            o.color[k].as_ref().unwrap(),
            8,
        );
    }
    // Depth in [0, 1] is stored exactly by a Depth32Float target.
    assert_eq!(e.depth, o.depth);
}

/// Non-finite constants from a `def` (rebuilt from their bits by the
/// translation) and from the application, and `texkill` on `.w` alone, on
/// both backends. Expected by hand: rcp(+inf) = +0 and rcp(+0) = +inf
/// (`rcp` page: 1/0 = +inf), rcp(-inf) = -0 and rcp(-0) = -inf; a NaN
/// moved through survives as a NaN; w = -1 kills every pixel of the second
/// draw.
#[test]
fn non_finite_constants_and_texkill_on_w() {
    let Some(g) = gpu("non_finite_constants_and_texkill_on_w") else {
        return;
    };
    let s = shader(
        "ps_3_0
def c1, 1.#INF, -1.#INF, -1.#IND, 1
rcp r0.x, c0.x
rcp r0.y, r0.x
rcp r0.z, c1.y
rcp r0.w, r0.z
mov oC0, r0
mov oC1, c1
mov oC2, c0
",
    );
    let mut d = Draw::new(2, 2);
    d.constants.float = vec![[f32::INFINITY, f32::NAN, f32::from_bits(0x7f80_0001), -0.0]];
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    let want0 = [0.0, f32::INFINITY, -0.0, f32::NEG_INFINITY];
    for out in [&e.color, &o.color] {
        for px in out[0].as_ref().unwrap() {
            for c in 0..4 {
                assert_eq!(px[c].to_bits(), want0[c].to_bits(), "oC0.{c}: {px:?}");
            }
        }
        let c1 = out[1].as_ref().unwrap()[0];
        assert_eq!(
            (c1[0], c1[1], c1[3]),
            (f32::INFINITY, f32::NEG_INFINITY, 1.0)
        );
        assert!(c1[2].is_nan());
        let c0 = out[2].as_ref().unwrap()[0];
        assert!(c0[0] == f32::INFINITY && c0[1].is_nan() && c0[2].is_nan());
    }
    let s = shader("ps_3_0\ndef c0, 1, 1, 1, -1\nmov r0, c0\ntexkill r0\nmov oC0, r0\n");
    let (e, o) = both(&g, &s, &Draw::new(2, 2), TargetKind::Raw);
    assert_eq!(e.killed, vec![true; 4]);
    assert_eq!(o.killed, vec![true; 4]);
}

/// The `hardware` rules on both backends, expected by hand: a denormal
/// constant (2^-149) reads as 0, 2^-126 × 0.5 = 2^-127 is written as 0,
/// 0 × inf = 0 (the constants come from the application, so no compiler
/// can fold them).
#[test]
fn hardware_rules_flush_denormals_on_both_backends() {
    let Some(g) = gpu("hardware_rules_flush_denormals_on_both_backends") else {
        return;
    };
    let s = shader(
        "ps_3_0
mov r0.x, c0.x
mov r1, c1
mul r0.y, c0.y, r1.x
mul r0.z, c0.z, c0.w
mov r0.w, c1.x
mov oC0, r0
",
    );
    let mut d = Draw::new(2, 2);
    d.float_rules = FloatRules::Hardware;
    d.constants.float = vec![
        [f32::from_bits(1), f32::MIN_POSITIVE, f32::INFINITY, 0.0],
        [0.5, 0.0, 0.0, 0.0],
    ];
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    for out in [&e.color, &o.color] {
        for px in out[0].as_ref().unwrap() {
            assert_eq!(px.map(f32::to_bits), [0, 0, 0, 0.5f32.to_bits()]);
        }
    }
}

/// A draw prepared once (pipeline compiled, targets allocated) and drawn
/// three times gives `run`'s output every time: killed pixels, both
/// colours bit for bit, depth.
#[test]
fn a_prepared_draw_gives_runs_output_each_time() {
    let Some(g) = gpu("a_prepared_draw_gives_runs_output_each_time") else {
        return;
    };
    let (s, d) = killing_draw();
    let once = backend::run(&g, &s, &d, TargetKind::Raw).unwrap();
    let ready = backend::prepare(&g, &s, &d, TargetKind::Raw).unwrap();
    for time in 0..3 {
        let again = ready.draw().unwrap();
        assert_eq!(once.killed, again.killed, "draw {time}");
        for k in 0..2 {
            assert_same(
                &format!("draw {time}, oC{k}"),
                once.color[k].as_ref().unwrap(),
                again.color[k].as_ref().unwrap(),
                8,
            );
        }
        assert_eq!(once.depth, again.depth, "draw {time}");
    }
}

/// A texture wider than any device allows is refused by `prepare` with an
/// error, not a panic: the error scopes the setup opened are closed in
/// order when it stops early (wgpu panics on scopes popped out of order).
#[test]
fn an_oversized_texture_is_an_error_from_prepare() {
    let Some(g) = gpu("an_oversized_texture_is_an_error_from_prepare") else {
        return;
    };
    let wide = 65_537; // Vulkan devices give at most 65,536 texels a side
    let texels = vec![[0.5f32; 4]; wide];
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ntexld r0, v0, s0\nmov oC0, r0\n");
    let mut d = Draw::new(2, 2);
    d.inputs
        .push((0, LinearInput::constant([0.5, 0.5, 0.0, 0.0])));
    let texture = Texture {
        width: wide as u32,
        height: 1,
        texels: &texels,
    };
    d.samplers
        .push((0, texture.into(), SamplerState::filtered(Filter::Point)));
    let e = backend::prepare(&g, &s, &d, TargetKind::Raw)
        .err()
        .expect("a 65,537-texel-wide texture is refused");
    assert!(e.to_string().contains("65537×1 texture"), "{e}");
}

/// `Gpu::open_cpu` opens a CPU device (llvmpipe), the speed benchmark's
/// peer, even where `Gpu::open` would take a real GPU.
#[test]
fn the_cpu_adapter_is_a_cpu_device() {
    match Gpu::open_cpu() {
        Ok(g) => assert_eq!(g.info().device_type, "Cpu", "{}", g.info().line()),
        Err(e) if std::env::var_os("CI").is_some() => {
            panic!("CI is set, so a CPU Vulkan adapter (llvmpipe) must open: {e}")
        }
        Err(e) => {
            use std::io::Write;
            let _ = writeln!(
                std::io::stderr(),
                "the_cpu_adapter_is_a_cpu_device: skipped: {e}"
            );
        }
    }
}

#[test]
fn vface_is_negative_on_a_back_facing_draw() {
    let Some(g) = gpu("vface_is_negative_on_a_back_facing_draw") else {
        return;
    };
    let s = shader("ps_3_0\ndcl vFace\ndef c0, 1, 0, 0, 1\ndef c1, 0, 1, 0, 1\nif_lt vFace, c0.y\nmov r0, c1\nelse\nmov r0, c0\nendif\nmov oC0, r0\n");
    for face in [Face::Front, Face::Back] {
        let mut d = Draw::new(3, 2);
        d.face = face;
        let (e, o) = both(&g, &s, &d, TargetKind::Raw);
        assert_same(
            &format!("{face:?}"),
            e.color[0].as_ref().unwrap(),
            o.color[0].as_ref().unwrap(),
            3,
        );
    }
}

/// dsx/dsy of a linear input: every pixel of a quad sees the same exact
/// difference, whichever pixels a device's coarse derivative uses.
#[test]
fn derivatives_of_linear_inputs_match() {
    let Some(g) = gpu("derivatives_of_linear_inputs_match") else {
        return;
    };
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndsx r0, v0\ndsy r1, v0\nmov oC0, r0\nmov oC1, r1\n");
    let mut d = Draw::new(6, 6);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.5, -1.0, 2.0, 0.0],
            ddx: [0.25, 0.0, -2.0, 1.0],
            ddy: [0.0, 0.5, 1.0, 4.0],
        },
    ));
    let (e, o) = both(&g, &s, &d, TargetKind::Raw);
    for k in 0..2 {
        assert_same(
            &format!("oC{k}"),
            e.color[k].as_ref().unwrap(),
            o.color[k].as_ref().unwrap(),
            6,
        );
    }
}

/// Every render-target format: the 32-bit float formats store each
/// channel exactly; the half formats round to the nearest half (ties to
/// even, as `TargetFormat::round`) or toward zero: Vulkan leaves that
/// choice to the implementation for colour attachments, and llvmpipe
/// rounds toward zero (the f16 subnormals here show it). D3DFMT_A8R8G8B8
/// (`Rgba8Unorm`) stores clamp(v)·255 as one of the two nearest codes
/// (Vulkan's float-to-UNORM conversion: "one of the two unsigned binary
/// integer values … closest", nearest preferred), where the emulator takes
/// the nearest of the exact product, half up (D3D10's rule). llvmpipe
/// rounds the product computed in f32, ties to even: for v = 0.3f
/// (v·255 = 76.500003, 76.5 in f32) it stores 76 where the emulator
/// stores 77, for v = 0.9f (229.499994, 229.5 in f32) 230 where the
/// emulator stores 229 — one code, inside Vulkan's rule, and the two
/// differences this draw shows. Channels a format does not store read
/// back as 1.
#[test]
fn target_formats_round_as_the_emulator_stores() {
    let Some(g) = gpu("target_formats_round_as_the_emulator_stores") else {
        return;
    };
    let s = shader("ps_3_0\ndcl_texcoord0 v0\nmov oC0, v0\n");
    let mut d = Draw::new(16, 16);
    d.inputs.push((
        0,
        LinearInput {
            base: [1.0001, -3.3e-5, 70000.0, 0.1],
            ddx: [0.000_37, 1.7e-6, 113.0, 0.01],
            ddy: [0.013, -2.1e-7, -97.0, 0.1],
        },
    ));
    for format in TargetFormat::ALL {
        let (e, o) = both(&g, &s, &d, TargetKind::Format(format));
        let mut other_rounding = 0;
        for (raw, got) in e.color[0]
            .as_ref()
            .unwrap()
            .iter()
            .zip(o.color[0].as_ref().unwrap())
        {
            for c in 0..4 {
                let ours = format.round(*raw)[c];
                let allowed = if !format.stores(c) {
                    [1.0, 1.0]
                } else {
                    match format.encoding() {
                        Encoding::Float => [raw[c], raw[c]],
                        Encoding::Half => [ours, f16_toward_zero(raw[c])],
                        Encoding::Unorm8 => {
                            let x = raw[c].clamp(0.0, 1.0) as f64 * 255.0;
                            [x.floor(), x.ceil()].map(|k| unorm8_value(k as u8))
                        }
                    }
                };
                assert!(
                    allowed.iter().any(|&a| same(got[c], a)),
                    "{}: channel {c}: {:e} stored as {:e}; allowed {allowed:?}",
                    format.d3d_name(),
                    raw[c],
                    got[c],
                );
                other_rounding += (!same(got[c], ours)) as u32;
            }
        }
        eprintln!(
            "{}: {other_rounding} values rounded otherwise than the emulator stores them",
            format.d3d_name()
        );
    }
}

/// `x` rounded toward zero to a half (finite halves only; beyond 65,504
/// it stays at 65,504, as round-toward-zero does).
fn f16_toward_zero(x: f32) -> f32 {
    let n = half::f16::from_f32(x);
    if n.to_f32().abs() > x.abs() || n.is_infinite() {
        // The nearest half is farther from zero: step one half toward it.
        // (Halves are sign and magnitude: one less is one step nearer 0;
        // one less than ∞ is 65,504.)
        half::f16::from_bits(n.to_bits() - 1).to_f32()
    } else {
        n.to_f32()
    }
}

/// `ps30 compare` on the luminance pipeline and on tone mapping: both
/// backends agree with the f64 reference within the derived bounds, and
/// every difference is explained by the probes (no finding).
#[test]
fn compare_explains_the_luminance_and_tone_mapping_differences() {
    let Some(g) = gpu("compare_explains_the_luminance_and_tone_mapping_differences") else {
        return;
    };
    use ps30::jobs::compare::{self, all, explain, probe};
    use ps30::jobs::luminance::{Settings, ShaderSource};
    let probes = probe::run(&g).unwrap();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr/forest.hdr");
    let img = ps30::core::image::load(&path, &Default::default()).unwrap();
    let b = |x: ps30::jobs::bundled::Bundled| ShaderSource::new(x.path, x.text);
    let c = compare::compare_luminance(
        &g,
        ("forest.hdr", &img),
        &b(ps30::jobs::bundled::CORRECTED_UNROLLED),
        None,
        &b(ps30::jobs::bundled::CORRECTED_PASS2),
        &Settings::default(),
    )
    .unwrap();
    assert!(c.gpu_agrees && c.emulator_agrees);
    let why = explain::luminance(&c, &probes);
    assert!(!why.finding, "{}", why.text);
    let t = all::compare_tonemap(&g, "forest.hdr", &img).unwrap();
    assert_eq!(t.gpu_within, t.pixels);
    let why = explain::tonemap(&t, &probes);
    assert!(!why.finding, "{}", why.text);
}
