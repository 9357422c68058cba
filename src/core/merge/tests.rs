//! The output merger against hand-computed values: every factor and
//! operation in each encoding (single, half with its own rounding, 8-bit
//! UNORM with its quantisation), the write mask, discarded pixels, clears.
//!
//! The source and destination of the float cases are dyadic (0.5, 0.25,
//! 0.75, 0.625 over 0.125, 0.5, 1, 0.25), so every factor and product is
//! exact in half and in single and the expected values are the exact
//! products. The rounding cases were worked out by hand from the half and
//! single grids (half: 11 significant bits, so a step of 2 between 2,048
//! and 4,096 and of 2⁻¹³ between 0.125 and 0.25); the 8-bit codes from
//! ⌊255·x + ½⌋ of the f32 result.

use super::*;
use crate::core::image::{unorm8_value, TargetFormat};

const S: [f32; 4] = [0.5, 0.25, 0.75, 0.625];
const D: [f32; 4] = [0.125, 0.5, 1.0, 0.25];

fn eq(src: BlendFactor, dest: BlendFactor, op: BlendOp) -> BlendState {
    BlendState::with(Equation { src, dest, op })
}

/// The factor's value for S over D, by the D3DBLEND table.
fn factor_table() -> Vec<(BlendFactor, [f32; 4])> {
    use BlendFactor::*;
    vec![
        (Zero, [0.0; 4]),
        (One, [1.0; 4]),
        (SrcColor, S),
        (InvSrcColor, [0.5, 0.75, 0.25, 0.375]),
        (SrcAlpha, [0.625; 4]),
        (InvSrcAlpha, [0.375; 4]),
        (DestAlpha, [0.25; 4]),
        (InvDestAlpha, [0.75; 4]),
        (DestColor, D),
        (InvDestColor, [0.875, 0.5, 0.0, 0.75]),
        // f = min(As, 1 − Ad) = min(0.625, 0.75); alpha takes 1.
        (SrcAlphaSat, [0.625, 0.625, 0.625, 1.0]),
        // D3DRS_BLENDFACTOR with (R, G, B, A) bytes (255, 0, 255, 0):
        // exact factors 1, 0, 1, 0.
        (Constant, [1.0, 0.0, 1.0, 0.0]),
        (InvConstant, [0.0, 1.0, 0.0, 1.0]),
    ]
}

fn with_factor(mut b: BlendState) -> BlendState {
    b.factor = [255, 0, 255, 0];
    b
}

#[test]
fn every_factor_on_the_source_and_on_the_destination_in_float_formats() {
    for format in [TargetFormat::A32B32G32R32F, TargetFormat::Rgba16F] {
        for (f, value) in factor_table() {
            let as_src = with_factor(eq(f, BlendFactor::Zero, BlendOp::Add));
            let want: [f32; 4] = std::array::from_fn(|c| S[c] * value[c]);
            assert_eq!(as_src.apply(format, S, D), want, "{format:?} src {f:?}");
            let as_dest = with_factor(eq(BlendFactor::Zero, f, BlendOp::Add));
            let want: [f32; 4] = std::array::from_fn(|c| D[c] * value[c]);
            assert_eq!(as_dest.apply(format, S, D), want, "{format:?} dest {f:?}");
        }
    }
}

#[test]
fn every_operation_in_float_formats() {
    use BlendOp::*;
    let cases = [
        (Add, [0.625, 0.75, 1.75, 0.875]),
        (Subtract, [0.375, -0.25, -0.25, 0.375]),
        (RevSubtract, [-0.375, 0.25, 0.25, -0.375]),
        (Min, [0.125, 0.25, 0.75, 0.25]),
        (Max, [0.5, 0.5, 1.0, 0.625]),
    ];
    for format in [TargetFormat::A32B32G32R32F, TargetFormat::Rgba16F] {
        for (op, want) in cases {
            let b = eq(BlendFactor::One, BlendFactor::One, op);
            assert_eq!(b.apply(format, S, D), want, "{format:?} {op:?}");
        }
        // MIN and MAX ignore the factors: with SRCALPHA / ZERO, still min(S, D).
        let b = eq(BlendFactor::SrcAlpha, BlendFactor::Zero, Min);
        assert_eq!(b.apply(format, S, D), [0.125, 0.25, 0.75, 0.25]);
        let b = eq(BlendFactor::Zero, BlendFactor::Zero, Max);
        assert_eq!(b.apply(format, S, D), [0.5, 0.5, 1.0, 0.625]);
    }
}

