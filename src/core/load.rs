//! A shader's bytes to validated shader in one call: recognise text or
//! bytecode, parse, expand REPEAT_BLOCK, lower and validate — and, for
//! `ps30 asm`, write the tokens.
//!
//! The [`front`](crate::core::front) end and [`valid`](crate::core::valid)
//! are separate stages joined by the AST; this module is the one place that
//! runs them in order and gathers every diagnostic on the way, so a caller
//! gets either a [`Shader`] with its warnings or all the errors at once.
//! Every command reads shaders through [`source_file`], which tells a
//! compiled shader from text by its first token (never by its name) and
//! turns it into its listing ([`bytecode::listing`]), so everything after
//! this point sees one kind of source.

use crate::core::bytecode::{self, ctab, ReadError};
use crate::core::diag::{codes, Diagnostic, Diagnostics, SourceError, SourceFile};
use crate::core::front::{ast, parse, repeat};
use crate::core::ir::Shader;
use crate::core::profile::Profile;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

/// Options of the front end.
#[derive(Clone, Debug)]
pub struct Options {
    /// Names usable as REPEAT_BLOCK counts (`-D name=value`).
    pub defines: BTreeMap<String, u64>,
    /// Cap on expanded statements (and on the items of a compiled shader).
    pub max_expanded: u64,
    /// `--strict`: the documented rules Microsoft's assembler does not
    /// enforce (warnings by default) are errors.
    pub strict: bool,
    /// `--caps`: the capabilities a ps_2_x shader is held to
    /// (`core/valid/caps.rs`); `None`: the assembler's, every one on.
    pub caps: Option<crate::core::profile::Ps2xCaps>,
    /// `--ps1-max-value`: D3DCAPS9.PixelShader1xMaxValue, the range of a
    /// ps_1_x shader's registers when it runs (`core/ps1/run.rs`).
    pub ps1_max_value: f32,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            defines: BTreeMap::new(),
            max_expanded: repeat::DEFAULT_MAX_EXPANDED,
            strict: false,
            caps: None,
            ps1_max_value: crate::core::ps1::run::DEFAULT_MAX_VALUE,
        }
    }
}

/// A shader loaded from source, with the warnings found on the way.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The source (a compiled shader: its listing).
    pub file: SourceFile,
    /// The validated shader.
    pub shader: Shader,
    /// Warnings of validation (errors make no `Loaded`).
    pub warnings: Diagnostics,
    /// The constant table the shader carries (fxc's `CTAB` comment block).
    pub constants: Option<ctab::ConstantTable>,
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

/// Bytes that are not a shader ps30 can read.
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // name: the input as messages call it; the rest as each variant says
pub enum NotASource {
    /// A compiled shader that does not read.
    Bytecode { name: String, error: ReadError },
    /// Text in UTF-16 or UTF-32, told by its byte-order mark.
    Wide {
        name: String,
        encoding: &'static str,
    },
    /// A Direct3D 10+ shader container.
    Dxbc { name: String },
}

impl fmt::Display for NotASource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NotASource::Bytecode { name, error } => write!(f, "{name}: {error}"),
            NotASource::Wide { name, encoding } => write!(
                f,
                "{name}: a {encoding} byte-order mark: the text is {encoding}, which Microsoft's assembler does not read ({}: shader version expected); save the file as ASCII or UTF-8 without a byte-order mark",
                codes::VERSION
            ),
            NotASource::Dxbc { name } => write!(
                f,
                "{name}: a Direct3D 10 or later shader (DXBC container); ps30 reads Direct3D 9 ps_3_0"
            ),
        }
    }
}

impl std::error::Error for NotASource {}

impl NotASource {
    /// Microsoft's code for the same input, where `D3DAssemble` refuses it
    /// too (a compiled shader or a DXBC container is not its input).
    pub fn code(&self) -> Option<codes::Code> {
        match self {
            NotASource::Wide { .. } => Some(codes::VERSION),
            _ => None,
        }
    }
}

/// The byte-order marks of UTF-32 and UTF-16 (UTF-32 LE first: it starts
/// with UTF-16 LE's).
const WIDE_MARKS: [(&[u8], &str); 4] = [
    (&[0xff, 0xfe, 0, 0], "UTF-32"),
    (&[0, 0, 0xfe, 0xff], "UTF-32"),
    (&[0xff, 0xfe], "UTF-16"),
    (&[0xfe, 0xff], "UTF-16"),
];

