//! `ps30 render --pixel`: one pixel's history through a draw list, on the
//! small lists of `tests/pixel_history/` — overdraw with a depth reject,
//! draws that miss the pixel for each reason the set-up knows, a helper
//! pixel, blending in drawing order, texkill, the alpha test and a clip
//! plane. Every expected value is derived here by hand from Direct3D 9's
//! rules (the derivation beside it), never read from ps30.
//!
//! The shaders: `all.psh` writes texcoord0 to oC0 and declares vPos and
//! vFace; `kill.psh` writes texcoord0 after `texkill v0`. Targets are
//! D3DFMT_A32B32G32R32F, so every value here is exact in f32.

use crate::common::bin::{in_repo, stderr, stdout};
use serde_json::Value;

/// The histories `render LIST --pixel …` gives in JSON.
fn histories(list: &str, pixels: &[&str]) -> Vec<Value> {
    let path = format!("tests/pixel_history/{list}");
    let mut args = vec!["render", path.as_str(), "--json"];
    for p in pixels {
        args.extend(["--pixel", p]);
    }
    let o = in_repo(&args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    v["pixels"].as_array().expect("pixels").clone()
}

fn vec4(v: &Value) -> [f64; 4] {
    let a = v.as_array().expect("four components");
    std::array::from_fn(|i| a[i].as_f64().expect("a number"))
}

/// The value of register `name` in a fragment's `inputs` or `outputs`.
fn register(list: &Value, name: &str) -> [f64; 4] {
    let r = list
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["register"] == name)
        .unwrap_or_else(|| panic!("no {name} in {list}"));
    vec4(&r["value"])
}

/// D24's stored form of a depth: round(z · (2²⁴ − 1)) / (2²⁴ − 1).
fn d24(z: f64) -> f64 {
    let max = f64::from((1u32 << 24) - 1);
    (z * max).round() / max
}

