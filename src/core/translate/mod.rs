//! The translation: a validated ps_3_0 shader lowered to a
//! [`naga::Module`] with one fragment entry point, checked by naga's
//! validator, from which naga's own writers produce WGSL, SPIR-V, GLSL,
//! HLSL and MSL — and which `core/gpu` draws on a Vulkan device.
//!
//! It exists so that a D3D9 shader can be read (and run) in a modern
//! language with a translation that is checked — by naga's validator, and
//! pixel by pixel against the emulator (`ps30 compare`) — rather than
//! trusted, and so that the emulator has a second witness.
//!
//! * `interface.rs` — the binding layout (constant block, textures,
//!   locations), shared with `core/gpu` and the header;
//! * `module.rs` — types, register variables, constants, entry points;
//! * `lower.rs` — operands, destinations and the arithmetic instructions;
//! * `texture.rs` — the texld family and the sampler state the shader
//!   emulates (LOD bias, MIRRORONCE, BORDER colours);
//! * `flow.rs` — if/rep/loop/break/call as naga's structured statements;
//! * `header.rs` — the comment block that opens every written file;
//! * `builder.rs` — expression and statement bookkeeping for one function.
//!
//! Special values follow the [`FloatRules`] given, as the emulator does.
//!
//! # Implicit derivatives under divergent flow
//!
//! D3D9 lets `texld`/`dsx`/`dsy` run inside flow control that may differ
//! between the pixels of a quad; their result is then undefined (facts
//! sheet §5), and the emulator reports where a draw did it (its gradient
//! findings). WGSL rejects such a program unless its
//! `derivative_uniformity` diagnostic is off. ps30 keeps the derivative
//! where the shader has it (moving it out of the branch would change what
//! the shader computes where flow is uniform) and, when naga's uniformity
//! analysis rejects the module or ps30's own look at the shader finds a
//! derivative under `if` on p0 or a comparison, in a loop a `break` can
//! leave, or in a subroutine called from such a place (naga's analysis does
//! not follow private variables, which other WGSL compilers treat as
//! varying), turns that diagnostic off for the module and says so, naming
//! the first such instruction, in [`Translation::notes`] and in the header.
//! Loops count here: naga cannot prove a loop counter uniform, so a `texld`
//! inside any `rep` needs the directive even when every pixel runs the
//! same count.

mod builder;
mod cube;
pub mod device_tests;
pub mod fixed;
mod flow;
pub mod header;
pub mod interface;
mod lower;
mod module;
pub mod records;
pub mod specialise;
mod texture;
pub mod vertex;

pub use interface::Interface;
pub use module::Entry;
pub use specialise::{SamplerSpec, Specialisation};

use crate::core::float_rules::FloatRules;
use crate::core::ir::Shader;
use builder::Fb;
use flow::Functions;
use lower::Lower;
use module::Ctx;
use naga::valid::{Capabilities, ValidationFlags, Validator};
use std::fmt;

/// The languages naga writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Target {
    /// WGSL, the language WebGPU runs and `core/gpu` draws with.
    Wgsl,
    /// SPIR-V 1.0, binary (Vulkan's).
    SpirV,
    /// GLSL 4.50 core.
    Glsl,
    /// HLSL shader model 5.1 (Direct3D 12's).
    Hlsl,
    /// Metal Shading Language 2.1.
    Msl,
}

impl Target {
    /// Every target, WGSL first.
    pub const ALL: [Target; 5] = [
        Target::Wgsl,
        Target::SpirV,
        Target::Glsl,
        Target::Hlsl,
        Target::Msl,
    ];

