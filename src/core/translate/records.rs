//! `Entry::Geometry` with fragment records: one device draw shades every
//! primitive of a draw whose output merger must run on the CPU (blending,
//! fog, pixel history), and each covered fragment appends what the
//! per-primitive read-back would have held for it — its triangle, pixel,
//! flags, depth, fog d and colours — to a storage buffer, so that the CPU
//! can put the fragments back in drawing order and merge them as before.
//!
//! * **Appending.** `ps30_record_count[0]` is an atomic counter; each
//!   fragment takes the next slot with `atomicAdd` and writes its
//!   [`stride`] words there if the slot is inside `ps30_records` (the
//!   caller sizes the buffer from the primitives' bounds and checks the
//!   count, so a slot outside it is an error there, never a silent loss).
//! * **Helpers.** Helper invocations make no stores or atomic writes
//!   (Vulkan 1.3, "Helper Invocations"), so only covered fragments append;
//!   helpers still run the shader, so derivatives are those of the
//!   per-primitive draw.
//! * **Exactness.** Every word is the bits of the value the per-primitive
//!   draw writes to its 32-bit attachments (floats bit-cast, not
//!   converted).

use super::builder::{Expr, Fb};
use naga::{
    AddressSpace, ArraySize, BinaryOperator, Expression, GlobalVariable, Handle, Module,
    ResourceBinding, Scalar, Span, Statement, StorageAccess, Type, TypeInner,
};

/// The bind group of the counter and the records.
pub const RECORDS_GROUP: u32 = 1;

/// The counter's binding in [`RECORDS_GROUP`]: an `array<atomic<u32>>`
/// whose first element counts the fragments.
pub const COUNTER_BINDING: u32 = 0;

/// The records' binding in [`RECORDS_GROUP`]: an `array<u32>`.
pub const RECORDS_BINDING: u32 = 1;

/// The words of a record before its colours: the triangle (the draw's
/// `primitive_index`), x, y, the flags (bit 0 covered, bit 1 killed), the
/// depth's bits (`oDepth`, or the rasterised z), and the fog d's bits (0
/// without fog).
pub const HEADER_WORDS: u32 = 6;

/// The words of one record of a shader writing `outputs` colours (`oC#`
/// in the interface's order, four words each).
pub fn stride(outputs: usize) -> u32 {
    HEADER_WORDS + 4 * outputs as u32
}

/// A `u32` array in storage at `binding` of [`RECORDS_GROUP`], of atomics
/// where `atomic`.
fn storage_array(m: &mut Module, name: &str, binding: u32, atomic: bool) -> Handle<GlobalVariable> {
    let mut ty = |inner| m.types.insert(Type { name: None, inner }, Span::UNDEFINED);
    let element = match atomic {
        true => ty(TypeInner::Atomic(Scalar::U32)),
        false => ty(TypeInner::Scalar(Scalar::U32)),
    };
    let array = ty(TypeInner::Array {
        base: element,
        size: ArraySize::Dynamic,
        stride: 4,
    });
    m.global_variables.append(
        GlobalVariable {
            name: Some(name.into()),
            space: AddressSpace::Storage {
                access: StorageAccess::LOAD | StorageAccess::STORE,
            },
            binding: Some(ResourceBinding {
                group: RECORDS_GROUP,
                binding,
            }),
            ty: array,
            init: None,
            memory_decorations: Default::default(),
        },
        Span::UNDEFINED,
    )
}

/// The bits of the f32 `value` as a u32.
pub(super) fn bits(fb: &mut Fb, value: Expr) -> Expr {
    fb.add(Expression::As {
        expr: value,
        kind: naga::ScalarKind::Uint,
        convert: None,
    })
}

/// Appends one record of `words` (u32 expressions, [`stride`] of them, in
/// the layout the module docs give): takes the next slot of the counter
/// and writes the words there where the slot fits in the records.
pub(super) fn append(m: &mut Module, fb: &mut Fb, words: &[Expr]) {
    let counter = storage_array(m, "ps30_record_count", COUNTER_BINDING, true);
    let records = storage_array(m, "ps30_records", RECORDS_BINDING, false);
    let u32_ty = m.types.insert(
        Type {
            name: None,
            inner: TypeInner::Scalar(Scalar::U32),
        },
        Span::UNDEFINED,
    );
    let base = fb.add(Expression::GlobalVariable(counter));
    let pointer = fb.index(base, 0);
    let one = fb.u32(1);
    let slot = fb.atomic_result(u32_ty);
    fb.push(Statement::Atomic {
        pointer,
        fun: naga::AtomicFunction::Add,
        value: one,
        result: Some(slot),
    });
    let array = fb.add(Expression::GlobalVariable(records));
    let length = fb.add(Expression::ArrayLength(array));
    let stride = fb.u32(words.len() as u32);
    let capacity = fb.binary(BinaryOperator::Divide, length, stride);
    let fits = fb.binary(BinaryOperator::Less, slot, capacity);
    fb.if_then(fits, |fb| {
        let stride = fb.u32(words.len() as u32);
        let first = fb.binary(BinaryOperator::Multiply, slot, stride);
        for (k, &word) in words.iter().enumerate() {
            let offset = fb.u32(k as u32);
            let index = fb.binary(BinaryOperator::Add, first, offset);
            let base = fb.add(Expression::GlobalVariable(records));
            let pointer = fb.add(Expression::Access { base, index });
            fb.store(pointer, word);
        }
    });
}
