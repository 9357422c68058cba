//! Triangle set-up as Direct3D 9 does it, for the emulator's draws: primitive
//! assembly, the viewport transform, facing and culling, which pixels a
//! triangle covers, and each interpolated value as a plane over the target.
//!
//! The emulator runs a shader over a whole target with inputs that vary
//! linearly (`base + x·ddx + y·ddy`). A triangle with w = 1 at every vertex
//! gives exactly that: its attributes are affine in screen space. So a draw
//! of triangles becomes one emulator draw per triangle (or per run of
//! triangles with the same planes and facing), whose results are kept where
//! the triangle covers the target. Pixels next to an edge see the plane
//! extended beyond the triangle — what a GPU's helper pixels compute too.
//!
//! The rules are `core/raster`'s (assembly, facing and culling, the
//! top-left rule), stated and tested there; this file adds what only the
//! corpus needs, each from Direct3D 9's documentation:
//! * pixel (x, y) is sampled at screen point (x, y): D3D9 puts pixel centres
//!   on integer coordinates ("Directly Mapping Texels to Pixels"); a clip-space
//!   vertex (x, y) lands at ((x + 1)·W/2, (1 − y)·H/2), the viewport being
//!   the whole render target (SetRenderTarget resets it);
//! * a pixel is covered when its centre is inside the triangle, or on a top
//!   or left edge (the top-left filling convention, "Rasterization Rules");
//! * front faces are clockwise on screen; D3DCULL_CCW (the default) drops
//!   counter-clockwise triangles, D3DCULL_CW clockwise ones; a triangle
//!   strip reverses the winding of every other triangle so that all of them
//!   face the same way (D3DPRIMITIVETYPE);
//! * flat shading takes colour values from the first vertex of each triangle
//!   — vertex 3i of a list, vertex i of a strip — except the specular
//!   alpha, which is interpolated (D3DSHADEMODE).
//!
//! Perspective (w ≠ 1) is not modelled: interpolation would no longer be
//! affine in screen space, and the emulator's inputs could not express it.

use super::case::{Cull, Positions, Primitive};
use crate::core::emu::{Face, LinearInput};
use crate::core::raster;

/// A vertex on screen: position in pixels and its values, one per input
/// register the shader reads.
#[derive(Clone, Debug, PartialEq)]
pub struct ScreenVertex {
    pub x: f64,
    pub y: f64,
    pub values: Vec<[f32; 4]>,
}

/// A triangle after assembly and culling, wound clockwise on screen.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    pub v: [ScreenVertex; 3],
    /// Index into `v` of the vertex flat shading takes its colour from.
    pub provoking: usize,
    pub face: Face,
    /// The same corners as the rasteriser holds them, for coverage.
    shape: raster::Triangle,
}

/// `v` as the rasteriser's vertex (position only).
fn corner(v: &ScreenVertex) -> raster::ScreenVertex {
    raster::ScreenVertex {
        x: v.x,
        y: v.y,
        z: 0.0,
        rhw: 1.0,
        values: Vec::new(),
    }
}

/// The screen position of a vertex given as `positions` on a `width ×
/// height` target.
pub fn to_screen(
    p: &[f64],
    positions: Positions,
    width: u32,
    height: u32,
) -> Result<(f64, f64), String> {
    let (w, name) = match positions {
        Positions::Clip => (if p.len() == 4 { p[3] } else { 1.0 }, "w"),
        Positions::Screen => (if p.len() == 4 { p[3] } else { f64::NAN }, "rhw"),
    };
    if !(3..=4).contains(&p.len()) || (positions == Positions::Screen && p.len() != 4) {
        return Err(format!(
            "a position has {} components; clip space takes (x, y, z[, w]), screen space (x, y, z, rhw)",
            p.len()
        ));
    }
    if !p.iter().all(|c| c.is_finite()) {
        return Err("a position is not finite".into());
    }
    if w != 1.0 {
        return Err(format!(
            "{name} = {w}: only {name} = 1 is modelled (perspective-correct interpolation is not)"
        ));
    }
    Ok(match positions {
        Positions::Clip => (
            (p[0] + 1.0) * f64::from(width) / 2.0,
            (1.0 - p[1]) * f64::from(height) / 2.0,
        ),
        Positions::Screen => (p[0], p[1]),
    })
}

