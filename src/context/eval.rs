//! Evaluator state (glMap1/glMap2, glMapGrid, GL_MAP*_* enables are caps) and
//! glEvalCoord: Mesa's rules (`main/eval.c`, `vbo/vbo_exec_eval.c`). A coordinate is
//! mapped to `(u - u1) * (1 / (u2 - u1))`; each enabled attribute map sets the current
//! attribute (texture coordinates and vertices use the highest enabled size), and the
//! vertex map emits a vertex; GL_AUTO_NORMAL takes the normal from the surface's partial
//! derivatives (`du × dv`, normalised with `1 / sqrt`).

use super::state::Cap;
use super::{Context, GlError, GlResult};
use crate::fixed_function::eval::{de_casteljau_surf, horner_curve, horner_surf};

/// The nine map kinds, in GL_MAP1_COLOR_4 … GL_MAP1_VERTEX_4 order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapKind {
    /// GL_MAP*_COLOR_4.
    Color4,
    /// GL_MAP*_INDEX.
    Index,
    /// GL_MAP*_NORMAL.
    Normal,
    /// GL_MAP*_TEXTURE_COORD_1.
    Tex1,
    /// GL_MAP*_TEXTURE_COORD_2.
    Tex2,
    /// GL_MAP*_TEXTURE_COORD_3.
    Tex3,
    /// GL_MAP*_TEXTURE_COORD_4.
    Tex4,
    /// GL_MAP*_VERTEX_3.
    Vertex3,
    /// GL_MAP*_VERTEX_4.
    Vertex4,
}

impl MapKind {
    /// All kinds, in enum order.
    pub const ALL: [MapKind; 9] = [
        MapKind::Color4,
        MapKind::Index,
        MapKind::Normal,
        MapKind::Tex1,
        MapKind::Tex2,
        MapKind::Tex3,
        MapKind::Tex4,
        MapKind::Vertex3,
        MapKind::Vertex4,
    ];
    /// Components per control point.
    pub fn dim(self) -> usize {
        match self {
            MapKind::Index | MapKind::Tex1 => 1,
            MapKind::Tex2 => 2,
            MapKind::Normal | MapKind::Tex3 | MapKind::Vertex3 => 3,
            MapKind::Color4 | MapKind::Tex4 | MapKind::Vertex4 => 4,
        }
    }
    /// The initial single control point.
    fn default_point(self) -> Vec<f32> {
        match self {
            MapKind::Color4 => vec![1.0; 4],
            MapKind::Index => vec![1.0],
            MapKind::Normal => vec![0.0, 0.0, 1.0],
            MapKind::Tex4 | MapKind::Vertex4 => vec![0.0, 0.0, 0.0, 1.0],
            k => vec![0.0; k.dim()],
        }
    }
    /// The enable of this kind for 1D (`two = false`) or 2D maps.
    pub fn cap(self, two: bool) -> Cap {
        let one = [
            Cap::Map1Color4,
            Cap::Map1Index,
            Cap::Map1Normal,
            Cap::Map1TexCoord1,
            Cap::Map1TexCoord2,
            Cap::Map1TexCoord3,
            Cap::Map1TexCoord4,
            Cap::Map1Vertex3,
            Cap::Map1Vertex4,
        ];
        let two_caps = [
            Cap::Map2Color4,
            Cap::Map2Index,
            Cap::Map2Normal,
            Cap::Map2TexCoord1,
            Cap::Map2TexCoord2,
            Cap::Map2TexCoord3,
            Cap::Map2TexCoord4,
            Cap::Map2Vertex3,
            Cap::Map2Vertex4,
        ];
        if two {
            two_caps[self as usize]
        } else {
            one[self as usize]
        }
    }
}

/// One map: orders, domain and control points (`[u][v][k]`, f32 as Mesa stores them).
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// Order in u.
    pub uorder: usize,
    /// Order in v (1 for 1D maps).
    pub vorder: usize,
    /// Domain in u.
    pub u: [f32; 2],
    /// Domain in v (2D maps).
    pub v: [f32; 2],
    /// Control points.
    pub points: Vec<f32>,
}

impl Map {
    fn initial(kind: MapKind) -> Self {
        Map {
            uorder: 1,
            vorder: 1,
            u: [0.0, 1.0],
            v: [0.0, 1.0],
            points: kind.default_point(),
        }
    }
    /// Mesa's `1 / (u2 - u1)`.
    fn du(&self) -> f32 {
        1.0f32 / (self.u[1] - self.u[0])
    }
    fn dv(&self) -> f32 {
        1.0f32 / (self.v[1] - self.v[0])
    }
}

/// A map grid (glMapGrid1/2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Segments.
    pub n: i32,
    /// Domain.
    pub d: [f32; 2],
}

impl Grid {
    /// The step Mesa stores: `(d2 - d1) / n`.
    pub fn step(&self) -> f32 {
        (self.d[1] - self.d[0]) / self.n as f32
    }
}

/// Evaluator state: the GL_EVAL_BIT attribute group except the enables (which are caps).
#[derive(Clone, Debug, PartialEq)]
pub struct EvalState {
    /// The 1D maps, by [`MapKind`].
    pub map1: Vec<Map>,
    /// The 2D maps, by [`MapKind`].
    pub map2: Vec<Map>,
    /// glMapGrid1.
    pub grid1: Grid,
    /// glMapGrid2 (u, v).
    pub grid2: [Grid; 2],
}

impl Default for EvalState {
    fn default() -> Self {
        let g = Grid {
            n: 1,
            d: [0.0, 1.0],
        };
        EvalState {
            map1: MapKind::ALL.iter().map(|&k| Map::initial(k)).collect(),
            map2: MapKind::ALL.iter().map(|&k| Map::initial(k)).collect(),
            grid1: g,
            grid2: [g, g],
        }
    }
}

