//! Shader profiles (shader models) as one parameter: which one a shader is,
//! read from its version token or its version line, and what that profile
//! allows — its register files and its limits. Which instructions exist in
//! which profile is a column of the instruction table
//! ([`isa::Opcode::profiles`](crate::core::isa::Opcode::profiles)).
//!
//! ps30 checks, runs and writes ps_3_0. Every other Direct3D 9 profile is
//! recognised and named, its rules are here, measured against Microsoft's
//! assembler (`tests/oracle/corpus/asm/profiles/`, docs/profiles.md), and
//! [`Profile::checked`] says which ones the rest of ps30 takes today.
//!
//! Two facts from Microsoft's tools shape the type:
//!
//! * `ps_2_a`, `ps_2_b` and `vs_2_a` are names of compile targets only. A
//!   shader compiled for them carries the `ps_2_x` / `vs_2_x` version token
//!   (`0xFFFF0201`, `0xFFFE0201`), and `D3DAssemble` refuses them as a
//!   version line (X2001, "shader version expected"). They are the
//!   `ps_2_x`/`vs_2_x` profile under fixed capabilities ([`Ps2xCaps`]).
//! * `ps_2_x` itself is a profile whose limits are a device's capabilities
//!   (D3DPSHADERCAPS2_0): [`Ps2xCaps`] holds them as options, with the set
//!   Microsoft's assembler checks a `ps_2_x` file against
//!   ([`Ps2xCaps::ASSEMBLER`], measured) and the two named targets'.

use std::fmt;

/// Which pipeline stage a profile programs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// A pixel shader (`ps_…`, version tokens `0xFFFF….`).
    Pixel,
    /// A vertex shader (`vs_…`, version tokens `0xFFFE….`).
    Vertex,
}

/// One Direct3D 9 shader profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
pub enum Profile {
    /// `ps_1_1`.
    Ps1_1,
    /// `ps_1_2`.
    Ps1_2,
    /// `ps_1_3`.
    Ps1_3,
    /// `ps_1_4`.
    Ps1_4,
    /// `ps_2_0`.
    Ps2_0,
    /// `ps_2_a`: an HLSL target; its bytecode is `ps_2_x`.
    Ps2A,
    /// `ps_2_b`: an HLSL target; its bytecode is `ps_2_x`.
    Ps2B,
    /// `ps_2_x`: ps_2_0 extended by device capabilities.
    Ps2X,
    /// `ps_3_0`.
    Ps3_0,
    /// `vs_1_1`.
    Vs1_1,
    /// `vs_2_0`.
    Vs2_0,
    /// `vs_2_a`: an HLSL target; its bytecode is `vs_2_x`.
    Vs2A,
    /// `vs_2_x`: vs_2_0 extended by device capabilities.
    Vs2X,
    /// `vs_3_0`.
    Vs3_0,
}

/// A set of profiles (one bit each), for the instruction table's column.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ProfileSet(u16);

impl ProfileSet {
    /// No profile.
    pub const NONE: ProfileSet = ProfileSet(0);

    /// The set of the listed profiles.
    pub const fn of(profiles: &[Profile]) -> ProfileSet {
        let mut bits = 0u16;
        let mut i = 0;
        while i < profiles.len() {
            bits |= 1 << profiles[i] as u16;
            i += 1;
        }
        ProfileSet(bits)
    }

    /// Both sets' profiles.
    pub const fn or(self, other: ProfileSet) -> ProfileSet {
        ProfileSet(self.0 | other.0)
    }

    /// Whether `p` is in the set.
    pub const fn has(self, p: Profile) -> bool {
        self.0 & (1 << p as u16) != 0
    }
}

