//! Mesa's matrix classification and inverse (`math/m_matrix.c` and `util_invert_mat4x4`),
//! with the exact f32 operation order.
//!
//! Mesa inverts the modelview with one of several routines chosen by the matrix *type*,
//! and the type comes from flags that each matrix call ORs in (glRotate → ROTATION,
//! glScale → UNIFORM/GENERAL_SCALE, glLoadMatrix → "analyse from scratch", …). The same
//! matrix can therefore have bit-different inverses depending on how it was built. The
//! lighting needs that inverse: its transpose transforms normals, its column 2 gives the
//! GL_RESCALE_NORMAL factor, and object-space lighting transforms light positions by it.
//!
//! [`MatFlags`] reproduces the flag bookkeeping; a matrix stack that calls its `on_*`
//! hooks gets Mesa's exact inverse from [`MatFlags::inverse`]. Without that bookkeeping,
//! [`MatFlags::from_scratch`] classifies the matrix by its contents, which is what Mesa
//! does after glLoadMatrix/glMultMatrix and usually agrees.

/// General (perspective, shear …).
pub const MAT_FLAG_GENERAL: u32 = 0x1;
/// A rotation.
pub const MAT_FLAG_ROTATION: u32 = 0x2;
/// A translation.
pub const MAT_FLAG_TRANSLATION: u32 = 0x4;
/// A uniform scale.
pub const MAT_FLAG_UNIFORM_SCALE: u32 = 0x8;
/// A non-uniform scale.
pub const MAT_FLAG_GENERAL_SCALE: u32 = 0x10;
/// A general 3D (affine) matrix.
pub const MAT_FLAG_GENERAL_3D: u32 = 0x20;
/// A perspective projection.
pub const MAT_FLAG_PERSPECTIVE: u32 = 0x40;
/// Singular.
pub const MAT_FLAG_SINGULAR: u32 = 0x80;
/// The type must be recomputed.
pub const MAT_DIRTY_TYPE: u32 = 0x100;
/// The flags must be recomputed from the contents.
pub const MAT_DIRTY_FLAGS: u32 = 0x200;
/// The inverse must be recomputed.
pub const MAT_DIRTY_INVERSE: u32 = 0x400;

const ANGLE_PRESERVING: u32 = MAT_FLAG_ROTATION | MAT_FLAG_TRANSLATION | MAT_FLAG_UNIFORM_SCALE;
const GEOMETRY: u32 = 0xFF;
const LENGTH_PRESERVING: u32 = MAT_FLAG_ROTATION | MAT_FLAG_TRANSLATION;
const FLAGS_3D: u32 = MAT_FLAG_ROTATION
    | MAT_FLAG_TRANSLATION
    | MAT_FLAG_UNIFORM_SCALE
    | MAT_FLAG_GENERAL_SCALE
    | MAT_FLAG_GENERAL_3D;
const DIRTY: u32 = MAT_DIRTY_TYPE | MAT_DIRTY_FLAGS | MAT_DIRTY_INVERSE;

const IDENTITY: [f32; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// Mesa's `GLmatrixtype`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MatrixType {
    /// MATRIX_GENERAL
    General,
    /// MATRIX_IDENTITY
    #[default]
    Identity,
    /// MATRIX_3D_NO_ROT
    NoRot3D,
    /// MATRIX_PERSPECTIVE
    Perspective,
    /// MATRIX_2D
    TwoD,
    /// MATRIX_2D_NO_ROT
    NoRot2D,
    /// MATRIX_3D
    ThreeD,
}

/// A matrix's flags and type as Mesa keeps them (`GLmatrix::flags`, `GLmatrix::type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct MatFlags {
    /// MAT_FLAG_* and MAT_DIRTY_* bits.
    pub flags: u32,
    /// The type of the last analysis.
    pub ty: MatrixType,
}

/// `TEST_MAT_FLAGS`: all geometry flags lie within `mask`.
#[inline]
fn test(flags: u32, mask: u32) -> bool {
    (GEOMETRY & !mask & flags) == 0
}

impl MatFlags {
    /// A freshly constructed (identity) matrix.
    pub const IDENTITY: MatFlags = MatFlags {
        flags: 0,
        ty: MatrixType::Identity,
    };

