//! Per-surfel projection of a 2D Gaussian surfel into one camera (METHOD.md §3) and its backward.
//!
//! A surfel with centre `c`, tangent axes `a = s_u t_u`, `b = s_v t_v` (all in OpenCV camera axes)
//! maps its local plane coordinates `u = (s, t, 1)` to homogeneous pixels by `M = K [a b c]`.
//! The ray through pixel `(x, y)` meets the surfel plane at `u ∝ adj(M) (x, y, 1)`, so with
//! `p = Q (x, y, 1)`, `Q = adj(M)` (rows: `M1×M2`, `M2×M0`, `M0×M1` as columns) the local coordinates
//! are `s = p.x / p.z`, `t = p.y / p.z`, and the OpenCV z-depth of the intersection is
//! `z = det(M) / p.z` (the homogeneous `w` of `M u`). This is the homogeneous ray–splat
//! transform of 2DGS written through the adjugate: per pixel it is 9 multiply-adds and one division.
//!
//! The screen-space low-pass filter of 2DGS is `ρ_2d = |(x, y) − μ|² / σ²` around the projected
//! centre `μ` (the pinhole projection of the surfel centre), `σ = lowpass_sigma_px`; a pixel uses
//! `ρ = min(s² + t², ρ_2d)` and `G = exp(−ρ / 2)`. As in the 2DGS code, a pixel where the filter
//! wins takes the centre's z-depth instead of the intersection's (so a surfel seen exactly edge-on,
//! whose plane passes through the camera centre, still draws a line at its own depth).
//!
//! The bounding box is exact for the alpha cut: a pixel can reach `α ≥ alpha_min` only where
//! `ρ ≤ 2 ln(o / alpha_min)`; the box is the union of the screen bounding box of that disc on the
//! surfel plane (a projected conic, through the dual conic `M diag(1, 1, −1/r²) Mᵀ`) and the
//! low-pass disc around `μ`. When the disc reaches the camera plane the conic is unbounded and the
//! box is the whole image.
//!
//! Everything is plain per-surfel math; callers parallelize over surfels.

use glam::{DMat3, DVec3};

use super::RasterSettings;
use crate::core::camera::Camera;
use crate::core::pose::PoseGrad;
use crate::core::surfels::{sigmoid, Surfels, IOR_MIN};

/// Number of per-surfel features composited besides depth: normal (3), albedo (3), roughness, IoR.
pub const NUM_FEATURES: usize = 8;

/// A surfel projected into one camera: everything the per-pixel loop needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projected {
    /// Rows of `Q = adj(M)`: `p = (q[0..3]·(x,y,1), q[3..6]·(x,y,1), q[6..9]·(x,y,1))`.
    pub q: [f64; 9],
    /// `det(M)`: the intersection depth is `det / p.z`.
    pub det: f64,
    /// Projected centre `μ` in pixels.
    pub mean: [f64; 2],
    /// Activated opacity.
    pub opacity: f64,
    /// Largest `ρ` whose alpha can reach `alpha_min`: `2 ln(opacity / alpha_min)` (finite).
    pub rho_cut: f64,
    /// World normal facing the camera, albedo (3), roughness, IoR (activated).
    pub features: [f64; NUM_FEATURES],
    /// OpenCV z-depth of the centre (sort key).
    pub view_depth: f64,
    /// Pixel bounding box `[x0, y0, x1, y1)` (end exclusive, clipped to the image, never empty).
    pub rect: [u32; 4],
}

impl Projected {
    /// The activated values [`project_backward`] reads.
    pub fn activations(&self) -> Activations {
        let f = &self.features;
        Activations {
            opacity: self.opacity,
            albedo: [f[3], f[4], f[5]],
            roughness: f[6],
            ior: f[7],
        }
    }
}

/// The activated values of a projected surfel that [`project_backward`] reads, for the
/// derivatives of their sigmoids (σ′ = σ (1 − σ)): what an engine keeps for the backward pass
/// besides the frame of its own per-pixel values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Activations {
    pub opacity: f64,
    pub albedo: [f64; 3],
    pub roughness: f64,
    /// `IOR_MIN + σ(ior)`.
    pub ior: f64,
}

/// Camera quantities shared by every surfel of one projection.
#[derive(Clone, Copy, Debug)]
pub struct ProjectionCamera {
    /// World-to-camera rotation (OpenCV axes).
    pub rotation: DMat3,
    /// World-to-camera translation.
    pub translation: DVec3,
    pub origin: DVec3,
    pub fx: f64,
    pub fy: f64,
    pub cx: f64,
    pub cy: f64,
    pub width: u32,
    pub height: u32,
}

