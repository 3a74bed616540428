//! Generated agreement with Mesa for the type checker:
//! - random well-typed expressions (a fixed-seed generator over the scalar, vector and
//!   matrix types, the operators, swizzles, constructors, `?:` and built-in calls of
//!   versions 1.10, 1.20, 1.30 and 3.30), which Mesa and we must both accept;
//! - the same shaders with one token of the expression replaced by a name, literal or
//!   operator of another type: acceptance must agree with Mesa's, and where both
//!   reject, the first error's line (the test prints the agreement rates).

mod common;
mod mesa;

use common::{mesa_first_error, our_first_error, Rng};
use mesa::{run, Context, Job};
use proptest::prelude::*;
use softgl_glsl::{compile_with_log, Stage};

/// The generator's types: base (`f` float, `i` int, `u` uint, `b` bool, `m` matrix)
/// and size.
#[derive(Clone, Copy, PartialEq)]
struct Ty(char, u8);

impl Ty {
    fn name(self) -> String {
        match (self.0, self.1) {
            ('f', 1) => "float".into(),
            ('i', 1) => "int".into(),
            ('u', 1) => "uint".into(),
            ('b', 1) => "bool".into(),
            ('f', n) => format!("vec{n}"),
            ('m', n) => format!("mat{n}"),
            (c, n) => format!("{c}vec{n}"),
        }
    }
    fn uniform(self) -> String {
        format!("u_{}{}", self.0, self.1)
    }
}

struct Gen {
    rng: Rng,
    version: u32,
}

impl Gen {
    fn literal(&mut self, t: Ty) -> String {
        let k = self.rng.next() % 5;
        match t.0 {
            'f' => format!("{k}.5"),
            'i' => format!("{k}"),
            'u' => format!("{k}u"),
            _ => ["true", "false"][k % 2].into(),
        }
    }

    /// An expression of type `t`, at most `depth` levels deep.
    fn expr(&mut self, t: Ty, depth: u32) -> String {
        let ints = self.version >= 130;
        let r = if depth == 0 {
            self.rng.next() % 2
        } else {
            self.rng.next() % 12
        };
        let sub = |g: &mut Gen, t: Ty| g.expr(t, depth.saturating_sub(1));
        match (r, t.0, t.1) {
            (0, _, _) => t.uniform(),
            (1, 'm', n) => format!(
                "{}({})",
                t.name(),
                self.literal(Ty('f', 1)).replace("5", &n.to_string())
            ),
            (1, _, 1) => self.literal(t),
            (1, c, n) => {
                let parts: Vec<String> = (0..n).map(|_| self.literal(Ty(c, 1))).collect();
                format!("{}({})", t.name(), parts.join(", "))
            }
            (2 | 3, 'f' | 'i' | 'u', _) | (2 | 3, 'm', _) => {
                let op = if t.0 == 'm' {
                    "+"
                } else {
                    *self.rng.pick(&["+", "-", "*", "/"])
                };
                format!("({} {op} {})", sub(self, t), sub(self, t))
            }
            (4, 'f' | 'i' | 'u', n) if n > 1 => {
                // vector op scalar
                format!("({} * {})", sub(self, t), sub(self, Ty(t.0, 1)))
            }
            (5, c, n) if c != 'm' => {
                // a swizzle of a vec4
                let comps = ["x", "y", "z", "w"];
                let s: String = (0..n).map(|_| *self.rng.pick(&comps)).collect();
                format!("{}.{s}", sub(self, Ty(c, 4)))
            }
            (6, _, _) => format!(
                "({} ? {} : {})",
                sub(self, Ty('b', 1)),
                sub(self, t),
                sub(self, t)
            ),
            (7, 'f', 1) => format!("dot({}, {})", sub(self, Ty('f', 3)), sub(self, Ty('f', 3))),
            (7, 'f', n) => {
                let f = *self
                    .rng
                    .pick(&["sin", "abs", "floor", "normalize", "fract"]);
                format!("{f}({})", sub(self, Ty('f', n)))
            }
            (8, 'f', n) => {
                let f = *self.rng.pick(&["max", "min", "pow", "step"]);
                format!("{f}({}, {})", sub(self, Ty('f', n)), sub(self, Ty('f', n)))
            }
            (9, 'f', n) if n > 1 => format!("({} * {})", sub(self, Ty('m', n)), sub(self, t)),
            (4, 'm', n) => format!("({} * {})", sub(self, Ty('m', n)), sub(self, t)),
            (9, 'b', 1) => {
                let op = *self.rng.pick(&["<", ">=", "==", "!="]);
                format!("({} {op} {})", sub(self, Ty('f', 1)), sub(self, Ty('f', 1)))
            }
            (10, 'b', 1) => {
                let op = *self.rng.pick(&["&&", "||", "^^"]);
                format!("({} {op} {})", sub(self, t), sub(self, t))
            }
            (10, 'i' | 'u', _) if ints => {
                let op = *self.rng.pick(&["&", "|", "^", "%"]);
                format!("({} {op} {})", sub(self, t), sub(self, t))
            }
            (11, 'f', n) => {
                // a conversion constructor from another base type
                let c = if ints {
                    *self.rng.pick(&['i', 'u', 'b'])
                } else {
                    *self.rng.pick(&['i', 'b'])
                };
                format!("{}({})", t.name(), sub(self, Ty(c, n)))
            }
            (7, 'i', 1) if self.version >= 120 => format!("({} + 1)", sub(self, t)),
            (9, 'f', 1) if self.version >= 120 => {
                // an implicit int to float conversion
                format!("({} + {})", sub(self, t), sub(self, Ty('i', 1)))
            }
            _ => t.uniform(),
        }
    }

