//! D3DDECLTYPE: how Direct3D 9 turns the bytes of a vertex buffer into the
//! four floats a vertex shader's `v#` register receives. A vertex
//! declaration names one type per element; this module knows each type's
//! size and its expansion, so that a raw vertex buffer (what a capture tool
//! dumps) reaches the vertex stage — the emulator's and the GPU backend's
//! alike — as the same floats.
//!
//! The rules are Microsoft's "D3DDECLTYPE enumeration" page (Direct3D 9),
//! type by type; every multi-byte value is little-endian, as the buffers of
//! the x86 machines Direct3D 9 runs on are:
//!
//! | type | bytes | the shader reads |
//! |---|---|---|
//! | FLOAT1–FLOAT4 | 4 per component | "expanded to (value, 0., 0., 1.)" and so on: missing y, z are 0, w is 1 |
//! | D3DCOLOR | 4 | "packed, unsigned bytes mapped to 0 to 1 range", "expanded to RGBA order": the DWORD 0xAARRGGBB (bytes B, G, R, A in memory) gives (R, G, B, A)/255 |
//! | UBYTE4 | 4 | the four unsigned bytes, unnormalised, in memory order |
//! | SHORT2, SHORT4 | 2 per component | the signed shorts, unnormalised: (a, b, 0, 1), (a, b, c, d) |
//! | UBYTE4N | 4 | "each byte normalized by dividing with 255.0f", in memory order, unswizzled (Wine's `fixed_function_decl_test` saw Windows draw the DWORD 0x00FFFF00 yellow as D3DCOLOR and cyan as UBYTE4N) |
//! | SHORT2N, SHORT4N | 2 per component | "first short/32767.0, second short/32767.0" (and 0, 1 for SHORT2N) |
//! | USHORT2N, USHORT4N | 2 per component | each unsigned short /65535.0 (and 0, 1 for USHORT2N) |
//! | UDEC3 | 4 | "unsigned, 10 10 10 format expanded to (value, value, value, 1)": x from bits 0–9, y 10–19, z 20–29, the top two bits ignored |
//! | DEC3N | 4 | "signed, 10 10 10 format normalized and expanded to (v[0]/511.0, v[1]/511.0, v[2]/511.0, 1)", each field two's complement |
//! | FLOAT16_2, FLOAT16_4 | 2 per component | IEEE 754 binary16 (s10e5) "expanded to (value, value, 0, 1)" / all four |
//!
//! The normalised signed types follow the Direct3D 9 page as written: the
//! most negative value is divided like any other, so SHORT2N's −32768
//! reads −32768/32767 = −1.0000305 and DEC3N's −512 reads −512/511 =
//! −1.0019569. Direct3D 10 changed the rule (its SNORM formats clamp the
//! most negative value to −1.0, "Data Conversion Rules"); a Direct3D 9
//! driver on Direct3D 10 hardware may therefore read −1.0 there. ps30
//! follows the Direct3D 9 document, the only statement of the Direct3D 9
//! rule, and says so where the difference can show (`docs/vertex-shaders.md`).
//! Every quotient is computed once and rounded to f32 (an exact integer
//! divided by an exact integer: the correctly rounded quotient).
//!
//! Raw FLOAT and FLOAT16 bits pass through unchanged, NaNs and infinities
//! included (a half's infinity is an f32 infinity, its NaN an f32 NaN, its
//! subnormals exact): the vertex stage receives what the buffer holds.

use half::f16;

/// One D3DDECLTYPE, by its number in d3d9types.h.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeclType {
    /// D3DDECLTYPE_FLOAT1 (0).
    Float1,
    /// D3DDECLTYPE_FLOAT2 (1).
    Float2,
    /// D3DDECLTYPE_FLOAT3 (2).
    Float3,
    /// D3DDECLTYPE_FLOAT4 (3).
    Float4,
    /// D3DDECLTYPE_D3DCOLOR (4).
    D3dColor,
    /// D3DDECLTYPE_UBYTE4 (5).
    Ubyte4,
    /// D3DDECLTYPE_SHORT2 (6).
    Short2,
    /// D3DDECLTYPE_SHORT4 (7).
    Short4,
    /// D3DDECLTYPE_UBYTE4N (8).
    Ubyte4N,
    /// D3DDECLTYPE_SHORT2N (9).
    Short2N,
    /// D3DDECLTYPE_SHORT4N (10).
    Short4N,
    /// D3DDECLTYPE_USHORT2N (11).
    Ushort2N,
    /// D3DDECLTYPE_USHORT4N (12).
    Ushort4N,
    /// D3DDECLTYPE_UDEC3 (13).
    Udec3,
    /// D3DDECLTYPE_DEC3N (14).
    Dec3N,
    /// D3DDECLTYPE_FLOAT16_2 (15).
    Float16x2,
    /// D3DDECLTYPE_FLOAT16_4 (16).
    Float16x4,
}

/// D3DDECLTYPE_UNUSED (17): the type of D3DDECL_END, which ends a declaration.
pub const UNUSED: u32 = 17;

