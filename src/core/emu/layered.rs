//! Cube and volume textures in the emulator: cube face selection, volume
//! addressing and trilinear filtering, and the texld family on both, with
//! their levels of detail.
//!
//! Kept apart from the 2D path (`sample.rs`, `texop.rs`), whose lane loops
//! are tuned for the luminance passes, because these samplers take three
//! coordinates and each sample first finds where it lands.
//!
//! # Cube textures
//! The face is the major axis of the direction (x, y, z), the component of
//! largest magnitude; ties go to z, then y (|z| ≥ |x|, |y| picks a z face;
//! else |y| ≥ |x| a y face), as Direct3D's functional specification orders
//! them. The face's (s, t) are Direct3D's cube-map table (MS "Cubic
//! Environment Mapping"; GL's table is the same):
//!
//! | face | sc | tc | ma |
//! |---|---|---|---|
//! | +X | −z | −y | x |
//! | −X | +z | −y | x |
//! | +Y | +x | +z | y |
//! | −Y | +x | −z | y |
//! | +Z | +x | −y | z |
//! | −Z | −x | −y | z |
//!
//! s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2, read as a 2D coordinate of the
//! face (t = 0 its top row). Filtering stays within the face: each face is
//! addressed with CLAMP, so a bilinear tap past a face's edge reads the
//! edge texel, as D3D9 hardware does without seamless filtering. Each face
//! has its own mip chain; all faces have the same number of levels.
//!
//! The level of detail uses the face coordinates: for `texld`, `texldp`
//! and `texldb` the quad's three lanes (top-left, top-right, bottom-left)
//! are all projected on the top-left lane's face, and λ is the 2D formula
//! of `texop.rs` on (s·E, t·E), E the edge of level 0. `texldd` maps the
//! given direction gradients to face gradients by the quotient rule,
//! ∂s = (∂sc − s′·∂ma)/(2·|ma|) with s′ = sc/|ma| (and ∂ma the gradient of
//! the major component with the face's sign). `texldl` takes src0.w.
//!
//! # Volume textures
//! (u, v, w) address the three sides as 2D textures address two, with
//! ADDRESSU, ADDRESSV and ADDRESSW; point picks the texel ⌊u·W⌋, ⌊v·H⌋,
//! ⌊w·D⌋, linear blends the eight around (u·W − ½, v·H − ½, w·D − ½)
//! (the 2D bilinear weights, then slices by the w weight). λ uses 3D
//! lengths: dX = (∂u/∂x·W, ∂v/∂x·H, ∂w/∂x·D). MIPFILTER LINEAR then blends
//! two levels: trilinear filtering of a 3D chain.

use super::{Address, Filter, SamplerState};
use crate::core::image::VolumeLevel;

/// Largest texture side accepted (keeps texel coordinates below 2^23, where
/// `sample.rs`'s `floor_index` is exact).
pub const MAX_TEXTURE_SIDE: u32 = 1 << 22;

/// A coordinate as the sampler addresses it: +∞ is taken as 2 and −∞ as
/// −1 (past the far and near edges, whatever the level's size), NaN as 0;
/// finite values are unchanged. Under CLAMP a lookup at ±∞ so reads the
/// edge texel, as Direct3D 9 hardware does, and under BORDER the border
/// colour (see docs/textures.md, "Non-finite coordinates", for the rule
/// under each address mode and its evidence). The translation applies the
/// same replacement (`core/translate/texture.rs`), so both backends
/// agree. Kept here because the 2D path (`sample.rs`) and the volume path
/// both use it.
#[inline(always)]
pub(super) fn finite_coordinate(u: f32) -> f32 {
    if u.is_nan() {
        0.0
    } else if u == f32::INFINITY {
        2.0
    } else if u == f32::NEG_INFINITY {
        -1.0
    } else {
        u
    }
}

