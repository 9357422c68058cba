//! DirectDraw Surface (DDS) texture files: 2D textures, cube maps and
//! volume textures with the mip levels their authors stored, in the D3D9
//! formats shaders read (8-bit ARGB/XRGB/ABGR, L8, A8L8, A8, R5G6B5,
//! 16-bit UNORM, half and single float, DXT1/DXT3/DXT5).
//!
//! The container is read by the `ddsfile` crate and DXT blocks are decoded
//! by `bcdec_rs`; this module decides what a file means for Direct3D 9 and
//! treats it as hostile input: every size is computed in 128 bits and
//! checked against [`ImageLimits`] and the bytes the file holds before any
//! texel memory exists, and every error names the field, face or level.
//!
//! Layout (D3D9's, as D3DX writes it): a 2D texture stores its levels one
//! after another; a cube stores face +X with all its levels, then −X, +Y,
//! −Y, +Z, −Z; a volume stores each level's slices in order. A level is
//! ⌊side/2^i⌋ (at least 1) on each side; a DXT level holds ⌈w/4⌉·⌈h/4⌉
//! blocks per slice. Channels a format lacks read as D3D9 samples them:
//! 1 for missing colour and alpha channels (L8 gives (L, L, L, 1)).

use super::{CubeMap, ImageError, ImageLimits, MipChain, VolumeChain, VolumeLevel};
use ddsfile::{Caps2, D3DFormat, Dds};
use std::path::Path;

const FORMAT: &str = "DDS";

/// Largest side accepted: Direct3D 9 hardware's largest texture
/// (D3DCAPS9.MaxTextureWidth is 8192 or 16384 on shipped devices).
const MAX_SIDE: u32 = 16384;

/// A texture file as Direct3D 9 creates it: its type and every level.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureFile {
    /// A 2D texture (HDR images: one level).
    Flat(MipChain),
    /// A cube texture.
    Cube(CubeMap),
    /// A volume texture.
    Volume(VolumeChain),
}

impl TextureFile {
    /// Width and height of level 0 (a cube's edge twice; a volume's first
    /// two sides).
    pub fn size(&self) -> (u32, u32) {
        match self {
            TextureFile::Flat(c) => c.level(0).map_or((0, 0), |l| (l.width, l.height)),
            TextureFile::Cube(c) => (c.edge(), c.edge()),
            TextureFile::Volume(v) => v.level(0).map_or((0, 0), |l| (l.width, l.height)),
        }
    }

    /// The kind, as `dcl_` names it: `2d`, `cube`, `volume`.
    pub fn kind(&self) -> &'static str {
        match self {
            TextureFile::Flat(_) => "2d",
            TextureFile::Cube(_) => "cube",
            TextureFile::Volume(_) => "volume",
        }
    }

    /// Number of mip levels.
    pub fn levels(&self) -> usize {
        match self {
            TextureFile::Flat(c) => c.len(),
            TextureFile::Cube(c) => c.face(0).len(),
            TextureFile::Volume(v) => v.len(),
        }
    }
}

/// Whether `bytes` start with the DDS magic number `DDS `.
pub fn is_dds(bytes: &[u8]) -> bool {
    bytes.starts_with(b"DDS ")
}

/// How one format's texels are stored.
#[derive(Clone, Copy, Debug)]
enum Layout {
    /// `bytes` per texel, decoded by `texel`.
    Plain {
        bytes: usize,
        texel: fn(&[u8]) -> [f32; 4],
    },
    /// 4×4 blocks of `bytes` bytes.
    Block { bytes: usize, kind: u8 },
}

fn unorm8(b: u8) -> f32 {
    b as f32 / 255.0
}

fn unorm16(b: &[u8]) -> f32 {
    u16::from_le_bytes([b[0], b[1]]) as f32 / 65535.0
}

fn half(b: &[u8]) -> f32 {
    half::f16::from_le_bytes([b[0], b[1]]).to_f32()
}

fn single(b: &[u8]) -> f32 {
    f32::from_le_bytes([b[0], b[1], b[2], b[3]])
}

