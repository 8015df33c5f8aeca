//! GridMap (METHOD.md §5): self-occlusion-aware lighting from local environment probes.
//!
//! Anchors sit on a 4×4×4 lattice spanning the mesh's bounding box enlarged 1.1× about its centre
//! ([`AnchorPlacement`]): with [`AnchorPlacement::Box`] (METHOD.md §5's decision, the default) on
//! its boundary only, the 8 corners, the two third-points of each of the 12 edges and the four
//! third-points of each of the 6 faces (8 + 24 + 24 = 56); with [`AnchorPlacement::Lattice`] at its
//! 8 interior points too (64), which see into the concavities the box's probes look at from
//! outside. Anchors inside the mesh are skipped. Each anchor gets a local cube map of the global
//! map's face size, rendered by one-step ray tracing against the mesh's BVH: a ray that hits at x
//! with mesh normal n′ carries λ′(x)·E_d(n′) (λ′ the inverse-distance-weighted albedo of the 3
//! surfel centres nearest x, E_d the global irradiance); a ray that misses carries the global
//! map's own texel (the activated base map, i.e. its bilinear lookup at the texel centre). The
//! local maps are prefiltered exactly like the global one (same plan, [`PreparedEnv::new_batch`])
//! and kept texel-major ([`ProbeTexels`]).
//!
//! Shading at a surface point x blends the probes with weights w_k ∝ 1/(‖x − a_k‖² + 1e-6):
//! diffuse irradiance Σ_k w_k E_d,k(n) everywhere; specular Σ_k w_k E_k(ω_r, r) where the mirror
//! ray from x is blocked by the mesh, the global map where it escapes.
//!
//! **Occlusion test.** The probe interface gives the shader's position and direction, not its
//! normal, so the mirror ray starts at x + ε·ω_r (ε = 1e-3 of the mesh's diagonal) and back-facing
//! hits (the ray leaving the mesh, which happens where the surfels lie slightly inside the
//! extracted surface) are stepped through; the first front-facing hit means "occluded".
//!
//! **Gradients.** GridMap is not differentiated (it is rebuilt from the current state on a
//! schedule): the blended parts contribute no gradient to any light, only the correct input
//! gradients (direction, roughness, normal, IoR) of the blended lookups; the escaping specular
//! passes its gradient to the global map as the plain global light would. The dependence of the
//! weights on the surface position is not differentiated (the shader does not take position
//! gradients).
//!
//! Threading: probe rendering is parallel over (anchor, texel row) with rayon, prefiltering and
//! the texel-major interleave over output texels; lookups are read-only and shared by the
//! shader's threads.

use std::sync::Arc;

use glam::DVec3;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::core::envmap::grid::Tap;
use crate::core::envmap::{
    inverse_activate, texel_dir, CubeMap, CubePoint, EnvMapError, LookupJacobian, PrefilterPlan,
    PreparedEnv,
};
use crate::core::filled::filled;
use crate::core::kdtree::KdTree;
use crate::core::mesh::bvh::Bvh;
use crate::core::mesh::TriangleMesh;
use crate::core::surfels::{sigmoid, Surfels};

/// Enlargement of the mesh's bounding box the anchors sit on.
pub const BOX_SCALE: f64 = 1.1;
/// Surfel centres whose albedo is blended at a ray hit.
pub const ALBEDO_NEIGHBOURS: usize = 3;
/// Anchors: the points of a 4×4×4 lattice on the box.
pub const MAX_ANCHORS: usize = 64;
/// Regularizer of the inverse-square anchor weights.
pub const WEIGHT_EPSILON: f64 = 1e-6;
/// Surfels at least this opaque carry the albedo seen by probe rays (all of them when none is).
const ALBEDO_MIN_OPACITY: f64 = 0.1;
/// Start offset of the mirror ray, as a fraction of the mesh's bounding-box diagonal.
const RAY_OFFSET: f64 = 1e-3;
/// Back faces stepped through before a mirror ray is declared escaping.
const MAX_EXITS: usize = 4;

#[derive(Debug, Error)]
pub enum GridMapError {
    #[error("GridMap needs a mesh with triangles")]
    EmptyMesh,
    #[error("GridMap needs surfels (for the albedo seen by probe rays)")]
    NoSurfels,
    #[error("every GridMap anchor lies inside the mesh (is the mesh inside out?)")]
    NoAnchors,
    #[error("the global cube map has face size {cube} but its prefiltered light has {prepared}")]
    SizeMismatch { cube: usize, prepared: usize },
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
}

