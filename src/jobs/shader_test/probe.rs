//! `probe` lines: which target, which pixels, which values, checked the way
//! vkd3d's `check_readback_data_*` checks them — every pixel of the
//! rectangle, floats within the line's ulps by vkd3d's `compare_float`
//! (sign-magnitude bits as integers), integers exactly — on the target's
//! bytes as the Direct3D 9 runner reads them back: A32B32G32R32F pixels
//! are 16 bytes, R32F pixels 4, and a probe reads its own element size at
//! `x × size` within the row.

use super::parse::Cursor;
use super::state::{Last, State, Stop};
use super::Verdict;
use crate::core::image::RenderTarget;

/// What a probe compares.
enum Expected {
    /// Floats (1, 2 or 4 read from an element of 4, 16 or 16 bytes) within
    /// `ulps`.
    Floats {
        values: Vec<f32>,
        element: u32,
        ulps: u32,
    },
    /// 32-bit words, exactly (1 of 4 bytes or 4 of 16).
    Words { values: Vec<u32> },
}

/// vkd3d's `compare_float`: the bit patterns as sign-magnitude integers,
/// at most `ulps` apart.
pub(super) fn compare_float(f: f32, g: f32, ulps: u32) -> bool {
    let key = |v: f32| {
        let i = v.to_bits() as i32;
        (if i < 0 { i32::MIN.wrapping_sub(i) } else { i }) as u32
    };
    let (x, y) = (key(f), key(g));
    x.abs_diff(y) <= ulps
}

fn list<'a, T>(c: &mut Cursor<'a>, read: impl Fn(&mut Cursor<'a>) -> Option<T>) -> Option<Vec<T>> {
    if !c.char('(') {
        return None;
    }
    let mut out = vec![read(c)?];
    while c.char(',') {
        out.push(read(c)?);
    }
    c.char(')').then_some(out)
}

/// The rectangle `(left, top, right, bottom)` a probe covers.
fn rect(c: &mut Cursor<'_>, t: &RenderTarget) -> Result<[u32; 4], Verdict> {
    if c.word("all") {
        return Ok([0, 0, t.width, t.height]);
    }
    let v = list(c, Cursor::uint).ok_or_else(|| Verdict::Fail {
        detail: "malformed probe arguments".into(),
    })?;
    c.ws();
    match v.as_slice() {
        [l, tp, r, b] => Ok([*l, *tp, *r, *b]),
        [x, y, 0] | [x, y] => Ok([*x, *y, x + 1, y + 1]),
        [_, _, _] => Err(Verdict::Unsupported {
            reason: "probes of array layers".into(),
        }),
        [x] => Ok([*x, 0, x + 1, 1]),
        _ => Err(Verdict::Fail {
            detail: "malformed probe arguments".into(),
        }),
    }
}

fn unsupported(reason: &str) -> Verdict {
    Verdict::Unsupported {
        reason: reason.into(),
    }
}

/// The values a probe expects.
fn expected(c: &mut Cursor<'_>) -> Result<Expected, Verdict> {
    let bad = || Verdict::Fail {
        detail: "malformed probe values".into(),
    };
    let floats = |c: &mut Cursor<'_>, element: u32| -> Result<Expected, Verdict> {
        let values = list(c, Cursor::float).ok_or_else(bad)?;
        let ulps = c.uint().unwrap_or(0);
        Ok(Expected::Floats {
            values,
            element,
            ulps,
        })
    };
    for (word, n) in [("rgba", 4), ("rg", 2), ("r", 1)] {
        if c.word(word) {
            let e = floats(c, if n == 1 { 4 } else { 16 })?;
            return match &e {
                Expected::Floats { values, .. } if values.len() == n => Ok(e),
                _ => Err(bad()),
            };
        }
    }
    if c.word("f32") {
        let e = floats(c, 0)?;
        return match e {
            Expected::Floats { values, ulps, .. } if matches!(values.len(), 1 | 2 | 4) => {
                Ok(Expected::Floats {
                    element: if values.len() == 1 { 4 } else { 16 },
                    values,
                    ulps,
                })
            }
            _ => Err(bad()),
        };
    }
    for word in ["u32", "i32", "rgbaui", "rgbai", "rui", "ri"] {
        if c.word(word) {
            let values = list(c, Cursor::uint).ok_or_else(bad)?;
            return match values.len() {
                1 | 4 => Ok(Expected::Words { values }),
                _ => Err(bad()),
            };
        }
    }
    for word in ["f64", "u64", "i64", "rui64", "ri64", "rd"] {
        if c.word(word) {
            return Err(unsupported(
                "64-bit probes (Direct3D 9 has no 64-bit targets)",
            ));
        }
    }
    Err(bad())
}

