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
//!
//! The GPU backend also fixes the draw's float constants: each `c#` read
//! without relative addressing becomes a literal, so that a device's
//! compiler folds what the float rules ask of it (a denormal flush, the
//! zero-multiply test) instead of computing it per pixel; and it flushes
//! the draw's inputs on the CPU under the `hardware` rules, so that the
//! shader reads them as they are.

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
    /// The bits of every `c#` the draw sets (registers past the end are
    /// zero), or `None`: read from the constant block at run time.
    constants: Option<Vec<[u32; 4]>>,
    /// The inputs (`v#`) arrive with denormals already flushed.
    inputs_flushed: bool,
    /// `Entry::Draw` reads `vPos` per pixel from the last layer of the
    /// draw's input texture (a draw of given pixels, whose place on the
    /// device need not be their place in the render target) instead of
    /// from the fragment's position.
    positions_given: bool,
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

    /// Fixes the float constants to `bits` (`c0`, `c1`, …; those past the
    /// end are zero, as the constant block holds them).
    pub fn set_constants(&mut self, bits: Vec<[u32; 4]>) {
        self.constants = Some(bits);
    }

    /// The bits of `c{register}` when the draw fixes them.
    pub fn constant(&self, register: u32) -> Option<[u32; 4]> {
        let c = self.constants.as_ref()?;
        Some(c.get(register as usize).copied().unwrap_or([0; 4]))
    }

    /// Says that the inputs arrive with denormals flushed to zeros of their
    /// sign (the GPU backend does it on the CPU under `hardware`).
    pub fn set_inputs_flushed(&mut self, flushed: bool) {
        self.inputs_flushed = flushed;
    }

    /// Whether the inputs arrive flushed.
    pub fn inputs_flushed(&self) -> bool {
        self.inputs_flushed
    }

    /// Sets whether `vPos` arrives as the input texture's last layer.
    pub fn set_positions_given(&mut self, given: bool) {
        self.positions_given = given;
    }

    /// Whether `vPos` arrives as the input texture's last layer.
    pub fn positions_given(&self) -> bool {
        self.positions_given
    }

    /// What sampler `register`'s translation carries.
    pub fn sampler(&self, register: u32) -> SamplerSpec {
        self.samplers
            .get(&register)
            .copied()
            .unwrap_or(SamplerSpec::GENERAL)
    }
}
