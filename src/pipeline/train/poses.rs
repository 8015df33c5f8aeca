//! Pose refinement in a run: each training view's camera is the capture's, moved by the view's
//! learned [`PoseCorrection`] (`TrainState::poses`), and a host step's pose gradient
//! ([`crate::core::raster::RasterGrads::pose`]) updates it by Adam, one optimizer group per view
//! (`pose.<index>`: a view's moments decay only when it is trained).
//!
//! The correction is optimized in coordinates that an image tells apart: a rotation about the
//! object's centre (which turns the object in the image but keeps it in place) and a translation
//! in units of the camera's distance to that centre (which shifts and scales the object's image).
//! A rotation about the camera's own centre would shift the image as a translation does, and the
//! two would trade against each other; about the object's centre, the two parts of a step move
//! the image in different ways, and one rate serves both. The rate starts at `lr_pose` at
//! `refine_views_from` and decays exponentially to 1 % of it by `refine_poses_until`, where the
//! poses stay.
//!
//! Under `pose_refinement: auto` the run decides at `refine_views_from`, once the surfels have a
//! shape, from how far each view's mask lies beside the silhouette it renders
//! ([`super::estimated_poses`]).
//!
//! Nothing holds the corrections' common part during the run: one motion of every camera,
//! matched by the surfels, changes no image. The surfels start from the capture's poses and keep
//! the run near their frame. Taking the common rigid motion out after each update (a projection
//! that is no descent direction while the surfels lag behind the cameras) made the poses drift
//! away on a fixed scene that plain updates bring back to within 0.001°. Instead, at the end of
//! the run, [`PoseRefinement::register`] moves the cameras and the surfels together by the
//! similarity under which the refined cameras see the object as the capture's do.

use glam::DVec3;

use crate::core::camera::Camera;
use crate::core::config::{AutoSwitch, TrainConfig};
use crate::core::envmap::CubeMap;
use crate::core::optim::{Adam, ExponentialLr, OptimError};
use crate::core::pose::{PoseCorrection, PoseGrad};
use crate::core::similarity::Similarity;
use crate::core::surfels::Surfels;

/// The rate at the last step, as a fraction of the first.
const FINAL_RATE_FRACTION: f64 = 0.01;

/// The training views' cameras as the capture gives them, and how their corrections are learned.
pub struct PoseRefinement {
    /// The uncorrected camera of each training view (the run's target order).
    cameras: Vec<Camera>,
    /// The object's centre: the pivot of the corrections' rotations as they are optimized.
    centre: DVec3,
    /// The steps that update the poses, and the rate from the first (`None`: refinement off).
    schedule: Option<(std::ops::Range<u32>, ExponentialLr)>,
    /// `on`, or `auto`: decided when the schedule starts.
    setting: AutoSwitch,
}

impl PoseRefinement {
    pub fn new(config: &TrainConfig, cameras: Vec<Camera>, object_centre: DVec3) -> Self {
        let steps = config.steps();
        let at = |fraction: f64| (fraction * f64::from(steps)).round() as u32;
        let (start, end) = (at(config.refine_views_from), at(config.refine_poses_until));
        let wanted = config.pose_refinement != AutoSwitch::Off;
        let schedule = (wanted && config.lr_pose > 0.0 && start < end).then_some((
            start..end,
            ExponentialLr {
                init: config.lr_pose,
                final_: config.lr_pose * FINAL_RATE_FRACTION,
                steps: end - start,
            },
        ));
        PoseRefinement {
            cameras,
            centre: object_centre,
            schedule,
            setting: config.pose_refinement,
        }
    }

    /// The object's centre the corrections turn about.
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    /// Whether the run may learn corrections at all (under `auto`, if it decides to).
    pub fn enabled(&self) -> bool {
        self.schedule.is_some()
    }

    /// Whether the poses are refined, where no measurement is needed to say: `None` under `auto`
    /// (until [`super::estimated_poses`] decides at the schedule's start).
    pub fn fixed_decision(&self) -> Option<bool> {
        match (&self.schedule, self.setting) {
            (Some(_), AutoSwitch::Auto) => None,
            (Some(_), AutoSwitch::On) => Some(true),
            _ => Some(false),
        }
    }

    /// Whether `auto` decides before iteration `it`, the run not having decided yet.
    pub fn decision_due(&self, it: u32, decided: Option<bool>) -> bool {
        decided.is_none()
            && self
                .schedule
                .as_ref()
                .is_some_and(|(steps, _)| steps.start <= it)
    }

