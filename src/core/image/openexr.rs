//! OpenEXR input and output through the `exr` crate (pure Rust; it decodes
//! every compression the test images use, including the lossy DWAB).
//!
//! Reading happens in steps: the first header's raw attributes (see
//! [`check_raw_header`]: an inverted data window, a channel named twice, a
//! compression this reader does not decode), then the headers as the `exr`
//! crate reads them, so that absurd sizes and unusable channel sets are
//! refused before any pixel memory is allocated; then the chunk table (see
//! [`check_chunks`]: every scan line or tile exactly once, and for DWA files
//! the size counters of every chunk); then the pixels of the first layer.
//! The layer's data window is the image (the display window is ignored).
//!
//! Render targets are written losslessly (ZIP) with the channels their
//! format stores, in their own sample type (half for the half formats, f32
//! otherwise): R32F as one f32 channel `R`, Rgba16F as half `R`, `G`, `B`,
//! `A`.

use super::write_atomically;
use super::{ForeignError, HdrImage, ImageError, ImageLimits, RenderTarget};
use exr::block::chunk::CompressedBlock;
use exr::block::reader::ChunksReader;
use exr::math::Vec2;
use exr::meta::attribute::IntegerBounds;
use exr::meta::header::Header;
use exr::prelude::{
    f16, AnyChannel, AnyChannels, Compression, Encoding, FlatSamples, Image, Layer,
    LayerAttributes, MetaData, WritableImage,
};
use std::io::{BufRead, Read, Seek};
use std::path::Path;
use std::sync::Mutex;

const FORMAT: &str = "OpenEXR";

/// What every read below works on. The `exr` crate's readers are generic over
/// the source; reading through one trait object builds its header and chunk
/// readers once, not once per caller's reader type (the header reader alone
/// was seven 28 KB copies in the release binary).
trait Source: BufRead + Seek + Send {}
impl<T: BufRead + Seek + Send> Source for T {}

/// Which file channels fill which of our R, G, B, A slots.
struct ChannelMap {
    /// (channel name, the RGBA slots it fills)
    sources: Vec<(&'static str, &'static [usize])>,
}

impl ChannelMap {
    /// R, G, B (and A) when the file has them; a grey `Y` or lone `R` file
    /// fills R, G and B from its one channel. Alpha stays 1 without an `A`.
    /// Luminance/chroma files (`Y`, `RY`, `BY`) are refused rather than read
    /// as grey.
    fn for_header(path: &Path, header: &Header) -> Result<ChannelMap, ImageError> {
        let has = |name: &str| header.channels.list.iter().any(|c| c.name.eq(name));
        let rgb = has("R") && has("G") && has("B");
        let chroma = has("RY") || has("BY");
        let mut sources: Vec<(&'static str, &'static [usize])> = if rgb {
            vec![("R", &[0]), ("G", &[1]), ("B", &[2])]
        } else if has("Y") && !chroma {
            vec![("Y", &[0, 1, 2])]
        } else if has("R") && !has("G") && !has("B") {
            vec![("R", &[0, 1, 2])]
        } else {
            let found: Vec<String> = header
                .channels
                .list
                .iter()
                .map(|c| c.name.to_string())
                .collect();
            let problem = format!(
                "needs channels R, G, B, or a single Y or R channel (luminance/chroma RY, BY \
                 is not supported); the file has [{}]",
                found.join(", ")
            );
            return Err(ImageError::bad_header(path, FORMAT, "channels", problem));
        };
        if has("A") {
            sources.push(("A", &[3]));
        }
        for channel in &header.channels.list {
            let used = sources.iter().any(|(name, _)| channel.name.eq(name));
            if used && (channel.sampling.x() != 1 || channel.sampling.y() != 1) {
                let problem = format!(
                    "channel {} is subsampled {}x{}; only full-resolution channels are supported",
                    channel.name,
                    channel.sampling.x(),
                    channel.sampling.y()
                );
                return Err(ImageError::bad_header(path, FORMAT, "channels", problem));
            }
        }
        Ok(ChannelMap { sources })
    }
}

/// The headers, checked (the raw attributes, then every layer's size
/// against `limits`); the file has at least one layer.
fn headers(
    path: &Path,
    reader: &mut dyn Source,
    limits: &ImageLimits,
) -> Result<MetaData, ImageError> {
    check_raw_header(path, &mut *reader)?;
    reader
        .rewind()
        .map_err(|e| ImageError::io(path, "read", e))?;
    let meta =
        MetaData::read_from_buffered(&mut *reader, false).map_err(|e| decode_error(path, e))?;
    for header in &meta.headers {
        let size = header.layer_size;
        limits.check(path, FORMAT, size.width() as u64, size.height() as u64)?;
    }
    if meta.headers.is_empty() {
        return Err(ImageError::bad_header(
            path,
            FORMAT,
            "headers",
            "the file has no layer",
        ));
    }
    Ok(meta)
}

/// The first layer's size (what [`read`] decodes), checked against
/// `limits`.
pub(super) fn size(
    path: &Path,
    mut reader: impl BufRead + Seek + Send,
    limits: &ImageLimits,
) -> Result<(u32, u32), ImageError> {
    let meta = headers(path, &mut reader, limits)?;
    let size = meta.headers[0].layer_size;
    Ok((size.width() as u32, size.height() as u32))
}

