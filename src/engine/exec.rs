//! The stage executor: an [`Ir`] compiled into a list of [`Step`]s (a precompiled
//! kernel and the register slots it reads and writes) and run over batches of 8-pixel
//! chunks.
//!
//! Compiling is register allocation and a table look-up per operation: every SSA value
//! gets a slot of a register file in L1 (a slot is freed after its last use; constants
//! get slots of their own, filled once per [`Program::run`] by the prologue, and so do
//! the pure operations whose operands are all per-run values: uniforms and what is
//! computed from them are hoisted out of the per-chunk body). Operations that nothing
//! with an effect needs are dropped first, and constants of the same bits share one slot
//! (a lowered shader reads whole variables and makes a constant per use: the lit,
//! textured fragment shader of `bench/scenes/shader_lit_tex.c` is 181 operations and 105
//! steps). Running
//! calls each step's kernel once per batch; the kernel loops over the batch's chunks, so
//! the indirect call is paid once per operation per batch, not per chunk.

use super::ir::{Blend8, Ir, Op, FCMPS, IOPS, UNS};
use super::kernels::{self, Kernel};
use crate::cpu::Isa;
use crate::fixed_function::fog::FogPlan;
use crate::framebuffer::draw_buffers::MORE_COLORS;
use crate::pipe::CompareFunc;

/// The most chunks one batch runs (a register slot holds one 8-lane value per chunk).
pub const MAX_BATCH: usize = 32;

/// The back-jumps of [`Op::LoopEnd`] a batch may take, over all of its loops: llvmpipe's
/// `LP_MAX_TGSI_LOOP_ITERATIONS`, the loop limiter it shares between every loop of a
/// shader (so a loop that never ends for some lane ends, as there).
pub const LOOP_LIMIT: u32 = 65535;

/// One compiled operation: its kernel, destination slot, operand slots and immediate.
#[derive(Clone, Copy)]
pub struct Step {
    /// The kernel.
    pub(super) k: Kernel,
    /// Destination slot (0 = the live mask for the fragment-interface operations).
    pub(super) d: u16,
    /// Operand slots.
    pub(super) a: [u16; 4],
    /// The operation's immediate (constant bits, plane, input, function code, ...).
    pub(super) imm: u32,
}

/// One chunk of 8 pixels: its first pixel's index in the colour and depth buffers, its
/// first pixel's x and its y as f32, its live lanes (bit i = lane i) and where its
/// triangle's planes start in the run's planes (one run may hold the chunks of several
/// triangles).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChunkIn {
    /// Index of lane 0 in the buffers.
    pub idx: usize,
    /// Pixel x of lane 0.
    pub fx: f32,
    /// Pixel y.
    pub fy: f32,
    /// Covered lanes.
    pub live: u8,
    /// The index in [`Io::planes`] of the chunk's plane 0.
    pub planes: u32,
}

/// A chunk pair's coordinates for [`TexSampler::sample`]: row 0 is the pair's first
/// chunk (the 2x2 quads' top row: the lower buffer row), row 1 the second.
pub struct QuadCoords {
    /// s per row and lane.
    pub s: [[f32; 8]; 2],
    /// t per row and lane.
    pub t: [[f32; 8]; 2],
    /// r (or a shadow lookup's reference) per row and lane.
    pub r: [[f32; 8]; 2],
    /// The lookup's level-of-detail argument per row and lane (0 without one).
    pub l: [[f32; 8]; 2],
    /// The lanes covered (a quad without one need not be sampled).
    pub live: [[bool; 8]; 2],
}

/// Samples the texture lookups a program computes the coordinates of ([`Op::Sample`]),
/// a chunk pair (two rows of 2x2 quads) at a time.
pub trait TexSampler {
    /// Samples lookup `lookup` at `c` into `out[row][lane]` (RGBA), for every quad that
    /// holds a live pixel (the others' texels may be left as they were); a lookup
    /// without a complete texture gives (0, 0, 0, 1).
    fn sample(&self, lookup: usize, c: &QuadCoords, out: &mut [[[f32; 4]; 8]; 2]);
}

