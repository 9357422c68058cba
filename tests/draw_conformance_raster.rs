//! Whole draws of lines, sized points and point sprites, fill modes and the
//! stencil test (tests/draw_conformance/, docs/draw.md), in the manner of
//! `draw_conformance.rs`: each list drawn with `ps30 render` and every
//! pixel compared with a value derived here — by hand from Direct3D 9's
//! rules (cited beside each case) or in f64 — never from ps30.

use crate::draw_conformance::{check, draw, near, Rgba, CLEAR, GREEN, RED};

#[test]
fn lines_follow_the_diamond_exit_rule_and_lastpixel() {
    // "Rasterization Rules (Direct3D 9)": lines that are not antialiased
    // follow GDI's rule, the diamond-exit rule (Direct3D 10's "Rasterization
    // Rules" spell it out): a line covers a pixel when it leaves the
    // diamond |dx| + |dy| < ½ round the pixel's centre; D3DRS_LASTPIXEL
    // (TRUE by default) adds the pixel whose diamond holds the end.
    let t = draw("lines.json");
    // "h": (1,1)→(6,1) along row 1 through centres. It leaves the diamonds
    // of columns 1–5 by their right corners (outside for an x-major line);
    // column 6 holds its end: drawn with LASTPIXEL (row 1), not without
    // (row 3, the same line). u runs 0 → 1 with t = (x − 1)/5 (w = 1 at
    // both ends, so perspective changes nothing: one ulp as `near` allows).
    let (width, pixels) = &t["h"];
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        let last = if y == 1 { 6 } else { 5 };
        if (y == 1 || y == 3) && (1..=last).contains(&x) {
            let u = f64::from(x - 1) / 5.0;
            assert!(near(got[0], u), "h ({x}, {y}): {got:?} want u {u}");
            assert_eq!((got[1], got[2], got[3]), (0.0, 0.0, 1.0), "h ({x}, {y})");
        } else {
            assert_eq!(*got, CLEAR, "h ({x}, {y})");
        }
    }
    // "diag": (1,1)→(7,4), x-major with slope ½, red. At x = 2, 4, 6 it
    // crosses y = 1.5, 2.5, 3.5: the bottom corner of the pixel above
    // (inside for an x-major line: it touches, then leaves — drawn) and the
    // top corner of the pixel below (outside: never entered). So (1,1),
    // (2,1), (3,2), (4,2), (5,3), (6,3) and the last pixel (7,4).
    // (9,1)→(12,7), y-major with dx/dy = ½, green: at y = 2, 4, 6 it
    // crosses x = 9.5, 10.5, 11.5, the right corner of the pixel on the
    // left (inside for a y-major line) and the left corner of the one on
    // the right (outside): (9,1), (9,2), (10,3), (10,4), (11,5), (11,6),
    // last (12,7).
    let red = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4)];
    let green = [(9, 1), (9, 2), (10, 3), (10, 4), (11, 5), (11, 6), (12, 7)];
    check(&t, "diag", |x, y| {
        if red.contains(&(x, y)) {
            RED
        } else if green.contains(&(x, y)) {
            GREEN
        } else {
            CLEAR
        }
    });
    // "strip": two strips of two lines each, blended ONE/ONE with
    // (¼, 0, 0, ¼) so a pixel shows how many times it was drawn. Without
    // LASTPIXEL, (1,1)→(4,1)→(4,4): the first line draws columns 1–3 and
    // leaves (4,1), its end, to the second, which leaves (4,1) through its
    // bottom corner (inside: it was in the diamond) — every pixel once:
    // (1..=3, 1), (4, 1..=3). With LASTPIXEL, (9,1)→(12,1)→(12,4): (12,1)
    // is the first line's last pixel and the second's first, drawn twice
    // (½); (12,4) is the second's last pixel.
    let once = [0.25, 0.0, 0.0, 0.25];
    let twice = [0.5, 0.0, 0.0, 0.5];
    check(&t, "strip", |x, y| match (x, y) {
        (1..=3, 1) | (4, 1..=3) => once,
        (9..=11, 1) | (12, 2..=4) => once,
        (12, 1) => twice,
        _ => CLEAR,
    });
}

