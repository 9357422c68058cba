//! Which primitives would have covered a watched pixel but lost the part
//! over it to clipping — the pixel history's "clipped" reason. Clipping
//! happens in clip space, before the divide, so the question is asked
//! there: the point of the unclipped primitive that projects onto the
//! pixel centre, and the planes that point lies beyond.
//!
//! * A triangle (solid fill): the clip-space point P = Σ bᵢ·Pᵢ whose
//!   projection is the pixel centre's (u, v) in normalised device
//!   coordinates solves Σ bᵢ·(xᵢ − u·wᵢ) = 0, Σ bᵢ·(yᵢ − v·wᵢ) = 0,
//!   Σ bᵢ = 1; the triangle lies over the pixel where every bᵢ ≥ 0 and
//!   P's w > 0 (in front of the eye). Its x and y planes never cut a
//!   pixel of the viewport (|u|, |v| ≤ 1 there), so what removes P is the
//!   near plane (z < 0), the far plane (z > w) or a user plane.
//! * A line: drawn unclipped from its projected ends (both in front of the
//!   eye); where it covers the pixel, P is the line's point nearest the
//!   centre on screen, taken back to clip space with perspective.
//! * A point is drawn whole or not at all, by its vertex against every
//!   plane, x and y included (the set-up's rule: `shapes` in `run.rs`):
//!   its square over the pixel counts when the vertex lies beyond any.
//!
//! Only watched pixels ask, so a draw without `--pixel` pays nothing.

use super::{ClipVertex, Geometry, Setup, Stage};
use crate::core::raster::clip::VIEW_VOLUME;
use crate::core::raster::{self, Primitive, Rect, ScreenVertex, Viewport};
use crate::jobs::render::geometry::state::FillMode;
use crate::jobs::render::history::ClippedAt;

/// The view volume's planes by name, in [`VIEW_VOLUME`]'s order.
const NAMES: [&str; 6] = [
    "left plane (x < −w)",
    "right plane (x > w)",
    "bottom plane (y < −w)",
    "top plane (y > w)",
    "near plane (z < 0)",
    "far plane (z > w)",
];

fn dot(p: &[f64; 4], q: &[f64; 4]) -> f64 {
    p.iter().zip(q).map(|(a, b)| a * b).sum()
}

/// The planes `p` lies beyond: the view volume's from `first` on, then
/// the user's.
fn beyond(g: &Geometry, p: &[f64; 4], first: usize) -> Vec<String> {
    let view = VIEW_VOLUME
        .iter()
        .zip(NAMES)
        .skip(first)
        .filter(|(plane, _)| dot(plane, p) < 0.0)
        .map(|(_, name)| name.to_string());
    let user = g
        .clip_planes
        .iter()
        .enumerate()
        .filter(|(_, plane)| dot(plane, p) < 0.0)
        .map(|(k, _)| format!("user clip plane {k}"));
    view.chain(user).collect()
}

/// The clip-space point of triangle `t` over normalised device
/// coordinates (u, v), if the triangle lies there in front of the eye.
fn triangle_point(t: [&[f64; 4]; 3], u: f64, v: f64) -> Option<[f64; 4]> {
    let row = |f: &dyn Fn(&[f64; 4]) -> f64| [f(t[0]), f(t[1]), f(t[2])];
    let m = [
        row(&|p| p[0] - u * p[3]),
        row(&|p| p[1] - v * p[3]),
        [1.0; 3],
    ];
    let det3 = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let det = det3(&m);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // Cramer's rule with the right-hand side (0, 0, 1).
    let b: [f64; 3] = std::array::from_fn(|k| {
        let mut mk = m;
        for (r, rhs) in [0.0, 0.0, 1.0].into_iter().enumerate() {
            mk[r][k] = rhs;
        }
        det3(&mk) / det
    });
    if b.iter().any(|&x| x < 0.0) {
        return None;
    }
    let p: [f64; 4] = std::array::from_fn(|c| b[0] * t[0][c] + b[1] * t[1][c] + b[2] * t[2][c]);
    (p[3] > 0.0).then_some(p)
}

