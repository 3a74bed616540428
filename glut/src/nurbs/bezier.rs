//! B-spline definitions and their Bézier pieces.
//!
//! A B-spline of order k over n control points has n + k knots; its valid parameter
//! range is [knot[k-1], knot[n]]. Over any interval [a, b] inside one knot span the
//! spline is a polynomial of degree k-1, whose Bézier control points are the spline's
//! blossom at (a, …, a, b, …, b): evaluated here with de Boor's recurrence, taking a
//! different argument at each level.

/// Why a knot vector is refused: GLU's NURBS error numbers 1…5.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KnotError {
    /// Order below 1 or above [`MAX_ORDER`] (error 1).
    Order = 1,
    /// Fewer than 2·order knots (error 2).
    TooFew = 2,
    /// The valid range is empty (error 3).
    EmptyRange = 3,
    /// A knot smaller than its predecessor (error 4).
    Decreasing = 4,
    /// A knot repeated more than `order` times (error 5).
    Multiplicity = 5,
}

/// The largest order accepted, as SGI's GLU.
pub const MAX_ORDER: usize = 24;

/// Checks a knot vector for a spline of `order`, in SGI's order of checks.
pub fn validate(knots: &[f32], order: i64) -> Result<(), KnotError> {
    if order < 1 || order > MAX_ORDER as i64 {
        return Err(KnotError::Order);
    }
    let k = order as usize;
    if knots.len() < 2 * k {
        return Err(KnotError::TooFew);
    }
    let last = knots.len() - 1;
    // SGI's test is one-sided: a range running backwards counts as empty too.
    let span = knots[last - (k - 1)] - knots[k - 1];
    if span < 1e-5 || knots.iter().any(|x| !x.is_finite()) {
        return Err(KnotError::EmptyRange);
    }
    if knots.windows(2).any(|w| w[0] > w[1]) {
        return Err(KnotError::Decreasing);
    }
    // Runs of (nearly) equal knots.
    let mut run = 1;
    for w in knots.windows(2) {
        if w[1] - w[0] < 1e-5 {
            run += 1;
            if run > k {
                return Err(KnotError::Multiplicity);
            }
        } else {
            run = 1;
        }
    }
    Ok(())
}

/// One direction of a spline: order and knots.
#[derive(Clone, Debug)]
pub struct Basis {
    /// The order k.
    pub order: usize,
    /// n + k knots.
    pub knots: Vec<f32>,
}

impl Basis {
    /// Number of control points.
    pub fn count(&self) -> usize {
        self.knots.len() - self.order
    }

    /// The valid parameter range.
    pub fn range(&self) -> (f32, f32) {
        (self.knots[self.order - 1], self.knots[self.count()])
    }

    /// The distinct knots inside the valid range, ends included.
    pub fn breakpoints(&self) -> Vec<f32> {
        let (a, b) = self.range();
        let mut v: Vec<f32> = self
            .knots
            .iter()
            .copied()
            .filter(|&x| x >= a && x <= b)
            .collect();
        v.dedup();
        v
    }

    /// The span l with knot[l] <= a < knot[l+1] holding [a, b], l in k-1 .. n-1.
    fn span(&self, a: f32) -> usize {
        let k = self.order;
        let n = self.count();
        let mut l = k - 1;
        while l + 1 < n && self.knots[l + 1] <= a {
            l += 1;
        }
        l
    }