#[test]
fn separate_alpha_blends_alpha_with_its_own_equation() {
    let mut b = BlendState::with(Equation::ADDITIVE);
    b.alpha = Some(Equation {
        src: BlendFactor::Zero,
        dest: BlendFactor::One,
        op: BlendOp::Add,
    });
    // Colour: S + D; alpha: keeps D's 0.25.
    assert_eq!(
        b.apply(TargetFormat::A32B32G32R32F, S, D),
        [0.625, 0.75, 1.75, 0.25]
    );
    // Without it, a colour factor supplies its alpha component: SRCCOLOR's
    // alpha is As, so alpha = As · As = 0.390625.
    let b = eq(BlendFactor::SrcColor, BlendFactor::Zero, BlendOp::Add);
    assert_eq!(b.apply(TargetFormat::A32B32G32R32F, S, D)[3], 0.390625);
}

#[test]
fn blending_off_replaces_and_stores_in_the_format() {
    let off = BlendState::OFF;
    assert_eq!(off.apply(TargetFormat::A32B32G32R32F, S, D), S);
    assert_eq!(
        off.apply(TargetFormat::Rgba16F, [0.1, 0.0, 0.0, 0.0], D)[0],
        0.099_975_586,
        "0.1 as a half: 0.0999755859375"
    );
}

#[test]
fn half_targets_round_every_blend_operation_to_half() {
    let add = BlendState::with(Equation::ADDITIVE);
    let f = TargetFormat::Rgba16F;
    let at = |dst: f32, src: f32| add.apply(f, [src; 4], [dst; 4])[0];
    // Halves between 2,048 and 4,096 are 2 apart: 2,049 is a tie and goes to
    // the even 2,048; 2,049.5 rounds up to 2,050; 2,051 ties to 2,052.
    assert_eq!(at(2048.0, 1.0), 2048.0);
    assert_eq!(at(2048.0, 1.5), 2050.0);
    assert_eq!(at(2048.0, 3.0), 2052.0);
    // 65,504 + 32 = 65,536 is past 65,520, the midpoint to the next step.
    assert_eq!(at(65504.0, 32.0), f32::INFINITY);
    // Products round too: the blend factor 51/255 = 0.2 is the half
    // 0.199951171875; 0.75 × that = 0.14996337890625 = 1228.5 steps of 2⁻¹³,
    // a tie that goes to the even 1228 · 2⁻¹³ = 0.14990234375. In single
    // floats the same blend gives f32(0.75 · f32(0.2)) = 0.15000000596 = f32(0.15).
    let mut b = eq(BlendFactor::Constant, BlendFactor::Zero, BlendOp::Add);
    b.factor = [51; 4];
    assert_eq!(b.apply(f, [0.75; 4], D)[0], 0.149_902_34);
    assert_eq!(b.apply(TargetFormat::A32B32G32R32F, [0.75; 4], D)[0], 0.15);
    // 1 − x rounds: 0.1 as a half is 0.0999755859375; 1 − that =
    // 0.9000244140625 lies between the halves 0.89990234375 and 0.900390625
    // (steps of 2⁻¹¹), nearer the first.
    let b = eq(BlendFactor::InvSrcColor, BlendFactor::Zero, BlendOp::Add);
    let src = [0.1, 1.0, 1.0, 1.0];
    // The result is src · (1 − src): 0.0999755859375 · 0.89990234375 =
    // 0.08996826410293579, which is 1474.08… steps of 2⁻¹⁴: 1474 · 2⁻¹⁴.
    assert_eq!(b.apply(f, src, D)[0], 1474.0 / 16384.0);
}

