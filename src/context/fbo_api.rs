//! Framebuffer and renderbuffer objects (GL_ARB_framebuffer_object): names, bindings,
//! attachments, renderbuffer storage and glBlitFramebuffer, validated in Mesa's order and
//! applied to [`super::fbo::FboState`]. The attachment queries are in
//! [`super::fbo_query`]; the C entry points in `ffi/framebuffers.rs`.

use super::fbo::{
    Attachment, RbFormat, Renderbuffer, TexImage, MAX_COLOR_ATTACHMENTS, MAX_RENDERBUFFER_SIZE,
    MAX_SAMPLES,
};
use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::*;
use crate::texture::{Target, MAX_3D_TEXTURE_SIZE, MAX_LEVELS};

/// Which bindings a framebuffer target names.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Binding {
    /// GL_FRAMEBUFFER: both.
    Both,
    /// GL_DRAW_FRAMEBUFFER.
    Draw,
    /// GL_READ_FRAMEBUFFER.
    Read,
}

/// The bindings a framebuffer target names (GL_INVALID_ENUM for another target).
pub(crate) fn binding(target: GLenum) -> GlResult<Binding> {
    match target {
        GL_FRAMEBUFFER => Ok(Binding::Both),
        GL_DRAW_FRAMEBUFFER => Ok(Binding::Draw),
        GL_READ_FRAMEBUFFER => Ok(Binding::Read),
        _ => Err(GlError::InvalidEnum),
    }
}

/// The object bound to `target` (GL_FRAMEBUFFER means the draw binding).
pub(crate) fn bound_name(c: &Context, target: GLenum) -> GlResult<u32> {
    Ok(match binding(target)? {
        Binding::Both | Binding::Draw => c.fbo.draw,
        Binding::Read => c.fbo.read,
    })
}

/// An attachment point: colour index, or depth / stencil / both.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Point {
    /// GL_COLOR_ATTACHMENTi.
    Color(usize),
    /// GL_DEPTH_ATTACHMENT.
    Depth,
    /// GL_STENCIL_ATTACHMENT.
    Stencil,
    /// GL_DEPTH_STENCIL_ATTACHMENT.
    DepthStencil,
}

/// Checks a renderbuffer target: GL_RENDERBUFFER is the only one (GL_INVALID_ENUM).
pub(crate) fn renderbuffer_target(target: GLenum) -> GlResult<()> {
    if target != GL_RENDERBUFFER {
        return Err(GlError::InvalidEnum);
    }
    Ok(())
}

/// The attachment point a token names: beyond GL_MAX_COLOR_ATTACHMENTS
/// GL_INVALID_OPERATION, not an attachment GL_INVALID_ENUM.
pub(crate) fn point(attachment: GLenum) -> GlResult<Point> {
    match attachment {
        GL_DEPTH_ATTACHMENT => Ok(Point::Depth),
        GL_STENCIL_ATTACHMENT => Ok(Point::Stencil),
        GL_DEPTH_STENCIL_ATTACHMENT => Ok(Point::DepthStencil),
        a if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + MAX_COLOR_ATTACHMENTS as u32)
            .contains(&a) =>
        {
            Ok(Point::Color((a - GL_COLOR_ATTACHMENT0) as usize))
        }
        // Beyond GL_MAX_COLOR_ATTACHMENTS but a real token: Mesa's INVALID_OPERATION.
        a if (GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT31).contains(&a) => {
            Err(GlError::InvalidOperation)
        }
        _ => Err(GlError::InvalidEnum),
    }
}