    /// The name used on the command line and as the file extension's stem
    /// (`wgsl`, `spirv`, `glsl`, `hlsl`, `msl`).
    pub fn name(self) -> &'static str {
        match self {
            Target::Wgsl => "wgsl",
            Target::SpirV => "spirv",
            Target::Glsl => "glsl",
            Target::Hlsl => "hlsl",
            Target::Msl => "msl",
        }
    }

    /// What the written file is.
    pub fn describe(self) -> &'static str {
        match self {
            Target::Wgsl => "WGSL",
            Target::SpirV => "SPIR-V 1.0 (binary; the header is its OpSource text)",
            Target::Glsl => "GLSL 4.50 core",
            Target::Hlsl => "HLSL shader model 5.1",
            Target::Msl => "Metal Shading Language 2.1",
        }
    }
}

/// Why a translation failed.
#[derive(Debug)]
pub enum TranslateError {
    /// Something the lowering does not express (named).
    Unsupported(String),
    /// naga's validator rejected the module: a bug in the lowering.
    Invalid(String),
    /// A naga writer failed.
    Write {
        /// The language being written.
        target: Target,
        /// The writer's own message.
        message: String,
    },
    /// The IR broke an invariant validation should guarantee.
    Internal(&'static str),
}

impl fmt::Display for TranslateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TranslateError::Unsupported(what) => write!(f, "cannot translate {what}"),
            TranslateError::Invalid(e) => {
                write!(f, "the translated module fails naga's validation: {e}")
            }
            TranslateError::Write { target, message } => {
                write!(f, "writing {}: {message}", target.describe())
            }
            TranslateError::Internal(what) => write!(f, "translation: {what}"),
        }
    }
}

impl std::error::Error for TranslateError {}

/// A validated translation.
pub struct Translation {
    /// The naga module, validated.
    pub module: naga::Module,
    /// The validator's analysis of [`Translation::module`], which naga's writers need.
    pub info: naga::valid::ModuleInfo,
    /// What an application binds where, as the header prints it.
    pub interface: Interface,
    /// The float rules the module computes special values by.
    pub rules: FloatRules,
    /// Which entry point the module has: an application's or the GPU backend's.
    pub entry: Entry,
    /// Whether the module turns WGSL's `derivative_uniformity` off.
    pub derivative_uniformity_off: bool,
    /// What a reader should know (each a sentence).
    pub notes: Vec<String>,
}

impl Translation {
    /// The entry point's name.
    pub fn entry_name(&self) -> &'static str {
        match self.entry {
            Entry::Application => "main",
            Entry::Draw => "ps30_draw",
            Entry::Geometry { .. } => "ps30_geometry",
        }
    }
}

/// Lowers `shader` and validates the module; every sampler reads its state
/// at run time ([`Specialisation::general`]).
pub fn translate(
    shader: &Shader,
    rules: FloatRules,
    entry: Entry,
) -> Result<Translation, TranslateError> {
    translate_specialised(shader, rules, entry, &Specialisation::general())
}

/// [`translate`] for sampler states known in advance: each sampler carries
/// only the emulation code `spec` names for it.
pub fn translate_specialised(
    shader: &Shader,
    rules: FloatRules,
    entry: Entry,
    spec: &Specialisation,
) -> Result<Translation, TranslateError> {
    let profile = shader.program().profile;
    let shader = shader
        .runnable()
        .map_err(|why| TranslateError::Unsupported(format!("a {profile} shader: {why}")))?;
    if !profile.runs() || profile.stage() != crate::core::profile::Stage::Pixel {
        return Err(TranslateError::Unsupported(format!(
            "a {profile} shader: ps30 translates ps_1_1–ps_1_4, ps_2_0, ps_2_x and ps_3_0 pixel shaders"
        )));
    }
    let mut module = naga::Module::default();
    let mut cx = Ctx::new(&mut module, shader, spec)?;
    cx.border = texture::add_border_function(&mut module, shader, &cx.t, spec);
    let functions = lower_functions(&mut module, &cx, shader, rules)?;
    let main = *functions
        .get(&MAIN)
        .ok_or(TranslateError::Internal("main was not lowered"))?;
    let interface = Interface::of(shader);
    module::entry_point(&mut module, &cx, &interface, main, entry);

    let mut notes = Vec::new();
    // naga's analysis does not follow private variables, which WGSL's
    // uniformity rules treat as varying per pixel: ps30 also looks for
    // itself (see `divergent_derivative`).
    let at_risk = divergent_derivative(shader);
    let strict = validate(&module);
    let (info, off) = match (strict, at_risk) {
        (Ok(info), None) => (info, false),
        (_, at) => {
            derivative_uniformity_off(&mut module);
            let info = validate(&module).map_err(TranslateError::Invalid)?;
            let place = at.map_or(String::new(), |i| {
                format!(
                    " (the first at instruction {}, `{}`)",
                    i + 1,
                    shader.instructions()[i].op
                )
            });
            notes.push(format!(
                "implicit derivatives (texld, texldp, texldb, dsx, dsy) sit in flow control that may differ between \
                 the pixels of a quad{place}; the module turns WGSL's derivative_uniformity diagnostic off, and where a \
                 quad's pixels do diverge the result is undefined, as in Direct3D 9 (ps30 profile and the emulator's \
                 gradient findings say where)"
            ));
            (info, true)
        }
    };
    Ok(Translation {
        module,
        info,
        interface,
        rules,
        entry,
        derivative_uniformity_off: off,
        notes,
    })
}

