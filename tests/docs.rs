//! The guide's examples are run: every ```console block of README.md and of
//! every page of docs/ holds `$ ps30 ARGS` lines, each run from the
//! repository root with the built binary, and the lines after it up to the
//! next `$` line or the end of the block are its exact standard output,
//! except that a line holding only `...` matches any number of lines. A
//! command ending in `2>&1` is compared on its standard output followed by
//! its standard error (an error's message, which goes to stderr).
//! Examples write under `target/docs-examples/`. Arguments are split at
//! spaces; single or double quotes keep spaces in one argument.

use std::path::{Path, PathBuf};
use std::process::Command;

/// One `$ ps30 …` line and the output it must print.
struct Example {
    place: String,
    args: Vec<String>,
    /// `2>&1`: standard error is compared too, after standard output.
    stderr: bool,
    expected: Vec<String>,
}

/// README.md and docs/*.md, sorted.
fn pages(root: &Path) -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    pages.insert(0, root.join("README.md"));
    pages
}

/// The examples of one page, in order.
fn examples(name: &str, text: &str) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    let mut in_console = false;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_end();
        if !in_console {
            in_console = trimmed == "```console";
            continue;
        }
        if trimmed.starts_with("```") {
            in_console = false;
        } else if let Some(command) = trimmed.strip_prefix("$ ") {
            let mut words = split(command);
            let stderr = words.last().is_some_and(|w| w == "2>&1");
            if stderr {
                words.pop();
            }
            assert_eq!(
                words.first().map(String::as_str),
                Some("ps30"),
                "{name}:{}: a console example runs ps30",
                i + 1
            );
            out.push(Example {
                place: format!("{name}:{}", i + 1),
                args: words[1..].to_vec(),
                stderr,
                expected: Vec::new(),
            });
        } else {
            let example = out
                .last_mut()
                .unwrap_or_else(|| panic!("{name}:{}: output before any `$ ps30` line", i + 1));
            example.expected.push(line.to_string());
        }
    }
    assert!(!in_console, "{name}: a console block is not closed");
    out
}

/// Splits a command line at spaces, quotes keeping spaces.
fn split(command: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut quote = None;
    let mut started = false;
    for c in command.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                started = true;
            }
            (None, ' ') => {
                if started || !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
                started = false;
            }
            (None, c) => word.push(c),
        }
    }
    if started || !word.is_empty() {
        words.push(word);
    }
    words
}

/// Whether `actual` matches `expected`, where a line `...` matches any
/// number of lines.
fn matches(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((first, rest)) if first == "..." => {
            (0..=actual.len()).any(|skip| matches(rest, &actual[skip..]))
        }
        Some((first, rest)) => actual
            .split_first()
            .is_some_and(|(a, more)| a == first && matches(rest, more)),
    }
}

#[test]
fn every_console_example_prints_what_the_guide_says() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(root.join("target/docs-examples")).unwrap();
    let mut failures = Vec::new();
    let mut count = 0;
    for page in pages(root) {
        let name = page.strip_prefix(root).unwrap().display().to_string();
        let text = std::fs::read_to_string(&page).unwrap();
        for example in examples(&name, &text) {
            count += 1;
            let out = Command::new(env!("CARGO_BIN_EXE_ps30"))
                .args(&example.args)
                .current_dir(root)
                .env_remove("NO_COLOR")
                .output()
                .expect("run ps30");
            let mut stdout = String::from_utf8_lossy(&out.stdout).into_owned();
            if example.stderr {
                stdout.push_str(&String::from_utf8_lossy(&out.stderr));
            }
            let actual: Vec<&str> = stdout.lines().collect();
            if !matches(&example.expected, &actual) {
                failures.push(format!(
                    "{}: `ps30 {}` printed:\n{stdout}\n(stderr: {})",
                    example.place,
                    example.args.join(" "),
                    String::from_utf8_lossy(&out.stderr)
                ));
            }
        }
    }
    assert!(count > 0, "no console examples found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_matcher_and_the_splitter() {
    let e = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert!(matches(&e(&["a", "...", "d"]), &["a", "b", "c", "d"]));
    assert!(matches(&e(&["a", "..."]), &["a"]));
    assert!(!matches(&e(&["a", "b"]), &["a", "b", "c"]));
    assert!(!matches(&e(&["a", "...", "x"]), &["a", "b"]));
    assert_eq!(split("check 'a b' c"), e(&["check", "a b", "c"]));
    assert_eq!(split("x \"\" y"), e(&["x", "", "y"]));
}
