//! The project's own conformance corpus (tests/d3d9_conformance/, described
//! in its README and in docs/conformance.md): HLSL compiled by Microsoft's
//! compiler (the oracle's fixtures under
//! tests/oracle/fixtures/hlsl/conformance/, written only by
//! tools/oracle/regen) and hand-made bytecode, drawn through `ps30 render`
//! with draw lists and through `ps30 run --inputs`, exactly as a user runs
//! them, and compared with values computed here — by hand or in f64 from the
//! rules of Direct3D 9 — never with ps30's own output.
//!
//! Render targets are D3DFMT_A32B32G32R32F unless a case is about formats,
//! so `-o DIR` writes each one's exact f32 values to `NAME.exr`.
//!
//! Tolerances, where a case has one, count roundings: a texel of an 8-bit
//! texture is the code c as c/255 (one correctly rounded division, or a
//! product with f32(1/255): at most 1 ulp), and each product and sum of a
//! filter adds at most half an ulp of the running result (every weight and
//! texel is ≥ 0, so the relative bound adds up). [`close`] takes that count.

use crate::common::bin::{ps30, repo, stderr};
use std::collections::HashMap;
use std::path::PathBuf;

type Rgba = [f32; 4];

fn corpus() -> PathBuf {
    repo().join("tests/d3d9_conformance")
}

/// What a list drew: each target's width and pixels, by name.
pub(crate) type Targets = HashMap<String, (u32, Vec<Rgba>)>;

/// The backends every list is drawn on: the emulator, and the GPU through
/// the translation (`render --backend gpu`: the shaders run on the device,
/// the pixel state around them is ps30's output merger on both).
const BACKENDS: [&str; 2] = ["emulator", "gpu"];

/// Renders `list` (a file of the corpus) through `ps30 render LIST -o DIR
/// --backend BACKEND` and reads every target back from its EXR file; `None`
/// on the GPU when this machine has no Vulkan device (outside CI).
fn render(list: &str, backend: &str) -> Option<Targets> {
    render_file(&corpus().join(list), backend)
}

/// [`render`] for a draw list anywhere (other corpora share it).
pub(crate) fn render_file(path: &std::path::Path, backend: &str) -> Option<Targets> {
    let list = path.display().to_string();
    let dir = tempfile::tempdir().unwrap();
    let o = ps30(
        &[
            "render",
            path.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
            "-q",
            "--backend",
            backend,
        ],
        repo(),
    );
    if backend == "gpu" && o.status.code() == Some(2) && std::env::var_os("CI").is_none() {
        eprintln!("{list} on the GPU: skipped: {}", stderr(&o));
        return None;
    }
    assert_eq!(
        o.status.code(),
        Some(0),
        "{list} ({backend}): {}",
        stderr(&o)
    );
    let text: serde_json::Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let mut out = HashMap::new();
    for t in text["targets"].as_array().unwrap() {
        let name = t["name"].as_str().unwrap();
        let exr = dir.path().join(format!("{name}.exr"));
        let img = ps30::core::image::load(&exr, &Default::default())
            .unwrap_or_else(|e| panic!("{list}: {name}: {e}"));
        out.insert(name.to_string(), (img.width, img.pixels));
    }
    Some(out)
}

/// `list` rendered on every backend that this machine has.
fn rendered(list: &str) -> Vec<(&'static str, Targets)> {
    BACKENDS
        .iter()
        .filter_map(|&b| render(list, b).map(|t| (b, t)))
        .collect()
}

/// Pixel (x, y) of target `name`.
fn px(t: &Targets, name: &str, x: u32, y: u32) -> Rgba {
    let (w, p) = &t[name];
    p[(y * w + x) as usize]
}

/// Whether `got` is within `roundings` half-ulps (2⁻²⁴ relative each) of
/// `want` in every channel; 0 only as 0.
fn close(got: Rgba, want: [f64; 4], roundings: u32) -> bool {
    got.iter().zip(want).all(|(&g, w)| {
        let tol = f64::from(roundings) * 2f64.powi(-24) * w.abs();
        (f64::from(g) - w).abs() <= tol
    })
}

fn assert_close(case: &str, got: Rgba, want: [f64; 4], roundings: u32) {
    assert!(
        close(got, want, roundings),
        "{case}: ps30 {got:?}, expected {want:?} (± {roundings} half-ulps)"
    );
}

