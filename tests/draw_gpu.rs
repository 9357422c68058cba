//! Draws of geometry on the GPU backend (llvmpipe here and in CI): every
//! list of `tests/draw_conformance/` run by `ps30 compare --list` on both
//! backends, which must agree or explain each difference (coverage within
//! the device's snapping bound, values by interpolation), and the
//! perspective case's interpolated values held to a bound derived from the
//! device's arithmetic against the f64 value of Direct3D 9's formula.
//! Without a Vulkan device (outside CI) the cases are skipped with a
//! message, as the other GPU tests are.

use crate::common::bin::{ps30, repo, stderr};
use crate::d3d9_conformance::{render_file, Targets};
use std::process::{Command, Output};

/// Lists whose every draw's targets come out bit-identical: their values
/// are constants, flat or pre-transformed positions where nothing is
/// interpolated across a varying w with a rounding (fill rule, facing,
/// vPos, the fan's flat colours, the alpha test's boundaries, blending, depth written from constant z,
/// two targets, points, triangles filled as points, the dense grid's flat
/// colours with its borders scissored, unwritten inputs' defaults, vertex
/// texture fetch, ps_1_x's bump-environment and texm3x3spec sampling texel
/// centres), and the lists of lines: the device shades the pixels
/// the emulator's set-up gives a line, with the inputs it computes
/// (`run/gpu_lines.rs`), so only the shader's instructions could differ,
/// and these copy, fog by exact factors or take exact differences.
const BIT_IDENTICAL: [&str; 20] = [
    "alpha_depth.json",
    "alpha_rounding.json",
    "blend.json",
    "bump.json",
    "depth.json",
    "depth_funcs.json",
    "face_cull.json",
    "fan_scissor.json",
    "fill_points.json",
    "fill_rule.json",
    "grid.json",
    "lines.json",
    "lines_gpu.json",
    "lines_vpos.json",
    "mrt.json",
    "point_sizes.json",
    "points.json",
    "unwritten.json",
    "vertex_fetch.json",
    "vpos.json",
];

/// `compare --list` of one list as JSON; `None` where no device opens
/// outside CI.
fn compare(list: &str) -> Option<(Option<i32>, serde_json::Value, String)> {
    let path = repo().join("tests/draw_conformance").join(list);
    let o = ps30(
        &["compare", "--list", path.to_str().unwrap(), "--json", "-q"],
        repo(),
    );
    let err = stderr(&o);
    if o.status.code() == Some(2)
        && err.contains("no GPU adapter")
        && std::env::var_os("CI").is_none()
    {
        eprintln!("{list} on the GPU: skipped: {err}");
        return None;
    }
    let json = serde_json::from_slice(&o.stdout).unwrap_or(serde_json::Value::Null);
    Some((o.status.code(), json, err))
}

#[test]
fn every_conformance_list_agrees_or_is_explained() {
    let dir = repo().join("tests/draw_conformance");
    let mut lists: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json") && n != "quad.json")
        .collect();
    lists.sort();
    assert!(lists.len() >= 17, "{lists:?}");
    for list in &lists {
        let Some((code, json, err)) = compare(list) else {
            return;
        };
        assert_eq!(code, Some(0), "{list}: {err}\n{json}");
        assert_eq!(json["explained"], true, "{list}: {json}");
        let steps = json["steps"].as_array().unwrap();
        assert!(!steps.is_empty(), "{list}");
        for step in steps {
            let why = &step["comparison"]["explanation"];
            assert_eq!(why["finding"], false, "{list}: {why}");
            if let Some(cov) = step.get("coverage") {
                // Coverage may differ only within the snapping bound.
                assert_eq!(cov["beyond"], 0, "{list}: {cov}");
            }
            if BIT_IDENTICAL.contains(&list.as_str()) {
                for ch in step["comparison"]["channels"].as_array().unwrap() {
                    assert_eq!(ch["identical"], ch["pixels"], "{list}: {ch}");
                }
                if let Some(cov) = step.get("coverage") {
                    assert_eq!(cov["emulator_only"], 0, "{list}: {cov}");
                    assert_eq!(cov["gpu_only"], 0, "{list}: {cov}");
                }
            }
        }
    }
}

