//! The shape of the crate, checked: imports point one way (core ← jobs ←
//! presentation ← command line), the library holds no command-line types,
//! no two modules import each other, directly or around a cycle, no
//! function is longer than a reader can hold ([`MAX_FUNCTION_LINES`]), and
//! every test file is part of the one test binary.
//!
//! The check reads the sources: every `crate::…` and `super::…` path in
//! code (comments and strings stripped), including the groups of `use`
//! statements, is resolved to the module it names. It is a textual reader,
//! not a compiler, so it errs on the side of seeing an import that is not
//! there (a doc link in code position, say) rather than missing one.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module path such as `core::emu::exec` (empty for the crate root).
type Module = Vec<String>;

/// Every `.rs` file under `src/` with the module path it defines. The
/// binary's modules (`main.rs`, `cli/`) are rooted at `bin`.
fn modules(src: &Path) -> BTreeMap<Module, PathBuf> {
    let mut out = BTreeMap::new();
    let mut stack = vec![src.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let rel = path.strip_prefix(src).unwrap();
            let mut parts: Module = rel
                .iter()
                .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
                .collect();
            if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
                parts.pop();
            }
            if parts.first().is_some_and(|p| p == "cli" || p == "main") {
                if parts[0] == "main" {
                    parts.clear();
                }
                parts.insert(0, "bin".into());
            }
            out.insert(parts, path);
        }
    }
    out
}

/// The source without comments, string and character literals. Line breaks
/// inside them are kept, so line numbers stay those of the source.
fn code_only(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let start = i;
                i += 2;
                while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b'/') {
                    i += 1;
                }
                i += 2;
                push_line_breaks(&mut out, &b[start..i.min(b.len())]);
            }
            b'r' if b.get(i + 1) == Some(&b'#') || b.get(i + 1) == Some(&b'"') => {
                // raw string r"…" or r#"…"#
                let mut j = i + 1;
                let mut hashes = 0;
                while b.get(j) == Some(&b'#') {
                    hashes += 1;
                    j += 1;
                }
                if b.get(j) != Some(&b'"')
                    || (i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
                {
                    out.push('r');
                    i += 1;
                    continue;
                }
                j += 1;
                let close: Vec<u8> = std::iter::once(b'"')
                    .chain(std::iter::repeat_n(b'#', hashes))
                    .collect();
                while j < b.len() && !b[j..].starts_with(&close) {
                    j += 1;
                }
                out.push_str("\"\"");
                push_line_breaks(&mut out, &b[i..j.min(b.len())]);
                i = j + close.len();
            }
            b'"' => {
                let start = i;
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
                out.push_str("\"\"");
                push_line_breaks(&mut out, &b[start..i.min(b.len())]);
            }
            b'\'' if b.get(i + 2) == Some(&b'\'') || (b.get(i + 1) == Some(&b'\\')) => {
                // a char literal ('x' or '\n'); lifetimes ('a) are left alone
                let mut j = i + 1;
                if b[j] == b'\\' {
                    j += 2;
                }
                while j < b.len() && b[j] != b'\'' {
                    j += 1;
                }
                i = j + 1;
                out.push_str("' '");
            }
            _ => {
                let ch = text[i..].chars().next().unwrap();
                out.push(ch);
                i += ch.len_utf8();
            }
        }
    }
    out
}

/// Appends the line breaks of `cut`, text left out of [`code_only`]'s output.
fn push_line_breaks(out: &mut String, cut: &[u8]) {
    for _ in cut.iter().filter(|&&c| c == b'\n') {
        out.push('\n');
    }
}

/// Expands a `use` tree (`a::{b, c::{d, e}}`) into plain paths.
fn expand_use(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        return vec![tree];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.len() - 1];
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(|p| {
            expand_use(p)
                .into_iter()
                .map(move |q| format!("{prefix}{q}"))
        })
        .collect()
}

/// The code with every `#[cfg(test)]` item cut out: a module's unit tests
/// are its own business.
fn without_test_modules(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while let Some(at) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..at]);
        let after = &rest[at..];
        let Some(open) = after.find('{') else {
            return out;
        };
        let mut depth = 0;
        let mut end = after.len();
        for (i, c) in after[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + i + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// Every path (`crate::a::b`, `super::c`, `ps30::d`) a module's code names.
fn paths_in(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    // `use` statements first, with their groups.
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before_ok = at == 0
            || !rest.as_bytes()[at - 1].is_ascii_alphanumeric() && rest.as_bytes()[at - 1] != b'_';
        let stmt_end = rest[at..].find(';').map_or(rest.len(), |e| at + e);
        if before_ok {
            out.extend(expand_use(&rest[at + 4..stmt_end]));
        }
        rest = &rest[(at + 4).min(rest.len())..];
    }
    // Then every inline path.
    let bytes = code.as_bytes();
    for root in ["crate::", "super::", "ps30::", "self::"] {
        let mut from = 0;
        while let Some(pos) = code[from..].find(root) {
            let start = from + pos;
            from = start + root.len();
            if start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'_') {
                continue;
            }
            let mut end = start;
            while end < bytes.len()
                && (bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_' || bytes[end] == b':')
            {
                end += 1;
            }
            out.push(code[start..end].trim_end_matches(':').to_string());
        }
    }
    out
}