impl ProjectionCamera {
    pub fn new(camera: &Camera) -> Self {
        let (rotation, translation) = camera.world_to_camera_opencv();
        ProjectionCamera {
            rotation,
            translation,
            origin: camera.origin(),
            fx: camera.fx,
            fy: camera.fy,
            cx: camera.cx,
            cy: camera.cy,
            width: camera.width,
            height: camera.height,
        }
    }
}

/// Intermediate values of the projection of one surfel, shared by forward and backward.
struct Geometry {
    /// Raw quaternion norm and the normalized quaternion (w, x, y, z).
    q_norm: f64,
    q_unit: [f64; 4],
    /// Activated rotation (columns t_u, t_v, normal).
    rot: DMat3,
    scale: [f64; 2],
    /// Camera-space tangent axes scaled, and centre.
    a: DVec3,
    b: DVec3,
    c: DVec3,
    /// Rows of M.
    m: [DVec3; 3],
    /// `+1` when the surfel normal already faces the camera, else `−1`.
    normal_sign: f64,
}

fn geometry(surfels: &Surfels, i: usize, cam: &ProjectionCamera) -> Geometry {
    let p = DVec3::from_array(surfels.position[i]);
    let [w, x, y, z] = surfels.rotation[i];
    let q_norm = (w * w + x * x + y * y + z * z).sqrt();
    let q_unit = [w / q_norm, x / q_norm, y / q_norm, z / q_norm];
    let rot = rotation_from_unit(q_unit);
    let scale = [surfels.log_scale[i][0].exp(), surfels.log_scale[i][1].exp()];
    let a = scale[0] * (cam.rotation * rot.x_axis);
    let b = scale[1] * (cam.rotation * rot.y_axis);
    let c = cam.rotation * p + cam.translation;
    let m2 = DVec3::new(a.z, b.z, c.z);
    let m0 = cam.fx * DVec3::new(a.x, b.x, c.x) + cam.cx * m2;
    let m1 = cam.fy * DVec3::new(a.y, b.y, c.y) + cam.cy * m2;
    let normal_sign = if rot.z_axis.dot(p - cam.origin) > 0.0 {
        -1.0
    } else {
        1.0
    };
    Geometry {
        q_norm,
        q_unit,
        rot,
        scale,
        a,
        b,
        c,
        m: [m0, m1, m2],
        normal_sign,
    }
}

/// Rotation matrix of a unit quaternion (w, x, y, z).
fn rotation_from_unit([w, x, y, z]: [f64; 4]) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y + w * z),
            2.0 * (x * z - w * y),
        ),
        DVec3::new(
            2.0 * (x * y - w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z + w * x),
        ),
        DVec3::new(
            2.0 * (x * z + w * y),
            2.0 * (y * z - w * x),
            1.0 - 2.0 * (x * x + y * y),
        ),
    )
}

/// Gradient of `Σ G_ij R_ij` with respect to the unit quaternion (w, x, y, z) of `R`.
fn rotation_backward([w, x, y, z]: [f64; 4], g: DMat3) -> [f64; 4] {
    // g.col(j)[i] = G_ij
    let gm = |i: usize, j: usize| g.col(j)[i];
    let (g00, g01, g02) = (gm(0, 0), gm(0, 1), gm(0, 2));
    let (g10, g11, g12) = (gm(1, 0), gm(1, 1), gm(1, 2));
    let (g20, g21, g22) = (gm(2, 0), gm(2, 1), gm(2, 2));
    [
        2.0 * (-z * g01 + y * g02 + z * g10 - x * g12 - y * g20 + x * g21),
        2.0 * (y * g01 + z * g02 + y * g10 - 2.0 * x * g11 - w * g12 + z * g20 + w * g21
            - 2.0 * x * g22),
        2.0 * (-2.0 * y * g00 + x * g01 + w * g02 + x * g10 + z * g12 - w * g20 + z * g21
            - 2.0 * y * g22),
        2.0 * (-2.0 * z * g00 - w * g01 + x * g02 + w * g10 - 2.0 * z * g11
            + y * g12
            + x * g20
            + y * g21),
    ]
}

