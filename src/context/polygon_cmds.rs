//! glPolygonMode, glPolygonStipple and glGetPolygonStipple on the rasterization state.

use super::raster_state::FillMode;
use super::state::Face;
use super::{Context, GlResult};

/// Reads the 32x32 stipple from 128 bytes (rows bottom-up, 4 bytes each).
fn stipple_from_bytes(b: &[u8; 128], lsb_first: bool) -> [u32; 32] {
    std::array::from_fn(|r| {
        let mut row = [b[4 * r], b[4 * r + 1], b[4 * r + 2], b[4 * r + 3]];
        if lsb_first {
            row = row.map(u8::reverse_bits);
        }
        u32::from_be_bytes(row)
    })
}

impl Context {
    /// glPolygonMode on the faces `face` names.
    pub(crate) fn polygon_mode(&mut self, face: Face, mode: FillMode) {
        let p = &mut self.raster.polygon;
        if face != Face::Back {
            p.mode_front = mode;
        }
        if face != Face::Front {
            p.mode_back = mode;
        }
    }

    /// glPolygonStipple from the client's 128 bytes (honours GL_UNPACK_LSB_FIRST; `None`
    /// for a NULL mask, which is ignored).
    pub(crate) fn polygon_stipple(&mut self, bytes: Option<&[u8; 128]>) -> GlResult<()> {
        if let Some(b) = bytes {
            self.raster.stipple.0 = stipple_from_bytes(b, self.state.unpack.lsb_first);
        }
        Ok(())
    }

    /// glGetPolygonStipple's 32 rows of 4 bytes (honours GL_PACK_LSB_FIRST).
    pub(crate) fn polygon_stipple_rows(&self) -> [[u8; 4]; 32] {
        let lsb = self.state.pack.lsb_first;
        self.raster.stipple.0.map(|r| {
            let b = r.to_be_bytes();
            if lsb {
                b.map(u8::reverse_bits)
            } else {
                b
            }
        })
    }
}