pub(super) fn read(
    path: &Path,
    mut reader: impl BufRead + Seek + Send,
    limits: &ImageLimits,
) -> Result<HdrImage, ImageError> {
    let reader: &mut dyn Source = &mut reader;
    let meta = headers(path, reader, limits)?;
    let header = &meta.headers[0];
    if header.deep {
        return Err(ImageError::bad_header(
            path,
            FORMAT,
            "type",
            "deep data is not supported",
        ));
    }
    let map = ChannelMap::for_header(path, header)?;
    let rewind =
        |reader: &mut dyn Source| reader.rewind().map_err(|e| ImageError::io(path, "read", e));
    if matches!(
        header.compression,
        Compression::HTJ2K32 | Compression::HTJ2K256
    ) {
        return Err(ImageError::bad_header(
            path,
            FORMAT,
            "compression",
            format!(
                "{} (High-Throughput JPEG 2000) is not supported",
                header.compression
            ),
        ));
    }
    rewind(reader)?;
    check_chunks(path, &mut *reader)?;

    let (width, height) = (header.layer_size.width(), header.layer_size.height());
    let channels = header.channels.clone();
    rewind(reader)?;
    let pixels = decode_pixels(path, reader, &map, &channels, (width, height))?;
    Ok(HdrImage {
        width: width as u32,
        height: height as u32,
        pixels,
    })
}

/// Decodes the first layer's full-resolution blocks straight into RGBA
/// pixels (alpha 1 where the file has none; every pixel is written, since
/// [`check_chunks`] found every row or tile in exactly one chunk),
/// converting each line of samples in bulk. Each block is read,
/// decompressed and written into its own rows by one thread of rayon's
/// current pool, so a command's thread bound holds for decoding too and
/// the calling thread only waits. Chunks are read in file order, one at a
/// time, so only the pixels and one block per thread are held, never the
/// whole file or a second copy. When blocks fail, the error reported is
/// that of the first in file order, as one thread decoding in order would
/// meet it.
fn decode_pixels(
    path: &Path,
    reader: &mut dyn Source,
    map: &ChannelMap,
    channels: &exr::meta::attribute::ChannelList,
    (width, height): (usize, usize),
) -> Result<Vec<[f32; 4]>, ImageError> {
    use rayon::iter::{ParallelBridge, ParallelIterator};
    let decode_error = |e| decode_error(path, e);
    let chunks = exr::block::read(reader, false)
        .map_err(decode_error)?
        .filter_chunks(false, |_, tile, block| {
            block.layer == 0 && tile.is_largest_resolution_level()
        })
        .map_err(decode_error)?;
    let meta = chunks.meta_data().clone();
    let target = Target::new(map, channels, (width, height));
    // Zeroed memory comes from the allocator as it is: the pixels are
    // written once, whole, by the blocks (see `LineBuffers::write`).
    let mut pixels = vec![[0.0f32; 4]; width * height];
    let rows: Vec<Mutex<&mut [[f32; 4]]>> =
        pixels.chunks_mut(width.max(1)).map(Mutex::new).collect();
    // The failing block first in file order, by its index. The bridge hands
    // out chunks in order and every chunk handed out is finished, so when
    // an error stops the work, every earlier chunk has been tried.
    let first_error: Mutex<Option<(usize, ImageError)>> = Mutex::new(None);
    // An error stops the work early; it is taken from `first_error` below.
    let _ = chunks.enumerate().par_bridge().try_for_each_init(
        LineBuffers::default,
        |lines, (index, chunk)| {
            let decoded = chunk
                .and_then(|c| exr::block::UncompressedBlock::decompress_chunk(c, &meta, false))
                .map_err(decode_error)
                .and_then(|block| target.insert(path, &block, &rows, lines));
            decoded.map_err(|e| {
                let mut first = first_error.lock().unwrap_or_else(|p| p.into_inner());
                if first.as_ref().is_none_or(|(i, _)| index < *i) {
                    *first = Some((index, e));
                }
            })
        },
    );
    drop(rows);
    match first_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        Some((_, e)) => Err(e),
        None => Ok(pixels),
    }
}

/// Where decoded blocks go: which RGBA slots each channel of the file
/// fills, in an image of `width` × `height` pixels.
struct Target {
    channels: exr::meta::attribute::ChannelList,
    /// Per channel of the file, in its order, the slots it fills (none: not
    /// read).
    slots: Vec<&'static [usize]>,
    width: usize,
    height: usize,
}

impl Target {
    fn new(
        map: &ChannelMap,
        channels: &exr::meta::attribute::ChannelList,
        (width, height): (usize, usize),
    ) -> Target {
        let slots = channels
            .list
            .iter()
            .map(|c| {
                map.sources
                    .iter()
                    .find(|(name, _)| c.name.eq(name))
                    .map_or(&[][..], |(_, slots)| *slots)
            })
            .collect();
        Target {
            channels: channels.clone(),
            slots,
            width,
            height,
        }
    }

