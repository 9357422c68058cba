//! Mip chains: a texture and its successively halved, box-filtered levels,
//! as `D3DXCreateTexture` / `D3DXFilterTexture` with `D3DX_FILTER_BOX` would
//! build them — and the same chain used as a *reduction*: a render target
//! averaged down to 1 × 1, every level stored in the target's format, the
//! way an application gets a mean from `D3DUSAGE_AUTOGENMIPMAP` or
//! `GenerateMipSubLevels`.
//!
//! Level sizes follow Direct3D 9: level `i` of a `w × h` texture is
//! `max(1, ⌊w / 2^i⌋) × max(1, ⌊h / 2^i⌋)`, down to 1 × 1, so a full chain
//! has `1 + ⌊log2(max(w, h))⌋` levels.
//!
//! # The filter, and odd sides
//!
//! Destination texel (x, y) of level i + 1 averages source texels of level
//! i; each side is filtered on its own, so a texel's weight is the product of
//! a column weight and a row weight ([`side_taps`]). For an even side both
//! rules below are the plain 2-texel average (the 2 × 2 box). They differ
//! where a side is odd — which Direct3D 9 leaves open: automatic generation
//! uses "the filter type … D3DTEXF_LINEAR" by default
//! (`IDirect3DBaseTexture9::SetAutoGenFilterType`), and the driver chooses
//! how to apply it:
//!
//! * [`OddSides::Fold`] — D3DX's box filter (`D3DX_FILTER_BOX`): the last
//!   destination column (row) also takes the source's last column (row), a
//!   3-wide box, so every source texel contributes, but the three share one
//!   destination texel while elsewhere two do: the chain's weights are no
//!   longer equal.
//! * [`OddSides::Bilinear`] — a level drawn as a half-size quad sampling the
//!   level above bilinearly at its texel centres (what `D3DTEXF_LINEAR`
//!   means for a draw): destination texel d of a side halved from n to m
//!   samples the source at `(d + ½)·n/m − ½`, between two texels with
//!   weights from the fraction (exact, not the hardware's fixed-point
//!   weights). For odd n some source texels get weight ¼, ¾ or none at all
//!   (a 3-texel side keeps only its middle texel).
//!
//! [`MipChain::build`] uses `Fold` and keeps levels in f32, summing in f64
//! and rounding once, so a level does not depend on summation order; NaN
//! and infinities propagate as in any average. [`MipChain::reduce`] takes
//! either rule and rounds every level as a render-target format stores it
//! (8-bit codes, halves, singles): each level then adds at most half a step
//! of the format to the final mean, and the weights of [`chain_weights`] say
//! how far a chain with odd sides is from the plain mean.

use super::{TargetFormat, Texture};

/// How a level treats a side with an odd number of texels (see the module
/// docs); even sides are the 2-texel average under both.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum OddSides {
    /// D3DX's box filter: the last destination texel takes three.
    Fold,
    /// A bilinear sample at each destination texel centre.
    Bilinear,
}

/// One level of a [`MipChain`].
#[derive(Clone, Debug, PartialEq)]
struct Level {
    width: u32,
    height: u32,
    texels: Vec<[f32; 4]>,
}

/// A texture with its mip levels, level 0 first. Build one with
/// [`MipChain::build`]; sample it by binding it to a sampler
/// (`crate::core::emu::TextureLevels::Chain`).
#[derive(Clone, Debug, PartialEq)]
pub struct MipChain {
    levels: Vec<Level>,
}

/// Number of levels of a full chain for a `w × h` base: 1 + ⌊log2(max(w, h))⌋
/// (0 for an empty base).
pub fn full_chain_levels(width: u32, height: u32) -> u32 {
    let m = width.max(height);
    if m == 0 {
        0
    } else {
        32 - m.leading_zeros()
    }
}