/// One probe line (after the word `probe`).
pub(super) fn probe(s: &mut State<'_>, line: &str, mut c: Cursor<'_>) -> Result<Verdict, Stop> {
    match &s.last {
        Last::Ok => {}
        Last::Failed(why) => {
            return Ok(Verdict::Fail {
                detail: format!("the draw before it failed: {why}"),
            })
        }
        Last::Unsupported(why) => return Ok(unsupported(why)),
    }
    let slot = if c.word("uav") || c.word("dsv") {
        return Ok(unsupported("probes of UAVs and depth views"));
    } else if c.word("rtv") || c.word("render target") {
        c.uint()
            .ok_or_else(|| format!("malformed render target index '{line}'"))?
    } else {
        0
    };
    let Some(rtv) = s.rtvs.get(&slot) else {
        return Err(format!("no render target {slot} to probe").into());
    };
    let r = match rect(&mut c, &rtv.target) {
        Ok(r) => r,
        Err(v) => return Ok(v),
    };
    let e = match expected(&mut c) {
        Ok(e) => e,
        Err(v) => return Ok(v),
    };
    let (w, h) = (rtv.target.width, rtv.target.height);
    let inside = [r[0].min(w), r[1].min(h), r[2].min(w), r[3].min(h)];
    let targets = match super::draw::replay(s, inside) {
        Ok(t) => t,
        Err(why) => return Ok(unsupported(&why)),
    };
    Ok(check(&targets[&slot], r, &e))
}

/// The 32-bit words of a target's row `y`, as the readback holds them.
fn row(t: &RenderTarget, y: u32) -> Vec<u32> {
    let channels = t.format.channels();
    (0..t.width)
        .flat_map(|x| {
            let v = t.texel(x, y);
            (0..channels).map(move |k| v[k].to_bits())
        })
        .collect()
}

fn check(t: &RenderTarget, [l, tp, r, b]: [u32; 4], e: &Expected) -> Verdict {
    if r > t.width || b > t.height || l > r || tp > b {
        return Verdict::Fail {
            detail: format!(
                "the rectangle ({l}, {tp}, {r}, {b}) is not inside the {}×{} target",
                t.width, t.height
            ),
        };
    }
    let (element, n) = match e {
        Expected::Floats {
            values, element, ..
        } => (*element as usize / 4, values.len()),
        Expected::Words { values } => (if values.len() == 1 { 1 } else { 4 }, values.len()),
    };
    for y in tp..b {
        let words = row(t, y);
        for x in l..r {
            let at = x as usize * element;
            let Some(got) = words.get(at..at + n) else {
                return unsupported("a probe element wider than the target's pixels");
            };
            let ok = match e {
                Expected::Floats { values, ulps, .. } => got
                    .iter()
                    .zip(values)
                    .all(|(g, v)| compare_float(f32::from_bits(*g), *v, *ulps)),
                Expected::Words { values } => got == values.as_slice(),
            };
            if !ok {
                let show = |w: &[u32]| match e {
                    Expected::Floats { .. } => w
                        .iter()
                        .map(|b| format!("{:.8e}", f32::from_bits(*b)))
                        .collect::<Vec<_>>()
                        .join(", "),
                    Expected::Words { .. } => w
                        .iter()
                        .map(|b| format!("{b:#010x}"))
                        .collect::<Vec<_>>()
                        .join(", "),
                };
                let want: Vec<u32> = match e {
                    Expected::Floats { values, .. } => values.iter().map(|v| v.to_bits()).collect(),
                    Expected::Words { values } => values.clone(),
                };
                return Verdict::Fail {
                    detail: format!(
                        "got ({}), expected ({}) at ({x}, {y})",
                        show(got),
                        show(&want)
                    ),
                };
            }
        }
    }
    Verdict::Pass
}

#[cfg(test)]
mod tests {
    use super::compare_float;

    #[test]
    fn ulps_count_across_zero_and_exactly() {
        assert!(compare_float(1.0, 1.0, 0));
        assert!(!compare_float(1.0, f32::from_bits(1.0f32.to_bits() + 1), 0));
        assert!(compare_float(1.0, f32::from_bits(1.0f32.to_bits() + 1), 1));
        // +0 and -0 are the same integer.
        assert!(compare_float(0.0, -0.0, 0));
        // A negative value's integer wraps below zero, and vkd3d takes the
        // difference unsigned: the smallest denormals on either side of
        // zero are 2³² − 2 apart, not 2.
        assert!(!compare_float(f32::from_bits(1), -f32::from_bits(1), 2));
        assert!(compare_float(
            -1.0,
            f32::from_bits((-1.0f32).to_bits() + 3),
            3
        ));
    }
}