    /// Flags for a matrix whose history is unknown: analysed from its contents.
    pub fn from_scratch(m: &[f32; 16]) -> MatFlags {
        let mut f = MatFlags {
            flags: MAT_FLAG_GENERAL | DIRTY,
            ty: MatrixType::General,
        };
        f.analyse(m);
        f
    }

    /// glLoadIdentity (`_math_matrix_set_identity`: geometry flags are kept).
    pub fn on_load_identity(&mut self) {
        self.ty = MatrixType::Identity;
        self.flags &= !(MAT_DIRTY_FLAGS | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE);
    }
    /// glLoadMatrix (when the matrix differs from the current one).
    pub fn on_load(&mut self) {
        self.flags = MAT_FLAG_GENERAL | DIRTY;
    }
    /// glMultMatrix (not called by Mesa for an identity argument).
    pub fn on_mult(&mut self) {
        self.flags |= MAT_FLAG_GENERAL | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE | MAT_DIRTY_FLAGS;
    }
    /// `matrix_multf` with `flags` (glRotate, glOrtho, glFrustum). Returns whether Mesa
    /// multiplies with `matmul34` (both operands 3D) rather than `matmul4`.
    fn multf(&mut self, flags: u32) -> bool {
        self.flags |= flags | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
        test(self.flags, FLAGS_3D)
    }
    /// glRotate with a non-zero angle and an axis that is not degenerate.
    pub fn on_rotate(&mut self) -> bool {
        self.multf(MAT_FLAG_ROTATION)
    }
    /// glOrtho.
    pub fn on_ortho(&mut self) -> bool {
        self.multf(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_TRANSLATION)
    }
    /// glFrustum.
    pub fn on_frustum(&mut self) -> bool {
        self.multf(MAT_FLAG_PERSPECTIVE)
    }
    /// glScale.
    pub fn on_scale(&mut self, x: f32, y: f32, z: f32) {
        if (x - y).abs() < 1e-8 && (x - z).abs() < 1e-8 {
            self.flags |= MAT_FLAG_UNIFORM_SCALE;
        } else {
            self.flags |= MAT_FLAG_GENERAL_SCALE;
        }
        self.flags |= MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
    }
    /// glTranslate.
    pub fn on_translate(&mut self) {
        self.flags |= MAT_FLAG_TRANSLATION | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
    }

    /// `_math_matrix_is_length_preserving` (meaningful after [`MatFlags::analyse`]).
    pub fn is_length_preserving(&self) -> bool {
        test(self.flags, LENGTH_PRESERVING)
    }

    /// `_math_matrix_analyse` without the inverse: updates the type (and, when the flags are
    /// dirty, the flags from the contents).
    pub fn analyse(&mut self, m: &[f32; 16]) {
        if self.flags & MAT_DIRTY_TYPE != 0 {
            if self.flags & MAT_DIRTY_FLAGS != 0 {
                self.analyse_from_scratch(m);
            } else {
                self.analyse_from_flags(m);
            }
        }
        self.flags &= !(MAT_DIRTY_FLAGS | MAT_DIRTY_TYPE);
    }

    /// `_math_matrix_analyse` followed by the inverse Mesa would store (identity when
    /// singular). Updates the flags (SINGULAR, dirty bits) as Mesa does.
    pub fn inverse(&mut self, m: &[f32; 16]) -> [f32; 16] {
        self.analyse(m);
        self.flags &= !MAT_DIRTY_INVERSE;
        match invert(m, self.ty, self.flags) {
            Some(inv) => {
                self.flags &= !MAT_FLAG_SINGULAR;
                inv
            }
            None => {
                self.flags |= MAT_FLAG_SINGULAR;
                IDENTITY
            }
        }
    }

