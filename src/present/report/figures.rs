//! Figures for `reports/`: charts drawn with plotters (titles, axes with
//! units, tick labels, legends, colour bars with values) in the embedded
//! DejaVu Sans, and downscaled previews, into 8-bit RGB canvases that are
//! then encoded as PNG ([`crate::core::image::encode_png_rgb8`]).
//!
//! A figure reads on its own: whatever its page says around it, its title
//! names the quantity, its axes the units and its legend or colour bar the
//! values. The same inputs give the same bytes on every run and for every
//! thread count: plotters draws on one thread in a fixed order, and the
//! font is compiled in (never looked up on the system).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The font every figure's text is drawn in, compiled in so that figures
/// do not depend on the fonts of the machine (`assets/fonts/LICENSE`), and
/// stored deflated: 142 KB of `DejaVuSans.ttf` as 75 KB of the binary,
/// inflated the first time a figure is drawn. The stored stream is the
/// file's raw deflate, written by `tools/subset-font` with the file; a test
/// holds it equal to the file.
const FONT_DEFLATED: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf.deflate");
/// The family name the font is registered under.
const FAMILY: &str = "sans-serif";

/// An RGB image with 8-bit channels, row-major, top row first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Canvas {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` pixels of three bytes (R, G, B), row by row.
    pub rgb: Vec<u8>,
}

/// The background of every figure.
pub const WHITE_RGB: [u8; 3] = [255, 255, 255];
/// Text and frames.
pub const BLACK_RGB: [u8; 3] = [0, 0, 0];
/// The lines between heat-map cells.
pub const GRID_RGB: [u8; 3] = [32, 32, 32];
/// A value that is not a number (NaN) in a heat map.
pub const LIGHT_RGB: [u8; 3] = [200, 200, 200];
/// Limits, and what passes them (beyond a bound, over a limit).
pub const RED_RGB: [u8; 3] = [214, 39, 40];

impl Canvas {
    /// A `width × height` canvas filled with `background`.
    pub fn new(width: u32, height: u32, background: [u8; 3]) -> Canvas {
        let n = width as usize * height as usize;
        Canvas {
            width,
            height,
            rgb: background.repeat(n),
        }
    }

    /// The pixel at (x, y).
    ///
    /// # Panics
    /// If (x, y) is outside the canvas.
    pub fn get(&self, x: u32, y: u32) -> [u8; 3] {
        assert!(x < self.width && y < self.height, "({x}, {y}) outside");
        let i = (y as usize * self.width as usize + x as usize) * 3;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }
}

/// Nine samples of matplotlib's viridis colour map (t = 0, 1/8, …, 1), in
/// sRGB: perceptually ordered from dark purple to yellow, readable in grey
/// and by most colour-blind readers.
const VIRIDIS: [[u8; 3]; 9] = [
    [68, 1, 84],
    [72, 40, 120],
    [62, 73, 137],
    [49, 104, 142],
    [38, 130, 142],
    [31, 158, 137],
    [53, 183, 121],
    [109, 205, 89],
    [253, 231, 37],
];

/// A viridis-like colour for `t` in [0, 1] (clamped; NaN is light grey),
/// linear between the nine samples.
pub fn viridis(t: f64) -> [u8; 3] {
    if t.is_nan() {
        return LIGHT_RGB;
    }
    let x = t.clamp(0.0, 1.0) * 8.0;
    let i = (x.floor() as usize).min(7);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    [0, 1, 2].map(|c| (a[c] as f64 + (b[c] as f64 - a[c] as f64) * f).round() as u8)
}

fn rgb(c: [u8; 3]) -> RGBColor {
    RGBColor(c[0], c[1], c[2])
}

/// The text of a figure: its title and its axes, with units.
#[derive(Clone, Copy, Debug)]
pub struct Labels<'a> {
    /// The figure's title: the quantity shown.
    pub title: &'a str,
    /// The x axis: its quantity and unit.
    pub x: &'a str,
    /// The y axis: its quantity and unit.
    pub y: &'a str,
}

/// The font's file, inflated once; the stored stream is compiled in and
/// checked by a test, so it inflates.
fn font() -> &'static [u8] {
    static FONT: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    FONT.get_or_init(|| {
        miniz_oxide::inflate::decompress_to_vec(FONT_DEFLATED)
            .expect("the compiled-in font inflates")
    })
}