fn bytes(c: [u32; 4]) -> [f64; 4] {
    c.map(|k| f64::from(k) / 255.0)
}

// ----- cube textures ---------------------------------------------------------

/// Texel (x, y) of level `l` of face `f` of textures/cube.dds
/// (tools/textures/make.py): (40·(f+1), 80·l + 16·x, 60·y, 255).
fn cube_texel(f: u32, l: u32, x: u32, y: u32) -> [f64; 4] {
    bytes([40 * (f + 1), 80 * l + 16 * x, 60 * y, 255])
}

/// The face and the face coordinates (s, t) of a direction, by the table of
/// Direct3D's cube maps (Microsoft's "Cubic Environment Mapping" page; the
/// same table as OpenGL's): the major axis picks the face; sc, tc are
/// (−z, −y) on +X, (z, −y) on −X, (x, z) on +Y, (x, −z) on −Y, (x, −y) on
/// +Z, (−x, −y) on −Z; s = (sc/|ma| + 1)/2. The corpus has no ties.
fn cube_face(d: [f64; 3]) -> (u32, f64, f64) {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let major = ax.max(ay).max(az);
    let ties = [ax, ay, az].iter().filter(|&&a| a == major).count();
    assert_eq!(ties, 1, "a tie for the major axis in {d:?}");
    let (f, sc, tc, ma) = if ax > ay && ax > az {
        if x > 0.0 {
            (0, -z, -y, ax)
        } else {
            (1, z, -y, ax)
        }
    } else if ay > az {
        if y > 0.0 {
            (2, x, z, ay)
        } else {
            (3, x, -z, ay)
        }
    } else if z > 0.0 {
        (4, x, -y, az)
    } else {
        (5, -x, -y, az)
    };
    (f, (sc / ma + 1.0) / 2.0, (tc / ma + 1.0) / 2.0)
}

/// Point sampling at level `l` of a 4×4 cube: the texel that holds (s, t).
fn cube_point(d: [f64; 3], l: u32) -> [f64; 4] {
    let (f, s, t) = cube_face(d);
    let side = f64::from(4u32 >> l);
    cube_texel(f, l, (s * side) as u32, (t * side) as u32)
}

#[test]
fn cube_faces_levels_seams_and_derivatives() {
    for (backend, t) in rendered("cube.json") {
        eprintln!("cube.json drawn on the {backend}");
        cube_faces_levels_seams_and_derivatives_on(&t);
    }
}

fn cube_faces_levels_seams_and_derivatives_on(t: &Targets) {
    // texldl at level 0 on every face, the texel centre (i + ½)/4 chosen
    // per face; f4_long is f4's direction doubled (the face coordinates
    // divide by the major axis).
    for (name, d) in [
        ("f0", [1.0, -0.25, 0.25]),
        ("f1", [-1.0, -0.75, 0.25]),
        ("f2", [0.75, 1.0, -0.75]),
        ("f3", [-0.75, -1.0, 0.25]),
        ("f4", [-0.25, 0.25, 1.0]),
        ("f5", [-0.25, 0.75, -1.0]),
        ("f4_long", [-0.5, 0.5, 2.0]),
    ] {
        assert_close(name, px(t, name, 0, 0), cube_point(d, 0), 2);
    }
    // Authored levels: level 1 of +Y, level 2 of −Z (each face has its own).
    assert_close(
        "f2_level1",
        px(t, "f2_level1", 0, 0),
        cube_point([0.75, 1.0, -0.75], 1),
        2,
    );
    assert_close(
        "f5_level2",
        px(t, "f5_level2", 0, 0),
        cube_point([-0.25, 0.75, -1.0], 2),
        2,
    );
    // Bilinear at s = 0.99 on +X, t = 0.625 (a texel row): u = 0.99·4 − ½ =
    // 3.46 blends texel 3 with texel 4, which does not exist on the face.
    // Direct3D 9 filters each face alone (no seamless cube filtering before
    // Direct3D 10.1): texel 4 is texel 3 clamped, so the result is texel
    // (3, 2) of face 0. A seamless filter would mix in texel (0, 2) of −Z,
    // the face across the edge, with weight 0.46.
    let (f, s, tt) = cube_face([1.0, -0.25, -0.98]);
    assert_eq!((f, (s * 4.0 - 0.5).floor(), tt * 4.0 - 0.5), (0, 3.0, 2.0));
    // The GPU backend binds a cube as its six faces and picks the face in
    // the shader (Vulkan's cube views filter seamlessly), so both backends
    // clamp at the face's edge.
    assert_close("seam", px(t, "seam", 0, 0), cube_texel(0, 0, 3, 2), 4);
    // Implicit level of detail: v0 = (x − ½ + px, ½ − py, 1) on +Z, so
    // s = (sc + 1)/2 moves by ½ per pixel: 2 texels of level 0 per pixel,
    // log2(2) = 1, level 1 (2×2), whose texel (px, py) sits at the pixel's
    // face coordinates (¼ or ¾).
    for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        assert_close(
            "implicit_lod",
            px(t, "implicit_lod", x, y),
            cube_texel(4, 1, x, y),
            2,
        );
    }
}

