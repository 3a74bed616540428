//! Prints the instruction-set levels this CPU can run (`SOFTGL_ISA` values, lowest
//! first, one line), for `scripts/test.sh`, which runs the comparisons under each.

fn main() {
    let names: Vec<&str> = softgl::cpu::supported_levels()
        .into_iter()
        .map(|l| l.name())
        .collect();
    println!("{}", names.join(" "));
}