/// The perspective triangle of `perspective.json` (A = (0, 0), B = (8, 0)
/// with w = 3, C = (0, 8); texcoord0 (0, 0), (1, 0), (0, 1)) as the two
/// planes the device interpolates on screen: N(x, y) = Σ λᵢ·uᵢ/wᵢ and
/// D(x, y) = Σ λᵢ/wᵢ, with λB = x/8, λC = y/8. For u: N = x/24, for v:
/// N = y/8; D = 1 − x/12. Returns (u, v, D, S_u, S_v, S_D), S being the
/// sum of the magnitudes of a plane's terms at the pixel centre in
/// framebuffer coordinates (x + ½, y + ½), where the device evaluates it.
fn planes(x: u32, y: u32) -> [f64; 6] {
    let (fx, fy) = (f64::from(x), f64::from(y));
    let d = 1.0 - fx / 12.0;
    let (xf, yf) = (fx + 0.5, fy + 0.5);
    // Each plane c0 + cx·x_f + cy·y_f: u's is (−1/48) + x_f/24, v's
    // (−1/16) + y_f/8, D's (1 + 1/24) − x_f/12.
    let s_u = 1.0 / 48.0 + xf / 24.0;
    let s_v = 1.0 / 16.0 + yf / 8.0;
    let s_d = 1.0 + 1.0 / 24.0 + xf / 12.0;
    [fx / 24.0 / d, fy / 8.0 / d, d, s_u, s_v, s_d]
}

#[test]
fn interpolation_on_the_device_is_within_its_derived_bound() {
    // The bound: a device that interpolates by plane equations in f32
    // (Mesa's llvmpipe sets up a0, dadx, dady per input from the three
    // vertices, lp_setup_tri.c, and the fragment adds a0 + dadx·x + dady·y
    // for N and for D, then divides) rounds each plane's coefficients in at
    // most 6 operations (two differences of vertex values, two products
    // with position differences, their difference, the product with
    // 1/area) and evaluates it in 4 (two products, two sums). Each rounding
    // is within ε = 2⁻²⁴ of a value no larger than the sum S of the
    // magnitudes of the plane's terms, so N and D each carry an absolute
    // error ≤ 10·ε·S. The quotient N/D then differs from the exact one by
    // at most (10·ε·S_N + |N/D|·10·ε·S_D)/D, plus ε·|N/D| for the division
    // itself (first order; the second-order terms are below 2⁻⁴⁰ here).
    // The vertex positions are integers moved by ½, exact in f32 and on
    // the device's sub-pixel grid, so they add nothing.
    let path = repo().join("tests/draw_conformance/perspective.json");
    let Some(t) = render_file(&path, "gpu") else {
        return;
    };
    let (width, pixels) = &t["values"];
    let eps = f64::powi(2.0, -24);
    let mut worst = 0.0f64;
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        if x + y >= 8 {
            // Outside the triangle (x + y < 8 by the top-left rule): the clear colour.
            assert_eq!(*got, [0.0; 4], "({x}, {y})");
            continue;
        }
        let [u, v, d, s_u, s_v, s_d] = planes(x, y);
        for (c, (want, s_n)) in [(u, s_u), (v, s_v)].into_iter().enumerate() {
            let bound = (10.0 * eps * s_n + want.abs() * 10.0 * eps * s_d) / d + eps * want.abs();
            let err = (f64::from(got[c]) - want).abs();
            worst = worst.max(err / bound);
            assert!(
                err <= bound,
                "({x}, {y}) component {c}: {} against {want} (|Δ| {err:e}, bound {bound:e})",
                got[c]
            );
        }
    }
    eprintln!("perspective on the device: largest |Δ|/bound {worst:.3}");
}

