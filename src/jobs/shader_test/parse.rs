//! The `.shader_test` text: a file split into its bracketed sections, each
//! with its numbered lines, and the small scanners its lines need (C's
//! `strtof`/`strtoul` spellings, words matched as vkd3d's runner matches
//! them, and the `(sm<4 | !glsl)` qualifier arguments).
//!
//! The layout follows vkd3d's `tests/shader_runner.c`: a line starting with
//! `[` opens a section; other lines belong to the open section; lines that
//! start with `%` and empty lines are dropped everywhere, shader sources
//! included.

/// The most bytes of a test file read (the suite's largest is under 64 KiB).
pub const MAX_FILE_BYTES: usize = 4 << 20;

/// What a section header names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `[require]`.
    Require,
    /// `[pixel shader …]`, `[vertex shader …]` or another stage, with the
    /// header's words after the stage (`fail(sm<4)`, `todo`, `d3dbc-hex`).
    Shader {
        /// `pixel`, `vertex`, `compute`, `geometry`, `hull`, `domain`, `effect`.
        stage: String,
        /// The header's text after the stage name, up to `]`.
        qualifiers: String,
    },
    /// `[sampler N]`.
    Sampler(u32),
    /// `[rtv N]` (`[render target N]`), `[srv N]` (`[texture N]`), `[uav N]`,
    /// `[vb N]` (`[vertex buffer N]`), `[dsv]`.
    Resource {
        /// `rtv`, `srv`, `uav`, `vb`, `dsv`.
        kind: &'static str,
        /// The slot.
        slot: u32,
    },
    /// `[input layout]`.
    InputLayout,
    /// `[test]`.
    Test,
    /// `[preproc]` or `[preproc fail]`.
    Preproc,
    /// A header vkd3d's runner does not know.
    Unknown(String),
}

/// One section: its header's line number and kind, and its lines.
#[derive(Clone, Debug)]
pub struct Section {
    /// 1-based line of the header.
    pub line: usize,
    /// What the header names.
    pub kind: Kind,
    /// `(line number, text)` of each kept line, without its line ending.
    pub lines: Vec<(usize, String)>,
}

/// Splits a test file into its sections (lines before the first header
/// are returned as errors by the runner, as vkd3d's are fatal).
pub fn sections(text: &str) -> (Vec<(usize, String)>, Vec<Section>) {
    let mut before = Vec::new();
    let mut out: Vec<Section> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.strip_suffix('\r').unwrap_or(raw);
        let number = i + 1;
        if line.starts_with('[') {
            out.push(Section {
                line: number,
                kind: header(line),
                lines: Vec::new(),
            });
        } else if !line.starts_with('%') && !line.is_empty() {
            match out.last_mut() {
                Some(s) => s.lines.push((number, line.to_string())),
                None => before.push((number, line.to_string())),
            }
        }
    }
    (before, out)
}

fn header(line: &str) -> Kind {
    let inner = line.trim_end();
    let slot = |prefix: &str| -> Option<u32> {
        inner
            .strip_prefix(prefix)?
            .strip_suffix(']')?
            .trim()
            .parse()
            .ok()
    };
    match inner {
        "[require]" => return Kind::Require,
        "[test]" => return Kind::Test,
        "[input layout]" => return Kind::InputLayout,
        "[preproc]" | "[preproc fail]" => return Kind::Preproc,
        "[dsv]" => {
            return Kind::Resource {
                kind: "dsv",
                slot: 0,
            }
        }
        _ => {}
    }
    for (prefix, kind) in [
        ("[rtv ", "rtv"),
        ("[render target ", "rtv"),
        ("[srv ", "srv"),
        ("[texture ", "srv"),
        ("[uav ", "uav"),
        ("[vb ", "vb"),
        ("[vertex buffer ", "vb"),
    ] {
        if let Some(slot) = slot(prefix) {
            return Kind::Resource { kind, slot };
        }
    }
    if let Some(n) = slot("[sampler ") {
        return Kind::Sampler(n);
    }
    for stage in [
        "pixel", "vertex", "compute", "geometry", "hull", "domain", "effect",
    ] {
        let open = if stage == "effect" {
            "[effect".to_string()
        } else {
            format!("[{stage} shader")
        };
        if let Some(rest) = inner.strip_prefix(&open) {
            if rest.starts_with([' ', ']', '(']) {
                let qualifiers = rest.strip_suffix(']').unwrap_or(rest).trim().to_string();
                return Kind::Shader {
                    stage: stage.to_string(),
                    qualifiers,
                };
            }
        }
    }
    Kind::Unknown(inner.to_string())
}

