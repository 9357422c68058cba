//! The module-level parts of a translation: types, the constant block, the
//! register variables, the shader's own `def`/`defi`/`defb` constants, and
//! the two entry points that wrap the lowered program.
//!
//! D3D9's registers are global to the program — subroutines read and write
//! the caller's `r#`, `aL` and `p0` — so every register is a private global
//! variable, zero at the start of each invocation (the emulator zeroes them
//! too). `v#` is one private array so that `v[aL + n]` can index it.

use super::builder::{Expr, Fb};
use super::interface::{self, Interface};
use super::TranslateError;
use crate::core::ir::Shader;
use crate::core::isa::{RegFile, SamplerType};
use naga::{
    AddressSpace, ArraySize, Binding, BuiltIn, Constant, Expression, GlobalVariable, Handle,
    ImageClass, ImageDimension, Interpolation, Literal, Module, ResourceBinding, Sampling, Scalar,
    ScalarKind, Span, Statement, StructMember, Type, TypeInner, VectorSize,
};
use std::collections::BTreeMap;

/// Type handles the lowering uses.
pub(super) struct Types {
    pub f32: Handle<Type>,
    pub i32: Handle<Type>,
    pub bool: Handle<Type>,
    pub vec2: Handle<Type>,
    pub vec3: Handle<Type>,
    pub vec4: Handle<Type>,
    pub ivec4: Handle<Type>,
    pub uvec4: Handle<Type>,
    pub bvec4: Handle<Type>,
}

/// A sampler's texture and sampler variables.
#[derive(Clone, Copy)]
pub(super) struct Tex {
    pub ty: SamplerType,
    pub image: Handle<GlobalVariable>,
    pub sampler: Handle<GlobalVariable>,
}

/// Everything module-level the function bodies refer to.
pub(super) struct Ctx {
    pub t: Types,
    pub consts: Handle<GlobalVariable>,
    pub temps: BTreeMap<u32, Handle<GlobalVariable>>,
    pub inputs: Handle<GlobalVariable>,
    pub pos: Handle<GlobalVariable>,
    pub face: Handle<GlobalVariable>,
    pub outputs: [Handle<GlobalVariable>; 4],
    pub depth: Handle<GlobalVariable>,
    pub al: Handle<GlobalVariable>,
    pub p0: Handle<GlobalVariable>,
    pub killed: Handle<GlobalVariable>,
    pub textures: BTreeMap<u32, Tex>,
    /// `ps30_border`, when a 2D or volume sampler may need it.
    pub border: Option<Handle<naga::Function>>,
    /// The emulation code each sampler carries (set by `core::translate`).
    pub spec: super::Specialisation,
    pub float_defs: BTreeMap<u32, Handle<Constant>>,
    /// The `def` registers with a denormal component: the only definitions
    /// the `hardware` rules must flush where they are read.
    pub float_defs_subnormal: std::collections::BTreeSet<u32>,
    /// Definitions holding ±∞ or NaN, as bits: read as a bitcast.
    pub float_def_bits: BTreeMap<u32, [u32; 4]>,
    pub int_defs: BTreeMap<u32, Handle<Constant>>,
    pub bool_defs: BTreeMap<u32, bool>,
    /// The shader's profile, which numbers its input slots.
    pub profile: crate::core::profile::Profile,
    /// A vertex shader's own registers (`vertex.rs`); `None` for pixel shaders.
    pub vertex: Option<VertexVars>,
}

/// `c#` registers in a vertex shader's constant block (c0–c255).
pub const VERTEX_FLOATS: u32 = 256;

/// Output rows of a vertex shader (`emu::vertex::output_row`'s).
pub const VERTEX_ROWS: u32 = crate::core::emu::vertex::OUTPUT_ROWS as u32;

/// The registers only vertex shaders have.
pub struct VertexVars {
    /// `a0`, four integers.
    pub a0: Handle<GlobalVariable>,
    /// The output rows, plus one that catches dropped writes.
    pub o: Handle<GlobalVariable>,
}

fn vertex_vars(m: &mut Module, t: &Types) -> VertexVars {
    let rows = array(m, t.vec4, VERTEX_ROWS + 1, 16);
    VertexVars {
        a0: global(m, "a0", AddressSpace::Private, None, t.ivec4),
        o: global(m, "o", AddressSpace::Private, None, rows),
    }
}