/// `ps30 render LIST --backend gpu` into `out`, with the switch `way`
/// (`PS30_PER_PRIMITIVE` or `PS30_RECORDS`) set, or neither: its status,
/// report and phase log.
fn render_gpu(list: &std::path::Path, out: &std::path::Path, way: Option<&str>) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_ps30"));
    c.args(["render", list.to_str().unwrap(), "--backend", "gpu", "-q"])
        .arg("-o")
        .arg(out)
        .current_dir(repo())
        .env_remove("NO_COLOR")
        .env_remove("PS30_PER_PRIMITIVE")
        .env_remove("PS30_RECORDS")
        .env("PS30_PHASES", "1");
    if let Some(way) = way {
        c.env(way, "1");
    }
    c.output().expect("run ps30")
}

/// The report lines of a run (the phase log's timings left out).
fn report(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout)
        .lines()
        .filter(|l| !l.starts_with("phase "))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn a_draw_in_one_pass_leaves_what_the_per_primitive_path_leaves() {
    // Every list the GPU backend draws, once each way: the reports (counts
    // of triangles, pixels written and discarded) and every target's
    // stored values must be the same bytes.
    let dir = repo().join("tests/draw_conformance");
    let tmp = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("one_pass");
    // Lists left out: fog and lines never go to the device in one pass
    // (fog runs on the CPU, and the fog lists are compared by
    // `a_draw_with_fragment_records_leaves_what_the_per_primitive_path_leaves`;
    // lines' pixels come from the emulator's line set-up), so both ways
    // are the same path; `quad.json` is a full-screen draw; `grid.json` is
    // the speed list's 288 triangles.
    let left_out = [
        "fog.json",
        "fog_odepth.json",
        "fog_w.json",
        "grid.json",
        "lines.json",
        "lines_gpu.json",
        "lines_vpos.json",
        "quad.json",
    ];
    let mut one_pass = Vec::new();
    let mut tested = Vec::new();
    for list in [
        "alpha_depth",
        "alpha_rounding",
        "blend",
        "bump",
        "clipping",
        "d3dcolor",
        "depth",
        "depth_funcs",
    ]
    .iter()
    .chain(&[
        "depth_ramp",
        "divergent",
        "face_cull",
        "fan_scissor",
        "fill_rule",
    ])
    .chain(&["fill_points", "mrt", "perspective", "pixel_centres"])
    .chain(&["point_sizes", "points", "stencil", "unwritten"])
    .chain(&["vertex_buffers", "vertex_fetch", "vertex_shaders", "vpos"])
    {
        let name = format!("{list}.json");
        tested.push(name.clone());
        let (a, b) = (tmp.join(list).join("each"), tmp.join(list).join("whole"));
        std::fs::create_dir_all(tmp.join(list)).unwrap();
        let each = render_gpu(&dir.join(&name), &a, Some("PS30_PER_PRIMITIVE"));
        if each.status.code() == Some(2)
            && stderr(&each).contains("no GPU adapter")
            && std::env::var_os("CI").is_none()
        {
            eprintln!("one pass on the GPU: skipped: {}", stderr(&each));
            return;
        }
        let whole = render_gpu(&dir.join(&name), &b, None);
        assert_eq!(each.status.code(), Some(0), "{name}: {}", stderr(&each));
        assert_eq!(whole.status.code(), Some(0), "{name}: {}", stderr(&whole));
        assert_eq!(report(&each), report(&whole), "{name}");
        if stderr(&whole).contains("geometry: in one pass") {
            one_pass.push(*list);
        }
        for e in std::fs::read_dir(&a).unwrap() {
            let file = e.unwrap().file_name();
            let (x, y) = (
                std::fs::read(a.join(&file)).unwrap(),
                std::fs::read(b.join(&file)).unwrap(),
            );
            assert!(x == y, "{name}: {file:?} differs");
        }
    }
    // The depth, stencil, alpha-test and two-target lists go to the device
    // whole; the blending ones do not. alpha_rounding.json puts every
    // alpha next to a rounding boundary of its target's comparison (8-bit,
    // half and float targets, every D3DCMP function), so that the device's
    // discard and the CPU's test must agree on each pixel.
    for list in [
        "depth",
        "depth_funcs",
        "stencil",
        "mrt",
        "points",
        "alpha_depth",
        "alpha_rounding",
    ] {
        assert!(
            one_pass.contains(&list),
            "{list} not in one pass: {one_pass:?}"
        );
    }
    assert!(!one_pass.contains(&"blend"), "{one_pass:?}");
    // Every list of the folder is either compared both ways or left out
    // above: a new list cannot be missed silently.
    let mut all: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    all.sort();
    tested.extend(left_out.iter().map(|n| n.to_string()));
    tested.sort();
    assert_eq!(all, tested);
}

