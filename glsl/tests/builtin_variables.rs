//! The built-in variable, uniform-state and constant tables against Mesa's compiler:
//! each is readable with its type (struct members too) in every version and stage the
//! tables list, assignable exactly when it is an output, absent elsewhere; sized
//! arrays have the size the tables give, and the constants the values they give.

mod batch;
mod mesa;

use batch::{expect, Case};
use softgl_glsl::builtins::state::CONSTANTS;
use softgl_glsl::builtins::variables::{Kind, Variable};
use softgl_glsl::builtins::{all_variables, variable};
use softgl_glsl::types::{Stage, Type, Version};
use std::collections::BTreeSet;

const STAGES: [Stage; 2] = [Stage::Vertex, Stage::Fragment];

fn case(version: Version, stage: Stage, line: String) -> Case {
    Case {
        version,
        stage,
        globals: vec![],
        line,
    }
}

/// The variable as an l-value of a non-array type (element 0 of an array) and its type.
fn element(v: &Variable) -> (String, Type) {
    match &v.ty {
        Type::Array(e, _) => (format!("{}[0]", v.name), (**e).clone()),
        t => (v.name.clone(), t.clone()),
    }
}

/// Every (variable, version, stage) of the tables in the vertex and fragment stages.
fn placements() -> Vec<(&'static Variable, Version, Stage)> {
    let mut out = Vec::new();
    for var in all_variables() {
        for v in Version::all() {
            for s in STAGES {
                if var.avail.exists(v, s) {
                    out.push((var, v, s));
                }
            }
        }
    }
    out
}

#[test]
fn variables_read_with_their_types() {
    let mut cases = Vec::new();
    for (var, v, s) in placements() {
        let (lv, ty) = element(var);
        let q = if var.kind == Kind::Constant {
            "const "
        } else {
            ""
        };
        cases.push(case(v, s, format!("{{ {q}{ty} x = {lv}; }}")));
        if let Type::Struct(st) = &ty {
            for m in &st.members {
                cases.push(case(v, s, format!("{{ {} x = {lv}.{}; }}", m.ty, m.name)));
            }
        }
        if let Type::Array(e, Some(n)) = &var.ty {
            cases.push(case(
                v,
                s,
                format!("{{ {e} x = {}[{}]; }}", var.name, n - 1),
            ));
        }
    }
    eprintln!(
        "{} variables, uniforms and constants in the tables",
        all_variables().len()
    );
    expect("reads with the tables' types", &cases, true, 60);
}

#[test]
fn outputs_and_only_outputs_are_assignable() {
    let (mut yes, mut no) = (Vec::new(), Vec::new());
    for (var, v, s) in placements() {
        let (lv, _) = element(var);
        let c = case(v, s, format!("{{ {lv} = {lv}; }}"));
        if var.writable() {
            yes.push(c);
        } else {
            no.push(c);
        }
    }
    // One to a shader: writing both gl_FragColor and gl_FragData is an error.
    expect("assignments to outputs", &yes, true, 1);
    expect(
        "assignments to inputs, uniforms and constants",
        &no,
        false,
        60,
    );
}

#[test]
fn variables_are_absent_where_the_tables_say() {
    let names: BTreeSet<&str> = all_variables().iter().map(|v| v.name.as_str()).collect();
    let mut cases = Vec::new();
    for name in names {
        for v in Version::all() {
            for s in STAGES {
                if variable(name, v, s, &[]).is_none() {
                    cases.push(case(v, s, format!("{{ {name}; }}")));
                }
            }
        }
    }
    expect(
        "names out of their version, stage or profile",
        &cases,
        false,
        60,
    );
}

/// A constant index one past a sized array is rejected (so the size is the tables'),
/// and each constant equals the tables' value in Mesa (`x[c == value ? 1 : -1]`).
#[test]
fn sizes_and_constant_values_are_mesas() {
    let (mut bounds, mut values) = (Vec::new(), Vec::new());
    for (var, v, s) in placements() {
        if let Type::Array(_, Some(n)) = &var.ty {
            bounds.push(case(v, s, format!("{{ {}[{n}]; }}", var.name)));
        }
        if let Some(x) = var.value {
            values.push(case(
                v,
                s,
                format!("{{ float x[{} == {x} ? 1 : -1]; }}", var.name),
            ));
        }
    }
    expect("indices one past a sized array", &bounds, false, 60);
    expect("constants equal to Mesa's", &values, true, 60);
    assert_eq!(CONSTANTS.len(), 23);
}

/// Each variable assigned to a struct makes Mesa name its type: "initializer of type T
/// cannot be assigned to variable of type Z", T the tables' type (a read into a
/// variable of the tables' type alone would pass an int for a float through the
/// implicit conversion).
#[test]
fn types_are_mesas() {
    let (cases, want): (Vec<Case>, Vec<String>) = placements()
        .into_iter()
        .map(|(var, v, s)| {
            batch::names_type(case(v, s, format!("{{ Z x = {}; }}", var.name)), &var.ty)
        })
        .unzip();
    batch::expect_errors("variable types", &cases, &want, 60);
}

/// The extension variables (ARB_draw_instanced's `gl_InstanceIDARB`): with the
/// extension enabled, Mesa names their type where the tables have them and rejects
/// them elsewhere.
#[test]
fn extension_variables_are_mesas() {
    let (mut there, mut want, mut absent) = (Vec::new(), Vec::new(), Vec::new());
    for var in all_variables().iter().filter(|v| v.avail.ext.is_some()) {
        let ext = var.avail.ext.unwrap();
        for v in Version::all() {
            for s in STAGES {
                let directive = format!("#extension {ext} : enable");
                let with_ext = |line: String| {
                    let mut c = case(v, s, line);
                    c.globals.push(directive.clone());
                    c
                };
                if var.avail.exists_with(v, s, &[ext]) {
                    let c = with_ext(format!("{{ Z x = {}; }}", var.name));
                    let (c, w) = batch::names_type(c, &var.ty);
                    there.push(c);
                    want.push(w);
                } else {
                    absent.push(with_ext(format!("{{ {}; }}", var.name)));
                }
            }
        }
    }
    batch::expect_errors("extension variables", &there, &want, 60);
    expect("extension variables out of their stage", &absent, false, 60);
}
