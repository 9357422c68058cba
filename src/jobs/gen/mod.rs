//! The generator: luminance shaders written by ps30 instead of by hand, and
//! the frame plans that choose them (`ps30 unroll`, `ps30 plan`).
//!
//! # Why it exists
//!
//! The article unrolls its pass-1 loop by cut and paste ("you will have to do
//! it manually using cut and paste or using your own code creator"), and picks
//! 125×128 blocks and an 11×8 intermediate target for a 1280×1024 frame by
//! reasoning about the limits. Both are mechanical and easy to get wrong: the
//! printed pass 1 resets u to the frame's edge, the printed pass 2 keeps the
//! BORDER padding in the mean (see `asm/corrected/`). This module does the
//! mechanical part for any frame size and any limits, and hands over shader
//! text that is proven to fit and, in the tests, proven to compute the right
//! answer.
//!
//! # Proof by construction
//!
//! Every listing is built as text (`asm.rs`), then loaded through the front
//! end and analysed by the cost model under the [`Profile`] ([`check`]). No
//! count is ever computed by hand: the headers' slots and executed figures,
//! every fit search and every figure of a plan come from [`cost::analyse`]
//! of a generated program. A shader that fails the check is never handed
//! over.
//!
//! # The generated code
//!
//! Set-up, u/v stepping and accumulation follow the article's listings, with
//! the two corrections ps30's emulator cross-check showed to be needed (see
//! `asm/corrected/`): each line ends with u = the block's start u (the
//! article set u = 0), and pass 2 subtracts the BORDER padding with c0.y.
//! The generator packs (dv, start u, du) into r3.yzw with one `mad` that
//! replaces the article's `mov r2.w, c1.x`, so the first correction costs no
//! instruction: the generated shaders have the article's exact counts
//! (125×128: 511 slots, 64,773 executed; 128×56: 20 slots, 64,853;
//! pass 2 for 11×8: 190 slots).

mod asm;
pub(crate) mod fit;
pub mod plan;
pub mod set;

pub use asm::{Pass1Form, Pass2Form};

/// The slot table the generator fits under: the documented one, which counts
/// every instruction at least as high as Microsoft's tools do, so a shader
/// that fits it fits either count. The generated listings use only
/// instructions the two tables cost alike (`texld` on 2D samplers, `mov`,
/// `add`, `mad`, `rep`, `endrep`, …), so their figures are the same under
/// both.
pub const FIT_TABLE: SlotTable = SlotTable::Documented;

/// The ps_3_0 profile the generator fits under ([`FIT_TABLE`]).
pub fn fitting_profile() -> Profile {
    Profile::ps_3_0().counting(FIT_TABLE)
}

use crate::core::cost::{self, Environment, Profile, Verdict};
use crate::core::isa::{Opcode, SlotTable};
use crate::core::load::{self, Options};
use crate::core::numbers::thousands;

/// A generator failure that is not "does not fit": the front end refused
/// text the generator wrote (a bug in ps30, reported with its diagnostics).
#[derive(Clone, Debug, PartialEq)]
pub struct GenError(pub String);

impl std::fmt::Display for GenError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for GenError {}

/// Front-end options for generated text: the expansion cap grows with the
/// slot limit, since a listing that fits has at most a few statements per
/// slot.
pub(crate) fn options(profile: &Profile) -> Options {
    Options {
        max_expanded: crate::core::front::repeat::DEFAULT_MAX_EXPANDED
            .max(profile.max_slots.saturating_mul(5).saturating_add(100)),
        ..Options::default()
    }
}

/// Loads generated text; a refusal is a generator bug.
pub(crate) fn load(name: &str, text: &str, profile: &Profile) -> Result<load::Loaded, GenError> {
    load::load_str(name, text, &options(profile)).map_err(|e| {
        GenError(format!(
            "ps30 generated a listing its own front end refuses (a bug):\n{}",
            e.diagnostics.render(&e.file)
        ))
    })
}