/// The bound on a value the device interpolates as the quotient N/D of two
/// planes (`interpolation_on_the_device_is_within_its_derived_bound` gives
/// the reasoning), against the exact quotient `q`: `s_n` and `s_d` are
/// the sums of the magnitudes of the planes' terms at the pixel centre
/// (x + ½, y + ½), `d` the exact D. Each plane here carries 12 roundings
/// of at most ε = 2⁻²⁴ of S: the 10 of its set-up and evaluation, and two
/// more of its vertex values, a/w being 1/w (one rounding) times a (one
/// more). A plane the device does not divide (z) has `d` = 1, `s_d` = 0.
fn quotient_bound(q: f64, s_n: f64, d: f64, s_d: f64) -> f64 {
    let eps = f64::powi(2.0, -24);
    (12.0 * eps * s_n + q.abs() * 12.0 * eps * s_d) / d + eps * q.abs()
}

#[test]
fn fog_on_the_device_is_within_its_derived_bound() {
    // Fog runs on the CPU on both backends (`core/raster/fog.rs`), from the
    // d each pixel brings back from the device: the rasterised z for table
    // fog from z (also after a shader that writes oDepth), the interpolated
    // w or vertex fog factor otherwise. Every draw below is white fogged
    // towards blue over an 8×2 target, so red = green = f, blue = alpha =
    // 1, and f64 blending of f32 values gives f·1 + (1 − f)·0 = f exactly
    // before its rounding to f32 (½ ulp ≤ ε·f). Pixel x's centre is at
    // framebuffer x_f = x + ½, where the device evaluates its planes.
    let dir = repo().join("tests/draw_conformance");
    let Some(fog) = render_file(&dir.join("fog.json"), "gpu") else {
        return;
    };
    let fog_w = render_file(&dir.join("fog_w.json"), "gpu").expect("a device opened");
    let odepth = render_file(&dir.join("fog_odepth.json"), "gpu").expect("a device opened");
    let eps = f64::powi(2.0, -24);
    // z runs 0 → 1 over x = 0 → 8, linear on screen (pre-transformed):
    // the plane −1/16 + x_f/8, S = 1/16 + x_f/8, not divided.
    let z = |x: f64| {
        (
            x / 8.0,
            quotient_bound(x / 8.0, 1.0 / 16.0 + (x + 0.5) / 8.0, 1.0, 0.0),
        )
    };
    // Linear fog from 0 to 1: f = 1 − z, off by as much as z is.
    let linear = |x: f64| {
        let (z, dz) = z(x);
        (1.0 - z, dz)
    };
    // EXP with density 2: f = e^(−2z); |Δf| ≤ 2·|Δz|·e^(2|Δz|)·f
    let exp = |x: f64| {
        let (z, dz) = z(x);
        let f = (-2.0 * z).exp();
        // (and e^x in f64 within an f64 ulp, 2⁻⁵²·f).
        (f, 2.0 * dz * (2.0 * dz).exp() * f + f64::powi(2.0, -52) * f)
    };
    // Vertex fog, 1 at x = 0 and 0 at x = 8 with w = 1: N = f/w is the
    // plane 1 + 1/16 − x_f/8 (S = 1 + 1/16 + x_f/8), D = 1/w the plane 1
    // (S = 1).
    let vertex = |x: f64| {
        let f = 1.0 - x / 8.0;
        (
            f,
            quotient_bound(f, 1.0 + 1.0 / 16.0 + (x + 0.5) / 8.0, 1.0, 1.0),
        )
    };
    // Table fog from w, w = 1 at x = 0 and 3 at x = 8: N = w/w is the
    // plane 1 (S = 1), D = 1/w the plane 1 + 1/24 − x_f/12 (S = 1 + 1/24 +
    // x_f/12); linear fog from 0 to 4: f = 1 − w/4, off by |Δw|/4.
    let from_w = |x: f64| {
        let d = 1.0 - x / 12.0;
        let w = 1.0 / d;
        let dw = quotient_bound(w, 1.0, d, 1.0 + 1.0 / 24.0 + (x + 0.5) / 12.0);
        (1.0 - w / 4.0, dw / 4.0)
    };
    type Want<'a> = dyn Fn(f64) -> (f64, f64) + 'a;
    let cases: [(&str, &Targets, &str, &Want<'_>); 6] = [
        ("fog.json", &fog, "linear", &linear),
        ("fog.json", &fog, "exp", &exp),
        ("fog.json", &fog, "vertex", &vertex),
        ("fog_w.json", &fog_w, "w", &from_w),
        ("fog_w.json", &fog_w, "spec", &vertex),
        ("fog_odepth.json", &odepth, "t", &linear),
    ];
    for (list, targets, name, want) in cases {
        let (width, pixels) = &targets[name];
        let mut worst = 0.0f64;
        for (i, got) in pixels.iter().enumerate() {
            let x = f64::from(i as u32 % width);
            let (f, bound) = want(x);
            let bound = bound + eps * f;
            for c in 0..2 {
                let err = (f64::from(got[c]) - f).abs();
                worst = worst.max(err / bound);
                assert!(
                    err <= bound,
                    "{list} {name} ({x}): {got:?} want {f} (|Δ| {err:e}, bound {bound:e})"
                );
            }
            assert_eq!((got[2], got[3]), (1.0, 1.0), "{list} {name} ({x})");
        }
        eprintln!("{list} {name} on the device: largest |Δ|/bound {worst:.3}");
    }
}

#[test]
fn vertex_texture_fetch_filters_and_borders_as_the_emulator() {
    // vertex_fetch.json with its vertex sampler filtering linearly between
    // the two texels (u = 0.5) and the other quad outside the texture
    // (u = 1.3) on a BORDER colour WebGPU has not (emulated in the shader,
    // as for pixel shaders): texldl's values on the device are the
    // emulator's bit for bit (a linear blend of two texels at weight ½ is
    // exact; the border colour is copied).
    let dir = repo().join("tests/draw_conformance");
    let text = std::fs::read_to_string(dir.join("vertex_fetch.json")).unwrap();
    let mut list: serde_json::Value = serde_json::from_str(&text).unwrap();
    for s in list["steps"].as_array_mut().unwrap() {
        s["shader"] = dir
            .join(s["shader"].as_str().unwrap())
            .to_str()
            .unwrap()
            .into();
        let g = &mut s["geometry"];
        if g.is_null() {
            continue;
        }
        g["vertex_shader"] = dir
            .join(g["vertex_shader"].as_str().unwrap())
            .to_str()
            .unwrap()
            .into();
        for (k, t) in g["vertices"]["attributes"]["texcoord0"]
            .as_array_mut()
            .unwrap()
            .iter_mut()
            .enumerate()
        {
            *t = serde_json::json!([if k < 4 { 0.5 } else { 1.3 }, 0.5, 0, 0]);
        }
        let s0 = &mut g["vertex_samplers"]["s0"];
        s0["filter"] = "linear".into();
        s0["address"] = "border".into();
        s0["border"] = serde_json::json!([0.25, 0.5, 0.75, 0.125]);
    }
    compare_bit_identical(
        &list,
        "vertex_fetch_border.json",
        "vertex textures on the GPU",
    );
}

#[test]
fn points_are_never_culled_on_the_device() {
    // points.json under D3DCULL_CW: D3DRS_CULLMODE culls triangles only, so
    // a point's square (clockwise on screen) is drawn on both backends.
    let dir = repo().join("tests/draw_conformance");
    let text = std::fs::read_to_string(dir.join("points.json")).unwrap();
    let mut list: serde_json::Value = serde_json::from_str(&text).unwrap();
    for s in list["steps"].as_array_mut().unwrap() {
        if let Some(shader) = s["shader"].as_str() {
            s["shader"] = dir.join(shader).to_str().unwrap().into();
        }
        if !s["geometry"].is_null() {
            s["geometry"]["cull"] = "cw".into();
        }
    }
    compare_bit_identical(&list, "points_cw.json", "points on the GPU");
}

/// Writes `list` as `name` in the tests' scratch folder and asserts that
/// `compare --list` finds every draw bit-identical with no coverage
/// difference (skipped, saying `what`, where no adapter exists outside CI).
fn compare_bit_identical(list: &serde_json::Value, name: &str, what: &str) {
    let tmp = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&tmp, serde_json::to_string(list).unwrap()).unwrap();
    let o = ps30(
        &["compare", "--list", tmp.to_str().unwrap(), "--json", "-q"],
        repo(),
    );
    let err = stderr(&o);
    if o.status.code() == Some(2)
        && err.contains("no GPU adapter")
        && std::env::var_os("CI").is_none()
    {
        eprintln!("{what}: skipped: {err}");
        return;
    }
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap_or_default();
    assert_eq!(o.status.code(), Some(0), "{err}\n{json}");
    for step in json["steps"].as_array().unwrap() {
        for ch in step["comparison"]["channels"].as_array().unwrap() {
            assert_eq!(ch["identical"], ch["pixels"], "{ch}");
        }
        if let Some(cov) = step.get("coverage") {
            assert_eq!(cov["emulator_only"], 0, "{cov}");
            assert_eq!(cov["gpu_only"], 0, "{cov}");
        }
    }
}