pub(super) fn ty(m: &mut Module, name: Option<&str>, inner: TypeInner) -> Handle<Type> {
    m.types.insert(
        Type {
            name: name.map(str::to_string),
            inner,
        },
        Span::UNDEFINED,
    )
}

fn vector(m: &mut Module, size: VectorSize, scalar: Scalar) -> Handle<Type> {
    ty(m, None, TypeInner::Vector { size, scalar })
}

pub(super) fn array(m: &mut Module, base: Handle<Type>, len: u32, stride: u32) -> Handle<Type> {
    ty(
        m,
        None,
        TypeInner::Array {
            base,
            size: ArraySize::Constant(std::num::NonZeroU32::new(len).expect("non-zero length")),
            stride,
        },
    )
}

fn member(name: &str, ty: Handle<Type>, offset: u32) -> StructMember {
    StructMember {
        name: Some(name.into()),
        ty,
        binding: None,
        offset,
    }
}

pub(super) fn global(
    m: &mut Module,
    name: &str,
    space: AddressSpace,
    binding: Option<u32>,
    ty: Handle<Type>,
) -> Handle<GlobalVariable> {
    m.global_variables.append(
        GlobalVariable {
            name: Some(name.into()),
            space,
            binding: binding.map(|b| ResourceBinding {
                group: 0,
                binding: b,
            }),
            ty,
            init: None,
            memory_decorations: Default::default(),
        },
        Span::UNDEFINED,
    )
}

fn types(m: &mut Module) -> Types {
    let f = Scalar::F32;
    Types {
        f32: ty(m, None, TypeInner::Scalar(f)),
        i32: ty(m, None, TypeInner::Scalar(Scalar::I32)),
        bool: ty(m, None, TypeInner::Scalar(Scalar::BOOL)),
        vec2: vector(m, VectorSize::Bi, f),
        vec3: vector(m, VectorSize::Tri, f),
        vec4: vector(m, VectorSize::Quad, f),
        ivec4: vector(m, VectorSize::Quad, Scalar::I32),
        uvec4: vector(m, VectorSize::Quad, Scalar::U32),
        bvec4: vector(m, VectorSize::Quad, Scalar::BOOL),
    }
}

/// The uniform block's type (layout in [`interface`]; a vertex shader's
/// block holds `floats` = 256 `c#`, and the members after it move up).
fn constant_block(m: &mut Module, t: &Types, floats: u32) -> Handle<Type> {
    let sampler = ty(
        m,
        Some("Ps30Sampler"),
        TypeInner::Struct {
            members: vec![
                member("lod", t.vec4, 0),
                member("border", t.vec4, 16),
                member("mirror_once", t.uvec4, 32),
                member("border_mode", t.uvec4, 48),
            ],
            span: interface::SAMPLER_STATE_SIZE,
        },
    );
    let c = array(m, t.vec4, floats, 16);
    let i = array(m, t.ivec4, 16, 16);
    let b = array(m, t.uvec4, 16, 16);
    let s = array(m, sampler, 16, interface::SAMPLER_STATE_SIZE);
    let extra = (floats - 224) * 16;
    ty(
        m,
        Some("Ps30Constants"),
        TypeInner::Struct {
            members: vec![
                member("c", c, interface::FLOATS_OFFSET),
                member("i", i, interface::INTS_OFFSET + extra),
                member("b", b, interface::BOOLS_OFFSET + extra),
                member("s", s, interface::SAMPLERS_OFFSET + extra),
            ],
            span: interface::CONSTANTS_SIZE + extra,
        },
    )
}

/// A constant of `ty` composed of `literals` (one literal: a scalar).
fn constant(
    m: &mut Module,
    name: String,
    ty: Handle<Type>,
    literals: &[Literal],
) -> Handle<Constant> {
    let parts: Vec<_> = literals
        .iter()
        .map(|&l| {
            m.global_expressions
                .append(Expression::Literal(l), Span::UNDEFINED)
        })
        .collect();
    let init = if parts.len() == 1 {
        parts[0]
    } else {
        m.global_expressions.append(
            Expression::Compose {
                ty,
                components: parts,
            },
            Span::UNDEFINED,
        )
    };
    m.constants.append(
        Constant {
            name: Some(name),
            ty,
            init,
        },
        Span::UNDEFINED,
    )
}

