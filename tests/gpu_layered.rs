//! Cube and volume textures on the GPU backend against the emulator: the
//! same draws on both (`dcl_cube`, `dcl_volume`; texld, texldp, texldl,
//! texldd), bit for bit where the device has no freedom (point filtering
//! away from texel edges, point mip selection away from k + ½), within a
//! bound derived from Vulkan's weight precision where it has some. Every
//! test draws on the adapter `common/gpu.rs` opens; without one it says it
//! was skipped (and fails under `CI`).
//!
//! The bound for linear filtering: Vulkan requires at least 4 bits of
//! sub-texel precision (`subTexelPrecisionBits` ≥ 4), so a device's weight
//! on each axis may be off by up to 2⁻⁵ from the emulator's f32 weight. A
//! lerp of texels in [0, 1] then moves by at most 2⁻⁵, and a d-linear
//! filter (bilinear on a cube face, trilinear in a volume) by at most
//! d · 2⁻⁵ — 1/16 for a face, 3/32 for a volume — plus f32 roundings of
//! the weights and sums (a few ulp of 1, covered by 2⁻²⁰).

use crate::common::gpu as gpu_device;

use gpu_device::gpu;
use ps30::core::emu::{
    self, Address, CubeMap, Draw, DrawOutput, Filter, LinearInput, MipChain, MipFilter,
    SamplerState, Texture, TextureLevels, VolumeChain,
};
use ps30::core::gpu::{self as backend, Gpu, GpuOutput, TargetKind};
use ps30::core::image::VolumeLevel;
use ps30::core::load::{load_str, Options};

fn shader(src: &str) -> ps30::core::ir::Shader {
    load_str("test.psh", src, &Options::default())
        .unwrap_or_else(|e| panic!("{e}"))
        .shader
}

fn both(g: &Gpu, s: &ps30::core::ir::Shader, d: &Draw) -> (DrawOutput, GpuOutput) {
    let e = emu::run(&emu::compile(s).unwrap(), d).unwrap();
    let o = backend::run(g, s, d, TargetKind::Raw).unwrap_or_else(|e| panic!("{e}"));
    (e, o)
}

/// Every channel of `oC0` within `bound` (0: bit for bit, NaN = NaN).
fn assert_close(what: &str, e: &DrawOutput, o: &GpuOutput, bound: f32) {
    let (ec, gc) = (e.color[0].as_ref().unwrap(), o.color[0].as_ref().unwrap());
    for (i, (a, b)) in ec.iter().zip(gc).enumerate() {
        for c in 0..4 {
            let ok = if bound == 0.0 {
                a[c].to_bits() == b[c].to_bits() || a[c].is_nan() && b[c].is_nan()
            } else {
                (a[c] - b[c]).abs() <= bound
            };
            assert!(
                ok,
                "{what}: pixel ({}, {}) channel {c}: emulator {}, GPU {} (bound {bound})",
                i as u32 % e.width,
                i as u32 / e.width,
                a[c],
                b[c]
            );
        }
    }
}

/// A sampler state: `mode` on all three axes, `filter` for MIN and MAG,
/// `mip` between levels, `border` for BORDER.
fn state(mode: Address, filter: Filter, mip: MipFilter, border: [f32; 4]) -> SamplerState {
    SamplerState {
        address_u: mode,
        address_v: mode,
        address_w: mode,
        border,
        mip_filter: mip,
        ..SamplerState::filtered(filter)
    }
}

const FACE_BOUND: f32 = 1.0 / 16.0 + 1.0 / 1048576.0;
const VOLUME_BOUND: f32 = 3.0 / 32.0 + 1.0 / 1048576.0;

/// A level of `e × e` texels, each different, in [0, 1], marked by `tag`.
fn level(e: u32, tag: f32) -> (u32, u32, Vec<[f32; 4]>) {
    let n = e * e;
    let texels = (0..n)
        .map(|i| {
            let f = i as f32 / n as f32;
            [f, 1.0 - f, tag, (i % e) as f32 / e as f32]
        })
        .collect();
    (e, e, texels)
}

/// A cube of 4×4 faces (with 2×2 and 1×1 mips when `mips`), each face and
/// level told apart by its blue channel.
fn cube(mips: bool) -> CubeMap {
    let faces = (0..6)
        .map(|f| {
            let sizes: &[u32] = if mips { &[4, 2, 1] } else { &[4] };
            let levels = sizes
                .iter()
                .enumerate()
                .map(|(i, &e)| level(e, (f * 3 + i) as f32 / 18.0))
                .collect();
            MipChain::from_levels(levels).unwrap()
        })
        .collect();
    CubeMap::from_faces(faces).unwrap()
}

