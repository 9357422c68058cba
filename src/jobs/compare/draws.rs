//! A draw list on both backends (`compare --list`): every draw's targets
//! after it, compared channel by channel with the statistics of one draw
//! ([`super::stats`]) and the same explanations ([`super::explain::draw`]),
//! and for a draw of geometry which pixels each primitive covered on each
//! backend.
//!
//! Two things differ between the backends on a draw of geometry beyond the
//! shaders' instructions, and each is named as such:
//!
//! * **Interpolation.** The device interpolates the pixel shader's inputs
//!   itself, in f32 with its own plane equations (Vulkan sets no precision
//!   for it), where the emulator computes each in f64 and rounds once: the
//!   inputs differ in their last bits, and so may what the shader makes of
//!   them.
//! * **Coverage.** The device snaps each vertex to its sub-pixel grid before
//!   it tests pixel centres; the emulator tests the exact (f64) triangle. A
//!   pixel covered on one backend only is a rasterisation difference,
//!   reported with its primitive and its distance from the primitive's
//!   nearest edge. It is explained when that distance is within the bound
//!   [`snap_bound`] derives; farther, it is a finding.

use super::explain::{self, Explanation};
use super::probe::Probe;
use super::stats::ChannelStats;
use super::{vertices, CompareError, DrawComparison};
use crate::core::gpu::Gpu;
use crate::jobs::backend::Backend;
use crate::jobs::render::geometry::run::{coverage, Coverage};
use crate::jobs::render::{self, DrawList, Settings, Step, TargetState};
use serde::Serialize;
use std::sync::Arc;

/// A pixel covered by a primitive on one backend only.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoverageDifference {
    /// The primitive's index in the draw (after assembly, in drawing order).
    pub primitive: usize,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// `emulator` or `gpu`: the backend that covered it.
    pub covered_by: &'static str,
    /// Distance in pixels from the pixel's centre to the nearest edge of
    /// the primitive as the emulator sets it up (after clipping and
    /// culling); `None` where the emulator draws none of it.
    pub distance: Option<f64>,
}

/// Which pixels a draw of geometry's primitives covered on each backend.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoverageComparison {
    /// Primitives in the draw.
    pub primitives: usize,
    /// (primitive, pixel) pairs covered on both backends.
    pub both: u64,
    /// Covered on the emulator only.
    pub emulator_only: u64,
    /// Covered on the device only.
    pub gpu_only: u64,
    /// The distance from an edge within which the device's snapping may
    /// move a pixel centre across it ([`snap_bound`]), in pixels.
    pub bound: f64,
    /// Differences farther from their primitive's edges than `bound`.
    pub beyond: u64,
    /// Up to ten differences, the farthest from an edge first.
    pub differences: Vec<CoverageDifference>,
}

/// One draw of the list on both backends.
#[derive(Clone, Debug, Serialize)]
pub struct StepComparison {
    /// The step's index in the list.
    pub index: usize,
    /// The targets the draw wrote, after it, channel by channel
    /// (`name.r` … and `name.depth` for a depth surface).
    pub comparison: DrawComparison,
    /// For a draw of geometry, the coverage on each backend.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coverage: Option<CoverageComparison>,
}

/// A draw list on both backends.
#[derive(Clone, Debug, Serialize)]
pub struct ListComparison {
    /// Every draw step.
    pub steps: Vec<StepComparison>,
}

impl ListComparison {
    /// Whether no step holds a finding.
    pub fn explained(&self) -> bool {
        self.steps
            .iter()
            .all(|s| s.comparison.explanation.as_ref().is_none_or(|e| !e.finding))
    }
}

/// The bound of a coverage difference, in pixels, for a `width × height`
/// target: how far the device may move an edge before it tests pixel
/// centres.
///
/// Vulkan snaps each vertex's framebuffer coordinates to a grid of
/// 2^−subPixelPrecisionBits pixel, with subPixelPrecisionBits ≥ 4 (Vulkan
/// 1.3, "Limits", minimum 4): a coordinate moves by at most half a step,
/// 2^−5, and a vertex by at most √2·2^−5. Before that, the vertex's
/// position reaches the device through f32 arithmetic — the half-pixel
/// offset (one multiply and one add), the perspective divide and the
/// viewport transform (a multiply and an add) — at most 4 roundings of a
/// value under max(width, height) pixels, each within 2^−24 of it relative:
/// 4·2^−24·max(width, height) per coordinate. Every point of an edge is a
/// convex combination of its ends, so it moves no more than they do; a
/// pixel centre farther than that from every edge of the exact triangle is
/// on the same side of the snapped one.
pub fn snap_bound(width: u32, height: u32) -> f64 {
    let f32_rounding = 4.0 * f64::powi(2.0, -24) * f64::from(width.max(height));
    std::f64::consts::SQRT_2 * (f64::powi(2.0, -5) + f32_rounding)
}

/// The distance from (x, y) to the segment a–b.
fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = match len2 {
        0.0 => 0.0,
        _ => (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0),
    };
    let (cx, cy) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
    (cx * cx + cy * cy).sqrt()
}