impl Ctx {
    /// Declares every type, variable and constant the program needs.
    pub fn new(
        m: &mut Module,
        shader: &Shader,
        spec: &super::Specialisation,
    ) -> Result<Ctx, TranslateError> {
        let t = types(m);
        let is_vertex = shader.program().profile.stage() == crate::core::profile::Stage::Vertex;
        let block = constant_block(m, &t, if is_vertex { VERTEX_FLOATS } else { 224 });
        let consts = global(
            m,
            "ps30",
            AddressSpace::Uniform,
            Some(interface::CONSTANTS_BINDING),
            block,
        );
        let p = shader.program();
        let mut textures = BTreeMap::new();
        for d in &p.samplers {
            // A cube map bound as its faces is a 2D array of six layers.
            let faces = d.ty == SamplerType::Cube && spec.sampler(d.index).faces;
            let dim = match d.ty {
                SamplerType::Tex2d => ImageDimension::D2,
                SamplerType::Cube if faces => ImageDimension::D2,
                SamplerType::Cube => ImageDimension::Cube,
                SamplerType::Volume => ImageDimension::D3,
            };
            let image_ty = ty(
                m,
                None,
                TypeInner::Image {
                    dim,
                    arrayed: faces,
                    class: ImageClass::Sampled {
                        kind: ScalarKind::Float,
                        multi: false,
                    },
                },
            );
            let sampler_ty = ty(m, None, TypeInner::Sampler { comparison: false });
            let image = global(
                m,
                &format!("s{}_texture", d.index),
                AddressSpace::Handle,
                Some(interface::texture_binding(d.index)),
                image_ty,
            );
            let sampler = global(
                m,
                &format!("s{}_sampler", d.index),
                AddressSpace::Handle,
                Some(interface::sampler_binding(d.index)),
                sampler_ty,
            );
            textures.insert(
                d.index,
                Tex {
                    ty: d.ty,
                    image,
                    sampler,
                },
            );
        }
        let mut temps = BTreeMap::new();
        let mut used = std::collections::BTreeSet::new();
        for ins in shader.instructions() {
            let regs = ins
                .dst
                .iter()
                .map(|d| (d.reg, 1))
                .chain(ins.src.iter().enumerate().map(|(k, s)| {
                    let rows = ins.op.matrix_shape().filter(|_| k == 1);
                    (s.reg, rows.map_or(1, |(n, _)| n))
                }));
            for (reg, rows) in regs {
                if reg.file == RegFile::Temp {
                    used.extend(reg.index..reg.index + rows);
                }
            }
        }
        for r in used {
            let g = global(m, &format!("r{r}"), AddressSpace::Private, None, t.vec4);
            temps.insert(r, g);
        }
        let input_array = array(m, t.vec4, if is_vertex { 16 } else { 10 }, 16);
        let inputs = global(m, "v", AddressSpace::Private, None, input_array);
        let pos = global(m, "vPos", AddressSpace::Private, None, t.vec4);
        let face = global(m, "vFace", AddressSpace::Private, None, t.vec4);
        let outputs = std::array::from_fn(|k| {
            global(m, &format!("oC{k}"), AddressSpace::Private, None, t.vec4)
        });
        let depth = global(m, "oDepth", AddressSpace::Private, None, t.vec4);
        let al = global(m, "aL", AddressSpace::Private, None, t.i32);
        let p0 = global(m, "p0", AddressSpace::Private, None, t.bvec4);
        let killed = global(m, "killed", AddressSpace::Private, None, t.bool);

        let mut float_defs = BTreeMap::new();
        let mut float_def_bits = BTreeMap::new();
        let float_defs_subnormal = p
            .float_defs
            .iter()
            .filter(|d| d.value.iter().any(|v| v.is_subnormal()))
            .map(|d| d.index)
            .collect();
        for d in &p.float_defs {
            // ±∞ and NaN have no literal in the shading languages (naga
            // refuses them): such a definition is rebuilt from its bits
            // where it is read (`lower.rs`), so every pattern survives.
            if d.value.iter().any(|v| !v.is_finite()) {
                float_def_bits.insert(d.index, d.value.map(f32::to_bits));
                continue;
            }
            let lits = d.value.map(Literal::F32);
            let c = constant(m, format!("c{}", d.index), t.vec4, &lits);
            float_defs.insert(d.index, c);
        }
        let mut int_defs = BTreeMap::new();
        for d in &p.int_defs {
            let lits = d.value.map(Literal::I32);
            let c = constant(m, format!("i{}", d.index), t.ivec4, &lits);
            int_defs.insert(d.index, c);
        }
        let bool_defs = p.bool_defs.iter().map(|d| (d.index, d.value)).collect();
        Ok(Ctx {
            vertex: is_vertex.then(|| vertex_vars(m, &t)),
            t,
            float_defs_subnormal,
            consts,
            temps,
            inputs,
            pos,
            face,
            outputs,
            depth,
            al,
            p0,
            killed,
            textures,
            // Added by `core::translate` with `texture::add_border_function`.
            border: None,
            spec: spec.clone(),
            float_defs,
            float_def_bits,
            int_defs,
            bool_defs,
            profile: shader.program().profile,
        })
    }

