//! The values of GLSL's built-in state uniforms (`gl_LightSource[]`, `gl_FrontMaterial`,
//! `gl_LightModel`, the light and light-model products, `gl_Fog`, `gl_DepthRange`,
//! `gl_ClipPlane[]`, `gl_Point`, `gl_TextureEnvColor[]`, the texgen planes) from the GL
//! state, as Mesa's `_mesa_fetch_state`
//! (`prog_statevars.c`) computes them, in f32 without fused multiply-adds:
//!
//! - `halfVector` is `normalize(normalize(position.xyz) + (0, 0, 1))` with `w = 1`, each
//!   normalisation `v · (1 / sqrtf(x² + y² + z²))` (skipped for a zero vector);
//! - `spotCosCutoff` is `_CosCutoff` (clamped at 0), `spotDirection` the eye-space
//!   direction;
//! - a light product's colour is the light's times the material's, channel by channel,
//!   with the material's alpha; the scene colour is `model ambient · material ambient +
//!   material emission` with the material's diffuse alpha;
//! - `gl_Fog.scale` is `1 / (end − start)`; `gl_DepthRange.diff` is `far − near`.
//!
//! The words follow the lowering's flattened layout: arrays element by element, struct
//! members in declaration order, each member's components packed.

use super::Context;
use crate::pipe::lighting::{Light, Material};

/// Mesa's `mesa_normalize3fv`.
fn normalize(v: [f32; 3]) -> [f32; 3] {
    let len = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if len == 0.0 {
        return v;
    }
    let inv = 1.0f32 / len.sqrt();
    v.map(|x| x * inv)
}

/// One `gl_LightSourceParameters`.
fn light_source(l: &Light, out: &mut Vec<f32>) {
    out.extend(l.ambient);
    out.extend(l.diffuse);
    out.extend(l.specular);
    out.extend(l.position);
    let p = normalize([l.position[0], l.position[1], l.position[2]]);
    let h = normalize([p[0], p[1], p[2] + 1.0]);
    out.extend(h);
    out.push(1.0);
    out.extend(l.spot_direction);
    out.push(l.spot_exponent);
    out.push(l.spot_cutoff);
    out.push(l.cos_cutoff);
    out.extend(l.attenuation);
}

/// One `gl_MaterialParameters`.
fn material(m: &Material, out: &mut Vec<f32>) {
    out.extend(m.emission);
    out.extend(m.ambient);
    out.extend(m.diffuse);
    out.extend(m.specular);
    out.push(m.shininess);
}

/// `a · b` per colour channel, with `b`'s alpha.
fn product(a: &[f32; 4], b: &[f32; 4]) -> [f32; 4] {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2], b[3]]
}

impl Context {
    /// The words of built-in uniform `name` (`count` components), or `None` when the
    /// draw does not supply it (the matrices: `builtin_matrices`).
    pub(crate) fn builtin_uniform_words(&self, name: &str, count: usize) -> Option<Vec<u32>> {
        if let Some(m) = self.builtin_matrix_words(name) {
            return (m.len() == count).then(|| m.iter().map(|x| x.to_bits()).collect());
        }
        let l = &self.light;
        let face = |name: &str| usize::from(name.starts_with("gl_Back"));
        let mut v = Vec::with_capacity(count);
        match name {
            "gl_LightSource" => l.lights.iter().for_each(|s| light_source(s, &mut v)),
            "gl_LightModel" => v.extend(l.model.ambient),
            "gl_FrontMaterial" | "gl_BackMaterial" => material(&l.material[face(name)], &mut v),
            "gl_FrontLightModelProduct" | "gl_BackLightModelProduct" => {
                let m = &l.material[face(name)];
                let a = &l.model.ambient;
                v.extend((0..3).map(|i| a[i] * m.ambient[i] + m.emission[i]));
                v.push(m.diffuse[3]);
            }
            "gl_FrontLightProduct" | "gl_BackLightProduct" => {
                let m = &l.material[face(name)];
                for s in &l.lights {
                    v.extend(product(&s.ambient, &m.ambient));
                    v.extend(product(&s.diffuse, &m.diffuse));
                    v.extend(product(&s.specular, &m.specular));
                }
            }
            "gl_Fog" => {
                let f = &l.fog;
                v.extend(f.color);
                v.extend([f.density, f.start, f.end, 1.0f32 / (f.end - f.start)]);
            }
            "gl_DepthRange" => {
                let [near, far] = self.state.depth_range.map(|d| d as f32);
                v.extend([near, far, far - near]);
            }
            "gl_ClipPlane" => v.extend(self.clip_planes.eye.iter().flatten()),
            "gl_Point" => {
                let p = &self.raster.point;
                v.extend([p.size, p.min_size, p.max_size, p.fade_threshold]);
                v.extend(p.attenuation);
            }
            // An int: its bits in the word.
            crate::shader::lower::INSTANCE_ID => v.push(f32::from_bits(self.draw_instance)),
            "gl_TextureEnvColor" => v.extend(self.textures.units.iter().flat_map(|u| u.env.color)),
            _ if name.starts_with("gl_EyePlane") || name.starts_with("gl_ObjectPlane") => {
                let k = "STRQ".find(name.chars().last()?)?;
                for u in &self.texgen.units {
                    v.extend(match name.starts_with("gl_Eye") {
                        true => u.eye_plane[k],
                        false => u.object_plane[k],
                    });
                }
            }
            _ => return None,
        }
        (v.len() == count).then(|| v.iter().map(|x| x.to_bits()).collect())
    }
}
