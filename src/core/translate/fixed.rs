//! The GPU backend's own small shaders, built as naga IR with the same
//! builder as the translations: the full-screen triangle every draw's
//! vertex stage runs, and the compute pass that fills a draw's inputs.
//! Built directly, they cannot fail to parse at run time and cost no
//! parse. Each function's comment gives the WGSL it builds; a test reads
//! that WGSL with naga's parser and checks both modules write back the
//! same WGSL.

use super::builder::{Expr, Fb};
use super::module::{global, ty};
use naga::{
    AddressSpace, ArraySize, BinaryOperator, Binding, BuiltIn, Expression, Module, Scalar,
    ScalarKind, ShaderStage, Statement, StorageAccess, StorageFormat, StructMember, TypeInner,
    VectorSize,
};

/// The full-screen triangle, drawn with three vertices and no buffer:
/// (−1, −1), (3, −1), (−1, 3), counter-clockwise in WebGPU's normalised
/// coordinates (the pipeline's `front_face` makes it front- or back-facing
/// as the draw asks).
///
/// ```wgsl
/// @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
///     let x = f32(i32(i & 1u) * 4 - 1);
///     let y = f32(i32(i >> 1u) * 4 - 1);
///     return vec4<f32>(x, y, 0.0, 1.0);
/// }
/// ```
pub fn full_screen_triangle() -> Module {
    let mut m = Module::default();
    add_full_screen_triangle(&mut m);
    m
}

/// Adds [`full_screen_triangle`]'s entry point `vs` to `m`.
fn add_full_screen_triangle(m: &mut Module) {
    let u32_ty = ty(m, None, TypeInner::Scalar(Scalar::U32));
    let vec4 = vec(m, VectorSize::Quad, Scalar::F32);
    let mut fb = Fb::new("vs");
    fb.f.arguments.push(naga::FunctionArgument {
        name: Some("i".into()),
        ty: u32_ty,
        binding: Some(Binding::BuiltIn(BuiltIn::VertexIndex)),
    });
    let i = fb.add(Expression::FunctionArgument(0));
    let one = fb.u32(1);
    let low = fb.binary(BinaryOperator::And, i, one);
    let one = fb.u32(1);
    let high = fb.binary(BinaryOperator::ShiftRight, i, one);
    let x = corner(&mut fb, low);
    fb.f.named_expressions.insert(x, "x".into());
    let y = corner(&mut fb, high);
    fb.f.named_expressions.insert(y, "y".into());
    let (zero, one) = (fb.f32(0.0), fb.f32(1.0));
    let position = fb.add(Expression::Compose {
        ty: vec4,
        components: vec![x, y, zero, one],
    });
    fb.push(Statement::Return {
        value: Some(position),
    });
    fb.f.result = Some(naga::FunctionResult {
        ty: vec4,
        binding: Some(Binding::BuiltIn(BuiltIn::Position { invariant: false })),
    });
    entry(m, fb, ShaderStage::Vertex, [0; 3]);
}

