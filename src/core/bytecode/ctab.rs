//! The constant table fxc stores in a comment block (`CTAB`): which
//! uniforms a shader has, by name, and where they live.
//!
//! A user with a compiled shader knows its constants by their HLSL names
//! (`g_fKey`), not by register, so ps30 decodes the table to list them and
//! to accept `--const g_fKey=0.18`. The layout is D3DX's
//! (D3DXSHADER_CONSTANTTABLE, D3DXSHADER_CONSTANTINFO, D3DXSHADER_TYPEINFO,
//! D3DXSHADER_STRUCTMEMBERINFO in d3dx9shader.h; Microsoft's pages of the
//! same names): a 28-byte header (size, creator, version, constant count,
//! constant-info offset, flags, target), 20 bytes per constant (name,
//! register set, index, count, reserved, type-info offset, default-value
//! offset), 16 bytes per type (class, type, rows, columns, elements, member
//! count, member-info offset) and 8 per struct member (name, type); every
//! offset counts bytes from the start of the table, just after `CTAB`.
//! A default value holds, per leaf of the type, four 32-bit values per
//! register row for float and integer registers and one per element for
//! booleans, the way D3DX's `SetDefaults` walks it.
//!
//! The table comes from the file, so it is decoded as hostile: every offset
//! and count is checked against the table's size before it is followed,
//! strings must end inside the table and are at most [`MAX_NAME`] bytes,
//! types nest at most [`MAX_DEPTH`] deep, and the bytes decoded in all
//! (names, types, defaults, shared or not) may not add up to more than
//! [`WORK_FACTOR`] times the table.

use crate::core::isa::RegFile;
use serde::Serialize;

/// Longest name or creator string accepted, in bytes.
pub const MAX_NAME: usize = 1024;
/// Deepest nesting of struct and array types.
pub const MAX_DEPTH: u32 = 16;
/// The decoded bytes may be at most this many times the table's size.
pub const WORK_FACTOR: usize = 8;

/// The decoded table.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ConstantTable {
    /// The compiler that wrote the table (`Microsoft (R) HLSL Shader Compiler …`).
    pub creator: String,
    /// The profile the shader was compiled for (`ps_3_0`).
    pub target: String,
    /// The version token the table names.
    pub version: u32,
    /// D3DXSHADER_* compile flags.
    pub flags: u32,
    /// The uniforms, in the table's order.
    pub constants: Vec<Constant>,
}

/// One uniform of the shader.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Constant {
    /// The HLSL name (`g_fKey`), the name `--const` accepts.
    pub name: String,
    /// Which register file it lives in.
    pub set: RegisterSet,
    /// First register.
    pub index: u16,
    /// Registers it takes.
    pub count: u16,
    /// Its HLSL type, members and array length included.
    #[serde(rename = "type")]
    pub ty: Type,
    /// The default value's 32-bit words, as D3DX lays them out (see the
    /// module docs); `None` when the table gives none.
    pub default: Option<Vec<u32>>,
}

/// D3DXREGISTER_SET.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RegisterSet {
    /// `b#` registers.
    Bool,
    /// `i#` registers.
    Int4,
    /// `c#` registers.
    Float4,
    /// `s#` samplers.
    Sampler,
}

impl RegisterSet {
    /// `bool`, `int4`, `float4`, `sampler`.
    pub fn name(self) -> &'static str {
        match self {
            RegisterSet::Bool => "bool",
            RegisterSet::Int4 => "int4",
            RegisterSet::Float4 => "float4",
            RegisterSet::Sampler => "sampler",
        }
    }

    /// The register prefix (`b`, `i`, `c`, `s`).
    pub fn prefix(self) -> &'static str {
        match self {
            RegisterSet::Bool => "b",
            RegisterSet::Int4 => "i",
            RegisterSet::Float4 => "c",
            RegisterSet::Sampler => "s",
        }
    }
}

