//! Lines on the GPU backend: line primitives and triangles filled as
//! wireframe. wgpu offers no choice of line rasterisation, and a Vulkan
//! device's default lines may be rectangular or non-strict, where Direct3D
//! 9 draws by the diamond-exit rule; so here the emulator's own set-up
//! (`core/raster/line.rs`) decides each line's pixels and their inputs —
//! perspective along the major axis, the quad grid's helpers included — and
//! the device runs the pixel shader on exactly those pixels, reading them
//! per pixel as a full-screen draw reads its inputs (`core::gpu::run` with
//! [`emu::Draw::pixels`]).
//!
//! Each device draw compiles its pipeline and uploads its textures, so the
//! lines are not drawn one window at a time: their windows (each its whole
//! quad grid, even-sized) are packed side by side at even offsets into one
//! atlas, shelf by shelf, and shaded in one draw. A quad of the atlas is
//! then a quad of exactly one window, so the device's derivatives are the
//! ones it takes over that window alone; `vPos` is each pixel's place in
//! the render target, which the draw gives per pixel
//! ([`PixelInputs::positions`]). An atlas holds at most [`BATCH_PIXELS`]
//! pixels of windows (a larger window has one to itself), so memory stays
//! bounded whatever the list; an atlas's pixels share one facing, the
//! draw's (a line is front-facing: `raster::Line::face`). The results then
//! take the emulator's path (fog, `texkill`, the
//! alpha test, depth, the output merger), in drawing order.

use super::{Drawn, Pass, Stage};
use crate::core::emu::{self, DrawOutput, PixelInputs};
use crate::core::gpu::{self, Gpu, GpuOutput};
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use crate::core::raster::fog::FogMode;
use crate::core::raster::triangle::Window;
use crate::core::raster::Face;
use crate::jobs::render::geometry::Geometry;
use crate::jobs::render::{DrawFailure, DrawStep};

/// The most pixels of windows one atlas holds (4 Mi: a 2048×2048 atlas,
/// 64 MiB an input layer at 16 bytes a texel): enough for a few hundred
/// lines across a 1024×1024 target in one draw, few enough that a list of
/// huge lines is drawn in bounded pieces.
const BATCH_PIXELS: u64 = 1 << 22;

/// One line's window, waiting for its atlas.
struct Piece {
    window: Window,
    /// The fog column's values over the window's quad grid, where fog
    /// rides along.
    fog: Option<Vec<[f32; 4]>>,
    face: Face,
}

/// What every atlas of the draw shares.
struct Atlas<'a> {
    device: &'a Gpu,
    shader: &'a Shader,
    d: &'a DrawStep,
    stage: &'a Stage,
    c: &'a super::gpu::Context<'a, 'a>,
    /// The shader reads `vPos`: the atlas carries each pixel's position.
    positions: bool,
}

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
    let positions = shader
        .program()
        .instructions
        .iter()
        .any(|i| i.src.iter().any(|s| s.reg.file == RegFile::Position));
    let atlas = Atlas {
        device,
        shader,
        d,
        stage,
        c,
        positions,
    };
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
    let (mut batch, mut batch_pixels) = (Vec::new(), 0u64);
    for (shape, provoking, _) in &shapes {
        if c.clip_rect.is_empty() {
            break;
        }
        let Some(mut window) = shape.pixels(c.clip_rect, &slots, &stage.values[*provoking]) else {
            continue;
        };
        let fog = match fog_column {
            true => window.inputs.values.pop().map(|(_, v)| v),
            false => None,
        };
        let (gw, gh) = grid_size(&window);
        let area = u64::from(gw) * u64::from(gh);
        pixels_left = pixels_left.checked_sub(area).ok_or_else(|| {
            DrawFailure::Message(format!(
                "the draw's lines cover more than {} pixels with their quads (raise it with --max-list-pixels)",
                c.settings.budget.max_pixels
            ))
        })?;
        let face = shape.face();
        let full = batch_pixels + area > BATCH_PIXELS;
        if batch.last().is_some_and(|p: &Piece| full || p.face != face) {
            atlas.shade(std::mem::take(&mut batch), pass, &mut drawn)?;
            batch_pixels = 0;
        }
        batch.push(Piece { window, fog, face });
        batch_pixels += area;
    }
    if !batch.is_empty() {
        atlas.shade(batch, pass, &mut drawn)?;
    }
    Ok(drawn)
}

/// A window's quad grid: its width and height rounded up to even.
fn grid_size(window: &Window) -> (u32, u32) {
    (
        PixelInputs::grid_width(window.width) as u32,
        PixelInputs::grid_width(window.height) as u32,
    )
}