#[test]
fn unorm8_blends_on_clamped_sources_and_quantises_the_result() {
    let f = TargetFormat::A8R8G8B8;
    // The destination as the target holds it: codes 32, 128, 255, 64.
    let d = [32u8, 128, 255, 64].map(unorm8_value);
    let codes = |v: [f32; 4]| v.map(|c| (c * 255.0).round() as u8);
    use BlendFactor::*;
    use BlendOp::*;
    let cases: [(BlendState, [u8; 4]); 8] = [
        (eq(SrcColor, Zero, Add), [64, 16, 143, 100]),
        (eq(DestColor, Zero, Add), [16, 32, 191, 40]),
        (eq(One, One, Add), [159, 192, 255, 223]),
        (eq(One, One, Subtract), [96, 0, 0, 95]),
        (eq(One, One, RevSubtract), [0, 64, 64, 0]),
        (eq(SrcAlpha, InvSrcAlpha, Add), [92, 88, 215, 124]),
        // f = min(0.625, 1 − 64/255) = 0.625; alpha × 1.
        (eq(SrcAlphaSat, Zero, Add), [80, 40, 120, 159]),
        (eq(InvDestColor, Zero, Add), [112, 32, 0, 119]),
    ];
    for (b, want) in cases {
        assert_eq!(codes(b.apply(f, S, d)), want, "{:?}", b.color);
    }
    // The source is clamped to [0, 1] before blending: 3 × 0.5 counts as 1.
    let b = eq(DestColor, Zero, Add);
    assert_eq!(
        codes(b.apply(f, [3.0, -1.0, f32::NAN, 0.5], d)),
        [32, 0, 0, 32]
    );
    // Additive accumulation saturates at 1.
    let add = BlendState::with(Equation::ADDITIVE);
    assert_eq!(codes(add.apply(f, [0.75; 4], [0.75; 4])), [255; 4]);
}

/// Every factor in an 8-bit target, on the source (F, ZERO) and on the
/// destination (ZERO, F), as codes. With the destination's codes
/// 32, 128, 255, 64 and the source 0.5, 0.25, 0.75, 0.625, a product is
/// worked out in code units: e.g. DESTALPHA on the source is s · 64 codes
/// (32, 16, 48, 40), SRCALPHA on the destination is 0.625 · each code
/// (20, 80, 159.375 → 159, 40), BLENDFACTOR (255, 0, 51, 128) on the source
/// is 127.5 → 128, 0, 38.25 → 38, 80; halves round up.
#[test]
fn every_factor_and_operation_in_an_8_bit_target() {
    use BlendFactor::*;
    let f = TargetFormat::A8R8G8B8;
    let d = [32u8, 128, 255, 64].map(unorm8_value);
    let codes = |v: [f32; 4]| v.map(|c| (c * 255.0).round() as u8);
    let table: [(BlendFactor, [u8; 4], [u8; 4]); 13] = [
        (Zero, [0, 0, 0, 0], [0, 0, 0, 0]),
        (One, [128, 64, 191, 159], [32, 128, 255, 64]),
        (SrcColor, [64, 16, 143, 100], [16, 32, 191, 40]),
        (InvSrcColor, [64, 48, 48, 60], [16, 96, 64, 24]),
        (SrcAlpha, [80, 40, 120, 100], [20, 80, 159, 40]),
        (InvSrcAlpha, [48, 24, 72, 60], [12, 48, 96, 24]),
        (DestAlpha, [32, 16, 48, 40], [8, 32, 64, 16]),
        (InvDestAlpha, [96, 48, 143, 119], [24, 96, 191, 48]),
        (DestColor, [16, 32, 191, 40], [4, 64, 255, 16]),
        (InvDestColor, [112, 32, 0, 119], [28, 64, 0, 48]),
        (SrcAlphaSat, [80, 40, 120, 159], [20, 80, 159, 64]),
        (Constant, [128, 0, 38, 80], [32, 0, 51, 32]),
        (InvConstant, [0, 64, 153, 79], [0, 128, 204, 32]),
    ];
    for (factor, on_src, on_dest) in table {
        let mut b = eq(factor, Zero, BlendOp::Add);
        b.factor = [255, 0, 51, 128];
        assert_eq!(codes(b.apply(f, S, d)), on_src, "src {factor:?}");
        let mut b = eq(Zero, factor, BlendOp::Add);
        b.factor = [255, 0, 51, 128];
        assert_eq!(codes(b.apply(f, S, d)), on_dest, "dest {factor:?}");
    }
    let b = eq(One, One, BlendOp::Min);
    assert_eq!(codes(b.apply(f, S, d)), [32, 64, 191, 64]);
    let b = eq(One, One, BlendOp::Max);
    assert_eq!(codes(b.apply(f, S, d)), [128, 128, 255, 159]);
}