/// Assembles `vertices` into triangles, drops the culled and degenerate
/// ones, and winds the rest clockwise.
pub fn assemble(
    vertices: &[ScreenVertex],
    primitive: Primitive,
    cull: Cull,
) -> Result<Vec<Triangle>, String> {
    let kind = match primitive {
        Primitive::TriangleList => raster::Primitive::TriangleList,
        Primitive::TriangleStrip => raster::Primitive::TriangleStrip,
    };
    let mut out = Vec::new();
    for a in raster::assemble(kind, vertices.len())? {
        let [p, q, r] = a.corners.map(|i| corner(&vertices[i]));
        let Some(shape) = raster::Triangle::new(p, q, r) else {
            continue; // degenerate: covers nothing
        };
        if cull.drops(shape.face) {
            continue;
        }
        // Clockwise order, as the rasteriser rewinds it.
        let order = if shape.face == Face::Front {
            a.corners
        } else {
            [a.corners[0], a.corners[2], a.corners[1]]
        };
        out.push(Triangle {
            v: order.map(|i| vertices[i].clone()),
            provoking: order.iter().position(|&i| i == a.provoking).unwrap_or(0),
            face: shape.face,
            shape,
        });
    }
    Ok(out)
}

impl Triangle {
    /// Whether the pixel centred at (`x`, `y`) is covered, with the
    /// top-left rule for centres exactly on an edge.
    pub fn covers(&self, x: f64, y: f64) -> bool {
        self.shape.covers(x, y)
    }