impl Atlas<'_> {
    /// Shades `pieces` (of one facing; one atlas unless the device's
    /// texture side splits it) and takes each into `pass` in drawing order.
    fn shade(
        &self,
        pieces: Vec<Piece>,
        pass: &mut Pass,
        drawn: &mut Drawn,
    ) -> Result<(), DrawFailure> {
        let mut outs: Vec<Option<DrawOutput>> = (0..pieces.len()).map(|_| None).collect();
        let face = pieces.first().map_or(Face::Front, |p| p.face);
        let sizes: Vec<(usize, (u32, u32))> = pieces
            .iter()
            .enumerate()
            .map(|(i, p)| (i, grid_size(&p.window)))
            .collect();
        for part in shelves(&sizes, self.device.limits.max_texture_dimension_2d) {
            self.draw(&pieces, &part, face, &mut outs)?;
        }
        for (piece, out) in pieces.iter().zip(outs) {
            let mut out = out.ok_or_else(|| {
                DrawFailure::Message("a line's window was left out of every atlas".into())
            })?;
            if let Some(f) = &self.c.fog {
                super::fog_pixels(&mut out, &piece.window, piece.fog.as_deref(), f);
            }
            drawn.triangles += 1;
            drawn.shaded += piece.window.inputs.covered.iter().filter(|&&k| k).count() as u64;
            pass.take(&piece.window, &out, self.d.pixel.alpha_test, piece.face)?;
        }
        Ok(())
    }

    /// One device draw of the atlas `part`, each piece's output cut from it
    /// into `outs`.
    fn draw(
        &self,
        pieces: &[Piece],
        part: &Packing,
        face: Face,
        outs: &mut [Option<DrawOutput>],
    ) -> Result<(), DrawFailure> {
        let grid = self.inputs(pieces, part);
        let (c, size) = (self.c, (part.width, part.height));
        let mut draw = super::gpu::pixel_draw(self.d, self.stage, c.samplers, c.settings, size);
        draw.inputs = Vec::new();
        draw.pixels = Some(&grid);
        draw.face = face;
        let shaded = gpu::run(self.device, self.shader, &draw, gpu::TargetKind::Raw)
            .map_err(|e| DrawFailure::Message(e.to_string()))?;
        for &(i, at) in &part.placed {
            let w = &pieces[i].window;
            outs[i] = Some(cropped(&shaded, at, w.width, w.height));
        }
        Ok(())
    }

    /// The atlas's inputs: each piece's values (and coverage, and with
    /// `positions` each pixel's place in the render target) copied to its
    /// place; the pixels between windows are uncovered, zero, at (0, 0).
    fn inputs(&self, pieces: &[Piece], part: &Packing) -> PixelInputs {
        let aw = part.width as usize;
        let n = aw * part.height as usize;
        let mut covered = vec![false; n];
        let slots: Vec<u32> = pieces.first().map_or(Vec::new(), |p| {
            p.window.inputs.values.iter().map(|(s, _)| *s).collect()
        });
        let mut values: Vec<(u32, Vec<[f32; 4]>)> =
            slots.iter().map(|&s| (s, vec![[0.0; 4]; n])).collect();
        let mut positions = self.positions.then(|| vec![(0, 0); n]);
        for &(i, (ax, ay)) in &part.placed {
            let w = &pieces[i].window;
            let (gw, gh) = grid_size(w);
            let (ox, oy) = w.inputs.origin;
            for y in 0..gh as usize {
                let row = (ay as usize + y) * aw + ax as usize;
                for x in 0..gw as usize {
                    if x < w.width as usize && y < w.height as usize {
                        covered[row + x] = w.inputs.covered[y * w.width as usize + x];
                    }
                    if let Some(p) = &mut positions {
                        p[row + x] = (ox + x as u32, oy + y as u32);
                    }
                }
                for ((_, to), (_, from)) in values.iter_mut().zip(&w.inputs.values) {
                    let from = &from[y * gw as usize..][..gw as usize];
                    to[row..row + gw as usize].copy_from_slice(from);
                }
            }
        }
        PixelInputs {
            origin: (0, 0),
            covered,
            values,
            positions,
        }
    }
}

/// Where one device draw's windows lie: an atlas of `width × height`
/// (both even), each piece (by index) at an even offset.
#[derive(Debug, PartialEq)]
struct Packing {
    width: u32,
    height: u32,
    placed: Vec<(usize, (u32, u32))>,
}

/// Shelf packing of `(index, (w, h))` grids, all even-sized: tallest first,
/// each shelf filled left to right up to a width near the square root of
/// the total area (at least the widest), a new shelf below when one is
/// full; a packing taller than `max_side` is split in two and each half
/// packed again (a window wider or taller than `max_side` leaves an atlas
/// that the device refuses by its size, as it would the window alone).
fn shelves(sizes: &[(usize, (u32, u32))], max_side: u32) -> Vec<Packing> {
    if sizes.is_empty() {
        return Vec::new();
    }
    let area: u64 = sizes
        .iter()
        .map(|(_, (w, h))| u64::from(*w) * u64::from(*h))
        .sum();
    let widest = sizes.iter().map(|(_, (w, _))| *w).max().unwrap_or(2);
    let side = ((area as f64).sqrt().ceil() as u32).next_multiple_of(2);
    let width = side.min(max_side & !1).max(widest);
    let mut order: Vec<&(usize, (u32, u32))> = sizes.iter().collect();
    order.sort_by_key(|(_, (_, h))| std::cmp::Reverse(*h));
    let (mut x, mut y, mut shelf) = (0u32, 0u32, 0u32);
    let mut placed = Vec::with_capacity(sizes.len());
    for &&(i, (w, h)) in &order {
        if x + w > width {
            (x, y, shelf) = (0, y + shelf, 0);
        }
        placed.push((i, (x, y)));
        x += w;
        shelf = shelf.max(h);
    }
    let height = y + shelf;
    if height > max_side && sizes.len() > 1 {
        let (a, b) = sizes.split_at(sizes.len() / 2);
        let mut parts = shelves(a, max_side);
        parts.extend(shelves(b, max_side));
        return parts;
    }
    vec![Packing {
        width,
        height,
        placed,
    }]
}

