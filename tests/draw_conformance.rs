//! Whole Direct3D 9 draws of geometry (tests/draw_conformance/, the
//! `geometry` field of draw lists, docs/draw.md): vertices through a vertex
//! shader or pre-transformed, clipping, the viewport, pixel centres, the
//! top-left rule, interpolation with perspective, quads at triangle edges,
//! vFace, vPos, culling, points, flat shading, the scissor, the depth
//! test and its functions, blending across the primitives of one draw, the
//! alpha test against depth, two render targets and vertex texture fetch —
//! each list drawn with `ps30 render` as a user draws it and every
//! pixel compared with a value derived here, by hand or in f64 from
//! Direct3D 9's rules (the derivation beside each case), never from ps30.
//! Targets are D3DFMT_A32B32G32R32F, read back exactly from their EXR.
//!
//! The cases follow the questions Wine's Direct3D 9 visual tests ask of a
//! driver (fill convention, pixel centres, perspective, clipping, depth,
//! vFace/vPos, point lists), with lists and expectations of their own.

use crate::common::bin::repo;
use crate::d3d9_conformance::{render_file, Targets};

pub(crate) type Rgba = [f32; 4];

pub(crate) const CLEAR: Rgba = [0.0; 4];
pub(crate) const RED: Rgba = [1.0, 0.0, 0.0, 1.0];
pub(crate) const GREEN: Rgba = [0.0, 1.0, 0.0, 1.0];
pub(crate) const BLUE: Rgba = [0.0, 0.0, 1.0, 1.0];

pub(crate) fn draw(list: &str) -> Targets {
    render_file(
        &repo().join("tests/draw_conformance").join(list),
        "emulator",
    )
    .expect("the emulator always draws")
}

/// Every pixel of target `name` against `want(x, y)`, exactly.
pub(crate) fn check(t: &Targets, name: &str, want: impl Fn(u32, u32) -> Rgba) {
    check_within(t, name, 0.0, want);
}

/// [`check`] within `tolerance` of each component.
pub(crate) fn check_within(
    t: &Targets,
    name: &str,
    tolerance: f32,
    want: impl Fn(u32, u32) -> Rgba,
) {
    let (width, pixels) = &t[name];
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        let w = want(x, y);
        let ok = (0..4).all(|c| got[c] == w[c] || (got[c] - w[c]).abs() <= tolerance);
        assert!(ok, "{name} ({x}, {y}): {got:?}, want {w:?}");
    }
}

#[test]
fn microsofts_top_left_examples_fill_15_and_10_pixels() {
    // "Rasterization Rules (Direct3D 9)": (0,0),(5,0),(5,5) covers the
    // centres with y ≤ x < 5 (its diagonal is a left edge, kept; x = 5 is
    // its right edge, dropped): 5+4+3+2+1 = 15. (0,5),(0,0),(5,5) covers
    // x < y < 5 (the diagonal is its right edge, x = 0 its left): 10.
    let t = draw("fill_rule.json");
    check(&t, "t", |x, y| match (x, y) {
        (x, y) if x < 5 && y < 5 && y <= x => RED,
        (x, y) if x < 5 && y < 5 => GREEN,
        _ => CLEAR,
    });
}

#[test]
fn pixel_centres_are_integers_and_the_viewport_maps_clip_space() {
    // Screen x = X + (1 + x)·W/2, so pixel i (centre i, no half-pixel
    // offset) sees clip x = 2(i − X)/W − 1, and y = 1 − 2(j − Y)/H. Whole
    // 8×4 target: (i/4 − 1, 1 − j/2). Viewport (2, 1, 4, 2): pixels 2–5 ×
    // 1–2 see ((i − 2)/2 − 1, 2 − j); the rest keep the clear colour. Every
    // value is a small dyadic fraction, exact in f32.
    let t = draw("pixel_centres.json");
    check(&t, "whole", |i, j| {
        [i as f32 / 4.0 - 1.0, 1.0 - j as f32 / 2.0, 0.0, 1.0]
    });
    check(&t, "viewport", |i, j| {
        if (2..6).contains(&i) && (1..3).contains(&j) {
            [(i as f32 - 2.0) / 2.0 - 1.0, 2.0 - j as f32, 0.0, 1.0]
        } else {
            CLEAR
        }
    });
}

