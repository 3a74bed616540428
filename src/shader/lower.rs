//! Lowering a checked fragment shader ([`softgl_glsl::hir`]) into the engine's IR.
//!
//! Every GLSL value becomes one SSA value per scalar component (vectors, matrices column
//! by column, arrays and structs flattened): floats are [`Ty::F32`], `int`/`uint`
//! [`Ty::I32`], `bool` [`Ty::Mask`]. Variables live in an environment from variable to
//! components; an assignment rebinds them.
//!
//! Control flow becomes masks: an `if` on a varying condition lowers both sides, each
//! under its condition, and an assignment under a mask is `Select(mask, new, old)`; an
//! `if` whose condition folds to a constant lowers only its taken side. Loops are unrolled
//! while their condition folds to a constant (counters are folded as they are computed);
//! `break`, `continue` and `return` clear their lanes from the mask for the rest of the
//! loop or function. User functions are inlined. `discard` is [`Op::Kill`] of the masked
//! lanes.
//!
//! Inputs: uniforms are [`Op::Uniform`] slots, one per scalar component ([`Lowered::uniforms`]),
//! so their arithmetic is hoisted into the program's prologue by the executor; varyings
//! (and the compatibility inputs such as `gl_Color`) are planes ([`Lowered::varyings`]),
//! perspective-corrected as llvmpipe does (`a_plane · (1 / w_plane)`, plane
//! [`PLANE_INV_W`]); `gl_FragCoord` is the pixel centre, the z plane [`PLANE_Z`] and 1/w.
//! The arithmetic of each built-in function is llvmpipe's (see [`super::builtins`]).
//!
//! Outputs: the colours ([`Lowered::colors`]) and a written `gl_FragDepth`
//! ([`Lowered::depth`]), which the draw's tail tests instead of the z plane
//! (`crate::engine::ff::tail_buffers`).

use super::control::{FnFrame, LoopFrame};
pub use super::texture::TexUse;
use crate::engine::ir::{Builder, FCmp, IOp, Ir, Op, Ty, Un, Val};
use softgl_glsl::builtins::variables::Kind as BKind;
use softgl_glsl::hir::{self, Const, Storage, Value, VarId};
use softgl_glsl::types::{Scalar, Type};
use std::collections::HashMap;

/// The plane of 1/w (llvmpipe's position w slot).
pub const PLANE_INV_W: u16 = 0;
/// The plane of window z.
pub const PLANE_Z: u16 = 1;
/// The first varying plane.
pub const FIRST_VARYING_PLANE: u16 = 2;

/// A named input of the lowered program: its first uniform slot or plane, and how many.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Slot {
    /// The GLSL name.
    pub name: String,
    /// The first uniform slot ([`Op::Uniform`]) or plane ([`Op::Interp`]).
    pub first: u16,
    /// The number of scalar components.
    pub count: u16,
    /// The components' scalar types, in order (an int's uniform slot holds its bits).
    pub scalars: Vec<Scalar>,
    /// A varying without perspective correction (`flat` or `noperspective`).
    pub linear: bool,
}

/// The draw buffers a fragment shader may write (`gl_MaxDrawBuffers`).
pub const MAX_DRAW_BUFFERS: usize = 8;

/// A lowered fragment shader: the program (without an output stage), the colour it
/// leaves in each draw buffer (`gl_FragColor`, the first user output, or
/// `gl_FragData[k]`), and where its inputs go.
#[derive(Clone, Debug)]
pub struct Lowered {
    /// The program.
    pub ir: Ir,
    /// Draw buffer 0's colour, four channels (`colors[0]`).
    pub color: [Val; 4],
    /// Each draw buffer's colour ([`MAX_DRAW_BUFFERS`]: glDrawBuffers' limit).
    pub colors: [[Val; 4]; MAX_DRAW_BUFFERS],
    /// The uniforms read, in the order of their slots.
    pub uniforms: Vec<Slot>,
    /// The varyings read, in the order of their planes.
    pub varyings: Vec<Slot>,
    /// The shader reads `gl_FrontFacing`: the uniform slot named [`FRONT_FACING`], which
    /// the draw sets per triangle (1 for a front face).
    pub front_facing: bool,
    /// The texture lookups, in the order of their input streams (lookup `k`'s texel is
    /// streams `4k..4k + 4`, [`Op::InputF`]).
    pub textures: Vec<TexUse>,
    /// The value written to `gl_FragDepth`, which replaces the interpolated depth in the
    /// tests (`None` when the shader never writes it).
    pub depth: Option<Val>,
}

