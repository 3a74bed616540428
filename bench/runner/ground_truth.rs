//! The analytic ground truth of the checkerboard ground plane of `c_tests/tex_truth_plane.h`
//! (scenes `c_tests/tex_aniso.c` and `bench/scenes/filter_study.c`), and the error of a
//! rendered image against it.
//!
//! The truth of a pixel is the exact black/white checkerboard (no texels, no mipmaps)
//! averaged over the pixel's square, `n × n` jittered stratified samples per pixel, in
//! f64. Each sample's window position is mapped back onto the plane `y = 0` through the
//! exact inverse of the plane's projection: the 3×3 homography of viewport · frustum ·
//! modelview restricted to the plane, built in f64 from the same calls as
//! `sgl_ground_view` in `c_tests/tex_common.h`. A sample that lands outside the quad,
//! behind the camera or beyond the near/far planes does not count; a pixel is judged only
//! where every sample lands on the quad (full coverage), so the plane's silhouette (where
//! rasterisation, not filtering, decides) is left out.
//!
//! Included with `#[path]` by `tests/aniso_truth.rs` and `examples/bench.rs`.

use rayon::prelude::*;

/// Texture size in texels (square), `SGL_TRUTH_TEX`.
const TEX: f64 = 512.0;
/// Checker cell size in texels, `SGL_TRUTH_CELL`.
const CELL: f64 = 64.0;
/// World units per texture repeat, `SGL_TRUTH_PERIOD` (a C float).
const PERIOD: f32 = 3.7;
/// The quad's x extent, `sgl_ground_plane` (C floats).
const XS: [f32; 2] = [-120.3, 119.7];
/// The quad's z extent, near then far, `sgl_ground_plane` (C floats).
const ZS: [f32; 2] = [2.1, -250.9];
/// Near and far planes of `sgl_ground_view`.
const NEAR_FAR: [f64; 2] = [0.71, 300.0];

type M4 = [[f64; 4]; 4];
type M3 = [[f64; 3]; 3];

fn mul4(a: &M4, b: &M4) -> M4 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

fn mul3(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn inverse3(m: &M3) -> M3 {
    let c =
        |r0: usize, c0: usize, r1: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    let adj = [
        [c(1, 1, 2, 2), -c(0, 1, 2, 2), c(0, 1, 1, 2)],
        [-c(1, 0, 2, 2), c(0, 0, 2, 2), -c(0, 0, 1, 2)],
        [c(1, 0, 2, 1), -c(0, 0, 2, 1), c(0, 0, 1, 1)],
    ];
    let det = m[0][0] * adj[0][0] + m[0][1] * adj[1][0] + m[0][2] * adj[2][0];
    adj.map(|row| row.map(|v| v / det))
}

/// `glFrustum` (row-major, column vectors).
fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> M4 {
    [
        [2.0 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2.0 * n / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n)],
        [0.0, 0.0, -1.0, 0.0],
    ]
}