/// What a run reads and writes besides its chunks.
pub struct Io<'a> {
    /// The planes [`Op::Interp`] evaluates, `[a0, dadx, dady]`: plane `p` of a chunk is
    /// `planes[chunk.planes + p]`.
    pub planes: &'a [[f32; 3]],
    /// The input streams [`Op::Input`] reads: one 8-lane value per chunk of the run.
    pub inputs: &'a [&'a [[u32; 8]]],
    /// The packed RGBA8 colour buffer (draw buffer 0).
    pub color: &'a mut [[u8; 4]],
    /// Draw buffers 1.., laid out as `color` (empty where the program writes none).
    pub more_colors: crate::framebuffer::draw_buffers::MoreRows<'a>,
    /// The depth buffer (may be empty when the program has no depth test).
    pub depth: &'a mut [u32],
    /// The stencil buffer (may be empty when the program has no stencil test).
    pub stencil: &'a mut [u8],
    /// The run's triangles face front (the stencil face [`Op::StencilDepth`] uses).
    pub front: bool,
    /// The uniforms [`Op::Uniform`] reads (per-triangle values such as flat colours).
    pub uniforms: &'a [f32],
    /// Receives each chunk's live lanes after the program (bit i = lane i), when it is
    /// at least as long as the chunks (left alone when empty).
    pub live_out: &'a mut [u8],
    /// Samples [`Op::Sample`]'s lookups (a program with one and no sampler gets
    /// (0, 0, 0, 1)).
    pub sampler: Option<&'a dyn TexSampler>,
    /// Receives [`Op::Output`]'s values: output `n` of chunk `k` at
    /// `k · Program::outputs() + n` (empty when the program has none; a fragment
    /// program's colours for a store outside the program, `engine::draw`).
    pub outputs: &'a mut [[u32; 8]],
}

/// The draw buffers of `io` as [`Ctx::colors`] holds them.
fn colors_of(io: &mut Io<'_>) -> [(*mut u32, usize); 1 + MORE_COLORS] {
    let mut out = [(std::ptr::null_mut(), 0); 1 + MORE_COLORS];
    out[0] = (io.color.as_mut_ptr() as *mut u32, io.color.len());
    for (o, m) in out[1..].iter_mut().zip(io.more_colors.iter_mut()) {
        *o = (m.as_mut_ptr() as *mut u32, m.len());
    }
    out
}

/// What a run counted: the lanes [`Op::Kill`] cleared, and the depth test's reads and
/// failures (as [`crate::stats::Stats`] counts them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Live lanes cleared by [`Op::Kill`] (the alpha test).
    pub killed: u64,
    /// Live lanes that reached [`Op::DepthTest`].
    pub depth_reads: u64,
    /// Of those, the lanes that failed it.
    pub depth_failed: u64,
    /// Live lanes that reached the stencil test ([`Op::StencilDepth`]).
    pub stencil_reads: u64,
    /// Of those, the lanes that failed it.
    pub stencil_failed: u64,
}

/// The state a kernel sees: the register file, the batch, and the run's buffers.
pub struct Ctx<'a> {
    regs: *mut [u32; 8],
    stride: usize,
    /// Chunks in this batch.
    pub(super) n: usize,
    /// Index of the batch's first chunk in the run (for the input streams).
    pub(super) base: usize,
    chunks: &'a [ChunkIn],
    /// The run's planes.
    pub(super) planes: &'a [[f32; 3]],
    /// The run's input streams.
    pub(super) inputs: &'a [&'a [[u32; 8]]],
    /// The program's blend plans.
    pub(super) blends: &'a [Blend8],
    /// The program's fog plans.
    pub(super) fogs: &'a [FogPlan],
    /// The run's uniforms.
    pub(super) uniforms: &'a [f32],
    /// The run's counts so far.
    pub(super) counts: Counts,
    /// Each draw buffer and its length ([`Op::LoadColor`]'s index).
    pub(super) colors: [(*mut u32, usize); 1 + MORE_COLORS],
    /// The depth buffer and its length.
    pub(super) depth: *mut u32,
    pub(super) depth_len: usize,
    /// The stencil buffer (a live lane lies inside it: `Program::run` checks).
    pub(super) stencil: *mut u8,
    /// The program's stencil plans ([`Op::StencilDepth`]).
    pub(super) stencils: &'a [crate::fragment::StencilPlan],
    /// The run's face.
    pub(super) front: bool,
    /// The outputs [`Op::Output`] writes (`outs_per` values per chunk), null when the
    /// program has none.
    pub(super) outs: *mut [u32; 8],
    pub(super) outs_per: usize,
    /// The run's sampler for [`Op::Sample`].
    pub(super) sampler: Option<&'a dyn TexSampler>,
    /// The texels [`Op::Sample`] writes and [`Op::Texel`] reads: stream n of batch chunk
    /// k at `n · MAX_BATCH + k` ([`TEXEL_STREAMS`] streams), null when the program
    /// samples nothing.
    pub(super) texels: *mut [u32; 8],
    /// The body step to go on at, set by [`Op::LoopEnd`]'s kernel.
    pub(super) jump: Option<usize>,
    /// The back-jumps the batch may still take ([`LOOP_LIMIT`]).
    pub(super) limiter: u32,
}