/// The first implicit-derivative instruction (texld, texldp, texldb, dsx,
/// dsy) that may run with part of a quad: inside an `if` on p0 or on a
/// comparison, inside a rep/loop that a `break` can leave early, or in a
/// subroutine called from such a place or by `callnz p0`. (`if b#` and
/// loop counts come from constants, the same for every pixel.)
fn divergent_derivative(shader: &Shader) -> Option<usize> {
    use crate::core::isa::{Opcode as O, RegFile};
    let ins = shader.instructions();
    let info = shader.info();
    let owner = |i: usize| -> Option<u32> {
        info.labels
            .iter()
            .filter(|(_, &at)| at as usize <= i)
            .max_by_key(|(_, &at)| at)
            .map(|(&l, _)| l)
    };
    let mut divergent_labels = std::collections::BTreeSet::new();
    // Repeat until no new label is found divergent (call depth ≤ 4).
    for _ in 0..8 {
        let mut stack: Vec<bool> = Vec::new();
        for (i, x) in ins.iter().enumerate() {
            let in_divergent_fn = owner(i).is_some_and(|l| divergent_labels.contains(&l));
            let divergent = in_divergent_fn || stack.iter().any(|&d| d);
            match x.op {
                O::If => stack.push(
                    x.src
                        .first()
                        .is_none_or(|s| s.reg.file != RegFile::ConstBool),
                ),
                O::Ifc => stack.push(true),
                O::Rep | O::Loop => {
                    let end = info
                        .matching
                        .get(i)
                        .copied()
                        .flatten()
                        .map_or(i, |m| m as usize);
                    stack.push(
                        ins[i..end]
                            .iter()
                            .any(|y| matches!(y.op, O::Break | O::BreakC | O::BreakP)),
                    );
                }
                O::EndIf | O::EndRep | O::EndLoop => {
                    stack.pop();
                }
                O::Label => stack.clear(),
                O::Call | O::CallNz => {
                    let pred = x.op == O::CallNz
                        && x.src
                            .get(1)
                            .is_some_and(|s| s.reg.file == RegFile::Predicate);
                    if divergent || pred {
                        if let Some(l) = x.src.first() {
                            divergent_labels.insert(l.reg.index);
                        }
                    }
                }
                O::TexLd | O::TexLdP | O::TexLdB | O::Dsx | O::Dsy if divergent => return Some(i),
                _ => {}
            }
        }
    }
    None
}

/// The key of `main` among the lowered functions (labels are 0..2047).
const MAIN: u32 = u32::MAX;

