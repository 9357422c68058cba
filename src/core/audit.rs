//! The constants a draw gives a shader, held against what the shader reads
//! and defines, so that no command runs a shader on values nobody chose.
//!
//! A ps_3_0 shader reads float (`c#`), integer (`i#`) and boolean (`b#`)
//! constants. Each comes from the shader's own `def`/`defi`/`defb`, or from
//! the application (ps30's `--const`, `--int`, `--bool`, or a job that sets
//! the article's interface), or from nobody — and then a draw reads zeros:
//! loop counts of 0, a luminance of 0, a sum of log2(0) = −∞, and a result
//! that looks like one. The audit finds four things:
//!
//! | finding | severity | why |
//! |---|---|---|
//! | a register the shader reads that nobody set | **error** for a run (the result would be made of zeros); a note for `check`, whose counts give the range instead | garbage in, garbage out |
//! | a value given for a register the shader's own `def` sets | warning | Direct3D lets the `def` win, so the given value has no effect |
//! | a value given for a register the shader never reads | warning | usually a typo in the register number |
//! | a `-D` name no REPEAT_BLOCK uses | warning | usually a typo in the name |
//!
//! An error tells the user how to set the register (zero included, if zero
//! is really meant). Only reads count: a shader may declare what it likes.

use crate::core::diag::Diagnostic;
use crate::core::ir::{Shader, Span};
use crate::core::isa::RegFile;
use std::collections::{BTreeMap, BTreeSet};

/// What the application gives a draw: the registers it sets, and the `-D`
/// names it bound.
#[derive(Clone, Debug, Default)]
pub struct Given {
    /// `c#` set by the application.
    pub floats: BTreeSet<u32>,
    /// `i#` set by the application.
    pub ints: BTreeSet<u32>,
    /// `b#` set by the application.
    pub bools: BTreeSet<u32>,
    /// `-D` names (REPEAT_BLOCK counts).
    pub defines: BTreeSet<String>,
    /// `c#` the command sets itself (a scene's constants): they count as
    /// set, and are never reported as unread or overridden.
    pub preset_floats: BTreeSet<u32>,
}

impl Given {
    /// The registers a job sets, with no `-D` names to check.
    pub fn registers(floats: &[u32], ints: &[u32], bools: &[u32]) -> Given {
        Given {
            floats: floats.iter().copied().collect(),
            ints: ints.iter().copied().collect(),
            bools: bools.iter().copied().collect(),
            ..Given::default()
        }
    }
}

/// What kind of finding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// Read, but set by neither the shader nor the application.
    Unset,
    /// Given, but the shader's `def` sets it.
    Overridden,
    /// Given, but never read.
    Unread,
    /// A `-D` name no REPEAT_BLOCK uses.
    UnusedDefine,
}

/// One finding of the audit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    /// What kind of finding it is.
    pub kind: Kind,
    /// `c1`, `i2`, `b0`, or the `-D` name.
    pub what: String,
    /// Where the shader reads it (unset) or defines it (overridden); `None`
    /// for what the shader does not mention.
    pub span: Option<Span>,
    /// How many instructions read it (unset).
    pub reads: usize,
    /// What the shader does use instead (unread: the registers of that file
    /// it reads; unused define: the names its REPEAT_BLOCKs use).
    pub instead: Vec<String>,
}

impl Kind {
    /// The kind's name in JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Unset => "unset_constant",
            Kind::Overridden => "overridden_constant",
            Kind::Unread => "unread_constant",
            Kind::UnusedDefine => "unused_define",
        }
    }
}

impl Finding {
    /// The sentence ps30 prints for it.
    pub fn message(&self) -> String {
        let what = &self.what;
        let flag = flag_of(what);
        match self.kind {
            Kind::Unset => format!(
                "{what} is read but never set: neither a `{}` in the shader nor {flag} gives it a value, so a draw reads 0 there",
                def_of(what)
            ),
            Kind::Overridden => format!(
                "{flag} {what}=… has no effect: the shader's own `{}` sets {what}, and in Direct3D the shader's value wins",
                def_of(what)
            ),
            Kind::Unread => format!("{flag} {what}=… is never read: the shader does not use {what}"),
            Kind::UnusedDefine => format!(
                "-D {what}=… is never used: no REPEAT_BLOCK count of the shader is called `{what}`"
            ),
        }
    }

    /// What to do about it.
    pub fn help(&self) -> String {
        let what = &self.what;
        let flag = flag_of(what);
        let instead: Vec<&str> = self.instead.iter().map(String::as_str).collect();
        match self.kind {
            Kind::Unset => format!("{} (zeros too, if zeros are meant)", setting(what)),
            Kind::Overridden => format!(
                "drop {flag} {what}, or remove the `{}` from the shader",
                def_of(what)
            ),
            Kind::Unread if instead.is_empty() => {
                format!("the shader reads no {} register", &what[..1])
            }
            Kind::Unread => format!("the shader reads {}", crate::core::numbers::list(&instead)),
            Kind::UnusedDefine if instead.is_empty() => {
                "the shader has no REPEAT_BLOCK with a named count".to_string()
            }
            Kind::UnusedDefine => format!(
                "its REPEAT_BLOCK counts are called {}",
                crate::core::numbers::list(&instead)
            ),
        }
    }

