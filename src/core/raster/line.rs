//! One line on screen, rasterised by Direct3D 9's rule for lines that are
//! not antialiased, and its values at any pixel with perspective.
//!
//! "Rasterization Rules (Direct3D 9)", *Point and line rules*: "Nonantialiased
//! line rendering rules are exactly the same as those for GDI lines" — the
//! diamond-exit rule (grid intersection quantization) that Direct3D 10's
//! "Rasterization Rules" write out in full: around each pixel centre lies a
//! diamond |dx| + |dy| < ½; of its border an x-major line (|slope| ≤ 1)
//! counts the two lower edges and the bottom corner as inside, the upper
//! edges and the top, left and right corners as outside, and a y-major line
//! counts the right corner inside too. A line covers a pixel when, going
//! from its first vertex to its second, it leaves the pixel's diamond.
//! D3DRS_LASTPIXEL (TRUE by default: "enables drawing of the last pixel in
//! a line") adds the pixel whose diamond holds the second vertex, which the
//! exit rule never draws; with it FALSE a line strip's shared vertices are
//! drawn once, by the line that leaves them.
//!
//! Values along the line are weighted by the pixel centre's position along
//! the major axis, t = (x − x₀)/(x₁ − x₀) for an x-major line, times 1/w
//! and normalised (perspective), as Direct3D 10's line rules and OpenGL's
//! segment rule sample them; depth is linear in t. Screen y grows down, so
//! the diamond's "lower" edges are those of larger y.

use super::triangle::{Cover, Window};
use super::{Face, Rect, ScreenVertex};

/// A line after clipping, with the pixels it covers within a limit.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// First and second vertex, in drawing order.
    pub v: [ScreenVertex; 2],
    /// |Δx| ≥ |Δy|.
    x_major: bool,
    /// The covered pixels' bounds (empty when none).
    covered_rect: Rect,
    /// Covered flags over `covered_rect`, row-major.
    covered: Vec<bool>,
}

/// Whether (dx, dy) from a pixel centre lies in its diamond, with the
/// border rule of the module docs.
pub fn in_diamond(dx: f64, dy: f64, y_major: bool) -> bool {
    let s = dx.abs() + dy.abs();
    s < 0.5 || (s == 0.5 && (dy > 0.0 || (y_major && dx == 0.5 && dy == 0.0)))
}

impl Line {
    /// The line from `a` to `b` and the pixels of `limit` it covers
    /// (`last_pixel`: D3DRS_LASTPIXEL). A line of no length covers nothing.
    pub fn new(a: ScreenVertex, b: ScreenVertex, last_pixel: bool, limit: Rect) -> Line {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let x_major = dx.abs() >= dy.abs();
        let mut line = Line {
            v: [a, b],
            x_major,
            covered_rect: Rect {
                left: 0,
                top: 0,
                right: 0,
                bottom: 0,
            },
            covered: Vec::new(),
        };
        let finite = [dx, dy, line.v[0].x, line.v[0].y]
            .iter()
            .all(|v| v.is_finite());
        if (dx == 0.0 && dy == 0.0) || !finite || limit.is_empty() {
            return line;
        }
        let hits = line.walk(last_pixel, limit);
        if let (Some(l), Some(r), Some(t), Some(bo)) = (
            hits.iter().map(|h| h.0).min(),
            hits.iter().map(|h| h.0).max(),
            hits.iter().map(|h| h.1).min(),
            hits.iter().map(|h| h.1).max(),
        ) {
            let rect = Rect {
                left: l,
                top: t,
                right: r + 1,
                bottom: bo + 1,
            };
            let w = (rect.right - rect.left) as usize;
            let mut flags = vec![false; w * (rect.bottom - rect.top) as usize];
            for (x, y) in hits {
                flags[(y - rect.top) as usize * w + (x - rect.left) as usize] = true;
            }
            line.covered_rect = rect;
            line.covered = flags;
        }
        line
    }

