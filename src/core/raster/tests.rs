//! The rules of `core/raster` against values worked out by hand (each
//! derivation beside its test) or given by Microsoft's own examples.

use super::clip::{clip, ClipVertex, VIEW_VOLUME};
use super::depth::DepthFormat;
use super::*;

fn sv(x: f64, y: f64, rhw: f64, value: f64) -> ScreenVertex {
    ScreenVertex {
        x,
        y,
        z: 0.5,
        rhw,
        values: vec![[value, 0.0, 0.0, 1.0]],
    }
}

fn count(t: &Triangle, side: u32) -> usize {
    (0..side)
        .flat_map(|y| (0..side).map(move |x| (x, y)))
        .filter(|&(x, y)| t.covers(f64::from(x), f64::from(y)))
        .count()
}

#[test]
fn microsofts_fill_rule_examples() {
    // "Rasterization Rules (Direct3D 9)": the triangle (0,0), (5,0), (5,5)
    // fills 15 pixels, (0,5), (0,0), (5,5) fills 10 (their shared edge is
    // the first one's left edge), and the square (0,0)–(5,5) fills 25.
    let a = Triangle::new(sv(0., 0., 1., 0.), sv(5., 0., 1., 0.), sv(5., 5., 1., 0.)).unwrap();
    let b = Triangle::new(sv(0., 5., 1., 0.), sv(0., 0., 1., 0.), sv(5., 5., 1., 0.)).unwrap();
    assert_eq!((count(&a, 8), count(&b, 8)), (15, 10));
    // The same two with the second wound the other way round: coverage
    // does not depend on the winding.
    let b2 = Triangle::new(sv(0., 5., 1., 0.), sv(5., 5., 1., 0.), sv(0., 0., 1., 0.)).unwrap();
    assert_eq!(count(&b2, 8), 10);
    assert_eq!(b2.face, Face::Back);
    // The rectangle (0.5, 0.5)–(2.5, 4.5): every centre it holds is
    // strictly inside, 2 columns (1, 2) by 4 rows (1–4) = 8 pixels.
    let r = [(0.5, 0.5), (2.5, 0.5), (0.5, 4.5), (2.5, 4.5)];
    let t1 = Triangle::new(
        sv(r[0].0, r[0].1, 1., 0.),
        sv(r[1].0, r[1].1, 1., 0.),
        sv(r[2].0, r[2].1, 1., 0.),
    )
    .unwrap();
    let t2 = Triangle::new(
        sv(r[1].0, r[1].1, 1., 0.),
        sv(r[3].0, r[3].1, 1., 0.),
        sv(r[2].0, r[2].1, 1., 0.),
    )
    .unwrap();
    assert_eq!(count(&t1, 8) + count(&t2, 8), 8);
}

#[test]
fn shared_edges_cover_each_centre_once() {
    // A fan of 12 thin triangles round (7.3, 6.1) over a 16×16 grid, edges
    // through many centres at odd slopes: every centre inside the hull is
    // covered by exactly one triangle.
    let c = sv(8.0, 8.0, 1.0, 0.0);
    let ring: Vec<ScreenVertex> = (0..12)
        .map(|i| {
            let a = f64::from(i) * std::f64::consts::TAU / 12.0;
            sv(8.0 + 6.0 * a.cos(), 8.0 + 6.0 * a.sin(), 1.0, 0.0)
        })
        .collect();
    let tris: Vec<Triangle> = (0..12)
        .filter_map(|i| Triangle::new(c.clone(), ring[i].clone(), ring[(i + 1) % 12].clone()))
        .collect();
    for y in 0..16 {
        for x in 0..16 {
            let n = tris.iter().filter(|t| t.covers(x as f64, y as f64)).count();
            assert!(n <= 1, "({x}, {y}) covered {n} times");
            if (x as f64 - 8.0).hypot(y as f64 - 8.0) < 5.0 {
                assert_eq!(n, 1, "({x}, {y})");
            }
        }
    }
}

