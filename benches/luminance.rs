//! The luminance pipeline's speed, measured side by side in one criterion
//! group on the article's frame size (`courtyard_1280x1024.exr`), so that
//! every ratio comes from one run:
//!
//! * `reference/f64`: the CPU reference's L̄w (every pixel once), one thread;
//! * `native/f32`: the floor — what pass 1 computes, written as a plain f32
//!   loop (luminance dot, `f32::log2`, block sums), one thread;
//! * `emulate/unrolled`: both passes of the corrected unrolled shaders
//!   (125×128 blocks), one emulator thread; `emulate/unrolled+lod` the same
//!   with `Draw::record_lod` on pass 1, as `ps30 luminance` runs it;
//!   `emulate/loop`: the corrected loop shaders (128×56 blocks);
//! * `pass1/1t`, `pass1/2t`: pass 1 alone on one and two emulator threads;
//! * `phase/decode/Nt`, `phase/crosscheck/Nt`: decoding the file, and the
//!   f64 cross-check's one scan (every term, the block bounds, the
//!   reference), on N threads;
//! * `command/luminance|tonemap|run/Nt`: what `ps30 luminance`, `ps30
//!   tonemap -o x.png` and `ps30 run` compute (decoding and, for the first
//!   two, the planned block's generated shaders included; tonemap's bands
//!   encoded to 8-bit sRGB, the PNG not compressed; no printing) with all
//!   their work on N threads, as `--threads N` runs them;
//! * `gpu/unrolled`, `gpu/loop`: the `emulate/*` draws on the GPU backend
//!   (the first Vulkan adapter: llvmpipe here), each pass as `--backend
//!   gpu` runs it — translation, pipeline, the image uploaded, the draw,
//!   the target read back; `gpu/pass1/Nt`: pass 1 alone that way on
//!   llvmpipe (the CPU adapter, even beside a real GPU) with N threads
//!   (`LP_NUM_THREADS`), beside `pass1/Nt`; `gpu/pass1-draw/Nt`: llvmpipe's
//!   draw alone — the shader translated, its pipeline compiled and the
//!   image uploaded once, beforehand; each iteration draws and reads the
//!   target back (`gpu::prepare`, `Prepared::draw`). Skipped, with a line
//!   saying so, without an adapter.
//!
//! The cross-check's bounds are not part of the `emulate/*` entries.
//!
//! The CPU entries run first, in the order above except that each
//! goal's two entries run back to back (`phase/decode/1t`, then
//! `command/luminance/1t` and `command/luminance/2t`, then
//! `phase/decode/2t`; the two `tonemap` entries; the two `run` entries): a
//! shared machine's speed drifts over minutes, and a ratio of times taken
//! minutes apart would carry the drift. The `gpu/*` entries run
//! last, their devices opened only then.
//!
//! After criterion's summary the benchmark prints the speed goals' table
//! (`support/goals.rs`): each goal's ratio from this run's entries, with the
//! machine stated; then, for the goals on the CPU whose entries ran (all but
//! the two against llvmpipe), the paired table: the goal's two workloads
//! timed in turn, 20 times, in this process (about 11 seconds for all six
//! here, nearly all of it the commands'). Both are also written to
//! `<criterion's directory>/courtyard_1280x1024/goals.md`.

#[path = "support/draws.rs"]
mod draws;
#[path = "support/goals.rs"]
mod goals;

use criterion::{criterion_group, Criterion};
use ps30::core::emu::{self, Address, Constants, Draw, Filter, LinearInput, SamplerState};
use ps30::core::gpu::{self, Gpu, TargetKind};
use ps30::core::image::{load, load_beside, HdrImage, ImageLimits, RenderTarget, TargetFormat};
use ps30::core::ir::Shader;
use ps30::core::load::{load_str, Loaded, Options};
use ps30::jobs::blocks;
use ps30::jobs::bundled::{CORRECTED_LOOP, CORRECTED_PASS2, CORRECTED_UNROLLED};
use ps30::jobs::luminance::reference::{self, Policy, DEFAULT_DELTA};
use ps30::jobs::luminance::{self, run_pass, PassSetup};
use ps30::jobs::tonemap;
use std::hint::black_box;
use std::path::Path;

