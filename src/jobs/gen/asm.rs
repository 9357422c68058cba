//! The generated listings as a small tree of lines, printed either with
//! REPEAT_BLOCK macros or fully expanded.
//!
//! Nothing here counts anything: a listing becomes numbers only after the
//! front end has loaded its text and the cost model has analysed it (see
//! [`super::check`]).

use std::fmt::Write;

/// One line or block of a listing.
#[derive(Clone, Debug)]
pub(crate) enum Item {
    /// An instruction or declaration with its comment.
    Line { code: String, comment: String },
    /// `BEGIN_REPEAT_BLOCK(count)` … `END_REPEAT_BLOCK`, or `count` copies.
    Repeat { count: u32, body: Vec<Item> },
    /// `rep i#` … `endrep`.
    Rep {
        reg: u32,
        comment: String,
        end_comment: String,
        body: Vec<Item>,
    },
}

fn line(code: &str, comment: &str) -> Item {
    Item::Line {
        code: code.to_string(),
        comment: comment.to_string(),
    }
}

/// Column at which line comments start.
const COMMENT_COLUMN: usize = 40;

fn push_line(out: &mut String, depth: usize, code: &str, comment: &str, with_comment: bool) {
    let text = format!("{}{}", "    ".repeat(depth), code);
    if with_comment && !comment.is_empty() {
        let pad = COMMENT_COLUMN.saturating_sub(text.chars().count()).max(1);
        let _ = writeln!(out, "{text}{}// {comment}", " ".repeat(pad));
    } else {
        let _ = writeln!(out, "{text}");
    }
}

/// Prints items; in the expanded form, comments appear on the first copy of
/// a repeated body only.
pub(crate) fn render(items: &[Item], macros: bool) -> String {
    let mut out = String::new();
    render_into(items, macros, 0, true, &mut out);
    out
}

fn render_into(items: &[Item], macros: bool, depth: usize, comments: bool, out: &mut String) {
    for item in items {
        match item {
            Item::Line { code, comment } => push_line(out, depth, code, comment, comments),
            Item::Repeat { count, body } => {
                if macros {
                    push_line(
                        out,
                        depth,
                        &format!("BEGIN_REPEAT_BLOCK({count})"),
                        "",
                        false,
                    );
                    render_into(body, macros, depth + 1, comments, out);
                    push_line(out, depth, "END_REPEAT_BLOCK", "", false);
                } else {
                    for i in 0..*count {
                        render_into(body, macros, depth, comments && i == 0, out);
                    }
                }
            }
            Item::Rep {
                reg,
                comment,
                end_comment,
                body,
            } => {
                push_line(out, depth, &format!("rep i{reg}"), comment, comments);
                render_into(body, macros, depth + 1, comments, out);
                push_line(out, depth, "endrep", end_comment, comments);
            }
        }
    }
}

/// The two forms of pass 1 the article gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Pass1Form {
    /// `rep i2` over lines, the line's texels unrolled (REPEAT_BLOCK).
    Unrolled,
    /// `rep i2` over lines, `rep i1` over texels.
    Loop,
}

impl Pass1Form {
    /// The form's name (`unrolled`, `loop`).
    pub fn name(self) -> &'static str {
        match self {
            Pass1Form::Unrolled => "unrolled",
            Pass1Form::Loop => "loop",
        }
    }

    /// Loop nesting depth the form needs.
    pub fn nesting(self) -> u32 {
        match self {
            Pass1Form::Unrolled => 1,
            Pass1Form::Loop => 2,
        }
    }
}

/// How pass 2 walks the intermediate target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Pass2Form {
    /// Every texel unrolled (the article's listing).
    Unrolled,
    /// `rep i0` over rows, each row's texels unrolled.
    RowLoop,
    /// `rep i0` over rows, `rep i1` over a row's texels.
    Nested,
}

impl Pass2Form {
    /// From the fewest executed instructions to the most.
    pub const ALL: [Pass2Form; 3] = [Pass2Form::Unrolled, Pass2Form::RowLoop, Pass2Form::Nested];

    /// The form's name (`unrolled`, `row loop`, `nested loops`).
    pub fn name(self) -> &'static str {
        match self {
            Pass2Form::Unrolled => "unrolled",
            Pass2Form::RowLoop => "row loop",
            Pass2Form::Nested => "nested loops",
        }
    }

    /// Loop nesting depth the form needs.
    pub fn nesting(self) -> u32 {
        match self {
            Pass2Form::Unrolled => 0,
            Pass2Form::RowLoop => 1,
            Pass2Form::Nested => 2,
        }
    }
}

/// Whether loop counts are defined in the shader (`defi`) or left to the
/// application (used while searching, with the counts given to the cost
/// model as constants).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Counts {
    Defined,
    Application,
}

fn preamble(defis: &[(u32, u32)], counts: Counts) -> Vec<Item> {
    let mut v = vec![
        line("ps_3_0", ""),
        line("dcl_texcoord0 v0.xy", ""),
        line("dcl_2d s0", ""),
    ];
    if counts == Counts::Defined {
        for (i, &(reg, n)) in defis.iter().enumerate() {
            v.push(line(
                &format!("defi i{reg}, {n}, 0, 0, 0"),
                if i == 0 {
                    "loop counts, fixed by the generator"
                } else {
                    ""
                },
            ));
        }
    }
    v
}