/// What the lowering of a shader for a draw depends on besides the shader.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    /// The rows are stored top-down in a target of this height: `gl_FragCoord.y` is
    /// `height − (row + 0.5)` (exact in f32), as Mesa's window-position transform gives
    /// it; `None`: `row + 0.5`.
    pub flip_height: Option<f32>,
    /// glShadeModel(GL_FLAT): `gl_Color` and `gl_SecondaryColor` are the provoking
    /// vertex's values, read from constant planes without the perspective divide (as
    /// `flat` varyings are).
    pub flat_colors: bool,
    /// The run's pixel coordinates ([`Op::FragX`], [`Op::FragY`]) are pixel centres (a
    /// multisample walk evaluates the planes there): `gl_FragCoord.xy` adds no 0.5.
    pub centred: bool,
}

/// The uniform slot name of `gl_FrontFacing` (not a uniform of the program: the draw
/// sets the word per triangle).
pub const FRONT_FACING: &str = "gl_FrontFacing";

/// The uniform that carries `gl_InstanceID` (and ARB_draw_instanced's `gl_InstanceIDARB`)
/// into a vertex shader: the draw runs once per instance and supplies it as built-in
/// state (`context::instanced`).
pub const INSTANCE_ID: &str = "gl_InstanceID";

/// The elements of `gl_TexCoord[]` (unsized in the shader): `gl_MaxTextureCoords`.
pub const TEX_COORDS: u32 = 8;

/// Why a shader does not lower (yet).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unsupported(pub String);

/// The result of a lowering step.
pub(super) type R<T> = Result<T, Unsupported>;

/// An error `Unsupported` with a message.
pub(super) fn no<T>(what: impl Into<String>) -> R<T> {
    Err(Unsupported(what.into()))
}

/// The scalar types of a type's flattened components.
pub(super) fn scalars(ty: &Type, out: &mut Vec<Scalar>) -> R<()> {
    match ty {
        Type::Scalar(s) => out.push(*s),
        Type::Vector(s, n) => out.extend(std::iter::repeat_n(*s, *n as usize)),
        Type::Matrix { cols, rows } => {
            out.extend(std::iter::repeat_n(Scalar::Float, (*cols * *rows) as usize))
        }
        Type::Array(t, Some(n)) => {
            for _ in 0..*n {
                scalars(t, out)?;
            }
        }
        Type::Struct(s) => {
            for m in &s.members {
                scalars(&m.ty, out)?;
            }
        }
        _ => return no(format!("values of type {ty:?}")),
    }
    Ok(())
}

/// The number of flattened components of a type.
pub(super) fn size(ty: &Type) -> R<usize> {
    let mut v = Vec::new();
    scalars(ty, &mut v)?;
    Ok(v.len())
}

/// The first component of `name` in `slots` (uniforms or attribute streams, numbered
/// in order of first use), its slot of components `sc` added on first use.
pub(super) fn slot_of(slots: &mut Vec<Slot>, name: &str, sc: &[Scalar]) -> u16 {
    if let Some(s) = slots.iter().find(|s| s.name == name) {
        return s.first;
    }
    let first = slots.iter().map(|s| s.count).sum::<u16>();
    slots.push(Slot {
        name: name.to_string(),
        first,
        count: sc.len() as u16,
        scalars: sc.to_vec(),
        linear: false,
    });
    first
}

