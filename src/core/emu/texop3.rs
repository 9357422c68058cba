//! The texld family on cube and volume samplers: three coordinates per
//! lane, and the level of detail from face coordinates (cubes) or 3D
//! lengths (volumes). The rules are in `layered.rs`'s module docs.

// Lane loops index several fixed-size rows with one lane index.
#![allow(clippy::needless_range_loop)]

use super::compile::{DstOp, SamplerOp, SrcOp, TexKind};
use super::exec::Worker;
use super::layered::{face_coords, face_gradient, major_face};
use super::math::modify;
use super::quad::lod_of_len2;
use super::sample::Sampler;
use super::LANES;

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
