//! Checks the reference harness itself: Mesa accepts a valid shader pair and links it,
//! and rejects a type error with its line and column.

mod mesa;
use mesa::{run, Context, Job};

#[test]
fn mesa_accepts_and_rejects() {
    let vs = "#version 330\nin vec4 p;\nvoid main() { gl_Position = p; }\n";
    let fs = "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    let bad = "#version 330\nout vec4 c;\nvoid main() { c = 1.0; }\n";
    let r = run(
        Context::Core33,
        &[
            Job::Vertex(vs),
            Job::Fragment(fs),
            Job::Link,
            Job::Fragment(bad),
        ],
    );
    assert!(r[0].ok && r[1].ok && r[2].ok, "{r:?}");
    assert!(!r[3].ok);
    assert_eq!(
        r[3].log,
        "0:3(15): error: value of type float cannot be assigned to variable of type vec4\n"
    );
    let old = "#version 110\nvoid main() { gl_FragColor = gl_Color; }\n";
    let r = run(Context::Compat, &[Job::Fragment(old)]);
    assert!(r[0].ok, "{r:?}");
}
