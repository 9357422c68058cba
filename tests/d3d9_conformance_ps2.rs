//! The conformance corpus for ps_2_0 and ps_2_x (tests/d3d9_conformance/ps2/,
//! described in tests/d3d9_conformance/README.md): HLSL compiled by
//! Microsoft's `D3DCompile` for ps_2_0
//! (tests/oracle/corpus/hlsl/conformance_ps2/) and ps_2_x assembly assembled
//! by `D3DAssemble` (tests/oracle/corpus/asm/conformance_ps2x/), the
//! bytecode being the oracle's fixtures, written only by
//! tools/oracle/regen. Every case runs the real binary as a user does —
//! `ps30 run FIXTURE --input … --const … --inputs FILE` — on the emulator and
//! on the GPU backend (llvmpipe or a real device; skipped, saying so, when
//! there is none), and is compared with values worked out here by hand from
//! Direct3D 9's rules, never with ps30's output.
//!
//! The target is D3DFMT_A16B16G16R16F (`--target-format f16`, the four
//! channels `run --texels` prints), so each expected value passes through
//! one rounding to half precision: at most 2⁻¹¹ of its magnitude (half has
//! an 11-bit significand; every expected value here is a normal half or 0).
//! A texel of an 8-bit texture is k/255 in f32 first (one rounding, 2⁻²⁴
//! relative). [`close`] allows exactly those two roundings; the arithmetic
//! cases choose inputs whose results are exact halves, so they pass
//! through no rounding at all.

use crate::common::bin::{ps30, repo, stderr};

type Rgba = [f64; 4];

/// The oracle's bytecode for a corpus file (`hlsl/…/NAME.hlsl` or
/// `asm/…/NAME.psh`).
fn fixture(rel: &str) -> String {
    repo()
        .join("tests/oracle/fixtures")
        .join(format!("{rel}.fxo"))
        .display()
        .to_string()
}

fn hlsl(name: &str) -> String {
    fixture(&format!("hlsl/conformance_ps2/{name}.hlsl"))
}

fn asm(name: &str) -> String {
    fixture(&format!("asm/conformance_ps2x/{name}.psh"))
}

fn inputs(name: &str) -> String {
    repo()
        .join(format!("tests/d3d9_conformance/ps2/{name}.inputs.json"))
        .display()
        .to_string()
}

/// Runs `shader` over a `size` target on `backend` and returns oC0's
/// texels, row by row.
fn run_on(backend: &str, shader: &str, size: &str, args: &[&str]) -> Vec<[f32; 4]> {
    let mut all = vec![
        "run",
        shader,
        "--target",
        size,
        "--target-format",
        "f16",
        "--texels",
        "--json",
        "--backend",
        backend,
    ];
    all.extend_from_slice(args);
    let o = ps30(&all, repo());
    assert!(o.status.success(), "{shader} on {backend}: {}", stderr(&o));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    json["texels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let c: Vec<f32> = p
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_f64().unwrap() as f32)
                .collect();
            [c[0], c[1], c[2], c[3]]
        })
        .collect()
}

/// Whether `got` is `want` after one rounding to half precision (and one
/// to f32 before it): within (2⁻¹¹ + 2⁻²³)·|want| in every channel.
fn close(got: [f32; 4], want: Rgba) -> bool {
    got.iter().zip(want).all(|(&g, w)| {
        let tol = (2f64.powi(-11) + 2f64.powi(-23)) * w.abs();
        (f64::from(g) - w).abs() <= tol
    })
}

/// Runs a case on the emulator and, where there is a device, on the GPU
/// backend, and compares every pixel with `want(x, y)`.
fn case(
    name: &str,
    shader: &str,
    (w, h): (u32, u32),
    args: &[&str],
    want: impl Fn(u32, u32) -> Rgba,
) {
    let size = format!("{w}x{h}");
    let mut backends = vec!["emulator"];
    if crate::common::gpu::gpu(name).is_some() {
        backends.push("gpu");
    }
    for backend in backends {
        let got = run_on(backend, shader, &size, args);
        assert_eq!(got.len(), (w * h) as usize, "{name} on {backend}");
        for y in 0..h {
            for x in 0..w {
                let (g, e) = (got[(y * w + x) as usize], want(x, y));
                assert!(
                    close(g, e),
                    "{name} on {backend}, pixel ({x}, {y}): ps30 {g:?}, expected {e:?}"
                );
            }
        }
    }
}

