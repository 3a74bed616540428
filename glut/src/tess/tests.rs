//! The tessellator's geometry checked against winding numbers counted directly: every
//! sample point inside per the rule lies in exactly one triangle, every other in none.

use super::arrange::{arrange, Vtx};
use super::sweep::{boundaries, classify, inside, triangulate};
use super::*;

fn vtx(p: (f64, f64)) -> Vtx {
    Vtx {
        s: p.0,
        t: p.1,
        xyz: [p.0, p.1, 0.0],
        data: std::ptr::null_mut(),
    }
}

/// Winding number of point `q` about the contours.
fn winding(contours: &[Vec<(f64, f64)>], q: (f64, f64)) -> i32 {
    let mut w = 0;
    for c in contours {
        for k in 0..c.len() {
            let (a, b) = (c[k], c[(k + 1) % c.len()]);
            if a.1 <= q.1 && b.1 > q.1 && arrange::orient(a, b, q) > 0.0 {
                w += 1;
            } else if a.1 > q.1 && b.1 <= q.1 && arrange::orient(a, b, q) < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

fn in_tri(v: &[Vtx], t: &[usize; 3], q: (f64, f64)) -> bool {
    (0..3).all(|k| arrange::orient(v[t[k]].st(), v[t[(k + 1) % 3]].st(), q) > 0.0)
}

/// Tessellates and checks coverage on a grid of sample points; returns the triangles.
fn check(contours: &[Vec<(f64, f64)>], rule: GLenum) -> usize {
    let mut input = Vec::new();
    let mut ids = Vec::new();
    for c in contours {
        ids.push((input.len()..input.len() + c.len()).collect::<Vec<_>>());
        input.extend(c.iter().map(|&p| vtx(p)));
    }
    let mut combine = |_, _, _, _| Some(std::ptr::NonNull::<c_void>::dangling().as_ptr());
    let arr = arrange(&input, &ids, &mut combine);
    let bounds = classify(&arr.verts, &arr.segs, rule);
    let tris = triangulate(&arr.verts, &bounds);
    for t in &tris {
        let o = arrange::orient(
            arr.verts[t[0]].st(),
            arr.verts[t[1]].st(),
            arr.verts[t[2]].st(),
        );
        assert!(o >= 0.0, "clockwise triangle {t:?}");
    }
    let mut bad = 0;
    for i in 0..97 {
        for j in 0..89 {
            // Irrational-ish offsets keep samples off the edges.
            let q = (
                -1.0 + i as f64 * 0.1234567 + 0.0101,
                -1.0 + j as f64 * 0.1312345 + 0.0123,
            );
            let want = inside(rule, winding(contours, q));
            let n = tris.iter().filter(|t| in_tri(&arr.verts, t, q)).count();
            if n != usize::from(want) {
                bad += 1;
            }
        }
    }
    assert_eq!(bad, 0, "{bad} samples wrong for rule {rule}");
    // Boundary loops enclose the inside: their total area equals the triangles'.
    let area = |p: &[usize]| -> f64 {
        (0..p.len())
            .map(|k| {
                let (a, b) = (arr.verts[p[k]].st(), arr.verts[p[(k + 1) % p.len()]].st());
                a.0 * b.1 - b.0 * a.1
            })
            .sum::<f64>()
    };
    let loops: f64 = boundaries(&arr.verts, &bounds)
        .iter()
        .map(|l| area(l))
        .sum();
    let tri_area: f64 = tris.iter().map(|t| area(t)).sum();
    assert!(
        (loops - tri_area).abs() < 1e-9 * (1.0 + tri_area.abs()),
        "{loops} vs {tri_area}"
    );
    tris.len()
}

const RULES: [GLenum; 5] = [
    WINDING_ODD,
    WINDING_NONZERO,
    WINDING_POSITIVE,
    WINDING_NEGATIVE,
    WINDING_ABS_GEQ_TWO,
];

#[test]
fn squares_holes_and_stars() {
    let outer = vec![(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
    let hole = vec![(3.0, 3.0), (3.0, 7.0), (7.0, 7.0), (7.0, 3.0)];
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::PI / 2.0 + k as f64 * 4.0 * std::f64::consts::PI / 5.0;
            (5.0 + 4.5 * a.cos(), 5.0 + 4.5 * a.sin())
        })
        .collect();
    let shifted: Vec<_> = outer.iter().map(|p| (p.0 + 4.0, p.1 + 3.0)).collect();
    let touching = vec![(10.0, 10.0), (12.0, 10.0), (12.0, 12.0)];
    for rule in RULES {
        check(&[outer.clone(), hole.clone()], rule);
        check(std::slice::from_ref(&star), rule);
        check(&[outer.clone(), shifted.clone(), star.clone()], rule);
        check(&[outer.clone(), touching.clone()], rule);
        check(&[outer.clone(), outer.clone()], rule);
    }
    assert!(check(std::slice::from_ref(&outer), WINDING_ODD) == 2);
}

#[test]
fn random_polygons_cover_what_the_winding_rule_says() {
    let mut seed = 12345u64;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 33) as f64 / (1u64 << 31) as f64) * 10.0
    };
    for _ in 0..150 {
        let n = 3 + (rnd() as usize % 12);
        let a: Vec<_> = (0..n).map(|_| (rnd(), rnd())).collect();
        let m = 3 + (rnd() as usize % 5);
        let b: Vec<_> = (0..m).map(|_| (rnd(), rnd())).collect();
        for rule in RULES {
            check(std::slice::from_ref(&a), rule);
            check(&[a.clone(), b.clone()], rule);
            check(
                &[a.clone(), b.clone(), b.iter().map(|p| (p.1, p.0)).collect()],
                rule,
            );
        }
    }
}

