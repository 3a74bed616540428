//! The checked tree itself: implicit conversions are explicit nodes, constants are
//! folded to the values worked out by hand here, calls name their signature, l-values
//! are marked, and array sizes come from constant expressions.

use softgl_glsl::ast::BinOp;
use softgl_glsl::hir::{Const, Expr, ExprKind, Program, Stmt, Value};
use softgl_glsl::types::{Scalar, Type};
use softgl_glsl::{compile, Stage};

fn program(src: &str) -> Program {
    compile(&[src], Stage::Fragment).unwrap_or_else(|log| panic!("{log}"))
}

/// The initializer of the local `name` in `main`.
fn init<'a>(p: &'a Program, name: &str) -> &'a Expr {
    let main = p.main().expect("main");
    let mut stack: Vec<&Stmt> = main.body.as_ref().unwrap().iter().collect();
    while let Some(s) = stack.pop() {
        match s {
            Stmt::Decl(v, Some(e)) if p.vars[*v].name == name => return e,
            Stmt::Block(b) => stack.extend(b.iter()),
            _ => {}
        }
    }
    panic!("no local {name}")
}

fn var_type<'a>(p: &'a Program, name: &str) -> &'a Type {
    &p.vars.iter().find(|v| v.name == name).expect(name).ty
}

#[test]
fn conversions_are_explicit() {
    let p = program("#version 120\nuniform int i;\nvoid main() { float f = i + 2.0; gl_FragColor = vec4(f); }\n");
    let e = init(&p, "f");
    assert_eq!(e.ty, Type::FLOAT);
    let ExprKind::Binary(BinOp::Add, a, b) = &e.kind else {
        panic!("{e:?}")
    };
    assert!(matches!(&a.kind, ExprKind::Convert(x) if x.ty == Type::INT));
    assert_eq!(a.ty, Type::FLOAT);
    assert!(matches!(b.kind, ExprKind::Literal));
}

#[test]
fn constants_fold() {
    let p = program(
        "#version 130\nconst int N = max(2, 3) * 2 - 1;\nconst vec2 v = mat2(2.0) * vec2(1.0, 3.0);\n\
         const bool b = (7 / 2 == 3) && !(1.5 > 2.0);\nconst uint u = (5u << 2u) | 1u;\n\
         out vec4 c;\nvoid main() { float a[N]; float w[int(v.y)]; a[4] = 0.0; w[5] = 1.0; c = vec4(a[4], w[5], b, u); }\n",
    );
    let value = |n: &str| p.vars.iter().find(|v| v.name == n).unwrap().value.clone();
    assert_eq!(value("N"), Some(Const::Scalars(vec![Value::Int(5)])));
    assert_eq!(
        value("v"),
        Some(Const::Scalars(vec![Value::Float(2.0), Value::Float(6.0)]))
    );
    assert_eq!(value("b"), Some(Const::Scalars(vec![Value::Bool(true)])));
    assert_eq!(value("u"), Some(Const::Scalars(vec![Value::Uint(21)])));
    assert_eq!(var_type(&p, "a"), &Type::FLOAT.array(Some(5)));
    assert_eq!(var_type(&p, "w"), &Type::FLOAT.array(Some(6)));
}

#[test]
fn calls_swizzles_and_lvalues() {
    let p = program(
        "#version 120\nuniform sampler2D s;\nfloat g(float x) { return x; }\n\
         void main() { vec4 t = texture2D(s, vec2(0.5)); float k = g(1); vec2 q = t.zx; t.yw = q; gl_FragColor = t * k; }\n",
    );
    let t = init(&p, "t");
    let ExprKind::Builtin(f, args) = &t.kind else {
        panic!("{t:?}")
    };
    assert_eq!(f.prototype(), "vec4 texture2D(sampler2D, vec2)");
    assert_eq!(args.len(), 2);
    let k = init(&p, "k");
    let ExprKind::Call(fid, args) = &k.kind else {
        panic!("{k:?}")
    };
    assert_eq!(p.functions[*fid].name, "g");
    // The int argument is converted to the float parameter.
    assert!(matches!(args[0].kind, ExprKind::Convert(_)));
    let q = init(&p, "q");
    assert!(matches!(&q.kind, ExprKind::Swizzle(_, idx) if idx == &vec![2, 0]));
    assert_eq!(q.ty, Type::Vector(Scalar::Float, 2));
    assert!(q.lvalue);
    let repeated = program(
        "#version 120\nvoid main() { vec4 t = vec4(1.0); vec2 r = t.xx; gl_FragColor = vec4(r, r); }\n",
    );
    assert!(!init(&repeated, "r").lvalue);
}

#[test]
fn errors_read_like_mesa() {
    let log = compile(
        &["#version 120\nvoid main() {\n  vec3 v = vec2(1.0) + vec3(1.0);\n}\n"],
        Stage::Fragment,
    )
    .unwrap_err();
    assert_eq!(
        log.to_string(),
        "0:3(11): error: vector size mismatch for arithmetic operator\n"
    );
}