/// The pixels of `lines_vpos.json`'s three lines, each holding its own
/// position (vpos.psh: oC0 = (vPos.x, vPos.y, 0, 1)), by the diamond-exit
/// rule as derived for "diag" above: (1,1)→(7,4) covers (1,1), (2,1),
/// (3,2), (4,2), (5,3), (6,3) and its last pixel (7,4); (9,1)→(12,7)
/// covers (9,1), (9,2), (10,3), (10,4), (11,5), (11,6), (12,7); and
/// (1,6)→(6,6), along row 6 through centres as "h" is, columns 1–6 (6 its
/// last pixel).
pub(crate) fn lines_vpos_want(x: u32, y: u32) -> Rgba {
    let first = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4)];
    let second = [(9, 1), (9, 2), (10, 3), (10, 4), (11, 5), (11, 6), (12, 7)];
    let third = (y == 6 && (1..=6).contains(&x)).then_some((x, y));
    match first.contains(&(x, y)) || second.contains(&(x, y)) || third.is_some() {
        true => [x as f32, y as f32, 0.0, 1.0],
        false => CLEAR,
    }
}

#[test]
fn lines_report_their_own_position_in_vpos() {
    let t = draw("lines_vpos.json");
    check(&t, "t", lines_vpos_want);
}

#[test]
fn values_along_a_line_are_perspective_correct() {
    // Clip-space A = (−1, ½, ½, 1) and B = (2.25, 1.5, 1.5, 3) on an 8×8
    // viewport: screen x = (1 + x/w)·4 gives 0 and 7, y = (1 − y/w)·4 gives
    // 2 for both; z/w = ½ at both, inside the view volume. Row 2, columns
    // 0–7 (7 is the last pixel). At column x, t = x/7 along the major axis,
    // and u = (t/3) / ((1 − t) + t/3) with perspective (affine would give
    // t). Alpha is w = 1 at both ends: exactly 1.
    let t = draw("lines.json");
    let (width, pixels) = &t["persp"];
    for (i, got) in pixels.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        if y != 2 {
            assert_eq!(*got, CLEAR, "persp ({x}, {y})");
            continue;
        }
        let t = f64::from(x) / 7.0;
        let u = (t / 3.0) / ((1.0 - t) + t / 3.0);
        assert!(near(got[0], u), "persp ({x}, {y}): {got:?} want {u}");
        assert_eq!(got[3], 1.0);
    }
    // Halfway along the screen (t = ½ would be column 3.5) the affine value
    // would be ½; at column 7·¾ ≈ 5 perspective gives far less: u(5) =
    // (5/21) / (2/7 + 5/21) = 5/11.
    assert!(near(pixels[2 * 8 + 5][0], 5.0 / 11.0));
}

const BLUE: Rgba = [0.0, 0.0, 1.0, 1.0];

#[test]
fn point_sizes_come_from_the_vertex_clamped_and_scaled() {
    // "Point Sprites (Direct3D 9)": a point is the square (X ± S/2, Y ± S/2)
    // rasterised by the triangle rules (centres on its left and top edges
    // kept, on its right and bottom edges dropped); S is the vertex's own
    // size if it has one, else D3DRS_POINTSIZE, clamped to
    // [D3DRS_POINTSIZE_MIN, D3DRS_POINTSIZE_MAX] (1 and, here, 4).
    let t = draw("point_sizes.json");
    // "sizes", through psize.vsh (vs_3_0 writing dcl_psize o2): size 3 at
    // (4, 4) → (2.5, 5.5)², centres 3–5 (red); size 100 at (11, 4) →
    // clamped to 4: (9, 13) × (2, 6), centres 9–12 × 2–5 (green); size ½ at
    // (4, 11) → clamped to 1: (3.5, 4.5)², the one centre (4, 11) (blue).
    check(&t, "sizes", |x, y| match (x, y) {
        (3..=5, 3..=5) => RED,
        (9..=12, 2..=5) => GREEN,
        (4, 11) => BLUE,
        _ => CLEAR,
    });
    // "ff": no vertex shader, the vertex's psize0 (D3DDECLUSAGE_PSIZE) 2 at
    // (3, 3): (2, 4)², centres 2–3.
    check(&t, "ff", |x, y| match (x, y) {
        (2..=3, 2..=3) => RED,
        _ => CLEAR,
    });
    // "scale": D3DRS_POINTSCALEENABLE with A = B = 0, C = 64 on the
    // fixed-function vertex (0, 0, ½): De = ½, Ss = Vh·Si·√(1/(C·De²)) =
    // 16·1·√(1/16) = 4, about screen (8, 8): centres 6–9.
    check(&t, "scale", |x, y| match (x, y) {
        (6..=9, 6..=9) => GREEN,
        _ => CLEAR,
    });
}

