//! The GPU backend: the emulator's draw, run on a real device through
//! wgpu's Vulkan backend — a second witness for every result ps30 prints.
//!
//! [`run`] takes exactly what [`emu::run`](crate::core::emu::run) takes — a
//! validated shader and an [`emu::Draw`](crate::core::emu::Draw) — and returns the same per-pixel
//! colour data ([`GpuOutput`], laid out like
//! [`emu::DrawOutput`](crate::core::emu::DrawOutput)'s colours). The
//! shader is the translation (`core/translate`, its `Entry::Draw` entry
//! point) under the draw's float rules; the draw is the emulator's:
//!
//! * **pixel centres**: the target is covered by one triangle; WebGPU's
//!   pixel (x, y) has its centre at (x + ½, y + ½), and the entry point
//!   subtracts ½ so `vPos` is (x, y) as in Direct3D 9;
//! * **inputs**: each `v#` is evaluated on the CPU at every pixel with the
//!   emulator's own formula ([`LinearInput::at`](crate::core::emu::LinearInput::at))
//!   and read by the shader from a texture array, so the GPU starts from
//!   bit-identical inputs and any difference comes from the shader's
//!   instructions, not from interpolation hardware;
//! * **targets**: one per written `oC#`, in the format asked for
//!   ([`TargetKind`]): the wgpu format that stores what the D3D9 one does
//!   (`R32Float` for D3DFMT_R32F, `Rgba16Float` for D3DFMT_A16B16G16R16F,
//!   `Rg16Float`, `R16Float`, `Rg32Float`, `Rgba32Float`, and `Rgba8Unorm`
//!   for D3DFMT_A8R8G8B8) — the device rounds what it stores — or
//!   `Rgba32Float`, the emulator's unrounded output;
//! * **samplers**: `sampler.rs` maps each D3D9 state to a wgpu sampler and
//!   texture view plus the `Ps30Sampler` values the shader applies itself;
//! * **texkill**: the pixel keeps running and its flag is read back, so a
//!   killed pixel is reported as the emulator reports it (colours zero).
//!
//! Without a Vulkan adapter, [`Gpu::open`] fails with [`GpuError::NoAdapter`],
//! whose message says how to get one; the build itself needs no Vulkan
//! (the loader is opened at run time).

mod draw;
mod geometry;
mod inputs;
mod one_pass;
mod records;
mod runtime_dir;
mod sampler;
mod teardown;
mod texture;
mod vertex;

pub use draw::{
    prepare, prepare_with, run, run_in_bands, run_in_bands_translated, run_translated,
    translate_ahead, GpuOutput, Prepared, TargetKind, Translated,
};
pub use geometry::{draw_geometry, GeometryDraw, ShadedPrimitive};
pub use one_pass::{
    draw_one_pass, one_pass_lacks, Compare, DepthSurface, OnePass, StencilSide, StencilTest,
};
pub use records::{draw_geometry_recorded, records_lack};
pub use teardown::{hand_off_at_exit, leave_at_exit};
pub use vertex::run_vertices;

use crate::core::emu::EmuError;
use crate::core::phases;
use crate::core::translate::TranslateError;
use std::fmt;
use std::sync::{Arc, Mutex, OnceLock};

/// What the device is, for reports.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct DeviceInfo {
    /// The adapter's name as the driver reports it (`llvmpipe (LLVM 15.0.6, 256 bits)`).
    pub name: String,
    /// `Vulkan`.
    pub backend: String,
    /// `Cpu`, `DiscreteGpu`, …
    pub device_type: String,
    /// The driver's name (`llvmpipe`, `NVIDIA`).
    pub driver: String,
    /// The driver's version string, as free text.
    pub driver_info: String,
    /// The PCI vendor id (0x10de NVIDIA, 0x10005 Mesa); 0 where the driver gives none.
    pub vendor: u32,
    /// The PCI device id within the vendor; 0 where the driver gives none.
    pub device: u32,
}