    /// A pointer to a global variable.
    pub fn var(&self, fb: &mut Fb, g: Handle<GlobalVariable>) -> Expr {
        fb.add(Expression::GlobalVariable(g))
    }

    /// A pointer to member `member` of the constant block.
    pub fn block(&self, fb: &mut Fb, member: u32) -> Expr {
        let base = self.var(fb, self.consts);
        fb.index(base, member)
    }
}

/// Which entry point wraps the lowered program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// `main`: inputs from the vertex stage by `@location`, as an
    /// application binds the shader; texkill discards the pixel.
    Application,
    /// `ps30_draw`: inputs from a per-pixel texture array (one layer per
    /// declared `v#`, in register order), the texkill flag written to
    /// `@location(4)` instead of discarding — how `core/gpu` draws, so that
    /// inputs are bit-identical to the emulator's and killed pixels are
    /// reported as the emulator reports them.
    Draw,
    /// `ps30_geometry`: the GPU backend's draw of geometry. Inputs arrive
    /// from its vertex stage by `@location`, interpolated with perspective,
    /// or flat where `flat` says (four bits per slot, laid out by
    /// [`interface::geometry_locations`]); every covered pixel writes its
    /// flags (covered, killed) to `@location(4)` and its depth (`oDepth`, or
    /// the rasterised z) to `@location(5)`, so that the alpha test, the
    /// depth test and the output merger run on the CPU as for every draw of
    /// the GPU backend.
    Geometry {
        /// Flat-shaded components, bit `4·slot + c`.
        flat: u64,
        /// `Some` for a whole draw in one render pass
        /// ([`super::device_tests`]): texkill and a failed alpha test
        /// discard, the depth is written as the surface stores it, covered and killed pixels are
        /// counted per triangle, and `@location(4)` holds 1.0 (no depth at
        /// `@location(5)`).
        tests: Option<super::device_tests::DeviceTests>,
        /// `Some` for a fogged draw: the fog's depth or factor at
        /// [`interface::GEOMETRY_FOG_LOCATION`] (never with `tests`).
        fog: Option<interface::GeometryFog>,
        /// Every covered pixel appends its record to a storage buffer
        /// ([`super::records`]) instead of writing `@location(0..6)`; only
        /// the flags are written, at `@location(4)` (never with `tests`).
        records: bool,
    },
}

/// An output's location (no interpolation: it leaves the pipeline).
/// A geometry draw's output of flags (covered, killed; `u32`) at `offset`.
fn flags_member(m: &mut Module, offset: u32) -> StructMember {
    StructMember {
        name: Some("flags".into()),
        ty: ty(m, None, TypeInner::Scalar(Scalar::U32)),
        binding: Some(output(interface::GEOMETRY_FLAGS_LOCATION)),
        offset,
    }
}

fn output(location: u32) -> Binding {
    Binding::Location {
        location,
        interpolation: None,
        sampling: None,
        blend_src: None,
        per_primitive: false,
    }
}