/// A D3DXSHADER_TYPEINFO.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Type {
    /// Scalar, vector, matrix, object or struct.
    pub class: Class,
    /// D3DXPARAMETER_TYPE, as its HLSL name (`float`, `sampler2D`;
    /// `unknown` for a code past the table of D3DX9's types).
    pub base: &'static str,
    /// The D3DXPARAMETER_TYPE code itself (3 `float`, 12 `sampler2D`).
    #[serde(skip)]
    pub code: u16,
    /// Rows of a matrix (1 for scalars and vectors).
    pub rows: u16,
    /// Columns (components of a vector; 1 for scalars).
    pub columns: u16,
    /// Array length (0 or 1: not an array).
    pub elements: u16,
    /// The members of a struct, in order; empty for every other class.
    pub members: Vec<Member>,
}

/// D3DXPARAMETER_CLASS.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Class {
    /// One component (`float`).
    Scalar,
    /// A vector (`float3`).
    Vector,
    /// A matrix stored row by row (`row_major float4x4`).
    MatrixRows,
    /// A matrix stored column by column, HLSL's default.
    MatrixColumns,
    /// A sampler or texture.
    Object,
    /// A struct: see [`Type::members`].
    Struct,
}

/// A struct member.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Member {
    /// The member's HLSL name.
    pub name: String,
    /// The member's type.
    #[serde(rename = "type")]
    pub ty: Type,
}

/// D3DXPARAMETER_TYPE names, by value.
const TYPE_NAMES: [&str; 20] = [
    "void",
    "bool",
    "int",
    "float",
    "string",
    "texture",
    "texture1D",
    "texture2D",
    "texture3D",
    "textureCUBE",
    "sampler",
    "sampler1D",
    "sampler2D",
    "sampler3D",
    "samplerCUBE",
    "pixelshader",
    "vertexshader",
    "pixelfragment",
    "vertexfragment",
    "unsupported",
];

/// Why a table does not decode, at a byte offset of the table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CtabError {
    /// Byte offset in the table (from just after `CTAB`).
    pub offset: usize,
    /// What is wrong there, in one sentence.
    pub message: String,
}

type R<T> = Result<T, CtabError>;

pub(super) fn err<T>(offset: usize, message: impl Into<String>) -> R<T> {
    Err(CtabError {
        offset,
        message: message.into(),
    })
}

/// Decodes a table: the comment body after its `CTAB` token.
pub fn decode(table: &[u32]) -> R<ConstantTable> {
    let bytes: Vec<u8> = table.iter().flat_map(|t| t.to_le_bytes()).collect();
    let mut d = Decoder::new(&bytes);
    let size = d.dword(0, "the header")?;
    if size != 28 {
        return err(0, format!("the header says it is {size} bytes; it is 28"));
    }
    let count = d.dword(12, "the header")? as usize;
    let info = d.dword(16, "the header")? as usize;
    let creator = d.string_at(4, "the creator")?;
    let target = d.string_at(24, "the target")?;
    if (info as u64) + 20 * count as u64 > bytes.len() as u64 {
        return err(
            12,
            format!(
                "{count} constants of 20 bytes at offset {info} run past the end of the table ({} bytes)",
                bytes.len()
            ),
        );
    }
    // The registers are checked against the profile the table names (its
    // version token); ps_3_0's files where it names none ps30 reads.
    let profile = crate::core::profile::Profile::from_token(d.dword(8, "the header")?)
        .filter(|p| p.checked())
        .unwrap_or_default();
    let constants = (0..count)
        .map(|i| d.constant(info + 20 * i, profile))
        .collect::<R<Vec<_>>>()?;
    Ok(ConstantTable {
        creator,
        target,
        version: d.dword(8, "the header")?,
        flags: d.dword(20, "the header")?,
        constants,
    })
}

/// Bounds-checked reads from a table of bytes, with a budget on the bytes
/// decoded in all; shared with the debug-information decoder.
pub(super) struct Decoder<'a> {
    pub(super) bytes: &'a [u8],
    /// Bytes decoded so far, against `budget`.
    work: usize,
    budget: usize,
}

