//! Which backend draws a job's passes: the emulator (the default) or a GPU
//! through the translation (`core/gpu`). One draw call for the jobs, so
//! that the luminance pipeline, `run`, tone mapping and `compare` draw the
//! same [`Draw`] the same way on either.

use crate::core::cost::Range;
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
}

impl fmt::Display for DrawError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DrawError::Emu(e) => write!(f, "emulator: {e}"),
            DrawError::Gpu(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for DrawError {}

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
            let out = match threads {
                Some(t) => emu::run_with_threads(&compiled, draw, t),
                None => emu::run(&compiled, draw),
            }
            .map_err(DrawError::Emu)?;
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
