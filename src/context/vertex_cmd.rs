//! Per-vertex commands as the C boundary hands them over: recorded into the vertex node
//! of the display list being compiled (run too under GL_COMPILE_AND_EXECUTE), or run now;
//! and glArrayElement, the per-vertex commands of one element of the enabled arrays.

use super::dlist::VertexOp;
use super::{Context, GlResult};

impl Context {
    /// Runs or records one per-vertex command.
    pub(crate) fn vertex_command(&mut self, op: VertexOp) -> GlResult<()> {
        match self.lists.compile_mode() {
            None => self.vertex_op(op),
            Some(execute) => {
                self.lists.push_op(op);
                if execute {
                    self.vertex_op(op)
                } else {
                    Ok(())
                }
            }
        }
    }

    /// glArrayElement: the per-vertex commands of element `i`, each run or recorded (in a
    /// display list the arrays are read at compile time); an error of one is recorded and
    /// the rest still run, as separate commands.
    pub(crate) fn array_element(&mut self, i: u32) {
        let mut ops = Vec::new();
        self.array_element_ops(i, &mut ops);
        for op in ops {
            if let Err(e) = self.vertex_command(op) {
                self.record_error(e);
            }
        }
    }
}
