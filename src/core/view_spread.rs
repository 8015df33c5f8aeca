//! What a quantity measured in every view has of each view's own, as opposed to what it shares
//! with the views that look from nearby: a camera's own error (its pose, its exposure) differs
//! from view to view at random, where what the model has not matched yet (a shape, a highlight)
//! changes smoothly with the direction a view looks from. Threading: none (a few dozen views).

use glam::DVec3;

/// Neighbouring views a view's value is compared with in [`own_part`].
pub const NEIGHBOURS: usize = 3;

/// RMS over the views of each view's value minus the mean value of the [`NEIGHBOURS`] views that
/// look from the nearest directions (`direction`: unit vectors from the object towards each
/// camera), the Euclidean length of the `N` components. Independent values of spread σ per
/// component give about σ·√(N·(1 + 1/NEIGHBOURS)); values that change smoothly from view to view
/// give little. `None` with fewer views than a view and its neighbours.
pub fn own_part<const N: usize>(views: &[(DVec3, [f64; N])]) -> Option<f64> {
    if views.len() <= NEIGHBOURS {
        return None;
    }
    let sum_sq: f64 = views
        .iter()
        .enumerate()
        .map(|(k, (direction, value))| {
            let mut others: Vec<(f64, &[f64; N])> = views
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != k)
                .map(|(_, (d, v))| (-direction.dot(*d), v))
                .collect();
            others.sort_by(|a, b| a.0.total_cmp(&b.0));
            (0..N)
                .map(|c| {
                    let mean = others[..NEIGHBOURS].iter().map(|(_, v)| v[c]).sum::<f64>()
                        / NEIGHBOURS as f64;
                    (value[c] - mean).powi(2)
                })
                .sum::<f64>()
        })
        .sum();
    Some((sum_sq / views.len() as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_that_follows_the_direction_is_nobodys_own() {
        let views: Vec<(DVec3, [f64; 1])> = (0..36)
            .map(|k| {
                let a = k as f64 / 36.0 * std::f64::consts::TAU;
                let d = DVec3::new(a.cos(), a.sin(), 0.0);
                (d, [if k == 7 { 1.0 + d.x } else { d.x }])
            })
            .collect();
        // View 7 stands out by 1; its three neighbours each count a third of it.
        let expected = ((1.0f64 + 3.0 * (1.0f64 / 3.0).powi(2)) / 36.0).sqrt();
        let found = own_part(&views).unwrap();
        assert!(
            (found - expected).abs() < 0.01,
            "{found} against {expected}"
        );
    }
}