// ----- volume textures -------------------------------------------------------

/// Texel (x, y, z) of level `l` of textures/volume.dds: (60x, 60y, 60z,
/// 255 − 100·l).
fn vol_texel(l: u32, x: u32, y: u32, z: u32) -> [f64; 4] {
    bytes([60 * x, 60 * y, 60 * z, 255 - 100 * l])
}

/// Trilinear filtering of level `l` at (u, v, w) in f64, wrap addressing.
fn vol_linear(l: u32, at: [f64; 3]) -> [f64; 4] {
    let side = 4i64 >> l;
    let mut sum = [0.0; 4];
    let taps = at.map(|c| {
        let p = c * side as f64 - 0.5;
        let i = p.floor();
        (i as i64, p - i)
    });
    for corner in 0..8 {
        let mut w = 1.0;
        let mut idx = [0u32; 3];
        for (a, &(i, frac)) in taps.iter().enumerate() {
            let hi = corner >> a & 1 == 1;
            w *= if hi { frac } else { 1.0 - frac };
            idx[a] = (i + i64::from(hi)).rem_euclid(side) as u32;
        }
        let t = vol_texel(l, idx[0], idx[1], idx[2]);
        for c in 0..4 {
            sum[c] += w * t[c];
        }
    }
    sum
}

#[test]
fn volume_texels_trilinear_and_authored_levels() {
    for (backend, t) in rendered("volume.json") {
        eprintln!("volume.json drawn on the {backend}");
        volume_texels_trilinear_and_authored_levels_on(&t);
    }
}

fn volume_texels_trilinear_and_authored_levels_on(t: &Targets) {
    // point: (0.375, 0.625, 0.875) is the centre of texel (1, 2, 3)
    assert_close("point", px(t, "point", 0, 0), vol_texel(0, 1, 2, 3), 2);
    // linear at the centre: the eight texels around it, weights ⅛ (17 sums
    // and products after the conversion)
    let centre = vol_linear(0, [0.5; 3]);
    assert_eq!(centre, bytes([90, 90, 90, 255]));
    assert_close("linear_centre", px(t, "linear_centre", 0, 0), centre, 34);
    // level 1 (authored alpha 155): (0.75, 0.25, 0.75) is texel (1, 0, 1)
    assert_close("level1", px(t, "level1", 0, 0), vol_texel(1, 1, 0, 1), 2);
    // LOD 0.5 with MIPFILTER LINEAR: half of each level's trilinear centre
    let want: [f64; 4] = std::array::from_fn(|c| {
        0.5 * vol_linear(0, [0.5; 3])[c] + 0.5 * vol_linear(1, [0.5; 3])[c]
    });
    assert_eq!(want, bytes([60, 60, 60, 205]));
    assert_close("trilinear", px(t, "trilinear", 0, 0), want, 70);
}

// ----- DDS files ---------------------------------------------------------------

#[test]
fn dds_block_compression_and_authored_mips() {
    for (backend, t) in rendered("dds.json") {
        eprintln!("dds.json drawn on the {backend}");
        dds_block_compression_and_authored_mips_on(&t);
    }
}