/// Every type in d3d9types.h order (index = D3DDECLTYPE value), with its name
/// without the `D3DDECLTYPE_` prefix.
pub const ALL: [(&str, DeclType); 17] = [
    ("FLOAT1", DeclType::Float1),
    ("FLOAT2", DeclType::Float2),
    ("FLOAT3", DeclType::Float3),
    ("FLOAT4", DeclType::Float4),
    ("D3DCOLOR", DeclType::D3dColor),
    ("UBYTE4", DeclType::Ubyte4),
    ("SHORT2", DeclType::Short2),
    ("SHORT4", DeclType::Short4),
    ("UBYTE4N", DeclType::Ubyte4N),
    ("SHORT2N", DeclType::Short2N),
    ("SHORT4N", DeclType::Short4N),
    ("USHORT2N", DeclType::Ushort2N),
    ("USHORT4N", DeclType::Ushort4N),
    ("UDEC3", DeclType::Udec3),
    ("DEC3N", DeclType::Dec3N),
    ("FLOAT16_2", DeclType::Float16x2),
    ("FLOAT16_4", DeclType::Float16x4),
];

impl DeclType {
    /// The type named `name` (`FLOAT3` or `D3DDECLTYPE_FLOAT3`, any case);
    /// `None` for UNUSED and for names that are no type.
    pub fn from_name(name: &str) -> Option<Self> {
        let upper = name.to_ascii_uppercase();
        let short = upper.strip_prefix("D3DDECLTYPE_").unwrap_or(&upper);
        ALL.iter().find(|(n, _)| *n == short).map(|(_, t)| *t)
    }

    /// The type numbered `value` in d3d9types.h; `None` for UNUSED (17)
    /// and past it.
    pub fn from_value(value: u32) -> Option<Self> {
        ALL.get(value as usize).map(|(_, t)| *t)
    }

    /// The name without the prefix (`FLOAT16_2`).
    pub fn name(self) -> &'static str {
        ALL.iter().find(|(_, t)| *t == self).map_or("?", |(n, _)| n)
    }

    /// Bytes one element of this type occupies in a vertex.
    pub fn size(self) -> usize {
        use DeclType::*;
        match self {
            Float1 | D3dColor | Ubyte4 | Short2 | Ubyte4N | Short2N | Ushort2N | Udec3 | Dec3N
            | Float16x2 => 4,
            Float2 | Short4 | Short4N | Ushort4N | Float16x4 => 8,
            Float3 => 12,
            Float4 => 16,
        }
    }

    /// The four floats the shader reads from `bytes` (at least
    /// [`size`](Self::size) of them; the rest are not read).
    pub fn decode(self, bytes: &[u8]) -> [f32; 4] {
        use DeclType::*;
        let b = |i: usize| bytes[i];
        let u16_at = |i: usize| u16::from_le_bytes([b(2 * i), b(2 * i + 1)]);
        let i16_at = |i: usize| u16_at(i) as i16;
        let u32_at =
            |i: usize| u32::from_le_bytes([b(4 * i), b(4 * i + 1), b(4 * i + 2), b(4 * i + 3)]);
        let f32_at = |i: usize| f32::from_bits(u32_at(i));
        let half = |i: usize| f16::from_bits(u16_at(i)).to_f32();
        // An exact integer over an exact integer, correctly rounded to f32.
        let ratio = |n: i32, d: f64| (f64::from(n) / d) as f32;
        let expand2 = |x: f32, y: f32| [x, y, 0.0, 1.0];
        match self {
            Float1 => [f32_at(0), 0.0, 0.0, 1.0],
            Float2 => expand2(f32_at(0), f32_at(1)),
            Float3 => [f32_at(0), f32_at(1), f32_at(2), 1.0],
            Float4 => [f32_at(0), f32_at(1), f32_at(2), f32_at(3)],
            // Memory B, G, R, A (the DWORD 0xAARRGGBB little-endian).
            D3dColor => [b(2), b(1), b(0), b(3)].map(|v| ratio(i32::from(v), 255.0)),
            Ubyte4 => [b(0), b(1), b(2), b(3)].map(f32::from),
            Short2 => expand2(f32::from(i16_at(0)), f32::from(i16_at(1))),
            Short4 => [0, 1, 2, 3].map(|i| f32::from(i16_at(i))),
            Ubyte4N => [b(0), b(1), b(2), b(3)].map(|v| ratio(i32::from(v), 255.0)),
            Short2N => expand2(
                ratio(i32::from(i16_at(0)), 32767.0),
                ratio(i32::from(i16_at(1)), 32767.0),
            ),
            Short4N => [0, 1, 2, 3].map(|i| ratio(i32::from(i16_at(i)), 32767.0)),
            Ushort2N => expand2(
                ratio(i32::from(u16_at(0)), 65535.0),
                ratio(i32::from(u16_at(1)), 65535.0),
            ),
            Ushort4N => [0, 1, 2, 3].map(|i| ratio(i32::from(u16_at(i)), 65535.0)),
            Udec3 => {
                let v = u32_at(0);
                let field = |k: u32| ((v >> (10 * k)) & 0x3FF) as f32;
                [field(0), field(1), field(2), 1.0]
            }
            Dec3N => {
                let v = u32_at(0);
                // Shift the 10-bit field to the top of an i32 and back: two's complement.
                let field = |k: u32| ratio(((v << (22 - 10 * k)) as i32) >> 22, 511.0);
                [field(0), field(1), field(2), 1.0]
            }
            Float16x2 => expand2(half(0), half(1)),
            Float16x4 => [half(0), half(1), half(2), half(3)],
        }
    }
}

#[cfg(test)]
mod tests;