/// The module a path names, seen from module `from`: its longest prefix
/// that is a module of the crate.
fn resolve(path: &str, from: &Module, known: &BTreeMap<Module, PathBuf>) -> Option<Module> {
    let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let (mut base, rest): (Module, &[&str]) = match *segs.first()? {
        "crate" => (
            if from.first().is_some_and(|f| f == "bin") {
                vec!["bin".into()]
            } else {
                vec![]
            },
            &segs[1..],
        ),
        "ps30" => (vec![], &segs[1..]),
        // Paths in a file are relative to the module the file defines.
        "self" => (from.clone(), &segs[1..]),
        "super" => {
            let mut b = from.clone();
            let mut i = 0;
            while segs.get(i) == Some(&"super") {
                b.pop();
                i += 1;
            }
            (b, &segs[i..])
        }
        _ => return None,
    };
    let mut best = None;
    for s in rest {
        base.push(s.to_string());
        if known.contains_key(&base) {
            best = Some(base.clone());
        } else {
            break;
        }
    }
    best
}

/// Edges between modules: `from` names `to`.
fn edges() -> (BTreeMap<Module, PathBuf>, BTreeSet<(Module, Module)>) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let known = modules(&src);
    let mut edges = BTreeSet::new();
    for (m, file) in &known {
        let code = without_test_modules(&code_only(&std::fs::read_to_string(file).unwrap()));
        for p in paths_in(&code) {
            if let Some(to) = resolve(&p, m, &known) {
                if &to != m && !m.starts_with(&to) {
                    edges.insert((m.clone(), to));
                }
            }
        }
    }
    (known, edges)
}

fn level(m: &Module) -> usize {
    match m.first().map(String::as_str) {
        Some("core") => 0,
        Some("jobs") => 1,
        Some("present") => 2,
        Some("bin") => 3,
        _ => 4, // the crate root (lib.rs) declares the levels
    }
}

fn name(m: &Module) -> String {
    if m.is_empty() {
        "crate".into()
    } else {
        m.join("::")
    }
}

#[test]
fn imports_point_down_the_levels() {
    let (_, edges) = edges();
    let wrong: Vec<String> = edges
        .iter()
        .filter(|(from, to)| level(from) < 4 && level(to) < 4 && level(to) > level(from))
        .map(|(from, to)| format!("{} imports {}", name(from), name(to)))
        .collect();
    assert!(
        wrong.is_empty(),
        "imports that point up a level:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_library_holds_no_command_line_types() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    for (m, file) in modules(&src) {
        if level(&m) == 3 {
            continue;
        }
        let code = code_only(&std::fs::read_to_string(&file).unwrap());
        if code.contains("clap") {
            found.push(name(&m));
        }
    }
    assert!(found.is_empty(), "library modules that use clap: {found:?}");
}

/// Cycles among `nodes` under `edges` (each reported once, by Tarjan's
/// strongly connected components).
fn cycles(edges: &BTreeSet<(Module, Module)>) -> Vec<Vec<Module>> {
    let mut nodes: BTreeSet<Module> = BTreeSet::new();
    for (a, b) in edges {
        nodes.insert(a.clone());
        nodes.insert(b.clone());
    }
    let nodes: Vec<Module> = nodes.into_iter().collect();
    let index_of: BTreeMap<&Module, usize> =
        nodes.iter().enumerate().map(|(i, m)| (m, i)).collect();
    let mut adj = vec![Vec::new(); nodes.len()];
    for (a, b) in edges {
        adj[index_of[a]].push(index_of[b]);
    }
    struct T {
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(v: usize, adj: &[Vec<usize>], t: &mut T) {
        t.index[v] = Some(t.next);
        t.low[v] = t.next;
        t.next += 1;
        t.stack.push(v);
        t.on[v] = true;
        for &w in &adj[v] {
            match t.index[w] {
                None => {
                    visit(w, adj, t);
                    t.low[v] = t.low[v].min(t.low[w]);
                }
                Some(iw) if t.on[w] => t.low[v] = t.low[v].min(iw),
                _ => {}
            }
        }
        if Some(t.low[v]) == t.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = t.stack.pop().unwrap();
                t.on[w] = false;
                comp.push(w);
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                t.out.push(comp);
            }
        }
    }
    let n = nodes.len();
    let mut t = T {
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() {
            visit(v, &adj, &mut t);
        }
    }
    t.out
        .into_iter()
        .map(|c| c.into_iter().map(|i| nodes[i].clone()).collect())
        .collect()
}