/// Applies an address mode to an integer texel index; `None` = border.
#[inline(always)]
pub(super) fn address(t: i64, n: i64, mode: Address) -> Option<i64> {
    match mode {
        Address::Wrap => Some(t.rem_euclid(n)),
        Address::Mirror => {
            // -(t + 1) cannot overflow for negative t.
            let t = if t < 0 { -(t + 1) } else { t };
            let flip = (t / n) & 1 == 1;
            let t = t % n;
            Some(if flip { n - 1 - t } else { t })
        }
        Address::Clamp => Some(t.clamp(0, n - 1)),
        Address::MirrorOnce => {
            let t = if t < 0 { -(t + 1) } else { t };
            Some(t.min(n - 1))
        }
        Address::Border => {
            if (0..n).contains(&t) {
                Some(t)
            } else {
                None
            }
        }
    }
}

/// The face (0 = +X … 5 = −Z) and its (s, t) for direction `p`.
#[inline]
pub(super) fn cube_face(p: [f32; 3]) -> (usize, f32, f32) {
    let f = major_face(p);
    let (s, t) = face_coords(f, p);
    (f, s, t)
}

/// The face direction `p` selects (ties: z, then y).
#[inline]
pub(super) fn major_face(p: [f32; 3]) -> usize {
    let [ax, ay, az] = p.map(f32::abs);
    let (axis, v) = if az >= ax && az >= ay {
        (2, p[2])
    } else if ay >= ax {
        (1, p[1])
    } else {
        (0, p[0])
    };
    2 * axis + usize::from(v.is_sign_negative())
}

/// (sc, tc, ma) of direction `p` on face `f` (Direct3D's table).
#[inline]
fn face_axes(f: usize, p: [f32; 3]) -> (f32, f32, f32) {
    let [x, y, z] = p;
    match f {
        0 => (-z, -y, x),
        1 => (z, -y, x),
        2 => (x, z, y),
        3 => (x, -z, y),
        4 => (x, -y, z),
        _ => (-x, -y, z),
    }
}

/// (s, t) of direction `p` projected on face `f`.
#[inline]
pub(super) fn face_coords(f: usize, p: [f32; 3]) -> (f32, f32) {
    let (sc, tc, ma) = face_axes(f, p);
    let m = ma.abs();
    ((sc / m + 1.0) * 0.5, (tc / m + 1.0) * 0.5)
}

/// The face-coordinate gradient (∂s, ∂t) of direction `p` on face `f` for
/// the direction gradient `g` (quotient rule; see the module docs).
#[inline]
pub(super) fn face_gradient(f: usize, p: [f32; 3], g: [f32; 3]) -> (f32, f32) {
    let (sc, tc, ma) = face_axes(f, p);
    let (dsc, dtc, dma) = face_axes(f, g);
    let m = ma.abs();
    let dm = if ma.is_sign_negative() { -dma } else { dma };
    (
        (dsc - sc / m * dm) / (2.0 * m),
        (dtc - tc / m * dm) / (2.0 * m),
    )
}

/// One level of a volume texture with its addressing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Level3<'a> {
    texels: &'a [[f32; 4]],
    w: i64,
    h: i64,
    d: i64,
    size: [f32; 3],
    address: [Address; 3],
    border: [f32; 4],
}