    fn types(&self) -> Vec<Ty> {
        let mut v = Vec::new();
        for c in ['f', 'i', 'b'] {
            for n in 1..=4 {
                v.push(Ty(c, n));
            }
        }
        if self.version >= 130 {
            for n in 1..=4 {
                v.push(Ty('u', n));
            }
        }
        for n in 2..=4 {
            v.push(Ty('m', n));
        }
        v
    }

    fn shader(&mut self) -> String {
        let types = self.types();
        let t = *self.rng.pick(&types);
        let e = self.expr(t, 3);
        let mut s = format!("#version {}\n", self.version);
        for u in &types {
            s.push_str(&format!("uniform {} {};\n", u.name(), u.uniform()));
        }
        let out = if self.version >= 130 {
            "c"
        } else {
            "gl_FragColor"
        };
        if self.version >= 130 {
            s.push_str("out vec4 c;\n");
        }
        s.push_str(&format!(
            "void main() {{\n  {} t = {e};\n  {out} = vec4(0.0);\n}}\n",
            t.name()
        ));
        s
    }
}

/// Tokens a mutation puts in place of one token of the expression.
const REPLACEMENTS: &[&str] = &[
    "u_f1", "u_f3", "u_i1", "u_i2", "u_b1", "u_m3", "1", "1.0", "true", "1u", "+", "*", "-", "==",
    "&&", "<", "vec2", "x", "xyz", "!", "%",
];

fn mutate(src: &str, rng: &mut Rng) -> String {
    let start = src.find("t = ").map(|i| i + 4).unwrap_or(0);
    let end = src[start..]
        .find(';')
        .map(|i| i + start)
        .unwrap_or(src.len());
    mutate_span(src, start, end, REPLACEMENTS, rng)
}

/// Replaces one token of `src[start..end]` by one of `tokens`.
fn mutate_span(src: &str, start: usize, end: usize, tokens: &[&str], rng: &mut Rng) -> String {
    let b = src.as_bytes();
    let mut spans = Vec::new();
    let mut i = start;
    let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c == b'.';
    while i < end {
        if b[i].is_ascii_whitespace() {
            i += 1;
        } else if word(b[i]) {
            let s = i;
            while i < end && word(b[i]) {
                i += 1;
            }
            spans.push((s, i));
        } else {
            spans.push((i, i + 1));
            i += 1;
        }
    }
    if spans.is_empty() {
        return src.to_string();
    }
    let (s, e) = spans[rng.next() % spans.len()];
    format!("{}{}{}", &src[..s], rng.pick(tokens), &src[e..])
}

fn env(k: &str, d: usize) -> usize {
    std::env::var(k)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(d)
}