    /// The finding as a diagnostic: an error when unset, else a warning.
    /// Findings without a place in the shader point at its start.
    pub fn diagnostic(&self) -> Diagnostic {
        let span = self.span.unwrap_or_default();
        let d = if self.kind == Kind::Unset {
            Diagnostic::error(span, self.message()).with_label(read_label(self))
        } else {
            let label = if self.kind == Kind::Overridden {
                "the shader's value"
            } else {
                ""
            };
            Diagnostic::warning(span, self.message()).with_label(label)
        };
        d.with_help(self.help())
    }
}

/// `c1 read here (and by 3 more instructions)`.
fn read_label(f: &Finding) -> String {
    match f.reads {
        0 | 1 => format!("{} read here", f.what),
        n => format!(
            "{} read here (and by {})",
            f.what,
            crate::core::numbers::plural(n as u64 - 1, "more instruction", "more instructions")
        ),
    }
}

/// `--const c1=x,y,z,w`: how to set a register.
fn setting(reg: &str) -> String {
    format!("{} {reg}={}", flag_of(reg), example_of(reg))
}

/// The unset reads as one error: the first read of each register labelled,
/// and one line of flags that sets them all. `None` when nothing is unset.
pub fn unset_diagnostic(found: &[Finding]) -> Option<Diagnostic> {
    let unset: Vec<&Finding> = found.iter().filter(|f| f.kind == Kind::Unset).collect();
    let first = unset.first()?;
    let names: Vec<&str> = unset.iter().map(|f| f.what.as_str()).collect();
    let mut d = Diagnostic::error(
        first.span.unwrap_or_default(),
        format!(
            "the shader reads {} but nothing sets {}: neither its own def/defi/defb nor the command line, so a draw would read 0 there",
            crate::core::numbers::list(&names),
            if names.len() == 1 { "it" } else { "them" }
        ),
    )
    .with_label(read_label(first));
    for f in &unset[1..] {
        d = d.with_secondary(f.span.unwrap_or_default(), read_label(f));
    }
    let flags: Vec<String> = unset.iter().map(|f| setting(&f.what)).collect();
    Some(d.with_help(format!(
        "set {} with {} (zeros too, if zeros are meant)",
        if names.len() == 1 { "it" } else { "them" },
        flags.join(" ")
    )))
}

/// `--const`, `--int`, `--bool` by register letter.
fn flag_of(reg: &str) -> &'static str {
    match reg.as_bytes().first() {
        Some(b'c') => "--const",
        Some(b'i') => "--int",
        Some(b'b') => "--bool",
        _ => "-D",
    }
}

fn def_of(reg: &str) -> &'static str {
    match reg.as_bytes().first() {
        Some(b'i') => "defi",
        Some(b'b') => "defb",
        _ => "def",
    }
}

fn example_of(reg: &str) -> &'static str {
    match reg.as_bytes().first() {
        Some(b'i') => "N[,start,step,0]",
        Some(b'b') => "true|false",
        _ => "x,y,z,w",
    }
}

/// The audit of one shader against what is given. Findings come in the
/// shader's order (unset reads first, by register), then what the shader
/// does not mention.
pub fn audit(shader: &Shader, defines_used: &BTreeSet<String>, given: &Given) -> Vec<Finding> {
    let program = shader.program();
    // Reads: register → (first span, count).
    let mut reads: BTreeMap<(u8, u32), (Span, usize)> = BTreeMap::new();
    // A relative read (`c[a0.x + n]`, `c[aL + n]`) reads registers only the
    // run knows: none of them is reported unset, and no float constant given
    // is reported unread.
    let mut relative = false;
    for instr in &program.instructions {
        for (k, src) in instr.src.iter().enumerate() {
            let file = match src.reg.file {
                RegFile::Const => 0,
                RegFile::ConstInt => 1,
                RegFile::ConstBool => 2,
                _ => continue,
            };
            if src.relative.is_some() {
                relative |= file == 0;
                continue;
            }
            // a matrix instruction reads its rows from consecutive registers
            let rows = match instr.op.matrix_shape() {
                Some((rows, _)) if k == 1 => rows,
                _ => 1,
            };
            for row in 0..rows {
                let e = reads
                    .entry((file, src.reg.index.saturating_add(row)))
                    .or_insert((instr.origin.span, 0));
                e.1 += 1;
            }
        }
    }
    let defined = |file: u8, i: u32| -> Option<Span> {
        match file {
            0 => program
                .float_defs
                .iter()
                .rev()
                .find(|d| d.index == i)
                .map(|d| d.origin.span),
            1 => program
                .int_defs
                .iter()
                .rev()
                .find(|d| d.index == i)
                .map(|d| d.origin.span),
            _ => program
                .bool_defs
                .iter()
                .rev()
                .find(|d| d.index == i)
                .map(|d| d.origin.span),
        }
    };
    let sets = [&given.floats, &given.ints, &given.bools];
    let name = |file: u8, i: u32| format!("{}{i}", ["c", "i", "b"][file as usize]);
    let mut found = Vec::new();
    for (&(file, i), &(span, n)) in &reads {
        let preset = file == 0 && given.preset_floats.contains(&i);
        if defined(file, i).is_none() && !sets[file as usize].contains(&i) && !preset {
            found.push(Finding {
                kind: Kind::Unset,
                what: name(file, i),
                span: Some(span),
                reads: n,
                instead: Vec::new(),
            });
        }
    }
    for (file, set) in sets.iter().enumerate() {
        let file = file as u8;
        for &i in set.iter() {
            if let Some(span) = defined(file, i) {
                found.push(Finding {
                    kind: Kind::Overridden,
                    what: name(file, i),
                    span: Some(span),
                    reads: 0,
                    instead: Vec::new(),
                });
            } else if !(reads.contains_key(&(file, i)) || relative && file == 0) {
                found.push(Finding {
                    kind: Kind::Unread,
                    what: name(file, i),
                    span: None,
                    reads: 0,
                    instead: reads
                        .keys()
                        .filter(|(f, _)| *f == file)
                        .map(|&(f, r)| name(f, r))
                        .collect(),
                });
            }
        }
    }
    for d in &given.defines {
        if !defines_used.contains(d) {
            found.push(Finding {
                kind: Kind::UnusedDefine,
                what: d.clone(),
                span: None,
                reads: 0,
                instead: defines_used.iter().cloned().collect(),
            });
        }
    }
    found
}

