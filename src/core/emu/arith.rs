//! Arithmetic and comparison handlers of the executor (the texld family is
//! in `texop.rs`). The handlers whose results the float rules change
//! (`core/float_rules.rs`: mul, mad, lrp, the dot products, nrm, log, rsq,
//! pow, frc) choose their scalar function by the draw's rules once per
//! batch of lanes.
//!
//! Every handler is a loop over all [`LANES`] lanes of fixed-size rows (so
//! the compiler can vectorise it), built from a few generic helpers:
//! `map1`/`map2`/`map3` for component-wise ops, `scalar1` for replicated
//! scalar results, `dot` for dot products. Results go to the `tmp` scratch
//! rows first and are written back by [`Worker::store`], which applies the
//! write mask, `_sat`, predication and the execution mask — reading all
//! sources before writing makes `add r0, r0.yxzw, r0` correct.

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::compile::{DstOp, SrcOp};
use super::exec::Worker;
use super::math::{self, modify};
use super::LANES;
use crate::core::float_rules::flush;
use crate::core::isa::Compare;

impl Worker<'_, '_> {
    /// Row read by component `c` of source `a` (relative `v[aL + n]` outside
    /// v0..v9 reads zeros).
    #[inline(always)]
    pub(super) fn row(&self, a: SrcOp, c: usize) -> usize {
        let base = if a.relative() {
            let layout = &self.ctx.compiled.layout;
            let input = layout.input as i64;
            let r = a.row as i64 + 4 * self.al as i64;
            if r >= input && r < input + 40 {
                r as usize
            } else {
                0
            }
        } else {
            a.row as usize
        };
        base + a.comp(c)
    }

    /// Lanes allowed to write component `c` of `d`: the execution mask and the
    /// predicate `(p0.c)` / `(!p0.c)`.
    #[inline(always)]
    fn write_mask(&self, d: DstOp, c: usize) -> u64 {
        let mut m = self.exec;
        if d.predicated() {
            let p = self.p[d.pred_comp(c)];
            m &= if d.pred_not() { !p } else { p };
        }
        m
    }

