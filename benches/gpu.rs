//! The GPU backend's speed, in two groups, each printed as a table of
//! ratios from this run after criterion's summary:
//!
//! * `translation` (llvmpipe, the CPU adapter, even beside a real GPU, at
//!   one and two threads through `LP_NUM_THREADS`): each shader's draw
//!   alone — uploads and pipeline made once, beforehand (`gpu::prepare`);
//!   each iteration draws and reads the target back (`Prepared::draw`) —
//!   of ps30's translation (`<shader>/translated/Nt`) beside a WGSL written
//!   by hand for the same computation on the same resources
//!   (`<shader>/wgsl/Nt`, `benches/wgsl/*.wgsl`, `gpu::prepare_with`). The
//!   shaders: the article's pass 1 (`asm/corrected/lum_pass1_unrolled.psh`,
//!   125×128 blocks) and the tone map (`asm/tonemap/reinhard.psh`), on the
//!   article's frame (`courtyard_1280x1024.exr`). Goal: the translation
//!   within 1.5× the hand-written shader.
//! * `uhd` (the first Vulkan adapter: a real GPU where there is one): the
//!   tone map's draw of a 3840×2160 frame (made up here: smooth gradients
//!   over six orders of magnitude) on the emulator on every core
//!   (`tonemap/emulator`, `emu::run`, its compilation done beforehand) and
//!   on the device (`tonemap/gpu`: `gpu::run`, everything a draw of `ps30
//!   tonemap --backend gpu` does — translation, pipeline, uploads, the draw
//!   and the read-back; `tonemap/gpu-draw`: the draw and read-back alone).
//!   Goal: the device's draw at least 20× faster than the emulator's.
//! * `command` (the first Vulkan adapter): whole commands as a user runs
//!   them — `ps30 tonemap` and `ps30 luminance` of the same frame written
//!   as a PFM, `--backend emulator` (every core) and `--backend gpu`, each
//!   iteration one process of the `ps30` binary built with this bench, or
//!   of the one `PS30_BENCH_BIN` names (a release build, say, on a machine
//!   the bench was copied to) (`<command>/<backend>`). Goal: the GPU at
//!   least as fast as the emulator, whole command. Beside them, `ps30
//!   render benches/lists/lines300.json` (150 lines and 50 wireframe
//!   triangles, shaded on the device through the emulator's line set-up,
//!   `run/gpu_lines.rs`) on both backends (`render-lines/<backend>`; no
//!   goal: docs/draw.md states where it stands).
//!
//! Skipped, with a line saying so, without an adapter.

#[allow(dead_code)]
#[path = "support/goals.rs"]
mod goals;

#[path = "support/draws.rs"]
mod draws;

use criterion::{criterion_group, Criterion};
use ps30::core::emu::{self, Address, Constants, Draw, Filter, LinearInput, SamplerState};
use ps30::core::gpu::{self, Gpu, TargetKind};
use ps30::core::image::{load, HdrImage, ImageLimits, RenderTarget, TargetFormat};
use ps30::core::ir::Shader;
use ps30::core::load::{load_str, Options};
use ps30::jobs::bundled::{CORRECTED_UNROLLED, TONEMAP_REINHARD};
use std::path::Path;

const TRANSLATION: &str = "translation";
const UHD: &str = "uhd";
const COMMAND: &str = "command";

/// The adapters each group drew on, for the tables.
static DEVICES: std::sync::Mutex<Vec<(&str, String)>> = std::sync::Mutex::new(Vec::new());

fn shader(src: (&str, &str)) -> Shader {
    load_str(src.0, src.1, &Options::default()).unwrap().shader
}

fn wgsl(name: &str) -> naga::Module {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("benches/wgsl")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    naga::front::wgsl::parse_str(&text).unwrap()
}

fn point(address: Address) -> SamplerState {
    SamplerState {
        address_u: address,
        address_v: address,
        border: [0.0; 4],
        ..SamplerState::filtered(Filter::Point)
    }
}

/// Pass 1's draw with 125×128 blocks, as `benches/luminance.rs` draws it.
fn pass1_draw(img: &HdrImage) -> Draw<'_> {
    draws::pass1_draw(img, 125, 128, point(Address::Border))
}

/// The tone map's draw of the whole image, as `ps30 tonemap` sets it up
/// (key 0.18, white point 50, L̄w 0.09 in `lw`).
fn tonemap_draw<'a>(img: &'a HdrImage, lw: &'a RenderTarget) -> Draw<'a> {
    let (w, h) = (img.width, img.height);
    let mut d = Draw::new(w, h);
    d.limits.max_target_pixels = d.limits.max_target_pixels.max(w as u64 * h as u64);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.5 / w as f32, 0.5 / h as f32, 0.0, 0.0],
            ddx: [1.0 / w as f32, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / h as f32, 0.0, 0.0],
        },
    ));
    let key = 0.18f32;
    d.constants = Constants {
        float: vec![
            [key, 1.0 / (key * 50.0 * 50.0), 0.0, 1.0],
            [0.27, 0.67, 0.06, 0.0],
            [0.5, 0.5, 0.0, 0.0],
        ],
        int: Vec::new(),
        bool: Vec::new(),
    };
    d.samplers
        .push((0, img.as_texture().into(), point(Address::Clamp)));
    d.samplers
        .push((1, lw.as_texture().into(), point(Address::Clamp)));
    d
}