    /// The pixels of `limit` the line covers: along the major axis, each
    /// column (row) whose diamonds the line can reach, and in it the three
    /// rows (columns) nearest the line.
    fn walk(&self, last_pixel: bool, limit: Rect) -> Vec<(u32, u32)> {
        let [a, b] = &self.v;
        // Major coordinate m, minor n.
        let (ma, mb, na, nb) = if self.x_major {
            (a.x, b.x, a.y, b.y)
        } else {
            (a.y, b.y, a.x, b.x)
        };
        let (lo_lim, hi_lim, nlo, nhi) = if self.x_major {
            (limit.left, limit.right, limit.top, limit.bottom)
        } else {
            (limit.top, limit.bottom, limit.left, limit.right)
        };
        let first = (ma.min(mb) - 0.5).floor().max(f64::from(lo_lim));
        let last = (ma.max(mb) + 0.5).ceil().min(f64::from(hi_lim) - 1.0);
        let mut out = Vec::new();
        let mut m = first;
        while m <= last {
            let t = ((m - ma) / (mb - ma)).clamp(0.0, 1.0);
            let n = (na + t * (nb - na)).round();
            for n in [n - 1.0, n, n + 1.0] {
                if n < f64::from(nlo) || n >= f64::from(nhi) {
                    continue;
                }
                let (px, py) = if self.x_major { (m, n) } else { (n, m) };
                if self.covers_centre(px, py, last_pixel) {
                    out.push((px as u32, py as u32));
                }
            }
            m += 1.0;
        }
        out
    }

    /// The diamond-exit rule for the pixel centred at (`px`, `py`).
    fn covers_centre(&self, px: f64, py: f64, last_pixel: bool) -> bool {
        let [a, b] = &self.v;
        let y_major = !self.x_major;
        let at = |t: f64| (a.x + t * (b.x - a.x) - px, a.y + t * (b.y - a.y) - py);
        // The segment within the closed diamond, Liang–Barsky over its four
        // sides n·d ≤ ½.
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (nx, ny) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
            let p = nx * (b.x - a.x) + ny * (b.y - a.y);
            let q = 0.5 - (nx * (a.x - px) + ny * (a.y - py));
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else if p > 0.0 {
                t1 = t1.min(q / p);
            } else {
                t0 = t0.max(q / p);
            }
        }
        if t0 > t1 {
            return false;
        }
        // The half-open diamond differs from the closed one on its border
        // only: the middle of the piece is inside unless the piece is a
        // single point or runs along a side, where its ends decide.
        let touches = [t0, t1, (t0 + t1) / 2.0].iter().any(|&t| {
            let (dx, dy) = at(t);
            in_diamond(dx, dy, y_major)
        });
        let end_inside = in_diamond(b.x - px, b.y - py, y_major);
        touches && (last_pixel || !end_inside)
    }

    /// How far along the major axis (x, y) lies: 0 at the first vertex, 1
    /// at the second.
    pub fn along(&self, x: f64, y: f64) -> f64 {
        let [a, b] = &self.v;
        if self.x_major {
            (x - a.x) / (b.x - a.x)
        } else {
            (y - a.y) / (b.y - a.y)
        }
    }

    /// A line has no facing: `vFace` reads it as front.
    pub fn face(&self) -> Face {
        Face::Front
    }

    /// Whether the pixel centred at (x, y) is covered.
    pub fn covers(&self, x: f64, y: f64) -> bool {
        let r = self.covered_rect;
        if x < f64::from(r.left) || y < f64::from(r.top) {
            return false;
        }
        let (i, j) = (
            (x - f64::from(r.left)) as u32,
            (y - f64::from(r.top)) as u32,
        );
        let w = r.right - r.left;
        x.fract() == 0.0
            && y.fract() == 0.0
            && i < w
            && j < r.bottom - r.top
            && self.covered[(j * w + i) as usize]
    }

    /// The covered pixels' rectangle within `clip`.
    pub fn bounds(&self, clip: Rect) -> Option<Rect> {
        let r = self.covered_rect.intersect(clip);
        (!r.is_empty()).then_some(r)
    }

    /// The pixel shader's view of the line within `clip`, as
    /// [`super::Triangle::pixels`] gives a triangle's: helpers of its quads
    /// take the line's values extended along the major axis.
    pub fn pixels(
        &self,
        clip: Rect,
        slots: &[(u32, usize, [bool; 4])],
        provoking: &[[f64; 4]],
    ) -> Option<Window> {
        super::triangle::window(self, clip, slots, provoking)
    }
}

impl Cover for Line {
    fn corners(&self) -> &[ScreenVertex] {
        &self.v
    }
    fn weights(&self, x: f64, y: f64) -> [f64; 3] {
        let t = self.along(x, y);
        [1.0 - t, t, 0.0]
    }
    fn covers(&self, x: f64, y: f64) -> bool {
        Line::covers(self, x, y)
    }
    fn bounds(&self, clip: Rect) -> Option<Rect> {
        Line::bounds(self, clip)
    }
}
