//! Triangle setup: snapping to 1/256 pixel, orientation and culling, exact integer edge
//! functions with llvmpipe's fill rule, and float plane equations for the attributes.
//!
//! Numbers (docs/llvmpipe-rules.md §6–§7): a window position is snapped as
//! `round_half_even(256 * f32(x - 0.5))`, so integer coordinate 256·p is the centre of
//! pixel p. Edge functions are 64-bit integers; a pixel exactly on an edge belongs to the
//! triangle only for left edges and bottom edges (in GL's y-up sense). Plane equations are
//! computed in f32 from the unsnapped positions, in Mesa's operation order, and give the
//! value at pixel (0,0)'s centre plus per-pixel steps.

use super::ClipVertex;

/// Sub-pixel bits of the snapped positions.
pub const SUBPIXEL_BITS: u32 = 8;

/// llvmpipe's 4x sample positions in 1/256 pixel (`lp_sample_pos_4x` scaled and rounded,
/// `lp_scene.c`), in the framebuffer's memory rows (an object's rows are GL's): sample s
/// of pixel (px, py) is at `(256·px + SAMPLE_POS[s][0], 256·py + SAMPLE_POS[s][1])`, i.e.
/// (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875) of the pixel.
pub const SAMPLE_POS: [[i64; 2]; 4] = [[96, 32], [224, 96], [32, 160], [160, 224]];
const ONE: i64 = 1 << SUBPIXEL_BITS;

/// A linear function of the pixel position: `a0 + dadx * px + dady * py`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    /// Value at pixel (0,0)'s centre.
    pub a0: f32,
    /// Step per pixel in x.
    pub dadx: f32,
    /// Step per pixel in y (y-down).
    pub dady: f32,
}

/// One integer edge function: inside where `c - a*256*px + b*256*py > 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Edge {
    /// y_i - y_{i+1} (snapped).
    pub a: i64,
    /// x_i - x_{i+1} (snapped).
    pub b: i64,
    /// Constant term including the fill-rule bias.
    pub c: i64,
}

impl Edge {
    /// The edge of sample `s` of [`SAMPLE_POS`] from the edge of test point (0, 0) (the
    /// pixel's corner) of a multisample set-up ([`setup_triangle_samples`]).
    #[inline(always)]
    pub fn at_sample(self, s: usize) -> Edge {
        let [sx, sy] = SAMPLE_POS[s];
        Edge {
            c: self.c - self.a * sx + self.b * sy,
            ..self
        }
    }

    /// The range of pixel x on row `py` where this edge is positive, as (min, max) with
    /// `i64::MIN`/`i64::MAX` for "unbounded"; `None` when no pixel on the row qualifies.
    #[inline]
    pub fn span(&self, py: i64) -> Option<(i64, i64)> {
        let e = self.c + self.b * ONE * py;
        let s = self.a * ONE;
        if s > 0 {
            Some((i64::MIN, (e - 1).div_euclid(s)))
        } else if s < 0 {
            Some(((-e).div_euclid(-s) + 1, i64::MAX))
        } else if e > 0 {
            Some((i64::MIN, i64::MAX))
        } else {
            None
        }
    }
}

/// Boxes at most this many pixels wide find a row's span by testing each pixel of the row
/// (three integer steps per pixel) instead of three 64-bit divisions.
pub const NARROW: i64 = 4;

impl SetupTriangle {
    /// Stores the provoking vertex's varyings for flat shading: `v(i)` for the first
    /// `nvary`, and its colour (`v(0..4)`, which must be valid) as 8-bit values.
    #[inline(always)]
    pub fn set_flat(&mut self, nvary: usize, v: impl Fn(usize) -> f32) {
        for (i, f) in self.flat[..nvary].iter_mut().enumerate() {
            *f = v(i);
        }
        let u = |i| crate::framebuffer::float_to_ubyte(v(i));
        self.flat_u8 = [u(0), u(1), u(2), u(3)];
    }

    /// The covered columns of row `py` within `lo..=hi`, cut by each edge's span: empty
    /// (`hi < lo`) when an edge covers none of the row.
    #[inline]
    pub(crate) fn cut_span(&self, py: i64, mut lo: i64, mut hi: i64) -> (i64, i64) {
        for e in &self.edges {
            match e.span(py) {
                Some((a, b)) => {
                    lo = lo.max(a);
                    hi = hi.min(b);
                }
                None => hi = lo - 1,
            }
        }
        (lo, hi)
    }