/// The `w × h` window at `at` of the device's results over an atlas, laid
/// out as the emulator's output of the window (a GPU counts nothing).
fn cropped(o: &GpuOutput, at: (u32, u32), w: u32, h: u32) -> DrawOutput {
    let color = o
        .color
        .iter()
        .map(|c| c.as_deref().map(|c| cut(c, o.width, at, (w, h))))
        .collect();
    let depth = o.depth.as_deref().map(|d| cut(d, o.width, at, (w, h)));
    let killed = cut(&o.killed, o.width, at, (w, h));
    emu::DrawOutput::uncounted((w, h), color, depth, killed)
}

/// The `w × h` rectangle at `(x, y)` of the rows of `v`, `width` wide.
fn cut<T: Copy>(v: &[T], width: u32, (x, y): (u32, u32), (w, h): (u32, u32)) -> Vec<T> {
    let (width, x, y) = (width as usize, x as usize, y as usize);
    (y..y + h as usize)
        .flat_map(|r| v[r * width + x..][..w as usize].iter().copied())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `p` places every grid of `sizes` once, at even offsets,
    /// inside the atlas and apart from every other.
    fn sound(p: &Packing, sizes: &[(usize, (u32, u32))]) -> bool {
        let size = |i: usize| sizes.iter().find(|(j, _)| *j == i).unwrap().1;
        let rect = |&(i, (x, y)): &(usize, (u32, u32))| (x, y, x + size(i).0, y + size(i).1);
        let inside = p.placed.iter().map(rect).all(|(x0, y0, x1, y1)| {
            x0.is_multiple_of(2) && y0.is_multiple_of(2) && x1 <= p.width && y1 <= p.height
        });
        let apart = p.placed.iter().enumerate().all(|(k, a)| {
            p.placed[k + 1..].iter().all(|b| {
                let (a, b) = (rect(a), rect(b));
                a.2 <= b.0 || b.2 <= a.0 || a.3 <= b.1 || b.3 <= a.1
            })
        });
        inside && apart && p.width.is_multiple_of(2) && p.height.is_multiple_of(2)
    }

    #[test]
    fn windows_are_packed_apart_at_even_offsets() {
        // Thirty grids of mixed even sizes: one atlas, each placed once.
        let sizes: Vec<(usize, (u32, u32))> = (0..30)
            .map(|i| {
                (
                    i,
                    (2 * (1 + (i as u32 * 7) % 13), 2 * (1 + (i as u32 * 5) % 11)),
                )
            })
            .collect();
        let parts = shelves(&sizes, 8192);
        assert_eq!(parts.len(), 1);
        assert!(sound(&parts[0], &sizes), "{:?}", parts[0]);
        let mut placed: Vec<usize> = parts[0].placed.iter().map(|(i, _)| *i).collect();
        placed.sort();
        assert_eq!(placed, (0..30).collect::<Vec<_>>());
        // The area is Σ 4·a·b over the grids; the atlas wastes less than
        // half of its own (tallest-first shelves of these sizes).
        let area: u32 = sizes.iter().map(|(_, (w, h))| w * h).sum();
        assert!(
            2 * area > parts[0].width * parts[0].height,
            "{:?}",
            parts[0]
        );
    }

    #[test]
    fn an_atlas_taller_than_the_device_allows_is_split() {
        // Four 6×6 grids under a 8-texel side: √144 = 12 is cut to 8, one
        // grid a shelf, 24 rows: split in halves, then quarters, each 6×6.
        let sizes: Vec<(usize, (u32, u32))> = (0..4).map(|i| (i, (6, 6))).collect();
        let parts = shelves(&sizes, 8);
        assert_eq!(parts.len(), 4);
        for p in &parts {
            assert_eq!((p.width, p.height, p.placed.len()), (6, 6, 1));
        }
        // A grid wider than the side widens its atlas past it (the device
        // then refuses the draw by its size).
        let parts = shelves(&[(0, (10, 2)), (1, (2, 2))], 8);
        assert!(parts.iter().any(|p| p.width == 10));
        assert_eq!(shelves(&[], 8), Vec::new());
    }
}