pub(super) fn location(location: u32, centroid: bool, interpolate: bool) -> Binding {
    Binding::Location {
        location,
        interpolation: Some(if interpolate {
            Interpolation::Perspective
        } else {
            Interpolation::Flat
        }),
        // A flat input has no sampling point (naga refuses one).
        sampling: match (interpolate, centroid) {
            (false, _) => None,
            (true, true) => Some(Sampling::Centroid),
            (true, false) => Some(Sampling::Center),
        },
        blend_src: None,
        per_primitive: false,
    }
}

/// Adds the entry point: copies the stage's inputs into the register
/// variables, calls `ps_main`, and returns the outputs.
pub(super) fn entry_point(
    m: &mut Module,
    cx: &Ctx,
    iface: &Interface,
    main: Handle<naga::Function>,
    entry: Entry,
) {
    let t = &cx.t;
    let mut fb = Fb::new(match entry {
        Entry::Application => "main",
        Entry::Draw => "ps30_draw",
        Entry::Geometry { .. } => "ps30_geometry",
    });
    let pos_ty = t.vec4;
    let mut args = vec![
        (
            "position",
            pos_ty,
            Binding::BuiltIn(BuiltIn::Position { invariant: false }),
        ),
        (
            "front_facing",
            t.bool,
            Binding::BuiltIn(BuiltIn::FrontFacing),
        ),
    ];
    let mut names = vec!["position".to_string(), "front_facing".to_string()];
    if entry == Entry::Application {
        for i in &iface.inputs {
            args.push(("v", t.vec4, location(i.location, i.centroid, true)));
            names.push(format!("v{}", i.register));
        }
    }
    let fog = geometry_arguments(entry, iface, t.vec4, (&mut args, &mut names));
    let (tests, records) = match entry {
        Entry::Geometry { tests, records, .. } => (tests, records),
        _ => (None, false),
    };
    if tests.is_some() || records {
        let u32_ty = ty(m, None, TypeInner::Scalar(Scalar::U32));
        args.push((
            "primitive_index",
            u32_ty,
            Binding::BuiltIn(BuiltIn::PrimitiveIndex),
        ));
        names.push("primitive_index".into());
    }
    for ((name, ty, binding), name_of) in args.iter().zip(&names) {
        let name = if *name == "v" {
            name_of.clone()
        } else {
            name.to_string()
        };
        fb.f.arguments.push(naga::FunctionArgument {
            name: Some(name),
            ty: *ty,
            binding: Some(binding.clone()),
        });
    }
    let position = fb.add(Expression::FunctionArgument(0));
    let front = fb.add(Expression::FunctionArgument(1));
    // vPos: D3D9 pixel centres are integers (facts sheet §2), WebGPU's are
    // at +0.5.
    let half = fb.f32(0.5);
    let half2 = fb.splat(half, VectorSize::Bi);
    let xy = fb.add(Expression::Swizzle {
        size: VectorSize::Bi,
        vector: position,
        pattern: [
            naga::SwizzleComponent::X,
            naga::SwizzleComponent::Y,
            naga::SwizzleComponent::X,
            naga::SwizzleComponent::X,
        ],
    });
    let centre = fb.binary(naga::BinaryOperator::Subtract, xy, half2);
    let zero = fb.f32(0.0);
    let (cx0, cy0) = (fb.index(centre, 0), fb.index(centre, 1));
    let vpos = fb.add(Expression::Compose {
        ty: t.vec4,
        components: vec![cx0, cy0, zero, zero],
    });
    let p = cx.var(&mut fb, cx.pos);
    fb.store(p, vpos);
    let (one, minus) = (fb.f32(1.0), fb.f32(-1.0));
    let sign = fb.select(front, one, minus);
    let vface = fb.splat(sign, VectorSize::Quad);
    let p = cx.var(&mut fb, cx.face);
    fb.store(p, vface);

    match entry {
        Entry::Application => {
            for (k, i) in iface.inputs.iter().enumerate() {
                let value = fb.add(Expression::FunctionArgument(2 + k as u32));
                let value = entering(&mut fb, i, value);
                let v = cx.var(&mut fb, cx.inputs);
                let slot = fb.index(v, i.register);
                fb.store(slot, value);
            }
        }
        Entry::Draw => draw_inputs(m, cx, iface, &mut fb, centre),
        Entry::Geometry { flat, .. } => geometry_inputs(cx, iface, &mut fb, flat),
    }
    // The fog's d, taken before the shader runs (it changes neither).
    let fog = fog.map(|f| match f {
        interface::GeometryFog::Varying => {
            let at = args.iter().position(|(n, _, _)| *n == "fog").unwrap_or(0);
            let v = fb.add(Expression::FunctionArgument(at as u32));
            fb.index(v, 0)
        }
        interface::GeometryFog::Depth => fb.index(position, 2),
    });

    fb.push(Statement::Call {
        function: main,
        arguments: Vec::new(),
        result: None,
    });
    if let Some(t) = tests {
        let counts = super::device_tests::counts(m);
        let primitive = fb.add(Expression::FunctionArgument(args.len() as u32 - 1));
        let killed = iface.kills.then_some(cx.killed);
        // The alpha test reads oC0 and leaves a pixel without one alone.
        let oc0 = iface.outputs.contains(&0).then_some(cx.outputs[0]);
        let alpha = oc0.zip(t.alpha);
        super::device_tests::count_and_kill(&mut fb, counts, primitive, killed, alpha);
    }
    if records {
        let primitive = fb.add(Expression::FunctionArgument(args.len() as u32 - 1));
        append_record(m, cx, iface, &mut fb, [primitive, position, centre], fog);
    }

    let result = outputs(m, cx, iface, &mut fb, entry, (position, fog));
    fb.f.result = result.map(|ty| naga::FunctionResult { ty, binding: None });
    let function = fb.finish();
    m.entry_points.push(naga::EntryPoint {
        name: function.name.clone().unwrap_or_default(),
        stage: naga::ShaderStage::Fragment,
        early_depth_test: None,
        workgroup_size: [0; 3],
        workgroup_size_overrides: None,
        function,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
}

/// Appends the covered pixel's record ([`super::records`]): `at` holds
/// the triangle's index, the fragment's position and its pixel centre
/// (D3D9's, integers); `fog` the fog's d where the draw is fogged.
fn append_record(
    m: &mut Module,
    cx: &Ctx,
    iface: &Interface,
    fb: &mut Fb,
    at: [Expr; 3],
    fog: Option<Expr>,
) {
    let [primitive, position, centre] = at;
    let (flags, depth) = flags_and_depth(cx, iface, fb, position);
    let mut words = vec![primitive];
    for c in 0..2 {
        let v = fb.index(centre, c);
        words.push(fb.add(Expression::As {
            expr: v,
            kind: ScalarKind::Uint,
            convert: Some(4),
        }));
    }
    words.push(flags);
    words.push(super::records::bits(fb, depth));
    words.push(match fog {
        Some(d) => super::records::bits(fb, d),
        None => fb.u32(0),
    });
    for &k in &iface.outputs {
        let p = cx.var(fb, cx.outputs[k as usize]);
        let colour = fb.load(p);
        for c in 0..4 {
            let v = fb.index(colour, c);
            words.push(super::records::bits(fb, v));
        }
    }
    super::records::append(m, fb, &words);
}

/// An entry point's argument: its name (`v` for an input, named by
/// register), type and binding.
type Argument = (&'static str, Handle<Type>, Binding);

/// The arguments `Entry::Geometry` adds after position and facing: each
/// input at its smooth and flat locations ([`interface::geometry_locations`]),
/// then a fogged draw's interpolated fog value; returns the draw's fog.
fn geometry_arguments(
    entry: Entry,
    iface: &Interface,
    vec4: Handle<Type>,
    (args, names): (&mut Vec<Argument>, &mut Vec<String>),
) -> Option<interface::GeometryFog> {
    let Entry::Geometry { flat, fog, .. } = entry else {
        return None;
    };
    for (i, (slot, smooth, flat)) in iface
        .inputs
        .iter()
        .zip(interface::geometry_locations(&iface.inputs, flat))
    {
        if let Some(l) = smooth {
            args.push(("v", vec4, location(l, i.centroid, true)));
            names.push(format!("v{slot}"));
        }
        if let Some(l) = flat {
            args.push(("v", vec4, location(l, false, false)));
            names.push(format!("v{slot}_flat"));
        }
    }
    if fog == Some(interface::GeometryFog::Varying) {
        let l = interface::geometry_fog_location(&iface.inputs, flat);
        args.push(("fog", vec4, location(l, false, true)));
        names.push("fog".into());
    }
    fog
}

/// An input's value as the shader sees it: ps_2_x colours clamped to
/// [0, 1] (`core/pixel_inputs.rs`; the emulator clamps them where it fills
/// its input rows).
fn entering(fb: &mut Fb, input: &interface::Input, value: Expr) -> Expr {
    if input.clamped {
        fb.math(naga::MathFunction::Saturate, &[value])
    } else {
        value
    }
}

/// `Entry::Geometry`'s inputs: each `v#` from its interpolated location,
/// its flat components from its flat one (the arguments after position and
/// facing, in [`interface::geometry_locations`]'s order).
fn geometry_inputs(cx: &Ctx, iface: &Interface, fb: &mut Fb, flat: u64) {
    let mut arg = 2u32;
    for (i, (slot, smooth, flat_at)) in iface
        .inputs
        .iter()
        .zip(interface::geometry_locations(&iface.inputs, flat))
    {
        let mut take = |present: Option<u32>| {
            present.map(|_| {
                arg += 1;
                fb.add(Expression::FunctionArgument(arg - 1))
            })
        };
        let (smooth, flat_value) = (take(smooth), take(flat_at));
        let value = match (smooth, flat_value) {
            (Some(s), Some(f)) => {
                let bits = (flat >> (4 * slot)) & 0xf;
                let components = (0..4)
                    .map(|c| fb.index(if bits & (1 << c) != 0 { f } else { s }, c))
                    .collect();
                fb.add(Expression::Compose {
                    ty: cx.t.vec4,
                    components,
                })
            }
            (Some(v), None) | (None, Some(v)) => v,
            (None, None) => continue,
        };
        let value = entering(fb, i, value);
        let v = cx.var(fb, cx.inputs);
        let p = fb.index(v, i.register);
        fb.store(p, value);
    }
}

/// `Entry::Draw`'s inputs: `v#` = layer k of the input texture at this
/// pixel, k counting declared inputs in register order. Where the draw
/// gives each pixel's position ([`super::Specialisation::positions_given`])
/// and the shader reads `vPos`, `vPos` is the layer after them, which
/// holds `(x, y, 0, 0)`: the pixel's place in the render target, not its
/// place in the draw.
fn draw_inputs(m: &mut Module, cx: &Ctx, iface: &Interface, fb: &mut Fb, centre: Expr) {
    let positions = cx.spec.positions_given() && iface.position;
    if iface.inputs.is_empty() && !positions {
        return;
    }
    let image_ty = ty(
        m,
        None,
        TypeInner::Image {
            dim: ImageDimension::D2,
            arrayed: true,
            class: ImageClass::Sampled {
                kind: ScalarKind::Float,
                multi: false,
            },
        },
    );
    let texture = global(
        m,
        "ps30_inputs",
        AddressSpace::Handle,
        Some(interface::DRAW_INPUTS_BINDING),
        image_ty,
    );
    let pixel = fb.add(Expression::As {
        expr: centre,
        kind: ScalarKind::Sint,
        convert: Some(4),
    });
    let level = fb.i32(0);
    let load = |fb: &mut Fb, layer: usize| {
        let image = fb.add(Expression::GlobalVariable(texture));
        let layer = fb.i32(layer as i32);
        fb.add(Expression::ImageLoad {
            image,
            coordinate: pixel,
            array_index: Some(layer),
            sample: None,
            level: Some(level),
        })
    };
    for (k, i) in iface.inputs.iter().enumerate() {
        let value = load(fb, k);
        let value = entering(fb, i, value);
        let v = cx.var(fb, cx.inputs);
        let slot = fb.index(v, i.register);
        fb.store(slot, value);
    }
    if positions {
        let value = load(fb, iface.inputs.len());
        let p = cx.var(fb, cx.pos);
        fb.store(p, value);
    }
}

/// `Entry::Geometry`'s flags of a covered pixel (bit 0 covered, bit 1
/// killed by texkill) and its depth (`oDepth` as written, or the
/// rasterised z of `position`).
fn flags_and_depth(cx: &Ctx, iface: &Interface, fb: &mut Fb, position: Expr) -> (Expr, Expr) {
    let covered = fb.u32(1);
    let flags = match iface.kills {
        true => {
            let p = cx.var(fb, cx.killed);
            let killed = fb.load(p);
            let (yes, no) = (fb.u32(3), covered);
            fb.select(killed, yes, no)
        }
        false => covered,
    };
    let depth = match iface.depth {
        true => {
            let p = cx.var(fb, cx.depth);
            let d = fb.load(p);
            fb.index(d, 0)
        }
        false => fb.index(position, 2),
    };
    (flags, depth)
}

/// The entry point's result: a struct of the written outputs (and the
/// texkill flag or discard). Returns its type, if any output exists.
/// `at` is the fragment's position and, for a fogged draw of geometry, the
/// fog's d.
fn outputs(
    m: &mut Module,
    cx: &Ctx,
    iface: &Interface,
    fb: &mut Fb,
    entry: Entry,
    at: (Expr, Option<Expr>),
) -> Option<Handle<Type>> {
    let (position, fog) = at;
    let t = &cx.t;
    let mut members = Vec::new();
    let mut values = Vec::new();
    let mut offset = 0;
    let records = matches!(entry, Entry::Geometry { records: true, .. });
    for &k in iface.outputs.iter().filter(|_| !records) {
        members.push(StructMember {
            name: Some(format!("oC{k}")),
            ty: t.vec4,
            binding: Some(output(k)),
            offset,
        });
        offset += 16;
        let p = cx.var(fb, cx.outputs[k as usize]);
        values.push(fb.load(p));
    }
    if let Entry::Geometry {
        tests: Some(tests), ..
    } = entry
    {
        let odepth = iface.depth.then_some(cx.depth);
        offset = super::device_tests::outputs(
            fb,
            (tests, t.f32, odepth),
            position,
            (&mut members, &mut values),
            offset,
        );
    } else if records {
        // The flags keep the pass an attachment; the records hold the rest.
        members.push(flags_member(m, offset));
        offset += 4;
        values.push(fb.u32(1));
    } else if let Entry::Geometry { .. } = entry {
        members.push(flags_member(m, offset));
        let (flags, depth) = flags_and_depth(cx, iface, fb, position);
        values.push(flags);
        members.push(StructMember {
            name: Some("depth".into()),
            ty: t.f32,
            binding: Some(output(interface::GEOMETRY_DEPTH_LOCATION)),
            offset: offset + 4,
        });
        offset += 8;
        values.push(depth);
        if let Some(d) = fog {
            members.push(StructMember {
                name: Some("fog".into()),
                ty: t.f32,
                binding: Some(output(interface::GEOMETRY_FOG_LOCATION)),
                offset,
            });
            offset += 4;
            values.push(d);
        }
    } else if iface.depth {
        members.push(StructMember {
            name: Some("oDepth".into()),
            ty: t.f32,
            binding: Some(Binding::BuiltIn(BuiltIn::FragDepth)),
            offset,
        });
        offset += 4;
        let p = cx.var(fb, cx.depth);
        let d = fb.load(p);
        values.push(fb.index(d, 0));
    }
    if iface.kills && !matches!(entry, Entry::Geometry { .. }) {
        let p = cx.var(fb, cx.killed);
        let killed = fb.load(p);
        match entry {
            Entry::Application => fb.if_then(killed, |fb| fb.push(Statement::Kill)),
            Entry::Draw => {
                let u32_ty = ty(m, None, TypeInner::Scalar(Scalar::U32));
                members.push(StructMember {
                    name: Some("killed".into()),
                    ty: u32_ty,
                    binding: Some(output(interface::DRAW_KILLED_LOCATION)),
                    offset,
                });
                offset += 4;
                let (yes, no) = (fb.u32(1), fb.u32(0));
                values.push(fb.select(killed, yes, no));
            }
            Entry::Geometry { .. } => {}
        }
    }
    if members.is_empty() {
        return None;
    }
    let out_ty = ty(
        m,
        Some("Ps30Out"),
        TypeInner::Struct {
            members,
            span: offset.max(16).next_multiple_of(16),
        },
    );
    let value = fb.add(Expression::Compose {
        ty: out_ty,
        components: values,
    });
    fb.push(Statement::Return { value: Some(value) });
    Some(out_ty)
}
