//! Float values in a draw list. JSON has no ∞ or NaN, and Direct3D 9 takes
//! any 32-bit pattern through `SetPixelShaderConstantF`, so a constant's
//! component is a JSON number or a string spelled as `--const` spells it
//! (`"inf"`, `"-inf"`, `"nan"`, `"0x7f800000"`: `numbers::parse_constant`).

use crate::core::numbers::parse_constant;
use serde::Deserialize;

/// One component of a float constant as the file gives it.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub(crate) enum FileFloat {
    /// A JSON number (must be within f32's range).
    Number(f64),
    /// A spelled value: a decimal, `inf`, `-inf`, `nan` or hex bits.
    Text(String),
}

impl FileFloat {
    /// The f32 the component stands for.
    fn value(&self) -> Result<f32, String> {
        match self {
            FileFloat::Number(x) => {
                let f = *x as f32;
                if f.is_finite() {
                    Ok(f)
                } else {
                    Err(format!(
                        "{x} is beyond f32's range (write \"inf\" or \"-inf\" for an infinity)"
                    ))
                }
            }
            FileFloat::Text(s) => parse_constant(s),
        }
    }
}

/// `v` as 1 to 4 f32s (missing components 0), any bit pattern allowed.
pub(crate) fn constant4(v: &[FileFloat]) -> Result<[f32; 4], String> {
    if v.is_empty() || v.len() > 4 {
        return Err(format!("expected 1 to 4 numbers, got {}", v.len()));
    }
    let mut out = [0f32; 4];
    for (o, x) in out.iter_mut().zip(v) {
        *o = x.value()?;
    }
    Ok(out)
}
