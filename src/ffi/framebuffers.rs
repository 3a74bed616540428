//! Framebuffer and renderbuffer objects (GL_ARB_framebuffer_object, `GL/glext.h`): names,
//! bindings, attachments, storage, status and the attachment queries. The EXT names that
//! differ (glBindFramebufferEXT and glBindRenderbufferEXT accept names never generated)
//! are here too; the other EXT names are aliases (`aliases_ext.rs`).
#![allow(non_snake_case)]

use super::enums::*;
use super::glext_enums::*;
use super::types::*;
use super::{non_negative, with_ctx, with_ctx_list};
use crate::context::fbo::{
    Attachment, FboState, ImageKind, RbFormat, Renderbuffer, MAX_COLOR_ATTACHMENTS,
    MAX_RENDERBUFFER_SIZE, MAX_SAMPLES,
};
use crate::context::{Context, GlError, GlResult};
use crate::texture::{Target, MAX_3D_TEXTURE_SIZE, MAX_LEVELS};

/// Which bindings a framebuffer target names.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Binding {
    /// GL_FRAMEBUFFER: both.
    Both,
    /// GL_DRAW_FRAMEBUFFER.
    Draw,
    /// GL_READ_FRAMEBUFFER.
    Read,
}

fn binding(target: GLenum) -> GlResult<Binding> {
    match target {
        GL_FRAMEBUFFER => Ok(Binding::Both),
        GL_DRAW_FRAMEBUFFER => Ok(Binding::Draw),
        GL_READ_FRAMEBUFFER => Ok(Binding::Read),
        _ => Err(GlError::InvalidEnum),
    }
}

/// The object bound to `target` (GL_FRAMEBUFFER means the draw binding).
fn bound_name(c: &Context, target: GLenum) -> GlResult<u32> {
    Ok(match binding(target)? {
        Binding::Both | Binding::Draw => c.fbo.draw,
        Binding::Read => c.fbo.read,
    })
}

/// An attachment point: colour index, or depth / stencil / both.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Point {
    Color(usize),
    Depth,
    Stencil,
    DepthStencil,
}

fn point(attachment: GLenum) -> GlResult<Point> {
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

/// Sets attachment `p` of the object bound to `target` to `a`.
fn attach(c: &mut Context, target: GLenum, p: Point, a: Attachment) -> GlResult<()> {
    let name = bound_name(c, target)?;
    if name == 0 {
        return Err(GlError::InvalidOperation);
    }
    c.fbo_edit(|c| {
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

/// Writes `names` to `out` (when not null).
///
/// # Safety
/// `out` must be writable for `names.len()` values or null.
unsafe fn write_names(out: *mut GLuint, names: &[u32]) {
    if out.is_null() {
        return;
    }
    for (i, &n) in names.iter().enumerate() {
        // SAFETY: the caller promises room for the names.
        unsafe { *out.add(i) = n };
    }
}

/// Reads `n` names (empty when `p` is null).
///
/// # Safety
/// `p` must be readable for `n` names or null.
unsafe fn read_names(n: usize, p: *const GLuint) -> Vec<u32> {
    if p.is_null() {
        return Vec::new();
    }
    // SAFETY: the caller promises n readable names.
    unsafe { std::slice::from_raw_parts(p, n) }.to_vec()
}

/// glGenFramebuffers.
///
/// # Safety
/// `framebuffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffers(n: GLsizei, framebuffers: *mut GLuint) {
    // SAFETY: the caller's promise, passed on.
    unsafe { gen_names(n, framebuffers, FboState::gen_framebuffers) }
}

/// The body of glGenFramebuffers and glGenRenderbuffers: `n` new names from `gen`.
///
/// # Safety
/// `out` must be writable for `n` names or null.
unsafe fn gen_names(n: GLsizei, out: *mut GLuint, gen: fn(&mut FboState, usize) -> Vec<u32>) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if !out.is_null() {
            let names = gen(&mut c.fbo, n);
            // SAFETY: the caller promises room for n names.
            unsafe { write_names(out, &names) };
        }
        Ok(())
    })
}

