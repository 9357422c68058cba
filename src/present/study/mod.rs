//! What `ps30 study` prints and writes: for each study a text summary, its
//! JSON, and a report page (Markdown) with its figures. Every number comes
//! from a study's result ([`crate::jobs::studies`]); figures go data →
//! chart spec ([`crate::present::report::figures`]) → raster.

pub mod article_chain;
pub mod log_lights;
pub mod mip_luminance;

use crate::present::report::figures::Canvas;

/// A report page and the figures it shows, ready to be written: the page
/// as `reports/NAME`, each figure as `reports/figures/FILE`.
pub struct Page {
    /// The page's file name (`log-lights.md`).
    pub name: String,
    /// The page.
    pub markdown: String,
    /// Its figures: file names under `figures/`, and the images.
    pub figures: Vec<(String, Canvas)>,
}

/// A Markdown table from a header and rows.
pub(crate) fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!(
        "| {} |\n|{}\n",
        header.join(" | "),
        "---|".repeat(header.len())
    );
    for r in rows {
        s.push_str(&format!("| {} |\n", r.join(" | ")));
    }
    s
}

/// A plain-text table: columns padded, numbers right-aligned (every column
/// but those in `left`).
pub(crate) fn text_table(header: &[&str], rows: &[Vec<String>], left: &[usize]) -> String {
    let mut all: Vec<Vec<String>> = vec![header.iter().map(|h| h.to_string()).collect()];
    all.extend(rows.iter().cloned());
    let widths: Vec<usize> = (0..header.len())
        .map(|i| all.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    let mut s = String::new();
    for r in &all {
        let mut line = String::new();
        for (i, cell) in r.iter().enumerate() {
            let pad = " ".repeat(widths[i] - cell.chars().count());
            if i > 0 {
                line.push_str("  ");
            }
            if left.contains(&i) {
                line.push_str(cell);
                line.push_str(&pad);
            } else {
                line.push_str(&pad);
                line.push_str(cell);
            }
        }
        s.push_str(line.trim_end());
        s.push('\n');
    }
    s
}

/// A percentage with a sign and two decimals: `+5.71 %`.
pub(crate) fn percent(v: f64) -> String {
    format!("{:+.2} %", 100.0 * v)
}