/// The pass that draws stored depths into a depth surface: the full-screen
/// triangle, and each pixel's depth read from a texture of the same size:
///
/// ```wgsl
/// @group(0) @binding(0) var stored: texture_2d<f32>;
/// struct Out { @builtin(frag_depth) depth: f32 }
/// @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
///     let x = f32(i32(i & 1u) * 4 - 1);
///     let y = f32(i32(i >> 1u) * 4 - 1);
///     return vec4<f32>(x, y, 0.0, 1.0);
/// }
/// @fragment fn fs(@builtin(position) p: vec4<f32>) -> Out {
///     return Out(textureLoad(stored, vec2<i32>(p.xy), 0).x);
/// }
/// ```
pub fn depth_load() -> Module {
    let mut m = Module::default();
    let image_ty = ty(
        &mut m,
        None,
        TypeInner::Image {
            dim: naga::ImageDimension::D2,
            arrayed: false,
            class: naga::ImageClass::Sampled {
                kind: ScalarKind::Float,
                multi: false,
            },
        },
    );
    let stored = global(&mut m, "stored", AddressSpace::Handle, Some(0), image_ty);
    let f32_ty = ty(&mut m, None, TypeInner::Scalar(Scalar::F32));
    let members = vec![StructMember {
        name: Some("depth".into()),
        ty: f32_ty,
        binding: Some(Binding::BuiltIn(BuiltIn::FragDepth)),
        offset: 0,
    }];
    let out_ty = ty(&mut m, Some("Out"), TypeInner::Struct { members, span: 4 });
    add_full_screen_triangle(&mut m);
    let vec4 = vec(&mut m, VectorSize::Quad, Scalar::F32);
    let mut fb = Fb::new("fs");
    fb.f.arguments.push(naga::FunctionArgument {
        name: Some("p".into()),
        ty: vec4,
        binding: Some(Binding::BuiltIn(BuiltIn::Position { invariant: false })),
    });
    let p = fb.add(Expression::FunctionArgument(0));
    let xy = fb.add(Expression::Swizzle {
        size: VectorSize::Bi,
        vector: p,
        pattern: [
            naga::SwizzleComponent::X,
            naga::SwizzleComponent::Y,
            naga::SwizzleComponent::X,
            naga::SwizzleComponent::X,
        ],
    });
    let coordinate = cast(&mut fb, xy, ScalarKind::Sint);
    let image = fb.add(Expression::GlobalVariable(stored));
    let level = fb.i32(0);
    let texel = fb.add(Expression::ImageLoad {
        image,
        coordinate,
        array_index: None,
        sample: None,
        level: Some(level),
    });
    let depth = fb.index(texel, 0);
    let out = fb.add(Expression::Compose {
        ty: out_ty,
        components: vec![depth],
    });
    fb.push(Statement::Return { value: Some(out) });
    fb.f.result = Some(naga::FunctionResult {
        ty: out_ty,
        binding: None,
    });
    entry(&mut m, fb, ShaderStage::Fragment, [0; 3]);
    m
}

/// `f32(i32(bit) * 4 - 1)`: −1 or 3, the triangle's corner on one axis.
fn corner(fb: &mut Fb, bit: Expr) -> Expr {
    let signed = cast(fb, bit, ScalarKind::Sint);
    let four = fb.i32(4);
    let scaled = fb.binary(BinaryOperator::Multiply, signed, four);
    let one = fb.i32(1);
    let shifted = fb.binary(BinaryOperator::Subtract, scaled, one);
    cast(fb, shifted, ScalarKind::Float)
}

fn cast(fb: &mut Fb, expr: Expr, kind: ScalarKind) -> Expr {
    fb.add(Expression::As {
        expr,
        kind,
        convert: Some(4),
    })
}