fn validate(module: &naga::Module) -> Result<naga::valid::ModuleInfo, String> {
    // PRIMITIVE_INDEX: the one-pass geometry entry point counts per
    // triangle (`device_tests`); no other entry point reads it.
    Validator::new(
        ValidationFlags::all(),
        Capabilities::default() | Capabilities::PRIMITIVE_INDEX,
    )
    .validate(module)
    .map_err(|e| {
        let mut s = e.to_string();
        let mut source = std::error::Error::source(e.as_inner());
        while let Some(inner) = source {
            s.push_str(": ");
            s.push_str(&inner.to_string());
            source = inner.source();
        }
        s
    })
}

fn derivative_uniformity_off(module: &mut naga::Module) {
    use naga::diagnostic_filter::{
        DiagnosticFilter, DiagnosticFilterNode, FilterableTriggeringRule, Severity,
        StandardFilterableTriggeringRule,
    };
    let node = module.diagnostic_filters.append(
        DiagnosticFilterNode {
            inner: DiagnosticFilter {
                new_severity: Severity::Off,
                triggering_rule: FilterableTriggeringRule::Standard(
                    StandardFilterableTriggeringRule::DerivativeUniformity,
                ),
            },
            parent: None,
        },
        naga::Span::UNDEFINED,
    );
    module.diagnostic_filter_leaf = Some(node);
}

/// Lowers main and every subroutine, callees before callers.
fn lower_functions(
    module: &mut naga::Module,
    cx: &Ctx,
    shader: &Shader,
    rules: FloatRules,
) -> Result<Functions, TranslateError> {
    let ins = shader.instructions();
    let info = shader.info();
    // (key, first instruction, one past the last)
    let mut bodies = vec![(MAIN, 0usize, info.main_end as usize)];
    let mut starts: Vec<(u32, usize)> =
        info.labels.iter().map(|(&l, &i)| (l, i as usize)).collect();
    starts.sort_by_key(|&(_, i)| i);
    for (k, &(label, at)) in starts.iter().enumerate() {
        let end = starts.get(k + 1).map_or(ins.len(), |&(_, i)| i);
        bodies.push((label, at + 1, end));
    }
    let calls = |start: usize, end: usize| -> Vec<u32> {
        ins[start..end]
            .iter()
            .filter(|x| {
                matches!(
                    x.op,
                    crate::core::isa::Opcode::Call | crate::core::isa::Opcode::CallNz
                )
            })
            .filter_map(|x| x.src.first().map(|s| s.reg.index))
            .collect()
    };
    // Depth-first, callees first (the validator refused recursion; a
    // visiting set guards against it anyway).
    let mut order = Vec::new();
    let mut state = std::collections::BTreeMap::new();
    fn visit(
        key: u32,
        bodies: &[(u32, usize, usize)],
        calls: &dyn Fn(usize, usize) -> Vec<u32>,
        state: &mut std::collections::BTreeMap<u32, bool>,
        order: &mut Vec<u32>,
    ) -> Result<(), TranslateError> {
        match state.get(&key) {
            Some(true) => return Ok(()),
            Some(false) => return Err(TranslateError::Unsupported("recursive calls".into())),
            None => {}
        }
        state.insert(key, false);
        let &(_, s, e) = bodies
            .iter()
            .find(|b| b.0 == key)
            .ok_or(TranslateError::Internal("a call to a missing label"))?;
        for callee in calls(s, e) {
            visit(callee, bodies, calls, state, order)?;
        }
        state.insert(key, true);
        order.push(key);
        Ok(())
    }
    for &(key, _, _) in &bodies {
        visit(key, &bodies, &calls, &mut state, &mut order)?;
    }
    let mut functions = Functions::new();
    for key in order {
        let &(_, s, e) = bodies
            .iter()
            .find(|b| b.0 == key)
            .ok_or(TranslateError::Internal("a function without a body"))?;
        let name = if key == MAIN {
            "ps_main".to_string()
        } else {
            format!("l{key}")
        };
        let mut l = Lower {
            cx,
            fb: Fb::new(&name),
            rules,
            loops: 0,
            flushed: Default::default(),
        };
        l.range(ins, &info.matching, &functions, s, e)?;
        let h = module
            .functions
            .append(l.fb.finish(), naga::Span::UNDEFINED);
        functions.insert(key, h);
    }
    Ok(functions)
}