#[test]
fn point_sprites_replace_texture_coordinates_across_the_point() {
    // D3DRS_POINTSPRITEENABLE: the texture spans the point, (0, 0) at its
    // top-left corner and (1, 1) at its bottom-right, the third and fourth
    // components 0 and 1. Size 4 at (12, 12): corners 10 and 14, centres
    // 10–13, u = (x − 10)/4 and v = (y − 10)/4 — quarters, exact. The same
    // point at (4, 4) without sprites keeps the vertex's (½, ½, ½, ½)
    // everywhere.
    let t = draw("point_sizes.json");
    check(&t, "sprite", |x, y| match (x, y) {
        (10..=13, 10..=13) => [(x as f32 - 10.0) / 4.0, (y as f32 - 10.0) / 4.0, 0.0, 1.0],
        (2..=5, 2..=5) => [0.5; 4],
        _ => CLEAR,
    });
}

#[test]
fn fill_modes_draw_edges_as_lines_and_vertices_as_points() {
    // D3DRS_FILLMODE on the triangle (1,1), (6,1), (1,6). Wireframe (red):
    // its three edges as lines, each with its last pixel (D3DRS_LASTPIXEL
    // is TRUE): (1,1)→(6,1) row 1, columns 1–6; (6,1)→(1,6) through the
    // centres (6−k, 1+k), leaving each diamond by a lower-left edge, its
    // end (1,6) the last pixel; (1,6)→(1,1) up column 1. Point (green, the
    // same triangle 8 columns right): its vertices as 1-pixel points,
    // (9,1), (14,1), (9,6).
    let t = draw("point_sizes.json");
    check(&t, "fill", |x, y| {
        let edge = (y == 1 && (1..=6).contains(&x))
            || (x + y == 7 && (1..=6).contains(&x))
            || (x == 1 && (1..=6).contains(&y));
        if edge {
            RED
        } else if [(9, 1), (14, 1), (9, 6)].contains(&(x, y)) {
            GREEN
        } else {
            CLEAR
        }
    });
}