/// The perspective triangle of `perspective.json` on screen: A = (0, 0),
/// B = (8, 0) with w = 3, C = (0, 8); texcoord0 (u, v) = (0,0), (1,0),
/// (0,1). At pixel (x, y) the screen weights are λB = x/8, λC = y/8,
/// λA = 1 − λB − λC, and with perspective u = (λB/3) / (λA + λB/3 + λC),
/// v = λC / (the same), in f64.
fn perspective(x: u32, y: u32) -> (f64, f64) {
    let (b, c) = (f64::from(x) / 8.0, f64::from(y) / 8.0);
    let a = 1.0 - b - c;
    let d = a + b / 3.0 + c;
    (b / 3.0 / d, c / d)
}

/// Whether `got` is `want` rounded to f32, allowing one ulp: ps30 computes
/// the same quotient in f64 in another order (each of its dozen operations
/// within 2^-53 relative), so the two f64 results differ by far less than
/// an f32 ulp and can round apart only when the value lies that close to
/// a rounding boundary — then by one ulp.
pub(crate) fn near(got: f32, want: f64) -> bool {
    let w = want as f32;
    got == w || (got - w).abs() <= f32::EPSILON * w.abs().max(f32::MIN_POSITIVE)
}

#[test]
fn interpolation_is_perspective_correct() {
    let t = draw("perspective.json");
    let (width, pixels) = &t["values"];
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        // Covered: x + y < 8 (the hypotenuse is a right edge).
        if x + y >= 8 {
            assert_eq!(*got, CLEAR, "({x}, {y})");
            continue;
        }
        let (u, v) = perspective(x, y);
        assert!(
            near(got[0], u) && near(got[1], v),
            "({x}, {y}): {got:?}, want ({u}, {v})"
        );
        assert_eq!((got[2], got[3]), (0.0, 1.0));
    }
    // Affine interpolation would give u = 4/8 at (4, 0); with perspective,
    // (1/6) / (1/2 + 1/6) = 0.25.
    assert_eq!(pixels[4][0], 0.25);
}

#[test]
fn gradients_at_triangle_edges_come_from_helper_pixels() {
    // The second triangle: P = (8, 0) with w = 3 and u = 1, Q = (8, 8),
    // R = (0, 8), u = 0 at both. At (x, y): λP = (8 − y)/8, λR = (8 − x)/8,
    // λQ = 1 − λP − λR, and u = (λP/3) / (λP/3 + λQ + λR) (the denominator
    // is 1 − 2λP/3 ≥ 1/3 over the grid). It covers x + y ≥ 8 (the
    // hypotenuse is its left edge). dsx and dsy are coarse: per 2×2 quad,
    // top-right − top-left and bottom-left − top-left, of values each lane
    // computed at its own centre — helper lanes outside the triangle
    // included, with the interpolation extended to them. A quad at
    // (6, 0), (4, 2), … has only its bottom-right pixel covered: its
    // differences come from three helpers. Each u is rounded to f32 (within
    // one ulp, as `near` says) and subtracted in f32: within 2 ulps of 1.
    let u = |x: u32, y: u32| {
        let (p, r) = ((8.0 - f64::from(y)) / 8.0, (8.0 - f64::from(x)) / 8.0);
        p / 3.0 / (p / 3.0 + (1.0 - p - r) + r)
    };
    let t = draw("perspective.json");
    let (width, pixels) = &t["gradients"];
    let mut helpers_read = 0;
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        if x + y < 8 {
            assert_eq!(*got, CLEAR, "({x}, {y})");
            continue;
        }
        let (qx, qy) = (x & !1, y & !1);
        let f = |x, y| u(x, y) as f32;
        let dx = f(qx + 1, qy) - f(qx, qy);
        let dy = f(qx, qy + 1) - f(qx, qy);
        let ulp = 2.0 * f32::EPSILON;
        assert!(near(got[0], u(x, y)), "({x}, {y})");
        assert!(
            (got[1] - dx).abs() <= ulp && (got[2] - dy).abs() <= ulp,
            "({x}, {y}): {got:?} want {dx}, {dy}"
        );
        if qx + qy + 1 < 8 {
            helpers_read += 1;
        }
    }
    // The quads (6,0), (4,2), (2,4), (0,6): one covered pixel each.
    assert_eq!(helpers_read, 4);
}

