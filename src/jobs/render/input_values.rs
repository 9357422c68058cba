//! An input's value as a person writes it on the command line
//! (`ps30 run --input t1=0.25,0.5`): the register or semantic it names,
//! resolved against the shader (`core/pixel_inputs.rs`), and a value that
//! is the same at every pixel or the target's own texture coordinates.

use crate::core::emu::LinearInput;
use crate::core::ir::Program;

/// `NAME=texcoord[,Z,W]` (x, y: pixel centres in [0, 1] of a `width ×
/// height` target; z, w as given, else 0) or `NAME=X[,Y,Z,W]` (the same at every pixel; missing components are 0,
/// each any 32-bit pattern `--const` takes) as `(slot, value)`.
pub fn parse(
    program: &Program,
    text: &str,
    size: (u32, u32),
) -> Result<(u32, LinearInput), String> {
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| format!("`{text}` is not NAME=texcoord or NAME=X[,Y,Z,W]"))?;
    let slot = crate::core::pixel_inputs::resolve(program, name.trim())?;
    let mut parts: Vec<&str> = value.split(',').collect();
    let texcoord = parts[0].trim().eq_ignore_ascii_case("texcoord");
    if texcoord {
        parts.remove(0);
        if parts.len() > 2 {
            return Err(format!("`{value}`: texcoord takes z and w at most"));
        }
    }
    if parts.len() > 4 {
        return Err(format!(
            "`{value}` has {} components; an input has 4",
            parts.len()
        ));
    }
    let mut base = [0.0f32; 4];
    let first = if texcoord { 2 } else { 0 };
    for (c, p) in parts.iter().enumerate() {
        base[first + c] =
            crate::core::numbers::parse_constant(p).map_err(|e| format!("{name}: {e}"))?;
    }
    if texcoord {
        let mut t = super::texcoord(size.0, size.1);
        t.base[2..].copy_from_slice(&base[2..]);
        return Ok((slot, t));
    }
    Ok((
        slot,
        LinearInput {
            base,
            ddx: [0.0; 4],
            ddy: [0.0; 4],
        },
    ))
}

/// An input's value as an inputs file gives it (`"inputs": {"t0":
/// "texcoord"}`), before the shader and the target are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Given {
    /// The pixel centres in [0, 1] of whatever target the draw has.
    Texcoord,
    /// A value with its per-pixel steps.
    Linear(LinearInput),
}

/// The inputs a file names, resolved against the shader (`(slot, value)`).
pub fn resolve_all(
    program: &Program,
    given: &[(String, Given)],
    size: (u32, u32),
) -> Result<Vec<(u32, LinearInput)>, String> {
    given
        .iter()
        .map(|(name, g)| {
            let slot = crate::core::pixel_inputs::resolve(program, name)
                .map_err(|e| format!("inputs.{name}: {e}"))?;
            Ok(match g {
                Given::Texcoord => (slot, super::texcoord(size.0, size.1)),
                Given::Linear(l) => (slot, *l),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::profile::Profile;

    #[test]
    fn constant_and_texcoord_values() {
        let p = Program {
            profile: Profile::Ps2_0,
            ..Program::default()
        };
        let (s, v) = parse(&p, "t1=0.25,0.5", (4, 4)).unwrap();
        assert_eq!((s, v.base), (3, [0.25, 0.5, 0.0, 0.0]));
        let (s, v) = parse(&p, "color0=texcoord", (4, 2)).unwrap();
        assert_eq!((s, v.ddy[1]), (0, 0.5));
        let (_, v) = parse(&p, "t0=texcoord,0.5,2", (4, 2)).unwrap();
        assert_eq!(v.base, [0.125, 0.25, 0.5, 2.0]);
        assert!(parse(&p, "t0=texcoord,1,2,3", (4, 4)).is_err());
        assert!(parse(&p, "t9=1", (4, 4)).is_err());
        assert!(parse(&p, "t0=1,2,3,4,5", (4, 4)).is_err());
        assert!(parse(&p, "t0", (4, 4)).is_err());
    }
}
