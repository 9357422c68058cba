//! Lines on the GPU backend: line primitives and triangles filled as
//! wireframe. wgpu offers no choice of line rasterisation, and a Vulkan
//! device's default lines may be rectangular or non-strict, where Direct3D
//! 9 draws by the diamond-exit rule; so here the emulator's own set-up
//! (`core/raster/line.rs`) decides each line's pixels and their inputs —
//! perspective along the major axis, the quad grid's helpers included — and
//! the device runs the pixel shader on exactly those pixels, reading them
//! per pixel as a full-screen draw reads its inputs (`core::gpu::run` with
//! [`emu::Draw::pixels`]). Its derivatives come from the device's own quads
//! over the same values, which the window's even origin lines up with the
//! emulator's. The results then take the emulator's path (fog, `texkill`,
//! the alpha test, depth, the output merger), in drawing order.

use super::{Drawn, Pass, Stage};
use crate::core::emu::{self, DrawOutput, PixelInputs};
use crate::core::gpu::{self, Gpu, GpuOutput};
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use crate::core::raster::fog::FogMode;
use crate::core::raster::triangle::Window;
use crate::jobs::render::geometry::Geometry;
use crate::jobs::render::{DrawFailure, DrawStep};

/// Every line of `g` shaded on `device` and taken into `pass`.
pub(super) fn shade_lines(
    device: &Gpu,
    shader: &Shader,
    d: &DrawStep,
    g: &Geometry,
    stage: &Stage,
    c: &super::gpu::Context,
    pass: &mut Pass,
) -> Result<Drawn, DrawFailure> {
    let reads_vpos = shader
        .program()
        .instructions
        .iter()
        .any(|i| i.src.iter().any(|s| s.reg.file == RegFile::Position));
    if reads_vpos {
        // The device's draw of a window puts the window at (0, 0).
        return Err(DrawFailure::Message(
            "the GPU backend draws lines through the emulator's set-up in a window of their own; a line whose shader reads vPos is drawn on the emulator only".into(),
        ));
    }
    let shapes = super::shapes(g, stage, c.viewport, c.clip_rect).map_err(DrawFailure::Message)?;
    let mut slots = stage.slot_list();
    // The fog column rides along as the emulator's does.
    let fog_column = c.fog.is_some_and(|f| f.mode == FogMode::Vertex || f.w);
    if fog_column {
        slots.push((super::FOG_SLOT, stage.slots.len() + 1, [false; 4]));
    }
    crate::core::phases::mark("geometry: lines through the emulator's set-up");
    let mut drawn = Drawn::default();
    let mut pixels_left = c.settings.budget.max_pixels;
    for (shape, provoking, _) in &shapes {
        if c.clip_rect.is_empty() {
            break;
        }
        let Some(mut window) = shape.pixels(c.clip_rect, &slots, &stage.values[*provoking]) else {
            continue;
        };
        let fog_values = match fog_column {
            true => window.inputs.values.pop().map(|(_, v)| v),
            false => None,
        };
        let (gw, gh) = (
            PixelInputs::grid_width(window.width) as u32,
            PixelInputs::grid_width(window.height) as u32,
        );
        pixels_left = pixels_left
            .checked_sub(u64::from(gw) * u64::from(gh))
            .ok_or_else(|| {
                DrawFailure::Message(format!(
                    "the draw's lines cover more than {} pixels with their quads (raise it with --max-list-pixels)",
                    c.settings.budget.max_pixels
                ))
            })?;
        let grid = padded(&window, gw, gh);
        let mut draw = super::gpu::pixel_draw(d, stage, c.samplers, c.settings, (gw, gh));
        draw.inputs = Vec::new();
        draw.pixels = Some(&grid);
        draw.face = shape.face();
        let shaded = gpu::run(device, shader, &draw, gpu::TargetKind::Raw)
            .map_err(|e| DrawFailure::Message(e.to_string()))?;
        let mut out = cropped(shaded, window.width, window.height);
        if let Some(f) = &c.fog {
            super::fog_pixels(&mut out, &window, fog_values.as_deref(), f);
        }
        drawn.triangles += 1;
        drawn.shaded += window.inputs.covered.iter().filter(|&&k| k).count() as u64;
        pass.take(&window, &out, d.pixel.alpha_test, shape.face())?;
    }
    Ok(drawn)
}

/// The window's inputs over its whole quad grid (`gw × gh`, even), as the
/// device's draw takes them: coverage padded with uncovered helpers.
fn padded(window: &Window, gw: u32, gh: u32) -> PixelInputs {
    let mut covered = vec![false; gw as usize * gh as usize];
    for (i, &k) in window.inputs.covered.iter().enumerate() {
        let (x, y) = (i % window.width as usize, i / window.width as usize);
        covered[y * gw as usize + x] = k;
    }
    PixelInputs {
        origin: window.inputs.origin,
        covered,
        values: window.inputs.values.clone(),
    }
}

/// The device's `gw × gh` results cut to the window's `w × h`, laid out as
/// the emulator's output of the window (a GPU counts nothing).
fn cropped(o: GpuOutput, w: u32, h: u32) -> DrawOutput {
    let gw = o.width as usize;
    let color = o
        .color
        .iter()
        .map(|c| c.as_deref().map(|c| cut(c, gw, w, h)))
        .collect();
    let depth = o.depth.as_deref().map(|d| cut(d, gw, w, h));
    let killed = cut(&o.killed, gw, w, h);
    emu::DrawOutput::uncounted((w, h), color, depth, killed)
}

/// The top-left `w × h` of the rows of `v`, `gw` wide.
fn cut<T: Copy>(v: &[T], gw: usize, w: u32, h: u32) -> Vec<T> {
    (0..h as usize)
        .flat_map(|y| v[y * gw..y * gw + w as usize].iter().copied())
        .collect()
}
