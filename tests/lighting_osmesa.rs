//! Per-vertex lighting against Mesa's OSMesa (llvmpipe): random lights, materials,
//! normals and modelviews (glRotate/glScale, GL_NORMALIZE, GL_RESCALE_NORMAL), one
//! flat-shaded triangle each, drawn into a GL_FLOAT buffer so that the provoking vertex's
//! clamped colour arrives unquantised; every channel must equal [`light_vertex`]'s f32
//! bits (the 8-bit `round_half_even(c·255)` match is reported too).
//!
//! Skipped (with a message) when `cc` or the system `libOSMesa` is missing. Environment:
//! `SOFTGL_LIGHT_CASES` (default 3000), `SOFTGL_LIGHT_VERBOSE=1` (print mismatches),
//! `SOFTGL_ISA` (a level without FMA pins the reference to `sse4.1`, see `softgl::cpu`),
//! `SOFTGL_LIGHT_FORCE_EYE=1` (force eye-space lighting, to show that it matters).

use softgl::context::lighting_state::LightingState;
use softgl::context::state::{Cap, Caps};
use softgl::ffi::enums::*;
use softgl::fixed_function::lighting::{eye_normal, eye_position, light_vertex, LightPlan};
use softgl::fixed_function::matrix::{Mat4, IDENTITY};
use softgl::fixed_function::mesa_matrix::MatFlags;
use std::path::PathBuf;
use std::process::Command;

const C_SRC: &str = r#"
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define W 16
int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    static float buf[W * W * 4];
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_FLOAT, W, W)) return 1;
    float v[64];
    int n = 0;
    while (1) {
        for (int i = 0; i < 60; i++) if (scanf("%f", &v[i]) != 1) goto done;
        const float *p = v;
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glShadeModel(GL_FLAT);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        /* light set with the identity modelview: eye space = given values */
        glLightfv(GL_LIGHT0, GL_POSITION, p + 0);
        glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, p + 4);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, p[7]);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, p[8]);
        glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, p[9]);
        glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, p[10]);
        glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, p[11]);
        glLightfv(GL_LIGHT0, GL_AMBIENT, p + 12);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, p + 16);
        glLightfv(GL_LIGHT0, GL_SPECULAR, p + 20);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, p + 24);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, p + 28);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, p + 32);
        glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, p + 36);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, p[40]);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, p + 41);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, (int)p[45]);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                      p[46] != 0 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
        if (p[50] != 0) glEnable(GL_NORMALIZE); else glDisable(GL_NORMALIZE);
        if (p[56] != 0) glEnable(GL_RESCALE_NORMAL); else glDisable(GL_RESCALE_NORMAL);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        if (p[51] != 0) glRotatef(p[51], p[52], p[53], p[54]);
        if (p[55] != 1) glScalef(p[55], p[55], p[55]);
        glNormal3f(p[47], p[48], p[49]);
        glBegin(GL_TRIANGLES);
        glVertex3f(p[57], -0.5f, p[58]);
        glVertex3f(0.5f, -0.5f, p[58]);
        glVertex3f(-0.5f, p[59], p[58]);
        glEnd();
        glFinish();
        int found = 0;
        for (int i = 0; i < W * W && !found; i++)
            if (buf[i * 4 + 3] == 1.0f) {
                unsigned u[3];
                memcpy(u, &buf[i * 4], 12);
                printf("%u %u %u\n", u[0], u[1], u[2]);
                found = 1;
            }
        if (!found) printf("x\n");
        n++;
    }
done:
    OSMesaDestroyContext(ctx);
    return 0;
}
"#;

/// A small deterministic generator (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
    fn range(&mut self, a: f32, b: f32) -> f32 {
        a + (b - a) * self.next()
    }
    fn color(&mut self) -> [f32; 4] {
        [self.next(), self.next(), self.next(), 1.0]
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Diffuse,
    Positional,
    Specular,
    Spot,
    LocalSeparate,
}