/// A made-up 3840×2160 frame: luminance from e⁻⁴ to e⁴ across, colours
/// varying smoothly.
fn uhd_image() -> HdrImage {
    let (w, h) = (3840u32, 2160u32);
    let pixels = (0..w as usize * h as usize)
        .map(|i| {
            let (x, y) = ((i % w as usize) as f32, (i / w as usize) as f32);
            let r = ((x / w as f32) * 8.0 - 4.0).exp() * (1.0 + 0.5 * (y / 37.0).sin());
            let g = ((y / h as f32) * 6.0 - 3.0).exp();
            let b = 0.5 + 0.4 * (x / 53.0 + y / 71.0).cos();
            [r, g, b, 1.0]
        })
        .collect();
    HdrImage {
        width: w,
        height: h,
        pixels,
    }
}

fn lw_target() -> RenderTarget {
    let mut lw = RenderTarget::new(1, 1, TargetFormat::R32F);
    lw.store(0, 0, [0.09, 0.0, 0.0, 0.0]);
    lw
}

/// The `translation` group: each shader's translation beside its
/// hand-written WGSL, on llvmpipe at one and two threads.
fn translation(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr/courtyard_1280x1024.exr");
    let img = load(&path, &ImageLimits::default()).unwrap();
    let lw = lw_target();
    let pass1 = shader((CORRECTED_UNROLLED.path, CORRECTED_UNROLLED.text));
    let tonemap = shader((TONEMAP_REINHARD.path, TONEMAP_REINHARD.text));
    let draws = [
        (
            "pass1",
            &pass1,
            pass1_draw(&img),
            "pass1.wgsl",
            TargetFormat::R32F,
        ),
        (
            "tonemap",
            &tonemap,
            tonemap_draw(&img, &lw),
            "tonemap.wgsl",
            TargetFormat::A32B32G32R32F,
        ),
    ];
    let mut g = c.benchmark_group(TRANSLATION);
    g.sample_size(20);
    for t in [1, 2] {
        // llvmpipe reads LP_NUM_THREADS when a device is created.
        std::env::set_var("LP_NUM_THREADS", t.to_string());
        let lp = Gpu::open_cpu();
        std::env::remove_var("LP_NUM_THREADS");
        let d = match &lp {
            Ok(d) => d,
            Err(e) => {
                eprintln!("{TRANSLATION}: skipped: {e}");
                return;
            }
        };
        DEVICES.lock().unwrap().push((TRANSLATION, d.info().line()));
        for (name, shader, draw, reference, format) in &draws {
            let kind = TargetKind::Format(*format);
            let translated = gpu::prepare(d, shader, draw, kind).unwrap();
            let by_hand = gpu::prepare_with(d, shader, draw, kind, wgsl(reference)).unwrap();
            g.bench_function(format!("{name}/translated/{t}t"), |b| {
                b.iter(|| translated.draw().unwrap().color.len())
            });
            g.bench_function(format!("{name}/wgsl/{t}t"), |b| {
                b.iter(|| by_hand.draw().unwrap().color.len())
            });
        }
    }
    g.finish();
}

/// The `uhd` group: the tone map of a 3840×2160 frame, emulated on every
/// core and drawn on the first adapter.
fn uhd(c: &mut Criterion) {
    let img = uhd_image();
    let lw = lw_target();
    let tonemap = shader((TONEMAP_REINHARD.path, TONEMAP_REINHARD.text));
    let draw = tonemap_draw(&img, &lw);
    let compiled = emu::compile(&tonemap).unwrap();
    let mut g = c.benchmark_group(UHD);
    g.sample_size(10);
    g.bench_function("tonemap/emulator", |b| {
        b.iter(|| emu::run(&compiled, &draw).unwrap().color.len())
    });
    let device = Gpu::open();
    let d = match &device {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{UHD}: tonemap/gpu: skipped: {e}");
            return;
        }
    };
    DEVICES.lock().unwrap().push((UHD, d.info().line()));
    g.bench_function("tonemap/gpu", |b| {
        b.iter(|| {
            gpu::run(d, &tonemap, &draw, TargetKind::Raw)
                .unwrap()
                .color
                .len()
        })
    });
    let ready = gpu::prepare(d, &tonemap, &draw, TargetKind::Raw).unwrap();
    g.bench_function("tonemap/gpu-draw", |b| {
        b.iter(|| ready.draw().unwrap().color.len())
    });
    g.finish();
}

/// `image` as a PFM file (RGB, little-endian, bottom row first).
fn write_pfm(path: &Path, image: &HdrImage) {
    let mut bytes = format!("PF\n{} {}\n-1.0\n", image.width, image.height).into_bytes();
    for row in image.pixels.chunks(image.width as usize).rev() {
        for p in row {
            for c in &p[..3] {
                bytes.extend_from_slice(&c.to_le_bytes());
            }
        }
    }
    std::fs::write(path, bytes).unwrap();
}

