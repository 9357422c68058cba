//! Numbers as ps30 prints them, in one place: thousands separators, plurals,
//! saturated counts and short decimals (a range of counts is spelled by
//! `cost::Range::text` with these), so that every command and report spells
//! a figure the same way. It sits below every other core module, so even
//! diagnostics can use it.

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

/// `1 error`, `12 errors`, `1,310,720 pixels`: a count with its noun in the
/// right number, thousands separated.
pub fn plural(n: u64, one: &str, many: &str) -> String {
    format!("{} {}", thousands(n), if n == 1 { one } else { many })
}

/// `a`, `a and b`, `a, b and c`.
pub fn list(items: &[&str]) -> String {
    match items {
        [] => String::new(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
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

/// [`number`] with the thousands of its integer part separated:
/// `-39,147.4`, `60,677`, `0.0808638`; `1.5000e-9` as it is.
pub fn number_grouped(v: f64) -> String {
    group_integer_part(&number(v))
}

/// `v` with `places` decimals and the thousands of its integer part
/// separated: `60,677.00`.
pub fn decimal(v: f64, places: usize) -> String {
    group_integer_part(&format!("{v:.places$}"))
}

/// Commas in the integer digits of a formatted number (not in an exponent
/// or a fraction).
fn group_integer_part(s: &str) -> String {
    if s.contains(['e', 'E', '∞', 'N']) {
        return s.to_string();
    }
    let (sign, rest) = match s.strip_prefix('-') {
        Some(r) => ("-", r),
        None => ("", s),
    };
    let (int, frac) = rest.split_at(rest.find('.').unwrap_or(rest.len()));
    match int.parse::<u64>() {
        Ok(n) => format!("{sign}{}{frac}", thousands(n)),
        Err(_) => s.to_string(),
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

/// Serializes an f32 a user or a table gave (δ, a brightness) as the
/// shortest decimal that reads back to it (`0.1`, not
/// `0.10000000149011612`); non-finite values as `null`. For
/// `#[serde(serialize_with = "…")]`.
pub fn serialize_f32_shortest<S: serde::Serializer>(v: &f32, s: S) -> Result<S::Ok, S::Error> {
    if v.is_finite() {
        s.serialize_f64(v.to_string().parse().unwrap_or(*v as f64))
    } else {
        s.serialize_none()
    }
}

/// A float constant as a user writes it: a decimal number, `inf`, `-inf`,
/// `nan`, `-nan` (any case, `infinity` too), or its 32 bits in hex
/// (`0x7f800000`, `0xffc00000`, `0x00000001` for the smallest denormal).
/// Direct3D 9 passes any 32-bit pattern through `SetPixelShaderConstantF`,
/// so every pattern can be spelled; `nan` is 0x7FC00000 and `-nan`
/// 0xFFC00000. A decimal too large for f32 is refused rather than turned
/// into ∞ unasked.
pub fn parse_constant(s: &str) -> Result<f32, String> {
    let t = s.trim();
    let lower = t.to_ascii_lowercase();
    if let Some(hex) = lower.strip_prefix("0x") {
        if hex.is_empty() || hex.len() > 8 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(format!(
                "`{s}`: hex bits are 0x and one to eight hex digits"
            ));
        }
        return u32::from_str_radix(hex, 16)
            .map(f32::from_bits)
            .map_err(|_| format!("`{s}` is not 32 hex bits"));
    }
    let word = lower.trim_start_matches(['+', '-']);
    let v: f32 = t.parse().map_err(|_| {
        format!("`{s}` is not a number (write a decimal, inf, -inf, nan or 0x… bits)")
    })?;
    if !v.is_finite() && !matches!(word, "inf" | "infinity" | "nan") {
        return Err(format!(
            "`{s}` is beyond f32's range (write inf or -inf for an infinity)"
        ));
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_take_every_bit_pattern() {
        let bits = |s: &str| parse_constant(s).map(f32::to_bits);
        assert_eq!(bits("inf"), Ok(0x7f80_0000));
        assert_eq!(bits("-INF"), Ok(0xff80_0000));
        assert_eq!(bits("nan"), Ok(0x7fc0_0000));
        assert_eq!(bits("-nan"), Ok(0xffc0_0000));
        assert_eq!(bits("0x7F800001"), Ok(0x7f80_0001));
        assert_eq!(bits("0x1"), Ok(1));
        assert_eq!(bits(" 0.5 "), Ok(0x3f00_0000));
        assert!(bits("1e39").is_err());
        assert!(bits("0x").is_err());
        assert!(bits("0x123456789").is_err());
        assert!(bits("nanx").is_err());
    }

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
        assert_eq!(plural(1, "line", "lines"), "1 line");
        assert_eq!(list(&["c1", "i1", "i2"]), "c1, i1 and i2");
        assert_eq!(number_grouped(-39147.398438), "-39,147.4");
        assert_eq!(number_grouped(0.0808638), "0.0808638");
        assert_eq!(decimal(60677.0, 2), "60,677.00");
        assert_eq!(decimal(-0.5, 2), "-0.50");
        assert_eq!(plural(0, "line", "lines"), "0 lines");
        assert_eq!(plural(12_345, "pixel", "pixels"), "12,345 pixels");
    }
}