    /// Writes one decoded block's lines into `rows`, the image's rows. The
    /// lines of one row (one per channel) are gathered in `lines` first and
    /// the row's pixels then written whole, its lock held only for that
    /// (blocks of other rows never wait). A line outside the data window is
    /// an error.
    fn insert(
        &self,
        path: &Path,
        block: &exr::block::UncompressedBlock,
        rows: &[Mutex<&mut [[f32; 4]]>],
        lines: &mut LineBuffers,
    ) -> Result<(), ImageError> {
        let (width, height) = (self.width, self.height);
        // The (x, y, n) of the row segment being gathered.
        let mut gathering = None;
        for line in block.lines(&self.channels) {
            let at = line.location;
            let slots = self.slots.get(at.channel).copied().unwrap_or(&[]);
            if slots.is_empty() {
                continue;
            }
            let (x, y, n) = (at.position.x(), at.position.y(), at.sample_count);
            if y >= height || x + n > width {
                let problem = format!("a block's line at ({x}, {y}) of {n} samples lies outside the {width}×{height} data window");
                return Err(ImageError::bad_header(path, FORMAT, "blocks", problem));
            }
            if gathering != Some((x, y, n)) {
                if let Some(segment) = gathering {
                    lines.write(rows, segment);
                }
                lines.start(n);
                gathering = Some((x, y, n));
            }
            lines
                .read(line, self.channels.list[at.channel].sample_type, slots)
                .map_err(|e| decode_error(path, e))?;
        }
        if let Some(segment) = gathering {
            lines.write(rows, segment);
        }
        Ok(())
    }
}

/// One row segment's samples, gathered line by line (a line per channel of
/// the file) before its pixels are written, and the buffers the samples
/// are converted through; reused from block to block by one thread.
#[derive(Default)]
struct LineBuffers {
    half: Vec<f16>,
    uint: Vec<u32>,
    /// Per RGBA slot, the segment's values as f32.
    slots: [Vec<f32>; 4],
    /// Which slots the segment's lines have filled so far.
    filled: [bool; 4],
}

impl LineBuffers {
    /// Starts a segment of `n` pixels, no slot filled yet.
    fn start(&mut self, n: usize) {
        for values in &mut self.slots {
            values.resize(n, 0.0);
        }
        self.filled = [false; 4];
    }

    /// The line's samples as f32 into each of `slots`: half through
    /// `half`'s slice conversion, u32 as `exr` converts them (`as f32`).
    fn read(
        &mut self,
        line: exr::block::lines::LineRef<'_>,
        sample_type: exr::meta::attribute::SampleType,
        slots: &[usize],
    ) -> exr::error::Result<()> {
        use exr::meta::attribute::SampleType;
        use half::slice::HalfFloatSliceExt;
        let n = line.location.sample_count;
        let mut values = std::mem::take(&mut self.slots[slots[0]]);
        match sample_type {
            SampleType::F16 => {
                self.half.resize(n, f16::ZERO);
                line.read_samples_into_slice(&mut self.half)?;
                self.half.convert_to_f32_slice(&mut values);
            }
            SampleType::F32 => line.read_samples_into_slice(&mut values)?,
            SampleType::U32 => {
                self.uint.resize(n, 0);
                line.read_samples_into_slice(&mut self.uint)?;
                for (f, &u) in values.iter_mut().zip(&self.uint) {
                    *f = u as f32;
                }
            }
        }
        for &slot in &slots[1..] {
            self.slots[slot].copy_from_slice(&values);
        }
        self.slots[slots[0]] = values;
        for &slot in slots {
            self.filled[slot] = true;
        }
        Ok(())
    }

    /// Writes the gathered segment, `n` pixels from (`x`, `y`), into its
    /// row. A slot no line filled is 0, alpha 1 (R, G and B are always
    /// filled, since every channel has a line in every row of a block, and
    /// alpha is filled when the file has `A`).
    fn write(&mut self, rows: &[Mutex<&mut [[f32; 4]]>], (x, y, n): (usize, usize, usize)) {
        for (slot, values) in self.slots.iter_mut().enumerate() {
            if !self.filled[slot] {
                values.fill(if slot == 3 { 1.0 } else { 0.0 });
            }
        }
        let [r, g, b, a] = &self.slots;
        let mut row = rows[y].lock().unwrap_or_else(|p| p.into_inner());
        let pixels = row[x..][..n].iter_mut();
        for (pixel, (((&r, &g), &b), &a)) in pixels.zip(r.iter().zip(g).zip(b).zip(a)) {
            *pixel = [r, g, b, a];
        }
    }
}

fn decode_error(path: &Path, e: exr::error::Error) -> ImageError {
    ImageError::Decode {
        path: path.to_path_buf(),
        format: FORMAT,
        source: Box::new(e),
    }
}

/// Compression methods by their number in the file, as the OpenEXR file
/// layout lists them (0–9); later numbers are newer methods this reader
/// does not decode.
const COMPRESSIONS: [&str; 10] = [
    "none", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB",
];

/// Largest first header read byte by byte (a real one is a few kilobytes).
const MAX_RAW_HEADER: u64 = 1 << 20;