/// An 8-bit texel as the shader reads it.
fn bytes(c: [u32; 4]) -> Rgba {
    c.map(|k| f64::from(k) / 255.0)
}

/// The texture coordinate `--input tN=texcoord` gives pixel (x, y) of a
/// `w × h` target: its centre in [0, 1].
fn centre(x: u32, y: u32, w: u32, h: u32) -> (f64, f64) {
    (
        (f64::from(x) + 0.5) / f64::from(w),
        (f64::from(y) + 0.5) / f64::from(h),
    )
}

// ----- inputs -----------------------------------------------------------------

#[test]
fn texture_coordinates_arrive_as_given_by_register_or_semantic() {
    // pass.hlsl: `return t` (dcl t0; mov oC0, t0). The centres of a 4×2
    // target are multiples of 1/8 and 1/4: exact halves.
    for name in ["t0", "texcoord0"] {
        let arg = format!("{name}=texcoord");
        case("pass", &hlsl("pass"), (4, 2), &["--input", &arg], |x, y| {
            let (u, v) = centre(x, y, 4, 2);
            [u, v, 0.0, 0.0]
        });
    }
}

#[test]
fn colour_inputs_are_clamped_to_zero_one() {
    // colours.hlsl: `return diffuse - specular` (v0 - v1). Microsoft's page
    // on the input colour register: v# hold "8 bits of unsigned data in the
    // range (0, +1)", so what the vertex stage gives is clamped before the
    // shader reads it: v0 = sat(2, -1, 0.5, 0.25) = (1, 0, 0.5, 0.25),
    // v1 = sat(0.25, 3, -2, 0.5) = (0.25, 1, 0, 0.5), and the difference is
    // (0.75, -1, 0.5, -0.25) — unclamped it would be (1.75, -4, 2.5, -0.25).
    case(
        "colours",
        &hlsl("colours"),
        (1, 1),
        &[
            "--input",
            "color0=2,-1,0.5,0.25",
            "--input",
            "v1=0.25,3,-2,0.5",
        ],
        |_, _| [0.75, -1.0, 0.5, -0.25],
    );
}

#[test]
fn texkill_on_a_texture_coordinate_discards_on_w_alone() {
    // texkill.hlsl: clip(t) is `texkill t0`, which discards when any of the
    // four components is negative (Microsoft's texkill page): w = -1 kills
    // (the target keeps its initial 0), w = 0 does not.
    case(
        "texkill",
        &hlsl("texkill"),
        (2, 1),
        &["--input", "t0=0.5,0.25,0.125,-1"],
        |_, _| [0.0; 4],
    );
    case(
        "texkill",
        &hlsl("texkill"),
        (2, 1),
        &["--input", "t0=0.5,0.25,0.125,0"],
        |_, _| [0.5, 0.25, 0.125, 0.0],
    );
}

// ----- texture reads ------------------------------------------------------------

#[test]
fn texld_reads_the_level_its_derivatives_pick() {
    // tex2d.hlsl: texld r0, t0, s0 on textures/mips.dds (4×4 with authored
    // levels red, green, blue at 200; point filtering, point mips). Over a
    // 2×2 target t0's derivative is 1/2 per pixel, 2 texels of level 0:
    // LOD log2(2) = 1, the green level.
    case(
        "tex2d",
        &hlsl("tex2d"),
        (2, 2),
        &["--input", "t0=texcoord", "--inputs", &inputs("mips")],
        |_, _| bytes([0, 200, 0, 255]),
    );
}