/// Directions across the middle of the face of `axis` (0..6: +X … −Z),
/// unnormalised (major component ±1.7): the minor components run from
/// −1.02 in steps of 0.255, so the face coordinates s, t stay in
/// [0.2, 0.8] — inside the face for bilinear taps (which need
/// [0.125, 0.875] on a 4-texel face) — and s·4 is never an integer.
fn across_face(axis: usize) -> LinearInput {
    let major = axis / 2;
    let sign = if axis.is_multiple_of(2) { 1.7 } else { -1.7 };
    let (a, b) = ((major + 1) % 3, (major + 2) % 3);
    let mut base = [0.0; 4];
    let (mut ddx, mut ddy) = ([0.0; 4], [0.0; 4]);
    base[major] = sign;
    base[a] = -1.02;
    base[b] = -1.02;
    ddx[a] = 0.255;
    ddy[b] = 0.255;
    LinearInput { base, ddx, ddy }
}

#[test]
fn cube_maps_pick_faces_and_texels_as_the_emulator() {
    let Some(g) = gpu("cube_maps_pick_faces_and_texels_as_the_emulator") else {
        return;
    };
    let map = cube(false);
    let texld =
        shader("ps_3_0\ndcl_texcoord0 v0.xyz\ndcl_cube s0\ntexld r0, v0, s0\nmov oC0, r0\n");
    // texldp divides by w = 2 first (the direction, so the face, is unchanged).
    let texldp = shader(
        "ps_3_0\ndcl_texcoord0 v0.xyz\ndcl_cube s0\ndef c0, 2, 2, 2, 2\nmul r1, v0.xyzz, c0\nmov r1.w, c0.w\ntexldp r0, r1, s0\nmov oC0, r0\n",
    );
    for axis in 0..6 {
        for filter in [Filter::Point, Filter::Linear] {
            for (name, s) in [("texld", &texld), ("texldp", &texldp)] {
                let mut d = Draw::new(8, 8);
                d.inputs.push((0, across_face(axis)));
                d.samplers
                    .push((0, TextureLevels::Cube(&map), SamplerState::filtered(filter)));
                let (e, o) = both(&g, s, &d);
                let bound = match filter {
                    Filter::Point => 0.0,
                    Filter::Linear => FACE_BOUND,
                };
                assert_close(&format!("{name} face {axis} {filter:?}"), &e, &o, bound);
            }
        }
    }
}

/// Per-face mip chains read at explicit levels (texldl: λ from −0.7 in
/// 0.3 steps, never k + ½, where Vulkan and D3D9 round apart) and with
/// given gradients (texldd), point mip filtering: the level picked and the
/// texel in it agree bit for bit.
#[test]
fn cube_mips_follow_texldl_and_texldd() {
    let Some(g) = gpu("cube_mips_follow_texldl_and_texldd") else {
        return;
    };
    let map = cube(true);
    let texldl = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_cube s0\ntexldl r0, v0, s0\nmov oC0, r0\n");
    // Gradients along a minor axis of the +X/−X faces, 0 to 3.1 face widths.
    let texldd = shader(
        "ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\ndcl_cube s0\ndef c1, 0, 0, 0, 0\nmov r1, v1\ntexldd r0, v0, s0, r1, c1\nmov oC0, r0\n",
    );
    for axis in [0, 1] {
        for (name, s) in [("texldl", &texldl), ("texldd", &texldd)] {
            let mut d = Draw::new(8, 8);
            let mut input = across_face(axis);
            input.base[3] = -0.7;
            input.ddx[3] = 0.3;
            d.inputs.push((0, input));
            if name == "texldd" {
                d.inputs.push((
                    1,
                    LinearInput {
                        base: [0.0, 0.0, 0.003, 0.0],
                        ddx: [0.0, 0.0, 0.0, 0.0],
                        ddy: [0.0, 0.0, 0.41, 0.0],
                    },
                ));
            }
            d.samplers.push((
                0,
                TextureLevels::Cube(&map),
                state(Address::Clamp, Filter::Point, MipFilter::Point, [0.0; 4]),
            ));
            let (e, o) = both(&g, s, &d);
            assert_close(&format!("{name} face {axis}"), &e, &o, 0.0);
        }
    }
}

