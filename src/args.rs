//! Parsers for command-line values (`WxH`, `cN=x,y,z,w`, `iN=…`, `bN=…`,
//! `NAME=N`), shared by every subcommand so that a value means the same thing
//! and fails with the same message wherever it is given.

/// `WxH` with both sides 1..=65536.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or("expected WxH, e.g. 64x64")?;
    let parse = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (1..=1 << 16).contains(&n))
    };
    match (parse(w), parse(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(format!(
            "`{s}`: both sides must be integers from 1 to 65536"
        )),
    }
}

pub fn parse_finite(s: &str) -> Result<f32, String> {
    s.trim()
        .parse::<f32>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("`{s}` is not a finite number"))
}

/// One to four finite numbers separated by commas.
pub fn parse_float4(s: &str) -> Result<[f32; 4], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.is_empty() || parts.len() > 4 {
        return Err("expected one to four numbers separated by commas".into());
    }
    let mut v = [0f32; 4];
    for (slot, p) in v.iter_mut().zip(&parts) {
        *slot = parse_finite(p)?;
    }
    Ok(v)
}

pub fn parse_register(s: &str, prefix: char, count: u32) -> Result<u32, String> {
    let n = s
        .strip_prefix(prefix)
        .and_then(|d| d.parse::<u32>().ok())
        .ok_or_else(|| format!("expected {prefix}0 … {prefix}{}", count - 1))?;
    if n >= count {
        return Err(format!(
            "{prefix}{n} does not exist ({prefix}0 … {prefix}{})",
            count - 1
        ));
    }
    Ok(n)
}

/// `cN=X[,Y,Z,W]`.
pub fn parse_float_const(s: &str) -> Result<(u32, [f32; 4]), String> {
    let (reg, value) = s
        .split_once('=')
        .ok_or("expected cN=X[,Y,Z,W], e.g. c3=0.27,0.67,0.06,0.01")?;
    Ok((parse_register(reg.trim(), 'c', 224)?, parse_float4(value)?))
}

/// `iN=X[,Y,Z,W]`.
pub fn parse_int_const(s: &str) -> Result<(u32, [i32; 4]), String> {
    let (reg, value) = s
        .split_once('=')
        .ok_or("expected iN=X[,Y,Z,W], e.g. i1=128")?;
    let reg = parse_register(reg.trim(), 'i', 16)?;
    let parts: Vec<&str> = value.split(',').collect();
    if parts.is_empty() || parts.len() > 4 {
        return Err("expected one to four integers".into());
    }
    let mut v = [0i32; 4];
    for (slot, p) in v.iter_mut().zip(&parts) {
        *slot = p
            .trim()
            .parse::<i32>()
            .map_err(|_| format!("`{p}` is not an integer"))?;
    }
    Ok((reg, v))
}

/// `bN=true|false`.
pub fn parse_bool_const(s: &str) -> Result<(u32, bool), String> {
    let (reg, value) = s.split_once('=').ok_or("expected bN=true|false")?;
    let reg = parse_register(reg.trim(), 'b', 16)?;
    let v = match value.trim() {
        "true" | "1" => true,
        "false" | "0" => false,
        other => return Err(format!("`{other}` is not true or false")),
    };
    Ok((reg, v))
}

/// `NAME=N`.
pub fn parse_define(s: &str) -> Result<(String, u64), String> {
    let (name, value) = s.split_once('=').ok_or("expected NAME=N, e.g. xsize=11")?;
    let valid = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(format!("`{name}` is not a valid name"));
    }
    let v = value
        .trim()
        .parse::<u64>()
        .map_err(|_| format!("`{value}` is not a non-negative integer"))?;
    Ok((name.to_string(), v))
}