    /// The covered pixels of row `py` among columns `x0..=x1` (a box at most [`NARROW`]
    /// pixels wide; of a wider one, its first `NARROW` columns) as a bit mask, bit k for
    /// pixel `x0 + k`. Exact: the pixels whose centre is inside all three edges, tested one
    /// by one (three integer steps per pixel, no branch per pixel).
    #[inline(always)]
    pub fn row_mask(&self, x0: i64, x1: i64, py: i64) -> u32 {
        row_mask(&self.edges, x0, x1, py)
    }

    /// The covered pixels of row `py` between columns `x0` and `x1` (inclusive), as
    /// `(first, last)`; `None` when none is covered. Exact: the same set as intersecting
    /// the three edges' [`Edge::span`]s.
    #[inline(always)]
    pub fn row_span(&self, x0: i64, x1: i64, py: i64) -> Option<(i64, i64)> {
        row_span(&self.edges, x0, x1, py)
    }
}

/// [`SetupTriangle::row_mask`] of a triangle with `edges`.
#[inline(always)]
pub fn row_mask(edges: &[Edge; 3], x0: i64, x1: i64, py: i64) -> u32 {
    // Written out rather than `edges.map(..)`: in the rasterizer's large
    // specialised functions LLVM left `map` out of line, a call per row whose result
    // came back through the stack.
    let [e0, e1, e2] = edges;
    let e = [
        e0.c + e0.b * ONE * py - e0.a * ONE * x0,
        e1.c + e1.b * ONE * py - e1.a * ONE * x0,
        e2.c + e2.b * ONE * py - e2.a * ONE * x0,
    ];
    let s = [e0.a * ONE, e1.a * ONE, e2.a * ONE];
    let n = x1 - x0;
    if n < 0 {
        return 0;
    }
    let mut mask = 0u32;
    let mut ek = e;
    // At most NARROW pixels; no early exit, so the only branch is the box width.
    for k in 0..=(n as u32).min(NARROW as u32 - 1) {
        mask |= (((ek[0] > 0) & (ek[1] > 0) & (ek[2] > 0)) as u32) << k;
        ek = [ek[0] - s[0], ek[1] - s[1], ek[2] - s[2]];
    }
    mask
}

/// [`SetupTriangle::row_span`] of a triangle with `edges`.
#[inline(always)]
pub fn row_span(edges: &[Edge; 3], x0: i64, x1: i64, py: i64) -> Option<(i64, i64)> {
    if x1 - x0 < NARROW {
        // The covered pixels of a row are consecutive, so the lowest and highest bits
        // of the row's mask are the span's ends.
        let mask = row_mask(edges, x0, x1, py);
        if mask == 0 {
            return None;
        }
        let first = mask.trailing_zeros() as i64;
        let last = 31 - mask.leading_zeros() as i64;
        return Some((x0 + first, x0 + last));
    }
    divided_span(edges, x0, x1, py)
}

/// [`row_span`] by the three edges' divisions, intersected.
#[inline(always)]
fn divided_span(edges: &[Edge; 3], x0: i64, x1: i64, py: i64) -> Option<(i64, i64)> {
    let (mut lo, mut hi) = (x0, x1);
    for e in edges {
        let (a, z) = e.span(py)?;
        lo = lo.max(a);
        hi = hi.min(z);
    }
    (lo <= hi).then_some((lo, hi))
}

/// A set-up triangle, ready for the rasterizer.
#[derive(Clone, Debug)]
pub struct SetupTriangle {
    /// The three edge functions.
    pub edges: [Edge; 3],
    /// Inclusive pixel bounding box (x0, y0, x1, y1) in y-down pixels, not yet clipped.
    pub bbox: [i64; 4],
    /// Whether the triangle faces front.
    pub front: bool,
    /// Window z.
    pub z: Plane,
    /// 1/w (only meaningful when `persp`).
    pub w: Plane,
    /// Whether 1/w varies (or is not 1): attributes need the perspective divide.
    pub persp: bool,
    /// Varying planes (pre-multiplied by 1/w when `persp`).
    pub vary: [Plane; super::MAX_VARY],
    /// The provoking vertex's varyings, for flat shading.
    pub flat: [f32; super::MAX_VARY],
    /// The provoking vertex's colour as 8-bit values (computed once per triangle).
    pub flat_u8: [u8; 4],
}

