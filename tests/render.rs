//! Draw lists: a user-written list of additive lights against the f64 sum of
//! its lights, the light-model shader against its CPU computation, mip
//! reductions against the f64 mean, and `ps30 render` on good and bad files.

use crate::common::bin;

use bin::{ps30, repo, stderr};
use ps30::core::image::{chain_weights, full_chain_levels, Encoding, OddSides, TargetFormat};
use ps30::core::merge::OutputState;
use ps30::jobs::render::{self, file, DrawList, DrawStep, Step, TargetSpec};
use ps30::jobs::scenes::lights::{Light, Scene};
use std::path::Path;

fn read(path: &str) -> file::Loaded {
    file::read(&repo().join(path), &file::FileLimits::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// Each draw of `list` alone, blending off, into an A32B32G32R32F target of
/// its size: the f32 colour the shader wrote at every pixel.
fn each_draw_alone(list: &DrawList) -> Vec<Vec<[f32; 4]>> {
    list.steps
        .iter()
        .filter_map(|s| match s {
            Step::Draw(d) => Some(d),
            _ => None,
        })
        .map(|d| {
            let t = &list.targets[d.target];
            let alone = DrawList {
                targets: vec![TargetSpec {
                    format: TargetFormat::A32B32G32R32F,
                    ..t.clone()
                }],
                steps: vec![Step::Draw(DrawStep {
                    target: 0,
                    output: OutputState::default(),
                    pixel: Default::default(),
                    geometry: None,
                    ..d.clone()
                })],
                ..list.clone()
            };
            // The CPU computations these draws are held to are plain IEEE
            // f32 (the `d3d9` rules): `hardware`, the default, would flush
            // the denormals a specular power like s^16 reaches.
            let settings = render::Settings {
                float_rules: ps30::core::float_rules::FloatRules::D3d9,
                ..Default::default()
            };
            let (_, states) = render::run(&alone, &settings, &mut |_, _| {}).unwrap();
            states[0].target.texels.clone()
        })
        .collect()
}

/// `drawlists/lights.json`: three lights added (ONE, ONE) into an
/// A16B16G16R16F target, RGB written. Against the f64 sum of the lights'
/// own values (each draw run alone into A32B32G32R32F, so exactly what the
/// shader wrote), every channel must be within the blend's rounding in half
/// floats:
///
/// * light k's f32 value ℓₖ is converted to half: error ≤ ρ(ℓₖ), with ρ(v)
///   half the spacing of halves at magnitude v (`Encoding::max_rounding_error`);
/// * the sum is rounded to half: error ≤ ρ(|stored sum|), and the stored sum
///   is at most Pₖ + Bₖ₋₁ + ρ(ℓₖ) (Pₖ the exact partial sum, Bₖ₋₁ the bound
///   so far), where ρ is largest because ρ only grows with the magnitude.
///
/// So Bₖ = Bₖ₋₁ + ρ(ℓₖ) + ρ(Pₖ + Bₖ₋₁ + ρ(ℓₖ)), B₀ = 0 (the clear is 0).
/// Alpha is not written and must stay 0.
#[test]
fn additive_lights_in_a_user_draw_list_equal_the_f64_sum_within_the_half_rounding() {
    let loaded = read("drawlists/lights.json");
    let list = &loaded.list;
    let lights = each_draw_alone(list);
    assert_eq!(lights.len(), 3);
    let (reports, states) = render::run(list, &Default::default(), &mut |_, _| {}).unwrap();
    let target = &states[0].target;
    assert_eq!(target.format, TargetFormat::Rgba16F);
    let rho = |v: f64| Encoding::Half.max_rounding_error(v);
    let (mut worst, mut used) = (0f64, 0f64);
    for (i, texel) in target.texels.iter().enumerate() {
        for c in 0..3 {
            let (mut sum, mut bound) = (0f64, 0f64);
            for l in &lights {
                let v = l[i][c] as f64;
                sum += v;
                bound += rho(v) + rho(sum + bound + rho(v));
            }
            let e = (texel[c] as f64 - sum).abs();
            assert!(
                e <= bound,
                "texel {i} channel {c}: {} vs {sum}, bound {bound}",
                texel[c]
            );
            worst = worst.max(e);
            used = used.max(e / bound);
        }
        assert_eq!(texel[3], 0.0, "alpha is masked off");
    }
    // The bound is not loose: some channel uses most of it.
    assert!(
        worst > 0.0 && used > 0.5,
        "largest error {worst}, {used} of a bound"
    );
    // The reduction step ran on the final target.
    assert!(matches!(
        reports.last().map(|r| &r.detail),
        Some(render::StepDetail::Mips { levels: 8, .. })
    ));
}

/// The per-light shader of `asm/lights/directional.psh` computes, bit for
/// bit, what `Scene::expected_light` computes on the CPU in the shader's
/// operation order, for lights of every direction class.
#[test]
fn the_directional_light_shader_matches_its_cpu_computation_bit_for_bit() {
    let scene = Scene::synthetic(64, 48).unwrap();
    let lights = [
        Light::new([0.48, 0.6, 0.64], [12.0, 10.5, 8.0]),
        Light::new([-0.8, 0.0, 0.6], [0.25, 0.35, 0.9]),
        Light::new([0.0, 0.0, -1.0], [1.0, 1.0, 1.0]),
    ];
    let list = ps30::jobs::studies::article_chain::draw_list(&scene, &lights).unwrap();
    let values = each_draw_alone(&list);
    for (light, v) in lights.iter().zip(&values) {
        for y in 0..scene.height {
            for x in 0..scene.width {
                let want = scene.expected_light(x, y, light).map(f32::to_bits);
                let got = v[(y * scene.width + x) as usize].map(f32::to_bits);
                assert_eq!(got, want, "pixel ({x}, {y}), light {light:?}");
            }
        }
    }
}

/// A draw list that writes a known pattern, exp2(−4u) across x, into an
/// A32B32G32R32F target and reduces it: for even (power-of-two) sides the 1×1 is the plain mean; for
/// odd sides it is the chain's weighted mean, not the plain one. Bound: each
/// of the n levels after the base rounds its averages to f32, at most half
/// an ulp of values ≤ the largest texel (1), so |1×1 − mean| ≤ n·2⁻²⁴.
#[test]
fn mip_reduction_against_the_f64_mean_for_even_and_odd_sizes() {
    for (w, h) in [(64u32, 32u32), (37, 23), (1280, 5)] {
        for odd in [OddSides::Fold, OddSides::Bilinear] {
            let text = format!(
                r#"{{"targets": [{{"name": "t", "size": "{w}x{h}", "format": "A32B32G32R32F"}}],
                    "steps": [{{"draw": "t", "shader": "log-lights:log", "inputs": {{"v0": "texcoord"}},
                               "constants": {{"c0": [4]}}}},
                              {{"mips": "t", "odd": "{}"}}]}}"#,
                if odd == OddSides::Fold {
                    "fold"
                } else {
                    "bilinear"
                }
            );
            let loaded = file::parse(&text, Path::new("inline.json"), &Default::default()).unwrap();
            let (reports, states) =
                render::run(&loaded.list, &Default::default(), &mut |_, _| {}).unwrap();
            let Some(render::StepDetail::Mips { levels, mean, .. }) =
                reports.last().map(|r| &r.detail)
            else {
                panic!("no reduction");
            };
            assert_eq!(*levels as u32, full_chain_levels(w, h));
            let texels = &states[0].target.texels;
            let n = (w * h) as f64;
            let plain: f64 = texels.iter().map(|t| t[0] as f64).sum::<f64>() / n;
            let (wx, wy) = (
                chain_weights(w, *levels as u32, odd),
                chain_weights(h, *levels as u32, odd),
            );
            let mut weighted = 0f64;
            for y in 0..h {
                for x in 0..w {
                    weighted +=
                        wx[x as usize] * wy[y as usize] * texels[(y * w + x) as usize][0] as f64;
                }
            }
            let bound = (*levels as f64 - 1.0) * 2f64.powi(-24);
            assert!(
                (mean[0] as f64 - weighted).abs() <= bound,
                "{w}×{h} {odd:?}"
            );
            if w.is_power_of_two() && h.is_power_of_two() {
                assert!(
                    (mean[0] as f64 - plain).abs() <= bound,
                    "{w}×{h}: the plain mean"
                );
            } else {
                // The folded chain over-weights the left columns of 1280 =
                // 5·256 (¼ against ⅙); the bilinear one skips columns and
                // favours the middle of a convex pattern: the mean moves.
                assert!(
                    (weighted - plain).abs() > 1e-3,
                    "{w}×{h} {odd:?}: {weighted} vs {plain}"
                );
            }
        }
    }
}

