//! Each D3DDECLTYPE decoded from bytes written here, against values
//! computed here from the documented rule of Microsoft's D3DDECLTYPE page
//! (the derivation beside each), edge values included.

use super::*;

fn le16(v: &[u16]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

fn le32(v: &[u32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

/// Bit-for-bit equality (so that −0.0, NaN and infinities are checked too).
fn same(got: [f32; 4], want: [f32; 4]) {
    let bits = |v: [f32; 4]| v.map(f32::to_bits);
    assert_eq!(bits(got), bits(want), "{got:?} against {want:?}");
}

#[test]
fn floats_are_filled_to_x_0_0_1() {
    // 1.5 = 0x3FC00000, −2 = 0xC0000000, 0.25 = 0x3E800000, 8 = 0x41000000.
    let b = le32(&[0x3FC0_0000, 0xC000_0000, 0x3E80_0000, 0x4100_0000]);
    same(DeclType::Float1.decode(&b), [1.5, 0.0, 0.0, 1.0]);
    same(DeclType::Float2.decode(&b), [1.5, -2.0, 0.0, 1.0]);
    same(DeclType::Float3.decode(&b), [1.5, -2.0, 0.25, 1.0]);
    same(DeclType::Float4.decode(&b), [1.5, -2.0, 0.25, 8.0]);
    // Raw bits pass through: an infinity, a NaN and −0 stay what they are.
    let odd = le32(&[0x7F80_0000, 0x7FC0_0001, 0x8000_0000, 1]);
    same(
        DeclType::Float4.decode(&odd),
        [
            f32::INFINITY,
            f32::from_bits(0x7FC0_0001),
            -0.0,
            f32::from_bits(1),
        ],
    );
}

#[test]
fn d3dcolor_is_bgra_in_memory_and_rgba_in_the_shader() {
    // The DWORD 0x80FF4000 (A 0x80, R 0xFF, G 0x40, B 0x00) is stored
    // little-endian as 00 40 FF 80; the shader reads (R, G, B, A)/255.
    let b = 0x80FF_4000u32.to_le_bytes();
    assert_eq!(b, [0x00, 0x40, 0xFF, 0x80]);
    same(
        DeclType::D3dColor.decode(&b),
        [1.0, 64.0 / 255.0, 0.0, 128.0 / 255.0],
    );
    // UBYTE4N reads the same bytes in memory order, unswizzled.
    same(
        DeclType::Ubyte4N.decode(&b),
        [0.0, 64.0 / 255.0, 1.0, 128.0 / 255.0],
    );
    same(DeclType::D3dColor.decode(&[0; 4]), [0.0; 4]);
    same(DeclType::D3dColor.decode(&[0xFF; 4]), [1.0; 4]);
}

#[test]
fn unsigned_bytes_are_read_as_integers_or_over_255() {
    let b = [0u8, 1, 128, 255];
    same(DeclType::Ubyte4.decode(&b), [0.0, 1.0, 128.0, 255.0]);
    same(
        DeclType::Ubyte4N.decode(&b),
        [0.0, 1.0 / 255.0, 128.0 / 255.0, 1.0],
    );
}

#[test]
fn shorts_are_signed_integers_filled_to_x_y_0_1() {
    // −32768 = 0x8000, 32767 = 0x7FFF, −1 = 0xFFFF.
    let b = le16(&[0x8000, 0x7FFF, 0xFFFF, 12345]);
    same(DeclType::Short2.decode(&b), [-32768.0, 32767.0, 0.0, 1.0]);
    same(
        DeclType::Short4.decode(&b),
        [-32768.0, 32767.0, -1.0, 12345.0],
    );
}

#[test]
fn normalised_shorts_divide_by_32767_without_a_clamp() {
    // D3D9's rule: s/32767.0. 32767 → 1 exactly; −32768 → −32768/32767 =
    // −(1 + 1/32767) = −(1 + 2⁻¹⁵ + 2⁻¹⁵/32767): the last term (≈ 2⁻³⁰) is
    // far below half an f32 ulp at 1 (2⁻²⁴), so it rounds to −(1 + 2⁻¹⁵) =
    // −1.000030517578125 — not Direct3D 10's clamped −1.
    let edge = -(1.0 + f32::powi(2.0, -15));
    assert_eq!(edge, -1.000_030_5);
    let b = le16(&[0x7FFF, 0x8000]);
    same(DeclType::Short2N.decode(&b), [1.0, edge, 0.0, 1.0]);
    // 0, 16384, −16384 (0xC000), −32767 (0x8001): f32 division of exact
    // integers is the correctly rounded quotient.
    let b = le16(&[0, 16384, 0xC000, 0x8001]);
    same(
        DeclType::Short4N.decode(&b),
        [0.0, 16384.0 / 32767.0, -16384.0 / 32767.0, -1.0],
    );
}

#[test]
fn normalised_unsigned_shorts_divide_by_65535() {
    same(
        DeclType::Ushort2N.decode(&le16(&[65535, 0])),
        [1.0, 0.0, 0.0, 1.0],
    );
    same(
        DeclType::Ushort4N.decode(&le16(&[1, 32768, 65535, 0])),
        [1.0 / 65535.0, 32768.0 / 65535.0, 1.0, 0.0],
    );
}

#[test]
fn udec3_reads_three_10_bit_fields_and_ignores_the_top_two() {
    // x = 0x3FF (1023, the largest), y = 0, z = 512, the top bits 11.
    let v = 0x3FF | (512 << 20) | (3 << 30);
    same(
        DeclType::Udec3.decode(&le32(&[v])),
        [1023.0, 0.0, 512.0, 1.0],
    );
    // All ones in the fields: 1023 each.
    same(
        DeclType::Udec3.decode(&le32(&[0x3FFF_FFFF])),
        [1023.0, 1023.0, 1023.0, 1.0],
    );
}

#[test]
fn dec3n_reads_signed_10_bit_fields_over_511() {
    // x = 0x1FF (511 → 1), y = 0x200 (−512 → −512/511, no clamp to −1),
    // z = 0x3FF (−1 → −1/511), the top bits 01 ignored.
    let v = 0x1FF | (0x200 << 10) | (0x3FF << 20) | (1 << 30);
    same(
        DeclType::Dec3N.decode(&le32(&[v])),
        [1.0, -512.0 / 511.0, -1.0 / 511.0, 1.0],
    );
    // Below −1, where Direct3D 10's SNORM rule would clamp it.
    assert!(DeclType::Dec3N.decode(&le32(&[v]))[1] < -1.0);
    same(DeclType::Dec3N.decode(&le32(&[0])), [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn halves_are_ieee_binary16_with_subnormals_infinities_and_nans() {
    // 0x3C00 = 1; 0xC000 = −2; 0x3555 = (1 + 341/1024)/4 = 1365/4096;
    // 0x7BFF = (2 − 2⁻¹⁰)·2¹⁵ = 65504, the largest half.
    same(
        DeclType::Float16x2.decode(&le16(&[0x3C00, 0xC000])),
        [1.0, -2.0, 0.0, 1.0],
    );
    same(
        DeclType::Float16x4.decode(&le16(&[0x3555, 0x7BFF, 0x0000, 0x8000])),
        [1365.0 / 4096.0, 65504.0, 0.0, -0.0],
    );
    // Subnormals: 0x0001 = 2⁻²⁴, 0x03FF = 1023·2⁻²⁴; infinities 0x7C00 and
    // 0xFC00.
    same(
        DeclType::Float16x4.decode(&le16(&[0x0001, 0x03FF, 0x7C00, 0xFC00])),
        [
            f32::powi(2.0, -24),
            1023.0 * f32::powi(2.0, -24),
            f32::INFINITY,
            f32::NEG_INFINITY,
        ],
    );
    // NaNs stay NaNs (quiet 0x7E00, signalling-pattern 0x7C01, negative 0xFE00).
    let nan = DeclType::Float16x4.decode(&le16(&[0x7E00, 0x7C01, 0xFE00, 0x3C00]));
    assert!(nan[..3].iter().all(|x| x.is_nan()), "{nan:?}");
    assert_eq!(nan[3], 1.0);
}

#[test]
fn names_values_and_sizes_follow_d3d9types_h() {
    assert_eq!(DeclType::from_name("float16_2"), Some(DeclType::Float16x2));
    assert_eq!(
        DeclType::from_name("D3DDECLTYPE_DEC3N"),
        Some(DeclType::Dec3N)
    );
    assert_eq!(DeclType::from_name("UNUSED"), None);
    assert_eq!(DeclType::from_name("FLOAT5"), None);
    assert_eq!(DeclType::from_value(4), Some(DeclType::D3dColor));
    assert_eq!(DeclType::from_value(16), Some(DeclType::Float16x4));
    assert_eq!(DeclType::from_value(UNUSED), None);
    // Sizes: components × bytes per component (FLOAT 4, SHORT and FLOAT16 2,
    // bytes 1; the packed 10:10:10:2 types one DWORD).
    let want = [4, 8, 12, 16, 4, 4, 4, 8, 4, 4, 8, 4, 8, 4, 4, 4, 8];
    for ((name, t), size) in ALL.iter().zip(want) {
        assert_eq!(t.size(), size, "{name}");
        assert_eq!(t.name(), *name);
    }
}

#[test]
fn what_windows_drew_in_wines_fixed_function_decl_test() {
    // Wine's dlls/d3d9/tests/visual.c, fixed_function_decl_test (colours
    // read back on Windows drivers): the DWORD 0x00FFFF00 as D3DCOLOR draws
    // 0x00FFFF00 (yellow: R and G full), the same DWORD as UBYTE4N draws
    // 0x0000FFFF (cyan: its bytes 00 FF FF 00 taken in memory order as R,
    // G, B, A), and USHORT4N (0, 0, 0xFFFF, 0xFFFF) draws 0x000000FF (blue).
    let dword = 0x00FF_FF00u32.to_le_bytes();
    same(DeclType::D3dColor.decode(&dword), [1.0, 1.0, 0.0, 0.0]);
    same(DeclType::Ubyte4N.decode(&dword), [0.0, 1.0, 1.0, 0.0]);
    same(
        DeclType::Ushort4N.decode(&le16(&[0, 0, 0xFFFF, 0xFFFF])),
        [0.0, 0.0, 1.0, 1.0],
    );
}