/// The storage of a D3D9 format, or `None` for one ps30 does not read.
fn layout(f: D3DFormat) -> Option<Layout> {
    use D3DFormat as F;
    let plain = |bytes, texel| Some(Layout::Plain { bytes, texel });
    match f {
        F::A8R8G8B8 => plain(4, |b| {
            [unorm8(b[2]), unorm8(b[1]), unorm8(b[0]), unorm8(b[3])]
        }),
        F::X8R8G8B8 => plain(4, |b| [unorm8(b[2]), unorm8(b[1]), unorm8(b[0]), 1.0]),
        F::A8B8G8R8 => plain(4, |b| {
            [unorm8(b[0]), unorm8(b[1]), unorm8(b[2]), unorm8(b[3])]
        }),
        F::X8B8G8R8 => plain(4, |b| [unorm8(b[0]), unorm8(b[1]), unorm8(b[2]), 1.0]),
        F::R8G8B8 => plain(3, |b| [unorm8(b[2]), unorm8(b[1]), unorm8(b[0]), 1.0]),
        F::L8 => plain(1, |b| [unorm8(b[0]), unorm8(b[0]), unorm8(b[0]), 1.0]),
        F::A8L8 => plain(2, |b| {
            [unorm8(b[0]), unorm8(b[0]), unorm8(b[0]), unorm8(b[1])]
        }),
        F::A8 => plain(1, |b| [0.0, 0.0, 0.0, unorm8(b[0])]),
        F::L16 => plain(2, |b| [unorm16(b), unorm16(b), unorm16(b), 1.0]),
        F::R5G6B5 => plain(2, |b| {
            let v = u16::from_le_bytes([b[0], b[1]]);
            [
                (v >> 11) as f32 / 31.0,
                ((v >> 5) & 63) as f32 / 63.0,
                (v & 31) as f32 / 31.0,
                1.0,
            ]
        }),
        F::G16R16 => plain(4, |b| [unorm16(b), unorm16(&b[2..]), 1.0, 1.0]),
        F::A16B16G16R16 => plain(8, |b| {
            [
                unorm16(b),
                unorm16(&b[2..]),
                unorm16(&b[4..]),
                unorm16(&b[6..]),
            ]
        }),
        F::R16F => plain(2, |b| [half(b), 1.0, 1.0, 1.0]),
        F::G16R16F => plain(4, |b| [half(b), half(&b[2..]), 1.0, 1.0]),
        F::A16B16G16R16F => plain(8, |b| {
            [half(b), half(&b[2..]), half(&b[4..]), half(&b[6..])]
        }),
        F::R32F => plain(4, |b| [single(b), 1.0, 1.0, 1.0]),
        F::G32R32F => plain(8, |b| [single(b), single(&b[4..]), 1.0, 1.0]),
        F::A32B32G32R32F => plain(16, |b| {
            [
                single(b),
                single(&b[4..]),
                single(&b[8..]),
                single(&b[12..]),
            ]
        }),
        F::DXT1 => Some(Layout::Block { bytes: 8, kind: 1 }),
        F::DXT2 | F::DXT3 => Some(Layout::Block { bytes: 16, kind: 3 }),
        F::DXT4 | F::DXT5 => Some(Layout::Block { bytes: 16, kind: 5 }),
        _ => None,
    }
}

/// Bytes of one `w × h` slice.
fn slice_bytes(layout: Layout, w: u32, h: u32) -> u128 {
    match layout {
        Layout::Plain { bytes, .. } => w as u128 * h as u128 * bytes as u128,
        Layout::Block { bytes, .. } => {
            w.div_ceil(4) as u128 * h.div_ceil(4) as u128 * bytes as u128
        }
    }
}