/// The size of a profile's register files: how many of each register a
/// shader may name (0: the profile has no such file).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Registers {
    /// Temporaries `r#`.
    pub temps: u32,
    /// Float constants `c#`. For vertex shaders the documented minimum
    /// (256): a device may have more, and Microsoft's assembler takes any
    /// index (`c256` is accepted in vs_2_0, vs_2_x and vs_3_0).
    pub float_consts: u32,
    /// Integer constants `i#`.
    pub int_consts: u32,
    /// Boolean constants `b#`.
    pub bool_consts: u32,
    /// Inputs `v#` (colours in ps_2_x; anything declared in ps_3_0 and vs).
    pub inputs: u32,
    /// Texture coordinates `t#` (ps_2_x and ps_1_x only).
    pub texcoords: u32,
    /// Samplers `s#`.
    pub samplers: u32,
    /// Colour outputs `oC#` (pixel shaders).
    pub colour_outputs: u32,
    /// Output registers `o#` (vs_3_0), or the named outputs' count in
    /// vs_1_1–vs_2_x (`oPos`, `oD0`–`oD1`, `oT0`–`oT7`, `oFog`, `oPts`: 12).
    pub outputs: u32,
    /// Whether the predicate register `p0` exists.
    pub predicate: bool,
    /// Whether the address register `a0` exists (vertex shaders).
    pub address: bool,
    /// Whether the loop counter `aL` exists.
    pub loop_counter: bool,
}

/// A profile's slot and flow-control limits. `None`: the profile has no
/// such limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Limits {
    /// Instruction slots in all (Microsoft's assembler refuses more: X5617
    /// in ps_2_x, X5755 in vs_2_x).
    pub slots: Option<u32>,
    /// Arithmetic (non-texture) slots (ps_2_0: 64, X5234 past it; ps_2_x:
    /// the total limit applies to them as well, X5234 then X5617).
    pub arithmetic: Option<u32>,
    /// Texture slots (ps_2_0: 32, X5607 past it).
    pub texture: Option<u32>,
    /// Levels of dependent texture reads (ps_2_0: 4, the first read and
    /// three that depend on it; X5775 past it).
    pub dependent_reads: Option<u32>,
    /// Nesting depth of static flow control (`if b#`, `rep`, `loop`,
    /// `call`).
    pub static_flow_depth: u32,
    /// Nesting depth of dynamic flow control (`if_comp`, `if p0`,
    /// `break_comp`, `breakp`, `callnz p0`).
    pub dynamic_flow_depth: u32,
    /// Executed instructions per invocation, where a profile bounds them.
    pub executed: Option<u32>,
}

/// The capabilities a `ps_2_x` shader is checked against
/// (D3DPSHADERCAPS2_0 and the instruction-slot count): options, like the
/// device caps they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Ps2xCaps {
    /// Predication: `setp`, `(p0)` and the `p0` forms of flow control.
    pub predication: bool,
    /// `dsx`, `dsy` and `texldd`.
    pub gradients: bool,
    /// Any swizzle on a source (otherwise ps_2_0's few).
    pub arbitrary_swizzle: bool,
    /// No limit on dependent texture reads.
    pub no_dependent_read_limit: bool,
    /// No separate limit on texture instructions.
    pub no_texture_instruction_limit: bool,
    /// Temporaries, 12 to 32.
    pub temps: u32,
    /// Instruction slots, 96 to 512.
    pub slots: u32,
    /// Nesting depth of static flow control, 0 to 4.
    pub static_flow_depth: u32,
    /// Nesting depth of dynamic flow control, 0 to 24.
    pub dynamic_flow_depth: u32,
}

impl Ps2xCaps {
    /// What `D3DAssemble` checks a `ps_2_x` file against, as measured: every
    /// option on, 512 slots (513 arithmetic slots refused, X5234 and
    /// X5617), 32 temporaries (`r31` accepted, `r32` X2005), no dependent
    /// read limit (five levels accepted) and no texture limit (33 accepted).
    /// The flow-control depths are the documented maxima, not measured.
    pub const ASSEMBLER: Ps2xCaps = Ps2xCaps {
        predication: true,
        gradients: true,
        arbitrary_swizzle: true,
        no_dependent_read_limit: true,
        no_texture_instruction_limit: true,
        temps: 32,
        slots: 512,
        static_flow_depth: 4,
        dynamic_flow_depth: 24,
    };