impl MipChain {
    /// Copies `base` as level 0 and box-filters levels below it: the full
    /// chain, or at most `max_levels` levels in all (D3D9's `Levels`
    /// argument; `Some(1)` is a texture without mips).
    pub fn build(base: Texture<'_>, max_levels: Option<u32>) -> Result<MipChain, String> {
        if base.width == 0 || base.height == 0 {
            return Err(format!("size {}x{} is empty", base.width, base.height));
        }
        let want = base.width as usize * base.height as usize;
        if base.texels.len() != want {
            return Err(format!(
                "{}x{} needs {} texels, got {}",
                base.width,
                base.height,
                want,
                base.texels.len()
            ));
        }
        let full = full_chain_levels(base.width, base.height);
        let count = match max_levels {
            Some(0) => return Err("a mip chain has at least one level".into()),
            Some(n) => n.min(full),
            None => full,
        };
        let mut levels = vec![Level {
            width: base.width,
            height: base.height,
            texels: base.texels.to_vec(),
        }];
        while (levels.len() as u32) < count {
            let next = halve(levels.last().expect("level 0 exists"), OddSides::Fold, None);
            levels.push(next);
        }
        Ok(MipChain { levels })
    }

    /// The full chain of `base` down to 1 × 1 with the `odd` rule, every
    /// level rounded as `format` stores it (`base` should already hold
    /// values of that format, as a render target does). The last level is
    /// the reduction's result.
    pub fn reduce(
        base: Texture<'_>,
        format: TargetFormat,
        odd: OddSides,
    ) -> Result<MipChain, String> {
        let mut chain = MipChain::build(base, Some(1))?;
        let full = full_chain_levels(base.width, base.height);
        while (chain.levels.len() as u32) < full {
            let next = halve(chain.levels.last().expect("level 0"), odd, Some(format));
            chain.levels.push(next);
        }
        Ok(chain)
    }

    /// The last (smallest) level's first texel: for a full chain, the 1 × 1
    /// reduction.
    pub fn last_texel(&self) -> [f32; 4] {
        self.levels.last().expect("a chain has level 0").texels[0]
    }

    /// A chain from levels the application made itself (D3D9 lets it fill
    /// every level): `levels[0]` is the base; each next level must have
    /// D3D9's halved size and the right number of texels.
    pub fn from_levels(levels: Vec<(u32, u32, Vec<[f32; 4]>)>) -> Result<MipChain, String> {
        let mut out: Vec<Level> = Vec::with_capacity(levels.len());
        for (i, (width, height, texels)) in levels.into_iter().enumerate() {
            if let Some(prev) = out.last() {
                let want = ((prev.width / 2).max(1), (prev.height / 2).max(1));
                if (width, height) != want || (prev.width, prev.height) == (1, 1) {
                    return Err(format!(
                        "level {i} is {width}x{height}; after {}x{} a mip level is {}x{}",
                        prev.width, prev.height, want.0, want.1
                    ));
                }
            } else if width == 0 || height == 0 {
                return Err(format!("size {width}x{height} is empty"));
            }
            if texels.len() != width as usize * height as usize {
                return Err(format!(
                    "level {i}: {width}x{height} needs {} texels, got {}",
                    width as usize * height as usize,
                    texels.len()
                ));
            }
            out.push(Level {
                width,
                height,
                texels,
            });
        }
        if out.is_empty() {
            return Err("a mip chain has at least one level".into());
        }
        Ok(MipChain { levels: out })
    }

    /// Number of levels (at least 1).
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Always false: a chain has level 0.
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// Level `i` as a texture view, if it exists.
    pub fn level(&self, i: usize) -> Option<Texture<'_>> {
        self.levels.get(i).map(|l| Texture {
            width: l.width,
            height: l.height,
            texels: &l.texels,
        })
    }

    /// Every level as a texture view, level 0 first.
    pub fn views(&self) -> Vec<Texture<'_>> {
        (0..self.len()).filter_map(|i| self.level(i)).collect()
    }
}

/// The source taps of destination index `d` of a side halved from `n` to
/// `m` texels: (source index, weight), and the divisor the weighted sum is
/// taken over (Fold: weights 1 over the tap count, so sums are formed as in
/// a plain average; Bilinear: weights summing to 1, divisor 1).
pub fn side_taps(d: u32, n: u32, m: u32, odd: OddSides) -> (Vec<(u32, f64)>, f64) {
    if n == 1 {
        return (vec![(0, 1.0)], 1.0);
    }
    match odd {
        OddSides::Fold => {
            let start = 2 * d;
            let end = if d + 1 == m { n } else { start + 2 };
            (
                (start..end).map(|i| (i, 1.0)).collect(),
                (end - start) as f64,
            )
        }
        OddSides::Bilinear => {
            let s = (d as f64 + 0.5) * n as f64 / m as f64 - 0.5;
            let t0 = s.floor();
            let w1 = s - t0;
            let t0 = t0 as u32;
            let mut taps = vec![(t0, 1.0 - w1)];
            if w1 > 0.0 {
                taps.push(((t0 + 1).min(n - 1), w1));
            }
            (taps, 1.0)
        }
    }
}

