//! Instruction probes: one instruction at a time on the emulator and on the
//! device, over 4,096 chosen inputs, each result also compared with the
//! correctly rounded value (f64, then rounded to f32). They say, for this
//! device, which instructions give the emulator's bits, which are less or
//! more accurate, whether `mad` is fused, in which order `dp4` adds, and
//! whether subnormals survive — the causes every shader-level difference
//! is traced to.
//!
//! Each probe is a ps_3_0 shader: `texld` reads the inputs from a 64×64
//! texture at texel centres (point sampling, so both backends read the same
//! bits), the instruction runs, `oC0` takes the result; the target is
//! unrounded f32. Inputs: the first 16 texels hold special values (±0, ±∞,
//! NaN, ±FLT_MAX, subnormals, 1, −1), the rest spread over magnitudes with
//! pseudo-random mantissas and signs (a fixed generator, so every run
//! probes the same values).

use super::stats::ulp_distance;
use super::CompareError;
use crate::core::emu::{self, Address, Draw, Filter, LinearInput, SamplerState, Texture};
use crate::core::gpu::{self, Gpu, TargetKind};
use crate::core::load::{self, Options};
use serde::Serialize;

const SIDE: u32 = 64;

/// What one probe found. Inputs fall in three groups: *ordinary* (every
/// operand and the exact result a finite normal f32 or zero, and inside
/// the instruction's documented range), *subnormal* (an operand or the
/// result is subnormal), and *special* (an operand or the exact result is
/// NaN or infinite, or outside the documented range — the first 16 texels
/// and what they make).
#[derive(Clone, Debug, Serialize)]
pub struct Probe {
    /// The instruction, as written in the probe shader.
    pub instruction: String,
    /// Inputs probed (texels of the probe's input texture).
    pub inputs: u64,
    /// Results bit-identical on both backends (every input).
    pub identical: u64,
    /// Inputs in the ordinary group.
    pub ordinary: u64,
    /// Ordinary inputs with bit-identical results.
    pub ordinary_identical: u64,
    /// Over ordinary inputs: the largest emulator-to-GPU distance, in ulps.
    pub max_ulp: u64,
    /// Over ordinary inputs: the largest absolute emulator-to-GPU difference.
    pub max_abs: f64,
    /// Over ordinary inputs: the emulator's largest distance from the
    /// correctly rounded result, in ulps.
    pub emulator_max_ulp_exact: u64,
    /// Over ordinary inputs: the GPU's largest distance from the correctly
    /// rounded result, in ulps.
    pub gpu_max_ulp_exact: u64,
    /// Over ordinary inputs: the emulator's largest absolute error against
    /// the exact (f64) result.
    pub emulator_max_abs_exact: f64,
    /// Over ordinary inputs: the GPU's largest absolute error against the
    /// exact (f64) result.
    pub gpu_max_abs_exact: f64,
    /// Vulkan's precision requirement for the instruction, in words.
    pub spec: String,
    /// Ordinary inputs on which the GPU misses [`Probe::spec`].
    pub gpu_outside_spec: u64,
    /// Ordinary inputs on which the emulator misses [`Probe::spec`].
    pub emulator_outside_spec: u64,
    /// Inputs in the subnormal group.
    pub subnormal: u64,
    /// Subnormal inputs whose results differ between the backends.
    pub subnormal_differ: u64,
    /// Of those, how many give the device's result when every subnormal
    /// (operand or result) is read as zero: the device flushes them.
    pub subnormal_as_zero: u64,
    /// Special inputs whose results differ: (input, emulator, GPU).
    pub specials: Vec<([f32; 4], f32, f32)>,
    /// For `mad` and `dp4`: over ordinary inputs where the orders give
    /// different f32 results, how many there are and how many GPU results
    /// equal each order's (`(order, inputs, matches)`).
    pub orders: Vec<(String, u64, u64)>,
    /// The ordinary input, emulator and GPU values of the largest distance.
    pub worst: Option<([f32; 4], f32, f32)>,
}