    /// Writes `tmp` to `d` for the components of `mask` (`tmp[0]` to all of
    /// them when `SCALAR`).
    #[inline(always)]
    pub(super) fn store<const SCALAR: bool>(&mut self, d: DstOp, mask: u8) {
        let n = self.span();
        if self.ctx.rules.flush_denormals() {
            // `hardware`: a denormal result is written as a zero.
            for c in 0..if SCALAR { 1 } else { 4 } {
                for v in &mut self.tmp[c][..n] {
                    *v = crate::core::float_rules::flush(*v);
                }
            }
        }
        let full = self.exec == self.live && !d.predicated();
        let sat = d.sat();
        let base = d.row as usize;
        let mut any = false;
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let lanes = if full { !0 } else { self.write_mask(d, c) };
            if lanes == 0 {
                continue;
            }
            any = true;
            let t = &self.tmp[if SCALAR { 0 } else { c }];
            let dst = &mut self.rows[base + c];
            if full {
                if sat {
                    for l in 0..n {
                        dst[l] = math::sat(t[l]);
                    }
                } else {
                    *dst = *t;
                }
            } else {
                for l in 0..n {
                    let v = if sat { math::sat(t[l]) } else { t[l] };
                    if (lanes >> l) & 1 != 0 {
                        dst[l] = v;
                    }
                }
            }
        }
        if any && d.output() {
            let k = (base - self.ctx.compiled.layout.output as usize) / 4;
            self.written |= 1 << k;
        }
    }

    /// Component-wise unary op.
    #[inline(always)]
    pub(super) fn map1(&mut self, d: DstOp, a: SrcOp, f: impl Fn(f32) -> f32) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let mask = d.mask();
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let ra = self.row(a, c);
            let src = &self.rows[ra];
            let out = &mut self.tmp[c];
            for l in 0..n {
                out[l] = f(modify(src[l], am, ax));
            }
        }
        self.store::<false>(d, mask);
    }

    /// Component-wise binary op.
    #[inline(always)]
    pub(super) fn map2(&mut self, d: DstOp, a: SrcOp, b: SrcOp, f: impl Fn(f32, f32) -> f32) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let mask = d.mask();
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let (ra, rb) = (self.row(a, c), self.row(b, c));
            let (sa, sb) = (&self.rows[ra], &self.rows[rb]);
            let out = &mut self.tmp[c];
            for l in 0..n {
                out[l] = f(modify(sa[l], am, ax), modify(sb[l], bm, bx));
            }
        }
        self.store::<false>(d, mask);
    }

    /// Component-wise ternary op.
    #[inline(always)]
    pub(super) fn map3(
        &mut self,
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        c3: SrcOp,
        f: impl Fn(f32, f32, f32) -> f32,
    ) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let (cm, cx) = c3.mod_bits();
        let mask = d.mask();
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let (ra, rb, rc) = (self.row(a, c), self.row(b, c), self.row(c3, c));
            let (sa, sb, sc) = (&self.rows[ra], &self.rows[rb], &self.rows[rc]);
            let out = &mut self.tmp[c];
            for l in 0..n {
                out[l] = f(
                    modify(sa[l], am, ax),
                    modify(sb[l], bm, bx),
                    modify(sc[l], cm, cx),
                );
            }
        }
        self.store::<false>(d, mask);
    }

    /// Scalar op on the source's first swizzle component (the replicate
    /// swizzle), replicated to every written component.
    #[inline(always)]
    pub(super) fn scalar1(&mut self, d: DstOp, a: SrcOp, f: impl Fn(f32) -> f32) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let ra = self.row(a, 0);
        let src = &self.rows[ra];
        let out = &mut self.tmp[0];
        for l in 0..n {
            out[l] = f(modify(src[l], am, ax));
        }
        self.store::<true>(d, d.mask());
    }

    // ----- the float rules (core/float_rules.rs) --------------------------

    #[inline(always)]
    pub(super) fn mul(&mut self, d: DstOp, a: SrcOp, b: SrcOp) {
        if self.ctx.rules.zero_mul() {
            self.map2(d, a, b, math::zmul)
        } else {
            self.map2(d, a, b, |x, y| x * y)
        }
    }

    #[inline(always)]
    pub(super) fn mad(&mut self, d: DstOp, a: SrcOp, b: SrcOp, c: SrcOp) {
        if self.ctx.rules.flush_denormals() {
            // `hardware`: a multiply, then an add (no fused multiply-add on
            // Direct3D 9 hardware); a denormal product is flushed before the add.
            self.map3(d, a, b, c, |x, y, z| flush(math::zmul(x, y)) + z)
        } else if self.ctx.rules.zero_mul() {
            self.map3(d, a, b, c, |x, y, z| math::zmul(x, y) + z)
        } else {
            self.map3(d, a, b, c, math::mad)
        }
    }

    #[inline(always)]
    pub(super) fn lrp(&mut self, d: DstOp, a: SrcOp, b: SrcOp, c: SrcOp) {
        if self.ctx.rules.flush_denormals() {
            // `hardware`: a denormal product is a zero (1 − x never is one)
            self.map3(d, a, b, c, |x, y, z| {
                flush(math::zmul(x, y)) + flush(math::zmul(1.0 - x, z))
            })
        } else if self.ctx.rules.zero_mul() {
            self.map3(d, a, b, c, |x, y, z| {
                math::zmul(x, y) + math::zmul(1.0 - x, z)
            })
        } else {
            self.map3(d, a, b, c, math::lrp)
        }
    }

    #[inline(always)]
    pub(super) fn log(&mut self, d: DstOp, a: SrcOp) {
        if self.ctx.rules.d3d9_specials() {
            self.scalar1(d, a, math::log)
        } else {
            self.scalar1(d, a, math::ieee_log)
        }
    }

    #[inline(always)]
    pub(super) fn rsq(&mut self, d: DstOp, a: SrcOp) {
        if self.ctx.rules.d3d9_specials() {
            self.scalar1(d, a, math::rsq)
        } else {
            self.scalar1(d, a, math::ieee_rsq)
        }
    }

    #[inline(always)]
    pub(super) fn frc(&mut self, d: DstOp, a: SrcOp) {
        if self.ctx.rules.d3d9_specials() {
            self.map1(d, a, math::frc)
        } else {
            self.map1(d, a, math::ieee_frc)
        }
    }

    #[inline(always)]
    pub(super) fn pow(&mut self, d: DstOp, a: SrcOp, b: SrcOp) {
        let n = self.span();
        let f = if self.ctx.rules.d3d9_specials() {
            math::pow
        } else {
            math::ieee_pow
        };
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let (ra, rb) = (self.row(a, 0), self.row(b, 0));
        let (sa, sb) = (&self.rows[ra], &self.rows[rb]);
        let out = &mut self.tmp[0];
        for l in 0..n {
            out[l] = f(modify(sa[l], am, ax), modify(sb[l], bm, bx));
        }
        self.store::<true>(d, d.mask());
    }

    /// `N`-component dot product of `a` and `b` into `tmp[k]`, summed left
    /// to right in f32, with the draw's product (chosen once, so that the
    /// lane loop is compiled with the product inlined and vectorises).
    #[inline(always)]
    pub(super) fn dot<const N: usize>(&mut self, _d: DstOp, a: SrcOp, b: SrcOp, k: usize) {
        if self.ctx.rules.flush_denormals() {
            // `hardware`: products and partial sums are results of their
            // own, each denormal one a zero
            let mul = |x, y| flush(math::zmul(x, y));
            self.dot_with::<N>(a, b, k, mul, |s, p| flush(s + p))
        } else if self.ctx.rules.zero_mul() {
            self.dot_with::<N>(a, b, k, math::zmul, |s, p| s + p)
        } else {
            self.dot_with::<N>(a, b, k, |x, y| x * y, |s, p| s + p)
        }
    }

    /// [`Worker::dot`] with the product `mul` and the sum `add`.
    #[inline(always)]
    fn dot_with<const N: usize>(
        &mut self,
        a: SrcOp,
        b: SrcOp,
        k: usize,
        mul: impl Fn(f32, f32) -> f32,
        add: impl Fn(f32, f32) -> f32,
    ) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let ra: [usize; N] = std::array::from_fn(|c| self.row(a, c));
        let rb: [usize; N] = std::array::from_fn(|c| self.row(b, c));
        let sa: [&[f32; LANES]; N] = std::array::from_fn(|c| &self.rows[ra[c]]);
        let sb: [&[f32; LANES]; N] = std::array::from_fn(|c| &self.rows[rb[c]]);
        let out = &mut self.tmp[k];
        for l in 0..n {
            let mut s = mul(modify(sa[0][l], am, ax), modify(sb[0][l], bm, bx));
            for c in 1..N {
                s = add(s, mul(modify(sa[c][l], am, ax), modify(sb[c][l], bm, bx)));
            }
            out[l] = s;
        }
    }

    /// `dp3` / `dp4`: the dot product, replicated to the written components.
    #[inline(always)]
    pub(super) fn dp<const N: usize>(&mut self, d: DstOp, a: SrcOp, b: SrcOp) {
        self.dot::<N>(d, a, b, 0);
        self.store::<true>(d, d.mask());
    }

    /// `dp2add`: a.x·b.x + a.y·b.y + c (c's replicate component).
    pub(super) fn dp2add(&mut self, d: DstOp, a: SrcOp, b: SrcOp, c3: SrcOp) {
        let n = self.span();
        self.dot::<2>(d, a, b, 0);
        let (cm, cx) = c3.mod_bits();
        let rc = self.row(c3, 0);
        let sc = &self.rows[rc];
        let out = &mut self.tmp[0];
        for l in 0..n {
            out[l] += modify(sc[l], cm, cx);
        }
        self.store::<true>(d, d.mask());
    }

    /// `m4x4` … `m3x2`: component k is the dot product with register b + k;
    /// components from `n` on are left untouched.
    pub(super) fn matrix(&mut self, d: DstOp, a: SrcOp, b: SrcOp, n: u8, dims: u8) {
        let n = (n as usize).min(4);
        for k in 0..n {
            let bk = SrcOp {
                row: b.row + 4 * k as u16,
                ..b
            };
            if dims == 3 {
                self.dot::<3>(d, a, bk, k);
            } else {
                self.dot::<4>(d, a, bk, k);
            }
        }
        self.store::<false>(d, d.mask() & ((1u8 << n) - 1));
    }

    /// `crs`: cross product of xyz; w is never written.
    pub(super) fn crs(&mut self, d: DstOp, a: SrcOp, b: SrcOp) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let ra: [usize; 3] = std::array::from_fn(|c| self.row(a, c));
        let rb: [usize; 3] = std::array::from_fn(|c| self.row(b, c));
        for c in 0..3 {
            let (i, j) = ((c + 1) % 3, (c + 2) % 3);
            let (ai, aj) = (&self.rows[ra[i]], &self.rows[ra[j]]);
            let (bi, bj) = (&self.rows[rb[i]], &self.rows[rb[j]]);
            let out = &mut self.tmp[c];
            for l in 0..n {
                out[l] = modify(ai[l], am, ax) * modify(bj[l], bm, bx)
                    - modify(aj[l], am, ax) * modify(bi[l], bm, bx);
            }
        }
        self.store::<false>(d, d.mask() & 0b0111);
    }

    /// `nrm`: src · (1/sqrt(x²+y²+z²)), FLT_MAX for a zero length (MS
    /// `nrm---ps`), applied to all four components.
    pub(super) fn nrm(&mut self, d: DstOp, a: SrcOp) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let r: [usize; 4] = std::array::from_fn(|c| self.row(a, c));
        let s: [&[f32; LANES]; 4] = std::array::from_fn(|c| &self.rows[r[c]]);
        let rules = self.ctx.rules;
        let scale_of = if rules.d3d9_specials() {
            math::nrm_scale
        } else {
            math::ieee_nrm_scale
        };
        let mul = if rules.zero_mul() {
            math::zmul
        } else {
            |x: f32, y: f32| x * y
        };
        let mut scale = [0.0f32; LANES];
        for l in 0..n {
            let (x, y, z) = (
                modify(s[0][l], am, ax),
                modify(s[1][l], am, ax),
                modify(s[2][l], am, ax),
            );
            scale[l] = scale_of(if rules.flush_denormals() {
                // `hardware`: the squares and sums as `dp3` computes them
                flush(flush(flush(x * x) + flush(y * y)) + flush(z * z))
            } else {
                x * x + y * y + z * z
            });
        }
        for c in 0..4 {
            let out = &mut self.tmp[c];
            for l in 0..n {
                out[l] = mul(modify(s[c][l], am, ax), scale[l]);
            }
        }
        self.store::<false>(d, d.mask());
    }

    /// `sincos`: x = cos, y = sin of the replicate component; z and w are
    /// left untouched (ps_3_0 form, MS `sincos---ps`).
    pub(super) fn sincos(&mut self, d: DstOp, a: SrcOp) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let ra = self.row(a, 0);
        let src = &self.rows[ra];
        let [t0, t1, _, _] = &mut self.tmp;
        for l in 0..n {
            let v = modify(src[l], am, ax);
            t0[l] = v.cos();
            t1[l] = v.sin();
        }
        self.store::<false>(d, d.mask() & 0b0011);
    }

    /// `dsx` / `dsy` (`neighbour` as in [`Self::deriv`]), recorded at
    /// gradient site `site`.
    #[inline(always)]
    pub(super) fn derivative(&mut self, d: DstOp, a: SrcOp, site: u16, neighbour: usize) {
        self.note_site(site);
        self.deriv(d, a, neighbour)
    }

    /// Coarse `dsx` (`neighbour` 1: top-right − top-left) or `dsy`
    /// (`neighbour` 2: bottom-left − top-left), one value per quad.
    pub(super) fn deriv(&mut self, d: DstOp, a: SrcOp, neighbour: usize) {
        let n = self.span();
        let (am, ax) = a.mod_bits();
        let mask = d.mask();
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let ra = self.row(a, c);
            let src = &self.rows[ra];
            let out = &mut self.tmp[c];
            for q in (0..n).step_by(4) {
                let v = modify(src[q + neighbour], am, ax) - modify(src[q], am, ax);
                out[q..q + 4].copy_from_slice(&[v; 4]);
            }
        }
        self.store::<false>(d, mask);
    }

    /// Lanes where `a.c <cmp> b.c` holds, for component `c` of the swizzles.
    #[inline(always)]
    fn compare_comp(&self, cmp: Compare, a: SrcOp, b: SrcOp, c: usize) -> u64 {
        let (am, ax) = a.mod_bits();
        let (bm, bx) = b.mod_bits();
        let sa = &self.rows[self.row(a, c)];
        let sb = &self.rows[self.row(b, c)];
        #[inline(always)]
        fn bits(
            sa: &[f32; LANES],
            sb: &[f32; LANES],
            (am, ax, bm, bx): (u32, u32, u32, u32),
            f: impl Fn(f32, f32) -> bool,
        ) -> u64 {
            let mut m = 0u64;
            for l in 0..LANES {
                m |= (f(modify(sa[l], am, ax), modify(sb[l], bm, bx)) as u64) << l;
            }
            m
        }
        let mods = (am, ax, bm, bx);
        match cmp {
            Compare::Gt => bits(sa, sb, mods, |x, y| x > y),
            Compare::Lt => bits(sa, sb, mods, |x, y| x < y),
            Compare::Ge => bits(sa, sb, mods, |x, y| x >= y),
            Compare::Le => bits(sa, sb, mods, |x, y| x <= y),
            Compare::Eq => bits(sa, sb, mods, |x, y| x == y),
            Compare::Ne => bits(sa, sb, mods, |x, y| x != y),
        }
    }

    /// `if_cmp` / `break_cmp`: compares the replicate components.
    pub(super) fn compare(&self, cmp: Compare, a: SrcOp, b: SrcOp) -> u64 {
        self.compare_comp(cmp, a, b, 0)
    }

    /// `setp_cmp p0.mask, a, b` (MS `setp-comp---ps`).
    pub(super) fn setp(&mut self, d: DstOp, a: SrcOp, b: SrcOp, cmp: Compare) {
        for c in 0..4 {
            if d.mask() & (1 << c) == 0 {
                continue;
            }
            let bits = self.compare_comp(cmp, a, b, c);
            let lanes = self.write_mask(d, c);
            self.p[c] = (self.p[c] & !lanes) | (bits & lanes);
        }
    }

    /// `texkill`: lanes to kill — any of the operand's x, y, z, w (those in
    /// its mask) below zero. ps_2_0 and later test all four components
    /// (Wine's wined3d: "2.0 shaders compare all 4 components in texkill";
    /// only ps_1_x's texture-coordinate form stops at .xyz); predication
    /// applies per component.
    pub(super) fn texkill(&self, d: DstOp) -> u64 {
        let n = self.span();
        let mut kill = 0u64;
        for c in 0..4 {
            if d.mask() & (1 << c) == 0 {
                continue;
            }
            let src = &self.rows[d.row as usize + c];
            let mut m = 0u64;
            for l in 0..n {
                m |= ((src[l] < 0.0) as u64) << l;
            }
            kill |= m & self.write_mask(d, c);
        }
        kill
    }
}