/// Where GridMap's anchors sit: points of a 4×4×4 lattice spanning the mesh's bounding box
/// enlarged 1.1× about its centre.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[cfg_attr(feature = "openapi", derive(utoipa::ToSchema))]
#[serde(rename_all = "snake_case")]
pub enum AnchorPlacement {
    /// The lattice's boundary, on the box's faces (56; METHOD.md §5, the paper's placement).
    #[default]
    Box,
    /// The whole lattice: the boundary and the 8 interior points (64), where outside the mesh.
    Lattice,
}

/// The anchor candidates of `placement` on the box `[min, max]` enlarged by `scale` about its
/// centre, in a fixed order (lattice order, x fastest).
pub fn anchor_candidates(
    min: DVec3,
    max: DVec3,
    scale: f64,
    placement: AnchorPlacement,
) -> Vec<DVec3> {
    let centre = 0.5 * (min + max);
    let half = 0.5 * (max - min) * scale;
    let lo = centre - half;
    let step = 2.0 * half / 3.0;
    let mut anchors = Vec::with_capacity(MAX_ANCHORS);
    for k in 0..4 {
        for j in 0..4 {
            for i in 0..4 {
                let on_boundary = [i, j, k].iter().any(|&c| c == 0 || c == 3);
                if on_boundary || placement == AnchorPlacement::Lattice {
                    anchors.push(lo + step * DVec3::new(i as f64, j as f64, k as f64));
                }
            }
        }
    }
    anchors
}

/// The candidates that lie outside the mesh.
pub fn outside_anchors(candidates: &[DVec3], bvh: &Bvh) -> Vec<DVec3> {
    candidates
        .iter()
        .copied()
        .filter(|&a| !bvh.contains(a))
        .collect()
}

/// Material seen by probe rays: inverse-distance-weighted albedo (and IoR) of the nearest surfel
/// centres.
pub struct SurfaceMaterial {
    tree: KdTree,
    albedo: Vec<DVec3>,
    ior: Vec<f64>,
}

impl SurfaceMaterial {
    /// From the surfels with opacity ≥ 0.1 (all when none is).
    pub fn from_surfels(surfels: &Surfels) -> Result<Self, GridMapError> {
        let mut chosen: Vec<usize> = (0..surfels.len())
            .filter(|&i| sigmoid(surfels.opacity[i]) >= ALBEDO_MIN_OPACITY)
            .collect();
        if chosen.is_empty() {
            chosen = (0..surfels.len()).collect();
        }
        if chosen.is_empty() {
            return Err(GridMapError::NoSurfels);
        }
        let active: Vec<_> = chosen.iter().map(|&i| surfels.get(i)).collect();
        Ok(SurfaceMaterial {
            tree: KdTree::build(&active.iter().map(|s| s.position).collect::<Vec<_>>()),
            albedo: active.iter().map(|s| s.albedo).collect(),
            ior: active.iter().map(|s| s.ior).collect(),
        })
    }

    /// (λ′, η′) at `x`: weights 1/distance over the [`ALBEDO_NEIGHBOURS`] nearest centres.
    pub fn at(&self, x: DVec3) -> (DVec3, f64) {
        let nearest = self.tree.k_nearest(x, ALBEDO_NEIGHBOURS);
        let mut albedo = DVec3::ZERO;
        let mut ior = 0.0;
        let mut total = 0.0;
        for (i, d2) in nearest {
            let w = 1.0 / d2.sqrt().max(1e-12);
            albedo += w * self.albedo[i];
            ior += w * self.ior[i];
            total += w;
        }
        (albedo / total, ior / total)
    }
}

/// The local cube map seen from `anchor` (stored values, face size of `global_cube`): rays that hit
/// the mesh carry λ′·E_d(n′) of the hit, rays that miss the global map's own stored texel.
pub fn render_probe(
    anchor: DVec3,
    bvh: &Bvh,
    material: &SurfaceMaterial,
    global_cube: &CubeMap,
    global: &PreparedEnv,
) -> CubeMap {
    let size = global_cube.size;
    let mut raw = global_cube.raw.clone();
    raw.par_chunks_mut(size * 3)
        .enumerate()
        .for_each(|(row, values)| {
            let (face, y) = (row / size, row % size);
            for x in 0..size {
                let dir = texel_dir(size, face, x, y);
                if let Some(hit) = bvh.intersect(anchor, dir, f64::INFINITY) {
                    let (albedo, ior) = material.at(hit.position);
                    let radiance = albedo * global.irradiance(hit.normal, ior);
                    for c in 0..3 {
                        values[x * 3 + c] = inverse_activate(radiance[c]);
                    }
                }
            }
        });
    CubeMap { size, raw }
}

