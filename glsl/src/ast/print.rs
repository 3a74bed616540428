//! Writes a syntax tree back as GLSL. Every operation is parenthesised, so the text
//! parses back to the same tree whatever the precedences; the tests use this for
//! round trips (`print(parse(print(t))) == print(t)`).

use super::*;
use std::fmt::Write;

/// The GLSL text of `shader`.
pub fn shader(s: &Shader) -> String {
    let mut o = String::new();
    let profile = match s.profile {
        crate::pp::Profile::None => "",
        crate::pp::Profile::Core => " core",
        crate::pp::Profile::Compatibility => " compatibility",
    };
    let _ = writeln!(o, "#version {}{profile}", s.version);
    for e in &s.extensions {
        let _ = writeln!(o, "#extension {} : {}", e.name, e.behavior);
    }
    for item in &s.items {
        match item {
            External::Decl(d) => decl(&mut o, d, 0),
            External::Function(f) => {
                proto(&mut o, &f.proto);
                o.push_str(" {\n");
                for st in &f.body {
                    stmt(&mut o, st, 1);
                }
                o.push_str("}\n");
            }
        }
    }
    o
}

fn indent(o: &mut String, n: usize) {
    for _ in 0..n {
        o.push_str("    ");
    }
}

fn qualifiers(o: &mut String, qs: &[Qualifier]) {
    for q in qs {
        let w = match q {
            Qualifier::Storage(s) => match s {
                Storage::Const => "const",
                Storage::In => "in",
                Storage::Out => "out",
                Storage::Inout => "inout",
                Storage::Attribute => "attribute",
                Storage::Uniform => "uniform",
                Storage::Varying => "varying",
                Storage::Centroid => "centroid",
            },
            Qualifier::Interp(i) => match i {
                Interp::Flat => "flat",
                Interp::Smooth => "smooth",
                Interp::Noperspective => "noperspective",
            },
            Qualifier::Invariant => "invariant",
            Qualifier::Precision(p) => precision(*p),
            Qualifier::Layout(ids) => {
                o.push_str("layout(");
                for (i, id) in ids.iter().enumerate() {
                    if i > 0 {
                        o.push_str(", ");
                    }
                    o.push_str(&id.name);
                    if let Some(v) = &id.value {
                        o.push_str(" = ");
                        expr(o, v);
                    }
                }
                o.push_str(") ");
                continue;
            }
        };
        o.push_str(w);
        o.push(' ');
    }
}

fn precision(p: Precision) -> &'static str {
    match p {
        Precision::Lowp => "lowp",
        Precision::Mediump => "mediump",
        Precision::Highp => "highp",
    }
}

fn dims(o: &mut String, d: &[ArraySize]) {
    for s in d {
        o.push('[');
        if let Some(e) = s {
            expr(o, e);
        }
        o.push(']');
    }
}

fn type_spec(o: &mut String, t: &TypeSpec, depth: usize) {
    match &t.name {
        TypeName::Named(n) => o.push_str(n),
        TypeName::Struct(s) => {
            o.push_str("struct ");
            if let Some(n) = &s.name {
                o.push_str(n);
                o.push(' ');
            }
            o.push_str("{\n");
            members(o, &s.members, depth + 1);
            indent(o, depth);
            o.push('}');
        }
    }
    dims(o, &t.array);
}

fn members(o: &mut String, ms: &[Member], depth: usize) {
    for m in ms {
        indent(o, depth);
        full_type(o, &m.ty, depth);
        declarators(o, &m.names);
        o.push_str(";\n");
    }
}

fn full_type(o: &mut String, t: &FullType, depth: usize) {
    qualifiers(o, &t.qualifiers);
    type_spec(o, &t.spec, depth);
}

fn declarators(o: &mut String, ds: &[Declarator]) {
    for (i, d) in ds.iter().enumerate() {
        o.push_str(if i == 0 { " " } else { ", " });
        o.push_str(&d.name);
        dims(o, &d.array);
        if let Some(e) = &d.init {
            o.push_str(" = ");
            expr(o, e);
        }
    }
}