fn dds_block_compression_and_authored_mips_on(t: &Targets) {
    // DXT1 (tools/textures/make.py): row 0 of block 0 holds indices 0–3 of
    // red 0xF800 and green 0x07E0: the 5:6:5 codes widen to 255, and the
    // two interpolated colours are (2·c0 + c1)/3 and (c0 + 2·c1)/3, exact
    // integers here. Block 1 has colour0 < colour1: index 3 is transparent
    // black (Microsoft's "Compressed Texture Resources" page).
    let dxt1 = [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [170, 85, 0, 255],
        [85, 170, 0, 255],
        [0, 0, 255, 255],
        [255, 0, 0, 255],
        [0, 0, 0, 0],
        [0, 0, 0, 0],
    ];
    for (x, want) in dxt1.into_iter().enumerate() {
        assert_close("dxt1", px(t, "dxt1", x as u32, 0), bytes(want), 2);
    }
    // DXT3: the colours of DXT1's block 0, alpha nibbles 0, 5, 10, 15 × 17.
    // DXT5: alpha0 252 > alpha1 0, codes 0, 1, 2, 7: 252, 0, 6·252/7 = 216
    // and 252/7 = 36.
    let colours = [[255, 0, 0], [0, 255, 0], [170, 85, 0], [85, 170, 0]];
    for (x, (a3, a5)) in [(0, 252), (85, 0), (170, 216), (255, 36)]
        .into_iter()
        .enumerate()
    {
        let [r, g, b] = colours[x];
        assert_close("dxt3", px(t, "dxt3", x as u32, 0), bytes([r, g, b, a3]), 2);
        assert_close("dxt5", px(t, "dxt5", x as u32, 0), bytes([r, g, b, a5]), 2);
    }
    // Authored levels (red, green, blue at 200): a box filter of level 0
    // would give red again. LOD 0.5 with MIPFILTER LINEAR is half of red and
    // half of green (three roundings after the conversion).
    assert_close("level0", px(t, "level0", 0, 0), bytes([200, 0, 0, 255]), 2);
    assert_close("level1", px(t, "level1", 0, 0), bytes([0, 200, 0, 255]), 2);
    assert_close("level2", px(t, "level2", 0, 0), bytes([0, 0, 200, 255]), 2);
    assert_close(
        "level0_5",
        px(t, "level0_5", 0, 0),
        bytes([100, 100, 0, 255]),
        5,
    );
}

// ----- non-finite constants ------------------------------------------------------

const INF: f32 = f32::INFINITY;

fn bits(v: Rgba) -> [u32; 4] {
    v.map(f32::to_bits)
}

/// Asserts `got` has the bits of `want`, channel by channel. On the GPU,
/// a channel also passes where `want` is a zero or a subnormal and the
/// device gave a zero of either sign: Vulkan lets a device flush
/// subnormals and drop the sign of a zero unless it offers
/// `shaderDenormPreserveFloat32` and `shaderSignedZeroInfNanPreserveFloat32`
/// (llvmpipe offers neither, and wgpu asks for neither) — the difference
/// `compare` explains (see `the_gpu_backend_agrees_or_compare_explains`).
fn assert_bits(case: &str, backend: &str, got: Rgba, want: Rgba) {
    let ok = got.iter().zip(want).all(|(&g, w)| {
        g.to_bits() == w.to_bits() || backend == "gpu" && (w == 0.0 || w.is_subnormal()) && g == 0.0
    });
    assert!(
        ok,
        "{case} ({backend}): {:08x?}, expected {:08x?}",
        bits(got),
        bits(want)
    );
}

#[test]
fn non_finite_constants_from_draw_lists_and_def() {
    for (backend, t) in rendered("nonfinite.json") {
        eprintln!("nonfinite.json drawn on the {backend}");
        non_finite_constants_from_draw_lists_and_def_on(&t, backend);
    }
}

