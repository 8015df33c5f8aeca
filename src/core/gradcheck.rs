//! Central finite differences in f64 for verifying hand-written backward passes.
//!
//! Every differentiable operation of the crate is tested by comparing its analytic gradient with
//! `(f(x + h e_i) − f(x − h e_i)) / 2h` over random inputs. Public so integration tests can use it.

/// Numerical gradient of a scalar function by central differences with step `h`.
pub fn numerical_gradient(f: &mut dyn FnMut(&[f64]) -> f64, x: &[f64], h: f64) -> Vec<f64> {
    let mut probe = x.to_vec();
    (0..x.len())
        .map(|i| {
            probe[i] = x[i] + h;
            let up = f(&probe);
            probe[i] = x[i] - h;
            let down = f(&probe);
            probe[i] = x[i];
            (up - down) / (2.0 * h)
        })
        .collect()
}

/// Worst disagreement between an analytic and a numerical gradient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mismatch {
    /// Index of the worst component.
    pub index: usize,
    pub analytic: f64,
    pub numerical: f64,
    /// `|a − n| / max(|a|, |n|, scale_floor)`.
    pub relative_error: f64,
}

/// Compares gradients component-wise with a relative error whose denominator is at least
/// `scale_floor` (so components that are both ~0 do not count as mismatches). Returns the worst one.
pub fn worst_mismatch(analytic: &[f64], numerical: &[f64], scale_floor: f64) -> Mismatch {
    assert_eq!(analytic.len(), numerical.len(), "gradient lengths differ");
    let mut worst = Mismatch {
        index: 0,
        analytic: 0.0,
        numerical: 0.0,
        relative_error: 0.0,
    };
    for (i, (&a, &n)) in analytic.iter().zip(numerical).enumerate() {
        let err = (a - n).abs() / a.abs().max(n.abs()).max(scale_floor);
        if err.is_nan() || err > worst.relative_error {
            worst = Mismatch {
                index: i,
                analytic: a,
                numerical: n,
                relative_error: err,
            };
        }
    }
    worst
}

/// Panics with a readable message when the analytic gradient of `f` at `x` disagrees with central
/// differences by more than `tolerance` (relative, with `scale_floor` as in [`worst_mismatch`]).
pub fn assert_gradient(
    what: &str,
    f: &mut dyn FnMut(&[f64]) -> f64,
    x: &[f64],
    analytic: &[f64],
    h: f64,
    tolerance: f64,
    scale_floor: f64,
) {
    let numerical = numerical_gradient(f, x, h);
    let worst = worst_mismatch(analytic, &numerical, scale_floor);
    assert!(
        worst.relative_error < tolerance,
        "{what}: gradient component {} analytic {:e} vs numerical {:e} (relative error {:e} > {tolerance:e})",
        worst.index,
        worst.analytic,
        worst.numerical,
        worst.relative_error
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepts_a_correct_gradient_and_rejects_a_wrong_one() {
        let mut f = |x: &[f64]| x[0].sin() * x[1] + x[1].powi(3);
        let x = [0.4f64, -1.3];
        let good = [x[0].cos() * x[1], x[0].sin() + 3.0 * x[1] * x[1]];
        assert_gradient("f", &mut f, &x, &good, 1e-6, 1e-6, 1e-9);
        let numerical = numerical_gradient(&mut f, &x, 1e-6);
        let bad = [good[0], good[1] * 1.01];
        let worst = worst_mismatch(&bad, &numerical, 1e-9);
        assert_eq!(worst.index, 1);
        assert!(worst.relative_error > 5e-3);
    }

    #[test]
    fn nan_is_always_the_worst_mismatch() {
        let worst = worst_mismatch(&[1.0, f64::NAN], &[1.0, 2.0], 1e-9);
        assert_eq!(worst.index, 1);
    }
}