/// Draws a `width × height` figure with `paint` on a white background.
fn draw(
    width: u32,
    height: u32,
    paint: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), String>,
) -> Result<Canvas, String> {
    static FONT_ONCE: std::sync::Once = std::sync::Once::new();
    FONT_ONCE.call_once(|| {
        // Registering a font that parses cannot fail; if it could not be
        // registered, drawing text reports the missing font below.
        let _ = plotters::style::register_font(FAMILY, FontStyle::Normal, font());
    });
    let mut rgb = vec![255u8; width as usize * height as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        paint(&root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(Canvas { width, height, rgb })
}

fn style(size: u32) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&BLACK)
}

/// A plotters error as text.
fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// The width of a heat map's colour bar, its values and its title.
const COLOUR_BAR: u32 = 150;

/// A heat map of per-cell values over an area in data units (e.g. blocks of
/// an image in pixels), with a colour bar that gives the values: cells with
/// `flagged` set are outlined in red, and `marks` are drawn as lines across
/// the colour bar (e.g. a bound at 0). `values` are row-major,
/// `x_edges.len() - 1` per row; `y_edges` count down from the top.
#[derive(Clone, Debug)]
pub struct HeatMap<'a> {
    /// Title and axes.
    pub labels: Labels<'a>,
    /// What the colour bar measures, with its unit.
    pub colorbar: &'a str,
    /// One value per cell, row by row from the top (NaN: light grey).
    pub values: &'a [f64],
    /// Cell boundaries in x, increasing, in data units.
    pub x_edges: &'a [f64],
    /// Cell boundaries in y, increasing downwards, in data units.
    pub y_edges: &'a [f64],
    /// The values mapped to the two ends of the colour map.
    pub range: (f64, f64),
    /// Values to mark across the colour bar.
    pub marks: &'a [f64],
    /// Cells to outline in red (e.g. beyond a bound); empty for none.
    pub flagged: &'a [bool],
    /// The figure's size in pixels.
    pub size: (u32, u32),
}

impl HeatMap<'_> {
    /// The figure.
    pub fn render(&self) -> Result<Canvas, String> {
        draw(self.size.0, self.size.1, |root| {
            let (map, bar) = root.split_horizontally(self.size.0.saturating_sub(COLOUR_BAR));
            self.map(&map)?;
            self.colour_bar(&bar)
        })
    }

    /// The map. Data y counts down from the top, the chart's up: the chart
    /// plots −y, so that its ticks fall on round values from the top.
    fn map(&self, area: &DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), String> {
        let nx = self.x_edges.len().saturating_sub(1);
        let ny = self.y_edges.len().saturating_sub(1);
        let x_max = self.x_edges.last().copied().unwrap_or(1.0);
        let y_max = self.y_edges.last().copied().unwrap_or(1.0);
        let mut chart = ChartBuilder::on(area)
            .caption(self.labels.title, style(17))
            .margin(8)
            .x_label_area_size(42)
            .y_label_area_size(58)
            .build_cartesian_2d(0f64..x_max, -y_max..0f64)
            .map_err(err)?;
        let flip = |y: f64| -y;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(self.labels.x)
            .y_desc(self.labels.y)
            .axis_desc_style(style(13))
            .label_style(style(12))
            .y_label_formatter(&|v| format!("{:.0}", -v + 0.0))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .draw()
            .map_err(err)?;
        let (lo, hi) = self.range;
        let t = |v: f64| if hi > lo { (v - lo) / (hi - lo) } else { 0.5 };
        let cell = |cx: usize, cy: usize| {
            [
                (self.x_edges[cx], flip(self.y_edges[cy])),
                (self.x_edges[cx + 1], flip(self.y_edges[cy + 1])),
            ]
        };
        let cells = (0..ny).flat_map(|cy| (0..nx).map(move |cx| (cx, cy)));
        chart
            .draw_series(cells.clone().map(|(cx, cy)| {
                let v = self.values.get(cy * nx + cx).copied().unwrap_or(f64::NAN);
                Rectangle::new(cell(cx, cy), rgb(viridis(t(v))).filled())
            }))
            .map_err(err)?;
        chart
            .draw_series(
                cells
                    .clone()
                    .map(|(cx, cy)| Rectangle::new(cell(cx, cy), rgb(GRID_RGB).stroke_width(1))),
            )
            .map_err(err)?;
        let flagged = cells.filter(|&(cx, cy)| self.flagged.get(cy * nx + cx) == Some(&true));
        chart
            .draw_series(
                flagged.map(|(cx, cy)| Rectangle::new(cell(cx, cy), rgb(RED_RGB).stroke_width(3))),
            )
            .map_err(err)?;
        Ok(())
    }

    fn colour_bar(&self, area: &DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), String> {
        let (lo, hi) = self.range;
        let hi = if hi > lo { hi } else { lo + 1.0 };
        let mut chart = ChartBuilder::on(area)
            .margin_top(34)
            .margin_bottom(50)
            .margin_left(28)
            .margin_right(8)
            .y_label_area_size(84)
            .build_cartesian_2d(0f64..1f64, lo..hi)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_desc(self.colorbar)
            .axis_desc_style(style(13))
            .label_style(style(12))
            .y_labels(6)
            .draw()
            .map_err(err)?;
        const STEPS: usize = 120;
        let step = (hi - lo) / STEPS as f64;
        chart
            .draw_series((0..STEPS).map(|i| {
                let v = lo + i as f64 * step;
                Rectangle::new(
                    [(0.0, v), (1.0, v + step)],
                    rgb(viridis((i as f64 + 0.5) / STEPS as f64)).filled(),
                )
            }))
            .map_err(err)?;
        chart
            .draw_series(
                self.marks
                    .iter()
                    .filter(|m| (lo..=hi).contains(*m))
                    .map(|&m| PathElement::new(vec![(0.0, m), (1.0, m)], BLACK.stroke_width(2))),
            )
            .map_err(err)?;
        Ok(())
    }
}

