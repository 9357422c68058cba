//! The luminance pipeline's speed against the f64 CPU reference, measured in
//! one run on the article's frame size (`courtyard_1280x1024.exr`):
//!
//! * `reference/f64`: the CPU reference's L̄w (every pixel once);
//! * `emulate/unrolled`: both passes of the corrected unrolled shaders
//!   (125×128 blocks), one emulator thread;
//! * `emulate/unrolled+lod`: the same with `Draw::record_lod` on pass 1,
//!   as `ps30 luminance` runs it (the LOD statistic behind its warning);
//! * `emulate/loop`: both passes of the corrected loop shaders (128×56
//!   blocks), one emulator thread.
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

fn compile(src: (&str, &str), defines: &[(&str, u64)]) -> emu::Compiled {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    emu::compile(&load_str(src.0, src.1, &opts).unwrap().shader).unwrap()
}

fn state() -> SamplerState {
    SamplerState {
        address_u: Address::Border,
        address_v: Address::Border,
        border: [0.0; 4],
        ..SamplerState::filtered(Filter::Point)
    }
}

/// Pass 1 then pass 2 on one thread; returns L̄w.
fn two_pass(
    img: &ps30::core::image::HdrImage,
    p1: &emu::Compiled,
    p2: &emu::Compiled,
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
    let out1 = emu::run_with_threads(p1, &d1, 1).unwrap();
    let mut t1 = RenderTarget::new(nx, ny, TargetFormat::R32F);
    for (i, v) in out1.color[0].as_ref().unwrap().iter().enumerate() {
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
    emu::run_with_threads(p2, &d2, 1).unwrap().color[0]
        .as_ref()
        .unwrap()[0][0]
}

fn luminance(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr/courtyard_1280x1024.exr");
    let img = load(&path, &ImageLimits::default()).unwrap();
    let unrolled = (
        compile(CORRECTED_UNROLLED.listing(), &[]),
        compile(CORRECTED_PASS2.listing(), &[("xsize", 11), ("ysize", 8)]),
    );
    let looped = (
        compile(CORRECTED_LOOP.listing(), &[]),
        compile(CORRECTED_PASS2.listing(), &[("xsize", 10), ("ysize", 19)]),
    );
    let mut g = c.benchmark_group("courtyard_1280x1024");
    g.sample_size(20);
    g.bench_function("reference/f64", |b| {
        b.iter(|| reference::log_average(black_box(&img), 1e-4, Policy::ABS).log_average)
    });
    g.bench_function("emulate/unrolled", |b| {
        b.iter(|| two_pass(black_box(&img), &unrolled.0, &unrolled.1, 125, 128, false))
    });
    g.bench_function("emulate/unrolled+lod", |b| {
        b.iter(|| two_pass(black_box(&img), &unrolled.0, &unrolled.1, 125, 128, true))
    });
    g.bench_function("emulate/loop", |b| {
        b.iter(|| two_pass(black_box(&img), &looped.0, &looped.1, 128, 56, false))
    });
    g.finish();
}

criterion_group!(benches, luminance);
criterion_main!(benches);
