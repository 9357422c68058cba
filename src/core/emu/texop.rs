//! The texld family: coordinates, level of detail from the quad's
//! gradients, sampling — and what the quads record about it.
//!
//! # Level of detail (facts sheet §5)
//!
//! Direct3D 9 gives no LOD formula; ps30 uses the D3D11.3 isotropic one
//! (§7.18.11), the nearest public definition. With (u, v) the coordinate
//! and (W, H) the size of level 0,
//!
//! * dX = (∂u/∂x·W, ∂v/∂x·H), dY = (∂u/∂y·W, ∂v/∂y·H), and
//!   λ = log2(max(|dX|, |dY|)) (Euclidean lengths), computed as
//!   ½·log2(max(|dX|², |dY|²)); a zero gradient gives λ = −∞;
//! * `texld`, `texldp`, `texldb` take ∂/∂x and ∂/∂y from the quad, coarse
//!   like `dsx`/`dsy`: one pair per quad, top-right − top-left and
//!   bottom-left − top-left of the coordinate *as this instruction computes
//!   it* in each lane (`texldp`: after the division by w). An inactive
//!   neighbour contributes whatever its register holds — on hardware that is
//!   undefined, so every execution with part of a quad is counted (see
//!   [`super::GradientSite`]);
//! * `texldb` adds its per-pixel src0.w; `texldl` uses src0.w as λ;
//!   `texldd` uses src2/src3 (.xy) as ∂/∂x and ∂/∂y per pixel;
//! * D3DSAMP_MIPMAPLODBIAS is added to every λ; level choice and filters
//!   are in `sample.rs`.
//!
//! λ is computed only where it can change a sample
//! ([`super::sample::Sampler::lod_matters`]) or where the quads record it
//! (the implicit-LOD instructions, for [`super::GradientSite::lod`]), so a
//! shader sampling a single-level texture pays only the per-quad statistic.

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::compile::{DstOp, SamplerOp, SrcOp, TexKind};
use super::exec::Worker;
use super::math::modify;
use super::quad::{lod_of_len2, quad_len2, quad_len2_range, quads_all, quads_any};
use super::sample::{Sampler, UNBOUND};
use super::LANES;

impl Worker<'_, '_> {
    /// Records that the executing lanes ran gradient site `site`.
    #[inline(always)]
    pub(super) fn note_site(&mut self, site: u16) {
        let e = self.exec;
        let any = quads_any(e);
        let div = any & !quads_all(e);
        if let Some(st) = self.sites.get_mut(site as usize) {
            st.quads |= any;
            st.divergent |= div;
            st.executions += any.count_ones() as u64;
            st.divergent_executions += div.count_ones() as u64;
        }
    }

    #[inline(always)]
    fn note_lod(&mut self, site: u16, lo: f32, hi: f32) {
        if !self.ctx.record_lod {
            return;
        }
        if let Some(st) = self.sites.get_mut(site as usize) {
            st.lod_min = st.lod_min.min(lo);
            st.lod_max = st.lod_max.max(hi);
        }
    }

