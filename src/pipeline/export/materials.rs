//! The learned materials at points of the extracted mesh: the mesh has positions and normals only,
//! the materials live on the surfels. Each point takes an opacity- and distance-weighted mean of
//! the albedo, roughness and IoR of its 8 nearest opaque surfels (all surfels when none is opaque).
//! Also the one IoR that stands for a whole surface (the area-weighted median), since glTF's
//! `KHR_materials_ior` holds one value per material.
//!
//! The same neighbours give the surface's normal where a texture needs it ([`SurfelSampler`]: the
//! surfels' normals, turned to one side and averaged).
//!
//! Used by the glTF export ([`super::gltf`], [`super::bake`]) and the service's material mesh
//! (`phygap-api`). Threading: the neighbour queries run in parallel over the points (rayon).

use glam::DVec3;
use rayon::prelude::*;
use thiserror::Error;

use crate::core::kdtree::KdTree;
use crate::core::mesh::TriangleMesh;
use crate::core::surfels::{Surfel, Surfels};

/// Surfels averaged per point.
pub const NEIGHBOURS: usize = 8;

/// Surfels at least this opaque carry the surface's material (the rest are fading or floaters).
pub const OPAQUE: f64 = 0.5;

/// Why materials could not be transferred.
#[derive(Debug, Error)]
pub enum MaterialError {
    #[error("the model holds no surfels to take materials from")]
    NoSurfels,
}

/// Material values at one point of the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexMaterial {
    /// Linear albedo (the diffuse colour), each channel in [0, 1].
    pub albedo: DVec3,
    /// Perceptual (Disney) roughness in [0, 1], the same as glTF's and three.js's.
    pub roughness: f64,
    /// Index of refraction.
    pub ior: f64,
}

/// The activated surfels of a model, one [`Surfel`] each.
pub fn surfel_list(surfels: &Surfels) -> Vec<Surfel> {
    (0..surfels.len()).map(|i| surfels.get(i)).collect()
}

/// The materials of `points`, each from its nearest surfels (opaque ones when there are any).
pub fn transfer_materials(
    points: &[DVec3],
    surfels: &[Surfel],
) -> Result<Vec<VertexMaterial>, MaterialError> {
    let _span = tracing::info_span!("transfer_materials", points = points.len()).entered();
    let sampler = SurfelSampler::new(surfels)?;
    Ok(sampler
        .sample(points, None)
        .into_iter()
        .map(|(material, _)| material)
        .collect())
}

/// The surfels that carry the surface's material, indexed for nearest-neighbour queries: the
/// opaque ones (all of them when none is).
pub struct SurfelSampler<'a> {
    sources: Vec<&'a Surfel>,
    tree: KdTree,
}

impl<'a> SurfelSampler<'a> {
    /// The sampler of `surfels`; an error when there are none.
    pub fn new(surfels: &'a [Surfel]) -> Result<Self, MaterialError> {
        let opaque: Vec<&Surfel> = surfels.iter().filter(|s| s.opacity >= OPAQUE).collect();
        let sources: Vec<&Surfel> = if opaque.is_empty() {
            surfels.iter().collect()
        } else {
            opaque
        };
        if sources.is_empty() {
            return Err(MaterialError::NoSurfels);
        }
        let centres: Vec<DVec3> = sources.iter().map(|s| s.position).collect();
        let tree = KdTree::build(&centres);
        Ok(SurfelSampler { sources, tree })
    }

    /// Surfels that carry the material.
    pub fn len(&self) -> usize {
        self.sources.len()
    }

    /// Whether there are none (never: [`SurfelSampler::new`] refuses that).
    pub fn is_empty(&self) -> bool {
        self.sources.is_empty()
    }