impl Context {
    /// glMap1/glMap2: `points` already gathered (uorder x vorder x dim, u-major).
    #[allow(clippy::too_many_arguments)]
    pub fn set_map(
        &mut self,
        kind: MapKind,
        two: bool,
        u: [f32; 2],
        v: [f32; 2],
        uorder: usize,
        vorder: usize,
        points: Vec<f32>,
    ) -> GlResult<()> {
        let map = Map {
            uorder,
            vorder,
            u,
            v,
            points,
        };
        if two {
            self.eval.map2[kind as usize] = map;
        } else {
            self.eval.map1[kind as usize] = map;
        }
        Ok(())
    }

    /// glMapGrid1 / glMapGrid2.
    pub fn map_grid(&mut self, g: &[Grid]) -> GlResult<()> {
        if g.iter().any(|g| g.n < 1) {
            return Err(GlError::InvalidValue);
        }
        match g {
            [a] => self.eval.grid1 = *a,
            [a, b] => self.eval.grid2 = [*a, *b],
            _ => {}
        }
        Ok(())
    }

    /// The enabled map of the highest size among `kinds` (Mesa prefers the last).
    fn active_map(&self, two: bool, kinds: &[MapKind]) -> Option<(MapKind, &Map)> {
        let maps = if two {
            &self.eval.map2
        } else {
            &self.eval.map1
        };
        kinds
            .iter()
            .rev()
            .find(|k| self.state.caps.get(k.cap(two)))
            .map(|&k| (k, &maps[k as usize]))
    }

    /// Whether a vertex map of this dimension is enabled (glEvalMesh does nothing else).
    pub fn eval_vertex_enabled(&self, two: bool) -> bool {
        self.active_map(two, &[MapKind::Vertex3, MapKind::Vertex4])
            .is_some()
    }

    /// glEvalCoord1/2 (`v` is `None` for 1D): sets the evaluated attributes and emits
    /// the evaluated vertex (inside glBegin/glEnd).
    pub fn eval_coord(&mut self, u: f32, v: Option<f32>) {
        let two = v.is_some();
        let v = v.unwrap_or(0.0);
        let eval = |m: &Map, dim: usize| -> [f32; 4] {
            let mut out = [0.0, 0.0, 0.0, 1.0];
            let uu = (u - m.u[0]) * m.du();
            if two {
                let vv = (v - m.v[0]) * m.dv();
                horner_surf(&m.points, &mut out, uu, vv, dim, m.uorder, m.vorder);
            } else {
                horner_curve(&m.points, dim, &mut out, uu, dim, m.uorder);
            }
            out
        };
        let tex = [MapKind::Tex1, MapKind::Tex2, MapKind::Tex3, MapKind::Tex4];
        let mut normal = self
            .active_map(two, &[MapKind::Normal])
            .map(|(k, m)| eval(m, k.dim()));
        let color = self
            .active_map(two, &[MapKind::Color4])
            .map(|(k, m)| eval(m, k.dim()));
        let texcoord = self.active_map(two, &tex).map(|(k, m)| eval(m, k.dim()));
        let mut vertex = None;
        if let Some((k, m)) = self.active_map(two, &[MapKind::Vertex3, MapKind::Vertex4]) {
            let dim = k.dim();
            let mut p = [0.0, 0.0, 0.0, 1.0];
            let uu = (u - m.u[0]) * m.du();
            if two {
                let vv = (v - m.v[0]) * m.dv();
                if self.state.caps.get(Cap::AutoNormal) {
                    let (mut du, mut dv) = ([0f32; 4], [0f32; 4]);
                    let (uo, vo) = (m.uorder, m.vorder);
                    de_casteljau_surf(&m.points, &mut p, &mut du, &mut dv, uu, vv, dim, uo, vo);
                    if dim == 4 {
                        for i in 0..3 {
                            du[i] = du[i] * p[3] - du[3] * p[i];
                            dv[i] = dv[i] * p[3] - dv[3] * p[i];
                        }
                    }
                    let mut nv = [
                        du[1] * dv[2] - du[2] * dv[1],
                        du[2] * dv[0] - du[0] * dv[2],
                        du[0] * dv[1] - du[1] * dv[0],
                        1.0,
                    ];
                    let len = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
                    if len != 0.0 {
                        let inv = 1.0f32 / len.sqrt();
                        for c in &mut nv[..3] {
                            *c *= inv;
                        }
                    }
                    normal = Some(nv);
                } else {
                    horner_surf(&m.points, &mut p, uu, vv, dim, m.uorder, m.vorder);
                }
            } else {
                horner_curve(&m.points, dim, &mut p, uu, dim, m.uorder);
            }
            if dim == 3 {
                p[3] = 1.0;
            }
            vertex = Some(p);
        }
        let cur = &mut self.state.current;
        if let Some(n) = normal {
            cur.normal = [n[0], n[1], n[2]];
        }
        if let Some(c) = color {
            cur.color = c;
        }
        if let Some(t) = texcoord {
            cur.texcoord[0] = t;
        }
        if let (Some(p), Some(_)) = (vertex, self.immediate.active) {
            // Out of memory drops the vertex (glEvalCoord has no error to report).
            let _ = self.push_immediate_vertex(p);
        }
    }

    /// glGetMap: the map of `kind`.
    pub fn map(&self, kind: MapKind, two: bool) -> &Map {
        if two {
            &self.eval.map2[kind as usize]
        } else {
            &self.eval.map1[kind as usize]
        }
    }
}