/// The `command` group: `ps30 tonemap` and `ps30 luminance` of a 3840×2160
/// PFM, whole processes, on the emulator and on the first adapter.
fn command(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("ps30-bench-gpu-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let pfm = dir.join("uhd.pfm");
    write_pfm(&pfm, &uhd_image());
    let exe =
        std::env::var_os("PS30_BENCH_BIN").unwrap_or_else(|| env!("CARGO_BIN_EXE_ps30").into());
    let run = |cmd: &str, backend: &str| {
        std::process::Command::new(&exe)
            .arg(cmd)
            .arg(&pfm)
            .args([
                "--max-pixels",
                "10000000",
                "--backend",
                backend,
                "-q",
                "--json",
            ])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .status()
            .unwrap()
            .code()
    };
    // Exit 1 is a cross-check that disagrees: still a whole run.
    if !matches!(run("luminance", "gpu"), Some(0 | 1)) {
        eprintln!("{COMMAND}: skipped: `ps30 luminance --backend gpu` found no device");
        let _ = std::fs::remove_dir_all(&dir);
        return;
    }
    if let Ok(d) = Gpu::open() {
        DEVICES.lock().unwrap().push((COMMAND, d.info().line()));
    }
    let mut g = c.benchmark_group(COMMAND);
    g.sample_size(10);
    for cmd in ["tonemap", "luminance"] {
        for backend in ["emulator", "gpu"] {
            g.bench_function(format!("{cmd}/{backend}"), |b| {
                b.iter(|| assert!(matches!(run(cmd, backend), Some(0 | 1))))
            });
        }
    }
    let lines = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/lists/lines300.json");
    let out = dir.join("lines");
    for backend in ["emulator", "gpu"] {
        g.bench_function(format!("render-lines/{backend}"), |b| {
            b.iter(|| {
                let status = std::process::Command::new(&exe)
                    .arg("render")
                    .arg(&lines)
                    .arg("-o")
                    .arg(&out)
                    .args(["--backend", backend, "-q"])
                    .stdout(std::process::Stdio::null())
                    .stderr(std::process::Stdio::null())
                    .status()
                    .unwrap();
                assert!(status.success());
            })
        });
    }
    g.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, translation, uhd, command);

/// `a / b` of two entries of `times`, as a table row against `bound`.
fn row(times: &[(String, f64)], a: &str, b: &str, bound: &str, met: fn(f64) -> bool) -> String {
    let time = |n: &str| times.iter().find(|(m, _)| m == n).map(|&(_, t)| t);
    match (time(a), time(b)) {
        (Some(x), Some(y)) => format!(
            "| `{a}` {:.2} ms / `{b}` {:.2} ms | {:.2} ({bound}) | {} |",
            x / 1e6,
            y / 1e6,
            x / y,
            if met(x / y) { "met" } else { "not met" }
        ),
        _ => format!("| `{a}` / `{b}` not measured in this run | | — |"),
    }
}

/// criterion's own `main`, then each group's table from this run.
fn main() {
    let started = std::time::SystemTime::now();
    benches();
    Criterion::default().configure_from_args().final_summary();
    let devices = DEVICES.lock().unwrap().clone();
    for (group, rows) in [
        (
            TRANSLATION,
            ["pass1", "tonemap"]
                .iter()
                .flat_map(|s| {
                    [1, 2].map(|t| {
                        let a = format!("{s}/translated/{t}t");
                        let b = format!("{s}/wgsl/{t}t");
                        (a, b, "≤ 1.5", (|r| r <= 1.5) as fn(f64) -> bool)
                    })
                })
                .collect::<Vec<_>>(),
        ),
        (
            UHD,
            vec![
                (
                    "tonemap/gpu".to_string(),
                    "tonemap/emulator".to_string(),
                    "≤ 0.05",
                    (|r| r <= 0.05) as fn(f64) -> bool,
                ),
                (
                    "tonemap/gpu-draw".to_string(),
                    "tonemap/emulator".to_string(),
                    "≤ 0.05",
                    (|r| r <= 0.05) as fn(f64) -> bool,
                ),
            ],
        ),
        (
            COMMAND,
            ["tonemap", "luminance"]
                .iter()
                .map(|cmd| {
                    (
                        format!("{cmd}/gpu"),
                        format!("{cmd}/emulator"),
                        "≤ 1",
                        (|r| r <= 1.0) as fn(f64) -> bool,
                    )
                })
                .collect(),
        ),
    ] {
        let times = goals::criterion_dirs()
            .into_iter()
            .map(|dir| goals::measured(&dir, group, started))
            .find(|t| !t.is_empty());
        let Some(times) = times else { continue };
        let on: Vec<&str> = devices
            .iter()
            .filter(|(g, _)| *g == group)
            .map(|(_, d)| d.as_str())
            .collect();
        println!(
            "\n`{group}` on {} (criterion's typical times, one run):\n\n| measured | ratio | |\n|---|---|---|",
            goals::machine(on.first().copied())
        );
        for (a, b, bound, met) in rows {
            println!("{}", row(&times, &a, &b, bound, met));
        }
    }
}