/// The streams of [`Ctx::texels`]: four channels per lookup.
pub const TEXEL_STREAMS: usize = 4 * crate::pipe::MAX_TEXTURE_UNITS;

impl Ctx<'_> {
    /// Slot `slot` of chunk `k` of the batch.
    #[inline(always)]
    pub(super) fn reg(&self, slot: u16, k: usize) -> *mut [u32; 8] {
        // Slots times the stride stay inside the register file (`Program::run` sizes it).
        self.regs.wrapping_add(slot as usize * self.stride + k)
    }

    /// Chunk `k` of the batch.
    #[inline(always)]
    pub(super) fn chunk(&self, k: usize) -> ChunkIn {
        self.chunks[self.base + k]
    }
}

/// The compare functions in the order of their codes in a step's immediate.
pub(super) const FUNCS: [CompareFunc; 8] = CompareFunc::ALL;

/// The code of a compare function in a step's immediate.
fn func_code(f: CompareFunc) -> u32 {
    FUNCS.iter().position(|&g| g == f).unwrap_or(0) as u32
}

/// The compare function of a step's immediate ([`func_code`]'s inverse).
#[inline(always)]
pub(super) fn func_of(code: u32) -> CompareFunc {
    FUNCS[code as usize & 7]
}

/// A compiled program: prologue (constants), body, the slot count, and the blend plans
/// its steps name.
#[derive(Clone)]
pub struct Program {
    prologue: Vec<Step>,
    body: Vec<Step>,
    slots: usize,
    blends: Vec<Blend8>,
    fogs: Vec<FogPlan>,
    stencils: Vec<crate::fragment::StencilPlan>,
    planes: usize,
    inputs: usize,
    uniforms: usize,
    depth: bool,
    outputs: usize,
    /// The program reads pixel positions or the colour buffer.
    pixels: bool,
    /// Bit n: the program reads or writes draw buffer n.
    buffers: u8,
    /// The program reads across the chunks of a pair ([`Program::quads`]).
    quads: bool,
    /// The program samples ([`Op::Sample`]).
    samples: bool,
    /// The program tests stencil ([`Op::StencilDepth`]).
    stencil: bool,
    /// The program has loops ([`Op::LoopEnd`]): its body runs with jumps.
    loops: bool,
}

/// Whether code for `want` may run where [`crate::cpu::isa`] reports `have`.
pub fn isa_allowed(want: Isa, have: Isa) -> bool {
    want == have || want == Isa::Base || (have == Isa::Avx2Fma && want == Isa::Fma)
}

/// Compiles `ir` for the detected instruction-set level.
pub fn compile(ir: &Ir) -> Program {
    compile_for(ir, crate::cpu::isa())
}