    /// The training views' cameras as the capture gives them.
    pub fn capture_cameras(&self) -> &[Camera] {
        &self.cameras
    }

    /// No correction for each view.
    pub fn identity(&self) -> Vec<PoseCorrection> {
        vec![PoseCorrection::IDENTITY; self.cameras.len()]
    }

    /// Training view `target`'s camera under `poses`.
    pub fn camera(&self, poses: &[PoseCorrection], target: usize) -> Camera {
        match poses.get(target) {
            Some(correction) => correction.apply(&self.cameras[target]),
            None => self.cameras[target],
        }
    }

    /// Every training view's camera under `poses`.
    pub fn cameras(&self, poses: &[PoseCorrection]) -> Vec<Camera> {
        (0..self.cameras.len())
            .map(|k| self.camera(poses, k))
            .collect()
    }

    /// The rate at iteration `it` of a run that has decided `refine`; `None` before refinement
    /// starts or when it is off.
    pub fn rate(&self, it: u32, refine: Option<bool>) -> Option<f64> {
        if refine != Some(true) {
            return None;
        }
        let (steps, rate) = self.schedule.as_ref()?;
        steps.contains(&it).then(|| rate.at(it - steps.start))
    }

    /// Puts the run back in the capture's frame. Refined cameras and the surfels they were fitted
    /// with may have moved together by a similarity, which no training image shows but every
    /// other view does (the test views, a user's new cameras, the mesh's coordinates): the one
    /// under which the refined cameras see the object (its centre and `radius`) as the capture's
    /// cameras do ([`Similarity::between_cameras`]) moves the surfels, the light and the
    /// corrections back. The capture's own errors average out over the views. Returns the motion
    /// applied; `None` (nothing moved) without corrections or a fit.
    pub fn register(
        &self,
        radius: f64,
        surfels: &mut Surfels,
        envmap: &mut CubeMap,
        poses: &mut [PoseCorrection],
    ) -> Option<Similarity> {
        if poses.len() != self.cameras.len() || poses.iter().all(|p| *p == PoseCorrection::IDENTITY)
        {
            return None;
        }
        let refined = self.cameras(poses);
        let motion = Similarity::between_cameras(&refined, &self.cameras, self.centre, radius)?;
        surfels.move_by(&motion);
        *envmap = envmap.rotated(motion.rotation);
        for ((pose, camera), capture) in poses.iter_mut().zip(&refined).zip(&self.cameras) {
            *pose = PoseCorrection::between(capture, &motion.camera(camera));
        }
        Some(motion)
    }