/// Checks what the `exr` crate lets through or reports vaguely, on the
/// first header's raw attributes: the data window must not be inverted, no
/// channel may be named twice, and the compression must be one of
/// [`COMPRESSIONS`] (a later one is named by its number).
fn check_raw_header(path: &Path, reader: &mut dyn Source) -> Result<(), ImageError> {
    let mut bytes = Vec::new();
    reader
        .take(MAX_RAW_HEADER)
        .read_to_end(&mut bytes)
        .map_err(|e| ImageError::io(path, "read", e))?;
    let bad = |field: &str, problem: String| ImageError::bad_header(path, FORMAT, field, problem);
    for (name, value) in raw_attributes(&bytes) {
        match name {
            "dataWindow" if value.len() == 16 => {
                let v: Vec<i32> = value
                    .chunks_exact(4)
                    .map(|c| i32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                    .collect();
                if v[2] < v[0] || v[3] < v[1] {
                    return Err(bad(
                        "dataWindow",
                        format!(
                            "the window ({}, {})–({}, {}) is inverted: its maximum is left of or above its minimum",
                            v[0], v[1], v[2], v[3]
                        ),
                    ));
                }
            }
            "channels" => {
                let mut seen: Vec<&[u8]> = Vec::new();
                let mut rest = value;
                while let Some(end) = rest.iter().position(|&b| b == 0).filter(|&e| e > 0) {
                    let channel = &rest[..end];
                    if seen.contains(&channel) {
                        return Err(bad(
                            "channels",
                            format!(
                                "channel {} is listed twice",
                                String::from_utf8_lossy(channel)
                            ),
                        ));
                    }
                    seen.push(channel);
                    rest = rest.get(end + 1 + 16..).unwrap_or_default();
                }
            }
            "compression" if value.len() == 1 && value[0] as usize >= COMPRESSIONS.len() => {
                let name = match value[0] {
                    10 => "HTJ2K256 (High-Throughput JPEG 2000)".to_string(),
                    11 => "HTJ2K32 (High-Throughput JPEG 2000)".to_string(),
                    n => format!("method {n}, newer than this reader knows,"),
                };
                return Err(bad(
                    "compression",
                    format!(
                        "compression {name} is not supported; this reader decodes methods 0–9 ({})",
                        COMPRESSIONS.join(", ")
                    ),
                ));
            }
            _ => {}
        }
    }
    Ok(())
}

/// The attributes of the first header, `(name, value)`, as far as they can
/// be read; the `exr` crate reports whatever is malformed.
fn raw_attributes(bytes: &[u8]) -> Vec<(&str, &[u8])> {
    let mut out = Vec::new();
    let mut pos = 8; // magic number and version
    let cstr = |at: usize| -> Option<(&str, usize)> {
        let len = bytes.get(at..)?.iter().position(|&b| b == 0)?;
        Some((
            std::str::from_utf8(&bytes[at..at + len]).ok()?,
            at + len + 1,
        ))
    };
    while bytes.get(pos).is_some_and(|&b| b != 0) {
        let Some((name, next)) = cstr(pos) else { break };
        let Some((_type, next)) = cstr(next) else {
            break;
        };
        let Some(size) = bytes.get(next..next + 4) else {
            break;
        };
        let size = i32::from_le_bytes([size[0], size[1], size[2], size[3]]);
        let start = next + 4;
        let Some(value) = usize::try_from(size)
            .ok()
            .and_then(|n| bytes.get(start..start.checked_add(n)?))
        else {
            break;
        };
        out.push((name, value));
        pos = start + value.len();
    }
    out
}

/// Walks the chunk table of layer 0 at full resolution, the chunks the
/// decoder will read:
///
/// * every scan line (or tile) must be covered by exactly one chunk: the
///   `exr` crate decodes a table that points two entries at one chunk, or
///   chunks that all claim y = 0, into an image with black rows;
/// * it guards against a flaw in the `exr` crate (1.74): every DWA chunk
///   starts with eleven u64 counters, and the decoder reserves memory for
///   the sizes and counts they record (e.g. the DC count) before it
///   inflates anything. A corrupt counter makes it ask for terabytes, and a
///   failed allocation aborts the whole process: no error, no unwinding. One
///   changed byte in `assets/hdr/city.exr` was enough. So none of a DWA
///   chunk's counters may exceed what the chunk's pixels can need.
fn check_chunks(path: &Path, reader: &mut dyn Source) -> Result<(), ImageError> {
    let chunks = exr::block::read(reader, false)
        .and_then(|r| {
            r.filter_chunks(false, |_, tile, block| {
                block.layer == 0 && tile.is_largest_resolution_level()
            })
        })
        .map_err(|e| decode_error(path, e))?;
    let Some(header) = chunks.headers().first().cloned() else {
        return Ok(()); // no layer, nothing to decode
    };
    let dwa = matches!(
        header.compression,
        Compression::DWAA(_) | Compression::DWAB(_)
    );
    let mut coverage = Coverage::new(&header);
    for chunk in chunks {
        let chunk = chunk.map_err(|e| decode_error(path, e))?;
        let (tile, data) = match &chunk.compressed_block {
            CompressedBlock::ScanLine(b) => {
                let tile = header.get_scan_line_block_tile_coordinates(b.y_coordinate);
                (tile, &b.compressed_pixels_le)
            }
            CompressedBlock::Tile(t) => (Ok(t.coordinates), &t.compressed_pixels_le),
            // Deep data was refused with the header.
            _ => continue,
        };
        let bounds = tile
            .and_then(|tile| header.get_absolute_block_pixel_coordinates(tile))
            .map_err(|e| decode_error(path, e))?;
        coverage.add(path, bounds)?;
        if dwa {
            check_dwa_counters(path, &header, bounds, data)?;
        }
    }
    coverage.complete(path)
}

/// How many chunks cover each pixel row (scan-line files) or each tile
/// (tiled files) of the full-resolution level.
struct Coverage {
    tiled: Option<Vec2<usize>>,
    size: Vec2<usize>,
    counts: Vec<u8>,
}

impl Coverage {
    fn new(header: &Header) -> Coverage {
        let size = header.layer_size;
        let tiled = match header.blocks {
            exr::meta::BlockDescription::Tiles(t) => Some(t.tile_size),
            exr::meta::BlockDescription::ScanLines => None,
        };
        let cells = match tiled {
            Some(t) => {
                size.width().div_ceil(t.width().max(1)) * size.height().div_ceil(t.height().max(1))
            }
            None => size.height(),
        };
        Coverage {
            tiled,
            size,
            counts: vec![0; cells],
        }
    }

    fn add(&mut self, path: &Path, b: IntegerBounds) -> Result<(), ImageError> {
        let (x, y) = (
            b.position.x().max(0) as usize,
            b.position.y().max(0) as usize,
        );
        let cells: Vec<usize> = match self.tiled {
            Some(t) => {
                let across = self.size.width().div_ceil(t.width().max(1));
                vec![(y / t.height().max(1)) * across + x / t.width().max(1)]
            }
            None => (y..y + b.size.height()).collect(),
        };
        for cell in cells {
            let Some(count) = self.counts.get_mut(cell) else {
                continue; // outside the image: the decoder refuses it
            };
            *count = count.saturating_add(1);
            if *count > 1 {
                let what = match self.tiled {
                    Some(_) => format!("the tile at ({x}, {y})"),
                    None => format!("scan line {cell}"),
                };
                let problem =
                    format!("{what} is stored in more than one chunk; the file is corrupt");
                return Err(ImageError::bad_header(path, FORMAT, "chunk table", problem));
            }
        }
        Ok(())
    }

    fn complete(&self, path: &Path) -> Result<(), ImageError> {
        let missing = self.counts.iter().filter(|&&c| c == 0).count();
        if let Some(first) = self.counts.iter().position(|&c| c == 0) {
            let what = match self.tiled {
                Some(_) => format!("{missing} tile(s), the first number {first} in row order,"),
                None => format!("{missing} scan line(s), the first y = {first},"),
            };
            let problem = format!("{what} are in no chunk; the file is corrupt");
            return Err(ImageError::bad_header(path, FORMAT, "chunk table", problem));
        }
        Ok(())
    }
}

/// Checks the counters of one DWA chunk covering `bounds`.
fn check_dwa_counters(
    path: &Path,
    header: &Header,
    bounds: IntegerBounds,
    data: &[u8],
) -> Result<(), ImageError> {
    let (width, height) = (bounds.size.width(), bounds.size.height());
    let raw_bytes = width * height * header.channels.bytes_per_pixel;
    // Empty chunks and chunks stored uncompressed have no counters.
    if data.is_empty() || data.len() == raw_bytes {
        return Ok(());
    }
    // Lossy channels are cut into 8x8 blocks: one DC and 63 AC
    // coefficients each, at most one block set per channel.
    let dct_blocks = width.div_ceil(8) * height.div_ceil(8) * header.channels.list.len();
    // (counter index, name, largest sane value); the RLE stream of n bytes
    // takes at most about n + n/127 bytes, so 2n + 64 is generous.
    let limits = [
        (1, "UNKNOWN uncompressed size", raw_bytes),
        (6, "RLE uncompressed size", 2 * raw_bytes + 64),
        (7, "RLE raw size", raw_bytes),
        (8, "AC count", 63 * dct_blocks),
        (9, "DC count", dct_blocks),
    ];
    for (index, name, limit) in limits {
        // A chunk too short for its counters is left to the decoder, which
        // reports it.
        let Some(bytes) = data.get(8 * index..8 * index + 8) else {
            continue;
        };
        let value = u64::from_le_bytes(bytes.try_into().unwrap_or_default());
        if value > limit as u64 {
            let problem = format!(
                "{name} is {value}, but a {width}x{height} block needs at most {limit}; \
                 the file is corrupt"
            );
            let field = format!("DWA chunk counters (block at y = {})", bounds.position.y());
            return Err(ImageError::bad_header(path, FORMAT, field, problem));
        }
    }
    Ok(())
}

/// Writes a render target as OpenEXR (ZIP-compressed scan lines), keeping its
/// exact stored values: the channels the format stores (`R`; `R`, `G`; or
/// `R`, `G`, `B`, `A`), as half for the half formats and as f32 for the
/// others (an 8-bit code k as the f32 value k/255 it reads back as).
pub fn write_exr(path: &Path, target: &RenderTarget) -> Result<(), ImageError> {
    let bytes = encode_exr(path, target)?;
    write_atomically(path, FORMAT, |w| {
        std::io::Write::write_all(w, &bytes)?;
        Ok(())
    })
}

/// The OpenEXR file [`write_exr`] writes, as bytes (for a
/// [`crate::core::output::Batch`]); `path` is only named in errors.
pub fn encode_exr(path: &Path, target: &RenderTarget) -> Result<Vec<u8>, ImageError> {
    let expected = target.width as u64 * target.height as u64;
    if target.texels.len() as u64 != expected {
        return Err(ImageError::DataLength {
            path: path.to_path_buf(),
            what: "render target",
            expected,
            found: target.texels.len() as u64,
        });
    }
    let texels = &target.texels;
    let half = target.format.encoding() == super::Encoding::Half;
    let channels: Vec<AnyChannel<FlatSamples>> = ["R", "G", "B", "A"]
        .iter()
        .enumerate()
        .take(target.format.channels())
        .map(|(i, name)| {
            let samples = if half {
                FlatSamples::F16(texels.iter().map(|t| f16::from_f32(t[i])).collect())
            } else {
                FlatSamples::F32(texels.iter().map(|t| t[i]).collect())
            };
            AnyChannel::new(*name, samples)
        })
        .collect();
    let layer = Layer::new(
        (target.width as usize, target.height as usize),
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(channels.into()),
    );
    let mut out = std::io::Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut out)
        .map_err(|e| ImageError::Encode {
            path: path.to_path_buf(),
            format: FORMAT,
            source: Box::new(e),
        })?;
    Ok(out.into_inner())
}

