//! `ps30 profile --list LIST`: one draw of a draw list, profiled as the
//! list draws it. The list runs up to that step (so its targets, depth and
//! stencil hold what the earlier steps left), and while the step runs its
//! pixel shader's costs are gathered primitive by primitive
//! ([`crate::jobs::render::costs`]): every covered pixel's own slots, every
//! 2×2 quad a primitive reached — helpers included, so a quad on a
//! triangle's edge pays for the lanes outside it — and the gradient sites,
//! from which come the divergent quads, the lockstep efficiency and the
//! divergent-gradient findings of a full-screen profile, and what each
//! source line cost over every primitive's quads ([`crate::core::emu::lines`]). A
//! draw of geometry through a vertex shader also gets the vertex shader's
//! runs: each vertex's executed slots against the cost model, and its
//! costs per source line.

use super::{costs_of, QuadCosts};
use crate::core::cost::{self, Range};
use crate::core::diag::SourceFile;
use crate::core::emu::findings::{findings, Finding, SiteSummary};
use crate::core::emu::{Draw, DrawOutput};
use crate::jobs::render::history::Recorder;
use crate::jobs::render::{self, DrawList, Settings, Source, Step};
use crate::jobs::vertices::VertexProfile;

/// What `profile --list` found for one draw.
#[derive(Clone, Debug)]
pub struct ListProfile {
    /// The draw step profiled.
    pub step: usize,
    /// The pixel shader's name in the list, and its source.
    pub shader: String,
    /// The pixel shader's source, for diagnostics.
    pub file: SourceFile,
    /// The draw carries geometry (else a full-screen quad).
    pub geometry: bool,
    /// Primitives that ran the pixel shader (a full-screen draw is one).
    pub primitives: u64,
    /// The cost model's shortest and longest executed count per pixel.
    pub static_executed: Range,
    /// The static slots and executed count fit the shader's profile.
    pub within_limits: bool,
    /// Every covered pixel's count lies in [`ListProfile::static_executed`].
    pub counts_agree: bool,
    /// Per-pixel and per-quad costs over every primitive's quads.
    pub costs: QuadCosts,
    /// What each source line of the pixel shader cost over them.
    pub lines: Vec<crate::core::emu::lines::LineRuns>,
    /// Quads with fewer than four covered pixels (at a primitive's edges).
    pub edge_quads: u64,
    /// Their lanes that ran as helpers only (4 − covered, summed).
    pub helper_lanes: u64,
    /// Every instruction that takes a gradient, summed over the primitives.
    pub gradients: Vec<SiteSummary>,
    /// Divergent-gradient findings.
    pub findings: Vec<Finding>,
    /// The vertex shader (its name) and its runs over the draw's vertices,
    /// or why they could not be profiled; `None` without one.
    pub vertex: Option<(String, Result<VertexProfile, String>)>,
}

impl ListProfile {
    /// Whether the run found a problem: a count outside the cost model, a
    /// shader over its limits, a divergent gradient.
    pub fn problem(&self) -> bool {
        !self.counts_agree
            || !self.within_limits
            || !self.findings.is_empty()
            || self.vertex.as_ref().is_some_and(|(_, v)| {
                v.as_ref()
                    .is_ok_and(|v| !v.within_limits || !v.counts_agree)
            })
    }
}

/// The step to profile: `step`, which must draw, or the list's last draw.
fn draw_step(list: &DrawList, step: Option<usize>) -> Result<usize, String> {
    match step {
        Some(s) => match list.steps.get(s) {
            Some(Step::Draw(_)) => Ok(s),
            Some(_) => Err(format!("step {s} is not a draw")),
            None => Err(format!(
                "step {s} is past the list's {} steps",
                list.steps.len()
            )),
        },
        None => list
            .steps
            .iter()
            .rposition(|s| matches!(s, Step::Draw(_)))
            .ok_or_else(|| "the list has no draw".to_string()),
    }
}

/// Profiles draw `step` of `list` (the last draw when `None`), with `bins`
/// histogram bins, on the emulator.
pub fn profile_list(
    list: &DrawList,
    step: Option<usize>,
    settings: &Settings,
    bins: usize,
) -> Result<ListProfile, String> {
    let step = draw_step(list, step)?;
    let mut upto = list.clone();
    upto.steps.truncate(step + 1);
    let mut recorder = Recorder::new(&upto, &[])?.with_costs(step);
    render::run_with_history(&upto, settings, &mut |_, _| {}, Some(&mut recorder))
        .map_err(|e| e.to_string())?;
    let Step::Draw(d) = &list.steps[step] else {
        return Err(format!("step {step} is not a draw"));
    };
    let gathered = recorder.costs().cloned().unwrap_or_default();
    let spec = &list.shaders[d.shader];
    let (shader, file) = (&spec.loaded.shader, &spec.loaded.file);
    let env = crate::jobs::backend::environment(&d.constants);
    let budget = cost::Profile::ps_3_0().for_profile(shader.program().profile);
    let analysis = cost::analyse(shader, file, &env, &budget).map_err(|e| e.to_string())?;
    let costs = costs_of(&gathered.pixels, &gathered.quads, bins);
    let counts_agree = gathered
        .pixels
        .iter()
        .all(|&e| analysis.executed.min <= e && e <= analysis.executed.max);
    // Divergent gradients only: the LOD warnings need the textures bound,
    // which the list's own run reports per step.
    let out = DrawOutput {
        gradients: gathered.gradients.clone(),
        ..DrawOutput::uncounted((0, 0), Vec::new(), None, Vec::new())
    };
    let found = findings(&out, &Draw::new(1, 1), file);
    Ok(ListProfile {
        step,
        shader: spec.name.clone(),
        file: file.clone(),
        geometry: d.geometry.is_some(),
        primitives: gathered.primitives,
        static_executed: analysis.executed,
        within_limits: analysis.verdict == cost::Verdict::Within,
        counts_agree,
        costs,
        lines: crate::core::emu::lines::pixel_lines(shader, file, &gathered.instructions),
        edge_quads: gathered.quads.iter().filter(|q| q.pixels < 4).count() as u64,
        helper_lanes: gathered.quads.iter().map(|q| 4 - q.pixels.min(4)).sum(),
        gradients: gathered
            .gradients
            .iter()
            .map(|g| SiteSummary::new(g, file))
            .collect(),
        findings: found,
        vertex: vertex_runs(list, d, settings),
    })
}

/// The vertex shader's runs over the draw's vertices, with the textures
/// its samplers read from the list's texture files.
fn vertex_runs(
    list: &DrawList,
    d: &render::DrawStep,
    settings: &Settings,
) -> Option<(String, Result<VertexProfile, String>)> {
    let g = d.geometry.as_ref()?;
    let spec = &list.shaders[g.vertex_shader?];
    let textures: Vec<_> = g
        .vertex_samplers
        .iter()
        .filter_map(|(s, source, state)| match source {
            Source::Texture(t) => list.textures[*t].file.clone().map(|f| (*s, f, *state)),
            Source::Target(_) => None,
        })
        .collect();
    let run = crate::jobs::vertices::profile(
        &spec.loaded.shader,
        &spec.loaded.file,
        g.vertex_constants.clone(),
        &textures,
        &g.vertices,
        settings.float_rules,
        settings.limits.max_executed_per_pixel,
    );
    Some((spec.name.clone(), run))
}