#[test]
fn texldb_adds_w_to_the_level_of_detail() {
    // tex2dbias.hlsl: texldb r0, t0, s0. Over a 4×4 target the texture's
    // 4×4 level 0 is one texel per pixel: LOD 0, plus t0.w. Bias 0, 1, 2
    // pick the red, green and blue levels of mips.dds.
    for (bias, colour) in [
        ("0", [200, 0, 0, 255]),
        ("1", [0, 200, 0, 255]),
        ("2", [0, 0, 200, 255]),
    ] {
        let t0 = format!("t0=texcoord,0,{bias}");
        case(
            "tex2dbias",
            &hlsl("tex2dbias"),
            (4, 4),
            &["--input", &t0, "--inputs", &inputs("mips")],
            |_, _| bytes(colour),
        );
    }
}

/// Texel (x, 0) of textures/dxt1.dds (tools/textures/make.py): block 0's
/// row 0 is red, green, (170, 85, 0), (85, 170, 0); block 1's is blue, red
/// and transparent black twice.
fn dxt1_row0(x: u32) -> Rgba {
    bytes(match x {
        0 | 5 => [255, 0, 0, 255],
        1 => [0, 255, 0, 255],
        2 => [170, 85, 0, 255],
        3 => [85, 170, 0, 255],
        4 => [0, 0, 255, 255],
        _ => [0, 0, 0, 0],
    })
}

#[test]
fn texldp_divides_by_w() {
    // tex2dproj.hlsl: texldp r0, t1, s0 with t1 = (0.625, 0.25, 0, 2):
    // (u, v) = (0.3125, 0.125), texel (floor(0.3125·8), floor(0.125·4)) =
    // (2, 0) of the 8×4 DXT1 texture. Undivided, u = 0.625 would be texel 5
    // (red).
    case(
        "tex2dproj",
        &hlsl("tex2dproj"),
        (1, 1),
        &["--input", "t1=0.625,0.25,0,2", "--inputs", &inputs("dxt1")],
        |_, _| dxt1_row0(2),
    );
}

#[test]
fn texcube_and_tex3d_read_layered_textures_from_texture_coordinates() {
    // texcube.hlsl: texld on dcl_cube s1 along t2 = (0.5, -1, 0.25). The
    // major axis is -y: face 3 (D3DCUBEMAP_FACE_NEGATIVE_Y), sc = x = 0.5,
    // tc = -z = -0.25, |ma| = 1; s = (0.5/1 + 1)/2 = 0.75, t = 0.375: texel
    // (3, 1) of the 4×4 face, (40·4, 16·3, 60·1) by make.py's formula.
    // Constant coordinates: zero derivatives, level 0.
    case(
        "texcube",
        &hlsl("texcube"),
        (1, 1),
        &["--input", "t2=0.5,-1,0.25", "--inputs", &inputs("cube")],
        |_, _| bytes([160, 48, 60, 255]),
    );
    // tex3d.hlsl: texld on dcl_volume s2 at t7 (the last texture
    // coordinate) = (pixel centre of a 4×4 target, 0.875): one texel per
    // pixel (LOD 0), texel (x, y, 3) of the 4×4×4 volume: (60x, 60y, 180).
    case(
        "tex3d",
        &hlsl("tex3d"),
        (4, 4),
        &[
            "--input",
            "t7=texcoord,0.875",
            "--inputs",
            &inputs("volume"),
        ],
        |x, y| bytes([60 * x, 60 * y, 180, 255]),
    );
}

// ----- arithmetic -----------------------------------------------------------------

