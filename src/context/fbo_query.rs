//! The framebuffer-object queries: glGetRenderbufferParameteriv and
//! glGetFramebufferAttachmentParameteriv, on the window's buffers and on objects.

use super::fbo::{Attachment, ImageKind};
use super::fbo_api::{bound_name, point, renderbuffer_target, Point};
use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::*;
use crate::texture::Target;

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
        // Mesa answers the encoding of a missing window depth or stencil buffer
        return match (kind, pname) {
            (1 | 2, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING) => Ok(GL_LINEAR as GLint),
            _ => Err(GlError::InvalidOperation),
        };
    }
    let bits = c.color_bits();
    let depth = fb.map_or(0, |f| f.depth_format.bits());
    let stencil = fb.map_or(0, |f| f.stencil_bits());
    size_param(
        pname,
        match kind {
            0 => [bits[0], bits[1], bits[2], bits[3], 0, 0],
            // Mesa's window depth and stencil are one buffer when both exist (Z24S8)
            _ if depth > 0 && stencil > 0 => [0, 0, 0, 0, depth, stencil],
            1 => [0, 0, 0, 0, depth, 0],
            _ => [0, 0, 0, 0, 0, stencil],
        },
        false,
    )
    // With a depth buffer the window's stencil is the stencil of Mesa's Z24S8 buffer,
    // whose component type is GL_UNSIGNED_NORMALIZED (GL_INDEX for a stencil-only S8).
    .map(|v| match (kind, pname) {
        (2, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) if depth > 0 => {
            GL_UNSIGNED_NORMALIZED as GLint
        }
        _ => v,
    })
}

/// The size, component-type and encoding queries common to every attachment (`float`: a
/// float depth image, whose component type is GL_FLOAT).
fn size_param(pname: GLenum, sizes: [i32; 6], float: bool) -> GlResult<GLint> {
    Ok(match pname {
        // The six size tokens are consecutive, in the order of `sizes`.
        p @ GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE..=GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => {
            sizes[(p - GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE) as usize]
        }
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
    // GL 4.4 (Mesa in every profile): a combined depth+stencil point has no single type
    if attachment == GL_DEPTH_STENCIL_ATTACHMENT
        && pname == GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE
    {
        return Err(GlError::InvalidOperation);
    }
    match (pname, a) {
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::None) => return Ok(GL_NONE as GLint),
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::None) => return Ok(0),
        (_, Attachment::None) => return Err(GlError::InvalidOperation),
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Renderbuffer(_)) => {
            return Ok(GL_RENDERBUFFER as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Texture(_)) => {
            return Ok(GL_TEXTURE as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Renderbuffer(n)) => {
            return Ok(n as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Texture(t)) => {
            return Ok(t.name as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Attachment::Texture(t)) => {
            return Ok(t.level as GLint)
        }
        (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, Attachment::Texture(t)) => {
            let obj = c.textures.objects.get(&t.name);
            return Ok(if obj.and_then(|o| o.target) == Some(Target::Cube) {
                (GL_TEXTURE_CUBE_MAP_POSITIVE_X + t.face as u32) as GLint
            } else {
                0
            });
        }
        (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Attachment::Texture(t)) => {
            return Ok(t.layer as GLint)
        }
        (
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
            | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
            | GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
            Attachment::Renderbuffer(_),
        ) => return Err(GlError::InvalidEnum),
        _ => {}
    }
    let kind = c.fbo.image_info(a, &c.textures).map(|i| i.kind);
    let float = matches!(
        kind,
        Some(ImageKind::Depth(crate::framebuffer::DepthFormat::Z32F, _))
    );
    // A packed depth-stencil image (renderbuffer or texture) reports its format's depth
    // and stencil bits at either attachment point, as Mesa does.
    let packed = match a {
        Attachment::Texture(t) => t
            .find(&c.textures)
            .is_some_and(|(_, img)| super::pack::depth::is_depth_stencil(img.internal_format)),
        _ => matches!(kind, Some(ImageKind::Depth(_, true))),
    };
    // A wide image's own sizes and type (GL_FLOAT even for a luminance image, which has
    // no red, green, blue or alpha bits).
    if let Some((w, float)) = c.fbo.wide_sizes(a, &c.textures) {
        return size_param(pname, [w[0], w[1], w[2], w[3], 0, 0], float).map(|v| match pname {
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE if float => GL_FLOAT as GLint,
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => GL_UNSIGNED_NORMALIZED as GLint,
            _ => v,
        });
    }
    let sizes = match kind {
        Some(ImageKind::Color(b)) => {
            let alpha = !matches!(
                b,
                crate::texture::BaseFormat::Rgb | crate::texture::BaseFormat::Luminance
            );
            [8, 8, 8, if alpha { 8 } else { 0 }, 0, 0]
        }
        Some(ImageKind::Depth(d, _)) => [0, 0, 0, 0, d.bits(), if packed { 8 } else { 0 }],
        Some(ImageKind::Stencil) => [0, 0, 0, 0, 0, 8],
        _ => [0; 6],
    };
    // The component type is the format's: GL_INDEX only for S8 and for Z32F_S8's stencil
    // (a Z24S8 stencil is GL_UNSIGNED_NORMALIZED).
    let index = match kind {
        Some(ImageKind::Stencil) => true,
        Some(ImageKind::Depth(_, _)) => float && attachment == GL_STENCIL_ATTACHMENT,
        _ => false,
    };
    let srgb = c.fbo.is_srgb(a, &c.textures);
    size_param(pname, sizes, float).map(|v| match pname {
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE if index => GL_INDEX as GLint,
        GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING if srgb => GL_SRGB as GLint,
        GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE if matches!(kind, Some(ImageKind::Depth(..))) => {
            if float {
                GL_FLOAT as GLint
            } else {
                GL_UNSIGNED_NORMALIZED as GLint
            }
        }
        _ => v,
    })
}

impl Context {
    /// glGetRenderbufferParameteriv of the bound renderbuffer.
    pub(crate) fn get_renderbuffer_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
    ) -> GlResult<GLint> {
        renderbuffer_target(target)?;
        let rb = self
            .fbo
            .bound_renderbuffer_mut()
            .ok_or(GlError::InvalidOperation)?;
        let sizes = rb.format.map_or([0; 6], |f| f.sizes());
        Ok(match pname {
            GL_RENDERBUFFER_WIDTH => rb.width as GLint,
            GL_RENDERBUFFER_HEIGHT => rb.height as GLint,
            GL_RENDERBUFFER_INTERNAL_FORMAT => rb.internal as GLint,
            // As for attachments: consecutive tokens in the order of `sizes`.
            p @ GL_RENDERBUFFER_RED_SIZE..=GL_RENDERBUFFER_STENCIL_SIZE => {
                sizes[(p - GL_RENDERBUFFER_RED_SIZE) as usize]
            }
            GL_RENDERBUFFER_SAMPLES => rb.samples as GLint,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetFramebufferAttachmentParameteriv of the window or the bound object.
    pub(crate) fn get_framebuffer_attachment_parameter(
        &self,
        target: GLenum,
        attachment: GLenum,
        pname: GLenum,
    ) -> GlResult<GLint> {
        let name = bound_name(self, target)?;
        if name == 0 {
            window_attachment_param(self, attachment, pname)
        } else {
            object_attachment_param(self, name, attachment, pname)
        }
    }
}