/// The probes' prefiltered maps, texel-major: in each buffer (a mip level or an irradiance map),
/// texel `t` of probe `k` is RGB at `(t · K + k) · 3` for `K` probes. A blend reads one texel of
/// every probe, so it reads one contiguous run instead of one scattered texel per probe; the gpu
/// kernels take the same layout.
#[derive(Clone, Debug)]
pub struct ProbeTexels {
    plan: Arc<PrefilterPlan>,
    /// Per mip level, finest first.
    pub levels: Vec<Vec<f64>>,
    /// Per irradiance map.
    pub irradiance: Vec<Vec<f64>>,
}

impl ProbeTexels {
    /// Interleaves the maps of `probes`, all prefiltered with `plan`.
    fn new(probes: &[PreparedEnv], plan: Arc<PrefilterPlan>) -> Self {
        // Per texel (in parallel), its RGB from every probe in turn.
        let interleave = |buffer: &(dyn Fn(&PreparedEnv) -> &[f64] + Sync)| -> Vec<f64> {
            let texels = probes.first().map_or(0, |p| buffer(p).len() / 3);
            let mut out = filled(texels * probes.len() * 3, 0.0);
            out.par_chunks_mut((probes.len() * 3).max(1))
                .enumerate()
                .for_each(|(t, row)| {
                    for (rgb, probe) in row.chunks_exact_mut(3).zip(probes) {
                        rgb.copy_from_slice(&buffer(probe)[t * 3..t * 3 + 3]);
                    }
                });
            out
        };
        ProbeTexels {
            levels: (0..plan.num_levels())
                .map(|l| interleave(&|p: &PreparedEnv| &p.levels[l]))
                .collect(),
            irradiance: (0..plan.num_irradiance_maps())
                .map(|m| interleave(&|p: &PreparedEnv| &p.irradiance[m]))
                .collect(),
            plan,
        }
    }

    /// The plan the probes were prefiltered with.
    pub fn plan(&self) -> &Arc<PrefilterPlan> {
        &self.plan
    }
}

/// Local light probes around a mesh, blended per surface point, over a global environment.
#[derive(Clone, Debug)]
pub struct GridMap {
    anchors: Vec<DVec3>,
    probes: ProbeTexels,
    bvh: Bvh,
    ray_offset: f64,
    pub(crate) global: PreparedEnv,
}

impl GridMap {
    /// Builds the probes at the anchors of `placement` for `mesh`, with the albedo of `surfels`,
    /// lit by the global map (`global_cube` and its prefiltered `global`, prepared with the plan
    /// the probes reuse).
    pub fn build(
        mesh: &TriangleMesh,
        surfels: &Surfels,
        global_cube: &CubeMap,
        global: PreparedEnv,
        placement: AnchorPlacement,
    ) -> Result<Self, GridMapError> {
        let _span =
            tracing::info_span!("gridmap_build", triangles = mesh.triangles.len()).entered();
        if global_cube.size != global.plan().spec.base_size {
            return Err(GridMapError::SizeMismatch {
                cube: global_cube.size,
                prepared: global.plan().spec.base_size,
            });
        }
        let (lo, hi) = mesh.bounds().ok_or(GridMapError::EmptyMesh)?;
        if mesh.triangles.is_empty() {
            return Err(GridMapError::EmptyMesh);
        }
        let bvh = Bvh::build(mesh);
        let anchors = outside_anchors(&anchor_candidates(lo, hi, BOX_SCALE, placement), &bvh);
        if anchors.is_empty() {
            return Err(GridMapError::NoAnchors);
        }
        let material = SurfaceMaterial::from_surfels(surfels)?;
        let cubes: Vec<CubeMap> = {
            let _span = tracing::info_span!("gridmap_probes", anchors = anchors.len()).entered();
            anchors
                .iter()
                .map(|&a| render_probe(a, &bvh, &material, global_cube, &global))
                .collect()
        };
        let locals = PreparedEnv::new_batch(&cubes, global.plan().clone())?;
        let probes = ProbeTexels::new(&locals, global.plan().clone());
        Ok(GridMap {
            anchors,
            probes,
            bvh,
            ray_offset: RAY_OFFSET * (hi - lo).length(),
            global,
        })
    }

