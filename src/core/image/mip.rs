//! Mip chains: a texture and its successively halved, box-filtered levels,
//! as `D3DXCreateTexture` / `D3DXFilterTexture` with `D3DX_FILTER_BOX` would
//! build them.
//!
//! Level sizes follow Direct3D 9: level `i` of a `w × h` texture is
//! `max(1, ⌊w / 2^i⌋) × max(1, ⌊h / 2^i⌋)`, down to 1 × 1, so a full chain
//! has `1 + ⌊log2(max(w, h))⌋` levels.
//!
//! The box filter: destination texel (x, y) of level i + 1 is the plain
//! average of the source texels of level i in columns `2x, 2x + 1` and rows
//! `2y, 2y + 1` — a 2 × 2 block, or 2 × 1 / 1 × 2 once a side has reached 1.
//! When a source side is odd, the last destination column (row) also takes
//! the source's last column (row), so every source texel contributes (a
//! 3-wide block at the edge). Sums are formed in f64 and rounded to f32
//! once, so a level does not depend on summation order; NaN and infinities
//! propagate as in any average.

use super::Texture;

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
            let next = halve(levels.last().expect("level 0 exists"));
            levels.push(next);
        }
        Ok(MipChain { levels })
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

/// Source index ranges feeding destination index `d` of a side halved from
/// `n` to `m` (see the module docs).
fn span(d: u32, n: u32, m: u32) -> std::ops::Range<u32> {
    if n == 1 {
        return 0..1;
    }
    let start = 2 * d;
    let end = if d + 1 == m { n } else { start + 2 };
    start..end
}

fn halve(src: &Level) -> Level {
    let (w, h) = ((src.width / 2).max(1), (src.height / 2).max(1));
    let mut texels = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        let rows = span(y, src.height, h);
        for x in 0..w {
            let cols = span(x, src.width, w);
            let mut sum = [0f64; 4];
            let mut n = 0u32;
            for sy in rows.clone() {
                for sx in cols.clone() {
                    let t = src.texels[(sy * src.width + sx) as usize];
                    for c in 0..4 {
                        sum[c] += t[c] as f64;
                    }
                    n += 1;
                }
            }
            texels.push(sum.map(|s| (s / n as f64) as f32));
        }
    }
    Level {
        width: w,
        height: h,
        texels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