fn non_finite_constants_from_draw_lists_and_def_on(t: &Targets, backend: &str) {
    let p = |n: &str| px(t, n, 0, 0);
    // c0 = (inf, −inf, inf, 0): rcp(rcp(±inf)) = rcp(±0) = ±inf; inf × 0 is
    // NaN under d3d9 and 0 under hardware; rcp(0) = +inf.
    let inf = p("inf");
    assert_eq!([inf[0], inf[1], inf[3]], [INF, -INF, INF]);
    assert!(inf[2].is_nan(), "inf × 0 under d3d9: {inf:?}");
    assert_eq!(bits(p("inf_hw")), bits([INF, -INF, 0.0, INF]));
    // c0 = (NaN, 0, 1, −0): NaN stays NaN; rcp(rcp(0)) = rcp(inf) = 0;
    // 1 × −0 = −0; rcp(−0) = −inf.
    let nan = p("nan");
    assert!(nan[0].is_nan());
    assert_eq!(
        bits([0.0, nan[1], nan[2], nan[3]]),
        bits([0.0, 0.0, -0.0, -INF])
    );
    // def_bits.hlsl: Microsoft's compiler writes 1e-45 as 0 and −1e-45 as −0
    // (its listing: `def c1, 0, -0, 1.17549435e-038, 0.5`); × (1, 1, ½, 1):
    // 2⁻¹²⁶ · ½ = 2⁻¹²⁷ is a denormal, kept by d3d9, a zero under hardware.
    let half_min = f32::from_bits(1 << 22);
    let small = [0.0, -0.0, half_min, 0.5];
    assert_bits("def_small", backend, p("def_small"), small);
    assert_bits(
        "def_small_hw",
        backend,
        p("def_small_hw"),
        [0.0, -0.0, 0.0, 0.5],
    );
    // Hand-made bytecode (tests/oracle/corpus/dis/def-bits): `def c0, X, 0,
    // 0, 1; mov oC0, c0`, X read from the token as it is.
    assert_eq!(bits(p("def_inf")), bits([INF, 0.0, 0.0, 1.0]));
    assert_eq!(bits(p("def_neg_inf")), bits([-INF, 0.0, 0.0, 1.0]));
    assert!(p("def_snan")[0].is_nan());
    assert!(p("def_nan_payload")[0].is_nan());
    let first = |n: &str| [p(n)[0], 0.0, 0.0, 0.0];
    let denormal = f32::from_bits(1);
    assert_bits(
        "def_denormal",
        backend,
        first("def_denormal"),
        [denormal, 0.0, 0.0, 0.0],
    );
    assert_bits(
        "def_denormal_hw",
        backend,
        first("def_denormal_hw"),
        [0.0; 4],
    );
    assert_bits(
        "def_neg_zero",
        backend,
        first("def_neg_zero"),
        [-0.0, 0.0, 0.0, 0.0],
    );
}

/// `ps30 run SHADER --inputs INPUTS ARGS -o DIR/o.exr -q` (SHADER below the
/// repository, INPUTS a path): the exit status, stderr, and the red channel of
/// every pixel when the run succeeded.
fn run_red(
    shader: &str,
    inputs: &std::path::Path,
    args: &[&str],
) -> (Option<i32>, String, Vec<f32>) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o.exr");
    let shader = repo().join(shader);
    let mut all = vec![
        "run",
        shader.to_str().unwrap(),
        "--inputs",
        inputs.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", out.to_str().unwrap(), "-q"]);
    let o = ps30(&all, repo());
    let red = match o.status.code() {
        Some(0) => ps30::core::image::load(&out, &Default::default())
            .unwrap()
            .pixels
            .iter()
            .map(|p| p[0])
            .collect(),
        _ => Vec::new(),
    };
    (o.status.code(), stderr(&o), red)
}

#[test]
fn non_finite_constants_from_the_command_line() {
    // The same shader through `ps30 run --const`: c0 = (inf, −inf, inf, 0)
    // into an R32F target: red is rcp(rcp(inf)) = inf. The inputs file sets
    // nothing (`run` needs --image or --inputs).
    let dir = tempfile::tempdir().unwrap();
    let inputs = dir.path().join("none.json");
    std::fs::write(&inputs, "{}").unwrap();
    let shader = "tests/oracle/fixtures/hlsl/conformance/nonfinite.hlsl.fxo";
    let args = ["--const", "c0=inf,-inf,inf,0", "--target", "1x1"];
    let (code, err, red) = run_red(shader, &inputs, &args);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(red, [INF]);
}

// ----- the pixel's fate ---------------------------------------------------------

/// A D3DCOLOR code of an 8-bit target for the float `v`: Direct3D 10's
/// FLOAT → UNORM rule (docs/render.md); the corpus keeps every value far
/// from a half step, where round-to-nearest rules could differ.
fn code(v: f64) -> u32 {
    let k = v.clamp(0.0, 1.0) * 255.0;
    assert!(
        (k - k.floor() - 0.5).abs() > 0.01,
        "{v} is near a half step"
    );
    (k + 0.5).floor() as u32
}

#[test]
fn texkill_mrt_alpha_test_clip_planes_and_flat_shading() {
    for (backend, t) in rendered("pixel.json") {
        eprintln!("pixel.json drawn on the {backend}");
        texkill_mrt_alpha_test_clip_planes_and_flat_shading_on(&t);
    }
}

