//! Quadric-error simplification of a triangle mesh to the size its detail needs, within a budget:
//! Garland–Heckbert edge collapses as meshoptimizer implements them (the `meshopt` crate), stopped
//! by whichever comes first of a triangle budget and a geometric error limit (absolute, in scene
//! units). A smooth object therefore ends far below the budget (a sphere needs a few thousand
//! triangles to stay within a fraction of a voxel of its dense mesh), a detailed one at the budget.
//!
//! The collapses keep the mesh's topology: a closed mesh stays closed, and the border of an open
//! one is locked in place (no boundary edge is added or moved). Vertex normals are recomputed from
//! the simplified faces; per-triangle material ids survive only when they are all equal (a collapse
//! merges triangles of different ids).
//!
//! Single-threaded (meshoptimizer's simplifier is sequential); about a second per million input
//! triangles.

use glam::DVec3;
use meshopt::SimplifyOptions;

use super::TriangleMesh;

/// When to stop collapsing edges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimplifyTarget {
    /// Most triangles of the result (a mesh already at most this size may still shrink, down to
    /// the error limit).
    pub max_triangles: usize,
    /// Largest geometric deviation a collapse may introduce, in scene units.
    pub max_error: f64,
}

/// What [`TriangleMesh::simplified`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Simplification {
    pub triangles_before: usize,
    pub triangles_after: usize,
    /// The deviation meshoptimizer reports for the result (scene units).
    pub error: f64,
}