    /// One Adam step on view `target`'s correction with its pose gradient `grad` at `rate`.
    ///
    /// The step is taken in the coordinates of the module's doc: with `p` the object's centre in
    /// the corrected camera's axes and `d = |p|`, a rotation `δω` about `p` and a translation
    /// `d·δu` change the correction by `δω` and `d·δu − δω × p`, so their gradients are
    /// `g_ω + g_τ × p` and `d·g_τ`.
    pub fn update(
        &self,
        adam: &mut Adam,
        poses: &mut [PoseCorrection],
        target: usize,
        grad: &PoseGrad,
        rate: f64,
    ) -> Result<(), OptimError> {
        let p = self.camera(poses, target).to_camera(self.centre);
        let d = p.length().max(1e-9);
        let g_rotation = DVec3::new(grad[0], grad[1], grad[2]);
        let g_translation = DVec3::new(grad[3], grad[4], grad[5]);
        let pivoted = g_rotation + g_translation.cross(p);
        let scaled = [
            pivoted.x,
            pivoted.y,
            pivoted.z,
            d * g_translation.x,
            d * g_translation.y,
            d * g_translation.z,
        ];
        // Adam's moments live in these coordinates; the values are the correction's own, so
        // only the step's displacement is read back.
        let current = poses[target];
        let before: [f64; 6] = {
            let [a, b, c] = current.rotation;
            let [x, y, z] = current.translation;
            [a, b, c, x / d, y / d, z / d]
        };
        let mut values = before;
        adam.step(&format!("pose.{target}"), &mut values, &scaled, rate)?;
        let delta_rotation = DVec3::new(
            values[0] - before[0],
            values[1] - before[1],
            values[2] - before[2],
        );
        let delta_shift = d * DVec3::new(
            values[3] - before[3],
            values[4] - before[4],
            values[5] - before[5],
        );
        let rotation = DVec3::from_array(current.rotation) + delta_rotation;
        let translation =
            DVec3::from_array(current.translation) + delta_shift - delta_rotation.cross(p);
        poses[target] = PoseCorrection {
            rotation: rotation.to_array(),
            translation: translation.to_array(),
        };
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::config::Iterations;
    use crate::core::pose::pose_error;

    fn ring(n: usize) -> Vec<Camera> {
        (0..n)
            .map(|k| {
                let a = k as f64 / n as f64 * std::f64::consts::TAU;
                let eye = DVec3::new(3.0 * a.cos(), 3.0 * a.sin(), 1.0);
                Camera::look_at(32, 32, 0.8, eye, DVec3::ZERO, DVec3::Z)
            })
            .collect()
    }

    fn config() -> TrainConfig {
        TrainConfig {
            iterations: Iterations::Fixed(1000),
            pose_refinement: AutoSwitch::On,
            ..TrainConfig::default()
        }
    }

    #[test]
    fn the_rate_starts_late_and_decays_to_a_hundredth_where_refinement_stops() {
        let config = TrainConfig {
            refine_poses_until: 0.5,
            ..config()
        };
        let refinement = PoseRefinement::new(&config, ring(4), DVec3::ZERO);
        let on = refinement.fixed_decision();
        assert_eq!(on, Some(true));
        assert_eq!(refinement.rate(49, on), None);
        assert!((refinement.rate(50, on).unwrap() - 1e-3).abs() < 1e-15);
        let last = refinement.rate(499, on).unwrap();
        assert!(last > 1e-5 && last < 1.02e-5, "{last}");
        assert_eq!(refinement.rate(500, on), None);
        let off = TrainConfig {
            pose_refinement: AutoSwitch::Off,
            ..config.clone()
        };
        let refinement = PoseRefinement::new(&off, ring(4), DVec3::ZERO);
        assert!(!refinement.enabled());
        assert_eq!(refinement.fixed_decision(), Some(false));
        assert_eq!(refinement.rate(100, Some(true)), None);
        assert!(!refinement.decision_due(100, None));
    }

    #[test]
    fn auto_decides_once_where_refinement_would_start() {
        let config = TrainConfig {
            pose_refinement: AutoSwitch::Auto,
            ..config()
        };
        let refinement = PoseRefinement::new(&config, ring(4), DVec3::ZERO);
        assert_eq!(refinement.fixed_decision(), None);
        assert!(!refinement.decision_due(49, None));
        assert!(refinement.decision_due(50, None));
        assert!(
            refinement.decision_due(700, None),
            "a resumed run decides when it gets there"
        );
        assert!(!refinement.decision_due(50, Some(false)));
        assert_eq!(
            refinement.rate(60, None),
            None,
            "nothing moves before the decision"
        );
        assert_eq!(refinement.rate(60, Some(false)), None);
        assert!(refinement.rate(60, Some(true)).is_some());
    }

    /// A run whose cameras and surfels drifted together by one similarity, each camera with its
    /// own small error on top: registering takes the common motion out of both and leaves each
    /// camera its own error.
    #[test]
    fn registering_takes_the_common_motion_out_of_cameras_and_surfels() {
        use crate::core::surfels::Surfel;
        use glam::{DMat3, DQuat, DVec2};
        use rand::{Rng, SeedableRng};
        let cameras = ring(12);
        let refinement = PoseRefinement::new(&config(), cameras.clone(), DVec3::ZERO);
        let drift = Similarity {
            rotation: DQuat::from_axis_angle(DVec3::new(0.3, -1.0, 0.4).normalize(), 0.01),
            scale: 1.004,
            translation: DVec3::new(0.01, -0.02, 0.005),
        };
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(4);
        let own: Vec<PoseCorrection> = (0..12)
            .map(|_| {
                PoseCorrection::from_array(std::array::from_fn(|_| rng.random_range(-2e-3..2e-3)))
            })
            .collect();
        let drifted: Vec<PoseCorrection> = cameras
            .iter()
            .zip(&own)
            .map(|(c, e)| PoseCorrection::between(c, &drift.camera(&e.apply(c))))
            .collect();
        let mut poses = drifted.clone();
        let surfel = Surfel {
            position: DVec3::new(0.2, 0.1, -0.3),
            scale: DVec2::new(0.02, 0.03),
            rotation: DMat3::IDENTITY,
            opacity: 0.5,
            albedo: DVec3::splat(0.4),
            roughness: 0.3,
            ior: 1.5,
        };
        let mut surfels = Surfels::default();
        surfels.push_activated(&surfel);
        surfels.move_by(&drift);
        let mut envmap = CubeMap::constant(4, DVec3::splat(0.7)).unwrap();
        let motion = refinement
            .register(1.0, &mut surfels, &mut envmap, &mut poses)
            .expect("a motion");
        // The common motion is found to within what the cameras' own errors leave of it.
        assert!(motion.rotation.angle_between(drift.rotation.inverse()) < 2e-3);
        let back = surfels.get(0);
        assert!(back.position.distance(surfel.position) < 5e-3, "{back:?}");
        assert!((back.scale.x / surfel.scale.x - 1.0).abs() < 2e-3);
        let error = |a: &[PoseCorrection]| -> f64 {
            a.iter()
                .zip(&cameras)
                .zip(&own)
                .map(|((p, c), e)| pose_error(&p.apply(c), &e.apply(c)).0)
                .sum::<f64>()
                / 12.0
        };
        assert!(error(&drifted) > 0.5, "the drift is 0.57°");
        assert!(error(&poses) < 0.1, "{}", error(&poses));
        assert!((envmap.texel_radiance(0).x - 0.7).abs() < 1e-9);
        // Nothing to register: no corrections.
        let mut none = refinement.identity();
        assert_eq!(
            refinement.register(1.0, &mut surfels, &mut envmap, &mut none),
            None
        );
    }

    /// Views whose cameras are off by known corrections, and per
    /// view a loss that is the squared pixel distance between points of the object seen by the
    /// corrected and by the true camera, its pose gradient taken by central differences as the
    /// rasterizer's is defined (a correction on top of the current camera): round-robin updates
    /// bring every view to its true pose.
    #[test]
    fn updates_bring_every_view_to_its_true_pose() {
        use rand::{Rng, SeedableRng};
        let cameras = ring(8);
        let refinement = PoseRefinement::new(&config(), cameras.clone(), DVec3::ZERO);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2);
        let truths: Vec<PoseCorrection> = (0..8)
            .map(|_| {
                PoseCorrection::from_array(std::array::from_fn(|_| rng.random_range(-0.01..0.01)))
            })
            .collect();
        let points: Vec<DVec3> = (0..12)
            .map(|_| DVec3::from_array(std::array::from_fn(|_| rng.random_range(-0.8..0.8))))
            .collect();
        let loss = |camera: &Camera, truth: &Camera| -> f64 {
            points
                .iter()
                .map(|&x| {
                    let (u, v, _) = camera.project(x).unwrap();
                    let (a, b, _) = truth.project(x).unwrap();
                    (u - a).powi(2) + (v - b).powi(2)
                })
                .sum()
        };
        let mut poses = refinement.identity();
        let mut adam = Adam::default();
        let visits = 300;
        for step in 0..8 * visits {
            let k = step % 8;
            let current = refinement.camera(&poses, k);
            let truth = truths[k].apply(&cameras[k]);
            let mut f = |x: &[f64]| {
                let delta = PoseCorrection::from_array(x.try_into().unwrap());
                loss(&delta.apply(&current), &truth)
            };
            let g = crate::core::gradcheck::numerical_gradient(&mut f, &[0.0; 6], 1e-7);
            let grad: PoseGrad = g.try_into().unwrap();
            let t = step as f64 / (8 * visits) as f64;
            let rate = 2e-3 * (1e-2f64).powf(t);
            refinement
                .update(&mut adam, &mut poses, k, &grad, rate)
                .unwrap();
        }
        for k in 0..8 {
            let (angle, distance) =
                pose_error(&refinement.camera(&poses, k), &truths[k].apply(&cameras[k]));
            assert!(angle < 0.01, "view {k} off by {angle}°");
            assert!(distance < 1e-3, "view {k} off by {distance}");
        }
    }