/// A horizontal bar chart of fractions of a limit: one group of bars per
/// named row (e.g. slots and executed instructions of one shader), an axis
/// in percent of the limit, a red line at 100 % and a legend naming the
/// bars. A bar beyond the limit turns red past the line.
#[derive(Clone, Debug)]
pub struct BarChart<'a> {
    /// Title and axes.
    pub labels: Labels<'a>,
    /// The name of each group, top to bottom.
    pub rows: &'a [String],
    /// Each group's bars, as fractions of the limit.
    pub groups: &'a [Vec<f64>],
    /// The legend: one name and colour per bar position in a group.
    pub bars: &'a [(&'a str, [u8; 3])],
    /// The fraction at the right end of the axis (≥ 1).
    pub max_fraction: f64,
    /// The figure's width in pixels (the height follows the rows).
    pub width: u32,
}

impl BarChart<'_> {
    /// The figure.
    pub fn render(&self) -> Result<Canvas, String> {
        let per_group = self.bars.len().max(1);
        let rows = self.groups.len();
        let height = 120 + rows as u32 * (16 * per_group as u32 + 12);
        let name_width = self
            .rows
            .iter()
            .map(|r| r.chars().count())
            .max()
            .unwrap_or(4) as u32
            * 8;
        draw(self.width, height, |root| {
            let top = self.max_fraction * 100.0;
            let mut chart = ChartBuilder::on(root)
                .caption(self.labels.title, style(17))
                .margin(10)
                .x_label_area_size(42)
                .y_label_area_size(name_width + 34)
                .build_cartesian_2d(0f64..top, 0f64..rows as f64)
                .map_err(err)?;
            chart
                .configure_mesh()
                .disable_y_mesh()
                .y_labels(0)
                .x_desc(self.labels.x)
                .y_desc(self.labels.y)
                .axis_desc_style(style(13))
                .label_style(style(12))
                .light_line_style(WHITE)
                .x_label_formatter(&|v| format!("{v:.0}%"))
                .draw()
                .map_err(err)?;
            // Row k (from the top) spans [rows - k - 1, rows - k].
            let band = 0.8 / per_group as f64;
            let span = |k: usize, b: usize| {
                let y1 = rows as f64 - k as f64 - 0.1 - b as f64 * band;
                (y1 - band, y1)
            };
            for (b, &(name, colour)) in self.bars.iter().enumerate() {
                let colour = rgb(colour);
                let bars = self.groups.iter().enumerate().filter_map(|(k, g)| {
                    let (y0, y1) = span(k, b);
                    let x = (*g.get(b)? * 100.0).clamp(0.0, 100.0);
                    Some(Rectangle::new([(0.0, y0), (x, y1)], colour.filled()))
                });
                chart
                    .draw_series(bars)
                    .map_err(err)?
                    .label(name)
                    .legend(move |(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 14, y + 5)], colour.filled())
                    });
                let over = self.groups.iter().enumerate().filter_map(|(k, g)| {
                    let v = *g.get(b)? * 100.0;
                    let (y0, y1) = span(k, b);
                    (v > 100.0).then(|| {
                        Rectangle::new([(100.0, y0), (v.min(top), y1)], rgb(RED_RGB).filled())
                    })
                });
                chart.draw_series(over).map_err(err)?;
            }
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(100.0, 0.0), (100.0, rows as f64)],
                    rgb(RED_RGB).stroke_width(2),
                )))
                .map_err(err)?
                .label("the limit (100%); a bar past it turns red")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 14, y)], rgb(RED_RGB).stroke_width(2))
                });
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::LowerRight)
                .background_style(WHITE.mix(0.9))
                .border_style(BLACK)
                .label_font(style(12))
                .draw()
                .map_err(err)?;
            // The row names, right-aligned against the axis.
            let names = style(12).pos(Pos::new(HPos::Right, VPos::Center));
            for (k, name) in self.rows.iter().enumerate() {
                let (x, y) = chart.backend_coord(&(0.0, rows as f64 - k as f64 - 0.5));
                root.draw(&Text::new(name.as_str(), (x - 8, y), names.clone()))
                    .map_err(err)?;
            }
            Ok(())
        })
    }
}