impl<'a> Decoder<'a> {
    /// A decoder over `bytes`, allowed [`WORK_FACTOR`] times their length.
    pub(super) fn new(bytes: &'a [u8]) -> Decoder<'a> {
        Decoder {
            bytes,
            work: 0,
            budget: WORK_FACTOR * bytes.len(),
        }
    }

    pub(super) fn spend(&mut self, n: usize, at: usize) -> R<()> {
        self.work = self.work.saturating_add(n);
        if self.work > self.budget {
            return err(
                at,
                format!(
                    "its references add up to more than {WORK_FACTOR} times its {} bytes (types or defaults shared over and over)",
                    self.bytes.len()
                ),
            );
        }
        Ok(())
    }

    pub(super) fn dword(&self, at: usize, what: &str) -> R<u32> {
        match self.bytes.get(at..at.saturating_add(4)) {
            Some(b) => Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            None => err(
                at,
                format!(
                    "{what} runs past the end of the table ({} bytes)",
                    self.bytes.len()
                ),
            ),
        }
    }

    pub(super) fn word(&self, at: usize, what: &str) -> R<u16> {
        match self.bytes.get(at..at.saturating_add(2)) {
            Some(b) => Ok(u16::from_le_bytes([b[0], b[1]])),
            None => err(
                at,
                format!(
                    "{what} runs past the end of the table ({} bytes)",
                    self.bytes.len()
                ),
            ),
        }
    }

    /// The string whose offset is the dword at `at`.
    pub(super) fn string_at(&mut self, at: usize, what: &str) -> R<String> {
        let offset = self.dword(at, what)? as usize;
        if offset == 0 {
            // D3DX reads offset 0 as no string.
            return Ok(String::new());
        }
        let rest = match self.bytes.get(offset..) {
            Some(rest) if offset < self.bytes.len() => rest,
            _ => {
                return err(
                    at,
                    format!(
                        "{what} is at offset {offset}, past the end of the table ({} bytes)",
                        self.bytes.len()
                    ),
                )
            }
        };
        let Some(len) = rest.iter().take(MAX_NAME + 1).position(|&b| b == 0) else {
            let why = if rest.len() > MAX_NAME {
                format!("longer than {MAX_NAME} bytes")
            } else {
                "not ended by a zero byte inside the table".to_string()
            };
            return err(offset, format!("{what} at offset {offset} is {why}"));
        };
        self.spend(len + 1, offset)?;
        Ok(String::from_utf8_lossy(&rest[..len]).into_owned())
    }

    /// One D3DXSHADER_CONSTANTINFO.
    fn constant(&mut self, at: usize, profile: crate::core::profile::Profile) -> R<Constant> {
        self.spend(20, at)?;
        let name = self.string_at(at, "a constant's name")?;
        let set = match self.word(at + 4, "a constant")? {
            0 => RegisterSet::Bool,
            1 => RegisterSet::Int4,
            2 => RegisterSet::Float4,
            3 => RegisterSet::Sampler,
            s => {
                return err(
                    at + 4,
                    format!(
                        "constant `{}` has register set {s}, which does not exist (0 to 3)",
                        escape(&name)
                    ),
                )
            }
        };
        let index = self.word(at + 6, "a constant")?;
        let count = self.word(at + 8, "a constant")?;
        // The registers it names must exist in the profile's register file of
        // that set (the table is hostile input: `--const NAME=` and `run`
        // would otherwise address registers that are not there).
        let file = match set {
            RegisterSet::Bool => RegFile::ConstBool,
            RegisterSet::Int4 => RegFile::ConstInt,
            RegisterSet::Float4 => RegFile::Const,
            RegisterSet::Sampler => RegFile::Sampler,
        };
        let available = profile.count(file);
        if u32::from(index) + u32::from(count) > available {
            return err(
                at + 6,
                format!(
                    "constant `{}` takes {}{index} to {}{} ({count} registers), past the last {} register, {}{}",
                    escape(&name),
                    set.prefix(),
                    set.prefix(),
                    (u32::from(index) + u32::from(count)).saturating_sub(1),
                    set.name(),
                    set.prefix(),
                    available.saturating_sub(1)
                ),
            );
        }
        let ty = self.ty(at + 12, 0)?;
        let default = self.default(at + 16, &ty, set, &name)?;
        Ok(Constant {
            name,
            set,
            index,
            count,
            ty,
            default,
        })
    }

    /// The D3DXSHADER_TYPEINFO (and its members) whose offset is the dword
    /// at `from`.
    fn ty(&mut self, from: usize, depth: u32) -> R<Type> {
        if depth > MAX_DEPTH {
            return err(from, format!("types nest more than {MAX_DEPTH} deep"));
        }
        let at = self.dword(from, "a type offset")? as usize;
        if at as u64 + 16 > self.bytes.len() as u64 {
            return err(
                from,
                format!(
                    "a type at offset {at} runs past the end of the table ({} bytes)",
                    self.bytes.len()
                ),
            );
        }
        self.spend(16, at)?;
        let class = match self.word(at, "a type")? {
            0 => Class::Scalar,
            1 => Class::Vector,
            2 => Class::MatrixRows,
            3 => Class::MatrixColumns,
            4 => Class::Object,
            5 => Class::Struct,
            c => {
                return err(
                    at,
                    format!("a type of class {c}, which does not exist (0 to 5)"),
                )
            }
        };
        // Any code is read: Microsoft's own tools name codes D3DX9 does not
        // have (Direct3D 10's types) and call the rest UNKNOWN.
        let code = self.word(at + 2, "a type")?;
        let base = TYPE_NAMES.get(code as usize).copied().unwrap_or("unknown");
        let member_count = self.word(at + 10, "a type")? as usize;
        let members_at = self.dword(at + 12, "a type")? as usize;
        let mut members = Vec::new();
        if class == Class::Struct && member_count > 0 {
            if members_at as u64 + 8 * member_count as u64 > self.bytes.len() as u64 {
                return err(
                    at + 10,
                    format!("{member_count} struct members at offset {members_at} run past the end of the table"),
                );
            }
            for m in 0..member_count {
                let m_at = members_at + 8 * m;
                self.spend(8, m_at)?;
                let name = self.string_at(m_at, "a member's name")?;
                members.push(Member {
                    name,
                    ty: self.ty(m_at + 4, depth + 1)?,
                });
            }
        }
        Ok(Type {
            class,
            base,
            code,
            rows: self.word(at + 4, "a type")?,
            columns: self.word(at + 6, "a type")?,
            elements: self.word(at + 8, "a type")?,
            members,
        })
    }

    /// The words of the default value whose offset is the dword at `from`
    /// (offset 0: none), checked to lie inside the table.
    fn default(
        &mut self,
        from: usize,
        ty: &Type,
        set: RegisterSet,
        name: &str,
    ) -> R<Option<Vec<u32>>> {
        let at = self.dword(from, "a constant")? as usize;
        if at == 0 {
            return Ok(None);
        }
        let words = ty.default_words(set);
        let end = (at as u64).saturating_add(words.saturating_mul(4));
        if end > self.bytes.len() as u64 {
            return err(
                from,
                format!(
                    "the default value of `{}` ({words} words at offset {at}) runs past the end of the table ({} bytes)",
                    escape(name),
                    self.bytes.len()
                ),
            );
        }
        self.spend(words as usize * 4, at)?;
        (0..words as usize)
            .map(|i| self.dword(at + 4 * i, "a default value"))
            .collect::<R<Vec<u32>>>()
            .map(Some)
    }
}

impl Type {
    /// 32-bit words of a default value of this type in a register set: per
    /// leaf, four per register row (float and integer registers) or one per
    /// element (booleans), times the array length (D3DX's walk).
    pub fn default_words(&self, set: RegisterSet) -> u64 {
        let one = if self.class == Class::Struct {
            self.members
                .iter()
                .map(|m| m.ty.default_words(set))
                .fold(0u64, u64::saturating_add)
        } else {
            let (rows, columns) = (self.rows as u64, self.columns as u64);
            match (set, self.class) {
                (RegisterSet::Float4 | RegisterSet::Int4, Class::MatrixColumns) => columns * 4,
                (RegisterSet::Float4 | RegisterSet::Int4, Class::Object) => rows * columns,
                (RegisterSet::Float4 | RegisterSet::Int4, _) => rows * 4,
                _ => rows * columns,
            }
        };
        one.saturating_mul((self.elements as u64).max(1))
    }