impl<'a> Level3<'a> {
    /// Checks a volume level and precomputes its sizes.
    pub(super) fn new(l: &'a VolumeLevel, state: &SamplerState) -> Result<Level3<'a>, String> {
        let max = MAX_TEXTURE_SIDE;
        if l.width > max || l.height > max || l.depth > max {
            return Err(format!(
                "size {}x{}x{} exceeds {max} per side",
                l.width, l.height, l.depth
            ));
        }
        let n = l.width as usize * l.height as usize * l.depth as usize;
        if n == 0 || l.texels.len() != n {
            return Err(format!(
                "{}x{}x{} needs {n} texels, got {}",
                l.width,
                l.height,
                l.depth,
                l.texels.len()
            ));
        }
        Ok(Level3 {
            texels: &l.texels,
            w: l.width as i64,
            h: l.height as i64,
            d: l.depth as i64,
            size: [l.width as f32, l.height as f32, l.depth as f32],
            address: [state.address_u, state.address_v, state.address_w],
            border: state.border,
        })
    }

    /// Depth of the level in slices.
    pub(super) fn depth(&self) -> f32 {
        self.size[2]
    }

    /// The texel at (x, y) of slice z, each already addressed (`None`: the
    /// border colour).
    #[inline]
    fn fetch(&self, x: Option<i64>, y: Option<i64>, z: Option<i64>) -> [f32; 4] {
        match (x, y, z) {
            (Some(x), Some(y), Some(z)) => self
                .texels
                .get(((z * self.h + y) * self.w + x) as usize)
                .copied()
                .unwrap_or(self.border),
            _ => self.border,
        }
    }

    /// One sample at (u, v, w) with `filter` (see the module docs).
    pub(super) fn sample(&self, filter: Filter, p: [f32; 3]) -> [f32; 4] {
        let p = p.map(finite_coordinate);
        let n = [self.w, self.h, self.d];
        let a = self.address;
        match filter {
            Filter::Point => {
                let t: [Option<i64>; 3] = std::array::from_fn(|i| {
                    address((p[i] * self.size[i]).floor() as i64, n[i], a[i])
                });
                self.fetch(t[0], t[1], t[2])
            }
            Filter::Linear => {
                let f: [f32; 3] = std::array::from_fn(|i| p[i] * self.size[i] - 0.5);
                let t = f.map(f32::floor);
                let wgt: [f32; 3] = std::array::from_fn(|i| f[i] - t[i]);
                let taps = |i: usize| {
                    let t0 = t[i] as i64;
                    [
                        address(t0, n[i], a[i]),
                        address(t0.saturating_add(1), n[i], a[i]),
                    ]
                };
                let (xs, ys, zs) = (taps(0), taps(1), taps(2));
                let slice = |z: Option<i64>| -> [f32; 4] {
                    let c00 = self.fetch(xs[0], ys[0], z);
                    let c10 = self.fetch(xs[1], ys[0], z);
                    let c01 = self.fetch(xs[0], ys[1], z);
                    let c11 = self.fetch(xs[1], ys[1], z);
                    std::array::from_fn(|c| {
                        let top = c00[c] * (1.0 - wgt[0]) + c10[c] * wgt[0];
                        let bottom = c01[c] * (1.0 - wgt[0]) + c11[c] * wgt[0];
                        top * (1.0 - wgt[1]) + bottom * wgt[1]
                    })
                };
                let (a0, b0) = (slice(zs[0]), slice(zs[1]));
                std::array::from_fn(|c| a0[c] * (1.0 - wgt[2]) + b0[c] * wgt[2])
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_axis_selects_its_face_with_the_table_coordinates() {
        // The centre of every face is (0.5, 0.5).
        let dirs = [
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ];
        for (i, d) in dirs.iter().enumerate() {
            assert_eq!(cube_face(*d), (i, 0.5, 0.5), "{d:?}");
        }
        // +X: s from −z, t from −y: (x=1, y=0.5, z=0.5) → s = 0.25, t = 0.25.
        assert_eq!(cube_face([1.0, 0.5, 0.5]), (0, 0.25, 0.25));
        // −Y: s from +x, t from −z.
        assert_eq!(cube_face([0.5, -1.0, 0.5]), (3, 0.75, 0.25));
    }

    #[test]
    fn ties_go_to_z_then_y() {
        assert_eq!(major_face([1.0, 1.0, 1.0]), 4);
        assert_eq!(major_face([1.0, -1.0, 0.5]), 3);
        assert_eq!(major_face([-1.0, 0.5, -1.0]), 5);
    }

    #[test]
    fn face_gradient_matches_a_difference_quotient() {
        let p = [0.9f32, 0.3, -0.2];
        let g = [0.01f32, 0.02, -0.03];
        let f = major_face(p);
        let (s0, t0) = face_coords(f, p);
        let q = [p[0] + g[0], p[1] + g[1], p[2] + g[2]];
        let (s1, t1) = face_coords(f, q);
        let (ds, dt) = face_gradient(f, p, g);
        // First-order: the difference differs by O(|g|²) ≈ 1e-3 relative.
        assert!((ds - (s1 - s0)).abs() < 2e-4, "{ds} {}", s1 - s0);
        assert!((dt - (t1 - t0)).abs() < 2e-4, "{dt} {}", t1 - t0);
    }
}