#[test]
fn point_fill_draws_the_clipped_polygons_vertices_as_points() {
    // D3DFILL_POINT: each triangle's vertices as points (point_size 2: the
    // square (X ± 1, Y ± 1), whose top-left rule covers centres X − 1 and
    // X, Y − 1 and Y), after culling and clipping. "pre": the clockwise
    // (1,1), (6,1), (1,5) with texcoords (1,0,0,1), (0,1,0,1), (0,0,1,1);
    // the counter-clockwise (9,1), (9,5), (14,1) is culled (D3DCULL_CCW)
    // and draws nothing.
    let t = draw("fill_points.json");
    let at =
        |x: u32, y: u32, cx: u32, cy: u32| (cx - 1..=cx).contains(&x) && (cy - 1..=cy).contains(&y);
    check(&t, "pre", |x, y| {
        if at(x, y, 1, 1) {
            [1.0, 0.0, 0.0, 1.0]
        } else if at(x, y, 6, 1) {
            [0.0, 1.0, 0.0, 1.0]
        } else if at(x, y, 1, 5) {
            [0.0, 0.0, 1.0, 1.0]
        } else {
            CLEAR
        }
    });
    // "clip": clip-space A (−0.75, −0.5, 0.5, 1), C (−0.75, 1, 0.5, 1),
    // B (1.5, −1, 1, 2) on a 16×8 viewport: on screen A (2, 6), C (2, 0),
    // B (14, 6), clockwise. The plane −x + 0.25·w ≥ 0 is 1 at A and C and
    // −1 at B, so it cuts A–B and C–B at their midpoints in clip space:
    // (0.375, −0.75, 0.75, 1.5) → screen (10, 6), texcoord (0.5, 0, 0.5, 1);
    // (0.375, 0, 0.75, 1.5) → (10, 4), texcoord (0, 0.5, 0.5, 1). Four
    // points, A's and C's whole (C's square loses its row −1 to the target's
    // edge only: a point is kept or dropped by its centre, never cut).
    check(&t, "clip", |x, y| {
        if at(x, y, 2, 6) {
            [1.0, 0.0, 0.0, 1.0]
        } else if at(x, y + 1, 2, 1) {
            [0.0, 1.0, 0.0, 1.0]
        } else if at(x, y, 10, 6) {
            [0.5, 0.0, 0.5, 1.0]
        } else if at(x, y, 10, 4) {
            [0.0, 0.5, 0.5, 1.0]
        } else {
            CLEAR
        }
    });
}

#[test]
fn every_stencil_op_from_five_from_255_and_from_0() {
    // D3DSTENCILOP with the reference 7 on stored 5 (rows 0–1), 255 (rows
    // 2–3, written by REPLACE) and 0 (rows 4–5), one op per column, applied
    // as the pass operation of an ALWAYS test; then, for each value v a
    // pixel can hold, a draw with STENCILFUNC EQUAL and reference v writes
    // (v, 0, 0, 1), so every pixel shows its stored value. KEEP keeps;
    // ZERO 0; REPLACE 7; INCRSAT 6, 255 (clamped), 1; DECRSAT 4, 254, 0
    // (clamped); INVERT 250, 0, 255; INCR 6, 0 (wrapped), 1; DECR 4, 254,
    // 255 (wrapped).
    let want: [[f32; 8]; 3] = [
        [5.0, 0.0, 7.0, 6.0, 4.0, 250.0, 6.0, 4.0],
        [255.0, 0.0, 7.0, 255.0, 254.0, 0.0, 0.0, 254.0],
        [0.0, 0.0, 7.0, 1.0, 0.0, 255.0, 1.0, 255.0],
    ];
    let t = draw("stencil.json");
    check(&t, "ops", |x, y| {
        [want[y as usize / 2][x as usize], 0.0, 0.0, 1.0]
    });
}

#[test]
fn stencil_function_masks_depth_fail_two_sides_and_the_alpha_test() {
    // Stored 5 everywhere; fail DECR, z-fail INVERT, pass INCR unless said:
    // 0: LESS with reference 3 — "(StencilRef & StencilMask) CompFunc
    //    (StencilBufferValue & StencilMask)", 3 < 5 passes: 6.
    // 1: GREATER with 3: 3 > 5 fails: 4.
    // 2: EQUAL with 21 and mask 15: 21 & 15 = 5 = 5 & 15, passes: 6.
    // 3: REPLACE 250 through write mask 15: (5 & ~15) | (250 & 15) = 10.
    // 4: depth 0.75 LESS the cleared 0.5 fails, the stencil passed: 250.
    // 5: depth 0.25 passes: 6.
    // 6: two-sided, D3DRS_CCW_STENCILPASS ZERO: row 0 drawn
    //    counter-clockwise (ZERO: 0), row 1 clockwise (INCR: 6).
    // 7: the alpha test (GREATER 0) drops alpha 0 before the stencil test:
    //    5 stays.
    let want = [6.0, 4.0, 6.0, 10.0, 250.0, 6.0, 0.0, 5.0];
    let t = draw("stencil.json");
    check(&t, "tests", |x, y| {
        let v = if x == 6 && y == 1 {
            6.0
        } else {
            want[x as usize]
        };
        [v, 0.0, 0.0, 1.0]
    });
}