/// The lowering of one shader.
#[derive(Clone)]
pub struct Lower<'p> {
    pub(super) p: &'p hir::Program,
    pub(super) b: Builder,
    /// Each value's constant bits, where it is a constant.
    consts: Vec<Option<u32>>,
    /// Each variable's components.
    pub(super) env: HashMap<VarId, Vec<Val>>,
    /// The mask of the enclosing conditions (`None`: every lane).
    pub(super) cond: Option<Val>,
    /// The loops being unrolled, innermost last.
    pub(super) loops: Vec<LoopFrame>,
    /// The functions being inlined, innermost last.
    pub(super) fns: Vec<FnFrame>,
    pub(super) uniforms: Vec<Slot>,
    /// The varyings read (fragment) or the attribute streams (vertex), in order.
    pub(super) varyings: Vec<Slot>,
    inv_w: Option<Val>,
    /// The expression nesting depth.
    pub(super) depth: usize,
    /// Writes ignore the lane mask (a loop's step, see `control`).
    pub(super) unmasked: bool,
    /// The last mask computed and what it was computed from.
    pub(super) exec_memo: Option<([Option<Val>; 4], Option<Val>)>,
    pub(super) opts: Options,
    front_facing: bool,
    /// A vertex shader: inputs are attribute streams ([`Op::InputF`]).
    pub(super) vertex: bool,
    /// The values that are a varying's component as read (its plane, and whether it is
    /// read without the perspective divide): what a texture lookup may take.
    pub(super) plane_vals: HashMap<Val, (u16, bool)>,
    /// The texture lookups so far.
    pub(super) textures: Vec<TexUse>,
    /// Each inlined function's sampler parameters: the sampler variable passed.
    pub(super) sampler_alias: HashMap<VarId, VarId>,
    /// The mutable variables ([`Op::VarLoad`]) and loops ([`Op::LoopBegin`]) made so far.
    pub(super) var_count: u16,
    pub(super) loop_count: u16,
}

/// Lowers a fragment shader.
pub fn lower_fragment(p: &hir::Program) -> Result<Lowered, Unsupported> {
    lower_fragment_with(p, Options::default())
}

/// Lowers a fragment shader for a draw with `opts`.
pub fn lower_fragment_with(p: &hir::Program, opts: Options) -> Result<Lowered, Unsupported> {
    let mut l = Lower::new(p, opts, false);
    l.run_main()?;
    let out = p
        .vars
        .iter()
        .position(|v| v.name == "gl_FragColor")
        .filter(|i| l.env.contains_key(i));
    let data = p
        .vars
        .iter()
        .position(|v| v.name == "gl_FragData")
        .and_then(|i| l.env.get(&i).cloned());
    // gl_FragColor goes to every draw buffer, as Mesa's `write_all_cbufs`; gl_FragData[k]
    // to draw buffer k; a user `out` to the draw buffers from its location on (the link
    // sets it, `context::frag_outputs`; 0 when unset), one per array element. A draw
    // buffer or component the shader writes nothing to gets zeros (llvmpipe's colour
    // outputs start as zeroed allocas).
    let zero = l.f32(0.0);
    let mut colors = [[zero; 4]; MAX_DRAW_BUFFERS];
    match (out, data) {
        (Some(i), _) => {
            let c = &l.env[&i];
            colors = [[c[0], c[1], c[2], c[3]]; MAX_DRAW_BUFFERS];
        }
        (None, Some(d)) => {
            for (k, c) in d.chunks_exact(4).take(MAX_DRAW_BUFFERS).enumerate() {
                colors[k] = [c[0], c[1], c[2], c[3]];
            }
        }
        _ => user_outputs(p, &l.env, &mut colors)?,
    }
    let depth = p
        .vars
        .iter()
        .position(|v| v.name == "gl_FragDepth")
        .and_then(|i| l.env.get(&i))
        .map(|d| d[0]);
    let ir =
        l.b.finish()
            .map_err(|e| Unsupported(format!("IR type error {e:?}")))?;
    Ok(Lowered {
        depth,
        ir,
        color: colors[0],
        colors,
        uniforms: l.uniforms,
        varyings: l.varyings,
        front_facing: l.front_facing,
        textures: l.textures,
    })
}

