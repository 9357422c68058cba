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
    /// A device still opening on a thread of its own ([`gpu::Opening`]): the
    /// first draw on it waits for it, so that a command's CPU work runs
    /// while the driver starts.
    Opening(Arc<gpu::Opening>),
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
            Backend::Gpu(_) | Backend::Opening(_) => "gpu",
        }
    }

    /// The device a GPU backend draws on (waiting for one still opening);
    /// `Ok(None)` for the emulator.
    pub fn gpu(&self) -> Result<Option<&Arc<Gpu>>, GpuError> {
        match self {
            Backend::Emulator => Ok(None),
            Backend::Gpu(g) => Ok(Some(g)),
            Backend::Opening(o) => o.wait().map(Some),
        }
    }

    /// Why the device could not be opened, if it was asked for and failed:
    /// a command reports that rather than the draw it stopped.
    pub fn open_error(&self) -> Option<GpuError> {
        self.gpu().err()
    }

    /// `emulator`, or `GPU: <device line>`.
    pub fn describe(&self) -> String {
        match self.gpu() {
            Ok(None) => "emulator".into(),
            Ok(Some(g)) => format!("GPU: {}", g.info().line()),
            Err(e) => format!("GPU: not opened ({e})"),
        }
    }

    /// Rows per band for a job that draws a `width`-pixel image in bands:
    /// `emulator` on the emulator (its batches want small bands), the
    /// device's [`Gpu::max_rows`] on a GPU (each draw there has a fixed
    /// cost: its inputs, targets and read-back buffers are made anew).
    pub fn band_rows(&self, width: u32, emulator: u32) -> u32 {
        match self.gpu() {
            Ok(Some(g)) => g.max_rows(width),
            _ => emulator,
        }
    }

    /// The device a GPU backend draws on; `None` for the emulator (and for
    /// a device that failed to open).
    pub fn device(&self) -> Option<&gpu::DeviceInfo> {
        self.gpu().ok().flatten().map(|g| g.info())
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

/// The device of a GPU backend, waiting for one still opening.
fn device(backend: &Backend) -> Result<&Arc<Gpu>, DrawError> {
    match backend.gpu() {
        Ok(Some(g)) => Ok(g),
        Ok(None) => Err(DrawError::Gpu(GpuError::Failed(
            "the emulator has no device".into(),
        ))),
        Err(e) => Err(DrawError::Gpu(e)),
    }
}

/// The device of a GPU backend and `draw`'s translation for it, made
/// before waiting for a device still opening ([`gpu::translate_ahead`]):
/// the translation then runs while the driver starts. A device not yet
/// open is taken to have BORDER addressing, as NVIDIA's, AMD's, Intel's
/// and llvmpipe's do; where it has not, the draw is translated again.
fn device_translated<'b>(
    backend: &'b Backend,
    shader: &Shader,
    draw: &Draw,
) -> Result<(&'b Arc<Gpu>, gpu::Translated), DrawError> {
    let border = match backend {
        Backend::Gpu(g) => g.clamp_to_border(),
        Backend::Opening(o) => o.ready().is_none_or(|g| g.clamp_to_border()),
        Backend::Emulator => true,
    };
    let ahead = gpu::translate_ahead(shader, draw, border);
    Ok((device(backend)?, ahead))
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
        Backend::Gpu(_) | Backend::Opening(_) => {
            gpu_cap(shader, file, draw)?;
            let (g, ahead) = device_translated(backend, shader, draw)?;
            let out =
                gpu::run_translated(g, shader, draw, target, ahead).map_err(DrawError::Gpu)?;
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

/// [`draw`] on a GPU, the target read back `rows` rows at a time and each
/// band handed to `band` (its first row and what it drew) as soon as it is
/// read, so that the caller checks one band while the next is read; `band`
/// returns `false` to stop. The emulator draws the whole target and hands
/// it on as one band: a job that wants the emulator in bands draws them
/// itself.
#[allow(clippy::too_many_arguments)] // `draw`'s arguments and the bands'
pub fn draw_in_bands(
    backend: &Backend,
    shader: &Shader,
    file: &SourceFile,
    draw: &Draw,
    target: TargetKind,
    threads: Option<usize>,
    rows: u32,
    band: &mut dyn FnMut(u32, Drawn) -> bool,
) -> Result<(), DrawError> {
    if matches!(backend, Backend::Emulator) {
        let drawn = self::draw(backend, shader, file, draw, target, threads)?;
        band(0, drawn);
        return Ok(());
    }
    gpu_cap(shader, file, draw)?;
    let (g, ahead) = device_translated(backend, shader, draw)?;
    gpu::run_in_bands_translated(g, shader, draw, (target, ahead), rows, &mut |y0, out| {
        band(
            y0,
            Drawn {
                width: out.width,
                height: out.height,
                color: out.color.into_iter().next().flatten(),
                executed: None,
                findings: Vec::new(),
            },
        )
    })
    .map_err(DrawError::Gpu)
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
        Backend::Gpu(_) | Backend::Opening(_) => {
            gpu_cap(shader, file, draw)?;
            let g = device(backend)?;
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
