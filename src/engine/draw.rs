//! The engine in the draw path: [`Walk`] takes the rows of triangles' chunks with the
//! units' sampled texels (the rasterizer's general textured walk samples them), gathers
//! up to [`MAX_BATCH`] rows, and runs the state's cached program over them; it counts
//! what the hand-written shaders count ([`Stats`]).
//!
//! One batch may hold the rows of several triangles (a shader draw's walk lives across
//! the triangles of a band, `crate::raster::shaded`): each row names its triangle's
//! planes. Running a batch writes its rows' pixels kernel by kernel (every row's depth,
//! then every row's colour), so two rows of one batch must not share a pixel: a row of
//! one triangle never overlaps another row of the same triangle, and a row that would
//! overlap a pending row of an earlier triangle runs the batch first ([`Walk::row`]).
//! So every pixel sees its fragments in primitive order, as drawing triangle by triangle
//! does; [`Walk::end`] runs the last batch.

use super::cache;
use super::exec::{ChunkIn, Io, Program, Scratch, TexSampler, MAX_BATCH};
use super::ff::FfState;
use super::lower::planes_into;
use crate::fragment::multisample::SAMPLES;
use crate::fragment::span::{store_chunk, unorm8, write_colors, StoreFormat, TexLanes, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::{ColorFormat, Target};
use crate::geometry::setup::SetupTriangle;
use crate::geometry::MAX_VARY;
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::rc::Rc;

/// Input streams at most: four channels per unit.
const STREAMS: usize = 4 * MAX_TEXTURE_UNITS;

/// The uniform words a program's walk passes at most ([`Walk::with_program`]): room for
/// GLSL's light state in a fragment shader (`gl_LightSource[]` is 232 words, the front
/// light products 96).
pub const MAX_UNIFORMS: usize = 512;

/// The planes of one triangle at most.
const SET: usize = 2 + MAX_VARY;

// A fixed-function walk's uniforms are its triangle's flat varyings.
const _: () = assert!(MAX_VARY <= MAX_UNIFORMS);

/// A walk's buffers, kept per thread between walks.
struct State {
    scratch: Scratch,
    chunks: [ChunkIn; MAX_BATCH],
    /// Lanes inside the row of each chunk (colour reads are counted per row).
    ns: [u8; MAX_BATCH],
    live_out: [u8; MAX_BATCH],
    /// Stream s of chunk k at `s * MAX_BATCH + k`.
    streams: Vec<[u32; 8]>,
    /// The plane sets of the batch's triangles, `set` planes each (the last one is the
    /// current triangle's).
    planes: Vec<[f32; 3]>,
    /// Plane sets in `planes`.
    sets: usize,
    /// The first chunk of the current triangle (the chunks before it are earlier
    /// triangles').
    first: usize,
    /// The program's uniforms.
    uniforms: [f32; MAX_UNIFORMS],
    /// The program's outputs (a store outside the program: [`host_store`]).
    outs: Vec<[u32; 8]>,
    /// Each chunk's coverage per sample (bit i: lane i) in a multisample walk.
    covs: [[u8; SAMPLES]; MAX_BATCH],
    len: usize,
    /// The pending chunks' pixels: per 8-pixel block of the buffers (its index / 8, plus
    /// one; 0 is an empty slot) the lanes covered, by open addressing. A chunk covers at
    /// most two blocks, so a full batch fills at most half the table.
    cover: [(usize, u8); COVER],
    /// The slots of `cover` in use.
    used: [u8; 2 * MAX_BATCH],
    nused: usize,
    /// Whether `cover` holds the pending chunks: only once a second triangle's rows join
    /// the batch (a batch of one triangle's rows needs no check).
    tracking: bool,
}

/// Slots of [`State::cover`].
const COVER: usize = 4 * MAX_BATCH;
const _: () = assert!(COVER <= 256);

impl State {
    fn new() -> Box<State> {
        let chunk = ChunkIn {
            idx: 0,
            fx: 0.0,
            fy: 0.0,
            live: 0,
            planes: 0,
        };
        Box::new(State {
            scratch: Scratch::default(),
            chunks: [chunk; MAX_BATCH],
            ns: [0; MAX_BATCH],
            live_out: [0; MAX_BATCH],
            streams: vec![[0; 8]; STREAMS * MAX_BATCH],
            planes: vec![[0.0; 3]; SET * MAX_BATCH],
            sets: 0,
            first: 0,
            uniforms: [0.0; MAX_UNIFORMS],
            outs: Vec::new(),
            covs: [[0; SAMPLES]; MAX_BATCH],
            len: 0,
            cover: [(0, 0); COVER],
            used: [0; 2 * MAX_BATCH],
            nused: 0,
            tracking: false,
        })
    }

    /// Whether a pending chunk covers a pixel of the chunk at `idx` with lanes `live`
    /// (when not, the chunk's pixels become pending).
    #[inline]
    fn claim(&mut self, idx: usize, live: u8) -> bool {
        // The chunk's lanes in the 8-pixel blocks `idx / 8` and the one after.
        let m = u16::from(live) << (idx % 8);
        let blocks = [(idx / 8, m as u8), (idx / 8 + 1, (m >> 8) as u8)];
        for &(b, lanes) in &blocks {
            if lanes != 0 && self.cover_of(b).1 & lanes != 0 {
                return true;
            }
        }
        for &(b, lanes) in &blocks {
            if lanes != 0 {
                let (slot, _) = self.cover_of(b);
                if self.cover[slot].0 == 0 {
                    self.cover[slot].0 = b + 1;
                    self.used[self.nused] = slot as u8;
                    self.nused += 1;
                }
                self.cover[slot].1 |= lanes;
            }
        }
        false
    }

    /// The slot of block `b` in [`State::cover`] (its own or the empty one where it
    /// would go) and its pending lanes.
    #[inline]
    fn cover_of(&self, b: usize) -> (usize, u8) {
        let mut slot = (b.wrapping_mul(0x9E37_79B9) >> 7) % COVER;
        loop {
            let (key, lanes) = self.cover[slot];
            if key == b + 1 {
                return (slot, lanes);
            }
            if key == 0 {
                return (slot, 0);
            }
            slot = (slot + 1) % COVER;
        }
    }

    /// Forgets the pending pixels (the batch has run).
    #[inline]
    fn clear_cover(&mut self) {
        for &slot in &self.used[..self.nused] {
            self.cover[usize::from(slot)] = (0, 0);
        }
        self.nused = 0;
    }
}

thread_local! {
    /// The buffers of this thread's last walk.
    static STATE: std::cell::Cell<Option<Box<State>>> = const { std::cell::Cell::new(None) };
}

/// A walk through the engine of one triangle, or of consecutive triangles of one program
/// (see the module doc).
pub struct Walk {
    st: Box<State>,
    prog: Rc<Program>,
    /// Planes per triangle: those the program reads.
    set: usize,
    units: usize,
    blend: bool,
    writes: bool,
    count_samples: bool,
    /// The uniforms are the walk's own (else the triangle's flat varyings).
    own_uniforms: bool,
    /// The walk's triangles face front (the stencil face).
    front: bool,
    /// The plan whose colour store runs after the program ([`host_store`]).
    host: Option<Box<FragPlan>>,
    /// What the rows' pixel coordinates add: 0.5 in a multisample walk, whose planes are
    /// evaluated at the pixel centres (`crate::fragment::multisample`).
    centre: f32,
    /// The sample coverage of the next rows ([`Walk::cover`]), per row of a pair.
    next_cov: [[u8; SAMPLES]; 2],
}

/// Which triangles the engine shades (`SOFTGL_ENGINE`).
#[inline]
pub fn mode() -> crate::tuning::Engine {
    crate::tuning::tuning().engine
}

/// Whether the engine writes `fb`: an RGBA8 layout, not a wide buffer.
/// Whether a program's variant for `plan` drawing into `fb` leaves its colour store to
/// the walk ([`super::ff::tail_buffers`]' `host`): wide and sRGB targets, logic ops, and
/// the formats without a packed RGBA8 word, which the per-fragment stores of
/// [`crate::fragment::span`] write; and the plans whose stencil and depth tests the walk
/// runs ([`test_and_store`]: multisampling, Z32 depth).
pub fn host_store(plan: &FragPlan, fb: &Target<'_>) -> bool {
    !target_ok(fb) || plan.logic.is_some() || plan.srgb || super::ff::tests_in_walk(plan)
}

fn target_ok(fb: &Target<'_>) -> bool {
    fb.wide.is_none()
        && matches!(
            fb.format,
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb
        )
}

/// The live bits of 8 lanes (bit i: lane i).
#[inline]
fn bits_of(live: &[bool; LANES]) -> u8 {
    live.iter()
        .enumerate()
        .fold(0u8, |b, (i, &on)| b | u8::from(on) << i)
}

/// The index in the buffers of pixel `x` of row `py`.
#[inline]
fn idx_of(fb: &Target<'_>, py: usize, x: usize) -> usize {
    (py - fb.y0) * fb.width + x
}

impl Walk {
    /// The walk of a triangle drawn with `plan` and `units` into `fb` (`persp`: the
    /// varyings take the perspective divide), when the state lowers (the caller checks
    /// [`enabled`]).
    pub fn new(
        plan: &FragPlan,
        units: &[UnitPlan<'_>],
        persp: bool,
        fb: &Target<'_>,
    ) -> Option<Walk> {
        if !target_ok(fb)
            || units.is_empty()
            || units.len() > MAX_TEXTURE_UNITS
            || !super::ff::covers(plan)
        {
            return None;
        }
        let mut envs = [None; MAX_TEXTURE_UNITS];
        for (e, u) in envs.iter_mut().zip(units) {
            *e = Some(u.env);
        }
        let prog = cache::program(&FfState {
            plan: *plan,
            envs,
            units: units.len() as u8,
            persp,
        })?;
        let st = STATE.with(|s| s.take()).unwrap_or_else(State::new);
        Some(Walk {
            st,
            set: prog.planes().clamp(1, SET),
            prog,
            units: units.len(),
            blend: plan.blend.is_some(),
            writes: plan.color_mask != [false; 4],
            count_samples: plan.count_samples,
            own_uniforms: false,
            front: true,
            host: None,
            centre: 0.0,
            next_cov: [[0; SAMPLES]; 2],
        })
    }

    /// The walk of triangles facing `front` drawn with the compiled program `prog` into
    /// `fb` under `plan` (its stencil test too), whose uniform `k` is the bits
    /// `uniforms[k]` and which reads the texels of `units` lookups ([`Walk::row`]);
    /// `None` when the target or the plan is not one the engine draws.
    pub fn with_program(
        prog: Rc<Program>,
        plan: &FragPlan,
        uniforms: &[u32; MAX_UNIFORMS],
        units: usize,
        fb: &Target<'_>,
        front: bool,
    ) -> Option<Walk> {
        // A program's variant multiplies the smooth coverage in itself
        // (`ff::smooth_colors`).
        let tail = FragPlan {
            smooth: None,
            ..*plan
        };
        let host = host_store(plan, fb);
        let covered = match host {
            true => super::ff::covers_host_tail(&tail),
            false => super::ff::covers_tail(&tail),
        };
        if !covered || units > MAX_TEXTURE_UNITS {
            return None;
        }
        let mut st = STATE.with(|s| s.take()).unwrap_or_else(State::new);
        for (d, &u) in st.uniforms.iter_mut().zip(uniforms) {
            *d = f32::from_bits(u);
        }
        Some(Walk {
            st,
            set: prog.planes().clamp(1, SET),
            prog,
            units,
            blend: plan.blend.is_some(),
            writes: plan.color_mask != [false; 4],
            count_samples: plan.count_samples,
            own_uniforms: true,
            front,
            host: host.then(|| {
                Box::new(FragPlan {
                    shader: None,
                    ..*plan
                })
            }),
            centre: if plan.ms.is_some() { 0.5 } else { 0.0 },
            next_cov: [[0; SAMPLES]; 2],
        })
    }

    /// Starts triangle `t`: its planes (and for a fixed-function walk its flat
    /// varyings, the program's uniforms) become those of its rows. A fixed-function walk
    /// draws one triangle ([`Walk::end`] after its rows).
    #[inline]
    pub fn begin(&mut self, t: &SetupTriangle, fb: &mut Target<'_>, stats: &mut Stats) {
        self.begin_with(t, fb, stats, None)
    }

    /// [`Walk::begin`] for a program that samples with `tex` ([`Walk::pair`]).
    #[inline]
    pub fn begin_with(
        &mut self,
        t: &SetupTriangle,
        fb: &mut Target<'_>,
        stats: &mut Stats,
        tex: Option<&dyn TexSampler>,
    ) {
        if self.st.sets == MAX_BATCH {
            self.flush(fb, stats, tex);
            self.st.sets = 0;
        }
        let st = &mut *self.st;
        if st.sets > 0 && st.first == st.len {
            // The previous triangle left no rows: its set is free.
            st.sets -= 1;
        }
        let at = st.sets * self.set;
        planes_into(t, &mut st.planes[at..at + self.set]);
        st.sets += 1;
        st.first = st.len;
        if st.len > 0 && !st.tracking {
            // Rows of two triangles in one batch from here on: cover the pending ones.
            st.tracking = true;
            for k in 0..st.len {
                let c = st.chunks[k];
                st.claim(c.idx, c.live);
            }
        }
        if !self.own_uniforms {
            st.uniforms[..MAX_VARY].copy_from_slice(&t.flat);
        }
    }

    /// Adds the row of 8 pixels from `x` in row `py` of the current triangle with its
    /// `live` lanes and the units' texels `tex`; runs the batch first when a pending row
    /// of an earlier triangle shares a pixel with it, and after it when the batch is full.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn row(
        &mut self,
        fb: &mut Target<'_>,
        py: usize,
        x: usize,
        live: &[bool; LANES],
        tex: &TexLanes,
        stats: &mut Stats,
    ) {
        let bits = bits_of(live);
        if bits == 0 {
            return;
        }
        let idx = idx_of(fb, py, x);
        if self.st.tracking && self.st.claim(idx, bits) {
            self.flush(fb, stats, None);
        }
        stats.fragments += u64::from(bits.count_ones());
        self.push(idx, x, py, bits, LANES.min(fb.width - x), tex);
        if self.st.len == MAX_BATCH {
            self.flush(fb, stats, None);
        }
    }

    /// Appends the chunk of 8 pixels from `x` in row `py` (at `idx` in the buffers) with
    /// `live` lanes, `inside` of them inside the row, and the units' texels `tex`.
    #[inline]
    fn push(&mut self, idx: usize, x: usize, py: usize, live: u8, inside: usize, tex: &TexLanes) {
        let st = &mut *self.st;
        let k = st.len;
        st.chunks[k] = ChunkIn {
            idx,
            fx: x as f32 + self.centre,
            fy: py as f32 + self.centre,
            live,
            planes: ((st.sets - 1) * self.set) as u32,
        };
        st.ns[k] = inside as u8;
        st.covs[k] = self.next_cov[py & 1];
        for (u, lanes) in tex.iter().enumerate().take(self.units) {
            // Stream 4u + ch of chunk k.
            crate::simd::pack::channels_into(
                lanes,
                &mut st.streams,
                4 * u * MAX_BATCH + k,
                MAX_BATCH,
            );
        }
        st.len += 1;
    }

    /// Sets the sample coverage of the rows added next (a multisample walk): `cov[r][s]`
    /// bit i for sample s of lane i of the pair's row r (a lone row's parity picks r).
    #[inline]
    pub fn cover(&mut self, cov: [[u8; SAMPLES]; 2]) {
        self.next_cov = cov;
    }

    /// Whether the walk's program reads 2x2 quads ([`Program::quads`]): its rows come
    /// by [`Walk::pair`], not [`Walk::row`].
    #[inline]
    pub fn quads(&self) -> bool {
        self.prog.quads()
    }

    /// Adds the rows `qy` (even) and `qy + 1` of the 8 pixels from `x` (even) of the
    /// current triangle, with their `live` lanes and the units' texels `tex`, as one
    /// pair of chunks (both, when one has no live lane, so that the program sees whole
    /// quads); the program's own lookups sample with `sampler`. Runs the batch first
    /// when a pending row of an earlier triangle shares a pixel, and after when full.
    #[allow(clippy::too_many_arguments)]
    pub fn pair(
        &mut self,
        fb: &mut Target<'_>,
        qy: usize,
        x: usize,
        live: &[[bool; LANES]; 2],
        tex: &[TexLanes; 2],
        stats: &mut Stats,
        sampler: Option<&dyn TexSampler>,
    ) {
        let bits = live.map(|l| bits_of(&l));
        if bits == [0, 0] {
            return;
        }
        // A row without live lanes (it may lie below the buffer) addresses its
        // partner's pixels; no kernel touches them.
        let live_row = usize::from(bits[0] == 0);
        let idx = (qy + live_row - fb.y0) * fb.width + x;
        if self.st.tracking
            && (0..2).any(|r| bits[r] != 0 && self.st.claim(idx_of(fb, qy + r, x), bits[r]))
        {
            self.flush(fb, stats, sampler);
        }
        if self.st.len + 2 > MAX_BATCH {
            self.flush(fb, stats, sampler);
        }
        for (r, &b) in bits.iter().enumerate() {
            stats.fragments += u64::from(b.count_ones());
            let (at, inside) = match b {
                0 => (idx, 0),
                _ => (idx_of(fb, qy + r, x), LANES.min(fb.width - x)),
            };
            self.push(at, x, qy + r, b, inside, &tex[r]);
        }
        if self.st.len == MAX_BATCH {
            self.flush(fb, stats, sampler);
        }
    }

    /// Runs the gathered rows and counts their work; the current triangle's planes
    /// become the batch's first set.
    fn flush(&mut self, fb: &mut Target<'_>, stats: &mut Stats, tex: Option<&dyn TexSampler>) {
        if self.st.len != 0 {
            self.run(fb, stats, tex);
        }
        let st = &mut *self.st;
        st.clear_cover();
        st.tracking = false;
        st.len = 0;
        st.first = 0;
        if st.sets > 1 {
            let at = (st.sets - 1) * self.set;
            st.planes.copy_within(at..at + self.set, 0);
            st.sets = 1;
        }
    }

    /// Runs the gathered rows (at least one) and counts their work.
    fn run(&mut self, fb: &mut Target<'_>, stats: &mut Stats, tex: Option<&dyn TexSampler>) {
        let st = &mut *self.st;
        let n = st.len;
        let mut inputs: [&[[u32; 8]]; STREAMS] = [&[]; STREAMS];
        for (s, i) in inputs.iter_mut().enumerate().take(4 * self.units) {
            *i = &st.streams[s * MAX_BATCH..s * MAX_BATCH + n];
        }
        let per = self.prog.outputs();
        if st.outs.len() < n * per {
            st.outs.resize(n * per, [0; 8]);
        }
        let mut io = Io {
            outputs: &mut st.outs[..n * per],
            planes: &st.planes,
            inputs: &inputs[..4 * self.units],
            color: &mut *fb.color,
            more_colors: fb.more_colors.each_mut().map(|c| &mut **c),
            depth: &mut *fb.depth,
            stencil: &mut *fb.stencil,
            front: self.front,
            uniforms: &st.uniforms,
            live_out: &mut st.live_out[..n],
            sampler: tex,
        };
        let c = self.prog.run(&mut st.scratch, &mut io, &st.chunks[..n], n);
        stats.alpha_failed += c.killed;
        stats.depth_reads += c.depth_reads;
        stats.depth_failed += c.depth_failed;
        stats.stencil_reads += c.stencil_reads;
        stats.stencil_failed += c.stencil_failed;
        if let Some(plan) = &self.host {
            match super::ff::tests_in_walk(plan) {
                true => test_and_store(plan, st, n, per, (self.front, self.centre), fb, stats),
                false => store_outputs(plan, st, n, per, fb, stats),
            }
            return;
        }
        for (&out, &w) in st.live_out[..n].iter().zip(&st.ns[..n]) {
            let passed = u64::from(out.count_ones());
            if self.count_samples {
                stats.samples_passed += passed;
            }
            if self.writes && passed != 0 {
                if self.blend {
                    stats.color_reads += u64::from(w);
                }
                stats.color_writes += passed;
            }
        }
    }

    /// Runs the last rows and gives the buffers back to the thread.
    #[inline]
    pub fn end(self, fb: &mut Target<'_>, stats: &mut Stats) {
        self.end_with(fb, stats, None)
    }

    /// [`Walk::end`] for a program that samples with `tex` ([`Walk::pair`]).
    #[inline]
    pub fn end_with(
        mut self,
        fb: &mut Target<'_>,
        stats: &mut Stats,
        tex: Option<&dyn TexSampler>,
    ) {
        self.flush(fb, stats, tex);
        self.st.sets = 0;
        STATE.with(|s| s.set(Some(self.st)));
    }
}

/// Draw buffer `b`'s colours that a host-store program ([`host_store`]) left for chunk
/// `k` of `st` (`per` outputs per chunk; zeros where it wrote none).
fn colors_of(st: &State, k: usize, per: usize, b: usize) -> [[f32; LANES]; 4] {
    std::array::from_fn(|ch| match 4 * b + ch < per {
        true => st.outs[k * per + 4 * b + ch].map(f32::from_bits),
        false => [0.0; LANES],
    })
}

/// Stores chunk `k`'s colours at its `live` lanes as the fixed-function walk stores
/// them: draw buffer 0 of sample plane `s` through [`store_chunk`] (wide, sRGB, logic
/// ops and every format) and, single-sampled, draw buffers 1.. through
/// [`write_colors`].
#[allow(clippy::too_many_arguments)]
fn store_colors(
    plan: &FragPlan,
    st: &State,
    k: usize,
    per: usize,
    live: &[bool; LANES],
    s: usize,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    if per < 4 || plan.color_mask == [false; 4] {
        return;
    }
    let (idx, w) = (st.chunks[k].idx, usize::from(st.ns[k]));
    let bytes = |cf: &[[f32; LANES]; 4]| -> [[u8; LANES]; 4] {
        std::array::from_fn(|ch| cf[ch].map(unorm8))
    };
    let out = StoreFormat::of(fb);
    let cf = colors_of(st, k, per, 0);
    let mut rows = fb.plane(s);
    store_chunk::<true, true>(plan, out, &mut rows, (idx, w), live, bytes(&cf), &cf, stats);
    if plan.ms.is_some() {
        return;
    }
    for (b, more) in fb.more_colors.iter_mut().enumerate() {
        if plan.more_buffers & 1 << b == 0 || 4 * (b + 2) > per {
            continue;
        }
        let cf = colors_of(st, k, per, b + 1);
        let dst = &mut more[idx..idx + w];
        write_colors::<true>(plan, out.format, dst, bytes(&cf), live, stats);
    }
}

/// Stores the colours of the live lanes of the `n` chunks of `st` after a host-store
/// program that ran the tests itself; counts the samples passed.
fn store_outputs(
    plan: &FragPlan,
    st: &State,
    n: usize,
    per: usize,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    for k in 0..n {
        let bits = st.live_out[k];
        if plan.count_samples {
            stats.samples_passed += u64::from(bits.count_ones());
        }
        if bits != 0 {
            let live: [bool; LANES] = std::array::from_fn(|i| bits >> i & 1 != 0);
            store_colors(plan, st, k, per, &live, 0, fb, stats);
        }
    }
}

/// The tests and stores of a program that leaves its stencil and depth tests to the
/// walk ([`super::ff::tests_in_walk`]), as `crate::fragment::multisample` (or, single-
/// sampled, `crate::fragment::span`) runs them for fixed function: for each sample of
/// the plan's mask (one without multisampling), the chunk's live lanes (after the
/// program's discards and alpha test) that cover it and pass alpha to coverage; the
/// stencil and depth tests at the sample point (the z plane there, evaluated as the
/// level's fixed-function walks do, or the written depth clamped as
/// `lp_build_depth_clamp` does, [`super::ff::DEPTH_OUTPUT`]); and the store. `centre`:
/// what the chunks' coordinates add to the pixel's corner ([`Walk::centre`]).
#[allow(clippy::too_many_arguments)]
fn test_and_store(
    plan: &FragPlan,
    st: &State,
    n: usize,
    per: usize,
    (front, centre): (bool, f32),
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    use crate::fragment::span::{eval, quantize_depth, stencil_depth_q, Fused, Unfused};
    use crate::fragment::MsPass;
    let (mask, a2c) = plan
        .ms
        .map_or((1, false), |m| (m.mask, m.alpha_to_coverage));
    let tests = match plan.depth {
        Some(_) => stencil_depth_q::<true, true>,
        None => stencil_depth_q::<false, true>,
    };
    let fused = crate::cpu::isa().fused();
    let written = usize::from(super::ff::DEPTH_OUTPUT);
    for k in 0..n {
        let bits = st.live_out[k];
        if bits == 0 {
            continue;
        }
        let c = st.chunks[k];
        let (x, y) = (c.fx - centre, c.fy - centre);
        let alpha = colors_of(st, k, per, 0)[3];
        // `minps` with 1 then `maxps` with 0: NaN becomes 1.
        let shader_z = (per > written).then(|| {
            st.outs[k * per + written].map(|b| {
                let z = f32::from_bits(b);
                let z = if z < 1.0 { z } else { 1.0 };
                if z > 0.0 {
                    z
                } else {
                    0.0
                }
            })
        });
        let [a0, dadx, dady] = st.planes[c.planes as usize + usize::from(super::lower::PLANE_Z)];
        let zp = crate::geometry::setup::Plane { a0, dadx, dady };
        for s in 0..SAMPLES {
            if mask & (1 << s) == 0 {
                continue;
            }
            let (cov, [sx, sy]) = match plan.ms {
                Some(_) => (st.covs[k][s] & bits, MsPass::pos(s)),
                None => (bits, [0.0; 2]),
            };
            let mut ls: [bool; LANES] = std::array::from_fn(|i| cov >> i & 1 != 0);
            if a2c {
                let threshold = MsPass::coverage_threshold(s);
                for (l, &a) in ls.iter_mut().zip(&alpha) {
                    // NaN alpha keeps no sample, as the ordered compare.
                    *l &= a > threshold;
                }
            }
            if !ls.iter().any(|&l| l) {
                continue;
            }
            let q: [u32; LANES] = std::array::from_fn(|i| {
                let Some(d) = plan.depth else {
                    return 0;
                };
                let z = match &shader_z {
                    Some(z) => z[i],
                    None if fused => eval::<Fused>(&zp, x + i as f32 + sx, y + sy),
                    None => eval::<Unfused>(&zp, x + i as f32 + sx, y + sy),
                };
                quantize_depth(d.format, z)
            });
            let at = (c.idx, usize::from(st.ns[k]));
            tests(front, plan, &mut fb.plane(s), at, &q, &mut ls, stats);
            if ls.iter().any(|&l| l) {
                store_colors(plan, st, k, per, &ls, s, fb, stats);
            }
        }
    }
}