/// A written translation: text, or SPIR-V words.
pub enum Written {
    /// Text languages: WGSL, GLSL, HLSL, MSL.
    Text(String),
    /// SPIR-V's words, little-endian bytes.
    Binary(Vec<u8>),
}

/// Writes the translation in `target`'s language, opening with `header`.
pub fn write(t: &Translation, target: Target, header: &str) -> Result<Written, TranslateError> {
    let fail = |message: String| TranslateError::Write { target, message };
    let entry = t.entry_name().to_string();
    let stage = naga::ShaderStage::Fragment;
    let text = match target {
        Target::Wgsl => {
            let body = naga::back::wgsl::write_string(
                &t.module,
                &t.info,
                naga::back::wgsl::WriterFlags::empty(),
            )
            .map_err(|e| fail(e.to_string()))?;
            let directive = if t.derivative_uniformity_off {
                "diagnostic(off, derivative_uniformity);\n\n"
            } else {
                ""
            };
            format!("{header}{directive}{body}")
        }
        Target::SpirV => {
            let options = naga::back::spv::Options {
                debug_info: Some(naga::back::spv::DebugInfo {
                    source_code: header,
                    file_name: "ps30",
                    language: naga::back::spv::SourceLanguage::Unknown,
                }),
                flags: naga::back::spv::WriterFlags::ADJUST_COORDINATE_SPACE
                    | naga::back::spv::WriterFlags::LABEL_VARYINGS,
                ..Default::default()
            };
            let pipeline = naga::back::spv::PipelineOptions {
                shader_stage: stage,
                entry_point: entry,
            };
            let words = naga::back::spv::write_vec(&t.module, &t.info, &options, Some(&pipeline))
                .map_err(|e| fail(e.to_string()))?;
            return Ok(Written::Binary(
                words.iter().flat_map(|w| w.to_le_bytes()).collect(),
            ));
        }
        Target::Glsl => {
            let options = naga::back::glsl::Options {
                version: naga::back::glsl::Version::Desktop(450),
                writer_flags: naga::back::glsl::WriterFlags::empty(),
                ..Default::default()
            };
            let pipeline = naga::back::glsl::PipelineOptions {
                shader_stage: stage,
                entry_point: entry,
                multiview: None,
            };
            let mut out = String::new();
            naga::back::glsl::Writer::new(
                &mut out,
                &t.module,
                &t.info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write())
            .map_err(|e| fail(e.to_string()))?;
            splice_after_version(header, &out)
        }
        Target::Hlsl => {
            let options = naga::back::hlsl::Options::default();
            let pipeline = naga::back::hlsl::PipelineOptions {
                entry_point: Some((stage, entry)),
            };
            let mut out = String::new();
            naga::back::hlsl::Writer::new(&mut out, &options, &pipeline)
                .write(&t.module, &t.info, None)
                .map_err(|e| fail(e.to_string()))?;
            format!("{header}{out}")
        }
        Target::Msl => {
            let options = naga::back::msl::Options {
                lang_version: (2, 1),
                ..Default::default()
            };
            let pipeline = naga::back::msl::PipelineOptions {
                entry_point: Some((stage, entry)),
                ..Default::default()
            };
            let (out, _) = naga::back::msl::write_string(&t.module, &t.info, &options, &pipeline)
                .map_err(|e| fail(e.to_string()))?;
            format!("{header}{out}")
        }
    };
    Ok(Written::Text(text))
}

/// GLSL must start with `#version`: the header goes right after it.
fn splice_after_version(header: &str, glsl: &str) -> String {
    match glsl.split_once('\n') {
        Some((version, rest)) => format!("{version}\n{header}{rest}"),
        None => format!("{glsl}\n{header}"),
    }
}
