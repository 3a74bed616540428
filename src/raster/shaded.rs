//! Triangles, lines and points of a draw with a fragment shader
//! ([`crate::shader::draw`]): the chunk rows of the textured walk ([`textured::Chunks`],
//! pairs of rows in 8-pixel chunks; for lines and points the chunks of their coverage,
//! [`CoverChunks`], on the planes of `lines.rs`) through the shader's compiled variant.
//! Under multisampling the chunks are those of the one-pass multisample walk
//! ([`super::multisample::MsChunks`]: pixel centres, coverage per sample), and the walk
//! tests and stores each sample. A primitive whose plan the engine does not draw (a
//! lookup that cannot read its unit …) is not drawn and is counted in
//! `program_tris_refused`: drawing it without its shader would be wrong. The planes of the varyings taken from the provoking vertex
//! (the colours under GL_FLAT, the shader's `flat` inputs) are made constant at its
//! values ([`flat_planes`]).
//!
//! The shader's texture lookups at varyings ([`crate::shader::draw::ShaderTexture`]) are
//! sampled here, a chunk's 2x2 quads at a time, before the program runs: each coordinate
//! is its varying's plane at the pixel times the pixel's `1 / w` (the value the program
//! reads: the plane evaluated as llvmpipe's interpolator does, `1 / w_plane` divided
//! once), then times `1 / q` for a projective lookup, and the draw's units sample them
//! with the fixed-function units' samplers and level-of-detail rules (the quad's
//! derivatives). Lookups at coordinates the program computes are sampled by the program
//! itself through [`Computed`], a chunk pair at a time, with the same samplers.
//!
//! Consecutive primitives of one [`Draw`] share one walk ([`Pending`]; a new one where
//! the shader reads `gl_FrontFacing`, or the two faces' stencil states differ, and the
//! facing changes), so that the engine runs the rows of several small triangles in one
//! batch; the draw runs the last rows when it ends.