#[test]
fn random_expressions_and_mutations_agree_with_mesa() {
    let n = env("GLSL_CHECK_CASES", 400);
    let mut shaders = Vec::new();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for (k, v) in [110u32, 120, 130, 330].iter().cycle().take(n).enumerate() {
        let mut g = Gen {
            rng: Rng(0x1234_5678 + k as u64 * 7919),
            version: *v,
        };
        shaders.push(g.shader());
    }
    let mutants: Vec<String> = shaders.iter().map(|s| mutate(s, &mut rng)).collect();
    let all: Vec<&String> = shaders.iter().chain(&mutants).collect();
    let core = |s: &str| s.starts_with("#version 330");
    let mut verdict = vec![(false, String::new()); all.len()];
    for ctx in [Context::Compat, Context::Core33] {
        let idx: Vec<usize> = (0..all.len())
            .filter(|i| core(all[*i]) == (ctx == Context::Core33))
            .collect();
        let jobs: Vec<Job> = idx.iter().map(|i| Job::Fragment(all[*i])).collect();
        for (i, o) in idx.iter().zip(run(ctx, &jobs)) {
            verdict[*i] = (o.ok, o.log);
        }
    }
    let mut valid_bad = Vec::new();
    for (s, (ok, log)) in shaders.iter().zip(&verdict) {
        let (p, ours) = compile_with_log(&[s], Stage::Fragment);
        if !ok {
            valid_bad.push(format!("Mesa rejects a generated shader:\n{s}{log}"));
        } else if p.is_none() {
            valid_bad.push(format!("we reject:\n{s}{ours}"));
        }
    }
    let (mut agree, mut both_err, mut same_line, mut same_text) = (0, 0, 0, 0);
    let mut disagree = Vec::new();
    for (s, (ok, log)) in mutants.iter().zip(&verdict[shaders.len()..]) {
        let (p, ours) = compile_with_log(&[s], Stage::Fragment);
        if p.is_some() == *ok {
            agree += 1;
        } else {
            disagree.push(format!("Mesa {ok}:\n{s}{log}ours:\n{ours}"));
        }
        if let (Some(o), Some(t)) = (our_first_error(&ours), mesa_first_error(log)) {
            both_err += 1;
            let line = |p: &str| p.split('(').next().unwrap_or("").to_string();
            if line(&o.0) == line(&t.0) {
                same_line += 1;
            }
            if o.2 == t.2.trim_end() || (o.2.starts_with("syntax") && t.2.starts_with(&o.2)) {
                same_text += 1;
            } else if std::env::var("GLSL_CHECK_SHOW").is_ok() {
                println!("text: ours `{}`, Mesa `{}`\n{s}", o.2, t.2);
            }
        }
    }
    println!(
        "{} generated shaders: {} disagreements; {} mutants: acceptance agrees on {agree}, \
         {both_err} rejected by both: {same_line} on Mesa's line, {same_text} word for word",
        shaders.len(),
        valid_bad.len(),
        mutants.len()
    );
    for d in disagree.iter().take(8) {
        println!("--- {d}");
    }
    assert!(valid_bad.is_empty(), "{}", valid_bad.join("\n"));
    assert!(
        agree * 100 >= mutants.len() * 97,
        "acceptance agrees on {agree} of {}",
        mutants.len()
    );
}

/// Atoms and operators of the random expression trees of the property below: names
/// of every type, literals, and constructors.
const ATOMS: &[&str] = &[
    "u_f1",
    "u_f3",
    "u_i1",
    "u_i2",
    "u_b1",
    "u_m3",
    "u_u1",
    "1",
    "1.0",
    "true",
    "1u",
    "-3",
    "vec2(1.0)",
    "ivec3(2)",
    "mat2(1.0)",
    "float[2](1.0, 2.0)",
    "u_f3.xy",
    "u_m3[1]",
    "nope",
];
const BINOPS: &[&str] = &[
    "+", "-", "*", "/", "%", "==", "!=", "<", ">=", "&&", "||", "^^", "&", "|", "^", "<<", ">>",
    ",", "=", "+=", "*=",
];

/// An expression from a flat list of choices: each step wraps the expression so far.
fn soup(steps: &[(u8, usize)]) -> String {
    let mut e = ATOMS[0].to_string();
    for &(kind, k) in steps {
        let a = ATOMS[k % ATOMS.len()];
        e = match kind % 8 {
            0 => format!("({e} {} {a})", BINOPS[k % BINOPS.len()]),
            1 => format!("({a} {} {e})", BINOPS[k % BINOPS.len()]),
            2 => format!("-({e})"),
            3 => format!(
                "({e}).{}",
                ["x", "xy", "zzz", "length()", "rgba", "s"][k % 6]
            ),
            4 => format!("({e})[{}]", k % 4),
            5 => format!("(u_b1 ? {e} : {a})"),
            6 => format!(
                "{}({e})",
                ["vec4", "float", "max", "sin", "mat3", "int", "S", "f"][k % 8]
            ),
            _ => format!(
                "{}({e}, {a})",
                ["vec2", "dot", "max", "mat2", "f", "S"][k % 6]
            ),
        };
    }
    e
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: std::env::var("GLSL_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(2000),
        ..ProptestConfig::default()
    })]

    /// Random operator trees over mixed types: the checker answers (accepts or gives an
    /// error), never panics.
    #[test]
    fn random_expression_trees_never_panic(
        version in prop::sample::select(vec![110u32, 120, 130, 150, 330]),
        steps in proptest::collection::vec((any::<u8>(), any::<usize>()), 0..40),
    ) {
        let src = format!(
            "#version {version}\nuniform float u_f1; uniform vec3 u_f3; uniform int u_i1;\n\
             uniform ivec2 u_i2; uniform bool u_b1; uniform mat3 u_m3;\n\
             struct S {{ float a; }};\nfloat f(float x) {{ return x; }}\n\
             void main() {{\n  float t = 0.0;\n  t = {};\n}}\n",
            soup(&steps)
        );
        let (p, log) = compile_with_log(&[&src], Stage::Fragment);
        prop_assert!(p.is_some() != log.has_errors());
    }
}