#[test]
fn the_alpha_test_compares_at_each_targets_precision_on_both_backends() {
    // alpha_rounding.json: one pixel per alpha a (column i), one row per
    // D3DCMP function, ALPHAREF 128, on an 8-bit, a half and a float
    // target; a pixel is written (red 0.25 ≠ 0) exactly where `x func r`
    // holds for the numbers Direct3D 9 compares at the target's precision
    // (docs/pixel-rules.md): 8-bit x = roundeven(a·255 in f32), r = 128;
    // half x = roundeven(a·32767 in f32), r = 128·2⁷ + 128/2 = 16448;
    // float x = a, r = 128/255 in f32. The alphas sit on and beside each
    // of these boundaries, so a device that rounded differently, compared
    // in another precision or flushed a subnormal would miss pixels. The
    // GPU backend draws the list in one pass (the alpha test as a discard).
    let path = repo().join("tests/draw_conformance/alpha_rounding.json");
    let list: serde_json::Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    let funcs = [
        "NEVER",
        "LESS",
        "EQUAL",
        "LESSEQUAL",
        "GREATER",
        "NOTEQUAL",
        "GREATEREQUAL",
        "ALWAYS",
    ];
    for backend in ["emulator", "gpu"] {
        let Some(t) = render_file(&path, backend) else {
            return;
        };
        let (mut passed, mut failed) = (0, 0);
        for step in list["steps"].as_array().unwrap() {
            let Some(name) = step["draw"].as_str() else {
                continue;
            };
            let func = step["alpha_test"]["func"].as_str().unwrap();
            let row = funcs.iter().position(|f| *f == func).unwrap();
            let colours = step["geometry"]["vertices"]["attributes"]["color0"]
                .as_array()
                .unwrap();
            let (width, pixels) = &t[name];
            for (i, c) in colours.iter().step_by(4).enumerate() {
                let a = c[3].as_f64().unwrap() as f32;
                let (x, r) = match name {
                    "u8" => ((a * 255.0).round_ties_even(), 128.0),
                    "h" => ((a * 32767.0).round_ties_even(), 16448.0),
                    _ => (a, 128.0f32 / 255.0),
                };
                let pass = match func {
                    "NEVER" => false,
                    "LESS" => x < r,
                    "EQUAL" => x == r,
                    "LESSEQUAL" => x <= r,
                    "GREATER" => x > r,
                    "NOTEQUAL" => x != r,
                    "GREATEREQUAL" => x >= r,
                    _ => true,
                };
                let got = pixels[row * *width as usize + i];
                assert_eq!(
                    got[0] > 0.0,
                    pass,
                    "{backend}: {name} {func} alpha {a:e} ({:#x}): {got:?}",
                    a.to_bits()
                );
                if pass {
                    passed += 1;
                } else {
                    failed += 1;
                }
            }
        }
        assert!(
            passed > 100 && failed > 100,
            "{passed} passed, {failed} failed"
        );
    }
}