/// Compiles `ir` for level `isa`.
///
/// # Panics
/// When `isa` is not allowed on this CPU ([`isa_allowed`]), the program needs more
/// than `u16::MAX` slots, or samples a lookup beyond [`TEXEL_STREAMS`]` / 4`.
pub fn compile_for(ir: &Ir, isa: Isa) -> Program {
    assert!(isa_allowed(isa, crate::cpu::isa()), "{isa:?} on this CPU");
    let t = kernels::table(isa);
    let n = ir.ops.len();
    let live = live_ops(ir);
    let mut last = vec![usize::MAX; n];
    for (i, op) in ir.ops.iter().enumerate().filter(|&(i, _)| live[i]) {
        for v in op.operands() {
            last[v.0 as usize] = i;
        }
    }
    // Constants of the same bits share one slot (the lowering makes one per use).
    let mut consts: std::collections::HashMap<u32, u16> = std::collections::HashMap::new();
    let mut slot = vec![0u16; n];
    let mut hoisted = vec![false; n];
    let mut free: Vec<u16> = Vec::new();
    // Slot 0 is the live mask, slots 1..=vars the mutable variables.
    let vars = ir
        .ops
        .iter()
        .filter_map(|op| match *op {
            Op::VarLoad(n, _) | Op::VarStore(n, _) => Some(n + 1),
            _ => None,
        })
        .max()
        .unwrap_or(0);
    let mut next = 1 + vars;
    extend_over_loops(ir, &live, &mut last);
    let mut loop_starts: std::collections::HashMap<u16, usize> = Default::default();
    let mut p = Program {
        prologue: Vec::new(),
        body: Vec::new(),
        slots: 0,
        blends: Vec::new(),
        fogs: Vec::new(),
        stencils: Vec::new(),
        planes: 0,
        inputs: 0,
        uniforms: 0,
        depth: false,
        outputs: 0,
        pixels: false,
        buffers: 0,
        quads: false,
        samples: false,
        stencil: false,
        loops: false,
    };
    for (i, op) in ir.ops.iter().enumerate() {
        if !live[i] {
            continue;
        }
        let ops = op.operands();
        let a = {
            let mut a = [0u16; 4];
            for (k, v) in ops.iter().enumerate() {
                a[k] = slot[v.0 as usize];
            }
            a
        };
        if let Op::Const(_, bits) = *op {
            hoisted[i] = true;
            if let Some(&s) = consts.get(&bits) {
                slot[i] = s;
                continue;
            }
            slot[i] = next;
            consts.insert(bits, next);
            next += 1;
            let step = Step {
                k: t.constant,
                d: slot[i],
                a,
                imm: bits,
            };
            p.prologue.push(step);
            continue;
        }
        // An operation of per-run values only (uniforms, constants and what is computed
        // from them) runs once per run in the prologue, in a slot of its own.
        let hoist =
            ir.types[i].is_some() && hoistable(op) && ops.iter().all(|v| hoisted[v.0 as usize]);
        if hoist {
            hoisted[i] = true;
            slot[i] = next;
            next += 1;
        }
        // Operands whose last use this is give their slots back first: a kernel reads a
        // chunk's operands before it writes that chunk's result.
        for v in &ops {
            let vi = v.0 as usize;
            if !hoist && last[vi] == i && !hoisted[vi] && !free.contains(&slot[vi]) {
                free.push(slot[vi]);
            }
        }
        let defines = ir.types[i].is_some();
        let d = if hoist {
            slot[i]
        } else if defines {
            let s = free.pop().unwrap_or_else(|| {
                next += 1;
                next - 1
            });
            slot[i] = s;
            s
        } else {
            0
        };
        let (k, imm): (Kernel, u32) = match *op {
            Op::Const(..) => unreachable!("handled above"),
            Op::Fog(_, f) => {
                p.fogs.push(f);
                (t.fog, (p.fogs.len() - 1) as u32)
            }
            Op::FragX => {
                p.pixels = true;
                (t.frag_x, 0)
            }
            Op::FragY => {
                p.pixels = true;
                (t.frag_y, 0)
            }
            Op::Interp(n) => {
                p.planes = p.planes.max(n as usize + 1);
                (t.interp, n as u32)
            }
            Op::Input(n) | Op::InputF(n) => {
                p.inputs = p.inputs.max(n as usize + 1);
                (t.input, n as u32)
            }
            Op::Uniform(n) => {
                p.uniforms = p.uniforms.max(n as usize + 1);
                (t.uniform, n as u32)
            }
            Op::And(..) => (t.and, 0),
            Op::Or(..) => (t.or, 0),

            Op::Add(..) => (t.add, 0),
            Op::Sub(..) => (t.sub, 0),
            Op::Mul(..) => (t.mul, 0),
            Op::Div(..) => (t.div, 0),
            Op::Min(..) => (t.min, 0),
            Op::Max(..) => (t.max, 0),
            Op::Mad(..) => (t.mad, 0),
            Op::Sat(_) => (t.sat, 0),
            Op::CvtRne(_) => (t.cvt, 0),
            Op::Bits(_) => (t.bits, 0),
            Op::FCmp(c, ..) => (t.fcmp, code_of(&FCMPS, c)),
            Op::SCmp(c, ..) => (t.scmp, code_of(&FCMPS, c)),
            Op::Un(u, _) => (t.unary, code_of(&UNS, u)),
            Op::IBin(o, ..) => (t.ibin, code_of(&IOPS, o)),
            Op::Pow(..) => (t.pow, 0),
            Op::Xor(..) => (t.xor, 0),
            Op::ItoF(_) => (t.itof, 0),
            Op::FtoI(_) => (t.ftoi, 0),
            Op::FromBits(_) => (t.from_bits, 0),
            Op::ICmp(f, ..) => (t.icmp, func_code(f)),
            Op::Byte(_, b) => (t.byte, b as u32),
            Op::UnpackUnorm8(_, b) => (t.unpack, b as u32),
            Op::PackUnorm8(_) => (t.pack, 0),
            Op::Select(..) => (t.select, 0),
            Op::Kill(_) => (t.kill, 0),
            Op::DepthTest { func, write, .. } => {
                p.depth = true;
                (t.depth, func_code(func) | (write as u32) << 8)
            }
            Op::StencilDepth { stencil, depth, .. } => {
                p.depth |= depth.is_some();
                p.stencil = true;
                p.stencils.push(stencil);
                let (func, write) = depth.unwrap_or((crate::pipe::CompareFunc::Always, false));
                let imm = (p.stencils.len() - 1) as u32
                    | func_code(func) << 16
                    | u32::from(write) << 20
                    | u32::from(depth.is_some()) << 21;
                (t.stencil_depth, imm)
            }
            Op::LoadColor(n) => {
                p.pixels = true;
                p.buffers |= 1 << n;
                (t.load_color, u32::from(n))
            }
            Op::Blend(b, ..) => {
                let over = cfg!(target_arch = "x86_64") && is_over(&b);
                p.blends.push(b);
                (t.blend, (p.blends.len() - 1) as u32 | (over as u32) << 16)
            }
            Op::StoreColor(n, _) => {
                p.pixels = true;
                p.buffers |= 1 << n;
                (t.store_color, u32::from(n))
            }
            Op::Output(n, _) => {
                p.outputs = p.outputs.max(n as usize + 1);
                (t.output, n as u32)
            }
            Op::Ddx(_) => {
                p.quads = true;
                (t.ddx, 0)
            }
            Op::Ddy(_) => {
                p.quads = true;
                (t.ddy, 0)
            }
            Op::Sample { lookup, .. } => {
                assert!(usize::from(lookup) < TEXEL_STREAMS / 4, "lookup {lookup}");
                p.quads = true;
                p.samples = true;
                (t.sample, u32::from(lookup))
            }
            Op::Texel(n) => {
                assert!(usize::from(n) < TEXEL_STREAMS, "texel stream {n}");
                p.samples = true;
                (t.texel, u32::from(n))
            }
            Op::VarLoad(..) | Op::VarStore(..) => (t.copy, 0),
            Op::LoopBegin(n) => {
                loop_starts.insert(n, p.body.len());
                continue;
            }
            Op::LoopEnd(n, _) => {
                p.loops = true;
                let start = loop_starts.get(&n).copied();
                (
                    t.loop_end,
                    start.expect("LoopEnd after its LoopBegin") as u32,
                )
            }
        };
        // A variable's slot is the source of a load and the destination of a store.
        let (d, a) = match *op {
            Op::VarLoad(n, _) => (d, [1 + n, 0, 0, 0]),
            Op::VarStore(n, _) => (1 + n, a),
            _ => (d, a),
        };
        if hoist {
            p.prologue.push(Step { k, d, a, imm });
            continue;
        }
        p.body.push(Step { k, d, a, imm });
        if defines && last[i] == usize::MAX {
            free.push(d);
        }
    }
    p.slots = next as usize;
    p
}

