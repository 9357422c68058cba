//! Numbers as ps30 prints them, in one place: thousands separators, ranges,
//! and short decimals, so that every command and report spells a figure the
//! same way.

use crate::core::cost::Range;
use serde_json::{json, Value};

/// `64853` → `64,853`.
pub fn thousands(v: u64) -> String {
    let s = v.to_string();
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// A count as [`thousands`] spells it, or `more than 18,446,744,073,709,551,614`
/// for a count that saturated: the cost model's arithmetic stops at
/// `u64::MAX` instead of wrapping, so that value means "at least this".
pub fn count(v: u64) -> String {
    if v == u64::MAX {
        format!("more than {}", thousands(u64::MAX - 1))
    } else {
        thousands(v)
    }
}

/// A range as `64,853` or `1,000–2,000` (saturated ends as [`count`] says).
pub fn range_text(r: Range) -> String {
    if r.is_exact() {
        count(r.min)
    } else {
        format!("{}–{}", count(r.min), count(r.max))
    }
}

/// A range as a JSON number when exact, `{"min":…,"max":…}` otherwise.
pub fn range_json(r: Range) -> Value {
    if r.is_exact() {
        json!(r.min)
    } else {
        json!({"min": r.min, "max": r.max})
    }
}

/// A number with about 6 significant digits, ∞ spelled out.
pub fn number(v: f64) -> String {
    if v.is_infinite() {
        return if v > 0.0 {
            "∞".into()
        } else {
            "−∞".into()
        };
    }
    if v == 0.0 || v.is_nan() {
        return format!("{v}");
    }
    let digits = v.abs().log10().floor() as i32 + 1;
    if (-3..=7).contains(&digits) {
        let s = format!("{:.*}", (6 - digits).max(0) as usize, v);
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.4e}")
    }
}

/// `125×128`.
pub fn size(w: u32, h: u32) -> String {
    format!("{w}×{h}")
}

/// A level of detail with two decimals (`7.00`), ∞ spelled out.
pub fn lod_text(v: f32) -> String {
    if v.is_finite() {
        format!("{v:.2}")
    } else {
        format!("{v}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_spell_infinity() {
        assert_eq!(number(0.18), "0.18");
        assert_eq!(number(4.0), "4");
        assert_eq!(number(31950.88), "31950.9");
        assert_eq!(number(0.0808638), "0.0808638");
        assert_eq!(number(f64::INFINITY), "∞");
        assert_eq!(number(1.5e-9), "1.5000e-9");
        assert_eq!(thousands(64853), "64,853");
        assert_eq!(thousands(999), "999");
    }
}