fn gen_case(r: &mut Rng, kind: Kind) -> Vec<f32> {
    let mut v = vec![0f32; 60];
    let positional =
        matches!(kind, Kind::Positional | Kind::Spot | Kind::LocalSeparate) && r.next() < 0.8;
    let pos = [r.range(-3.0, 3.0), r.range(-3.0, 3.0), r.range(-1.0, 4.0)];
    let w = if positional { r.range(0.5, 2.0) } else { 0.0 };
    v[0..4].copy_from_slice(&[pos[0], pos[1], pos[2], w]);
    v[4..7].copy_from_slice(&[r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(-1.0, 0.2)]);
    v[7] = if kind == Kind::Spot {
        r.range(5.0, 90.0)
    } else {
        180.0
    };
    v[8] = if kind == Kind::Spot {
        r.range(0.0, 128.0)
    } else {
        0.0
    };
    let att = kind != Kind::Diffuse && r.next() < 0.6;
    v[9] = if att { r.range(0.2, 2.0) } else { 1.0 };
    v[10] = if att { r.range(0.0, 1.0) } else { 0.0 };
    v[11] = if att { r.range(0.0, 0.5) } else { 0.0 };
    let spec = matches!(kind, Kind::Specular | Kind::Spot | Kind::LocalSeparate);
    for (i, c) in [r.color(), r.color(), r.color()].iter().enumerate() {
        v[12 + 4 * i..16 + 4 * i].copy_from_slice(c);
    }
    let mut md = r.color();
    md[3] = 1.0;
    let ms = if spec {
        r.color()
    } else {
        [0.0, 0.0, 0.0, 1.0]
    };
    let me = [r.range(0.0, 0.3), r.range(0.0, 0.3), r.range(0.0, 0.3), 1.0];
    v[24..28].copy_from_slice(&r.color());
    v[28..32].copy_from_slice(&md);
    v[32..36].copy_from_slice(&ms);
    v[36..40].copy_from_slice(&me);
    v[40] = if spec { r.range(0.0, 128.0) } else { 0.0 };
    v[41..45].copy_from_slice(&[r.range(0.0, 0.4), r.range(0.0, 0.4), r.range(0.0, 0.4), 1.0]);
    v[45] = (kind == Kind::LocalSeparate && r.next() < 0.5) as u8 as f32;
    v[46] = (kind == Kind::LocalSeparate && r.next() < 0.5) as u8 as f32;
    v[47..50].copy_from_slice(&[r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(0.0, 1.5)]);
    v[50] = (r.next() < 0.5) as u8 as f32;
    v[51] = if r.next() < 0.5 {
        r.range(-180.0, 180.0)
    } else {
        0.0
    };
    v[52..55].copy_from_slice(&[r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(-1.0, 1.0)]);
    v[55] = if r.next() < 0.3 {
        r.range(0.5, 1.2)
    } else {
        1.0
    };
    v[56] = (v[50] == 0.0 && r.next() < 0.5) as u8 as f32;
    v[57] = -0.5;
    v[58] = r.range(-0.3, 0.3);
    v[59] = 0.5;
    v
}

fn rhe(c: f32) -> i32 {
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    (c * 255.0).round_ties_even() as i32
}

/// Our colour for case `v`. `flags` carries Mesa's modelview flags from case to case:
/// glLoadIdentity keeps the geometry flags of earlier glRotate/glScale calls.
fn ours(v: &[f32], fma: bool, flags: &mut MatFlags) -> [f32; 3] {
    let mut ls = LightingState::default();
    let id = IDENTITY.0;
    let arr = |i: usize| [v[i], v[i + 1], v[i + 2], v[i + 3]];
    ls.set_light(GL_LIGHT0, GL_POSITION, &arr(0), &id).unwrap();
    ls.set_light(GL_LIGHT0, GL_SPOT_DIRECTION, &[v[4], v[5], v[6], 0.0], &id)
        .unwrap();
    for (k, pname) in [
        GL_SPOT_CUTOFF,
        GL_SPOT_EXPONENT,
        GL_CONSTANT_ATTENUATION,
        GL_LINEAR_ATTENUATION,
        GL_QUADRATIC_ATTENUATION,
    ]
    .iter()
    .enumerate()
    {
        ls.set_light(GL_LIGHT0, *pname, &[v[7 + k], 0.0, 0.0, 0.0], &id)
            .unwrap();
    }
    ls.set_light(GL_LIGHT0, GL_AMBIENT, &arr(12), &id).unwrap();
    ls.set_light(GL_LIGHT0, GL_DIFFUSE, &arr(16), &id).unwrap();
    ls.set_light(GL_LIGHT0, GL_SPECULAR, &arr(20), &id).unwrap();
    for (k, pname) in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION]
        .iter()
        .enumerate()
    {
        ls.set_material(GL_FRONT_AND_BACK, *pname, &arr(24 + 4 * k), false)
            .unwrap();
    }
    ls.set_material(
        GL_FRONT_AND_BACK,
        GL_SHININESS,
        &[v[40], 0.0, 0.0, 0.0],
        false,
    )
    .unwrap();
    ls.model.ambient = arr(41);
    ls.model.local_viewer = v[45] != 0.0;
    ls.model.separate_specular = v[46] != 0.0;
    let mut caps = Caps::default();
    caps.set(Cap::Lighting, true);
    caps.set(Cap::Light0, true);
    caps.set(Cap::Normalize, v[50] != 0.0);
    caps.set(Cap::RescaleNormal, v[56] != 0.0);
    let mut mv: Mat4 = IDENTITY;
    flags.on_load_identity();
    if v[51] != 0.0 {
        let before = mv;
        mv.rotate(v[51], v[52], v[53], v[54]);
        if mv != before {
            flags.on_rotate();
        }
    }
    if v[55] != 1.0 {
        mv.scale(v[55], v[55], v[55]);
        flags.on_scale(v[55], v[55], v[55]);
    }
    let force_eye = std::env::var("SOFTGL_LIGHT_FORCE_EYE").is_ok();
    let en = softgl::plan::light_enables(&caps);
    let plan = LightPlan::new(&ls, &en, [1.0; 4], &mv, Some(*flags), force_eye, fma).unwrap();
    let p = [v[57], v[59], v[58], 1.0]; // the last (provoking) vertex
    let eye = eye_position(&mv, [-0.5, p[1], p[2], 1.0]);
    let n = eye_normal(&plan, [v[47], v[48], v[49]]);
    let out = light_vertex(&plan, eye, n, [1.0; 4]);
    // llvmpipe's vertex colour clamp (max then min with x86 semantics) was observed to turn
    // a NaN channel into 1.0; the vertex stage owns that clamp, it is mirrored here.
    let clamp = |c: f32| {
        if c.is_nan() {
            1.0
        } else if c > 0.0 {
            c.min(1.0)
        } else {
            0.0
        }
    };
    // A float colour buffer: the vertex colours are clamped, the fragment sum is not.
    if ls.model.separate_specular {
        std::array::from_fn(|i| clamp(out.front[i]) + clamp(out.front_spec[i]))
    } else {
        std::array::from_fn(|i| clamp(out.front[i]))
    }
}

