//! The parser's trees and the preprocessor's arithmetic: operator precedence and
//! associativity against the spec's table (written out by hand here), statement and
//! declaration shapes, and `#if` evaluation and macro expansion against Mesa's glcpp.

mod mesa;

use mesa::{run, Context, Job};
use softgl_glsl::ast::{print, Decl, ExprKind, External, Qualifier, StmtKind, TypeName};
use softgl_glsl::{parse, parse_with_log, Shader, Stage};

fn frag(src: &str) -> Shader {
    parse(&[src], Stage::Fragment).unwrap_or_else(|log| panic!("{src}\n{log}"))
}

/// The fully parenthesised text of the expression statement in `void main(){ E; }`.
fn expr_text(version: u32, e: &str) -> String {
    let s = frag(&format!("#version {version}\nvoid main() {{ {e}; }}\n"));
    let External::Function(f) = &s.items[0] else {
        panic!()
    };
    let StmtKind::Expr(Some(x)) = &f.body[0].kind else {
        panic!("{:?}", f.body[0])
    };
    let mut o = String::new();
    print::expr(&mut o, x);
    o
}

#[test]
fn precedence_and_associativity() {
    let cases = [
        ("x = a + b * c - d", "(x = ((a + (b * c)) - d))"),
        ("a - b - c", "((a - b) - c)"),
        ("a / b * c % d", "(((a / b) * c) % d)"),
        ("a = b = c", "(a = (b = c))"),
        ("a += b -= c", "(a += (b -= c))"),
        ("a ? b : c ? d : e", "(a ? b : (c ? d : e))"),
        ("a ? b, c : d", "(a ? (b, c) : d)"),
        ("a, b, c", "((a, b), c)"),
        ("a || b ^^ c && d", "(a || (b ^^ (c && d)))"),
        ("a | b ^ c & d", "(a | (b ^ (c & d)))"),
        ("a == b < c", "(a == (b < c))"),
        ("a << b + c", "(a << (b + c))"),
        ("a < b << c", "(a < (b << c))"),
        ("a & b == c", "(a & (b == c))"),
        ("-a++", "(-(a++))"),
        ("!a.b[1].c", "(!a.b[1].c)"),
        ("++a--", "(++(a--))"),
        ("- -a", "(-(-a))"),
        ("~a * b", "((~a) * b)"),
        ("(a + b) * c", "((a + b) * c)"),
        ("f(a, b)[2].xy", "f(a, b)[2].xy"),
        ("vec4(1.0).x", "vec4(1.0).x"),
        ("float[2](1.0, 2.0)[1]", "float[2](1.0, 2.0)[1]"),
        ("a.length()", "a.length()"),
        (
            "x = 0x10 + 010 + 3u + 1.5e1 + .5",
            "(x = ((((16 + 8) + 3u) + 15.0) + 0.5))",
        ),
    ];
    for (src, want) in cases {
        assert_eq!(expr_text(330, src), want, "{src}");
    }
}

#[test]
fn expression_positions_follow_mesa() {
    // Mesa locates a binary operation at its left operand's first token (counting the
    // parenthesis) and a prefix operation at its operator.
    let s = frag("#version 330\nvoid main() {\n   x  =  (a + b)  * -c; }\n");
    let External::Function(f) = &s.items[0] else {
        panic!()
    };
    let StmtKind::Expr(Some(e)) = &f.body[0].kind else {
        panic!()
    };
    assert_eq!(e.pos.to_string(), "0:3(2)");
    let ExprKind::Assign(None, _, rhs) = &e.kind else {
        panic!()
    };
    assert_eq!(rhs.pos.to_string(), "0:3(6)");
    let ExprKind::Binary(_, l, r) = &rhs.kind else {
        panic!()
    };
    assert_eq!(l.pos.to_string(), "0:3(7)");
    assert_eq!(r.pos.to_string(), "0:3(16)");
}