/// `round_half_even(256 * f32(v - 0.5))` as llvmpipe's SSE path snaps.
#[inline]
pub fn snap(v: f32) -> i64 {
    super::round_even((v - 0.5) * 256.0) as i64
}

/// [`snap`] of four values before the conversion to integers, lane by lane without
/// branches (the same operations as `round_even`, so the compiler can use one vector
/// operation for the four).
#[inline(always)]
fn snap4(v: [f32; 4]) -> [f32; 4] {
    round_even4(v.map(|v| (v - 0.5) * 256.0))
}

/// [`snap4`] without the half-pixel offset (multisample set-up): `round_half_even(256·v)`.
#[inline(always)]
fn snap4_ms(v: [f32; 4]) -> [f32; 4] {
    round_even4(v.map(|v| v * 256.0))
}

/// `round_even` of four values, lane by lane without branches.
#[inline(always)]
fn round_even4(t: [f32; 4]) -> [f32; 4] {
    const BIG: f32 = 8_388_608.0;
    let mut out = [0f32; 4];
    for l in 0..4 {
        let c = BIG.copysign(t[l]);
        let r = (t[l] + c) - c;
        out[l] = if t[l].abs() < BIG { r } else { t[l] };
    }
    out
}

/// The largest snapped coordinate we accept; beyond it a triangle is dropped (clipping keeps
/// real geometry far inside this; only garbage such as NaN reaches it).
const MAX_SNAPPED: f32 = (1u64 << 40) as f32;

/// What setup decided about a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetupResult {
    /// Draw it: the output triangle was filled in.
    Draw,
    /// Zero area after snapping, or not finite.
    Degenerate,
    /// Removed by face culling.
    Culled,
    /// Its bounding box holds no pixel centre, so it covers no pixel (only
    /// [`setup_triangle_shaded`] reports this, before computing the planes; the other
    /// entry points give such triangles as `Draw` with an empty `bbox`).
    Empty,
}

/// Face-culling inputs for setup.
#[derive(Clone, Copy, Debug)]
pub struct CullMode {
    /// Cull front faces.
    pub front: bool,
    /// Cull back faces.
    pub back: bool,
    /// Triangles wound counter-clockwise in raster space (positive area) face front.
    pub front_ccw: bool,
    /// The top-left fill rule (llvmpipe's `bottom_edge_rule = 0`): horizontal edges at
    /// the smallest raster y include their pixel centres, instead of those at the largest
    /// (the window buffer's bottom-edge rule). Framebuffer objects and GL_UPPER_LEFT each
    /// toggle it.
    pub top_left: bool,
}

/// Sets up triangle (v0, v1, v2) with `nvary` varyings into `fill` (v2 is the provoking
/// vertex whose varyings flat shading uses).
pub fn setup_triangle(
    v: [&ClipVertex; 3],
    nvary: usize,
    cull: CullMode,
    back: Option<usize>,
    fill: &mut SetupTriangle,
) -> SetupResult {
    setup_inner(v, nvary, cull, back, (true, false), Snap::Centre, fill)
}