    /// The pixels the triangle covers on a `width × height` target, as
    /// row-major indices.
    pub fn pixels(&self, width: u32, height: u32) -> impl Iterator<Item = usize> + '_ {
        let xs = self.v.iter().map(|v| v.x);
        let ys = self.v.iter().map(|v| v.y);
        let clamp = |v: f64, hi: u32| v.clamp(0.0, f64::from(hi)) as u32;
        let x0 = clamp(xs.clone().fold(f64::INFINITY, f64::min).floor(), width);
        let x1 = clamp(xs.fold(f64::NEG_INFINITY, f64::max).ceil() + 1.0, width);
        let y0 = clamp(ys.clone().fold(f64::INFINITY, f64::min).floor(), height);
        let y1 = clamp(ys.fold(f64::NEG_INFINITY, f64::max).ceil() + 1.0, height);
        (y0..y1).flat_map(move |y| {
            (x0..x1)
                .filter(move |&x| self.covers(f64::from(x), f64::from(y)))
                .map(move |x| y as usize * width as usize + x as usize)
        })
    }

    /// Value `k` as a plane over the target: exact in f64 through the three
    /// vertices, rounded to f32 once. `flat` marks the components that take
    /// the provoking vertex's value instead.
    pub fn plane(&self, k: usize, flat: [bool; 4]) -> LinearInput {
        let [p0, p1, p2] = &self.v;
        let (d1x, d1y, d2x, d2y) = (p1.x - p0.x, p1.y - p0.y, p2.x - p0.x, p2.y - p0.y);
        let det = d1x * d2y - d2x * d1y;
        let mut out = LinearInput::default();
        for (c, &is_flat) in flat.iter().enumerate() {
            if is_flat {
                out.base[c] = self.v[self.provoking].values[k][c];
                continue;
            }
            let a0 = f64::from(p0.values[k][c]);
            let (e1, e2) = (
                f64::from(p1.values[k][c]) - a0,
                f64::from(p2.values[k][c]) - a0,
            );
            let ddx = (e1 * d2y - e2 * d1y) / det;
            let ddy = (e2 * d1x - e1 * d2x) / det;
            out.ddx[c] = ddx as f32;
            out.ddy[c] = ddy as f32;
            out.base[c] = (a0 - ddx * p0.x - ddy * p0.y) as f32;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, value: f32) -> ScreenVertex {
        ScreenVertex {
            x,
            y,
            values: vec![[value, 0.0, 0.0, 1.0]],
        }
    }

    /// The quad Wine draws most: a strip over the whole 640×480 target.
    fn full_strip() -> Vec<ScreenVertex> {
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| {
                let (sx, sy) = to_screen(&[x, y, 0.1], Positions::Clip, 640, 480).unwrap();
                v(sx, sy, i as f32)
            })
            .collect()
    }

    #[test]
    fn clip_space_maps_to_d3d9_screen_coordinates() {
        let s = |x, y| to_screen(&[x, y, 0.5], Positions::Clip, 640, 480).unwrap();
        assert_eq!(s(-1.0, 1.0), (0.0, 0.0));
        assert_eq!(s(1.0, -1.0), (640.0, 480.0));
        assert_eq!(s(0.0, 0.0), (320.0, 240.0));
        assert_eq!(
            to_screen(&[5.0, 6.0, 0.1, 1.0], Positions::Screen, 8, 8).unwrap(),
            (5.0, 6.0)
        );
        for (p, pos) in [
            (vec![0.0, 0.0, 0.0, 2.0], Positions::Clip),
            (vec![0.0, 0.0, 0.0], Positions::Screen),
            (vec![0.0, 0.0], Positions::Clip),
            (vec![f64::NAN, 0.0, 0.0], Positions::Clip),
        ] {
            assert!(to_screen(&p, pos, 8, 8).is_err(), "{p:?}");
        }
    }

    #[test]
    fn a_strip_quad_covers_every_pixel_once_and_faces_front() {
        let tris = assemble(&full_strip(), Primitive::TriangleStrip, Cull::Ccw).unwrap();
        assert_eq!(tris.len(), 2);
        assert!(tris.iter().all(|t| t.face == Face::Front));
        let mut hits = vec![0u8; 640 * 480];
        for t in &tris {
            for i in t.pixels(640, 480) {
                hits[i] += 1;
            }
        }
        assert!(hits.iter().all(|&h| h == 1));
        // Strip triangle i takes its flat colour from vertex i.
        assert_eq!(tris[0].v[tris[0].provoking].values[0][0], 0.0);
        assert_eq!(tris[1].v[tris[1].provoking].values[0][0], 1.0);
    }

    #[test]
    fn culling_drops_the_faces_the_mode_names() {
        // Counter-clockwise on screen: a back face.
        let back = vec![v(0.0, 0.0, 0.0), v(0.0, 4.0, 0.0), v(4.0, 0.0, 0.0)];
        let faces = |cull| {
            assemble(&back, Primitive::TriangleList, cull)
                .unwrap()
                .iter()
                .map(|t| t.face)
                .collect::<Vec<_>>()
        };
        assert_eq!(faces(Cull::Ccw), vec![]);
        assert_eq!(faces(Cull::Cw), vec![Face::Back]);
        assert_eq!(faces(Cull::None), vec![Face::Back]);
        let degenerate = vec![v(0.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(2.0, 2.0, 0.0)];
        assert!(assemble(&degenerate, Primitive::TriangleList, Cull::None)
            .unwrap()
            .is_empty());
        assert!(assemble(&back[..2], Primitive::TriangleList, Cull::None).is_err());
        assert!(assemble(&back[..2], Primitive::TriangleStrip, Cull::None).is_err());
    }

    #[test]
    fn the_top_left_rule_decides_centres_on_edges() {
        // A 4×4 square from (0, 0) to (4, 4) as two triangles: pixels with
        // centres on the top and left edges are in, right and bottom out.
        let square = vec![
            v(0.0, 0.0, 0.0),
            v(4.0, 0.0, 0.0),
            v(0.0, 4.0, 0.0),
            v(4.0, 4.0, 0.0),
        ];
        let tris = assemble(&square, Primitive::TriangleStrip, Cull::None).unwrap();
        let mut covered: Vec<usize> = tris.iter().flat_map(|t| t.pixels(8, 8)).collect();
        covered.sort();
        let want: Vec<usize> = (0..4)
            .flat_map(|y| (0..4).map(move |x| y * 8 + x))
            .collect();
        assert_eq!(covered, want);
    }

    #[test]
    fn planes_interpolate_at_pixel_centres_and_flat_takes_the_provoking_vertex() {
        let tri = assemble(
            &[v(0.0, 0.0, 1.0), v(8.0, 0.0, 3.0), v(0.0, 4.0, 5.0)],
            Primitive::TriangleList,
            Cull::None,
        )
        .unwrap()
        .remove(0);
        let p = tri.plane(0, [false; 4]);
        // value = 1 + x/4 + y
        assert_eq!(p.at(0.0, 0.0)[0], 1.0);
        assert_eq!(p.at(4.0, 2.0)[0], 4.0);
        assert_eq!(p.ddx[0], 0.25);
        assert_eq!(p.ddy[0], 1.0);
        let flat = tri.plane(0, [true, false, false, false]);
        assert_eq!((flat.base[0], flat.ddx[0], flat.ddy[0]), (1.0, 0.0, 0.0));
    }
}