/// The weight each of the `n` texels of one side of the base has in the
/// last level of a chain of `levels` levels (sides halve as D3D9's do): the
/// 1 × 1 reduction of a `w × h` base is Σ wx(x)·wy(y)·texel(x, y). Every
/// weight is 1/n for a power of two; odd sides on the way make them unequal.
pub fn chain_weights(n: u32, levels: u32, odd: OddSides) -> Vec<f64> {
    let mut weights = vec![1.0f64];
    let sizes: Vec<u32> = (0..levels.max(1))
        .map(|i| (n >> i.min(31)).max(1))
        .collect();
    // Walk from the last level up: a texel's weight is shared among its taps.
    for pair in sizes.windows(2).rev() {
        let (big, small) = (pair[0], pair[1]);
        let mut up = vec![0f64; big as usize];
        for d in 0..small {
            let (taps, norm) = side_taps(d, big, small, odd);
            for (i, w) in taps {
                up[i as usize] += weights[d as usize] * w / norm;
            }
        }
        weights = up;
    }
    weights
}

fn halve(src: &Level, odd: OddSides, format: Option<TargetFormat>) -> Level {
    let (w, h) = ((src.width / 2).max(1), (src.height / 2).max(1));
    let mut texels = Vec::with_capacity(w as usize * h as usize);
    let columns: Vec<_> = (0..w).map(|x| side_taps(x, src.width, w, odd)).collect();
    for y in 0..h {
        let (rows, row_norm) = side_taps(y, src.height, h, odd);
        for (cols, col_norm) in &columns {
            let mut sum = [0f64; 4];
            for &(sy, wy) in &rows {
                for &(sx, wx) in cols {
                    let t = src.texels[(sy * src.width + sx) as usize];
                    for c in 0..4 {
                        sum[c] += wy * wx * t[c] as f64;
                    }
                }
            }
            let mean = sum.map(|s| s / (row_norm * col_norm));
            texels.push(match format {
                Some(f) => f.round_f64(mean),
                None => mean.map(|m| m as f32),
            });
        }
    }
    Level {
        width: w,
        height: h,
        texels,
    }
}

