//! Texture coordinate generation, computed as llvmpipe runs Mesa's fixed-function vertex
//! program (`main/ffvertex_prog.c`, `build_texture_transform`, `build_sphere_texgen`,
//! `build_reflect_texgen`), in f32.
//!
//! Numbers (docs/llvmpipe-rules.md §1, §3): DP4/DP3 become multiply/add chains summed from
//! the highest component down; MAD is a multiply then an add; RSQ is `1/sqrt(|x|)`.
//! - object linear: `dp4(object position, object plane)`;
//! - eye linear: `dp4(eye position, eye plane)`, the eye position being the modelview
//!   transform of [`super::lighting::eye_position`] (shared with lighting and fog);
//! - sphere map: `u = normalize(eye.xyz)`, `r = u - (2·dp3(n, u))·n`,
//!   `m = rsq(dp3(r + (0,0,1), r + (0,0,1)))·0.5`, result `r·m + 0.5`;
//! - reflection map: `r`; normal map: `n`.
//!
//! `n` is the program's transformed normal: every mode that reads it needs eye
//! coordinates, so it is the inverse-transpose modelview times the normal, then
//! normalised (GL_NORMALIZE) or scaled (GL_RESCALE_NORMAL), as in lighting.
//! Coordinates whose generation is disabled pass the vertex's texture coordinate through.

use super::gallivm_math::rsq;
use super::lighting::{dp3, inverse_transpose_rows};
use super::matrix::Mat4;
use super::mesa_matrix::MatFlags;
use crate::pipe::{TexGenMode, TexGenUnit};

/// `DP4` as llvmpipe lowers it: highest component first.
#[inline(always)]
pub fn dp4(a: [f32; 4], b: [f32; 4]) -> f32 {
    ((a[3] * b[3] + a[2] * b[2]) + a[1] * b[1]) + a[0] * b[0]
}

/// The generation of one texture unit, for the current draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenPlan {
    /// Mode of S, T, R, Q, `None` where generation is off.
    pub modes: [Option<TexGenMode>; 4],
    /// Object planes.
    pub object: [[f32; 4]; 4],
    /// Eye planes.
    pub eye: [[f32; 4]; 4],
}

impl TexGenPlan {
    /// The plan of a unit, or `None` when none of its coordinates is generated.
    pub fn new(u: &TexGenUnit) -> Option<TexGenPlan> {
        if u.enabled & 15 == 0 {
            return None;
        }
        Some(TexGenPlan {
            modes: std::array::from_fn(|c| (u.enabled & (1 << c) != 0).then_some(u.mode[c])),
            object: u.object_plane,
            eye: u.eye_plane,
        })
    }

    /// Whether any coordinate reads eye coordinates (Mesa's `TEXGEN_NEED_EYE_COORD`).
    pub fn needs_eye(&self) -> bool {
        self.modes.iter().flatten().any(|m| m.needs_eye())
    }

    /// Whether any coordinate reads the transformed normal.
    pub fn needs_normal(&self) -> bool {
        self.modes.iter().flatten().any(|m| {
            matches!(
                m,
                TexGenMode::SphereMap | TexGenMode::ReflectionMap | TexGenMode::NormalMap
            )
        })
    }
}

/// The transformed normal of the vertex program in eye space (texgen without lighting).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalXform {
    invtrans: [[f32; 3]; 3],
    normalize: bool,
    scale: Option<f32>,
}

impl NormalXform {
    /// The transform for modelview `mv` (Mesa flags `flags`) with GL_NORMALIZE and
    /// GL_RESCALE_NORMAL as given, in eye space.
    pub fn new(mv: &Mat4, flags: MatFlags, normalize: bool, rescale: bool) -> Self {
        let mut flags = flags;
        flags.analyse(&mv.0);
        let (invtrans, inv) = inverse_transpose_rows(mv, Some(flags));
        let mut scale = 1.0f32;
        if !flags.is_length_preserving() {
            let mut f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
            if f < 1e-12 {
                f = 1.0;
            }
            scale = 1.0 / f.sqrt();
        }
        NormalXform {
            invtrans,
            normalize,
            scale: rescale.then_some(scale),
        }
    }

    /// Transforms one normal.
    pub fn apply(&self, n: [f32; 3]) -> [f32; 3] {
        let t = self.invtrans.map(|row| dp3(n, row));
        if self.normalize {
            normalize(t)
        } else if let Some(s) = self.scale {
            t.map(|c| c * s)
        } else {
            t
        }
    }
}

/// The program's `emit_normalize_vec3`: `v · rsq(dp3(v, v))`.
#[inline(always)]
fn normalize(v: [f32; 3]) -> [f32; 3] {
    let s = rsq(dp3(v, v));
    v.map(|c| c * s)
}

/// The reflection vector `u - (2 n·u) n` with `u` the normalised eye position.
#[inline(always)]
fn reflect(n: [f32; 3], eye: [f32; 4]) -> [f32; 3] {
    let u = normalize([eye[0], eye[1], eye[2]]);
    let d = dp3(n, u);
    let d2 = d + d;
    std::array::from_fn(|i| -d2 * n[i] + u[i])
}

/// Generates the texture coordinates of one unit: `tc` is the vertex's own coordinate,
/// `obj` its object position, `eye` its eye position and `n` its transformed normal
/// (the last two only read when the plan needs them).
#[inline(always)]
pub fn generate(
    plan: &TexGenPlan,
    tc: [f32; 4],
    obj: [f32; 4],
    eye: [f32; 4],
    n: [f32; 3],
) -> [f32; 4] {
    let mut out = tc;
    let mut refl = None;
    for c in 0..4 {
        let Some(mode) = plan.modes[c] else { continue };
        out[c] = match mode {
            TexGenMode::ObjectLinear => dp4(obj, plan.object[c]),
            TexGenMode::EyeLinear => dp4(eye, plan.eye[c]),
            TexGenMode::NormalMap => n[c],
            TexGenMode::ReflectionMap => refl.get_or_insert_with(|| reflect(n, eye))[c],
            TexGenMode::SphereMap => {
                let r = *refl.get_or_insert_with(|| reflect(n, eye));
                let t = [r[0], r[1], r[2] + 1.0];
                let m = rsq(dp3(t, t)) * 0.5;
                r[c] * m + 0.5
            }
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipe::TexGenUnit;

    #[test]
    fn object_linear_and_passthrough() {
        let mut u = TexGenUnit {
            enabled: 1,
            ..Default::default()
        };
        u.mode[0] = TexGenMode::ObjectLinear;
        u.object_plane[0] = [0.5, 0.0, 0.0, 0.25];
        let p = TexGenPlan::new(&u).unwrap();
        let out = generate(
            &p,
            [9.0, 8.0, 7.0, 1.0],
            [2.0, 3.0, 4.0, 1.0],
            [0.0; 4],
            [0.0; 3],
        );
        assert_eq!(out, [1.25, 8.0, 7.0, 1.0]);
    }

    #[test]
    fn sphere_map_facing_viewer_is_centre() {
        let u = TexGenUnit {
            enabled: 3,
            mode: [TexGenMode::SphereMap; 4],
            ..Default::default()
        };
        let p = TexGenPlan::new(&u).unwrap();
        // Eye straight down -z, normal towards the viewer: r = (0,0,1), centre of the map.
        let out = generate(
            &p,
            [0.0, 0.0, 0.0, 1.0],
            [0.0; 4],
            [0.0, 0.0, -5.0, 1.0],
            [0.0, 0.0, 1.0],
        );
        assert_eq!(&out[..2], &[0.5, 0.5]);
    }
}
