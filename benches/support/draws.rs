//! The article's pass 1 as a draw, shared by the benchmarks that draw it
//! (`luminance.rs` on every backend, `gpu.rs` beside the hand-written WGSL).

use ps30::core::emu::{Constants, Draw, LinearInput, SamplerState};
use ps30::core::image::HdrImage;

/// Pass 1's draw: an `nx × ny` target, each pixel summing one `bw × bh`
/// block of `img` through sampler state `state`.
pub fn pass1_draw(img: &HdrImage, bw: u32, bh: u32, state: SamplerState) -> Draw<'_> {
    let (w, h) = (img.width, img.height);
    let mut d = Draw::new(w.div_ceil(bw), h.div_ceil(bh));
    d.inputs.push((
        0,
        LinearInput {
            base: [0.5 / w as f32, 0.5 / h as f32, 0.0, 0.0],
            ddx: [bw as f32 / w as f32, 0.0, 0.0, 0.0],
            ddy: [0.0, bh as f32 / h as f32, 0.0, 0.0],
        },
    ));
    d.constants = Constants {
        float: vec![
            [0.0; 4],
            [1.0 / w as f32, 1.0 / h as f32, 0.0, 1.0],
            [0.0; 4],
            [0.27, 0.67, 0.06, 0.01],
        ],
        int: vec![[0; 4], [bw as i32, 0, 0, 0], [bh as i32, 0, 0, 0]],
        bool: Vec::new(),
    };
    d.samplers.push((0, img.as_texture().into(), state));
    d
}