/// The set-up shared by both passes: r0.xy = (u, v) at the block's top-left
/// texel centre, r0.w = 0, and r3.yzw = (dv, start u, du) in one `mad`:
/// y = v0.x·0 + c1.y, z = v0.x·1 + 0, w = v0.x·0 + c1.x (c1 = (du, dv, 0, 1)).
///
/// r3 replaces both the article's `mov r2.w, c1.x` (du) and the corrected
/// listings' extra `mad r3.xy, …` (start u, dv): the line-end fix costs no
/// instruction. The per-texel value goes to r3.x, so `r3.wxxx` feeds the
/// article's `add r0.xw, r0.xwww, …` (u += du, sum += value).
fn setup(pass1: bool) -> Vec<Item> {
    let mut v = vec![
        line(
            "mov r0.xy, v0.xy",
            "(u, v) = centre of the block's top-left texel",
        ),
        line("mov r0.zw, c0.z", "clear the accumulator r0.w"),
    ];
    if pass1 {
        v.push(line(
            "mov r1.w, c3.w",
            "r1.w = sqrt(delta), so dp4 adds r1.w * c3.w = delta",
        ));
    }
    v.push(line(
        "mad r3.yzw, v0.x, c1.zzwz, c1.xyzx",
        "r3.yzw = (dv, start u, du)",
    ));
    v
}

fn line_end() -> Item {
    line(
        "mad r0.xy, r0.xy, c1.zw, r3.zy",
        "u = start u (not 0, the frame's edge), v += dv",
    )
}

/// The pass-1 listing: sums log2|delta + L| over `taps × rows` texels.
pub(crate) fn pass1(form: Pass1Form, taps: u32, rows: u32, counts: Counts) -> Vec<Item> {
    let sample = vec![
        line("texld r1.xyz, r0, s0", "the texel at (u, v)"),
        line(
            "dp4 r3.x, r1.xyzw, c3.xyzw",
            "delta + L = 0.27R + 0.67G + 0.06B + delta",
        ),
        line("log r3.x, r3.x", "log2|delta + L|"),
        line(
            "add r0.xw, r0.xwww, r3.wxxx",
            "u += du, sum += log2|delta + L|",
        ),
    ];
    let (defis, x_loop) = match form {
        Pass1Form::Unrolled => (
            vec![(2, rows)],
            Item::Repeat {
                count: taps,
                body: sample,
            },
        ),
        Pass1Form::Loop => (
            vec![(1, taps), (2, rows)],
            Item::Rep {
                reg: 1,
                comment: match counts {
                    Counts::Defined => format!("{taps} texels per line"),
                    Counts::Application => "i1 texels per line".to_string(),
                },
                end_comment: String::new(),
                body: sample,
            },
        ),
    };
    let mut v = preamble(&defis, counts);
    v.extend(setup(true));
    v.push(Item::Rep {
        reg: 2,
        comment: match counts {
            Counts::Defined => crate::core::numbers::plural(rows as u64, "line", "lines"),
            Counts::Application => "i2 lines".to_string(),
        },
        end_comment: String::new(),
        body: vec![x_loop, line_end()],
    });
    v.push(line("mov oC0.xyzw, r0.www", "the block's sum"));
    v
}

/// The pass-2 listing: sums an `nx × ny` target, removes the padding with
/// c0.y, divides by N with c0.x and converts back with `exp`.
pub(crate) fn pass2(form: Pass2Form, nx: u32, ny: u32) -> Vec<Item> {
    let tap = vec![
        line("texld r3.x, r0, s0", "one block's sum"),
        line("add r0.xw, r0.xwww, r3.wxxx", "u += du, total += sum"),
    ];
    let row = |body: Vec<Item>| -> Vec<Item> { vec![Item::Repeat { count: nx, body }, line_end()] };
    let (defis, walk) = match form {
        Pass2Form::Unrolled => (
            Vec::new(),
            Item::Repeat {
                count: ny,
                body: row(tap),
            },
        ),
        Pass2Form::RowLoop => (
            vec![(0, ny)],
            Item::Rep {
                reg: 0,
                comment: format!("{ny} rows"),
                end_comment: String::new(),
                body: row(tap),
            },
        ),
        Pass2Form::Nested => (
            vec![(0, ny), (1, nx)],
            Item::Rep {
                reg: 0,
                comment: format!("{ny} rows"),
                end_comment: String::new(),
                body: vec![
                    Item::Rep {
                        reg: 1,
                        comment: format!("{nx} texels per row"),
                        end_comment: String::new(),
                        body: tap,
                    },
                    line_end(),
                ],
            },
        ),
    };
    let mut v = preamble(&defis, Counts::Defined);
    v.extend(setup(false));
    v.push(walk);
    v.push(line(
        "mad r0.x, r0.w, c0.x, c0.y",
        "total / N - padding: the mean of log2|delta + L|",
    ));
    v.push(line(
        "exp r0.x, r0.x",
        "back to a luminance: the log-average",
    ));
    v.push(line("mov oC0.xyzw, r0.xxxx", ""));
    v
}

/// Header comment lines, each prefixed with `// `.
pub(crate) fn comment_block(lines: &[String]) -> String {
    let mut out = String::new();
    for l in lines {
        if l.is_empty() {
            out.push_str("//\n");
        } else {
            let _ = writeln!(out, "// {l}");
        }
    }
    out
}