/// One line of a [`LineChart`]: points in data units, joined in order, and
/// its name in the legend. A point with a non-finite coordinate breaks the
/// line.
#[derive(Clone, Debug)]
pub struct Series {
    /// The name in the legend.
    pub name: String,
    /// (x, y) in data units, in order.
    pub points: Vec<(f64, f64)>,
    /// The line's colour.
    pub color: [u8; 3],
}

/// A line chart: named series over an x range and a y range (linear or
/// log10), tick labels, dashed horizontal reference lines with names, and
/// a legend. Values beyond the y range are drawn at its edge (clipped, not
/// dropped), so a curve that leaves the chart is seen to leave it.
#[derive(Clone, Debug)]
pub struct LineChart<'a> {
    /// Title and axes.
    pub labels: Labels<'a>,
    /// The lines.
    pub series: &'a [Series],
    /// The x axis, in data units.
    pub x_range: (f64, f64),
    /// The y axis, in data units (values beyond it are drawn at its edge).
    pub y_range: (f64, f64),
    /// Plot y as log10 (y_range then must be positive).
    pub log_y: bool,
    /// Dashed horizontal lines at these y values, with their names.
    pub hlines: &'a [(f64, [u8; 3], &'a str)],
    /// Where the legend goes (where the lines are not).
    pub legend: SeriesLabelPosition,
    /// The figure's size in pixels.
    pub size: (u32, u32),
}