#[test]
fn vface_is_the_facing_and_cull_modes_drop_the_named_winding() {
    // Left square wound clockwise on screen (a front face: vFace > 0, red),
    // right square counter-clockwise (back: blue). D3DCULL_CCW drops the
    // right one, D3DCULL_CW the left.
    let t = draw("face_cull.json");
    check(&t, "none", |x, _| if x < 4 { RED } else { BLUE });
    check(&t, "ccw", |x, _| if x < 4 { RED } else { CLEAR });
    check(&t, "cw", |x, _| if x < 4 { CLEAR } else { BLUE });
}

#[test]
fn vpos_holds_integer_pixel_coordinates() {
    // The rectangle (1,1)–(7,3) covers columns 1–6 and rows 1–2 (right and
    // bottom edges dropped); ps_3_0's vPos is the pixel's integer position.
    let t = draw("vpos.json");
    check(&t, "t", |x, y| {
        if (1..7).contains(&x) && (1..3).contains(&y) {
            [x as f32, y as f32, 0.0, 1.0]
        } else {
            CLEAR
        }
    });
}

#[test]
fn clipping_against_near_far_and_user_planes() {
    // A clip-space quad over 8×4, texcoord0 = clip (x, y); pixel i is at
    // clip x = i/4 − 1. Near: z = x + 0.1 ≥ 0 keeps x ≥ −0.1, screen ≥ 3.6:
    // columns 4–7. Far: z = x + 1.1 ≤ w = 1 keeps x ≤ −0.1: columns 0–3.
    // The plane (−1, 0, 0, 0.45) keeps x ≤ 0.45, screen ≤ 5.8: columns
    // 0–5. Values are those of the unclipped quad where drawn (clipping
    // blends linearly, and the kept part interpolates as before) up to the
    // rounding of the new vertices: the blend and the barycentrics are f64
    // operations on magnitudes below 8, each within 2^-53·8 ≈ 9e-16, a few
    // dozen of them: 1e-13 bounds the sum.
    let t = draw("clipping.json");
    let value = |i: u32, j: u32| [i as f32 / 4.0 - 1.0, 1.0 - j as f32 / 2.0, 0.0, 1.0];
    let tol = 1e-13;
    check_within(
        &t,
        "near",
        tol,
        |i, j| if i >= 4 { value(i, j) } else { CLEAR },
    );
    check_within(
        &t,
        "far",
        tol,
        |i, j| if i <= 3 { value(i, j) } else { CLEAR },
    );
    check_within(
        &t,
        "plane",
        tol,
        |i, j| if i <= 5 { value(i, j) } else { CLEAR },
    );
}

#[test]
fn a_dense_grid_covers_every_pixel_once_with_borders_clipped_by_the_guard_band() {
    // grid.json: vertex (i, j) is on screen at (4i − 7.5, 4j − 7.5), so
    // cell (i, j) spans x ∈ (4i − 7.5, 4i − 3.5), y likewise; its triangles
    // are A B C (upper left, colour (i, j, 0, 1)) and B D C (lower right,
    // (i, j, 1, 1)), flat. Every screen coordinate is a small dyadic
    // number (clip position = NDC × w with w ∈ {1, 1.5, 3, 0.75}, exact).
    // No pixel centre lies on a cell's sides (they are at odd halves); the
    // diagonal B→C is u + v = 4 (u, v the centre's offsets in the cell),
    // through integer centres: it runs up in B D C (a left edge, kept)
    // and down in A B C (dropped), so u + v ≥ 4 is the lower-right
    // triangle's. The cells across the left and top borders (and the right
    // and bottom ones) are drawn whole and scissored: every one of the
    // 32×32 pixels is covered exactly once.
    let t = draw("grid.json");
    check(&t, "grid", |x, y| {
        let (sx, sy) = (f64::from(x) + 7.5, f64::from(y) + 7.5);
        let (i, j) = ((sx / 4.0).floor(), (sy / 4.0).floor());
        let (u, v) = (sx - 4.0 * i, sy - 4.0 * j);
        let lower = if u + v >= 4.0 { 1.0 } else { 0.0 };
        [i as f32, j as f32, lower, 1.0]
    });
}