fn proto(o: &mut String, p: &Prototype) {
    full_type(o, &p.ret, 0);
    let _ = write!(o, " {}(", p.name);
    for (i, a) in p.params.iter().enumerate() {
        if i > 0 {
            o.push_str(", ");
        }
        full_type(o, &a.ty, 0);
        if let Some(n) = &a.name {
            o.push(' ');
            o.push_str(n);
        }
        dims(o, &a.array);
    }
    o.push(')');
}

fn decl(o: &mut String, d: &Decl, depth: usize) {
    indent(o, depth);
    match d {
        Decl::Vars { ty, vars } => {
            full_type(o, ty, depth);
            declarators(o, vars);
        }
        Decl::Prototype(p) => proto(o, p),
        Decl::Precision {
            precision: p, ty, ..
        } => {
            let _ = write!(o, "precision {} ", precision(*p));
            type_spec(o, ty, depth);
        }
        Decl::Block(b) => {
            qualifiers(o, &b.qualifiers);
            let _ = writeln!(o, "{} {{", b.name);
            members(o, &b.members, depth + 1);
            indent(o, depth);
            o.push('}');
            if let Some((n, d)) = &b.instance {
                o.push(' ');
                o.push_str(n);
                dims(o, d);
            }
        }
        Decl::Default { qualifiers: q, .. } => qualifiers(o, q),
        Decl::Invariant { names } => {
            o.push_str("invariant ");
            let n: Vec<&str> = names.iter().map(|(n, _)| n.as_str()).collect();
            o.push_str(&n.join(", "));
        }
    }
    o.push_str(";\n");
}

fn condition(o: &mut String, c: &Condition) {
    match c {
        Condition::Expr(e) => expr(o, e),
        Condition::Decl { ty, name, init, .. } => {
            full_type(o, ty, 0);
            let _ = write!(o, " {name} = ");
            expr(o, init);
        }
    }
}

fn stmt(o: &mut String, s: &Stmt, depth: usize) {
    if let StmtKind::Decl(d) = &s.kind {
        return decl(o, d, depth);
    }
    indent(o, depth);
    match &s.kind {
        StmtKind::Decl(_) => {}
        StmtKind::Expr(e) => {
            if let Some(e) = e {
                expr(o, e);
            }
            o.push_str(";\n");
        }
        StmtKind::Compound(b) => {
            o.push_str("{\n");
            for st in b {
                stmt(o, st, depth + 1);
            }
            indent(o, depth);
            o.push_str("}\n");
        }
        StmtKind::If(c, a, b) => {
            o.push_str("if (");
            expr(o, c);
            o.push_str(")\n");
            stmt(o, a, depth + 1);
            if let Some(b) = b {
                indent(o, depth);
                o.push_str("else\n");
                stmt(o, b, depth + 1);
            }
        }
        StmtKind::Switch(e, b) => {
            o.push_str("switch (");
            expr(o, e);
            o.push_str(") {\n");
            for st in b {
                stmt(o, st, depth + 1);
            }
            indent(o, depth);
            o.push_str("}\n");
        }
        StmtKind::Case(e) => {
            o.push_str("case ");
            expr(o, e);
            o.push_str(":\n");
        }
        StmtKind::Default => o.push_str("default:\n"),
        StmtKind::While(c, b) => {
            o.push_str("while (");
            condition(o, c);
            o.push_str(")\n");
            stmt(o, b, depth + 1);
        }
        StmtKind::DoWhile(b, c) => {
            o.push_str("do\n");
            stmt(o, b, depth + 1);
            indent(o, depth);
            o.push_str("while (");
            expr(o, c);
            o.push_str(");\n");
        }
        StmtKind::For {
            init,
            cond,
            step,
            body,
        } => {
            o.push_str("for (\n");
            stmt(o, init, depth + 1);
            indent(o, depth + 1);
            if let Some(c) = cond {
                condition(o, c);
            }
            o.push_str("; ");
            if let Some(s) = step {
                expr(o, s);
            }
            o.push_str(")\n");
            stmt(o, body, depth + 1);
        }
        StmtKind::Break => o.push_str("break;\n"),
        StmtKind::Continue => o.push_str("continue;\n"),
        StmtKind::Discard => o.push_str("discard;\n"),
        StmtKind::Return(e) => {
            o.push_str("return");
            if let Some(e) = e {
                o.push(' ');
                expr(o, e);
            }
            o.push_str(";\n");
        }
    }
}