#[test]
fn lines_read_their_place_in_the_target_as_vpos_on_the_device() {
    // The device shades a draw's lines together in one atlas
    // (`run/gpu_lines.rs`), each window somewhere else than in the target;
    // vPos must still read each pixel's place in the target, the values
    // derived by hand beside `lines_vpos_want`.
    let list = repo().join("tests/draw_conformance/lines_vpos.json");
    let Some(t) = render_file(&list, "gpu") else {
        return;
    };
    crate::draw_conformance::check(&t, "t", crate::draw_conformance_raster::lines_vpos_want);
}

/// The same bytes from `a` and `b`, two folders of a list's targets.
fn same_files(name: &str, a: &std::path::Path, b: &std::path::Path) {
    for e in std::fs::read_dir(a).unwrap() {
        let file = e.unwrap().file_name();
        let (x, y) = (
            std::fs::read(a.join(&file)).unwrap(),
            std::fs::read(b.join(&file)).unwrap(),
        );
        assert!(x == y, "{name}: {file:?} differs");
    }
}

#[test]
fn a_draw_with_fragment_records_leaves_what_the_per_primitive_path_leaves() {
    // Every list of the folder that draws triangles or points, once a
    // render pass per primitive and once in the recorded draw (one device
    // draw, every fragment recorded and put back in drawing order; forced
    // with PS30_RECORDS where the list could take one pass): the reports
    // and every target's stored values must be the same bytes. Blending,
    // fog (all four kinds), point fills whose squares overlap within one
    // primitive, depth, stencil, the alpha test, texkill, two targets and
    // derivatives are among them, and a point fill whose three squares
    // overlap within one primitive ([`overlapping_points`]). Lines are set up on the CPU
    // (`gpu_lines.rs`) and `quad.json` is a full-screen draw: neither
    // draws geometry through either path. `blend_batches.json` (benches)
    // has more records than one batch holds, so its draw is split.
    let dir = repo().join("tests/draw_conformance");
    let tmp = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("records");
    let neither = [
        "lines.json",
        "lines_gpu.json",
        "lines_vpos.json",
        "quad.json",
    ];
    let mut lists: Vec<std::path::PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .filter(|p| !neither.iter().any(|n| p.ends_with(n)))
        .collect();
    lists.sort();
    assert!(lists.len() >= 25, "{lists:?}");
    lists.push(repo().join("benches/lists/blend_batches.json"));
    lists.push(overlapping_points(&tmp.join("lists")));
    for list in &lists {
        let name = list.file_name().unwrap().to_string_lossy().into_owned();
        let out = tmp.join("out").join(&name);
        let (a, b) = (out.join("each"), out.join("recorded"));
        std::fs::create_dir_all(&out).unwrap();
        let each = render_gpu(list, &a, Some("PS30_PER_PRIMITIVE"));
        if each.status.code() == Some(2)
            && stderr(&each).contains("no GPU adapter")
            && std::env::var_os("CI").is_none()
        {
            eprintln!("records on the GPU: skipped: {}", stderr(&each));
            return;
        }
        let recorded = render_gpu(list, &b, Some("PS30_RECORDS"));
        assert_eq!(each.status.code(), Some(0), "{name}: {}", stderr(&each));
        assert_eq!(
            recorded.status.code(),
            Some(0),
            "{name}: {}",
            stderr(&recorded)
        );
        assert_eq!(report(&each), report(&recorded), "{name}");
        let log = stderr(&recorded);
        assert!(
            log.contains("geometry: in one device draw, merged on the CPU"),
            "{name}: not recorded: {log}"
        );
        assert!(!log.contains("geometry: per primitive"), "{name}: {log}");
        same_files(&name, &a, &b);
        if name == "blend_batches.json" {
            let batches = log.matches("geometry (records): batch read back").count();
            assert!(batches >= 2, "{name}: {batches} batch(es): {log}");
        }
    }
}