/// A 4×4×4 volume (with mips when `mips`), each texel different.
fn volume(mips: bool) -> VolumeChain {
    let sizes: &[u32] = if mips { &[4, 2, 1] } else { &[4] };
    let levels = sizes
        .iter()
        .enumerate()
        .map(|(l, &n)| {
            let count = n * n * n;
            let texels = (0..count)
                .map(|i| {
                    let f = i as f32 / count as f32;
                    [f, 1.0 - f, (i / (n * n)) as f32 / n as f32, l as f32 / 3.0]
                })
                .collect();
            VolumeLevel {
                width: n,
                height: n,
                depth: n,
                texels,
            }
        })
        .collect();
    VolumeChain::from_levels(levels).unwrap()
}

/// A volume sampled across [−1.3, 2.3] on u and v at three depths outside
/// and inside [0, 1], with every address mode on all three axes (BORDER in
/// a hardware colour and in one the shader adds; MIRRORONCE, which the
/// shader mirrors) and both filters. u·4, v·4, w·4 and their − ½ are never
/// integers, so point sampling agrees bit for bit.
#[test]
fn volume_textures_address_and_filter_as_the_emulator() {
    let Some(g) = gpu("volume_textures_address_and_filter_as_the_emulator") else {
        return;
    };
    let vol = volume(false);
    let s = shader("ps_3_0\ndcl_texcoord0 v0.xyz\ndcl_volume s0\ntexld r0, v0, s0\nmov oC0, r0\n");
    let modes = [
        (Address::Wrap, [0.0; 4]),
        (Address::Mirror, [0.0; 4]),
        (Address::Clamp, [0.0; 4]),
        (Address::Border, [1.0; 4]),
        (Address::Border, [0.25, 0.5, 0.75, 1.0]),
        (Address::MirrorOnce, [0.0; 4]),
    ];
    for (mode, border) in modes {
        for filter in [Filter::Point, Filter::Linear] {
            for w in [-0.7f32, 0.33, 1.45] {
                let mut d = Draw::new(24, 24);
                d.inputs.push((
                    0,
                    LinearInput {
                        base: [-1.3, -1.3, w, 0.0],
                        ddx: [0.15, 0.0, 0.0, 0.0],
                        ddy: [0.0, 0.15, 0.0, 0.0],
                    },
                ));
                d.samplers.push((
                    0,
                    TextureLevels::Volume(&vol),
                    state(mode, filter, MipFilter::None, border),
                ));
                let (e, o) = both(&g, &s, &d);
                let bound = match filter {
                    Filter::Point => 0.0,
                    Filter::Linear => VOLUME_BOUND,
                };
                assert_close(
                    &format!("{mode:?} {border:?} {filter:?} w {w}"),
                    &e,
                    &o,
                    bound,
                );
            }
        }
    }
}

/// A volume's 3D mips at explicit levels (texldl, point mip filter): the
/// level and texel agree bit for bit.
#[test]
fn volume_mips_follow_texldl() {
    let Some(g) = gpu("volume_mips_follow_texldl") else {
        return;
    };
    let vol = volume(true);
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_volume s0\ntexldl r0, v0, s0\nmov oC0, r0\n");
    let mut d = Draw::new(16, 4);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.03, 0.07, 0.41, -0.8],
            ddx: [0.061, 0.0, 0.0, 0.3],
            ddy: [0.0, 0.23, 0.0, 0.0],
        },
    ));
    d.samplers.push((
        0,
        TextureLevels::Volume(&vol),
        state(Address::Wrap, Filter::Point, MipFilter::Point, [0.0; 4]),
    ));
    let (e, o) = both(&g, &s, &d);
    assert_close("texldl volume", &e, &o, 0.0);
}

/// A declared cube or volume sampler with nothing bound reads (0, 0, 0, 1)
/// on both backends.
#[test]
fn unbound_cube_and_volume_samplers_read_the_default() {
    let Some(g) = gpu("unbound_cube_and_volume_samplers_read_the_default") else {
        return;
    };
    for dcl in ["dcl_cube", "dcl_volume"] {
        let s = shader(&format!(
            "ps_3_0\ndcl_texcoord0 v0.xyz\n{dcl} s0\ntexld r0, v0, s0\nmov oC0, r0\n"
        ));
        let mut d = Draw::new(4, 4);
        d.inputs.push((0, across_face(2)));
        let (e, o) = both(&g, &s, &d);
        assert_close(dcl, &e, &o, 0.0);
        assert_eq!(o.color[0].as_ref().unwrap()[0], [0.0, 0.0, 0.0, 1.0]);
    }
}