/// The coverage of one draw compared, pixel by pixel and primitive by
/// primitive.
fn compare_coverage(c: &Coverage, width: u32, height: u32) -> CoverageComparison {
    let bound = snap_bound(width, height);
    let mut out = CoverageComparison {
        primitives: c.emulator.len(),
        both: 0,
        emulator_only: 0,
        gpu_only: 0,
        bound,
        beyond: 0,
        differences: Vec::new(),
    };
    for (p, (e, g)) in c.emulator.iter().zip(&c.gpu).enumerate() {
        let only = |a: &[u32], b: &[u32]| -> Vec<u32> {
            a.iter()
                .copied()
                .filter(|i| b.binary_search(i).is_err())
                .collect()
        };
        let (e_only, g_only) = (only(e, g), only(g, e));
        out.both += (e.len() - e_only.len()) as u64;
        out.emulator_only += e_only.len() as u64;
        out.gpu_only += g_only.len() as u64;
        let sides = [(e_only, "emulator"), (g_only, "gpu")];
        for (pixels, covered_by) in sides {
            for i in pixels {
                let (x, y) = (i % width, i / width);
                let centre = [f64::from(x), f64::from(y)];
                let distance = c.triangles[p]
                    .iter()
                    .flat_map(|t| {
                        (0..3).map(move |k| segment_distance(centre, t[k], t[(k + 1) % 3]))
                    })
                    .reduce(f64::min);
                if distance.is_none_or(|d| d > bound) {
                    out.beyond += 1;
                }
                out.differences.push(CoverageDifference {
                    primitive: p,
                    x,
                    y,
                    covered_by,
                    distance,
                });
            }
        }
    }
    out.differences.sort_by(|a, b| {
        let far = |d: &CoverageDifference| d.distance.unwrap_or(f64::INFINITY);
        far(b).total_cmp(&far(a))
    });
    out.differences.truncate(10);
    out
}

/// What one backend's run of the list left after each draw: the targets
/// and, for draws of geometry on the emulator's pass, the coverage.
struct Run {
    after: Vec<(usize, Vec<TargetState>)>,
    coverage: Vec<(usize, Coverage)>,
}

/// Runs `list` under `settings`; with `device`, each draw of geometry's
/// coverage is also taken on both backends.
fn run(
    list: &DrawList,
    settings: &Settings,
    device: Option<&Arc<Gpu>>,
) -> Result<Run, CompareError> {
    let mut r = Run {
        after: Vec::new(),
        coverage: Vec::new(),
    };
    let mut failed: Option<String> = None;
    render::run(list, settings, &mut |report, states| {
        let Step::Draw(d) = &list.steps[report.index] else {
            return;
        };
        r.after.push((report.index, states.to_vec()));
        if let (Some(device), Some(_)) = (device, &d.geometry) {
            match coverage(list, d, states, settings, device) {
                Ok(c) => r.coverage.push((report.index, c)),
                Err(e) => {
                    let message = match e {
                        render::DrawFailure::Message(m) => m,
                        render::DrawFailure::Emu(e) => e.to_string(),
                    };
                    failed.get_or_insert(format!("steps[{}]: {message}", report.index));
                }
            }
        }
    })
    .map_err(|e| CompareError::Other(e.to_string()))?;
    match failed {
        Some(e) => Err(CompareError::Other(e)),
        None => Ok(r),
    }
}

/// One target's channels (those its format stores) on both backends, and
/// its depth surface if it has one.
fn target_channels(name: &str, e: &TargetState, g: &TargetState) -> Vec<ChannelStats> {
    let (t, w) = (&e.target, e.target.width);
    let mut out = Vec::new();
    for c in (0..4).filter(|&c| t.format.stores(c)) {
        let ev: Vec<f32> = t.texels.iter().map(|v| v[c]).collect();
        let gv: Vec<f32> = g.target.texels.iter().map(|v| v[c]).collect();
        let channel = format!("{name}.{}", ["r", "g", "b", "a"][c]);
        out.push(ChannelStats::of(channel, w, &ev, &gv));
    }
    if let (Some(ed), Some(gd)) = (&e.depth, &g.depth) {
        let ev: Vec<f32> = ed.values.iter().map(|&v| v as f32).collect();
        let gv: Vec<f32> = gd.values.iter().map(|&v| v as f32).collect();
        out.push(ChannelStats::of(format!("{name}.depth"), w, &ev, &gv));
    }
    out
}