#[test]
fn perspective_interpolation_weighs_by_one_over_w() {
    // A triangle with corners (0,0) w=1 value 0, (8,0) w=4 value 1,
    // (0,8) w=1 value 0. Along the top row at x, the screen weight of the
    // second corner is x/8; with perspective the value is
    // (x/8)(1/4) / ((x/8)(1/4) + (1 − x/8)·1) = x / (x + 4(8 − x)).
    // At x = 4: 4 / (4 + 16) = 0.2 (affine would give 0.5).
    let t = Triangle::new(sv(0., 0., 1., 0.), sv(8., 0., 0.25, 1.), sv(0., 8., 1., 0.)).unwrap();
    let at = |x: f64| t.value(0, t.barycentric(x, 0.0), [false; 4], &[0.0; 4])[0];
    assert_eq!(at(4.0), 0.2);
    assert_eq!(at(0.0), 0.0);
    assert_eq!(at(8.0), 1.0);
    // w = 1 everywhere: affine.
    let a = Triangle::new(sv(0., 0., 1., 0.), sv(8., 0., 1., 1.), sv(0., 8., 1., 0.)).unwrap();
    assert_eq!(
        a.value(0, a.barycentric(2.0, 0.0), [false; 4], &[0.0; 4])[0],
        0.25
    );
    // Flat components take the provoking vertex's value.
    let flat = t.value(
        0,
        t.barycentric(4.0, 0.0),
        [true, false, false, false],
        &[9.0; 4],
    );
    assert_eq!(flat[0], 9.0);
}

#[test]
fn viewport_maps_clip_space_to_d3d9_pixel_centres() {
    // X + (1 + x/w)·W/2, Y + (1 − y/w)·H/2, MinZ + z/w·(MaxZ − MinZ).
    let v = Viewport {
        x: 10,
        y: 20,
        width: 100,
        height: 50,
        min_z: 0.25,
        max_z: 0.75,
    };
    assert_eq!(v.to_screen([-1.0, 1.0, 0.0, 1.0]), [10.0, 20.0, 0.25, 1.0]);
    assert_eq!(v.to_screen([2.0, -2.0, 2.0, 2.0]), [110.0, 70.0, 0.75, 0.5]);
    assert_eq!(v.to_screen([0.0, 0.0, 0.5, 1.0]), [60.0, 45.0, 0.5, 1.0]);
}

#[test]
fn clipping_keeps_the_view_volume_and_blends_values_linearly() {
    let cv = |x: f64, z: f64, value: f64| ClipVertex {
        pos: [x, 0.0, z, 1.0],
        values: vec![[value; 4]],
    };
    // Wholly inside: unchanged.
    let tri = vec![cv(0.0, 0.5, 0.0), cv(0.5, 0.5, 1.0), cv(0.0, 0.6, 2.0)];
    assert_eq!(clip(tri.clone(), &VIEW_VOLUME), tri);
    // x from −3 to 1 along an edge: the plane x = −w cuts it at t = 0.5,
    // where the value is halfway, 5 (between 0 and 10).
    let cut = clip(
        vec![cv(-3.0, 0.5, 0.0), cv(1.0, 0.5, 10.0), cv(1.0, 0.6, 10.0)],
        &VIEW_VOLUME,
    );
    assert!(cut.iter().all(|v| v.pos[0] >= -1.0));
    assert!(cut
        .iter()
        .any(|v| v.pos[0] == -1.0 && v.values[0][0] == 5.0));
    // Behind the near plane (z < 0) everywhere: nothing left.
    assert!(clip(
        vec![cv(0.0, -0.1, 0.0), cv(0.5, -0.2, 0.0), cv(0.0, -0.3, 0.0)],
        &VIEW_VOLUME
    )
    .is_empty());
}

#[test]
fn assembly_of_every_primitive_type() {
    let corners = |p, n| {
        assemble(p, n)
            .unwrap()
            .iter()
            .map(|a| (a.corners, a.provoking))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        corners(Primitive::TriangleList, 6),
        vec![([0, 1, 2], 0), ([3, 4, 5], 3)]
    );
    assert_eq!(
        corners(Primitive::TriangleStrip, 5),
        vec![([0, 1, 2], 0), ([2, 1, 3], 1), ([2, 3, 4], 2)]
    );
    assert_eq!(
        corners(Primitive::TriangleFan, 5),
        vec![([0, 1, 2], 1), ([0, 2, 3], 2), ([0, 3, 4], 3)]
    );
    assert_eq!(
        corners(Primitive::PointList, 2),
        vec![([0, 0, 0], 0), ([1, 1, 1], 1)]
    );
    assert!(assemble(Primitive::TriangleList, 4).is_err());
    assert!(assemble(Primitive::TriangleFan, 2).is_err());
    assert_eq!(
        Primitive::from_name("D3DPT_TRIANGLEFAN"),
        Some(Primitive::TriangleFan)
    );
    assert_eq!(
        corners(Primitive::LineList, 4),
        vec![([0, 1, 1], 0), ([2, 3, 3], 2)]
    );
    assert_eq!(
        corners(Primitive::LineStrip, 3),
        vec![([0, 1, 1], 0), ([1, 2, 2], 1)]
    );
    assert!(assemble(Primitive::LineList, 3).is_err());
    assert!(assemble(Primitive::LineStrip, 1).is_err());
    assert_eq!(
        Primitive::from_name("D3DPT_LINESTRIP"),
        Some(Primitive::LineStrip)
    );
    assert_eq!(Primitive::from_name("line_loop"), None);
}