#[test]
fn no_module_imports_another_around_a_cycle() {
    let (_, edges) = edges();
    let found = cycles(&edges);
    let text: Vec<String> = found
        .iter()
        .map(|c| c.iter().map(name).collect::<Vec<_>>().join(" ↔ "))
        .collect();
    assert!(
        text.is_empty(),
        "modules in import cycles:\n{}",
        text.join("\n")
    );
}

#[test]
fn no_folder_imports_another_around_a_cycle() {
    // The same at the level of the folders a newcomer sees: core::emu,
    // core::image, jobs::luminance, present::report, ...
    let (_, edges) = edges();
    let folder = |m: &Module| -> Module { m.iter().take(2).cloned().collect() };
    let folded: BTreeSet<(Module, Module)> = edges
        .iter()
        .map(|(a, b)| (folder(a), folder(b)))
        .filter(|(a, b)| a != b && !a.is_empty() && !b.is_empty() && a.len() == 2 && b.len() == 2)
        .collect();
    let found = cycles(&folded);
    let text: Vec<String> = found
        .iter()
        .map(|c| c.iter().map(name).collect::<Vec<_>>().join(" ↔ "))
        .collect();
    assert!(
        text.is_empty(),
        "folders in import cycles:\n{}",
        text.join("\n")
    );
}

#[test]
fn the_reader_sees_imports() {
    // The checks above are only as good as this reader: it must see a
    // grouped `use`, a `super::` path and an inline path, and must not see
    // one in a comment or a string.
    let code = without_test_modules(&code_only(
        "use super::{exec::Worker, math::{log, exp}};\n// use crate::jobs::x;\nlet s = \"crate::present::y\";\n#[cfg(test)]\nmod tests { use crate::jobs::z; }\nlet v = crate::core::isa::X;\n",
    ));
    let paths = paths_in(&code);
    for want in [
        "super::exec::Worker",
        "super::math::log",
        "super::math::exp",
        "crate::core::isa::X",
    ] {
        assert!(
            paths.iter().any(|p| p == want),
            "{want} not seen in {paths:?}"
        );
    }
    assert!(
        !paths
            .iter()
            .any(|p| p.contains("jobs") || p.contains("present")),
        "{paths:?}"
    );
}

// ----- function length ---------------------------------------------------------

/// The longest a function in `src/` may be, from its `fn` line to its
/// closing brace: long functions are split along their natural seams (one
/// function per instruction family, per check, per phase).
const MAX_FUNCTION_LINES: usize = 150;

/// Functions allowed to be longer, as (file under `src/`, function name,
/// why). Only tables belong here: a function whose length is its data, one
/// row per line, reads no better split. None does today (the instruction
/// table, `core/isa.rs`'s `TABLE`, is a constant, not a function).
const LONG_FUNCTIONS_ALLOWED: &[(&str, &str, &str)] = &[];

/// A function found in source code.
#[derive(Debug, PartialEq)]
struct Function {
    name: String,
    /// 1-based line of its `fn`.
    line: usize,
    /// Lines from its `fn` to its closing brace, both included.
    lines: usize,
}

/// Every function with a body in `code` (the output of [`code_only`], so no
/// brace of a comment or a string counts), nested ones included.
fn functions(code: &str) -> Vec<Function> {
    let b = code.as_bytes();
    let line_starts: Vec<usize> = std::iter::once(0)
        .chain(code.match_indices('\n').map(|(i, _)| i + 1))
        .collect();
    let line_of = |pos: usize| line_starts.partition_point(|&s| s <= pos);
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(pos) = code[from..].find("fn") {
        let at = from + pos;
        from = at + 2;
        if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
            continue;
        }
        let after = &code[at + 2..];
        let rest = after.trim_start();
        if rest.len() == after.len() {
            continue; // `fn(` of a function pointer type, or `fnord`
        }
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            continue;
        }
        // The body is the first `{` outside parentheses and brackets (an
        // array type `[T; N]` holds a `;`); a `;` there ends a declaration
        // without one.
        let mut depth = 0i32;
        let mut open = None;
        for (k, &c) in b.iter().enumerate().skip(at + 2) {
            match c {
                b'(' | b'[' => depth += 1,
                b')' | b']' => depth -= 1,
                b'{' if depth == 0 => {
                    open = Some(k);
                    break;
                }
                b';' if depth == 0 => break,
                _ => {}
            }
        }
        let Some(open) = open else { continue };
        let mut depth = 0i32;
        let close = b[open..].iter().position(|&c| {
            match c {
                b'{' => depth += 1,
                b'}' => depth -= 1,
                _ => {}
            }
            depth == 0
        });
        let Some(close) = close else { continue };
        out.push(Function {
            name,
            line: line_of(at),
            lines: line_of(open + close) - line_of(at) + 1,
        });
    }
    out
}