/// Decodes one `w × h` slice from `data` (exactly [`slice_bytes`] long).
fn decode_slice(layout: Layout, w: u32, h: u32, data: &[u8], out: &mut Vec<[f32; 4]>) {
    let (w, h) = (w as usize, h as usize);
    match layout {
        Layout::Plain { bytes, texel } => {
            out.extend(data.chunks_exact(bytes).take(w * h).map(texel));
        }
        Layout::Block { bytes, kind } => {
            let start = out.len();
            out.resize(start + w * h, [0.0; 4]);
            let bw = w.div_ceil(4);
            for (i, block) in data.chunks_exact(bytes).enumerate() {
                let (bx, by) = (i % bw, i / bw);
                let mut rgba = [0u8; 64];
                match kind {
                    1 => bcdec_rs::bc1(block, &mut rgba, 16),
                    3 => bcdec_rs::bc2(block, &mut rgba, 16),
                    _ => bcdec_rs::bc3(block, &mut rgba, 16),
                }
                for y in 0..4 {
                    for x in 0..4 {
                        let (tx, ty) = (bx * 4 + x, by * 4 + y);
                        if tx < w && ty < h {
                            let p = &rgba[(y * 4 + x) * 4..][..4];
                            out[start + ty * w + tx] =
                                [unorm8(p[0]), unorm8(p[1]), unorm8(p[2]), unorm8(p[3])];
                        }
                    }
                }
            }
        }
    }
}

/// What the header says, checked.
struct Shape {
    width: u32,
    height: u32,
    depth: u32,
    faces: u32,
    levels: u32,
    layout: Layout,
    volume: bool,
}