    fn analyse_from_flags(&mut self, m: &[f32; 16]) {
        let f = self.flags;
        self.ty = if test(f, 0) {
            MatrixType::Identity
        } else if test(
            f,
            MAT_FLAG_TRANSLATION | MAT_FLAG_UNIFORM_SCALE | MAT_FLAG_GENERAL_SCALE,
        ) {
            if m[10] == 1.0 && m[14] == 0.0 {
                MatrixType::NoRot2D
            } else {
                MatrixType::NoRot3D
            }
        } else if test(f, FLAGS_3D) {
            if m[8] == 0.0
                && m[9] == 0.0
                && m[2] == 0.0
                && m[6] == 0.0
                && m[10] == 1.0
                && m[14] == 0.0
            {
                MatrixType::TwoD
            } else {
                MatrixType::ThreeD
            }
        } else if m[4] == 0.0
            && m[12] == 0.0
            && m[1] == 0.0
            && m[13] == 0.0
            && m[2] == 0.0
            && m[6] == 0.0
            && m[3] == 0.0
            && m[7] == 0.0
            && m[11] == -1.0
            && m[15] == 0.0
        {
            MatrixType::Perspective
        } else {
            MatrixType::General
        };
    }

    #[allow(clippy::identity_op)]
    fn analyse_from_scratch(&mut self, m: &[f32; 16]) {
        const fn zero(i: u32) -> u32 {
            1 << i
        }
        const fn one(i: u32) -> u32 {
            1 << (i + 16)
        }
        const MASK_NO_TRX: u32 = zero(12) | zero(13) | zero(14);
        const MASK_NO_2D_SCALE: u32 = one(0) | one(5);
        // The third row and column of the identity with a last column (0, 0, 0, 1): the
        // part the 2D masks share; MASK_3D is its last column.
        const MASK_3D: u32 = zero(3) | zero(7) | zero(11) | one(15);
        const Z_IDENTITY: u32 = zero(2) | zero(6) | one(10) | zero(14) | MASK_3D;
        const MASK_2D: u32 = zero(8) | zero(9) | Z_IDENTITY;
        const MASK_2D_NO_ROT: u32 = zero(4) | zero(1) | MASK_2D;
        const MASK_IDENTITY: u32 = one(0) | zero(12) | one(5) | zero(13) | MASK_2D_NO_ROT;
        const MASK_3D_NO_ROT: u32 =
            zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | MASK_3D;
        const MASK_PERSPECTIVE: u32 = zero(4)
            | zero(12)
            | zero(1)
            | zero(13)
            | zero(2)
            | zero(6)
            | zero(3)
            | zero(7)
            | zero(15);
        let sq = |x: f32| x * x;
        let eps2 = sq(1e-6f32);

        let mut mask = 0u32;
        for (i, &v) in m.iter().enumerate() {
            if v == 0.0 {
                mask |= 1 << i;
            }
        }
        if m[0] == 1.0 {
            mask |= 1 << 16;
        }
        if m[5] == 1.0 {
            mask |= 1 << 21;
        }
        if m[10] == 1.0 {
            mask |= 1 << 26;
        }
        if m[15] == 1.0 {
            mask |= 1 << 31;
        }
        self.flags &= !GEOMETRY;
        if mask & MASK_NO_TRX != MASK_NO_TRX {
            self.flags |= MAT_FLAG_TRANSLATION;
        }
        if mask == MASK_IDENTITY {
            self.ty = MatrixType::Identity;
        } else if mask & MASK_2D_NO_ROT == MASK_2D_NO_ROT {
            self.ty = MatrixType::NoRot2D;
            if mask & MASK_NO_2D_SCALE != MASK_NO_2D_SCALE {
                self.flags |= MAT_FLAG_GENERAL_SCALE;
            }
        } else if mask & MASK_2D == MASK_2D {
            let mm = m[0] * m[0] + m[1] * m[1];
            let m4m4 = m[4] * m[4] + m[5] * m[5];
            let mm4 = m[0] * m[4] + m[1] * m[5];
            self.ty = MatrixType::TwoD;
            if sq(mm - 1.0) > eps2 || sq(m4m4 - 1.0) > eps2 {
                self.flags |= MAT_FLAG_GENERAL_SCALE;
            }
            if sq(mm4) > eps2 {
                self.flags |= MAT_FLAG_GENERAL_3D;
            } else {
                self.flags |= MAT_FLAG_ROTATION;
            }
        } else if mask & MASK_3D_NO_ROT == MASK_3D_NO_ROT {
            self.ty = MatrixType::NoRot3D;
            if sq(m[0] - m[5]) < eps2 && sq(m[0] - m[10]) < eps2 {
                if sq(m[0] - 1.0) > eps2 {
                    self.flags |= MAT_FLAG_UNIFORM_SCALE;
                }
            } else {
                self.flags |= MAT_FLAG_GENERAL_SCALE;
            }
        } else if mask & MASK_3D == MASK_3D {
            let dot3 = |a: usize, b: usize| m[a] * m[b] + m[a + 1] * m[b + 1] + m[a + 2] * m[b + 2];
            let c1 = dot3(0, 0);
            let c2 = dot3(4, 4);
            let c3 = dot3(8, 8);
            let d1 = dot3(0, 4);
            self.ty = MatrixType::ThreeD;
            if sq(c1 - c2) < eps2 && sq(c1 - c3) < eps2 {
                if sq(c1 - 1.0) > eps2 {
                    self.flags |= MAT_FLAG_UNIFORM_SCALE;
                }
            } else {
                self.flags |= MAT_FLAG_GENERAL_SCALE;
            }
            if sq(d1) < eps2 {
                // CROSS3(cp, m, m+4); SUB_3V(cp, cp, m+8)
                let cp = [
                    m[1] * m[6] - m[2] * m[5] - m[8],
                    m[2] * m[4] - m[0] * m[6] - m[9],
                    m[0] * m[5] - m[1] * m[4] - m[10],
                ];
                let len2 = cp[0] * cp[0] + cp[1] * cp[1] + cp[2] * cp[2];
                if len2 < eps2 {
                    self.flags |= MAT_FLAG_ROTATION;
                } else {
                    self.flags |= MAT_FLAG_GENERAL_3D;
                }
            } else {
                self.flags |= MAT_FLAG_GENERAL_3D;
            }
        } else if mask & MASK_PERSPECTIVE == MASK_PERSPECTIVE && m[11] == -1.0 {
            self.ty = MatrixType::Perspective;
            self.flags |= MAT_FLAG_GENERAL;
        } else {
            self.ty = MatrixType::General;
            self.flags |= MAT_FLAG_GENERAL;
        }
    }
}