#[test]
fn a_d3dcolor_vertex_reaches_the_shader_as_rgba() {
    // D3DDECLTYPE_D3DCOLOR: the packed ARGB DWORD 0x80FF4000 is "expanded
    // to (R, G, B, A)": (255, 64, 0, 128) / 255. Every vertex has the same
    // colour, so interpolation returns it: the f64 weighted mean of one f32
    // value rounds back to that value.
    let t = draw("d3dcolor.json");
    check(&t, "t", |_, _| [1.0, 64.0 / 255.0, 0.0, 128.0 / 255.0]);
}

#[test]
fn fog_blends_the_colour_after_a_ps_2_0_shader() {
    // A white quad over 8×2 whose depth runs from 0 at x = 0 to 1 at x = 8
    // (pre-transformed z, linear on screen): pixel x has d = x/8. Fog
    // colour blue; "Fog Blending": C = f·white + (1 − f)·blue, alpha kept.
    // Linear table fog, start 0, end 1: f = 1 − x/8 (dyadic, exact). EXP
    // with density 2: f = e^(−2x/8), in f64. Vertex fog from the specular
    // (color1) alpha, 1 at the left and 0 at the right: the same 1 − x/8,
    // interpolated (w = 1 everywhere). ps_3_0 has no fixed-function fog:
    // white.
    let t = draw("fog.json");
    let fogged = |f: f64| [f as f32, f as f32, 1.0, 1.0];
    let linear = |x: u32, _| fogged(1.0 - f64::from(x) / 8.0);
    check(&t, "linear", linear);
    check(&t, "vertex", linear);
    check(&t, "ps3", |_, _| [1.0; 4]);
    // The same linear table fog after a ps_2_0 shader that writes oDepth
    // (t0.x = 0.25): fog reads the interpolated z ("Pixel Fog" computes
    // it from the rasterised depth), so the colour is linear's, while the
    // depth surface holds oDepth.
    check(&draw("fog_odepth.json"), "t", linear);
    let (width, pixels) = &t["exp"];
    for (i, got) in pixels.iter().enumerate() {
        let x = i as u32 % width;
        let f = (-2.0 * f64::from(x) / 8.0).exp();
        assert!(
            near(got[0], f) && near(got[1], f),
            "exp ({x}): {got:?} want {f}"
        );
        assert_eq!((got[2], got[3]), (1.0, 1.0));
    }
}

/// The spacing of f32 values at `x` (one ulp).
fn ulp(x: f64) -> f64 {
    let f = x.abs() as f32;
    f64::from(f32::from_bits(f.to_bits() + 1) - f)
}

#[test]
fn table_fog_from_w_and_vertex_fog_from_a_shaders_specular_alpha() {
    // "w": table fog from eye-relative depth ("Eye-Relative vs. Z-Based
    // Depth": used when the projection matrix's fourth column is not
    // [0, 0, 0, 1]; the list says so with "depth": "w"). A strip over 8×2
    // whose clip w is 1 at the left edge and 3 at the right: 1/w is linear
    // on screen, so at pixel x (screen weight t = x/8) w = 1/(1 − 2t/3) =
    // 12/(12 − x). Linear fog from 0 to 4: f = 1 − w/4, fog colour blue over
    // white: (f, f, 1, 1). w = 1, 1.5, 2 at x = 0, 4, 6 (exact). Elsewhere
    // w reaches the fog stage rounded to f32 (interpolated values are
    // f32): |Δw| ≤ ulp(w)/2, so |Δf| ≤ ulp(w)/8, and f is rounded to f32
    // once more, ½ ulp(f).
    let t = draw("fog_w.json");
    let (width, pixels) = &t["w"];
    for (i, got) in pixels.iter().enumerate() {
        let x = f64::from(i as u32 % width);
        let w = 12.0 / (12.0 - x);
        let f = 1.0 - w / 4.0;
        let bound = if [0.0, 4.0, 6.0].contains(&x) {
            0.0
        } else {
            ulp(w) / 8.0 + ulp(f) / 2.0
        };
        for c in 0..2 {
            assert!(
                (f64::from(got[c]) - f).abs() <= bound,
                "w ({x}): {got:?} want {f} within {bound}"
            );
        }
        assert_eq!((got[2], got[3]), (1.0, 1.0), "w ({x})");
    }
    // "spec": a vs_2_0 that writes no oFog but writes oD1: vertex fog reads
    // the specular alpha (vkd3d's fog.shader_test, recorded on native
    // Direct3D 9, fogs by `specular.a`). Alpha 1 at the left, 0 at the
    // right, w = 1: f = 1 − x/8 (dyadic, exact).
    check(&t, "spec", |x, _| {
        let f = 1.0 - x as f32 / 8.0;
        [f, f, 1.0, 1.0]
    });
}

