//! Robustness of the lowering (the front end has its own fuzzer, `glsl/tests/fuzz.rs`):
//! the valid corpus of `glsl/tests/corpus/valid`, mutated by deleting, duplicating and
//! swapping pieces and inserting tokens that reach the lowering's less common paths
//! (lookups with LOD arguments, `texelFetch`, integer division and shifts, derivatives,
//! loops, `gl_InstanceID`, located and integer outputs, integer attributes), is compiled; every program the front end accepts is lowered for its stage
//! and, when lowered, compiled for the executor. None may panic, and each must finish
//! within a time bound. proptest's `PROPTEST_CASES` runs more cases than its default 256
//! per property (the library reads no environment outside `tuning`).

use proptest::prelude::*;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Tokens inserted by the mutations.
const VOCAB: &[&str] = &[
    "texture2D(",
    "texture2DLod(",
    "textureLod(",
    "texelFetch(",
    "textureSize(",
    "textureProj(",
    "shadow2D(",
    "textureCube(",
    "dFdx(",
    "fwidth(",
    "uniform sampler2D s;",
    "uniform samplerCube c;",
    "ivec2(",
    "uint(",
    " / 0",
    " % 7u",
    " << 40",
    " >> -3",
    " / ",
    " % ",
    "for (int i = 0; i < 9; i++) ",
    "if (gl_FragCoord.x > 3.0) discard;",
    "gl_FragData[1]",
    "gl_FragColor",
    "1e38",
    "-0.0",
    "2147483647",
    "(",
    ")",
    ",",
    ";",
    "{",
    "}",
    ".xyzw",
    "[2]",
    "#version 130\n",
    "return;",
    "uniform sampler2D sa[3];",
    "texture2D(sa[2], ",
    "gl_FragDepth = ",
    "gl_InstanceID",
    "gl_InstanceIDARB",
    "#version 330\n",
    "layout(location = 1) out vec4 q;",
    "layout(location = 7) out vec4 r[2];",
    "out vec3 o3;",
    "out int oi;",
    "in ivec4 ia;",
    "in uint ua;",
];

/// The valid corpus: each file's text and whether it is a vertex shader.
fn corpus() -> Vec<(String, bool)> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("glsl/tests/corpus/valid");
    let mut files: Vec<_> = std::fs::read_dir(root)
        .expect("corpus directory")
        .map(|e| e.expect("entry").path())
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let vertex = p.extension().is_some_and(|e| e == "vert");
            (std::fs::read_to_string(&p).expect("corpus file"), vertex)
        })
        .collect()
}

/// Compiles `src`, lowers what compiles and compiles what lowers.
fn lower_any(src: &str, vertex: bool) {
    let stage = match vertex {
        true => softgl_glsl::Stage::Vertex,
        false => softgl_glsl::Stage::Fragment,
    };
    let start = Instant::now();
    if let Ok(p) = softgl_glsl::compile(&[src], stage) {
        let ir = match vertex {
            true => super::vertex::lower_vertex(&p).ok().map(|l| l.ir),
            false => super::lower::lower_fragment(&p).ok().map(|l| l.ir),
        };
        if let Some(ir) = ir {
            crate::engine::exec::compile(&ir);
        }
    }
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "took {:?}: {src:.200}",
        start.elapsed()
    );
}

proptest! {

    #[test]
    fn mutated_shaders_lower_without_panics(
        file in 0usize..64,
        edits in proptest::collection::vec((0usize..4, any::<u32>(), any::<u32>(), 0..VOCAB.len()), 1..6),
    ) {
        thread_local!(static CORPUS: Vec<(String, bool)> = corpus());
        let (text, vertex) = CORPUS.with(|c| c[file % c.len()].clone());
        let mut src = text.into_bytes();
        for (kind, a, b, t) in edits {
            let n = src.len().max(1);
            let (a, b) = ((a as usize) % n, (b as usize) % n);
            let (lo, hi) = (a.min(b).min(src.len()), a.max(b).min(src.len()));
            match kind {
                0 => {
                    src.drain(lo..hi.min(lo + 40));
                }
                1 => {
                    let piece = src[lo..hi.min(lo + 40)].to_vec();
                    src.splice(lo..lo, piece);
                }
                2 => {
                    src.splice(lo..lo, VOCAB[t].bytes());
                }
                _ => {
                    if hi < src.len() {
                        src.swap(lo, hi);
                    }
                }
            }
        }
        lower_any(&String::from_utf8_lossy(&src), vertex);
    }

    #[test]
    fn generated_shaders_lower_without_panics(
        picks in proptest::collection::vec(any::<usize>(), 1..14),
    ) {
        lower_any(&generated(&picks), false);
    }
}