/// The worst a frame's weights can do to the mean of encodings in [0, 1]:
/// ½·Σ|w − 1/N| over the pixels (the pixels above 1/N all 1, the others
/// 0). The weights are products of a column and a row weight, which take
/// few distinct values, so the sum runs over pairs of distinct values.
pub fn weight_bound(w: u32, h: u32, odd: OddSides) -> f64 {
    let levels = full_chain_levels(w, h);
    let distinct = |side: Vec<f64>| {
        let mut counts: std::collections::BTreeMap<u64, f64> = Default::default();
        for v in side {
            *counts.entry(v.to_bits()).or_default() += 1.0;
        }
        counts
            .into_iter()
            .map(|(bits, n)| (f64::from_bits(bits), n))
            .collect::<Vec<_>>()
    };
    let (wx, wy) = (
        distinct(chain_weights(w, levels, odd)),
        distinct(chain_weights(h, levels, odd)),
    );
    let n = w as f64 * h as f64;
    let mut total = 0f64;
    for &(a, na) in &wy {
        for &(b, nb) in &wx {
            total += na * nb * (a * b - 1.0 / n).abs();
        }
    }
    total / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::image::{unorm8_value, TargetFormat};

    fn chain(w: u32, h: u32, f: impl Fn(u32, u32) -> f32) -> MipChain {
        let texels: Vec<[f32; 4]> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| [f(x, y), 0.0, 0.0, 1.0])
            .collect();
        MipChain::build(
            Texture {
                width: w,
                height: h,
                texels: &texels,
            },
            None,
        )
        .unwrap()
    }

    fn reds(t: Texture<'_>) -> Vec<f32> {
        t.texels.iter().map(|p| p[0]).collect()
    }

    #[test]
    fn level_counts_and_sizes_follow_d3d9() {
        assert_eq!(full_chain_levels(256, 256), 9);
        assert_eq!(full_chain_levels(1280, 1024), 11);
        assert_eq!(full_chain_levels(1, 1), 1);
        assert_eq!(full_chain_levels(5, 1), 3);
        let c = chain(5, 3, |_, _| 1.0);
        let sizes: Vec<(u32, u32)> = c.views().iter().map(|t| (t.width, t.height)).collect();
        assert_eq!(sizes, [(5, 3), (2, 1), (1, 1)]);
    }

    #[test]
    fn power_of_two_levels_are_2x2_box_averages() {
        // 4×4, texel (x, y) = x + 4y.
        let c = chain(4, 4, |x, y| (x + 4 * y) as f32);
        // Level 1 texel (0,0) = (0 + 1 + 4 + 5) / 4 = 2.5; (1,0) = (2+3+6+7)/4 = 4.5;
        // (0,1) = (8+9+12+13)/4 = 10.5; (1,1) = 12.5. Level 2 = mean of all = 7.5.
        assert_eq!(reds(c.level(1).unwrap()), [2.5, 4.5, 10.5, 12.5]);
        assert_eq!(reds(c.level(2).unwrap()), [7.5]);
        assert!(c.level(3).is_none());
        assert_eq!(c.len(), 3);
    }

    #[test]
    fn odd_sides_fold_the_last_column_into_the_edge_texel() {
        // 3×1: [0, 3, 9] → level 1 is 1×1 = mean of all three = 4.
        let c = chain(3, 1, |x, _| [0.0, 3.0, 9.0][x as usize]);
        assert_eq!(reds(c.level(1).unwrap()), [4.0]);
        // 5×2: columns (0,1) and (2,3,4).
        let c = chain(5, 2, |x, y| (x + 10 * y) as f32);
        // (0+1+10+11)/4 = 5.5; (2+3+4+12+13+14)/6 = 8.
        assert_eq!(reds(c.level(1).unwrap()), [5.5, 8.0]);
    }

    #[test]
    fn level_limits_and_bad_bases_are_refused_or_honoured() {
        let texels = [[1.0f32; 4]; 16];
        let base = Texture {
            width: 4,
            height: 4,
            texels: &texels,
        };
        assert_eq!(MipChain::build(base, Some(1)).unwrap().len(), 1);
        assert_eq!(MipChain::build(base, Some(2)).unwrap().len(), 2);
        assert_eq!(MipChain::build(base, Some(99)).unwrap().len(), 3);
        assert!(MipChain::build(base, Some(0)).is_err());
        let short = Texture {
            width: 4,
            height: 4,
            texels: &texels[..15],
        };
        assert!(MipChain::build(short, None).is_err());
        let empty = Texture {
            width: 0,
            height: 4,
            texels: &[],
        };
        assert!(MipChain::build(empty, None).is_err());
    }

    #[test]
    fn chain_weights_by_hand() {
        // Fold, 5 → 2 → 1: columns 0, 1 share destination 0 (½ each), 2, 3, 4
        // share destination 1 (⅓ each); then 2 → 1 halves both: ¼ and ⅙.
        let w = chain_weights(5, 3, OddSides::Fold);
        let want = [0.25, 0.25, 1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0];
        for (a, b) in w.iter().zip(want) {
            assert!((a - b).abs() < 1e-15, "{w:?}");
        }
        // Bilinear, 5 → 2: destination 0 samples at 0.75 (¼ of column 0, ¾
        // of column 1), destination 1 at 3.25 (¾ of 3, ¼ of 4); column 2 is
        // never read. Then ½ each.
        assert_eq!(
            chain_weights(5, 3, OddSides::Bilinear),
            [0.125, 0.375, 0.0, 0.375, 0.125]
        );
        // A 3-texel side halved by a bilinear sample keeps only its middle.
        assert_eq!(chain_weights(3, 2, OddSides::Bilinear), [0.0, 1.0, 0.0]);
        // Powers of two: every texel 1/n under both rules.
        for odd in [OddSides::Fold, OddSides::Bilinear] {
            assert_eq!(chain_weights(8, 4, odd), [0.125; 8]);
            // A side that reaches 1 before the other stays put.
            assert_eq!(chain_weights(2, 4, odd), [0.5, 0.5]);
            assert_eq!(chain_weights(1, 3, odd), [1.0]);
            let sum: f64 = chain_weights(1280, 11, odd).iter().sum();
            assert!((sum - 1.0).abs() < 1e-12);
        }
    }

    fn reduce_red(
        w: u32,
        h: u32,
        f: &dyn Fn(u32, u32) -> f32,
        fmt: TargetFormat,
        odd: OddSides,
    ) -> (f32, f64, f64) {
        let texels: Vec<[f32; 4]> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| fmt.round([f(x, y), 0.0, 0.0, 1.0]))
            .collect();
        let base = Texture {
            width: w,
            height: h,
            texels: &texels,
        };
        let chain = MipChain::reduce(base, fmt, odd).unwrap();
        assert_eq!(chain.len() as u32, full_chain_levels(w, h));
        let levels = chain.len() as u32;
        let (wx, wy) = (chain_weights(w, levels, odd), chain_weights(h, levels, odd));
        let mut weighted = 0f64;
        let mut mean = 0f64;
        for y in 0..h {
            for x in 0..w {
                let t = texels[(y * w + x) as usize][0] as f64;
                weighted += wx[x as usize] * wy[y as usize] * t;
                mean += t;
            }
        }
        (
            chain.last_texel()[0],
            weighted,
            mean / (w as f64 * h as f64),
        )
    }

    #[test]
    fn reduction_is_the_mean_for_even_sides_and_the_weighted_mean_for_odd() {
        let f = |x: u32, y: u32| ((x * 7 + y * 13) % 17) as f32 * 0.25 + 0.5;
        for odd in [OddSides::Fold, OddSides::Bilinear] {
            // 16×8, f32 levels: every average of dyadic values here is exact
            // until the last levels; the bound is half an f32 ulp of the mean
            // per level (4 of them after the base).
            let (got, weighted, mean) = reduce_red(16, 8, &f, TargetFormat::R32F, odd);
            assert_eq!(weighted, mean);
            assert!((got as f64 - mean).abs() <= 4.0 * 0.5 * f32::EPSILON as f64 * mean);
            // 5×3: the chain is the weighted mean (f32 rounding per level,
            // 3 levels after the base), and not the plain mean.
            let (got, weighted, mean) = reduce_red(5, 3, &f, TargetFormat::R32F, odd);
            assert!((got as f64 - weighted).abs() <= 3.0 * 0.5 * f32::EPSILON as f64 * weighted);
            assert!(
                (weighted - mean).abs() > 1e-3,
                "{odd:?}: {weighted} vs {mean}"
            );
        }
    }

    #[test]
    fn an_8_bit_chain_rounds_every_level_half_up() {
        // Codes 0 and 1 in a checkerboard: each 2×2 average is half a code,
        // which the FLOAT → UNORM rule rounds up to 1; the next levels
        // average codes 1 and stay there. The true mean is 0.5/255: the chain
        // is half a code high.
        let f = |x: u32, y: u32| ((x + y) % 2) as f32 / 255.0;
        let (got, weighted, mean) = reduce_red(4, 4, &f, TargetFormat::A8R8G8B8, OddSides::Fold);
        assert_eq!(got, 1.0 / 255.0);
        // Both means are half the stored code 1, f32(1/255) / 2.
        let half_code = unorm8_value(1) as f64 / 2.0;
        assert_eq!((weighted, mean), (half_code, half_code));
        // Half a code per level at most: 2 levels after the base.
        assert!((got as f64 - mean).abs() <= 2.0 * 0.5 / 255.0);
    }

    #[test]
    fn application_levels_must_halve() {
        let l = |w: u32, h: u32, v: f32| (w, h, vec![[v; 4]; (w * h) as usize]);
        let c = MipChain::from_levels(vec![l(4, 2, 0.0), l(2, 1, 1.0), l(1, 1, 2.0)]).unwrap();
        assert_eq!(reds(c.level(2).unwrap()), [2.0]);
        assert!(MipChain::from_levels(vec![l(4, 2, 0.0), l(1, 1, 1.0)]).is_err());
        assert!(MipChain::from_levels(vec![l(1, 1, 0.0), l(1, 1, 1.0)]).is_err());
        assert!(MipChain::from_levels(vec![]).is_err());
        assert!(MipChain::from_levels(vec![(2, 2, vec![[0.0; 4]; 3])]).is_err());
    }
}