    /// Texture coordinates of every lane into `aux` (`texldp`: divided by
    /// w, MS `texldp---ps`).
    #[inline(always)]
    fn tex_coords(&mut self, a: SrcOp, projected: bool) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let (ru, rv, rw) = (self.row(a, 0), self.row(a, 1), self.row(a, 3));
        let [u, v] = &mut self.aux;
        let (su, sv, sw) = (&self.rows[ru], &self.rows[rv], &self.rows[rw]);
        if projected {
            for l in 0..n {
                let w = modify(sw[l], am, ax);
                u[l] = modify(su[l], am, ax) / w;
                v[l] = modify(sv[l], am, ax) / w;
            }
        } else {
            for l in 0..n {
                u[l] = modify(su[l], am, ax);
                v[l] = modify(sv[l], am, ax);
            }
        }
    }

    /// λ of `texld`/`texldp`/`texldb` from the quads' gradients: recorded
    /// for `site`, and written per lane to `lod` when `need` (`bias_w`: the
    /// source whose w `texldb` adds).
    #[inline(always)]
    fn implicit_lod(&mut self, sm: &Sampler, site: u16, need: bool, bias_w: Option<SrcOp>) {
        let n = self.span();
        let (wf, hf) = sm.size();
        let bias = sm.bias();
        let any = quads_any(self.exec);
        if !need && bias_w.is_none() {
            // Only the statistic.
            let (lo, hi) = quad_len2_range(n, &self.aux[0], &self.aux[1], wf, hf, any);
            if let Some(st) = self.sites.get_mut(site as usize) {
                st.len2_min = if lo < st.len2_min { lo } else { st.len2_min };
                st.len2_max = if hi > st.len2_max { hi } else { st.len2_max };
            }
            return;
        }
        let mut lod = [0f32; LANES];
        for q in 0..n / 4 {
            let lq = lod_of_len2(quad_len2(&self.aux[0], &self.aux[1], wf, hf, q)) + bias;
            lod[4 * q..4 * q + 4].copy_from_slice(&[lq; 4]);
        }
        if let Some(w) = bias_w {
            // texldb: "LOD bias = src0.w" per pixel (MS `texldb---ps`); the
            // documented range [-16, 15] is not enforced (outside it the
            // result is undefined).
            let (am, ax) = w.mod_bits();
            let rw = &self.rows[self.row(w, 3)];
            for l in 0..n {
                lod[l] += modify(rw[l], am, ax);
            }
        }
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        let e = self.exec;
        for l in 0..n {
            if (e >> l) & 1 != 0 {
                lo = lo.min(lod[l]);
                hi = hi.max(lod[l]);
            }
        }
        if lo <= hi {
            self.note_lod(site, lo, hi);
        }
        self.lod = lod;
    }

    /// `texld`, `texldp`, `texldb`, `texldl` on a 2D sampler.
    #[inline(always)]
    pub(super) fn texld(&mut self, d: DstOp, a: SrcOp, s: SamplerOp, kind: TexKind, site: u16) {
        let n = self.span();
        if kind != TexKind::LdL {
            self.note_site(site);
        }
        let ctx = self.ctx;
        let sampler = ctx.samplers.get(s.index as usize).and_then(|x| x.as_ref());
        if let Some(sm) = sampler.filter(|sm| sm.is_3d()) {
            return self.texld_3d(d, a, s, sm, kind, site, None);
        }
        self.tex_coords(a, kind == TexKind::LdP);
        let need = sampler.is_some_and(|sm| sm.lod_matters());
        if let Some(sm) = sampler {
            match kind {
                TexKind::Ld | TexKind::LdP if need || ctx.record_lod => {
                    self.implicit_lod(sm, site, need, None)
                }
                TexKind::LdB if need || ctx.record_lod => {
                    self.implicit_lod(sm, site, need, Some(a))
                }
                TexKind::Ld | TexKind::LdP | TexKind::LdB => {}
                TexKind::LdL => {
                    if need {
                        // texldl: λ = src0.w + MIPMAPLODBIAS (MS `texldl---ps`).
                        let (am, ax) = a.mod_bits();
                        let rw = &self.rows[self.row(a, 3)];
                        let bias = sm.bias();
                        for l in 0..n {
                            self.lod[l] = modify(rw[l], am, ax) + bias;
                        }
                    }
                }
            }
        }
        self.tex_sample(d, s, sampler, need);
    }

    /// `texldd`: λ from the given gradients (src2 = ∂/∂x, src3 = ∂/∂y, .xy).
    pub(super) fn texldd(&mut self, d: DstOp, a: SrcOp, s: SamplerOp, gx: SrcOp, gy: SrcOp) {
        let n = self.span();
        let ctx = self.ctx;
        let sampler = ctx.samplers.get(s.index as usize).and_then(|x| x.as_ref());
        if let Some(sm) = sampler.filter(|sm| sm.is_3d()) {
            return self.texld_3d(d, a, s, sm, TexKind::Ld, 0, Some((gx, gy)));
        }
        self.tex_coords(a, false);
        let need = sampler.is_some_and(|sm| sm.lod_matters());
        if let (Some(sm), true) = (sampler, need) {
            let (wf, hf) = sm.size();
            let bias = sm.bias();
            let (xm, xx) = gx.mod_bits();
            let (ym, yx) = gy.mod_bits();
            let (gxu, gxv) = (&self.rows[self.row(gx, 0)], &self.rows[self.row(gx, 1)]);
            let (gyu, gyv) = (&self.rows[self.row(gy, 0)], &self.rows[self.row(gy, 1)]);
            for l in 0..n {
                let (xu, xv) = (modify(gxu[l], xm, xx) * wf, modify(gxv[l], xm, xx) * hf);
                let (yu, yv) = (modify(gyu[l], ym, yx) * wf, modify(gyv[l], ym, yx) * hf);
                let len2 = (xu * xu + xv * xv).max(yu * yu + yv * yv);
                self.lod[l] = lod_of_len2(len2) + bias;
            }
        }
        self.tex_sample(d, s, sampler, need);
    }

    /// Samples at the coordinates in `aux` (and the LODs in `lod` when
    /// `need`) and stores the result.
    #[inline(always)]
    fn tex_sample(&mut self, d: DstOp, s: SamplerOp, sampler: Option<&Sampler>, need: bool) {
        let swz: [usize; 4] = std::array::from_fn(|c| ((s.swz >> (2 * c)) & 3) as usize);
        let n = self.span();
        let Some(sampler) = sampler else {
            for c in 0..4 {
                self.tmp[c] = [UNBOUND[swz[c]]; LANES];
            }
            self.store::<false>(d, d.mask());
            return;
        };
        if need {
            sampler.sample_lanes_lod(n, &self.aux[0], &self.aux[1], &self.lod, swz, &mut self.tmp);
            self.store::<false>(d, d.mask());
            return;
        }
        // Writes to every executing lane gather straight into the written
        // components of the destination (the coordinates are already in
        // `aux`, so nothing reads them).
        if d.mask() != 0 && self.exec == self.live && !d.predicated() && !d.sat() {
            let base = d.row as usize;
            if let Some(dst) = self.rows.get_mut(base..base + 4) {
                if let Ok(dst) = <&mut [[f32; LANES]; 4]>::try_from(dst) {
                    sampler.sample_lanes(n, &self.aux[0], &self.aux[1], swz, d.mask(), dst);
                    if d.output() {
                        let k = (base - self.ctx.compiled.layout.output as usize) / 4;
                        self.written |= 1 << k;
                    }
                    return;
                }
            }
        }
        sampler.sample_lanes(n, &self.aux[0], &self.aux[1], swz, d.mask(), &mut self.tmp);
        self.store::<false>(d, d.mask());
    }
}