#[test]
fn inputs_nothing_writes_read_direct3d_9s_defaults() {
    // Wine's test_uninitialized_varyings and vkd3d's uninitialized-varyings
    // (both recorded on Windows): behind a vs_2_0 that writes only oPos,
    // ps_2_0's colour v0 reads (1, 1, 1, 1) and t0 reads 0 (xyz; w is 0
    // or 1 by vendor, 0 here); writing only oD0.x = oT0.x = 0.5 gives
    // (0.5, 1, 1, 1) and (0.5, 0, 0, 0). ps_3_0's colour behind a vs_3_0
    // without one reads 0 (drivers disagree). Without a vertex shader a
    // vertex without color0 is white, and its texcoord0 0.
    let t = draw("unwritten.json");
    let cases: [(&str, Rgba); 7] = [
        ("color_none", [1.0; 4]),
        ("texcoord_none", [0.0; 4]),
        ("color_x", [0.5, 1.0, 1.0, 1.0]),
        ("texcoord_x", [0.5, 0.0, 0.0, 0.0]),
        ("ps3_color_none", [0.0; 4]),
        ("fixed_color", [1.0; 4]),
        ("fixed_texcoord", [0.0; 4]),
    ];
    for (name, want) in cases {
        check(&t, name, |_, _| want);
    }
}

#[test]
fn vertex_shaders_feed_the_pixel_shader_by_semantic() {
    // vs_3_0 halves x and y (c0 = (0.5, 0.5, 1, 1)): the quad covers screen
    // 2–6 on 8×8, pixels 2–5 in each direction; pixel i sees scaled clip
    // x = i/4 − 1, so texcoord0 (the unscaled position) = 2(i/4 − 1).
    let t = draw("vertex_shaders.json");
    check(&t, "vs3", |i, j| {
        if (2..6).contains(&i) && (2..6).contains(&j) {
            [i as f32 / 2.0 - 2.0, 2.0 - j as f32 / 2.0, 0.0, 1.0]
        } else {
            CLEAR
        }
    });
    // vs_2_0 oD0 → ps_2_0 v0 (color0 (0.25, 0.5, 0.75, 1)), oT0 → t0
    // (clip x = i/4 − 1 into alpha).
    check(&t, "vs2", |i, _| [0.25, 0.5, 0.75, i as f32 / 4.0 - 1.0]);
}

#[test]
fn points_are_squares_rasterised_by_the_triangle_rules() {
    // A point of size S is the square (X ± S/2, Y ± S/2). (2, 3): the
    // square 1.5–2.5 × 2.5–3.5 holds the centre (2, 3) only. (5.5, 1.5):
    // 5–6 × 1–2 holds (5, 1) on its top-left corner (kept); (6, ·) and
    // (·, 2) lie on its right and bottom edges. Size 2 at (3, 6): 2–4 × 5–7
    // holds columns 2–3, rows 5–6.
    let t = draw("points.json");
    check(&t, "points", |x, y| match (x, y) {
        (2, 3) => RED,
        (5, 1) => GREEN,
        (2..=3, 5..=6) => BLUE,
        _ => CLEAR,
    });
}

#[test]
fn an_indexed_fan_with_flat_shading_and_a_scissor() {
    // Indices [2, 0, 3, 1] draw v0 (0,0) red, v1 (8,0) green, v2 (8,8)
    // blue, v3 (0,8) yellow as a fan: (v0, v1, v2) covers y ≤ x (its
    // diagonal a left edge) and flat-shades with v1, green; (v0, v2, v3)
    // covers y > x, with v2, blue.
    let t = draw("fan_scissor.json");
    check(&t, "fan", |x, y| if y <= x { GREEN } else { BLUE });
    // The scissor RECT (2, 1, 5, 3): columns 2–4, rows 1–2.
    check(&t, "scissor", |i, j| {
        if (2..5).contains(&i) && (1..3).contains(&j) {
            [i as f32 / 4.0 - 1.0, 1.0 - j as f32 / 2.0, 0.0, 1.0]
        } else {
            CLEAR
        }
    });
}

