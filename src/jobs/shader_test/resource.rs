//! Resource sections (`[rtv N]`, `[srv N]`, `[vb N]`) as vkd3d's
//! `parse_resource_directive` reads them, and textures made from them as
//! the Direct3D 9 runner makes them: A32B32G32R32F or R32F (sampled as
//! (r, 1, 1, 1)), 2D with its levels, volume or cube, the data level after
//! level (and face after face), rows packed.

use super::parse::Cursor;
use crate::core::image::{CubeMap, MipChain, TextureFile, VolumeChain, VolumeLevel};

/// The largest side of a target or texture a file may ask for.
const MAX_SIDE: u32 = 8192;
/// The most data bytes a resource may hold.
const MAX_DATA: usize = 64 << 20;

/// One mip level as `MipChain::from_levels` takes it: width, height, texels.
type Level = (u32, u32, Vec<[f32; 4]>);

/// A texture ready for a draw list.
#[derive(Clone, Debug)]
pub(super) struct Texture {
    /// Level 0's size.
    pub width: u32,
    pub height: u32,
    /// Its levels (2D), faces or slices.
    pub file: TextureFile,
}

/// A resource section's lines, read.
#[derive(Clone, Debug, Default)]
pub(super) struct ResourceText {
    pub format: Option<String>,
    texel_size: u32,
    dimension: Option<String>,
    pub width: u32,
    pub height: u32,
    depth: u32,
    levels: u32,
    pub data: Vec<u8>,
}

/// vkd3d's format names with their texel sizes.
const FORMATS: [(&str, u32); 12] = [
    ("r32g32b32a32-float", 16),
    ("r32g32b32a32-sint", 16),
    ("r32g32b32a32-uint", 16),
    ("r32g32-float", 8),
    ("r32g32-sint", 8),
    ("r32g32-uint", 8),
    ("r32-float-shadow", 4),
    ("r32-float", 4),
    ("r32-sint", 4),
    ("r32-uint", 4),
    ("r32-typeless", 4),
    ("unknown", 0),
];

/// A format name after white space: the name and its texel size.
pub(super) fn format(c: &mut Cursor<'_>) -> Result<(String, u32), String> {
    for (name, size) in FORMATS {
        if c.word(name) {
            return Ok((name.to_string(), size));
        }
    }
    Err(format!("unknown format '{}'", c.rest.trim()))
}

/// A target's size within bounds.
pub(super) fn check_size(w: u32, h: u32) -> Result<(), String> {
    if w == 0 || h == 0 || w > MAX_SIDE || h > MAX_SIDE {
        return Err(format!("size {w}x{h} is outside 1..={MAX_SIDE} on a side"));
    }
    Ok(())
}

/// `( kind , a , b , c )` of a `size` line.
fn size_args(c: &mut Cursor<'_>) -> Option<(String, Vec<u32>)> {
    if !c.char('(') {
        return None;
    }
    c.ws();
    let len = c
        .rest
        .find(|ch: char| !ch.is_ascii_alphanumeric() && ch != '_')?;
    let kind = c.rest[..len].to_string();
    c.rest = &c.rest[len..];
    let mut args = Vec::new();
    while c.char(',') {
        c.ws();
        args.push(c.uint()?);
    }
    c.char(')').then_some((kind, args))
}

impl ResourceText {
    /// One line of the section.
    pub fn line(&mut self, line: &str) -> Result<(), String> {
        let mut c = Cursor::new(line);
        if c.word("format") {
            let (name, size) = format(&mut c)?;
            self.format = Some(name);
            self.texel_size = size;
        } else if c.word("stride") {
            self.texel_size = c
                .uint()
                .ok_or_else(|| format!("malformed stride '{line}'"))?;
            self.format = Some("unknown".into());
        } else if c.word("size") {
            let (kind, a) =
                size_args(&mut c).ok_or_else(|| format!("malformed resource size '{line}'"))?;
            let want = match kind.as_str() {
                "2d" => 2,
                "3d" | "2dms" | "2darray" => 3,
                "cube" | "buffer" | "raw_buffer" | "counter_buffer" => 1,
                _ => return Err(format!("malformed resource size '{line}'")),
            };
            if a.len() != want {
                return Err(format!("malformed resource size '{line}'"));
            }
            (self.width, self.height, self.depth) = match kind.as_str() {
                "2dms" => (a[1], a[2], 1),
                "cube" => (a[0], a[0], 1),
                "2d" => (a[0], a[1], 1),
                "3d" | "2darray" => (a[0], a[1], a[2]),
                _ => (a[0], 1, 1),
            };
            self.dimension = Some(kind);
        } else if c.word("levels") {
            self.levels = c
                .uint()
                .ok_or_else(|| format!("malformed levels '{line}'"))?;
        } else {
            self.data_line(line)?;
        }
        Ok(())
    }

