//! D3D9 sampler state on WebGPU: a wgpu sampler, the range of mip levels
//! the texture view shows, and the `Ps30Sampler` values the translated
//! shader applies itself (`core/translate/interface.rs`).
//!
//! | D3D9 | here |
//! |---|---|
//! | WRAP, MIRROR, CLAMP | `Repeat`, `MirrorRepeat`, `ClampToEdge` |
//! | BORDER, colour (0,0,0,0), (0,0,0,1), (1,1,1,1) | `ClampToBorder` with that colour |
//! | BORDER, any other colour | `ClampToBorder` transparent black; the shader adds the colour (`border_mode`) |
//! | MIRRORONCE | `ClampToEdge`; the shader takes \|u\| (`mirror_once`) |
//! | ADDRESSW | the volume texture's w axis as U and V (2D: unused) |
//! | any address mode on a cube map | none: the faces, a 2D array the shader picks from, are clamped (`ClampToEdge`), so filtering stops at a face's edge as in Direct3D 9 |
//! | MAG/MINFILTER POINT, LINEAR | `Nearest`, `Linear` |
//! | MIPFILTER NONE | a view of the base level only |
//! | MIPFILTER POINT, LINEAR | the whole chain, `Nearest`/`Linear` between levels |
//! | MAXMIPLEVEL m | NONE: the view's base level; POINT/LINEAR: `lod_min_clamp` = m |
//! | MIPMAPLODBIAS | `lod.x`/`lod.y`/`lod.z` (WebGPU samplers have no bias) |
//!
//! Where this differs from the emulator's rules (`core/emu/sample.rs`):
//! a device computes the level of detail of the view's base level, so with
//! MIPFILTER NONE the shader adds the base level back into its bias (it
//! only decides magnification against minification there); with a mip
//! filter and MAXMIPLEVEL > 0, Vulkan clamps λ to m before choosing the
//! filter, so a λ ≤ 0 minifies where the emulator magnifies (this matters
//! only when MAGFILTER ≠ MINFILTER); MIPFILTER POINT rounds λ = k + ½ down
//! (Vulkan's ⌈λ + ½⌉ − 1) where the emulator rounds up (⌊λ + ½⌋). A custom
//! BORDER colour with linear filtering is emulated on level 0 only, so it
//! is refused with a mip filter.

use super::GpuError;
use crate::core::emu::{Address, Filter, MipFilter, SamplerState};
use crate::core::isa::SamplerType;
use crate::core::translate::SamplerSpec;

/// Everything the draw sets up for one `s#`.
pub(super) struct Mapped {
    pub descriptor: wgpu::SamplerDescriptor<'static>,
    /// First level and number of levels of the texture view.
    pub base_level: u32,
    pub level_count: u32,
    /// The `Ps30Sampler` block, 64 bytes.
    pub block: [u8; 64],
    /// Whether the sampler filters linearly (needs a filterable texture).
    pub filtering: bool,
    /// The emulation code the translation needs for this state.
    pub spec: SamplerSpec,
}

fn filter(f: Filter) -> wgpu::FilterMode {
    match f {
        Filter::Point => wgpu::FilterMode::Nearest,
        Filter::Linear => wgpu::FilterMode::Linear,
    }
}

/// The hardware border colour for `c`, if WebGPU has it.
fn hardware_border(c: [f32; 4]) -> Option<wgpu::SamplerBorderColor> {
    match c {
        [0.0, 0.0, 0.0, 0.0] => Some(wgpu::SamplerBorderColor::TransparentBlack),
        [0.0, 0.0, 0.0, 1.0] => Some(wgpu::SamplerBorderColor::OpaqueBlack),
        [1.0, 1.0, 1.0, 1.0] => Some(wgpu::SamplerBorderColor::OpaqueWhite),
        _ => None,
    }
}

