//! Multisampling and antialiased lines in draw lists, refused by name.
//!
//! Direct3D 9 names how many samples a render target has
//! (`D3DMULTISAMPLE_TYPE`, with a quality level per device) but not where
//! they lie in the pixel: sample positions are the hardware's (fixed
//! standard patterns arrived with Direct3D 10.1), so which samples an edge
//! covers, where a `_centroid` input is evaluated and what the resolve
//! averages would be one vendor's answer, not Direct3D 9's. Likewise
//! D3DRS_ANTIALIASEDLINEENABLE only asks for "antialiased" lines where
//! D3DLINECAPS_ANTIALIAS says the device has them; the coverage it computes
//! is not specified (the DirectX 9 SDK's "Line Drawing" page; the driver
//! guide's "Supporting Single-Pixel-Wide Antialiased Lines"). So a list
//! that asks for either is refused at the field, with the reason, rather
//! than drawn with a pattern ps30 would have to invent; the values that
//! change nothing (D3DMULTISAMPLE_NONE, quality 0, antialiased lines off)
//! are accepted.

use serde_json::Value;

/// Why a multisampled target is not drawn.
const WHY: &str = "Direct3D 9 leaves the sample positions to the hardware (no standard pattern before Direct3D 10.1), so edge coverage, `_centroid` and the resolve would be one vendor's; ps30 draws one sample per pixel (D3DMULTISAMPLE_NONE)";

/// A target's `multisample` (a D3DMULTISAMPLE_TYPE name, its short form
/// `none`/`4_samples`, or its number) and `multisample_quality`: `Ok` for
/// one sample per pixel, else the message for the field that asks for more
/// (`quality` is true when that field is `multisample_quality`).
pub(crate) fn check_target(
    kind: Option<&Value>,
    quality: Option<u32>,
) -> Result<(), (bool, String)> {
    let samples = match kind {
        None => 0,
        Some(Value::Number(n)) => n.as_u64().filter(|&n| n <= 16).ok_or_else(|| {
            (false, format!("{n} is not a D3DMULTISAMPLE_TYPE (0 to 16)"))
        })?,
        Some(Value::String(s)) => samples_of(s).ok_or_else(|| {
            (
                false,
                format!("`{s}` is not a D3DMULTISAMPLE_TYPE (D3DMULTISAMPLE_NONE, _NONMASKABLE, _2_SAMPLES … _16_SAMPLES)"),
            )
        })?,
        Some(other) => {
            return Err((false, format!("{other} is not a D3DMULTISAMPLE_TYPE name or number")))
        }
    };
    if samples != 0 {
        let name = match samples {
            1 => "D3DMULTISAMPLE_NONMASKABLE".to_string(),
            n => format!("D3DMULTISAMPLE_{n}_SAMPLES"),
        };
        return Err((false, format!("{name} is not drawn: {WHY}")));
    }
    match quality {
        Some(q) if q > 0 => Err((
            true,
            format!("quality {q} needs a multisampled target (D3DMULTISAMPLE_NONE has quality 0 only), which is not drawn: {WHY}"),
        )),
        _ => Ok(()),
    }
}

/// D3DMULTISAMPLE_TYPE's number for a name, with or without the prefix,
/// in any case.
fn samples_of(name: &str) -> Option<u64> {
    let upper = name.to_ascii_uppercase();
    let short = upper.strip_prefix("D3DMULTISAMPLE_").unwrap_or(&upper);
    match short {
        "NONE" => Some(0),
        "NONMASKABLE" => Some(1),
        _ => short
            .strip_suffix("_SAMPLES")
            .and_then(|n| n.parse::<u64>().ok())
            .filter(|n| (2..=16).contains(n)),
    }
}

/// A draw's `antialiased_lines` (D3DRS_ANTIALIASEDLINEENABLE) where the
/// draw has lines (line primitives, wireframe triangles; elsewhere the
/// state changes nothing and the caller passes `None`): `Ok` when off or
/// absent, else why it is not drawn.
pub(crate) fn check_lines(on: Option<bool>) -> Result<(), String> {
    if on == Some(true) {
        return Err("D3DRS_ANTIALIASEDLINEENABLE is not drawn: Direct3D 9 leaves an antialiased line's coverage to the hardware (D3DLINECAPS_ANTIALIAS says a device has them, nothing says what they cover); ps30 draws lines aliased, by the diamond-exit rule (false, the default)".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn one_sample_is_accepted_and_more_are_refused_by_name() {
        for ok in [
            None,
            Some(json!(0)),
            Some(json!("D3DMULTISAMPLE_NONE")),
            Some(json!("none")),
        ] {
            assert_eq!(check_target(ok.as_ref(), Some(0)), Ok(()));
        }
        let e = check_target(Some(&json!("4_samples")), None).unwrap_err();
        assert!(
            !e.0 && e.1.starts_with("D3DMULTISAMPLE_4_SAMPLES is not drawn: "),
            "{e:?}"
        );
        let e = check_target(Some(&json!(1)), None).unwrap_err();
        assert!(
            e.1.starts_with("D3DMULTISAMPLE_NONMASKABLE is not drawn"),
            "{e:?}"
        );
        assert!(check_target(Some(&json!(17)), None).is_err());
        assert!(check_target(Some(&json!("D3DMULTISAMPLE_1_SAMPLES")), None).is_err());
        assert!(check_target(None, Some(1)).unwrap_err().0);
        assert_eq!(check_lines(Some(false)), Ok(()));
        assert!(check_lines(Some(true)).is_err());
    }
}