impl LineChart<'_> {
    /// `y` clamped into the y range (NaN stays NaN and breaks the line).
    fn clip(&self, y: f64) -> f64 {
        let (lo, hi) = self.y_range;
        if y.is_nan() {
            y
        } else {
            y.clamp(lo, hi)
        }
    }

    /// The series as runs of finite points (a non-finite point breaks it).
    fn runs(&self, s: &Series) -> Vec<Vec<(f64, f64)>> {
        let mut runs = vec![Vec::new()];
        for &(x, y) in &s.points {
            let y = if self.log_y && y <= 0.0 {
                self.y_range.0
            } else {
                self.clip(y)
            };
            if x.is_finite() && y.is_finite() {
                runs.last_mut().expect("one run at least").push((x, y));
            } else if !runs.last().is_some_and(Vec::is_empty) {
                runs.push(Vec::new());
            }
        }
        runs
    }

    /// The figure.
    pub fn render(&self) -> Result<Canvas, String> {
        draw(self.size.0, self.size.1, |root| {
            let (x0, x1) = self.x_range;
            let (y0, y1) = self.y_range;
            let builder = |root| {
                let mut b = ChartBuilder::on(root);
                b.caption(self.labels.title, style(17))
                    .margin(10)
                    .x_label_area_size(42)
                    .y_label_area_size(64);
                b
            };
            if self.log_y {
                let mut chart = builder(root)
                    .build_cartesian_2d(x0..x1, (y0..y1).log_scale())
                    .map_err(err)?;
                chart
                    .configure_mesh()
                    .x_desc(self.labels.x)
                    .y_desc(self.labels.y)
                    .axis_desc_style(style(13))
                    .label_style(style(12))
                    .y_label_formatter(&|v| format!("{v:e}"))
                    .light_line_style(WHITE)
                    .draw()
                    .map_err(err)?;
                self.lines(&mut chart)
            } else {
                let mut chart = builder(root)
                    .build_cartesian_2d(x0..x1, y0..y1)
                    .map_err(err)?;
                chart
                    .configure_mesh()
                    .x_desc(self.labels.x)
                    .y_desc(self.labels.y)
                    .axis_desc_style(style(13))
                    .label_style(style(12))
                    .light_line_style(WHITE)
                    .draw()
                    .map_err(err)?;
                self.lines(&mut chart)
            }
        })
    }

    /// The reference lines, the series and the legend, on either y scale.
    fn lines<'b, Y>(
        &self,
        chart: &mut ChartContext<
            'b,
            BitMapBackend<'b>,
            Cartesian2d<plotters::coord::types::RangedCoordf64, Y>,
        >,
    ) -> Result<(), String>
    where
        Y: plotters::coord::ranged1d::Ranged<ValueType = f64>,
    {
        let (x0, x1) = self.x_range;
        for &(y, colour, name) in self.hlines {
            let colour = rgb(colour);
            let dashes = (0..60).map(move |k| {
                let a = x0 + (x1 - x0) * k as f64 / 60.0;
                let b = a + (x1 - x0) * 0.6 / 60.0;
                PathElement::new(vec![(a, y), (b, y)], colour.stroke_width(2))
            });
            chart
                .draw_series(dashes)
                .map_err(err)?
                .label(name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 6, y)], colour.stroke_width(2))
                });
        }
        for s in self.series {
            let colour = rgb(s.color);
            let mut first = true;
            for run in self.runs(s) {
                let drawn = chart
                    .draw_series(LineSeries::new(run, colour.stroke_width(2)))
                    .map_err(err)?;
                if first {
                    drawn.label(s.name.as_str()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 14, y)], colour.stroke_width(2))
                    });
                    first = false;
                }
            }
        }
        chart
            .configure_series_labels()
            .position(self.legend.clone())
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font(style(12))
            .draw()
            .map_err(err)?;
        Ok(())
    }
}

