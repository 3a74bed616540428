//! The built-in function tables against Mesa's compiler: every generated signature is
//! called, with arguments of exactly its parameter types and its result assigned to its
//! return type, in every version and in the vertex and fragment stages that have it,
//! and Mesa must accept it; calls the tables say do not resolve (argument types no
//! overload accepts, a signature taken to a version, stage or profile without it) must
//! be rejected.

mod batch;
mod mesa;

use batch::{compile, expect, Case};
use softgl_glsl::builtins::{all_functions, overloads, resolve, Function};
use softgl_glsl::types::{basic_types, Stage, Type, Version};
use std::collections::{BTreeSet, HashSet};

const STAGES: [Stage; 2] = [Stage::Vertex, Stage::Fragment];

/// The case calling `name` with arguments of `args` (assigning the result to `ret`).
/// Arguments are uninitialised locals, or constants where the parameter says so
/// (`(type, out, constant)`).
fn call(
    version: Version,
    stage: Stage,
    name: &str,
    args: &[(Type, bool, bool)],
    ret: Option<&str>,
) -> Case {
    let mut globals = Vec::new();
    let mut decls = String::new();
    let mut names = Vec::new();
    for (i, (ty, _, constant)) in args.iter().enumerate() {
        if let Type::Sampler(s) = ty {
            globals.push(format!("uniform {} u_{};", s.name(), s.name()));
            names.push(format!("u_{}", s.name()));
        } else if *constant {
            decls += &format!("const {ty} a{i} = {ty}(0); ");
            names.push(format!("a{i}"));
        } else {
            decls += &format!("{ty} a{i}; ");
            names.push(format!("a{i}"));
        }
    }
    let call = format!("{name}({})", names.join(", "));
    let line = match ret {
        Some("void") | None => format!("{{ {decls}{call}; }}"),
        Some(r) => format!("{{ {decls}{r} r = {call}; }}"),
    };
    Case {
        version,
        stage,
        globals,
        line,
    }
}

fn args_of(f: &Function) -> Vec<(Type, bool, bool)> {
    f.params
        .iter()
        .map(|p| (p.ty.clone(), p.out, p.constant))
        .collect()
}

#[test]
fn every_signature_is_accepted() {
    let mut cases = Vec::new();
    let mut geometry_only = 0;
    for f in all_functions() {
        if f.avail.since[0].is_none() && f.avail.since[2].is_none() {
            geometry_only += 1;
        }
        for v in Version::all() {
            for stage in STAGES {
                if f.exists(v, stage) {
                    cases.push(call(
                        v,
                        stage,
                        &f.name,
                        &args_of(f),
                        Some(&f.ret.to_string()),
                    ));
                }
            }
        }
    }
    eprintln!(
        "{} signatures ({geometry_only} geometry-only, not testable here)",
        all_functions().len()
    );
    for v in Version::all() {
        let n = |s| all_functions().iter().filter(|f| f.exists(v, s)).count();
        let (vs, fs) = (n(Stage::Vertex), n(Stage::Fragment));
        eprintln!(
            "  {}: {vs} in vertex, {fs} in fragment shaders",
            v.directive()
        );
    }
    expect("every signature where it exists", &cases, true, 60);
}

/// Every (name, argument types) of a signature somewhere, called in each version and
/// stage where the tables say it does not resolve.
#[test]
fn signatures_are_rejected_where_they_do_not_exist() {
    let mut seen = HashSet::new();
    let mut cases = Vec::new();
    for f in all_functions() {
        let args: Vec<Type> = f.params.iter().map(|p| p.ty.clone()).collect();
        for v in Version::all() {
            for stage in STAGES {
                let types_exist = args.iter().all(|t| t.exists_in(v));
                if types_exist
                    && resolve(&f.name, &args, v, stage, &[]).is_err()
                    && seen.insert((f.prototype(), v, stage))
                {
                    cases.push(call(v, stage, &f.name, &args_of(f), None));
                }
            }
        }
    }
    expect(
        "signatures out of their version, stage or profile",
        &cases,
        false,
        60,
    );
}