/// Puts the user-defined outputs of `p` the lowering wrote (`env`) into `colors`, by
/// location (see [`lower_fragment_with`]). Outputs that are not floats are refused.
fn user_outputs(
    p: &hir::Program,
    env: &HashMap<usize, Vec<Val>>,
    colors: &mut [[Val; 4]; MAX_DRAW_BUFFERS],
) -> R<()> {
    for (i, v) in p.vars.iter().enumerate() {
        let Some(vals) = env.get(&i).filter(|_| v.storage == Storage::Out) else {
            continue;
        };
        let elem = match &v.ty {
            Type::Array(e, _) => &**e,
            t => t,
        };
        let n = match elem {
            Type::Scalar(Scalar::Float) => 1,
            Type::Vector(Scalar::Float, n) => usize::from(*n),
            _ => return no(format!("fragment output {} of type {elem:?}", v.name)),
        };
        let at = usize::try_from(v.location.unwrap_or(0)).unwrap_or(MAX_DRAW_BUFFERS);
        for (k, c) in vals.chunks_exact(n).enumerate() {
            if let Some(dst) = colors.get_mut(at + k) {
                dst[..n].copy_from_slice(c);
            }
        }
    }
    Ok(())
}

impl<'p> Lower<'p> {
    /// A lowering of `p` (`vertex`: its inputs are attribute streams, see
    /// [`super::vertex`]).
    pub(super) fn new(p: &'p hir::Program, opts: Options, vertex: bool) -> Self {
        Lower {
            p,
            b: Builder::new(),
            consts: Vec::new(),
            env: HashMap::new(),
            cond: None,
            loops: Vec::new(),
            fns: Vec::new(),
            uniforms: Vec::new(),
            varyings: Vec::new(),
            inv_w: None,
            depth: 0,
            unmasked: false,
            exec_memo: None,
            opts,
            front_facing: false,
            vertex,
            plane_vals: HashMap::new(),
            textures: Vec::new(),
            sampler_alias: HashMap::new(),
            var_count: 0,
            loop_count: 0,
        }
    }

    /// Lowers the globals' initializers and `main`.
    pub(super) fn run_main(&mut self) -> R<()> {
        let p = self.p;
        for (v, init) in &p.globals {
            if let Some(e) = init {
                let val = self.expr(e)?;
                self.env.insert(*v, val);
            }
        }
        let main = p.main().ok_or_else(|| Unsupported("no main".into()))?;
        self.fns.push(FnFrame::default());
        self.block(main.body.as_deref().unwrap_or(&[]))
    }
}

