//! The luminance pipeline's speed against the f64 CPU reference, measured in
//! one run on the article's frame size (`courtyard_1280x1024.exr`):
//!
//! * `reference/f64`: the CPU reference's L̄w (every pixel once);
//! * `emulate/unrolled`: both passes of the corrected unrolled shaders
//!   (125×128 blocks), one emulator thread;
//! * `emulate/unrolled+lod`: the same with `Draw::record_lod` on pass 1,
//!   as `ps30 luminance` runs it (the LOD statistic behind its warning);
//! * `emulate/loop`: both passes of the corrected loop shaders (128×56
//!   blocks), one emulator thread;
//! * `gpu/unrolled`, `gpu/loop`: the same draws on the GPU backend (the
//!   first Vulkan adapter: llvmpipe here), each pass as `--backend gpu`
//!   runs it — translation, pipeline, the image uploaded, the draw, the
//!   target read back. Skipped, with a line saying so, without an adapter.
//!
//! The target is `emulate/unrolled` within 3× of `reference/f64`.
//! The cross-check (block bounds) is not part of the timed work.

use criterion::{criterion_group, criterion_main, Criterion};
use ps30::core::emu::{self, Address, Constants, Draw, Filter, LinearInput, SamplerState};
use ps30::core::image::{load, ImageLimits, RenderTarget, TargetFormat};
use ps30::core::load::{load_str, Options};
use ps30::jobs::bundled::{CORRECTED_LOOP, CORRECTED_PASS2, CORRECTED_UNROLLED};
use ps30::jobs::luminance::reference::{self, Policy};
use std::hint::black_box;
use std::path::Path;

fn shader(src: (&str, &str), defines: &[(&str, u64)]) -> ps30::core::ir::Shader {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    load_str(src.0, src.1, &opts).unwrap().shader
}

/// How a pass is drawn: oC0 per pixel.
type Backend<'a> = &'a dyn Fn(usize, &Draw) -> Vec<[f32; 4]>;

fn state() -> SamplerState {
    SamplerState {
        address_u: Address::Border,
        address_v: Address::Border,
        border: [0.0; 4],
        ..SamplerState::filtered(Filter::Point)
    }
}

/// Pass 1 (`run(0, …)`) then pass 2 (`run(1, …)`); returns L̄w.
fn two_pass(
    img: &ps30::core::image::HdrImage,
    run: Backend,
    bw: u32,
    bh: u32,
    record_lod: bool,
) -> f32 {
    let (w, h) = (img.width, img.height);
    let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
    let mut d1 = Draw::new(nx, ny);
    d1.record_lod = record_lod;
    d1.inputs.push((
        0,
        LinearInput {
            base: [0.5 / w as f32, 0.5 / h as f32, 0.0, 0.0],
            ddx: [bw as f32 / w as f32, 0.0, 0.0, 0.0],
            ddy: [0.0, bh as f32 / h as f32, 0.0, 0.0],
        },
    ));
    d1.constants = Constants {
        float: vec![
            [0.0; 4],
            [1.0 / w as f32, 1.0 / h as f32, 0.0, 1.0],
            [0.0; 4],
            [0.27, 0.67, 0.06, 0.01],
        ],
        int: vec![[0; 4], [bw as i32, 0, 0, 0], [bh as i32, 0, 0, 0]],
        bool: Vec::new(),
    };
    d1.samplers.push((0, img.as_texture().into(), state()));
    let out1 = run(0, &d1);
    let mut t1 = RenderTarget::new(nx, ny, TargetFormat::R32F);
    for (i, v) in out1.iter().enumerate() {
        t1.store(i as u32 % nx, i as u32 / nx, *v);
    }
    let mut d2 = Draw::new(1, 1);
    d2.inputs.push((
        0,
        LinearInput::constant([0.5 / nx as f32, 0.5 / ny as f32, 0.0, 0.0]),
    ));
    d2.constants.float = vec![
        [1.0 / (w * h) as f32, 0.0, 0.0, 0.0],
        [1.0 / nx as f32, 1.0 / ny as f32, 0.0, 1.0],
    ];
    d2.samplers.push((0, t1.as_texture().into(), state()));
    run(1, &d2)[0][0]
}

/// The emulator on one thread.
fn emulator(passes: &[emu::Compiled; 2]) -> impl Fn(usize, &Draw) -> Vec<[f32; 4]> + '_ {
    move |k, d| {
        emu::run_with_threads(&passes[k], d, 1).unwrap().color[0]
            .take()
            .unwrap()
    }
}

/// The GPU backend, targets in R32Float.
fn gpu<'a>(
    g: &'a ps30::core::gpu::Gpu,
    passes: &'a [ps30::core::ir::Shader; 2],
) -> impl Fn(usize, &Draw) -> Vec<[f32; 4]> + 'a {
    move |k, d| {
        let kind = ps30::core::gpu::TargetKind::Format(TargetFormat::R32F);
        ps30::core::gpu::run(g, &passes[k], d, kind).unwrap().color[0]
            .take()
            .unwrap()
    }
}

fn luminance(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr/courtyard_1280x1024.exr");
    let img = load(&path, &ImageLimits::default()).unwrap();
    let unrolled = [
        shader(CORRECTED_UNROLLED.listing(), &[]),
        shader(CORRECTED_PASS2.listing(), &[("xsize", 11), ("ysize", 8)]),
    ];
    let looped = [
        shader(CORRECTED_LOOP.listing(), &[]),
        shader(CORRECTED_PASS2.listing(), &[("xsize", 10), ("ysize", 19)]),
    ];
    let compiled = |s: &[ps30::core::ir::Shader; 2]| s.clone().map(|s| emu::compile(&s).unwrap());
    let (emu_unrolled, emu_looped) = (compiled(&unrolled), compiled(&looped));
    let device = ps30::core::gpu::Gpu::open();
    let mut g = c.benchmark_group("courtyard_1280x1024");
    g.sample_size(20);
    g.bench_function("reference/f64", |b| {
        b.iter(|| reference::log_average(black_box(&img), 1e-4, Policy::ABS).log_average)
    });
    let e = emulator(&emu_unrolled);
    g.bench_function("emulate/unrolled", |b| {
        b.iter(|| two_pass(black_box(&img), &e, 125, 128, false))
    });
    g.bench_function("emulate/unrolled+lod", |b| {
        b.iter(|| two_pass(black_box(&img), &e, 125, 128, true))
    });
    let e = emulator(&emu_looped);
    g.bench_function("emulate/loop", |b| {
        b.iter(|| two_pass(black_box(&img), &e, 128, 56, false))
    });
    match &device {
        Ok(d) => {
            let run = gpu(d, &unrolled);
            g.bench_function("gpu/unrolled", |b| {
                b.iter(|| two_pass(black_box(&img), &run, 125, 128, false))
            });
            let run = gpu(d, &looped);
            g.bench_function("gpu/loop", |b| {
                b.iter(|| two_pass(black_box(&img), &run, 128, 56, false))
            });
        }
        Err(e) => eprintln!("gpu/unrolled, gpu/loop: skipped: {e}"),
    }
    g.finish();
}

criterion_group!(benches, luminance);
criterion_main!(benches);