/// Keeps the values a loop's body uses but does not define alive to the loop's end: the
/// body runs again from its start, and reads them again.
fn extend_over_loops(ir: &Ir, live: &[bool], last: &mut [usize]) {
    let mut begins: std::collections::HashMap<u16, usize> = Default::default();
    for (j, op) in ir.ops.iter().enumerate() {
        match *op {
            Op::LoopBegin(n) => {
                begins.insert(n, j);
            }
            Op::LoopEnd(n, _) => {
                let Some(&b) = begins.get(&n) else { continue };
                for (i, o) in ir.ops.iter().enumerate().take(j + 1).skip(b) {
                    if !live[i] {
                        continue;
                    }
                    for v in o.operands() {
                        let vi = v.0 as usize;
                        if vi < b && last[vi] != usize::MAX {
                            last[vi] = last[vi].max(j);
                        }
                    }
                }
            }
            _ => {}
        }
    }
}

/// Which operations a program needs: those with an effect (they define no value, or
/// kill lanes, test depth, store colour or write an output) and, transitively, their
/// operands. The lowering of a shader reads whole variables (all of `gl_TexCoord[]`'s
/// 32 planes for one `.st`) and leaves dead values; they cost no step.
fn live_ops(ir: &Ir) -> Vec<bool> {
    let mut live = vec![false; ir.ops.len()];
    for (i, op) in ir.ops.iter().enumerate().rev() {
        let effect = ir.types[i].is_none()
            || matches!(
                op,
                Op::Kill(_)
                    | Op::DepthTest { .. }
                    | Op::StencilDepth { .. }
                    | Op::StoreColor(..)
                    | Op::Output(..)
            );
        if effect || live[i] {
            live[i] = true;
            for v in op.operands() {
                live[v.0 as usize] = true;
            }
        }
    }
    live
}

