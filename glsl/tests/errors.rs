//! The error corpus: shaders with preprocessor or syntax errors that Mesa rejects.
//! For each, our first error must be on Mesa's line; preprocessor errors must read as
//! Mesa's word for word, and syntax errors must start as Mesa's does
//! (`syntax error, unexpected X`, Mesa's `expecting …` list aside) at Mesa's column.

mod common;
mod mesa;

use common::{mesa_first_error, our_first_error};
use mesa::{run, Context, Job};
use softgl_glsl::{parse_with_log, Stage};

/// (name, stage, source). `v` is a vertex shader, `f` a fragment shader.
const CASES: &[(&str, char, &str)] = &[
    // Preprocessor: conditionals.
    (
        "if_unterminated",
        'f',
        "#version 330\n#if 1\nvoid main(){}\n",
    ),
    (
        "ifdef_unterminated",
        'f',
        "#version 330\n#ifdef FOO\nvoid main(){}\n",
    ),
    (
        "ifndef_unterminated",
        'v',
        "#version 120\n#ifndef FOO\n#if 0\n#endif\nvoid main(){}\n",
    ),
    ("endif_alone", 'f', "#version 330\n#endif\nvoid main(){}\n"),
    ("else_alone", 'f', "#version 330\n#else\nvoid main(){}\n"),
    ("elif_alone", 'f', "#version 110\n#elif 1\nvoid main(){}\n"),
    (
        "multiple_else",
        'f',
        "#version 330\n#if 1\n#else\n#else\n#endif\nvoid main(){}\n",
    ),
    (
        "elif_after_else",
        'f',
        "#version 330\n#if 1\n#else\n#elif 1\n#endif\nvoid main(){}\n",
    ),
    (
        "if_no_expr",
        'f',
        "#version 330\n#if\n#endif\nvoid main(){}\n",
    ),
    (
        "elif_no_expr",
        'f',
        "#version 330\n#if 0\n#elif\n#endif\nvoid main(){}\n",
    ),
    (
        "ifdef_no_name",
        'f',
        "#version 330\n#ifdef\n#endif\nvoid main(){}\n",
    ),
    (
        "ifdef_number",
        'f',
        "#version 330\n#ifdef 1\n#endif\nvoid main(){}\n",
    ),
    (
        "if_div_zero",
        'f',
        "#version 330\n#if 1/0\n#endif\nvoid main(){}\n",
    ),
    (
        "if_mod_zero",
        'f',
        "#version 130\n#if 5 % (2 - 2)\n#endif\nvoid main(){}\n",
    ),
    (
        "if_dangling_op",
        'f',
        "#version 330\n#if 1 +\n#endif\nvoid main(){}\n",
    ),
    (
        "if_open_paren",
        'f',
        "#version 330\n#if (1\n#endif\nvoid main(){}\n",
    ),
    (
        "if_defined_alone",
        'f',
        "#version 330\n#if defined\n#endif\nvoid main(){}\n",
    ),
    (
        "if_defined_paren_number",
        'v',
        "#version 330\n#if defined(1)\n#endif\nvoid main(){}\n",
    ),
    (
        "if_float",
        'f',
        "#version 330\n#if 1.5\n#endif\nvoid main(){}\n",
    ),
    (
        "if_two_numbers",
        'f',
        "#version 330\n\n#if 1 2\n#endif\nvoid main(){}\n",
    ),
    (
        "nested_unterminated",
        'f',
        "#version 330\n#if 1\n#if 0\n#endif\nvoid main(){}\n",
    ),
    // Preprocessor: macros.
    (
        "paste_invalid",
        'f',
        "#version 330\n#define CAT(a,b) a ## b\nint x = CAT(+,-);\n",
    ),
    (
        "hash_in_macro_body",
        'f',
        "#version 330\n#define F(x) #x\nvoid main(){}\n",
    ),
    (
        "macro_redefined",
        'f',
        "#version 330\n#define A 1\n#define A 2\nvoid main(){}\n",
    ),
    (
        "macro_redefined_params",
        'f',
        "#version 330\n#define A(x) x\n#define A(y) y\nvoid main(){}\n",
    ),
    (
        "macro_too_many_args",
        'f',
        "#version 330\n#define F(x) x\nint a = F(1,2);\nvoid main(){}\n",
    ),
    (
        "macro_too_few_args",
        'v',
        "#version 330\n#define F(a,b) a\nint b = F(2);\n",
    ),
    (
        "macro_args_to_empty",
        'v',
        "#version 330\n#define F() 1\nint b = F(2);\n",
    ),
    (
        "macro_unterminated_call",
        'f',
        "#version 330\n#define F(x) x\nint a = F(1;\nvoid main(){}\n",
    ),
    (
        "macro_gl_prefix",
        'f',
        "#version 330\n#define GL_FOO 1\nvoid main(){}\n",
    ),
    (
        "macro_defined_name",
        'f',
        "#version 330\n#define defined 1\nvoid main(){}\n",
    ),
    (
        "macro_no_name",
        'f',
        "#version 330\n#define\nvoid main(){}\n",
    ),
    (
        "macro_number_name",
        'f',
        "#version 330\n#define 3 4\nvoid main(){}\n",
    ),
    (
        "macro_bad_params",
        'f',
        "#version 330\n#define A(x x\nvoid main(){}\n",
    ),
    (
        "macro_dup_params",
        'f',
        "#version 330\n#define A(x,x) x\nvoid main(){}\n",
    ),
    (
        "undef_gl",
        'f',
        "#version 330\n#undef GL_core_profile\nvoid main(){}\n",
    ),
    ("non_directive", 'f', "#version 330\n#foo\nvoid main(){}\n"),
    (
        "line_no_number",
        'f',
        "#version 330\n#line\nvoid main(){}\n",
    ),
    (
        "error_directive",
        'f',
        "#version 330\n#error hello   world\nvoid main(){}\n",
    ),
    (
        "error_in_taken_branch",
        'v',
        "#version 110\n#if __VERSION__ == 110\n#error old  version\n#endif\n",
    ),
    ("hash_in_text", 'f', "#version 330\nint a #;\n"),
    (
        "unterminated_comment",
        'f',
        "#version 330\nvoid main(){ /* \n",
    ),
    (
        "unterminated_comment_lines",
        'f',
        "#version 330\nvoid main(){}\n/* one\ntwo\n  three",
    ),
    ("version_late", 'f', "void main(){}\n#version 330\n"),
    (
        "version_twice",
        'f',
        "#version 330\n#version 330\nvoid main(){}\n",
    ),
    // #version and #extension (errors of Mesa's compiler, not glcpp).
    ("version_unknown", 'f', "#version 331\nvoid main(){}\n"),
    (
        "version_profile_early",
        'f',
        "#version 140 core\nvoid main(){}\n",
    ),
    (
        "version_bad_profile",
        'f',
        "#version 330 foo\nvoid main(){}\n",
    ),
    (
        "extension_unknown_require",
        'f',
        "#version 330\n#extension GL_FOO : require\nvoid main(){}\n",
    ),
    (
        "extension_all_require",
        'f',
        "#version 330\n#extension all : require\nvoid main(){}\n",
    ),
    (
        "extension_no_colon",
        'f',
        "#version 330\n#extension GL_ARB_explicit_attrib_location require\nvoid main(){}\n",
    ),
    (
        "extension_bad_behavior",
        'f',
        "#version 330\n#extension GL_ARB_explicit_attrib_location : bogus\nvoid main(){}\n",
    ),
    // Lexer: reserved words, literals, stray characters.
    (
        "reserved_input",
        'f',
        "#version 330\nvoid main(){ int input = 1; }\n",
    ),
    (
        "reserved_switch_110",
        'f',
        "#version 110\nvoid main(){ int switch = 1; }\n",
    ),
    (
        "reserved_precision_120",
        'f',
        "#version 120\nvoid main(){ float highp = 1.0; }\n",
    ),
    (
        "reserved_superp_130",
        'v',
        "#version 130\nfloat superp;\nvoid main(){}\n",
    ),
    (
        "reserved_image_150",
        'v',
        "#version 150\nuniform image2D img;\nvoid main(){}\n",
    ),
    ("reserved_dvec", 'f', "#version 330\ndvec3 d;\n"),
    (
        "literal_too_big",
        'f',
        "#version 330\nint a = 99999999999;\n",
    ),
    (
        "hex_no_digits",
        'f',
        "#version 330\nvoid main(){ int a = 0x; }\n",
    ),
    (
        "octal_nine",
        'f',
        "#version 330\nvoid main(){ int a = 09; }\n",
    ),
    (
        "at_sign",
        'f',
        "#version 330\nvoid main(){ int a = 1 @ 2; }\n",
    ),
    (
        "dollar",
        'f',
        "#version 330\nvoid main(){ int a = 1 $ 2; }\n",
    ),
    ("string_literal", 'f', "#version 330\nint a \"s\";\n"),
    ("backslash", 'f', "#version 330\nint a \\;\n"),
    // Syntax errors: declarations.
    (
        "missing_semicolon",
        'f',
        "#version 330\nvoid main(){ int x = 1 }\n",
    ),
    (
        "missing_init",
        'f',
        "#version 330\nvoid main(){ int x = ; }\n",
    ),
    (
        "eof_in_function",
        'f',
        "#version 330\nvoid main(){ int x = 1; \n",
    ),
    ("eof_after_brace", 'f', "#version 330\nvoid main(){\n"),
    ("eof_after_type", 'f', "#version 330\nint x = 1; int\n"),
    (
        "eof_after_blanks",
        'f',
        "#version 330\nint x = 1; int   \n\n",
    ),
    ("eof_no_newline", 'f', "#version 330\nint x = 1; int   "),
    ("stray_brace", 'f', "#version 330\n}\n"),
    ("stray_brace_indented", 'f', "#version 330\n   }\n"),
    ("two_names", 'f', "#version 330\nint b; int a b;\n"),
    ("type_after_name", 'f', "#version 330\nint a float;\n"),
    (
        "struct_name_after_name",
        'f',
        "#version 330\nstruct S { int x; };\nint a S;\n",
    ),
    (
        "empty_struct",
        'f',
        "#version 330\nstruct S { };\nvoid main(){}\n",
    ),
    (
        "struct_missing_semicolon",
        'f',
        "#version 330\nstruct S { int x; }\nvoid main(){}\n",
    ),
    (
        "struct_member_init",
        'v',
        "#version 330\nstruct S { int x = 1; };\n",
    ),
    (
        "block_missing_semicolon",
        'v',
        "#version 330\nuniform B { vec4 a; }\nvoid main(){}\n",
    ),
    ("layout_empty", 'v', "#version 330\nlayout() in vec4 p;\n"),
    (
        "layout_no_paren",
        'v',
        "#version 330\nlayout location = 0 in vec4 p;\n",
    ),
    (
        "layout_trailing_comma",
        'v',
        "#version 330\nlayout(location = 0,) in vec4 p;\n",
    ),
    ("precision_no_type", 'f', "#version 330\nprecision highp;\n"),
    (
        "precision_no_qualifier",
        'f',
        "#version 330\nprecision float;\n",
    ),
    (
        "param_missing_comma",
        'f',
        "#version 330\nvoid f(int a int b) {}\n",
    ),
    (
        "param_trailing_comma",
        'f',
        "#version 330\nvoid f(int a,) {}\n",
    ),
    (
        "function_in_function",
        'f',
        "#version 330\nvoid main() { void g() {} }\n",
    ),
    ("array_unclosed", 'f', "#version 330\nfloat a[3;\n"),
    ("keyword_as_name", 'f', "#version 330\nint a in;\n"),
    ("uniform_as_name", 'f', "#version 330\nint a uniform;\n"),
    ("layout_as_name_330", 'f', "#version 330\nint a layout;\n"),
    ("void_as_name", 'f', "#version 330\nint a void;\n"),
    ("for_as_name", 'f', "#version 330\nint a for;\n"),
    ("flat_as_name", 'f', "#version 330\nint a flat;\n"),
    ("invariant_as_name", 'f', "#version 330\nint a invariant;\n"),
    // Syntax errors: expressions.
    ("binary_no_rhs", 'f', "#version 330\nint x = 1 + }\n"),
    ("binary_no_rhs_tight", 'f', "#version 330\nint x = 1+}\n"),
    (
        "paren_expr_then_brace",
        'f',
        "#version 330\nint x = (1+2) }\n",
    ),
    ("call_then_brace", 'f', "#version 330\nint x = f(1,2) }\n"),
    ("field_then_brace", 'f', "#version 330\nint x = y.z }\n"),
    ("index_then_brace", 'f', "#version 330\nint x = y[2] }\n"),
    ("tab_indent", 'f', "#version 330\n\tint x }\n"),
    ("comment_in_line", 'f', "#version 330\nint x /* c */ }\n"),
    (
        "comment_spanning_lines",
        'f',
        "#version 330\nint a /* x\n y */ b;\n",
    ),
    ("line_comment", 'f', "#version 330\nint x // c\n }\n"),
    (
        "macro_expansion_error",
        'f',
        "#version 330\n#define A 1 2\nint   x = A;\n",
    ),
    (
        "macro_call_spanning_lines",
        'f',
        "#version 330\n#define F(x,y) x\nint a = F(1,\n 2) 3;\n",
    ),
    (
        "line_directive",
        'f',
        "#version 330\n#line 20 5\nint a 1;\n",
    ),
    (
        "line_directive_hex",
        'f',
        "#version 330\n#line 0x10\nint a 1;\n",
    ),
    (
        "continuation",
        'f',
        "#version 330\nint a = 1 \\\n + 2 3;\nvoid main(){}\n",
    ),
    (
        "continuation_next_line",
        'f',
        "#version 330\n#define A 1 \\\n  + 1\nint a = A;\nint b c;\n",
    ),
    (
        "unclosed_call",
        'f',
        "#version 330\nvoid main(){ float x = max(1.0, 2.0; }\n",
    ),
    (
        "unclosed_paren",
        'f',
        "#version 330\nvoid main(){ float x = (1.0 + 2.0; }\n",
    ),
    (
        "unclosed_index",
        'f',
        "#version 330\nvoid main(){ float a[2]; float x = a[1; }\n",
    ),
    (
        "ternary_no_colon",
        'f',
        "#version 330\nvoid main(){ float x = true ? 1.0 ; }\n",
    ),
    (
        "double_operator",
        'f',
        "#version 330\nvoid main(){ float x = 1.0 * / 2.0; }\n",
    ),
    (
        "assign_to_sum",
        'f',
        "#version 330\nvoid main(){ float a, b; a + b = 1.0; }\n",
    ),
    (
        "dot_number",
        'f',
        "#version 330\nvoid main(){ vec4 v; float x = v.1; }\n",
    ),
    (
        "constructor_no_args_paren",
        'f',
        "#version 330\nvoid main(){ vec4 v = vec4; }\n",
    ),
    (
        "array_ctor_no_paren",
        'f',
        "#version 330\nvoid main(){ float a[2] = float[2]; }\n",
    ),
    (
        "postfix_on_type",
        'f',
        "#version 330\nvoid main(){ float++; }\n",
    ),
    // Syntax errors: statements.
    (
        "if_no_paren",
        'f',
        "#version 330\nvoid main(){ if true {} }\n",
    ),
    (
        "if_unclosed",
        'f',
        "#version 330\nvoid main(){ if (true {} }\n",
    ),
    (
        "else_alone_stmt",
        'f',
        "#version 330\nvoid main(){ else {} }\n",
    ),
    (
        "for_missing_semicolon",
        'f',
        "#version 330\nvoid main(){ for (int i = 0 i < 3; i++) {} }\n",
    ),
    (
        "for_too_many_parts",
        'f',
        "#version 330\nvoid main(){ for (int i = 0; i < 3; i++; ) {} }\n",
    ),
    (
        "while_no_paren",
        'f',
        "#version 330\nvoid main(){ while 1 {} }\n",
    ),
    (
        "do_no_while",
        'f',
        "#version 330\nvoid main(){ do {} (true); }\n",
    ),
    (
        "do_no_semicolon",
        'f',
        "#version 330\nvoid main(){ do {} while (false) }\n",
    ),
    (
        "return_no_semicolon",
        'f',
        "#version 330\nfloat f(){ return 1.0 }\n",
    ),
    (
        "break_no_semicolon",
        'f',
        "#version 330\nvoid main(){ for(;;) { break } }\n",
    ),
    (
        "discard_no_semicolon",
        'f',
        "#version 330\nvoid main(){ discard }\n",
    ),
    (
        "case_no_colon",
        'f',
        "#version 330\nvoid main(){ switch (1) { case 1 break; } }\n",
    ),
    (
        "default_no_colon",
        'f',
        "#version 330\nvoid main(){ switch (1) { default break; } }\n",
    ),
    (
        "switch_no_brace",
        'f',
        "#version 330\nvoid main(){ switch (1) case 1: ; }\n",
    ),
    (
        "switch_in_110",
        'f',
        "#version 110\nvoid main(){ switch (1) { } }\n",
    ),
    ("unbalanced_braces", 'f', "#version 330\nvoid main(){ { }\n"),
    ("statement_at_file_scope", 'f', "#version 330\nx = 1;\n"),
    ("return_at_file_scope", 'f', "#version 330\nreturn;\n"),
    ("uint_in_110", 'v', "#version 110\nuint u;\n"),
    ("flat_in_120", 'v', "#version 120\nflat varying float f;\n"),
    (
        "layout_in_130",
        'v',
        "#version 130\nlayout(location = 0) in vec4 p;\n",
    ),
    ("mat2x3_in_110", 'v', "#version 110\nuniform mat2x3 m;\n"),
    (
        "sampler2DMS_in_140",
        'f',
        "#version 140\nuniform sampler2DMS s;\n",
    ),
];