impl Probe {
    /// Whether every input, special ones included, gives identical results.
    pub fn all_identical(&self) -> bool {
        self.identical == self.inputs
    }

    /// Whether ordinary inputs give identical results.
    pub fn ordinary_identical(&self) -> bool {
        self.ordinary_identical == self.ordinary
    }
}

/// One evaluation order of a probe's formula, in f32.
type Order = fn([f32; 4]) -> f32;

/// A precision requirement: its text, and whether `(input, exact, result)`
/// meets it.
type Spec = (&'static str, fn([f32; 4], f64, f32) -> bool);

/// A probe's definition.
struct Def {
    instruction: &'static str,
    /// Inputs for texel i.
    input: fn(u32) -> [f32; 4],
    /// The exact result (f64), when it is a number.
    exact: fn([f32; 4]) -> f64,
    /// Alternative evaluation orders of the same formula, in f32.
    orders: &'static [(&'static str, Order)],
    /// c0 for the probe (set by the application).
    c0: [f32; 4],
    /// Lines the shader adds before the instruction (a `def`).
    prologue: &'static str,
    /// The documented input range of src0.x (sincos: [−π, π]); outside it
    /// an input is special.
    domain: Option<(f32, f32)>,
    /// The result in f32 with subnormal operands and results read as zero
    /// (what a flushing device computes), for the subnormal group.
    flushed: fn([f32; 4]) -> f32,
    /// The precision Vulkan requires of the SPIR-V the translation emits
    /// (Vulkan spec, "Precision and Operation of SPIR-V Instructions"), and
    /// whether a result meets it: `(text, ok(input, exact, result))`.
    spec: Spec,
}

/// One unit in the last place of an f32 near `x`.
fn ulp(x: f64) -> f64 {
    let a = (x.abs() as f32).max(f32::MIN_POSITIVE);
    (f32::from_bits(a.to_bits() + 1) - a) as f64
}

fn within_ulps(exact: f64, value: f32, n: f64) -> bool {
    (value as f64 - exact).abs() <= n * ulp(exact)
}

const CORRECTLY_ROUNDED: Spec = ("correctly rounded", |_, exact, v| {
    within_ulps(exact, v, 0.5)
});