impl DeviceInfo {
    /// One line: `llvmpipe (LLVM 15.0.6, 256 bits), Vulkan, Cpu, driver llvmpipe (Mesa 22.3.6 (LLVM 15.0.6))`.
    pub fn line(&self) -> String {
        format!(
            "{}, {}, {}, driver {} ({})",
            self.name, self.backend, self.device_type, self.driver, self.driver_info
        )
    }
}

/// An open device.
pub struct Gpu {
    pub(crate) device: wgpu::Device,
    /// An error wgpu reported outside the error scopes of a draw (wgpu's
    /// default would panic); `run` returns it as [`GpuError::Failed`].
    pub(crate) uncaptured: std::sync::Arc<std::sync::Mutex<Option<String>>>,
    pub(crate) queue: wgpu::Queue,
    pub(crate) features: wgpu::Features,
    pub(crate) limits: wgpu::Limits,
    /// Fragment shaders may write storage buffers (wgpu's downlevel flag
    /// FRAGMENT_WRITABLE_STORAGE), as [`records`] needs.
    pub(crate) fragment_storage: bool,
    /// Large textures uploaded by earlier draws (`texture.rs`): the passes
    /// of one command sample the same image.
    pub(crate) textures: texture::Cache,
    /// The compute pipeline that makes a large draw's inputs on the device
    /// (`inputs.rs`), made by the first draw that needs it.
    pub(crate) fill: OnceLock<Result<inputs::Fill, String>>,
    info: DeviceInfo,
}

/// Why the GPU backend could not run a draw.
#[derive(Debug)]
pub enum GpuError {
    /// No Vulkan adapter: the message says how to get one.
    NoAdapter(String),
    /// The adapter would not give a device.
    Device(String),
    /// The draw is not one the emulator would run either.
    Draw(EmuError),
    /// The vertex draw is not one the emulator's vertex stage would run either.
    Vertices(crate::core::emu::vertex::VertexError),
    /// The shader did not translate.
    Translate(TranslateError),
    /// The device cannot do what the draw asks (a feature or a limit).
    Unsupported(String),
    /// wgpu reported an error while drawing or reading back.
    Failed(String),
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::NoAdapter(why) => write!(
                f,
                "no GPU adapter: wgpu found no Vulkan device ({why}). Install a Vulkan driver — on Debian or Ubuntu, \
                 `apt-get install mesa-vulkan-drivers` gives llvmpipe, a CPU Vulkan device — or leave out --backend gpu"
            ),
            GpuError::Device(e) => write!(f, "the GPU adapter gave no device: {e}"),
            GpuError::Draw(e) => write!(f, "{e}"),
            GpuError::Vertices(e) => write!(f, "{e}"),
            GpuError::Translate(e) => write!(f, "{e}"),
            GpuError::Unsupported(e) => write!(f, "the GPU cannot draw this: {e}"),
            GpuError::Failed(e) => write!(f, "GPU: {e}"),
        }
    }
}

impl std::error::Error for GpuError {}

impl GpuError {
    /// The same error again, for a second caller of [`Opening::wait`]
    /// (opening fails only with [`GpuError::NoAdapter`] or
    /// [`GpuError::Device`]; anything else keeps its message).
    fn again(&self) -> GpuError {
        match self {
            GpuError::NoAdapter(why) => GpuError::NoAdapter(why.clone()),
            GpuError::Device(why) => GpuError::Device(why.clone()),
            other => GpuError::Failed(other.to_string()),
        }
    }
}

/// A device being opened on a thread of its own: a GPU driver takes a large
/// part of a second to start (0.15–0.2 s for NVIDIA's), so a command starts
/// it first and does its CPU work — decoding the image, planning the passes,
/// the f64 reference — meanwhile; the first draw waits for it
/// ([`Opening::wait`]). The thread hands the device over as soon as it is
/// open and ends on its own: waiting for the thread's end instead (a
/// join) cost 11 ms of the first draw on an NVIDIA H200, the driver's
/// per-thread teardown (docs/speed.md).
pub struct Opening {
    handed: Arc<(Mutex<Option<Opened>>, std::sync::Condvar)>,
    opened: OnceLock<Opened>,
}