#[test]
fn ps_2_0_arithmetic_on_exact_values() {
    // arith.hlsl: rsq, rcp, exp, log of c0 = (4, 8, 3, 16): 1/√4 = 0.5,
    // 1/8, 2³ = 8, log2(16) = 4, all exact in f32 and in half.
    case(
        "arith",
        &hlsl("arith"),
        (1, 1),
        &["--const", "c0=4,8,3,16"],
        |_, _| [0.5, 0.125, 8.0, 4.0],
    );
    // select.hlsl with k = c0 = (0.25, 0.75, 2, 4), t0 the centres of a 4×1
    // target (u = (x + 0.5)/4, v = 0.5) and v0.x = 0.375:
    // x: u > 0.5 ? 0.25 : 0.75; y: u·2 + 0.5·4; z: 0.375·4 = 1.5;
    // w: lerp(0.25, 0.75, u) = 0.25 + 0.5u. Every value is a multiple of
    // 1/16 below 4: exact.
    case(
        "select",
        &hlsl("select"),
        (4, 1),
        &[
            "--input",
            "t0=texcoord",
            "--input",
            "v0=0.375",
            "--const",
            "c0=0.25,0.75,2,4",
        ],
        |x, y| {
            let (u, v) = centre(x, y, 4, 1);
            [
                if u > 0.5 { 0.25 } else { 0.75 },
                2.0 * u + 4.0 * v,
                1.5,
                0.25 + 0.5 * u,
            ]
        },
    );
}

#[test]
fn inputs_files_name_inputs_as_draw_lists_do() {
    // ps2/select.inputs.json gives select.hlsl's inputs by semantic and
    // register (texcoord0 = the pixel centres, v0.x = 0.375) and c0: the
    // values of ps_2_0_arithmetic_on_exact_values' second case.
    case(
        "select",
        &hlsl("select"),
        (4, 1),
        &["--inputs", &inputs("select")],
        |x, y| {
            let (u, v) = centre(x, y, 4, 1);
            [
                if u > 0.5 { 0.25 } else { 0.75 },
                2.0 * u + 4.0 * v,
                1.5,
                0.25 + 0.5 * u,
            ]
        },
    );
}

// ----- ps_2_x: predication, flow control, gradients ---------------------------------

#[test]
fn predication_selects_per_component() {
    // predication.psh: r0 = c2 (0.25); setp_gt p0, t0, c0 (0.5); (p0) mov
    // r0, c1 (1). t0 = (u, 0.5, 0.75, 0.25) over a 4×1 target: x is 1 where
    // u > 0.5 (pixels 2, 3); y: 0.5 > 0.5 is false; z true; w false.
    case(
        "predication",
        &asm("predication"),
        (4, 1),
        &["--input", "t0=texcoord,0.75,0.25"],
        |x, _| [if x >= 2 { 1.0 } else { 0.25 }, 0.25, 1.0, 0.25],
    );
}

#[test]
fn dynamic_branches_and_breaks_follow_each_pixel() {
    // dynamic.psh over a 4×2 target: r1.x = 1 where t0.x > 0.5, else 0.5;
    // the rep runs until r1.y ≥ t0.y·8, adding 1 each time: t0.y = 0.25
    // stops at 2, 0.75 at 6; r1.y·0.125 = 0.25 and 0.75.
    case(
        "dynamic",
        &asm("dynamic"),
        (4, 2),
        &["--input", "t0=texcoord"],
        |x, y| {
            let (u, v) = centre(x, y, 4, 2);
            let count = (v * 8.0).ceil();
            [if u > 0.5 { 1.0 } else { 0.5 }, count * 0.125, 0.0, 0.0]
        },
    );
}

#[test]
fn static_flow_control_follows_the_applications_constants() {
    // static.psh: r0 = i1.x × c0 (0.25, 0.5, 0, 0); doubled if b0; plus c1
    // (0, 0, 1, 0.5) through `callnz l0, b1`.
    // i1 = 3, b0 and b1 true: (1.5, 3, 0, 0) + c1 = (1.5, 3, 1, 0.5).
    case(
        "static",
        &asm("static"),
        (1, 1),
        &[
            "--input", "t0=0", "--int", "i1=3", "--bool", "b0=true", "--bool", "b1=true",
        ],
        |_, _| [1.5, 3.0, 1.0, 0.5],
    );
    // i1 = 1, both false: c0 once.
    case(
        "static",
        &asm("static"),
        (1, 1),
        &[
            "--input", "t0=0", "--int", "i1=1", "--bool", "b0=false", "--bool", "b1=false",
        ],
        |_, _| [0.25, 0.5, 0.0, 0.0],
    );
}