#[test]
fn grid_aligned_polygons_with_shared_edges() {
    // Collinear overlaps, vertices on edges, vertical edges.
    let a = vec![(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
    let b = vec![(2.0, 0.0), (6.0, 0.0), (6.0, 4.0), (2.0, 4.0)];
    let c = vec![(4.0, 2.0), (8.0, 2.0), (8.0, 6.0), (4.0, 6.0)];
    let d = vec![
        (0.0, 0.0),
        (2.0, 2.0),
        (4.0, 0.0),
        (4.0, 4.0),
        (2.0, 2.0),
        (0.0, 4.0),
    ];
    for rule in RULES {
        check(&[a.clone(), b.clone(), c.clone()], rule);
        check(std::slice::from_ref(&d), rule);
        check(&[a.clone(), b.iter().rev().copied().collect()], rule);
    }
}

#[test]
fn degenerate_input_never_panics() {
    let mut seed = 99u64;
    let mut rnd = |k: u64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) % k
    };
    let specials = [
        0.0,
        1.0,
        -1.0,
        1e-300,
        1e300,
        f64::NAN,
        f64::INFINITY,
        0.5,
        2.0,
    ];
    for _ in 0..2000 {
        let mut contours = Vec::new();
        for _ in 0..1 + rnd(3) {
            let n = rnd(7) as usize;
            let c: Vec<(f64, f64)> = (0..n)
                .map(|_| {
                    let pick = |r: u64| {
                        if r < 9 {
                            specials[r as usize]
                        } else {
                            (r % 4) as f64
                        }
                    };
                    (pick(rnd(14)), pick(rnd(14)))
                })
                .collect();
            contours.push(c);
        }
        let mut input = Vec::new();
        let mut ids = Vec::new();
        for c in &contours {
            ids.push((input.len()..input.len() + c.len()).collect::<Vec<_>>());
            input.extend(c.iter().map(|&p| vtx(p)));
        }
        for rule in RULES {
            let mut combine = |_, _, _, _| None;
            let arr = arrange(&input, &ids, &mut combine);
            let bounds = classify(&arr.verts, &arr.segs, rule);
            let _ = triangulate(&arr.verts, &bounds);
            let _ = boundaries(&arr.verts, &bounds);
        }
    }
}
