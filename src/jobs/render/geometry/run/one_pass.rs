//! A draw of geometry on the GPU backend in one render pass
//! (`core::gpu::draw_one_pass`), where what the CPU would do after the
//! device is a function of the last pixel to pass each test: no blending,
//! no pixel history, and a depth surface of a format whose stored values
//! the device can hold exactly. The alpha test runs on the device, by the
//! CPU's arithmetic ([`alpha`]). Every other draw
//! takes the per-primitive path, and [`refusal`] says why.
//!
//! The draw's results are the per-primitive path's: the device's depth
//! and stencil tests are Direct3D 9's on the stored values
//! (`core/gpu/one_pass.rs` cites each rule), primitives reach the targets
//! in order, and with blending off the output merger of the last pixel
//! written at each place leaves what merging every pixel in turn leaves.
//! The counts of the step's report — triangles, pixels shaded, written
//! and discarded — come from the device's counters.

use super::{DepthBuffer, Drawn, Pass};
use crate::core::gpu::{self, Compare, DepthSurface, GeometryDraw, Gpu, StencilSide, StencilTest};
use crate::core::ir::Shader;
use crate::core::merge;
use crate::core::raster::depth::DepthFormat;
use crate::core::translate::device_tests::{AlphaDiscard, DepthStore};
use crate::jobs::render::geometry::Geometry;
use crate::jobs::render::pixel_state::CmpFunc;
use crate::jobs::render::{DrawFailure, DrawStep, Settings};

/// Why draw `d` of `g` cannot be drawn in one pass on `device` (`None`
/// when it can).
pub(super) fn refusal(device: &Gpu, d: &DrawStep, g: &Geometry, pass: &Pass) -> Option<String> {
    if std::env::var_os("PS30_PER_PRIMITIVE").is_some() {
        return Some("PS30_PER_PRIMITIVE is set".into());
    }
    if pass.watch.is_some() {
        return Some("the pixel history records every primitive's tests".into());
    }
    if d.output.blend.enabled {
        return Some(
            "blending runs on the CPU (the output merger rounds each blend as the target's format stores it)"
                .into(),
        );
    }
    if let Some((buffer, _)) = &pass.depth {
        let Some(store) = store(buffer.format) else {
            return Some(format!(
                "a {} depth surface has no exact form on the device",
                buffer.format.name()
            ));
        };
        if buffer.values.iter().any(|&v| to_device(store, v).is_none()) {
            return Some("the depth surface holds a value its format does not store".into());
        }
    }
    let stencil = pass.depth.is_some() && g.state.stencil.is_some();
    gpu::one_pass_lacks(device, stencil).map(str::to_string)
}

/// How `format` stores a depth, where the device can hold it exactly.
fn store(format: DepthFormat) -> Option<DepthStore> {
    #[allow(unreachable_patterns)]
    match format {
        DepthFormat::D16 => Some(DepthStore::Unorm(16)),
        DepthFormat::D24X8 | DepthFormat::D24S8 => Some(DepthStore::Unorm(24)),
        DepthFormat::D32F => Some(DepthStore::Float),
        _ => None,
    }
}

/// A stored depth `v` (as `DepthFormat::store` gives it) in the device's
/// form: `k·2⁻ᵇ` for `v = k/(2ᵇ − 1)`, or the float itself.
fn to_device(store: DepthStore, v: f64) -> Option<f32> {
    match store {
        DepthStore::Unorm(bits) => {
            let max = 2f64.powi(i32::from(bits)) - 1.0;
            let k = (v * max).round();
            (k / max == v).then(|| (k * 2f64.powi(-i32::from(bits))) as f32)
        }
        DepthStore::Float => (f64::from(v as f32) == v).then_some(v as f32),
    }
}

/// The device's form back as the stored depth.
fn from_device(store: DepthStore, d: f32) -> f64 {
    match store {
        DepthStore::Unorm(bits) => {
            let k = f64::from(d) * 2f64.powi(i32::from(bits));
            k / (2f64.powi(i32::from(bits)) - 1.0)
        }
        DepthStore::Float => f64::from(d),
    }
}

/// The draw's alpha test as the device runs it (`None` where every pixel
/// passes it: no test, or D3DCMP_ALWAYS).
fn alpha(d: &DrawStep) -> Option<AlphaDiscard> {
    use naga::BinaryOperator as B;
    let test = d.pixel.alpha_test?;
    let func = match test.func {
        CmpFunc::Always => return None,
        CmpFunc::Never => None,
        CmpFunc::Less => Some(B::Less),
        CmpFunc::Equal => Some(B::Equal),
        CmpFunc::LessEqual => Some(B::LessEqual),
        CmpFunc::Greater => Some(B::Greater),
        CmpFunc::NotEqual => Some(B::NotEqual),
        CmpFunc::GreaterEqual => Some(B::GreaterEqual),
    };
    Some(AlphaDiscard {
        scale: test.scale(),
        // The reference as the CPU compares it (it does not depend on the alpha).
        reference: test.compared(0.0).1.to_bits(),
        func,
    })
}