/// `glRotatef(deg, x, y, z)` with a unit axis.
fn rotate(deg: f32, axis: [f64; 3]) -> M4 {
    let a = (deg as f64).to_radians();
    let (s, c) = a.sin_cos();
    let [x, y, z] = axis;
    let k = 1.0 - c;
    [
        [x * x * k + c, x * y * k - z * s, x * z * k + y * s, 0.0],
        [y * x * k + z * s, y * y * k + c, y * z * k - x * s, 0.0],
        [x * z * k - y * s, y * z * k + x * s, z * z * k + c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// `glTranslatef(x, y, z)`.
fn translate(x: f32, y: f32, z: f32) -> M4 {
    [
        [1.0, 0.0, 0.0, x as f64],
        [0.0, 1.0, 0.0, y as f64],
        [0.0, 0.0, 1.0, z as f64],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// Projection · modelview of `sgl_ground_view(aspect)`.
fn ground_mvp(aspect: f64) -> M4 {
    let p = frustum(
        -0.53 * aspect,
        0.53 * aspect,
        -0.53,
        0.53,
        NEAR_FAR[0],
        NEAR_FAR[1],
    );
    let mv = mul4(
        &mul4(
            &rotate(7.3, [1.0, 0.0, 0.0]),
            &rotate(13.7, [0.0, 1.0, 0.0]),
        ),
        &translate(0.37, -1.13, 0.0),
    );
    mul4(&p, &mv)
}

/// The checkerboard's value (0 or 255) at world point (x, 0, z).
#[inline]
fn checker(x: f64, z: f64) -> f64 {
    let period = PERIOD as f64;
    let u = (x / period * TEX / CELL).floor() as i64;
    let v = (z / period * TEX / CELL).floor() as i64;
    if (u + v).rem_euclid(2) == 1 {
        255.0
    } else {
        0.0
    }
}

/// A 64-bit mix (splitmix64's finaliser) for reproducible per-sample jitter.
#[inline]
fn hash(mut x: u64) -> u64 {
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

/// The ground-truth image: grey level and plane coverage per pixel, rows from the bottom.
pub struct Truth {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Samples per pixel along each axis.
    pub samples: usize,
    /// Mean checkerboard value (0..=255) over the samples that land on the plane.
    pub value: Vec<f64>,
    /// Share of the pixel's samples that land on the plane, 0..=1.
    pub coverage: Vec<f64>,
}

/// Computes the truth of a `width × height` frame with `samples × samples` per pixel.
pub fn ground_truth(width: usize, height: usize, samples: usize) -> Truth {
    let mvp = ground_mvp(width as f64 / height as f64);
    // Plane point (X, Z, 1) → clip (x, y, w): columns 0, 2, 3 and rows 0, 1, 3 of the MVP.
    let g: M3 = [0, 1, 3].map(|r| [0, 2, 3].map(|c| mvp[r][c]));
    // Viewport (0, 0, width, height): window = size/2 · (ndc + 1), homogeneous.
    let (hw, hh) = (width as f64 / 2.0, height as f64 / 2.0);
    let vp: M3 = [[hw, 0.0, hw], [0.0, hh, hh], [0.0, 0.0, 1.0]];
    let inv = inverse3(&mul3(&vp, &g));
    let wrow = mvp[3];
    let (x0, x1) = (XS[0] as f64, XS[1] as f64);
    let (z1, z0) = (ZS[1] as f64, ZS[0] as f64);
    let n = samples.max(1);
    let mut value = vec![0.0; width * height];
    let mut coverage = vec![0.0; width * height];
    value
        .par_chunks_mut(width)
        .zip(coverage.par_chunks_mut(width))
        .enumerate()
        .for_each(|(py, (vrow, crow))| {
            for px in 0..width {
                let (mut sum, mut hits) = (0.0, 0usize);
                for k in 0..n * n {
                    let h = hash(((py * width + px) * n * n + k) as u64);
                    let jx = (h >> 11) as f64 / (1u64 << 53) as f64;
                    let jy = (hash(h) >> 11) as f64 / (1u64 << 53) as f64;
                    let wx = px as f64 + ((k % n) as f64 + jx) / n as f64;
                    let wy = py as f64 + ((k / n) as f64 + jy) / n as f64;
                    let a = inv[0][0] * wx + inv[0][1] * wy + inv[0][2];
                    let b = inv[1][0] * wx + inv[1][1] * wy + inv[1][2];
                    let c = inv[2][0] * wx + inv[2][1] * wy + inv[2][2];
                    let (x, z) = (a / c, b / c);
                    // clip w = eye distance along the view axis: within [near, far].
                    let w = wrow[0] * x + wrow[2] * z + wrow[3];
                    let on_plane = (NEAR_FAR[0]..=NEAR_FAR[1]).contains(&w)
                        && (x0..=x1).contains(&x)
                        && (z1..=z0).contains(&z);
                    if !on_plane {
                        continue;
                    }
                    sum += checker(x, z);
                    hits += 1;
                }
                vrow[px] = if hits > 0 { sum / hits as f64 } else { 0.0 };
                crow[px] = hits as f64 / (n * n) as f64;
            }
        });
    Truth {
        width,
        height,
        samples: n,
        value,
        coverage,
    }
}

/// The error of a rendered image against the truth, over the R, G and B channels of the
/// fully covered pixels, in 8-bit units.
#[derive(Clone, Copy, Debug)]
pub struct TruthError {
    /// Mean absolute error, 0..=255.
    pub mae: f64,
    /// Root mean square error, 0..=255.
    pub rmse: f64,
    /// Peak signal-to-noise ratio, `10·log10(255²/MSE)` dB.
    pub psnr: f64,
    /// How many pixels were judged.
    pub pixels: usize,
}

impl Truth {
    /// The error of an RGBA8 image of the truth's size, `rowbytes` per row; `y_up` when
    /// the first row in memory is the bottom row (OSMesa's default).
    pub fn error(&self, rgba: &[u8], rowbytes: usize, y_up: bool) -> TruthError {
        let (mut abs, mut sq, mut pixels) = (0.0, 0.0, 0usize);
        for y in 0..self.height {
            let row = if y_up { y } else { self.height - 1 - y };
            for x in 0..self.width {
                let i = y * self.width + x;
                if self.coverage[i] < 1.0 {
                    continue;
                }
                let px = &rgba[row * rowbytes + 4 * x..row * rowbytes + 4 * x + 3];
                for &c in px {
                    let d = c as f64 - self.value[i];
                    abs += d.abs();
                    sq += d * d;
                }
                pixels += 1;
            }
        }
        let n = (3 * pixels).max(1) as f64;
        let mse = sq / n;
        TruthError {
            mae: abs / n,
            rmse: mse.sqrt(),
            psnr: 10.0 * (255.0 * 255.0 / mse).log10(),
            pixels,
        }
    }

    /// The truth as an 8-bit grey image, top row first; uncovered pixels are dark red.
    pub fn to_rgb(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.width * self.height * 3);
        for y in (0..self.height).rev() {
            for x in 0..self.width {
                let i = y * self.width + x;
                if self.coverage[i] < 1.0 {
                    out.extend_from_slice(&[90, 0, 0]);
                } else {
                    let v = self.value[i].round().clamp(0.0, 255.0) as u8;
                    out.extend_from_slice(&[v, v, v]);
                }
            }
        }
        out
    }
}