#[test]
fn depth_tests_formats_and_odepth() {
    let t = draw("depth.json");
    // LESSEQUAL: red at 0.5, green at 0.7 fails, blue at 0.3 over the left
    // half passes.
    check(&t, "order", |x, _| if x < 2 { BLUE } else { RED });
    // Cleared to 0: red at 0.5 under the default LESSEQUAL fails (0.5 > 0);
    // green at 0.7 under GREATER passes and writes 0.7; blue at 0.9 over
    // the top half passes with writes off; red at 0.8 passes where 0.7 is
    // stored — everywhere, which it would not over the top half had the
    // blue draw written 0.9.
    check(&t, "greater", |_, _| RED);
    // D16 stores 0.5 and 0.500005 both as code 32768 (0.5·65535 = 32767.5
    // and 0.500005·65535 = 32767.83 round to it): LESSEQUAL passes, green.
    check(&t, "d16", |_, _| GREEN);
    // D24 stores 8388608 and 8388691: 0.500005 is behind, red stays.
    check(&t, "d24", |_, _| RED);
    // oDepth replaces the interpolated depth: 0.25 < 0.5 on the left
    // (drawn at z 0.9), 0.75 on the right fails (drawn at z 0.1).
    check(&t, "odepth", |x, _| if x < 2 { GREEN } else { RED });
}

#[test]
fn divergent_gradients_are_reported_on_geometry_draws() {
    // texcoord0.x at column i is 1.1·i/8 (w = 1, u from 0 to 1.1 over 8
    // pixels): 0.275 at column 2, 0.4125 at column 3, so `if_lt v0.x, 0.3`
    // splits every quad of columns 2–3 the triangle reaches — rows 0–5
    // (x + y < 8 with x = 2 or 3), three quads — and `dsx` of a temporary
    // inside it reads a neighbour that did not run it.
    let path = repo().join("tests/draw_conformance/divergent.json");
    let o = crate::common::bin::ps30(&["render", path.to_str().unwrap()], repo());
    assert_eq!(o.status.code(), Some(0));
    let err = crate::common::bin::stderr(&o);
    assert!(err.contains("`dsx` ran in divergent quads"), "{err}");
    assert!(
        err.contains("3 of 7 quads ran it with only part of their pixels"),
        "{err}"
    );
}

#[test]
fn bad_geometry_is_refused_with_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let shader = repo().join("tests/draw_conformance/texcoord.psh");
    let run = |geometry: &str| {
        let list = format!(
            r#"{{"targets": [{{"name": "t", "size": "4x4", "format": "A8R8G8B8"}}],
                "steps": [{{"draw": "t", "shader": {shader:?}, "geometry": {geometry}}}]}}"#
        );
        let path = dir.path().join("list.json");
        std::fs::write(&path, list).unwrap();
        let o = crate::common::bin::ps30(&["render", path.to_str().unwrap()], repo());
        assert_eq!(o.status.code(), Some(2), "{geometry}");
        crate::common::bin::stderr(&o)
    };
    let verts = r#"{"attributes": {"positiont0": [[0, 0, 0, 1], [4, 0, 0, 1], [0, 4, 0, 1]]}}"#;
    for (geometry, want) in [
        (
            format!(r#"{{"primitive": "line_loop", "vertices": {verts}}}"#),
            "steps[0].geometry.primitive: `line_loop` is not one of",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "indices": [0, 1, 3], "vertices": {verts}}}"#),
            "steps[0].geometry.indices[2]: 3 is past the last of 3 vertices",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "vertices": {verts}, "viewport": {{"x": 2, "y": 0, "width": 4, "height": 4}}}}"#),
            "steps[0].geometry.viewport: the rectangle must lie within the 4x4 target",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "vertices": {verts}, "depth": {{"format": "D24FS8"}}}}"#),
            "steps[0].geometry.depth.format: `D24FS8` is not one of D16, D16_LOCKABLE, D15S1, D24X8, D24S8, D24X4S4, D32, D32F_LOCKABLE",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "vertices": {verts}, "vertex_samplers": {{"s4": {{"texture": "t"}}}}}}"#),
            "steps[0].geometry.vertex_samplers.s4:",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "vertices": {verts}, "vertex_samplers": {{"s0": {{"texture": "t"}}}}}}"#),
            "steps[0].geometry.vertex_samplers.s0.texture: `t` is the target this draw renders to",
        ),
        (
            r#"{"primitive": "triangle_strip", "vertices": "missing.json"}"#.to_string(),
            "steps[0].geometry.vertices:",
        ),
        (
            format!(r#"{{"primitive": "triangle_list", "vertices": {verts}, "vertex_shader": {shader:?}}}"#),
            "steps[0].geometry.vertex_shader: a ps_3_0 shader; the vertex stage runs",
        ),
    ] {
        let err = run(&geometry);
        assert!(err.contains(want), "{geometry}: {err}");
    }
}