/// Runs `list` on the emulator and on `gpu` (`settings` gives the rest:
/// limits, budget, float rules), and compares every draw, explained by
/// `probes`.
pub fn compare_list(
    gpu: &Arc<Gpu>,
    list: &DrawList,
    settings: &Settings,
    probes: &[Probe],
) -> Result<ListComparison, CompareError> {
    let emulated = Settings {
        backend: Backend::Emulator,
        ..settings.clone()
    };
    let on_device = Settings {
        backend: Backend::Gpu(gpu.clone()),
        ..settings.clone()
    };
    let e = run(list, &emulated, Some(gpu))?;
    let g = run(list, &on_device, None)?;
    let mut steps = Vec::new();
    for ((index, es), (_, gs)) in e.after.iter().zip(&g.after) {
        let Step::Draw(d) = &list.steps[*index] else {
            continue;
        };
        let written =
            std::iter::once(d.target).chain(d.pixel.outputs.iter().flatten().map(|(t, _)| *t));
        let channels: Vec<ChannelStats> = written
            .flat_map(|t| target_channels(&list.targets[t].name, &es[t], &gs[t]))
            .collect();
        let spec = &list.targets[d.target];
        let coverage = e
            .coverage
            .iter()
            .find(|(i, _)| i == index)
            .map(|(_, c)| compare_coverage(c, spec.width, spec.height));
        let mut shaders = vec![&list.shaders[d.shader].loaded.shader];
        if let Some(vs) = d.geometry.as_ref().and_then(|g| g.vertex_shader) {
            shaders.push(&list.shaders[vs].loaded.shader);
        }
        let mut opcodes: Vec<String> = shaders
            .iter()
            .flat_map(|s| vertices::probed_ops(s))
            .collect();
        opcodes.sort_unstable();
        opcodes.dedup();
        let mut comparison = DrawComparison {
            shader: list.shaders[d.shader].name.clone(),
            width: spec.width,
            height: spec.height,
            target: spec.format.d3d_name().into(),
            float_rules: d
                .pixel
                .float_rules
                .unwrap_or(settings.float_rules)
                .name()
                .into(),
            channels,
            killed_mismatches: 0,
            worst_inputs: Vec::new(),
            opcodes,
            filtering: Vec::new(),
            explanation: None,
        };
        let profile = list.shaders[d.shader].loaded.shader.program().profile;
        let fog = d.geometry.as_ref().and_then(|g| g.state.fog);
        if let Some(f) = fog.filter(|_| profile != crate::core::profile::Profile::Ps3_0) {
            comparison.filtering.push(fog_clause(&f));
        }
        comparison.explanation = Some(explain_step(&mut comparison, coverage.as_ref(), probes));
        steps.push(StepComparison {
            index: *index,
            comparison,
            coverage,
        });
    }
    Ok(ListComparison { steps })
}

/// Why a fogged draw's colours may differ: the fog itself runs on the CPU
/// on both backends, from a d that each backend's rasteriser gives.
fn fog_clause(f: &crate::core::raster::fog::Fog) -> String {
    use crate::core::raster::fog::FogMode;
    let d = match (f.mode, f.w) {
        (FogMode::Vertex, _) => "vertex fog's factor, interpolated with perspective",
        (_, true) => "table fog's w, interpolated with perspective",
        _ => "table fog's z, the rasterised depth (not oDepth)",
    };
    format!(
        "the fog is blended on the CPU on both backends from {d}, which the device interpolates in f32 and the emulator in f64, rounded once"
    )
}

/// A step's explanation: the draw's ([`explain::draw`]), with
/// interpolation and coverage as further causes where the draw is one of
/// geometry, and a coverage difference beyond [`snap_bound`] a finding.
fn explain_step(
    c: &mut DrawComparison,
    coverage: Option<&CoverageComparison>,
    probes: &[Probe],
) -> Explanation {
    if let Some(cov) = coverage {
        c.filtering.push(
            "the device interpolates the pixel shader's inputs itself, in f32 (Vulkan sets no precision for it), where the emulator computes them in f64 and rounds once".into(),
        );
        let differ = cov.emulator_only + cov.gpu_only;
        if differ > cov.beyond && differ > 0 {
            c.filtering.push(format!(
                "{} pixels are covered on one backend only, each within {:.3} pixel of an edge of its primitive, where the device's sub-pixel snapping may move it",
                differ - cov.beyond,
                cov.bound
            ));
        }
    }
    let mut e = explain::draw(c, probes);
    if let Some(cov) = coverage.filter(|c| c.beyond > 0) {
        let first = &cov.differences[0];
        let place = match first.distance {
            Some(d) => format!("{d:.3} pixel from its nearest edge"),
            None => "where the emulator draws none of it".into(),
        };
        e.finding = true;
        e.device = false;
        e.text = format!(
            "FINDING: {} pixels covered on one backend only beyond the snapping bound of {:.3} pixel: e.g. ({}, {}) by primitive {} on the {} only, {place}; {}",
            cov.beyond, cov.bound, first.x, first.y, first.primitive, first.covered_by, e.text
        );
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_distances() {
        assert_eq!(segment_distance([0.0, 1.0], [0.0, 0.0], [2.0, 0.0]), 1.0);
        assert_eq!(segment_distance([3.0, 0.0], [0.0, 0.0], [2.0, 0.0]), 1.0);
        assert_eq!(segment_distance([1.0, 1.0], [1.0, 1.0], [1.0, 1.0]), 0.0);
    }

    #[test]
    fn the_snapping_bound() {
        // √2·(1/32 + 4·2⁻²⁴·8) for an 8×8 target.
        let b = snap_bound(8, 8);
        assert!((b - std::f64::consts::SQRT_2 * (1.0 / 32.0 + 32.0 / 16_777_216.0)).abs() < 1e-15);
    }
}