#[test]
fn render_runs_the_example_lists_and_writes_every_target() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = ps30(
        &[
            "render",
            "drawlists/log-lights.json",
            "-o",
            out.to_str().unwrap(),
            "--every-step",
        ],
        repo(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("blend DESTCOLOR ZERO ADD, alpha DESTALPHA ZERO ADD"),
        "{text}"
    );
    assert!(
        text.contains("recovered   256×2 D3DFMT_A32B32G32R32F"),
        "{text}"
    );
    for name in ["log", "recovered", "raw8", "half"] {
        assert!(out.join(format!("{name}.exr")).exists());
        assert!(out.join(format!("{name}.png")).exists());
    }
    // Every step's snapshot: 13 steps, EXR and PNG each.
    assert!(out.join("004-recovered.exr").exists());
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), 4 * 2 + 13 * 2);
    let o = ps30(&["render", "drawlists/lights.json", "--json"], repo());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["steps"].as_array().unwrap().len(), 5);
    assert_eq!(v["steps"][1]["blend"], "ONE ONE ADD");
    assert_eq!(v["steps"][1]["write"], "rgb");
    assert_eq!(v["targets"][0]["format"], "D3DFMT_A16B16G16R16F");
}

#[test]
fn render_outputs_are_the_same_for_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    for (out, threads) in [(&a, "1"), (&b, "2")] {
        let o = ps30(
            &[
                "render",
                "drawlists/lights.json",
                "-o",
                out.to_str().unwrap(),
                "--threads",
                threads,
            ],
            repo(),
        );
        assert!(o.status.success(), "{}", stderr(&o));
    }
    for f in ["light.exr", "light.png"] {
        assert_eq!(
            std::fs::read(a.join(f)).unwrap(),
            std::fs::read(b.join(f)).unwrap(),
            "{f}"
        );
    }
}

