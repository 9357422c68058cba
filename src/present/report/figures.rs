//! Figures for `reports/`: a tiny deterministic rasteriser that draws heat
//! maps, bar charts, line charts and downscaled previews into 8-bit RGB
//! canvases and leaves them to be encoded as PNG
//! ([`crate::core::image::encode_png_rgb8`]).
//!
//! Everything is integer pixel arithmetic or plain f64 with a fixed order,
//! so the same inputs give the same bytes on every run and for every thread
//! count. Text labels are not rasterised: the Markdown around each figure
//! carries them, and each figure's caption gives its value range.

/// An RGB image with 8-bit channels, row-major, top row first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Canvas {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

pub const WHITE: [u8; 3] = [255, 255, 255];
pub const BLACK: [u8; 3] = [0, 0, 0];
pub const GRID: [u8; 3] = [32, 32, 32];
pub const LIGHT: [u8; 3] = [200, 200, 200];
pub const RED: [u8; 3] = [214, 39, 40];

impl Canvas {
    pub fn new(width: u32, height: u32, background: [u8; 3]) -> Canvas {
        let n = width as usize * height as usize;
        Canvas {
            width,
            height,
            rgb: background.repeat(n),
        }
    }

    /// Sets one pixel; pixels outside the canvas are ignored.
    pub fn put(&mut self, x: i64, y: i64, c: [u8; 3]) {
        if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
            return;
        }
        let i = (y as usize * self.width as usize + x as usize) * 3;
        self.rgb[i..i + 3].copy_from_slice(&c);
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

    /// Fills the rectangle [x0, x0 + w) × [y0, y0 + h), clipped.
    pub fn fill(&mut self, x0: i64, y0: i64, w: i64, h: i64, c: [u8; 3]) {
        for y in y0.max(0)..(y0 + h).min(self.height as i64) {
            for x in x0.max(0)..(x0 + w).min(self.width as i64) {
                self.put(x, y, c);
            }
        }
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
        return LIGHT;
    }
    let t = t.clamp(0.0, 1.0) * 8.0;
    let i = (t.floor() as usize).min(7);
    let f = t - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    std::array::from_fn(|c| (a[c] as f64 + (b[c] as f64 - a[c] as f64) * f).round() as u8)
}

/// A heat map over a grid of cells whose pixel boundaries are given, so the
/// cells keep the geometry of what they summarise (a block of an image
/// becomes a rectangle of the block's shape; partial edge blocks are
/// narrower). `values` are row-major, `x_edges.len() - 1` per row.
#[derive(Clone, Debug)]
pub struct HeatMap<'a> {
    pub values: &'a [f64],
    /// Pixel x of each cell boundary, increasing, starting at 0.
    pub x_edges: &'a [u32],
    /// Pixel y of each cell boundary, increasing, starting at 0.
    pub y_edges: &'a [u32],
    /// The values mapped to the two ends of the colour map.
    pub range: (f64, f64),
    /// Values to mark with a tick under the legend (besides both ends).
    pub marks: &'a [f64],
    /// Cells to outline in red (e.g. beyond a bound); empty for none.
    pub flagged: &'a [bool],
}

/// Height of the legend strip under a heat map: gap, gradient, ticks.
const LEGEND_GAP: u32 = 6;
const LEGEND_BAR: u32 = 14;
const LEGEND_TICKS: u32 = 7;