/// A small deterministic generator (SplitMix64).
fn mix(i: u32, k: u32) -> u64 {
    let mut z = (i as u64) << 8 | k as u64;
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Special values for the first 16 texels.
const SPECIALS: [f32; 16] = [
    0.0,
    -0.0,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::NAN,
    f32::MAX,
    -f32::MAX,
    1.0,
    -1.0,
    f32::MIN_POSITIVE,
    1.0e-40,
    -1.0e-40,
    0.5,
    2.0,
    3.0e-39,
    -3.0e-39,
];

/// A value with exponent in `[lo, hi)`, a pseudo-random mantissa and sign.
fn spread(i: u32, k: u32, lo: i32, hi: i32, signed: bool) -> f32 {
    let r = mix(i, k);
    let e = lo + (r % (hi - lo) as u64) as i32;
    let m = 1.0 + ((r >> 16) & 0x7f_ffff) as f32 / 8_388_608.0;
    let s = if signed && (r >> 40) & 1 == 1 {
        -1.0
    } else {
        1.0
    };
    s * m * (e as f32).exp2()
}

fn unary(lo: i32, hi: i32, signed: bool) -> impl Fn(u32) -> [f32; 4] {
    move |i| {
        if i < 16 {
            [SPECIALS[i as usize]; 4]
        } else {
            [spread(i, 0, lo, hi, signed); 4]
        }
    }
}

fn mad_input(i: u32) -> [f32; 4] {
    if i < 16 {
        return [
            SPECIALS[i as usize],
            0.0,
            SPECIALS[(i as usize + 3) % 16],
            1.0,
        ];
    }
    let a = spread(i, 1, -8, 8, true);
    let b = spread(i, 2, -8, 8, true);
    // c near −a·b makes the two roundings visible.
    let c = -(a as f64 * b as f64) as f32 * (1.0 + spread(i, 3, -12, -4, true));
    [a, b, c, 1.0]
}

fn vector_input(i: u32) -> [f32; 4] {
    if i < 16 {
        return [SPECIALS[i as usize], 1.0, -1.0, 0.5];
    }
    std::array::from_fn(|k| spread(i, 10 + k as u32, -6, 6, true))
}

fn pow_input(i: u32) -> [f32; 4] {
    if i < 16 {
        return [
            SPECIALS[i as usize],
            [0.0, 0.5, 2.0, -1.0][i as usize % 4],
            0.0,
            0.0,
        ];
    }
    [
        spread(i, 4, -8, 8, true),
        spread(i, 5, -4, 3, true),
        0.0,
        0.0,
    ]
}

fn angle_input(i: u32) -> [f32; 4] {
    if i < 16 {
        return [SPECIALS[i as usize]; 4];
    }
    let u = (mix(i, 6) >> 40) as f32 / (1u64 << 24) as f32;
    [(2.0 * u - 1.0) * std::f32::consts::PI; 4]
}

fn subnormal_input(i: u32) -> [f32; 4] {
    if i < 16 {
        return [SPECIALS[i as usize]; 4];
    }
    [spread(i, 7, -120, -100, true); 4]
}

fn dot4(v: [f32; 4]) -> [f64; 4] {
    // dp4 r1, r0, r0.wzyx
    let w = [v[3], v[2], v[1], v[0]];
    std::array::from_fn(|k| v[k] as f64 * w[k] as f64)
}

fn defs() -> Vec<Def> {
    let mut defs = transcendental_defs();
    defs.extend(arithmetic_defs());
    defs.extend(denormal_defs());
    defs
}

/// The probes of the transcendental instructions: log, exp, rcp, rsq, pow.
fn transcendental_defs() -> Vec<Def> {
    vec![
        Def {
            instruction: "log r1, r0.x",
            input: |i| unary(-126, 127, true)(i),
            exact: |v| (v[0] as f64).abs().log2(),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| d3d9_log(flush(v[0])),
            spec: (
                "log2: 3 ulp, absolute 2^-21 for x in [0.5, 2]",
                |v, exact, r| {
                    let x = v[0].abs();
                    if (0.5..=2.0).contains(&x) {
                        (r as f64 - exact).abs() <= 2f64.powi(-21)
                    } else {
                        within_ulps(exact, r, 3.0)
                    }
                },
            ),
        },
        Def {
            instruction: "exp r1, r0.x",
            input: |i| {
                if i < 16 {
                    [SPECIALS[i as usize]; 4]
                } else {
                    let u = (mix(i, 8) >> 40) as f32 / (1u64 << 24) as f32;
                    [(u - 0.5) * 250.0; 4]
                }
            },
            exact: |v| (v[0] as f64).exp2(),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(flush(v[0]).exp2()),
            spec: ("exp2: 3 + 2·|x| ulp", |v, exact, r| {
                within_ulps(exact, r, 3.0 + 2.0 * v[0].abs() as f64)
            }),
        },
        Def {
            instruction: "rcp r1, r0.x",
            input: |i| unary(-126, 126, true)(i),
            exact: |v| 1.0 / v[0] as f64,
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(1.0 / flush(v[0])),
            spec: ("division: 2.5 ulp", |_, exact, r| within_ulps(exact, r, 2.5)),
        },
        Def {
            instruction: "rsq r1, r0.x",
            input: |i| unary(-126, 127, true)(i),
            exact: |v| 1.0 / (v[0] as f64).abs().sqrt(),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(1.0 / flush(v[0]).abs().sqrt()),
            spec: ("inversesqrt: 2 ulp", |_, exact, r| within_ulps(exact, r, 2.0)),
        },
        Def {
            instruction: "pow r1, r0.x, r0.y",
            input: pow_input,
            exact: |v| (v[0] as f64).abs().powf(v[1] as f64),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(flush(v[0]).abs().powf(flush(v[1]))),
            spec: (
                "pow: inherited from exp2(y·log2 x): log2's error times |y|, the product's rounding, then exp2's 3 + 2·|y·log2 x| ulp",
                |v, exact, r| {
                    let (x, y) = ((v[0] as f64).abs(), v[1] as f64);
                    let l = x.log2();
                    let e_log = if (0.5..=2.0).contains(&x) {
                        2f64.powi(-21)
                    } else {
                        3.0 * ulp(l)
                    };
                    let t = (y * l).abs();
                    let u = f32::EPSILON as f64 / 2.0;
                    let relative = std::f64::consts::LN_2 * (y.abs() * e_log + u * t);
                    (r as f64 - exact).abs() <= exact.abs() * relative + (3.0 + 2.0 * t) * ulp(exact)
                },
            ),
        },
    ]
}

/// The probes of arithmetic: mad and dp4 (fused or not, in which order),
/// frc, sincos and nrm.
fn arithmetic_defs() -> Vec<Def> {
    vec![
        Def {
            instruction: "mad r1, r0.x, r0.y, r0.z",
            input: mad_input,
            exact: |v| v[0] as f64 * v[1] as f64 + v[2] as f64,
            orders: &[
                ("unfused", |v| v[0] * v[1] + v[2]),
                ("fused", |v| v[0].mul_add(v[1], v[2])),
            ],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(flush(flush(v[0]) * flush(v[1])) + flush(v[2])),
            spec: ("fma or mul then add: each correctly rounded", |v, _, r| {
                r.to_bits() == v[0].mul_add(v[1], v[2]).to_bits()
                    || r.to_bits() == (v[0] * v[1] + v[2]).to_bits()
            }),
        },
        Def {
            instruction: "dp4 r1, r0, r0.wzyx",
            input: vector_input,
            exact: |v| dot4(v).iter().sum(),
            orders: &[
                ("left to right", |v| {
                    v[0] * v[3] + v[1] * v[2] + v[2] * v[1] + v[3] * v[0]
                }),
                ("pairwise", |v| {
                    (v[0] * v[3] + v[1] * v[2]) + (v[2] * v[1] + v[3] * v[0])
                }),
                ("left to right, fused", |v| {
                    v[3].mul_add(v[0], v[2].mul_add(v[1], v[1].mul_add(v[2], v[0] * v[3])))
                }),
            ],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| {
                let f = v.map(flush);
                let p = |a: f32, b: f32| flush(a * b);
                flush(flush(flush(p(f[0], f[3]) + p(f[1], f[2])) + p(f[2], f[1])) + p(f[3], f[0]))
            },
            spec: (
                "dot: products and sums each rounded, any order",
                |v, exact, r| {
                    let terms: f64 = dot4(v).iter().map(|t| t.abs()).sum();
                    (r as f64 - exact).abs() <= 8.0 * f32::EPSILON as f64 / 2.0 * terms
                },
            ),
        },
        Def {
            instruction: "frc r1, r0",
            input: |i| unary(-24, 24, true)(i),
            exact: |v| (v[0] as f64) - (v[0] as f64).floor(),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| {
                let x = flush(v[0]);
                let f = flush(x - x.floor());
                if f >= 1.0 {
                    1.0 - f32::EPSILON / 2.0
                } else {
                    f
                }
            },
            spec: CORRECTLY_ROUNDED,
        },
        Def {
            instruction: "sincos r1.xy, r0.x",
            input: angle_input,
            exact: |v| (v[0] as f64).cos(),
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: Some((-std::f32::consts::PI, std::f32::consts::PI)),
            flushed: |v| flush(flush(v[0]).cos()),
            spec: ("cos: absolute 2^-11 in [-π, π]", |_, exact, r| {
                (r as f64 - exact).abs() <= 2f64.powi(-11)
            }),
        },
        Def {
            instruction: "nrm r1, r0",
            input: vector_input,
            exact: |v| {
                let f = v[0] as f64 * v[0] as f64
                    + v[1] as f64 * v[1] as f64
                    + v[2] as f64 * v[2] as f64;
                v[0] as f64 / f.sqrt()
            },
            orders: &[],
            prologue: "",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| {
                let f = v.map(flush);
                let sq = |a: f32| flush(a * a);
                let len = flush(flush(sq(f[0]) + sq(f[1])) + sq(f[2]));
                let scale = if len == 0.0 {
                    f32::MAX
                } else {
                    1.0 / len.sqrt()
                };
                flush(f[0] * scale)
            },
            spec: (
                "inversesqrt 2 ulp, products rounded: taken as 4 ulp",
                |_, exact, r| within_ulps(exact, r, 4.0),
            ),
        },
    ]
}

/// The probes of subnormal inputs and results (mul, add) and of a
/// multiplication by a def'd zero.
fn denormal_defs() -> Vec<Def> {
    vec![
        Def {
            instruction: "mul r1, r0, c0.x",
            input: subnormal_input,
            exact: |v| v[0] as f64 * 2f64.powi(-30),
            orders: &[],
            prologue: "",
            c0: [9.313_226e-10, 0.0, 0.0, 0.0],
            domain: None,
            flushed: |v| flush(flush(v[0]) * 9.313_226e-10),
            spec: CORRECTLY_ROUNDED,
        },
        Def {
            instruction: "add r1, r0, c0.x",
            input: |i| {
                if i < 16 {
                    [SPECIALS[i as usize]; 4]
                } else {
                    [spread(i, 9, -140, -120, true); 4]
                }
            },
            exact: |v| v[0] as f64 + 1.0e-40f32 as f64,
            orders: &[],
            prologue: "",
            c0: [1.0e-40, 0.0, 0.0, 0.0],
            domain: None,
            flushed: |v| flush(flush(v[0])),
            spec: CORRECTLY_ROUNDED,
        },
        Def {
            instruction: "mul r1, r0, c1.x",
            input: |i| unary(-100, 100, true)(i),
            exact: |v| v[0] as f64 * 0.0,
            orders: &[],
            prologue: "def c1, 0, 0, 0, 0\n",
            c0: [0.0; 4],
            domain: None,
            flushed: |v| flush(v[0]) * 0.0,
            spec: CORRECTLY_ROUNDED,
        },
    ]
}

/// `x` with a subnormal read as zero (sign kept).
fn flush(x: f32) -> f32 {
    if x.is_subnormal() {
        0.0f32.copysign(x)
    } else {
        x
    }
}

/// `log` under the D3D9 rules (as `core/emu/math.rs`, in f64 then f32).
fn d3d9_log(x: f32) -> f32 {
    if x == 0.0 {
        -f32::MAX
    } else {
        (x as f64).abs().log2() as f32
    }
}

/// The probe shader for `instruction`.
fn source(prologue: &str, instruction: &str) -> String {
    format!(
        "ps_3_0\ndcl_texcoord0 v0.xy\ndcl_2d s0\n{prologue}texld r0, v0, s0\nmov r1, c0.y\n{instruction}\nmov oC0, r1\n"
    )
}

/// Runs every probe on the emulator and on `gpu`.
pub fn run(gpu: &Gpu) -> Result<Vec<Probe>, CompareError> {
    defs().iter().map(|d| run_one(gpu, d)).collect()
}

fn run_one(gpu: &Gpu, d: &Def) -> Result<Probe, CompareError> {
    let text = source(d.prologue, d.instruction);
    let loaded = load::load_str("probe.psh", &text, &Options::default())
        .map_err(|e| CompareError::Other(format!("probe `{}`: {e}", d.instruction)))?;
    let n = SIDE * SIDE;
    let texels: Vec<[f32; 4]> = (0..n).map(d.input).collect();
    let mut draw = Draw::new(SIDE, SIDE);
    draw.inputs.push((
        0,
        LinearInput {
            base: [0.5 / SIDE as f32, 0.5 / SIDE as f32, 0.0, 0.0],
            ddx: [1.0 / SIDE as f32, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / SIDE as f32, 0.0, 0.0],
        },
    ));
    draw.constants.float = vec![d.c0];
    draw.samplers.push((
        0,
        Texture {
            width: SIDE,
            height: SIDE,
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
    let compiled = emu::compile(&loaded.shader).map_err(CompareError::Emu)?;
    let e = emu::run_with_threads(&compiled, &draw, 1).map_err(CompareError::Emu)?;
    let g = gpu::run(gpu, &loaded.shader, &draw, TargetKind::Raw).map_err(CompareError::Gpu)?;
    let (Some(ec), Some(gc)) = (&e.color[0], &g.color[0]) else {
        return Err(CompareError::Other(format!(
            "probe `{}` wrote no oC0",
            d.instruction
        )));
    };
    let mut p = Probe {
        instruction: d.instruction.to_string(),
        inputs: n as u64,
        identical: 0,
        ordinary: 0,
        ordinary_identical: 0,
        max_ulp: 0,
        max_abs: 0.0,
        emulator_max_ulp_exact: 0,
        gpu_max_ulp_exact: 0,
        emulator_max_abs_exact: 0.0,
        gpu_max_abs_exact: 0.0,
        spec: d.spec.0.to_string(),
        gpu_outside_spec: 0,
        emulator_outside_spec: 0,
        subnormal: 0,
        subnormal_differ: 0,
        subnormal_as_zero: 0,
        specials: Vec::new(),
        orders: d
            .orders
            .iter()
            .map(|(name, _)| (name.to_string(), 0, 0))
            .collect(),
        worst: None,
    };
    for (i, input) in texels.iter().enumerate() {
        let (ev, gv) = (ec[i][0], gc[i][0]);
        let bits = ev.to_bits() == gv.to_bits();
        p.identical += bits as u64;
        // NaN payloads are not values: any NaN is the same special.
        let same = bits || ev.is_nan() && gv.is_nan();
        let exact = (d.exact)(*input);
        let rounded = exact as f32;
        let outside = d
            .domain
            .is_some_and(|(lo, hi)| !(input[0] >= lo && input[0] <= hi));
        let subnormal = input.iter().any(|v| v.is_subnormal())
            || d.c0[0].is_subnormal()
            || rounded.is_subnormal()
            || ev.is_subnormal();
        if !subnormal && (outside || !input.iter().all(|v| v.is_finite()) || !rounded.is_finite()) {
            if !same {
                p.specials.push((*input, ev, gv));
            }
            continue;
        }
        if subnormal {
            p.subnormal += 1;
            if !same {
                p.subnormal_differ += 1;
                let z = (d.flushed)(*input);
                p.subnormal_as_zero += (gv == z || gv.is_nan() && z.is_nan()) as u64;
            }
            continue;
        }
        p.ordinary += 1;
        p.ordinary_identical += bits as u64;
        if let Some(u) = ulp_distance(ev, gv) {
            if u > p.max_ulp {
                p.max_ulp = u;
                p.worst = Some((*input, ev, gv));
            }
        }
        p.max_abs = p.max_abs.max((ev as f64 - gv as f64).abs());
        if let Some(u) = ulp_distance(ev, rounded) {
            p.emulator_max_ulp_exact = p.emulator_max_ulp_exact.max(u);
        }
        if let Some(u) = ulp_distance(gv, rounded) {
            p.gpu_max_ulp_exact = p.gpu_max_ulp_exact.max(u);
        }
        p.emulator_max_abs_exact = p.emulator_max_abs_exact.max((ev as f64 - exact).abs());
        p.gpu_outside_spec += !(d.spec.1)(*input, exact, gv) as u64;
        p.emulator_outside_spec += !(d.spec.1)(*input, exact, ev) as u64;
        p.gpu_max_abs_exact = p.gpu_max_abs_exact.max((gv as f64 - exact).abs());
        if d.orders.len() > 1 {
            let values: Vec<f32> = d.orders.iter().map(|(_, f)| f(*input)).collect();
            if values.iter().any(|v| v.to_bits() != values[0].to_bits()) {
                for (k, v) in values.iter().enumerate() {
                    p.orders[k].1 += 1;
                    p.orders[k].2 += (v.to_bits() == gv.to_bits()) as u64;
                }
            }
        }
    }
    Ok(p)
}
