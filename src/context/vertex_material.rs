//! glMaterial between glBegin and glEnd: Mesa's vbo module treats the material terms as
//! per-vertex attributes, so each vertex is lit with the material current when it was
//! given, not the one current at glEnd. Once a batch sees such a call, every vertex of it
//! carries a snapshot of both faces' materials (vertices before the call get the material
//! they were given with), and the draw lights each vertex with its own.

use super::error::GlResult;
use super::lighting_state::Material;
use super::Context;

impl Context {
    /// Appends an immediate-mode vertex (inside glBegin/glEnd) and, when the batch has
    /// per-vertex materials or generic attributes, those it is given with.
    #[inline]
    pub fn push_immediate_vertex(&mut self, pos: [f32; 4]) -> GlResult<()> {
        let im = &mut self.immediate;
        im.verts.push_current(pos, &self.state.current)?;
        if im.generic_inside {
            im.verts.push_generic(&self.generic_current)?;
        }
        if im.per_vertex_material {
            im.materials.push(self.light.material);
        }
        Ok(())
    }

    /// Called before a glMaterial changes the material: inside glBegin/glEnd it switches
    /// the batch to per-vertex materials, giving the vertices so far the material they
    /// were specified with.
    pub fn material_changing(&mut self) {
        let im = &mut self.immediate;
        if im.active.is_none() || im.per_vertex_material {
            return;
        }
        im.per_vertex_material = true;
        im.materials.clear();
        im.materials.resize(im.verts.len(), self.light.material);
    }

    /// Takes the per-vertex materials of the batch being drawn (one per vertex), leaving
    /// the batch without them.
    pub fn take_vertex_materials(&mut self) -> Option<Vec<[Material; 2]>> {
        let im = &mut self.immediate;
        let on = std::mem::replace(&mut im.per_vertex_material, false);
        let m = std::mem::take(&mut im.materials);
        (on && m.len() == im.verts.len()).then_some(m)
    }
}