    /// The `ps_2_a` target (Microsoft's documentation of ps_2_x).
    pub const PS_2_A: Ps2xCaps = Ps2xCaps {
        temps: 22,
        ..Ps2xCaps::ASSEMBLER
    };

    /// The `ps_2_b` target: ps_2_0's instructions and `texldd`, with 32
    /// temporaries, 512 slots and no texture limit. Microsoft's
    /// documentation also lifts the dependent-read limit, but its compiler
    /// keeps it (measured: five levels refused for ps_2_b, X4018, accepted
    /// for ps_2_a), and it writes `texldd` for `tex2Dgrad` although `ddx`
    /// is refused (X4532), so `gradients` stays off and the instruction
    /// table lists `texldd` for ps_2_b alone.
    pub const PS_2_B: Ps2xCaps = Ps2xCaps {
        predication: false,
        gradients: false,
        arbitrary_swizzle: false,
        no_dependent_read_limit: false,
        no_texture_instruction_limit: true,
        temps: 32,
        slots: 512,
        static_flow_depth: 0,
        dynamic_flow_depth: 0,
    };

    /// Capabilities as a person names them (`ps30 … --caps LIST`): a
    /// comma-separated list that starts from [`Ps2xCaps::MINIMUM`] and turns
    /// on each flag it names — `predication`, `gradients`,
    /// `arbitrary-swizzle`, `no-dependent-read-limit`,
    /// `no-texture-instruction-limit`, or D3DPS20CAPS's own names
    /// (`D3DPS20CAPS_PREDICATION`, `GRADIENTINSTRUCTIONS`, `ARBITRARYSWIZZLE`,
    /// `NODEPENDENTREADLIMIT`, `NOTEXINSTRUCTIONLIMIT`) — and sets each number
    /// it gives: `temps=N` (NumTemps, 12–32), `slots=N`
    /// (NumInstructionSlots, 96–512), `static-flow=N`
    /// (StaticFlowControlDepth, 0–4), `dynamic-flow=N`
    /// (DynamicFlowControlDepth, 0–24). A named set replaces everything
    /// before it: `assembler` (what `D3DAssemble` assumes, the default),
    /// `ps_2_a`, `ps_2_b`, `minimum`.
    pub fn parse(text: &str) -> Result<Ps2xCaps, String> {
        let mut caps = Ps2xCaps::MINIMUM;
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let lower = item.to_ascii_lowercase().replace('_', "-");
            let name = lower.strip_prefix("d3dps20caps-").unwrap_or(&lower);
            let (key, value) = match name.split_once('=') {
                Some((k, v)) => (k.trim(), Some(v.trim())),
                None => (name, None),
            };
            let number = |lo: u32, hi: u32| -> Result<u32, String> {
                let v = value.ok_or_else(|| format!("`{item}` needs a value: {key}=N"))?;
                v.parse::<u32>()
                    .ok()
                    .filter(|n| (lo..=hi).contains(n))
                    .ok_or_else(|| format!("`{item}`: {key} is {lo} to {hi}"))
            };
            match (key, value.is_some()) {
                ("assembler", false) => caps = Ps2xCaps::ASSEMBLER,
                ("ps-2-a", false) => caps = Ps2xCaps::PS_2_A,
                ("ps-2-b", false) => caps = Ps2xCaps::PS_2_B,
                ("minimum", false) => caps = Ps2xCaps::MINIMUM,
                ("predication", false) => caps.predication = true,
                ("gradients" | "gradientinstructions", false) => caps.gradients = true,
                ("arbitrary-swizzle" | "arbitraryswizzle", false) => caps.arbitrary_swizzle = true,
                ("no-dependent-read-limit" | "nodependentreadlimit", false) => {
                    caps.no_dependent_read_limit = true
                }
                ("no-texture-instruction-limit" | "notexinstructionlimit", false) => {
                    caps.no_texture_instruction_limit = true
                }
                ("temps" | "numtemps", _) => caps.temps = number(12, 32)?,
                ("slots" | "numinstructionslots", _) => caps.slots = number(96, 512)?,
                ("static-flow" | "staticflowcontroldepth", _) => {
                    caps.static_flow_depth = number(0, 4)?
                }
                ("dynamic-flow" | "dynamicflowcontroldepth", _) => {
                    caps.dynamic_flow_depth = number(0, 24)?
                }
                _ => {
                    return Err(format!(
                    "`{item}` is no ps_2_x capability (predication, gradients, arbitrary-swizzle, \
                         no-dependent-read-limit, no-texture-instruction-limit, temps=N, slots=N, \
                         static-flow=N, dynamic-flow=N; or assembler, ps_2_a, ps_2_b, minimum)"
                ))
                }
            }
        }
        Ok(caps)
    }

    /// The slot and flow-control limits these capabilities set.
    pub fn limits(self) -> Limits {
        Limits {
            slots: Some(self.slots),
            arithmetic: Some(self.slots),
            texture: (!self.no_texture_instruction_limit).then_some(32),
            dependent_reads: (!self.no_dependent_read_limit).then_some(4),
            static_flow_depth: self.static_flow_depth,
            dynamic_flow_depth: self.dynamic_flow_depth,
            executed: Some(self.slots),
        }
    }

    /// The least a ps_2_x device has: every option off, 12 temporaries, 96
    /// slots.
    pub const MINIMUM: Ps2xCaps = Ps2xCaps {
        predication: false,
        gradients: false,
        arbitrary_swizzle: false,
        no_dependent_read_limit: false,
        no_texture_instruction_limit: false,
        temps: 12,
        slots: 96,
        static_flow_depth: 0,
        dynamic_flow_depth: 0,
    };
}