#[test]
fn overlapping_triangles_of_one_draw_blend_in_draw_order() {
    // Three full-height quads in one triangle list, blended ONE/ONE: every
    // pixel is the sum of all that cover it (D3D9 blends each primitive
    // over what the earlier ones left). Columns 0–1 take (0.25, 0.5, 0,
    // 0.5) + (0.5, 0.25, 0.125, 0.25) + (0.125, 0, 0.5, 0) = (0.875, 0.75,
    // 0.625, 0.75); columns 2–3 the first two: (0.75, 0.75, 0.125, 0.75).
    // Had a later triangle replaced the earlier one, or been blended with
    // the target as it stood before the draw, a single quad's colour (or
    // the last two's sum) would show. Every sum is of dyadic fractions:
    // exact in f32.
    let t = draw("blend.json");
    check(&t, "add", |x, _| {
        if x < 2 {
            [0.875, 0.75, 0.625, 0.75]
        } else {
            [0.75, 0.75, 0.125, 0.75]
        }
    });
    // SRCALPHA/INVSRCALPHA over a clear to blue (0, 0, 1, 1), alpha
    // blended by the same factors (no separate alpha): red at alpha 0.5
    // everywhere gives 0.5·(1, 0, 0, 0.5) + 0.5·(0, 0, 1, 1) = (0.5, 0,
    // 0.5, 0.75); then green at alpha 0.25 over columns 0–1 gives
    // 0.25·(0, 1, 0, 0.25) + 0.75·(0.5, 0, 0.5, 0.75) = (0.375, 0.25,
    // 0.375, 0.625). The other order would give (0.5, 0.125, 0.375,
    // 0.65625) there. Exact in f32 (dyadic, few bits).
    check(&t, "over", |x, _| {
        if x < 2 {
            [0.375, 0.25, 0.375, 0.625]
        } else {
            [0.5, 0.0, 0.5, 0.75]
        }
    });
}

#[test]
fn a_pixel_failing_the_alpha_test_writes_no_depth() {
    // Draw 1 (z 0.25, ALPHAFUNC GREATEREQUAL, ALPHAREF 128): red with
    // alpha 0 (0 < 128/255 on this float target: discarded) over columns
    // 0–1, alpha 1 (kept) over columns 2–3. Draw 2 (z 0.5, LESSEQUAL, no alpha
    // test): green everywhere. Where the alpha test discarded, the depth
    // is still the clear's 1 and 0.5 passes; where red was drawn, 0.25 is
    // stored and 0.5 fails.
    let t = draw("alpha_depth.json");
    check(&t, "t", |x, _| if x < 2 { GREEN } else { RED });
}

#[test]
fn two_targets_take_oc0_and_oc1_and_share_the_alpha_test() {
    // The triangle (0,0), (4,0), (0,4) covers the centres with x + y < 4
    // (the hypotenuse is a right edge). oC0 = texcoord0, red at every
    // vertex; oC1 = texcoord1, (0,0,0,1), (1,0,0,1), (0,1,0,1) at the
    // corners, so (x/4, y/4, 0, 1) at pixel (x, y) (w = 1: the
    // interpolation is affine; quarters are exact in f32). Neither target
    // is touched outside the triangle.
    let t = draw("mrt.json");
    check(&t, "c0", |x, y| if x + y < 4 { RED } else { CLEAR });
    check(&t, "c1", |x, y| {
        if x + y < 4 {
            [x as f32 / 4.0, y as f32 / 4.0, 0.0, 1.0]
        } else {
            CLEAR
        }
    });
    // The alpha test reads oC0's alpha and discards the pixel in every
    // target: two quads, oC0 red with alpha 0 (0 < ALPHAREF 128/255:
    // discarded) over columns 0–1 and alpha 1 (kept) over columns 2–3,
    // oC1 blue throughout. Only columns 2–3 are written, in both targets.
    check(&t, "a0", |x, _| if x < 2 { CLEAR } else { RED });
    check(&t, "a1", |x, _| if x < 2 { CLEAR } else { BLUE });
}

