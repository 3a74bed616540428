//! 4x4 matrices and matrix stacks, with Mesa's exact f32 operation order.
//!
//! Matrices are column-major (`m[col * 4 + row]`), as GL stores them. Every operation uses
//! the evaluation order of Mesa's `math/m_matrix.c`, because the reference rounds each f32
//! multiply and add separately and a different order changes the last bit of a vertex.

use super::mesa_matrix::MatFlags;

/// A column-major 4x4 f32 matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat4(pub [f32; 16]);

/// The identity matrix.
pub const IDENTITY: Mat4 = Mat4([
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
]);

impl Default for Mat4 {
    fn default() -> Self {
        IDENTITY
    }
}

impl Mat4 {
    /// Element at `row`, `col`.
    #[inline]
    pub fn at(&self, row: usize, col: usize) -> f32 {
        self.0[col * 4 + row]
    }

    /// `self * b`, summed left to right as Mesa's `matmul4` does.
    pub fn mul(&self, b: &Mat4) -> Mat4 {
        let mut p = [0f32; 16];
        for i in 0..4 {
            let (ai0, ai1, ai2, ai3) = (self.at(i, 0), self.at(i, 1), self.at(i, 2), self.at(i, 3));
            for j in 0..4 {
                p[j * 4 + i] =
                    ai0 * b.at(0, j) + ai1 * b.at(1, j) + ai2 * b.at(2, j) + ai3 * b.at(3, j);
            }
        }
        Mat4(p)
    }

    /// The transpose (for glLoadTransposeMatrix).
    pub fn transpose(&self) -> Mat4 {
        let mut t = [0f32; 16];
        for r in 0..4 {
            for c in 0..4 {
                t[r * 4 + c] = self.0[c * 4 + r];
            }
        }
        Mat4(t)
    }

    /// glTranslate: updates column 3 in place, left to right.
    #[allow(clippy::assign_op_pattern)] // `m12 += …` would add in another order
    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        let m = &mut self.0;
        for r in 0..4 {
            m[12 + r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
        }
    }

    /// glScale: multiplies columns 0-2 in place.
    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        let m = &mut self.0;
        for r in 0..4 {
            m[r] *= x;
            m[4 + r] *= y;
            m[8 + r] *= z;
        }
    }

    /// glRotate (degrees), with Mesa's single-axis shortcuts and axis normalisation.
    /// Returns whether the matrix was multiplied (false for a degenerate axis).
    pub fn rotate(&mut self, angle: f32, x: f32, y: f32, z: f32) -> bool {
        let rad = (angle as f64 * std::f64::consts::PI / 180.0) as f32;
        let (s, c) = (rad.sin(), rad.cos());
        let mut m = IDENTITY.0;
        let set = |m: &mut [f32; 16], r: usize, col: usize, v: f32| m[col * 4 + r] = v;
        // Mesa's shortcut for a rotation about a coordinate axis: the plane of axes `i`
        // and `j`, turned the other way when the axis is negative.
        let plane = |m: &mut [f32; 16], i: usize, j: usize, negative: bool| {
            set(m, i, i, c);
            set(m, j, j, c);
            let (a, b) = if negative { (s, -s) } else { (-s, s) };
            set(m, i, j, a);
            set(m, j, i, b);
        };
        let optimized = if x == 0.0 && y == 0.0 && z != 0.0 {
            plane(&mut m, 0, 1, z < 0.0);
            true
        } else if x == 0.0 && y != 0.0 && z == 0.0 {
            plane(&mut m, 2, 0, y < 0.0);
            true
        } else if x != 0.0 && y == 0.0 && z == 0.0 {
            plane(&mut m, 1, 2, x < 0.0);
            true
        } else {
            false
        };
        if !optimized {
            let mag = (x * x + y * y + z * z).sqrt();
            if mag <= 1.0e-4 || mag.is_nan() {
                return false;
            }
            let (x, y, z) = (x / mag, y / mag, z / mag);
            let (xx, yy, zz) = (x * x, y * y, z * z);
            let (xy, yz, zx) = (x * y, y * z, z * x);
            let (xs, ys, zs) = (x * s, y * s, z * s);
            let one_c = 1.0 - c;
            set(&mut m, 0, 0, one_c * xx + c);
            set(&mut m, 0, 1, one_c * xy - zs);
            set(&mut m, 0, 2, one_c * zx + ys);
            set(&mut m, 1, 0, one_c * xy + zs);
            set(&mut m, 1, 1, one_c * yy + c);
            set(&mut m, 1, 2, one_c * yz - xs);
            set(&mut m, 2, 0, one_c * zx - ys);
            set(&mut m, 2, 1, one_c * yz + xs);
            set(&mut m, 2, 2, one_c * zz + c);
        }
        *self = self.mul(&Mat4(m));
        true
    }

    /// The glFrustum matrix (arguments already converted to f32).
    pub fn frustum(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
        let x = (2.0 * n) / (r - l);
        let y = (2.0 * n) / (t - b);
        let a = (r + l) / (r - l);
        let bb = (t + b) / (t - b);
        let c = -(f + n) / (f - n);
        let d = -(2.0 * f * n) / (f - n);
        Mat4([
            x, 0.0, 0.0, 0.0, 0.0, y, 0.0, 0.0, a, bb, c, -1.0, 0.0, 0.0, d, 0.0,
        ])
    }

    /// The glOrtho matrix (arguments already converted to f32).
    pub fn ortho(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
        let mut m = IDENTITY.0;
        m[0] = 2.0 / (r - l);
        m[12] = -(r + l) / (r - l);
        m[5] = 2.0 / (t - b);
        m[13] = -(t + b) / (t - b);
        m[10] = -2.0 / (f - n);
        m[14] = -(f + n) / (f - n);
        Mat4(m)
    }

    /// `M * v` as Mesa's fixed-function vertex program computes it:
    /// `((vx·C0 + vy·C1) + vz·C2) + vw·C3`, every product and sum rounded to f32.
    #[inline]
    pub fn transform(&self, v: [f32; 4]) -> [f32; 4] {
        let m = &self.0;
        let mut o = [0f32; 4];
        for (r, out) in o.iter_mut().enumerate() {
            *out = v[0] * m[r] + v[1] * m[4 + r] + v[2] * m[8 + r] + v[3] * m[12 + r];
        }
        o
    }
}