/// A position in one line, scanned the way vkd3d's runner scans it.
#[derive(Clone, Copy, Debug)]
pub struct Cursor<'a> {
    /// What is left of the line.
    pub rest: &'a str,
}

impl<'a> Cursor<'a> {
    /// A cursor at the start of `line`.
    pub fn new(line: &'a str) -> Cursor<'a> {
        Cursor { rest: line }
    }

    /// Skips white space.
    pub fn ws(&mut self) {
        self.rest = self.rest.trim_start();
    }

    /// Whether only white space is left.
    pub fn at_end(&self) -> bool {
        self.rest.trim().is_empty()
    }

    /// vkd3d's `match_string`: after white space, `token` followed by white
    /// space, the end of the line, `(` or `]`; consumes it and the white
    /// space after it.
    pub fn word(&mut self, token: &str) -> bool {
        let s = self.rest.trim_start();
        let Some(after) = s.strip_prefix(token) else {
            return false;
        };
        if !(after.is_empty()
            || after.starts_with(|c: char| c.is_whitespace() || c == '(' || c == ']'))
        {
            return false;
        }
        self.rest = after.trim_start();
        true
    }

    /// Consumes `c` after white space.
    pub fn char(&mut self, c: char) -> bool {
        let s = self.rest.trim_start();
        match s.strip_prefix(c) {
            Some(after) => {
                self.rest = after;
                true
            }
            None => false,
        }
    }

    /// C's `strtof`: a float after white space (decimal, `inf`, `nan`).
    pub fn float(&mut self) -> Option<f32> {
        let (v, rest) = strtof(self.rest)?;
        self.rest = rest;
        Some(v)
    }

    /// C's `strtoul` with base 0 (decimal, `0x` hexadecimal, `0` octal; a
    /// minus sign negates modulo 2³²), as a `u32`.
    pub fn uint(&mut self) -> Option<u32> {
        let (v, rest) = strtoul(self.rest)?;
        self.rest = rest;
        Some(v)
    }

    /// `sscanf("%d")`-like signed integer.
    pub fn int(&mut self) -> Option<i32> {
        self.uint().map(|u| u as i32)
    }
}

/// C's `strtof`: leading white space, then the longest float; the value
/// and what follows, or `None` when no number starts there.
pub fn strtof(s: &str) -> Option<(f32, &str)> {
    let t = s.trim_start();
    let b = t.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let word = |w: &str| t.len() >= i + w.len() && t[i..i + w.len()].eq_ignore_ascii_case(w);
    if word("infinity") || word("inf") || word("nan") {
        let len = if word("infinity") { 8 } else { 3 };
        let v: f32 = t[..i + len].to_ascii_lowercase().parse().ok()?;
        return Some((v, &t[i + len..]));
    }
    let digits_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let mut any = i > digits_start;
    if i < b.len() && b[i] == b'.' {
        i += 1;
        let f = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        any |= i > f;
    }
    if !any {
        return None;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        let e = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j > e {
            i = j;
        }
    }
    let text = &t[..i];
    let v: f32 = text
        .trim_end_matches('.')
        .parse()
        .or_else(|_| text.parse())
        .ok()?;
    Some((v, &t[i..]))
}

/// C's `strtoul(s, &end, 0)` reduced to 32 bits (saturating as C's
/// `unsigned long` of 64 bits does not, so larger values are refused).
pub fn strtoul(s: &str) -> Option<(u32, &str)> {
    let t = s.trim_start();
    let (neg, body) = match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    };
    let (radix, digits) =
        if let Some(h) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X")) {
            if h.starts_with(|c: char| c.is_ascii_hexdigit()) {
                (16, h)
            } else {
                (10, body)
            }
        } else if body.starts_with('0') {
            (8, body)
        } else {
            (10, body)
        };
    let len = digits
        .find(|c: char| !c.is_digit(radix))
        .unwrap_or(digits.len());
    if len == 0 {
        return None;
    }
    let v = u64::from_str_radix(&digits[..len], radix).ok()?;
    let v = u32::try_from(v).ok()?;
    let v = if neg { v.wrapping_neg() } else { v };
    Some((v, &digits[len..]))
}