/// The registers read but never set, by name (`c1, i2`), for one-line
/// summaries; empty when there are none.
pub fn unset_names(found: &[Finding]) -> Vec<&str> {
    found
        .iter()
        .filter(|f| f.kind == Kind::Unset)
        .map(|f| f.what.as_str())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::load::{load_str, Options};

    fn run(src: &str, given: &Given) -> Vec<(Kind, String)> {
        let l = load_str("t.psh", src, &Options::default()).unwrap();
        audit(&l.shader, &l.defines_used, given)
            .into_iter()
            .map(|f| (f.kind, f.what))
            .collect()
    }

    const LOOP: &str = "ps_3_0\ndefi i0, 4, 0, 0, 0\ndef c2, 1, 1, 1, 1\nmov r0, c0\nrep i1\nadd r0, r0, c1\nendrep\nif b0\nmov r0, c2\nendif\nmov oC0, r0\n";

    #[test]
    fn unset_reads_are_found_and_set_ones_are_not() {
        let found = run(LOOP, &Given::default());
        assert_eq!(
            found,
            vec![
                (Kind::Unset, "c0".to_string()),
                (Kind::Unset, "c1".to_string()),
                (Kind::Unset, "i1".to_string()),
                (Kind::Unset, "b0".to_string()),
            ]
        );
        let all = Given::registers(&[0, 1], &[1], &[0]);
        assert_eq!(run(LOOP, &all), vec![]);
    }

    #[test]
    fn overrides_unread_values_and_unused_names_are_found() {
        let mut given = Given::registers(&[0, 1, 2, 7], &[0, 1], &[0]);
        given.defines.insert("xsiz".to_string());
        assert_eq!(
            run(LOOP, &given),
            vec![
                (Kind::Overridden, "c2".to_string()),
                (Kind::Unread, "c7".to_string()),
                (Kind::Overridden, "i0".to_string()),
                (Kind::UnusedDefine, "xsiz".to_string()),
            ]
        );
    }

    #[test]
    fn names_used_by_repeat_blocks_are_used() {
        let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(n)\nmov r0, c0\nEND_REPEAT_BLOCK\nmov oC0, r0\n";
        let mut opts = Options::default();
        opts.defines.insert("n".into(), 2);
        let l = load_str("t.psh", src, &opts).unwrap();
        let mut given = Given::registers(&[0], &[], &[]);
        given.defines.insert("n".into());
        assert!(audit(&l.shader, &l.defines_used, &given).is_empty());
    }

    #[test]
    fn messages_name_the_flag_and_the_fix() {
        let f = &audit_of(LOOP)[2];
        assert_eq!(f.what, "i1");
        assert!(
            f.message()
                .contains("neither a `defi` in the shader nor --int gives"),
            "{}",
            f.message()
        );
        assert!(f.help().contains("--int i1="), "{}", f.help());
        let d = unset_diagnostic(&audit_of(LOOP)).unwrap();
        assert_eq!(d.severity, crate::core::diag::Severity::Error);
        assert!(
            d.message
                .starts_with("the shader reads c0, c1, i1 and b0 but nothing sets them"),
            "{}",
            d.message
        );
        assert_eq!(d.secondary.len(), 3);
        assert!(d.help.unwrap().contains(
            "--const c0=x,y,z,w --const c1=x,y,z,w --int i1=N[,start,step,0] --bool b0=true|false"
        ));
    }

    fn audit_of(src: &str) -> Vec<Finding> {
        let l = load_str("t.psh", src, &Options::default()).unwrap();
        audit(&l.shader, &l.defines_used, &Given::default())
    }
}
