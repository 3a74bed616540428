//! The time-vs-error chart: a scatter plot drawn straight into an RGB image.
//!
//! No plotting crate and no installed font: text comes from `font.txt`, a 13 px
//! bitmap of DejaVu Sans with four coverage levels made once by `gen_font.py`.
//! The x axis is the median frame time on a log10 scale, the y axis the error
//! (100 − % identical pixels against llvmpipe with one thread) on a log scale
//! from 0.0001 % to 100 %, with 0 drawn on its own line below it. Each point is one (scene, size, renderer); its label is the
//! scene's short id and the size, placed greedily where it overlaps no other
//! label. [`draw_with`] takes another y axis (the filter study plots the mean absolute
//! error against a ground truth).

use image::{Rgb, RgbImage};

/// A logarithmic y axis: its label, its range, and whether 0 gets its own line below it.
pub struct YAxis {
    /// Text along the axis.
    pub label: String,
    /// Smallest value shown apart from 0: a power of ten.
    pub min: f64,
    /// Largest value shown: a power of ten.
    pub max: f64,
    /// Whether values ≤ 0 are drawn on their own line at the bottom.
    pub zero_line: bool,
}

/// The benchmark's y axis: % of pixels not identical to llvmpipe with one thread, from
/// 0.0001 % (about one pixel of a 1024x1024 frame) to 100 %, with 0 at the bottom.
pub fn percent_off_axis() -> YAxis {
    YAxis {
        label: "error: % of pixels not identical to llvmpipe, 1 thread (log scale; 0 at the \
                bottom)"
            .into(),
        min: 1e-4,
        max: 100.0,
        zero_line: true,
    }
}

/// One point of the chart.
pub struct Point {
    /// Median frame time in milliseconds (x, log scale); must be > 0.
    pub ms: f64,
    /// The error (y), in the unit of the chart's [`YAxis`]: percent of pixels not
    /// identical to the reference for [`draw`].
    pub error_pct: f64,
    /// Index into the series (renderer) list: decides colour and marker.
    pub series: usize,
    /// Whether the marker is drawn hollow (used for the larger size).
    pub hollow: bool,
    /// Text drawn beside the point.
    pub label: String,
}

/// A renderer's name and colour for the legend.
pub struct Series {
    /// Legend text.
    pub name: String,
    /// Marker colour.
    pub color: [u8; 3],
}

struct Font {
    height: i32,
    glyphs: Vec<(i32, Vec<Vec<u8>>)>,
}

impl Font {
    fn load() -> Font {
        let text = include_str!("font.txt");
        let mut height = 17;
        let mut glyphs: Vec<(i32, Vec<Vec<u8>>)> = Vec::new();
        for line in text.lines() {
            if let Some(rest) = line.strip_prefix("# ") {
                if let Some(h) = rest
                    .split("cell height ")
                    .nth(1)
                    .and_then(|s| s.split(',').next())
                    .and_then(|s| s.trim().parse().ok())
                {
                    height = h;
                }
            } else if let Some(rest) = line.strip_prefix("glyph ") {
                let adv = rest
                    .split_whitespace()
                    .nth(1)
                    .and_then(|s| s.parse().ok())
                    .unwrap_or(6);
                glyphs.push((adv, Vec::new()));
            } else if let Some(row) = line.strip_prefix('|') {
                let row = row.strip_suffix('|').unwrap_or(row);
                let levels = row
                    .bytes()
                    .map(|b| match b {
                        b'.' => 85,
                        b'+' => 170,
                        b'#' => 255,
                        _ => 0,
                    })
                    .collect();
                if let Some(g) = glyphs.last_mut() {
                    g.1.push(levels);
                }
            }
        }
        Font { height, glyphs }
    }

    fn glyph(&self, c: char) -> Option<&(i32, Vec<Vec<u8>>)> {
        let i = (c as u32).checked_sub(32)? as usize;
        self.glyphs
            .get(i)
            .or_else(|| self.glyphs.get(('?' as usize) - 32))
    }

    fn width(&self, s: &str) -> i32 {
        s.chars().filter_map(|c| self.glyph(c)).map(|g| g.0).sum()
    }
}

struct Canvas {
    img: RgbImage,
    font: Font,
}

impl Canvas {
    fn put(&mut self, x: i32, y: i32, c: [u8; 3], alpha: u8) {
        if x < 0 || y < 0 || x >= self.img.width() as i32 || y >= self.img.height() as i32 {
            return;
        }
        let p = self.img.get_pixel_mut(x as u32, y as u32);
        let a = alpha as u32;
        for (d, s) in p.0.iter_mut().zip(c) {
            *d = ((s as u32 * a + *d as u32 * (255 - a) + 127) / 255) as u8;
        }
    }

    fn rect(&mut self, x0: i32, y0: i32, x1: i32, y1: i32, c: [u8; 3]) {
        for y in y0..=y1 {
            for x in x0..=x1 {
                self.put(x, y, c, 255);
            }
        }
    }