#[inline(always)]
fn at(m: &[f32; 16], r: usize, c: usize) -> f32 {
    m[c * 4 + r]
}

/// `inv_mat_tab[type]`: the inverse, or `None` when singular.
pub fn invert(m: &[f32; 16], ty: MatrixType, flags: u32) -> Option<[f32; 16]> {
    match ty {
        MatrixType::General | MatrixType::Perspective => invert_general(m),
        MatrixType::Identity => Some(IDENTITY),
        MatrixType::NoRot3D => invert_no_rot::<3>(m, flags),
        MatrixType::TwoD | MatrixType::ThreeD => invert_3d(m, flags),
        MatrixType::NoRot2D => invert_no_rot::<2>(m, flags),
    }
}

fn set(o: &mut [f32; 16], r: usize, c: usize, v: f32) {
    o[c * 4 + r] = v;
}

fn translation_part(m: &[f32; 16], o: &mut [f32; 16]) {
    for r in 0..3 {
        let v =
            -(at(m, 0, 3) * at(o, r, 0) + at(m, 1, 3) * at(o, r, 1) + at(m, 2, 3) * at(o, r, 2));
        set(o, r, 3, v);
    }
}

fn invert_3d_general(m: &[f32; 16]) -> Option<[f32; 16]> {
    let mut o = [0f32; 16];
    let (mut pos, mut neg) = (0f32, 0f32);
    let terms = [
        at(m, 0, 0) * at(m, 1, 1) * at(m, 2, 2),
        at(m, 1, 0) * at(m, 2, 1) * at(m, 0, 2),
        at(m, 2, 0) * at(m, 0, 1) * at(m, 1, 2),
        -at(m, 2, 0) * at(m, 1, 1) * at(m, 0, 2),
        -at(m, 1, 0) * at(m, 0, 1) * at(m, 2, 2),
        -at(m, 0, 0) * at(m, 2, 1) * at(m, 1, 2),
    ];
    for t in terms {
        if t >= 0.0 {
            pos += t;
        } else {
            neg += t;
        }
    }
    let det = pos + neg;
    if det.abs() < 1e-25 {
        return None;
    }
    let det = 1.0 / det;
    let a = |r, c| at(m, r, c);
    set(&mut o, 0, 0, (a(1, 1) * a(2, 2) - a(2, 1) * a(1, 2)) * det);
    set(&mut o, 0, 1, -(a(0, 1) * a(2, 2) - a(2, 1) * a(0, 2)) * det);
    set(&mut o, 0, 2, (a(0, 1) * a(1, 2) - a(1, 1) * a(0, 2)) * det);
    set(&mut o, 1, 0, -(a(1, 0) * a(2, 2) - a(2, 0) * a(1, 2)) * det);
    set(&mut o, 1, 1, (a(0, 0) * a(2, 2) - a(2, 0) * a(0, 2)) * det);
    set(&mut o, 1, 2, -(a(0, 0) * a(1, 2) - a(1, 0) * a(0, 2)) * det);
    set(&mut o, 2, 0, (a(1, 0) * a(2, 1) - a(2, 0) * a(1, 1)) * det);
    set(&mut o, 2, 1, -(a(0, 0) * a(2, 1) - a(2, 0) * a(0, 1)) * det);
    set(&mut o, 2, 2, (a(0, 0) * a(1, 1) - a(1, 0) * a(0, 1)) * det);
    translation_part(m, &mut o);
    // Row 3 of `out` is never written by Mesa here: the buffer keeps its previous contents
    // (the last inverse). For affine matrices that is (0,0,0,1) in practice.
    o[15] = 1.0;
    Some(o)
}