#[test]
fn lighting_matches_osmesa() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("lighting_osmesa");
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("ref.c");
    let exe = dir.join("ref");
    std::fs::write(&src, C_SRC).unwrap();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let ok = Command::new(&cc)
        .args(["-O1", "-o"])
        .arg(&exe)
        .arg(&src)
        .args(["-Wl,--allow-shlib-undefined", "-lOSMesa"])
        .status()
        .map(|s| s.success())
        .unwrap_or(false);
    if !ok {
        eprintln!("skipped: cannot build against the system libOSMesa");
        return;
    }
    let n: usize = std::env::var("SOFTGL_LIGHT_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3000);
    let kinds = [
        Kind::Diffuse,
        Kind::Positional,
        Kind::Specular,
        Kind::Spot,
        Kind::LocalSeparate,
    ];
    let mut rng = Rng(0x9E3779B97F4A7C15);
    let cases: Vec<(Kind, Vec<f32>)> = (0..n)
        .map(|i| {
            let k = kinds[i % kinds.len()];
            (k, gen_case(&mut rng, k))
        })
        .collect();
    let mut input = String::new();
    for (_, v) in &cases {
        for x in v {
            input.push_str(&format!("{:e} ", x));
        }
        input.push('\n');
    }
    let input_path = dir.join("cases.txt");
    std::fs::write(&input_path, &input).unwrap();
    let out = Command::new(&exe)
        .stdin(std::fs::File::open(&input_path).unwrap())
        .env("GALLIUM_DRIVER", "llvmpipe")
        .envs(softgl::cpu::reference_cpu_caps().map(|v| ("GALLIUM_OVERRIDE_CPU_CAPS", v)))
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let refs: Vec<Option<[f32; 3]>> = text
        .lines()
        .map(|l| {
            let v: Vec<u32> = l
                .split_whitespace()
                .filter_map(|x| x.parse().ok())
                .collect();
            (v.len() == 3).then(|| [0, 1, 2].map(|i| f32::from_bits(v[i])))
        })
        .collect();
    assert_eq!(refs.len(), cases.len(), "reference output incomplete");
    let fma = softgl::cpu::isa().fused();
    let mut flags = MatFlags::IDENTITY;
    let results: Vec<[f32; 3]> = cases
        .iter()
        .map(|(_, v)| ours(v, fma, &mut flags))
        .collect();
    let mut report = String::new();
    let mut diffuse_ok = true;
    for k in kinds {
        let (mut total, mut exact, mut byte_exact, mut worst_ulp) = (0, 0, 0, 0u32);
        let mut shown = 0;
        for (((kind, v), r), o) in cases.iter().zip(&refs).zip(&results) {
            let Some(r) = r else { continue };
            if *kind != k {
                continue;
            }
            total += 1;
            let o = *o;
            let ulp = (0..3)
                .map(|i| (o[i].to_bits() as i64 - r[i].to_bits() as i64).unsigned_abs() as u32)
                .max()
                .unwrap();
            if o.map(rhe) == r.map(rhe) {
                byte_exact += 1;
            }
            if ulp == 0 {
                exact += 1;
            } else {
                worst_ulp = worst_ulp.max(ulp);
                if std::env::var("SOFTGL_LIGHT_VERBOSE").is_ok() {
                    eprintln!(
                        "MISMATCH {k:?} norm={} rot={} scale={} rescale={} w={}",
                        v[50],
                        v[51] != 0.0,
                        v[55],
                        v[56],
                        v[3]
                    );
                }
                if shown < 3 && std::env::var("SOFTGL_LIGHT_VERBOSE").is_ok() {
                    eprintln!("{k:?} ours {o:?} ref {r:?} case {v:?}");
                    shown += 1;
                }
            }
        }
        let line = format!(
            "{k:?}: {exact}/{total} bit-exact f32 ({:.2}%), worst {worst_ulp} ulp; \
             8-bit {byte_exact}/{total}\n",
            100.0 * exact as f64 / total.max(1) as f64,
        );
        report.push_str(&line);
        if exact != total {
            diffuse_ok = false;
        }
    }
    eprint!("{report}");
    assert!(diffuse_ok, "lighting must be bit-exact:\n{report}");
}
