//! The lit block path ([`VertexStage::run_block`] with lighting) against the scalar
//! vertex stage, bit for bit.

use super::*;
use crate::fixed_function::lighting::{LightEnables, LightPlan};
use crate::fixed_function::matrix::{Mat4, IDENTITY};
use crate::fixed_function::mesa_matrix::MatFlags;
use crate::geometry::fetch::VertexIn;
use crate::geometry::Viewport;
use crate::pipe::{
    CurrentAttribs, Face, FogMode, FogState, LightingState, MaterialParam, TexGenMode, TexGenState,
    MAX_LIGHTS,
};

/// Random values with some specials mixed in (zeros of both signs, ±1, huge, NaN).
fn value(r: u32, scale: f32) -> f32 {
    const SPECIAL: [f32; 8] = [0.0, -0.0, 1.0, -1.0, 0.5, 1e30, f32::NAN, 2.0];
    if r.is_multiple_of(23) {
        SPECIAL[(r / 23) as usize % SPECIAL.len()]
    } else {
        (f32::from_bits((r >> 9) | 0x3f80_0000) - 1.5) * scale
    }
}

/// The lighting state of `case`: a directional headlight, a spot light with attenuation
/// and a positional light (or the headlight alone), with the model, material and colour
/// material switches the case's bits give.
fn state(case: u32, rng: &mut impl FnMut() -> u32) -> (LightingState, LightEnables) {
    let mut ls = LightingState::default();
    let mut en = LightEnables {
        lighting: true,
        lights: [false; MAX_LIGHTS],
        normalize: case & 32 != 0,
        rescale_normal: case & 512 != 0,
        color_material: case & 8 != 0,
    };
    let mut c = || value(rng(), 1.0).abs().min(1.0);
    ls.model.two_side = case & 2 != 0;
    ls.model.separate_specular = case & 4 != 0;
    ls.model.local_viewer = case & 16 != 0;
    ls.model.ambient = [c(), c(), c(), 1.0];
    for f in 0..2 {
        let m = &mut ls.material[f];
        m.ambient = [c(), c(), c(), c()];
        m.diffuse = [c(), c(), c(), c()];
        m.specular = [c(), c(), c(), 1.0];
        m.emission = [c() * 0.1, 0.0, c() * 0.1, 1.0];
        m.shininess = if case & 128 != 0 {
            0.0
        } else {
            1.0 + 100.0 * c()
        };
    }
    ls.color_material.mode = [
        MaterialParam::AmbientAndDiffuse,
        MaterialParam::Diffuse,
        MaterialParam::Specular,
        MaterialParam::Emission,
    ][(case >> 10) as usize % 4];
    ls.color_material.face =
        [Face::FrontAndBack, Face::Front, Face::Back][(case >> 12) as usize % 3];
    en.lights[0] = true;
    let l = &mut ls.lights[0];
    l.position = [0.0, 0.0, 1.0, 0.0];
    l.diffuse = [c(), c(), c(), 1.0];
    l.specular = [c(), c(), c(), 1.0];
    if case & 256 == 0 {
        en.lights[1] = true;
        let l = &mut ls.lights[1];
        l.position = [1.0, 4.0, 2.0, 1.0];
        l.spot_direction = [-0.2, -1.0, -0.3];
        l.spot_cutoff = 45.0;
        l.cos_cutoff = 45f32.to_radians().cos();
        l.spot_exponent = 10.0 * c();
        l.attenuation = [1.0, 0.1 * c(), 0.01 * c()];
        l.ambient = [c(), c(), c(), 1.0];
        l.diffuse = [c(), c(), c(), 1.0];
        l.specular = [c(), c(), c(), 1.0];
        en.lights[3] = true;
        let l = &mut ls.lights[3];
        l.position = [-2.0, 1.0, 3.0, 1.0];
        l.diffuse = [c(), c(), c(), 1.0];
    }
    (ls, en)
}