fn line_pixels(a: (f64, f64), b: (f64, f64), last: bool) -> Vec<(u32, u32)> {
    let limit = Rect {
        left: 0,
        top: 0,
        right: 16,
        bottom: 16,
    };
    let l = Line::new(sv(a.0, a.1, 1., 0.), sv(b.0, b.1, 1., 0.), last, limit);
    (0..16u32)
        .flat_map(|y| (0..16u32).map(move |x| (x, y)))
        .filter(|&(x, y)| l.covers(f64::from(x), f64::from(y)))
        .collect()
}

#[test]
fn the_diamond_border_rule() {
    // The border of the diamond round (0, 0): the lower edges and the
    // bottom corner are inside; the upper edges and the top, left and right
    // corners outside — except the right corner for a y-major line.
    assert!(line::in_diamond(0.0, 0.5, false));
    assert!(line::in_diamond(-0.25, 0.25, false));
    assert!(line::in_diamond(0.25, 0.25, false));
    assert!(!line::in_diamond(0.0, -0.5, false));
    assert!(!line::in_diamond(0.25, -0.25, false));
    assert!(!line::in_diamond(-0.5, 0.0, false));
    assert!(!line::in_diamond(0.5, 0.0, false));
    assert!(line::in_diamond(0.5, 0.0, true));
    assert!(!line::in_diamond(-0.5, 0.0, true));
}

#[test]
fn lines_by_the_diamond_exit_rule() {
    // A horizontal line between centres: columns 1–4 left through their
    // right corners, column 5 holds the end (drawn only with LASTPIXEL).
    let row = |n: u32| (1..=n).map(|x| (x, 2)).collect::<Vec<_>>();
    assert_eq!(line_pixels((1., 2.), (5., 2.), false), row(4));
    assert_eq!(line_pixels((1., 2.), (5., 2.), true), row(5));
    // Drawn the other way, the first pixel is the one left out.
    let back = line_pixels((5., 2.), (1., 2.), false);
    assert_eq!(back, (2..=5).map(|x| (x, 2)).collect::<Vec<_>>());
    // A line wholly inside one diamond leaves none; with LASTPIXEL its
    // pixel is drawn. A line of no length draws nothing either way.
    assert!(line_pixels((3.1, 3.0), (3.3, 3.1), false).is_empty());
    assert_eq!(line_pixels((3.1, 3.0), (3.3, 3.1), true), vec![(3, 3)]);
    assert!(line_pixels((3., 3.), (3., 3.), true).is_empty());
    // A horizontal line along the boundary between rows 2 and 3 (y = 2.5)
    // runs through the bottom corners of row 2 (inside) and the top
    // corners of row 3 (outside): row 2 only.
    assert_eq!(
        line_pixels((0.75, 2.5), (4.75, 2.5), false),
        (1..=4).map(|x| (x, 2)).collect::<Vec<_>>()
    );
    // A vertical line along x = 2.5 (y-major): the right corners of column
    // 2 are inside, the left corners of column 3 outside.
    assert_eq!(
        line_pixels((2.5, 0.75), (2.5, 4.75), false),
        (1..=4).map(|y| (2, y)).collect::<Vec<_>>()
    );
}

#[test]
fn values_along_a_line_take_perspective() {
    // Corner values 0 and 1, 1/w = 1 and ¼: at t = ½ the weights are
    // ½·1 and ½·¼, so the value is (⅛)/(⅝) = 0.2 (affine: 0.5).
    let limit = Rect {
        left: 0,
        top: 0,
        right: 16,
        bottom: 16,
    };
    let l = Line::new(sv(0., 0., 1., 0.), sv(8., 0., 0.25, 1.), true, limit);
    let w = l.pixels(limit, &[(0, 0, [false; 4])], &[[0.0; 4]]).unwrap();
    assert_eq!(w.inputs.values[0].1[4][0], 0.2);
    assert_eq!(w.inputs.covered.iter().filter(|c| **c).count(), 9);
}