    /// The material and the surface normal at each of `points`, the same weighted mean of its
    /// [`NEIGHBOURS`] nearest surfels for both. A surfel's normal (its rotation's third column)
    /// has no side, so each is turned toward the point's `reference_normals` entry before the mean
    /// (the reference itself where the mean vanishes); without references the normals returned
    /// are the references' stand-in, +Z, and only the materials mean anything.
    pub fn sample(
        &self,
        points: &[DVec3],
        reference_normals: Option<&[DVec3]>,
    ) -> Vec<(VertexMaterial, DVec3)> {
        points
            .par_iter()
            .enumerate()
            .map(|(i, &p)| {
                let reference = reference_normals.map_or(DVec3::Z, |r| r[i]);
                let nearest = self.tree.k_nearest(p, NEIGHBOURS);
                // A Gaussian falloff whose width is the farthest neighbour's distance: the nearest
                // surfels dominate, and a point between two materials blends them smoothly.
                let width2 = nearest.last().map_or(1.0, |n| n.1).max(1e-12);
                let mut sum = VertexMaterial {
                    albedo: DVec3::ZERO,
                    roughness: 0.0,
                    ior: 0.0,
                };
                let mut normal = DVec3::ZERO;
                let mut total = 0.0;
                for &(index, distance2) in &nearest {
                    let surfel = self.sources[index];
                    let weight = surfel.opacity.max(1e-3) * (-distance2 / (2.0 * width2)).exp();
                    sum.albedo += weight * surfel.albedo;
                    sum.roughness += weight * surfel.roughness;
                    sum.ior += weight * surfel.ior;
                    let axis = surfel.rotation.col(2);
                    normal += weight * axis * axis.dot(reference).signum();
                    total += weight;
                }
                let normal = if reference_normals.is_some() {
                    normal
                        .try_normalize()
                        .filter(|n| n.is_finite())
                        .unwrap_or(reference)
                } else {
                    DVec3::Z
                };
                if total > 0.0 && total.is_finite() {
                    let material = VertexMaterial {
                        albedo: sum.albedo / total,
                        roughness: sum.roughness / total,
                        ior: sum.ior / total,
                    };
                    (material, normal)
                } else {
                    // A point with no finite neighbour (NaN position): the nearest source's values.
                    let s = self.sources[nearest.first().map_or(0, |n| n.0)];
                    let material = VertexMaterial {
                        albedo: s.albedo,
                        roughness: s.roughness,
                        ior: s.ior,
                    };
                    (material, reference)
                }
            })
            .collect()
    }
}

