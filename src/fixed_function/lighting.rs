//! Per-vertex fixed-function lighting, computed the way llvmpipe runs Mesa's generated
//! vertex program (`main/ffvertex_prog.c`, `build_lighting`), in f32.
//!
//! Numbers (docs/llvmpipe-rules.md §1, §16):
//! - Every MAD is a multiply then an add, never fused; DP3 is `((a2·b2 + a1·b1) + a0·b0)`.
//! - RSQ is `1/sqrt(|x|)` (two correctly rounded operations); RCP is a division.
//! - LIT and the spot exponent use gallivm's polynomial `pow` ([`super::gallivm_math`]),
//!   whose internal multiply-adds *are* fused on FMA hosts ([`LightPlan::fma`]).
//! - CPU-side precomputations (light × material products, scene colour, normalised
//!   directions, half vectors, object-space light positions) follow `prog_statevars.c`
//!   and `light.c` operation for operation.
//!
//! Mesa lights in *object space* when nothing needs eye coordinates (all lights
//! directional, no spot, no local viewer, no separate specular, a length-preserving
//! modelview, no eye-space texgen or point attenuation): then the normal is used as given
//! and the light directions are transformed into object space instead. [`LightPlan`]
//! reproduces that choice because it changes the rounding.
//!
//! Quirks reproduced on purpose: with all shininesses 0 and an attenuated or spot light,
//! Mesa's program feeds `n·L` into LIT's exponent, so the specular factor is
//! `pow(n·L, n·L)` (not 1); `pow(0, 0)` is 0; distance attenuation builds `(r·d, d, q)`
//! with `q = VP·VP`, `r = rsq(q)` and `d = sqrt(q)` (NIR rewrites `rcp(rsq(q))` into
//! `sqrt(q)` and `sqrt(q)·sqrt(q)` into `|q|`), so its first component is not exactly 1.
//! Measured bit-exact in f32 against OSMesa (tests/lighting_osmesa.rs, float buffer).
//!
//! The outputs are not clamped; the vertex stage clamps colours to [0, 1] as llvmpipe's
//! draw module does.

#[cfg(target_arch = "x86_64")]
pub mod lanes;

use super::gallivm_math::{pow, rsq};
use super::matrix::Mat4;
use super::mesa_matrix::MatFlags;
use crate::pipe::{LightModel, LightingState, Material, Tracked, MAX_LIGHTS};

/// `DP3` as llvmpipe lowers it: highest component first.
#[inline(always)]
pub fn dp3(a: [f32; 3], b: [f32; 3]) -> f32 {
    (a[2] * b[2] + a[1] * b[1]) + a[0] * b[0]
}

#[inline(always)]
fn xyz(v: [f32; 4]) -> [f32; 3] {
    [v[0], v[1], v[2]]
}

#[inline(always)]
fn scale3(v: [f32; 3], s: f32) -> [f32; 3] {
    [v[0] * s, v[1] * s, v[2] * s]
}

/// The program's `emit_normalize_vec3`: `v · rsq(dp3(v, v))`.
#[inline(always)]
fn normalize_shader(v: [f32; 3]) -> [f32; 3] {
    scale3(v, rsq(dp3(v, v)))
}

/// Mesa's C `NORMALIZE_3FV`: left-to-right length, `1.0f/sqrtf`, skipped for length 0.
pub fn normalize_cpu(v: [f32; 3]) -> [f32; 3] {
    let len = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if len != 0.0 {
        scale3(v, 1.0 / len.sqrt())
    } else {
        v
    }
}

/// The eye position as the program computes it (`emit_transpose_matrix_transform_vec4`):
/// `((x·C0 + y·C1) + z·C2) + w·C3` with each product and sum rounded.
pub fn eye_position(mv: &Mat4, p: [f32; 4]) -> [f32; 4] {
    let m = &mv.0;
    std::array::from_fn(|r| {
        let t = p[0] * m[r];
        let t = p[1] * m[4 + r] + t;
        let t = p[2] * m[8 + r] + t;
        p[3] * m[12 + r] + t
    })
}

/// Light, material and colour outputs of one vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LitColors {
    /// Front primary colour (COL0).
    pub front: [f32; 4],
    /// Back primary colour (BFC0); equal to `front` without two-sided lighting.
    pub back: [f32; 4],
    /// Front secondary colour (COL1): the specular sum with GL_SEPARATE_SPECULAR_COLOR,
    /// otherwise (0,0,0,1).
    pub front_spec: [f32; 4],
    /// Back secondary colour (BFC1).
    pub back_spec: [f32; 4],
}

