//! Renderbuffer storage and depth texture images lent to the working copy of the bound
//! draw object, so that binding, unbinding and drawing copy none of it.
//!
//! A renderbuffer keeps one colour, depth or stencil buffer per sample plane, in the
//! working copy's own type and row order (GL's rows, `width` per row). When the working
//! copy of the bound draw object has the renderbuffer's size and the same layout for a
//! part (RGBA8 or RGBA sRGB colour, any depth, stencil), assembling the working copy moves
//! the buffer into it instead of copying ([`lend`]), and the renderbuffer holds an empty
//! buffer meanwhile; unbinding (or any other parking of the working copy) moves it back
//! ([`Context::return_loans`]). Nothing reads a renderbuffer but the copies of
//! [`super::fbo_image`], which skip an empty buffer, and the reads through another
//! framebuffer binding, which take a copy back first ([`Context::unlend_for`]). A loan is
//! returned only to the storage it came from (`Renderbuffer::storage_id`): a
//! renderbuffer given new storage or deleted meanwhile keeps its new state, and the lent
//! buffer is dropped with the working copy.
//!
//! A depth texture image is lent the same way when it is a whole level of the working
//! copy's size on huge pages (its texels are the depths as little-endian u32, the working
//! copy's values, so [`HugeBuf::cast`] moves them without a copy): a shadow map is then
//! drawn in place, where each pass used to write its whole map back (16 MB for MuJoCo's
//! 2048² maps, 64 MB for 4096², 14% of the showcase scene's samples). A level is moved to
//! huge pages the first time it is lent. While lent the level's texels are empty: the
//! texture is incomplete to sampling (a feedback loop, whose result GL leaves undefined),
//! the fbo_image copies skip it, and every command that reads or changes the texture
//! directly takes the image back first ([`Context::unlend_texture`], called by
//! `fbo_touch` and `fbo_sync_texture`). It goes back only to a level that is still empty
//! and of its size.

use super::fbo::{Attachment, FboState, RbFormat, TexImage};
use super::Context;
use crate::framebuffer::{ColorFormat, Framebuffer};
use crate::memory::{HugeBuf, Plain};
use crate::texture::{BaseFormat, TextureState};

/// Which buffer of a renderbuffer's sample plane a loan moved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The colour buffer.
    Color,
    /// The depth buffer.
    Depth,
    /// The stencil buffer.
    Stencil,
}

/// Where a lent buffer came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Owner {
    /// A renderbuffer: its name and the storage the buffer belongs to
    /// (`Renderbuffer::storage_id`).
    Renderbuffer(u32, u64),
    /// A depth texture image.
    Texture(TexImage),
}

impl Owner {
    /// The attachment that names the owner.
    fn attachment(self) -> Attachment {
        match self {
            Owner::Renderbuffer(name, _) => Attachment::Renderbuffer(name),
            Owner::Texture(t) => Attachment::Texture(t),
        }
    }
}

/// A renderbuffer buffer or depth texture image held by the working copy of the bound
/// draw object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Loan {
    /// Where it came from.
    pub owner: Owner,
    /// The sample plane (0 for a single-sample renderbuffer), which is also the working
    /// copy's plane that holds it.
    pub plane: usize,
    /// Which buffer.
    pub part: Part,
}

/// Moves buffer `from` into `to` when it holds `n` values; whether it did.
fn take_into<T: Plain>(from: &mut HugeBuf<T>, to: &mut HugeBuf<T>, n: usize) -> bool {
    if from.len() != n || n == 0 {
        return false;
    }
    *to = std::mem::replace(from, HugeBuf::empty());
    true
}

/// Lends the depth buffer of working copy `fb` the texels of depth texture image `t` when
/// they are one whole level of its size (moving them onto huge pages the first time);
/// the loan made.
fn lend_texture(textures: &mut TextureState, fb: &mut Framebuffer, t: TexImage) -> Option<Loan> {
    let img = t.find_mut(textures)?;
    let n = fb.width * fb.height;
    let whole = t.layer == 0 && img.texels.len() == n && n > 0;
    if !whole || img.base != BaseFormat::Depth || img.floats.is_some() {
        return None;
    }
    if (img.width, img.height) != (fb.width, fb.height) {
        return None;
    }
    if !img.texels.is_mapped() {
        let mut m = HugeBuf::filled(n, [0u8; 4]);
        if !m.is_mapped() {
            return None;
        }
        m.copy_from_slice(&img.texels);
        img.texels = m;
    }
    let texels = std::mem::replace(&mut img.texels, HugeBuf::empty());
    match texels.cast::<u32>() {
        Ok(d) => fb.depth = d,
        Err(t) => {
            img.texels = t;
            return None;
        }
    }
    Some(Loan {
        owner: Owner::Texture(t),
        plane: 0,
        part: Part::Depth,
    })
}

