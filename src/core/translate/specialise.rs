//! What a translation may assume about a draw's sampler state, so that the
//! shader the GPU backend compiles carries only the emulation code the
//! draw's states ask for (as Direct3D 9 drivers specialise pipelines to
//! the states bound with them).
//!
//! An application's translation assumes nothing: every sampler reads its
//! `Ps30Sampler` record at run time and applies LOD bias, MIRRORONCE and a
//! BORDER colour as the record says ([`SamplerSpec::GENERAL`]). The GPU
//! backend knows each state before it compiles, and asks for the code of
//! the states it binds: a plain CLAMP/WRAP/MIRROR sampler without bias
//! samples the texture and nothing more ([`SamplerSpec::PLAIN`]), and a
//! cube map is bound as its six faces so that its filtering is Direct3D
//! 9's. New texture kinds take the same per-sampler record.

use std::collections::BTreeMap;

/// The emulation code one sampler's translation carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SamplerSpec {
    /// The shader takes |u| on the axes the record marks (MIRRORONCE).
    pub mirror_once: bool,
    /// The shader adds a BORDER colour WebGPU lacks (`ps30_border`).
    pub border: bool,
    /// The shader reads the LOD bias from the record (MIPMAPLODBIAS, and
    /// MAXMIPLEVEL's shift of the level without mips); without it the
    /// device's own level of detail is taken unchanged.
    pub lod: bool,
    /// A cube map is bound as its six faces, a 2D array, and the shader
    /// picks the face and its (s, t) itself (`cube.rs`), so that filtering
    /// stops at the face's edge as Direct3D 9 hardware's does; a cube view
    /// is filtered seamlessly across faces by every Vulkan device.
    pub faces: bool,
}

impl SamplerSpec {
    /// Everything read from the record at run time: any state is drawn right.
    pub const GENERAL: SamplerSpec = SamplerSpec {
        mirror_once: true,
        border: true,
        lod: true,
        faces: false,
    };
    /// No emulation at all: the device's sampler does everything.
    pub const PLAIN: SamplerSpec = SamplerSpec {
        mirror_once: false,
        border: false,
        lod: false,
        faces: false,
    };
}

/// A [`SamplerSpec`] per sampler register; a register not named is
/// [`SamplerSpec::GENERAL`].
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Specialisation {
    samplers: BTreeMap<u32, SamplerSpec>,
}

impl Specialisation {
    /// No assumption: every sampler general (an application's translation).
    pub fn general() -> Specialisation {
        Specialisation::default()
    }

    /// Sets what sampler `register`'s translation carries.
    pub fn set(&mut self, register: u32, spec: SamplerSpec) {
        self.samplers.insert(register, spec);
    }

    /// What sampler `register`'s translation carries.
    pub fn sampler(&self, register: u32) -> SamplerSpec {
        self.samplers
            .get(&register)
            .copied()
            .unwrap_or(SamplerSpec::GENERAL)
    }
}