    /// Whole host steps on a fixed scene (three spheres of different colours: no pose of the
    /// camera sees the same image as another), the surfels frozen: four views rendered from
    /// true poses and started from poses off by up to 0.6° and 2 % of the distance are brought
    /// back by the pose gradient of the real losses.
    #[test]
    fn host_steps_recover_the_poses_of_a_fixed_scene() {
        use crate::core::brdf_lut::BrdfLut;
        use crate::core::envmap::{MipChainSpec, PrefilterPlan, PreparedEnv};
        use crate::core::events::Stage;
        use crate::core::loss::LossWeights;
        use crate::core::raster::cpu::CpuBackend;
        use crate::core::raster::RasterSettings;
        use crate::core::step::ViewTarget;
        use crate::pipeline::train::host_step::{self, StepInputs};
        use crate::testing::sphere_surfels;
        use rand::{Rng, SeedableRng};
        use std::borrow::Cow;

        let mut surfels = sphere_surfels(DVec3::ZERO, 0.8, 1500, DVec3::new(0.8, 0.6, 0.4));
        for (centre, radius, albedo) in [
            (DVec3::new(1.3, 0.0, 0.2), 0.35, DVec3::new(0.1, 0.2, 0.7)),
            (DVec3::new(-0.3, 1.2, 0.5), 0.3, DVec3::new(0.2, 0.7, 0.2)),
        ] {
            let other = sphere_surfels(centre, radius, 500, albedo);
            for i in 0..other.len() {
                surfels.push_activated(&other.get(i));
            }
        }
        let settings = RasterSettings::default();
        let cameras: Vec<Camera> = (0..4)
            .map(|k| {
                let a = k as f64 * 1.3;
                let eye = DVec3::new(4.5 * a.cos(), 4.5 * a.sin(), 1.5);
                Camera::look_at(64, 64, 0.7, eye, DVec3::new(0.3, 0.3, 0.2), DVec3::Z)
            })
            .collect();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let truths: Vec<PoseCorrection> = (0..4)
            .map(|_| {
                PoseCorrection::from_array(std::array::from_fn(|k| {
                    let size = if k < 3 { 0.01 } else { 0.08 };
                    rng.random_range(-size..size)
                }))
            })
            .collect();
        // The views as the true cameras see them: colour = albedo (plain 2DGS), α-premultiplied.
        let targets: Vec<(Vec<f32>, Vec<f32>)> = cameras
            .iter()
            .zip(&truths)
            .map(|(camera, truth)| {
                let g = CpuBackend
                    .forward(&surfels, &truth.apply(camera), &settings)
                    .unwrap()
                    .gbuffers;
                let photometric = g
                    .albedo
                    .iter()
                    .zip(&g.alpha)
                    .flat_map(|(c, &a)| c.map(|v| (v * a) as f32))
                    .collect();
                (photometric, g.alpha.iter().map(|&a| a as f32).collect())
            })
            .collect();
        let plan = PrefilterPlan::new(MipChainSpec {
            base_size: 8,
            min_size: 4,
            ..MipChainSpec::default()
        })
        .unwrap();
        let env = PreparedEnv::new(&crate::io::model::initial_envmap(8).unwrap(), plan).unwrap();
        let config = TrainConfig {
            iterations: Iterations::Fixed(800),
            pose_refinement: AutoSwitch::On,
            refine_views_from: 0.0,
            lr_pose: 3e-3,
            ..TrainConfig::default()
        };
        let inputs = StepInputs {
            backend: &CpuBackend,
            settings,
            lut: BrdfLut::shared(),
            weights: LossWeights::for_object(&config, 1.0),
        };
        let refinement = PoseRefinement::new(&config, cameras.clone(), DVec3::new(0.3, 0.3, 0.2));
        let mut poses = refinement.identity();
        let mut adam = Adam::default();
        let error = |poses: &[PoseCorrection], k: usize| {
            pose_error(&refinement.camera(poses, k), &truths[k].apply(&cameras[k]))
        };
        let before: Vec<(f64, f64)> = (0..4).map(|k| error(&poses, k)).collect();
        for it in 0..800u32 {
            let k = it as usize % 4;
            let target = ViewTarget {
                view: k,
                photometric: Cow::Borrowed(&targets[k].0),
                stokes: None,
                polarizer: None,
                mask: Cow::Borrowed(&targets[k].1),
                gain: 1.0,
                polarization_confidence: None,
                mask_weight: None,
            };
            let result = host_step::run(
                &inputs,
                &surfels,
                &env,
                &Default::default(),
                &refinement.camera(&poses, k),
                &target,
                [1.0; 3],
                Stage::Geometry,
            )
            .unwrap();
            let rate = refinement.rate(it, Some(true)).unwrap();
            refinement
                .update(&mut adam, &mut poses, k, &result.pose.unwrap(), rate)
                .unwrap();
        }
        for (k, (angle_before, distance_before)) in before.iter().enumerate() {
            let (angle, distance) = error(&poses, k);
            assert!(
                angle < 0.1 * angle_before && distance < 0.2 * distance_before,
                "view {k}: {angle}° and {distance} from {angle_before}° and {distance_before}"
            );
        }
    }
}