/// Lends working copy `fb` (sample plane `plane`) the buffer of renderbuffer image `a` in
/// its role (`stencil`: the stencil attachment), or the texels of depth texture image `a`,
/// when the layouts agree; the loan made.
pub(super) fn lend(
    fbo: &mut FboState,
    textures: &mut TextureState,
    fb: &mut Framebuffer,
    a: Attachment,
    plane: usize,
    stencil: bool,
) -> Option<Loan> {
    let name = match a {
        Attachment::Renderbuffer(name) => name,
        Attachment::Texture(t) if !stencil && plane == 0 => {
            return lend_texture(textures, fb, t);
        }
        _ => return None,
    };
    let rb = fbo.renderbuffers.get_mut(&name)?.as_mut()?;
    if (rb.width, rb.height) != (fb.width, fb.height) {
        return None;
    }
    let p = if rb.samples == 0 { 0 } else { plane };
    let n = fb.width * fb.height;
    let part = match (rb.format?, stencil) {
        (RbFormat::Rgba8 | RbFormat::Srgb(true), false)
            if fb.format == ColorFormat::Rgba && fb.wide.is_none() =>
        {
            take_into(rb.color.get_mut(p)?, &mut fb.color, n).then_some(Part::Color)?
        }
        (RbFormat::Depth(d) | RbFormat::DepthStencil(d), false) if fb.depth_format == d => {
            take_into(rb.depth.get_mut(p)?, &mut fb.depth, n).then_some(Part::Depth)?
        }
        (RbFormat::DepthStencil(_) | RbFormat::Stencil8, true) => {
            take_into(rb.stencil.get_mut(p)?, &mut fb.stencil, n).then_some(Part::Stencil)?
        }
        _ => return None,
    };
    Some(Loan {
        owner: Owner::Renderbuffer(name, rb.storage_id),
        plane: p,
        part,
    })
}

/// Moves a lent buffer back from `from` into the renderbuffer's empty slot `to` (`keep`:
/// leaves a copy in `from`, for a working copy that stays in use).
fn give_back<T: Plain>(from: &mut HugeBuf<T>, to: Option<&mut HugeBuf<T>>, keep: bool) {
    if let Some(to) = to.filter(|t| t.is_empty() && !from.is_empty()) {
        *to = if keep {
            from.clone()
        } else {
            std::mem::replace(from, HugeBuf::empty())
        };
    }
}

/// Moves lent depth texels back from `from` into texture image `t` when its level is
/// still empty and of their size (`keep`: leaves a copy in `from`).
fn give_back_texture(
    textures: &mut TextureState,
    from: &mut HugeBuf<u32>,
    t: TexImage,
    keep: bool,
) {
    let Some(img) = t.find_mut(textures) else {
        return;
    };
    let n = from.len();
    if !img.texels.is_empty() || n == 0 || img.width * img.height != n {
        return;
    }
    let d = if keep {
        from.clone()
    } else {
        std::mem::replace(from, HugeBuf::empty())
    };
    // A clone of a large buffer is mapped too, so the cast holds; a heap one would be
    // copied value by value.
    img.texels = d
        .cast::<[u8; 4]>()
        .unwrap_or_else(|d| d.iter().map(|v| v.to_le_bytes()).collect());
}

/// Ends loan `l` of working copy `fb`: the buffer goes back to its renderbuffer in
/// `rbs` (a copy of it with `keep`) when that still has the storage it came from, or to
/// its texture image in `textures`.
fn give_back_loan(
    rbs: &mut Renderbuffers,
    textures: &mut TextureState,
    fb: &mut Framebuffer,
    l: Loan,
    keep: bool,
) {
    let (name, storage_id) = match l.owner {
        Owner::Renderbuffer(name, id) => (name, id),
        Owner::Texture(t) => return give_back_texture(textures, &mut fb.depth, t, keep),
    };
    let rb = rbs.get_mut(&name).and_then(|r| r.as_mut());
    let Some(rb) = rb.filter(|rb| rb.storage_id == storage_id) else {
        return;
    };
    match l.part {
        Part::Color => give_back(&mut fb.color, rb.color.get_mut(l.plane), keep),
        Part::Depth => give_back(&mut fb.depth, rb.depth.get_mut(l.plane), keep),
        Part::Stencil => give_back(&mut fb.stencil, rb.stencil.get_mut(l.plane), keep),
    }
}

