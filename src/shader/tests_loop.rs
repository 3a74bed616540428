//! Which loops the lowering unrolls and which it emits as loops ([`Op::LoopBegin`]), and
//! what it refuses.

use super::lower::lower_fragment;
use crate::engine::ir::Op;

/// The loops in the lowering of fragment shader `src` (`Err`: the reason it is refused).
fn loops(src: &str) -> Result<usize, String> {
    let p = softgl_glsl::compile(&[src], softgl_glsl::Stage::Fragment).expect("compiles");
    let l = lower_fragment(&p).map_err(|e| e.0)?;
    let begins =
        l.ir.ops
            .iter()
            .filter(|o| matches!(o, Op::LoopBegin(_)))
            .count();
    let ends =
        l.ir.ops
            .iter()
            .filter(|o| matches!(o, Op::LoopEnd(..)))
            .count();
    assert_eq!(begins, ends, "{src}");
    Ok(begins)
}

#[test]
fn constant_loops_unroll_and_the_others_are_loops() {
    let body = "c += gl_Color * 0.1;";
    let constant = format!("void main() {{ vec4 c = vec4(0.0); for (int i = 0; i < 4; i++) {{ {body} }} gl_FragColor = c; }}");
    assert_eq!(loops(&constant), Ok(0));
    let uniform = format!("uniform int n; void main() {{ vec4 c = vec4(0.0); for (int i = 0; i < n; i++) {{ {body} }} gl_FragColor = c; }}");
    assert_eq!(loops(&uniform), Ok(1));
    let data = format!("void main() {{ vec4 c = vec4(0.0); while (c.r < gl_Color.g) {{ {body} }} gl_FragColor = c; }}");
    assert_eq!(loops(&data), Ok(1));
    let long = format!("void main() {{ vec4 c = vec4(0.0); for (int i = 0; i < 2000; i++) {{ {body} }} gl_FragColor = c; }}");
    assert_eq!(loops(&long), Ok(1), "past the unroll limit");
    // A constant loop inside a loop is unrolled in its body; two loops in a row are two.
    let nested = format!("uniform int n; void main() {{ vec4 c = vec4(0.0); for (int i = 0; i < n; i++) {{ for (int j = 0; j < 3; j++) {{ {body} }} }} do {{ {body} }} while (c.a < 0.5); gl_FragColor = c; }}");
    assert_eq!(loops(&nested), Ok(2));
}

#[test]
fn a_return_inside_a_loop_that_is_not_unrolled_is_a_loop() {
    let src = "uniform int n;
        float f() { for (int i = 0; i < n; i++) { if (gl_Color.r > 0.5) return 1.0; } return 0.0; }
        void main() { gl_FragColor = vec4(f()); }";
    assert_eq!(loops(src), Ok(1));
    // Unrolled, the same return lowers without a loop.
    let unrolled = src.replace("i < n", "i < 3");
    assert_eq!(loops(&unrolled), Ok(0));
    // main's own return from a loop, and a return from the inner of two loops.
    let main = "uniform int n; void main() { gl_FragColor = vec4(0.0);
        for (int i = 0; i < n; i++) { if (gl_Color.g > 0.5) return; gl_FragColor += gl_Color; } }";
    assert_eq!(loops(main), Ok(1));
    let nested =
        "uniform int n; vec2 g() { for (int i = 0; i < n; i++) { for (int j = 0; j < i; j++) {
        if (gl_Color.b > float(j) * 0.1) return vec2(float(i), float(j)); } } return vec2(0.0); }
        void main() { gl_FragColor = vec4(g(), 0.0, 1.0); }";
    assert_eq!(loops(nested), Ok(2));
}