/// The code of `x` in a step's immediate: its index in `list`.
fn code_of<T: PartialEq>(list: &[T], x: T) -> u32 {
    list.iter().position(|y| *y == x).unwrap_or(0) as u32
}

/// Whether `op` computes per run when its operands do: a pure operation of its operands
/// (not the pixel's position, an input stream or the fragment interface).
fn hoistable(op: &Op) -> bool {
    !matches!(
        op,
        Op::FragX
            | Op::FragY
            | Op::Interp(_)
            | Op::Input(_)
            | Op::InputF(_)
            | Op::Kill(_)
            | Op::DepthTest { .. }
            | Op::StencilDepth { .. }
            | Op::LoadColor(_)
            | Op::Blend(..)
            | Op::StoreColor(..)
            | Op::Output(..)
            | Op::Ddx(_)
            | Op::Ddy(_)
            | Op::Sample { .. }
            | Op::Texel(_)
            | Op::VarLoad(..)
    )
}

/// Whether `b` is the "over" blend the AVX2 backend has a dedicated kernel for.
fn is_over(b: &Blend8) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        crate::fragment::simd::blend_is_over(b)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = b;
        false
    }
}

/// The register file a program runs in, reused from run to run.
#[derive(Default)]
pub struct Scratch {
    regs: Vec<[u32; 8]>,
    /// [`Ctx::texels`], allocated by the first program that samples.
    texels: Vec<[u32; 8]>,
}

impl Program {
    /// The number of steps (prologue and body).
    pub fn len(&self) -> usize {
        self.prologue.len() + self.body.len()
    }

    /// The steps that run once per run (constants and hoisted per-run values).
    pub fn prologue_len(&self) -> usize {
        self.prologue.len()
    }

    /// Whether the program has no steps.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The planes it reads: one more than the highest [`Op::Interp`] index (0 for none).
    pub fn planes(&self) -> usize {
        self.planes
    }

    /// The register slots it needs per chunk.
    pub fn slots(&self) -> usize {
        self.slots
    }

    /// Whether the program reads across the two chunks of a pair (derivatives, texture
    /// lookups at computed coordinates): its chunks must come in pairs, the rows `y` and
    /// `y + 1` of the same pixels with `y` even (2x2 quads), at even indices of the run,
    /// and it must run in batches of an even size.
    pub fn quads(&self) -> bool {
        self.quads
    }