/// For every signature, each argument but samplers and `out` ones replaced by every
/// other basic type of the version: rejected when no overload accepts the new tuple.
/// Returns the cases (shared with the acceptance of the tuples that do resolve).
fn mixes(version: Version, stage: Stage) -> (Vec<(Case, String)>, Vec<Case>) {
    let mut seen = HashSet::new();
    let (mut good, mut bad) = (Vec::new(), Vec::new());
    let basics = basic_types(version);
    for f in all_functions().iter().filter(|f| f.exists(version, stage)) {
        let args: Vec<Type> = f.params.iter().map(|p| p.ty.clone()).collect();
        for (i, p) in f.params.iter().enumerate() {
            if p.out || matches!(p.ty, Type::Sampler(_)) {
                continue;
            }
            for t in &basics {
                let mut a = args.clone();
                a[i] = t.clone();
                if !seen.insert((f.name.clone(), a.clone())) {
                    continue;
                }
                let with_out: Vec<(Type, bool, bool)> = a
                    .iter()
                    .cloned()
                    .zip(&f.params)
                    .map(|(t, p)| (t, p.out, p.constant))
                    .collect();
                match resolve(&f.name, &a, version, stage, &[]) {
                    Ok(r) => {
                        let case = call(version, stage, &f.name, &with_out, Some("Z"));
                        good.push(batch::names_type(case, &r.ret));
                    }
                    Err(_) => bad.push(call(version, stage, &f.name, &with_out, None)),
                }
            }
        }
    }
    (good, bad)
}

/// Every `n`-th case, about `keep` of them (the rejected mixes number hundreds of
/// thousands; a stride keeps every function and version represented).
fn sample<T>(cases: Vec<T>, keep: usize) -> Vec<T> {
    let n = cases.len().div_ceil(keep).max(1);
    cases.into_iter().step_by(n).collect()
}

/// All the mixes that [`resolve`] resolves must select the signature Mesa selects
/// (Mesa names its return type); a sample of the others must be rejected.
#[test]
fn argument_mixes_resolve_as_the_tables_say() {
    let (mut good, mut bad) = (Vec::new(), Vec::new());
    let mut total = (0, 0);
    for v in Version::all() {
        for stage in STAGES {
            let (g, b) = mixes(v, stage);
            total = (total.0 + g.len(), total.1 + b.len());
            good.extend(g);
            bad.extend(sample(b, 1000));
        }
    }
    eprintln!(
        "argument mixes: {} resolving, {} not; sampled:",
        total.0, total.1
    );
    expect("argument mixes not in the tables", &bad, false, 80);
    let (cases, want): (Vec<Case>, Vec<String>) = good.into_iter().unzip();
    batch::expect_errors(
        "argument mixes resolving (Mesa's choice of signature)",
        &cases,
        &want,
        80,
    );
}

/// Mesa lists every overload of a name when a call matches none: for every name,
/// version and stage, the listed signatures (those whose types the version has: Mesa
/// also lists e.g. `textureSize(isampler2DRect)` in 1.30, where the type does not exist)
/// are exactly the tables' overloads. This catches overloads missing from the tables.
#[test]
fn overload_sets_are_mesas() {
    let names: BTreeSet<&str> = all_functions().iter().map(|f| f.name.as_str()).collect();
    check_overload_sets(&names, None);
}

/// The extensions whose built-in functions the tables have.
const EXTENSIONS: [&str; 4] = [
    "GL_ARB_shader_texture_lod",
    "GL_ARB_shader_bit_encoding",
    "GL_EXT_texture_array",
    "GL_ARB_texture_multisample",
];

