//! Run a pixel shader over an HDR image in the emulator and read the result:
//! every pixel of a bundled image scaled by a constant, its luminance
//! compared with the same arithmetic on the CPU.
//!
//! ```text
//! cargo run --example run_over_image
//! ```

use ps30::core::{emu, image, load};
use ps30::jobs::{assets, luminance};

/// Samples the image at each pixel's texel and scales it by c0.
const SHADER: &str = "\
ps_3_0
dcl_texcoord0 v0.xy
dcl_2d s0
texld r0, v0, s0
mul oC0, r0, c0
";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let img = assets::load("city.exr")?;
    let loaded = load::load_str("scale.psh", SHADER, &load::Options::default())
        .map_err(|e| e.diagnostics.render(&e.file))?;
    let compiled = emu::compile(&loaded.shader)?;

    // One pixel of the target per texel: v0 is each texel's centre.
    let (w, h) = (img.width, img.height);
    let mut draw = emu::Draw::new(w, h);
    draw.inputs.push((0, luminance::block_start(w, h, 1, 1)));
    draw.samplers
        .push((0, img.as_texture().into(), emu::SamplerState::default()));
    draw.constants.float = vec![[0.5, 0.5, 0.5, 1.0]];
    let out = emu::run(&compiled, &draw)?;

    // oC0, row-major; the emulator's f32 product of an exactly halved value
    // is exact, so it equals the CPU's.
    let c0 = out.color[0].as_ref().expect("the shader writes oC0");
    let mean = |px: &mut dyn Iterator<Item = [f32; 4]>| {
        let (sum, n) = px.fold((0.0, 0u64), |(s, n), p| (s + image::luminance(p), n + 1));
        sum / n as f64
    };
    let emulated = mean(&mut c0.iter().copied());
    let cpu = mean(&mut img.pixels.iter().map(|p| p.map(|c| c * 0.5)));
    println!(
        "{w}×{h} pixels, {} executed instructions per pixel; mean luminance {emulated:.6} (CPU {cpu:.6})",
        out.executed[0]
    );
    assert_eq!(emulated, cpu);
    Ok(())
}