/// A shader's source from its bytes: a compiled shader (its first token is
/// a version token) becomes its listing; anything else is text, read as
/// Microsoft's assembler reads it: up to the first NUL byte (what follows
/// is ignored), UTF-8, or one byte a character where it is not UTF-8
/// (comments in a Windows code page; any such character outside a comment
/// is refused by the parser). UTF-16 and UTF-32 text is refused by its
/// byte-order mark; a UTF-8 byte-order mark is kept for the parser to
/// refuse where it stands.
pub fn source_file(
    name: &str,
    mut bytes: Vec<u8>,
    options: &Options,
) -> Result<SourceFile, NotASource> {
    if crate::core::ps1::tokens::is_ps1(&bytes) {
        // ps_1_x: its own token stream, read as Microsoft's listing of it.
        let program =
            crate::core::ps1::tokens::decode(&bytes, options.max_expanded).map_err(|error| {
                NotASource::Bytecode {
                    name: name.to_string(),
                    error,
                }
            })?;
        let text = crate::core::ps1::listing::listing(&program);
        let crc = bytecode::crc32(&bytes);
        return Ok(SourceFile::compiled(name, text, Vec::new()).with_bytecode_crc32(crc));
    }
    if bytecode::is_bytecode(&bytes) {
        let module = bytecode::read::read(&bytes, options.max_expanded).map_err(|error| {
            NotASource::Bytecode {
                name: name.to_string(),
                error,
            }
        })?;
        let l = bytecode::listing::listing(&module);
        let crc = bytecode::crc32(&bytes);
        return Ok(SourceFile::compiled(name, l.text, l.anchors).with_bytecode_crc32(crc));
    }
    if bytes.starts_with(b"DXBC") {
        return Err(NotASource::Dxbc { name: name.into() });
    }
    if let Some(&(_, encoding)) = WIDE_MARKS.iter().find(|(m, _)| bytes.starts_with(m)) {
        return Err(NotASource::Wide {
            name: name.into(),
            encoding,
        });
    }
    if let Some(nul) = bytes.iter().position(|&b| b == 0) {
        bytes.truncate(nul);
    }
    let text = String::from_utf8(bytes)
        .unwrap_or_else(|e| e.into_bytes().into_iter().map(char::from).collect());
    Ok(SourceFile::new(name, text))
}

/// Microsoft's listing (`D3DDisassemble`'s text) of a compiled shader of
/// any profile ps30 reads, ps_1_x included (at most `max_items` items).
pub fn microsoft_listing(bytes: &[u8], max_items: u64) -> Result<String, ReadError> {
    if crate::core::ps1::tokens::is_ps1(bytes) {
        let program = crate::core::ps1::tokens::decode(bytes, max_items)?;
        return Ok(crate::core::ps1::listing::listing(&program));
    }
    bytecode::read::read(bytes, max_items).map(|m| bytecode::microsoft::listing(&m))
}

/// What the stages produced on the way to a shader.
struct Stages {
    stmts: Vec<ast::Stmt>,
    expanded: Vec<repeat::Expanded>,
    loaded: Loaded,
}

/// Parses, expands and validates a source file.
pub fn load(file: SourceFile, options: &Options) -> Result<Loaded, SourceError> {
    if let Some(profile) = ps1_version(&file.text) {
        return ps1_stages(file, profile, options).map(|(loaded, _)| loaded);
    }
    stages(file, options).map(|s| s.loaded)
}

/// The ps_1_x version a source's first statement names, if it names one:
/// such a source goes through [`crate::core::ps1`] (another instruction
/// set and syntax).
pub fn ps1_version(text: &str) -> Option<Profile> {
    text.lines()
        .map(|l| parse::strip_comment(l).trim())
        .find(|l| !l.is_empty())
        .and_then(Profile::from_version_line)
        .filter(|p| p.is_ps1())
}

/// A ps_1_x source through [`crate::core::ps1`]: the shader and its program.
fn ps1_stages(
    file: SourceFile,
    profile: Profile,
    options: &Options,
) -> Result<(Loaded, crate::core::ps1::Program), SourceError> {
    match crate::core::ps1::load(&file, profile, options.ps1_max_value) {
        Ok(l) => Ok((
            Loaded {
                file,
                shader: l.shader,
                warnings: Diagnostics::default(),
                constants: None,
                defines_used: BTreeSet::new(),
            },
            l.program,
        )),
        Err(diagnostics) => Err(SourceError { file, diagnostics }),
    }
}

/// Loads a shader from a string (name used in messages).
pub fn load_str(name: &str, text: &str, options: &Options) -> Result<Loaded, SourceError> {
    load(SourceFile::new(name, text), options)
}

/// Loads a source and writes its tokens (`ps30 asm`): the program must
/// validate; its comment blocks, the constant table among them, are
/// written where they stand.
pub fn assemble(file: SourceFile, options: &Options) -> Result<(Loaded, Vec<u32>), SourceError> {
    if let Some(profile) = ps1_version(&file.text) {
        let (loaded, program) = ps1_stages(file, profile, options)?;
        return Ok((loaded, crate::core::ps1::tokens::encode(&program)));
    }
    let s = stages(file, options)?;
    if s.loaded.warnings.warnings().any(|d| d.code.is_some()) {
        // What Microsoft's assembler refuses is not written.
        let mut diagnostics = s.loaded.warnings;
        diagnostics.make_refusals();
        return Err(SourceError {
            file: s.loaded.file,
            diagnostics,
        });
    }
    match bytecode::write::assemble(&s.stmts, &s.expanded) {
        Ok(module) => Ok((s.loaded, bytecode::write::encode(&module))),
        Err(diagnostics) => Err(SourceError {
            file: s.loaded.file,
            diagnostics,
        }),
    }
}