/// The inputs' fill: each pixel's inputs as a column term plus a row term
/// (`core/gpu/inputs.rs` says why), one layer per input register:
///
/// ```wgsl
/// struct Size { w: u32, h: u32, layers: u32, unused: u32 }
/// @group(0) @binding(0) var<uniform> size: Size;
/// @group(0) @binding(1) var<storage, read> columns: array<vec4<f32>>;
/// @group(0) @binding(2) var<storage, read> rows: array<vec4<f32>>;
/// @group(0) @binding(3) var inputs: texture_storage_2d_array<rgba32float, write>;
///
/// @compute @workgroup_size(16, 16, 1)
/// fn fill(@builtin(global_invocation_id) id: vec3<u32>) {
///     let w = size.w;
///     let h = size.h;
///     if (id.x >= w) | (id.y >= h) {
///         return;
///     }
///     let v = columns[id.z * w + id.x] + rows[id.z * h + id.y];
///     textureStore(inputs, vec2<u32>(id.x, id.y), id.z, v);
/// }
/// ```
pub fn inputs_fill() -> Module {
    let mut m = Module::default();
    let u32_ty = ty(&mut m, None, TypeInner::Scalar(Scalar::U32));
    let members = ["w", "h", "layers", "unused"]
        .iter()
        .enumerate()
        .map(|(k, name)| StructMember {
            name: Some((*name).into()),
            ty: u32_ty,
            binding: None,
            offset: 4 * k as u32,
        })
        .collect();
    let size_ty = ty(
        &mut m,
        Some("Size"),
        TypeInner::Struct { members, span: 16 },
    );
    let vec4 = vec(&mut m, VectorSize::Quad, Scalar::F32);
    let vec3u = vec(&mut m, VectorSize::Tri, Scalar::U32);
    let vec2u = vec(&mut m, VectorSize::Bi, Scalar::U32);
    let rows_ty = ty(
        &mut m,
        None,
        TypeInner::Array {
            base: vec4,
            size: ArraySize::Dynamic,
            stride: 16,
        },
    );
    let image_ty = ty(
        &mut m,
        None,
        TypeInner::Image {
            dim: naga::ImageDimension::D2,
            arrayed: true,
            class: naga::ImageClass::Storage {
                format: StorageFormat::Rgba32Float,
                access: StorageAccess::STORE,
            },
        },
    );
    let read = AddressSpace::Storage {
        access: StorageAccess::LOAD,
    };
    let size = global(&mut m, "size", AddressSpace::Uniform, Some(0), size_ty);
    let columns = global(&mut m, "columns", read, Some(1), rows_ty);
    let rows = global(&mut m, "rows", read, Some(2), rows_ty);
    let inputs = global(&mut m, "inputs", AddressSpace::Handle, Some(3), image_ty);

    let mut fb = Fb::new("fill");
    fb.f.arguments.push(naga::FunctionArgument {
        name: Some("id".into()),
        ty: vec3u,
        binding: Some(Binding::BuiltIn(BuiltIn::GlobalInvocationId)),
    });
    let id = fb.add(Expression::FunctionArgument(0));
    let size_of = |fb: &mut Fb, member: u32| {
        let block = fb.add(Expression::GlobalVariable(size));
        let field = fb.index(block, member);
        fb.load(field)
    };
    let (x, y, z) = (fb.index(id, 0), fb.index(id, 1), fb.index(id, 2));
    let (w, h) = (size_of(&mut fb, 0), size_of(&mut fb, 1));
    fb.f.named_expressions.insert(w, "w".into());
    fb.f.named_expressions.insert(h, "h".into());
    let outside_x = fb.binary(BinaryOperator::GreaterEqual, x, w);
    let outside_y = fb.binary(BinaryOperator::GreaterEqual, y, h);
    let outside = fb.binary(BinaryOperator::InclusiveOr, outside_x, outside_y);
    fb.if_then(outside, |fb| fb.push(Statement::Return { value: None }));
    let term = |fb: &mut Fb, array, extent, along| {
        let first = fb.binary(BinaryOperator::Multiply, z, extent);
        let index = fb.binary(BinaryOperator::Add, first, along);
        let base = fb.add(Expression::GlobalVariable(array));
        let element = fb.add(Expression::Access { base, index });
        fb.load(element)
    };
    let column = term(&mut fb, columns, w, x);
    let row = term(&mut fb, rows, h, y);
    let value = fb.binary(BinaryOperator::Add, column, row);
    fb.f.named_expressions.insert(value, "v".into());
    let coordinate = fb.add(Expression::Compose {
        ty: vec2u,
        components: vec![x, y],
    });
    let image = fb.add(Expression::GlobalVariable(inputs));
    fb.push(Statement::ImageStore {
        image,
        coordinate,
        array_index: Some(z),
        value,
    });
    fb.push(Statement::Return { value: None });
    entry(&mut m, fb, ShaderStage::Compute, [16, 16, 1]);
    m
}