/// A list (written under `dir`) of one triangle filled as points of size
/// 6 whose corners are 2 pixels apart, blended ONE + ONE: its three squares
/// overlap, so that a pixel gets two or three fragments of one primitive
/// with different colours. Both GPU paths draw each point of a point fill
/// as a primitive of its own, so that every fragment is merged in turn,
/// as the emulator merges them.
fn overlapping_points(dir: &std::path::Path) -> std::path::PathBuf {
    let shader = repo().join("tests/draw_conformance/texcoord.psh");
    let list = format!(
        r#"{{"description": "overlapping points of one primitive",
  "targets": [{{"name": "p", "size": "12x12", "format": "A32B32G32R32F"}}],
  "steps": [{{"draw": "p", "shader": {shader:?}, "blend": {{"src": "ONE", "dest": "ONE", "op": "ADD"}},
    "geometry": {{"primitive": "triangle_list", "cull": "none", "point_size": 6, "fill_mode": "point",
      "vertices": {{"attributes": {{
        "positiont0": [[5, 5, 0.5, 1], [7, 5, 0.5, 1], [5, 7, 0.5, 1]],
        "texcoord0": [[1, 0, 0, 1], [0, 2, 0, 1], [0, 0, 4, 1]]}}}}}}}}]}}"#
    );
    std::fs::create_dir_all(dir).unwrap();
    let path = dir.join("overlapping_points.json");
    std::fs::write(&path, list).unwrap();
    path
}

