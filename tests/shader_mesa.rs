//! Fragment shaders lowered by `softgl::shader` and run by the engine's executor, against
//! the same shaders drawn by Mesa's llvmpipe (issue 43 items 2 and 4).
//!
//! Each case is a fragment shader drawn over a full 64×64 window: inputs from
//! `gl_FragCoord`, uniforms and one varying, the outputs as floats (an OSMesa GL_FLOAT
//! buffer on Mesa's side, the raw bits of each channel on ours). Every instruction-set
//! level the CPU has runs; the fused levels are compared with llvmpipe as it runs here
//! (FMA), the unfused ones with llvmpipe under `GALLIUM_OVERRIDE_CPU_CAPS=sse4.1`. The
//! table (exact share, largest ulp and absolute difference per built-in family) prints
//! with `--nocapture`; each family must reach its recorded exactness.

#[path = "shader_mesa/harness.rs"]
mod harness;

use harness::{mesa, ours, Case, Diff, VS};
use softgl::cpu::Isa;
use std::collections::BTreeMap;

/// `t` over the window: 4096 distinct values `(x + 64·y)·s.x + s.y`.
const T: &str = "vec2 p = gl_FragCoord.xy; float t = (p.x + p.y * 64.0) * s.x + s.y;";

/// The corners of `v`: per component `c0 + cx·X + cy·Y` at X, Y = ±1.
fn corners() -> [[f32; 4]; 4] {
    let c = [
        [0.25, 0.75, -1.5],
        [1.0, -2.0, 0.5],
        [0.0, 8.0, 4.0],
        [-1.0, 3.0, 1.0],
    ];
    let xy = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    xy.map(|(x, y)| c.map(|[c0, cx, cy]| c0 + cx * x + cy * y))
}

fn case(name: &'static str, family: &'static str, fs: String, s: [f32; 4]) -> Case {
    Case {
        name,
        family,
        vs: VS,
        fs: Box::leak(fs.into_boxed_str()),
        floats: vec![("s", s.to_vec())],
        ints: vec![],
        tex: corners(),
    }
}

/// A shader with `uniform vec4 s`, `t` defined, and `body` writing `gl_FragColor`.
fn fs(body: &str) -> String {
    format!("uniform vec4 s;\nvoid main() {{\n{T}\n{body}\n}}\n")
}

fn cases() -> Vec<Case> {
    let s_wide = [1.0 / 256.0, -8.3, 1.7, 0.45];
    let s_trig = [1.0 / 64.0, -32.0, 2.5, -0.75];
    let mut v = vec![
        case(
            "arith",
            "arithmetic",
            fs("float x = p.x * s.z + p.y * s.w - s.y;\n\
                float y = (p.y - s.w) / (p.x + s.x);\n\
                gl_FragColor = vec4(x, y, x * y - s.z, (x + s.w) / (y - 2.2));"),
            [0.3, 3.3, 0.37, -1.21],
        ),
        case(
            "exp_log",
            "exp2/log2/exp/log",
            fs(
                "gl_FragColor = vec4(exp2(t), log2(abs(t) + s.x), exp(t * 0.7), \
                log(abs(t) + 0.001));",
            ),
            s_wide,
        ),
        case(
            "pow",
            "pow",
            fs("gl_FragColor = vec4(pow(abs(t), s.z), pow(p.x / 64.0, t), \
                pow(2.5, t * 0.25), pow(t * t, s.w));"),
            s_wide,
        ),
        case(
            "sin_cos",
            "sin/cos/tan",
            fs("gl_FragColor = vec4(sin(t), cos(t), sin(t * s.z), tan(t * 0.1));"),
            s_trig,
        ),
        case(
            "rounding",
            "floor/ceil/fract/mod/sign/abs",
            fs("gl_FragColor = vec4(floor(t), ceil(t * s.z), fract(t), mod(t, s.z));"),
            s_wide,
        ),
        case(
            "rounding2",
            "floor/ceil/fract/mod/sign/abs",
            fs(
                "gl_FragColor = vec4(sign(floor(t) - s.w), abs(t), mod(-t, s.w), \
                fract(-t * s.z));",
            ),
            s_wide,
        ),
        case(
            "minmax",
            "min/max/clamp/mix/step/smoothstep",
            fs(
                "gl_FragColor = vec4(clamp(t, -1.5, s.z), mix(t, s.z, fract(t)), \
                step(s.w, t) + min(t, s.w), smoothstep(-2.0, s.z, t) + max(t * 0.5, -s.z));",
            ),
            s_wide,
        ),
        case(
            "geometry",
            "sqrt/inversesqrt/length/dot",
            fs("vec3 d = vec3(p * s.x - 0.3, t);\n\
                gl_FragColor = vec4(sqrt(abs(t)), inversesqrt(abs(t) + 0.01), length(d), \
                dot(d, vec3(s.z, s.w, 1.3)));"),
            s_wide,
        ),
        case(
            "geometry2",
            "normalize/cross/reflect/distance",
            fs("vec3 d = vec3(p * s.x - 0.3, t);\n\
                vec3 n = vec3(s.z, s.w, -0.6);\n\
                vec3 q = normalize(d); vec3 c = cross(d, n); vec3 r = reflect(d, normalize(n));\n\
                gl_FragColor = vec4(q.x + c.y, c.z, r.x, distance(d, n));"),
            s_wide,
        ),
        case(
            "control",
            "control flow",
            format!(
                "uniform vec4 s;\n\
                 float f(float x, out float y) {{ y = x * 0.5; if (x > 0.0) return x * x; \
                 return -x; }}\n\
                 void main() {{\n{T}\n\
                 float acc = 0.0;\n\
                 for (int i = 0; i < 8; i++) {{ acc += float(i) * t; if (acc > s.z) break; \
                 if (i == 3) continue; acc -= 0.25; }}\n\
                 float y; float r = f(t, y);\n\
                 if (t < -6.0) discard;\n\
                 vec4 c = t > 0.5 ? vec4(acc, r, y, 1.0) : vec4(r, acc, 0.0, y);\n\
                 if (fract(t) > 0.5) {{ c.w = c.x * 2.0; }} else {{ c.z = -c.y; }}\n\
                 gl_FragColor = c;\n}}\n"
            ),
            s_wide,
        ),
    ];
    v.push(Case {
        name: "int_bool_matrix",
        family: "int/bool/matrix",
        vs: VS,
        fs: "uniform mat3 m; uniform ivec2 k;\n\
             void main() {\n\
             ivec2 ip = ivec2(gl_FragCoord.xy);\n\
             int q = ip.x * k.x - ip.y * 3 + k.y;\n\
             bool big = q > 40 && ip.y < 50;\n\
             vec3 v3 = m * vec3(gl_FragCoord.xy, 1.0);\n\
             gl_FragColor = vec4(float(q), big ? 1.0 : -1.0, v3.x, \
             (vec3(1.0, 2.0, 3.0) * m).y + v3.z);\n}\n",
        floats: vec![("m", vec![0.3, -1.1, 0.7, 2.9, 0.13, -0.5, 1.7, 0.25, -3.1])],
        ints: vec![("k", vec![3, -17])],
        tex: corners(),
    });
    v.push(Case {
        name: "varying",
        family: "varying",
        vs: VS,
        fs: "varying vec4 v;\n\
             void main() { gl_FragColor = vec4(v.x * v.y, sin(v.z), exp2(v.w), \
             v.x + v.y - v.z); }\n",
        floats: vec![],
        ints: vec![],
        tex: corners(),
    });
    v
}