impl Lower<'_> {
    /// Appends `op`, folding it when its operands are constants, and factoring a sum of
    /// two products with a common factor ([`Lower::factor`]).
    pub(super) fn op(&mut self, op: Op) -> Val {
        if let Op::Add(p, q) = op {
            if let Some(v) = self.factor(p, q) {
                return v;
            }
        }
        let folded = self.fold(&op);
        if let (Some(bits), Some(ty)) = (folded, self.result_ty(&op)) {
            return self.konst(ty, bits);
        }
        let v = self.b.push(op);
        self.consts.resize(v.0 as usize + 1, None);
        v
    }

    /// `a·b + a·c` as `a·(b + c)`, as NIR's algebraic pass rewrites every inexact sum of
    /// two products that share a factor (`nir_opt_algebraic.py`:
    /// `('~fadd', ('fmul', a, b), ('fmul', a, c))`; products and sums commute, and equal
    /// constants are one value after `nir_opt_cse`). `None` when `p + q` is not such a
    /// sum. A varying as read (its plane times `1 / w`) is no product to NIR: llvmpipe
    /// interpolates it outside the shader.
    fn factor(&mut self, p: Val, q: Val) -> Option<Val> {
        if self.plane_vals.contains_key(&p) || self.plane_vals.contains_key(&q) {
            return None;
        }
        let (&Op::Mul(a, b), &Op::Mul(c, d)) = (self.b.op_of(p)?, self.b.op_of(q)?) else {
            return None;
        };
        let same = |x: Val, y: Val| {
            x == y || matches!((self.cval(x), self.cval(y)), (Some(i), Some(j)) if i == j)
        };
        let (k, x, y) = if same(a, c) {
            (a, b, d)
        } else if same(a, d) {
            (a, b, c)
        } else if same(b, c) {
            (b, a, d)
        } else if same(b, d) {
            (b, a, c)
        } else {
            return None;
        };
        let sum = self.op(Op::Add(x, y));
        Some(self.op(Op::Mul(k, sum)))
    }

    /// A constant of type `ty` (one op per use; the executor fills it once per run).
    pub(super) fn konst(&mut self, ty: Ty, bits: u32) -> Val {
        let v = self.b.push(Op::Const(ty, bits));
        self.consts.resize(v.0 as usize + 1, None);
        self.consts[v.0 as usize] = Some(bits);
        v
    }

    /// An f32 constant.
    pub(super) fn f32(&mut self, x: f32) -> Val {
        self.konst(Ty::F32, x.to_bits())
    }

    /// An i32 constant.
    pub(super) fn i32(&mut self, x: i32) -> Val {
        self.konst(Ty::I32, x as u32)
    }

    /// A mask constant.
    pub(super) fn mask(&mut self, on: bool) -> Val {
        self.konst(Ty::Mask, if on { u32::MAX } else { 0 })
    }

    /// `v`'s constant bits, if it is one.
    pub(super) fn cval(&self, v: Val) -> Option<u32> {
        self.consts.get(v.0 as usize).copied().flatten()
    }

    /// `v`'s type.
    pub(super) fn ty(&self, v: Val) -> Ty {
        self.b.ty(v).unwrap_or(Ty::F32)
    }

    fn result_ty(&self, op: &Op) -> Option<Ty> {
        Some(match op {
            Op::FCmp(..) | Op::SCmp(..) => Ty::Mask,
            Op::IBin(..) | Op::FtoI(_) | Op::Bits(_) => Ty::I32,
            Op::And(a, _) | Op::Or(a, _) | Op::Xor(a, _) | Op::Select(_, a, _) => self.ty(*a),
            _ => Ty::F32,
        })
    }

    /// The constant value of `op` when it is exact IEEE (or integer) arithmetic of
    /// constants, as llvmpipe would compute it at run time.
    fn fold(&self, op: &Op) -> Option<u32> {
        let c = |v: &Val| self.cval(*v);
        let f = |v: &Val| c(v).map(f32::from_bits);
        let i = |v: &Val| c(v).map(|b| b as i32);
        let fb = |x: f32| Some(x.to_bits());
        let mb = |x: bool| Some(if x { u32::MAX } else { 0 });
        match op {
            Op::Add(a, b) => fb(f(a)? + f(b)?),
            Op::Sub(a, b) => fb(f(a)? - f(b)?),
            Op::Mul(a, b) => fb(f(a)? * f(b)?),
            Op::Div(a, b) => fb(f(a)? / f(b)?),
            Op::Un(Un::Neg, a) => Some(c(a)? ^ 0x8000_0000),
            Op::Un(Un::Abs, a) => Some(c(a)? & 0x7fff_ffff),
            Op::Un(Un::Floor, a) => fb(f(a)?.floor()),
            Op::IBin(o, a, b) => {
                let (x, y) = (i(a)?, i(b)?);
                // GLSL IR folds a division or remainder by zero to 0.
                let by_zero = matches!(o, IOp::Div | IOp::UDiv | IOp::URem) && y == 0;
                Some(if by_zero { 0 } else { o.apply(x, y) } as u32)
            }
            Op::SCmp(o, a, b) => mb(cmp(*o, i(a)?, i(b)?)),
            Op::FCmp(o, a, b) => mb(cmp(*o, f(a)?, f(b)?)),
            Op::And(a, b) => Some(c(a)? & c(b)?),
            Op::Or(a, b) => Some(c(a)? | c(b)?),
            Op::Xor(a, b) => Some(c(a)? ^ c(b)?),
            Op::ItoF(a) => fb(i(a)? as f32),
            Op::Select(m, a, b) => match c(m) {
                Some(m) => c(if m != 0 { a } else { b }),
                None => c(a).filter(|&x| Some(x) == c(b)),
            },
            _ => None,
        }
    }

    /// A variable's components, materialising an input on its first read.
    pub(super) fn read_var(&mut self, id: VarId) -> R<Vec<Val>> {
        if let Some(v) = self.env.get(&id) {
            return Ok(v.clone());
        }
        let var = &self.p.vars[id];
        let mut sc = Vec::new();
        match &var.ty {
            Type::Array(t, None) if var.name == "gl_TexCoord" => {
                scalars(&Type::Array(t.clone(), Some(TEX_COORDS)), &mut sc)?
            }
            ty => scalars(ty, &mut sc)?,
        }
        let vals = match var.storage {
            Storage::Const => match &var.value {
                Some(c) => self.constant(c, &var.ty)?,
                None => return no("a constant without value"),
            },
            Storage::Uniform | Storage::Builtin(BKind::Uniform) => {
                let first = self.uniform_slot(&var.name, &sc);
                let mut out = Vec::new();
                for (k, s) in sc.iter().enumerate() {
                    let u = self.op(Op::Uniform(first + k as u16));
                    out.push(match s {
                        Scalar::Float => u,
                        Scalar::Int | Scalar::Uint => self.op(Op::Bits(u)),
                        Scalar::Bool => {
                            let bits = self.op(Op::Bits(u));
                            let zero = self.i32(0);
                            self.op(Op::SCmp(FCmp::Ne, bits, zero))
                        }
                    });
                }
                out
            }
            Storage::In | Storage::Builtin(BKind::Input) => self.input(id, &sc)?,
            _ => sc
                .iter()
                .map(|s| match s {
                    Scalar::Float => self.f32(0.0),
                    Scalar::Bool => self.mask(false),
                    _ => self.i32(0),
                })
                .collect(),
        };
        self.env.insert(id, vals.clone());
        Ok(vals)
    }

    /// The first slot of uniform `name` of components `sc`, added on first use.
    pub(super) fn uniform_slot(&mut self, name: &str, sc: &[Scalar]) -> u16 {
        slot_of(&mut self.uniforms, name, sc)
    }

    /// A stage input: `gl_FragCoord`, `gl_FrontFacing`, or a varying's planes (a vertex
    /// shader's attribute streams, [`super::vertex`]).
    fn input(&mut self, id: VarId, sc: &[Scalar]) -> R<Vec<Val>> {
        let var = &self.p.vars[id];
        if self.vertex {
            if matches!(var.name.as_str(), "gl_InstanceID" | "gl_InstanceIDARB") {
                let first = self.uniform_slot(INSTANCE_ID, &[Scalar::Int]);
                let u = self.op(Op::Uniform(first));
                return Ok(vec![self.op(Op::Bits(u))]);
            }
            return self.attribute(&var.name.clone(), sc);
        }
        match var.name.as_str() {
            "gl_FragCoord" => {
                let (mut x, mut y) = (self.op(Op::FragX), self.op(Op::FragY));
                if !self.opts.centred {
                    let half = self.f32(0.5);
                    x = self.op(Op::Add(x, half));
                    y = self.op(Op::Add(y, half));
                }
                if let Some(h) = self.opts.flip_height {
                    let h = self.f32(h);
                    y = self.op(Op::Sub(h, y));
                }
                let z = self.op(Op::Interp(PLANE_Z));
                let w = self.op(Op::Interp(PLANE_INV_W));
                return Ok(vec![x, y, z, w]);
            }
            "gl_FrontFacing" => {
                self.front_facing = true;
                let first = self.uniform_slot(FRONT_FACING, &[Scalar::Bool]);
                let u = self.op(Op::Uniform(first));
                let bits = self.op(Op::Bits(u));
                let zero = self.i32(0);
                return Ok(vec![self.op(Op::SCmp(FCmp::Ne, bits, zero))]);
            }
            _ => {}
        }
        if sc.iter().any(|s| *s != Scalar::Float) {
            return no(format!("non-float varying {}", var.name));
        }
        let linear = matches!(
            var.interp,
            Some(softgl_glsl::ast::Interp::Flat | softgl_glsl::ast::Interp::Noperspective)
        ) || (self.opts.flat_colors
            && matches!(var.name.as_str(), "gl_Color" | "gl_SecondaryColor"));
        let first = FIRST_VARYING_PLANE + self.varyings.iter().map(|s| s.count).sum::<u16>();
        self.varyings.push(Slot {
            name: var.name.clone(),
            first,
            count: sc.len() as u16,
            scalars: sc.to_vec(),
            linear,
        });
        let mut out = Vec::new();
        for k in 0..sc.len() as u16 {
            let a = self.op(Op::Interp(first + k));
            let v = if linear {
                a
            } else {
                let w = self.inv_w_rcp();
                self.op(Op::Mul(a, w))
            };
            self.plane_vals.insert(v, (first + k, linear));
            out.push(v);
        }
        Ok(out)
    }

    /// `1 / w_plane`, computed once (for every lane: a value lowered under a condition
    /// is still computed for all lanes).
    fn inv_w_rcp(&mut self) -> Val {
        if let Some(v) = self.inv_w {
            return v;
        }
        let one = self.f32(1.0);
        let w = self.op(Op::Interp(PLANE_INV_W));
        let v = self.op(Op::Div(one, w));
        self.inv_w = Some(v);
        v
    }

    /// The components of a constant of type `ty`.
    pub(super) fn constant(&mut self, c: &Const, ty: &Type) -> R<Vec<Val>> {
        let mut out = Vec::new();
        self.flatten_const(c, &mut out);
        if out.len() != size(ty)? {
            return no("a constant of the wrong size");
        }
        Ok(out)
    }

    fn flatten_const(&mut self, c: &Const, out: &mut Vec<Val>) {
        match c {
            Const::Scalars(v) => {
                for x in v {
                    let val = match *x {
                        Value::Bool(b) => self.mask(b),
                        Value::Int(i) => self.i32(i),
                        Value::Uint(u) => self.i32(u as i32),
                        Value::Float(f) => self.f32(f),
                    };
                    out.push(val);
                }
            }
            Const::Aggregate(items) => {
                for i in items {
                    self.flatten_const(i, out);
                }
            }
        }
    }
}