fn stages(file: SourceFile, options: &Options) -> Result<Stages, SourceError> {
    let fail = |file: SourceFile, mut diagnostics: Diagnostics| {
        diagnostics.sort();
        Err(SourceError { file, diagnostics })
    };
    if let Some(d) = parse::missing_version(&file.text) {
        // Not a shader at all: one error saying so, not one per line.
        return fail(file, only(d));
    }
    let (stmts, mut diags) = parse::parse(&file.text);
    if let Some(d) = other_version(&stmts) {
        // The rest would be judged by the wrong rules: the version says it all.
        return fail(file, only(d));
    }
    let profile = stmts
        .first()
        .and_then(crate::core::valid::checked_profile)
        .unwrap_or_default();
    if diags.has_errors() {
        // Still report macro problems of the lines that did parse.
        if let Err(more) = repeat::expand(&stmts, &options.defines, options.max_expanded) {
            diags.extend(more);
        }
        // And the checks of each line that did parse on its own.
        for stmt in &stmts {
            if let ast::Stmt::Instr(instr) = stmt {
                if let Err(d) = crate::core::valid::lower::lower(instr, profile) {
                    diags.push(d);
                }
            }
        }
        return fail(file, diags);
    }
    let expanded = match repeat::expand(&stmts, &options.defines, options.max_expanded) {
        Ok(e) => e,
        Err(d) => return fail(file, d),
    };
    let constants = match constant_table(expanded.iter().map(|e| &stmts[e.stmt])) {
        Ok(t) => t,
        Err(d) => return fail(file, only(d)),
    };
    let validated = crate::core::valid::validate(&stmts, &expanded, &file).and_then(|(s, w)| {
        let refused = match options.caps {
            Some(caps) => crate::core::valid::caps::check(s.program(), s.info(), caps, &file),
            None => Diagnostics::default(),
        };
        if refused.has_errors() {
            Err(refused)
        } else {
            Ok((s, w))
        }
    });
    match validated {
        Ok((_, mut warnings)) if options.strict && warnings.has_strict() => {
            warnings.make_strict();
            fail(file, warnings)
        }
        Ok((shader, mut warnings)) => {
            warnings.sort();
            let defines_used = count_names(&stmts);
            Ok(Stages {
                stmts,
                expanded,
                loaded: Loaded {
                    defines_used,
                    file,
                    shader,
                    warnings,
                    constants,
                },
            })
        }
        Err(d) => fail(file, d),
    }
}

/// One diagnostic as the list of a file.
fn only(d: Diagnostic) -> Diagnostics {
    let mut all = Diagnostics::default();
    all.push(d);
    all
}

/// A first statement that names a shader model ps30 does not check
/// (`ps_1_4`, `ps_2_b`, `ps_4_0`).
fn other_version(stmts: &[ast::Stmt]) -> Option<Diagnostic> {
    let first = stmts.first()?;
    match first {
        ast::Stmt::Version { text, span, .. }
            if crate::core::valid::checked_profile(first).is_none() =>
        {
            Some(crate::core::valid::version_refusal(text, *span))
        }
        _ => None,
    }
}

/// The constant table of a source, when it carries one that decodes: for
/// looking names up before a job loads the shader (a table that does not
/// decode is an error when the shader is loaded).
pub fn constant_table_of(file: &SourceFile, options: &Options) -> Option<ctab::ConstantTable> {
    let (stmts, _) = parse::parse(&file.text);
    let expanded = repeat::expand(&stmts, &options.defines, options.max_expanded).ok()?;
    constant_table(expanded.iter().map(|e| &stmts[e.stmt]))
        .ok()
        .flatten()
}

/// The first `CTAB` comment block of the program as it will be written (the
/// expanded statements: a block inside `BEGIN_REPEAT_BLOCK(0)` is not
/// written, so it is no table), decoded. Every other `CTAB` block must
/// decode too, as the bytecode reader requires of what `asm` writes.
fn constant_table<'a>(
    stmts: impl Iterator<Item = &'a ast::Stmt>,
) -> Result<Option<ctab::ConstantTable>, Diagnostic> {
    let mut first = None;
    for stmt in stmts {
        let ast::Stmt::Comment { tokens, span } = stmt else {
            continue;
        };
        if tokens.first() != Some(&bytecode::CTAB) {
            continue;
        }
        let table = ctab::decode(&tokens[1..]).map_err(|e| {
            Diagnostic::error(
                *span,
                format!("the constant table does not decode: {}", e.message),
            )
            .with_label(format!("at byte {} of the table", e.offset))
        })?;
        first.get_or_insert(table);
    }
    Ok(first)
}
