//! Two sets of per-pixel colours compared channel by channel: identical
//! bits, distances in units in the last place (ulp), NaN and ∞
//! disagreements, and the worst pixels.
//!
//! The ulp distance of two f32 values is how many representable floats lie
//! between them: the bit patterns are mapped to integers that grow with the
//! value (negative floats reversed), so +0 and −0 are 0 ulp apart though
//! not bit-identical, 1.0 and the next float up are 1 ulp apart, and the
//! distance across 0 counts the floats on both sides. A pair with a NaN or
//! an infinity on one side only has no distance: it is counted apart.

use serde::Serialize;

/// The histogram's bucket edges: 0, 1, 2, 3–4, 5–16, 17–256, 257–65,536,
/// more.
pub const BUCKETS: [(u64, u64); 8] = [
    (0, 0),
    (1, 1),
    (2, 2),
    (3, 4),
    (5, 16),
    (17, 256),
    (257, 65_536),
    (65_537, u64::MAX),
];

/// The label of bucket `i` (`0`, `1`, `3–4`, `>65,536`).
pub fn bucket_label(i: usize) -> String {
    let (lo, hi) = BUCKETS[i];
    if hi == u64::MAX {
        format!(">{}", crate::core::numbers::thousands(lo - 1))
    } else if lo == hi {
        lo.to_string()
    } else {
        format!(
            "{}–{}",
            crate::core::numbers::thousands(lo),
            crate::core::numbers::thousands(hi)
        )
    }
}

/// The f32's position on the line of floats.
fn ordered(x: f32) -> i64 {
    let b = x.to_bits();
    let magnitude = (b & 0x7fff_ffff) as i64;
    if b >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    }
}

/// The ulp distance of two finite-or-infinite floats; `None` when exactly
/// one is NaN or exactly one is infinite (or they are opposite infinities).
pub fn ulp_distance(a: f32, b: f32) -> Option<u64> {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => return Some(0),
        (false, false) => {}
        _ => return None,
    }
    if a.is_infinite() || b.is_infinite() {
        return (a == b).then_some(0);
    }
    Some(ordered(a).abs_diff(ordered(b)))
}

/// Whether `a` is subnormal and `b` is ±0.
pub fn is_flush(a: f32, b: f32) -> bool {
    a.is_subnormal() && b == 0.0
}

/// Whether `a` is ±∞ and `b` the largest half of the same sign.
pub fn is_saturation(a: f32, b: f32) -> bool {
    a.is_infinite() && b.abs() == 65_504.0 && a.signum() == b.signum()
}

/// One pixel where the backends differ most.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Worst {
    /// Column, in pixels from the left.
    pub x: u32,
    /// Row, in pixels from the top.
    pub y: u32,
    /// The emulator's value, stored as the target stores it.
    pub emulator: f32,
    /// The GPU's value, as the target stored it.
    pub gpu: f32,
    /// `None`: a NaN or ∞ on one side only.
    pub ulp: Option<u64>,
}

/// One channel of one output over a draw.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ChannelStats {
    /// `oC0.r`, `oDepth`, …
    pub channel: String,
    /// Pixels compared.
    pub pixels: u64,
    /// Bit-identical values (NaNs count as identical only with equal bits).
    pub identical: u64,
    /// Pixels per ulp bucket ([`BUCKETS`]), NaN/∞ disagreements left out.
    pub histogram: [u64; 8],
    /// The largest distance in ulps, NaN/∞ disagreements left out.
    pub max_ulp: u64,
    /// A NaN on one side only.
    pub nan_mismatches: u64,
    /// An infinity on one side only, or opposite infinities.
    pub inf_mismatches: u64,
    /// Pixels where one side holds a subnormal and the other ±0: a
    /// backend that flushes subnormals to zero (as GPUs do) against one
    /// that keeps them (the emulator, IEEE).
    pub subnormal_flushes: u64,
    /// Pixels where one side holds ±∞ and the other ±65,504 of the same
    /// sign: an f16 target rounding toward zero against one rounding to
    /// nearest.
    pub f16_saturations: u64,
    /// Up to five pixels, the largest distances first (NaN/∞ mismatches
    /// before any distance).
    pub worst: Vec<Worst>,
}