#[test]
fn gradient_instructions_and_texldd() {
    // gradients.psh over a 4×2 target, t0 = the pixel centres: dsx t0.x =
    // 1/4 per pixel, dsy t0.y = 1/2. texldd on mips.dds with gradients
    // (0.5, 0) and (0, 0.5): 0.5·4 = 2 texels of level 0 per pixel, LOD 1,
    // the green level: r3 = (0.25, 0.5, green.g, green.r).
    case(
        "gradients",
        &asm("gradients"),
        (4, 2),
        &["--input", "t0=texcoord", "--inputs", &inputs("mips")],
        |_, _| [0.25, 0.5, 200.0 / 255.0, 0.0],
    );
}

#[test]
fn texldp_and_texldb_in_one_ps_2_x_shader() {
    // texldp_texldb.psh on dxt1.dds: texldp at t1 = (0.625, 0.25, 0, 2) →
    // texel (2, 0) as in texldp_divides_by_w; texldb at t2 = (0.5625,
    // 0.125, 0, 5) → texel (4, 0), blue (the single level: the bias changes
    // nothing; divided by w it would be texel 0, red). `mov r2.zw, r1.yz`:
    // a source swizzle is indexed by the destination's component, and .yz
    // is .yzzz, so z and w both take r1.z: r2 = (r0.x, r0.y, r1.z, r1.z).
    let (p, b) = (dxt1_row0(2), dxt1_row0(4));
    case(
        "texldp_texldb",
        &asm("texldp_texldb"),
        (1, 1),
        &[
            "--input",
            "t1=0.625,0.25,0,2",
            "--input",
            "t2=0.5625,0.125,0,5",
            "--inputs",
            &inputs("dxt1"),
        ],
        |_, _| [p[0], p[1], b[2], b[2]],
    );
}

#[test]
fn draw_lists_name_ps_2_0_inputs_by_register_and_semantic() {
    // ps2/inputs.json through `ps30 render -o DIR`: pass.hlsl with t0 named
    // `t0` and `texcoord0`, both the pixel centres; colours.hlsl with
    // color0 = (-1 + 2x, 0.5, 1.5, 0.25) and color1 = (0, 0, 0, 4x) over a
    // 2×1 target (x = 0, 1 at the pixels' integer centres, the draw lists'
    // base being the value at pixel 0). Clamped: v0 = (sat(-1 + 2x), 0.5, 1,
    // 0.25), v1.w = sat(4x); v0 - v1 = (0, 0.5, 1, 0.25) at x = 0 and
    // (1, 0.5, 1, -0.75) at x = 1.
    let dir = tempfile::tempdir().unwrap();
    let list = repo().join("tests/d3d9_conformance/ps2/inputs.json");
    let o = ps30(
        &[
            "render",
            list.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
            "-q",
        ],
        repo(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let read = |name: &str| {
        let img =
            ps30::core::image::load(&dir.path().join(format!("{name}.exr")), &Default::default())
                .unwrap();
        (img.width, img.pixels)
    };
    for target in ["by_register", "by_semantic"] {
        let (w, p) = read(target);
        for (i, got) in p.iter().enumerate() {
            let (x, y) = (i as u32 % w, i as u32 / w);
            let (u, v) = centre(x, y, 4, 2);
            assert_eq!(got.map(f64::from), [u, v, 0.0, 0.0], "{target} ({x}, {y})");
        }
    }
    let (_, p) = read("colours");
    assert_eq!(p[0], [0.0, 0.5, 1.0, 0.25]);
    assert_eq!(p[1], [1.0, 0.5, 1.0, -0.75]);
}

// ----- around the shader: several targets, flat shading -----------------------------

/// `ps30 render LIST -o DIR --backend BACKEND -q` for a list of `ps2/`: each
/// target's width and pixels, read back from its EXR file (f32, so values
/// pass unrounded except where the target's own format rounds them).
fn render_ps2(
    list: &str,
    backend: &str,
) -> std::collections::BTreeMap<String, (u32, Vec<[f32; 4]>)> {
    let dir = tempfile::tempdir().unwrap();
    let path = repo().join(format!("tests/d3d9_conformance/ps2/{list}"));
    let o = ps30(
        &[
            "render",
            path.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
            "--backend",
            backend,
            "-q",
        ],
        repo(),
    );
    assert!(o.status.success(), "{list} on {backend}: {}", stderr(&o));
    let mut out = std::collections::BTreeMap::new();
    for e in std::fs::read_dir(dir.path()).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "exr") {
            continue;
        }
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        let img = ps30::core::image::load(&p, &Default::default()).unwrap();
        out.insert(name, (img.width, img.pixels));
    }
    out
}