/// Writes linear RGB floats as OpenEXR with f32 channels `R`, `G`, `B`.
pub fn write_rgb_f32(
    path: &Path,
    width: u32,
    height: u32,
    rgb: &[[f32; 3]],
) -> Result<(), ImageError> {
    let expected = width as u64 * height as u64;
    if rgb.len() as u64 != expected {
        return Err(ImageError::DataLength {
            path: path.to_path_buf(),
            what: "RGB pixels",
            expected,
            found: rgb.len() as u64,
        });
    }
    let planes = std::array::from_fn(|i| rgb.iter().map(|p| p[i]).collect());
    let image = Image::from_layer(rgb_layer(width, height, planes));
    write_atomically(path, FORMAT, |w| {
        image.write().to_buffered(w)?;
        Ok(())
    })
}

/// The layer [`write_rgb_f32`] writes: f32 `R`, `G`, `B`, ZIP-compressed
/// scan lines in increasing order.
fn rgb_layer(width: u32, height: u32, planes: [Vec<f32>; 3]) -> Layer<AnyChannels<FlatSamples>> {
    let channels: Vec<AnyChannel<FlatSamples>> = ["R", "G", "B"]
        .into_iter()
        .zip(planes)
        .map(|(name, plane)| AnyChannel::new(name, FlatSamples::F32(plane)))
        .collect();
    Layer::new(
        (width as usize, height as usize),
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(channels.into()),
    )
}

