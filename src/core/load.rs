//! Text to validated shader in one call: parse, expand REPEAT_BLOCK, lower
//! and validate.
//!
//! The [`front`](crate::core::front) end and [`valid`](crate::core::valid)
//! are separate stages joined by the AST; this module is the one place that
//! runs them in order and gathers every diagnostic on the way, so a caller
//! gets either a [`Shader`] with its warnings or all the errors at once.

use crate::core::diag::{Diagnostics, SourceError, SourceFile};
use crate::core::front::{ast, parse, repeat};
use crate::core::ir::{Origin, Shader};
use std::collections::{BTreeMap, BTreeSet};

/// Options of the front end.
#[derive(Clone, Debug)]
pub struct Options {
    /// Names usable as REPEAT_BLOCK counts (`-D name=value`).
    pub defines: BTreeMap<String, u64>,
    /// Cap on expanded statements.
    pub max_expanded: u64,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            defines: BTreeMap::new(),
            max_expanded: repeat::DEFAULT_MAX_EXPANDED,
        }
    }
}

/// A shader loaded from source, with the warnings found on the way.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The source, for diagnostics.
    pub file: SourceFile,
    /// The validated shader.
    pub shader: Shader,
    /// Warnings of validation (errors make no `Loaded`).
    pub warnings: Diagnostics,
    /// The names the source uses as REPEAT_BLOCK counts (what `-D` can
    /// bind; see [`crate::core::audit`]).
    pub defines_used: BTreeSet<String>,
}

/// The names used as REPEAT_BLOCK counts in `stmts`.
fn count_names(stmts: &[ast::Stmt]) -> BTreeSet<String> {
    stmts
        .iter()
        .filter_map(|s| match s {
            ast::Stmt::RepeatBegin {
                count: ast::Count::Name { name, .. },
                ..
            } => Some(name.clone()),
            _ => None,
        })
        .collect()
}

/// Parses, expands and validates a source file.
pub fn load(file: SourceFile, options: &Options) -> Result<Loaded, SourceError> {
    if let Some(d) = parse::missing_version(&file.text) {
        let mut diagnostics = Diagnostics::default();
        diagnostics.push(d);
        return Err(SourceError { file, diagnostics });
    }
    let (stmts, mut diags) = parse::parse(&file.text);
    if diags.has_errors() {
        // Still report macro problems of the lines that did parse.
        if let Err(more) = repeat::expand(&stmts, &options.defines, options.max_expanded) {
            diags.extend(more);
        }
        // And the checks of each line that did parse on its own.
        for stmt in &stmts {
            if let ast::Stmt::Instr(instr) = stmt {
                let origin = Origin::at(instr.span);
                if let Err(d) = crate::core::valid::lower::lower(instr, &origin) {
                    diags.push(d);
                }
            }
        }
        diags.sort();
        return Err(SourceError {
            file,
            diagnostics: diags,
        });
    }
    let expanded = match repeat::expand(&stmts, &options.defines, options.max_expanded) {
        Ok(e) => e,
        Err(d) => {
            return Err(SourceError {
                file,
                diagnostics: d,
            })
        }
    };
    match crate::core::valid::validate(&stmts, &expanded, &file) {
        Ok((shader, mut warnings)) => {
            warnings.sort();
            Ok(Loaded {
                defines_used: count_names(&stmts),
                file,
                shader,
                warnings,
            })
        }
        Err(mut d) => {
            d.sort();
            Err(SourceError {
                file,
                diagnostics: d,
            })
        }
    }
}

/// Loads a shader from a string (name used in messages).
pub fn load_str(name: &str, text: &str, options: &Options) -> Result<Loaded, SourceError> {
    load(SourceFile::new(name, text), options)
}
