//! One triangle on screen: its facing, which pixel centres it covers by
//! the top-left rule, and its values at any pixel with perspective (the
//! rules are in the module docs of [`super`]).
//!
//! Edge functions are computed in f64 from each edge's two vertices taken
//! in one fixed order (the lesser point first) and negated as the winding
//! needs, so two triangles that share an edge compute the same number for
//! it: no pixel centre on a shared edge is drawn twice or missed.

use super::{Face, Rect};
use crate::core::emu::PixelInputs;

/// A vertex on screen: position in pixels, depth, 1/w, and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct ScreenVertex {
    /// Column, pixel centres on integers.
    pub x: f64,
    /// Row, down.
    pub y: f64,
    /// Depth after the viewport's depth range.
    pub z: f64,
    /// 1/w (1 for values without perspective).
    pub rhw: f64,
    /// One value per pixel-shader input.
    pub values: Vec<[f64; 4]>,
}

/// A triangle after culling, wound clockwise on screen (every edge function
/// positive inside).
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    /// The corners, clockwise.
    pub v: [ScreenVertex; 3],
    /// The facing it was drawn with (before rewinding).
    pub face: Face,
    /// Twice the area, positive.
    area2: f64,
}

/// Twice the signed area on screen (y down): positive for clockwise.
pub fn area2(a: &ScreenVertex, b: &ScreenVertex, c: &ScreenVertex) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// The edge function of a→b at (x, y): positive to the right of the edge
/// on screen (inside a clockwise triangle), computed from the lesser
/// endpoint so that b→a gives exactly its negation.
fn edge(a: (f64, f64), b: (f64, f64), x: f64, y: f64) -> f64 {
    let f = |a: (f64, f64), b: (f64, f64)| (b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0);
    if a <= b {
        f(a, b)
    } else {
        -f(b, a)
    }
}

impl Triangle {
    /// The triangle `a, b, c` in that winding, or `None` when it has no
    /// area (it covers nothing).
    pub fn new(a: ScreenVertex, b: ScreenVertex, c: ScreenVertex) -> Option<Triangle> {
        let area = area2(&a, &b, &c);
        let (face, v) = match area {
            x if x > 0.0 => (Face::Front, [a, b, c]),
            x if x < 0.0 => (Face::Back, [a, c, b]),
            _ => return None,
        };
        Some(Triangle {
            v,
            face,
            area2: area.abs(),
        })
    }

    fn point(&self, i: usize) -> (f64, f64) {
        (self.v[i].x, self.v[i].y)
    }

    /// The three edge functions at (x, y): edge i runs from corner i to
    /// corner i + 1.
    fn edges(&self, x: f64, y: f64) -> [f64; 3] {
        std::array::from_fn(|i| edge(self.point(i), self.point((i + 1) % 3), x, y))
    }

    /// Whether the pixel centred at (`x`, `y`) is covered: inside, or on a
    /// top or left edge.
    pub fn covers(&self, x: f64, y: f64) -> bool {
        let e = self.edges(x, y);
        (0..3).all(|i| {
            let (a, b) = (self.point(i), self.point((i + 1) % 3));
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            // Clockwise with y down: a top edge runs right along a row, a
            // left edge runs up.
            e[i] > 0.0 || (e[i] == 0.0 && ((dy == 0.0 && dx > 0.0) || dy < 0.0))
        })
    }

    /// Screen barycentric weights of the corners at (x, y) (summing to 1;
    /// outside the triangle some are negative).
    pub fn barycentric(&self, x: f64, y: f64) -> [f64; 3] {
        let e = self.edges(x, y);
        // The weight of corner i is the edge opposite it.
        [e[1] / self.area2, e[2] / self.area2, e[0] / self.area2]
    }

    /// Value `k` at barycentrics `l`, with perspective: each corner weighs
    /// l·(1/w), normalised. `flat` components take `provoking` instead.
    pub fn value(&self, k: usize, l: [f64; 3], flat: [bool; 4], provoking: &[f64; 4]) -> [f32; 4] {
        value(&self.v, k, &l, flat, provoking)
    }

    /// Depth at barycentrics `l`: z is linear on screen.
    pub fn depth(&self, l: [f64; 3]) -> f64 {
        depth(&self.v, &l)
    }

    /// The rectangle of pixel centres the triangle's bounds hold, within
    /// `clip` (viewport, scissor and target together); `None` when empty.
    pub fn bounds(&self, clip: Rect) -> Option<Rect> {
        let lo = |f: fn(&ScreenVertex) -> f64| self.v.iter().map(f).fold(f64::INFINITY, f64::min);
        let hi =
            |f: fn(&ScreenVertex) -> f64| self.v.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
        let (x0, x1) = (lo(|v| v.x).ceil(), hi(|v| v.x).floor() + 1.0);
        let (y0, y1) = (lo(|v| v.y).ceil(), hi(|v| v.y).floor() + 1.0);
        let to = |v: f64, max: u32| v.clamp(0.0, f64::from(max)) as u32;
        let r = Rect {
            left: to(x0, clip.right),
            top: to(y0, clip.bottom),
            right: to(x1, clip.right),
            bottom: to(y1, clip.bottom),
        }
        .intersect(clip);
        (!r.is_empty()).then_some(r)
    }

