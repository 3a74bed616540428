//! Primitive assembly: which vertex triples make the triangles of a draw, in llvmpipe's
//! order (docs/llvmpipe-rules.md §5). The order matters twice: setup uses the first vertex as the
//! interpolation origin, and a quad's diagonal depends on it.

use crate::pipe::Primitive;

/// How the reference routes a draw, which decides the GL_QUADS / GL_QUAD_STRIP split.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawPath {
    /// glBegin/glEnd or glDrawArrays with no vertex outside the clip volume.
    ArraysNoClip,
    /// glDrawElements with no vertex outside the clip volume.
    ElementsNoClip,
    /// Any vertex of the draw outside the clip volume: the draw module's decomposition.
    Clip,
}

/// Calls `tri(a, b, c)` with positions into `n` vertices for every triangle of `mode`.
/// `flat` is GL_FLAT shading. Vertices beyond the last whole primitive are ignored.
pub fn triangles(
    mode: Primitive,
    n: usize,
    path: DrawPath,
    flat: bool,
    mut tri: impl FnMut(usize, usize, usize),
) {
    match mode {
        Primitive::Triangles => {
            for i in (0..n / 3 * 3).step_by(3) {
                tri(i, i + 1, i + 2);
            }
        }
        Primitive::TriangleStrip => {
            for i in 2..n {
                if i % 2 == 0 {
                    tri(i - 2, i - 1, i);
                } else {
                    tri(i - 1, i - 2, i);
                }
            }
        }
        Primitive::TriangleFan => {
            for i in 2..n {
                tri(0, i - 1, i);
            }
        }
        Primitive::Quads => {
            for q in (0..n / 4 * 4).step_by(4) {
                let (v0, v1, v2, v3) = (q, q + 1, q + 2, q + 3);
                if path == DrawPath::ArraysNoClip && !flat {
                    tri(v0, v1, v2);
                    tri(v0, v2, v3);
                } else {
                    tri(v0, v1, v3);
                    tri(v1, v2, v3);
                }
            }
        }
        Primitive::QuadStrip => {
            let mut k = 0;
            while k + 3 < n {
                let (a, b, c, d) = (k, k + 1, k + 2, k + 3);
                if path == DrawPath::Clip {
                    tri(c, a, d);
                    tri(a, b, d);
                } else {
                    tri(a, b, d);
                    tri(c, a, d);
                }
                k += 2;
            }
        }
        Primitive::Polygon => {
            for i in 2..n {
                tri(i - 1, i, 0);
            }
        }
        Primitive::Points | Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip => {}
    }
}

/// Calls `line(a, b, reset)` for every segment of a line mode; `reset` marks the segments
/// that restart the line stipple pattern (every GL_LINES segment, the first of a strip or
/// loop), as the draw module's decomposition flags them.
pub fn lines(mode: Primitive, n: usize, mut line: impl FnMut(usize, usize, bool)) {
    match mode {
        Primitive::Lines => {
            for i in (0..n / 2 * 2).step_by(2) {
                line(i, i + 1, true);
            }
        }
        Primitive::LineStrip => {
            for i in 1..n {
                line(i - 1, i, i == 1);
            }
        }
        Primitive::LineLoop if n >= 2 => {
            for i in 1..n {
                line(i - 1, i, i == 1);
            }
            line(n - 1, 0, false);
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(
        mode: Primitive,
        n: usize,
        path: DrawPath,
        flat: bool,
    ) -> Vec<(usize, usize, usize)> {
        let mut v = vec![];
        triangles(mode, n, path, flat, |a, b, c| v.push((a, b, c)));
        v
    }

    #[test]
    fn quad_diagonal_depends_on_path() {
        let split_02 = vec![(0, 1, 2), (0, 2, 3)];
        let split_13 = vec![(0, 1, 3), (1, 2, 3)];
        for (path, flat, want) in [
            (DrawPath::ArraysNoClip, false, &split_02),
            (DrawPath::Clip, false, &split_13),
            (DrawPath::ArraysNoClip, true, &split_13),
            (DrawPath::ElementsNoClip, false, &split_13),
        ] {
            assert_eq!(&collect(Primitive::Quads, 4, path, flat), want);
        }
    }

    #[test]
    fn strip_alternates_and_polygon_ends_on_v0() {
        assert_eq!(
            collect(Primitive::TriangleStrip, 5, DrawPath::ArraysNoClip, false),
            vec![(0, 1, 2), (2, 1, 3), (2, 3, 4)]
        );
        assert_eq!(
            collect(Primitive::Polygon, 5, DrawPath::Clip, false),
            vec![(1, 2, 0), (2, 3, 0), (3, 4, 0)]
        );
        assert!(collect(Primitive::Triangles, 2, DrawPath::Clip, false).is_empty());
    }
}