/// What opening a device gave.
type Opened = Result<Arc<Gpu>, GpuError>;

impl Opening {
    /// Starts `open` on a new thread.
    pub fn start(open: impl FnOnce() -> Opened + Send + 'static) -> Opening {
        let handed = Arc::new((Mutex::new(None), std::sync::Condvar::new()));
        let slot = handed.clone();
        let thread = std::thread::Builder::new()
            .name("gpu-open".into())
            .spawn(move || {
                // A panic inside the driver's start is reported as a failed open.
                let opened = std::panic::catch_unwind(std::panic::AssertUnwindSafe(open))
                    .unwrap_or_else(|_| {
                        Err(GpuError::Device("opening the device panicked".into()))
                    });
                phases::mark("device: handed over");
                let (result, ready) = &*slot;
                if let Ok(mut r) = result.lock() {
                    *r = Some(opened);
                }
                ready.notify_all();
            })
            .map_err(|e| GpuError::Device(format!("no thread to open the device on: {e}")));
        let opening = Opening {
            handed,
            opened: OnceLock::new(),
        };
        if let Err(e) = thread {
            let _ = opening.opened.set(Err(e));
        }
        opening
    }

    /// The device, once opened (the first caller waits for it).
    pub fn wait(&self) -> Result<&Arc<Gpu>, GpuError> {
        let opened = self.opened.get_or_init(|| {
            let opened = self.take();
            phases::mark("device ready for the first draw");
            opened
        });
        opened.as_ref().map_err(GpuError::again)
    }

    /// The device if it was opened and waited for already; never waits.
    pub fn ready(&self) -> Option<&Arc<Gpu>> {
        self.opened.get().and_then(|o| o.as_ref().ok())
    }

    /// Waits for the opening thread's result and takes it.
    fn take(&self) -> Opened {
        let (result, ready) = &*self.handed;
        let Ok(mut r) = result.lock() else {
            return Err(GpuError::Device("the device was not opened".into()));
        };
        loop {
            if let Some(opened) = r.take() {
                return opened;
            }
            r = match ready.wait(r) {
                Ok(r) => r,
                Err(_) => return Err(GpuError::Device("the device was not opened".into())),
            };
        }
    }
}

impl Drop for Opening {
    /// Waits for a device still opening: a process must not exit while a
    /// thread is inside the driver's start-up.
    fn drop(&mut self) {
        if self.opened.get().is_none() {
            let _ = self.take();
        }
    }
}

/// Features used when the adapter has them: BORDER addressing with a
/// colour, linear filtering of 32-bit float textures, clip distances
/// for the user clip planes of draws of geometry, and for a draw of
/// geometry in one pass the primitive index, blending into 32-bit floats
/// and a 32-bit float depth with stencil (all exist on llvmpipe and on
/// current desktop GPUs).
const WANTED: wgpu::Features = wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER
    .union(wgpu::Features::FLOAT32_FILTERABLE)
    .union(wgpu::Features::CLIP_DISTANCES)
    .union(wgpu::Features::PRIMITIVE_INDEX)
    .union(wgpu::Features::FLOAT32_BLENDABLE)
    .union(wgpu::Features::DEPTH32FLOAT_STENCIL8);

impl Gpu {
    /// Opens the first Vulkan adapter (a real GPU is preferred to a CPU one).
    pub fn open() -> Result<Gpu, GpuError> {
        Gpu::open_adapter(false)
    }

    /// Opens a CPU Vulkan adapter (Mesa's llvmpipe), even where a real GPU
    /// is present: the peer the emulator's speed is measured against.
    pub fn open_cpu() -> Result<Gpu, GpuError> {
        Gpu::open_adapter(true)
    }