fn texkill_mrt_alpha_test_clip_planes_and_flat_shading_on(t: &Targets) {
    let exact = |case: &str, got: Rgba, want: [f64; 4]| assert_close(case, got, want, 0);
    // texkill v0 with w = 0.75 − 0.5·x: pixels 2 and 3 have only w < 0 and
    // are discarded; the target keeps its clear colour (1, 0, 1, 1).
    for x in 0..4 {
        let w = 0.75 - 0.5 * f64::from(x);
        let want = if w < 0.0 {
            [1.0, 0.0, 1.0, 1.0]
        } else {
            [0.25, 0.5, 0.75, w]
        };
        exact("texkill", px(t, "texkill", x, 0), want);
    }
    // Three targets: oC0 = v0 = (⅛ + ¼x, ¼, ½, 1) as f32; oC1 = v0 · ½ into
    // A8R8G8B8 cleared to white through COLORWRITEENABLE rb; oC2 = v0.wzyx
    // into A16B16G16R16F (every value a short binary fraction: exact).
    for x in 0..4 {
        let r = 0.125 + 0.25 * f64::from(x);
        exact("mrt_a", px(t, "mrt_a", x, 0), [r, 0.25, 0.5, 1.0]);
        let b = px(t, "mrt_b", x, 0).map(|v| (f64::from(v) * 255.0).round() as u32);
        assert_eq!(b, [code(r * 0.5), 255, code(0.25), 255], "mrt_b {x}");
        exact("mrt_c", px(t, "mrt_c", x, 0), [1.0, 0.5, 0.25, r]);
    }
    // Alpha test: alpha = 0.2 + 0.2x, codes 51, 102, 153, 204. GREATER 102
    // keeps pixels 2 and 3; EQUAL 153 keeps pixel 2; the others stay 0.
    // Clip planes 2.5 − x and x − 0.5 keep pixels 1 and 2.
    for x in 0..4u32 {
        let a = f64::from(0.2f32 + x as f32 * 0.2f32);
        let v = [0.25, 0.5, 0.75, a];
        let keep = |yes: bool| if yes { v } else { [0.0; 4] };
        let c = code(a);
        exact("alpha_greater", px(t, "alpha_greater", x, 0), keep(c > 102));
        exact("alpha_equal", px(t, "alpha_equal", x, 0), keep(c == 153));
        let d = f64::from(x);
        exact(
            "clip",
            px(t, "clip", x, 0),
            keep(2.5 - d >= 0.0 && d - 0.5 >= 0.0),
        );
    }
    // Flat shading: colour inputs hold the first vertex's value, the quad's
    // top-left corner, half a pixel up and left of pixel (0, 0)'s centre:
    // base − ½·ddx − ½·ddy (docs/pixel-rules.md). color1's alpha stays
    // interpolated (D3DSHADE_FLAT flattens the specular colour, not its
    // alpha, which carries fog): 0.5 + 0.125·x.
    for (x, y) in [(0, 0), (3, 0), (0, 1), (3, 1)] {
        exact(
            "flat_a",
            px(t, "flat_a", x, y),
            [0.4375, 0.125, 0.75, 1.0625],
        );
        let alpha = 0.5 + 0.125 * f64::from(x);
        exact("flat_b", px(t, "flat_b", x, y), [0.125, 0.5, 0.1875, alpha]);
    }
}

// ----- hardware float rules ----------------------------------------------------

#[test]
fn zero_times_infinity_and_denormal_products() {
    for (backend, t) in rendered("float_rules.json") {
        eprintln!("float_rules.json drawn on the {backend}");
        zero_times_infinity_and_denormal_products_on(&t, backend);
    }
}