fn binop(op: BinOp) -> &'static str {
    BINOPS
        .iter()
        .find(|(_, _, b)| *b == op)
        .map_or("?", |(t, _, _)| t)
}

fn list(o: &mut String, a: &[Expr], open: char, close: char) {
    o.push(open);
    for (i, e) in a.iter().enumerate() {
        if i > 0 {
            o.push_str(", ");
        }
        expr(o, e);
    }
    o.push(close);
}

fn args(o: &mut String, a: &[Expr]) {
    list(o, a, '(', ')');
}

/// Writes an expression, fully parenthesised.
pub fn expr(o: &mut String, e: &Expr) {
    match &e.kind {
        ExprKind::Ident(n) => o.push_str(n),
        ExprKind::Int(v) => {
            let _ = write!(o, "{v}");
        }
        ExprKind::Uint(v) => {
            let _ = write!(o, "{v}u");
        }
        ExprKind::Int64(v) => {
            let _ = write!(o, "{v}l");
        }
        ExprKind::Uint64(v) => {
            let _ = write!(o, "{v}ul");
        }
        ExprKind::Float(v) if v.is_finite() => {
            let _ = write!(o, "{v:?}");
        }
        ExprKind::Float(_) => o.push_str("1e999"),
        ExprKind::Bool(v) => {
            let _ = write!(o, "{v}");
        }
        ExprKind::Unary(op, a) => {
            let (pre, post) = match op {
                UnOp::Plus => ("+", ""),
                UnOp::Neg => ("-", ""),
                UnOp::Not => ("!", ""),
                UnOp::BitNot => ("~", ""),
                UnOp::PreInc => ("++", ""),
                UnOp::PreDec => ("--", ""),
                UnOp::PostInc => ("", "++"),
                UnOp::PostDec => ("", "--"),
            };
            o.push('(');
            o.push_str(pre);
            expr(o, a);
            o.push_str(post);
            o.push(')');
        }
        ExprKind::Binary(op, a, b) => {
            o.push('(');
            expr(o, a);
            let _ = write!(o, " {} ", binop(*op));
            expr(o, b);
            o.push(')');
        }
        ExprKind::Assign(op, a, b) => {
            o.push('(');
            expr(o, a);
            let t = ASSIGNOPS
                .iter()
                .find(|(_, x)| x == op)
                .map_or("=", |(t, _)| t);
            let _ = write!(o, " {t} ");
            expr(o, b);
            o.push(')');
        }
        ExprKind::Ternary(c, a, b) => {
            o.push('(');
            expr(o, c);
            o.push_str(" ? ");
            expr(o, a);
            o.push_str(" : ");
            expr(o, b);
            o.push(')');
        }
        ExprKind::Comma(a, b) => {
            o.push('(');
            expr(o, a);
            o.push_str(", ");
            expr(o, b);
            o.push(')');
        }
        ExprKind::Index(a, i) => {
            expr(o, a);
            o.push('[');
            expr(o, i);
            o.push(']');
        }
        ExprKind::Field(a, n) => {
            expr(o, a);
            o.push('.');
            o.push_str(n);
        }
        ExprKind::Call(c, a) => {
            match c {
                Callee::Name(n) => o.push_str(n),
                Callee::Type(t) => type_spec(o, t, 0),
                Callee::Expr(e) => {
                    o.push('(');
                    expr(o, e);
                    o.push(')');
                }
            }
            args(o, a);
        }
        ExprKind::InitList(items) => list(o, items, '{', '}'),
        ExprKind::Method(a, n, x) => {
            expr(o, a);
            o.push('.');
            o.push_str(n);
            args(o, x);
        }
    }
}
