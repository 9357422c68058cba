//! The shaders shipped inside the binary, by one naming scheme
//! (`family:variant`), so that every job and command finds them the same way
//! and the binary needs no source tree to run them.
//!
//! Every command that reads a shader takes either one of these names or a
//! file path; [`resolve`] is the one place that decides which, and a name
//! that is neither gets the closest bundled name as a suggestion.

/// A bundled shader: its short name, the repository path it was read from at
/// build time, a one-line summary, and its text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bundled {
    /// `article:loop`, `corrected:pass2`, `lights:select`, ...
    pub name: &'static str,
    /// `asm/article/lum_pass1_loop.psh`, ...
    pub path: &'static str,
    /// What the shader is, in one line (listings show it).
    pub summary: &'static str,
    /// The assembly text.
    pub text: &'static str,
}

macro_rules! bundled {
    ($name:literal, $path:literal, $summary:literal) => {
        Bundled {
            name: $name,
            path: $path,
            summary: $summary,
            text: include_str!(concat!("../../", $path)),
        }
    };
}

/// The article's listings, as transcribed in `asm/article/`.
pub const ARTICLE_LOOP: Bundled = bundled!(
    "article:loop",
    "asm/article/lum_pass1_loop.psh",
    "luminance pass 1 as printed: rep/rep loop over an i1×i2 block"
);
/// `article:unrolled`: the article's unrolled pass 1.
pub const ARTICLE_UNROLLED: Bundled = bundled!(
    "article:unrolled",
    "asm/article/lum_pass1_unrolled.psh",
    "luminance pass 1 as printed: 125 samples per line unrolled, rep i2 over lines"
);
/// `article:pass2`: the article's pass 2.
pub const ARTICLE_PASS2: Bundled = bundled!(
    "article:pass2",
    "asm/article/lum_pass2.psh",
    "luminance pass 2 as printed: sums the xsize×ysize target (-D xsize=… -D ysize=…)"
);

/// The corrected listings (`asm/corrected/`), each change explained in its header.
pub const CORRECTED_LOOP: Bundled = bundled!(
    "corrected:loop",
    "asm/corrected/lum_pass1_loop.psh",
    "pass 1, loop form, with the line-end fix"
);
/// `corrected:unrolled`: pass 1, unrolled, corrected.
pub const CORRECTED_UNROLLED: Bundled = bundled!(
    "corrected:unrolled",
    "asm/corrected/lum_pass1_unrolled.psh",
    "pass 1, unrolled form (125 per line), with the line-end fix"
);
/// `corrected:pass2`: pass 2, corrected.
pub const CORRECTED_PASS2: Bundled = bundled!(
    "corrected:pass2",
    "asm/corrected/lum_pass2.psh",
    "pass 2 with the BORDER-padding correction c0.y"
);

/// `asm/lights/select.psh`: the light-model selection with texldl (LOD 0) in
/// the branches.
pub const LIGHTS_SELECT: Bundled = bundled!(
    "lights:select",
    "asm/lights/select.psh",
    "light-model selection by G-buffer ID, texldl in the branches"
);
/// `asm/lights/select_texld.psh`: the same with texld, which ps30 flags.
pub const LIGHTS_TEXLD: Bundled = bundled!(
    "lights:texld",
    "asm/lights/select_texld.psh",
    "the same selection with texld in the branches (gradients undefined)"
);

/// `asm/lights/directional.psh`: the same light models with the light
/// (direction, half vector, colour) set per draw, for drawing several lights.
pub const LIGHTS_DIRECTIONAL: Bundled = bundled!(
    "lights:directional",
    "asm/lights/directional.psh",
    "one light of many: the light models with the light in c5–c7, set per draw"
);

/// Log-luminance encoded into 8-bit alpha, for averaging by the mip chain
/// (`asm/mip-luminance/`).
pub const MIP_LUMINANCE_ENCODE: Bundled = bundled!(
    "mip-luminance:encode",
    "asm/mip-luminance/encode.psh",
    "log-luminance encoded into 8-bit alpha, to be averaged by the mip chain"
);

/// The log-lights comparison (`asm/log-lights/`): a light stored raw, the
/// same light stored as exp2(−light), and the recovery −log2.
pub const LOG_LIGHTS_LIGHT: Bundled = bundled!(
    "log-lights:light",
    "asm/log-lights/light.psh",
    "a light stored raw into RGBA8 (additive blending, saturates at 1)"
);
/// `log-lights:log`: a light stored as exp2(−light).
pub const LOG_LIGHTS_LOG: Bundled = bundled!(
    "log-lights:log",
    "asm/log-lights/log.psh",
    "a light stored as exp2(-light), for multiplicative blending"
);
/// `log-lights:recover`: a light recovered from a log-lights buffer.
pub const LOG_LIGHTS_RECOVER: Bundled = bundled!(
    "log-lights:recover",
    "asm/log-lights/recover.psh",
    "the light recovered from a log-lights buffer: -log2(value)"
);

/// The article's tone-mapping operator in ps_3_0 (`asm/tonemap/`).
pub const TONEMAP_REINHARD: Bundled = bundled!(
    "tonemap:reinhard",
    "asm/tonemap/reinhard.psh",
    "Reinhard's global operator, L̄w read from pass 2's 1×1 target"
);

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

/// What a shader argument names: a bundled shader, or a file to read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Named<'a> {
    /// One of [`ALL`].
    Bundled(Bundled),
    /// A path.
    File(&'a str),
}

/// The one rule for a shader argument: a bundled name (`family:variant`, see
/// [`ALL`]) names that shader; anything else is a file path.
pub fn resolve(spec: &str) -> Named<'_> {
    match find(spec) {
        Some(b) => Named::Bundled(b),
        None => Named::File(spec),
    }
}

/// The bundled name closest to `spec`, when `spec` looks like a misspelt one:
/// within two edits of a name, or a family or variant of it given alone
/// (`article`, `pass2`). `None` when nothing is close.
pub fn suggest(spec: &str) -> Option<&'static str> {
    let spec = spec.trim().to_ascii_lowercase();
    let closest = ALL
        .iter()
        .map(|b| (strsim::levenshtein(&spec, b.name), b.name))
        .min()
        .filter(|&(d, _)| d <= 2)
        .map(|(_, name)| name);
    closest.or_else(|| {
        ALL.iter().map(|b| b.name).find(|name| {
            let (family, variant) = name.split_once(':').unwrap_or((name, ""));
            spec == family || spec == variant || spec.trim_end_matches(':') == family
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_resolve() {
        for b in ALL {
            assert_eq!(ALL.iter().filter(|o| o.name == b.name).count(), 1);
            assert_eq!(resolve(b.name), Named::Bundled(b));
            assert!(b.text.contains("ps_3_0"), "{}", b.name);
        }
        assert_eq!(
            resolve("asm/article/lum_pass1_loop.psh"),
            Named::File("asm/article/lum_pass1_loop.psh")
        );
    }

    #[test]
    fn typos_get_the_closest_name() {
        assert_eq!(suggest("article:loopp"), Some("article:loop"));
        assert_eq!(suggest("Corrected:Pass2"), Some("corrected:pass2"));
        assert_eq!(suggest("corected:unroled"), Some("corrected:unrolled"));
        assert_eq!(suggest("tonemap"), Some("tonemap:reinhard"));
        assert_eq!(suggest("pass2"), Some("article:pass2"));
        assert_eq!(suggest("my_shader.psh"), None);
    }
}