impl Profile {
    /// Every profile, in the order of the enum.
    pub const ALL: [Profile; 14] = [
        Profile::Ps1_1,
        Profile::Ps1_2,
        Profile::Ps1_3,
        Profile::Ps1_4,
        Profile::Ps2_0,
        Profile::Ps2A,
        Profile::Ps2B,
        Profile::Ps2X,
        Profile::Ps3_0,
        Profile::Vs1_1,
        Profile::Vs2_0,
        Profile::Vs2A,
        Profile::Vs2X,
        Profile::Vs3_0,
    ];

    /// The profile's name as a version line and a compile target spell it.
    pub fn name(self) -> &'static str {
        match self {
            Profile::Ps1_1 => "ps_1_1",
            Profile::Ps1_2 => "ps_1_2",
            Profile::Ps1_3 => "ps_1_3",
            Profile::Ps1_4 => "ps_1_4",
            Profile::Ps2_0 => "ps_2_0",
            Profile::Ps2A => "ps_2_a",
            Profile::Ps2B => "ps_2_b",
            Profile::Ps2X => "ps_2_x",
            Profile::Ps3_0 => "ps_3_0",
            Profile::Vs1_1 => "vs_1_1",
            Profile::Vs2_0 => "vs_2_0",
            Profile::Vs2A => "vs_2_a",
            Profile::Vs2X => "vs_2_x",
            Profile::Vs3_0 => "vs_3_0",
        }
    }

    /// The profile a name spells (`ps_2_0`, `vs_3_0`; the HLSL target names
    /// `ps_2_a`, `ps_2_b`, `vs_2_a` too), or `None`.
    pub fn from_name(name: &str) -> Option<Profile> {
        Profile::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The pipeline stage.
    pub fn stage(self) -> Stage {
        if self.name().starts_with("ps") {
            Stage::Pixel
        } else {
            Stage::Vertex
        }
    }

    /// The version token a shader of this profile starts with. `ps_2_a` and
    /// `ps_2_b` write `ps_2_x`'s, `vs_2_a` `vs_2_x`'s.
    pub fn version_token(self) -> u32 {
        let kind: u32 = match self.stage() {
            Stage::Pixel => 0xFFFF_0000,
            Stage::Vertex => 0xFFFE_0000,
        };
        let (major, minor) = match self {
            Profile::Ps1_1 | Profile::Vs1_1 => (1, 1),
            Profile::Ps1_2 => (1, 2),
            Profile::Ps1_3 => (1, 3),
            Profile::Ps1_4 => (1, 4),
            Profile::Ps2_0 | Profile::Vs2_0 => (2, 0),
            Profile::Ps2A | Profile::Ps2B | Profile::Ps2X | Profile::Vs2A | Profile::Vs2X => (2, 1),
            Profile::Ps3_0 | Profile::Vs3_0 => (3, 0),
        };
        kind | major << 8 | minor
    }

    /// The profile a version token names, if any (`0xFFFF0201` is
    /// `ps_2_x`, whichever target wrote it).
    pub fn from_token(token: u32) -> Option<Profile> {
        [
            Profile::Ps1_1,
            Profile::Ps1_2,
            Profile::Ps1_3,
            Profile::Ps1_4,
            Profile::Ps2_0,
            Profile::Ps2X,
            Profile::Ps3_0,
            Profile::Vs1_1,
            Profile::Vs2_0,
            Profile::Vs2X,
            Profile::Vs3_0,
        ]
        .into_iter()
        .find(|p| p.version_token() == token)
    }

    /// The profile of a version line as written (`ps_2_0`, `ps.2.0`,
    /// `vs_2_x`), or `None` for a version no Direct3D 9 profile has
    /// (`ps_2_1`, `ps_2_sw`, `ps_4_0`). Whether Microsoft's assembler reads
    /// the line is [`Profile::assembles`].
    pub fn from_version_line(text: &str) -> Option<Profile> {
        Profile::from_name(&text.replace('.', "_"))
    }

    /// Whether Microsoft's assembler reads the profile's name as a version
    /// line: every profile but the three HLSL-only target names (measured:
    /// `ps_2_a`, `ps_2_b`, `vs_2_a` are X2001).
    pub fn assembles(self) -> bool {
        !matches!(self, Profile::Ps2A | Profile::Ps2B | Profile::Vs2A)
    }

    /// Whether ps30 reads, checks, counts, assembles and lists shaders of
    /// this profile: ps_1_1–ps_1_4 (through `core::ps1`), ps_2_0, ps_2_x,
    /// ps_3_0, vs_2_0, vs_2_x and vs_3_0. The others (vs_1_1 and the
    /// HLSL-only target names) are recognised and refused with their name.
    pub fn checked(self) -> bool {
        self.is_ps1()
            || matches!(
                self,
                Profile::Ps2_0
                    | Profile::Ps2X
                    | Profile::Ps3_0
                    | Profile::Vs2_0
                    | Profile::Vs2X
                    | Profile::Vs3_0
            )
    }

    /// Whether the profile is one of ps_1_1–ps_1_4, whose instruction set,
    /// syntax and token stream are their own (`core::ps1`).
    pub fn is_ps1(self) -> bool {
        matches!(
            self,
            Profile::Ps1_1 | Profile::Ps1_2 | Profile::Ps1_3 | Profile::Ps1_4
        )
    }

    /// The `ps_2_x` capabilities a profile is checked against: the two named
    /// targets' and the assembler's for `ps_2_x` itself; `None` for every
    /// other profile.
    pub fn ps2x_caps(self) -> Option<Ps2xCaps> {
        match self {
            Profile::Ps2A => Some(Ps2xCaps::PS_2_A),
            Profile::Ps2B => Some(Ps2xCaps::PS_2_B),
            Profile::Ps2X => Some(Ps2xCaps::ASSEMBLER),
            _ => None,
        }
    }

    /// The register files (see [`Registers`]). ps_2_0 and ps_2_x edges were
    /// measured with Microsoft's assembler (`r11`/`r12`, `c31`/`c32`,
    /// `t7`/`t8`, `v1`/`v2`, `s15`/`s16`, `oC3`/`oC4`; `r31`/`r32` in
    /// ps_2_x, vs_2_x, vs_3_0; `v15`/`v16` in vs); the rest are Microsoft's
    /// documentation.
    pub fn registers(self) -> Registers {
        let pixel2 = |temps| Registers {
            temps,
            float_consts: 32,
            int_consts: 16,
            bool_consts: 16,
            inputs: 2,
            texcoords: 8,
            samplers: 16,
            colour_outputs: 4,
            outputs: 0,
            predicate: true,
            address: false,
            loop_counter: false,
        };
        let vertex = |temps, loops| Registers {
            temps,
            float_consts: 256,
            int_consts: 16,
            bool_consts: 16,
            inputs: 16,
            texcoords: 0,
            samplers: 0,
            colour_outputs: 0,
            outputs: 12,
            predicate: true,
            address: true,
            loop_counter: loops,
        };
        match self {
            Profile::Ps1_1 | Profile::Ps1_2 | Profile::Ps1_3 => Registers {
                float_consts: 8,
                inputs: 2,
                int_consts: 0,
                bool_consts: 0,
                texcoords: 4,
                samplers: 0,
                predicate: false,
                ..pixel2(2)
            },
            Profile::Ps1_4 => Registers {
                float_consts: 8,
                inputs: 2,
                int_consts: 0,
                bool_consts: 0,
                texcoords: 6,
                samplers: 0,
                predicate: false,
                ..pixel2(6)
            },
            Profile::Ps2_0 => Registers {
                int_consts: 0,
                bool_consts: 0,
                predicate: false,
                ..pixel2(12)
            },
            Profile::Ps2A | Profile::Ps2B | Profile::Ps2X => {
                let caps = self.ps2x_caps().unwrap_or(Ps2xCaps::ASSEMBLER);
                Registers {
                    predicate: caps.predication,
                    ..pixel2(caps.temps)
                }
            }
            Profile::Ps3_0 => Registers {
                float_consts: 224,
                inputs: 10,
                texcoords: 0,
                loop_counter: true,
                ..pixel2(32)
            },
            Profile::Vs1_1 => Registers {
                float_consts: 96,
                int_consts: 0,
                bool_consts: 0,
                predicate: false,
                ..vertex(12, false)
            },
            Profile::Vs2_0 => Registers {
                predicate: false,
                ..vertex(12, true)
            },
            Profile::Vs2A => vertex(13, true),
            Profile::Vs2X => vertex(32, true),
            Profile::Vs3_0 => Registers {
                samplers: 4,
                ..vertex(32, true)
            },
        }
    }

    /// The slot and flow-control limits (see [`Limits`]): measured with
    /// Microsoft's assembler where it enforces them (ps_2_0's 64 + 32 and
    /// four dependent levels, ps_2_x's 512, vs_2_0's and vs_2_x's 256),
    /// Microsoft's documentation otherwise. ps_3_0's 512 is a minimum the
    /// assembler does not enforce (ps30 warns past it).
    pub fn limits(self) -> Limits {
        let none = Limits {
            slots: None,
            arithmetic: None,
            texture: None,
            dependent_reads: None,
            static_flow_depth: 0,
            dynamic_flow_depth: 0,
            executed: None,
        };
        match self {
            // No flow control: every slot runs once.
            Profile::Ps1_1 | Profile::Ps1_2 | Profile::Ps1_3 => Limits {
                slots: Some(12),
                arithmetic: Some(8),
                texture: Some(4),
                executed: Some(12),
                ..none
            },
            // Per phase 6 texture and 8 arithmetic slots (core::ps1::rules).
            Profile::Ps1_4 => Limits {
                slots: Some(28),
                arithmetic: Some(16),
                texture: Some(12),
                dependent_reads: Some(2),
                executed: Some(28),
                ..none
            },
            // No flow control: every slot runs once, so 96 executed.
            Profile::Ps2_0 => Limits {
                slots: Some(96),
                arithmetic: Some(64),
                texture: Some(32),
                dependent_reads: Some(4),
                executed: Some(96),
                ..none
            },
            Profile::Ps2A | Profile::Ps2B | Profile::Ps2X => {
                self.ps2x_caps().unwrap_or(Ps2xCaps::ASSEMBLER).limits()
            }
            Profile::Ps3_0 | Profile::Vs3_0 => Limits {
                slots: Some(512),
                static_flow_depth: 4,
                dynamic_flow_depth: 24,
                executed: Some(65_535),
                ..none
            },
            Profile::Vs1_1 => Limits {
                slots: Some(128),
                ..none
            },
            Profile::Vs2_0 => Limits {
                slots: Some(256),
                static_flow_depth: 4,
                executed: Some(1_024),
                ..none
            },
            Profile::Vs2A | Profile::Vs2X => Limits {
                slots: Some(256),
                static_flow_depth: 4,
                dynamic_flow_depth: 24,
                executed: Some(65_535),
                ..none
            },
        }
    }
}