    /// Data words: an integer (its 32 bits as written, C's `strtoul` with
    /// base 0) unless a `.` follows it, then a float (`strtof`).
    fn data_line(&mut self, line: &str) -> Result<(), String> {
        let mut rest = line;
        loop {
            let word = match super::parse::strtoul(rest) {
                Some((u, r)) if !r.starts_with('.') => Some((u, r)),
                _ => super::parse::strtof(rest).map(|(f, r)| (f.to_bits(), r)),
            };
            let Some((bits, r)) = word else { break };
            if self.data.len() >= MAX_DATA {
                return Err(format!("more than {MAX_DATA} bytes of data"));
            }
            self.data.extend_from_slice(&bits.to_le_bytes());
            rest = r;
        }
        Ok(())
    }

    /// The texture the Direct3D 9 runner creates, or why ps30 cannot.
    pub fn texture(&self) -> Result<Texture, String> {
        let format = self.format.as_deref().unwrap_or("r32g32b32a32-float");
        let one = match format {
            "r32g32b32a32-float" => false,
            "r32-float" => true,
            f => {
                return Err(format!(
                    "texture format {f} (vkd3d's Direct3D 9 runner creates none)"
                ))
            }
        };
        let kind = self.dimension.as_deref().unwrap_or("2d");
        let (w, h, d) = (self.width, self.height, self.depth.max(1));
        check_size(w, h)?;
        if d > MAX_SIDE {
            return Err(format!("depth {d} is over {MAX_SIDE}"));
        }
        let levels = self.levels.max(1);
        let mut words = self
            .data
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes(b.try_into().expect("chunks of four bytes")));
        let mut take = |n: usize| -> Result<Vec<[f32; 4]>, String> {
            let per = if one { 1 } else { 4 };
            let mut out = Vec::with_capacity(n);
            for _ in 0..n {
                let mut t = [1.0f32; 4];
                for c in t.iter_mut().take(per) {
                    *c = words.next().ok_or_else(|| {
                        format!(
                            "the data holds {} bytes, fewer than its levels need",
                            self.data.len()
                        )
                    })?;
                }
                out.push(t);
            }
            Ok(out)
        };
        let side = |s: u32, l: u32| (s >> l).max(1);
        let file = match kind {
            "2d" => {
                let mut chain = Vec::new();
                for l in 0..levels {
                    let (lw, lh) = (side(w, l), side(h, l));
                    chain.push((lw, lh, take((lw * lh) as usize)?));
                }
                TextureFile::Flat(MipChain::from_levels(chain)?)
            }
            "3d" => {
                let mut chain = Vec::new();
                for l in 0..levels {
                    let (lw, lh, ld) = (side(w, l), side(h, l), side(d, l));
                    let texels = take((lw * lh * ld) as usize)?;
                    chain.push(VolumeLevel {
                        width: lw,
                        height: lh,
                        depth: ld,
                        texels,
                    });
                }
                TextureFile::Volume(VolumeChain::from_levels(chain)?)
            }
            "cube" => {
                let mut faces: Vec<Vec<Level>> = vec![Vec::new(); 6];
                for l in 0..levels {
                    let e = side(w, l);
                    for face in faces.iter_mut() {
                        face.push((e, e, take((e * e) as usize)?));
                    }
                }
                let chains = faces
                    .into_iter()
                    .map(MipChain::from_levels)
                    .collect::<Result<Vec<_>, _>>()?;
                TextureFile::Cube(CubeMap::from_faces(chains)?)
            }
            other => {
                return Err(format!(
                    "{other} textures (vkd3d's Direct3D 9 runner makes none)"
                ))
            }
        };
        Ok(Texture {
            width: w,
            height: h,
            file,
        })
    }
}