use super::prim_tex::{Cover, CoverChunks};
use super::textured;
use super::Draw;
use crate::engine::draw::Walk;
use crate::engine::exec::{QuadCoords, TexSampler};
use crate::fragment::multisample::SAMPLES;
use crate::fragment::span::{eval, Fused, Madd, TexLanes, Unfused, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::shader::draw::{FragShader, ShaderRef, ShaderTexture};
use crate::stats::Stats;
use crate::texture::lookup::{self, LookupKind};
use crate::texture::UnitPlan;
use std::cell::RefCell;
use std::sync::Arc;

/// No texels: a shader's walk has no units.
const NO_TEXELS: TexLanes = [[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS];

/// A shader draw's walk kept across the triangles of a [`Draw`], so that one batch of
/// the engine holds the rows of several small triangles ([`crate::engine::draw`]).
pub(super) struct Pending {
    walk: Walk,
    /// The facing the walk's uniforms hold (when the shader reads `gl_FrontFacing`).
    front: bool,
    /// The registered shader, for its texture lookups.
    shader: Option<Arc<FragShader>>,
    /// A chunk's sampled texels per row (lanes that are not live hold any value).
    texels: Box<[TexLanes; 2]>,
    /// Each lookup's index in the draw's units ([`ShaderRef::tex_units`]).
    slots: [u8; MAX_TEXTURE_UNITS],
    /// The texels of the program's own lookups ([`Computed`]).
    quad_texels: RefCell<Box<[TexLanes; 2]>>,
}

impl Pending {
    /// Runs the walk's last rows (the program's own lookups sample `units`).
    pub(super) fn end(self, units: &[UnitPlan<'_>], fb: &mut Target<'_>, stats: &mut Stats) {
        let lookups = self.shader.as_ref().map_or(&[][..], |s| &s.textures[..]);
        let tex = Computed {
            lookups,
            slots: &self.slots,
            units,
            buf: &self.quad_texels,
        };
        self.walk.end_with(fb, stats, Some(&tex));
    }
}

/// The sampler of a program's lookups at computed coordinates ([`ShaderTexture::computed`]):
/// the draw's units with the same samplers and level-of-detail rules as the lookups
/// sampled before the program runs.
struct Computed<'a, 'u> {
    lookups: &'a [ShaderTexture],
    slots: &'a [u8; MAX_TEXTURE_UNITS],
    units: &'a [UnitPlan<'u>],
    /// Where the samplers write (lookup k's texels at index k).
    buf: &'a RefCell<Box<[TexLanes; 2]>>,
}

impl TexSampler for Computed<'_, '_> {
    fn sample(&self, lookup: usize, c: &QuadCoords, out: &mut [[[f32; 4]; 8]; 2]) {
        let unit = self
            .slots
            .get(lookup)
            .map_or(usize::MAX, |&u| usize::from(u));
        let (Some(u), Some(lk)) = (self.units.get(unit), self.lookups.get(lookup)) else {
            *out = [[[0.0, 0.0, 0.0, 1.0]; 8]; 2];
            return;
        };
        if lk.kind != LookupKind::Implicit {
            return by_quad(u, lk.kind, c, out);
        }
        let mut buf = self.buf.borrow_mut();
        sample_at(u, lookup, c, &mut buf);
        for (o, row) in out.iter_mut().zip(buf.iter()) {
            *o = row[lookup];
        }
    }
}

/// A lookup of `kind` other than [`LookupKind::Implicit`] ([`crate::texture::lookup`])
/// of unit `u` at `c`, quad by quad (those with a live pixel).
fn by_quad(u: &UnitPlan<'_>, kind: LookupKind, c: &QuadCoords, out: &mut [[[f32; 4]; 8]; 2]) {
    for j in 0..LANES / 2 {
        let (a, b) = (2 * j, 2 * j + 1);
        let quad = |v: &[[f32; 8]; 2]| [v[0][a], v[0][b], v[1][a], v[1][b]];
        let live = [c.live[0][a], c.live[0][b], c.live[1][a], c.live[1][b]];
        if !live.iter().any(|&l| l) {
            continue;
        }
        let (s, t, r, l) = (quad(&c.s), quad(&c.t), quad(&c.r), quad(&c.l));
        let v = match kind {
            LookupKind::Fetch => std::array::from_fn(|i| lookup::fetch(u, s[i], t[i], l[i])),
            LookupKind::Size => [lookup::size(u, l[0]); 4],
            _ => {
                let r = u.needs_r().then_some(r);
                lookup::sample_quad_lods(u, kind, (s, t, r), l, live)
            }
        };
        out[0][a] = v[0];
        out[0][b] = v[1];
        out[1][a] = v[2];
        out[1][b] = v[3];
    }
}

/// [`super::sample_unit`] of unit `u` for lookup `k` at `c`, fused where the level
/// fuses (compiled with its features, as [`sample_fused`]).
fn sample_at(u: &UnitPlan<'_>, k: usize, c: &QuadCoords, texels: &mut [TexLanes; 2]) {
    #[inline(always)]
    fn go<M: Madd>(u: &UnitPlan<'_>, k: usize, c: &QuadCoords, texels: &mut [TexLanes; 2]) {
        let rr = if u.needs_r() { Some(&c.r) } else { None };
        super::sample_unit::<M>(u, k, &c.s, &c.t, rr, &c.live, texels);
    }
    if !crate::cpu::isa().fused() {
        return go::<Unfused>(u, k, c, texels);
    }
    #[cfg(target_arch = "x86_64")]
    {
        /// # Safety
        /// The CPU has AVX2 and FMA.
        #[target_feature(enable = "avx2,fma")]
        unsafe fn avx2(u: &UnitPlan<'_>, k: usize, c: &QuadCoords, t: &mut [TexLanes; 2]) {
            go::<Fused>(u, k, c, t)
        }
        /// # Safety
        /// The CPU has FMA.
        #[target_feature(enable = "fma")]
        unsafe fn fma(u: &UnitPlan<'_>, k: usize, c: &QuadCoords, t: &mut [TexLanes; 2]) {
            go::<Fused>(u, k, c, t)
        }
        if crate::cpu::isa().avx2() {
            // SAFETY: the AVX2 level has AVX2 and FMA (`cpu::isa`).
            unsafe { avx2(u, k, c, texels) }
        } else {
            // SAFETY: the level fuses, so the CPU has FMA (`cpu::isa`).
            unsafe { fma(u, k, c, texels) }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    go::<Fused>(u, k, c, texels)
}

/// Draws `t` in box `b` (cut to the region) with shader `sh`: its rows join the draw's
/// pending walk (a new one when the triangle's facing changes the uniforms). Out of line
/// and cold: the branch to it must not change how the fixed-function walks around it
/// are compiled.
#[cold]
#[inline(never)]
pub(super) fn triangle(t: &SetupTriangle, b: [i64; 4], sh: &ShaderRef, d: &mut Draw<'_, '_>) {
    let flat = flat_planes(t, d.plan);
    let planes = flat.as_ref().unwrap_or(t);
    if d.plan.ms.is_some() {
        // Set up for every sample: the chunks at the pixel centres with each sample's
        // coverage (`crate::engine::draw::Walk::cover`).
        let edges = super::multisample::sample_edges(t);
        walk(planes, super::multisample::MsChunks::new(&edges, b), sh, d);
    } else {
        walk(planes, single(textured::Chunks::new(t, b)), sh, d);
    }
}

/// Single-sample chunks, with no sample coverage.
#[inline(always)]
fn single(chunks: impl Iterator<Item = textured::Chunk>) -> impl Iterator<Item = MsItem> {
    chunks.map(|c| (c, [[0; SAMPLES]; 2]))
}

/// A chunk and its sample coverage per row (zero in a single-sample walk).
type MsItem = (textured::Chunk, [[u8; SAMPLES]; 2]);

/// `t` with the planes of the varyings taken from the provoking vertex
/// ([`super::prims::flat_varyings`]: the colours under GL_FLAT, the shader's `flat`
/// inputs) made constant at its values (the program reads them without the perspective
/// divide, `shader::lower::Options::flat_colors`), or `None` when there are none.
fn flat_planes(t: &SetupTriangle, plan: &FragPlan) -> Option<SetupTriangle> {
    let mut mask = super::prims::flat_varyings(plan);
    if mask == 0 {
        return None;
    }
    let mut f = t.clone();
    while mask != 0 {
        let v = mask.trailing_zeros() as usize;
        mask &= mask - 1;
        if let (Some(p), Some(&a0)) = (f.vary.get_mut(v), t.flat.get(v)) {
            *p = Plane {
                a0,
                dadx: 0.0,
                dady: 0.0,
            };
        }
    }
    Some(f)
}

/// Draws the pixels of `cover` in box `b` (cut to the region) with the planes of `t` (a
/// line's or a point's, [`super::lines`]) and shader `sh`, as [`triangle`] draws a
/// triangle's (`t.front`: [`Draw::prim_front`]).
#[cold]
#[inline(never)]
pub(super) fn covered<C: Cover>(
    t: &SetupTriangle,
    b: [i64; 4],
    cover: &C,
    sh: &ShaderRef,
    d: &mut Draw<'_, '_>,
) {
    match flat_planes(t, d.plan) {
        Some(f) => walk(&f, single(CoverChunks::new(cover, b)), sh, d),
        None => walk(t, single(CoverChunks::new(cover, b)), sh, d),
    }
}

/// Whether every lookup of a shader can read the unit it is bound to (`texelFetch` of a
/// depth texture and the like are refused: [`lookup::reads`]).
fn readable(
    lookups: &[ShaderTexture],
    slots: &[u8; MAX_TEXTURE_UNITS],
    units: &[UnitPlan<'_>],
) -> bool {
    lookups.iter().zip(slots).all(|(lk, &u)| {
        units
            .get(usize::from(u))
            .is_none_or(|u| lookup::reads(u, lk.kind))
    })
}

/// The chunks of `t` through the draw's pending shader walk ([`triangle`]).
#[inline(always)]
fn walk(
    t: &SetupTriangle,
    chunks: impl Iterator<Item = MsItem>,
    sh: &ShaderRef,
    d: &mut Draw<'_, '_>,
) {
    let (plan, units, fb, stats) = (d.plan, d.units, &mut *d.fb, &mut *d.stats);
    // A walk runs one face's uniforms (`gl_FrontFacing`) and stencil state.
    let per_face = sh.facing.is_some() || plan.stencil.is_some_and(|s| s.front != s.back);
    let reuse = matches!(&d.shaded, Some(p) if !per_face || p.front == t.front);
    if !reuse {
        if let Some(p) = d.shaded.take() {
            p.end(units, fb, stats);
        }
        let Some(walk) = crate::shader::draw::walk(sh, plan, fb, t.front) else {
            stats.program_tris_refused += 1;
            return;
        };
        let shader = match sh.ntex {
            0 => None,
            _ => match crate::shader::draw::shader_of(sh) {
                Some(s) if readable(&s.textures, &sh.tex_units, units) => Some(s),
                _ => {
                    walk.end(fb, stats);
                    stats.program_tris_refused += 1;
                    return;
                }
            },
        };
        d.shaded = Some(Pending {
            walk,
            front: t.front,
            shader,
            texels: Box::new([NO_TEXELS; 2]),
            slots: sh.tex_units,
            quad_texels: RefCell::new(Box::new([NO_TEXELS; 2])),
        });
    }
    let Some(p) = d.shaded.as_mut() else {
        return;
    };
    let (w, texels) = (&mut p.walk, &mut *p.texels);
    let lookups = p.shader.as_ref().map_or(&[][..], |s| &s.textures[..]);
    let tex = Computed {
        lookups,
        slots: &p.slots,
        units,
        buf: &p.quad_texels,
    };
    let fused = crate::cpu::isa().fused();
    let quads = w.quads();
    w.begin_with(t, fb, stats, Some(&tex));
    for (c, cov) in chunks {
        w.cover(cov);
        if !lookups.is_empty() {
            let io = Lookups {
                t,
                lookups,
                slots: &sh.tex_units,
                units,
                c: &c,
            };
            if fused {
                sample_fused(&io, texels);
            } else {
                sample::<Unfused>(&io, texels);
            }
        }
        if quads {
            let (qy, x) = (c.qy as usize, c.x as usize);
            w.pair(fb, qy, x, &c.live, texels, stats, Some(&tex));
            continue;
        }
        for (r, live) in c.live.iter().enumerate() {
            let py = (c.qy + r as i64) as usize;
            w.row(fb, py, c.x as usize, live, &texels[r], stats);
        }
    }
}

/// What sampling a chunk's lookups reads.
struct Lookups<'a, 'u> {
    t: &'a SetupTriangle,
    lookups: &'a [ShaderTexture],
    /// Each lookup's index in `units`, or `NO_UNIT`.
    slots: &'a [u8; MAX_TEXTURE_UNITS],
    units: &'a [UnitPlan<'u>],
    c: &'a textured::Chunk,
}

/// [`sample`], fused, compiled with FMA; at the AVX2 level [`sample_avx2`].
fn sample_fused(io: &Lookups<'_, '_>, texels: &mut [TexLanes; 2]) {
    #[cfg(target_arch = "x86_64")]
    {
        /// # Safety
        /// The CPU has FMA.
        #[target_feature(enable = "fma")]
        unsafe fn fma(io: &Lookups<'_, '_>, texels: &mut [TexLanes; 2]) {
            sample::<Fused>(io, texels)
        }
        if crate::cpu::isa().avx2() {
            // SAFETY: the AVX2 level has AVX2 and FMA (`cpu::isa`).
            unsafe { sample_avx2(io, texels) }
        } else {
            // SAFETY: the level fuses, so the CPU has FMA (`cpu::isa`).
            unsafe { fma(io, texels) }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    sample::<Fused>(io, texels)
}

/// [`sample`] (fused) with the coordinates on 8 lanes: the same operations on each lane
/// (`1 / w`, the plane times it, `1 / q` and the products), then the same samplers.
///
/// # Safety
/// The CPU has AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn sample_avx2(io: &Lookups<'_, '_>, texels: &mut [TexLanes; 2]) {
    use crate::fragment::simd_tex::eval8;
    use crate::simd::F32x8;
    let (t, c) = (io.t, io.c);
    // SAFETY: (whole body) this function's AVX2 and FMA; loads and stores of 8 f32 from
    // and into 8-lane arrays.
    unsafe {
        let one = F32x8::splat(1.0);
        let fx = F32x8::load(c.fx.as_ptr());
        let fy = [F32x8::splat(c.fy[0]), F32x8::splat(c.fy[1])];
        // Loops, not closures: a closure is compiled without this function's features.
        let mut oow = [one; 2];
        for r in 0..2 {
            oow[r] = one.div(eval8::<true>(&t.w, fx, fy[r]));
        }
        for (k, lk) in io.lookups.iter().enumerate() {
            if lk.computed {
                continue;
            }
            let Some(u) = io.units.get(usize::from(io.slots[k])) else {
                for row in texels.iter_mut() {
                    row[k] = [[0.0, 0.0, 0.0, 1.0]; LANES];
                }
                continue;
            };
            // s, t, r, q per row
            let mut co = [[F32x8::zero(); 2]; 4];
            for (dst, spec) in co.iter_mut().zip(&lk.coords) {
                let Some((v, linear)) = *spec else {
                    continue;
                };
                let p = &t.vary[usize::from(v)];
                for r in 0..2 {
                    let a = eval8::<true>(p, fx, fy[r]);
                    dst[r] = if linear { a } else { a.mul(oow[r]) };
                }
            }
            if lk.proj {
                let [s, tt, rr, q] = &mut co;
                for r in 0..2 {
                    let rq = one.div(q[r]);
                    s[r] = s[r].mul(rq);
                    tt[r] = tt[r].mul(rq);
                    rr[r] = rr[r].mul(rq);
                }
            }
            let mut out = [[[0f32; LANES]; 2]; 3];
            for (o, v) in out.iter_mut().zip(&co) {
                for r in 0..2 {
                    v[r].store(o[r].as_mut_ptr());
                }
            }
            let rr = if u.needs_r() { Some(&out[2]) } else { None };
            super::sample_unit::<Fused>(u, k, &out[0], &out[1], rr, &c.live, texels);
        }
    }
}

/// Samples every lookup for the 2x2 quads of the chunk that hold a live pixel (see the
/// module doc); a lookup without a complete texture gives (0, 0, 0, 1).
#[inline(always)]
fn sample<M: Madd>(io: &Lookups<'_, '_>, texels: &mut [TexLanes; 2]) {
    let (t, c) = (io.t, io.c);
    let mut oow = [[0f32; LANES]; 2];
    for (o, &fy) in oow.iter_mut().zip(&c.fy) {
        for (o, &fx) in o.iter_mut().zip(&c.fx) {
            *o = 1.0f32 / eval::<M>(&t.w, fx, fy);
        }
    }
    for (k, lk) in io.lookups.iter().enumerate() {
        if lk.computed {
            continue;
        }
        let Some(u) = io.units.get(usize::from(io.slots[k])) else {
            for row in texels.iter_mut() {
                row[k] = [[0.0, 0.0, 0.0, 1.0]; LANES];
            }
            continue;
        };
        // s, t, r, q per row and lane
        let mut co = [[[0f32; LANES]; 2]; 4];
        for (dst, spec) in co.iter_mut().zip(&lk.coords) {
            let Some((v, linear)) = *spec else {
                continue;
            };
            let p = &t.vary[usize::from(v)];
            for r in 0..2 {
                for i in 0..LANES {
                    let a = eval::<M>(p, c.fx[i], c.fy[r]);
                    dst[r][i] = if linear { a } else { a * oow[r][i] };
                }
            }
        }
        if lk.proj {
            let [s, tt, rr, q] = &mut co;
            for r in 0..2 {
                for i in 0..LANES {
                    let rq = 1.0f32 / q[r][i];
                    s[r][i] *= rq;
                    tt[r][i] *= rq;
                    rr[r][i] *= rq;
                }
            }
        }
        let rr = if u.needs_r() { Some(&co[2]) } else { None };
        super::sample_unit::<M>(u, k, &co[0], &co[1], rr, &c.live, texels);
    }
}