    fn hline(&mut self, x0: i32, x1: i32, y: i32, c: [u8; 3]) {
        self.rect(x0, y, x1, y, c);
    }

    fn vline(&mut self, x: i32, y0: i32, y1: i32, c: [u8; 3]) {
        self.rect(x, y0, x, y1, c);
    }

    /// Draws `s` with its top-left corner at (x, y), `scale` times enlarged.
    fn text(&mut self, x: i32, y: i32, s: &str, c: [u8; 3], scale: i32) {
        let mut pen = x;
        for ch in s.chars() {
            let Some((adv, rows)) = self.font.glyph(ch).cloned() else {
                continue;
            };
            for (gy, row) in rows.iter().enumerate() {
                for (gx, &a) in row.iter().enumerate() {
                    if a == 0 {
                        continue;
                    }
                    for sy in 0..scale {
                        for sx in 0..scale {
                            self.put(
                                pen + gx as i32 * scale + sx,
                                y + gy as i32 * scale + sy,
                                c,
                                a,
                            );
                        }
                    }
                }
            }
            pen += adv * scale;
        }
    }

    /// Draws `s` rotated 90° counter-clockwise, reading bottom to top, its
    /// baseline-left corner at (x, y).
    fn text_vertical(&mut self, x: i32, y: i32, s: &str, c: [u8; 3]) {
        let mut pen = y;
        for ch in s.chars() {
            let Some((adv, rows)) = self.font.glyph(ch).cloned() else {
                continue;
            };
            for (gy, row) in rows.iter().enumerate() {
                for (gx, &a) in row.iter().enumerate() {
                    if a != 0 {
                        self.put(x + gy as i32, pen - gx as i32, c, a);
                    }
                }
            }
            pen -= adv;
        }
    }

    fn marker(&mut self, cx: i32, cy: i32, series: usize, hollow: bool, c: [u8; 3]) {
        let r = 5i32;
        for dy in -r..=r {
            for dx in -r..=r {
                let (inside, edge) = match series % 3 {
                    // Circle.
                    0 => {
                        let d2 = dx * dx + dy * dy;
                        (d2 <= r * r, d2 >= (r - 1) * (r - 1))
                    }
                    // Square.
                    1 => (true, dx.abs() == r || dy.abs() == r),
                    // Triangle, point up.
                    _ => {
                        let half = (dy + r) / 2;
                        (dx.abs() <= half, dx.abs() >= half - 1 || dy == r)
                    }
                };
                if inside && (!hollow || edge) {
                    self.put(cx + dx, cy + dy, c, 255);
                }
            }
        }
    }
}

/// Renders the benchmark chart (y: [`percent_off_axis`]) as a 1500x950 image.
pub fn draw(title: &str, series: &[Series], points: &[Point], legend: &[String]) -> RgbImage {
    draw_with(title, series, points, legend, &percent_off_axis(), true)
}