#[test]
fn segments_clip_against_planes() {
    // z ≥ 0 and z ≤ w on a segment from z = −1 to z = 3 (w = 1): kept from
    // t = ¼ to ½, the values blended alike.
    let v = |z: f64, value: f64| ClipVertex {
        pos: [0.0, 0.0, z, 1.0],
        values: vec![[value; 4]],
    };
    let (a, b) = clip::clip_segment(v(-1.0, 0.0), v(3.0, 4.0), &VIEW_VOLUME[4..]).unwrap();
    assert_eq!((a.pos[2], b.pos[2]), (0.0, 1.0));
    assert_eq!((a.values[0][0], b.values[0][0]), (1.0, 2.0));
    assert!(clip::clip_segment(v(-2.0, 0.0), v(-1.0, 0.0), &VIEW_VOLUME[4..]).is_none());
}

#[test]
fn stencil_ops_test_and_write_mask() {
    use stencil::{run, StencilOp as Op, StencilOps};
    // Every op on 5, 255 and 0 with reference 7, by hand.
    let want = [
        (Op::Keep, [5, 255, 0]),
        (Op::Zero, [0, 0, 0]),
        (Op::Replace, [7, 7, 7]),
        (Op::IncrSat, [6, 255, 1]),
        (Op::DecrSat, [4, 254, 0]),
        (Op::Invert, [250, 0, 255]),
        (Op::Incr, [6, 0, 1]),
        (Op::Decr, [4, 254, 255]),
    ];
    for (op, out) in want {
        for (stored, w) in [5u8, 255, 0].into_iter().zip(out) {
            assert_eq!(op.apply(stored, 7, 255), w, "{op:?} on {stored}");
        }
    }
    assert_eq!(Op::from_name("d3dstencilop_incrsat"), Some(Op::IncrSat));
    let ops = StencilOps {
        fail: Op::Decr,
        zfail: Op::Invert,
        pass: Op::Incr,
    };
    let less = |a: u8, b: u8| a < b;
    // The reference on the left: 3 < 5 passes.
    let o = run(5, less, || true, &ops, 3, 0xFF, 0xFF, 0xFF);
    assert_eq!((o.passed, o.depth_passed, o.written), (true, true, 6));
    // Masked: (7 & 1) < (6 & 1) is 1 < 0, fails: DECR.
    let o = run(6, less, || panic!("no depth test"), &ops, 7, 1, 0xFF, 0xFF);
    assert_eq!((o.passed, o.op, o.written), (false, Op::Decr, 5));
    // Depth fails: INVERT of 0x05 through write mask 0x0F: 0x0A.
    let o = run(5, |_, _| true, || false, &ops, 0, 0xFF, 0x0F, 0xFF);
    assert_eq!((o.survives(), o.written), (false, 0x0A));
    // Four stencil bits (D3DFMT_D24X4S4, largest value 15): INCR of 15
    // wraps to 0, INVERT of 5 (0101) is 10 (1010), not 250.
    let o = run(15, |_, _| true, || true, &ops, 0, 0xFF, 0xFF, 15);
    assert_eq!(o.written, 0);
    let o = run(5, |_, _| true, || false, &ops, 0, 0xFF, 0xFF, 15);
    assert_eq!(o.written, 10);
    assert_eq!(Op::IncrSat.apply(15, 0, 15), 15);
    assert_eq!(Op::Decr.apply(0, 0, 1), 1);
}

#[test]
fn point_sizes_clamp_and_scale() {
    let p = points::PointState::default();
    assert_eq!(p.size_of(None, None), 1.0);
    assert_eq!(p.size_of(Some(100.0), None), 64.0);
    assert_eq!(p.size_of(Some(0.25), None), 1.0);
    // Scale (1, 0, 0) by default: Vh·Si.
    let s = points::PointState {
        scale: Some([1.0, 0.0, 0.0]),
        ..p
    };
    assert_eq!(s.size_of(Some(0.125), Some(([3.0, 4.0, 0.0], 64.0))), 8.0);
    // C = 1: Vh·Si/De with De = 5.
    let s = points::PointState {
        scale: Some([0.0, 0.0, 1.0]),
        ..p
    };
    assert_eq!(s.size_of(Some(1.0), Some(([3.0, 4.0, 0.0], 40.0))), 8.0);
}