    /// The pixel shader's view of the triangle within `clip`: a window on
    /// the quad grid holding its bounds, the pixels covered, each input's
    /// value at every pixel of the window's quads (helpers included), and
    /// each covered pixel's depth (`f64::NAN` elsewhere). `slots` pairs each
    /// input slot with the index of its value in the vertices; `flat` its
    /// components flat shading holds at `provoking`'s values. `None` when
    /// the triangle covers no pixel of `clip`.
    pub fn pixels(
        &self,
        clip: Rect,
        slots: &[(u32, usize, [bool; 4])],
        provoking: &[[f64; 4]],
    ) -> Option<Window> {
        window(self, clip, slots, provoking)
    }
}

impl Cover for Triangle {
    fn corners(&self) -> &[ScreenVertex] {
        &self.v
    }
    fn weights(&self, x: f64, y: f64) -> [f64; 3] {
        self.barycentric(x, y)
    }
    fn covers(&self, x: f64, y: f64) -> bool {
        Triangle::covers(self, x, y)
    }
    fn bounds(&self, clip: Rect) -> Option<Rect> {
        Triangle::bounds(self, clip)
    }
}

/// What a window of pixels needs of a primitive on screen (a triangle, or
/// a line of `super::line`): its corners, the screen weights of the
/// corners at a pixel centre, which centres it covers, and its bounds.
pub(crate) trait Cover {
    /// The corners (two for a line, three for a triangle).
    fn corners(&self) -> &[ScreenVertex];
    /// Screen weights of the corners at (x, y), summing to 1 (a line's
    /// third is 0).
    fn weights(&self, x: f64, y: f64) -> [f64; 3];
    /// Whether the pixel centred at (x, y) is covered.
    fn covers(&self, x: f64, y: f64) -> bool;
    /// The covered pixels' rectangle within `clip`; `None` when empty.
    fn bounds(&self, clip: Rect) -> Option<Rect>;
}

/// Value `k` of `corners` at screen weights `l`, with perspective: each
/// corner weighs l·(1/w), normalised. `flat` components take `provoking`.
pub(crate) fn value(
    corners: &[ScreenVertex],
    k: usize,
    l: &[f64; 3],
    flat: [bool; 4],
    provoking: &[f64; 4],
) -> [f32; 4] {
    let p: Vec<f64> = corners.iter().zip(l).map(|(v, l)| l * v.rhw).collect();
    let sum: f64 = p.iter().sum();
    std::array::from_fn(|c| {
        if flat[c] {
            return provoking[c] as f32;
        }
        let v = corners
            .iter()
            .zip(&p)
            .map(|(v, p)| p * v.values[k][c])
            .sum::<f64>()
            / sum;
        v as f32
    })
}

/// Depth of `corners` at screen weights `l`: z is linear on screen.
pub(crate) fn depth(corners: &[ScreenVertex], l: &[f64; 3]) -> f64 {
    corners.iter().zip(l).map(|(v, l)| l * v.z).sum()
}

/// The window of `shape` within `clip` ([`Triangle::pixels`] says what it
/// holds).
pub(crate) fn window(
    shape: &impl Cover,
    clip: Rect,
    slots: &[(u32, usize, [bool; 4])],
    provoking: &[[f64; 4]],
) -> Option<Window> {
    let b = shape.bounds(clip)?;
    let origin = (b.left & !1, b.top & !1);
    let (w, h) = (b.right - origin.0, b.bottom - origin.1);
    let (gw, gh) = (PixelInputs::grid_width(w), PixelInputs::grid_width(h));
    let mut covered = vec![false; w as usize * h as usize];
    let mut depths = vec![f64::NAN; covered.len()];
    let mut values: Vec<(u32, Vec<[f32; 4]>)> = slots
        .iter()
        .map(|&(s, _, _)| (s, Vec::with_capacity(gw * gh)))
        .collect();
    let corners = shape.corners();
    let mut any = false;
    for j in 0..gh {
        for i in 0..gw {
            let (x, y) = (origin.0 as usize + i, origin.1 as usize + j);
            let (fx, fy) = (x as f64, y as f64);
            let l = shape.weights(fx, fy);
            for ((_, k, flat), (_, out)) in slots.iter().zip(values.iter_mut()) {
                out.push(value(corners, *k, &l, *flat, &provoking[*k]));
            }
            let in_clip = (clip.left as usize..clip.right as usize).contains(&x)
                && (clip.top as usize..clip.bottom as usize).contains(&y);
            if i < w as usize && j < h as usize && in_clip && shape.covers(fx, fy) {
                covered[j * w as usize + i] = true;
                depths[j * w as usize + i] = depth(corners, &l);
                any = true;
            }
        }
    }
    any.then_some(Window {
        width: w,
        height: h,
        inputs: PixelInputs {
            origin,
            covered,
            values,
            positions: None,
        },
        depth: depths,
    })
}

/// What [`Triangle::pixels`] gives the pixel shader and the depth test.
#[derive(Clone, Debug, PartialEq)]
pub struct Window {
    /// The window's width in pixels (its emulator draw's target width).
    pub width: u32,
    /// Its height.
    pub height: u32,
    /// Coverage and per-pixel values, for [`crate::core::emu::Draw::pixels`].
    pub inputs: PixelInputs,
    /// Interpolated depth of each covered pixel, row-major in the window.
    pub depth: Vec<f64>,
}