#[test]
fn depth_functions_at_equal_and_nearly_equal_depths() {
    // Each 2×2 target: red drawn first with ZFUNC ALWAYS (its depth
    // written), then green with the named function. At equal depth (0.5
    // in D24S8, 0.3 in D32F) LESS, NOTEQUAL and NEVER fail (red stays);
    // LESSEQUAL, EQUAL and GREATEREQUAL pass (green). NEVER fails even for
    // the nearer 0.25. GREATER with 0.500005 over 0.5: D16 rounds both to
    // code 32768 (0.5·65535 = 32767.5 and 0.500005·65535 = 32767.83, to
    // nearest), equal, so it fails; D24 stores 8388608 and 8388691
    // (0.5·16777215 = 8388607.5, 0.500005·16777215 = 8388691.4), behind,
    // so it passes.
    let t = draw("depth_funcs.json");
    for (name, want) in [
        ("less", RED),
        ("lessequal", GREEN),
        ("equal", GREEN),
        ("notequal", RED),
        ("greater_d16", RED),
        ("greater_d24", GREEN),
        ("never", RED),
        ("greaterequal", GREEN),
    ] {
        check(&t, name, |_, _| want);
    }
}

#[test]
fn vertex_texture_fetch_moves_and_colours_vertices() {
    // The 2×1 target `texels` is drawn first with texcoord0 = (1, 0, 0, 0)
    // + x·(−1, 1, 0, 0.5): texel 0 (1, 0, 0, 0), texel 1 (0, 1, 0, 0.5).
    // fetch.vsh reads s0 with texldl at texcoord0 (point filtering, LOD 0)
    // and adds the texel's alpha to clip x. Quad A (clip x −1…0) reads
    // u = 0.25, texel 0: alpha 0, so it stays on columns 0–3 and carries
    // (1, 0, 0, 0). Quad B (clip x 0…0.5) reads u = 0.75, texel 1: moved by
    // 0.5 to clip 0.5…1, screen 6–8, columns 6–7, with (0, 1, 0, 0.5);
    // columns 4–5 stay clear (green, had the texel's alpha not moved it;
    // red, had it read texel 0). All values exact in f32.
    let t = draw("vertex_fetch.json");
    check(&t, "t", |x, _| match x {
        0..=3 => [1.0, 0.0, 0.0, 0.0],
        6..=7 => [0.0, 1.0, 0.0, 0.5],
        _ => CLEAR,
    });
}

#[test]
fn depth_is_interpolated_linearly_on_screen() {
    // The first strip runs from z 0 (x = 0, 1/w = 1) to z 1 (x = 8,
    // 1/w = 0.25) and is written whole (D32F, cleared to 1): Direct3D 9
    // interpolates z (z/w after the divide) linearly in screen space, so
    // column x stores x/8. The second, flat at 0.4375 = 3.5/8 under LESS,
    // passes where 3.5/8 < x/8: columns 4–7. Interpolated with perspective
    // instead, z at column x would be (λ·0.25)/((1 − λ) + λ·0.25) with
    // λ = x/8: 0.2, 0.294, 0.429 at columns 4–6 (all below 0.4375) and
    // 0.636 at column 7, so columns 4–6 would stay red.
    let t = draw("depth_ramp.json");
    check(&t, "t", |x, _| if x >= 4 { GREEN } else { RED });
}