#[test]
fn unorm8_quantisation_at_zero_the_half_step_and_one() {
    let f = TargetFormat::A8R8G8B8;
    let off = BlendState::OFF;
    let code = |x: f32| (off.apply(f, [x; 4], [0.0; 4])[0] * 255.0).round() as u8;
    // 0.5/255 is not an f32; its nearest f32 is 0.0019607844, just above, so
    // it rounds up to code 1; the f32 before it stays at 0.
    let half_step = 0.5f32 / 255.0;
    assert!((half_step as f64) > 0.5 / 255.0);
    assert_eq!(code(half_step), 1);
    assert_eq!(code(f32::from_bits(half_step.to_bits() - 1)), 0);
    assert_eq!(code(0.0), 0);
    assert_eq!(code(-1e-30), 0);
    assert_eq!(code(1.0), 255);
    // The same at the top: the f32s either side of 254.5/255.
    let top = (254.5f64 / 255.0) as f32;
    let (below, above) = if (top as f64) < 254.5 / 255.0 {
        (top, f32::from_bits(top.to_bits() + 1))
    } else {
        (f32::from_bits(top.to_bits() - 1), top)
    };
    assert_eq!((code(below), code(above)), (254, 255));
    assert_eq!(code(f32::INFINITY), 255);
    // Adding half a step to code 254 lands on 255; adding less stays.
    let add = BlendState::with(Equation::ADDITIVE);
    let d = [unorm8_value(254); 4];
    let sum = |x: f32| (add.apply(f, [x; 4], d)[0] * 255.0).round() as u8;
    assert_eq!(sum(0.6 / 255.0), 255);
    assert_eq!(sum(0.4 / 255.0), 254);
}

fn target(format: TargetFormat, texels: Vec<[f32; 4]>) -> RenderTarget {
    let mut t = RenderTarget::new(texels.len() as u32, 1, format);
    for (i, v) in texels.into_iter().enumerate() {
        t.store(i as u32, 0, v);
    }
    t
}

#[test]
fn the_write_mask_keeps_the_channels_it_does_not_name() {
    let mut t = target(TargetFormat::A32B32G32R32F, vec![D, D]);
    let state = OutputState {
        blend: BlendState::with(Equation::ADDITIVE),
        write: ColorWrite::from_letters("ga").unwrap(),
    };
    let stats = merge(&mut t, &[S, S], &[false, false], &state).unwrap();
    assert_eq!(stats.written, 2);
    // R and B keep D; G and A take S + D.
    assert_eq!(t.texel(0, 0), [0.125, 0.75, 1.0, 0.875]);
    // Nothing enabled: nothing changes.
    let none = OutputState {
        write: ColorWrite(0),
        ..OutputState::default()
    };
    merge(&mut t, &[S, S], &[false, false], &none).unwrap();
    assert_eq!(t.texel(1, 0), [0.125, 0.75, 1.0, 0.875]);
    // A format without G, B, A keeps reading 1 there whatever is written.
    let mut r = target(TargetFormat::R32F, vec![[0.0; 4]]);
    merge(&mut r, &[S], &[false], &OutputState::default()).unwrap();
    assert_eq!(r.texel(0, 0), [0.5, 1.0, 1.0, 1.0]);
}