    /// The HLSL spelling of the type (`float4`, `row_major float4x4`,
    /// `sampler2D`, `struct { … }`), without array brackets.
    pub fn hlsl(&self) -> String {
        match self.class {
            Class::Scalar | Class::Object => self.base.to_string(),
            Class::Vector => format!("{}{}", self.base, self.columns),
            Class::MatrixRows => format!("row_major {}{}x{}", self.base, self.rows, self.columns),
            Class::MatrixColumns => format!("{}{}x{}", self.base, self.rows, self.columns),
            Class::Struct => {
                let members: Vec<String> = self
                    .members
                    .iter()
                    .map(|m| format!("{} {}{};", m.ty.hlsl(), m.name, m.ty.array()))
                    .collect();
                format!("struct {{ {} }}", members.join(" "))
            }
        }
    }

    /// The type as `D3DDisassemble`'s parameter list spells it: Microsoft's
    /// type names (`Texture2D`, `PixelShader`), a vector's column count
    /// even when it is 1 (`float1`), `row_major` matrices marked; not for
    /// structs, whose members are listed instead.
    pub fn listing_spelling(&self) -> String {
        let base = LISTING_TYPE_NAMES
            .get(self.code as usize)
            .copied()
            .unwrap_or("UNKNOWN");
        match self.class {
            Class::Vector => format!("{base}{}", self.columns),
            Class::MatrixRows => format!("row_major {base}{}x{}", self.rows, self.columns),
            Class::MatrixColumns => format!("{base}{}x{}", self.rows, self.columns),
            Class::Scalar | Class::Object | Class::Struct => base.to_string(),
        }
    }

