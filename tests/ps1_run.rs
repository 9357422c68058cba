//! ps_1_x shaders run from the outside: `ps30 run`, a draw list with
//! geometry, `compare` against the GPU backend, the bump-environment
//! instructions over a draw list's stage state, and that state's errors. Expected values are worked out beside each test
//! from the shaders in `tests/ps1_run/`.

use crate::common::bin::{in_repo, stderr, stdout};
use crate::common::gpu as gpu_device;
use serde_json::Value;

#[test]
fn run_gives_the_texcoord_colour() {
    // texcoord.psh: r = saturate(t0.x) · 0.5. `--input t0=texcoord` puts
    // the pixel centres of a 2×2 target at x = 0.25 and 0.75, so red is
    // 0.125 in the left column and 0.375 in the right (`run`'s target
    // stores red only).
    let out = in_repo(&[
        "run",
        "tests/ps1_run/texcoord.psh",
        "--target",
        "2x2",
        "--input",
        "v0=1,1,1,0.75",
        "--input",
        "t0=texcoord,0.5,1",
        "--json",
        "--texels",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let json: Value = serde_json::from_str(&stdout(&out)).unwrap();
    let red: Vec<f64> = json["texels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t[0].as_f64().unwrap())
        .collect();
    assert_eq!(red, [0.125, 0.375, 0.125, 0.375]);
    // Two slots (texcoord, the co-issued pair), executed as counted.
    assert_eq!(json["pass"]["slots"], 2);
    assert_eq!(json["pass"]["counts_agree"], true);
}

#[test]
fn a_draw_list_draws_ps_1_4_geometry() {
    // phases.psh over a full-target quad whose texcoord0 is (0.5, 0.25, 2)
    // and color0 (0.5, 1, 0.25) at every vertex: r0.rgb = (0.5·0.5,
    // 0.25·1, 2·0.25) = (0.25, 0.25, 0.5), alpha c0.b = 0.75, at all four
    // pixels.
    let out = in_repo(&["render", "tests/ps1_run/geometry.json", "--json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let json: Value = serde_json::from_str(&stdout(&out)).unwrap();
    let channels = json["targets"][0]["channels"].as_array().unwrap();
    for (c, want) in channels.iter().zip([0.25, 0.25, 0.5, 0.75]) {
        assert_eq!(c["min"], want);
        assert_eq!(c["max"], want);
    }
    assert_eq!(json["steps"][0]["detail"]["merged"]["written"], 4);
}

#[test]
fn the_bump_instructions_draw_the_hand_derived_pixels_on_both_backends() {
    // tests/draw_conformance/bump.json. `dudv` holds (0.25, -0.25, 0.5, 1)
    // at every pixel; `env` the texel centres ((i + ½)/4, (j + ½)/4, 0, 1)
    // (texcoord0 0…1 across a pre-transformed quad from -½ to 3½: pixel
    // (i, j) is sampled at (i, j)). Stage 1's matrix (M00, M01, M10, M11)
    // = (2, 1, -1, 2): by the texbem and bem pages u' = u + M00·du +
    // M10·dv = u + 0.5 + 0.25 = u + 0.75 and v' = v + M01·du + M11·dv =
    // v + 0.25 - 0.5 = v - 0.25: three texels right and one up, wrapped
    // (WRAP, the draw list's default), at the texel's centre. texbeml
    // scales rgb by du/dv's b · LSCALE + LOFFSET = 0.5·1 + 0.25 = 0.75.
    let centre = |k: u32| (k as f32 + 0.5) / 4.0;
    let moved = |x: u32, y: u32| [centre((x + 3) % 4), centre((y + 3) % 4), 0.0, 1.0];
    let t = crate::draw_conformance::draw("bump.json");
    crate::draw_conformance::check(&t, "texbem", moved);
    crate::draw_conformance::check(&t, "bem", moved);
    crate::draw_conformance::check(&t, "texbeml", |x, y| {
        let [r, g, b, a] = moved(x, y);
        [r * 0.75, g * 0.75, b * 0.75, a]
    });
    // texm3x3spec: t0 = (0.25, -0.25, 0.5); coordinates 1 and 2 are
    // (0, 0, 2), 3 is 0, so the rows N = (1, 1, 0); E = c0 = (0.125,
    // 0.875, 0): N·E = 1, N·N = 2, R = 2·(1/2)·N − E = (0.875, 0.125, 0),
    // the texel centre (3, 0) of `env` at every pixel.
    crate::draw_conformance::check(&t, "spec", |_, _| [0.875, 0.125, 0.0, 1.0]);
    // The GPU backend: the same pixels, bit for bit (tests/draw_gpu.rs
    // compares the whole list as well).
    let path = crate::common::bin::repo().join("tests/draw_conformance/bump.json");
    if let Some(gpu) = crate::d3d9_conformance::render_file(&path, "gpu") {
        for name in ["texbem", "bem", "texbeml", "spec"] {
            assert_eq!(gpu[name], t[name], "{name}");
        }
    }
}

#[test]
fn bump_state_is_checked_where_it_is_given() {
    // A non-finite value, a stage past s5 and a constant the state would
    // overwrite exit 2 naming the field.
    let dir = tempfile::tempdir().unwrap();
    let shader = in_repo_path("tests/draw_conformance/bump_texbem.psh");
    let list = |sampler: &str, constants: &str| {
        format!(
            r#"{{"targets": [{{"name": "e", "size": "2x2", "format": "A32B32G32R32F"}},
                {{"name": "t", "size": "2x2", "format": "A32B32G32R32F"}}],
              "steps": [{{"draw": "t", "shader": "{shader}", "constants": {{{constants}}},
                "samplers": {{"s0": {{"texture": "e"}}, {sampler}}}}}]}}"#
        )
    };
    for (sampler, constants, field) in [
        (
            r#""s1": {"texture": "e", "bump_matrix": [1, 2, 3, 1e40]}"#,
            "",
            "steps[0].samplers.s1.bump_matrix",
        ),
        (
            r#""s1": {"texture": "e", "bump_lscale": -1e39}"#,
            "",
            "steps[0].samplers.s1.bump_lscale",
        ),
        (
            r#""s6": {"texture": "e", "bump_loffset": 1}"#,
            "",
            "steps[0].samplers.s6",
        ),
        (
            r#""s1": {"texture": "e", "bump_loffset": 1}"#,
            r#""c19": [0, 0, 0, 0]"#,
            "steps[0].samplers.s1",
        ),
    ] {
        let path = dir.path().join("l.json");
        std::fs::write(&path, list(sampler, constants)).unwrap();
        let out = in_repo(&["render", path.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{field}: {}", stderr(&out));
        assert!(stderr(&out).contains(field), "{field}: {}", stderr(&out));
    }
    // An inputs file gives the state the same way, checked the same way.
    let texture = in_repo_path("assets/textures/dxt1.dds");
    let inputs = dir.path().join("i.json");
    let text = format!(
        r#"{{"samplers": {{"s1": {{"texture": "{texture}", "bump_matrix": [0, 0, 0, 1e40]}}}}}}"#
    );
    std::fs::write(&inputs, text).unwrap();
    let out = in_repo(&[
        "run",
        &shader,
        "--inputs",
        inputs.to_str().unwrap(),
        "--target",
        "1x1",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("samplers.s1.bump_matrix: 1e40 is not a finite f32"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_gpu_backend_draws_ps_1_x_as_the_emulator_does() {
    if gpu_device::gpu("the_gpu_backend_draws_ps_1_x_as_the_emulator_does").is_none() {
        return;
    }
    // The same lowering runs on both: every pixel bit-identical.
    let out = in_repo(&[
        "compare",
        "tests/ps1_run/texcoord.psh",
        "--target",
        "4x4",
        "--input",
        "v0=1,1,1,0.75",
        "--input",
        "t0=texcoord,0.5,1",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("every pixel bit-identical"),
        "{}",
        stdout(&out)
    );
}

fn in_repo_path(p: &str) -> String {
    crate::common::bin::repo().join(p).display().to_string()
}