fn invert_3d(m: &[f32; 16], flags: u32) -> Option<[f32; 16]> {
    if !test(flags, ANGLE_PRESERVING) {
        return invert_3d_general(m);
    }
    let mut o = IDENTITY;
    if flags & MAT_FLAG_UNIFORM_SCALE != 0 {
        let scale =
            at(m, 0, 0) * at(m, 0, 0) + at(m, 0, 1) * at(m, 0, 1) + at(m, 0, 2) * at(m, 0, 2);
        if scale == 0.0 {
            return None;
        }
        let scale = 1.0 / scale;
        for r in 0..3 {
            for c in 0..3 {
                set(&mut o, r, c, scale * at(m, c, r));
            }
        }
    } else if flags & MAT_FLAG_ROTATION != 0 {
        for r in 0..3 {
            for c in 0..3 {
                set(&mut o, r, c, at(m, c, r));
            }
        }
    } else {
        set(&mut o, 0, 3, -at(m, 0, 3));
        set(&mut o, 1, 3, -at(m, 1, 3));
        set(&mut o, 2, 3, -at(m, 2, 3));
        return Some(o);
    }
    if flags & MAT_FLAG_TRANSLATION != 0 {
        translation_part(m, &mut o);
    } else {
        set(&mut o, 0, 3, 0.0);
        set(&mut o, 1, 3, 0.0);
        set(&mut o, 2, 3, 0.0);
    }
    Some(o)
}

/// `invert_matrix_3d_no_rot` (`N` = 3) and `invert_matrix_2d_no_rot` (`N` = 2): a scale
/// of the first `N` axes and a translation.
fn invert_no_rot<const N: usize>(m: &[f32; 16], flags: u32) -> Option<[f32; 16]> {
    if (0..N).any(|i| at(m, i, i) == 0.0) {
        return None;
    }
    let mut o = IDENTITY;
    for i in 0..N {
        set(&mut o, i, i, 1.0 / at(m, i, i));
    }
    if flags & MAT_FLAG_TRANSLATION != 0 {
        for i in 0..N {
            let v = -(at(m, i, 3) * at(&o, i, i));
            set(&mut o, i, 3, v);
        }
    }
    Some(o)
}

