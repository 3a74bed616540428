//! Per-fragment operation calls of GL 1.x (`GL/gl.h`): blending, alpha test, stencil,
//! logic op.
#![allow(non_snake_case)]

use super::types::*;
use super::with_ctx_list_keep;
use crate::context::clamp01;
use crate::context::error::GlError;
use crate::context::fragment_state::{BlendEquation, BlendFactor, LogicOp, StencilOp};
use crate::context::state::CompareFunc;
use crate::context::Context;

/// Which faces a stencil call changes.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Faces {
    Front,
    Back,
    Both,
}

impl Faces {
    /// Converts GL_FRONT/GL_BACK/GL_FRONT_AND_BACK.
    pub(crate) fn from_gl(e: GLenum) -> Result<Self, GlError> {
        use super::enums::*;
        Ok(match e {
            GL_FRONT => Faces::Front,
            GL_BACK => Faces::Back,
            GL_FRONT_AND_BACK => Faces::Both,
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

/// Applies `f` to the stencil state of the selected faces.
pub(crate) fn stencil_faces(
    c: &mut Context,
    faces: Faces,
    f: impl Fn(&mut crate::context::fragment_state::StencilFace),
) {
    let fr = &mut c.state.frag;
    if faces != Faces::Back {
        f(&mut fr.stencil_front);
    }
    if faces != Faces::Front {
        f(&mut fr.stencil_back);
    }
}

/// Shared by glBlendFunc and glBlendFuncSeparate.
pub(crate) fn blend_func(src_rgb: GLenum, dst_rgb: GLenum, src_a: GLenum, dst_a: GLenum) {
    with_ctx_list_keep(move |c| {
        let (sr, dr) = (
            BlendFactor::from_gl(src_rgb)?,
            BlendFactor::from_gl(dst_rgb)?,
        );
        let (sa, da) = (BlendFactor::from_gl(src_a)?, BlendFactor::from_gl(dst_a)?);
        let b = &mut c.state.frag.blend;
        (b.src_rgb, b.dst_rgb, b.src_a, b.dst_a) = (sr, dr, sa, da);
        Ok(())
    })
}

/// Shared by glBlendEquation and glBlendEquationSeparate.
pub(crate) fn blend_equation(rgb: GLenum, alpha: GLenum) {
    with_ctx_list_keep(move |c| {
        let (r, a) = (BlendEquation::from_gl(rgb)?, BlendEquation::from_gl(alpha)?);
        c.state.frag.blend.eq_rgb = r;
        c.state.frag.blend.eq_a = a;
        Ok(())
    })
}

/// Shared by glStencilFunc and glStencilFuncSeparate.
pub(crate) fn stencil_func(faces: Faces, func: GLenum, reference: GLint, mask: GLuint) {
    with_ctx_list_keep(move |c| {
        let f = CompareFunc::from_gl(func)?;
        stencil_faces(c, faces, |s| {
            s.func = f;
            s.reference = reference;
            s.value_mask = mask;
        });
        Ok(())
    })
}

/// Shared by glStencilOp and glStencilOpSeparate.
pub(crate) fn stencil_op(faces: Faces, fail: GLenum, zfail: GLenum, zpass: GLenum) {
    with_ctx_list_keep(move |c| {
        let (a, b, d) = (
            StencilOp::from_gl(fail)?,
            StencilOp::from_gl(zfail)?,
            StencilOp::from_gl(zpass)?,
        );
        stencil_faces(c, faces, |s| {
            s.fail = a;
            s.zfail = b;
            s.zpass = d;
        });
        Ok(())
    })
}

/// Shared by glStencilMask and glStencilMaskSeparate.
pub(crate) fn stencil_mask(faces: Faces, mask: GLuint) {
    with_ctx_list_keep(move |c| {
        stencil_faces(c, faces, |s| s.writemask = mask);
        Ok(())
    })
}

/// glBlendFunc.
#[no_mangle]
pub extern "C" fn glBlendFunc(sfactor: GLenum, dfactor: GLenum) {
    blend_func(sfactor, dfactor, sfactor, dfactor)
}

/// glBlendEquation (GL 1.4 / ARB_imaging).
#[no_mangle]
pub extern "C" fn glBlendEquation(mode: GLenum) {
    blend_equation(mode, mode)
}

/// glBlendColor (clamped to [0,1], as GL 1.x specifies).
#[no_mangle]
pub extern "C" fn glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
    with_ctx_list_keep(move |c| {
        c.state.frag.blend.color = [red, green, blue, alpha].map(|v| clamp01(v as f64) as f32);
        Ok(())
    })
}

/// glAlphaFunc.
#[no_mangle]
pub extern "C" fn glAlphaFunc(func: GLenum, ref_: GLclampf) {
    with_ctx_list_keep(move |c| {
        c.alpha_func(CompareFunc::from_gl(func)?, ref_);
        Ok(())
    })
}

/// glStencilFunc (both faces).
#[no_mangle]
pub extern "C" fn glStencilFunc(func: GLenum, ref_: GLint, mask: GLuint) {
    stencil_func(Faces::Both, func, ref_, mask)
}

/// glStencilOp (both faces).
#[no_mangle]
pub extern "C" fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) {
    stencil_op(Faces::Both, fail, zfail, zpass)
}

/// glStencilMask (both faces).
#[no_mangle]
pub extern "C" fn glStencilMask(mask: GLuint) {
    stencil_mask(Faces::Both, mask)
}

/// glLogicOp.
#[no_mangle]
pub extern "C" fn glLogicOp(opcode: GLenum) {
    with_ctx_list_keep(move |c| {
        let op = LogicOp::from_gl(opcode)?;
        c.state.frag.logic_op = op;
        Ok(())
    })
}