/// The texture attachment for `texture` at `level` of `target` (`None` for texture 0):
/// GL_INVALID_OPERATION for a name that is no texture or a target it was not made for,
/// GL_INVALID_VALUE for a level or layer out of range.
fn texture_attachment(
    c: &Context,
    textarget: Option<GLenum>,
    texture: GLuint,
    level: GLint,
    layer: GLint,
) -> GlResult<Attachment> {
    if texture == 0 {
        return Ok(Attachment::None);
    }
    let obj = c.textures.objects.get(&texture);
    let Some(have) = obj.and_then(|o| o.target) else {
        return Err(GlError::InvalidOperation);
    };
    let (want, face) = match textarget {
        // glFramebufferTextureLayer: any layered target.
        None if have == Target::Tex3D => (Target::Tex3D, 0),
        None => return Err(GlError::InvalidOperation),
        Some(GL_TEXTURE_1D) => (Target::Tex1D, 0),
        Some(GL_TEXTURE_2D) => (Target::Tex2D, 0),
        Some(GL_TEXTURE_3D) => (Target::Tex3D, 0),
        Some(f)
            if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..GL_TEXTURE_CUBE_MAP_POSITIVE_X + 6)
                .contains(&f) =>
        {
            (Target::Cube, (f - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize)
        }
        Some(_) => return Err(GlError::InvalidOperation),
    };
    if want != have {
        return Err(GlError::InvalidOperation);
    }
    let levels = if have == Target::Tex3D {
        crate::texture::MAX_3D_LEVELS
    } else {
        MAX_LEVELS
    };
    if level < 0 || level as usize >= levels {
        return Err(GlError::InvalidValue);
    }
    if layer < 0 || layer as usize >= MAX_3D_TEXTURE_SIZE {
        return Err(GlError::InvalidValue);
    }
    Ok(Attachment::Texture(TexImage {
        name: texture,
        face,
        level: level as usize,
        layer: layer as usize,
    }))
}

/// A renderbuffer object as first bound: no storage, internal format GL_RGBA.
fn new_renderbuffer() -> Renderbuffer {
    Renderbuffer {
        internal: GL_RGBA,
        ..Default::default()
    }
}

/// The colour attachment glDrawBuffer / glReadBuffer select on a framebuffer object:
/// GL_NONE or GL_COLOR_ATTACHMENTi; the window's buffer names are GL_INVALID_OPERATION
/// there, anything else GL_INVALID_ENUM.
pub(crate) fn object_buffer(mode: GLenum) -> GlResult<Option<usize>> {
    match mode {
        GL_NONE => Ok(None),
        GL_FRONT_LEFT | GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT | GL_FRONT | GL_BACK
        | GL_LEFT | GL_RIGHT | GL_FRONT_AND_BACK => Err(GlError::InvalidOperation),
        GL_AUX0..=GL_AUX3 => Err(GlError::InvalidOperation),
        m => match point(m)? {
            Point::Color(i) => Ok(Some(i)),
            _ => Err(GlError::InvalidEnum),
        },
    }
}

impl Context {
    /// The glFramebuffer* attach calls: once `target` and `attachment` are known tokens,
    /// sets that attachment point of the object bound to `target` to what `image` names
    /// (its checks come after the tokens', before the binding's).
    fn attach(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        image: impl FnOnce(&Context) -> GlResult<Attachment>,
    ) -> GlResult<()> {
        binding(target)?;
        let p = point(attachment)?;
        let a = image(self)?;
        let name = bound_name(self, target)?;
        if name == 0 {
            return Err(GlError::InvalidOperation);
        }
        self.fbo_edit(|c| {
            let f = c.fbo.object_mut(name).ok_or(GlError::InvalidOperation)?;
            match p {
                Point::Color(i) => f.color[i] = a,
                Point::Depth => f.depth = a,
                Point::Stencil => f.stencil = a,
                Point::DepthStencil => (f.depth, f.stencil) = (a, a),
            }
            Ok(())
        })
    }

    /// glGenFramebuffers: fills `names` with unused framebuffer names.
    pub(crate) fn gen_framebuffers(&mut self, names: &mut [GLuint]) {
        let fresh = self.fbo.gen_framebuffers(names.len());
        names.copy_from_slice(&fresh);
    }