/// With each extension enabled, the overload sets of the names it touches are Mesa's,
/// and every signature it adds is accepted wherever the tables say it exists.
#[test]
fn extension_functions_are_mesas() {
    for ext in EXTENSIONS {
        let names: BTreeSet<&str> = all_functions()
            .iter()
            .filter(|f| f.avail.ext == Some(ext))
            .map(|f| f.name.as_str())
            .collect();
        check_overload_sets(&names, Some(ext));
        let mut cases = Vec::new();
        for f in all_functions().iter().filter(|f| f.avail.ext == Some(ext)) {
            for v in Version::all() {
                for stage in STAGES.into_iter().filter(|s| f.exists_with(v, *s, &[ext])) {
                    let mut c = call(v, stage, &f.name, &args_of(f), Some(&f.ret.to_string()));
                    c.globals.push(format!("#extension {ext} : enable"));
                    cases.push(c);
                }
            }
        }
        expect(&format!("signatures of {ext}"), &cases, true, 60);
    }
}

/// Compares the overload sets of `names` in every version and stage, with `ext`
/// enabled, with the candidates Mesa lists for a call that matches none.
fn check_overload_sets(names: &BTreeSet<&str>, ext: Option<&str>) {
    let exts: Vec<&str> = ext.into_iter().collect();
    let mut cases = Vec::new();
    let mut want = Vec::new();
    for v in Version::all() {
        for stage in STAGES {
            for &name in names {
                let mut ours: Vec<String> = overloads(name, v, stage, &exts)
                    .iter()
                    .map(|f| f.prototype().replace("out ", ""))
                    .collect();
                ours.sort();
                want.push(ours);
                let mut globals = vec!["struct Z { float z; };".to_string()];
                globals.extend(ext.map(|e| format!("#extension {e} : enable")));
                let line = format!("{{ Z z; {name}(z); }}");
                cases.push(Case {
                    version: v,
                    stage,
                    globals,
                    line,
                });
            }
        }
    }
    let mut bad = Vec::new();
    for ((ok, log), (c, ours)) in compile(&cases, 40).into_iter().zip(cases.iter().zip(&want)) {
        let mut mesa: Vec<String> = log
            .lines()
            .filter_map(|l| l.split_once(": error:    ").map(|(_, p)| p.to_string()))
            .filter(|p| mentioned_types_exist(p, c.version, &exts))
            .collect();
        mesa.sort();
        if ok != Some(false) || &mesa != ours {
            let only_mesa: Vec<&String> = mesa.iter().filter(|p| !ours.contains(p)).collect();
            let only_ours: Vec<&String> = ours.iter().filter(|p| !mesa.contains(p)).collect();
            let (v, s) = (c.version.directive(), c.stage);
            bad.push(format!(
                "{v} {s:?} {}: Mesa only {only_mesa:?}, tables only {only_ours:?}",
                c.line
            ));
        }
    }
    let what = format!(
        "overload sets{}",
        ext.map(|e| format!(" with {e}")).unwrap_or_default()
    );
    eprintln!(
        "{what}: {} names by version and stage, {} equal to Mesa's",
        cases.len(),
        cases.len() - bad.len()
    );
    assert!(
        bad.is_empty(),
        "{what}:\n{}",
        bad[..bad.len().min(40)].join("\n")
    );
}

/// Whether every type a printed prototype names exists in `v` with `exts` enabled.
fn mentioned_types_exist(proto: &str, v: Version, exts: &[&str]) -> bool {
    proto
        .split(|c: char| !c.is_alphanumeric())
        .filter_map(Type::named)
        .all(|t| t.exists_with(v, exts))
}

/// The result of every signature, assigned to a struct, makes Mesa name its type:
/// "initializer of type RET cannot be assigned to variable of type Z", RET the tables'
/// return type (the acceptance test alone would let an int result pass for a float
/// one through the implicit conversion).
#[test]
fn return_types_are_mesas() {
    let (mut cases, mut want) = (Vec::new(), Vec::new());
    for f in all_functions().iter().filter(|f| f.ret != Type::Void) {
        for v in Version::all() {
            for stage in STAGES.into_iter().filter(|s| f.exists(v, *s)) {
                let c = call(v, stage, &f.name, &args_of(f), Some("Z"));
                let (c, w) = batch::names_type(c, &f.ret);
                cases.push(c);
                want.push(w);
            }
        }
    }
    batch::expect_errors("return types", &cases, &want, 60);
}