    /// Runs the program over `chunks`, `batch` chunks (at most [`MAX_BATCH`]) per kernel
    /// call.
    ///
    /// # Panics
    /// When a chunk's live lanes lie outside the colour buffer (or the depth buffer, when
    /// the program tests depth), when an input stream is shorter than `chunks`, or when
    /// the program names a plane or an input that `io` lacks.
    pub fn run(
        &self,
        scratch: &mut Scratch,
        io: &mut Io<'_>,
        chunks: &[ChunkIn],
        batch: usize,
    ) -> Counts {
        let stride = match self.quads {
            // Pairs stay in one batch.
            true => batch.clamp(2, MAX_BATCH) & !1,
            false => batch.clamp(1, MAX_BATCH),
        };
        assert!(
            io.outputs.len() >= chunks.len() * self.outputs,
            "too few outputs"
        );
        assert!(io.inputs.len() >= self.inputs);
        assert!(io.uniforms.len() >= self.uniforms);
        let live_out = io.live_out.len() >= chunks.len();
        assert!(io.inputs.iter().all(|s| s.len() >= chunks.len()));
        for c in chunks {
            let end = c.idx + (8 - c.live.leading_zeros() as usize);
            assert!(
                c.live == 0 || end <= io.color.len(),
                "chunk outside the colour buffer"
            );
            for (k, m) in io.more_colors.iter().enumerate() {
                assert!(
                    c.live == 0 || self.buffers & 2 << k == 0 || end <= m.len(),
                    "chunk outside draw buffer {}",
                    k + 1
                );
            }
            assert!(c.live == 0 || io.depth.is_empty() || end <= io.depth.len());
            assert!(c.planes as usize + self.planes <= io.planes.len());
        }
        if self.depth {
            assert!(chunks.iter().all(|c| c.live == 0 || !io.depth.is_empty()));
        }
        if self.stencil {
            assert!(chunks.iter().all(|c| {
                c.live == 0 || c.idx + (8 - c.live.leading_zeros() as usize) <= io.stencil.len()
            }));
        }
        let need = self.slots * stride;
        if scratch.regs.len() < need {
            scratch.regs.resize(need, [0; 8]);
        }
        if self.samples && scratch.texels.is_empty() {
            scratch.texels = vec![[0; 8]; TEXEL_STREAMS * MAX_BATCH];
        }
        let mut ctx = Ctx {
            regs: scratch.regs.as_mut_ptr(),
            stride,
            n: stride,
            base: 0,
            chunks,
            planes: io.planes,
            inputs: io.inputs,
            blends: &self.blends,
            fogs: &self.fogs,
            uniforms: io.uniforms,
            counts: Counts::default(),
            colors: colors_of(io),
            depth: io.depth.as_mut_ptr(),
            depth_len: io.depth.len(),
            stencil: io.stencil.as_mut_ptr(),
            stencils: &self.stencils,
            front: io.front,
            outs: io.outputs.as_mut_ptr(),
            outs_per: self.outputs,
            sampler: io.sampler,
            texels: match self.samples {
                true => scratch.texels.as_mut_ptr(),
                false => std::ptr::null_mut(),
            },
            jump: None,
            limiter: LOOP_LIMIT,
        };
        // SAFETY: the steps' slots are below `self.slots` (compile) and the register file
        // holds `slots * stride` values; the chunks' live lanes lie in the buffers
        // (checked above), as do the chunks' outputs; the kernels were chosen for a level
        // this CPU has (compile).
        unsafe {
            for s in &self.prologue {
                (s.k)(&mut ctx, s);
            }
            let mut base = 0;
            while base < chunks.len() {
                let n = stride.min(chunks.len() - base);
                ctx.n = n;
                ctx.base = base;
                for k in 0..n {
                    *ctx.reg(0, k) = live_lanes(chunks[base + k].live);
                }
                self.run_body(&mut ctx);
                if live_out {
                    for k in 0..n {
                        io.live_out[base + k] = live_bits(&*ctx.reg(0, k));
                    }
                }
                base += n;
            }
        }
        ctx.counts
    }
}

