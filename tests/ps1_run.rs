//! ps_1_x shaders run from the outside: `ps30 run`, a draw list with
//! geometry, `compare` against the GPU backend, and the refusal of what
//! ps30 does not run yet. Expected values are worked out beside each test
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
fn what_ps30_does_not_run_is_refused_by_name() {
    let out = in_repo(&[
        "run",
        "asm/ps1x/bump.psh",
        "--target",
        "2x2",
        "--image",
        "assets/hdr/city.exr",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("a ps_1_1 shader: `texbem` (line 7): ps30 does not run it yet"),
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