/// Deepest rep/loop nesting of a program.
pub fn loop_nesting(shader: &crate::core::ir::Shader) -> u32 {
    let (mut depth, mut max) = (0u32, 0u32);
    for i in shader.instructions() {
        match i.op {
            Opcode::Rep | Opcode::Loop => {
                depth += 1;
                max = max.max(depth);
            }
            Opcode::EndRep | Opcode::EndLoop => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    max
}

/// A listing that went through the front end and the cost model.
#[derive(Clone, Debug)]
pub struct Checked {
    /// Static instruction slots.
    pub slots: u64,
    /// Executed instruction slots per pixel (exact: generated shaders have
    /// no data-dependent flow).
    pub executed: u64,
    /// Deepest rep nesting.
    pub nesting: u32,
    /// Largest rep count.
    pub max_rep: u64,
    /// Why it does not fit the profile (empty when it fits).
    pub problems: Vec<String>,
}

impl Checked {
    /// Whether the shader fits the profile.
    pub fn fits(&self) -> bool {
        self.problems.is_empty()
    }
}

/// Loads `text` and measures it under `profile` (loop counts from `defi`
/// or, where the listing leaves them to the application, from `env`).
pub fn check_with(
    name: &str,
    text: &str,
    env: &Environment,
    profile: &Profile,
) -> Result<Checked, GenError> {
    let loaded = load(name, text, profile)?;
    measure(&loaded, env, profile)
}

/// [`check_with`] for a listing that defines all its loop counts.
pub fn check(name: &str, text: &str, profile: &Profile) -> Result<Checked, GenError> {
    check_with(name, text, &Environment::default(), profile)
}

pub(crate) fn measure(
    loaded: &load::Loaded,
    env: &Environment,
    profile: &Profile,
) -> Result<Checked, GenError> {
    let a = cost::analyse(&loaded.shader, &loaded.file, env, profile)
        .map_err(|e| GenError(format!("{}: {e}", loaded.file.name)))?;
    let nesting = loop_nesting(&loaded.shader);
    let max_rep = a.loops.iter().map(|l| l.iterations.max).max().unwrap_or(0);
    let mut problems = Vec::new();
    if !a.executed.is_exact() {
        problems.push(format!(
            "the executed count depends on data ({}–{})",
            a.executed.min, a.executed.max
        ));
    }
    if a.slots > profile.max_slots {
        problems.push(format!(
            "{} slots, over the limit of {} by {}",
            thousands(a.slots),
            thousands(profile.max_slots),
            thousands(a.slots - profile.max_slots)
        ));
    }
    if a.executed.max > profile.max_executed {
        problems.push(format!(
            "{} executed per pixel, over the limit of {} by {}",
            thousands(a.executed.max),
            thousands(profile.max_executed),
            thousands(a.executed.max - profile.max_executed)
        ));
    }
    if a.verdict != Verdict::Within && problems.is_empty() {
        problems.push("the cost model's verdict is not \"within limits\"".into());
    }
    if max_rep > profile.max_rep_count as u64 {
        problems.push(format!(
            "a rep count of {max_rep}, beyond the profile's {}",
            profile.max_rep_count
        ));
    }
    if nesting > profile.max_loop_nesting {
        problems.push(format!(
            "loops nested {nesting} deep, beyond the profile's {}",
            profile.max_loop_nesting
        ));
    }
    Ok(Checked {
        slots: a.slots,
        executed: a.executed.max,
        nesting,
        max_rep,
        problems,
    })
}

/// A profile's limits in one line: `512 slots, 65,535 executed, rep ≤ 255,
/// loops nested ≤ 4`.
pub fn profile_text(p: &Profile) -> String {
    format!(
        "{} slots, {} executed, rep counts ≤ {}, loops nested ≤ {}",
        thousands(p.max_slots),
        thousands(p.max_executed),
        p.max_rep_count,
        p.max_loop_nesting
    )
}