/// Bad lists: exit 2, the file and the place in it named, nothing run.
#[test]
fn bad_draw_lists_name_the_place() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &str); 11] = [
        ("{", "line 1 column 1"),
        (
            r#"{"targets": [], "steps": [], "extra": 1}"#,
            "unknown field `extra`",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R8G8B8"}], "steps": []}"#,
            "targets[0].format: unknown format `R8G8B8`",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "0x8", "format": "R32F"}], "steps": []}"#,
            "targets[0].size",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R32F"}], "steps": [{"clear": "u"}]}"#,
            "steps[0].clear: no target named `u`",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R32F"}], "steps": [{"clear": "t", "draw": "t"}]}"#,
            "steps[0]: a step is exactly one of",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R32F"}], "steps": [{"draw": "t", "shader": "log-lights:light", "blend": {"src": "ONE", "dest": "BOTHSRCALPHA"}}]}"#,
            "steps[0].blend.dest: unknown blend factor `BOTHSRCALPHA`",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R32F"}], "steps": [{"draw": "t", "shader": "log-lights:light", "write": "rgbq"}]}"#,
            "steps[0].write",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "A8R8G8B8"}], "steps": [{"draw": "t", "shader": "log-lights:recover", "inputs": {"v0": "texcoord"}, "samplers": {"s0": {"texture": "t"}}}]}"#,
            "the target this draw renders to",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "8x8", "format": "R32F"}], "steps": [{"draw": "t", "shader": "log-lights:light", "constants": {"c0": [1e39]}}]}"#,
            "steps[0].constants.c0",
        ),
        (
            r#"{"targets": [{"name": "t", "size": "65536x65536", "format": "R32F"}], "steps": []}"#,
            "--max-pixels",
        ),
    ];
    for (i, (text, want)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("bad{i}.json"));
        std::fs::write(&path, text).unwrap();
        let o = ps30(&["render", path.to_str().unwrap()], repo());
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "case {i}: {err}");
        assert!(
            err.contains(want) && err.contains(&format!("bad{i}.json")),
            "case {i}: {err}"
        );
        assert!(!err.contains("panicked"), "case {i}: {err}");
    }
    // A shader that does not exist, and too many steps for --max-steps.
    let path = dir.path().join("steps.json");
    std::fs::write(
        &path,
        r#"{"targets": [{"name": "t", "size": "2x2", "format": "R32F"}], "steps": [{"clear": "t"}, {"clear": "t"}]}"#,
    )
    .unwrap();
    let o = ps30(
        &["render", path.to_str().unwrap(), "--max-steps", "1"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("2 steps, more than the limit of 1"),
        "{}",
        stderr(&o)
    );
    let o = ps30(
        &["render", path.to_str().unwrap(), "--max-steps", "2"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// The clear colour is a D3DCOLOR in every format; an 8-bit target written
/// in alpha only keeps its other channels; a discarded pixel keeps its
/// texel (here: a shader that kills the left half).
#[test]
fn clears_write_masks_and_discards_through_a_draw_list() {
    let text = r#"{"targets": [{"name": "t", "size": "4x2", "format": "A8R8G8B8"}],
        "steps": [{"clear": "t", "color": [10, 20, 30, 40]},
                  {"draw": "t", "shader": "kill.psh", "inputs": {"v0": "texcoord"}, "write": "ba"}]}"#;
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("kill.psh"),
        "ps_3_0\ndcl_texcoord0 v0.xy\ndef c0, -0.5, 0, 0, 0\ndef c1, 1, 0.5, 0.25, 0.75\nadd r0, v0.x, c0.x\ntexkill r0\nmov oC0, c1\n",
    )
    .unwrap();
    let loaded = file::parse(text, &dir.path().join("list.json"), &Default::default()).unwrap();
    let (reports, states) = render::run(&loaded.list, &Default::default(), &mut |_, _| {}).unwrap();
    let t = &states[0].target;
    let code = |v: f32| (v * 255.0).round() as u8;
    // Left half (u < 0.5) killed: the clear colour.
    assert_eq!(t.texel(0, 0).map(code), [10, 20, 30, 40]);
    assert_eq!(t.texel(1, 1).map(code), [10, 20, 30, 40]);
    // Right half: R, G kept; B = 0.25 → 64; A = 0.75 → 191.25 → 191.
    assert_eq!(t.texel(2, 0).map(code), [10, 20, 64, 191]);
    assert_eq!(t.texel(3, 1).map(code), [10, 20, 64, 191]);
    match &reports[1].detail {
        render::StepDetail::Draw { merged, .. } => {
            assert_eq!((merged.written, merged.killed), (4, 4))
        }
        _ => panic!("a draw"),
    }
}

/// `-o DIR` is all or nothing, and never writes over an input: a run that
/// fails at its second step leaves no file (and no directory it created);
/// a target named like one of the list's images is refused before anything
/// is written, and the image is untouched.
#[test]
fn render_outputs_are_all_or_nothing_and_never_an_input() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = ps30(
        &[
            "render",
            "drawlists/lights.json",
            "-o",
            out.to_str().unwrap(),
            "--every-step",
            "--max-executed-per-pixel",
            "10",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("steps[1]"), "{}", stderr(&o));
    assert!(!out.exists(), "a failed run leaves nothing behind");

    let src = repo().join("assets/hdr/sunset.pfm");
    let image = dir.path().join("frame.exr");
    let target = ps30::core::image::load(&src, &Default::default()).unwrap();
    let rt = ps30::core::image::RenderTarget {
        width: target.width,
        height: target.height,
        format: TargetFormat::A32B32G32R32F,
        texels: target.pixels.clone(),
    };
    ps30::core::image::write_exr(&image, &rt).unwrap();
    let before = std::fs::read(&image).unwrap();
    let list = dir.path().join("list.json");
    std::fs::write(
        &list,
        r#"{"targets": [{"name": "frame", "size": "4x4", "format": "R32F"}],
            "textures": [{"name": "img", "image": "frame.exr"}],
            "steps": [{"clear": "frame"}]}"#,
    )
    .unwrap();
    let o = ps30(
        &[
            "render",
            list.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("frame.exr"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&image).unwrap(), before);
    assert!(!dir.path().join("frame.png").exists());
}

/// `float_rules` and `alpha_test` in a draw list. By hand: v0 is the pixel
/// centre's texture coordinate, (x + ½)/4 for x = 0..3: 0.125, 0.375, 0.625,
/// 0.875, whose 8-bit codes are 32, 96, 159, 223 (floor(255·a + ½)); with
/// GREATEREQUAL 128 the two left columns are discarded. c0 = (0, inf): the
/// `hardware` rules make 0 × inf = 0 where `d3d9` gives NaN.
#[test]
fn alpha_test_and_float_rules_from_a_draw_list() {
    let dir = std::env::temp_dir().join(format!("ps30-pixel-state-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("a.psh"),
        "ps_3_0\ndcl_texcoord0 v0\nmul r0.x, c0.x, c0.y\nmov r0.yzw, v0.x\nmov oC0, r0\n",
    )
    .unwrap();
    let list = |rules: &str| {
        format!(
            r#"{{"targets": [{{"name": "t", "size": "4x1", "format": "A32B32G32R32F"}}],
               "steps": [{{"clear": "t", "color": [255, 255, 255, 255]}},
                         {{"draw": "t", "shader": "a.psh", "inputs": {{"v0": "texcoord"}},
                           "constants": {{"c0": [0, "inf"]}}, "float_rules": "{rules}",
                           "alpha_test": {{"func": "GREATEREQUAL", "ref": 128}}}}]}}"#
        )
    };
    for (rules, nan) in [("hardware", false), ("d3d9", true)] {
        let path = dir.join(format!("{rules}.json"));
        std::fs::write(&path, list(rules)).unwrap();
        let loaded = file::read(&path, &Default::default()).unwrap();
        let (_, states) = render::run(&loaded.list, &Default::default(), &mut |_, _| {}).unwrap();
        let px: Vec<[f32; 4]> = (0..4).map(|x| states[0].target.texel(x, 0)).collect();
        assert_eq!(
            px[0], [1.0; 4],
            "{rules}: alpha 0.125 fails, the clear stays"
        );
        assert_eq!(px[1], [1.0; 4], "{rules}: alpha 0.375 fails");
        for p in &px[2..] {
            assert_eq!(p[0].is_nan(), nan, "{rules}: 0 × inf");
            assert!(p[3] >= 0.5);
        }
    }
}

