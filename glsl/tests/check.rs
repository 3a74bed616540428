//! The type checker against Mesa: the valid corpus checks clean, and the type-error
//! corpus (`tests/corpus/type_errors.txt`) is accepted or rejected as Mesa does, with
//! the first error on Mesa's line; the test prints how many messages agree word for
//! word.

mod common;
mod mesa;

use common::{mesa_first_error, our_first_error};
use softgl_glsl::compile_with_log;

#[test]
fn valid_corpus_checks() {
    let corpus = common::corpus("valid");
    for (name, stage, src) in &corpus {
        let (p, log) = compile_with_log(&[src], *stage);
        assert!(p.is_some(), "{name} rejected:\n{log}");
    }
    println!("{} valid shaders check clean", corpus.len());
}

#[test]
fn type_errors_agree_with_mesa() {
    let cases = common::cases_from("type_errors.txt");
    assert!(cases.len() >= 150, "{} cases", cases.len());
    let mesa = mesa::verdicts(&cases);
    let (mut bad, mut same_text, mut errors) = (Vec::new(), 0, 0);
    for ((name, stage, src), (ok, log)) in cases.iter().zip(&mesa) {
        let theirs = &mesa_first_error(log);
        let (p, log) = compile_with_log(&[src], *stage);
        let ours = our_first_error(&log);
        if p.is_some() != *ok {
            bad.push(format!(
                "{name}: Mesa {ok}, ours {}: {theirs:?} / {ours:?}",
                p.is_some()
            ));
            continue;
        }
        if let (Some(o), Some(t)) = (&ours, theirs) {
            errors += 1;
            let line = |p: &str| p.split('(').next().unwrap_or("").to_string();
            if line(&o.0) != line(&t.0) {
                bad.push(format!(
                    "{name}: line {} vs Mesa {}: {} / {}",
                    o.0, t.0, o.2, t.2
                ));
            } else if o.2 == t.2.trim_end()
                || (o.2.starts_with("syntax error") && t.2.starts_with(&o.2))
            {
                same_text += 1;
            } else {
                println!("{name}: text differs: ours `{}`, Mesa `{}`", o.2, t.2);
            }
        }
    }
    println!(
        "{} cases, {} rejected; {same_text} of {errors} first errors word for word as Mesa's",
        cases.len(),
        errors
    );
    assert!(
        bad.is_empty(),
        "{} disagreements:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