/// The file [`write_rgb_f32`] writes, made a band of rows at a time: the
/// rows are packed into the file's blocks of scan lines (16 for ZIP), the
/// blocks a band fills are compressed in parallel on rayon's current pool,
/// and a thread writes them through the `exr` crate's chunk writer, in
/// order, so that no more than a band and a few blocks are held. The
/// headers, chunks and offset table are the whole-image writer's.
pub(super) struct RgbScanLines {
    width: usize,
    height: usize,
    lines_per_block: usize,
    /// The block being filled: per scan line, each channel's row of f32 in
    /// the file's channel order (B, G, R).
    pending: Vec<u8>,
    /// Scan lines given so far.
    lines: usize,
    headers: exr::meta::Headers,
    chunks: Option<std::sync::mpsc::SyncSender<exr::block::chunk::Chunk>>,
    writer: Option<std::thread::JoinHandle<exr::error::UnitResult>>,
}

impl RgbScanLines {
    /// Starts the writing thread on `file` (a staged file, written from its
    /// start).
    pub(super) fn start(file: std::fs::File, width: u32, height: u32) -> RgbScanLines {
        use exr::block::writer::ChunksWriter;
        let headers = Image::from_layer(rgb_layer(width, height, Default::default()))
            .write()
            .infer_meta_data();
        let lines_per_block = headers[0].compression.scan_lines_per_block();
        // A few chunks in flight: the writer writes while the next band is drawn.
        let (chunks, queue) = std::sync::mpsc::sync_channel::<exr::block::chunk::Chunk>(4);
        let for_writer = headers.clone();
        let writer = std::thread::spawn(move || {
            let out = std::io::BufWriter::new(file);
            exr::block::write(out, for_writer, true, move |_, writer| {
                for (index, chunk) in queue.into_iter().enumerate() {
                    writer.write_chunk(index, chunk)?;
                }
                Ok(())
            })
        });
        RgbScanLines {
            width: width as usize,
            height: height as usize,
            lines_per_block,
            pending: Vec::new(),
            lines: 0,
            headers,
            chunks: Some(chunks),
            writer: Some(writer),
        }
    }

    /// Adds whole rows (top row first; alpha is not written).
    pub(super) fn rows(&mut self, pixels: &[[f32; 4]]) -> Result<(), ForeignError> {
        use rayon::prelude::*;
        let mut filled = Vec::new();
        for row in pixels.chunks_exact(self.width.max(1)) {
            for c in [2, 1, 0] {
                for p in row {
                    self.pending.extend_from_slice(&p[c].to_le_bytes());
                }
            }
            self.lines += 1;
            if self.lines.is_multiple_of(self.lines_per_block) || self.lines == self.height {
                filled.push(self.block());
            }
        }
        let headers = &self.headers;
        let chunks: Vec<_> = filled
            .into_par_iter()
            .map(|block| block.compress_to_chunk(headers))
            .collect::<Result<_, _>>()?;
        for chunk in chunks {
            if self.chunks.as_ref().map(|c| c.send(chunk).is_ok()) != Some(true) {
                // The thread stopped: its error says why.
                let stopped = self.join().err();
                return Err(stopped.unwrap_or_else(|| "the OpenEXR writer stopped".into()));
            }
        }
        Ok(())
    }