/// The backends a case runs on: the emulator, and the GPU backend where
/// there is a device.
fn backends(name: &str) -> Vec<&'static str> {
    let mut b = vec!["emulator"];
    if crate::common::gpu::gpu(name).is_some() {
        b.push("gpu");
    }
    b
}

#[test]
fn four_render_targets_and_flat_shaded_colours() {
    for backend in backends("ps2 pixel.json") {
        let t = render_ps2("pixel.json", backend);
        let px = |name: &str, x: u32, y: u32| {
            let (w, p) = &t[name];
            p[(y * w + x) as usize].map(f64::from)
        };
        // mrt.hlsl over a 4×1 target with t0 = (⅛ + ¼x, ¼, ½, 1): oC0 = t0,
        // oC1 = t0·½, oC2 = t0.wzyx, oC3 = t0 + ¼, each into its target. Every
        // value is a short binary fraction: exact in f32 and in half (mrt_c).
        for x in 0..4 {
            let r = 0.125 + 0.25 * f64::from(x);
            let at = |n: &str| px(n, x, 0);
            assert_eq!(at("mrt_a"), [r, 0.25, 0.5, 1.0], "{backend} mrt_a {x}");
            assert_eq!(
                at("mrt_b"),
                [r * 0.5, 0.125, 0.25, 0.5],
                "{backend} mrt_b {x}"
            );
            assert_eq!(at("mrt_c"), [1.0, 0.5, 0.25, r], "{backend} mrt_c {x}");
            assert_eq!(
                at("mrt_d"),
                [r + 0.25, 0.5, 0.75, 1.25],
                "{backend} mrt_d {x}"
            );
        }
        // flat_color.hlsl under D3DSHADE_FLAT: each colour holds the first
        // vertex's value, base − ½·ddx − ½·ddy (docs/pixel-rules.md), and
        // ps_2_0 clamps it to [0, 1] as it enters the shader: color0 =
        // (0.5 − 1/16, 0.25 − 1/8, 0.75, 1 + 1/16) → (0.4375, 0.125, 0.75, 1).
        // color1's alpha stays interpolated (D3DSHADE_FLAT flattens the
        // specular colour, not its alpha): 0.75 + x/8, clamped at x = 3
        // (1.125 → 1); its colour (0.25 − 1/8, 0.5, 0.25 − 1/16).
        for (x, y) in [(0, 0), (1, 0), (3, 0), (0, 1), (3, 1)] {
            assert_eq!(
                px("flat_a", x, y),
                [0.4375, 0.125, 0.75, 1.0],
                "{backend} flat_a ({x}, {y})"
            );
            let alpha = (0.75 + 0.125 * f64::from(x)).min(1.0);
            assert_eq!(
                px("flat_b", x, y),
                [0.125, 0.5, 0.1875, alpha],
                "{backend} flat_b ({x}, {y})"
            );
        }
    }
}

// ----- float rules and constants that are not finite -------------------------------------