impl HeatMap<'_> {
    /// Draws the map, 1-pixel grid lines on the cell boundaries, and a
    /// legend row under it: the colour map from `range.0` (left) to
    /// `range.1` (right) with ticks at both ends and at each mark.
    pub fn render(&self) -> Canvas {
        let nx = self.x_edges.len().saturating_sub(1);
        let ny = self.y_edges.len().saturating_sub(1);
        let w = self.x_edges.last().copied().unwrap_or(0).max(1);
        let h = self.y_edges.last().copied().unwrap_or(0);
        let mut c = Canvas::new(w, h + LEGEND_GAP + LEGEND_BAR + LEGEND_TICKS, WHITE);
        let (lo, hi) = self.range;
        let t = |v: f64| {
            if hi > lo {
                (v - lo) / (hi - lo)
            } else {
                0.5
            }
        };
        for cy in 0..ny {
            for cx in 0..nx {
                let v = self.values.get(cy * nx + cx).copied().unwrap_or(f64::NAN);
                let (x0, x1) = (self.x_edges[cx] as i64, self.x_edges[cx + 1] as i64);
                let (y0, y1) = (self.y_edges[cy] as i64, self.y_edges[cy + 1] as i64);
                c.fill(x0, y0, x1 - x0, y1 - y0, viridis(t(v)));
            }
        }
        for cy in 0..ny {
            for cx in 0..nx {
                if !self.flagged.get(cy * nx + cx).copied().unwrap_or(false) {
                    continue;
                }
                let (x0, x1) = (self.x_edges[cx] as i64, self.x_edges[cx + 1] as i64);
                let (y0, y1) = (self.y_edges[cy] as i64, self.y_edges[cy + 1] as i64);
                // A 2-pixel red frame inside the cell's grid lines.
                c.fill(x0 + 1, y0 + 1, x1 - x0 - 1, 2, RED);
                c.fill(x0 + 1, y1 - 2, x1 - x0 - 1, 2, RED);
                c.fill(x0 + 1, y0 + 1, 2, y1 - y0 - 1, RED);
                c.fill(x1 - 2, y0 + 1, 2, y1 - y0 - 1, RED);
            }
        }
        for &x in self.x_edges {
            let x = (x as i64).min(w as i64 - 1);
            c.fill(x, 0, 1, h as i64, GRID);
        }
        for &y in self.y_edges {
            let y = (y as i64).min(h as i64 - 1);
            c.fill(0, y, w as i64, 1, GRID);
        }
        let top = (h + LEGEND_GAP) as i64;
        for x in 0..w {
            let f = if w > 1 {
                x as f64 / (w - 1) as f64
            } else {
                0.5
            };
            c.fill(x as i64, top, 1, LEGEND_BAR as i64, viridis(f));
        }
        let tick = |c: &mut Canvas, x: i64| {
            c.fill(x, top + LEGEND_BAR as i64, 1, LEGEND_TICKS as i64, BLACK);
        };
        tick(&mut c, 0);
        tick(&mut c, w as i64 - 1);
        for &m in self.marks {
            let f = t(m);
            if (0.0..=1.0).contains(&f) {
                tick(&mut c, (f * (w - 1) as f64).round() as i64);
            }
        }
        c
    }
}

/// A horizontal bar chart of fractions of a limit: one group of bars per
/// row (e.g. slots and executed instructions of one shader), an axis with
/// ticks every 25 % and a red line at 100 % (the limit). A bar beyond the
/// limit turns red past the line.
#[derive(Clone, Debug)]
pub struct BarChart<'a> {
    /// Each group's bars, as fractions of the limit.
    pub groups: &'a [Vec<f64>],
    /// One colour per bar position in a group.
    pub colors: &'a [[u8; 3]],
    /// The fraction at the right end of the axis (≥ 1).
    pub max_fraction: f64,
    /// Pixels from 0 to `max_fraction`.
    pub plot_width: u32,
}

const BAR: i64 = 12;
const BAR_GAP: i64 = 2;
const GROUP_GAP: i64 = 12;
const MARGIN: i64 = 12;
const AXIS: i64 = 14;

impl BarChart<'_> {
    /// The pixel length of a fraction.
    fn x_of(&self, f: f64) -> i64 {
        (f / self.max_fraction * self.plot_width as f64).round() as i64
    }

    pub fn render(&self) -> Canvas {
        let bars: i64 = self.groups.iter().map(|g| g.len() as i64).sum();
        let groups = self.groups.len() as i64;
        let plot_h = bars * BAR
            + self
                .groups
                .iter()
                .map(|g| (g.len() as i64 - 1).max(0) * BAR_GAP)
                .sum::<i64>()
            + (groups + 1) * GROUP_GAP;
        let w = 2 * MARGIN + self.plot_width as i64 + 1;
        let h = 2 * MARGIN + plot_h + AXIS;
        let mut c = Canvas::new(w as u32, h as u32, WHITE);
        let (left, top) = (MARGIN, MARGIN);
        let limit = left + self.x_of(1.0);
        // Light guides every 25 %, the limit line in red.
        let mut f = 0.25;
        while f <= self.max_fraction + 1e-9 {
            c.fill(left + self.x_of(f), top, 1, plot_h, LIGHT);
            f += 0.25;
        }
        let mut y = top + GROUP_GAP;
        for g in self.groups {
            for (i, &v) in g.iter().enumerate() {
                let color = self.colors[i % self.colors.len().max(1)];
                let len = self.x_of(v.clamp(0.0, self.max_fraction));
                c.fill(left + 1, y, len, BAR, color);
                if v > 1.0 {
                    c.fill(limit + 1, y, left + 1 + len - limit - 1, BAR, RED);
                }
                y += BAR + BAR_GAP;
            }
            y += GROUP_GAP - BAR_GAP;
        }
        c.fill(limit, top, 1, plot_h, RED);
        // Axes: left edge and bottom, ticks every 25 % (longer at 0, 100 %).
        c.fill(left, top, 1, plot_h + 1, BLACK);
        c.fill(left, top + plot_h, self.plot_width as i64 + 1, 1, BLACK);
        let mut k = 0;
        loop {
            let f = k as f64 * 0.25;
            if f > self.max_fraction + 1e-9 {
                break;
            }
            let long = k % 4 == 0;
            c.fill(
                left + self.x_of(f),
                top + plot_h + 1,
                1,
                if long { AXIS - 4 } else { AXIS / 2 },
                BLACK,
            );
            k += 1;
        }
        c
    }
}

