//! The semantic types against the specifications and Mesa: the std140 rules on the
//! OpenGL specification's worked example, each type's name as Mesa prints it, which
//! versions have each type, and each version's implicit conversions.

mod batch;
mod mesa;

use batch::{expect, expect_errors, Case};
use softgl_glsl::types::std140::{array_stride, layout, matrix_stride, struct_offsets};
use softgl_glsl::types::{basic_types, Member, Sampler, Stage, Struct, Type, Version};
use std::sync::Arc;

fn parse(name: &str) -> Type {
    Type::named(name).unwrap()
}

fn strukt(name: &str, members: &[(&str, Type)]) -> Type {
    Type::Struct(Arc::new(Struct {
        name: name.into(),
        members: members
            .iter()
            .map(|(n, ty)| Member {
                name: n.to_string(),
                ty: ty.clone(),
            })
            .collect(),
    }))
}

/// The two struct types of the specification's example block (GLSL: `struct F { int
/// d; bvec2 e; }; struct O { uvec3 j; vec2 k; float l[2]; vec2 m; mat3 n[2]; };`).
fn example_structs() -> (Type, Type) {
    let f = strukt("F", &[("d", parse("int")), ("e", parse("bvec2"))]);
    let members = "uvec3 j; vec2 k; float l[2]; vec2 m; mat3 n[2]";
    let o: Vec<(String, Type)> = members
        .split(';')
        .map(|m| softgl_glsl::builtins::variables::declaration(m, &[]).unwrap())
        .collect();
    let o: Vec<(&str, Type)> = o.iter().map(|(n, t)| (n.as_str(), t.clone())).collect();
    (f, strukt("O", &o))
}

/// The example block of the OpenGL 4.5 specification, section 7.6.2.2, with the
/// offsets its comments give.
#[test]
fn std140_follows_the_specification_example() {
    let (f, o) = example_structs();
    let block = strukt(
        "Example",
        &[
            ("a", Type::FLOAT),
            ("b", parse("vec2")),
            ("c", parse("vec3")),
            ("f", f.clone()),
            ("g", Type::FLOAT),
            ("h", Type::FLOAT.array(Some(2))),
            ("i", parse("mat2x3")),
            ("o", o.clone().array(Some(2))),
        ],
    );
    let Type::Struct(b) = &block else {
        unreachable!()
    };
    assert_eq!(
        struct_offsets(b, false).unwrap(),
        [0, 8, 16, 32, 48, 64, 96, 128]
    );
    let Type::Struct(os) = &o else { unreachable!() };
    // o[0].j 128, k 144, l 160 (l[1] 176), m 192, n 208 (n[1] 256); o[1] at 304.
    assert_eq!(struct_offsets(os, false).unwrap(), [0, 16, 32, 64, 80]);
    assert_eq!(array_stride(&o.clone().array(Some(2)), false), Some(176));
    assert_eq!(array_stride(&parse("mat3").array(Some(2)), false), Some(48));
    assert_eq!(array_stride(&Type::FLOAT.array(Some(2)), false), Some(16));
    assert_eq!(matrix_stride(&parse("mat2x3"), false), Some(16));
    assert_eq!(layout(&f, false).map(|l| (l.align, l.size)), Some((16, 16)));
    // The block ends at 480 ("pad end of o[1]").
    assert_eq!(layout(&block, false).map(|l| l.size), Some(480));
}