    /// `[n]` for an array, else nothing.
    pub fn array(&self) -> String {
        if self.elements > 1 {
            format!("[{}]", self.elements)
        } else {
            String::new()
        }
    }
}

impl Constant {
    /// The first register, as assembly spells it (`c4`, `s0`).
    pub fn register(&self) -> String {
        format!("{}{}", self.set.prefix(), self.index)
    }

    /// The default of each register it takes, as four words (float and
    /// integer registers) or one (booleans), as far as the default covers
    /// them.
    pub fn register_defaults(&self) -> Vec<Vec<u32>> {
        let Some(words) = &self.default else {
            return Vec::new();
        };
        let per = match self.set {
            RegisterSet::Bool => 1,
            RegisterSet::Sampler => return Vec::new(),
            _ => 4,
        };
        words
            .chunks_exact(per)
            .take(self.count as usize)
            .map(<[u32]>::to_vec)
            .collect()
    }
}

/// The creator `D3DDisassemble` names when a table gives none (offset 0).
pub const DEFAULT_CREATOR: &str = "Microsoft (R) D3DX9 Shader Disassembler";

/// Microsoft's spelling of the D3DXPARAMETER_TYPE codes in a listing's
/// parameter list (codes past these print `UNKNOWN`).
const LISTING_TYPE_NAMES: [&str; 40] = [
    "void",
    "bool",
    "int",
    "float",
    "string",
    "Texture",
    "Texture1D",
    "Texture2D",
    "Texture3D",
    "TextureCube",
    "sampler",
    "sampler1D",
    "sampler2D",
    "sampler3D",
    "samplerCUBE",
    "PixelShader",
    "VertexShader",
    "pixelfragment",
    "vertexfragment",
    "uint",
    "byte",
    "GeometryShader",
    "RasterizerState",
    "DepthStencilState",
    "BlendState",
    "Buffer",
    "UNKNOWN",
    "UNKNOWN",
    "Texture1DArray",
    "Texture2DArray",
    "RenderTargetView",
    "DepthStencilView",
    "Texture2DMS",
    "Texture2DMSArray",
    "TextureCubeArray",
    "HullShader",
    "DomainShader",
    "interface",
    "ComputeShader",
    "double",
];

/// The comment block `D3DDisassemble` writes above `ps_3_0` for a constant
/// table (`table`: the comment body after its `CTAB` token), line for line:
/// the creator; then, when the table has constants, each parameter in the
/// table's order as HLSL (a constant named like the one before it is the
/// same parameter in another register set and is not repeated; structs
/// spelled out member by member, set apart by lines of indentation) and
/// the registers they take, sorted by register set (bool, int4, float4,
/// sampler) and number, with the name column as wide as the longest name
/// and at least 12; then a blank line. A table too short for its header
/// gives nothing, one that does not decode a line saying so. With
/// `escape`, names are written through [`escape`] so that no byte of a
/// hostile table can end a comment line (ps30's annotated listing, which
/// the front end reads back); without, as the table holds them.
pub fn listing_header(table: &[u32], escape_names: bool) -> String {
    let name = |s: &str| {
        if escape_names {
            escape(s)
        } else {
            s.to_string()
        }
    };
    if table.len() < 7 {
        return String::new();
    }
    let mut out = String::new();
    comment_line(&mut out, "");
    let creator = if table[1] == 0 {
        DEFAULT_CREATOR.to_string()
    } else {
        let bytes: Vec<u8> = table.iter().flat_map(|t| t.to_le_bytes()).collect();
        let mut d = Decoder {
            bytes: &bytes,
            work: 0,
            budget: bytes.len(),
        };
        d.string_at(4, "the creator").unwrap_or_default()
    };
    comment_line(&mut out, &format!(" Generated by {}", name(&creator)));
    let t = match decode(table) {
        Ok(t) => t,
        Err(_) => {
            out.push_str("<invalid constant table>\n");
            return out;
        }
    };
    if t.constants.is_empty() {
        return out;
    }
    for l in ["", " Parameters:", ""] {
        comment_line(&mut out, l);
    }
    let mut params: Vec<(&str, &Type)> = Vec::new();
    for (i, c) in t.constants.iter().enumerate() {
        if i == 0 || t.constants[i - 1].name != c.name {
            params.push((&c.name, &c.ty));
        }
    }
    parameters(&mut out, &params, 3, &name);
    for l in ["", "", " Registers:", ""] {
        comment_line(&mut out, l);
    }
    let mut rows: Vec<&Constant> = t.constants.iter().collect();
    rows.sort_by_key(|c| (c.set as u8, c.index));
    let width = rows
        .iter()
        .map(|c| name(&c.name).len())
        .max()
        .unwrap_or(0)
        .max(12);
    comment_line(&mut out, &format!("   {:<width$} Reg   Size", "Name"));
    comment_line(&mut out, &format!("   {} ----- ----", "-".repeat(width)));
    for c in rows {
        let n = name(&c.name);
        let pad = " ".repeat(width - n.len());
        let row = format!("   {n}{pad} {:<5} {:>4}", c.register(), c.count);
        comment_line(&mut out, &row);
    }
    comment_line(&mut out, "");
    out.push('\n');
    out
}

/// `//` and the text, as one line of `out`.
fn comment_line(out: &mut String, text: &str) {
    out.push_str("//");
    out.push_str(text);
    out.push('\n');
}

/// Parameters (or a struct's members) at an indentation, with a line of
/// the indentation alone between two items when either is a struct.
fn parameters(
    out: &mut String,
    items: &[(&str, &Type)],
    indent: usize,
    name: &dyn Fn(&str) -> String,
) {
    let pad = " ".repeat(indent);
    let is_struct = |t: &Type| t.class == Class::Struct;
    for (i, (n, ty)) in items.iter().enumerate() {
        if i > 0 && (is_struct(ty) || is_struct(items[i - 1].1)) {
            comment_line(out, &pad);
        }
        let (n, array) = (name(n), ty.array());
        if is_struct(ty) {
            comment_line(out, &format!("{pad}struct"));
            comment_line(out, &format!("{pad}{{"));
            let members: Vec<(&str, &Type)> = ty
                .members
                .iter()
                .map(|m| (m.name.as_str(), &m.ty))
                .collect();
            parameters(out, &members, indent + 4, name);
            comment_line(out, "");
            comment_line(out, &format!("{pad}}} {n}{array};"));
        } else {
            comment_line(out, &format!("{pad}{} {n}{array};", ty.listing_spelling()));
        }
    }
}

/// Printable ASCII as is; anything else as `\u{…}` escapes.
pub fn escape(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_graphic() || c == ' ' {
                c.to_string()
            } else {
                c.escape_unicode().to_string()
            }
        })
        .collect()
}