/// Texel (x, y) of [`nonfinite_texels`]: its own value on every channel.
fn texel_value(x: usize, y: usize) -> [f32; 4] {
    let i = (y * 4 + x) as f32;
    [i / 16.0, 1.0 - i / 16.0, x as f32 / 4.0, y as f32 / 4.0]
}

fn nonfinite_texels() -> Vec<[f32; 4]> {
    (0..16).map(|i| texel_value(i % 4, i / 4)).collect()
}

/// What a lookup at `u` (non-finite) and v = 0.375 (row 1's centre, so v
/// contributes no blend) reads under CLAMP, BORDER and MIRRORONCE, by the
/// rule of docs/textures.md ("Non-finite coordinates"), derived by hand:
/// +∞ and −∞ are the far and near edge texels under CLAMP, the border colour
/// under BORDER, the far edge under MIRRORONCE (|−∞| = +∞); NaN is u = 0 —
/// texel 0 under CLAMP and MIRRORONCE with either filter, and under BORDER
/// texel 0 when point sampled, half texel 0 and half border when linear
/// (the taps of u·4 − ½ = −½ are −1 and 0 with weights ½).
fn nonfinite_expected(mode: Address, filter: Filter, u: f32, border: [f32; 4]) -> [f32; 4] {
    let (first, last) = (texel_value(0, 1), texel_value(3, 1));
    match (mode, u.is_nan(), u > 0.0) {
        (Address::Border, true, _) if filter == Filter::Linear => {
            std::array::from_fn(|c| first[c] * 0.5 + border[c] * 0.5)
        }
        (_, true, _) => first,
        (Address::Border, false, _) => border,
        (Address::MirrorOnce, false, _) => last,
        (_, false, true) => last,
        (_, false, false) => first,
    }
}

/// Lookups at +∞, −∞ and NaN on u (from constants, any bit pattern) with
/// each address mode and filter: the emulator reads what the rule says
/// (derived by hand for CLAMP, BORDER and MIRRORONCE; WRAP and MIRROR have
/// no evidence and are only compared), and the GPU backend — whose Vulkan
/// lookup would be undefined there — reads the same, bit for bit but for
/// the rounding of a ½ · a + ½ · b blend (2⁻²⁰ for texels in [0, 1]).
#[test]
fn non_finite_coordinates_clamp_to_the_edge_on_both_backends() {
    let texels = nonfinite_texels();
    let s = shader("ps_3_0\ndcl_2d s0\nmov r1, c0\ntexld r0, r1, s0\nmov oC0, r0\n");
    let compiled = emu::compile(&s).unwrap();
    let g = gpu("non_finite_coordinates_clamp_to_the_edge_on_both_backends");
    let border = [0.25, 0.5, 0.75, 1.0];
    let modes = [
        Address::Clamp,
        Address::Border,
        Address::MirrorOnce,
        Address::Wrap,
        Address::Mirror,
    ];
    for mode in modes {
        for filter in [Filter::Point, Filter::Linear] {
            for u in [f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
                let mut d = Draw::new(2, 2);
                d.constants.float = vec![[u, 0.375, 0.0, 0.0]];
                d.samplers.push((
                    0,
                    Texture {
                        width: 4,
                        height: 4,
                        texels: &texels,
                    }
                    .into(),
                    state(mode, filter, MipFilter::None, border),
                ));
                let what = format!("{mode:?} {filter:?} u = {u}");
                let e = emu::run(&compiled, &d).unwrap();
                let got = e.color[0].as_ref().unwrap()[0];
                if !matches!(mode, Address::Wrap | Address::Mirror) {
                    let want = nonfinite_expected(mode, filter, u, border);
                    assert_eq!(got, want, "{what}: the emulator");
                }
                if let Some(g) = &g {
                    let o = backend::run(g, &s, &d, TargetKind::Raw).unwrap();
                    assert_close(&what, &e, &o, 1.0 / 1048576.0);
                }
            }
        }
    }
}