/// Multiple render targets through a draw list. By hand: oC0 = (1, 0, 0,
/// a) with a = v0.x (0.125, 0.375, 0.625, 0.875 over four pixels), oC1 =
/// (0.25, 0.5, 0.75, 1) through the write mask `rg` onto a target cleared
/// to white, oC2 = v0 into an R32F target (red only is stored). The alpha
/// test (GREATEREQUAL 128) discards the two left pixels in every target.
#[test]
fn multiple_render_targets_with_their_own_masks_and_formats() {
    let dir = std::env::temp_dir().join(format!("ps30-mrt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("mrt.psh"),
        "ps_3_0\ndcl_texcoord0 v0\ndef c0, 1, 0, 0.25, 0.5\ndef c1, 0.75, 1, 0, 0\n\
         mov r0, c0.xyyy\nmov r0.w, v0.x\nmov oC0, r0\n\
         mov r1.xy, c0.zw\nmov r1.zw, c1.xy\nmov oC1, r1\nmov oC2, v0\n",
    )
    .unwrap();
    let list = r#"{"targets": [{"name": "a", "size": "4x1", "format": "A8R8G8B8"},
                               {"name": "b", "size": "4x1", "format": "A16B16G16R16F"},
                               {"name": "c", "size": "4x1", "format": "R32F"},
                               {"name": "small", "size": "2x1", "format": "R32F"}],
       "steps": [{"clear": "b", "color": [255, 255, 255, 255]},
                 {"draw": "a", "shader": "mrt.psh", "inputs": {"v0": "texcoord"},
                  "alpha_test": {"func": "GREATEREQUAL", "ref": 128},
                  "outputs": {"oC1": {"target": "b", "write": "rg"}, "oC2": "c"}}]}"#;
    let path = dir.join("mrt.json");
    std::fs::write(&path, list).unwrap();
    let loaded = file::read(&path, &Default::default()).unwrap();
    let (_, states) = render::run(&loaded.list, &Default::default(), &mut |_, _| {}).unwrap();
    let px = |t: usize, x: u32| states[t].target.texel(x, 0);
    for x in 0..2 {
        assert_eq!(px(0, x), [0.0; 4], "pixel {x} discarded: a keeps its clear");
        assert_eq!(px(1, x), [1.0; 4], "pixel {x} discarded: b keeps white");
        assert_eq!(px(2, x)[0], 0.0);
    }
    for x in 2..4 {
        let a = (x as f32 + 0.5) / 4.0;
        // 8-bit alpha: the code floor(255a + 1/2) read back as code/255.
        let code = (255.0 * a + 0.5).floor() / 255.0;
        assert_eq!(px(0, x), [1.0, 0.0, 0.0, code]);
        // 0.25 and 0.5 are exact in half; b and a stay white (the mask).
        assert_eq!(px(1, x), [0.25, 0.5, 1.0, 1.0]);
        assert_eq!(px(2, x)[0], a, "R32F stores v0.x exactly");
    }
    // A target of another size is refused, naming the field.
    std::fs::write(&path, list.replace(r#""oC2": "c""#, r#""oC2": "small""#)).unwrap();
    let e = file::read(&path, &Default::default())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("steps[1].outputs.oC2") && e.contains("one size"),
        "{e}"
    );
}