fn zero_times_infinity_and_denormal_products_on(t: &Targets, backend: &str) {
    // a = (0, 1, 1, 2⁻⁷⁰), b = (inf, 2, 3, 2⁻⁷⁰), c = (5, 0, 0, 2⁻¹²⁶);
    // x = a.x·b.x, y = a.x·b.x + c.x, z = a.xyz·b.xyz, w = a.w·b.w + c.w.
    let d = px(t, "d3d9", 0, 0);
    assert!(d[0].is_nan() && d[1].is_nan() && d[2].is_nan(), "{d:?}");
    // 2⁻¹²⁶ + 2⁻¹⁴⁰ = 2⁻¹²⁶·(1 + 2⁻¹⁴): exact in f32. A GPU may flush the
    // subnormal product 2⁻¹⁴⁰ (Vulkan without shaderDenormPreserveFloat32,
    // as on llvmpipe), which leaves 2⁻¹²⁶.
    let kept = 2f64.powi(-126) + 2f64.powi(-140);
    let flushed = 2f64.powi(-126);
    let w = f64::from(d[3]);
    assert!(
        w == kept || backend == "gpu" && w == flushed,
        "d3d9 ({backend}): w = {w:e}"
    );
    // hardware: 0 × inf = 0 in mul, mad and dp3; the product 2⁻¹⁴⁰ inside
    // mad is a denormal, flushed before the add.
    let h = px(t, "hardware", 0, 0);
    assert_eq!(bits(h), bits([0.0, 5.0, 5.0, f32::MIN_POSITIVE]));
}

// ----- inputs from a file --------------------------------------------------------

/// `ps30 run SHADER --inputs many_constants.inputs.json` on `backend`: red
/// of every pixel of a 2×2 R32F target; `None` without a GPU (outside CI).
fn run_many_constants(backend: &str) -> Option<Vec<f32>> {
    let shader = "tests/oracle/fixtures/hlsl/conformance/many_constants.hlsl.fxo";
    let inputs = corpus().join("many_constants.inputs.json");
    let args = ["--target", "2x2", "--backend", backend];
    let (code, err, red) = run_red(shader, &inputs, &args);
    if backend == "gpu" && code == Some(2) && std::env::var_os("CI").is_none() {
        eprintln!("many_constants on the GPU: skipped: {err}");
        return None;
    }
    assert_eq!(code, Some(0), "{backend}: {err}");
    Some(red)
}

#[test]
fn forty_constants_and_a_texture_from_an_inputs_file() {
    // c0–c39 = (1/64, 1/32, 0, 1/128): the sum's red is 40/64 = 0.625
    // exactly; s0 = textures/mips.dds, level 0 red 200: red = 0.625 · 200/255
    // (the texel's conversion: 1 ulp; the product: ½ ulp).
    let want = 0.625 * 200.0 / 255.0;
    for backend in ["emulator", "gpu"] {
        let Some(red) = run_many_constants(backend) else {
            continue;
        };
        for r in red {
            assert_close(backend, [r, 0.0, 0.0, 0.0], [want, 0.0, 0.0, 0.0], 3);
        }
    }
}

#[test]
fn every_list_of_the_corpus_is_checked_here() {
    // A list added to the folder without a test here would check nothing.
    let mut lists: Vec<String> = std::fs::read_dir(corpus())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    lists.sort();
    let checked = [
        "cube.json",
        "dds.json",
        "float_rules.json",
        "many_constants.inputs.json",
        "nonfinite.json",
        "pixel.json",
        "volume.json",
    ];
    assert_eq!(lists, checked);
}

// ----- the GPU backend -----------------------------------------------------------

/// `ps30 compare SHADER` with `inputs` (an inputs file's JSON, textures by
/// absolute path) and `args`: the emulator against the GPU. `None` without
/// an adapter (outside CI).
fn compare(shader: &str, inputs: &str, args: &[&str]) -> Option<serde_json::Value> {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("inputs.json");
    std::fs::write(&file, inputs).unwrap();
    let shader = repo().join(shader);
    let mut all = vec![
        "compare",
        shader.to_str().unwrap(),
        "--inputs",
        file.to_str().unwrap(),
        "--json",
    ];
    all.extend_from_slice(args);
    let o = ps30(&all, repo());
    if o.status.code() == Some(2) && std::env::var_os("CI").is_none() {
        eprintln!("compare {}: skipped: {}", shader.display(), stderr(&o));
        return None;
    }
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}: {}",
        shader.display(),
        stderr(&o)
    );
    Some(serde_json::from_slice(&o.stdout).unwrap())
}

/// The constants of `float_rules.json` for `compare`, and its 1×1 target.
const FLOAT_RULES_ARGS: [&str; 8] = [
    "--const",
    "c0=0,1,1,0x1c800000",
    "--const",
    "c1=inf,2,3,0x1c800000",
    "--const",
    "c2=5,0,0,0x00800000",
    "--target",
    "1x1",
];