/// `ps30 compare` runs the DDS cube and volume draws of docs/textures.md
/// on both backends: the cube (point filtered) bit for bit, the volume
/// (trilinear) within rounding, its difference explained by the device's
/// filtering rather than reported as a finding.
#[test]
fn compare_runs_cube_and_volume_draws_from_dds_files() {
    if gpu("compare_runs_cube_and_volume_draws_from_dds_files").is_none() {
        return;
    }
    for (shader, inputs, why) in [
        (
            "asm/textures/cube-lod.psh",
            "asm/textures/cube.json",
            "why: bit-identical",
        ),
        (
            "asm/textures/volume.psh",
            "asm/textures/volume.json",
            "s0 (volume) filters linearly",
        ),
    ] {
        let o = crate::common::bin::in_repo(&[
            "compare", shader, "--inputs", inputs, "--target", "4x4",
        ]);
        let out = crate::common::bin::stdout(&o);
        assert!(
            o.status.success(),
            "{shader}: {out}{}",
            crate::common::bin::stderr(&o)
        );
        assert!(out.contains(why), "{shader}: {out}");
        assert!(!out.contains("FINDING"), "{shader}: {out}");
    }
}

/// Ties for the major axis: Direct3D 9 does not say which face a direction
/// with two equal largest components reads; its successor does ("In the
/// case of a tie, the following precedence should occur: Z, Y, X", the
/// Direct3D 11.3 functional specification, §7.18.7), and the emulator
/// follows it. Each direction below ties, and the face it must read comes
/// from that precedence, computed here; the blue channel of the cube of
/// [`cube`] names the face (face f, level 0: 3f/18). The GPU must agree
/// bit for bit: where a device broke ties otherwise, this test would say so.
#[test]
fn cube_ties_pick_z_then_y_on_both_backends() {
    let Some(g) = gpu("cube_ties_pick_z_then_y_on_both_backends") else {
        return;
    };
    let map = cube(false);
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_cube s0\ntexldl r0, v0, s0\nmov oC0, r0\n");
    let dirs: [[f32; 3]; 8] = [
        [1.0, 1.0, 0.5],
        [-1.0, 1.0, 0.25],
        [1.0, -1.0, -0.5],
        [1.0, 0.5, 1.0],
        [-1.0, 0.25, -1.0],
        [0.5, 1.0, 1.0],
        [0.25, -1.0, -1.0],
        [-1.0, -1.0, -1.0],
    ];
    for d in dirs {
        let a = d.map(f32::abs);
        let m = a[0].max(a[1]).max(a[2]);
        let axis = if a[2] == m {
            2
        } else if a[1] == m {
            1
        } else {
            0
        };
        let face = axis * 2 + usize::from(d[axis] < 0.0);
        let mut draw = Draw::new(1, 1);
        draw.inputs.push((
            0,
            LinearInput {
                base: [d[0], d[1], d[2], 0.0],
                ddx: [0.0; 4],
                ddy: [0.0; 4],
            },
        ));
        draw.samplers.push((
            0,
            TextureLevels::Cube(&map),
            state(Address::Clamp, Filter::Point, MipFilter::None, [0.0; 4]),
        ));
        let (e, o) = both(&g, &s, &draw);
        let blue = e.color[0].as_ref().unwrap()[0][2];
        assert_eq!(blue, (face * 3) as f32 / 18.0, "emulator at {d:?}");
        assert_close(&format!("tie {d:?}"), &e, &o, 0.0);
    }
}

