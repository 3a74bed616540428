//! Unit tests of `geometry/setup.rs`.

use super::*;

fn v(x: f32, y: f32) -> ClipVertex {
    ClipVertex {
        win: [x, y, 0.5, 1.0],
        ..Default::default()
    }
}

/// Covered pixels of a triangle, by brute force over the edges.
fn coverage(t: &SetupTriangle) -> Vec<(i64, i64)> {
    let mut out = vec![];
    for py in t.bbox[1]..=t.bbox[3] {
        for px in t.bbox[0]..=t.bbox[2] {
            if t.edges
                .iter()
                .all(|e| e.c - e.a * ONE * px + e.b * ONE * py > 0)
            {
                out.push((px, py));
            }
        }
    }
    out
}

const NOCULL: CullMode = CullMode {
    front: false,
    back: false,
    front_ccw: true,
    top_left: false,
};

#[test]
fn fill_rule_matches_llvmpipe_example() {
    // GL (0.5,0.5),(2.5,0.5),(0.5,2.5) in an 8-high buffer covers GL pixels (0,0),(1,0),(0,1).
    let h = 8.0;
    let tri = [v(0.5, h - 0.5), v(2.5, h - 0.5), v(0.5, h - 2.5)];
    let mut t = SetupTriangle::default();
    assert!(matches!(
        setup_triangle([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, &mut t),
        SetupResult::Draw
    ));
    let mut c = coverage(&t);
    c.sort();
    assert_eq!(c, vec![(0, 6), (0, 7), (1, 7)]);
}

#[test]
fn tiny_triangles_are_empty_exactly_when_no_centre_is_covered() {
    // Small triangles at 1/64-pixel positions around a few pixel centres, both windings:
    // `setup_triangle_shaded` calls a triangle Empty exactly when the brute-force
    // coverage of the full setup is empty.
    let mut next = crate::test_rng::xorshift32(0x9E37_79B9);
    let (mut empty, mut drawn) = (0, 0);
    for _ in 0..20_000 {
        let p = |r: u32| 3.0 + (r % 160) as f32 / 64.0;
        let tri: Vec<ClipVertex> = (0..3).map(|_| v(p(next()), p(next()))).collect();
        let mut full = SetupTriangle::default();
        let r = setup_triangle([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, &mut full);
        if !matches!(r, SetupResult::Draw) {
            continue;
        }
        let covered = !coverage(&full).is_empty();
        let mut t = SetupTriangle::default();
        let r = setup_triangle_shaded([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, false, &mut t);
        match r {
            SetupResult::Empty => {
                assert!(
                    !covered,
                    "{:?}",
                    tri.iter().map(|v| v.win).collect::<Vec<_>>()
                );
                empty += 1;
            }
            SetupResult::Draw => {
                assert_eq!(t.edges, full.edges);
                // Boxes of at most 2x2 centres are always decided by setup.
                let small = t.bbox[2] - t.bbox[0] <= 1 && t.bbox[3] - t.bbox[1] <= 1;
                assert!(covered || !small);
                drawn += 1;
            }
            _ => panic!("setup_triangle drew it"),
        }
    }
    // Both outcomes occur many times.
    assert!(empty > 1000 && drawn > 1000, "{empty} {drawn}");
}

#[test]
fn span_agrees_with_brute_force() {
    let tri = [v(1.3, 2.7), v(17.9, 5.1), v(6.2, 19.4)];
    let mut t = SetupTriangle::default();
    assert!(matches!(
        setup_triangle([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, &mut t),
        SetupResult::Draw
    ));
    let brute = coverage(&t);
    let mut spans = vec![];
    for py in t.bbox[1]..=t.bbox[3] {
        let (lo, hi) = t.cut_span(py, t.bbox[0], t.bbox[2]);
        for px in lo..=hi {
            spans.push((px, py));
        }
    }
    assert_eq!(brute, spans);
    assert!(brute.len() > 50);
}

#[test]
fn narrow_row_span_agrees_with_division() {
    let tris = [
        [v(1.3, 2.7), v(7.9, 5.1), v(3.2, 9.4)],
        [v(0.5, 0.5), v(3.0, 0.5), v(0.5, 3.0)],
        [v(5.7, 1.1), v(1.2, 4.9), v(6.6, 8.8)],
    ];
    for tri in &tris {
        let mut t = SetupTriangle::default();
        assert!(matches!(
            setup_triangle([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, &mut t),
            SetupResult::Draw
        ));
        for py in t.bbox[1] - 1..=t.bbox[3] + 1 {
            for (x0, x1) in [(t.bbox[0], t.bbox[2]), (t.bbox[0] + 1, t.bbox[2] - 1)] {
                let mut want = Some((x0, x1));
                for e in &t.edges {
                    want = match (want, e.span(py)) {
                        (Some((lo, hi)), Some((a, z))) => Some((lo.max(a), hi.min(z))),
                        _ => None,
                    };
                }
                let want = want.filter(|(lo, hi)| lo <= hi);
                assert_eq!(t.row_span(x0, x1, py), want);
            }
        }
    }
}

/// A small deterministic generator for the randomised tests.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// A float in [0, 1).
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// The reference for `row_span`: the three edges' divisions, intersected.
fn reference_span(t: &SetupTriangle, x0: i64, x1: i64, py: i64) -> Option<(i64, i64)> {
    divided_span(&t.edges, x0, x1, py)
}

#[test]
fn row_span_agrees_with_division_on_random_triangles() {
    let mut r = XorShift(0x9e37_79b9_7f4a_7c15);
    let mut checked = 0;
    for n in 0..20000 {
        // Scales from sub-pixel to huge; every fourth triangle on pixel centres, every
        // eighth on 1/256 sub-pixel positions.
        let scale = [0.7f32, 3.0, 9.0, 40.0, 3000.0][n % 5];
        let pos = |r: &mut XorShift| {
            let v = 20.0 + r.unit() * scale;
            match n % 8 {
                0 | 4 => v.floor() + 0.5,
                2 => (v * 256.0).floor() / 256.0,
                _ => v,
            }
        };
        let tri = [0; 3].map(|_| v(pos(&mut r), pos(&mut r)));
        let mut t = SetupTriangle::default();
        if !matches!(
            setup_triangle([&tri[0], &tri[1], &tri[2]], 0, NOCULL, None, &mut t),
            SetupResult::Draw
        ) {
            continue;
        }
        let rows = (t.bbox[3] - t.bbox[1]).min(40);
        for py in t.bbox[1] - 1..=t.bbox[1] + rows + 1 {
            let mut windows = vec![(t.bbox[0], t.bbox[2]), (t.bbox[0] - 1, t.bbox[2] + 1)];
            for w in 0..6 {
                let x = t.bbox[0] - 1 + (r.next() % 6) as i64;
                windows.push((x, x + w - 1));
            }
            for (x0, x1) in windows {
                assert_eq!(
                    t.row_span(x0, x1, py),
                    reference_span(&t, x0, x1, py),
                    "triangle {tri:?} row {py} window {x0}..={x1}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 100_000);
}

#[test]
fn plane4_matches_scalar_planes_bit_for_bit() {
    let mut r = XorShift(12345);
    let f =
        |r: &mut XorShift| (r.unit() - 0.5) * [1.0f32, 1e-3, 300.0, 7e5][(r.next() % 4) as usize];
    for _ in 0..20000 {
        let pc = PlaneConsts {
            dy20o: f(&mut r),
            dy01o: f(&mut r),
            dx01o: f(&mut r),
            dx20o: f(&mut r),
            x0c: f(&mut r),
            y0c: f(&mut r),
        };
        let a = [0; 3].map(|_| [0; 4].map(|_| f(&mut r)));
        let four = pc.plane4(a[0], a[1], a[2]);
        for l in 0..4 {
            // The reference: the scalar formula, spelled out in Mesa's order.
            let (a0, a1, a2) = (a[0][l], a[1][l], a[2][l]);
            let da01 = a0 - a1;
            let da20 = a2 - a0;
            let dadx = da01 * pc.dy20o - da20 * pc.dy01o;
            let dady = da20 * pc.dx01o - da01 * pc.dx20o;
            let a0 = a0 - (dadx * pc.x0c + dady * pc.y0c);
            let got = four[l];
            assert_eq!(
                [got.a0, got.dadx, got.dady].map(f32::to_bits),
                [a0, dadx, dady].map(f32::to_bits)
            );
            assert_eq!(pc.plane(a[0][l], a[1][l], a[2][l]), got);
        }
    }
}

#[test]
fn snap4_matches_snap() {
    let mut r = XorShift(777);
    let mut vals = vec![
        0.5f32,
        -0.5,
        1.5 / 256.0,
        0.5 + 0.5 / 256.0,
        0.5 + 1.5 / 256.0,
    ];
    vals.extend([-1e30, 1e30, 4e7, -4e7, 32767.998, -0.0, 0.0]);
    for _ in 0..100_000 {
        let k = (r.next() % 2_000_000) as f32 - 1_000_000.0;
        // Ties (k + 0.5)/256 + 0.5, near-ties and arbitrary values.
        vals.push((k + 0.5) / 256.0 + 0.5);
        vals.push(k / 256.0 + 0.5 + r.unit() / 256.0);
        vals.push((r.unit() - 0.5) * 70000.0);
    }
    for c in vals.chunks_exact(4) {
        let v = [c[0], c[1], c[2], c[3]];
        let got = snap4(v);
        for l in 0..4 {
            assert_eq!(got[l] as i64, snap(v[l]), "{}", v[l]);
        }
    }
}

#[test]
fn square_shares_diagonal_without_overlap() {
    // Two triangles of a square: each covered pixel exactly once.
    let q = [v(1.5, 1.5), v(4.5, 1.5), v(4.5, 4.5), v(1.5, 4.5)];
    let mut all = vec![];
    for (a, b, c) in [(0, 1, 2), (0, 2, 3)] {
        let mut t = SetupTriangle::default();
        if let SetupResult::Draw = setup_triangle([&q[a], &q[b], &q[c]], 0, NOCULL, None, &mut t) {
            all.extend(coverage(&t));
        }
    }
    let n = all.len();
    all.sort();
    all.dedup();
    assert_eq!(n, all.len(), "double-covered pixel");
    assert_eq!(n, 9);
}
#[test]
fn avx2_setup_matches_baseline_bit_for_bit() {
    let fast = SetupVariant::detect();
    if !fast.avx2 {
        eprintln!("no AVX2 on this CPU: only the baseline copy exists to run");
        return;
    }
    let mut next = crate::test_rng::xorshift32(0xa5e7_0f1c);
    let odd = [f32::NAN, f32::INFINITY, -1e30, 0.0, -0.0, 1e-30, 3.5, 1e12];
    let mut val = |scale: f32| {
        let r = next();
        if r.is_multiple_of(64) {
            odd[(r >> 6) as usize % odd.len()]
        } else {
            (r >> 8) as f32 / (1 << 24) as f32 * scale
        }
    };
    let mut counts = [0u32; 4];
    for case in 0..20_000 {
        // Tiny, small and large triangles, some with varying 1/w.
        let scale = [2.0, 12.0, 300.0][case % 3];
        let (ox, oy) = (val(200.0), val(200.0));
        let vs: Vec<ClipVertex> = (0..3)
            .map(|_| {
                let mut c = ClipVertex {
                    win: [ox + val(scale), oy + val(scale), val(1.0), 1.0],
                    ..Default::default()
                };
                if case % 2 == 1 {
                    c.win[3] = 0.25 + val(2.0);
                }
                for x in c.vary.iter_mut() {
                    *x = val(1.0);
                }
                c
            })
            .collect();
        let cull = CullMode {
            front: case % 7 == 3,
            back: case % 5 == 2,
            front_ccw: case % 4 < 2,
            top_left: false,
        };
        let back = (case % 6 == 1).then_some(super::super::VARY_TEX);
        let nvary = [4, 7, 16, 22][case % 4];
        let flat = case % 9 == 0;
        let v = [&vs[0], &vs[1], &vs[2]];
        let (mut a, mut b) = (SetupTriangle::default(), SetupTriangle::default());
        let ra = SetupVariant::baseline().shaded(v, nvary, cull, back, flat, &mut a);
        let rb = fast.shaded(v, nvary, cull, back, flat, &mut b);
        let kind = |r: &SetupResult| match r {
            SetupResult::Draw => 0,
            SetupResult::Degenerate => 1,
            SetupResult::Culled => 2,
            SetupResult::Empty => 3,
        };
        assert_eq!(kind(&ra), kind(&rb), "case {case}");
        counts[kind(&ra)] += 1;
        // Debug prints every f32 exactly (and NaN, -0.0 as such).
        assert_eq!(format!("{a:?}"), format!("{b:?}"), "case {case}");
    }
    assert!(counts.iter().all(|&c| c > 200), "{counts:?}");
}