/// The shader models the Direct3D 9 runner knows, by index: 0 is 2.0, 1 is
/// 3.0, 2 is 4.0 and so on (vkd3d's `enum shader_model`).
pub const MODELS: [&str; 8] = ["2.0", "3.0", "4.0", "4.1", "5.0", "5.1", "6.0", "6.2"];

/// A shader model spelled as vkd3d's `match_shader_model_string` reads it
/// (`3.0`, or `3` for `3.0`); the index in [`MODELS`] and the rest.
pub fn model(s: &str) -> Option<(usize, &str)> {
    for (i, m) in MODELS.iter().enumerate() {
        if let Some(rest) = s.strip_prefix(m) {
            return Some((i, rest));
        }
        let b = s.as_bytes();
        if m.ends_with(".0")
            && b.first() == m.as_bytes().first()
            && !b.get(1).is_some_and(|c| *c == b'.' || c.is_ascii_digit())
        {
            return Some((i, &s[1..]));
        }
    }
    None
}

/// The tags vkd3d's qualifiers may name (none of which the Direct3D 9
/// runner has), longest first where one is a prefix of another.
const TAGS: [&str; 10] = [
    "d3d12",
    "glsl",
    "llvmpipe",
    "mesa<23.3",
    "msl",
    "mvk<1.2.11",
    "mvk",
    "opengl",
    "vulkan",
    "warp",
];

/// Qualifier arguments `(a & b | c)` after a word: whether they hold for a
/// runner at shader model `sm` with no tags, and the models they select (a
/// bit per [`MODELS`] index). No parenthesis: holds, every model. `Err`: a
/// malformed argument.
pub fn qualifier_args(c: &mut Cursor<'_>, sm: usize) -> Result<(bool, u32), String> {
    if !c.rest.starts_with('(') {
        return Ok((true, !0));
    }
    c.rest = &c.rest[1..];
    let (mut holds, mut mask) = (false, 0u32);
    let mut first = true;
    loop {
        if c.rest.starts_with(')') {
            c.rest = &c.rest[1..];
            c.ws();
            return Ok((holds, mask));
        }
        if !first {
            if !c.rest.starts_with('|') {
                return Err(format!("malformed qualifier arguments '{}'", c.rest));
            }
            c.rest = &c.rest[1..];
        }
        first = false;
        let (h, m) = conjunction(c, sm)?;
        holds |= h;
        mask |= m;
    }
}