/// Flat shading and a user clip plane from a draw list. By hand: v0 (a
/// colour) is 0.5 + 0.25·x at pixel x; flat, it holds its value at the
/// quad's first vertex, the corner half a pixel left of pixel 0's centre:
/// 0.5 − 0.125 = 0.375 everywhere. The plane 1.5 − x is 1.5, 0.5, −0.5,
/// −1.5: pixels 2 and 3 are clipped and keep the clear (0).
#[test]
fn flat_shading_and_clip_planes_from_a_draw_list() {
    let dir = std::env::temp_dir().join(format!("ps30-flat-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("c.psh"), "ps_3_0\ndcl_color0 v0\nmov oC0, v0\n").unwrap();
    let list = |extra: &str| {
        format!(
            r#"{{"targets": [{{"name": "t", "size": "4x1", "format": "R32F"}}],
               "steps": [{{"draw": "t", "shader": "c.psh",
                 "inputs": {{"v0": {{"base": [0.5], "ddx": [0.25]}}}}{extra}}}]}}"#
        )
    };
    let red = |extra: &str| -> Vec<f32> {
        let path = dir.join("c.json");
        std::fs::write(&path, list(extra)).unwrap();
        let loaded = file::read(&path, &Default::default()).unwrap();
        let (_, states) = render::run(&loaded.list, &Default::default(), &mut |_, _| {}).unwrap();
        (0..4).map(|x| states[0].target.texel(x, 0)[0]).collect()
    };
    assert_eq!(red(""), vec![0.5, 0.75, 1.0, 1.25]);
    assert_eq!(red(r#", "shade": "flat""#), vec![0.375; 4]);
    assert_eq!(
        red(r#", "clip_planes": [{"base": 1.5, "ddx": -1}]"#),
        vec![0.5, 0.75, 0.0, 0.0]
    );
}