/// `texldb` on a cube and a volume (the quad's own level of detail plus
/// src.w) and `texldd` on a volume (the level from the given gradients),
/// point mip filtering, on both backends. The implicit level on a cube
/// face here is log2(0.3) (the face coordinates move 0.255/1.7/2 per pixel
/// on a 4-texel face), and the bias runs 1 + 0.35·x: the levels above 0
/// sit at least 0.13 from any k + ½, where the two backends could round apart
/// within Vulkan's 4 bits of level precision (mipmapPrecisionBits ≥ 4:
/// 1/16). The volume's gradients are chosen the same way.
#[test]
fn texldb_on_cubes_and_volumes_and_texldd_on_volumes_agree() {
    let Some(g) = gpu("texldb_on_cubes_and_volumes_and_texldd_on_volumes_agree") else {
        return;
    };
    let map = cube(true);
    let texldb_cube =
        shader("ps_3_0\ndcl_texcoord0 v0\ndcl_cube s0\ntexldb r0, v0, s0\nmov oC0, r0\n");
    for axis in [0, 3, 4] {
        let mut d = Draw::new(8, 8);
        let mut input = across_face(axis);
        input.base[3] = 1.0;
        input.ddx[3] = 0.35;
        d.inputs.push((0, input));
        d.samplers.push((
            0,
            TextureLevels::Cube(&map),
            state(Address::Clamp, Filter::Point, MipFilter::Point, [0.0; 4]),
        ));
        let (e, o) = both(&g, &texldb_cube, &d);
        assert_close(&format!("texldb cube face {axis}"), &e, &o, 0.0);
        // the blue tag (3f + level)/18 says which levels were read: all three
        let levels = levels_read(&e, |c| (c[2] * 18.0).round() as u32 % 3);
        assert_eq!(levels, vec![0, 1, 2], "texldb cube face {axis}");
    }
    let vol = volume(true);
    let volume_state = state(Address::Wrap, Filter::Point, MipFilter::Point, [0.0; 4]);
    // u moves 0.061 per pixel on a 4-texel side: 0.244 texels, log2 = −2.03;
    // the bias 1.3 + 0.35·x gives −0.73 … 1.72, the levels above 0 at least
    // 0.13 from k + ½.
    let texldb_volume =
        shader("ps_3_0\ndcl_texcoord0 v0\ndcl_volume s0\ntexldb r0, v0, s0\nmov oC0, r0\n");
    let mut d = Draw::new(8, 4);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.03, 0.07, 0.41, 1.3],
            ddx: [0.061, 0.0, 0.0, 0.35],
            ddy: [0.0, 0.0, 0.0, 0.0],
        },
    ));
    d.samplers
        .push((0, TextureLevels::Volume(&vol), volume_state));
    let (e, o) = both(&g, &texldb_volume, &d);
    assert_close("texldb volume", &e, &o, 0.0);
    // alpha is level/3: every level of the chain was read
    let by_alpha = |c: [f32; 4]| (c[3] * 3.0).round() as u32;
    assert_eq!(levels_read(&e, by_alpha), vec![0, 1, 2], "texldb volume");
    // texldd: the w gradient of v1 (constant along a row) grows with y:
    // 0.06 + 0.25·y on a 4-texel side is 0.24, 1.24, 2.24, 3.24 texels,
    // levels −2.06, 0.31, 1.16, 1.70 (none within 0.19 of k + ½).
    let texldd_volume = shader(
        "ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\ndcl_volume s0\ndef c1, 0, 0, 0, 0\nmov r1, v1\ntexldd r0, v0, s0, r1, c1\nmov oC0, r0\n",
    );
    let mut d = Draw::new(8, 4);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.03, 0.07, 0.41, 0.0],
            ddx: [0.061, 0.0, 0.0, 0.0],
            ddy: [0.0, 0.23, 0.0, 0.0],
        },
    ));
    d.inputs.push((
        1,
        LinearInput {
            base: [0.0, 0.0, 0.06, 0.0],
            ddx: [0.0; 4],
            ddy: [0.0, 0.0, 0.25, 0.0],
        },
    ));
    d.samplers
        .push((0, TextureLevels::Volume(&vol), volume_state));
    let (e, o) = both(&g, &texldd_volume, &d);
    assert_close("texldd volume", &e, &o, 0.0);
    assert_eq!(levels_read(&e, by_alpha), vec![0, 1, 2], "texldd volume");
}

/// The distinct levels a draw read, by `level` of each pixel's colour.
fn levels_read(e: &DrawOutput, level: impl Fn([f32; 4]) -> u32) -> Vec<u32> {
    let mut l: Vec<u32> = e.color[0]
        .as_ref()
        .unwrap()
        .iter()
        .map(|&c| level(c))
        .collect();
    l.sort_unstable();
    l.dedup();
    l
}