/// The area-weighted median of the per-vertex IoR: each vertex weighs a third of the area of the
/// triangles around it, and the result is the IoR below which half of the surface lies. A median
/// rather than a mean, so that a few vertices with an outlying IoR (a floater, a seam between
/// materials) do not pull the value; weighted by area, so that the marching-cubes tessellation's
/// density does not either. `None` for a mesh without area or a `materials` list of another length.
pub fn area_weighted_median_ior(mesh: &TriangleMesh, materials: &[VertexMaterial]) -> Option<f64> {
    if materials.len() != mesh.vertices.len() {
        return None;
    }
    let mut weights = vec![0.0f64; mesh.vertices.len()];
    for (t, triangle) in mesh.triangles.iter().enumerate() {
        if triangle.iter().any(|&i| i as usize >= weights.len()) {
            return None;
        }
        let [a, b, c] = mesh.triangle_corners(t);
        let third = (b - a).cross(c - a).length() / 6.0;
        if third.is_finite() {
            for &i in triangle {
                weights[i as usize] += third;
            }
        }
    }
    let mut pairs: Vec<(f64, f64)> = materials
        .iter()
        .zip(&weights)
        .filter(|(m, &w)| m.ior.is_finite() && w > 0.0)
        .map(|(m, &w)| (m.ior, w))
        .collect();
    let total: f64 = pairs.iter().map(|p| p.1).sum();
    if pairs.is_empty() || total <= 0.0 {
        return None;
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut below = 0.0;
    for &(ior, weight) in &pairs {
        below += weight;
        if below >= 0.5 * total {
            return Some(ior);
        }
    }
    pairs.last().map(|p| p.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat3, DVec2};

    fn surfel(position: DVec3, albedo: DVec3, roughness: f64, ior: f64, opacity: f64) -> Surfel {
        Surfel {
            position,
            scale: DVec2::splat(0.01),
            rotation: DMat3::IDENTITY,
            opacity,
            albedo,
            roughness,
            ior,
        }
    }

    #[test]
    fn each_vertex_takes_the_material_of_the_surfels_around_it() {
        // A red rough cluster at x = -1 and a blue smooth one at x = +1, plus a transparent
        // floater (green) right on the first vertex that must be ignored.
        let mut surfels = Vec::new();
        for k in 0..10 {
            let jitter = DVec3::new(0.0, 0.01 * k as f64, 0.0);
            surfels.push(surfel(
                DVec3::new(-1.0, 0.0, 0.0) + jitter,
                DVec3::new(0.8, 0.1, 0.1),
                0.9,
                1.4,
                0.95,
            ));
            surfels.push(surfel(
                DVec3::new(1.0, 0.0, 0.0) + jitter,
                DVec3::new(0.1, 0.1, 0.8),
                0.1,
                2.0,
                0.95,
            ));
        }
        surfels.push(surfel(
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            0.5,
            1.7,
            0.05,
        ));
        let points = [DVec3::new(-1.0, 0.0, 0.0), DVec3::new(1.0, 0.05, 0.0)];
        let m = transfer_materials(&points, &surfels).unwrap();
        assert!(
            (m[0].albedo - DVec3::new(0.8, 0.1, 0.1)).length() < 1e-9,
            "{:?}",
            m[0]
        );
        assert!((m[0].roughness - 0.9).abs() < 1e-9 && (m[0].ior - 1.4).abs() < 1e-9);
        assert!(
            (m[1].albedo - DVec3::new(0.1, 0.1, 0.8)).length() < 1e-9,
            "{:?}",
            m[1]
        );
        assert!((m[1].roughness - 0.1).abs() < 1e-9 && (m[1].ior - 2.0).abs() < 1e-9);
        assert!(matches!(
            transfer_materials(&points, &[]),
            Err(MaterialError::NoSurfels)
        ));
    }

    #[test]
    fn the_median_ior_follows_the_surface_area_not_the_vertex_count() {
        // A big sphere (IoR 1.45 on three quarters of its area, 1.6 on the rest) beside a small,
        // finely tessellated one (IoR 2.2) that has more vertices than the big one.
        let big = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 2);
        let small = TriangleMesh::icosphere(DVec3::new(4.0, 0.0, 0.0), 0.2, 4);
        assert!(small.vertices.len() > big.vertices.len());
        let mut mesh = big.clone();
        let offset = mesh.vertices.len() as u32;
        mesh.vertices.extend(&small.vertices);
        mesh.triangles
            .extend(small.triangles.iter().map(|t| t.map(|i| i + offset)));
        let material = |ior| VertexMaterial {
            albedo: DVec3::splat(0.5),
            roughness: 0.3,
            ior,
        };
        let materials: Vec<VertexMaterial> = mesh
            .vertices
            .iter()
            .enumerate()
            .map(|(i, v)| match i < offset as usize {
                true if v[2] > 0.5 => material(1.6),
                true => material(1.45),
                false => material(2.2),
            })
            .collect();
        assert_eq!(area_weighted_median_ior(&mesh, &materials), Some(1.45));
        // An unweighted median would pick the small sphere's value.
        let mut iors: Vec<f64> = materials.iter().map(|m| m.ior).collect();
        iors.sort_by(f64::total_cmp);
        assert_eq!(iors[iors.len() / 2], 2.2);
        assert_eq!(area_weighted_median_ior(&mesh, &materials[1..]), None);
        assert_eq!(
            area_weighted_median_ior(&TriangleMesh::default(), &[]),
            None
        );
    }
}