/// One line of a [`LineChart`]: points in data units, joined in order. A
/// point with a non-finite coordinate breaks the line.
#[derive(Clone, Debug)]
pub struct Series {
    pub points: Vec<(f64, f64)>,
    pub color: [u8; 3],
}

/// A line chart: series over an x range and a y range (linear or log10),
/// light guides at the given ticks, optional horizontal reference lines,
/// and axes. Values beyond the y range are drawn at its edge (clipped, not
/// dropped), so a curve that leaves the chart is seen to leave it. Labels
/// are the page's business (see the module docs).
#[derive(Clone, Debug)]
pub struct LineChart<'a> {
    pub series: &'a [Series],
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
    /// Plot y as log10 (y_range and y_ticks then must be positive).
    pub log_y: bool,
    /// Plot area in pixels (without margins).
    pub width: u32,
    pub height: u32,
    pub x_ticks: &'a [f64],
    pub y_ticks: &'a [f64],
    /// Dashed horizontal lines at these y values.
    pub hlines: &'a [(f64, [u8; 3])],
}

impl LineChart<'_> {
    fn px(&self, x: f64) -> f64 {
        let (a, b) = self.x_range;
        MARGIN as f64 + (x - a) / (b - a) * self.width as f64
    }

    /// The pixel row of `y`, clamped to the plot; `None` for NaN.
    fn py(&self, y: f64) -> Option<f64> {
        let (a, b) = self.y_range;
        let t = if self.log_y {
            if y.is_nan() {
                return None;
            }
            let y = if y > 0.0 {
                y.log10()
            } else {
                f64::NEG_INFINITY
            };
            (y - a.log10()) / (b.log10() - a.log10())
        } else {
            if y.is_nan() {
                return None;
            }
            (y - a) / (b - a)
        };
        let t = t.clamp(0.0, 1.0);
        Some(MARGIN as f64 + (1.0 - t) * self.height as f64)
    }

    pub fn render(&self) -> Canvas {
        let w = self.width as i64 + 2 * MARGIN + 1;
        let h = self.height as i64 + 2 * MARGIN + AXIS;
        let mut c = Canvas::new(w as u32, h as u32, WHITE);
        let (left, top) = (MARGIN, MARGIN);
        let bottom = top + self.height as i64;
        for &x in self.x_ticks {
            let px = self.px(x).round() as i64;
            c.fill(px, top, 1, self.height as i64, LIGHT);
            c.fill(px, bottom + 1, 1, AXIS / 2, BLACK);
        }
        for &y in self.y_ticks {
            if let Some(py) = self.py(y) {
                let py = py.round() as i64;
                c.fill(left, py, self.width as i64, 1, LIGHT);
                c.fill(left - AXIS / 2, py, AXIS / 2, 1, BLACK);
            }
        }
        for &(y, color) in self.hlines {
            if let Some(py) = self.py(y) {
                let py = py.round() as i64;
                let mut x = left;
                while x < left + self.width as i64 {
                    c.fill(x, py, 6, 1, color);
                    x += 10;
                }
            }
        }
        for s in self.series {
            let mut last: Option<(f64, f64)> = None;
            for &(x, y) in &s.points {
                let p = if x.is_finite() {
                    self.py(y).map(|py| (self.px(x), py))
                } else {
                    None
                };
                if let (Some(a), Some(b)) = (last, p) {
                    segment(&mut c, a, b, s.color);
                }
                last = p;
            }
        }
        c.fill(left, top, 1, self.height as i64 + 1, BLACK);
        c.fill(left, bottom, self.width as i64 + 1, 1, BLACK);
        c
    }
}

