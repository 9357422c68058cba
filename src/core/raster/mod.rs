//! The fixed-function stages between a vertex shader and a pixel shader,
//! as Direct3D 9 runs them: primitive assembly, clipping, the perspective
//! divide, the viewport transform, culling, which pixels a triangle covers,
//! and every vertex output interpolated with perspective into the pixel
//! shader's inputs. It exists so that a draw of geometry (`jobs/render`'s
//! `geometry`) and the conformance corpus's set-up (`jobs/conformance`)
//! share one statement of these rules; it is plain arithmetic on plain
//! data, and hands the emulator [`crate::core::emu::PixelInputs`].
//!
//! The rules, each with its source:
//! * **Assembly** (D3DPRIMITIVETYPE): a triangle list takes vertices three
//!   at a time; a strip closes a triangle with every vertex after the
//!   second, every other one wound the other way so all face alike; a fan
//!   joins vertex 0 with each pair after it. A point list draws each vertex
//!   as a point. Flat shading's colour comes from the first vertex of each
//!   triangle (D3DSHADEMODE: "the color of the first vertex"): vertex i of a
//!   strip, vertex i + 1 of a fan (wined3d draws D3D9 with OpenGL's
//!   first-vertex convention, whose provoking vertex of fan triangle i is
//!   i + 1).
//! * **Clipping** ("Viewports and Clipping (Direct3D 9)"): a vertex is in
//!   the view volume when −w ≤ x ≤ w, −w ≤ y ≤ w and 0 ≤ z ≤ w; each
//!   enabled user plane (SetClipPlane, in clip space when a vertex shader
//!   runs) keeps dot(plane, position) ≥ 0. Attributes are linear in clip
//!   space, so a vertex made on a plane takes the linear blend of the two
//!   it lies between. Triangles are clipped as guard-band hardware clips
//!   them ([`clip::GUARD_BAND`]): against near and far (0 ≤ z ≤ w), the
//!   user planes and a guard band a thousand viewports wide, then
//!   scissored to the viewport. Clipping at x = ±w and y = ±w instead
//!   would put an edge on the viewport's border, and with the half-pixel
//!   offset a row or column of pixel centres lies exactly on it (y/w = 1
//!   is row 0's centres): the clipped vertex, rounded, lands the edge a
//!   hair inside or outside them, and a border row or column of pixels is
//!   lost or kept by rounding. Scissoring keeps exactly the viewport's
//!   pixels, as every guard-band part does (D3DCAPS9's GuardBandLeft …
//!   GuardBandBottom describe the band; "Viewports and Clipping" the
//!   volume).
//! * **Viewport** (D3DVIEWPORT9, "Viewports and Clipping"): screen x =
//!   X + (1 + x/w)·Width/2, y = Y + (1 − y/w)·Height/2, z = MinZ +
//!   (z/w)·(MaxZ − MinZ); pre-transformed vertices (D3DFVF_XYZRHW) give
//!   screen x, y, z and 1/w themselves and are not clipped.
//! * **Pixel centres** ("Directly Mapping Texels to Pixels (Direct3D 9)"):
//!   pixel (i, j) is sampled at screen point (i, j) — the half-pixel offset
//!   Direct3D 10 removed. **Coverage** ("Rasterization Rules (Direct3D 9)"):
//!   a pixel belongs to a triangle when its centre is inside, or on a top
//!   edge (horizontal, above the interior) or a left edge; only pixels of
//!   the viewport and the scissor rectangle (D3DRS_SCISSORTESTENABLE) are
//!   drawn.
//! * **Facing and culling** (D3DCULL): front faces are clockwise on screen;
//!   D3DCULL_CCW (the default) drops counter-clockwise triangles, D3DCULL_CW
//!   clockwise ones. `vFace` is the facing's sign.
//! * **Interpolation**: with perspective — each value's weight at a pixel is
//!   its screen barycentric times 1/w, normalised (what every Direct3D 9
//!   part did for texture coordinates and colours alike, and what D3DRS_WRAP
//!   and `_centroid` aside the docs never qualify); depth is z/w, linear on
//!   screen. Without multisampling a pixel has one sample, its centre, so
//!   `_centroid` reads the centre value ("centroid ... has no effect when
//!   multisampling is off").
//! * **Points** ("Point Sprites", "Point and line rules"): a point of size S
//!   (D3DRS_POINTSIZE, 1 by default) is the screen square (X ± S/2, Y ± S/2)
//!   with the vertex's values at every corner, rasterised by the triangle
//!   rules; a point whose z is outside the view volume is not drawn.
//! * **Lines** ([`line`]): the diamond-exit rule of GDI lines, with
//!   D3DRS_LASTPIXEL; a line is clipped against z and the user planes only
//!   and scissored to the viewport, as guard-band hardware does (clipping
//!   it at x = ±w would end it on the viewport's first column of centres,
//!   whose pixel the exit rule then leaves out). A line list takes
//!   vertices two at a time, a strip joins each vertex to the next; the
//!   provoking vertex of flat shading is a line's first.
//! * **Point sizes, sprites, stencil, fog** ([`points`], [`stencil`], [`fog`]).