/// One enabled light, with its per-draw constants.
#[derive(Clone, Copy, Debug)]
struct PlannedLight {
    /// Positional (w ≠ 0): `pos` is the position divided by w; directional: `pos` is the
    /// normalised direction to the light (VP).
    positional: bool,
    pos: [f32; 3],
    /// STATE_LIGHT_HALF_VECTOR (directional light, infinite viewer).
    half: [f32; 3],
    /// Normalised spot direction, cos cutoff, exponent (cutoff ≠ 180).
    spot: Option<([f32; 3], f32, f32)>,
    /// Attenuation factors when they are not (1,0,0) and the light is positional.
    atten: Option<[f32; 3]>,
    /// The light's ambient, diffuse, specular (for tracked material terms).
    colors: [[f32; 4]; 3],
    /// STATE_LIGHTPROD per face: ambient, diffuse, specular.
    prod: [[[f32; 4]; 3]; 2],
}

/// The enables lighting reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LightEnables {
    /// GL_LIGHTING.
    pub lighting: bool,
    /// GL_LIGHT0 … GL_LIGHT7.
    pub lights: [bool; MAX_LIGHTS],
    /// GL_NORMALIZE.
    pub normalize: bool,
    /// GL_RESCALE_NORMAL.
    pub rescale_normal: bool,
    /// GL_COLOR_MATERIAL.
    pub color_material: bool,
}

/// Everything the per-vertex lighting needs, computed once per draw from the state.
#[derive(Clone, Debug)]
pub struct LightPlan {
    /// Whether gallivm's multiply-adds fuse on this host.
    pub fma: bool,
    /// Mesa's `_NeedEyeCoords`: lighting in eye space (otherwise object space).
    pub need_eye_coords: bool,
    normalize: bool,
    /// Some(scale) when the normal is multiplied by STATE_NORMAL_SCALE.
    normal_scale: Option<f32>,
    /// Rows of the inverse-transpose modelview (columns of Mesa's inverse).
    invtrans: [[f32; 3]; 3],
    /// glLightModel: ambient, local viewer, two-sided, separate specular.
    model: LightModel,
    shininess_is_zero: bool,
    material: [Material; 2],
    tracked: [Tracked; 2],
    scene: [[f32; 4]; 2],
    lights: Vec<PlannedLight>,
    /// The vertex's own materials (glMaterial inside glBegin/glEnd): lit with per-vertex
    /// products and scene colour, as Mesa's program does for material attributes.
    pub vertex_material: Option<[Material; 2]>,
}

/// The rows of the inverse transpose of the modelview's upper 3x3 (what
/// STATE_MODELVIEW_MATRIX_INVTRANS gives the program), and the inverse itself.
pub fn inverse_transpose_rows(mv: &Mat4, flags: Option<MatFlags>) -> ([[f32; 3]; 3], [f32; 16]) {
    let mut f = flags.unwrap_or_else(|| MatFlags::from_scratch(&mv.0));
    let inv = f.inverse(&mv.0);
    (
        std::array::from_fn(|r| [inv[r * 4], inv[r * 4 + 1], inv[r * 4 + 2]]),
        inv,
    )
}