/// Statements valid in [`generated`]'s program, over its `vec4 a`, `int i`, `float x`.
const STATEMENTS: &[&str] = &[
    "a += texture(s, a.xy);",
    "a += textureLod(s, a.xy, x);",
    "a += texture(s, a.xy, x);",
    "a += textureProjLod(s, a.xyz, x);",
    "a += texelFetch(s, ivec2(a.xy), i);",
    "i += textureSize(s, i).x;",
    "a += textureLod(c, a.xyz, x);",
    "x += texture(d, a.xyz);",
    "a += texture2D(s, v.xy);",
    "i = i / (i - 3);",
    "i = i % 5;",
    "i = i << i;",
    "i = -i >> 2;",
    "{ uint u = uint(i) / 3u; i += int(u % uint(k)) + int(u >> 33u); }",
    "x += dFdx(a.x) + fwidth(x) - dFdy(a.w);",
    "if (x > 0.5) discard;",
    "if (a.x > x) { a = a.yzwx; } else { i += 1; }",
    "for (int j = 0; j < 4; j++) { a += vec4(j); }",
    "while (i > 100) { i -= 7; }",
    "a = a * mat4(x);",
    "x = pow(abs(x), 2.2) + exp2(x) + log2(x);",
    "a = normalize(a) + vec4(length(a.xyz));",
    "x = float(i) * 1e38 / x;",
    "a = mix(a, a.wzyx, x);",
    "a = clamp(a, 0.0, x);",
    "i = (i & 12) | (i ^ k) | ~i;",
    "x = uint(i) < uint(k) ? x : -x;",
    "a += texture(t[1], a.xy) + texture2D(t[0], v.xy);",
    "x += settle(x);",
    "if (x > 0.2) gl_FragDepth = x; else gl_FragDepth = a.z;",
    "for (int j = 0; j < k; j++) { if (a.x > float(j)) { o = a; return; } a += vec4(0.1); }",
];

/// A `#version 130` fragment shader running `picks` of [`STATEMENTS`] in order.
fn generated(picks: &[usize]) -> String {
    let body: Vec<&str> = picks
        .iter()
        .map(|&k| STATEMENTS[k % STATEMENTS.len()])
        .collect();
    format!(
        "#version 130\n\
         uniform sampler2D s; uniform samplerCube c; uniform sampler2DShadow d;\n\
         uniform sampler2D t[2];\n\
         uniform int k; uniform float f; in vec4 v; out vec4 o;\n\
         float settle(float y) {{ for (int j = 0; j < k; j++) {{ y = y * 0.5 + 0.1;\n\
           if (y < 0.3) return y; }} return 1.0; }}\n\
         void main() {{ vec4 a = v; int i = k; float x = f;\n{}\no = a + vec4(x) + vec4(i); }}\n",
        body.join("\n")
    )
}

#[test]
fn generated_statements_compile_and_lower() {
    // Every statement alone is valid GLSL 1.30 (an invalid one would only exercise the
    // front end), and every one lowers (a loop whose trip count is not constant runs as
    // an engine loop).
    let mut refused = Vec::new();
    for (k, statement) in STATEMENTS.iter().enumerate() {
        let src = generated(&[k]);
        let p = softgl_glsl::compile(&[&src], softgl_glsl::Stage::Fragment)
            .unwrap_or_else(|e| panic!("{src}: {e:?}"));
        if super::lower::lower_fragment(&p).is_err() {
            refused.push(*statement);
        }
    }
    assert!(refused.is_empty(), "refused: {refused:?}");
}

#[test]
fn the_corpus_itself_lowers_without_panics() {
    for (src, vertex) in corpus() {
        lower_any(&src, vertex);
    }
}