pub mod clip;
pub mod depth;
pub mod fog;
pub mod line;
pub mod points;
pub mod stencil;
pub mod triangle;

pub use line::Line;
pub use triangle::{ScreenVertex, Triangle};

use serde::{Deserialize, Serialize};

/// D3DPRIMITIVETYPE.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Primitive {
    /// D3DPT_POINTLIST: every vertex one point.
    PointList,
    /// D3DPT_LINELIST: every two vertices one line.
    LineList,
    /// D3DPT_LINESTRIP: each vertex after the first ends a line from the
    /// one before it.
    LineStrip,
    /// D3DPT_TRIANGLELIST: every three vertices one triangle.
    TriangleList,
    /// D3DPT_TRIANGLESTRIP: each vertex after the second closes a triangle
    /// with the two before it.
    TriangleStrip,
    /// D3DPT_TRIANGLEFAN: vertex 0 with each pair of neighbours after it.
    TriangleFan,
}

impl Primitive {
    /// Every primitive type, with its name in draw lists.
    pub const ALL: [(&'static str, Primitive); 6] = [
        ("point_list", Primitive::PointList),
        ("line_list", Primitive::LineList),
        ("line_strip", Primitive::LineStrip),
        ("triangle_list", Primitive::TriangleList),
        ("triangle_strip", Primitive::TriangleStrip),
        ("triangle_fan", Primitive::TriangleFan),
    ];

    /// The type a draw list names (`triangle_strip`, or D3DPT_TRIANGLESTRIP).
    pub fn from_name(name: &str) -> Option<Primitive> {
        let lower = name.to_ascii_lowercase();
        let plain = lower
            .strip_prefix("d3dpt_")
            .unwrap_or(&lower)
            .replace('_', "");
        Self::ALL
            .iter()
            .find(|(n, _)| n.replace('_', "") == plain)
            .map(|&(_, p)| p)
    }
}

/// D3DRS_CULLMODE. The default is Direct3D 9's, `ccw`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Cull {
    /// D3DCULL_NONE: both facings are drawn.
    None,
    /// D3DCULL_CW: triangles wound clockwise on screen are dropped.
    Cw,
    /// D3DCULL_CCW: triangles wound counter-clockwise on screen are dropped.
    #[default]
    Ccw,
}

/// The facing of a triangle, as `vFace` reports it.
pub use crate::core::emu::Face;

impl Cull {
    /// Whether a triangle of this facing is dropped.
    pub fn drops(self, face: Face) -> bool {
        match self {
            Cull::None => false,
            Cull::Cw => face == Face::Front,
            Cull::Ccw => face == Face::Back,
        }
    }
}

/// D3DVIEWPORT9: the rectangle of the target clip space maps to, and the
/// depth range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Viewport {
    /// Left pixel column.
    pub x: u32,
    /// Top pixel row.
    pub y: u32,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Depth of z/w = 0.
    pub min_z: f32,
    /// Depth of z/w = 1.
    pub max_z: f32,
}

impl Viewport {
    /// The whole of a `width × height` target, depth 0 to 1 (what
    /// SetRenderTarget resets the viewport to).
    pub fn whole(width: u32, height: u32) -> Viewport {
        Viewport {
            x: 0,
            y: 0,
            width,
            height,
            min_z: 0.0,
            max_z: 1.0,
        }
    }

    /// Clip-space (x, y, z, w) on screen: (x, y, z, 1/w).
    pub fn to_screen(&self, p: [f64; 4]) -> [f64; 4] {
        let rhw = 1.0 / p[3];
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let (z0, z1) = (f64::from(self.min_z), f64::from(self.max_z));
        [
            f64::from(self.x) + (1.0 + p[0] * rhw) * w / 2.0,
            f64::from(self.y) + (1.0 - p[1] * rhw) * h / 2.0,
            z0 + p[2] * rhw * (z1 - z0),
            rhw,
        ]
    }

    /// The viewport's pixels as a rectangle.
    pub fn rect(&self) -> Rect {
        Rect {
            left: self.x,
            top: self.y,
            right: self.x.saturating_add(self.width),
            bottom: self.y.saturating_add(self.height),
        }
    }
}

/// A rectangle of pixels, a D3D RECT: columns `left..right`, rows
/// `top..bottom` (the scissor rectangle's form).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Rect {
    /// First column.
    pub left: u32,
    /// First row.
    pub top: u32,
    /// One past the last column.
    pub right: u32,
    /// One past the last row.
    pub bottom: u32,
}

