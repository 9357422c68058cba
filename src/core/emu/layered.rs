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

use super::compile::{DstOp, SamplerOp, SrcOp, TexKind};
use super::exec::Worker;
use super::math::modify;
use super::quad::lod_of_len2;
use super::sample::{Level, Sampler};
use super::{Address, Filter, SamplerState, LANES};
use crate::core::image::{Texture, VolumeLevel};

/// The face (0 = +X … 5 = −Z) and its (s, t) for direction `p`.
#[inline]
pub(super) fn cube_face(p: [f32; 3]) -> (usize, f32, f32) {
    let f = major_face(p);
    let (s, t) = face_coords(f, p);
    (f, s, t)
}

/// The face direction `p` selects (ties: z, then y).
#[inline]
fn major_face(p: [f32; 3]) -> usize {
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
fn face_coords(f: usize, p: [f32; 3]) -> (f32, f32) {
    let (sc, tc, ma) = face_axes(f, p);
    let m = ma.abs();
    ((sc / m + 1.0) * 0.5, (tc / m + 1.0) * 0.5)
}

/// The face-coordinate gradient (∂s, ∂t) of direction `p` on face `f` for
/// the direction gradient `g` (quotient rule; see the module docs).
#[inline]
fn face_gradient(f: usize, p: [f32; 3], g: [f32; 3]) -> (f32, f32) {
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
    /// Slice 0 as a 2D level: its sizes and its texel fetch, reused for
    /// every slice by offsetting rows (slices are stacked below it).
    plane: Level<'a>,
    d: i64,
    df: f32,
    h: i64,
    aw: Address,
    border: [f32; 4],
    filter_slices: &'a [[f32; 4]],
    w: usize,
}

impl<'a> Level3<'a> {
    /// Checks a volume level and precomputes its sizes.
    pub(super) fn new(l: &'a VolumeLevel, state: &SamplerState) -> Result<Level3<'a>, String> {
        let max = super::sample::MAX_TEXTURE_SIDE;
        if l.width > max || l.height > max || l.depth > max {
            return Err(format!(
                "size {}x{}x{} exceeds {max} per side",
                l.width, l.height, l.depth
            ));
        }
        let n = l.width as usize * l.height as usize;
        let plane = Level::new(
            &Texture {
                width: l.width,
                height: l.height,
                texels: l.texels.get(..n).ok_or("no texels")?,
            },
            state,
        )?;
        if l.texels.len() != n * l.depth as usize {
            return Err(format!(
                "{}x{}x{} needs {} texels, got {}",
                l.width,
                l.height,
                l.depth,
                n * l.depth as usize,
                l.texels.len()
            ));
        }
        Ok(Level3 {
            plane,
            d: l.depth as i64,
            df: l.depth as f32,
            h: l.height as i64,
            aw: state.address_w,
            border: state.border,
            filter_slices: &l.texels,
            w: l.width as usize,
        })
    }

    /// Depth of the level in slices.
    pub(super) fn depth(&self) -> f32 {
        self.df
    }

    /// The texel at (x, y) of slice z, each already addressed (`None`: the
    /// border colour).
    #[inline]
    fn fetch(&self, x: Option<i64>, y: Option<i64>, z: Option<i64>) -> [f32; 4] {
        match (x, y, z) {
            (Some(x), Some(y), Some(z)) => self
                .filter_slices
                .get(((z * self.h + y) as usize) * self.w + x as usize)
                .copied()
                .unwrap_or(self.border),
            _ => self.border,
        }
    }

    /// One sample at (u, v, w) with `filter` (see the module docs).
    pub(super) fn sample(&self, filter: Filter, p: [f32; 3]) -> [f32; 4] {
        let (wf, hf) = self.plane.size();
        let (wi, au, av) = (wf as i64, self.plane.address_u(), self.plane.address_v());
        let addr = |t: i64, n: i64, m: Address| super::sample::address(t, n, m);
        match filter {
            Filter::Point => {
                let x = (p[0] * wf).floor() as i64;
                let y = (p[1] * hf).floor() as i64;
                let z = (p[2] * self.df).floor() as i64;
                self.fetch(
                    addr(x, wi, au),
                    addr(y, self.h, av),
                    addr(z, self.d, self.aw),
                )
            }
            Filter::Linear => {
                let f = [p[0] * wf - 0.5, p[1] * hf - 0.5, p[2] * self.df - 0.5];
                let t = f.map(f32::floor);
                let wgt = [f[0] - t[0], f[1] - t[1], f[2] - t[2]];
                let (x0, y0, z0) = (t[0] as i64, t[1] as i64, t[2] as i64);
                let xs = [addr(x0, wi, au), addr(x0.saturating_add(1), wi, au)];
                let ys = [addr(y0, self.h, av), addr(y0.saturating_add(1), self.h, av)];
                let zs = [
                    addr(z0, self.d, self.aw),
                    addr(z0.saturating_add(1), self.d, self.aw),
                ];
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
                let (a, b) = (slice(zs[0]), slice(zs[1]));
                std::array::from_fn(|c| a[c] * (1.0 - wgt[2]) + b[c] * wgt[2])
            }
        }
    }
}

impl Worker<'_, '_> {
    /// The (x, y, z) of every lane's texture coordinate, with `texldp`'s
    /// division by w, and every lane's w.
    fn coords_3d(&self, a: SrcOp, projected: bool) -> ([[f32; 3]; LANES], [f32; LANES]) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let rows = [
            self.row(a, 0),
            self.row(a, 1),
            self.row(a, 2),
            self.row(a, 3),
        ];
        let mut p = [[0f32; 3]; LANES];
        let mut w = [0f32; LANES];
        for l in 0..n {
            let v = rows.map(|r| modify(self.rows[r][l], am, ax));
            w[l] = v[3];
            p[l] = if projected {
                [v[0] / v[3], v[1] / v[3], v[2] / v[3]]
            } else {
                [v[0], v[1], v[2]]
            };
        }
        (p, w)
    }

    /// λ from one pair of coordinate differences (∂/∂x, ∂/∂y) of lane
    /// coordinate `p`, before the bias.
    fn lod_3d(sm: &Sampler, p: [f32; 3], gx: [f32; 3], gy: [f32; 3]) -> f32 {
        let (wf, hf) = sm.size();
        let len2 = |g: [f32; 3]| -> f32 {
            if sm.is_cube() {
                let f = major_face(p);
                let (ds, dt) = face_gradient(f, p, g);
                (ds * wf) * (ds * wf) + (dt * hf) * (dt * hf)
            } else {
                let d = sm.depth();
                let v = [g[0] * wf, g[1] * hf, g[2] * d];
                v[0] * v[0] + v[1] * v[1] + v[2] * v[2]
            }
        };
        lod_of_len2(len2(gx).max(len2(gy)))
    }

    /// Quad-implicit λ of lane `l` (coarse: the top-left lane's
    /// differences; a cube's neighbours are projected on its face).
    fn implicit_lod_3d(sm: &Sampler, p: &[[f32; 3]; LANES], l: usize) -> f32 {
        let q = l & !3;
        let (p0, p1, p2) = (p[q], p[q + 1], p[q + 2]);
        let (wf, hf) = sm.size();
        let len2 = if sm.is_cube() {
            let f = major_face(p0);
            let (s0, t0) = face_coords(f, p0);
            let d = |pn: [f32; 3]| {
                let (s, t) = face_coords(f, pn);
                let (ds, dt) = ((s - s0) * wf, (t - t0) * hf);
                ds * ds + dt * dt
            };
            d(p1).max(d(p2))
        } else {
            let depth = sm.depth();
            let d = |pn: [f32; 3]| {
                let v = [
                    (pn[0] - p0[0]) * wf,
                    (pn[1] - p0[1]) * hf,
                    (pn[2] - p0[2]) * depth,
                ];
                v[0] * v[0] + v[1] * v[1] + v[2] * v[2]
            };
            d(p1).max(d(p2))
        };
        lod_of_len2(len2)
    }

    /// The texld family (`grads`: texldd's ∂/∂x and ∂/∂y sources) on a
    /// cube or volume sampler; see the module docs.
    #[allow(clippy::too_many_arguments)] // one instruction's operands
    pub(super) fn texld_3d(
        &mut self,
        d: DstOp,
        a: SrcOp,
        s: SamplerOp,
        sm: &Sampler,
        kind: TexKind,
        site: u16,
        grads: Option<(SrcOp, SrcOp)>,
    ) {
        let n = self.span();
        let (p, w) = self.coords_3d(a, kind == TexKind::LdP && grads.is_none());
        let bias = sm.bias();
        let mut lod = [f32::NEG_INFINITY; LANES];
        let mut seen = (f32::INFINITY, f32::NEG_INFINITY);
        let implicit = grads.is_none() && kind != TexKind::LdL;
        if sm.lod_matters() || (implicit && self.ctx.record_lod) {
            for l in 0..n {
                lod[l] = match grads {
                    Some((gx, gy)) => {
                        let g = |src: SrcOp| {
                            let (m, x) = src.mod_bits();
                            let r = [self.row(src, 0), self.row(src, 1), self.row(src, 2)];
                            r.map(|r| modify(self.rows[r][l], m, x))
                        };
                        Self::lod_3d(sm, p[l], g(gx), g(gy)) + bias
                    }
                    None if kind == TexKind::LdL => w[l] + bias,
                    None if kind == TexKind::LdB => Self::implicit_lod_3d(sm, &p, l) + bias + w[l],
                    None => Self::implicit_lod_3d(sm, &p, l) + bias,
                };
                if (self.exec >> l) & 1 != 0 {
                    seen = (seen.0.min(lod[l]), seen.1.max(lod[l]));
                }
            }
        }
        if implicit && self.ctx.record_lod && seen.0 <= seen.1 {
            if let Some(st) = self.sites.get_mut(site as usize) {
                st.lod_min = st.lod_min.min(seen.0);
                st.lod_max = st.lod_max.max(seen.1);
            }
        }
        if !sm.lod_matters() {
            lod = [f32::NEG_INFINITY; LANES];
        }
        let swz: [usize; 4] = std::array::from_fn(|c| ((s.swz >> (2 * c)) & 3) as usize);
        for l in 0..n {
            let t = sm.sample_3d(p[l], lod[l]);
            for c in 0..4 {
                self.tmp[c][l] = t[swz[c]];
            }
        }
        self.store::<false>(d, d.mask());
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