/// A 2-pixel-wide line from `a` to `b` (pixel coordinates), one dot per
/// step of the longer axis.
fn segment(c: &mut Canvas, a: (f64, f64), b: (f64, f64), color: [u8; 3]) {
    let steps = (b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil().max(1.0) as i64;
    for i in 0..=steps {
        let t = i as f64 / steps as f64;
        let x = (a.0 + (b.0 - a.0) * t).round() as i64;
        let y = (a.1 + (b.1 - a.1) * t).round() as i64;
        c.fill(x, y, 2, 2, color);
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

    #[test]
    fn viridis_ends_and_order() {
        assert_eq!(viridis(0.0), [68, 1, 84]);
        assert_eq!(viridis(1.0), [253, 231, 37]);
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(0.5), [38, 130, 142]);
        assert_eq!(viridis(f64::NAN), LIGHT);
        // Green rises monotonically along the map.
        let mut g = 0;
        for i in 0..=100 {
            let c = viridis(i as f64 / 100.0);
            assert!(c[1] >= g);
            g = c[1];
        }
    }

    #[test]
    fn heat_map_cells_keep_their_geometry() {
        let values = [0.0, 1.0, 0.5, f64::NAN];
        let map = HeatMap {
            values: &values,
            x_edges: &[0, 10, 20],
            y_edges: &[0, 6, 9],
            range: (0.0, 1.0),
            marks: &[0.5],
            flagged: &[false, true, false, false],
        };
        let c = map.render();
        assert_eq!((c.width, c.height), (20, 9 + 6 + 14 + 7));
        assert_eq!(c.get(5, 3), viridis(0.0));
        assert_eq!(c.get(15, 3), viridis(1.0), "inside the frame");
        assert_eq!(c.get(11, 3), RED, "the flagged cell's frame");
        assert_eq!(c.get(15, 1), RED);
        assert_eq!(c.get(5, 7), viridis(0.5));
        assert_eq!(c.get(15, 7), LIGHT);
        assert_eq!(c.get(10, 3), GRID, "boundary column");
        // Legend: gradient, and a tick under the middle.
        assert_eq!(c.get(0, 9 + 6), viridis(0.0));
        assert_eq!(c.get(19, 9 + 6), viridis(1.0));
        assert_eq!(c.get(10, 9 + 6 + 14), BLACK);
    }

    #[test]
    fn bars_are_as_long_as_their_fraction_and_red_past_the_limit() {
        let groups = vec![vec![0.5, 1.1]];
        let chart = BarChart {
            groups: &groups,
            colors: &[[1, 2, 3], [4, 5, 6]],
            max_fraction: 1.25,
            plot_width: 500,
        };
        let c = chart.render();
        let y0 = (MARGIN + GROUP_GAP + 1) as u32;
        let left = MARGIN as u32;
        // 0.5 of the limit = 200 px of 500 for 1.25.
        assert_eq!(c.get(left + 200, y0), [1, 2, 3]);
        assert_ne!(c.get(left + 202, y0), [1, 2, 3]);
        let y1 = y0 + (BAR + BAR_GAP) as u32;
        assert_eq!(c.get(left + 300, y1), [4, 5, 6]);
        assert_eq!(c.get(left + 420, y1), RED, "beyond 100 % (400 px)");
        assert_eq!(c.get(left + 440, y1), RED);
        assert_ne!(c.get(left + 442, y1), RED);
    }

    #[test]
    fn line_charts_put_points_where_their_values_are_and_clip_the_rest() {
        let series = [Series {
            points: vec![(0.0, 1.0), (10.0, 100.0), (20.0, 1e9)],
            color: [1, 2, 3],
        }];
        let chart = LineChart {
            series: &series,
            x_range: (0.0, 20.0),
            y_range: (1.0, 1e4),
            log_y: true,
            width: 200,
            height: 100,
            x_ticks: &[10.0],
            y_ticks: &[100.0],
            hlines: &[],
        };
        let c = chart.render();
        let (left, top) = (MARGIN as u32, MARGIN as u32);
        // (10, 100): x at 100 px, y half-way up the 4 decades: 50 px.
        assert_eq!(c.get(left + 100, top + 50), [1, 2, 3]);
        // (0, 1) sits on the bottom axis corner; 1e9 is clipped to the top.
        assert_eq!(c.get(left + 200, top), [1, 2, 3]);
        // The guide at y = 100 away from the line, and the axis.
        assert_eq!(c.get(left + 20, top + 50), LIGHT);
        assert_eq!(c.get(left, top + 10), BLACK);
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