#[test]
fn std140_rules_one_by_one() {
    let l = |t: &Type| layout(t, false).map(|l| (l.align, l.size));
    assert_eq!(l(&Type::FLOAT), Some((4, 4)));
    assert_eq!(l(&Type::BOOL), Some((4, 4)));
    assert_eq!(l(&parse("ivec2")), Some((8, 8)));
    assert_eq!(l(&parse("vec3")), Some((16, 12)));
    assert_eq!(l(&parse("uvec4")), Some((16, 16)));
    // Rule 4: vec2[3] strides 16, not 8; rule 5: mat3x2 is 3 columns of vec2.
    assert_eq!(l(&parse("vec2").array(Some(3))), Some((16, 48)));
    assert_eq!(l(&parse("mat3x2")), Some((16, 48)));
    // Rule 7: row-major mat3x2 is 2 rows of vec3.
    assert_eq!(
        layout(&parse("mat3x2"), true).map(|l| (l.align, l.size)),
        Some((16, 32))
    );
    // A float after a vec3 packs into its fourth component.
    let s = strukt("S", &[("v", parse("vec3")), ("x", Type::FLOAT)]);
    let Type::Struct(st) = &s else { unreachable!() };
    assert_eq!(struct_offsets(st, false).unwrap(), [0, 12]);
    assert_eq!(l(&s), Some((16, 16)));
    let sampler = Type::Sampler(Sampler::all()[0]);
    assert_eq!(l(&sampler), None);
    assert_eq!(l(&Type::FLOAT.array(None)), None);
}

/// A case that assigns a value of type `from` (a local, or a sampler uniform) to a
/// variable of type `to`.
fn assign(v: Version, from: &Type, to: &Type) -> Case {
    let (globals, decl) = match from {
        Type::Sampler(s) => (
            vec![format!("uniform {} u_{};", s.name(), s.name())],
            format!("u_{}", s.name()),
        ),
        Type::Array(e, Some(n)) => (vec![], format!("a; {e} a[{n}]")),
        _ => (vec![], format!("a; {from} a")),
    };
    let line = match decl.split_once("; ") {
        Some((name, local)) => format!("{{ {local}; {to} b = {name}; }}"),
        None => format!("{{ {to} b = {decl}; }}"),
    };
    Case {
        version: v,
        stage: Stage::Fragment,
        globals,
        line,
    }
}

/// Mesa names a type in "initializer of type X cannot be assigned to variable of type
/// Y": every type of every version, by [`Type`]'s `Display`.
#[test]
fn names_are_mesas() {
    let mut cases = Vec::new();
    let mut want = Vec::new();
    for v in Version::all() {
        let mut types = basic_types(v);
        types.extend(
            Sampler::all()
                .into_iter()
                .filter(|s| s.since() <= v.number)
                .map(Type::Sampler),
        );
        types.push(parse("vec3").array(Some(3)));
        for t in types {
            let to = if t == Type::BOOL {
                Type::INT
            } else {
                Type::BOOL
            };
            want.push(format!(
                "initializer of type {t} cannot be assigned to variable of type {to}"
            ));
            cases.push(assign(v, &t, &to));
        }
    }
    expect_errors("type names", &cases, &want, 60);
}

/// Every pair of basic types of each version: `T a; U b = a;` compiles exactly when
/// the tables say T converts to U; a type a version lacks does not compile there.
#[test]
fn conversions_and_existence_are_mesas() {
    let (mut yes, mut no, mut missing) = (Vec::new(), Vec::new(), Vec::new());
    for v in Version::all() {
        let all = basic_types(Version::new(330, false));
        for from in &all {
            for to in &all {
                let case = assign(v, from, to);
                if !from.exists_in(v) || !to.exists_in(v) {
                    missing.push(case);
                } else if from.converts_to(to, v) {
                    yes.push(case);
                } else {
                    no.push(case);
                }
            }
        }
    }
    expect("assignments the conversions allow", &yes, true, 60);
    expect("assignments they do not", &no, false, 60);
    // An unknown type name is a syntax error that ends the parse: one to a shader.
    expect(
        "assignments naming a type the version lacks",
        &missing,
        false,
        1,
    );
}