/// The group every entry belongs to.
const GROUP: &str = "courtyard_1280x1024";

/// The adapter `gpu/pass1*/Nt` drew on, for the goals' table.
static PEER: std::sync::OnceLock<String> = std::sync::OnceLock::new();

fn shader(src: (&str, &str), defines: &[(&str, u64)]) -> Shader {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    load_str(src.0, src.1, &opts).unwrap().shader
}

/// Both passes, as the emulator and the GPU backend take them.
struct Passes {
    shaders: [Shader; 2],
    compiled: [emu::Compiled; 2],
}

impl Passes {
    fn new(pass1: Shader, pass2: Shader) -> Passes {
        let compiled = [&pass1, &pass2].map(|s| emu::compile(s).unwrap());
        Passes {
            shaders: [pass1, pass2],
            compiled,
        }
    }
}

/// Who draws a pass: the emulator on a number of threads, or a GPU.
#[derive(Clone, Copy)]
enum Drawer<'a> {
    Emulator(&'a Passes, usize),
    Gpu(&'a Gpu, &'a Passes),
}

impl Drawer<'_> {
    /// Pass `k`'s oC0, one value per pixel.
    fn draw(self, k: usize, d: &Draw) -> Vec<[f32; 4]> {
        let out = match self {
            Drawer::Emulator(p, threads) => {
                emu::run_with_threads(&p.compiled[k], d, threads)
                    .unwrap()
                    .color
            }
            Drawer::Gpu(g, p) => {
                let kind = TargetKind::Format(TargetFormat::R32F);
                gpu::run(g, &p.shaders[k], d, kind).unwrap().color
            }
        };
        out.into_iter().next().flatten().unwrap()
    }
}

fn state() -> SamplerState {
    SamplerState {
        address_u: Address::Border,
        address_v: Address::Border,
        address_w: Address::Border,
        border: [0.0; 4],
        ..SamplerState::filtered(Filter::Point)
    }
}

/// Pass 1's draw: an `nx × ny` target, each pixel summing one block.
fn pass1_draw(img: &HdrImage, bw: u32, bh: u32, record_lod: bool) -> Draw<'_> {
    let mut d1 = draws::pass1_draw(img, bw, bh, state());
    d1.record_lod = record_lod;
    d1
}

/// Pass 1: the `nx × ny` R32F target.
fn pass1(img: &HdrImage, by: Drawer, bw: u32, bh: u32, record_lod: bool) -> RenderTarget {
    let d1 = pass1_draw(img, bw, bh, record_lod);
    let (nx, ny) = (d1.target_width, d1.target_height);
    let out1 = by.draw(0, &d1);
    let mut t1 = RenderTarget::new(nx, ny, TargetFormat::R32F);
    for (i, v) in out1.iter().enumerate() {
        t1.store(i as u32 % nx, i as u32 / nx, *v);
    }
    t1
}

/// Pass 1 then pass 2; returns L̄w.
fn two_pass(img: &HdrImage, by: Drawer, bw: u32, bh: u32, record_lod: bool) -> f32 {
    let (w, h) = (img.width, img.height);
    let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
    let t1 = pass1(img, by, bw, bh, record_lod);
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
    by.draw(1, &d2)[0][0]
}

/// The floor: pass 1's arithmetic as a plain f32 loop over 125×128 blocks
/// (black outside the image, as BORDER addressing reads), returning the sum
/// of the block sums so nothing is optimised away.
fn native_f32(img: &HdrImage, bw: u32, bh: u32) -> f32 {
    let (w, h) = (img.width, img.height);
    let black = 1e-4f32.log2();
    let mut total = 0.0;
    for by in 0..h.div_ceil(bh) {
        for bx in 0..w.div_ceil(bw) {
            let mut sum = 0f32;
            for y in by * bh..(by + 1) * bh {
                for x in bx * bw..(bx + 1) * bw {
                    sum += if x < w && y < h {
                        let p = img.pixels[(y * w + x) as usize];
                        (0.27 * p[0] + 0.67 * p[1] + 0.06 * p[2] + 1e-4)
                            .abs()
                            .log2()
                    } else {
                        black
                    };
                }
            }
            total += sum;
        }
    }
    total
}