/// Defines a copy of [`setup_triangle_shaded`] with the given attributes (and `unsafe`
/// when given): the one body, compiled once per instruction set.
macro_rules! shaded_copy {
    ($(#[$attr:meta])* $vis:vis $name:ident $($unsafe:tt)?) => {
        $(#[$attr])*
        $vis $($unsafe)? fn $name(v: [&ClipVertex; 3], nvary: usize, cull: CullMode, back: Option<usize>, flat: bool, fill: &mut SetupTriangle) -> SetupResult {
            setup_inner(v, nvary, cull, back, (flat, true), Snap::Centre, fill)
        }
    };
}

shaded_copy!(
    /// [`setup_triangle`] for a draw that knows its shading: the flat-shading values
    /// (`fill.flat`, `fill.flat_u8`) are only written when `flat`, since only flat-shaded
    /// spans read them. A triangle that covers no pixel centre is reported as
    /// [`SetupResult::Empty`] without its planes (most of setup's work).
    pub setup_triangle_shaded
);

shaded_copy!(
    /// [`setup_triangle_shaded`] compiled for AVX2: the same f32 and i64 operations (Rust
    /// never fuses a multiply and an add on its own), so the same results, with
    /// three-operand instructions instead of SSE2's register copies.
    ///
    /// # Safety
    /// The CPU must have AVX2 and the bit instructions of `cpu::isa`'s AVX2 variants.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
    setup_triangle_shaded_avx2 unsafe
);

/// Which compiled copy of [`setup_triangle_shaded`] a draw runs, chosen once per draw.
#[derive(Clone, Copy, Debug)]
pub struct SetupVariant {
    /// Run the AVX2 copy (only ever true on a CPU that has AVX2).
    avx2: bool,
    /// A multisample draw: set up for every sample of [`SAMPLE_POS`]
    /// ([`setup_triangle_samples`]).
    samples: bool,
}

impl SetupVariant {
    /// The fastest copy this CPU can run.
    pub fn detect() -> Self {
        SetupVariant {
            avx2: crate::cpu::isa().avx2(),
            samples: false,
        }
    }

    /// The set-up of a multisample draw: every sample of [`SAMPLE_POS`] at once, through
    /// [`setup_triangle_samples`] (never the AVX2 copies).
    pub fn all_samples() -> Self {
        SetupVariant {
            avx2: false,
            samples: true,
        }
    }

    /// Whether this is the AVX2 copy (the CPU has AVX2).
    pub fn is_avx2(self) -> bool {
        self.avx2
    }

    /// The baseline (SSE2) copy, whatever the CPU.
    #[cfg(test)]
    pub fn baseline() -> Self {
        SetupVariant {
            avx2: false,
            samples: false,
        }
    }

    /// [`setup_triangle_shaded`], in this variant's copy.
    #[inline(always)]
    pub fn shaded(
        self,
        v: [&ClipVertex; 3],
        nvary: usize,
        cull: CullMode,
        back: Option<usize>,
        flat: bool,
        fill: &mut SetupTriangle,
    ) -> SetupResult {
        if self.samples {
            return setup_triangle_samples(v, nvary, cull, back, flat, fill);
        }
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is only set by `detect`, from an AVX2 `isa()` (AVX2 and the bit
            // instructions).
            return unsafe { setup_triangle_shaded_avx2(v, nvary, cull, back, flat, fill) };
        }
        setup_triangle_shaded(v, nvary, cull, back, flat, fill)
    }
}

/// [`setup_triangle_shaded`] for a 4x multisample draw, every sample at once, as llvmpipe
/// sets up with `setup->multisample`: positions snapped as `round_half_even(256·v)` (no
/// −0.5 pixel offset), so that the integer test point of pixel (px, py) is its corner
/// (256·px, 256·py). llvmpipe tests sample s at `c + (sy·dcdy − sx·dcdx) >> 8`, the edge
/// moved to the sample point with the same tie rule: [`Edge::at_sample`] gives those
/// edges (moving the vertices by −[`SAMPLE_POS`]`[s]` changes only each edge's `c`, by
/// `−a·sx + b·sy`), and the box is the union of the four samples' boxes. The plane
/// equations' `a0` is the value at pixel (0,0)'s corner (`pixel_center = 0`): the shader
/// adds 0.5 (attributes) or the sample position (depth) to the pixel's coordinates. The
/// planes come from the unsnapped positions, the same for every sample.
pub fn setup_triangle_samples(
    v: [&ClipVertex; 3],
    nvary: usize,
    cull: CullMode,
    back: Option<usize>,
    flat: bool,
    fill: &mut SetupTriangle,
) -> SetupResult {
    setup_inner(v, nvary, cull, back, (flat, true), Snap::Samples, fill)
}

/// Where setup puts the rasterizer's integer test point of a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Snap {
    /// The pixel's centre (single-sample rasterization).
    Centre,
    /// Every sample point ([`setup_triangle_samples`]).
    Samples,
}

/// The smallest and largest coordinate of the sample points of [`SAMPLE_POS`] on either
/// axis.
const SAMPLE_SPAN: [i64; 2] = [32, 224];

/// Setup; `(flat, skip_empty)` as [`setup_triangle_shaded`]'s `flat` and whether an empty
/// triangle is reported as `Empty`.
#[inline(always)]
fn setup_inner(
    v: [&ClipVertex; 3],
    nvary: usize,
    cull: CullMode,
    back: Option<usize>,
    (flat, skip_empty): (bool, bool),
    snap: Snap,
    fill: &mut SetupTriangle,
) -> SetupResult {
    // The six coordinates as lanes (x0 y0 x1 y1, x2 y2), checked and snapped without a
    // branch per value.
    let lo = [v[0].win[0], v[0].win[1], v[1].win[0], v[1].win[1]];
    let hi = [v[2].win[0], v[2].win[1], 0.0, 0.0];
    let lim = MAX_SNAPPED / 256.0;
    let ok = (0..4).fold(true, |ok, l| ok & (lo[l].abs() < lim) & (hi[l].abs() < lim));
    if !ok {
        return SetupResult::Degenerate;
    }
    let (lo, hi) = match snap {
        Snap::Centre => (snap4(lo), snap4(hi)),
        Snap::Samples => (snap4_ms(lo), snap4_ms(hi)),
    };
    let (mut p0, mut p1, p2) = (v[0], v[1], v[2]);
    // One `cvttss2si` each: `as` adds the saturation of NaN and out-of-range values (five
    // instructions a value), which cannot occur here.
    // SAFETY: every coordinate passed `|c| < 2^32` above (NaN fails it), so the snapped
    // value is finite and below 2^41 in magnitude: an i64 holds it exactly.
    let [x0, y0, x1, y1] = lo.map(|c| unsafe { c.to_int_unchecked::<i64>() });
    // SAFETY: as above.
    let [x2, y2] = [hi[0], hi[1]].map(|c| unsafe { c.to_int_unchecked::<i64>() });
    let area = (x0 - x1) * (y2 - y0) - (x2 - x0) * (y0 - y1);
    if area == 0 {
        return SetupResult::Degenerate;
    }
    let ccw = area > 0;
    let front = ccw == cull.front_ccw;
    if (front && cull.front) || (!front && cull.back) {
        return SetupResult::Culled;
    }
    // Two-sided lighting: a back-facing triangle takes the back colours (llvmpipe's
    // `lp_twoside` setup step).
    let swapped: [ClipVertex; 3];
    let p2 = if let (false, Some(o)) = (front, back) {
        swapped = [p0, p1, p2].map(|p| {
            let mut q = *p;
            q.vary.copy_within(o..o + 8, 0);
            q
        });
        (p0, p1) = (&swapped[0], &swapped[1]);
        &swapped[2]
    } else {
        p2
    };
    setup_rest(
        p0,
        p1,
        p2,
        [x0, x1, x2],
        [y0, y1, y2],
        ccw,
        (front, cull.top_left),
        (nvary, flat, skip_empty, snap),
        fill,
    )
}

/// Whether a box of at most 2x2 pixel centres (`bbox`, inclusive, not empty) has a centre
/// inside all three `edges` (the rasterizer's exact test); larger boxes answer `true`
/// untested. Tiny triangles often cover no centre at all, and this finds it before the
/// planes are computed.
#[inline(always)]
fn tiny_box_covered(edges: &[Edge; 3], bbox: [i64; 4]) -> bool {
    if bbox[2] - bbox[0] > 1 || bbox[3] - bbox[1] > 1 {
        return true;
    }
    // The box's extent past its first centre is 0 or 1 pixel per axis: as an all-ones or
    // zero mask, a step to the second column or row is an AND instead of a multiply.
    let (mx, my) = (-(bbox[2] - bbox[0]), -(bbox[3] - bbox[1]));
    // Whether each of the four centres is inside every edge so far.
    let mut inside = [true; 4];
    for e in edges {
        // The edge's value at the first centre, then one step right and one step down.
        let v00 = e.c - e.a * ONE * bbox[0] + e.b * ONE * bbox[1];
        let v10 = v00 - ((e.a * ONE) & mx);
        let dy = (e.b * ONE) & my;
        let (v01, v11) = (v00 + dy, v10 + dy);
        for (k, v) in [v00, v10, v01, v11].into_iter().enumerate() {
            inside[k] &= v > 0;
        }
    }
    inside[0] | inside[1] | inside[2] | inside[3]
}

/// A triangle's constants for its plane equations (Mesa's order, lp_state_setup.c; f32,
/// no FMA): the position deltas scaled by 1/area, and vertex 0 relative to pixel (0,0)'s
/// centre.
#[derive(Clone, Copy)]
struct PlaneConsts {
    dy20o: f32,
    dy01o: f32,
    dx01o: f32,
    dx20o: f32,
    x0c: f32,
    y0c: f32,
}

impl PlaneConsts {
    /// The plane through the values `a0`, `a1`, `a2` at the three vertices.
    #[inline(always)]
    fn plane(&self, a0: f32, a1: f32, a2: f32) -> Plane {
        let da01 = a0 - a1;
        let da20 = a2 - a0;
        let dadx = da01 * self.dy20o - da20 * self.dy01o;
        let dady = da20 * self.dx01o - da01 * self.dx20o;
        Plane {
            a0: a0 - (dadx * self.x0c + dady * self.y0c),
            dadx,
            dady,
        }
    }

    /// Four [`Self::plane`]s, lane by lane with the same operations (written as lanes so
    /// the compiler can use one vector operation for the four).
    #[inline(always)]
    fn plane4(&self, a0: [f32; 4], a1: [f32; 4], a2: [f32; 4]) -> [Plane; 4] {
        let mut dadx = [0f32; 4];
        let mut dady = [0f32; 4];
        let mut a = [0f32; 4];
        for l in 0..4 {
            let da01 = a0[l] - a1[l];
            let da20 = a2[l] - a0[l];
            dadx[l] = da01 * self.dy20o - da20 * self.dy01o;
            dady[l] = da20 * self.dx01o - da01 * self.dx20o;
        }
        for l in 0..4 {
            a[l] = a0[l] - (dadx[l] * self.x0c + dady[l] * self.y0c);
        }
        std::array::from_fn(|l| Plane {
            a0: a[l],
            dadx: dadx[l],
            dady: dady[l],
        })
    }
}

/// The part of setup after culling: edges and planes of (p0, p1, p2), reordered when
/// clockwise. Inlined into each entry point, so the AVX2 copy has its own.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn setup_rest<'v>(
    mut p0: &'v ClipVertex,
    mut p1: &'v ClipVertex,
    p2: &'v ClipVertex,
    xs: [i64; 3],
    ys: [i64; 3],
    ccw: bool,
    (front, top_left): (bool, bool),
    (nvary, flat, skip_empty, snap): (usize, bool, bool, Snap),
    fill: &mut SetupTriangle,
) -> SetupResult {
    let ([mut x0, mut x1, x2], [mut y0, mut y1, y2]) = (xs, ys);
    if !ccw {
        std::mem::swap(&mut p0, &mut p1);
        std::mem::swap(&mut x0, &mut x1);
        std::mem::swap(&mut y0, &mut y1);
    }
    let xs = [x0, x1, x2];
    let ys = [y0, y1, y2];
    let mut edges = [Edge { a: 0, b: 0, c: 0 }; 3];
    for i in 0..3 {
        let j = (i + 1) % 3;
        let a = ys[i] - ys[j];
        let b = xs[i] - xs[j];
        let mut c = a * xs[i] - b * ys[i];
        // Left edges (a < 0) and, by the bottom-edge rule, bottom edges (b < 0) include
        // the pixel centres on them; by the top-left rule, top edges (b > 0) instead.
        if a < 0 || (a == 0 && if top_left { b > 0 } else { b < 0 }) {
            c += 1;
        }
        edges[i] = Edge { a, b, c };
    }
    // (Written out: `Iterator::min`/`max` were not inlined, 2% of a sprite frame.)
    let minx = x0.min(x1).min(x2);
    let maxx = x0.max(x1).max(x2);
    let miny = y0.min(y1).min(y2);
    let maxy = y0.max(y1).max(y2);
    // The pixels whose test point may lie inside; for all four samples the union of
    // their boxes (sample s's box is this one's with the vertices moved by −its offset,
    // and the offsets span 32..=224 on both axes).
    let (lo_off, hi_off) = match snap {
        Snap::Samples => (SAMPLE_SPAN[1], SAMPLE_SPAN[0]),
        Snap::Centre => (0, 0),
    };
    let bbox = [
        (minx - lo_off + ONE - 1).div_euclid(ONE),
        (miny - lo_off + ONE - 1).div_euclid(ONE),
        (maxx - hi_off).div_euclid(ONE),
        (maxy - hi_off).div_euclid(ONE),
    ];
    if skip_empty && (bbox[0] > bbox[2] || bbox[1] > bbox[3]) {
        return SetupResult::Empty;
    }
    // (The tiny-box test knows one test point per pixel.)
    if skip_empty && snap == Snap::Centre && !tiny_box_covered(&edges, bbox) {
        return SetupResult::Empty;
    }

    // Plane equations in f32, Mesa's order (lp_state_setup.c), no FMA.
    let (fx0, fy0) = (p0.win[0], p0.win[1]);
    let (fx1, fy1) = (p1.win[0], p1.win[1]);
    let (fx2, fy2) = (p2.win[0], p2.win[1]);
    // a0 at pixel (0,0)'s centre, or (multisample) at its corner.
    let half = if snap == Snap::Centre { 0.5f32 } else { 0.0 };
    let x0c = fx0 - half;
    let y0c = fy0 - half;
    let dx01 = fx0 - fx1;
    let dy01 = fy0 - fy1;
    let dx20 = fx2 - fx0;
    let dy20 = fy2 - fy0;
    let ooa = 1.0f32 / (dx01 * dy20 - dy01 * dx20);
    let dx20o = dx20 * ooa;
    let dy20o = dy20 * ooa;
    let dx01o = dx01 * ooa;
    let dy01o = dy01 * ooa;
    let pc = PlaneConsts {
        dy20o,
        dy01o,
        dx01o,
        dx20o,
        x0c,
        y0c,
    };
    fill.edges = edges;
    fill.bbox = bbox;
    fill.front = front;
    fill.z = pc.plane(p0.win[2], p1.win[2], p2.win[2]);
    let (w0, w1, w2) = (p0.win[3], p1.win[3], p2.win[3]);
    fill.persp = !(w0 == 1.0 && w1 == 1.0 && w2 == 1.0);
    fill.w = pc.plane(w0, w1, w2);
    let persp = fill.persp;
    // Four varyings at a time (the same operations per lane as `plane`), then the rest.
    let lanes = |p: &ClipVertex, w: f32, i: usize| -> [f32; 4] {
        let v = [p.vary[i], p.vary[i + 1], p.vary[i + 2], p.vary[i + 3]];
        if persp {
            v.map(|a| a * w)
        } else {
            v
        }
    };
    let n4 = nvary.min(super::MAX_VARY) / 4 * 4;
    for i in (0..n4).step_by(4) {
        let out = pc.plane4(lanes(p0, w0, i), lanes(p1, w1, i), lanes(p2, w2, i));
        fill.vary[i..i + 4].copy_from_slice(&out);
    }
    for i in n4..nvary {
        fill.vary[i] = if persp {
            pc.plane(p0.vary[i] * w0, p1.vary[i] * w1, p2.vary[i] * w2)
        } else {
            pc.plane(p0.vary[i], p1.vary[i], p2.vary[i])
        };
    }
    // Only the varyings this draw writes (the rest stay as the draw's first triangle left
    // them: zero, like the vertices' unused varyings).
    if flat {
        fill.set_flat(nvary, |i| p2.vary[i]);
    }
    SetupResult::Draw
}

impl Default for SetupTriangle {
    fn default() -> Self {
        SetupTriangle {
            edges: [Edge { a: 0, b: 0, c: 0 }; 3],
            bbox: [0; 4],
            front: true,
            z: Plane::default(),
            w: Plane::default(),
            persp: false,
            vary: [Plane::default(); super::MAX_VARY],
            flat: [0.0; super::MAX_VARY],
            flat_u8: [0; 4],
        }
    }
}

#[cfg(test)]
#[path = "setup_tests.rs"]
mod tests;