#[test]
fn errors_match_mesa() {
    let jobs: Vec<Job> = CASES
        .iter()
        .map(|&(_, st, src)| {
            if st == 'v' {
                Job::Vertex(src)
            } else {
                Job::Fragment(src)
            }
        })
        .collect();
    let mesa = run(Context::Compat, &jobs);
    let mut failures = Vec::new();
    let mut agree_col = 0;
    for (&(name, st, src), m) in CASES.iter().zip(&mesa) {
        let stage = if st == 'v' {
            Stage::Vertex
        } else {
            Stage::Fragment
        };
        assert!(!m.ok, "{name}: Mesa accepts it, so it does not belong here");
        let Some(theirs) = mesa_first_error(&m.log) else {
            failures.push(format!("{name}: no error line in Mesa's log {:?}", m.log));
            continue;
        };
        let (tree, log) = parse_with_log(&[src], stage);
        let Some(ours) = our_first_error(&log) else {
            failures.push(format!("{name}: we accept it (tree: {})", tree.is_some()));
            continue;
        };
        let line = |p: &str| p.split('(').next().unwrap_or("").to_string();
        let ok = line(&ours.0) == line(&theirs.0)
            && ours.1 == theirs.1
            && if ours.2.starts_with("syntax error, unexpected ") {
                theirs.2.starts_with(&ours.2)
            } else {
                ours.2 == theirs.2.trim_end()
                    || (ours.2.starts_with("GLSL ") && theirs.2.starts_with(&ours.2[..20]))
            };
        if !ok {
            failures.push(format!("{name}: ours {ours:?}, Mesa's {theirs:?}"));
        } else if ours.0 == theirs.0 {
            agree_col += 1;
        } else {
            println!(
                "{name}: column differs: ours {}, Mesa's {}",
                ours.0, theirs.0
            );
        }
    }
    println!(
        "{} error cases; {} agree with Mesa on the line and message, {} also on the column",
        CASES.len(),
        CASES.len() - failures.len(),
        agree_col
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