/// glDeleteFramebuffers: a bound object's bindings revert to the window first.
///
/// # Safety
/// `framebuffers` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteFramebuffers(n: GLsizei, framebuffers: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        // SAFETY: the caller promises n readable names.
        for name in unsafe { read_names(n, framebuffers) } {
            if name == 0 {
                continue;
            }
            if c.fbo.draw == name {
                c.set_draw_framebuffer(0);
            }
            if c.fbo.read == name {
                c.fbo.read = 0;
            }
            c.fbo.framebuffers.remove(&name);
        }
        Ok(())
    })
}

/// Binds `name` to `target`; `any_name` lets names never generated create objects (the
/// EXT entry point's rule).
fn bind_framebuffer(target: GLenum, name: GLuint, any_name: bool) {
    with_ctx(|c| {
        let b = binding(target)?;
        if name != 0 {
            match c.fbo.framebuffers.get_mut(&name) {
                Some(Some(_)) => {}
                Some(slot) => *slot = Some(Default::default()),
                None if any_name => {
                    c.fbo.framebuffers.insert(name, Some(Default::default()));
                }
                None => return Err(GlError::InvalidOperation),
            }
        }
        if b != Binding::Read {
            c.set_draw_framebuffer(name);
        }
        if b != Binding::Draw {
            c.fbo.read = name;
        }
        Ok(())
    })
}

/// glBindFramebuffer (the compatibility profile, like the EXT call, takes names never
/// generated; only a core profile refuses them, as Mesa does).
#[no_mangle]
pub extern "C" fn glBindFramebuffer(target: GLenum, framebuffer: GLuint) {
    bind_framebuffer(target, framebuffer, true)
}

/// glBindFramebufferEXT (any name creates an object).
#[no_mangle]
pub extern "C" fn glBindFramebufferEXT(target: GLenum, framebuffer: GLuint) {
    bind_framebuffer(target, framebuffer, true)
}

/// glIsFramebuffer: true for names of objects that have been bound.
#[no_mangle]
pub extern "C" fn glIsFramebuffer(framebuffer: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.fbo.object(framebuffer).is_some() as GLboolean))
}

/// glCheckFramebufferStatus.
#[no_mangle]
pub extern "C" fn glCheckFramebufferStatus(target: GLenum) -> GLenum {
    with_ctx(|c| {
        let name = bound_name(c, target)?;
        Ok(c.fbo.status(name, &c.textures).to_gl())
    })
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
    Ok(Attachment::Texture {
        name: texture,
        face,
        level: level as usize,
        layer: layer as usize,
    })
}

/// The common body of the glFramebufferTexture* calls.
fn framebuffer_texture(
    target: GLenum,
    attachment: GLenum,
    textarget: Option<GLenum>,
    dims: Option<u8>,
    texture: GLuint,
    level: GLint,
    layer: GLint,
) {
    with_ctx(|c| {
        binding(target)?;
        let p = point(attachment)?;
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
        let a = texture_attachment(c, textarget, texture, level, layer)?;
        attach(c, target, p, a)
    })
}

/// glFramebufferTexture1D.
#[no_mangle]
pub extern "C" fn glFramebufferTexture1D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    framebuffer_texture(
        target,
        attachment,
        Some(textarget),
        Some(1),
        texture,
        level,
        0,
    )
}

/// glFramebufferTexture2D.
#[no_mangle]
pub extern "C" fn glFramebufferTexture2D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    framebuffer_texture(
        target,
        attachment,
        Some(textarget),
        Some(2),
        texture,
        level,
        0,
    )
}

/// glFramebufferTexture3D: slice `zoffset` of a 3D texture.
#[no_mangle]
pub extern "C" fn glFramebufferTexture3D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
    zoffset: GLint,
) {
    framebuffer_texture(
        target,
        attachment,
        Some(textarget),
        Some(3),
        texture,
        level,
        zoffset,
    )
}

/// glFramebufferTextureLayer: layer `layer` of a 3D texture.
#[no_mangle]
pub extern "C" fn glFramebufferTextureLayer(
    target: GLenum,
    attachment: GLenum,
    texture: GLuint,
    level: GLint,
    layer: GLint,
) {
    framebuffer_texture(target, attachment, None, None, texture, level, layer)
}