/// Each sampler type declares as a uniform exactly in the versions from its `since`.
#[test]
fn samplers_exist_from_their_version() {
    let mut wrong = Vec::new();
    let mut n = 0;
    for ctx in [mesa::Context::Compat, mesa::Context::Core33] {
        let mut srcs = Vec::new();
        for v in Version::all()
            .into_iter()
            .filter(|v| batch::context(*v) == ctx)
        {
            for s in Sampler::all() {
                let src = format!(
                    "{}\nuniform {} u;\nvoid main() {{}}\n",
                    v.directive(),
                    s.name()
                );
                srcs.push((v, s, src));
            }
        }
        let jobs: Vec<mesa::Job> = srcs
            .iter()
            .map(|(_, _, src)| mesa::Job::Fragment(src))
            .collect();
        for ((v, s, _), r) in srcs.iter().zip(mesa::run(ctx, &jobs)) {
            n += 1;
            if r.ok != (s.since() <= v.number) {
                wrong.push(format!("{} {}: {}", v.directive(), s.name(), r.log));
            }
        }
    }
    eprintln!(
        "sampler types: {n} declarations, {} as the table says",
        n - wrong.len()
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The std140 base alignment and size of a type, checked against Mesa through
/// ARB_enhanced_layouts' explicit offsets: a member at an offset that is not a
/// multiple of its base alignment, or one that overlaps the previous member, is an
/// error. For each type T: T at its alignment after a float is accepted, at half of it
/// rejected (when that is a multiple of 4); a float at T's size after T is accepted,
/// 4 bytes earlier rejected.
#[test]
fn std140_alignment_and_size_are_mesas() {
    let (f, o) = example_structs();
    let globals = "struct F { int d; bvec2 e; };\nstruct O { uvec3 j; vec2 k; float l[2]; vec2 m; mat3 n[2]; };\n";
    let mut types: Vec<(Type, bool)> = Vec::new();
    for t in basic_types(Version::new(330, false)) {
        let m = matches!(t, Type::Matrix { .. });
        types.push((t.clone(), false));
        types.push((t.clone().array(Some(3)), false));
        if m {
            types.push((t.clone(), true));
            types.push((t.array(Some(2)), true));
        }
    }
    for s in [f, o] {
        types.push((s.clone(), false));
        types.push((s.array(Some(2)), false));
    }
    let mut srcs = Vec::new();
    for (t, row) in &types {
        let l = layout(t, *row).unwrap();
        let q = if *row { ", row_major" } else { "" };
        let decl = match t {
            Type::Array(e, Some(n)) => format!("{e} x[{n}]"),
            _ => format!("{t} x"),
        };
        let block = |members: String| {
            format!("#version 330\n#extension GL_ARB_enhanced_layouts : require\n{globals}layout(std140) uniform B {{ {members} }};\nvoid main() {{}}\n")
        };
        let at = |off: u32| {
            block(format!(
                "layout(offset = 0) float p; layout(offset = {off}{q}) {decl};"
            ))
        };
        let after = |off: u32| {
            block(format!(
                "layout(offset = 0{q}) {decl}; layout(offset = {off}) float y;"
            ))
        };
        let what = format!("{t}{q}");
        srcs.push((
            format!("{what} at {}", l.align.max(4)),
            true,
            at(l.align.max(4)),
        ));
        if l.align >= 16 {
            srcs.push((format!("{what} at {}", l.align / 2), false, at(l.align / 2)));
        }
        srcs.push((
            format!("float after {what} at {}", l.size),
            true,
            after(l.size),
        ));
        srcs.push((
            format!("float after {what} at {}", l.size - 4),
            false,
            after(l.size - 4),
        ));
    }
    let jobs: Vec<mesa::Job> = srcs.iter().map(|s| mesa::Job::Fragment(&s.2)).collect();
    let out = mesa::run(mesa::Context::Core33, &jobs);
    let bad: Vec<String> = srcs
        .iter()
        .zip(&out)
        .filter(|(s, r)| r.ok != s.1)
        .map(|(s, r)| format!("{} (want ok={}): {}", s.0, s.1, r.log))
        .collect();
    eprintln!(
        "std140 against Mesa: {} types, {} checks, {} as the layout says",
        types.len(),
        srcs.len(),
        srcs.len() - bad.len()
    );
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