#[test]
fn overdraw_with_a_depth_reject_and_every_way_to_miss() {
    let h = &histories("overdraw.json", &["1,2"])[0];
    assert_eq!(
        (h["target"].as_str(), h["x"].as_u64(), h["y"].as_u64()),
        (Some("t"), Some(1), Some(2))
    );
    let steps = h["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 7);
    // Clear to the D3DCOLOR (0, 0, 0, 255).
    assert_eq!(steps[0]["kind"], "clear");
    assert_eq!(vec4(&steps[0]["after"]), [0.0, 0.0, 0.0, 1.0]);
    // Step 1: the quad (0,0)–(4,4) at z = 0.25 as two triangles, the first
    // (0,0),(4,0),(0,4). Pixel (1, 2): x + y = 3 < 4, inside the first
    // (screen weights 1 − x/4 − y/4, x/4, y/4 = 0.25, 0.25, 0.5); the
    // second triangle's quad (0..1, 2..3) holds (1, 3) (x + y = 4, on the
    // shared edge: the second's by the top-left rule), so (1, 2) is a
    // helper there.
    let f = steps[1]["fragments"].as_array().unwrap();
    assert_eq!(f.len(), 2);
    assert_eq!(f[0]["helper"], false);
    assert_eq!(f[0]["primitive"]["index"], 0);
    let w: Vec<f64> = f[0]["primitive"]["weights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_f64().unwrap())
        .collect();
    assert_eq!(w, [0.25, 0.25, 0.5]);
    assert_eq!(
        f[0]["quad_covered"], 3,
        "(0,2), (1,2), (0,3) are inside, (1,3) is on the far edge"
    );
    assert_eq!(register(&f[0]["inputs"], "v0"), [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(register(&f[0]["inputs"], "vPos"), [1.0, 2.0, 0.0, 0.0]);
    // (0,0) → (4,0) → (0,4) is clockwise on screen (y down): a front face.
    assert_eq!(register(&f[0]["inputs"], "vFace"), [1.0; 4]);
    assert_eq!(register(&f[0]["outputs"], "oC0"), [1.0, 0.0, 0.0, 1.0]);
    // A depth buffer cleared to 1; z = 0.25 as D24 stores it passes LESSEQUAL.
    let d = &f[0]["depth"];
    assert_eq!(d["z"].as_f64(), Some(d24(0.25)));
    assert_eq!(d["stored"].as_f64(), Some(1.0));
    assert_eq!(
        (
            d["func"].as_str(),
            d["passed"].as_bool(),
            d["written"].as_bool()
        ),
        (Some("LESSEQUAL"), Some(true), Some(true))
    );
    // Blending off: the source replaces black.
    let b = &f[0]["blend"];
    assert!(b["terms"].is_null());
    assert_eq!(vec4(&b["dest"]), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(vec4(&b["result"]), [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(f[0]["fate"], "written");
    assert_eq!(
        (f[1]["helper"].as_bool(), f[1]["fate"].as_str()),
        (Some(true), Some("helper"))
    );
    assert!(f[1]["outputs"].as_array().unwrap().is_empty());
    // Step 2: green at z = 0.75 is behind: 0.75 ≤ 0.25 fails, nothing
    // written, no blend.
    let f = &steps[2]["fragments"][0];
    assert_eq!(f["fate"], "depth_test");
    assert_eq!(f["depth"]["z"].as_f64(), Some(d24(0.75)));
    assert_eq!(f["depth"]["stored"].as_f64(), Some(d24(0.25)));
    assert_eq!(
        (
            f["depth"]["passed"].as_bool(),
            f["depth"]["written"].as_bool()
        ),
        (Some(false), Some(false))
    );
    assert!(f["blend"].is_null());
    assert_eq!(vec4(&steps[2]["after"]), [1.0, 0.0, 0.0, 1.0]);
    // Steps 3–6 miss the pixel, each for its own reason.
    let missed = |k: usize| {
        assert!(steps[k]["fragments"].as_array().unwrap().is_empty());
        assert_eq!(vec4(&steps[k]["after"]), [1.0, 0.0, 0.0, 1.0]);
        steps[k]["missed"].as_str().unwrap().to_string()
    };
    // The quad wound counter-clockwise, under the default D3DCULL_CCW.
    assert!(missed(3).starts_with("culled"), "{}", missed(3));
    // The scissor RECT [2, 0, 4, 4] leaves columns 2 and 3.
    assert!(missed(4).starts_with("scissored"), "{}", missed(4));
    // A quad over columns 2 and 3 only (its left edge at x = 2).
    assert!(
        missed(5).starts_with("outside every primitive"),
        "{}",
        missed(5)
    );
    // The viewport x = 2, width 2.
    assert!(
        missed(6).starts_with("outside the viewport"),
        "{}",
        missed(6)
    );
    assert_eq!(vec4(&h["last"]), [1.0, 0.0, 0.0, 1.0]);
}

#[test]
fn a_helper_pixel_shows_the_values_extended_past_the_edge() {
    // The triangle (0,0),(4,0),(0,4) with texcoord0 = (0,0), (1,0), (0,1):
    // with 1/w = 1 the value at (x, y) is (x/4, y/4, 0, 1). Pixel (1, 3)
    // is on the edge x + y = 4, which runs down-left: neither a top nor a
    // left edge, so not covered; its quad (0..1, 2..3) has (0,2), (1,2),
    // (0,3) inside, so it runs as a helper with (0.25, 0.75, 0, 1).
    let h = histories("helper.json", &["1,3", "1,2"]);
    let f = h[0]["steps"][0]["fragments"].as_array().unwrap();
    assert_eq!(f.len(), 1);
    assert_eq!(f[0]["helper"], true);
    assert_eq!(f[0]["fate"], "helper");
    assert_eq!(f[0]["quad_covered"], 3);
    assert_eq!(register(&f[0]["inputs"], "v0"), [0.25, 0.75, 0.0, 1.0]);
    assert!(f[0]["executed"].is_null());
    assert_eq!(vec4(&h[0]["last"]), [0.0; 4], "a helper writes nothing");
    // Its covered neighbour (1, 2) gets (0.25, 0.5, 0, 1) and writes it.
    let g = &h[1]["steps"][0]["fragments"][0];
    assert_eq!(g["helper"], false);
    assert_eq!(register(&g["inputs"], "v0"), [0.25, 0.5, 0.0, 1.0]);
    assert_eq!(vec4(&h[1]["last"]), [0.25, 0.5, 0.0, 1.0]);
}

#[test]
fn blending_in_drawing_order_with_its_terms() {
    let h = &histories("blend.json", &["1,1"])[0];
    let steps = h["steps"].as_array().unwrap();
    // Clear to (0, 0, 255, 255): blue, alpha 1.
    assert_eq!(vec4(&steps[0]["after"]), [0.0, 0.0, 1.0, 1.0]);
    // Step 1, SRCALPHA / INVSRCALPHA: both triangles cover (1, 1) (the
    // second, (0,0),(2,0),(0,4), holds x/2 + y/4 < 1: 0.75). Red at alpha
    // 0.5 over blue: 0.5·(1,0,0,0.5) + 0.5·(0,0,1,1) = (0.5, 0, 0.5, 0.75);
    // then green at 0.25: 0.25·(0,1,0,0.25) + 0.75·(0.5,0,0.5,0.75) =
    // (0.375, 0.25, 0.375, 0.625).
    let f = steps[1]["fragments"].as_array().unwrap();
    assert_eq!(f.len(), 2);
    let b0 = &f[0]["blend"];
    assert_eq!(vec4(&b0["dest"]), [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(vec4(&b0["terms"]["source_factor"]), [0.5; 4]);
    assert_eq!(vec4(&b0["terms"]["dest_factor"]), [0.5; 4]);
    assert_eq!(vec4(&b0["result"]), [0.5, 0.0, 0.5, 0.75]);
    let b1 = &f[1]["blend"];
    assert_eq!(f[1]["primitive"]["index"], 1);
    assert_eq!(vec4(&b1["source"]), [0.0, 1.0, 0.0, 0.25]);
    assert_eq!(
        vec4(&b1["dest"]),
        [0.5, 0.0, 0.5, 0.75],
        "the first triangle's result"
    );
    assert_eq!(vec4(&b1["terms"]["source_factor"]), [0.25; 4]);
    assert_eq!(vec4(&b1["terms"]["dest_factor"]), [0.75; 4]);
    assert_eq!(vec4(&b1["result"]), [0.375, 0.25, 0.375, 0.625]);
    // Step 2, a full-screen draw adding (0.125, 0.125, 0.125, 0) with
    // ONE/ONE, write rgb: (0.5, 0.375, 0.5) and alpha kept at 0.625.
    let f = &steps[2]["fragments"][0];
    assert!(f["primitive"].is_null());
    assert_eq!(register(&f["inputs"], "vPos"), [1.0, 1.0, 0.0, 0.0]);
    assert_eq!(vec4(&f["blend"]["result"]), [0.5, 0.375, 0.5, 0.625]);
    assert_eq!(steps[2]["merger"]["write"], 7);
    assert_eq!(vec4(&h["last"]), [0.5, 0.375, 0.5, 0.625]);
}

#[test]
fn texkill_the_alpha_test_and_a_clip_plane() {
    let h = histories("kill.json", &["0,2", "2,2"]);
    // Step 1: texcoord0.x runs from −1 at x = 0 to 3 at x = 4 (−1 + x):
    // at x = 0 it is −1 and texkill discards; at x = 2 it is 1.
    let killed = &h[0]["steps"][1]["fragments"][0];
    assert_eq!(register(&killed["inputs"], "v0"), [-1.0, 0.0, 0.0, 1.0]);
    assert_eq!(
        (killed["killed"].as_bool(), killed["fate"].as_str()),
        (Some(true), Some("killed"))
    );
    assert!(killed["blend"].is_null() && killed["depth"].is_null());
    assert_eq!(vec4(&h[0]["steps"][1]["after"]), [0.0; 4]);
    let kept = &h[1]["steps"][1]["fragments"][0];
    assert_eq!(kept["fate"], "written");
    assert_eq!(vec4(&h[1]["steps"][1]["after"]), [1.0, 0.0, 0.0, 1.0]);
    // Step 2: on this 32-bit float target the alpha test compares the
    // alpha itself, 0.5, with 200/255: GREATER fails.
    for p in &h {
        let a = &p["steps"][2]["fragments"][0]["alpha_test"];
        assert_eq!(
            (
                a["code"].as_f64(),
                a["func"].as_str(),
                a["reference"].as_u64()
            ),
            (Some(0.5), Some("GREATER"), Some(200))
        );
        assert_eq!(a["passed"], false);
        assert_eq!(p["steps"][2]["fragments"][0]["fate"], "alpha_test");
    }
    // Step 3: the plane's distance 1.5 − x is 1.5 at x = 0 (kept) and
    // −0.5 at x = 2 (removed).
    assert_eq!(h[0]["steps"][3]["fragments"][0]["fate"], "written");
    assert_eq!(vec4(&h[0]["last"]), [0.25, 0.25, 0.25, 1.0]);
    let clipped = &h[1]["steps"][3]["fragments"][0];
    assert_eq!(
        (clipped["clip_plane"].as_u64(), clipped["fate"].as_str()),
        (Some(0), Some("clipped"))
    );
    assert_eq!(vec4(&h[1]["last"]), [1.0, 0.0, 0.0, 1.0]);
}

#[test]
fn the_text_reads_without_a_caption_and_bad_pixels_are_refused() {
    let o = in_repo(&[
        "render",
        "tests/pixel_history/overdraw.json",
        "--pixel",
        "t:1,2",
        "--color",
        "never",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    for line in [
        "pixel (1, 2) of `t` (D3DFMT_A32B32G32R32F), 7 steps on the target:",
        "      → failed the depth test",
        "    not covered: scissored (the rectangle is [2, 0, 4, 4])",
        "  last: (1, 0, 0, 1)",
    ] {
        assert!(
            text.lines().any(|l| l == line),
            "no line {line:?} in\n{text}"
        );
    }
    for (pixel, says) in [
        ("4,0", "outside `t`, which is 4×4"),
        ("nope:1,1", "no target named `nope`"),
        ("1", "X,Y or TARGET:X,Y"),
    ] {
        let o = in_repo(&[
            "render",
            "tests/pixel_history/overdraw.json",
            "--pixel",
            pixel,
        ]);
        assert_eq!(o.status.code(), Some(2), "--pixel {pixel}");
        assert!(stderr(&o).contains(says), "--pixel {pixel}: {}", stderr(&o));
    }
}

#[test]
fn every_step_writes_a_geometry_draws_targets_and_its_second_output() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let o = in_repo(&[
        "render",
        "tests/pixel_history/mrt.json",
        "-o",
        out,
        "--every-step",
        "-q",
        "--pixel",
        "b:1,1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let read = |name: &str| {
        let img = ps30::core::image::load(&dir.path().join(name), &Default::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        img.pixels
    };
    // Step 0 clears `a` to blue; step 1 draws the triangle (0,0),(4,0),(0,4)
    // over it: red at (1, 1) (x + y = 2 < 4), blue left at (3, 3).
    assert_eq!(read("000-a.exr")[5], [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(read("001-a.exr")[5], [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(read("001-a.exr")[15], [0.0, 0.0, 1.0, 1.0]);
    // oC1 into `b` with write mask rg: (0.5, 0.25) over b's initial zeros.
    assert_eq!(read("001-b.exr")[5], [0.5, 0.25, 0.0, 0.0]);
    assert!(
        !dir.path().join("000-b.exr").exists(),
        "step 0 leaves b alone"
    );
    // The history of b's pixel (1, 1) is the draw's oC1.
    let h = &histories("mrt.json", &["b:1,1"])[0];
    let step = &h["steps"][0];
    assert_eq!(
        (step["step"].as_u64(), step["output"].as_u64()),
        (Some(1), Some(1))
    );
    let f = &step["fragments"][0];
    assert_eq!(register(&f["outputs"], "oC1"), [0.5, 0.25, 0.75, 1.0]);
    assert_eq!(vec4(&f["blend"]["result"]), [0.5, 0.25, 0.0, 0.0]);
}

#[test]
fn an_output_the_shader_does_not_write_leaves_its_target_alone() {
    // all.psh writes oC0 only; b is bound to oC1 and cleared to blue. The
    // ps_3_0 output-register page: an unwritten oCn does not update its
    // render target — in a draw of geometry as in a full-screen one.
    let h = &histories("unwritten.json", &["b:0,0"])[0];
    for k in [1, 2] {
        let step = &h["steps"][k];
        assert_eq!(step["output"], 1);
        assert_eq!(step["fragments"][0]["fate"], "no_output", "step {k}");
        assert!(step["fragments"][0]["blend"].is_null());
        assert_eq!(vec4(&step["after"]), [0.0, 0.0, 1.0, 1.0], "step {k}");
    }
}

/// `clipped[k]` of a step: its kind, index, vertices, planes and position.
fn clipped(step: &Value, k: usize) -> (String, u64, Vec<u64>, Vec<String>, [f64; 4]) {
    let c = &step["clipped"][k];
    (
        c["kind"].as_str().unwrap().to_string(),
        c["primitive"].as_u64().unwrap(),
        c["vertices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap())
            .collect(),
        c["planes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p.as_str().unwrap().to_string())
            .collect(),
        vec4(&c["position"]),
    )
}

/// Whether two clip-space positions agree to f64 rounding: the position
/// over the pixel solves a 3×3 system of small exact numbers (Cramer's
/// rule, a few dozen operations on values ≤ 9), so 1e-12 is thousands of
/// times the worst rounding and far below any difference that matters.
fn same(a: [f64; 4], b: [f64; 4]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-12)
}

#[test]
fn clipping_that_removed_a_primitive_over_the_pixel_is_named() {
    // tests/pixel_history/clipped.json: an 8×4 target, vertices in clip
    // space (no vertex shader: identity transforms). Pixel (1, 1)'s centre
    // is at normalised (u, v) = (2·1/8 − 1, 1 − 2·1/4) = (−0.75, 0.5).
    // "Viewports and Clipping (Direct3D 9)": the view volume keeps
    // 0 ≤ z ≤ w, and a user clip plane keeps a·x + b·y + c·z + d·w ≥ 0.
    let both = histories("clipped.json", &["1,1", "7,1"]);
    let steps = both[0]["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 6);
    let near = "near plane (z < 0)".to_string();
    // Step 1: the triangle (−1,−1), (−1,3), (3,−1) covers the viewport;
    // its z equals its x (w = 1), so over the pixel it is at
    // (−0.75, 0.5, −0.75, 1): beyond the near plane, nothing drawn.
    let s = &steps[1];
    assert!(s["fragments"].as_array().unwrap().is_empty());
    assert_eq!(
        s["missed"],
        "clipped: triangle 0 lies over it beyond the near plane (z < 0)"
    );
    let (kind, index, vertices, planes, at) = clipped(s, 0);
    assert_eq!(
        (kind.as_str(), index, vertices),
        ("triangle", 0, vec![0, 1, 2])
    );
    assert_eq!(planes, vec![near.clone()]);
    assert!(same(at, [-0.75, 0.5, -0.75, 1.0]), "{at:?}");
    // Step 2: z = 0.5 everywhere, user plane (1, 0, 0, 0) keeps x ≥ 0;
    // x = −0.75 there.
    let s = &steps[2];
    assert!(s["fragments"].as_array().unwrap().is_empty());
    let (_, _, _, planes, at) = clipped(s, 0);
    assert_eq!(planes, vec!["user clip plane 0".to_string()]);
    assert!(same(at, [-0.75, 0.5, 0.5, 1.0]), "{at:?}");
    // Step 3: the same triangle at z = 1.5 (beyond the far plane z ≤ w),
    // then at z = 0.5 in blue: the second is drawn (the first reached
    // triangle), the first is named as clipped.
    let s = &steps[3];
    assert_eq!(s["fragments"].as_array().unwrap().len(), 1);
    assert!(s["missed"].is_null());
    let (_, index, vertices, planes, at) = clipped(s, 0);
    assert_eq!((index, vertices), (0, vec![0, 1, 2]));
    assert_eq!(planes, vec!["far plane (z > w)".to_string()]);
    assert!(same(at, [-0.75, 0.5, 1.5, 1.0]), "{at:?}");
    assert_eq!(s["clipped"].as_array().unwrap().len(), 1);
    assert_eq!(vec4(&s["after"]), [0.0, 0.0, 1.0, 1.0]);
    // Step 4: one point far from (1, 1): nothing clipped there.
    assert!(steps[4]["clipped"].is_null());
    assert_eq!(
        steps[4]["missed"],
        "outside every primitive (0 reached the pixel shader)"
    );
    // Step 5: a line along row 1 from (−1, 0.5, −1, 1) to (1, 0.5, 1, 1):
    // on screen from x = 0 to 8 through the centres of row 1 (the
    // diamond-exit rule covers (1, 1)); at x = 1 its parameter is 1/8 (w
    // = 1: no perspective), so it is at (−0.75, 0.5, −0.75, 1).
    let s = &steps[5];
    let (kind, index, vertices, planes, at) = clipped(s, 0);
    assert_eq!((kind.as_str(), index, vertices), ("line", 0, vec![0, 1]));
    assert_eq!(planes, vec![near]);
    assert!(same(at, [-0.75, 0.5, -0.75, 1.0]), "{at:?}");
    // Pixel (7, 1), step 4: the point at (1.125, 0.5, 0.5, 1) is on
    // screen at ((1 + 1.125)·4, (1 − 0.5)·2) = (8.5, 1); size 4 covers
    // centres with 6.5 ≤ x < 10.5, so (7, 1) — but its vertex lies right
    // of the view volume (x > w), and a point is drawn whole or not at
    // all by its vertex.
    let s = &both[1]["steps"][4];
    assert!(s["fragments"].as_array().unwrap().is_empty());
    let (kind, index, vertices, planes, at) = clipped(s, 0);
    assert_eq!((kind.as_str(), index, vertices), ("point", 0, vec![0]));
    assert_eq!(planes, vec!["right plane (x > w)".to_string()]);
    assert_eq!(at, [1.125, 0.5, 0.5, 1.0]);
    // The text names them too.
    let o = in_repo(&[
        "render",
        "tests/pixel_history/clipped.json",
        "--pixel",
        "1,1",
    ]);
    let text = stdout(&o);
    assert!(
        text.contains(
            "    not covered: clipped: triangle 0 lies over it beyond the near plane (z < 0)\n"
        ),
        "{text}"
    );
    assert!(
        text.contains("    clipped triangle 0 (vertices 0, 1, 2) at (-0.75, 0.5, 1.5, 1): beyond the far plane (z > w)\n"),
        "{text}"
    );
}

#[test]
fn the_other_depth_formats_store_depth_and_stencil_as_their_bits() {
    // depth_formats.json: a triangle at z = 0.375 (= 3/8) over (0, 0) of
    // each 2×2 target, func ALWAYS. D3DFORMAT: D16_LOCKABLE "a 16-bit
    // z-buffer bit depth", D15S1 "15 bits for the depth channel", D32 "a
    // 32-bit z-buffer bit depth", D24X4S4 "24 bits for the depth channel";
    // an n-bit UNORM stores round(z·(2ⁿ − 1))/(2ⁿ − 1). 0.375·(2ⁿ − 1) ends
    // in .625 for every n here, so it rounds up whatever the last bit of the
    // interpolated z: 24576/65535, 12288/32767, 1610612736/4294967295 and
    // 6291456/16777215.
    let want = [
        ("d16l", 24576.0 / 65535.0),
        ("d15s1", 12288.0 / 32767.0),
        ("d32", 1610612736.0 / 4294967295.0),
        ("d24x4s4", 6291456.0 / 16777215.0),
    ];
    let pixels: Vec<String> = want.iter().map(|(t, _)| format!("{t}:0,0")).collect();
    let refs: Vec<&str> = pixels.iter().map(String::as_str).collect();
    let h = histories("depth_formats.json", &refs);
    for ((t, z), h) in want.iter().zip(&h) {
        let d = &h["steps"][0]["fragments"][0]["depth"];
        assert_eq!(d["z"].as_f64(), Some(*z), "{t}: {d}");
        assert_eq!(d["written"], true, "{t}");
    }
    // The stencil: D3DSTENCILOP's INCRSAT clamps "to the maximum value",
    // INCR wraps "to zero if the new value exceeds the maximum value", DECR
    // "to the maximum value if the new value is less than zero"; the
    // maximum of n bits is 2ⁿ − 1, 15 in D24X4S4 and 1 in D15S1. INVERT
    // flips the n bits.
    let stencil = |target: &str| -> Vec<(u64, u64)> {
        let h = &histories("depth_formats.json", &[&format!("{target}:0,0")])[0];
        h["steps"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| {
                let st = &s["fragments"][0]["stencil"];
                (
                    st["stored"].as_u64().unwrap(),
                    st["written"].as_u64().unwrap(),
                )
            })
            .collect()
    };
    // D24X4S4: clear 14, INCRSAT → 15; INCRSAT at 15 stays 15 (8 bits
    // would give 16); clear 0, DECR → 15; INVERT of 15 (1111) → 0.
    assert_eq!(stencil("s4"), [(14, 15), (15, 15), (0, 15), (15, 0)]);
    // D15S1: clear 1, INCR → 0 (wraps past 1); INVERT of 0 → 1; INCRSAT
    // at 1 stays 1.
    assert_eq!(stencil("s1"), [(1, 0), (0, 1), (1, 1)]);
}