#[test]
fn declarations_and_statements() {
    let s = frag(
        "#version 330\n\
         layout(std140, location = 2) uniform Block { mat4 m; } blocks[2];\n\
         struct S { float a, b[2]; };\n\
         S s1, s2[3] = S[3](S(1.0, float[2](0.0, 1.0)), S(2.0, float[](0.0, 1.0)), s1);\n\
         invariant gl_FragCoord;\n\
         precision highp float;\n\
         void f(in float a[2], out S o);\n\
         void main() { S x; x.a = 1.0; for (S y; ; ) break; switch (1) { case 1: default: ; } }\n",
    );
    assert_eq!(s.items.len(), 7);
    let External::Decl(Decl::Block(b)) = &s.items[0] else {
        panic!()
    };
    assert_eq!(b.name, "Block");
    let Qualifier::Layout(ids) = &b.qualifiers[0] else {
        panic!()
    };
    assert_eq!(ids.len(), 2);
    assert_eq!(ids[1].name, "location");
    assert!(ids[1].value.is_some());
    assert_eq!(b.instance.as_ref().unwrap().0, "blocks");
    let External::Decl(Decl::Vars { ty, vars }) = &s.items[1] else {
        panic!()
    };
    assert!(vars.is_empty());
    assert!(
        matches!(&ty.spec.name, TypeName::Struct(st) if st.members.len() == 1 && st.members[0].names.len() == 2)
    );
    let External::Decl(Decl::Vars { vars, .. }) = &s.items[2] else {
        panic!()
    };
    assert_eq!(vars.len(), 2);
    assert_eq!(vars[1].array.len(), 1);
    assert!(matches!(s.items[3], External::Decl(Decl::Invariant { .. })));
    assert!(matches!(s.items[4], External::Decl(Decl::Precision { .. })));
    let External::Decl(Decl::Prototype(p)) = &s.items[5] else {
        panic!()
    };
    assert_eq!(p.params.len(), 2);
    let External::Function(f) = &s.items[6] else {
        panic!()
    };
    assert!(matches!(f.body[0].kind, StmtKind::Decl(_)));
    assert!(matches!(f.body[1].kind, StmtKind::Expr(Some(_))));
    assert!(matches!(f.body[2].kind, StmtKind::For { .. }));
    let StmtKind::Switch(_, body) = &f.body[3].kind else {
        panic!()
    };
    assert_eq!(body.len(), 3);
}

#[test]
fn versions_and_profiles() {
    let s = frag("  /* lead */ \n#version 150 compatibility\nvoid main(){}\n");
    assert_eq!(s.version, 150);
    assert_eq!(s.profile, softgl_glsl::pp::Profile::Compatibility);
    assert_eq!(frag("void main(){}").version, 110);
    // A word is a keyword only from the version that has it.
    assert!(parse(
        &["#version 110\nfloat flat, uint, layout, mat2x3;\n"],
        Stage::Vertex
    )
    .is_ok());
    assert!(parse(&["#version 130\nfloat flat;\n"], Stage::Vertex).is_err());
    assert!(parse(&["#version 130\nfloat layout;\n"], Stage::Vertex).is_ok());
    assert!(parse(&["#version 140\nfloat layout;\n"], Stage::Vertex).is_err());
    // Mesa's grammar rejects a layout identifier it does not know, there and then.
    let (_, log) = parse_with_log(
        &["#version 330\nlayout(binding_point) uniform B { int x; };\n"],
        Stage::Vertex,
    );
    assert_eq!(
        log.to_string(),
        "0:2(8): error: unrecognized layout identifier `binding_point'\n"
    );
}

#[test]
fn multiple_sources_are_concatenated() {
    let s = parse(
        &["#version 330\n", "uniform float a;", "\nvoid main(){}\n"],
        Stage::Vertex,
    )
    .unwrap();
    assert_eq!(s.items.len(), 2);
    let (_, log) = parse_with_log(&["#version 330\n", "int x\n", "int y;"], Stage::Vertex);
    assert_eq!(
        log.to_string(),
        "0:3(1): error: syntax error, unexpected BASIC_TYPE_TOK\n"
    );
}