impl TriangleMesh {
    /// The mesh simplified to `target` (module doc). A mesh without triangles comes back as it is.
    pub fn simplified(&self, target: SimplifyTarget) -> (TriangleMesh, Simplification) {
        let _span = tracing::info_span!(
            "simplify",
            triangles = self.triangles.len(),
            max_triangles = target.max_triangles,
            max_error = target.max_error
        )
        .entered();
        let before = self.triangles.len();
        let Some((lo, hi)) = self.bounds() else {
            return (
                self.clone(),
                Simplification {
                    triangles_before: before,
                    triangles_after: before,
                    error: 0.0,
                },
            );
        };
        // f32 positions relative to the box centre keep the precision the scene's offset would eat.
        let centre = 0.5 * (lo + hi);
        let positions: Vec<[f32; 3]> = self
            .vertices
            .iter()
            .map(|v| (DVec3::from_array(*v) - centre).as_vec3().to_array())
            .collect();
        let indices: Vec<u32> = self.triangles.iter().flatten().copied().collect();
        let options = SimplifyOptions::LockBorder | SimplifyOptions::ErrorAbsolute;
        let mut error = 0f32;
        // meshoptimizer stops at the first of a size and an error: first down to the error
        // limit, whatever the size; past the budget, again from the dense mesh down to the
        // budget, whatever the error.
        let mut kept = meshopt::simplify_decoder(
            &indices,
            &positions,
            0,
            target.max_error.max(0.0) as f32,
            options,
            Some(&mut error),
        );
        if kept.len() > 3 * target.max_triangles {
            kept = meshopt::simplify_decoder(
                &indices,
                &positions,
                3 * target.max_triangles,
                f32::MAX,
                options,
                Some(&mut error),
            );
        }
        let triangles: Vec<[u32; 3]> = kept.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
        let uniform_id = self
            .material_ids
            .first()
            .filter(|&&id| self.material_ids.iter().all(|&m| m == id));
        let mut mesh = TriangleMesh {
            vertices: self.vertices.clone(),
            normals: Vec::new(),
            material_ids: uniform_id.map_or_else(Vec::new, |&id| vec![id; triangles.len()]),
            triangles,
        };
        mesh.drop_unreferenced_vertices();
        if self.has_normals() {
            mesh.compute_vertex_normals();
        }
        let after = mesh.triangles.len();
        tracing::info!(before, after, error, "simplified the mesh");
        (
            mesh,
            Simplification {
                triangles_before: before,
                triangles_after: after,
                error: f64::from(error),
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::mesh::chamfer_l1_with;

    /// A dense sphere (subdivision 6: 81,920 triangles) reduced to a 2,000-triangle budget (a
    /// tighter one than its error limit would give) keeps its shape: closed, outward, every vertex on the sphere within the error limit's order, and
    /// its Chamfer-L1 distance to the dense one a small fraction of the radius.
    #[test]
    fn a_dense_sphere_fits_its_budget_and_stays_a_closed_sphere() {
        let dense = TriangleMesh::icosphere(DVec3::new(1.0, -2.0, 0.5), 1.0, 6);
        assert_eq!(dense.triangles.len(), 81_920);
        let (coarse, report) = dense.simplified(SimplifyTarget {
            max_triangles: 2_000,
            max_error: 1e-3,
        });
        assert_eq!(report.triangles_before, 81_920);
        assert_eq!(report.triangles_after, coarse.triangles.len());
        assert!(
            coarse.triangles.len() <= 2_000 && coarse.triangles.len() > 1_000,
            "{} triangles",
            coarse.triangles.len()
        );
        assert_eq!(coarse.boundary_edges(), 0);
        assert_eq!(coarse.normals.len(), coarse.vertices.len());
        assert!(coarse.signed_volume() > 0.0);
        let centre = DVec3::new(1.0, -2.0, 0.5);
        for v in &coarse.vertices {
            let r = DVec3::from_array(*v).distance(centre);
            assert!((r - 1.0).abs() < 1e-5, "vertex at radius {r}");
        }
        // 2,000 triangles over a unit sphere lie about 2.5e-3 from it on average.
        let chamfer = chamfer_l1_with(&coarse, &dense, 20_000, 4).unwrap();
        let back = chamfer_l1_with(&dense, &coarse, 20_000, 5).unwrap();
        assert!(chamfer < 4e-3 && back < 4e-3, "Chamfer {chamfer} / {back}");
        assert!(
            report.error > 1e-3 && report.error < 0.01,
            "{}",
            report.error
        );
    }

    /// The error limit stops a smooth mesh well below a generous budget, a tighter limit keeps
    /// more triangles, and a budget below what the limit allows wins.
    #[test]
    fn the_error_limit_sets_the_size_below_the_budget() {
        let dense = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 5);
        let size = |max_triangles, max_error| {
            dense
                .simplified(SimplifyTarget {
                    max_triangles,
                    max_error,
                })
                .0
                .triangles
                .len()
        };
        let (loose, tight) = (size(usize::MAX, 1e-2), size(usize::MAX, 1e-3));
        assert!(loose < 2_000, "{loose}");
        assert!(size(usize::MAX, 1e-6) > tight);
        let capped = size(loose / 2, 1e-2);
        assert!(capped <= loose / 2 && capped > loose / 3, "{capped}");
        assert!(
            tight > 2 * loose && tight < dense.triangles.len(),
            "{tight}"
        );
    }

    /// An open mesh keeps its border exactly: the hemisphere's rim edges are all still there.
    #[test]
    fn an_open_border_is_kept_in_place() {
        let mut half = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 5);
        half.triangles
            .retain(|t| t.iter().all(|&v| half.vertices[v as usize][2] > -1e-9));
        half.drop_unreferenced_vertices();
        half.material_ids = vec![4; half.triangles.len()];
        let rim = half.boundary_edges();
        assert!(rim > 50, "{rim} rim edges");
        let (coarse, _) = half.simplified(SimplifyTarget {
            max_triangles: 500,
            max_error: 0.1,
        });
        assert_eq!(coarse.boundary_edges(), rim);
        assert!(coarse.triangles.len() < half.triangles.len() / 4);
        assert_eq!(coarse.material_ids, vec![4; coarse.triangles.len()]);
        assert!(coarse
            .vertices
            .iter()
            .all(|v| (DVec3::from_array(*v).length() - 1.0).abs() < 1e-6));
    }
}