#[test]
fn the_gpu_backend_agrees_or_compare_explains() {
    const FX: &str = "tests/oracle/fixtures/hlsl/conformance/";
    const DIS: &str = "tests/oracle/corpus/dis/def-bits/";
    let texture = |name: &str| {
        let path = corpus().join("textures").join(name);
        format!(
            r#"{{"samplers": {{"s0": {{"texture": {:?}}}}}}}"#,
            path.to_str().unwrap()
        )
    };
    let identical: Vec<(String, String, Vec<&str>)> = vec![
        (
            format!("{FX}nonfinite.hlsl.fxo"),
            "{}".into(),
            vec![
                "--const",
                "c0=inf,-inf,inf,0",
                "--target",
                "1x1",
                "--float-rules",
                "d3d9",
            ],
        ),
        (
            format!("{FX}nonfinite.hlsl.fxo"),
            "{}".into(),
            vec![
                "--const",
                "c0=inf,-inf,inf,0",
                "--target",
                "1x1",
                "--float-rules",
                "hardware",
            ],
        ),
        (
            format!("{FX}nonfinite.hlsl.fxo"),
            "{}".into(),
            vec![
                "--const",
                "c0=nan,0,1,0x80000000",
                "--target",
                "1x1",
                "--float-rules",
                "d3d9",
            ],
        ),
        (
            format!("{FX}float_rules.hlsl.fxo"),
            "{}".into(),
            [&FLOAT_RULES_ARGS[..], &["--float-rules", "hardware"]].concat(),
        ),
        (
            format!("{DIS}pos-inf.fxo"),
            "{}".into(),
            vec!["--target", "1x1"],
        ),
        (
            format!("{DIS}neg-inf.fxo"),
            "{}".into(),
            vec!["--target", "1x1"],
        ),
        (
            format!("{DIS}neg-zero.fxo"),
            "{}".into(),
            vec!["--target", "1x1"],
        ),
        (
            format!("{DIS}denormal-min.fxo"),
            "{}".into(),
            vec!["--target", "1x1", "--float-rules", "hardware"],
        ),
        (
            format!("{FX}tex2d_at.hlsl.fxo"),
            texture("dxt1.dds"),
            vec!["--target", "8x4"],
        ),
        (
            format!("{FX}tex2d_at.hlsl.fxo"),
            texture("dxt3.dds"),
            vec!["--target", "4x4"],
        ),
        (
            format!("{FX}tex2d_at.hlsl.fxo"),
            texture("dxt5.dds"),
            vec!["--target", "4x4"],
        ),
        (
            format!("{FX}tex2d_at.hlsl.fxo"),
            texture("mips.dds"),
            vec!["--target", "4x4"],
        ),
    ];
    for (shader, inputs, args) in &identical {
        let Some(c) = compare(shader, inputs, args) else {
            return;
        };
        assert_eq!(
            c["all_identical"], true,
            "{shader} {args:?}: {}",
            c["comparison"]["explanation"]
        );
    }
    // def_bits: `def c1, 0, -0, …` times 1 is −0 by IEEE 754; llvmpipe gives
    // +0, which Vulkan allows (no SignedZeroInfNanPreserve): `compare` says so.
    let args = [
        "--const",
        "c0=1,1,0.5,1",
        "--target",
        "1x1",
        "--float-rules",
        "hardware",
    ];
    if let Some(c) = compare(&format!("{FX}def_bits.hlsl.fxo"), "{}", &args) {
        let why = &c["comparison"]["explanation"];
        assert_eq!(why["finding"], false, "{why}");
        if c["all_identical"] == false {
            assert!(
                why["text"].as_str().unwrap().contains("opposite sign"),
                "{why}"
            );
        }
    }
    // Under d3d9 the device (llvmpipe flushes subnormals) loses the
    // denormal product inside `mad`: a difference `compare` explains.
    let args = [&FLOAT_RULES_ARGS[..], &["--float-rules", "d3d9"]].concat();
    let Some(c) = compare(&format!("{FX}float_rules.hlsl.fxo"), "{}", &args) else {
        return;
    };
    let why = &c["comparison"]["explanation"];
    assert_eq!(why["finding"], false, "{why}");
    if c["all_identical"] == false {
        assert!(
            why["text"].as_str().unwrap().contains("flushes subnormals"),
            "{why}"
        );
    }
}