impl Default for Profile {
    /// ps_3_0, the profile ps30 runs.
    fn default() -> Profile {
        Profile::Ps3_0
    }
}

impl fmt::Display for Profile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_tokens_and_version_lines_agree() {
        for p in Profile::ALL {
            assert_eq!(Profile::from_name(p.name()), Some(p));
            let t = p.version_token();
            let named = Profile::from_token(t).unwrap();
            assert_eq!(named.version_token(), t, "{p}");
            assert_eq!(named == p, p.assembles(), "{p}");
            assert_eq!(Profile::from_version_line(p.name()), Some(p));
        }
        assert_eq!(Profile::from_token(0xFFFF_0201), Some(Profile::Ps2X));
        assert_eq!(Profile::from_token(0xFFFE_0300), Some(Profile::Vs3_0));
        assert_eq!(Profile::from_token(0xFFFF_0202), None);
        assert_eq!(Profile::from_token(0xFFFF_0400), None);
        assert_eq!(Profile::from_version_line("ps.2.0"), Some(Profile::Ps2_0));
        assert_eq!(Profile::from_version_line("ps_2_1"), None);
        assert_eq!(Profile::from_version_line("ps_2_sw"), None);
    }

    #[test]
    fn caps_parse_from_lists_and_named_sets() {
        assert_eq!(Ps2xCaps::parse(""), Ok(Ps2xCaps::MINIMUM));
        assert_eq!(Ps2xCaps::parse("assembler"), Ok(Ps2xCaps::ASSEMBLER));
        assert_eq!(Ps2xCaps::parse("ps_2_b"), Ok(Ps2xCaps::PS_2_B));
        let c = Ps2xCaps::parse("D3DPS20CAPS_PREDICATION,dynamic-flow=24,temps=22").unwrap();
        assert!(c.predication && !c.gradients);
        assert_eq!((c.dynamic_flow_depth, c.temps, c.slots), (24, 22, 96));
        let c = Ps2xCaps::parse("ps_2_a,slots=256").unwrap();
        assert_eq!((c.temps, c.slots), (22, 256));
        assert!(Ps2xCaps::parse("temps=40").is_err());
        assert!(Ps2xCaps::parse("temps").is_err());
        assert!(Ps2xCaps::parse("loops").is_err());
    }

    #[test]
    fn sets_hold_what_they_are_made_of() {
        let s = ProfileSet::of(&[Profile::Ps2_0, Profile::Vs3_0]);
        assert!(s.has(Profile::Ps2_0) && s.has(Profile::Vs3_0));
        assert!(!s.has(Profile::Ps3_0) && !ProfileSet::NONE.has(Profile::Ps2_0));
        assert!(s.or(ProfileSet::of(&[Profile::Ps3_0])).has(Profile::Ps3_0));
    }

    #[test]
    fn ps_2_0_limits_are_64_plus_32_with_four_levels() {
        let l = Profile::Ps2_0.limits();
        assert_eq!(
            (l.arithmetic, l.texture, l.dependent_reads),
            (Some(64), Some(32), Some(4))
        );
        assert_eq!(Profile::Vs2_0.limits().slots, Some(256));
        assert_eq!(Profile::Ps2B.registers().temps, 32);
        assert_eq!(Profile::Ps2A.registers().temps, 22);
        assert!(!Profile::Ps2_0.registers().predicate);
    }
}