/// Every colour `run_block` writes for lit vertices equals what `run_into` writes, bit
/// for bit (NaN as one value), over the lighting configurations of the cases: fused or
/// not, two-sided, separate specular, colour material (each mode and face), local viewer,
/// GL_NORMALIZE and GL_RESCALE_NORMAL, a scaling modelview, zero shininess, directional
/// light alone (object-space lighting) or with spot and positional lights; runs starting
/// anywhere and of any length (partial blocks of lanes).
#[test]
fn lit_run_block_writes_what_run_into_writes() {
    let vp = Viewport::new([0, 0, 320, 240], [0.0, 1.0], 240);
    if !VertexStage::new(IDENTITY, IDENTITY, vp, false).block_ok() {
        return;
    }
    let mut rng = crate::test_rng::xorshift32(0x1157_0bad);
    let cur = CurrentAttribs::default();
    for case in 0..(1u32 << 15) {
        if case % 11 != 0 {
            continue; // a spread of the cases keeps the test quick
        }
        let (ls, en) = state(case, &mut rng);
        let s = if case & 64 != 0 { 0.5 } else { 1.0 };
        let mv = Mat4([
            0.8 * s,
            0.6 * s,
            0.0,
            0.0, //
            -0.6 * s,
            0.8 * s,
            0.0,
            0.0, //
            0.0,
            0.0,
            s,
            0.0, //
            0.3,
            -0.2,
            -5.0,
            1.0,
        ]);
        let fma = case & 1 != 0;
        let mut stage = VertexStage::new(mv, mv, vp, fma);
        stage.add_texture_unit(1, &IDENTITY);
        stage.add_texture_unit(3, &mv);
        // Texture coordinate generation on both units (eye-linear, sphere map,
        // object-linear), and fog of each mode, in some of the cases.
        let mut tg = TexGenState::default();
        let mode = [
            TexGenMode::EyeLinear,
            TexGenMode::SphereMap,
            TexGenMode::ObjectLinear,
        ];
        for (i, u) in [1, 3].into_iter().enumerate() {
            let g = &mut tg.units[u];
            g.enabled = ((case >> (2 * i)) & 3) as u8 * 5 % 16;
            g.mode = [
                mode[case as usize % 3],
                mode[(case as usize / 3) % 3],
                mode[0],
                mode[0],
            ];
            g.eye_plane[0] = [0.25, -1.0, 0.5, 2.0];
            g.object_plane[1] = [1.0, 0.5, -0.25, 0.0];
        }
        let other_eye = stage.add_texgen(
            &tg,
            MatFlags::from_scratch(&mv.0),
            en.normalize,
            en.rescale_normal,
        );
        if case % 3 != 0 {
            stage.fog = Some(FogState {
                mode: [FogMode::Linear, FogMode::Exp, FogMode::Exp2][case as usize % 3],
                start: 1.0,
                end: 9.0,
                density: 0.3,
                coord_from_attrib: case & 0x4000 != 0,
                ..Default::default()
            });
        }
        let color = [0.5, 0.25, 1.0, 0.75];
        stage.light = LightPlan::new(&ls, &en, color, &mv, None, other_eye, fma);
        if case % 5 == 4 {
            // Unlit, with the secondary colour: fog and texgen on the unlit block path.
            stage.light = None;
            stage.color_sum = true;
        }
        assert!(stage.block_ok());
        let n = 40 + (case as usize % 13);
        let verts: Vec<VertexIn> = (0..n)
            .map(|_| {
                let mut p = || value(rng(), 6.0);
                let mut v = VertexIn::with_current([p(), p(), p(), 1.0], &cur);
                v.normal = [p(), p(), p()];
                let mut c = || value(rng(), 2.0);
                v.color = [c(), c(), c(), c()];
                v.texcoord[3] = [c(), c(), c(), c()];
                v.fog_coord = c();
                v.secondary = [c(), c(), c(), c()];
                v
            })
            .collect();
        let mut slot = verts.new_slot();
        let mut want = vec![ClipVertex::default(); n];
        for (i, o) in want.iter_mut().enumerate() {
            verts.vertex_into(i, &mut slot);
            stage.run_into(&slot.v, o);
        }
        let first = case as usize % 5;
        let mut got = vec![ClipVertex::default(); n - first];
        let mut slot = verts.new_slot();
        stage.run_block(&verts[..], first, &mut slot, &mut got);
        let nv = stage.nvary();
        let bits = |v: &ClipVertex| -> Vec<u32> {
            v.clip
                .iter()
                .chain(&v.win)
                .chain(&v.vary[..nv])
                .map(|f| {
                    if f.is_nan() {
                        f32::NAN.to_bits()
                    } else {
                        f.to_bits()
                    }
                })
                .collect()
        };
        for (j, g) in got.iter().enumerate() {
            let w = &want[first + j];
            assert_eq!(bits(g), bits(w), "case {case:#x}, vertex {}", first + j);
        }
    }
}