/// Maps `state` for a texture of `levels` levels declared `ty`.
pub(super) fn map(
    state: &SamplerState,
    levels: u32,
    sampler: u32,
    ty: SamplerType,
    clamp_to_border: bool,
) -> Result<Mapped, GpuError> {
    // A 2D texture is addressed on u and v, a volume on u, v and w; a cube
    // map's faces are clamped whatever the state says (see the module docs).
    let axes = match ty {
        SamplerType::Tex2d => vec![state.address_u, state.address_v],
        SamplerType::Volume => vec![state.address_u, state.address_v, state.address_w],
        SamplerType::Cube => Vec::new(),
    };
    let address = |i: usize| axes.get(i).copied().unwrap_or(Address::Clamp);
    let any_border = axes.contains(&Address::Border);
    if any_border && !clamp_to_border {
        return Err(GpuError::Unsupported(format!(
            "s{sampler} uses BORDER addressing and the device lacks ADDRESS_MODE_CLAMP_TO_BORDER"
        )));
    }
    let hardware = hardware_border(state.border);
    let emulate_border = any_border && hardware.is_none();
    let linear = state.mag_filter == Filter::Linear || state.min_filter == Filter::Linear;
    if emulate_border && linear && state.mip_filter != MipFilter::None && levels > 1 {
        return Err(GpuError::Unsupported(format!(
            "s{sampler}: a BORDER colour other than (0,0,0,0), (0,0,0,1) or (1,1,1,1) with linear filtering \
             and mipmaps is not emulated (WebGPU has only those three border colours)"
        )));
    }
    let mode = |a: Address| match a {
        Address::Wrap => wgpu::AddressMode::Repeat,
        Address::Mirror => wgpu::AddressMode::MirrorRepeat,
        Address::Clamp | Address::MirrorOnce => wgpu::AddressMode::ClampToEdge,
        Address::Border => wgpu::AddressMode::ClampToBorder,
    };
    let base = state.max_mip_level.min(levels.saturating_sub(1));
    let (base_level, level_count, mip_filter, lod_min) = match state.mip_filter {
        MipFilter::None => (base, 1, wgpu::MipmapFilterMode::Nearest, 0.0),
        MipFilter::Point => (0, levels, wgpu::MipmapFilterMode::Nearest, base as f32),
        MipFilter::Linear => (0, levels, wgpu::MipmapFilterMode::Linear, base as f32),
    };
    // The device measures λ on the view's base level; with one level in
    // the view only the magnification test depends on it, so the shader
    // adds the base level back (see the module docs).
    let shift = if state.mip_filter == MipFilter::None {
        base as f32
    } else {
        0.0
    };
    let bias = state.mip_lod_bias;
    let lod = [bias + shift, bias, (bias + shift).exp2(), 0.0];
    let border = if emulate_border {
        state.border
    } else {
        [0.0; 4]
    };
    let flag = |on: bool| on as u32;
    let mirror_once: [u32; 3] = std::array::from_fn(|i| flag(address(i) == Address::MirrorOnce));
    let border_axes: [u32; 3] =
        std::array::from_fn(|i| flag(emulate_border && address(i) == Address::Border));
    let border_filter = match (emulate_border, linear) {
        (false, _) => 0,
        (true, false) => 1,
        (true, true) => 2,
    };
    let mut block = [0u8; 64];
    let words: [[u32; 4]; 4] = [
        lod.map(f32::to_bits),
        border.map(f32::to_bits),
        [mirror_once[0], mirror_once[1], mirror_once[2], 0],
        [
            border_axes[0],
            border_axes[1],
            border_axes[2],
            border_filter,
        ],
    ];
    for (i, w) in words.iter().flatten().enumerate() {
        block[4 * i..4 * i + 4].copy_from_slice(&w.to_le_bytes());
    }
    Ok(Mapped {
        descriptor: wgpu::SamplerDescriptor {
            label: None,
            address_mode_u: mode(address(0)),
            address_mode_v: mode(address(1)),
            address_mode_w: mode(address(2)),
            mag_filter: filter(state.mag_filter),
            min_filter: filter(state.min_filter),
            mipmap_filter: mip_filter,
            lod_min_clamp: lod_min,
            lod_max_clamp: 32.0,
            compare: None,
            anisotropy_clamp: 1,
            border_color: if any_border {
                Some(hardware.unwrap_or(wgpu::SamplerBorderColor::TransparentBlack))
            } else {
                None
            },
        },
        base_level,
        level_count,
        block,
        filtering: linear || state.mip_filter == MipFilter::Linear,
        // `lod` as [0, 0, 2⁰, 0] is the device's own level of detail.
        spec: SamplerSpec {
            mirror_once: mirror_once.contains(&1),
            border: emulate_border,
            lod: lod != [0.0, 0.0, 1.0, 0.0],
            // bound as its faces: see `texture::view_dimension`
            faces: ty == SamplerType::Cube,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(block: &[u8; 64]) -> Vec<u32> {
        block
            .chunks(4)
            .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    }

    #[test]
    fn the_luminance_sampler_is_plain_hardware() {
        let m = map(&SamplerState::default(), 1, 0, SamplerType::Tex2d, true).unwrap();
        assert_eq!(
            m.descriptor.address_mode_u,
            wgpu::AddressMode::ClampToBorder
        );
        assert_eq!(
            m.descriptor.border_color,
            Some(wgpu::SamplerBorderColor::TransparentBlack)
        );
        // No bias (2^0 = 1 for texldd), no emulation.
        let w = words(&m.block);
        assert_eq!(w[2], 1f32.to_bits());
        assert!(w[4..].iter().all(|&x| x == 0), "{w:?}");
        assert_eq!(
            m.spec,
            SamplerSpec::PLAIN,
            "nothing for the shader to emulate"
        );
    }

    #[test]
    fn other_border_colours_and_mirror_once_are_emulated() {
        let s = SamplerState {
            address_u: Address::Border,
            address_v: Address::MirrorOnce,
            address_w: Address::MirrorOnce,
            border: [0.25, 0.5, 0.75, 1.0],
            ..SamplerState::filtered(Filter::Linear)
        };
        let m = map(&s, 1, 3, SamplerType::Tex2d, true).unwrap();
        assert_eq!(m.descriptor.address_mode_v, wgpu::AddressMode::ClampToEdge);
        let w = words(&m.block);
        assert_eq!(w[4..8], [0.25f32, 0.5, 0.75, 1.0].map(f32::to_bits));
        assert_eq!(w[8..12], [0, 1, 0, 0], "mirror once on v");
        assert_eq!(w[12..16], [1, 0, 0, 2], "border on u, linear");
        let emulated = SamplerSpec {
            mirror_once: true,
            border: true,
            lod: false,
            faces: false,
        };
        assert_eq!(m.spec, emulated);
        let refused = map(
            &SamplerState {
                mip_filter: MipFilter::Linear,
                ..s
            },
            4,
            3,
            SamplerType::Tex2d,
            true,
        );
        assert!(matches!(refused, Err(GpuError::Unsupported(_))));
    }

    #[test]
    fn max_mip_level_without_mips_is_the_views_base_and_the_bias_shift() {
        let s = SamplerState {
            max_mip_level: 2,
            mip_lod_bias: 0.5,
            ..SamplerState::default()
        };
        let m = map(&s, 4, 0, SamplerType::Tex2d, true).unwrap();
        assert_eq!((m.base_level, m.level_count), (2, 1));
        let w = words(&m.block);
        assert_eq!(f32::from_bits(w[0]), 2.5);
        assert_eq!(f32::from_bits(w[1]), 0.5);
        assert!(m.spec.lod, "a bias is read by the shader");
        let with_mips = map(
            &SamplerState {
                mip_filter: MipFilter::Point,
                ..s
            },
            4,
            0,
            SamplerType::Tex2d,
            true,
        )
        .unwrap();
        assert_eq!((with_mips.base_level, with_mips.level_count), (0, 4));
        assert_eq!(with_mips.descriptor.lod_min_clamp, 2.0);
    }
}
