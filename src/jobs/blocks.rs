//! Which blocks the luminance passes use on an image, when the user does
//! not say: the planner's choice for the image's size, with the generator's
//! shaders for it, or the block a named shader was written for.
//!
//! The article's blocks (125×128 unrolled, 128×56 loop) were chosen for
//! 1280×1024. On a 3×7 image a 125×128 block reads 15,979 texels of BORDER
//! padding for 21 real ones, and the f32 sum of that padding drowns the
//! image. So a run that names no shaders asks [`crate::jobs::gen::plan`]
//! for the image's own size and runs the shaders
//! [`crate::jobs::gen::set::generate`] writes for the
//! recommended configuration; a run that names a pass-1 shader takes the
//! block from the shader: a generated shader's header states it, a bundled
//! listing has the article's.

use crate::core::cost::Profile;
use crate::jobs::gen::plan::{self, Candidate};
use crate::jobs::gen::set::{self, BlockChoice, Role};
use crate::jobs::gen::GenError;
use crate::jobs::luminance::ShaderSource;

/// Luminance passes planned for an image size.
#[derive(Clone, Debug)]
pub struct Planned {
    /// The recommended candidate (`unrolled 117×128 → 11×8`, …).
    pub candidate: Candidate,
    /// The pass-1 shader written for it.
    pub pass1: ShaderSource,
    /// The pass-2 shader written for its target.
    pub pass2: ShaderSource,
    /// Why the planner chose it, in one sentence.
    pub why: String,
}

impl Planned {
    /// The block, as the pipeline takes it.
    pub fn block(&self) -> (u32, u32) {
        (self.candidate.block[0], self.candidate.block[1])
    }
}

/// The planner's recommendation for a `w × h` image under the ps_3_0
/// profile, with its generated pass-1 and pass-2 shaders (BORDER padding in
/// x; pass 2 corrects it exactly). Shader names are the files `ps30 unroll
/// --frame WxH` would write, marked as generated.
pub fn planned(w: u32, h: u32, delta: f64) -> Result<Planned, GenError> {
    let profile = Profile::ps_3_0();
    let p = plan::plan((w, h), &profile, delta)?;
    let candidate = p
        .recommended
        .as_ref()
        .and_then(|n| p.candidates.iter().find(|c| &c.name == n))
        .cloned()
        .ok_or_else(|| {
            GenError(format!(
                "no two-pass configuration of the luminance passes fits a {w}×{h} image under the ps_3_0 limits (see `ps30 plan --frame {w}x{h}`)"
            ))
        })?;
    let bundle = set::generate(
        &set::Request {
            frame: (w, h),
            picks: vec![(
                candidate.variant,
                BlockChoice::Given(candidate.block[0], candidate.block[1]),
            )],
            macros: false,
            delta,
            // The planned passes pad the last column with BORDER.
            last_columns: false,
        },
        &profile,
    )?;
    let source = |role: Role| {
        bundle
            .shaders
            .iter()
            .find(|g| g.role == role)
            .map(|g| ShaderSource::new(format!("(generated) {}", g.file), g.text.clone()))
            .ok_or_else(|| {
                GenError(format!(
                    "the generator wrote no {role:?} shader for {w}×{h}"
                ))
            })
    };
    Ok(Planned {
        pass1: source(Role::Pass1)?,
        pass2: source(Role::Pass2)?,
        why: p.why.clone(),
        candidate,
    })
}

/// The block a pass-1 shader was written for: what a generated shader's
/// first line states (`… 117×128 blocks …`), or the article's block for its
/// bundled listings (`bundled` is the bundled name, if the shader is one).
pub fn block_of(text: &str, bundled: Option<&str>) -> Option<(u32, u32)> {
    match bundled {
        Some("article:unrolled" | "corrected:unrolled") => return Some((125, 128)),
        Some("article:loop" | "corrected:loop") => return Some((128, 56)),
        _ => {}
    }
    let first = text.lines().next()?;
    let rest = first.strip_prefix("// ps30 unroll: luminance pass 1")?;
    let before = &rest[..rest.find(" blocks")?];
    let size = before.rsplit(' ').next()?;
    let (bw, bh) = size.split_once('×')?;
    Some((bw.parse().ok()?, bh.parse().ok()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_come_from_headers_and_the_article() {
        assert_eq!(
            block_of("// ps30 unroll: luminance pass 1, unrolled form, 117×128 blocks, for a 1280×1024 frame\nps_3_0\n", None),
            Some((117, 128))
        );
        assert_eq!(
            block_of("// ps30 unroll: luminance pass 1 for the LAST column of 214×32 blocks, loop form, reading 210×32 texels, for a 1280×1024 frame\n", None),
            Some((214, 32))
        );
        assert_eq!(
            block_of("ps_3_0\n", Some("corrected:loop")),
            Some((128, 56))
        );
        assert_eq!(block_of("ps_3_0\n", None), None);
    }

    #[test]
    fn a_tiny_image_gets_blocks_of_its_size() {
        let p = planned(3, 7, 1e-4).unwrap();
        assert_eq!(p.block(), (3, 7));
        assert_eq!(p.candidate.padded_samples, 0);
        assert!(p.pass1.file.text.contains("ps_3_0"));
    }
}