/// The renderbuffer table.
type Renderbuffers = std::collections::HashMap<u32, Option<super::fbo::Renderbuffer>>;

impl Context {
    /// The working copy's plane `plane` (0: `fb`, else [`FboState::ms_planes`]).
    fn plane_fb(&mut self, plane: usize) -> Option<&mut Framebuffer> {
        match plane {
            0 => self.fb.as_mut(),
            k => self.fbo.ms_planes.get_mut(k - 1),
        }
    }

    /// Ends `loans`: each buffer goes back to its renderbuffer (as a copy with `keep`),
    /// when that still has the storage it came from. Pending draws are settled first.
    fn end_loans(&mut self, loans: Vec<Loan>, keep: bool) {
        if loans.is_empty() {
            return;
        }
        // Recorded clears live in the working copy: write them before the buffers go.
        for k in 0..=self.fbo.ms_planes.len() {
            if let Some(fb) = self.plane_fb(k) {
                fb.resolve();
            }
        }
        for l in loans {
            let fb = match l.plane {
                0 => self.fb.as_mut(),
                k => self.fbo.ms_planes.get_mut(k - 1),
            };
            if let Some(fb) = fb {
                give_back_loan(&mut self.fbo.renderbuffers, &mut self.textures, fb, l, keep);
            }
        }
    }

    /// Moves every lent buffer back into its renderbuffer (before the working copy is
    /// parked or dropped).
    pub(super) fn return_loans(&mut self) {
        let loans = std::mem::take(&mut self.fbo.loans);
        self.end_loans(loans, false);
    }

    /// Before texture `texture` is read or changed directly: its images lent to the
    /// working copy go back to it as copies (the working copy keeps drawing into its own,
    /// which `write_back` then copies as it does an image that was never lent).
    pub(super) fn unlend_texture(&mut self, texture: u32) {
        let (give, keep): (Vec<Loan>, Vec<Loan>) = std::mem::take(&mut self.fbo.loans)
            .into_iter()
            .partition(|l| matches!(l.owner, Owner::Texture(t) if t.name == texture));
        self.fbo.loans = keep;
        self.end_loans(give, true);
    }

    /// Before object `name` is read through another binding: the renderbuffers and
    /// texture images it shares with the draw object's working copy get their lent
    /// buffers back as copies (the working copy keeps drawing into its own).
    pub(super) fn unlend_for(&mut self, name: u32) {
        let Some(f) = self.fbo.object(name) else {
            return;
        };
        let attached: Vec<Attachment> = f
            .color
            .iter()
            .chain([&f.depth, &f.stencil])
            .copied()
            .collect();
        let (give, keep): (Vec<Loan>, Vec<Loan>) = std::mem::take(&mut self.fbo.loans)
            .into_iter()
            .partition(|l| attached.contains(&l.owner.attachment()));
        self.fbo.loans = keep;
        self.end_loans(give, true);
    }
}

impl Context {
    /// Runs `f` over every sample plane of the multisample read framebuffer (`None` when
    /// there is nothing to read): the draw framebuffer's own planes when it is the one
    /// read, else planes of the read object whose renderbuffer buffers are lent to them
    /// for the while (a resolving blit then copies nothing to read its source).
    pub fn with_read_planes<R>(&mut self, f: impl FnOnce(&[Framebuffer]) -> R) -> Option<R> {
        self.fbo_sync();
        if self.reads_other_buffer() && self.read_samples() == 0 {
            return Some(f(&[self.read_other_buffer()?]));
        }
        if self.fbo.read == self.fbo.draw {
            let mut planes = vec![self.fb.take()?];
            planes.append(&mut self.fbo.ms_planes);
            let r = f(&planes);
            self.fbo.ms_planes = planes.split_off(1);
            self.fb = planes.pop();
            return Some(r);
        }
        let name = self.fbo.read;
        self.unlend_for(name);
        let obj = self.fbo.object_mut(name)?;
        let saved = obj.draw_buffer;
        obj.draw_buffer = obj.read_buffer;
        let planes = self.lend_planes(name);
        if let Some(obj) = self.fbo.object_mut(name) {
            obj.draw_buffer = saved;
        }
        let (planes, loans) = planes?;
        let r = f(&planes);
        let mut planes = planes;
        for l in loans {
            if let Some(fb) = planes.get_mut(l.plane) {
                give_back_loan(
                    &mut self.fbo.renderbuffers,
                    &mut self.textures,
                    fb,
                    l,
                    false,
                );
            }
        }
        Some(r)
    }
}