/// `util_invert_mat4x4`: Gaussian elimination with partial pivoting, unrolled as in Mesa.
#[allow(clippy::needless_range_loop)]
pub fn invert_general(m: &[f32; 16]) -> Option<[f32; 16]> {
    let mut w = [[0f32; 8]; 4];
    for r in 0..4 {
        for c in 0..4 {
            w[r][c] = at(m, r, c);
        }
        w[r][4 + r] = 1.0;
    }
    // Row "pointers" r0..r3 as indices into w.
    let mut r = [0usize, 1, 2, 3];
    let fab = |w: &[[f32; 8]; 4], i: usize, c: usize| w[i][c].abs();
    for k in 0..3 {
        // Pivot: the largest of column k bubbles up from the last row to row k.
        for i in (k + 1..4).rev() {
            if fab(&w, r[i], k) > fab(&w, r[i - 1], k) {
                r.swap(i, i - 1);
            }
        }
        if w[r[k]][k] == 0.0 {
            return None;
        }
        // Eliminate variable k from the rows below.
        let mut m = [0f32; 4];
        for i in k + 1..4 {
            m[i] = w[r[i]][k] / w[r[k]][k];
        }
        for c in k + 1..8 {
            let s = w[r[k]][c];
            // Mesa skips the right half's zeros, except in the last step.
            if c < 4 || s != 0.0 || k == 2 {
                for i in k + 1..4 {
                    w[r[i]][c] -= m[i] * s;
                }
            }
        }
    }
    if w[r[3]][3] == 0.0 {
        return None;
    }
    let s = 1.0 / w[r[3]][3];
    for c in 4..8 {
        w[r[3]][c] *= s;
    }
    for k in (1..4).rev() {
        // Back substitute row k - 1, then take column k out of the rows above it.
        let (ik, ip) = (r[k], r[k - 1]);
        let m = w[ip][k];
        let s = 1.0 / w[ip][k - 1];
        for c in 4..8 {
            w[ip][c] = s * (w[ip][c] - w[ik][c] * m);
        }
        for &ij in &r[..k - 1] {
            let m = w[ij][k];
            for c in 4..8 {
                w[ij][c] -= w[ik][c] * m;
            }
        }
    }
    let (i0, i1, i2, i3) = (r[0], r[1], r[2], r[3]);
    let mut out = [0f32; 16];
    for (row, &i) in [i0, i1, i2, i3].iter().enumerate() {
        for c in 0..4 {
            set(&mut out, row, c, w[i][4 + c]);
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mul(a: &[f32; 16], b: &[f32; 16]) -> [f32; 16] {
        let mut p = [0f32; 16];
        for i in 0..4 {
            for j in 0..4 {
                p[j * 4 + i] = (0..4).map(|k| at(a, i, k) * at(b, k, j)).sum();
            }
        }
        p
    }

    fn near_identity(p: &[f32; 16]) -> bool {
        p.iter()
            .zip(IDENTITY.iter())
            .all(|(a, b)| (a - b).abs() < 1e-5)
    }

    #[test]
    fn inverses_are_inverses() {
        let general = [
            2.0, 0.5, 0.1, 0.2, -0.3, 1.5, 0.4, 0.1, 0.7, -0.2, 3.0, 0.3, 1.0, 2.0, 3.0, 1.0,
        ];
        let inv = invert_general(&general).unwrap();
        assert!(near_identity(&mul(&general, &inv)));
        let mut f = MatFlags::from_scratch(&general);
        assert_eq!(f.ty, MatrixType::General);
        assert!(near_identity(&mul(&general, &f.inverse(&general))));

        // Rotation about z by 90° plus translation, as glRotate/glTranslate build it.
        let rt = [
            0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 5.0, 6.0, 7.0, 1.0,
        ];
        let mut f = MatFlags::IDENTITY;
        f.on_rotate();
        f.on_translate();
        let inv = f.inverse(&rt);
        assert_eq!(f.ty, MatrixType::ThreeD, "m[14] != 0");
        assert!(f.is_length_preserving());
        assert!(near_identity(&mul(&rt, &inv)));

        let s = [
            2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 1.0, 1.0, 1.0, 1.0,
        ];
        let mut f = MatFlags::IDENTITY;
        f.on_scale(2.0, 3.0, 4.0);
        f.on_translate();
        let inv = f.inverse(&s);
        assert_eq!(f.ty, MatrixType::NoRot3D);
        assert!(!f.is_length_preserving());
        assert!(near_identity(&mul(&s, &inv)));
        assert!(invert_general(&[0.0; 16]).is_none());
    }
}