/// glFramebufferRenderbuffer.
#[no_mangle]
pub extern "C" fn glFramebufferRenderbuffer(
    target: GLenum,
    attachment: GLenum,
    renderbuffertarget: GLenum,
    renderbuffer: GLuint,
) {
    with_ctx(|c| {
        binding(target)?;
        let p = point(attachment)?;
        if renderbuffertarget != GL_RENDERBUFFER {
            return Err(GlError::InvalidEnum);
        }
        let a = if renderbuffer == 0 {
            Attachment::None
        } else if matches!(c.fbo.renderbuffers.get(&renderbuffer), Some(Some(_))) {
            Attachment::Renderbuffer(renderbuffer)
        } else {
            return Err(GlError::InvalidOperation);
        };
        attach(c, target, p, a)
    })
}

/// glGenRenderbuffers.
///
/// # Safety
/// `renderbuffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffers(n: GLsizei, renderbuffers: *mut GLuint) {
    // SAFETY: the caller's promise, passed on.
    unsafe { gen_names(n, renderbuffers, FboState::gen_renderbuffers) }
}

/// glDeleteRenderbuffers: detached from the bound framebuffers, unbound if bound.
///
/// # Safety
/// `renderbuffers` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteRenderbuffers(n: GLsizei, renderbuffers: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        // SAFETY: the caller promises n readable names.
        let names = unsafe { read_names(n, renderbuffers) };
        c.fbo_edit(|c| {
            c.detach_bound(|a| matches!(a, Attachment::Renderbuffer(r) if names.contains(&r)));
            for &name in names.iter().filter(|&&n| n != 0) {
                if c.fbo.renderbuffer == name {
                    c.fbo.renderbuffer = 0;
                }
                c.fbo.renderbuffers.remove(&name);
            }
            Ok(())
        })
    })
}

/// Binds renderbuffer `name`; `any_name` as for [`bind_framebuffer`].
fn bind_renderbuffer(target: GLenum, name: GLuint, any_name: bool) {
    with_ctx(|c| {
        if target != GL_RENDERBUFFER {
            return Err(GlError::InvalidEnum);
        }
        if name != 0 {
            match c.fbo.renderbuffers.get_mut(&name) {
                Some(Some(_)) => {}
                Some(slot) => *slot = Some(new_renderbuffer()),
                None if any_name => {
                    c.fbo.renderbuffers.insert(name, Some(new_renderbuffer()));
                }
                None => return Err(GlError::InvalidOperation),
            }
        }
        c.fbo.renderbuffer = name;
        Ok(())
    })
}

/// A renderbuffer object as first bound: no storage, internal format GL_RGBA.
fn new_renderbuffer() -> Renderbuffer {
    Renderbuffer {
        internal: GL_RGBA,
        ..Default::default()
    }
}

/// glBindRenderbuffer (names never generated are taken, as by glBindFramebuffer).
#[no_mangle]
pub extern "C" fn glBindRenderbuffer(target: GLenum, renderbuffer: GLuint) {
    bind_renderbuffer(target, renderbuffer, true)
}

/// glBindRenderbufferEXT (any name creates an object).
#[no_mangle]
pub extern "C" fn glBindRenderbufferEXT(target: GLenum, renderbuffer: GLuint) {
    bind_renderbuffer(target, renderbuffer, true)
}

/// glIsRenderbuffer: true for names of objects that have been bound.
#[no_mangle]
pub extern "C" fn glIsRenderbuffer(renderbuffer: GLuint) -> GLboolean {
    with_ctx(|c| Ok(matches!(c.fbo.renderbuffers.get(&renderbuffer), Some(Some(_))) as GLboolean))
}