#[test]
fn no_function_is_longer_than_a_reader_can_hold() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut long = Vec::new();
    let mut allowed_seen = BTreeSet::new();
    for file in modules(&src).into_values() {
        let rel = file
            .strip_prefix(&src)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        let code = code_only(&std::fs::read_to_string(&file).unwrap());
        for f in functions(&code) {
            if f.lines <= MAX_FUNCTION_LINES {
                continue;
            }
            match LONG_FUNCTIONS_ALLOWED
                .iter()
                .find(|(path, name, _)| *path == rel && *name == f.name)
            {
                Some(&(path, name, _)) => {
                    allowed_seen.insert((path, name));
                }
                None => long.push(format!(
                    "src/{rel}:{} fn {}: {} lines",
                    f.line, f.name, f.lines
                )),
            }
        }
    }
    assert!(
        long.is_empty(),
        "functions longer than {MAX_FUNCTION_LINES} lines (split them along their seams, \
         or add a table to LONG_FUNCTIONS_ALLOWED with the reason):\n{}",
        long.join("\n")
    );
    // An allowance outlives its function's length only by mistake.
    let stale: Vec<String> = LONG_FUNCTIONS_ALLOWED
        .iter()
        .filter(|(path, name, _)| !allowed_seen.contains(&(*path, *name)))
        .map(|(path, name, _)| format!("src/{path} fn {name}"))
        .collect();
    assert!(
        stale.is_empty(),
        "LONG_FUNCTIONS_ALLOWED names functions that are no longer than \
         {MAX_FUNCTION_LINES} lines (or no longer exist):\n{}",
        stale.join("\n")
    );
}

#[test]
fn the_reader_measures_functions() {
    // The length check is only as good as this measure: braces in strings
    // and comments do not count, line breaks inside them do, an array type
    // in a signature does not end it, a declaration without a body is not a
    // function, and a function one line over the limit is seen as such.
    let long_body = "    let x = 1;\n".repeat(MAX_FUNCTION_LINES - 1);
    let text = format!(
        "trait T {{\n    fn declared(&self) -> [u8; 4];\n}}\n\
         fn short(a: [u8; 2]) -> u8 {{\n    let s = \"}} {{\n}}\";\n    /* }}\n */ a[0] // }}\n}}\n\
         fn long() {{\n{long_body}}}\n\
         pub(crate) fn outer() {{\n    fn inner() {{}}\n    let f: fn(u8) = |_| {{}};\n}}\n"
    );
    let found = functions(&code_only(&text));
    let want = [
        ("short", 4, 6),
        ("long", 10, MAX_FUNCTION_LINES + 1),
        ("outer", 10 + MAX_FUNCTION_LINES + 1, 4),
        ("inner", 10 + MAX_FUNCTION_LINES + 2, 1),
    ];
    let want: Vec<Function> = want
        .iter()
        .map(|&(name, line, lines)| Function {
            name: name.into(),
            line,
            lines,
        })
        .collect();
    assert_eq!(found, want);
    assert!(found[1].lines > MAX_FUNCTION_LINES);
}

/// The integration tests are one binary (`tests/suite.rs`, `autotests =
/// false` in Cargo.toml): a file in `tests/` that `suite.rs` does not
/// declare would never be compiled or run.
#[test]
fn every_test_file_is_part_of_the_suite() {
    let tests = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let suite = std::fs::read_to_string(tests.join("suite.rs")).unwrap();
    let declared: BTreeSet<&str> = suite
        .lines()
        .filter_map(|l| l.strip_prefix("mod ")?.strip_suffix(';'))
        .collect();
    let mut files = BTreeSet::new();
    for entry in std::fs::read_dir(&tests).unwrap() {
        let path = entry.unwrap().path();
        let is_rust = path.extension().is_some_and(|e| e == "rs");
        let stem = path.file_stem().unwrap().to_str().unwrap().to_string();
        if is_rust && stem != "suite" {
            files.insert(stem);
        }
    }
    let missing: Vec<&String> = files
        .iter()
        .filter(|f| !declared.contains(f.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "tests/suite.rs does not declare {missing:?}"
    );
    // And the reading above finds the declarations it should: every file,
    // plus `common`, which is a folder.
    assert_eq!(declared.len(), files.len() + 1, "{declared:?}");
    assert!(declared.contains("common") && declared.contains("layering"));
}