/// `#if` expressions and macro expansions whose truth Mesa's glcpp and ours must agree
/// on: each shader fails with `#error` exactly when the condition holds.
const CONDITIONS: &[(&str, &str)] = &[
    ("", "1 + 2 * 3 == 7"),
    ("", "(1 + 2) * 3 == 9"),
    ("", "-1 < 0"),
    ("", "~0 == -1"),
    ("", "!0 && !!5"),
    ("", "7 / 2 == 3 && -7 / 2 == -3 && -7 % 3 == -1"),
    ("", "1 << 4 == 16 && 256 >> 4 == 16"),
    ("", "0x10 == 16 && 010 == 8 && 0XfF == 255"),
    ("", "(5 & 3) == 1 && (5 | 3) == 7 && (5 ^ 3) == 6"),
    ("", "2 > 1 == 1"),
    ("", "1 || 1 / 0"),
    ("", "4294967295 == -1"),
    ("", "2147483648 > 0"),
    ("", "UNDEFINED == 0"),
    ("", "UNDEFINED"),
    (
        "",
        "defined(__LINE__) && defined __FILE__ && defined __VERSION__",
    ),
    ("", "__LINE__ == 3"),
    ("", "__VERSION__ == 330"),
    ("", "GL_core_profile"),
    ("", "defined GL_compatibility_profile"),
    ("#define A 1\n", "A"),
    ("#define A 1\n#undef A\n", "defined A"),
    ("#define A B\n#define B 2\n", "A == 2"),
    ("#define A A\n", "defined A && A == 0"),
    ("#define A B\n#define B A\n", "A == 0"),
    ("#define F(x) x * 2\n", "F(3) == 6"),
    ("#define F(x) x * 2\n", "F(1 + 2) == 5"),
    ("#define F(x) (x) * 2\n", "F(1 + 2) == 6"),
    ("#define F(x, y) x - y\n", "F(F(5, 1), 2) == 2"),
    ("#define F(x) x\n#define G F\n", "G(7) == 7"),
    ("#define F(x) x\n", "F((1, 2)) == 1 || 1"),
    ("#define F() 9\n", "F() == 9"),
    ("#define F(x) #x\n", "0"),
    ("#define ONE 1\n#define F(x) x + ONE\n", "F(ONE) == 2"),
    ("#define F(x) x\n", "F"),
    ("#define E\n", "E 1 E"),
    ("#define X defined(Y)\n#define Y\n", "X"),
    ("#define CAT(a, b) a ## b\n#define xy 5\n", "CAT(x, y) == 5"),
    ("#define CAT(a, b) a ## b\n", "CAT(1, 2) == 12"),
    ("#define P 1 ## 0\n", "P == 10"),
];

#[test]
fn conditions_agree_with_mesa() {
    let srcs: Vec<String> = CONDITIONS
        .iter()
        .map(|(defs, cond)| {
            format!("#version 330\n{defs}#if {cond}\n#error yes\n#endif\nvoid main(){{}}\n")
        })
        .collect();
    let jobs: Vec<Job> = srcs.iter().map(|s| Job::Fragment(s)).collect();
    let mesa = run(Context::Compat, &jobs);
    let mut bad = Vec::new();
    for ((case, src), m) in CONDITIONS.iter().zip(&srcs).zip(&mesa) {
        let (_, log) = parse_with_log(&[src], Stage::Fragment);
        let ours = log.to_string();
        let mesa_fired = m.log.contains("#error yes");
        let ours_fired = ours.contains("#error yes");
        let ours_failed = log.has_errors() && !ours_fired;
        if mesa_fired != ours_fired || (m.ok == ours_failed && !mesa_fired) {
            bad.push(format!(
                "{case:?}: Mesa {:?} ok={}, ours {ours:?}",
                m.log, m.ok
            ));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