/// Screen interval `[lo, hi]` of the tangent lines `x = const` of the conic whose dual has
/// entries `c00 = Mi·D·Mi`, `c02 = Mi·D·M2`, `c22 = M2·D·M2`; `None` when unbounded.
fn conic_extent(c00: f64, c02: f64, c22: f64) -> Option<(f64, f64)> {
    if c22.is_nan() || c22 >= 0.0 {
        return None;
    }
    let disc = (c02 * c02 - c00 * c22).max(0.0).sqrt();
    let r0 = (c02 + disc) / c22;
    let r1 = (c02 - disc) / c22;
    (r0.is_finite() && r1.is_finite()).then(|| (r0.min(r1), r0.max(r1)))
}

/// First and one-past-last pixel index whose centre `i + 0.5` lies in `[lo, hi]`, clipped to `n`.
fn pixel_span(lo: f64, hi: f64, n: u32) -> (u32, u32) {
    let first = (lo - 0.5).ceil().max(0.0);
    let last = (hi - 0.5).floor() + 1.0;
    let first = if first.is_nan() { 0.0 } else { first };
    let last = if last.is_nan() { 0.0 } else { last };
    (first.min(n as f64) as u32, last.clamp(0.0, n as f64) as u32)
}

/// Projects surfel `i`; `None` when it cannot cover any pixel (behind the near plane, too
/// transparent, off screen, degenerate or non-finite).
pub fn project(
    surfels: &Surfels,
    i: usize,
    cam: &ProjectionCamera,
    settings: &RasterSettings,
) -> Option<Projected> {
    let opacity = sigmoid(surfels.opacity[i]);
    if opacity.is_nan() || opacity < settings.alpha_min || opacity <= 0.0 {
        return None;
    }
    let geo = geometry(surfels, i, cam);
    if geo.c.z.is_nan() || geo.c.z <= settings.near {
        return None;
    }
    let [m0, m1, m2] = geo.m;
    let px = m1.cross(m2);
    let py = m2.cross(m0);
    let pc = m0.cross(m1);
    let det = m2.dot(pc);
    let q = [
        px.x, py.x, pc.x, //
        px.y, py.y, pc.y, //
        px.z, py.z, pc.z,
    ];
    let mean = [
        cam.fx * geo.c.x / geo.c.z + cam.cx,
        cam.fy * geo.c.y / geo.c.z + cam.cy,
    ];
    let normal = geo.normal_sign * geo.rot.z_axis;
    let albedo = surfels.albedo[i].map(sigmoid);
    let features = [
        normal.x,
        normal.y,
        normal.z,
        albedo[0],
        albedo[1],
        albedo[2],
        sigmoid(surfels.roughness[i]),
        IOR_MIN + sigmoid(surfels.ior[i]),
    ];
    let finite = q.iter().all(|v| v.is_finite())
        && det.is_finite()
        && mean.iter().all(|v| v.is_finite())
        && features.iter().all(|v| v.is_finite());
    if !finite {
        return None;
    }

    // Alpha cut: α = o·G ≥ alpha_min  ⇔  ρ ≤ 2 ln(o / alpha_min).
    // Kept finite so that `ρ ≤ rho_cut` also rejects ρ = ∞ (a ray parallel to the plane).
    let rho_cut = if settings.alpha_min > 0.0 {
        (2.0 * (opacity / settings.alpha_min).ln()).min(f64::MAX)
    } else {
        f64::MAX
    };
    let radius = rho_cut.sqrt();
    let (w, h) = (cam.width, cam.height);
    let full = (0.0, w as f64, 0.0, h as f64);
    let (mut xlo, mut xhi, mut ylo, mut yhi) = if radius.is_finite() {
        let d = DVec3::new(1.0, 1.0, -1.0 / (radius * radius));
        let dot = |u: DVec3, v: DVec3| (u * d).dot(v);
        let c22 = dot(m2, m2);
        match (
            conic_extent(dot(m0, m0), dot(m0, m2), c22),
            conic_extent(dot(m1, m1), dot(m1, m2), c22),
        ) {
            (Some((x0, x1)), Some((y0, y1))) => (x0, x1, y0, y1),
            _ => full,
        }
    } else {
        full
    };
    if settings.lowpass_sigma_px > 0.0 {
        let r2d = settings.lowpass_sigma_px * radius;
        let r2d = if r2d.is_finite() { r2d } else { f64::MAX };
        xlo = xlo.min(mean[0] - r2d);
        xhi = xhi.max(mean[0] + r2d);
        ylo = ylo.min(mean[1] - r2d);
        yhi = yhi.max(mean[1] + r2d);
    }
    let (x0, x1) = pixel_span(xlo, xhi, w);
    let (y0, y1) = pixel_span(ylo, yhi, h);
    if x0 >= x1 || y0 >= y1 {
        return None;
    }
    Some(Projected {
        q,
        det,
        mean,
        opacity,
        rho_cut,
        features,
        view_depth: geo.c.z,
        rect: [x0, y0, x1, y1],
    })
}