impl Program {
    /// Runs the body's steps over the batch in `ctx`: in order, or, for a program with
    /// loops, from the step each [`Op::LoopEnd`] jumps back to, with the batch's loop
    /// limiter full.
    ///
    /// # Safety
    /// As a kernel's: the steps' slots lie in `ctx`'s register file and its chunks' live
    /// lanes in its buffers ([`Program::run`], [`Program::run_streams`]).
    #[inline(always)]
    unsafe fn run_body(&self, ctx: &mut Ctx<'_>) {
        // SAFETY: the caller's promise, for every step.
        unsafe {
            if !self.loops {
                for s in &self.body {
                    (s.k)(ctx, s);
                }
                return;
            }
            ctx.limiter = LOOP_LIMIT;
            let mut i = 0;
            while let Some(s) = self.body.get(i) {
                (s.k)(ctx, s);
                i = ctx.jump.take().unwrap_or(i + 1);
            }
        }
    }

    /// The outputs per chunk the program writes ([`Op::Output`]).
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// Runs a program without fragment interface (a vertex shader) over `chunks` chunks
    /// of 8 lanes in batches of [`MAX_BATCH`]: [`Op::Input`] streams from `inputs` (one
    /// value per chunk), [`Op::Uniform`] from `uniforms`, and each chunk's outputs into
    /// `outputs[chunk · self.outputs() + n]`.
    ///
    /// # Panics
    /// When the program reads planes, pixel positions or buffers, when a stream is
    /// shorter than `chunks`, or when `outputs` is too short.
    pub fn run_streams(
        &self,
        scratch: &mut Scratch,
        inputs: &[&[[u32; 8]]],
        uniforms: &[f32],
        outputs: &mut [[u32; 8]],
        chunks: usize,
    ) {
        assert!(self.planes == 0 && !self.depth && !self.pixels && !self.quads && !self.samples);
        assert!(!self.stencil);
        assert!(inputs.len() >= self.inputs && inputs.iter().all(|s| s.len() >= chunks));
        assert!(uniforms.len() >= self.uniforms);
        assert!(outputs.len() >= chunks * self.outputs);
        // Only the pixel and buffer kernels read a chunk (asserted absent above): these
        // are placeholders.
        let lanes = [ChunkIn {
            idx: 0,
            fx: 0.0,
            fy: 0.0,
            live: 0xFF,
            planes: 0,
        }; MAX_BATCH];
        let need = self.slots * MAX_BATCH;
        if scratch.regs.len() < need {
            scratch.regs.resize(need, [0; 8]);
        }
        let mut ctx = Ctx {
            regs: scratch.regs.as_mut_ptr(),
            stride: MAX_BATCH,
            n: MAX_BATCH,
            base: 0,
            chunks: &lanes,
            planes: &[],
            inputs,
            blends: &[],
            fogs: &self.fogs,
            uniforms,
            counts: Counts::default(),
            colors: [(std::ptr::null_mut(), 0); 1 + MORE_COLORS],
            depth: std::ptr::null_mut(),
            depth_len: 0,
            stencil: std::ptr::null_mut(),
            stencils: &[],
            front: true,
            outs: outputs.as_mut_ptr(),
            outs_per: self.outputs,
            sampler: None,
            texels: std::ptr::null_mut(),
            jump: None,
            limiter: LOOP_LIMIT,
        };
        // SAFETY: as in `run`; the outputs hold `chunks · self.outputs` values (checked)
        // and a step's output index is below `self.outputs` (compile); no step reads a
        // chunk or a buffer (asserted above).
        unsafe {
            for s in &self.prologue {
                (s.k)(&mut ctx, s);
            }
            let mut base = 0;
            while base < chunks {
                let n = MAX_BATCH.min(chunks - base);
                ctx.n = n;
                ctx.base = base;
                for k in 0..n {
                    *ctx.reg(0, k) = [u32::MAX; 8];
                }
                self.run_body(&mut ctx);
                base += n;
            }
        }
    }
}

/// The live bits of a lane mask (bit i: lane i).
#[inline(always)]
fn live_bits(m: &[u32; 8]) -> u8 {
    m.iter()
        .enumerate()
        .fold(0, |acc, (i, &v)| acc | (((v >> 31) as u8) << i))
}

/// The lane mask of 8 live bits.
#[inline(always)]
fn live_lanes(bits: u8) -> [u32; 8] {
    std::array::from_fn(|i| 0u32.wrapping_sub((bits >> i & 1) as u32))
}
