//! The shaders shipped inside the binary, by one naming scheme
//! (`family:variant`), so that every job and command finds them the same way
//! and the binary needs no source tree to run them.

/// A bundled shader: its short name, the repository path it was read from at
/// build time, and its text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bundled {
    /// `article:loop`, `corrected:pass2`, `lights:select`, ...
    pub name: &'static str,
    /// `asm/article/lum_pass1_loop.psh`, ...
    pub path: &'static str,
    /// The assembly text.
    pub text: &'static str,
}

macro_rules! bundled {
    ($name:literal, $path:literal) => {
        Bundled {
            name: $name,
            path: $path,
            text: include_str!(concat!("../../", $path)),
        }
    };
}

/// The article's listings, as transcribed in `asm/article/`.
pub const ARTICLE_LOOP: Bundled = bundled!("article:loop", "asm/article/lum_pass1_loop.psh");
pub const ARTICLE_UNROLLED: Bundled =
    bundled!("article:unrolled", "asm/article/lum_pass1_unrolled.psh");
pub const ARTICLE_PASS2: Bundled = bundled!("article:pass2", "asm/article/lum_pass2.psh");

/// The corrected listings (`asm/corrected/`), each change explained in its header.
pub const CORRECTED_LOOP: Bundled = bundled!("corrected:loop", "asm/corrected/lum_pass1_loop.psh");
pub const CORRECTED_UNROLLED: Bundled =
    bundled!("corrected:unrolled", "asm/corrected/lum_pass1_unrolled.psh");
pub const CORRECTED_PASS2: Bundled = bundled!("corrected:pass2", "asm/corrected/lum_pass2.psh");

/// `asm/lights/select.psh`: the light-model selection with texldl (LOD 0) in
/// the branches.
pub const LIGHTS_SELECT: Bundled = bundled!("lights:select", "asm/lights/select.psh");
/// `asm/lights/select_texld.psh`: the same with texld, which ps30 flags.
pub const LIGHTS_TEXLD: Bundled = bundled!("lights:texld", "asm/lights/select_texld.psh");

/// `asm/lights/directional.psh`: the same light models with the light
/// (direction, half vector, colour) set per draw, for drawing several lights.
pub const LIGHTS_DIRECTIONAL: Bundled =
    bundled!("lights:directional", "asm/lights/directional.psh");

/// Log-luminance encoded into 8-bit alpha, for averaging by the mip chain
/// (`asm/mip-luminance/`).
pub const MIP_LUMINANCE_ENCODE: Bundled =
    bundled!("mip-luminance:encode", "asm/mip-luminance/encode.psh");

/// The log-lights comparison (`asm/log-lights/`): a light stored raw, the
/// same light stored as exp2(−light), and the recovery −log2.
pub const LOG_LIGHTS_LIGHT: Bundled = bundled!("log-lights:light", "asm/log-lights/light.psh");
pub const LOG_LIGHTS_LOG: Bundled = bundled!("log-lights:log", "asm/log-lights/log.psh");
pub const LOG_LIGHTS_RECOVER: Bundled =
    bundled!("log-lights:recover", "asm/log-lights/recover.psh");

/// The article's tone-mapping operator in ps_3_0 (`asm/tonemap/`).
pub const TONEMAP_REINHARD: Bundled = bundled!("tonemap:reinhard", "asm/tonemap/reinhard.psh");

/// Every bundled shader, in the order listings show them.
pub const ALL: [Bundled; 14] = [
    ARTICLE_LOOP,
    ARTICLE_UNROLLED,
    ARTICLE_PASS2,
    CORRECTED_LOOP,
    CORRECTED_UNROLLED,
    CORRECTED_PASS2,
    LIGHTS_SELECT,
    LIGHTS_TEXLD,
    LIGHTS_DIRECTIONAL,
    MIP_LUMINANCE_ENCODE,
    LOG_LIGHTS_LIGHT,
    LOG_LIGHTS_LOG,
    LOG_LIGHTS_RECOVER,
    TONEMAP_REINHARD,
];

/// The bundled shader with this short name.
pub fn find(name: &str) -> Option<Bundled> {
    ALL.iter().copied().find(|b| b.name == name)
}

impl Bundled {
    /// `(path, text)`, the form the jobs take a listing in.
    pub const fn listing(&self) -> (&'static str, &'static str) {
        (self.path, self.text)
    }
}

/// `(path, text)` of the bundled shader with this short name.
pub fn listing(name: &str) -> Option<(&'static str, &'static str)> {
    find(name).map(|b| b.listing())
}