    /// The block just filled, ending at the last line given.
    fn block(&mut self) -> exr::block::UncompressedBlock {
        let rows = (self.lines - 1) % self.lines_per_block + 1;
        exr::block::UncompressedBlock {
            index: exr::block::BlockIndex {
                layer: 0,
                pixel_position: Vec2(0, self.lines - rows),
                pixel_size: Vec2(self.width, rows),
                level: Vec2(0, 0),
            },
            data: std::mem::take(&mut self.pending),
        }
    }

    /// Waits for the writing thread to complete the file (every row must
    /// have been given).
    pub(super) fn finish(mut self) -> Result<(), ForeignError> {
        self.join()
    }

    /// Ends the queue and waits for the thread (once).
    fn join(&mut self) -> Result<(), ForeignError> {
        self.chunks = None;
        match self.writer.take().map(|w| w.join()) {
            Some(Ok(written)) => Ok(written?),
            Some(Err(_)) => Err("the OpenEXR writer panicked".into()),
            None => Ok(()),
        }
    }
}

impl Drop for RgbScanLines {
    /// Abandoned (an error elsewhere): the thread ends with an incomplete
    /// file, which its staged file's drop removes; no thread outlives it.
    fn drop(&mut self) {
        let _ = self.join();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::image::load;
    use crate::core::image::TargetFormat;

    fn load_default(path: &Path) -> Result<HdrImage, ImageError> {
        load(path, &ImageLimits::default())
    }

    fn write_channels(
        path: &Path,
        width: usize,
        height: usize,
        channels: Vec<AnyChannel<FlatSamples>>,
    ) {
        let layer = Layer::new(
            (width, height),
            LayerAttributes::default(),
            Encoding::SMALL_LOSSLESS,
            AnyChannels::sort(channels.into()),
        );
        Image::from_layer(layer).write().to_file(path).unwrap();
    }

    #[test]
    fn rgba16f_target_round_trips_exactly() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.exr");
        let mut target = RenderTarget::new(3, 2, TargetFormat::Rgba16F);
        target.store(0, 0, [1.0001, -2.5, 70000.0, 0.5]);
        target.store(2, 1, [1e-6, 3.0, 65504.0, 0.0]);
        write_exr(&path, &target).unwrap();
        let image = load_default(&path).unwrap();
        assert_eq!((image.width, image.height), (3, 2));
        assert_eq!(image.pixels, target.texels);
    }

    #[test]
    fn r32f_target_reads_back_as_grey() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.exr");
        let mut target = RenderTarget::new(2, 2, TargetFormat::R32F);
        target.store(1, 1, [0.123_456_79, 9.0, 9.0, 9.0]);
        write_exr(&path, &target).unwrap();
        let image = load_default(&path).unwrap();
        assert_eq!(
            image.pixel(1, 1),
            [0.123_456_79, 0.123_456_79, 0.123_456_79, 1.0]
        );
        assert_eq!(image.pixel(0, 0), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn grey_y_channel_fills_rgb() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("y.exr");
        let y = FlatSamples::F16(vec![f16::from_f32(0.25), f16::from_f32(4.0)]);
        write_channels(&path, 2, 1, vec![AnyChannel::new("Y", y)]);
        let image = load_default(&path).unwrap();
        assert_eq!(
            image.pixels,
            vec![[0.25, 0.25, 0.25, 1.0], [4.0, 4.0, 4.0, 1.0]]
        );
    }