fn compare(f: CmpFunc) -> Compare {
    match f {
        CmpFunc::Never => Compare::Never,
        CmpFunc::Less => Compare::Less,
        CmpFunc::Equal => Compare::Equal,
        CmpFunc::LessEqual => Compare::LessEqual,
        CmpFunc::Greater => Compare::Greater,
        CmpFunc::NotEqual => Compare::NotEqual,
        CmpFunc::GreaterEqual => Compare::GreaterEqual,
        CmpFunc::Always => Compare::Always,
    }
}

/// The draw's depth surface and tests as the device takes them.
fn surface(g: &Geometry, pass: &Pass) -> Option<DepthSurface> {
    let (buffer, state) = pass.depth.as_ref()?;
    let store = store(buffer.format)?;
    let side = |s: &crate::jobs::render::geometry::state::StencilSide| StencilSide {
        compare: compare(s.func),
        fail: s.ops.fail,
        depth_fail: s.ops.zfail,
        pass: s.ops.pass,
    };
    Some(DepthSurface {
        store,
        compare: compare(state.func),
        write: state.write,
        stored: buffer
            .values
            .iter()
            .map(|&v| to_device(store, v).unwrap_or(0.0))
            .collect(),
        stencil: g.state.stencil.map(|s| StencilTest {
            front: side(&s.cw),
            back: side(s.ccw.as_ref().unwrap_or(&s.cw)),
            reference: s.reference,
            mask: s.mask,
            write_mask: s.write_mask,
            stored: buffer.stencil.clone(),
        }),
    })
}

/// Draws `geometry` in one pass and takes its results into `pass`: the
/// depth surface, the colours through the output merger, the counts.
pub(super) fn draw(
    device: &Gpu,
    shader: &Shader,
    (d, geometry, g): (&DrawStep, &GeometryDraw, &Geometry),
    settings: &Settings,
    pass: &mut Pass,
) -> Result<Drawn, DrawFailure> {
    let surface = surface(g, pass);
    let out = gpu::draw_one_pass(device, shader, geometry, surface.as_ref(), alpha(d))
        .map_err(|e| DrawFailure::Message(e.to_string()))?;
    let mut drawn = Drawn::default();
    let mut counts = out.counts.iter();
    for prim in &geometry.primitives {
        let covered: u64 = counts
            .by_ref()
            .take(prim.len())
            .map(|c| u64::from(c[0]))
            .sum();
        if covered > 0 {
            drawn.triangles += prim.len() as u64;
            drawn.shaded += covered;
        }
    }
    if drawn.shaded > settings.budget.max_pixels {
        return Err(DrawFailure::Message(format!(
            "the draw's primitives cover more than {} pixels (raise it with --max-list-pixels)",
            settings.budget.max_pixels
        )));
    }
    pass.merged.killed += out.counts.iter().map(|c| u64::from(c[1])).sum::<u64>();
    if let (Some((buffer, _)), Some(s)) = (&mut pass.depth, &surface) {
        take_surface(buffer, s.store, &out);
    }
    merge_colors(pass, &out)?;
    Ok(drawn)
}

/// The device's depth and stencil values back into `buffer`.
fn take_surface(buffer: &mut DepthBuffer, store: DepthStore, out: &gpu::OnePass) {
    if let Some(depth) = &out.depth {
        for (v, &d) in buffer.values.iter_mut().zip(depth) {
            *v = from_device(store, d);
        }
    }
    if let Some(stencil) = &out.stencil {
        buffer.stencil.copy_from_slice(stencil);
    }
}

/// Each written output's last colours through the output merger, as the
/// per-primitive path's merges leave them with blending off.
fn merge_colors(pass: &mut Pass, out: &gpu::OnePass) -> Result<(), DrawFailure> {
    let skip: Vec<bool> = out.written.iter().map(|&n| n == 0).collect();
    if skip.iter().all(|&s| s) {
        return Ok(());
    }
    let written: u64 = out.written.iter().map(|&n| u64::from(n)).sum();
    for (k, t) in pass.targets.iter_mut().enumerate() {
        let (Some((state, output)), Some(Some(colors))) = (t, out.color.get(k)) else {
            continue;
        };
        merge::merge(&mut state.target, colors, &skip, output)
            .map_err(|e| DrawFailure::Message(format!("oC{k}: {e}")))?;
        if k == 0 {
            pass.merged.written += written;
        }
        state.mips = None;
    }
    Ok(())
}