impl LightPlan {
    /// The plan for the current state, or `None` when GL_LIGHTING is off.
    ///
    /// `mv_flags` are Mesa's flags of the modelview (see [`MatFlags`]); `None` classifies
    /// the matrix from its contents. `other_eye_coords` is true when something besides
    /// lighting needs eye coordinates (eye-linear/sphere/reflection/normal-map texgen,
    /// point-size attenuation), which moves lighting into eye space.
    pub fn new(
        ls: &LightingState,
        en: &LightEnables,
        current_color: [f32; 4],
        mv: &Mat4,
        mv_flags: Option<MatFlags>,
        other_eye_coords: bool,
        fma: bool,
    ) -> Option<LightPlan> {
        if !en.lighting {
            return None;
        }
        let enabled: Vec<usize> = (0..MAX_LIGHTS).filter(|&i| en.lights[i]).collect();
        let model = &ls.model;
        let mut flags = mv_flags.unwrap_or_else(|| MatFlags::from_scratch(&mv.0));
        flags.analyse(&mv.0);
        let light_need_eye = enabled.iter().any(|&i| {
            let l = &ls.lights[i];
            l.position[3] != 0.0 || l.spot_cutoff != 180.0
        }) || model.separate_specular
            || model.local_viewer;
        let need_eye_coords = other_eye_coords || light_need_eye || !flags.is_length_preserving();
        let (invtrans, inv) = inverse_transpose_rows(mv, Some(flags));
        let m = &mv.0;

        let normalize = en.normalize;
        let rescale = en.rescale_normal;
        // update_modelview_scale
        let mut inv_scale = 1.0f32;
        if !flags.is_length_preserving() {
            let mut f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
            if f < 1e-12 {
                f = 1.0;
            }
            inv_scale = if need_eye_coords {
                1.0 / f.sqrt()
            } else {
                f.sqrt()
            };
        }
        let normal_scale = (need_eye_coords == rescale).then_some(inv_scale);

        let cm = en.color_material;
        let tracked = if cm {
            [ls.color_material.tracked(0), ls.color_material.tracked(1)]
        } else {
            [Tracked::default(); 2]
        };
        // With GL_COLOR_MATERIAL on, Mesa's material already holds the current colour.
        let mut material = ls.material;
        if cm {
            let mut tmp = ls.clone();
            tmp.sync_color_material(current_color);
            material = tmp.material;
        }
        let two_side = model.two_side;
        let shininess_is_zero =
            material[0].shininess == 0.0 && !(two_side && material[1].shininess != 0.0);
        let scene = [0, 1].map(|f| scene_color(&model.ambient, &material[f]));

        let eye_z_dir = if need_eye_coords {
            [0.0, 0.0, 1.0]
        } else {
            // TRANSFORM_NORMAL(_EyeZDir, (0,0,1), m)
            [
                0.0 * m[0] + 0.0 * m[1] + 1.0 * m[2],
                0.0 * m[4] + 0.0 * m[5] + 1.0 * m[6],
                0.0 * m[8] + 0.0 * m[9] + 1.0 * m[10],
            ]
        };
        let lights = enabled
            .iter()
            .map(|&i| {
                let l = &ls.lights[i];
                let mut p = if need_eye_coords {
                    l.position
                } else {
                    crate::pipe::transform_point(&inv, l.position)
                };
                let positional = l.position[3] != 0.0;
                let mut half = [0.0; 3];
                if positional {
                    let w_inv = 1.0 / p[3];
                    p = [p[0] * w_inv, p[1] * w_inv, p[2] * w_inv, p[3]];
                } else {
                    // STATE_LIGHT_POSITION_NORMALIZED and STATE_LIGHT_HALF_VECTOR
                    let n = normalize_cpu(xyz(p));
                    let s = [
                        n[0] + eye_z_dir[0],
                        n[1] + eye_z_dir[1],
                        n[2] + eye_z_dir[2],
                    ];
                    half = normalize_cpu(s);
                    p = [n[0], n[1], n[2], p[3]];
                }
                let spot = (l.spot_cutoff != 180.0).then(|| {
                    let d = normalize_cpu(normalize_cpu(l.spot_direction));
                    (d, l.cos_cutoff, l.spot_exponent)
                });
                let attenuated = l.attenuation != [1.0, 0.0, 0.0];
                let colors = [l.ambient, l.diffuse, l.specular];
                let prod = [0, 1].map(|f| {
                    let mt = &material[f];
                    [mt.ambient, mt.diffuse, mt.specular]
                        .iter()
                        .zip(colors.iter())
                        .map(|(mc, lc)| light_prod(lc, mc))
                        .collect::<Vec<_>>()
                        .try_into()
                        .unwrap_or([[0.0; 4]; 3])
                });
                PlannedLight {
                    positional,
                    pos: xyz(p),
                    half,
                    spot,
                    atten: (attenuated && positional).then_some(l.attenuation),
                    colors,
                    prod,
                }
            })
            .collect();
        Some(LightPlan {
            fma,
            need_eye_coords,
            normalize,
            normal_scale,
            invtrans,
            model: *model,
            shininess_is_zero,
            material,
            tracked,
            scene,
            lights,
            vertex_material: None,
        })
    }

    /// Prepares for per-vertex materials `mats`: a shininess given per vertex counts as
    /// active (Mesa's `check_active_shininess` sees the material attribute).
    pub fn vary_material(&mut self, mats: &[[Material; 2]]) {
        let two = self.model.two_side;
        if mats
            .iter()
            .any(|m| m[0].shininess != 0.0 || (two && m[1].shininess != 0.0))
        {
            self.shininess_is_zero = false;
        }
    }