    /// Tiles share rows, so blocks of one row are written by different
    /// threads: every pixel must still be written once, alpha included,
    /// whatever the number of threads (1, 2, 5) and the tiles' order.
    #[test]
    fn tiled_file_decodes_alike_on_any_thread_count() {
        use exr::prelude::{Blocks, LineOrder};
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("tiled.exr");
        let (width, height) = (53, 37); // partial tiles at the right and bottom
        let plane = |k: usize| -> Vec<f32> {
            (0..width * height)
                .map(|i| (i * 7 + k) as f32 * 0.25)
                .collect()
        };
        let channels: Vec<AnyChannel<FlatSamples>> = ["R", "G", "B"]
            .iter()
            .enumerate()
            .map(|(k, name)| AnyChannel::new(*name, FlatSamples::F32(plane(k))))
            .collect();
        let encoding = Encoding {
            compression: Compression::ZIP1,
            blocks: Blocks::Tiles(Vec2(16, 8)),
            line_order: LineOrder::Unspecified,
        };
        let layer = Layer::new(
            (width, height),
            LayerAttributes::default(),
            encoding,
            AnyChannels::sort(channels.into()),
        );
        Image::from_layer(layer).write().to_file(&path).unwrap();
        let expected: Vec<[f32; 4]> = (0..width * height)
            .map(|i| {
                let v = |k: usize| (i * 7 + k) as f32 * 0.25;
                [v(0), v(1), v(2), 1.0]
            })
            .collect();
        for threads in [1, 2, 5] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let image = pool.install(|| load_default(&path)).unwrap();
            assert_eq!((image.width, image.height), (53, 37));
            assert!(image.pixels == expected, "{threads} threads");
        }
    }

    #[test]
    fn luminance_chroma_files_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("yc.exr");
        let channel = |name| AnyChannel::new(name, FlatSamples::F32(vec![1.0; 4]));
        write_channels(
            &path,
            2,
            2,
            vec![channel("Y"), channel("RY"), channel("BY")],
        );
        let err = load_default(&path).unwrap_err();
        assert!(err.to_string().contains("RY"), "{err}");
    }

    #[test]
    fn unusable_channels_are_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("z.exr");
        let z = FlatSamples::F32(vec![1.0; 4]);
        write_channels(&path, 2, 2, vec![AnyChannel::new("Z", z)]);
        let err = load_default(&path).unwrap_err();
        assert!(matches!(err, ImageError::BadHeader { .. }), "{err}");
        assert!(err.to_string().contains("[Z]"), "{err}");
    }

    #[test]
    fn corrupt_dwa_counter_is_an_error_not_an_abort() {
        // city.exr (DWAB) has its first chunk at byte 1208: y (i32), size
        // (i32), then the eleven u64 DWA counters; the DC count (counter 9)
        // is 12288 = (1024/8) * (256/8) * 3 channels.
        let mut bytes =
            std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/hdr/city.exr")).unwrap();
        let dc_count = 1208 + 8 + 9 * 8;
        assert_eq!(bytes[dc_count..dc_count + 8], 12288u64.to_le_bytes());
        // One changed byte, as found by corrupting the file at random: the
        // exr crate alone would try to reserve 2 * 85 * 2^40 bytes and abort.
        bytes[dc_count + 5] = 85;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("corrupt.exr");
        std::fs::write(&path, bytes).unwrap();
        let err = load_default(&path).unwrap_err();
        assert!(matches!(err, ImageError::BadHeader { .. }), "{err}");
        assert!(err.to_string().contains("DC count"), "{err}");
    }

    #[test]
    fn truncated_file_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.exr");
        let mut target = RenderTarget::new(64, 64, TargetFormat::Rgba16F);
        for i in 0..64 {
            target.store(i, i, [i as f32; 4]);
        }
        write_exr(&path, &target).unwrap();
        let full = std::fs::read(&path).unwrap();
        for len in [4, 20, 200, full.len() / 2, full.len() - 1] {
            std::fs::write(&path, &full[..len]).unwrap();
            let err = load_default(&path).unwrap_err();
            assert!(err.to_string().contains("t.exr"), "{len}: {err}");
        }
    }

    /// A minimal scan-line EXR header claiming `width` x `height` pixels, one
    /// half channel R, no compression, followed by no data at all.
    fn exr_header_only(width: i32, height: i32) -> Vec<u8> {
        fn attribute(out: &mut Vec<u8>, name: &str, kind: &str, value: &[u8]) {
            out.extend(name.as_bytes());
            out.push(0);
            out.extend(kind.as_bytes());
            out.push(0);
            out.extend((value.len() as i32).to_le_bytes());
            out.extend(value);
        }
        let window: Vec<u8> = [0, 0, width - 1, height - 1]
            .iter()
            .flat_map(|v: &i32| v.to_le_bytes())
            .collect();
        // chlist: name, pixel type (1 = half), pLinear + 3 reserved, x/y sampling; then a 0 byte.
        let mut channels = b"R\0".to_vec();
        channels.extend(1i32.to_le_bytes());
        channels.extend([0, 0, 0, 0]);
        channels.extend(1i32.to_le_bytes());
        channels.extend(1i32.to_le_bytes());
        channels.push(0);

        let mut out = vec![0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0];
        attribute(&mut out, "channels", "chlist", &channels);
        attribute(&mut out, "compression", "compression", &[0]);
        attribute(&mut out, "dataWindow", "box2i", &window);
        attribute(&mut out, "displayWindow", "box2i", &window);
        attribute(&mut out, "lineOrder", "lineOrder", &[0]);
        attribute(&mut out, "pixelAspectRatio", "float", &1f32.to_le_bytes());
        attribute(&mut out, "screenWindowCenter", "v2f", &[0; 8]);
        attribute(&mut out, "screenWindowWidth", "float", &1f32.to_le_bytes());
        out.push(0); // end of header
        out
    }

    #[test]
    fn absurd_size_is_refused_before_decoding() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("huge.exr");
        std::fs::write(&path, exr_header_only(100_000, 100_000)).unwrap();
        let err = load_default(&path).unwrap_err();
        assert!(
            matches!(
                err,
                ImageError::TooLarge {
                    width: 100_000,
                    height: 100_000,
                    ..
                }
            ),
            "{err}"
        );
        assert!(err.to_string().contains("--max-pixels"), "{err}");
    }

    #[test]
    fn hand_made_header_is_a_valid_exr() {
        // The same header for a small size fails only for lack of pixel
        // data (the offset table is missing), which shows the huge case
        // above was refused by the size check and not by a header error.
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("small.exr");
        std::fs::write(&path, exr_header_only(4, 4)).unwrap();
        MetaData::read_from_file(&path, true).unwrap();
        let err = load_default(&path).unwrap_err();
        assert!(matches!(err, ImageError::Decode { .. }), "{err}");
    }
}