/// The comparison `a OP b`.
pub(super) fn cmp<T: PartialOrd>(op: FCmp, a: T, b: T) -> bool {
    match op {
        FCmp::Lt => a < b,
        FCmp::Le => a <= b,
        FCmp::Gt => a > b,
        FCmp::Ge => a >= b,
        FCmp::Eq => a == b,
        FCmp::Ne => a != b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_of_products_with_a_common_factor_are_factored_as_nir_does() {
        let p = softgl_glsl::compile(
            &["uniform float u; varying float a; varying float b;
               void main() { gl_FragColor = vec4(a * u + b * u, u * a + 0.5 * u, a * 0.3 + b * 0.3, a * u + b * 0.3); }"],
            softgl_glsl::Stage::Fragment,
        )
        .expect("compiles");
        let l = lower_fragment(&p).unwrap();
        let op = |v: Val| l.ir.ops[v.0 as usize];
        let konst = |v: Val| match op(v) {
            Op::Const(_, bits) => Some(f32::from_bits(bits)),
            _ => None,
        };
        for ch in 0..3 {
            let Op::Mul(k, s) = op(l.color[ch]) else {
                panic!("channel {ch}: {:?}", op(l.color[ch]));
            };
            assert!(matches!(op(s), Op::Add(..)), "channel {ch}: {:?}", op(s));
            if ch == 2 {
                assert_eq!(konst(k), Some(0.3), "equal constants are one factor");
            }
        }
        // Nothing in common: the sum stays.
        assert!(matches!(op(l.color[3]), Op::Add(..)));
        // Two varyings share `1 / w` as read, but NIR never sees that product.
        let p = softgl_glsl::compile(
            &["varying float a; varying float b; void main() { gl_FragColor = vec4(a + b); }"],
            softgl_glsl::Stage::Fragment,
        )
        .expect("compiles");
        let l = lower_fragment(&p).unwrap();
        assert!(matches!(l.ir.ops[l.color[0].0 as usize], Op::Add(..)));
    }
}
