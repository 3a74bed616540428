//! Per-fragment work: interpolation of the varyings, the depth test and the colour write,
//! specialised per draw by a small [`FragPlan`] derived from the GL state.
//!
//! Numbers (llvmpipe-rules §7, §8, §13): every attribute is a plane evaluated per pixel
//! as `fmuladd(dady, py, fmuladd(dadx, px, a0))`; perspective attributes are multiplied by
//! `1 / w_plane`; z is clamped to [0,1] and quantised with round-half-even; colours are
//! clamped to [0,1] and converted with `round_half_even(c * 255)`.

pub mod span;

use crate::context::state::{Cap, CompareFunc, ShadeModel, State};
use crate::framebuffer::DepthFormat;

/// What the fragment stage does for one draw, derived once from the state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragPlan {
    /// The depth test, when enabled and a depth buffer exists.
    pub depth: Option<DepthPlan>,
    /// Flat shading: the colour is the provoking vertex's.
    pub flat: bool,
    /// glColorMask.
    pub color_mask: [bool; 4],
    /// Whether the host fuses multiply-adds.
    pub fma: bool,
}

/// The depth test of a draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthPlan {
    /// glDepthFunc.
    pub func: CompareFunc,
    /// glDepthMask.
    pub write: bool,
    /// Buffer layout.
    pub format: DepthFormat,
}

impl FragPlan {
    /// Derives the plan from the state and the framebuffer's buffers.
    pub fn new(state: &State, depth_format: DepthFormat, fma: bool) -> Self {
        let depth = (state.caps.get(Cap::DepthTest) && depth_format != DepthFormat::None)
            .then_some(DepthPlan {
                func: state.depth_func,
                write: state.depth_mask,
                format: depth_format,
            });
        FragPlan {
            depth,
            flat: state.shade_model == ShadeModel::Flat,
            color_mask: state.color_mask,
            fma,
        }
    }

    /// Whether fragments of this plan can change anything.
    pub fn writes_anything(&self) -> bool {
        self.color_mask.iter().any(|&m| m) || self.depth.is_some_and(|d| d.write)
    }
}
