//! Robustness: random bytes, random token soups and mutated corpus shaders must never
//! make the front end panic, and hostile shaders (deep nesting, exploding macros) end
//! in an error rather than a stack overflow or a long run.

mod common;

use proptest::prelude::*;
use softgl_glsl::{compile_with_log, parse_with_log, Stage};

const VOCAB: &[&str] = &[
    "#version 330\n",
    "#version 110\n",
    "#version 150 core\n",
    "#define ",
    "#undef ",
    "#if ",
    "#ifdef ",
    "#ifndef ",
    "#elif ",
    "#else\n",
    "#endif\n",
    "#line ",
    "#error ",
    "#pragma ",
    "#extension ",
    "defined",
    "__LINE__",
    "__FILE__",
    "__VERSION__",
    "A",
    "B",
    "F(",
    "F",
    "x",
    "y",
    "main",
    "void",
    "float",
    "int",
    "uint",
    "vec4",
    "mat4x3",
    "bool",
    "sampler2D",
    "struct",
    "S",
    "uniform",
    "in",
    "out",
    "inout",
    "const",
    "attribute",
    "varying",
    "centroid",
    "flat",
    "smooth",
    "noperspective",
    "invariant",
    "layout",
    "location",
    "std140",
    "precision",
    "highp",
    "lowp",
    "if",
    "else",
    "for",
    "while",
    "do",
    "switch",
    "case",
    "default",
    "break",
    "continue",
    "return",
    "discard",
    "true",
    "1",
    "0x1F",
    "017",
    "1u",
    "1.5",
    ".5e3",
    "2.0f",
    "99999999999",
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ";",
    ",",
    ".",
    ":",
    "?",
    "=",
    "+=",
    "<<=",
    "++",
    "--",
    "+",
    "-",
    "*",
    "/",
    "%",
    "<<",
    ">>",
    "<",
    ">=",
    "==",
    "!=",
    "&&",
    "||",
    "^^",
    "&",
    "|",
    "^",
    "!",
    "~",
    "##",
    "#",
    "\\\n",
    "/*",
    "*/",
    "//",
    "\n",
    " ",
    "\t",
    "@",
    "\"",
    "input",
];

fn parse_any(src: &str) {
    for stage in [Stage::Vertex, Stage::Fragment] {
        let (tree, log) = parse_with_log(&[src], stage);
        assert!(tree.is_some() != log.has_errors() || tree.is_none());
        let _ = log.to_string();
        // The type checker too, where the parse succeeds.
        if tree.is_some() {
            let (p, log) = compile_with_log(&[src], stage);
            assert!(p.is_some() != log.has_errors());
        }
    }
}

proptest! {
    // `GLSL_FUZZ_CASES` runs more cases than the default 3000 per property.
    #![proptest_config(ProptestConfig {
        cases: std::env::var("GLSL_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(3000),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        parse_any(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn token_soup(toks in proptest::collection::vec(0..VOCAB.len(), 0..300)) {
        let src: String = toks.iter().map(|&i| VOCAB[i]).collect::<Vec<_>>().join(" ");
        parse_any(&src);
        let tight: String = toks.iter().map(|&i| VOCAB[i]).collect();
        parse_any(&tight);
    }

    #[test]
    fn mutated_corpus(file in 0usize..64, edits in proptest::collection::vec((0usize..4, any::<u32>(), any::<u32>(), 0..VOCAB.len()), 1..8)) {
        let corpus = common::corpus("valid");
        let mut src = corpus[file % corpus.len()].2.clone().into_bytes();
        for (kind, a, b, t) in edits {
            let n = src.len().max(1);
            let (a, b) = ((a as usize) % n, (b as usize) % n);
            let (lo, hi) = (a.min(b).min(src.len()), a.max(b).min(src.len()));
            match kind {
                0 => { src.drain(lo..hi.min(lo + 40)); }
                1 => { let piece = src[lo..hi.min(lo + 40)].to_vec(); src.splice(lo..lo, piece); }
                2 => { src.splice(lo..lo, VOCAB[t].bytes()); }
                _ => { if hi < src.len() { src.swap(lo, hi); } }
            }
        }
        parse_any(&String::from_utf8_lossy(&src));
    }
}

fn first_error(src: &str) -> String {
    let (tree, log) = parse_with_log(&[src], Stage::Fragment);
    assert!(tree.is_none(), "accepted: {src:.80}");
    log.first_error().unwrap().to_string()
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    for depth in [300, 10_000, 200_000] {
        let parens = format!(
            "void main() {{ float x = {}1.0{}; }}",
            "(".repeat(depth),
            ")".repeat(depth)
        );
        assert!(
            first_error(&parens).contains("nesting deeper than 256"),
            "{depth}"
        );
        let negs = format!("void main() {{ float x = {}1.0; }}", "- ".repeat(depth));
        assert!(first_error(&negs).contains("nesting deeper than 256"));
        let braces = format!("void main() {}{}", "{".repeat(depth), "}".repeat(depth));
        assert!(first_error(&braces).contains("nesting deeper than 256"));
        let ifs = format!("void main() {{ {} ; }}", "if (true) ".repeat(depth));
        assert!(first_error(&ifs).contains("nesting deeper than 256"));
        let structs = "struct { ".repeat(depth) + "float x;" + &" } y;".repeat(depth);
        assert!(first_error(&structs).contains("nesting deeper than 256"));
        let inits = format!(
            "float x[1] = {}1.0{};",
            "{".repeat(depth),
            "}".repeat(depth)
        );
        assert!(first_error(&inits).contains("nesting deeper than 256"));
        let hash_ifs = "#if 1\n".repeat(depth) + "void main(){}\n";
        assert!(first_error(&hash_ifs).contains("#if nesting too deep"));
        let pp_parens = format!("#if {}1{}\n#endif\n", "(".repeat(depth), ")".repeat(depth));
        assert!(first_error(&pp_parens).contains("syntax error"));
    }
    // 256 levels are fine.
    let ok = format!(
        "void main() {{ float x = {}1.0{}; }}",
        "(".repeat(200),
        ")".repeat(200)
    );
    assert!(parse_with_log(&[&ok], Stage::Fragment).0.is_some());
}

#[test]
fn exploding_macros_hit_the_budget() {
    let mut src = String::from("#define M0 x x\n");
    for i in 1..40 {
        src += &format!("#define M{i} M{} M{}\n", i - 1, i - 1);
    }
    src += "float f() { return M39; }\n";
    assert!(first_error(&src).contains("macro expansion exceeds the limit"));
    let nested = String::from("#define F(x) F(F(x))\nint a = F(F(F(F(1))));\n");
    let _ = parse_with_log(&[&nested], Stage::Fragment);
    let args = "#define G(x) x\nint a = ".to_string()
        + &"G(".repeat(5000)
        + "1"
        + &")".repeat(5000)
        + ";\n";
    assert!(first_error(&args).contains("macro arguments nest too deeply"));
}

#[test]
fn macro_call_over_many_lines_is_bounded() {
    let src = "#define F(x) x\nint a = F(\n".to_string() + &"1 +\n".repeat(200_000) + "1);\n";
    assert!(first_error(&src).contains("syntax error, unexpected end of file"));
    let short = "#define F(x) x\nint a = F(\n".to_string() + &"1 +\n".repeat(100) + "1);\n";
    assert!(parse_with_log(&[&short], Stage::Fragment).0.is_some());
}