    /// Whether [`light_vertex`] reads the eye position (positional lights, or a local
    /// viewer with a specular term). When it does, Mesa's fog coordinate comes from the
    /// same eye position (see [`super::fog::vertex_fog_coord`]).
    pub fn needs_eye_position(&self) -> bool {
        self.lights.iter().any(|l| l.positional)
            || (self.model.local_viewer && !self.shininess_is_zero)
    }

    /// Whether the back colours differ from the front ones (GL_LIGHT_MODEL_TWO_SIDE).
    pub fn two_side(&self) -> bool {
        self.model.two_side
    }

    /// Whether the secondary colour carries the specular sum.
    pub fn separate_specular(&self) -> bool {
        self.model.separate_specular
    }
}

/// STATE_LIGHTPROD: `light[i]·material[i]` for rgb, the material's alpha.
#[inline(always)]
fn light_prod(light: &[f32; 4], mat: &[f32; 4]) -> [f32; 4] {
    [
        light[0] * mat[0],
        light[1] * mat[1],
        light[2] * mat[2],
        mat[3],
    ]
}

/// STATE_LIGHTMODEL_SCENECOLOR: `lm_ambient·ambient + emission`, diffuse alpha.
#[inline(always)]
fn scene_color(lm: &[f32; 4], m: &Material) -> [f32; 4] {
    [
        lm[0] * m.ambient[0] + m.emission[0],
        lm[1] * m.ambient[1] + m.emission[1],
        lm[2] * m.ambient[2] + m.emission[2],
        m.diffuse[3],
    ]
}

/// The normal the lighting uses (`get_transformed_normal`): transformed by the
/// inverse-transpose modelview in eye space, then normalised (GL_NORMALIZE, with
/// `rsq`) or rescaled (GL_RESCALE_NORMAL's CPU-computed factor).
#[inline(always)]
pub fn eye_normal(plan: &LightPlan, normal: [f32; 3]) -> [f32; 3] {
    if !plan.need_eye_coords && !plan.normalize && plan.normal_scale.is_none() {
        return normal;
    }
    let mut n = normal;
    if plan.need_eye_coords {
        n = [
            dp3(normal, plan.invtrans[0]),
            dp3(normal, plan.invtrans[1]),
            dp3(normal, plan.invtrans[2]),
        ];
    }
    if plan.normalize {
        n = normalize_shader(n);
    } else if let Some(s) = plan.normal_scale {
        n = scale3(n, s);
    }
    n
}

/// LIT's y and z: `max(x, 0)` and `x > 0 ? pow(max(y, 0), clamp(w, ±128)) : 0`.
#[inline(always)]
fn lit(x: f32, y: f32, w: f32, fma: bool) -> (f32, f32) {
    let ly = x.max(0.0);
    #[allow(clippy::manual_clamp)] // fmin then fmax, as ptn_lit builds it
    let wc = w.min(128.0).max(-128.0);
    let p = pow(y.max(0.0), wc, fma);
    (ly, if 0.0 >= x { 0.0 } else { p })
}

#[inline(always)]
fn mad4(s: f32, v: [f32; 4], acc: [f32; 4]) -> [f32; 4] {
    std::array::from_fn(|i| s * v[i] + acc[i])
}

#[inline(always)]
fn add4(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
    std::array::from_fn(|i| a[i] + b[i])
}

#[inline(always)]
fn mul4(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
    std::array::from_fn(|i| a[i] * b[i])
}