/// `ps30 run SHADER --target 1x1 --target-format f16 -o DIR/o.exr` with
/// `args` on `backend`: the one texel of the four-channel half target as the
/// EXR file holds it (infinities with their signs, NaN and −0 kept; every
/// finite value the cases expect is an exact half).
fn run_f32(backend: &str, shader: &str, args: &[&str]) -> [f32; 4] {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o.exr");
    let mut all = vec![
        "run",
        shader,
        "--target",
        "1x1",
        "--target-format",
        "f16",
        "--backend",
        backend,
        "-q",
        "-o",
        out.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    let o = ps30(&all, repo());
    assert!(o.status.success(), "{shader} on {backend}: {}", stderr(&o));
    ps30::core::image::load(&out, &Default::default())
        .unwrap()
        .pixels[0]
}

#[test]
fn zero_times_infinity_under_both_float_rules() {
    // float_rules.hlsl compiled for ps_2_0 with a = c0 = (0, 1, 1, 0),
    // b = c1 = (inf, 2, 3, inf), c = c2 = (5, 0, 0, 0.5): x = a.x·b.x (mul),
    // y = a.x·b.x + c.x (mad), z = a.xyz·b.xyz (dp3), w = a.w·b.w + c.w
    // (mad). Every one holds 0 × inf: NaN under `d3d9` (IEEE 754's invalid
    // product, docs/float-rules.md), 0 under `hardware`, which gives
    // (0, 5, 0 + 2 + 3, 0.5), each exact.
    let shader = hlsl("float_rules");
    let consts = [
        "--const",
        "c0=0,1,1,0",
        "--const",
        "c1=inf,2,3,inf",
        "--const",
        "c2=5,0,0,0.5",
    ];
    for backend in backends("ps2 float_rules") {
        let mut d3d9 = consts.to_vec();
        d3d9.extend_from_slice(&["--float-rules", "d3d9"]);
        let t = run_f32(backend, &shader, &d3d9);
        assert!(t.iter().all(|v| v.is_nan()), "{backend} d3d9: {t:?}");
        let mut hw = consts.to_vec();
        hw.extend_from_slice(&["--float-rules", "hardware"]);
        let t = run_f32(backend, &shader, &hw);
        assert_eq!(t, [0.0, 5.0, 5.0, 0.5], "{backend} hardware");
    }
}

#[test]
fn constants_that_are_not_finite_numbers() {
    // nonfinite.hlsl compiled for ps_2_0 without optimisation: x =
    // rcp(rcp(k.x)), y = rcp(rcp(k.y)), z = k.z·k.w, w = rcp(k.w). With
    // k = (inf, −inf, 2, 0.25) under IEEE 754's reciprocal (rcp(±inf) = ±0,
    // rcp(±0) = ±inf; docs/float-rules.md): x = +inf, y = −inf, z = 0.5,
    // w = 4. Under `d3d9`, as the ps_3_0 corpus's `inf` and `nan` draws.
    let shader = hlsl("nonfinite");
    for backend in backends("ps2 nonfinite") {
        let t = run_f32(
            backend,
            &shader,
            &["--const", "c0=inf,-inf,2,0.25", "--float-rules", "d3d9"],
        );
        assert_eq!(t, [f32::INFINITY, f32::NEG_INFINITY, 0.5, 4.0], "{backend}");
        // k = (NaN, 0, 1, −0): NaN propagates through rcp; rcp(rcp(0)) =
        // rcp(inf) = 0; 1·(−0) = −0; rcp(−0) = −inf (the ps_3_0 corpus's
        // `nan` case, which both backends pass bit for bit).
        let t = run_f32(
            backend,
            &shader,
            &["--const", "c0=nan,0,1,0x80000000", "--float-rules", "d3d9"],
        );
        assert!(t[0].is_nan(), "{backend}: {t:?}");
        let bits = |v: f32| v.to_bits();
        assert_eq!(
            [t[1], t[2], t[3]].map(bits),
            [0.0f32, -0.0, f32::NEG_INFINITY].map(bits),
            "{backend}: {t:?}"
        );
    }
}