/// The bytes of `vertex_buffers.vb`, built here from the values the list's
/// declarations say they hold (little-endian, as Direct3D 9's buffers).
fn vertex_buffer_bytes() -> Vec<u8> {
    let corners = [
        (-1i16, 1i16, 0i16, 0i16),
        (1, 1, 8, 0),
        (-1, -1, 0, 8),
        (1, -1, 8, 8),
    ];
    let mut b = Vec::new();
    // Draw 1, stride 24: SHORT4N position (x·32767, y·32767, 0, 32767),
    // D3DCOLOR 0x80FF4000, FLOAT16_4 (0x3800, 0xC000, 0x0001, 0x7BFF),
    // SHORT2 (u, v).
    for (x, y, u, v) in corners {
        for s in [x * 32767, y * 32767, 0, 32767] {
            b.extend(s.to_le_bytes());
        }
        b.extend(0x80FF_4000u32.to_le_bytes());
        for h in [0x3800u16, 0xC000, 0x0001, 0x7BFF] {
            b.extend(h.to_le_bytes());
        }
        b.extend(u.to_le_bytes());
        b.extend(v.to_le_bytes());
    }
    // Draw 2 at byte 96, stride 28: FLOAT2 position, SHORT2N (32767,
    // −32768), DEC3N 0x3FF801FF (x 0x1FF, y 0x200, z 0x3FF), USHORT4N
    // (65535, 0, 1, 32768), UBYTE4N bytes (0, 64, 255, 128).
    for (x, y, _, _) in corners {
        b.extend(f32::from(x).to_le_bytes());
        b.extend(f32::from(y).to_le_bytes());
        b.extend(32767i16.to_le_bytes());
        b.extend((-32768i16).to_le_bytes());
        b.extend(0x3FF8_01FFu32.to_le_bytes());
        for s in [65535u16, 0, 1, 32768] {
            b.extend(s.to_le_bytes());
        }
        b.extend([0u8, 64, 255, 128]);
    }
    b
}

#[test]
fn vertex_buffers_of_every_kind_reach_the_shaders_decoded_by_type() {
    // D3DDECLTYPE's rules (Microsoft's page; core/decltype.rs cites them),
    // applied here by hand. Both draws cover the 8×8 target (clip −1…1, a
    // strip of two triangles, top-left rule: all 64 centres).
    let file = repo().join("tests/draw_conformance/vertex_buffers.vb");
    assert_eq!(std::fs::read(file).unwrap(), vertex_buffer_bytes());
    let t = draw("vertex_buffers.json");
    // Draw 1, through decl.vsh (vs_3_0, every input moved to an output):
    // SHORT4N ±32767/32767 = ±1 places the corners; D3DCOLOR 0x80FF4000
    // reads (R, G, B, A) = (255, 64, 0, 128)/255; the halves are 0.5, −2,
    // 2⁻²⁴ (the smallest subnormal half, a normal f32) and 65504 (the
    // largest half); UDEC3 0x200003FF from the inline stream is x 0x3FF,
    // y 0, z 0x200: (1023, 0, 512, 1). Constant across the vertices, each
    // interpolates to itself (the f64 weighted mean of one f32 value rounds
    // back to it). SHORT2 (u, v) runs from 0 to 8 across the target: pixel
    // (i, j) at screen (i, j) has weights i/8, j/8, so (i, j, 0, 1), exact.
    check(&t, "d0", |_, _| [1.0, 64.0 / 255.0, 0.0, 128.0 / 255.0]);
    check(&t, "d1", |_, _| [0.5, -2.0, f32::powi(2.0, -24), 65504.0]);
    check(&t, "d2", |_, _| [1023.0, 0.0, 512.0, 1.0]);
    check(&t, "d3", |i, j| [i as f32, j as f32, 0.0, 1.0]);
    // Draw 2, no vertex shader (FLOAT2 position0 as clip space, filled to
    // (x, y, 0, 1)), read from byte 96 of the same file with its count
    // derived: (208 − 96 − 28)/28 + 1 = 4. UBYTE4N bytes (0, 64, 255, 128)
    // in memory order: (0, 64, 255, 128)/255. SHORT2N (32767, −32768):
    // 32767/32767 = 1 and −32768/32767, Direct3D 9's unclamped rule, which
    // rounds to −(1 + 2⁻¹⁵) (core/decltype's tests derive it). DEC3N x 511,
    // y −512, z −1 over 511: (1, −512/511, −1/511, 1). USHORT4N over 65535:
    // (1, 0, 1/65535, 32768/65535).
    check(&t, "n0", |_, _| [0.0, 64.0 / 255.0, 1.0, 128.0 / 255.0]);
    check(&t, "n1", |_, _| {
        [1.0, -(1.0 + f32::powi(2.0, -15)), 0.0, 1.0]
    });
    check(&t, "n2", |_, _| [1.0, -512.0 / 511.0, -1.0 / 511.0, 1.0]);
    check(&t, "n3", |_, _| {
        [1.0, 0.0, 1.0 / 65535.0, 32768.0 / 65535.0]
    });
}