    /// glGenRenderbuffers: fills `names` with unused renderbuffer names.
    pub(crate) fn gen_renderbuffers(&mut self, names: &mut [GLuint]) {
        let fresh = self.fbo.gen_renderbuffers(names.len());
        names.copy_from_slice(&fresh);
    }

    /// glDeleteFramebuffers: a bound object's bindings revert to the window first.
    pub(crate) fn delete_framebuffers(&mut self, names: &[GLuint]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            if self.fbo.draw == name {
                self.set_draw_framebuffer(0);
            }
            if self.fbo.read == name {
                self.fbo.read = 0;
            }
            self.fbo.framebuffers.remove(&name);
        }
    }

    /// Binds `name` to `target`; `any_name` lets names never generated create objects (the
    /// EXT entry point's rule).
    pub(crate) fn bind_framebuffer_object(
        &mut self,
        target: GLenum,
        name: GLuint,
        any_name: bool,
    ) -> GlResult<()> {
        let b = binding(target)?;
        if name != 0 {
            match self.fbo.framebuffers.get_mut(&name) {
                Some(Some(_)) => {}
                Some(slot) => *slot = Some(Default::default()),
                None if any_name => {
                    self.fbo.framebuffers.insert(name, Some(Default::default()));
                }
                None => return Err(GlError::InvalidOperation),
            }
        }
        if b != Binding::Read {
            self.set_draw_framebuffer(name);
        }
        if b != Binding::Draw {
            self.fbo.read = name;
        }
        Ok(())
    }

    /// glIsFramebuffer: true for names of objects that have been bound.
    pub(crate) fn is_framebuffer(&self, name: GLuint) -> bool {
        self.fbo.object(name).is_some()
    }

    /// glCheckFramebufferStatus.
    pub(crate) fn check_framebuffer_status(&self, target: GLenum) -> GlResult<GLenum> {
        let name = bound_name(self, target)?;
        Ok(self.fbo.status(name, &self.textures).to_gl())
    }

    /// The glFramebufferTexture* calls (`dims`: the entry point's dimension, `None` for
    /// glFramebufferTextureLayer).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn framebuffer_texture(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        textarget: Option<GLenum>,
        dims: Option<u8>,
        texture: GLuint,
        level: GLint,
        layer: GLint,
    ) -> GlResult<()> {
        self.attach(target, attachment, |c| {
            // The 1D/2D/3D entry points take only their own texture targets.
            let fits = match (dims, textarget) {
                (Some(1), Some(t)) => t == GL_TEXTURE_1D,
                (Some(2), Some(t)) => {
                    t == GL_TEXTURE_2D
                        || (GL_TEXTURE_CUBE_MAP_POSITIVE_X..GL_TEXTURE_CUBE_MAP_POSITIVE_X + 6)
                            .contains(&t)
                }
                (Some(3), Some(t)) => t == GL_TEXTURE_3D,
                _ => true,
            };
            if !fits && texture != 0 {
                return Err(GlError::InvalidOperation);
            }
            texture_attachment(c, textarget, texture, level, layer)
        })
    }

    /// glFramebufferRenderbuffer.
    pub(crate) fn framebuffer_renderbuffer(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        renderbuffertarget: GLenum,
        renderbuffer: GLuint,
    ) -> GlResult<()> {
        self.attach(target, attachment, |c| {
            renderbuffer_target(renderbuffertarget)?;
            if renderbuffer == 0 {
                Ok(Attachment::None)
            } else if matches!(c.fbo.renderbuffers.get(&renderbuffer), Some(Some(_))) {
                Ok(Attachment::Renderbuffer(renderbuffer))
            } else {
                Err(GlError::InvalidOperation)
            }
        })
    }

    /// glDeleteRenderbuffers: detached from the bound framebuffers, unbound if bound.
    pub(crate) fn delete_renderbuffers(&mut self, names: &[GLuint]) -> GlResult<()> {
        self.fbo_edit(|c| {
            c.detach_bound(|a| matches!(a, Attachment::Renderbuffer(r) if names.contains(&r)));
            for &name in names.iter().filter(|&&n| n != 0) {
                if c.fbo.renderbuffer == name {
                    c.fbo.renderbuffer = 0;
                }
                c.fbo.renderbuffers.remove(&name);
            }
            Ok(())
        })
    }

    /// Binds renderbuffer `name`; `any_name` as for [`Context::bind_framebuffer_object`].
    pub(crate) fn bind_renderbuffer(
        &mut self,
        target: GLenum,
        name: GLuint,
        any_name: bool,
    ) -> GlResult<()> {
        renderbuffer_target(target)?;
        if name != 0 {
            match self.fbo.renderbuffers.get_mut(&name) {
                Some(Some(_)) => {}
                Some(slot) => *slot = Some(new_renderbuffer()),
                None if any_name => {
                    self.fbo
                        .renderbuffers
                        .insert(name, Some(new_renderbuffer()));
                }
                None => return Err(GlError::InvalidOperation),
            }
        }
        self.fbo.renderbuffer = name;
        Ok(())
    }

    /// glIsRenderbuffer: true for names of objects that have been bound.
    pub(crate) fn is_renderbuffer(&self, name: GLuint) -> bool {
        matches!(self.fbo.renderbuffers.get(&name), Some(Some(_)))
    }

    /// glRenderbufferStorage(Multisample) on the bound renderbuffer.
    pub(crate) fn renderbuffer_storage(
        &mut self,
        target: GLenum,
        samples: GLsizei,
        internal: GLenum,
        w: GLsizei,
        h: GLsizei,
    ) -> GlResult<()> {
        renderbuffer_target(target)?;
        let format = RbFormat::from_internal(internal).ok_or(GlError::InvalidEnum)?;
        let max = MAX_RENDERBUFFER_SIZE as GLsizei;
        if !(0..=max).contains(&w) || !(0..=max).contains(&h) {
            return Err(GlError::InvalidValue);
        }
        // Mesa has ARB_internalformat_query: more samples than the format offers is
        // INVALID_OPERATION, a negative count INVALID_VALUE.
        if samples < 0 {
            return Err(GlError::InvalidValue);
        }
        if samples > MAX_SAMPLES {
            return Err(GlError::InvalidOperation);
        }
        if self.fbo.bound_renderbuffer_mut().is_none() {
            return Err(GlError::InvalidOperation);
        }
        self.fbo_edit(|c| {
            let rb = c
                .fbo
                .bound_renderbuffer_mut()
                .ok_or(GlError::InvalidOperation)?;
            // llvmpipe's one multisample count: any request of 1..=4 gets 4.
            let samples = if samples > 0 { MAX_SAMPLES as u32 } else { 0 };
            rb.allocate(internal, format, w as usize, h as usize, samples)?;
            let name = c.fbo.renderbuffer;
            c.fbo.bump(Attachment::Renderbuffer(name));
            Ok(())
        })
    }

    /// glBlitFramebuffer from the read to the draw framebuffer.
    pub(crate) fn blit_framebuffer(
        &mut self,
        src: [GLint; 4],
        dst: [GLint; 4],
        mask: GLbitfield,
        filter: GLenum,
    ) -> GlResult<()> {
        let all = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
        if mask & !all != 0 {
            return Err(GlError::InvalidValue);
        }
        let linear = match filter {
            GL_NEAREST => false,
            GL_LINEAR => true,
            _ => return Err(GlError::InvalidEnum),
        };
        if linear && mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT) != 0 {
            return Err(GlError::InvalidOperation);
        }
        let m = crate::pixels::blit::BlitMask {
            color: mask & GL_COLOR_BUFFER_BIT != 0,
            depth: mask & GL_DEPTH_BUFFER_BIT != 0,
            stencil: mask & GL_STENCIL_BUFFER_BIT != 0,
        };
        crate::context::pixel_ops::blit::blit(self, src, dst, m, linear)
    }
}