impl ChannelStats {
    /// Compares `emulator[i]` with `gpu[i]` over a `width`-wide image.
    pub fn of(channel: String, width: u32, emulator: &[f32], gpu: &[f32]) -> ChannelStats {
        let mut s = ChannelStats {
            channel,
            pixels: emulator.len() as u64,
            identical: 0,
            histogram: [0; 8],
            max_ulp: 0,
            nan_mismatches: 0,
            inf_mismatches: 0,
            subnormal_flushes: 0,
            f16_saturations: 0,
            worst: Vec::new(),
        };
        let mut ranked: Vec<(u64, usize, Option<u64>)> = Vec::new();
        for (i, (&e, &g)) in emulator.iter().zip(gpu).enumerate() {
            if e.to_bits() == g.to_bits() {
                s.identical += 1;
            } else if is_flush(e, g) || is_flush(g, e) {
                s.subnormal_flushes += 1;
            }
            let d = ulp_distance(e, g);
            match d {
                Some(d) => {
                    let b = BUCKETS
                        .iter()
                        .position(|&(lo, hi)| d >= lo && d <= hi)
                        .unwrap_or(7);
                    s.histogram[b] += 1;
                    s.max_ulp = s.max_ulp.max(d);
                    if d > 0 {
                        ranked.push((d, i, Some(d)));
                    }
                }
                None => {
                    if is_saturation(e, g) || is_saturation(g, e) {
                        s.f16_saturations += 1;
                    }
                    if e.is_nan() != g.is_nan() {
                        s.nan_mismatches += 1;
                    } else {
                        s.inf_mismatches += 1;
                    }
                    ranked.push((u64::MAX, i, None));
                }
            }
        }
        // Largest first; ties by position, so the list is deterministic.
        ranked.sort_unstable_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
        s.worst = ranked
            .iter()
            .take(5)
            .map(|&(_, i, ulp)| Worst {
                x: (i % width.max(1) as usize) as u32,
                y: (i / width.max(1) as usize) as u32,
                emulator: emulator[i],
                gpu: gpu[i],
                ulp,
            })
            .collect();
        s
    }

    /// Whether every pixel is bit-identical.
    pub fn all_identical(&self) -> bool {
        self.identical == self.pixels
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_distances() {
        assert_eq!(ulp_distance(1.0, 1.0), Some(0));
        assert_eq!(
            ulp_distance(1.0, f32::from_bits(1.0f32.to_bits() + 3)),
            Some(3)
        );
        assert_eq!(ulp_distance(0.0, -0.0), Some(0));
        // The smallest subnormals on either side of zero: 2 apart.
        assert_eq!(ulp_distance(f32::from_bits(1), -f32::from_bits(1)), Some(2));
        assert_eq!(ulp_distance(f32::NAN, 1.0), None);
        assert_eq!(ulp_distance(f32::NAN, f32::NAN), Some(0));
        assert_eq!(ulp_distance(f32::INFINITY, f32::MAX), None);
        assert_eq!(ulp_distance(f32::INFINITY, f32::NEG_INFINITY), None);
        assert_eq!(ulp_distance(f32::INFINITY, f32::INFINITY), Some(0));
    }

    #[test]
    fn channel_stats_count_buckets_and_rank_the_worst() {
        let one = 1.0f32;
        let up = |k: u32| f32::from_bits(one.to_bits() + k);
        let e = [one, one, one, one, 0.0, 2.0];
        let g = [one, up(1), up(4), up(300), -0.0, f32::NAN];
        let s = ChannelStats::of("oC0.r".into(), 3, &e, &g);
        assert_eq!(s.identical, 1);
        assert_eq!(s.histogram, [2, 1, 0, 1, 0, 0, 1, 0]);
        assert_eq!(s.max_ulp, 300);
        assert_eq!(s.nan_mismatches, 1);
        assert_eq!(s.subnormal_flushes, 0);
        let f = ChannelStats::of("x".into(), 1, &[1e-40, 0.0], &[0.0, 0.0]);
        assert_eq!((f.identical, f.subnormal_flushes), (1, 1));
        assert_eq!((s.worst[0].x, s.worst[0].y, s.worst[0].ulp), (2, 1, None));
        assert_eq!(s.worst[1].ulp, Some(300));
        assert_eq!(bucket_label(3), "3–4");
        assert_eq!(bucket_label(7), ">65,536");
    }
}
