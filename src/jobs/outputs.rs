//! What a pass wrote, register by register and channel by channel: which
//! outputs (`oC0`…`oC3`, `oDepth`) and components the shader writes, which
//! of them the render target stores, and the minimum, maximum and mean of
//! every stored channel — so `ps30 run` reports everything the shader
//! produced, not only `oC0.r`.

use crate::core::image::RenderTarget;
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use serde::Serialize;

/// One output register the shader writes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct OutputRegister {
    /// `oC0`, `oC1`, …, `oDepth`.
    pub register: String,
    /// The components some instruction writes (`rgba` letters), in order.
    pub written: String,
    /// Per stored channel of the target, its statistics; empty when the
    /// pass binds no target to this register.
    pub stored: Vec<ChannelStats>,
    /// Written components the target's format does not store (R32F keeps
    /// red only), in `rgba` letters.
    pub dropped: String,
}

/// Statistics of one stored channel over every texel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ChannelStats {
    /// `r`, `g`, `b` or `a`.
    pub channel: char,
    /// Over the finite values (`None` when there is none).
    pub min: Option<f64>,
    /// Over the finite values.
    pub max: Option<f64>,
    /// Over the finite values.
    pub mean: Option<f64>,
    /// Texels whose value is NaN or infinite.
    pub non_finite: u64,
}

const LETTERS: [char; 4] = ['r', 'g', 'b', 'a'];

/// The outputs of `shader`, with the statistics of `target` (the target
/// bound to `oC0`) for what it stores.
pub fn summarise(shader: &Shader, target: &RenderTarget) -> Vec<OutputRegister> {
    // A ps_1_x shader's colour is its r0, which its lowering writes to oC0.
    let shader = shader.runnable().unwrap_or(shader);
    let mut masks: Vec<(RegFile, u32, u8)> = Vec::new();
    for instr in shader.instructions() {
        let Some(dst) = &instr.dst else { continue };
        if !matches!(dst.reg.file, RegFile::ColorOut | RegFile::DepthOut) {
            continue;
        }
        match masks
            .iter_mut()
            .find(|(f, i, _)| *f == dst.reg.file && *i == dst.reg.index)
        {
            Some(entry) => entry.2 |= dst.mask.0,
            None => masks.push((dst.reg.file, dst.reg.index, dst.mask.0)),
        }
    }
    masks.sort_by_key(|&(file, index, _)| (file == RegFile::DepthOut, index));
    masks
        .into_iter()
        .map(|(file, index, mask)| {
            let has = |c: usize| mask & (1 << c) != 0;
            if file == RegFile::DepthOut {
                return OutputRegister {
                    register: "oDepth".to_string(),
                    written: String::new(),
                    stored: Vec::new(),
                    dropped: String::new(),
                };
            }
            let stores = |c: usize| target.format.stores(c);
            let bound = index == 0;
            OutputRegister {
                register: format!("oC{index}"),
                written: (0..4).filter(|&c| has(c)).map(|c| LETTERS[c]).collect(),
                stored: (0..4)
                    .filter(|&c| bound && has(c) && stores(c))
                    .map(|c| channel_stats(target, c))
                    .collect(),
                dropped: (0..4)
                    .filter(|&c| bound && has(c) && !stores(c))
                    .map(|c| LETTERS[c])
                    .collect(),
            }
        })
        .collect()
}

fn channel_stats(target: &RenderTarget, c: usize) -> ChannelStats {
    let (mut min, mut max, mut sum, mut n, mut non_finite) =
        (f64::INFINITY, f64::NEG_INFINITY, 0f64, 0u64, 0u64);
    for t in &target.texels {
        let v = t[c] as f64;
        if v.is_finite() {
            min = min.min(v);
            max = max.max(v);
            sum += v;
            n += 1;
        } else {
            non_finite += 1;
        }
    }
    let some = |v: f64| (n > 0).then_some(v);
    ChannelStats {
        channel: LETTERS[c],
        min: some(min),
        max: some(max),
        mean: some(sum / n.max(1) as f64),
        non_finite,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::load::{load_str, Options};

    #[test]
    fn every_written_register_and_channel_is_listed() {
        let src = "ps_3_0\ndef c0, 1, 2, 3, 4\nmov oC0.xy, c0\nmov oC0.w, c0\nmov oC1, c0\nmov oDepth, c0.x\n";
        let l = load_str("t.psh", src, &Options::default()).unwrap();
        let mut t = RenderTarget::new(2, 1, crate::core::image::TargetFormat::R32F);
        t.store(0, 0, [1.0, 2.0, 0.0, 4.0]);
        t.store(1, 0, [f32::NEG_INFINITY, 0.0, 0.0, 0.0]);
        let out = summarise(&l.shader, &t);
        let names: Vec<&str> = out.iter().map(|o| o.register.as_str()).collect();
        assert_eq!(names, ["oC0", "oC1", "oDepth"]);
        assert_eq!(out[0].written, "rga");
        assert_eq!(out[0].dropped, "ga");
        assert_eq!(out[0].stored.len(), 1);
        let r = &out[0].stored[0];
        assert_eq!((r.min, r.max, r.non_finite), (Some(1.0), Some(1.0), 1));
        assert!(out[1].stored.is_empty());
    }
}
