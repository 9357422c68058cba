//! Which backend draws a job's passes: the emulator (the default) or a GPU
//! through the translation (`core/gpu`). One draw call for the jobs, so
//! that the luminance pipeline, `run`, tone mapping and `compare` draw the
//! same [`Draw`] the same way on either.

use crate::core::cost::{self, Environment, Profile, Range};
use crate::core::diag::SourceFile;
use crate::core::emu::{self, findings::Finding, Draw};
use crate::core::gpu::{self, Gpu, GpuError, TargetKind};
use crate::core::ir::Shader;
use std::fmt;
use std::sync::Arc;

/// The backend a job draws with.
#[derive(Clone, Default)]
pub enum Backend {
    /// The CPU emulator.
    #[default]
    Emulator,
    /// A device opened with [`Gpu::open`].
    Gpu(Arc<Gpu>),
}

impl fmt::Debug for Backend {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe())
    }
}

impl Backend {
    /// `emulator` or `gpu`.
    pub fn name(&self) -> &'static str {
        match self {
            Backend::Emulator => "emulator",
            Backend::Gpu(_) => "gpu",
        }
    }

    /// `emulator`, or `GPU: <device line>`.
    pub fn describe(&self) -> String {
        match self {
            Backend::Emulator => "emulator".into(),
            Backend::Gpu(g) => format!("GPU: {}", g.info().line()),
        }
    }

    /// Rows per band for a job that draws a `width`-pixel image in bands:
    /// `emulator` on the emulator (its batches want small bands), the
    /// device's [`Gpu::max_rows`] on a GPU (each draw there has a fixed
    /// cost: its inputs, targets and read-back buffers are made anew).
    pub fn band_rows(&self, width: u32, emulator: u32) -> u32 {
        match self {
            Backend::Emulator => emulator,
            Backend::Gpu(g) => g.max_rows(width),
        }
    }

    /// The device a GPU backend draws on; `None` for the emulator.
    pub fn device(&self) -> Option<&gpu::DeviceInfo> {
        match self {
            Backend::Emulator => None,
            Backend::Gpu(g) => Some(g.info()),
        }
    }
}

/// What a draw gave a job.
#[derive(Clone, Debug)]
pub struct Drawn {
    /// Target width in pixels.
    pub width: u32,
    /// Target height in pixels.
    pub height: u32,
    /// `oC0` per pixel (`None` if the shader never writes it).
    pub color: Option<Vec<[f32; 4]>>,
    /// Executed slots per pixel (min, max) — the emulator counts them, a GPU
    /// does not.
    pub executed: Option<Range>,
    /// The emulator's warnings about the draw's quads (none from a GPU).
    pub findings: Vec<Finding>,
}

/// Why a draw failed.
#[derive(Debug)]
pub enum DrawError {
    /// The emulator refused or could not finish the draw.
    Emu(emu::EmuError),
    /// The translation, the device or the read-back failed.
    Gpu(GpuError),
    /// A pixel may execute more slots than the per-pixel cap: a GPU cannot
    /// stop a pixel part way (and drivers cut long loops short without a
    /// word), so the draw is refused there.
    OverCapOnGpu {
        /// The cost model's longest path, per pixel.
        executed: u64,
        /// `--max-executed-per-pixel`.
        cap: u64,
    },
}

impl fmt::Display for DrawError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DrawError::Emu(e) => write!(f, "emulator: {e}"),
            DrawError::Gpu(e) => write!(f, "{e}"),
            DrawError::OverCapOnGpu { executed, cap } => write!(
                f,
                "a pixel may execute up to {} instruction slots (the cost model's longest path for these constants), over the cap of {} (--max-executed-per-pixel): a GPU cannot stop a pixel part way and drivers cut long loops short without a word, so ps30 does not draw it there (the emulator stops the first pixel that passes the cap)",
                crate::core::numbers::thousands(*executed),
                crate::core::numbers::thousands(*cap)
            ),
        }
    }
}

impl std::error::Error for DrawError {}