    /// Anchor positions (those outside the mesh, in candidate order).
    pub fn anchors(&self) -> &[DVec3] {
        &self.anchors
    }

    /// The prefiltered local maps of the anchors, texel-major.
    pub fn probe_texels(&self) -> &ProbeTexels {
        &self.probes
    }

    /// The BVH of the mesh the probes were rendered against (the occlusion test's).
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// Start offset of the occlusion test's mirror ray along its direction.
    pub fn ray_offset(&self) -> f64 {
        self.ray_offset
    }

    /// The global light used where mirror rays escape (and receiving their gradient).
    pub fn global(&self) -> &PreparedEnv {
        &self.global
    }

    /// Replaces the global light (the learned map moved) without rebuilding the probes.
    pub fn set_global(&mut self, global: PreparedEnv) {
        self.global = global;
    }

    /// Normalized blend weights of the anchors at `x` (written into `out`, one per anchor).
    pub fn weights_into(&self, x: DVec3, out: &mut [f64]) {
        let mut total = 0.0;
        for (w, a) in out.iter_mut().zip(&self.anchors) {
            *w = 1.0 / (x.distance_squared(*a) + WEIGHT_EPSILON);
            total += *w;
        }
        out.iter_mut().for_each(|w| *w /= total);
    }

    /// Normalized blend weights of the anchors at `x`.
    pub fn weights(&self, x: DVec3) -> Vec<f64> {
        let mut w = vec![0.0; self.anchors.len()];
        self.weights_into(x, &mut w);
        w
    }

    /// Whether the mirror ray from `x` along `dir` is blocked by the mesh (see the module docs).
    pub fn occluded(&self, x: DVec3, dir: DVec3) -> bool {
        let Some(dir) = dir.try_normalize() else {
            return false;
        };
        let mut origin = x + self.ray_offset * dir;
        for _ in 0..MAX_EXITS {
            match self.bvh.intersect(origin, dir, f64::INFINITY) {
                None => return false,
                Some(hit) if hit.normal.dot(dir) < 0.0 => return true,
                Some(hit) => origin = hit.position + self.ray_offset * dir,
            }
        }
        false
    }

    /// Blended texel values at `taps` of one buffer of every probe.
    fn blend_taps(
        &self,
        weights: &[f64],
        taps: &[Tap; 4],
        buffer: impl Fn(&ProbeTexels) -> &[f64],
    ) -> [DVec3; 4] {
        let data = buffer(&self.probes);
        let row = weights.len() * 3;
        let mut values = [DVec3::ZERO; 4];
        for (v, &(t, _)) in values.iter_mut().zip(taps) {
            for (rgb, &w) in data[t * row..(t + 1) * row].chunks_exact(3).zip(weights) {
                *v += w * DVec3::new(rgb[0], rgb[1], rgb[2]);
            }
        }
        values
    }

    /// Σ_k w_k E_d,k(n) and its Jacobian in (n, ior).
    pub(crate) fn blended_irradiance(
        &self,
        x: DVec3,
        normal: DVec3,
        ior: f64,
    ) -> (DVec3, LookupJacobian) {
        let mut weights = [0.0; MAX_ANCHORS];
        let weights = &mut weights[..self.anchors.len()];
        self.weights_into(x, weights);
        let plan = self.global.plan();
        let (taps, dw) = plan.irradiance_grid().taps_with_grad(normal);
        let (a, b, t, dt) = plan.irradiance_blend(ior);
        let maps: &[(usize, f64)] = if a == b || t == 0.0 {
            &[(a, 1.0)]
        } else {
            &[(a, 1.0 - t), (b, t)]
        };
        let mut value = DVec3::ZERO;
        let mut jacobian = LookupJacobian::default();
        let mut per_map = [DVec3::ZERO; 2];
        for (m, &(map, scale)) in maps.iter().enumerate() {
            let blended = self.blend_taps(weights, &taps, |l| &l.irradiance[map]);
            accumulate_taps(&taps, &dw, &blended, scale, &mut value, &mut jacobian);
            per_map[m] = weighted_sum(&taps, &blended);
        }
        if maps.len() == 2 {
            jacobian.d_scalar = (per_map[1] - per_map[0]) * dt;
        }
        (value, jacobian)
    }