/// The common body of glRenderbufferStorage(Multisample).
fn renderbuffer_storage(
    target: GLenum,
    samples: GLsizei,
    internal: GLenum,
    w: GLsizei,
    h: GLsizei,
) {
    with_ctx(|c| {
        if target != GL_RENDERBUFFER {
            return Err(GlError::InvalidEnum);
        }
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
        if c.fbo.bound_renderbuffer_mut().is_none() {
            return Err(GlError::InvalidOperation);
        }
        c.fbo_edit(|c| {
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
    })
}

/// glRenderbufferStorage.
#[no_mangle]
pub extern "C" fn glRenderbufferStorage(
    target: GLenum,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    renderbuffer_storage(target, 0, internalformat, width, height)
}

/// glRenderbufferStorageMultisample: `samples` above GL_MAX_SAMPLES is GL_INVALID_OPERATION.
#[no_mangle]
pub extern "C" fn glRenderbufferStorageMultisample(
    target: GLenum,
    samples: GLsizei,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    renderbuffer_storage(target, samples, internalformat, width, height)
}

/// glGetRenderbufferParameteriv.
///
/// # Safety
/// `params` must be writable for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetRenderbufferParameteriv(
    target: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    let v = with_ctx(|c| {
        if target != GL_RENDERBUFFER {
            return Err(GlError::InvalidEnum);
        }
        let rb = c
            .fbo
            .bound_renderbuffer_mut()
            .ok_or(GlError::InvalidOperation)?;
        let sizes = rb.format.map_or([0; 6], |f| f.sizes());
        Ok(Some(match pname {
            GL_RENDERBUFFER_WIDTH => rb.width as GLint,
            GL_RENDERBUFFER_HEIGHT => rb.height as GLint,
            GL_RENDERBUFFER_INTERNAL_FORMAT => rb.internal as GLint,
            GL_RENDERBUFFER_RED_SIZE => sizes[0],
            GL_RENDERBUFFER_GREEN_SIZE => sizes[1],
            GL_RENDERBUFFER_BLUE_SIZE => sizes[2],
            GL_RENDERBUFFER_ALPHA_SIZE => sizes[3],
            GL_RENDERBUFFER_DEPTH_SIZE => sizes[4],
            GL_RENDERBUFFER_STENCIL_SIZE => sizes[5],
            GL_RENDERBUFFER_SAMPLES => rb.samples as GLint,
            _ => return Err(GlError::InvalidEnum),
        }))
    });
    if let (Some(v), false) = (v, params.is_null()) {
        // SAFETY: the caller promises one writable value.
        unsafe { *params = v };
    }
}

/// glGetFramebufferAttachmentParameteriv.
///
/// # Safety
/// `params` must be writable for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameteriv(
    target: GLenum,
    attachment: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    let v = with_ctx(|c| {
        let name = bound_name(c, target)?;
        let v = if name == 0 {
            window_attachment_param(c, attachment, pname)?
        } else {
            object_attachment_param(c, name, attachment, pname)?
        };
        Ok(Some(v))
    });
    if let (Some(v), false) = (v, params.is_null()) {
        // SAFETY: the caller promises one writable value.
        unsafe { *params = v };
    }
}

/// An attachment query on the window (GL_FRAMEBUFFER_DEFAULT attachments).
fn window_attachment_param(c: &Context, attachment: GLenum, pname: GLenum) -> GlResult<GLint> {
    let fb = c.window_fb();
    let (kind, present) = match attachment {
        GL_FRONT_LEFT | GL_BACK_LEFT | GL_FRONT | GL_BACK | GL_LEFT => (0, true),
        GL_DEPTH => (1, fb.is_some_and(|f| !f.depth.is_empty())),
        GL_STENCIL => (2, fb.is_some_and(|f| !f.stencil.is_empty())),
        _ => return Err(GlError::InvalidEnum),
    };
    if pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE {
        return Ok(if present {
            GL_FRAMEBUFFER_DEFAULT
        } else {
            GL_NONE
        } as GLint);
    }
    if !present {
        return Err(GlError::InvalidOperation);
    }
    let bits = c.color_bits();
    let depth = fb.map_or(0, |f| f.depth_format.bits());
    let stencil = fb.map_or(0, |f| f.stencil_bits());
    size_param(
        pname,
        match kind {
            0 => [bits[0], bits[1], bits[2], bits[3], 0, 0],
            1 => [0, 0, 0, 0, depth, 0],
            _ => [0, 0, 0, 0, 0, stencil],
        },
        false,
    )
}