/// Gradient of the loss with respect to one surfel's [`Projected`] values (summed over pixels).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProjectedGrad {
    pub q: [f64; 9],
    pub det: f64,
    pub mean: [f64; 2],
    pub opacity: f64,
    pub features: [f64; NUM_FEATURES],
    /// On the centre's view depth (the depth of low-pass filter hits).
    pub view_depth: f64,
}

impl ProjectedGrad {
    pub fn add(&mut self, other: &ProjectedGrad) {
        for (a, b) in self.q.iter_mut().zip(&other.q) {
            *a += b;
        }
        self.det += other.det;
        self.mean[0] += other.mean[0];
        self.mean[1] += other.mean[1];
        self.opacity += other.opacity;
        self.view_depth += other.view_depth;
        for (a, b) in self.features.iter_mut().zip(&other.features) {
            *a += b;
        }
    }
}

/// Raw-parameter gradient of one surfel, in the layout of one row of [`Surfels`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RawGrad {
    pub position: [f64; 3],
    pub log_scale: [f64; 2],
    pub rotation: [f64; 4],
    pub opacity: f64,
    pub albedo: [f64; 3],
    pub roughness: f64,
    pub ior: f64,
    /// `|dL/dμ|`: the loss gradient with respect to a screen-space translation of the whole
    /// projected surfel (its footprint and its low-pass centre together), in 1/pixels.
    pub mean2d_norm: f64,
    /// This surfel's share of the gradient on the view's pose correction at zero
    /// ([`crate::core::pose`]): rotation, then translation, in the camera's OpenCV axes.
    pub pose: PoseGrad,
}