/// The cost model's environment for a draw: every integer and boolean
/// constant as the draw sets it (0 / false where it sets none).
pub fn environment(c: &emu::Constants) -> Environment {
    let mut env = Environment::default();
    for i in 0..16usize {
        env.ints
            .insert(i as u32, c.int.get(i).copied().unwrap_or([0; 4]));
        env.bools
            .insert(i as u32, c.bool.get(i).copied().unwrap_or(false));
    }
    env
}

/// Holds a GPU draw to the emulator's per-pixel cap, by the cost model's
/// longest path (an upper bound on every pixel's count).
fn gpu_cap(shader: &Shader, file: &SourceFile, draw: &Draw) -> Result<(), DrawError> {
    let cap = draw.limits.max_executed_per_pixel;
    let a = cost::analyse(
        shader,
        file,
        &environment(&draw.constants),
        &Profile::ps_3_0(),
    );
    // A count the model cannot bound is no reason to refuse: the draw's own
    // checks (`emu::check`) still apply.
    match a {
        Ok(a) if a.executed.max > cap => Err(DrawError::OverCapOnGpu {
            executed: a.executed.max,
            cap,
        }),
        _ => Ok(()),
    }
}

/// Draws `draw` of `shader` on `backend`. On a GPU, `target` is the format
/// the device stores `oC0` in; the emulator's values are unrounded (the
/// caller stores them in a [`RenderTarget`](crate::core::image::RenderTarget),
/// which rounds them as the format does).
pub fn draw(
    backend: &Backend,
    shader: &Shader,
    file: &SourceFile,
    draw: &Draw,
    target: TargetKind,
    threads: Option<usize>,
) -> Result<Drawn, DrawError> {
    match backend {
        Backend::Emulator => {
            let compiled = emu::compile(shader).map_err(DrawError::Emu)?;
            let out = draw_output(backend, shader, &compiled, file, draw, threads)?;
            let (min, max) =
                emu::on_threads(threads.unwrap_or(0), || executed_range(&out.executed))
                    .map_err(DrawError::Emu)?;
            let findings = emu::findings::findings(&out, draw, file);
            Ok(Drawn {
                width: out.width,
                height: out.height,
                color: out.color.into_iter().next().flatten(),
                executed: Some(Range { min, max }),
                findings,
            })
        }
        Backend::Gpu(g) => {
            gpu_cap(shader, file, draw)?;
            let out = gpu::run(g, shader, draw, target).map_err(DrawError::Gpu)?;
            Ok(Drawn {
                width: out.width,
                height: out.height,
                color: out.color.into_iter().next().flatten(),
                executed: None,
                findings: Vec::new(),
            })
        }
    }
}

/// Runs `draw` of `shader` on `backend` and returns all it produced: every
/// `oC#` unrounded, the discards and, on the emulator, each pixel's
/// executed count (zeros from a GPU, which counts nothing). `compiled` is
/// the emulator's form of `shader`, made once by the caller.
pub fn draw_output(
    backend: &Backend,
    shader: &Shader,
    compiled: &emu::Compiled,
    file: &SourceFile,
    draw: &Draw,
    threads: Option<usize>,
) -> Result<emu::DrawOutput, DrawError> {
    match backend {
        Backend::Emulator => match threads {
            Some(t) => emu::run_with_threads(compiled, draw, t),
            None => emu::run(compiled, draw),
        }
        .map_err(DrawError::Emu),
        Backend::Gpu(g) => {
            gpu_cap(shader, file, draw)?;
            let out = gpu::run(g, shader, draw, TargetKind::Raw).map_err(DrawError::Gpu)?;
            Ok(out.into_draw_output())
        }
    }
}

/// The smallest and largest per-pixel count (0 and 0 for no pixels), in
/// one parallel pass: on a large target two serial scans cost a tenth of
/// the draw.
fn executed_range(executed: &[u64]) -> (u64, u64) {
    use rayon::prelude::*;
    if executed.is_empty() {
        return (0, 0);
    }
    executed
        .par_iter()
        .with_min_len(1 << 14)
        .fold(|| (u64::MAX, 0), |(lo, hi), &e| (lo.min(e), hi.max(e)))
        .reduce(|| (u64::MAX, 0), |a, b| (a.0.min(b.0), a.1.max(b.1)))
}