/// What the vertex stage of a draw of geometry is made of (the caller
/// derives each part: `core/gpu/geometry.rs`).
pub struct GeometryStage<'a> {
    /// Each pixel-shader input: its register and its smooth and flat
    /// locations ([`super::interface::geometry_locations`]).
    pub locations: &'a [(u32, Option<u32>, Option<u32>)],
    /// The register each vertex attribute after the position carries
    /// (attribute k + 1 holds `slots[k]`).
    pub slots: &'a [u32],
    /// For pre-transformed positions, 2/W and 2/H of the target: the
    /// position is screen x, y, z and 1/w, turned back into clip space.
    pub screen: Option<(f32, f32)>,
    /// The half-pixel move, in clip units per w: x += w·dx, y −= w·dy.
    pub offset: (f32, f32),
    /// The user clip planes, each dotted with the clip-space position.
    pub clip_planes: &'a [[f32; 4]],
    /// For a fog the device interpolates, its location: the attribute
    /// after the slots' is handed on there with perspective.
    pub fog: Option<u32>,
}

/// The vertex stage of a draw of geometry. For a 128×64 target of
/// pre-transformed positions, one smooth input `v0` from attribute 1, one
/// flat input `v1` nobody writes and one clip plane, it is:
///
/// ```wgsl
/// enable clip_distances;
/// struct Out {
///     @builtin(position) position: vec4<f32>,
///     @location(0) @interpolate(perspective, center) v0: vec4<f32>,
///     @location(1) @interpolate(flat) v1_flat: vec4<f32>,
///     @builtin(clip_distances) clip: array<f32, 1>,
/// }
/// @vertex fn vs(@location(0) p: vec4<f32>, @location(1) a0: vec4<f32>) -> Out {
///     var o: Out;
///     let w = 1.0 / p.w;
///     let c = vec4<f32>((p.x * 0.015625 - 1.0) * w, (1.0 - p.y * 0.03125) * w, p.z * w, w);
///     o.position = vec4<f32>(c.x + c.w * 0.0078125, c.y - c.w * 0.015625, c.z, c.w);
///     o.clip[0] = dot(vec4<f32>(1.0, 0.0, 0.0, 0.5), c);
///     o.v0 = a0;
///     o.v1_flat = vec4<f32>(0.0);
///     return o;
/// }
/// ```
pub fn geometry_vertex(stage: &GeometryStage) -> Module {
    let mut m = Module::default();
    let f32_ty = ty(&mut m, None, TypeInner::Scalar(Scalar::F32));
    let vec4 = vec(&mut m, VectorSize::Quad, Scalar::F32);
    let mut members = vec![StructMember {
        name: Some("position".into()),
        ty: vec4,
        binding: Some(Binding::BuiltIn(BuiltIn::Position { invariant: false })),
        offset: 0,
    }];
    // The members' indices, as (register, smooth, flat).
    let mut outputs = Vec::new();
    for &(register, smooth, flat) in stage.locations {
        let mut member = |name: String, location: u32, interpolate: bool| {
            members.push(StructMember {
                name: Some(name),
                ty: vec4,
                binding: Some(super::module::location(location, false, interpolate)),
                offset: 16 * members.len() as u32,
            });
            members.len() as u32 - 1
        };
        let smooth = smooth.map(|l| member(format!("v{register}"), l, true));
        let flat = flat.map(|l| member(format!("v{register}_flat"), l, false));
        outputs.push((register, smooth, flat));
    }
    let fog = stage.fog.map(|l| {
        members.push(StructMember {
            name: Some("fog".into()),
            ty: vec4,
            binding: Some(super::module::location(l, false, true)),
            offset: 16 * members.len() as u32,
        });
        members.len() as u32 - 1
    });
    let planes = stage.clip_planes.len() as u32;
    let clip = (planes > 0).then(|| {
        let array = super::module::array(&mut m, f32_ty, planes, 4);
        members.push(StructMember {
            name: Some("clip".into()),
            ty: array,
            binding: Some(Binding::BuiltIn(BuiltIn::ClipDistances)),
            offset: 16 * members.len() as u32,
        });
        members.len() as u32 - 1
    });
    let span = members.last().map_or(0, |last| match clip {
        Some(_) => last.offset + 4 * planes,
        None => last.offset + 16,
    });
    let out_ty = ty(&mut m, Some("Out"), TypeInner::Struct { members, span });

    let mut fb = Fb::new("vs");
    let attribute = |name: String, location: u32| naga::FunctionArgument {
        name: Some(name),
        ty: vec4,
        binding: Some(Binding::Location {
            location,
            interpolation: None,
            sampling: None,
            blend_src: None,
            per_primitive: false,
        }),
    };
    fb.f.arguments.push(attribute("p".into(), 0));
    let attributes = stage.slots.len() as u32 + u32::from(fog.is_some());
    for k in 0..attributes {
        fb.f.arguments.push(attribute(format!("a{k}"), k + 1));
    }
    let o = fb.local("o", out_ty);
    let p = fb.add(Expression::FunctionArgument(0));
    let c = match stage.screen {
        Some(scale) => clip_space(&mut fb, vec4, p, scale),
        None => p,
    };
    let (cx, cy, cz, cw) = (
        fb.index(c, 0),
        fb.index(c, 1),
        fb.index(c, 2),
        fb.index(c, 3),
    );
    let moved = |fb: &mut Fb, op, along, by: f32| {
        let by = fb.f32(by);
        let step = fb.binary(BinaryOperator::Multiply, cw, by);
        fb.binary(op, along, step)
    };
    let x = moved(&mut fb, BinaryOperator::Add, cx, stage.offset.0);
    let y = moved(&mut fb, BinaryOperator::Subtract, cy, stage.offset.1);
    let position = fb.add(Expression::Compose {
        ty: vec4,
        components: vec![x, y, cz, cw],
    });
    let field = fb.index(o, 0);
    fb.store(field, position);
    if let Some(member) = clip {
        for (i, plane) in stage.clip_planes.iter().enumerate() {
            let components = plane.iter().map(|&v| fb.f32(v)).collect();
            let plane = fb.add(Expression::Compose {
                ty: vec4,
                components,
            });
            let distance = fb.math(naga::MathFunction::Dot, &[plane, c]);
            let array = fb.index(o, member);
            let element = fb.index(array, i as u32);
            fb.store(element, distance);
        }
    }
    for &(register, smooth, flat) in &outputs {
        for member in [smooth, flat].into_iter().flatten() {
            let value = match stage.slots.iter().position(|&s| s == register) {
                Some(k) => fb.add(Expression::FunctionArgument(k as u32 + 1)),
                None => {
                    let zero = fb.f32(0.0);
                    fb.splat(zero, VectorSize::Quad)
                }
            };
            let field = fb.index(o, member);
            fb.store(field, value);
        }
    }
    if let Some(member) = fog {
        let value = fb.add(Expression::FunctionArgument(attributes));
        let field = fb.index(o, member);
        fb.store(field, value);
    }
    let value = fb.load(o);
    fb.push(Statement::Return { value: Some(value) });
    fb.f.result = Some(naga::FunctionResult {
        ty: out_ty,
        binding: None,
    });
    entry(&mut m, fb, ShaderStage::Vertex, [0; 3]);
    m
}