/// Runs `f` with all of its parallel work on `threads` threads.
fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

/// The workloads that both an entry times and the paired measurement
/// (`goals::paired`) alternates with its goal's other workload: the
/// emulator's two passes, the f64 reference and the native floor on the
/// decoded image, one thread each; decoding alone and the whole commands on
/// N threads.
struct Workloads {
    path: std::path::PathBuf,
    loop1: Loaded,
    img: HdrImage,
    unrolled: Passes,
}

impl Workloads {
    fn new() -> Workloads {
        let (name, text) = CORRECTED_LOOP.listing();
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr/courtyard_1280x1024.exr");
        Workloads {
            img: load(&path, &ImageLimits::default()).unwrap(),
            path,
            loop1: load_str(name, text, &Options::default()).unwrap(),
            unrolled: Passes::new(
                shader(CORRECTED_UNROLLED.listing(), &[]),
                shader(CORRECTED_PASS2.listing(), &[("xsize", 11), ("ysize", 8)]),
            ),
        }
    }

    /// The workload of the entry `name`: `reference/f64`, `native/f32`,
    /// `emulate/unrolled` (one thread), `phase/decode/Nt` or
    /// `command/luminance|tonemap|run/Nt` (all its work on N threads).
    fn workload(&self, name: &str) -> Option<Box<dyn FnMut() + '_>> {
        let on_one: Option<fn(&Workloads)> = match name {
            "reference/f64" => Some(|w| {
                black_box(on_threads(1, || {
                    reference::log_average(black_box(&w.img), 1e-4, Policy::ABS).log_average
                }));
            }),
            "native/f32" => Some(|w| {
                black_box(native_f32(black_box(&w.img), 125, 128));
            }),
            "emulate/unrolled" => Some(|w| {
                let by = Drawer::Emulator(&w.unrolled, 1);
                black_box(two_pass(black_box(&w.img), by, 125, 128, false));
            }),
            _ => None,
        };
        if let Some(work) = on_one {
            return Some(Box::new(move || work(self)));
        }
        let (what, threads) = name.rsplit_once('/')?;
        let t: usize = threads.strip_suffix('t')?.parse().ok()?;
        let work: fn(&Workloads, usize) = match what {
            "phase/decode" => |w, _| {
                black_box(load(&w.path, &ImageLimits::default()).unwrap().width);
            },
            "command/luminance" => |w, t| {
                black_box(w.luminance(t));
            },
            "command/tonemap" => |w, t| {
                black_box(w.tonemap(t));
            },
            "command/run" => |w, t| {
                black_box(w.run(t));
            },
            _ => return None,
        };
        Some(Box::new(move || on_threads(t, || work(self, t))))
    }

    /// As `ps30 luminance IMAGE` runs: the block planned for the image
    /// (beside the decoding) and the shaders generated for it.
    fn luminance(&self, t: usize) -> f64 {
        let (img, planned) = load_beside(&self.path, &ImageLimits::default(), |w, h| {
            blocks::planned(w, h, DEFAULT_DELTA)
        })
        .unwrap();
        let planned = planned.unwrap();
        let settings = luminance::Settings {
            block: planned.block(),
            threads: Some(t),
            ..Default::default()
        };
        luminance::run(&img, &planned.pass1, &planned.pass2, &settings)
            .unwrap()
            .log_average
    }

    /// As `ps30 tonemap IMAGE -o x.png` runs, short of compressing the PNG:
    /// each band encoded to 8-bit sRGB.
    fn tonemap(&self, t: usize) -> usize {
        let img = load(&self.path, &ImageLimits::default()).unwrap();
        let settings = tonemap::Settings {
            threads: Some(t),
            ..Default::default()
        };
        let mut rgb = Vec::with_capacity(3 * img.pixels.len());
        tonemap::run_into(&img, &settings, &|_, _| {}, &mut |band| {
            rgb.extend(tonemap::to_srgb8(band));
            Ok(())
        })
        .unwrap();
        rgb.len()
    }

    /// `ps30 run corrected:loop` over the image into a 10×8 target (128×128
    /// blocks), as the README's example does on another image.
    fn run(&self, threads: usize) -> f32 {
        let img = load(&self.path, &ImageLimits::default()).unwrap();
        let setup = PassSetup {
            target: (10, 8),
            constants: Constants {
                float: vec![
                    [0.0; 4],
                    [1.0 / 1280.0, 1.0 / 1024.0, 0.0, 1.0],
                    [0.0; 4],
                    [0.27, 0.67, 0.06, 0.01],
                ],
                int: vec![[0; 4], [128, 0, 0, 0], [128, 0, 0, 0]],
                bool: Vec::new(),
            },
            sampler: state(),
            format: TargetFormat::R32F,
            threads: Some(threads),
            limits: emu::EmuLimits::default(),
            backend: ps30::jobs::backend::Backend::Emulator,
            float_rules: ps30::core::float_rules::FloatRules::D3d9,
            textures: Vec::new(),
            inputs: Vec::new(),
        };
        run_pass(&self.loop1, Some(&img), &setup)
            .unwrap()
            .target
            .texel(0, 0)[0]
    }
}