/// Chains the gradient on the projected values of surfel `index` back to its raw parameters
/// (`activations`: those its projection computed).
pub fn project_backward(
    surfels: &Surfels,
    index: usize,
    activations: &Activations,
    cam: &ProjectionCamera,
    grad: &ProjectedGrad,
) -> RawGrad {
    let geo = geometry(surfels, index, cam);
    let [m0, m1, m2] = geo.m;
    let px = m1.cross(m2);
    let py = m2.cross(m0);
    let pc = m0.cross(m1);
    let g = &grad.q;
    // Column j of Q (coefficient of x, y, 1): gradient vectors over the three rows of p.
    let gpx = DVec3::new(g[0], g[3], g[6]);
    let gpy = DVec3::new(g[1], g[4], g[7]);
    let gpc = DVec3::new(g[2], g[5], g[8]);
    // Px = M1×M2, Py = M2×M0, Pc = M0×M1, det = M0·Px.
    let gm0 = gpy.cross(m2) + m1.cross(gpc) + grad.det * px;
    let gm1 = m2.cross(gpx) + gpc.cross(m0) + grad.det * py;
    let gm2 = gpx.cross(m1) + m0.cross(gpy) + grad.det * pc;

    // Screen translation by δ: M0 += δx M2, M1 += δy M2, μ += δ.
    let mean2d = [gm0.dot(m2) + grad.mean[0], gm1.dot(m2) + grad.mean[1]];

    // M0 = fx (a.x, b.x, c.x) + cx M2, M1 = fy (a.y, b.y, c.y) + cy M2, M2 = (a.z, b.z, c.z).
    let col = |k: usize| {
        DVec3::new(
            cam.fx * gm0[k],
            cam.fy * gm1[k],
            cam.cx * gm0[k] + cam.cy * gm1[k] + gm2[k],
        )
    };
    let ga = col(0);
    let gb = col(1);
    let mut gc = col(2);
    let c = geo.c;
    gc.x += cam.fx * grad.mean[0] / c.z;
    gc.y += cam.fy * grad.mean[1] / c.z;
    gc.z -= (cam.fx * c.x * grad.mean[0] + cam.fy * c.y * grad.mean[1]) / (c.z * c.z);
    gc.z += grad.view_depth;

    // A correction (ω, τ) moves a, b, c by ω × a, ω × b, ω × c + τ.
    let pose_rotation = geo.a.cross(ga) + geo.b.cross(gb) + c.cross(gc);
    let pose = [
        pose_rotation.x,
        pose_rotation.y,
        pose_rotation.z,
        gc.x,
        gc.y,
        gc.z,
    ];

    let wt = cam.rotation.transpose();
    let position = (wt * gc).to_array();
    let log_scale = [ga.dot(geo.a), gb.dot(geo.b)];
    let g_tu = geo.scale[0] * (wt * ga);
    let g_tv = geo.scale[1] * (wt * gb);
    let f = &grad.features;
    let g_tn = geo.normal_sign * DVec3::new(f[0], f[1], f[2]);
    let g_unit = rotation_backward(geo.q_unit, DMat3::from_cols(g_tu, g_tv, g_tn));
    let qu = geo.q_unit;
    let proj: f64 = (0..4).map(|k| qu[k] * g_unit[k]).sum();
    let rotation = std::array::from_fn(|k| (g_unit[k] - qu[k] * proj) / geo.q_norm);

    // sigmoid' = σ (1 − σ), from the activated values the projection kept.
    let dsig = |s: f64| s * (1.0 - s);
    let act = activations;
    RawGrad {
        position,
        log_scale,
        rotation,
        opacity: grad.opacity * dsig(act.opacity),
        albedo: [
            f[3] * dsig(act.albedo[0]),
            f[4] * dsig(act.albedo[1]),
            f[5] * dsig(act.albedo[2]),
        ],
        roughness: f[6] * dsig(act.roughness),
        ior: f[7] * dsig(act.ior - IOR_MIN),
        mean2d_norm: (mean2d[0] * mean2d[0] + mean2d[1] * mean2d[1]).sqrt(),
        pose,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::surfels::rotation_matrix;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn unit_rotation_matches_the_surfel_activation() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..20 {
            let q: [f64; 4] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
            let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
            let r = rotation_from_unit(q.map(|v| v / n));
            assert!(r.abs_diff_eq(rotation_matrix(q), 1e-12));
        }
    }

    #[test]
    fn rotation_backward_matches_finite_differences() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for _ in 0..5 {
            let q: [f64; 4] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
            let g = DMat3::from_cols_array(&std::array::from_fn(|_| rng.random_range(-1.0..1.0)));
            let mut f = |x: &[f64]| {
                let r = rotation_from_unit([x[0], x[1], x[2], x[3]]);
                (0..3).map(|j| r.col(j).dot(g.col(j))).sum::<f64>()
            };
            let analytic = rotation_backward(q, g);
            crate::core::gradcheck::assert_gradient(
                "rotation", &mut f, &q, &analytic, 1e-6, 1e-7, 1e-9,
            );
        }
    }

    #[test]
    fn exact_box_contains_the_centre_and_matches_a_fronto_parallel_disc() {
        // Camera at the origin looking down −Z (OpenGL) = +z OpenCV; surfel at z = 4 facing it.
        let camera = Camera::look_at(64, 64, 1.0, DVec3::ZERO, -DVec3::Z, DVec3::Y);
        let cam = ProjectionCamera::new(&camera);
        let mut s = Surfels::zeros(1);
        s.position[0] = [0.0, 0.0, -4.0];
        s.rotation[0] = [1.0, 0.0, 0.0, 0.0];
        s.log_scale[0] = [0.2f64.ln(), 0.2f64.ln()];
        s.opacity[0] = 2.0;
        let settings = RasterSettings {
            lowpass_sigma_px: 0.0,
            ..RasterSettings::default()
        };
        let p = project(&s, 0, &cam, &settings).unwrap();
        let o = sigmoid(2.0);
        let r = (2.0 * (o * 255.0).ln()).sqrt();
        let half = camera.fx * 0.2 * r / 4.0;
        let (x0, x1) = pixel_span(32.0 - half, 32.0 + half, 64);
        assert_eq!(p.rect, [x0, x0, x1, x1]);
        assert!((p.mean[0] - 32.0).abs() < 1e-12 && (p.mean[1] - 32.0).abs() < 1e-12);
        // Depth at the centre pixel direction: det / p.z.
        let pz = p.q[6] * 32.0 + p.q[7] * 32.0 + p.q[8];
        assert!((p.det / pz - 4.0).abs() < 1e-12);
    }
}