#[test]
fn bad_render_states_are_refused_by_field() {
    let dir = tempfile::tempdir().unwrap();
    let shader = crate::common::bin::repo().join("tests/draw_conformance/texcoord.psh");
    let verts = r#"{"attributes": {"positiont0": [[0, 0, 0, 1], [4, 0, 0, 1], [0, 4, 0, 1]]}}"#;
    for (extra, want) in [
        (
            r#""stencil": {"pass": "INCR"}"#,
            "steps[0].geometry.stencil: the stencil lives in a depth-stencil surface with stencil bits",
        ),
        (
            r#""depth": {"format": "D16"}, "stencil": {}"#,
            "steps[0].geometry.stencil:",
        ),
        (
            r#""depth": {"format": "D24S8"}, "stencil": {"zfail": "INCREMENT"}"#,
            "steps[0].geometry.stencil.zfail: `INCREMENT` is not a D3DSTENCILOP",
        ),
        (
            r#""depth": {"format": "D24S8"}, "stencil": {"ccw": {"func": "SOMETIMES"}}"#,
            "steps[0].geometry.stencil.ccw.func: `SOMETIMES` is not a D3DCMPFUNC",
        ),
        (
            r#""depth": {"format": "D24X4S4"}, "stencil": {"ref": 16}"#,
            "steps[0].geometry.stencil.ref: 16: D3DFMT_D24X4S4's stencil holds 0 to 15",
        ),
        (
            r#""point_size_min": 8, "point_size_max": 4"#,
            "steps[0].geometry.point_size_min: 8 is above point_size_max 4",
        ),
        (r#""fill_mode": "dots""#, "steps[0].geometry.fill_mode:"),
        (r#""fog": {"mode": "fast"}"#, "steps[0].geometry.fog.mode:"),
        (
            r#""fog": {"mode": "vertex", "depth": "w"}"#,
            "steps[0].geometry.fog.depth: vertex fog reads no depth",
        ),
        (
            r#""fog": {"mode": "linear", "depth": "eye"}"#,
            "steps[0].geometry.fog.depth:",
        ),
        (
            r#""point_scale": [0, 0, 0]"#,
            "steps[0].geometry.point_scale:",
        ),
    ] {
        let list = format!(
            r#"{{"targets": [{{"name": "t", "size": "4x4", "format": "A8R8G8B8"}}],
                "steps": [{{"draw": "t", "shader": {shader:?}, "geometry": {{"primitive": "triangle_list", "vertices": {verts}, {extra}}}}}]}}"#
        );
        let path = dir.path().join("list.json");
        std::fs::write(&path, list).unwrap();
        let o = crate::common::bin::ps30(
            &["render", path.to_str().unwrap()],
            crate::common::bin::repo(),
        );
        assert_eq!(o.status.code(), Some(2), "{extra}");
        let err = crate::common::bin::stderr(&o);
        assert!(err.contains(want), "{extra}: {err}");
    }
}