fn conjunction(c: &mut Cursor<'_>, sm: usize) -> Result<(bool, u32), String> {
    let (mut holds, mut mask) = (true, !0u32);
    loop {
        c.ws();
        if c.rest.starts_with(')') || c.rest.starts_with('|') {
            return Ok((holds, mask));
        }
        if let Some(r) = c.rest.strip_prefix("sm>=") {
            let (m, rest) = model(r).ok_or_else(|| format!("unknown shader model '{r}'"))?;
            c.rest = rest;
            mask &= !((1u32 << m) - 1);
            holds &= sm >= m;
        } else if let Some(r) = c.rest.strip_prefix("sm<") {
            let (m, rest) = model(r).ok_or_else(|| format!("unknown shader model '{r}'"))?;
            c.rest = rest;
            mask &= (1u32 << m) - 1;
            holds &= sm < m;
        } else {
            let negate = c.rest.starts_with('!');
            let r = c.rest.trim_start_matches('!');
            let tag = TAGS
                .iter()
                .find(|t| r.starts_with(*t))
                .ok_or_else(|| format!("invalid qualifier argument '{}'", c.rest))?;
            c.rest = &r[tag.len()..];
            // The Direct3D 9 runner has no tags: a tag never matches.
            holds &= negate;
        }
        c.ws();
        if let Some(r) = c.rest.strip_prefix('&') {
            c.rest = r;
        } else if !(c.rest.starts_with(')') || c.rest.starts_with('|')) {
            return Err(format!("invalid qualifier argument '{}'", c.rest));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sections_keep_their_lines_and_drop_comments() {
        let (before, s) = sections("[require]\nshader model >= 3.0\n% note\n\n[pixel shader fail(sm<4)]\nfloat4 main() : sv_target { return 0; }\n[rtv 1]\n[texture 2]\n[test]\ndraw quad\n");
        assert!(before.is_empty());
        assert_eq!(s.len(), 5);
        assert_eq!(s[0].lines, vec![(2, "shader model >= 3.0".to_string())]);
        assert_eq!(
            s[1].kind,
            Kind::Shader {
                stage: "pixel".into(),
                qualifiers: "fail(sm<4)".into()
            }
        );
        assert_eq!(
            s[2].kind,
            Kind::Resource {
                kind: "rtv",
                slot: 1
            }
        );
        assert_eq!(
            s[3].kind,
            Kind::Resource {
                kind: "srv",
                slot: 2
            }
        );
        assert_eq!(s[4].lines[0].0, 10);
    }

    #[test]
    fn numbers_read_as_c_reads_them() {
        assert_eq!(strtof(" 1.5e2x"), Some((150.0, "x")));
        assert_eq!(strtof("-inf)").map(|v| v.0), Some(f32::NEG_INFINITY));
        assert!(strtof("nan").unwrap().0.is_nan());
        assert_eq!(strtof("abc"), None);
        assert_eq!(strtof("2."), Some((2.0, "")));
        assert_eq!(strtoul("0x10 "), Some((16, " ")));
        assert_eq!(strtoul("010"), Some((8, "")));
        assert_eq!(strtoul("-1"), Some((u32::MAX, "")));
        assert_eq!(strtoul("7.5"), Some((7, ".5")));
    }

    #[test]
    fn qualifiers_hold_for_the_model_and_no_tag() {
        let eval = |s: &str, sm| qualifier_args(&mut Cursor::new(s), sm).unwrap();
        assert!(eval("(sm<4)", 0).0);
        assert!(!eval("(sm>=4)", 1).0);
        assert!(eval("(sm>=3)", 1).0);
        assert!(!eval("(glsl | sm<3)", 1).0);
        assert!(eval("(!glsl & sm<4)", 0).0);
        assert_eq!(eval("(sm<4)", 0).1, 0b11);
        assert_eq!(eval(" x", 0), (true, !0));
        assert!(qualifier_args(&mut Cursor::new("(bogus)"), 0).is_err());
    }

    #[test]
    fn words_end_at_space_parenthesis_or_bracket() {
        let mut c = Cursor::new("todo(sm<4) draw quad");
        assert!(c.word("todo"));
        assert_eq!(c.rest, "(sm<4) draw quad");
        assert!(!Cursor::new("drawn").word("draw"));
        assert!(Cursor::new("draw").word("draw"));
    }
}