/// Every level this CPU runs, with whether it fuses.
fn levels() -> Vec<Isa> {
    [Isa::Avx2Fma, Isa::Fma, Isa::Base]
        .into_iter()
        .filter(|&l| softgl::engine::exec::isa_allowed(l, softgl::cpu::isa()))
        .collect()
}

#[test]
fn shaders_match_mesa() {
    let cases = cases();
    let fused = mesa(&cases, None);
    let unfused = mesa(&cases, Some("sse4.1"));
    let mut table: BTreeMap<(&str, String), Diff> = BTreeMap::new();
    let mut per_case = Vec::new();
    let mut failures = Vec::new();
    for isa in levels() {
        let reference = if isa.fused() { &fused } else { &unfused };
        for (c, r) in cases.iter().zip(reference) {
            let r = r
                .as_ref()
                .unwrap_or_else(|log| panic!("{}: Mesa: {log}", c.name));
            let o = match ours(c, isa) {
                Ok(o) => o,
                Err(e) => {
                    failures.push(format!("{isa:?} {}: {e}", c.name));
                    continue;
                }
            };
            let mut d = Diff::default();
            d.add(&o, r);
            per_case.push(format!(
                "{:?} {}: {:.2}% exact (RGBA {:?} of {}), max {} ulp, max abs {:.3e}",
                isa,
                c.name,
                d.percent(),
                d.by_channel,
                d.total / 4,
                d.max_ulp,
                d.max_abs
            ));
            let lvl = if isa.fused() { "fused" } else { "unfused" };
            table
                .entry((c.family, lvl.to_string()))
                .or_default()
                .merge(&d);
        }
    }
    eprintln!("{}", per_case.join("\n"));
    eprintln!("| family | levels | channels | exact | max ulp | max abs |");
    eprintln!("|---|---|---|---|---|---|");
    for ((f, l), d) in &table {
        eprintln!(
            "| {f} | {l} | {} | {:.2}% | {} | {:.2e} |",
            d.total,
            d.percent(),
            d.max_ulp,
            d.max_abs
        );
    }
    assert!(failures.is_empty(), "not lowered:\n{}", failures.join("\n"));
    for ((f, l), d) in &table {
        let want = min_exact(f);
        assert!(
            d.percent() >= want,
            "{f} ({l}): {:.2}% exact, below {want}%",
            d.percent()
        );
    }
}

/// The exactness each family reaches (percent of channels bit-identical to llvmpipe),
/// as measured at stop 57; below 100, the suspected cause (not yet confirmed):
fn min_exact(family: &str) -> f64 {
    match family {
        // `a·b + c·d − e`: NIR orders the three-term sum differently (the quotients
        // and the products themselves match).
        "arithmetic" => 75.5,
        // `exp(t·0.7)`: NIR folds `(t·0.7)·log2 e` into `t·(0.7·log2 e)`; exp2, log2
        // and log match exactly.
        "exp2/log2/exp/log" => 93.6,
        // `length` and `dot` of vec3: the order of the three products' sum (lower_fdot
        // versus nir_lower_alu_to_scalar's reversed reduction).
        "sqrt/inversesqrt/length/dot" => 90.2,
        // The same dot order in normalize and distance, and `cross(...).z`.
        "normalize/cross/reflect/distance" => 75.3,
        // Matrix times vector and vector times matrix: the order of the column sums.
        "int/bool/matrix" => 81.8,
        _ => 100.0,
    }
}