/// A matrix stack with a fixed maximum depth (GL_MAX_*_STACK_DEPTH). Each entry also
/// carries Mesa's matrix flags, which choose the inverse routine lighting uses.
#[derive(Clone, Debug)]
pub struct MatrixStack {
    stack: Vec<Mat4>,
    flags: Vec<MatFlags>,
    max_depth: usize,
}

impl MatrixStack {
    /// A stack holding the identity, allowing `max_depth` entries.
    pub fn new(max_depth: usize) -> Self {
        MatrixStack {
            stack: vec![IDENTITY],
            flags: vec![MatFlags::IDENTITY],
            max_depth,
        }
    }
    /// The top matrix.
    #[inline]
    pub fn top(&self) -> &Mat4 {
        self.stack.last().expect("a matrix stack is never empty")
    }
    /// The top matrix, for modification.
    #[inline]
    pub fn top_mut(&mut self) -> &mut Mat4 {
        self.stack
            .last_mut()
            .expect("a matrix stack is never empty")
    }
    /// The top matrix's Mesa flags.
    pub fn top_flags(&self) -> MatFlags {
        self.flags.last().copied().unwrap_or(MatFlags::IDENTITY)
    }
    /// The top matrix and its flags, for modification.
    pub fn top_both_mut(&mut self) -> (&mut Mat4, &mut MatFlags) {
        let m = self
            .stack
            .last_mut()
            .expect("a matrix stack is never empty");
        let f = self
            .flags
            .last_mut()
            .expect("a matrix stack is never empty");
        (m, f)
    }
    /// Pushes a copy of the top; `false` (and nothing changes) when the stack is full.
    pub fn push(&mut self) -> bool {
        if self.stack.len() >= self.max_depth {
            return false;
        }
        let top = *self.top();
        self.stack.push(top);
        self.flags.push(self.top_flags());
        true
    }
    /// Pops the top; `false` (and nothing changes) when only one entry is left.
    pub fn pop(&mut self) -> bool {
        if self.stack.len() <= 1 {
            return false;
        }
        self.stack.pop();
        self.flags.pop();
        true
    }
    /// The number of entries (GL_*_STACK_DEPTH).
    pub fn depth(&self) -> usize {
        self.stack.len()
    }
    /// GL_MAX_*_STACK_DEPTH.
    pub fn max_depth(&self) -> usize {
        self.max_depth
    }
}

/// Plane `p` times the inverse of the stack's top matrix (Mesa's
/// `_mesa_transform_vector(u, p, inv)`): object to eye space with the modelview, eye to
/// clip space with the projection.
pub fn plane_times_inverse(modelview: &MatrixStack, p: [f32; 4]) -> [f32; 4] {
    let mut flags = modelview.top_flags();
    let m = flags.inverse(&modelview.top().0);
    std::array::from_fn(|i| {
        p[0] * m[i * 4] + p[1] * m[i * 4 + 1] + p[2] * m[i * 4 + 2] + p[3] * m[i * 4 + 3]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn translate_then_transform_moves_origin() {
        let mut m = IDENTITY;
        m.translate(1.5, -2.0, 3.0);
        assert_eq!(m.transform([0.0, 0.0, 0.0, 1.0]), [1.5, -2.0, 3.0, 1.0]);
    }

    #[test]
    fn rotate_z_90_maps_x_to_y() {
        let mut m = IDENTITY;
        m.rotate(90.0, 0.0, 0.0, 1.0);
        let v = m.transform([1.0, 0.0, 0.0, 1.0]);
        assert!((v[0]).abs() < 1e-7 && (v[1] - 1.0).abs() < 1e-7, "{v:?}");
    }

    #[test]
    fn axis_shortcuts_agree_with_the_general_rotation() {
        // A tiny off-axis component takes the general path; each signed coordinate axis
        // the shortcut.
        for axis in [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            for sign in [1.0f32, -1.0] {
                let [x, y, z] = axis.map(|a| a * sign);
                let (mut fast, mut general) = (IDENTITY, IDENTITY);
                fast.rotate(30.0, x, y, z);
                general.rotate(30.0, x + 1e-9, y + 1e-9, z + 1e-9);
                for i in 0..16 {
                    assert!((fast.0[i] - general.0[i]).abs() < 1e-6, "{axis:?} {sign}");
                }
            }
        }
    }

    #[test]
    fn stack_limits() {
        let mut s = MatrixStack::new(2);
        assert!(!s.pop());
        assert!(s.push());
        assert!(!s.push());
        assert_eq!(s.depth(), 2);
    }

    #[test]
    fn general_axis_rotation_is_orthonormal() {
        let mut m = IDENTITY;
        m.rotate(33.0, 1.0, 2.0, 3.0);
        let p = m.mul(&m.transpose());
        for r in 0..4 {
            for c in 0..4 {
                let e = if r == c { 1.0 } else { 0.0 };
                assert!((p.at(r, c) - e).abs() < 1e-6);
            }
        }
    }
}