impl Rect {
    /// The pixels in both.
    pub fn intersect(self, o: Rect) -> Rect {
        Rect {
            left: self.left.max(o.left),
            top: self.top.max(o.top),
            right: self.right.min(o.right),
            bottom: self.bottom.min(o.bottom),
        }
    }

    /// Whether it holds no pixel.
    pub fn is_empty(&self) -> bool {
        self.left >= self.right || self.top >= self.bottom
    }
}

impl Primitive {
    /// Whether it draws lines.
    pub fn is_line(self) -> bool {
        matches!(self, Primitive::LineList | Primitive::LineStrip)
    }
}

/// A primitive on screen, ready for the pixel shader: a triangle (points
/// are two) or a line.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A triangle after culling.
    Triangle(Triangle),
    /// A line with the pixels it covers.
    Line(Line),
}

impl Shape {
    /// Its facing, as `vFace` reports it (a line is front-facing).
    pub fn face(&self) -> Face {
        match self {
            Shape::Triangle(t) => t.face,
            Shape::Line(l) => l.face(),
        }
    }

    /// The rectangle of pixels it may cover within `clip`.
    pub fn bounds(&self, clip: Rect) -> Option<Rect> {
        match self {
            Shape::Triangle(t) => t.bounds(clip),
            Shape::Line(l) => l.bounds(clip),
        }
    }

    /// Whether the pixel centred at (x, y) is covered.
    pub fn covers(&self, x: f64, y: f64) -> bool {
        match self {
            Shape::Triangle(t) => t.covers(x, y),
            Shape::Line(l) => l.covers(x, y),
        }
    }

    /// Its corners on screen: two for a line, three for a triangle.
    pub fn corners(&self) -> &[ScreenVertex] {
        match self {
            Shape::Triangle(t) => triangle::Cover::corners(t),
            Shape::Line(l) => triangle::Cover::corners(l),
        }
    }

    /// The screen weights of its corners at (x, y), summing to 1 (a
    /// line's third is 0).
    pub fn weights(&self, x: f64, y: f64) -> [f64; 3] {
        match self {
            Shape::Triangle(t) => triangle::Cover::weights(t, x, y),
            Shape::Line(l) => triangle::Cover::weights(l, x, y),
        }
    }

    /// Its window of pixels for the pixel shader ([`Triangle::pixels`]).
    pub fn pixels(
        &self,
        clip: Rect,
        slots: &[(u32, usize, [bool; 4])],
        provoking: &[[f64; 4]],
    ) -> Option<triangle::Window> {
        match self {
            Shape::Triangle(t) => t.pixels(clip, slots, provoking),
            Shape::Line(l) => l.pixels(clip, slots, provoking),
        }
    }
}

/// One primitive after assembly: vertex indices in winding order and the
/// index of the vertex flat shading takes its colour from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Assembled {
    /// The vertices (a point repeats its one vertex, a line its second).
    pub corners: [usize; 3],
    /// The provoking vertex (one of `corners`).
    pub provoking: usize,
}

/// The primitives `count` vertices make as `primitive`; an error names a
/// count that makes a partial primitive.
pub fn assemble(primitive: Primitive, count: usize) -> Result<Vec<Assembled>, String> {
    let tri = |corners: [usize; 3], provoking| Assembled { corners, provoking };
    Ok(match primitive {
        Primitive::PointList => (0..count).map(|i| tri([i, i, i], i)).collect(),
        Primitive::LineList => {
            if !count.is_multiple_of(2) {
                return Err(format!(
                    "a line list needs a multiple of 2 vertices, not {count}"
                ));
            }
            (0..count / 2)
                .map(|l| tri([2 * l, 2 * l + 1, 2 * l + 1], 2 * l))
                .collect()
        }
        Primitive::LineStrip if count < 2 => {
            return Err(format!(
                "a line strip needs at least 2 vertices, not {count}"
            ))
        }
        Primitive::LineStrip => (0..count - 1).map(|i| tri([i, i + 1, i + 1], i)).collect(),
        Primitive::TriangleList => {
            if !count.is_multiple_of(3) {
                return Err(format!(
                    "a triangle list needs a multiple of 3 vertices, not {count}"
                ));
            }
            (0..count / 3)
                .map(|t| tri([3 * t, 3 * t + 1, 3 * t + 2], 3 * t))
                .collect()
        }
        Primitive::TriangleStrip | Primitive::TriangleFan if count < 3 => {
            return Err(format!(
                "a triangle strip or fan needs at least 3 vertices, not {count}"
            ))
        }
        Primitive::TriangleStrip => (0..count - 2)
            .map(|i| {
                let corners = if i % 2 == 0 {
                    [i, i + 1, i + 2]
                } else {
                    [i + 1, i, i + 2]
                };
                tri(corners, i)
            })
            .collect(),
        Primitive::TriangleFan => (1..count - 1).map(|i| tri([0, i, i + 1], i)).collect(),
    })
}

#[cfg(test)]
mod tests;