/// What a corpus mutation puts in place of one token: names, types, qualifiers,
/// literals and operators that change types.
const CORPUS_REPLACEMENTS: &[&str] = &[
    "float",
    "vec3",
    "int",
    "mat3",
    "bool",
    "uniform",
    "const",
    "in",
    "out",
    "1",
    "1.0",
    "true",
    "1u",
    "+",
    "*",
    "==",
    "&&",
    "x",
    "xyz",
    "gl_Position",
    "gl_FragColor",
    "gl_Vertex",
    "texture",
    "texture2D",
    "discard",
    "break",
    "return",
    "[0]",
    "[9]",
    ".w",
    "flat",
];

/// The valid corpus with one token (after the `#version` line) replaced: acceptance
/// agrees with Mesa's on at least 97% of the shaders, and where both reject, the first
/// error is on Mesa's line for at least 90% (the printed rates are the measurement).
#[test]
fn mutated_corpus_types_agree_with_mesa() {
    let per = env("GLSL_CHECK_MUTATIONS", 30);
    let corpus = common::corpus("valid");
    let mut rng = Rng(0x5eed_0fc4_ec00);
    let mut cases = Vec::new();
    for (name, stage, src) in &corpus {
        let start = src.find('\n').map(|i| i + 1).unwrap_or(0);
        for k in 0..per {
            let m = mutate_span(src, start, src.len(), CORPUS_REPLACEMENTS, &mut rng);
            cases.push((format!("{name}#{k}"), *stage, m));
        }
    }
    let mesa = mesa::verdicts(&cases);
    let (mut agree, mut both, mut same_line, mut same_text) = (0, 0, 0, 0);
    let mut shown = 0;
    for ((name, stage, src), (ok, log)) in cases.iter().zip(&mesa) {
        let theirs = mesa_first_error(log);
        let (p, ours_log) = compile_with_log(&[src], *stage);
        let ours = our_first_error(&ours_log);
        if p.is_some() == *ok {
            agree += 1;
        } else if shown < 12 {
            shown += 1;
            println!("{name}: Mesa {ok} {theirs:?}, ours {ours:?}");
            if std::env::var("GLSL_CHECK_SHOW").is_ok() {
                println!("{src}");
            }
        }
        if let (Some(o), Some(t)) = (&ours, &theirs) {
            both += 1;
            let line = |p: &str| p.split('(').next().unwrap_or("").to_string();
            same_line += usize::from(line(&o.0) == line(&t.0));
            let text = o.2 == t.2.trim_end() || common::agrees(o, t);
            same_text += usize::from(text);
            if !text && std::env::var("GLSL_CHECK_SHOW").is_ok() {
                println!("{name}: ours {o:?}, Mesa {t:?}");
            }
        }
    }
    println!(
        "{} mutated corpus shaders: acceptance agrees on {agree}; {both} rejected by both: \
         {same_line} on Mesa's line, {same_text} word for word",
        cases.len()
    );
    assert!(
        agree * 100 >= cases.len() * 97,
        "{agree} of {}",
        cases.len()
    );
    assert!(same_line * 100 >= both * 90, "{same_line} of {both}");
}

#[test]
fn long_operator_chains_are_bounded() {
    // The parser builds `a + a + ... + a` with a loop: a left-nested tree as deep as
    // the chain is long, which the checker must refuse rather than overflow its stack.
    for n in [10, 1000, 100_000] {
        let chain = vec!["1.0"; n].join(" + ");
        let src = format!("#version 120\nvoid main() {{ gl_FragColor = vec4({chain}); }}\n");
        let (p, log) = compile_with_log(&[&src], Stage::Fragment);
        if n <= 1000 {
            assert!(p.is_some(), "{n}: {log}");
        } else {
            assert!(p.is_none());
        }
    }
}