    /// The weights w[j][i] such that Bézier point j over [a, b] is Σ w[j][i]·P[first+i]:
    /// returns (first, weights), weights k × k.
    pub fn bezier_weights(&self, a: f32, b: f32) -> (usize, Vec<Vec<f64>>) {
        let k = self.order;
        let l = self.span(a);
        let first = l + 1 - k;
        // Local knots T[m] = knot[m + l - (k-1) + 1], m in 0 .. 2k-2.
        let t = |m: usize| f64::from(self.knots[m + l + 2 - k]);
        let (a, b) = (f64::from(a), f64::from(b));
        let mut out = Vec::with_capacity(k);
        for j in 0..k {
            // d[i] as weight vectors over the k local points.
            let mut d: Vec<Vec<f64>> = (0..k)
                .map(|i| (0..k).map(|q| f64::from(u8::from(q == i))).collect())
                .collect();
            for r in 1..k {
                // Arguments: k-1-j copies of a, then j copies of b.
                let u = if r <= k - 1 - j { a } else { b };
                for i in (r..k).rev() {
                    let lo = t(i - 1);
                    let hi = t(i + k - 1 - r);
                    let den = hi - lo;
                    let alpha = if den > 0.0 { (u - lo) / den } else { 0.0 };
                    let prev = d[i - 1].clone();
                    for (x, p) in d[i].iter_mut().zip(prev) {
                        *x = (1.0 - alpha) * p + alpha * *x;
                    }
                }
            }
            out.push(d[k - 1].clone());
        }
        (first, out)
    }
}

/// The Bézier control points (k × dim, f32) of a curve over [a, b] inside one span.
pub fn curve_piece(basis: &Basis, pts: &[f32], dim: usize, a: f32, b: f32) -> Vec<f32> {
    let (first, w) = basis.bezier_weights(a, b);
    let mut out = Vec::with_capacity(basis.order * dim);
    for row in &w {
        for c in 0..dim {
            let s: f64 = row
                .iter()
                .enumerate()
                .map(|(i, &x)| x * f64::from(pts[(first + i) * dim + c]))
                .sum();
            out.push(s as f32);
        }
    }
    out
}

/// The Bézier patch (ks × kt × dim, s outer) of a surface whose control points are
/// `pts[(i * nt + j) * dim + c]`, over [s0, s1] × [t0, t1].
pub fn surface_piece(
    sb: &Basis,
    tb: &Basis,
    pts: &[f32],
    dim: usize,
    s: (f32, f32),
    t: (f32, f32),
) -> Vec<f32> {
    let nt = tb.count();
    let (fs, ws) = sb.bezier_weights(s.0, s.1);
    let (ft, wt) = tb.bezier_weights(t.0, t.1);
    let mut out = Vec::with_capacity(sb.order * tb.order * dim);
    for rs in &ws {
        for rt in &wt {
            for c in 0..dim {
                let mut acc = 0.0f64;
                for (i, &a) in rs.iter().enumerate() {
                    if a == 0.0 {
                        continue;
                    }
                    for (j, &b) in rt.iter().enumerate() {
                        acc += a * b * f64::from(pts[((fs + i) * nt + ft + j) * dim + c]);
                    }
                }
                out.push(acc as f32);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bezier_knots_give_the_points_back() {
        let b = Basis {
            order: 4,
            knots: vec![0., 0., 0., 0., 1., 1., 1., 1.],
        };
        let pts = [0., 0., 1., 2., 3., 2., 4., 0.];
        assert_eq!(curve_piece(&b, &pts, 2, 0.0, 1.0), pts.to_vec());
    }

    #[test]
    fn uniform_quadratic_midpoints() {
        // Uniform quadratic B-spline: the Bézier ends are the midpoints of the legs.
        let b = Basis {
            order: 3,
            knots: vec![0., 1., 2., 3., 4., 5.],
        };
        let pts = [0., 2., 4.];
        assert_eq!(curve_piece(&b, &pts, 1, 2.0, 3.0), vec![1.0, 2.0, 3.0]);
    }

    #[test]
    fn knot_errors() {
        assert_eq!(validate(&[0., 1.], 0), Err(KnotError::Order));
        assert_eq!(validate(&[0., 1., 2.], 2), Err(KnotError::TooFew));
        assert_eq!(validate(&[0., 0., 0., 0.], 2), Err(KnotError::EmptyRange));
        assert_eq!(validate(&[0., 2., 1., 3.], 2), Err(KnotError::EmptyRange));
        assert_eq!(
            validate(&[0., 1., 3., 2., 4., 5.], 2),
            Err(KnotError::Decreasing)
        );
        assert_eq!(
            validate(&[0., 1., 1., 1., 2., 3.], 2),
            Err(KnotError::Multiplicity)
        );
        assert_eq!(validate(&[0., 0., 1., 1.], 2), Ok(()));
    }
}