/// Renders a chart with the y axis `y`; `size_legend` adds the filled/hollow size legend.
pub fn draw_with(
    title: &str,
    series: &[Series],
    points: &[Point],
    legend: &[String],
    y: &YAxis,
    size_legend: bool,
) -> RgbImage {
    let (width, height) = (1500i32, 950i32);
    let mut cv = Canvas {
        img: RgbImage::from_pixel(width as u32, height as u32, Rgb([255, 255, 255])),
        font: Font::load(),
    };
    let fh = cv.font.height;
    let black = [0, 0, 0];
    let grid = [225, 225, 225];
    let grid_major = [190, 190, 190];
    let (left, top, right, bottom) = (90, 60, width - 330, height - 70);

    // x range: whole decades around the data.
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in points.iter().filter(|p| p.ms > 0.0 && p.ms.is_finite()) {
        lo = lo.min(p.ms.log10());
        hi = hi.max(p.ms.log10());
    }
    if !lo.is_finite() {
        (lo, hi) = (-1.0, 2.0);
    }
    let (lo, hi) = (lo.floor(), hi.ceil().max(lo.floor() + 1.0));
    let xs = |ms: f64| left + ((ms.log10() - lo) / (hi - lo) * (right - left) as f64) as i32;
    // y: optionally 0 on its own line at the bottom, then log10 from y.min to y.max.
    let zero_gap = if y.zero_line { 36 } else { 0 };
    let (ylo, yhi) = (y.min.log10().round() as i32, y.max.log10().round() as i32);
    let ys = |e: f64| {
        if e <= 0.0 || !e.is_finite() {
            return bottom;
        }
        let t = (e.clamp(y.min, y.max).log10() - ylo as f64) / (yhi - ylo).max(1) as f64;
        bottom - zero_gap - (t * (bottom - zero_gap - top) as f64) as i32
    };

    // Grid and ticks.
    for decade in lo as i32..=hi as i32 {
        for m in 1..10 {
            let v = 10f64.powi(decade) * m as f64;
            if v.log10() > hi + 1e-9 {
                break;
            }
            let x = xs(v);
            cv.vline(x, top, bottom, if m == 1 { grid_major } else { grid });
            if m == 1 || m == 2 || m == 5 {
                let s = fmt_tick(v);
                let w = cv.font.width(&s);
                cv.text(x - w / 2, bottom + 6, &s, black, 1);
            }
        }
    }
    let decades = (ylo..=yhi).map(|d| {
        if d < 0 {
            format!("0.{}1", "0".repeat((-d - 1) as usize))
        } else {
            format!("1{}", "0".repeat(d as usize))
        }
    });
    let zero = y.zero_line.then(|| "0".to_owned());
    for e in zero.into_iter().chain(decades) {
        let yy = ys(e.parse().unwrap_or(0.0));
        cv.hline(left, right, yy, grid_major);
        let w = cv.font.width(&e);
        cv.text(left - 8 - w, yy - fh / 2 - 2, &e, black, 1);
    }
    for decade in ylo..yhi {
        for m in 2..10 {
            let yy = ys(10f64.powi(decade) * m as f64);
            cv.hline(left, right, yy, grid);
        }
    }
    cv.hline(left, right, bottom, black);
    cv.vline(left, top, bottom, black);

    // Titles.
    cv.text(left, 14, title, black, 2);
    let xl = "median frame time, ms (log scale)";
    let w = cv.font.width(xl);
    cv.text((left + right) / 2 - w / 2, bottom + 30, xl, black, 1);
    let w = cv.font.width(&y.label);
    cv.text_vertical(18, (top + bottom) / 2 + w / 2, &y.label, black);

    // Points first, then labels placed greedily so they do not overlap.
    let mut taken: Vec<(i32, i32, i32, i32)> = Vec::new();
    for p in points.iter().filter(|p| p.ms > 0.0 && p.ms.is_finite()) {
        let (x, y) = (xs(p.ms), ys(p.error_pct));
        taken.push((x - 6, y - 6, x + 6, y + 6));
        let c = series.get(p.series).map_or(black, |s| s.color);
        cv.marker(x, y, p.series, p.hollow, c);
    }
    for p in points.iter().filter(|p| p.ms > 0.0 && p.ms.is_finite()) {
        let (x, y) = (xs(p.ms), ys(p.error_pct));
        let w = cv.font.width(&p.label);
        let c = series.get(p.series).map_or(black, |s| s.color);
        let dark = [c[0] / 2, c[1] / 2, c[2] / 2];
        let mut placed = None;
        'search: for step in 0..60 {
            let dy = (step / 2) * (fh - 5) * if step % 2 == 0 { -1 } else { 1 };
            for dx in [8, -8 - w] {
                let bx = x + dx;
                let by = y - fh / 2 - 1 + dy;
                let b = (bx, by + 3, bx + w, by + fh - 4);
                let inside = b.0 >= left && b.2 <= right && b.1 >= top - 20 && b.3 <= bottom;
                let free = taken
                    .iter()
                    .all(|t| b.2 < t.0 || b.0 > t.2 || b.3 < t.1 || b.1 > t.3);
                if inside && free {
                    placed = Some((bx, by, b));
                    break 'search;
                }
            }
        }
        if let Some((bx, by, b)) = placed {
            if (by + fh / 2 - y).abs() > fh / 2 {
                // Leader line from the marker to a displaced label.
                let lx = if bx > x { bx - 1 } else { bx + w + 1 };
                draw_line(&mut cv, x, y, lx, by + fh / 2, [150, 150, 150]);
            }
            cv.text(bx, by, &p.label, dark, 1);
            taken.push(b);
        }
    }

    // Legend: renderers, sizes, then the scene ids.
    let lx = right + 20;
    let mut ly = top;
    cv.text(lx, ly, "renderer", black, 1);
    ly += fh + 4;
    for (i, s) in series.iter().enumerate() {
        cv.marker(lx + 6, ly + fh / 2, i, false, s.color);
        cv.text(lx + 18, ly, &s.name, black, 1);
        ly += fh + 2;
    }
    ly += 8;
    if size_legend {
        cv.marker(lx + 6, ly + fh / 2, 0, false, [90, 90, 90]);
        cv.text(lx + 18, ly, "filled: smaller size", black, 1);
        ly += fh + 2;
        cv.marker(lx + 6, ly + fh / 2, 0, true, [90, 90, 90]);
        cv.text(lx + 18, ly, "hollow: larger size", black, 1);
        ly += fh + 12;
        cv.text(lx, ly, "scenes", black, 1);
        ly += fh + 4;
    }
    for line in legend {
        cv.text(lx, ly, line, black, 1);
        ly += fh;
    }
    cv.img
}

fn draw_line(cv: &mut Canvas, x0: i32, y0: i32, x1: i32, y1: i32, c: [u8; 3]) {
    let n = (x1 - x0).abs().max((y1 - y0).abs()).max(1);
    for i in 0..=n {
        let x = x0 + (x1 - x0) * i / n;
        let y = y0 + (y1 - y0) * i / n;
        cv.put(x, y, c, 255);
    }
}

fn fmt_tick(v: f64) -> String {
    if v >= 1.0 {
        format!("{}", v.round() as i64)
    } else {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').to_owned()
    }
}