#[test]
fn depth_formats_round_to_their_bits() {
    // D16: 0.5·65535 = 32767.5 rounds to 32768 → 32768/65535.
    assert_eq!(DepthFormat::D16.store(0.5), 32768.0 / 65535.0);
    assert_eq!(DepthFormat::D24S8.store(0.5), 8388608.0 / 16777215.0);
    assert_eq!(DepthFormat::D16.store(1.5), 1.0);
    assert_eq!(DepthFormat::D16.store(-1.0), 0.0);
    assert_eq!(DepthFormat::D32F.store(0.1), f64::from(0.1f32));
    assert_eq!(
        DepthFormat::from_name("D3DFMT_D24X8"),
        Some(DepthFormat::D24X8)
    );
}

#[test]
fn a_window_sits_on_the_quad_grid_with_helper_values() {
    // Triangle (1,1), (4,1), (1,4) on a big clip rect: bounds columns 1–4,
    // rows 1–4; the window starts at (0, 0) (even) and is 5×5, its grid
    // 6×6. Value = x (affine): every grid pixel holds its own x, helpers too.
    let mk = |x: f64, y: f64| ScreenVertex {
        x,
        y,
        z: y / 8.0,
        rhw: 1.0,
        values: vec![[x, y, 0.0, 0.0]],
    };
    let t = Triangle::new(mk(1.0, 1.0), mk(4.0, 1.0), mk(1.0, 4.0)).unwrap();
    let clip_rect = Rect {
        left: 0,
        top: 0,
        right: 64,
        bottom: 64,
    };
    let w = t
        .pixels(clip_rect, &[(3, 0, [false; 4])], &[[0.0; 4]])
        .unwrap();
    assert_eq!((w.width, w.height, w.inputs.origin), (5, 5, (0, 0)));
    assert_eq!(w.inputs.values[0].1.len(), 36);
    // The barycentrics are f64 quotients of products of coordinates below
    // 8: each of the dozen operations errs by at most 2^-53 of a magnitude
    // below 64, so 1e-12 bounds the sum of their errors with room to spare.
    for j in 0..6 {
        for i in 0..6 {
            let v = w.inputs.values[0].1[j * 6 + i][0];
            assert!((f64::from(v) - i as f64).abs() < 1e-12, "({i}, {j}): {v}");
        }
    }
    // Covered: x ≥ 1, y ≥ 1, x + y < 5 (the hypotenuse is a right edge),
    // plus x + y = 5 excluded: (1,1),(2,1),(3,1),(1,2),(2,2),(1,3) = 6.
    assert_eq!(w.inputs.covered.iter().filter(|&&c| c).count(), 6);
    assert_eq!(w.depth[5 + 1], 1.0 / 8.0);
    // A scissor of columns 2.. drops column 1.
    let r = Rect {
        left: 2,
        ..clip_rect
    };
    let w = t.pixels(r, &[], &[]).unwrap();
    assert_eq!((w.inputs.origin, w.width), ((2, 0), 3));
    assert_eq!(w.inputs.covered.iter().filter(|&&c| c).count(), 3);
}

#[test]
fn fog_factors_and_blend() {
    use fog::{Fog, FogMode};
    let f = |mode| Fog {
        mode,
        color: [0.0, 0.0, 1.0, 0.0],
        start: 0.25,
        end: 0.75,
        density: 2.0,
        w: false,
    };
    // Linear: (0.75 − 0.5)/(0.75 − 0.25) = ½; clamped outside [start, end].
    assert_eq!(f(FogMode::Linear).factor(0.5), 0.5);
    assert_eq!(f(FogMode::Linear).factor(0.0), 1.0);
    assert_eq!(f(FogMode::Linear).factor(1.0), 0.0);
    assert_eq!(f(FogMode::Exp).factor(0.5), (-1.0f64).exp());
    assert_eq!(f(FogMode::Exp2).factor(0.5), (-1.0f64).exp());
    assert_eq!(f(FogMode::Vertex).factor(1.5), 1.0);
    // Half fogged white: (½, ½, 1), alpha as written.
    let c = f(FogMode::Vertex).blend([1.0, 1.0, 1.0, 0.25], 0.5);
    assert_eq!(c, [0.5, 0.5, 1.0, 0.25]);
}