#[test]
fn overlapping_points_of_a_point_fill_are_each_merged_as_on_the_emulator() {
    // Three 6×6 squares around (5, 5), (7, 5) and (5, 7) (centres on pixel
    // centres: each covers x, y in [c − 3, c + 3), 36 pixels): blended
    // ONE + ONE, every fragment adds its point's colour, so the emulator
    // writes 3 · 36 = 108 fragments. Each point's colour is its vertex's
    // texcoord0 (no sprite coordinates), sums of small integers, exact in
    // f32 in any order: the GPU backend must leave the same bytes, by the
    // recorded draw and by a pass per primitive.
    let tmp = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("overlapping_points");
    let list = overlapping_points(&tmp.join("lists"));
    let emulated = tmp.join("emulator");
    let o = ps30(
        &[
            "render",
            list.to_str().unwrap(),
            "-q",
            "-o",
            emulated.to_str().unwrap(),
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let text = json.to_string();
    assert!(text.contains("\"written\":108"), "{text}");
    for way in [None, Some("PS30_PER_PRIMITIVE")] {
        let out = tmp.join(format!("gpu-{}", way.unwrap_or("recorded")));
        let g = render_gpu(&list, &out, way);
        if g.status.code() == Some(2)
            && stderr(&g).contains("no GPU adapter")
            && std::env::var_os("CI").is_none()
        {
            eprintln!("overlapping points on the GPU: skipped: {}", stderr(&g));
            return;
        }
        assert_eq!(g.status.code(), Some(0), "{way:?}: {}", stderr(&g));
        same_files("overlapping_points.json", &emulated, &out);
    }
}