    /// Σ_k w_k E_k(dir, r) and its Jacobian in (dir, r).
    pub(crate) fn blended_specular(
        &self,
        x: DVec3,
        dir: DVec3,
        roughness: f64,
    ) -> (DVec3, LookupJacobian) {
        let mut weights = [0.0; MAX_ANCHORS];
        let weights = &mut weights[..self.anchors.len()];
        self.weights_into(x, weights);
        let (l0, t, dt) = self.global.level_blend(roughness);
        let grids = &self.global.plan().grids;
        let point = CubePoint::of(dir);
        let mut value = DVec3::ZERO;
        let mut jacobian = LookupJacobian::default();
        let mut per_level = [DVec3::ZERO; 2];
        for (k, (level, scale)) in [(l0, 1.0 - t), (l0 + 1, t)].into_iter().enumerate() {
            let (taps, dw) = grids[level].taps_at(&point);
            let blended = self.blend_taps(weights, &taps, |l| &l.levels[level]);
            accumulate_taps(&taps, &dw, &blended, scale, &mut value, &mut jacobian);
            per_level[k] = weighted_sum(&taps, &blended);
        }
        jacobian.d_scalar = (per_level[1] - per_level[0]) * dt;
        (value, jacobian)
    }
}

/// Adds `scale` × one map's bilinear lookup (tap weights `taps`, their direction gradients `dw`,
/// blended tap values `values`) into `value` and its direction derivatives into `jacobian`.
fn accumulate_taps(
    taps: &[Tap; 4],
    dw: &[DVec3; 4],
    values: &[DVec3; 4],
    scale: f64,
    value: &mut DVec3,
    jacobian: &mut LookupJacobian,
) {
    for ((&(_, w), dw), v) in taps.iter().zip(dw).zip(values) {
        *value += scale * w * *v;
        for (d, dw_i) in jacobian.d_dir.iter_mut().zip(dw.to_array()) {
            *d += (dw_i * scale) * *v;
        }
    }
}