/// The luminance formats from the raw pixel-format fields of `bytes` (the
/// DDS_PIXELFORMAT at byte 76): `ddsfile` 0.6 keeps the channel masks only
/// for RGB formats, so it names no luminance format it reads.
fn luminance_format(bytes: &[u8]) -> Option<D3DFormat> {
    let word = |i: usize| {
        let b = bytes.get(76 + 4 * i..80 + 4 * i)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let (flags, count, r, a) = (word(1)?, word(3)?, word(4)?, word(7)?);
    const LUMINANCE: u32 = 0x2_0000;
    const FOURCC: u32 = 0x4;
    if flags & LUMINANCE == 0 || flags & FOURCC != 0 {
        return None;
    }
    match (count, r, a) {
        (8, 0xff, 0) => Some(D3DFormat::L8),
        (16, 0xff, 0xff00) => Some(D3DFormat::A8L8),
        (16, 0xffff, 0) => Some(D3DFormat::L16),
        _ => None,
    }
}

fn shape(path: &Path, dds: &Dds, bytes: &[u8], limits: &ImageLimits) -> Result<Shape, ImageError> {
    let bad = |field: &str, problem: String| ImageError::bad_header(path, FORMAT, field, problem);
    let format = dds
        .get_d3d_format()
        .or_else(|| luminance_format(bytes))
        .ok_or_else(|| {
            bad(
                "pixel format",
                if dds.header10.is_some() {
                    "is a DXGI (DX10) format; Direct3D 9 texture files use D3DFMT formats".into()
                } else {
                    "is not a D3D9 format ps30 reads".into()
                },
            )
        })?;
    let layout = layout(format).ok_or_else(|| {
        bad(
            "pixel format",
            format!("D3DFMT_{format:?} is not read (A8R8G8B8, X8R8G8B8, A8B8G8R8, R8G8B8, L8, A8L8, A8, L16, R5G6B5, G16R16, A16B16G16R16, R16F, G16R16F, A16B16G16R16F, R32F, G32R32F, A32B32G32R32F, DXT1-DXT5)"),
        )
    })?;
    let caps2 = dds.header.caps2;
    let cube = caps2.contains(Caps2::CUBEMAP);
    let volume = caps2.contains(Caps2::VOLUME) || dds.header.depth.is_some_and(|d| d > 1);
    if cube && volume {
        return Err(bad("caps2", "claims both a cube map and a volume".into()));
    }
    if cube && !caps2.contains(Caps2::CUBEMAP_ALLFACES) {
        return Err(bad(
            "caps2",
            "a cube map without all six faces (Direct3D 9 cube textures have six)".into(),
        ));
    }
    let (width, height) = (dds.header.width, dds.header.height);
    let depth = if volume {
        dds.header.depth.unwrap_or(1)
    } else {
        1
    };
    for (field, v) in [("width", width), ("height", height), ("depth", depth)] {
        if v == 0 {
            return Err(bad(field, "is zero".into()));
        }
        if v > MAX_SIDE {
            return Err(bad(field, format!("{v} is more than {} texels", MAX_SIDE)));
        }
    }
    if cube && width != height {
        return Err(bad(
            "width",
            format!("cube faces are square; {width}x{height}"),
        ));
    }
    let full = 32 - width.max(height).max(depth).leading_zeros();
    let levels = dds.header.mip_map_count.unwrap_or(1).max(1);
    if levels > full {
        return Err(bad(
            "mip map count",
            format!("{levels} levels, but a {width}x{height}x{depth} texture has at most {full}"),
        ));
    }
    let faces = if cube { 6 } else { 1 };
    let texels: u128 = (0..levels)
        .map(|i| {
            let s = |n: u32| (n >> i).max(1) as u128;
            s(width) * s(height) * s(depth)
        })
        .sum::<u128>()
        * faces as u128;
    if texels > limits.max_pixels as u128 {
        return Err(ImageError::TooLarge {
            path: path.to_path_buf(),
            width: width as u64,
            height: height as u64 * depth as u64 * faces as u64,
            limit: limits.max_pixels,
        });
    }
    Ok(Shape {
        width,
        height,
        depth,
        faces,
        levels,
        layout,
        volume,
    })
}

/// Reads a DDS file held in memory (`path` names it in errors).
pub fn read(path: &Path, bytes: &[u8], limits: &ImageLimits) -> Result<TextureFile, ImageError> {
    let dds = Dds::read(bytes).map_err(|e| ImageError::Decode {
        path: path.to_path_buf(),
        format: FORMAT,
        source: Box::new(e),
    })?;
    let s = shape(path, &dds, bytes, limits)?;
    // Every byte the levels need, before decoding any.
    let need: u128 = (0..s.levels)
        .map(|i| {
            let side = |n: u32| (n >> i).max(1);
            slice_bytes(s.layout, side(s.width), side(s.height)) * side(s.depth) as u128
        })
        .sum::<u128>()
        * s.faces as u128;
    if need > dds.data.len() as u128 {
        return Err(ImageError::Truncated {
            path: path.to_path_buf(),
            format: FORMAT,
            missing: format!(
                "{} bytes of texels for {} face(s) of {} level(s); the file holds {}",
                need,
                s.faces,
                s.levels,
                dds.data.len()
            ),
        });
    }
    let mut at = 0usize;
    let mut faces = Vec::with_capacity(s.faces as usize);
    let mut volume = Vec::new();
    for _ in 0..s.faces {
        let mut chain = Vec::with_capacity(s.levels as usize);
        for i in 0..s.levels {
            let side = |n: u32| (n >> i).max(1);
            let (w, h, d) = (side(s.width), side(s.height), side(s.depth));
            let one = slice_bytes(s.layout, w, h) as usize;
            let mut texels = Vec::with_capacity(w as usize * h as usize * d as usize);
            for _ in 0..d {
                decode_slice(s.layout, w, h, &dds.data[at..at + one], &mut texels);
                at += one;
            }
            if s.volume {
                volume.push(VolumeLevel {
                    width: w,
                    height: h,
                    depth: d,
                    texels,
                });
            } else {
                chain.push((w, h, texels));
            }
        }
        if !s.volume {
            faces.push(chain);
        }
    }
    let bad = |e: String| ImageError::bad_header(path, FORMAT, "levels", e);
    if s.volume {
        return VolumeChain::from_levels(volume)
            .map(TextureFile::Volume)
            .map_err(bad);
    }
    let mut chains = faces
        .into_iter()
        .map(MipChain::from_levels)
        .collect::<Result<Vec<_>, _>>()
        .map_err(bad)?;
    if s.faces == 6 {
        CubeMap::from_faces(chains)
            .map(TextureFile::Cube)
            .map_err(bad)
    } else {
        Ok(TextureFile::Flat(chains.remove(0)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ddsfile::NewD3dParams;

    /// A DDS file of `format` with `data` as its texels.
    fn file(
        w: u32,
        h: u32,
        depth: Option<u32>,
        levels: u32,
        format: D3DFormat,
        caps2: Option<Caps2>,
        data: Vec<u8>,
    ) -> Vec<u8> {
        let mut dds = Dds::new_d3d(NewD3dParams {
            height: h,
            width: w,
            depth,
            format,
            mipmap_levels: Some(levels),
            caps2,
        })
        .unwrap();
        dds.data = data;
        let mut out = Vec::new();
        dds.write(&mut out).unwrap();
        // The pixel formats D3DX writes (`ddsfile` writes float formats as
        // RGB bit masks): L8 as LUMINANCE with mask 0xff, float formats by
        // their D3DFMT code as the FourCC.
        let pf = match format {
            D3DFormat::L8 => Some([0x2_0000u32, 0, 8, 0xff, 0, 0, 0]),
            D3DFormat::A16B16G16R16F => Some([4, 113, 0, 0, 0, 0, 0]),
            D3DFormat::R32F => Some([4, 114, 0, 0, 0, 0, 0]),
            _ => None,
        };
        for (i, v) in pf.iter().flatten().enumerate() {
            out[80 + 4 * i..84 + 4 * i].copy_from_slice(&v.to_le_bytes());
        }
        out
    }

    fn read_ok(bytes: &[u8]) -> TextureFile {
        read(Path::new("t.dds"), bytes, &ImageLimits::default()).unwrap()
    }

    fn read_err(bytes: &[u8]) -> String {
        read(Path::new("t.dds"), bytes, &ImageLimits::default())
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn a8r8g8b8_is_stored_b_g_r_a_and_authored_mips_are_kept() {
        // 2×1 level 0 (B, G, R, A bytes), then a 1×1 level 1 that is not the
        // average of level 0: it must survive as written.
        let data = vec![255, 0, 0, 255, 0, 255, 0, 51, 0, 0, 255, 0];
        let t = read_ok(&file(2, 1, None, 2, D3DFormat::A8R8G8B8, None, data));
        let TextureFile::Flat(c) = t else {
            panic!("not 2D")
        };
        assert_eq!(c.len(), 2);
        let l0 = c.level(0).unwrap();
        assert_eq!(l0.texels, &[[0.0, 0.0, 1.0, 1.0], [0.0, 1.0, 0.0, 0.2]]);
        assert_eq!(c.level(1).unwrap().texels, &[[1.0, 0.0, 0.0, 0.0]]);
    }

    #[test]
    fn missing_channels_read_as_one() {
        let t = read_ok(&file(1, 1, None, 1, D3DFormat::L8, None, vec![51]));
        assert_eq!(
            t,
            TextureFile::Flat(
                MipChain::from_levels(vec![(1, 1, vec![[0.2, 0.2, 0.2, 1.0]])]).unwrap()
            )
        );
        let t = read_ok(&file(
            1,
            1,
            None,
            1,
            D3DFormat::R32F,
            None,
            2.5f32.to_le_bytes().to_vec(),
        ));
        let TextureFile::Flat(c) = t else { panic!() };
        assert_eq!(c.level(0).unwrap().texels, &[[2.5, 1.0, 1.0, 1.0]]);
        let h = [
            half::f16::from_f32(-0.5).to_le_bytes(),
            half::f16::from_f32(8.0).to_le_bytes(),
            half::f16::from_f32(0.25).to_le_bytes(),
            half::f16::from_f32(1.0).to_le_bytes(),
        ]
        .concat();
        let t = read_ok(&file(1, 1, None, 1, D3DFormat::A16B16G16R16F, None, h));
        let TextureFile::Flat(c) = t else { panic!() };
        assert_eq!(c.level(0).unwrap().texels, &[[-0.5, 8.0, 0.25, 1.0]]);
    }

    #[test]
    fn dxt1_texels_from_the_block_bits() {
        // colour0 = 0xF800 (565 red: 31 → 255), colour1 = 0x001F (blue).
        // colour0 > colour1: four colours, c2 = ⅔c0 + ⅓c1 = (170, 0, 85),
        // c3 = ⅓c0 + ⅔c1 = (85, 0, 170) — both exact in 8 bits. Indices:
        // 2 bits per texel, texel 0 lowest; row 0 = 0b11_10_01_00.
        let block = vec![0x00, 0xF8, 0x1F, 0x00, 0xE4, 0x00, 0x00, 0x00];
        let t = read_ok(&file(4, 4, None, 1, D3DFormat::DXT1, None, block));
        let TextureFile::Flat(c) = t else { panic!() };
        let l = c.level(0).unwrap();
        let v = |r: f32, b: f32| [r / 255.0, 0.0, b / 255.0, 1.0];
        assert_eq!(
            l.texels[0..4],
            [v(255.0, 0.0), v(0.0, 255.0), v(170.0, 85.0), v(85.0, 170.0)]
        );
        assert_eq!(l.texels[4], v(255.0, 0.0));
        // colour0 ≤ colour1: three colours and index 3 transparent black.
        let block = vec![0x1F, 0x00, 0x00, 0xF8, 0x03, 0x00, 0x00, 0x00];
        let TextureFile::Flat(c) = read_ok(&file(4, 4, None, 1, D3DFormat::DXT1, None, block))
        else {
            panic!()
        };
        assert_eq!(c.level(0).unwrap().texels[0], [0.0; 4]);
    }

    #[test]
    fn dxt_levels_smaller_than_a_block_use_one_block() {
        // 2×2 DXT5, 2 levels: each level one 16-byte block. Alpha block:
        // a0 = 255, a1 = 0, all indices 0 → alpha 1; colour all c0 = white.
        let mut block = vec![255, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0x00, 0x00, 0, 0, 0, 0];
        block.extend_from_within(..);
        let TextureFile::Flat(c) = read_ok(&file(2, 2, None, 2, D3DFormat::DXT5, None, block))
        else {
            panic!()
        };
        assert_eq!(c.level(1).unwrap().texels, &[[1.0; 4]]);
        assert_eq!(c.level(0).unwrap().texels.len(), 4);
    }

    #[test]
    fn cube_faces_in_d3d_order_and_volumes_by_slice() {
        // 1×1 faces, face f = (f, 0, 0, 255) as A8R8G8B8 (B, G, R, A).
        let data: Vec<u8> = (0..6u8).flat_map(|f| [0, 0, f, 255]).collect();
        let caps = Caps2::CUBEMAP | Caps2::CUBEMAP_ALLFACES;
        let TextureFile::Cube(c) =
            read_ok(&file(1, 1, None, 1, D3DFormat::A8R8G8B8, Some(caps), data))
        else {
            panic!()
        };
        for f in 0..6 {
            assert_eq!(c.face(f).level(0).unwrap().texels[0][0], f as f32 / 255.0);
        }
        // 1×1×3 L8 volume: slices 10, 20, 30.
        let TextureFile::Volume(v) = read_ok(&file(
            1,
            1,
            Some(3),
            1,
            D3DFormat::L8,
            Some(Caps2::VOLUME),
            vec![10, 20, 30],
        )) else {
            panic!()
        };
        let l = v.level(0).unwrap();
        assert_eq!((l.depth, l.texels[2][0]), (3, 30.0 / 255.0));
    }

    #[test]
    fn hostile_files_are_refused_with_the_place() {
        // Truncated texels.
        let e = read_err(&file(4, 4, None, 1, D3DFormat::A8R8G8B8, None, vec![0; 63]));
        assert!(e.contains("64 bytes") && e.contains("holds 63"), "{e}");
        // More levels than the size allows.
        let e = read_err(&file(
            4,
            4,
            None,
            4,
            D3DFormat::A8R8G8B8,
            None,
            vec![0; 1000],
        ));
        assert!(
            e.contains("mip map count") && e.contains("at most 3"),
            "{e}"
        );
        // A cube with five faces.
        let caps = Caps2::CUBEMAP | Caps2::CUBEMAP_POSITIVEX;
        let e = read_err(&file(
            1,
            1,
            None,
            1,
            D3DFormat::A8R8G8B8,
            Some(caps),
            vec![0; 24],
        ));
        assert!(e.contains("six"), "{e}");
        // A huge claimed size fails before any allocation.
        let mut big = file(1, 1, None, 1, D3DFormat::A8R8G8B8, None, vec![0; 4]);
        big[12..16].copy_from_slice(&16384u32.to_le_bytes());
        big[16..20].copy_from_slice(&16384u32.to_le_bytes());
        let e = read_err(&big);
        assert!(e.contains("16384"), "{e}");
        // Garbage and truncated headers.
        for n in [0, 4, 50, 127] {
            let mut b = b"DDS ".to_vec();
            b.resize(n.max(4), 0xAB);
            let _ = read_err(&b);
        }
        let e = read_err(&file(1, 1, None, 1, D3DFormat::UYVY, None, vec![0; 4]));
        assert!(e.contains("pixel format"), "{e}");
    }
}