fn luminance(c: &mut Criterion) {
    let work = Workloads::new();
    let (img, unrolled) = (&work.img, &work.unrolled);
    let looped = Passes::new(
        shader(CORRECTED_LOOP.listing(), &[]),
        shader(CORRECTED_PASS2.listing(), &[("xsize", 10), ("ysize", 19)]),
    );
    let mut g = c.benchmark_group(GROUP);
    g.sample_size(10);
    let entry = |g: &mut criterion::BenchmarkGroup<'_, _>, name: &str| {
        let mut work = work.workload(name).expect("an entry with a workload");
        g.bench_function(name, |b| b.iter(&mut work));
    };
    for name in ["reference/f64", "native/f32", "emulate/unrolled"] {
        entry(&mut g, name);
    }
    g.bench_function("emulate/unrolled+lod", |b| {
        b.iter(|| {
            two_pass(
                black_box(img),
                Drawer::Emulator(unrolled, 1),
                125,
                128,
                true,
            )
        })
    });
    g.bench_function("emulate/loop", |b| {
        b.iter(|| two_pass(black_box(img), Drawer::Emulator(&looped, 1), 128, 56, false))
    });
    for t in [1, 2] {
        g.bench_function(format!("pass1/{t}t"), |b| {
            b.iter(|| {
                pass1(
                    black_box(img),
                    Drawer::Emulator(unrolled, t),
                    125,
                    128,
                    false,
                )
            })
        });
    }
    // Each goal's two entries back to back (see the module docs): decoding
    // on one thread, the command on one and on two, decoding on two.
    entry(&mut g, "phase/decode/1t");
    entry(&mut g, "command/luminance/1t");
    entry(&mut g, "command/luminance/2t");
    entry(&mut g, "phase/decode/2t");
    for t in [1, 2] {
        g.bench_function(format!("phase/crosscheck/{t}t"), |b| {
            b.iter(|| {
                on_threads(t, || {
                    luminance::pass1_bounds(black_box(img), (125, 128), 1e-4, Policy::ABS).1
                })
            })
        });
    }
    for name in [
        "command/tonemap/1t",
        "command/tonemap/2t",
        "command/run/1t",
        "command/run/2t",
    ] {
        entry(&mut g, name);
    }
    // The GPU entries come last, and the Vulkan devices are opened only
    // now, so that no driver's threads or allocations are in the process
    // while the CPU entries run — as none are in a `ps30 luminance` one.
    gpu_entries(&mut g, img, unrolled, &looped);
    g.finish();
}