/// The level of detail where the coordinates are not finite. It comes
/// from the quad's raw coordinates (the edge clamp of docs/textures.md
/// applies to the lookup, not to the derivatives): a quad whose pixels
/// share one infinite coordinate has ∞ − ∞ = NaN as its derivative and
/// reads level 0; a quad where one pixel's coordinate is infinite and its
/// neighbour's finite has an infinite derivative, λ = +∞, and reads the
/// smallest level. Direct3D 9 and Vulkan leave both undefined: this is
/// ps30's rule, and the test holds the GPU to it bit for bit, so a device
/// that picks otherwise shows up here. The levels of a 4×4 chain are told
/// apart by their first channel, which holds the level's number.
#[test]
fn the_level_of_detail_at_non_finite_coordinates() {
    let levels = (0..3u32)
        .map(|l| {
            let (e, _, mut texels) = level(4 >> l, 0.5);
            for t in &mut texels {
                t[0] = l as f32;
            }
            (e, e, texels)
        })
        .collect();
    let chain = MipChain::from_levels(levels).unwrap();
    // x = rcp(v0.x) with v0.x = pixel x: +∞ at x = 0, 1 at x = 1; the
    // second quad (x = 2, 3) is finite: ½ − ⅓ of a 4-texel side is 0.67
    // texels, λ = −0.58, level 0.
    let varying = shader(
        "ps_3_0\ndcl_texcoord0 v0.x\ndcl_2d s0\ndef c0, 0, 0.375, 0, 0\nmov r1, c0\nrcp r1.x, v0.x\ntexld r0, r1, s0\nmov oC0, r0\n",
    );
    let constant = shader(
        "ps_3_0\ndcl_texcoord0 v0.x\ndcl_2d s0\ndef c0, 0, 0.375, 0, 0\nmov r1, c0\nrcp r1.x, c0.x\ntexld r0, r1, s0\nmov oC0, r0\n",
    );
    let g = gpu("the_level_of_detail_at_non_finite_coordinates");
    for (name, s, want) in [
        (
            "one infinite pixel per quad",
            &varying,
            [2.0, 2.0, 0.0, 0.0],
        ),
        ("every pixel infinite", &constant, [0.0; 4]),
    ] {
        let mut d = Draw::new(4, 2);
        d.inputs.push((
            0,
            LinearInput {
                base: [0.0; 4],
                ddx: [1.0, 0.0, 0.0, 0.0],
                ddy: [0.0; 4],
            },
        ));
        d.samplers.push((
            0,
            TextureLevels::Chain(&chain),
            state(Address::Clamp, Filter::Point, MipFilter::Point, [0.0; 4]),
        ));
        let e = emu::run(&emu::compile(s).unwrap(), &d).unwrap();
        let row: Vec<f32> = e.color[0].as_ref().unwrap()[..4]
            .iter()
            .map(|c| c[0])
            .collect();
        assert_eq!(row, want, "{name}: the level each pixel read (emulator)");
        if let Some(g) = &g {
            let o = backend::run(g, s, &d, TargetKind::Raw).unwrap();
            assert_close(name, &e, &o, 0.0);
        }
    }
}

/// Bilinear lookups within half a texel of a face's edge read that face
/// alone on both backends: Direct3D 9 hardware clamps each face (the GPU
/// backend samples the faces as a 2D array for that reason; a Vulkan cube
/// view would blend in the neighbouring face). The faces' blue tags differ
/// by at least 6/18 between a face and any face it touches, so a blend of
/// the neighbour at the weights here (up to 0.47) would move blue by far
/// more than [`FACE_BOUND`].
#[test]
fn cube_faces_are_filtered_alone_at_their_edges() {
    let Some(g) = gpu("cube_faces_are_filtered_alone_at_their_edges") else {
        return;
    };
    let map = cube(false);
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl_cube s0\ntexldl r0, v0, s0\nmov oC0, r0\n");
    // +X: s = (−z + 1)/2 runs 0.95 … 0.992 along x; −Y: s = (x + 1)/2 the same.
    let edges = [
        LinearInput {
            base: [1.0, -0.9, -0.9, 0.0],
            ddx: [0.0, 0.0, -0.012, 0.0],
            ddy: [0.0, 0.25, 0.0, 0.0],
        },
        LinearInput {
            base: [0.9, -1.0, -0.9, 0.0],
            ddx: [0.012, 0.0, 0.0, 0.0],
            ddy: [0.0, 0.0, 0.25, 0.0],
        },
    ];
    for (i, input) in edges.into_iter().enumerate() {
        let mut d = Draw::new(8, 8);
        d.inputs.push((0, input));
        d.samplers.push((
            0,
            TextureLevels::Cube(&map),
            state(Address::Clamp, Filter::Linear, MipFilter::None, [0.0; 4]),
        ));
        let (e, o) = both(&g, &s, &d);
        assert_close(&format!("edge {i}"), &e, &o, FACE_BOUND);
    }
}