/// A pre-transformed position (screen x, y, z and 1/w) back in clip space
/// against a viewport of the whole target with depth 0 to 1:
/// `w = 1/p.w`, `((p.x·sx − 1)·w, (1 − p.y·sy)·w, p.z·w, w)`.
fn clip_space(fb: &mut Fb, vec4: naga::Handle<naga::Type>, p: Expr, (sx, sy): (f32, f32)) -> Expr {
    let (px, py, pz, pw) = (
        fb.index(p, 0),
        fb.index(p, 1),
        fb.index(p, 2),
        fb.index(p, 3),
    );
    let one = fb.f32(1.0);
    let w = fb.binary(BinaryOperator::Divide, one, pw);
    fb.f.named_expressions.insert(w, "w".into());
    let sx = fb.f32(sx);
    let x = fb.binary(BinaryOperator::Multiply, px, sx);
    let one = fb.f32(1.0);
    let x = fb.binary(BinaryOperator::Subtract, x, one);
    let x = fb.binary(BinaryOperator::Multiply, x, w);
    let one = fb.f32(1.0);
    let sy = fb.f32(sy);
    let y = fb.binary(BinaryOperator::Multiply, py, sy);
    let y = fb.binary(BinaryOperator::Subtract, one, y);
    let y = fb.binary(BinaryOperator::Multiply, y, w);
    let z = fb.binary(BinaryOperator::Multiply, pz, w);
    let c = fb.add(Expression::Compose {
        ty: vec4,
        components: vec![x, y, z, w],
    });
    fb.f.named_expressions.insert(c, "c".into());
    c
}

