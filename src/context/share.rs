//! Objects that OSMesa contexts created with a `sharelist` share: texture objects, buffer
//! objects, display lists, shader and program objects, and (as in Mesa 22.3) framebuffer and renderbuffer objects
//! (GL's share group). The bindings stay each context's own.
//!
//! The tables live in one [`ShareGroup`] per group. A context that becomes current on a
//! thread checks the tables out into its own state (so the drawing code reads them as plain
//! fields, without locks), and checks them back in when it stops being current. Contexts of
//! one group are therefore meant to be current on one thread at a time; a second context of
//! the group made current while the tables are out works on empty tables until they return.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use super::arrays::BufferObject;
use super::Context;
use crate::texture::TextureObject;

/// The tables of one share group.
#[derive(Default)]
pub struct SharedObjects {
    /// Named texture objects.
    pub textures: HashMap<u32, TextureObject>,
    /// The next name glGenTextures tries.
    pub next_texture: u32,
    /// Buffer objects by name.
    pub buffers: HashMap<u32, Option<BufferObject>>,
    /// Display lists and their names.
    pub lists: super::dlist::ListTable,
    /// Framebuffer and renderbuffer objects and their names.
    pub fbo: super::fbo::FboTables,
    /// Shader and program objects.
    pub shaders: super::shader_objects::ShaderTable,
}

/// A share group: the tables, while no context of the group has them checked out.
#[derive(Clone, Default)]
pub struct ShareGroup(Arc<Mutex<Option<SharedObjects>>>);

impl ShareGroup {
    /// Moves the group's tables into `c` (if they are in the group).
    pub fn check_out(&self, c: &mut Context) {
        let Ok(mut g) = self.0.lock() else { return };
        if let Some(s) = g.take() {
            c.textures.objects = s.textures;
            c.textures.next_name = s.next_texture;
            c.arrays.buffers = s.buffers;
            c.lists.put_table(s.lists);
            c.fbo.put_tables(s.fbo);
            c.shaders.table = s.shaders;
            c.fbo_check_out();
        }
    }

    /// Moves `c`'s tables back into the group (when the group does not hold any).
    pub fn check_in(&self, c: &mut Context) {
        // A draw still on the pool may be reading the tables' texture images.
        c.settle_draws();
        let Ok(mut g) = self.0.lock() else { return };
        if g.is_none() {
            c.fbo_check_in();
            *g = Some(SharedObjects {
                textures: std::mem::take(&mut c.textures.objects),
                next_texture: std::mem::replace(&mut c.textures.next_name, 1),
                buffers: std::mem::take(&mut c.arrays.buffers),
                lists: c.lists.take_table(),
                fbo: c.fbo.take_tables(),
                shaders: std::mem::take(&mut c.shaders.table),
            });
        }
    }
}
