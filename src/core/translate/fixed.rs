//! The GPU backend's own small shaders, built as naga IR with the same
//! builder as the translations: the full-screen triangle every draw's
//! vertex stage runs, and the compute pass that fills a draw's inputs.
//! Building them directly, not parsing WGSL text, keeps naga's WGSL parser
//! out of the binary (about 170 KB of it). Each function's comment gives
//! the WGSL it builds; a test reads that WGSL with naga's parser and checks
//! both modules write back the same WGSL.

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
    let u32_ty = ty(&mut m, None, TypeInner::Scalar(Scalar::U32));
    let vec4 = vec(&mut m, VectorSize::Quad, Scalar::F32);
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
    entry(&mut m, fb, ShaderStage::Vertex, [0; 3]);
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
        assert_eq!(wgsl.len(), 2, "{wgsl:?}");
        for (built, text) in [full_screen_triangle(), inputs_fill()].iter().zip(&wgsl) {
            let parsed = naga::front::wgsl::parse_str(text).expect("the comment's WGSL parses");
            assert_eq!(written(built), written(&parsed), "{text}");
        }
    }
}