/// The size, component-type and encoding queries common to every attachment (`float`: a
/// float depth image, whose component type is GL_FLOAT).
fn size_param(pname: GLenum, sizes: [i32; 6], float: bool) -> GlResult<GLint> {
    Ok(match pname {
        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE => sizes[0],
        GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => sizes[1],
        GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => sizes[2],
        GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => sizes[3],
        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => sizes[4],
        GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => sizes[5],
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => {
            if sizes[..5].iter().all(|&s| s == 0) {
                GL_INDEX as GLint
            } else if float {
                GL_FLOAT as GLint
            } else {
                GL_UNSIGNED_NORMALIZED as GLint
            }
        }
        GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => GL_LINEAR as GLint,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// An attachment query on object `name`.
fn object_attachment_param(
    c: &Context,
    name: u32,
    attachment: GLenum,
    pname: GLenum,
) -> GlResult<GLint> {
    let f = c.fbo.object(name).ok_or(GlError::InvalidOperation)?;
    let a = match point(attachment).map_err(|_| GlError::InvalidEnum)? {
        Point::Color(i) => f.color[i],
        Point::Depth => f.depth,
        Point::Stencil => f.stencil,
        Point::DepthStencil if f.depth != f.stencil => return Err(GlError::InvalidOperation),
        Point::DepthStencil => f.depth,
    };
    match (pname, a) {
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::None) => return Ok(GL_NONE as GLint),
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::None) => return Ok(0),
        (_, Attachment::None) => return Err(GlError::InvalidOperation),
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Renderbuffer(_)) => {
            return Ok(GL_RENDERBUFFER as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Texture { .. }) => {
            return Ok(GL_TEXTURE as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Renderbuffer(n)) => {
            return Ok(n as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Texture { name, .. }) => {
            return Ok(name as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Attachment::Texture { level, .. }) => {
            return Ok(level as GLint)
        }
        (
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
            Attachment::Texture { name, face, .. },
        ) => {
            let cube = c.textures.objects.get(&name).and_then(|o| o.target) == Some(Target::Cube);
            return Ok(if cube {
                (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face as u32) as GLint
            } else {
                0
            });
        }
        (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Attachment::Texture { layer, .. }) => {
            return Ok(layer as GLint)
        }
        (
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
            | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
            | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
            Attachment::Renderbuffer(_),
        ) => return Err(GlError::InvalidEnum),
        _ => {}
    }
    let stencil_point = attachment == GL_STENCIL_ATTACHMENT;
    let kind = c.fbo.image_info(a, &c.textures).map(|i| i.kind);
    let float = matches!(
        kind,
        Some(ImageKind::Depth(crate::framebuffer::DepthFormat::Z32F, _))
    );
    let sizes = match kind {
        Some(ImageKind::Color(b)) => {
            let alpha = !matches!(
                b,
                crate::texture::BaseFormat::Rgb | crate::texture::BaseFormat::Luminance
            );
            [8, 8, 8, if alpha { 8 } else { 0 }, 0, 0]
        }
        Some(ImageKind::Depth(d, s)) => {
            let st = if s { 8 } else { 0 };
            if stencil_point {
                [0, 0, 0, 0, 0, st]
            } else {
                [0, 0, 0, 0, d.bits(), st]
            }
        }
        Some(ImageKind::Stencil) => [0, 0, 0, 0, 0, 8],
        _ => [0; 6],
    };
    size_param(pname, sizes, float)
}

/// glBlitFramebuffer.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glBlitFramebuffer(
    srcX0: GLint,
    srcY0: GLint,
    srcX1: GLint,
    srcY1: GLint,
    dstX0: GLint,
    dstY0: GLint,
    dstX1: GLint,
    dstY1: GLint,
    mask: GLbitfield,
    filter: GLenum,
) {
    // Compiled into display lists, as Mesa's OPCODE_BLIT_FRAMEBUFFER.
    with_ctx_list(move |c| {
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
        crate::context::pixel_ops::blit::blit(
            c,
            [srcX0, srcY0, srcX1, srcY1],
            [dstX0, dstY0, dstX1, dstY1],
            m,
            linear,
        )
    })
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

/// glBlitFramebufferEXT (GL_EXT_framebuffer_blit; Mesa resolves it through
/// OSMesaGetProcAddress without exporting it).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glBlitFramebufferEXT(
    srcX0: GLint,
    srcY0: GLint,
    srcX1: GLint,
    srcY1: GLint,
    dstX0: GLint,
    dstY0: GLint,
    dstX1: GLint,
    dstY1: GLint,
    mask: GLbitfield,
    filter: GLenum,
) {
    glBlitFramebuffer(
        srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter,
    )
}