/// The `gpu/*` entries, on the first Vulkan adapter and on llvmpipe.
fn gpu_entries(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    img: &HdrImage,
    unrolled: &Passes,
    looped: &Passes,
) {
    let device = Gpu::open();
    match &device {
        Ok(d) => {
            g.bench_function("gpu/unrolled", |b| {
                b.iter(|| two_pass(black_box(img), Drawer::Gpu(d, unrolled), 125, 128, false))
            });
            g.bench_function("gpu/loop", |b| {
                b.iter(|| two_pass(black_box(img), Drawer::Gpu(d, looped), 128, 56, false))
            });
        }
        Err(e) => eprintln!("gpu/unrolled, gpu/loop: skipped: {e}"),
    }
    // The peer is llvmpipe, a CPU adapter, opened even beside a real GPU.
    // It reads LP_NUM_THREADS when a device is created: one device per
    // thread count, for pass 1 beside `pass1/1t` and `pass1/2t` — as the
    // backend runs it, and its draw alone.
    for t in [1, 2] {
        std::env::set_var("LP_NUM_THREADS", t.to_string());
        let lp = Gpu::open_cpu();
        std::env::remove_var("LP_NUM_THREADS");
        match &lp {
            Ok(d) => {
                PEER.get_or_init(|| d.info().name.clone());
                g.bench_function(format!("gpu/pass1/{t}t"), |b| {
                    b.iter(|| pass1(black_box(img), Drawer::Gpu(d, unrolled), 125, 128, false))
                });
                let draw = pass1_draw(img, 125, 128, false);
                let kind = TargetKind::Format(TargetFormat::R32F);
                let ready = gpu::prepare(d, &unrolled.shaders[0], &draw, kind).unwrap();
                g.bench_function(format!("gpu/pass1-draw/{t}t"), |b| {
                    b.iter(|| ready.draw().unwrap().color.len())
                });
            }
            Err(e) => eprintln!("gpu/pass1/{t}t, gpu/pass1-draw/{t}t: skipped: {e}"),
        }
    }
}

criterion_group!(benches, luminance);

/// How many ratios the paired measurement takes for each goal.
const PAIRS: usize = 20;

/// The paired measurement (`goals::paired`) of every goal on the CPU whose
/// two entries this run measured.
fn paired_rows(times: &[(String, f64)]) -> Vec<(&'static goals::Goal, goals::Paired)> {
    let work = Workloads::new();
    let measured = |name: &str| times.iter().any(|(n, _)| n == name);
    let mut rows = Vec::new();
    for g in goals::GOALS {
        if !(measured(g.numerator) && measured(g.denominator)) {
            continue;
        }
        let (Some(mut a), Some(mut b)) = (work.workload(g.numerator), work.workload(g.denominator))
        else {
            continue; // a goal on llvmpipe: no workload here
        };
        eprintln!("paired: {} / {}, {PAIRS} times", g.numerator, g.denominator);
        rows.extend(goals::paired(PAIRS, &mut a, &mut b).map(|p| (g, p)));
    }
    rows
}

/// criterion's own `main`, then the goals' table from this run's entries.
fn main() {
    let started = std::time::SystemTime::now();
    benches();
    Criterion::default().configure_from_args().final_summary();
    let times = goals::criterion_dirs()
        .into_iter()
        .map(|dir| (goals::measured(&dir, GROUP, started), dir))
        .find(|(times, _)| !times.is_empty());
    let Some((times, dir)) = times else {
        return; // nothing measured: a listing, a filter that matched nothing
    };
    let mut table = goals::table(&goals::machine(PEER.get().map(String::as_str)), &times);
    println!("\n{table}");
    let paired = goals::paired_table(&paired_rows(&times));
    if !paired.is_empty() {
        println!("{paired}");
        table = format!("{table}\n{paired}");
    }
    let path = dir.join(GROUP).join("goals.md");
    if let Err(e) = std::fs::write(&path, &table) {
        eprintln!("goals: could not write {}: {e}", path.display());
    }
}