fn vec(m: &mut Module, size: VectorSize, scalar: Scalar) -> naga::Handle<naga::Type> {
    ty(m, None, TypeInner::Vector { size, scalar })
}

/// Appends `fb`'s function as the module's entry point.
fn entry(m: &mut Module, fb: Fb, stage: ShaderStage, workgroup_size: [u32; 3]) {
    let function = fb.finish();
    m.entry_points.push(naga::EntryPoint {
        name: function.name.clone().unwrap_or_default(),
        stage,
        early_depth_test: None,
        workgroup_size,
        workgroup_size_overrides: None,
        function,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The WGSL blocks of this file's comments, in order.
    fn documented_wgsl() -> Vec<String> {
        let mut blocks = Vec::new();
        let mut current: Option<String> = None;
        for line in include_str!("fixed.rs").lines() {
            let Some(text) = line.trim_start().strip_prefix("///") else {
                continue;
            };
            let text = text.strip_prefix(' ').unwrap_or(text);
            match (&mut current, text) {
                (None, "```wgsl") => current = Some(String::new()),
                (Some(_), "```") => blocks.extend(current.take()),
                (Some(block), _) => {
                    block.push_str(text);
                    block.push('\n');
                }
                (None, _) => {}
            }
        }
        blocks
    }

    fn written(module: &Module) -> String {
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(module)
        .expect("the module validates");
        let text =
            naga::back::wgsl::write_string(module, &info, naga::back::wgsl::WriterFlags::empty())
                .expect("WGSL is written");
        renumbered(&text)
    }

    /// `text` with the writer's names for unnamed values (`_e17`: the
    /// expression's index, which differs between the parser's arena and
    /// the builder's) replaced by their order of first appearance.
    fn renumbered(text: &str) -> String {
        let mut names: Vec<String> = Vec::new();
        let mut out = String::new();
        let mut rest = text;
        while let Some(at) = rest.find("_e") {
            out.push_str(&rest[..at]);
            let digits = rest[at + 2..]
                .find(|c: char| !c.is_ascii_digit())
                .unwrap_or(rest.len() - at - 2);
            let name = &rest[at..at + 2 + digits];
            let k = match names.iter().position(|n| n == name) {
                Some(k) => k,
                None => {
                    names.push(name.to_string());
                    names.len() - 1
                }
            };
            out.push_str(&format!("_v{k}"));
            rest = &rest[at + 2 + digits..];
        }
        out.push_str(rest);
        out
    }

    #[test]
    fn each_module_is_the_wgsl_its_comment_gives() {
        let wgsl = documented_wgsl();
        assert_eq!(wgsl.len(), 4, "{wgsl:?}");
        let geometry = geometry_vertex(&GeometryStage {
            locations: &[(0, Some(0), None), (1, None, Some(1))],
            slots: &[0],
            screen: Some((2.0 / 128.0, 2.0 / 64.0)),
            offset: (1.0 / 128.0, 1.0 / 64.0),
            clip_planes: &[[1.0, 0.0, 0.0, 0.5]],
            fog: None,
        });
        let built = [
            full_screen_triangle(),
            depth_load(),
            inputs_fill(),
            geometry,
        ];
        for (built, text) in built.iter().zip(&wgsl) {
            let parsed = naga::front::wgsl::parse_str(text).expect("the comment's WGSL parses");
            assert_eq!(written(built), written(&parsed), "{text}");
        }
    }
}
