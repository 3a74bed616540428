//! The fragment operations' plan: which tests run, blending and logic op, from the
//! enable bits and the fragment state.

use crate::fragment::{BlendPlan, DepthPlan, FragPlan, StencilFacePlan, StencilPlan};
use crate::framebuffer::{float_to_ubyte, DepthFormat};
use crate::pipe::{BlendEquation, BlendFactor, Cap, Caps, CompareFunc, FragmentOps};
use crate::pipe::{LogicOp, ShadeModel};

/// The state the fragment operations are planned from.
#[derive(Clone, Copy, Debug)]
pub struct FragState<'a> {
    /// glEnable bits.
    pub caps: &'a Caps,
    /// Blending, alpha test, stencil and logic op.
    pub ops: &'a FragmentOps,
    /// glDepthFunc.
    pub depth_func: CompareFunc,
    /// glDepthMask.
    pub depth_mask: bool,
    /// glShadeModel.
    pub shade_model: ShadeModel,
    /// The colour channels drawing writes (glColorMask, none under GL_NONE).
    pub color_mask: [bool; 4],
}

/// The fragment plan of `s` for buffers of `depth_format` (and a stencil buffer when
/// `has_stencil`); `fma` when the host fuses multiply-adds. Fog, separate specular,
/// sample counting, smoothing and multisampling are left off for the draw to add.
pub fn fragment(
    s: &FragState<'_>,
    depth_format: DepthFormat,
    has_stencil: bool,
    fma: bool,
) -> FragPlan {
    let caps = s.caps;
    let fr = s.ops;
    let depth =
        (caps.get(Cap::DepthTest) && depth_format != DepthFormat::None).then_some(DepthPlan {
            func: s.depth_func,
            write: s.depth_mask,
            format: depth_format,
        });
    let alpha = (caps.get(Cap::AlphaTest) && fr.alpha_func != CompareFunc::Always)
        .then(|| (fr.alpha_func, float_to_ubyte(fr.alpha_ref)));
    let stencil = (caps.get(Cap::StencilTest) && has_stencil).then(|| StencilPlan {
        front: StencilFacePlan::new(&fr.stencil_front),
        back: StencilFacePlan::new(&fr.stencil_back),
    });
    let logic =
        (caps.get(Cap::ColorLogicOp) && fr.logic_op != LogicOp::Copy).then_some(fr.logic_op);
    let b = &fr.blend;
    let blend = (caps.get(Cap::Blend) && !caps.get(Cap::ColorLogicOp)).then(|| {
        // The state tracker forces ONE, ONE for MIN and MAX.
        let fix = |eq: BlendEquation, f: BlendFactor| {
            if matches!(eq, BlendEquation::Min | BlendEquation::Max) {
                BlendFactor::One
            } else {
                f
            }
        };
        BlendPlan {
            src_rgb: fix(b.eq_rgb, b.src_rgb),
            dst_rgb: fix(b.eq_rgb, b.dst_rgb),
            src_a: fix(b.eq_a, b.src_a),
            dst_a: fix(b.eq_a, b.dst_a),
            eq_rgb: b.eq_rgb,
            eq_a: b.eq_a,
            color: b.color.map(float_to_ubyte),
        }
    });
    // Blending that leaves the source unchanged (ONE, ZERO, ADD) is no blending.
    let blend = blend.filter(|p| {
        !(p.src_rgb == BlendFactor::One
            && p.src_a == BlendFactor::One
            && p.dst_rgb == BlendFactor::Zero
            && p.dst_a == BlendFactor::Zero
            && p.eq_rgb == BlendEquation::Add
            && p.eq_a == BlendEquation::Add)
    });
    FragPlan {
        depth,
        flat: s.shade_model == ShadeModel::Flat,
        color_mask: s.color_mask,
        fma,
        alpha,
        stencil,
        blend,
        logic,
        separate_specular: false,
        fog: None,
        count_samples: false,
        smooth: None,
        ms: None,
        blend_color: b.color,
        // set by the draw, which knows the colour buffer (`srgb_store`)
        srgb: false,
        shader: None,
        more_buffers: 0,
    }
}

/// Whether a draw into a colour buffer that is sRGB-encoded (`buffer_srgb`) encodes its
/// writes: only while GL_FRAMEBUFFER_SRGB is on (llvmpipe then views the surface through
/// its sRGB format; otherwise through the linear one).
pub fn srgb_store(caps: &Caps, buffer_srgb: bool) -> bool {
    buffer_srgb && caps.get(Cap::FramebufferSrgb)
}
