//! The error corpus: shaders with preprocessor or syntax errors that Mesa rejects.
//! For each, our first error must be on Mesa's line; preprocessor errors must read as
//! Mesa's word for word, and syntax errors must start as Mesa's does
//! (`syntax error, unexpected X`, Mesa's `expecting …` list aside) at Mesa's column.
//! The shaders are in `tests/corpus/errors.txt`.

mod common;
mod mesa;

use common::{mesa_first_error, our_first_error};
use mesa::{run, Context, Job};
use softgl_glsl::parse_with_log;

#[test]
fn errors_match_mesa() {
    let cases = common::error_cases();
    assert!(cases.len() >= 140, "{} cases", cases.len());
    let jobs = common::jobs(&cases, Job::Vertex, Job::Fragment);
    let mesa = run(Context::Compat, &jobs);
    let mut failures = Vec::new();
    let mut agree_col = 0;
    for ((name, stage, src), m) in cases.iter().zip(&mesa) {
        let stage = *stage;
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
        let ok = common::agrees(&ours, &theirs);
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
        cases.len(),
        cases.len() - failures.len(),
        agree_col
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        agree_col * 100 >= cases.len() * 98,
        "columns agree in {agree_col}"
    );
}