/// Downscales linear RGBA pixels by an integer factor f = ⌈width / max_width⌉
/// with a box filter: each output pixel is the plain mean, in linear light,
/// of the f × f input pixels it covers (fewer at the right and bottom edges).
/// Returns the new size and pixels; f = 1 returns a copy.
pub fn box_downscale(
    width: u32,
    height: u32,
    pixels: &[[f32; 4]],
    max_width: u32,
) -> (u32, u32, Vec<[f32; 4]>) {
    let f = width.div_ceil(max_width.max(1)).max(1);
    let (ow, oh) = (width.div_ceil(f), height.div_ceil(f));
    let mut out = Vec::with_capacity(ow as usize * oh as usize);
    for oy in 0..oh {
        for ox in 0..ow {
            let mut sum = [0f64; 4];
            let mut n = 0f64;
            for y in oy * f..((oy + 1) * f).min(height) {
                for x in ox * f..((ox + 1) * f).min(width) {
                    let p = pixels[y as usize * width as usize + x as usize];
                    for c in 0..4 {
                        sum[c] += p[c] as f64;
                    }
                    n += 1.0;
                }
            }
            out.push(sum.map(|s| (s / n) as f32));
        }
    }
    (ow, oh, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The compiled-in font inflates to the file of the source tree.
    #[test]
    fn the_font_is_the_file() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf");
        assert!(font() == &std::fs::read(path).unwrap()[..]);
    }

    #[test]
    fn viridis_ends_and_order() {
        assert_eq!(viridis(0.0), [68, 1, 84]);
        assert_eq!(viridis(1.0), [253, 231, 37]);
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(0.5), [38, 130, 142]);
        assert_eq!(viridis(f64::NAN), LIGHT_RGB);
        // Green rises monotonically along the map.
        let mut g = 0;
        for i in 0..=100 {
            let c = viridis(i as f64 / 100.0);
            assert!(c[1] >= g);
            g = c[1];
        }
    }

    /// How many pixels of a canvas have exactly this colour.
    fn count(c: &Canvas, colour: [u8; 3]) -> usize {
        c.rgb.chunks_exact(3).filter(|p| *p == colour).count()
    }

    fn labels() -> Labels<'static> {
        Labels {
            title: "a title",
            x: "x (px)",
            y: "y (px)",
        }
    }

    #[test]
    fn heat_maps_colour_their_cells_and_draw_text() {
        let values = [0.0, 1.0, 0.5, f64::NAN];
        let map = HeatMap {
            labels: labels(),
            colorbar: "value",
            values: &values,
            x_edges: &[0.0, 100.0, 200.0],
            y_edges: &[0.0, 60.0, 90.0],
            range: (0.0, 1.0),
            marks: &[0.5],
            flagged: &[false, true, false, false],
            size: (520, 320),
        };
        let c = map.render().unwrap();
        assert_eq!((c.width, c.height), (520, 320));
        // Every cell's colour is there in quantity, the flagged frame too.
        for colour in [viridis(0.0), viridis(1.0), viridis(0.5), LIGHT_RGB, RED_RGB] {
            assert!(count(&c, colour) > 100, "{colour:?}: {}", count(&c, colour));
        }
        // Text is drawn: anti-aliased grey pixels that are neither the
        // background nor a map colour exist.
        assert!(c
            .rgb
            .chunks_exact(3)
            .any(|p| p[0] == p[1] && p[1] == p[2] && p[0] > 40 && p[0] < 200));
        assert_eq!(map.render().unwrap(), c, "the same bytes twice");
    }

    #[test]
    fn bar_charts_mark_the_limit_and_what_passes_it() {
        let groups = vec![vec![0.5, 1.1], vec![0.2, 0.3]];
        let rows = ["one".to_string(), "two".to_string()];
        let chart = BarChart {
            labels: labels(),
            rows: &rows,
            groups: &groups,
            bars: &[("slots", [1, 2, 3]), ("executed", [4, 5, 6])],
            max_fraction: 1.25,
            width: 600,
        };
        let c = chart.render().unwrap();
        assert!(count(&c, [1, 2, 3]) > 100);
        assert!(count(&c, [4, 5, 6]) > 100);
        assert!(
            count(&c, RED_RGB) > 50,
            "the limit line and the part past it"
        );
    }

    #[test]
    fn line_charts_draw_every_series() {
        let series = [
            Series {
                name: "up".into(),
                points: vec![(0.0, 1.0), (10.0, 100.0), (20.0, 1e9)],
                color: [1, 2, 3],
            },
            Series {
                name: "flat".into(),
                points: vec![(0.0, 10.0), (20.0, 10.0)],
                color: [4, 5, 6],
            },
        ];
        let chart = LineChart {
            labels: labels(),
            series: &series,
            x_range: (0.0, 20.0),
            y_range: (1.0, 1e4),
            log_y: true,
            hlines: &[(1000.0, [7, 8, 9], "a reference")],
            legend: SeriesLabelPosition::LowerRight,
            size: (500, 300),
        };
        let c = chart.render().unwrap();
        for colour in [[1, 2, 3], [4, 5, 6], [7, 8, 9]] {
            assert!(count(&c, colour) > 20, "{colour:?}");
        }
    }

    #[test]
    fn box_downscale_averages_in_linear_light() {
        // 5×3 image, max width 2: factor 3, output 2×1.
        let px: Vec<[f32; 4]> = (0..15).map(|i| [i as f32, 0.0, 0.0, 1.0]).collect();
        let (w, h, out) = box_downscale(5, 3, &px, 2);
        assert_eq!((w, h), (2, 1));
        // Columns 0..3 of rows 0..3: mean of 0,1,2,5,6,7,10,11,12 = 6.
        assert_eq!(out[0][0], 6.0);
        // Columns 3..5: 3,4,8,9,13,14 → 8.5.
        assert_eq!(out[1][0], 8.5);
        let (w, h, same) = box_downscale(5, 3, &px, 512);
        assert_eq!((w, h), (5, 3));
        assert_eq!(same, px);
    }
}