#[test]
fn discarded_pixels_write_nothing() {
    let mut t = target(TargetFormat::Rgba16F, vec![D, D, D]);
    let state = OutputState {
        blend: BlendState::with(Equation::ADDITIVE),
        ..OutputState::default()
    };
    let stats = merge(&mut t, &[S, S, S], &[false, true, false], &state).unwrap();
    assert_eq!((stats.written, stats.killed), (2, 1));
    assert_eq!(t.texel(1, 0), D);
    assert_eq!(t.texel(2, 0), [0.625, 0.75, 1.75, 0.875]);
    assert!(merge(&mut t, &[S], &[false], &state).is_err());
}

#[test]
fn destination_alpha_of_a_format_without_alpha_is_one() {
    // G16R16F reads A = 1, so INVDESTALPHA is 0 and SRCALPHASAT's f is 0.
    let t = target(TargetFormat::G16R16F, vec![D]);
    let b = eq(BlendFactor::One, BlendFactor::InvDestAlpha, BlendOp::Add);
    assert_eq!(b.apply(t.format, S, t.texel(0, 0)), [0.5, 0.25, 1.0, 1.0]);
    let b = eq(BlendFactor::SrcAlphaSat, BlendFactor::One, BlendOp::Add);
    assert_eq!(b.apply(t.format, S, t.texel(0, 0)), [0.125, 0.5, 1.0, 1.0]);
}

#[test]
fn clears_write_a_d3dcolor_in_every_format() {
    let mut t = target(TargetFormat::A8R8G8B8, vec![S]);
    clear(&mut t, [255, 128, 0, 64]);
    assert_eq!(
        t.texel(0, 0),
        [1.0, unorm8_value(128), 0.0, unorm8_value(64)]
    );
    let mut h = target(TargetFormat::R16F, vec![S, S]);
    clear(&mut h, [51, 255, 255, 255]);
    // 51/255 = 0.2 stored as the half 0.199951171875; G, B, A read 1.
    assert_eq!(h.texel(1, 0), [0.199_951_17, 1.0, 1.0, 1.0]);
    let mut w = target(TargetFormat::A32B32G32R32F, vec![S]);
    clear(&mut w, [255; 4]);
    assert_eq!(w.texel(0, 0), [1.0; 4]);
}

#[test]
fn names_round_trip() {
    for f in BlendFactor::ALL {
        assert_eq!(BlendFactor::from_name(f.d3d_name()), Some(f));
        let long = format!("d3dblend_{}", f.d3d_name().to_lowercase());
        assert_eq!(BlendFactor::from_name(&long), Some(f));
    }
    for o in BlendOp::ALL {
        assert_eq!(BlendOp::from_name(o.d3d_name()), Some(o));
    }
    assert_eq!(BlendFactor::from_name("BOTHSRCALPHA"), None);
    assert_eq!(ColorWrite::from_letters("rgba"), Some(ColorWrite::ALL));
    assert_eq!(ColorWrite::from_letters("A").map(|m| m.0), Some(8));
    assert_eq!(ColorWrite::from_letters("rr"), None);
    assert_eq!(ColorWrite::from_letters("q"), None);
    assert_eq!(ColorWrite(5).letters(), "rb");
    assert_eq!(ColorWrite(0).letters(), "-");
}