    /// `cpu`: wgpu's fallback adapter, a CPU device, is asked for.
    fn open_adapter(cpu: bool) -> Result<Gpu, GpuError> {
        phases::mark("device: opening");
        runtime_dir::ensure();
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            flags: wgpu::InstanceFlags::empty(),
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: cpu,
            ..Default::default()
        }))
        .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        phases::mark("device: adapter");
        let features = adapter.features() & WANTED;
        let limits = adapter.limits();
        let fragment_storage = adapter
            .get_downlevel_capabilities()
            .flags
            .contains(wgpu::DownlevelFlags::FRAGMENT_WRITABLE_STORAGE);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("ps30"),
            required_features: features,
            required_limits: limits.clone(),
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        phases::mark("device: opened");
        let uncaptured = std::sync::Arc::new(std::sync::Mutex::new(None));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(std::sync::Arc::new(move |e: wgpu::Error| {
            if let Ok(mut slot) = sink.lock() {
                slot.get_or_insert_with(|| e.to_string());
            }
        }));
        let a = adapter.get_info();
        if a.device_type != wgpu::DeviceType::Cpu {
            teardown::note_hardware();
        }
        Ok(Gpu {
            device,
            uncaptured,
            queue,
            features,
            limits,
            fragment_storage,
            textures: Default::default(),
            fill: OnceLock::new(),
            info: DeviceInfo {
                name: a.name,
                backend: format!("{:?}", a.backend),
                device_type: format!("{:?}", a.device_type),
                driver: a.driver,
                driver_info: a.driver_info,
                vendor: a.vendor,
                device: a.device,
            },
        })
    }

    /// What the opened device is, for reports ([`DeviceInfo::line`]).
    pub fn info(&self) -> &DeviceInfo {
        &self.info
    }

    /// Whether 32-bit float textures can be filtered linearly.
    pub fn float32_filterable(&self) -> bool {
        self.features.contains(wgpu::Features::FLOAT32_FILTERABLE)
    }

    /// The most rows of a `width`-pixel target one draw should cover: within
    /// the device's texture side and read-back buffer size (an
    /// `Rgba32Float` target, the widest drawn), and at most 2²³ pixels (a
    /// 3840×2160 frame in one draw), so that a large image drawn in bands
    /// holds a bounded part of it at a time. Each draw uploads its textures
    /// and compiles its pipeline, so fewer, larger draws are faster here,
    /// where the emulator prefers small bands.
    pub fn max_rows(&self, width: u32) -> u32 {
        const MAX_PIXELS: u64 = 1 << 23;
        let width = width.max(1) as u64;
        let pitch = (width * 16).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as u64)
            * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as u64;
        let rows = (MAX_PIXELS / width)
            .min(self.limits.max_buffer_size / pitch)
            .min(self.limits.max_texture_dimension_2d as u64);
        rows.clamp(1, u32::MAX as u64) as u32
    }

    /// Whether BORDER addressing is available.
    pub fn clamp_to_border(&self) -> bool {
        self.features
            .contains(wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER)
    }
}

/// Colour attachments of `views` (a target per location, or none), each
/// cleared to transparent black and stored (every pass of the backend's
/// draws starts from cleared targets).
fn cleared_attachments(
    views: &[Option<wgpu::TextureView>],
) -> Vec<Option<wgpu::RenderPassColorAttachment<'_>>> {
    views
        .iter()
        .map(|v| {
            v.as_ref().map(|view| wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })
        })
        .collect()
}

/// A buffer binding that compute shaders read (or write), in the layouts of
/// the vertex stage and of the inputs made on the device.
fn compute_buffer(binding: u32, ty: wgpu::BufferBindingType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// A read-write storage buffer the fragment stage binds at `binding`
/// (the one-pass draw's counters, the recorded draw's counter and records).
fn fragment_storage(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: false },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}