/// Lights one vertex. `eye_pos` is [`eye_position`] of the vertex (read only when
/// [`LightPlan::needs_eye_position`]), `normal` is [`eye_normal`]'s result and `color` the
/// vertex's primary colour (used for GL_COLOR_MATERIAL).
///
/// Always inlined: the vertex stage has a copy compiled with FMA
/// ([`super::transform::VertexStage::run_into`]), where gallivm's fused multiply-adds and
/// floors are instructions rather than calls into libm.
#[inline(always)]
pub fn light_vertex(
    plan: &LightPlan,
    eye_pos: [f32; 4],
    normal: [f32; 3],
    color: [f32; 4],
) -> LitColors {
    let fma = plan.fma;
    let faces = if plan.model.two_side { 2 } else { 1 };
    // Per-face material with the tracked terms replaced by the vertex colour.
    // Copied only when something changes it (a per-draw copy of both faces' materials
    // was a visible part of lit vertices).
    let varying = plan.vertex_material.is_some();
    let base = plan.vertex_material.as_ref().unwrap_or(&plan.material);
    let mut mat_buf;
    let mut scene = plan.scene;
    let mat: &[Material; 2] = if varying || plan.tracked[..faces].iter().any(|t| t.any()) {
        mat_buf = *base;
        for f in 0..faces {
            let t = plan.tracked[f];
            if varying && !t.any() {
                scene[f] = scene_color(&plan.model.ambient, &mat_buf[f]);
            }
            if t.any() {
                mat_buf[f].apply_tracked(t, color);
                scene[f] = scene_color(&plan.model.ambient, &mat_buf[f]);
            }
        }
        &mat_buf
    } else {
        base
    };
    let mut col0 = scene;
    let mut col1 = [[0.0, 0.0, 0.0, 1.0]; 2];

    let v = xyz(eye_pos);
    let eye_hat = if plan.model.local_viewer && !plan.shininess_is_zero {
        normalize_shader(v)
    } else {
        [0.0; 3]
    };
    for l in &plan.lights {
        let (vp, dist) = if l.positional {
            let d = [l.pos[0] - v[0], l.pos[1] - v[1], l.pos[2] - v[2]];
            let q = dp3(d, d);
            let r = rsq(q);
            (scale3(d, r), Some((r, q)))
        } else {
            (l.pos, None)
        };
        let mut att: Option<f32> = None;
        if let Some((dir, cos_cutoff, exponent)) = l.spot {
            let s = dp3([-vp[0], -vp[1], -vp[2]], dir);
            let slt = if cos_cutoff < s { 1.0 } else { 0.0 };
            att = Some(slt * pow(s.abs(), exponent, fma));
        }
        if let (Some(k), Some((r, q))) = (l.atten, dist) {
            // dist = (r, r, r, r); RCP → yz = 1/r; MUL xz by y → (r·d, d, d·d).
            // NIR's `~frcp(frsq(a)) → fsqrt(a)` turns the RCP of the RSQ into a sqrt.
            // and `~fmul(fsqrt(a), fsqrt(a)) → fabs(a)` makes d·d the squared distance itself.
            let d = q.abs().sqrt();
            let dv = [r * d, d, q.abs()];
            let q = 1.0 / dp3(k, dv);
            att = Some(match att {
                Some(a) => q * a,
                None => q,
            });
        }
        let half = if plan.shininess_is_zero {
            [0.0; 3]
        } else if plan.model.local_viewer {
            normalize_shader([vp[0] - eye_hat[0], vp[1] - eye_hat[1], vp[2] - eye_hat[2]])
        } else if !l.positional {
            l.half
        } else {
            normalize_shader([vp[0] + 0.0, vp[1] + 0.0, vp[2] + 1.0])
        };
        let nl = dp3(normal, vp);
        // dots = (n·VP, n·H, -back shininess, front shininess), or n·VP everywhere.
        let dots = if plan.shininess_is_zero {
            [nl; 4]
        } else {
            [nl, dp3(normal, half), -mat[1].shininess, mat[0].shininess]
        };
        for f in 0..faces {
            let (x, y, w) = if f == 0 {
                (dots[0], dots[1], dots[3])
            } else {
                (-dots[0], -dots[1], -dots[2])
            };
            let [amb, diff, spec] = if varying || plan.tracked[f].any() {
                let m = &mat[f];
                [
                    mul4(l.colors[0], m.ambient),
                    mul4(l.colors[1], m.diffuse),
                    mul4(l.colors[2], m.specular),
                ]
            } else {
                l.prod[f]
            };
            let (ly, lz);
            if let Some(a) = att {
                let (y0, z0) = lit(x, y, w, fma);
                ly = y0 * a;
                lz = z0 * a;
                col0[f] = mad4(a, amb, col0[f]);
            } else {
                if plan.shininess_is_zero {
                    ly = 0.0f32.max(x);
                    lz = if 0.0 < x { 1.0 } else { 0.0 };
                } else {
                    (ly, lz) = lit(x, y, w, fma);
                }
                col0[f] = add4(amb, col0[f]);
            }
            col0[f] = mad4(ly, diff, col0[f]);
            if plan.model.separate_specular {
                col1[f] = mad4(lz, spec, col1[f]);
            } else {
                col0[f] = mad4(lz, spec, col0[f]);
            }
        }
    }
    let out = |f: usize| {
        let c = col0[f];
        [c[0], c[1], c[2], scene[f][3]]
    };
    let spec_out = |f: usize| {
        let c = col1[f];
        [c[0], c[1], c[2], 1.0]
    };
    let front = out(0);
    let front_spec = spec_out(0);
    let (back, back_spec) = if plan.model.two_side {
        (out(1), spec_out(1))
    } else {
        (front, front_spec)
    };
    LitColors {
        front,
        back,
        front_spec,
        back_spec,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed_function::matrix::IDENTITY;

    /// GL_LIGHTING on, light 0 on when `light0`, colour material when `cm`.
    fn caps(light0: bool, cm: bool) -> LightEnables {
        let mut lights = [false; MAX_LIGHTS];
        lights[0] = light0;
        LightEnables {
            lighting: true,
            lights,
            color_material: cm,
            ..Default::default()
        }
    }

    #[test]
    fn default_light0_diffuse() {
        let ls = LightingState::default();
        let c = caps(true, false);
        let plan = LightPlan::new(&ls, &c, [1.0; 4], &IDENTITY, None, false, false).unwrap();
        assert!(
            !plan.need_eye_coords,
            "directional light, identity: object space"
        );
        let n = eye_normal(&plan, [0.0, 0.0, 1.0]);
        let out = light_vertex(&plan, [0.0; 4], n, [1.0; 4]);
        // scene 0.2·0.2 = 0.04 (f32), + 0.8·1 diffuse; ambient light 0.
        let scene = 0.2f32 * 0.2f32 + 0.0;
        let want = 1.0f32 * 0.8f32 + (0.0f32 + scene);
        assert_eq!(out.front, [want, want, want, 1.0]);
        // Facing away: only the scene colour.
        let out = light_vertex(&plan, [0.0; 4], [0.0, 0.0, -1.0], [1.0; 4]);
        assert_eq!(out.front[0], scene);
    }

    #[test]
    fn no_lights_gives_scene_colour_and_disabled_gives_none() {
        let mut ls = LightingState::default();
        ls.material[0].emission = [0.1, 0.2, 0.3, 1.0];
        let plan = LightPlan::new(
            &ls,
            &caps(false, false),
            [1.0; 4],
            &IDENTITY,
            None,
            false,
            false,
        )
        .unwrap();
        let out = light_vertex(&plan, [0.0; 4], [0.0, 0.0, 1.0], [1.0; 4]);
        assert_eq!(out.front[2], 0.2f32 * 0.2 + 0.3);
        assert!(LightPlan::new(
            &ls,
            &LightEnables::default(),
            [1.0; 4],
            &IDENTITY,
            None,
            false,
            false
        )
        .is_none());
    }

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn color_material_tracks_vertex_colour() {
        let ls = LightingState::default();
        let c = caps(true, true);
        let plan = LightPlan::new(&ls, &c, [1.0; 4], &IDENTITY, None, false, false).unwrap();
        let col = [0.5, 0.25, 1.0, 0.75];
        let out = light_vertex(&plan, [0.0; 4], [0.0, 0.0, 1.0], col);
        for i in 0..3 {
            let scene = 0.2f32 * col[i] + 0.0;
            assert_eq!(out.front[i], 1.0 * (1.0 * col[i]) + (0.0 * col[i] + scene));
        }
        assert_eq!(out.front[3], 0.75, "alpha is the (tracked) diffuse alpha");
    }

    #[test]
    fn spot_and_attenuation_are_finite_and_bounded() {
        let mut ls = LightingState::default();
        let mv = IDENTITY.0;
        ls.set_light(0x4000, 0x1203, &[0.0, 0.0, 5.0, 1.0], &mv)
            .unwrap();
        ls.set_light(0x4000, 0x1206, &[30.0, 0.0, 0.0, 0.0], &mv)
            .unwrap();
        ls.set_light(0x4000, 0x1205, &[10.0, 0.0, 0.0, 0.0], &mv)
            .unwrap();
        ls.set_light(0x4000, 0x1208, &[0.1, 0.0, 0.0, 0.0], &mv)
            .unwrap();
        let c = caps(true, false);
        let plan = LightPlan::new(&ls, &c, [1.0; 4], &IDENTITY, None, false, false).unwrap();
        assert!(plan.need_eye_coords && plan.needs_eye_position());
        let on_axis = light_vertex(&plan, [0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        let off = light_vertex(&plan, [4.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        // On axis: spot factor 1, attenuation 1/(1 + 0.1·5) = 2/3.
        assert!((on_axis.front[0] - (0.04 + 0.8 / 1.5)).abs() < 1e-5);
        assert_eq!(off.front[0], 0.2f32 * 0.2 + 0.0, "outside the 30° cone");
    }
}
