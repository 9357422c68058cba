//! Clipping in homogeneous clip space: a triangle against the view volume's
//! six planes and the user's, one plane at a time (Sutherland–Hodgman), in
//! f64. A vertex made on a plane is the linear blend of the edge's two
//! vertices at the plane, position and values alike (values are linear in
//! clip space; "Viewports and Clipping (Direct3D 9)" defines the volume).

/// A vertex in clip space with the values it carries to the pixel shader.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipVertex {
    /// (x, y, z, w) as the vertex shader wrote `oPos`.
    pub pos: [f64; 4],
    /// One value per pixel-shader input it feeds.
    pub values: Vec<[f64; 4]>,
}

/// The view volume as planes p with dot(p, position) ≥ 0 inside:
/// −w ≤ x ≤ w, −w ≤ y ≤ w, 0 ≤ z ≤ w.
pub const VIEW_VOLUME: [[f64; 4]; 6] = [
    [1.0, 0.0, 0.0, 1.0],
    [-1.0, 0.0, 0.0, 1.0],
    [0.0, 1.0, 0.0, 1.0],
    [0.0, -1.0, 0.0, 1.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, -1.0, 1.0],
];

/// How far past the viewport the guard band reaches, in half-widths of
/// the viewport: |x|, |y| ≤ 1024·w.
pub const GUARD: f64 = 1024.0;

/// The planes a triangle is clipped against before the user's: near and
/// far (0 ≤ z ≤ w, which also keeps w ≥ 0) and a guard band of
/// [`GUARD`] viewports in x and y. Guard-band hardware clips only these
/// and scissors to the viewport: clipping at x = ±w or y = ±w would make
/// edges on the viewport's border, on which a row or column of pixel
/// centres lies exactly, and the clipped vertex, rounded, lands that edge
/// a hair inside or outside those centres. The guard band's own edges lie
/// a thousand viewports out, where no pixel is drawn; they keep the
/// perspective divide finite (a vertex at w = 0 is outside them unless it
/// is the origin).
pub const GUARD_BAND: [[f64; 4]; 6] = [
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, -1.0, 1.0],
    [1.0, 0.0, 0.0, GUARD],
    [-1.0, 0.0, 0.0, GUARD],
    [0.0, 1.0, 0.0, GUARD],
    [0.0, -1.0, 0.0, GUARD],
];

fn distance(plane: &[f64; 4], p: &[f64; 4]) -> f64 {
    plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] * p[3]
}

fn lerp(a: &ClipVertex, b: &ClipVertex, t: f64) -> ClipVertex {
    let mix = |x: f64, y: f64| x + (y - x) * t;
    ClipVertex {
        pos: std::array::from_fn(|c| mix(a.pos[c], b.pos[c])),
        values: a
            .values
            .iter()
            .zip(&b.values)
            .map(|(u, v)| std::array::from_fn(|c| mix(u[c], v[c])))
            .collect(),
    }
}

/// Whether every plane keeps `p` (a point's test: points are drawn whole
/// or not at all).
pub fn inside(planes: &[[f64; 4]], p: &[f64; 4]) -> bool {
    planes.iter().all(|pl| distance(pl, p) >= 0.0)
}

/// The polygon left of `polygon` on the inner side of every plane (empty
/// when nothing is). A polygon wholly inside comes back unchanged, its
/// vertices bit for bit.
pub fn clip(polygon: Vec<ClipVertex>, planes: &[[f64; 4]]) -> Vec<ClipVertex> {
    let mut poly = polygon;
    for plane in planes {
        if poly.is_empty() {
            break;
        }
        let d: Vec<f64> = poly.iter().map(|v| distance(plane, &v.pos)).collect();
        if d.iter().all(|&x| x >= 0.0) {
            continue;
        }
        let mut out = Vec::with_capacity(poly.len() + 1);
        for i in 0..poly.len() {
            let j = (i + 1) % poly.len();
            if d[i] >= 0.0 {
                out.push(poly[i].clone());
            }
            if (d[i] >= 0.0) != (d[j] >= 0.0) {
                // Computed from the inside vertex, so that both triangles
                // sharing the edge make the same new vertex.
                let (a, b, da, db) = if d[i] >= 0.0 {
                    (i, j, d[i], d[j])
                } else {
                    (j, i, d[j], d[i])
                };
                out.push(lerp(&poly[a], &poly[b], da / (da - db)));
            }
        }
        poly = out;
    }
    poly
}

/// The part of the segment `a`–`b` on the inner side of every plane, its
/// ends blended linearly (`None` when nothing is); an end inside every
/// plane comes back bit for bit.
pub fn clip_segment(
    a: ClipVertex,
    b: ClipVertex,
    planes: &[[f64; 4]],
) -> Option<(ClipVertex, ClipVertex)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for plane in planes {
        let (da, db) = (distance(plane, &a.pos), distance(plane, &b.pos));
        match (da >= 0.0, db >= 0.0) {
            (true, true) => {}
            (false, false) => return None,
            (false, true) => t0 = t0.max(da / (da - db)),
            (true, false) => t1 = t1.min(da / (da - db)),
        }
    }
    if t0 > t1 {
        return None;
    }
    let start = if t0 > 0.0 {
        lerp(&a, &b, t0)
    } else {
        a.clone()
    };
    let end = if t1 < 1.0 { lerp(&a, &b, t1) } else { b };
    Some((start, end))
}