/// Σ_t w_t v_t: one map's bilinear lookup from its blended tap values.
fn weighted_sum(taps: &[Tap; 4], values: &[DVec3; 4]) -> DVec3 {
    taps.iter().zip(values).map(|(&(_, w), v)| w * *v).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::envmap::{activate, NUM_FACES};
    use crate::core::gradcheck::assert_gradient;
    use crate::core::light::LightProbe;
    use crate::pipeline::reconstruction::prefilter_plan;
    use crate::testing::{sphere_surfels, spheres_with_a_gap, two_spheres};

    /// GridMap with the box's anchors (the two spheres' interior lattice points lie inside them,
    /// so both placements give the same 56).
    fn build(
        mesh: &TriangleMesh,
        surfels: &Surfels,
        cube: &CubeMap,
        global: PreparedEnv,
    ) -> GridMap {
        GridMap::build(mesh, surfels, cube, global, AnchorPlacement::Box).unwrap()
    }

    const SIZE: usize = 16;

    /// A smooth, clearly directional sky: bright towards +Z and +X.
    fn sky() -> CubeMap {
        let radiance: Vec<f64> = (0..NUM_FACES * SIZE * SIZE)
            .flat_map(|t| {
                let (face, rest) = (t / (SIZE * SIZE), t % (SIZE * SIZE));
                let d = texel_dir(SIZE, face, rest % SIZE, rest / SIZE);
                let v = 0.2 + 1.5 * d.z.max(0.0) + 0.8 * d.x.max(0.0);
                [v, 0.9 * v, 0.7 * v + 0.1]
            })
            .collect();
        CubeMap::from_radiance(SIZE, &radiance).unwrap()
    }

    fn prepared(cube: &CubeMap, fresnel: bool) -> PreparedEnv {
        PreparedEnv::new(cube, prefilter_plan(SIZE, fresnel, 1).unwrap()).unwrap()
    }

    #[test]
    fn a_probe_whose_rays_all_miss_equals_the_global_map_exactly() {
        let cube = sky();
        let global = prepared(&cube, false);
        let nothing = Bvh::build(&TriangleMesh::default());
        let material =
            SurfaceMaterial::from_surfels(&sphere_surfels(DVec3::ZERO, 1.0, 100, DVec3::ONE))
                .unwrap();
        let probe = render_probe(
            DVec3::new(2.0, 1.0, 0.5),
            &nothing,
            &material,
            &cube,
            &global,
        );
        assert_eq!(probe, cube);
        let local = PreparedEnv::new_batch(&[probe], global.plan().clone()).unwrap();
        assert_eq!(local[0].levels, global.levels);
        assert_eq!(local[0].irradiance, global.irradiance);
    }

    #[test]
    fn a_ray_that_hits_carries_albedo_times_irradiance_of_the_hit() {
        let cube = sky();
        let global = prepared(&cube, false);
        let mesh = TriangleMesh::icosphere(DVec3::ZERO, 1.0, 3);
        let bvh = Bvh::build(&mesh);
        let albedo = DVec3::new(0.2, 0.5, 0.8);
        let material =
            SurfaceMaterial::from_surfels(&sphere_surfels(DVec3::ZERO, 1.0, 2000, albedo)).unwrap();
        let anchor = DVec3::new(2.5, 0.3, -0.2);
        let probe = render_probe(anchor, &bvh, &material, &cube, &global);
        let (mut hits, mut misses) = (0, 0);
        for face in 0..NUM_FACES {
            for y in 0..SIZE {
                for x in 0..SIZE {
                    let t = (face * SIZE + y) * SIZE + x;
                    let got = DVec3::from_slice(&probe.raw[t * 3..t * 3 + 3]);
                    match bvh.intersect(anchor, texel_dir(SIZE, face, x, y), f64::INFINITY) {
                        Some(hit) => {
                            hits += 1;
                            let expected = albedo * global.irradiance(hit.normal, 1.5);
                            let radiance =
                                DVec3::new(activate(got.x), activate(got.y), activate(got.z));
                            assert!(
                                (radiance - expected).abs().max_element() < 1e-9,
                                "{radiance} vs {expected}"
                            );
                            // The bounce differs from the sky behind the sphere.
                            let sky = DVec3::from_slice(&cube.raw[t * 3..t * 3 + 3]);
                            assert!((got - sky).abs().max_element() > 1e-3);
                        }
                        None => {
                            misses += 1;
                            assert_eq!(got, DVec3::from_slice(&cube.raw[t * 3..t * 3 + 3]));
                        }
                    }
                }
            }
        }
        // The sphere (radius 1 at distance ≈ 2.5) covers ~4% of the probe's directions.
        assert!(hits > 30 && misses > 1000, "{hits} hits, {misses} misses");
    }

    #[test]
    fn anchors_are_the_56_lattice_boundary_points_and_inside_ones_are_skipped() {
        let candidates = anchor_candidates(
            DVec3::splat(-1.0),
            DVec3::splat(1.0),
            BOX_SCALE,
            AnchorPlacement::Box,
        );
        assert_eq!(candidates.len(), 56);
        // Coordinates are ±1.1 (box faces) or ±1.1/3 (thirds).
        let corner_count = candidates
            .iter()
            .filter(|a| a.abs().min_element() > 1.0)
            .count();
        assert_eq!(corner_count, 8);
        for a in &candidates {
            assert!((a.abs().max_element() - 1.1).abs() < 1e-12, "{a}");
        }
        // A sphere of radius 1.4 holds the 24 face-third points (|a| ≈ 1.22) but not the corners
        // (1.91) or the edge thirds (1.62).
        let bvh = Bvh::build(&TriangleMesh::icosphere(DVec3::ZERO, 1.4, 3));
        let kept = outside_anchors(&candidates, &bvh);
        assert_eq!(kept.len(), 32);
        assert!(kept.iter().all(|a| a.length() > 1.4));
        // Around its own mesh every anchor is outside.
        let (mesh, surfels) = two_spheres();
        let cube = sky();
        let grid = build(&mesh, &surfels, &cube, prepared(&cube, false));
        assert_eq!(grid.anchors().len(), 56);
    }

    /// `lattice` adds the 8 interior points (coordinates ±1.1/3) to the box's 56, in lattice
    /// order, and skips those inside the mesh like any other.
    #[test]
    fn the_lattice_adds_the_eight_interior_points() {
        let (lo, hi) = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let boundary = anchor_candidates(lo, hi, BOX_SCALE, AnchorPlacement::Box);
        let lattice = anchor_candidates(lo, hi, BOX_SCALE, AnchorPlacement::Lattice);
        assert_eq!(lattice.len(), MAX_ANCHORS);
        let interior: Vec<DVec3> = lattice
            .iter()
            .copied()
            .filter(|a| a.abs().max_element() < 1.0)
            .collect();
        assert_eq!(interior.len(), 8);
        for a in &interior {
            assert!(
                (a.abs() - DVec3::splat(1.1 / 3.0)).abs().max_element() < 1e-12,
                "{a}"
            );
        }
        let others: Vec<DVec3> = lattice
            .iter()
            .copied()
            .filter(|a| a.abs().max_element() >= 1.0)
            .collect();
        assert_eq!(others, boundary);
        // A sphere of radius 0.7 holds the interior points (|a| ≈ 0.64) and nothing else.
        let bvh = Bvh::build(&TriangleMesh::icosphere(DVec3::ZERO, 0.7, 3));
        assert_eq!(outside_anchors(&lattice, &bvh), boundary);
    }

    /// Two small spheres, a light one and a dark one between which the interior anchors lie: a
    /// point of the light sphere facing the dark one gets irradiance closer to the occluded
    /// truth (the sky seen past the dark sphere, integrated by brute force over the hemisphere)
    /// from the lattice's probes than from the box's, which see the gap from outside.
    #[test]
    fn interior_anchors_bring_the_irradiance_of_a_concavity_closer_to_the_truth() {
        let (mesh, surfels) = spheres_with_a_gap();
        let cube = sky();
        let global = prepared(&cube, false);
        let lattice = GridMap::build(
            &mesh,
            &surfels,
            &cube,
            global.clone(),
            AnchorPlacement::Lattice,
        )
        .unwrap();
        let boundary = build(&mesh, &surfels, &cube, global.clone());
        assert_eq!(boundary.anchors().len(), 56);
        assert_eq!(lattice.anchors().len(), 64);
        // On the bright sphere, facing the dark one.
        let x = DVec3::new(0.5, 0.0, 0.0);
        let n = DVec3::X;
        let bvh = Bvh::build(&mesh);
        let steps = 200;
        let mut truth = DVec3::ZERO;
        for i in 0..steps {
            for j in 0..2 * steps {
                // Midpoint rule in (cos θ, φ) about n: dω = d(cos θ) dφ.
                let cos_theta = (i as f64 + 0.5) / steps as f64;
                let phi = std::f64::consts::TAU * (j as f64 + 0.5) / (2 * steps) as f64;
                let sin_theta = (1.0 - cos_theta * cos_theta).sqrt();
                let dir = DVec3::new(cos_theta, sin_theta * phi.cos(), sin_theta * phi.sin());
                let d_omega = (1.0 / steps as f64) * (std::f64::consts::TAU / (2 * steps) as f64);
                if bvh.intersect(x + 1e-6 * dir, dir, f64::INFINITY).is_none() {
                    truth += cube.sample(dir) * cos_theta * d_omega / std::f64::consts::PI;
                }
            }
        }
        let unoccluded = global.irradiance(n, 1.5);
        let (with_box, with_lattice) = (
            boundary.irradiance(x, n, 1.5),
            lattice.irradiance(x, n, 1.5),
        );
        println!(
            "irradiance: sky {unoccluded}, box {with_box}, lattice {with_lattice}, truth {truth}"
        );
        assert!(truth.x < 0.95 * unoccluded.x, "the dark sphere occludes");
        let error = |e: DVec3| (e - truth).abs().element_sum();
        assert!(
            error(with_lattice) < 0.8 * error(with_box),
            "lattice {with_lattice}, box {with_box}, truth {truth}"
        );
    }

    #[test]
    fn weights_are_normalized_and_favour_near_anchors() {
        let (mesh, surfels) = two_spheres();
        let cube = sky();
        let grid = build(&mesh, &surfels, &cube, prepared(&cube, false));
        for x in [
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(3.0, 0.5, -0.7),
            grid.anchors()[7],
        ] {
            let w = grid.weights(x);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            assert!(w.iter().all(|&w| w > 0.0));
            let mut order: Vec<usize> = (0..w.len()).collect();
            order.sort_by(|&a, &b| {
                x.distance(grid.anchors()[a])
                    .total_cmp(&x.distance(grid.anchors()[b]))
            });
            // Inverse-square falloff: w_a / w_b = (‖x − a_b‖² + ε) / (‖x − a_a‖² + ε).
            let d2 = |k: usize| x.distance_squared(grid.anchors()[k]) + WEIGHT_EPSILON;
            let ratio = w[0] / w[5];
            assert!((ratio - d2(5) / d2(0)).abs() < 1e-9 * ratio, "{ratio}");
            // Equidistant anchors (the box is symmetric) may differ by rounding.
            assert!(order.windows(2).all(|p| w[p[0]] >= w[p[1]] * (1.0 - 1e-12)));
        }
        assert!(grid.weights(grid.anchors()[7])[7] > 0.999);
    }

    #[test]
    fn occluded_mirror_rays_use_the_blend_and_escaping_ones_the_global_map() {
        let (mesh, surfels) = two_spheres();
        let cube = sky();
        let global = prepared(&cube, false);
        let grid = build(&mesh, &surfels, &cube, global.clone());
        let r = 0.35;
        // From A's surface toward B: blocked.
        let x = DVec3::new(1.0, 0.0, 0.0);
        let dir = DVec3::new(1.0, 0.05, 0.1);
        assert!(grid.occluded(x, dir));
        let w = grid.weights(x);
        // Each probe prefiltered on its own, as a map of its own.
        let material = SurfaceMaterial::from_surfels(&surfels).unwrap();
        let local = |k: usize| {
            let probe = render_probe(grid.anchors()[k], grid.bvh(), &material, &cube, &global);
            PreparedEnv::new(&probe, global.plan().clone()).unwrap()
        };
        let blend: DVec3 = (0..grid.anchors().len())
            .map(|k| w[k] * local(k).specular(dir, r))
            .sum();
        let got = grid.specular(x, dir, r);
        assert!(
            (got - blend).abs().max_element() < 1e-12,
            "{got} vs {blend}"
        );
        assert!((got - global.specular(dir, r)).length() > 1e-2);
        let mut env_grad = grid.zero_grad();
        grid.specular_backward(x, dir, r, DVec3::ONE, &mut env_grad);
        assert!(env_grad.levels.iter().flatten().all(|&g| g == 0.0));
        // From A's top, straight up: free sky, exactly the global light and its gradient.
        let top = DVec3::new(0.0, 0.0, 1.0);
        let up = DVec3::new(0.1, 0.0, 1.0);
        assert!(!grid.occluded(top, up));
        assert_eq!(grid.specular(top, up, r), global.specular(up, r));
        let mut expected = global.zero_grad();
        let reference = global.specular_backward(up, r, DVec3::ONE, &mut expected);
        let mut env_grad = grid.zero_grad();
        assert_eq!(
            grid.specular_backward(top, up, r, DVec3::ONE, &mut env_grad),
            reference
        );
        assert_eq!(env_grad, expected);
        // A point slightly inside the mesh (surfels below the extracted surface) is not blocked
        // by the surface it sits under.
        assert!(!grid.occluded(DVec3::new(0.0, 0.0, 0.99), up));
        // Diffuse light is darker facing the dark sphere than the sky alone.
        let toward_b = grid.irradiance(x, DVec3::X, 1.5);
        assert!(toward_b.x < global.irradiance(DVec3::X, 1.5).x);
        let mut env_grad = grid.zero_grad();
        grid.irradiance_backward(x, DVec3::X, 1.5, DVec3::ONE, &mut env_grad);
        assert!(env_grad.irradiance.iter().flatten().all(|&g| g == 0.0));
    }

    #[test]
    fn blended_lookup_gradients_match_finite_differences() {
        let (mesh, surfels) = two_spheres();
        let cube = sky();
        for (seed, fresnel) in [(1u64, false), (2, true), (3, true)] {
            use rand::{Rng, SeedableRng};
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let grid = build(&mesh, &surfels, &cube, prepared(&cube, fresnel));
            for _ in 0..6 {
                let x = DVec3::new(
                    rng.random_range(-1.0..4.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                let g = DVec3::new(rng.random(), rng.random(), rng.random());
                let n = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                let ior = rng.random_range(1.35..2.25);
                let mut scratch = grid.zero_grad();
                let (gn, gi) = grid.irradiance_backward(x, n, ior, g, &mut scratch);
                let mut f = |p: &[f64]| grid.irradiance(x, DVec3::from_slice(&p[..3]), p[3]).dot(g);
                assert_gradient(
                    "blended irradiance (n, ior)",
                    &mut f,
                    &[n.x, n.y, n.z, ior],
                    &[gn.x, gn.y, gn.z, gi],
                    1e-7,
                    1e-5,
                    1e-6,
                );
                let r = rng.random_range(0.1..0.95);
                let (gd, gr) = grid.blended_specular(x, n, r).1.backward(g);
                let mut f = |p: &[f64]| {
                    grid.blended_specular(x, DVec3::from_slice(&p[..3]), p[3])
                        .0
                        .dot(g)
                };
                assert_gradient(
                    "blended specular (dir, r)",
                    &mut f,
                    &[n.x, n.y, n.z, r],
                    &[gd.x, gd.y, gd.z, gr],
                    1e-7,
                    1e-5,
                    1e-6,
                );
            }
        }
    }
}