/// The clip-space point of line `a`–`b` over pixel (x, y), if the
/// unclipped line (both ends in front of the eye) covers the pixel.
fn line_point(at: &Setup<'_>, a: &ClipVertex, b: &ClipVertex, x: u32, y: u32) -> Option<[f64; 4]> {
    if a.pos[3] <= 0.0 || b.pos[3] <= 0.0 {
        return None;
    }
    let screen = |v: &ClipVertex| {
        let [sx, sy, z, rhw] = at.viewport.to_screen(v.pos);
        ScreenVertex {
            x: sx,
            y: sy,
            z,
            rhw,
            values: Vec::new(),
        }
    };
    let (sa, sb) = (screen(a), screen(b));
    let pixel = Rect {
        left: x,
        top: y,
        right: x + 1,
        bottom: y + 1,
    };
    let line = raster::Line::new(sa.clone(), sb.clone(), at.g.state.last_pixel, pixel);
    let (fx, fy) = (f64::from(x), f64::from(y));
    if !line.covers(fx, fy) {
        return None;
    }
    // The screen parameter of the centre's nearest point, then the clip
    // parameter with perspective (1/w is linear on screen).
    let (dx, dy) = (sb.x - sa.x, sb.y - sa.y);
    let len = dx * dx + dy * dy;
    let t = if len > 0.0 {
        (((fx - sa.x) * dx + (fy - sa.y) * dy) / len).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = t * sb.rhw / ((1.0 - t) * sa.rhw + t * sb.rhw);
    Some(std::array::from_fn(|c| {
        a.pos[c] + (b.pos[c] - a.pos[c]) * s
    }))
}

/// The primitives of the draw that lie over pixel (x, y) of `viewport`
/// where clipping removed them, in drawing order.
pub(super) fn at(
    g: &Geometry,
    stage: &Stage,
    viewport: &Viewport,
    limit: Rect,
    (x, y): (u32, u32),
) -> Vec<ClippedAt> {
    if stage.transformed {
        // Pre-transformed vertices are not clipped.
        return Vec::new();
    }
    let order: Vec<usize> = match &g.indices {
        Some(ix) => ix.iter().map(|&i| i as usize).collect(),
        None => (0..stage.positions.len()).collect(),
    };
    let Ok(prims) = raster::assemble(g.primitive, order.len()) else {
        return Vec::new();
    };
    let at = Setup {
        g,
        stage,
        viewport,
        limit,
    };
    let (w, h) = (f64::from(viewport.width), f64::from(viewport.height));
    let u = 2.0 * (f64::from(x) - f64::from(viewport.x)) / w - 1.0;
    let v = 1.0 - 2.0 * (f64::from(y) - f64::from(viewport.y)) / h;
    let corner = |i: usize| ClipVertex {
        pos: stage.positions[i],
        values: stage.values[i].clone(),
    };
    let mut out = Vec::new();
    for (index, prim) in prims.iter().enumerate() {
        let [a, b, c] = prim.corners.map(|i| order[i]);
        let (kind, vertices, found) = if g.primitive == Primitive::PointList {
            let p = stage.positions[a];
            let over = !beyond(g, &p, 0).is_empty()
                && p[3] > 0.0
                && at.point(corner(a)).iter().any(|s| match s {
                    raster::Shape::Triangle(t) => t.covers(f64::from(x), f64::from(y)),
                    _ => false,
                });
            ("point", vec![a], over.then_some((p, 0)))
        } else if g.primitive.is_line() {
            let p = line_point(&at, &corner(a), &corner(b), x, y);
            ("line", vec![a, b], p.map(|p| (p, 4)))
        } else if g.state.fill == FillMode::Solid {
            let t = [a, b, c].map(|i| &stage.positions[i]);
            let p = triangle_point(t, u, v);
            ("triangle", vec![a, b, c], p.map(|p| (p, 4)))
        } else {
            continue;
        };
        let Some((position, first)) = found else {
            continue;
        };
        let planes = beyond(g, &position, first);
        if planes.is_empty() {
            continue;
        }
        out.push(ClippedAt {
            kind,
            primitive: index,
            vertices,
            position,
            planes,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::triangle_point;

    #[test]
    fn the_point_over_a_pixel_solves_the_projection() {
        // A triangle in the plane z = 2 with w = 2 (ndc x, y from −1 to 1):
        // the centre (0, 0) lies on it at clip (0, 0, 2, 2) scaled.
        let t = [
            [-2.0, -2.0, 2.0, 2.0],
            [2.0, -2.0, 2.0, 2.0],
            [0.0, 2.0, 2.0, 2.0],
        ];
        let p = triangle_point([&t[0], &t[1], &t[2]], 0.0, 0.0).unwrap();
        assert_eq!(p, [0.0, 0.0, 2.0, 2.0]);
        // Outside it: (0.9, 0.9) in ndc.
        assert!(triangle_point([&t[0], &t[1], &t[2]], 0.9, 0.9).is_none());
        // w varying: corners with w = 1, 1, 3 and ndc positions (−1, −1),
        // (1, −1), (0, 1): the ray through ndc (0, 1) meets the third
        // corner itself.
        let t = [
            [-1.0, -1.0, 0.0, 1.0],
            [1.0, -1.0, 0.0, 1.0],
            [0.0, 3.0, 0.0, 3.0],
        ];
        let p = triangle_point([&t[0], &t[1], &t[2]], 0.0, 1.0).unwrap();
        assert!(
            p.iter().zip(&t[2]).all(|(a, b)| (a - b).abs() < 1e-12),
            "{p:?}"
        );
    }
}
