//! Synthetic full-Stokes captures rendered by the project's own PolarDR: analytic shapes (sphere,
//! torus) ray-marched through their signed distance, lit by a procedural HDR sky, written in the
//! capture format with ground-truth G-buffers. They make README's main command and the core's
//! tests work on a fresh clone without `../shared`.
//!
//! Threading: views are rendered in parallel with rayon, one view per task.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use glam::DVec3;
use rayon::prelude::*;
use serde_json::json;
use thiserror::Error;

use crate::brdf_lut::BrdfLut;
use crate::camera::Camera;
use crate::envmap::{CubeMap, EnvMapError, PreparedEnv, WorldUp};
use crate::image_io::{self, Image, ImageError};
use crate::reconstruction::prefilter_plan;
use crate::shading::{self, PixelInput};

/// Face size of the cube maps the synthetic views are lit by.
const ENV_FACE_SIZE: usize = 64;

/// The analytic object of a synthetic capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    /// Unit sphere (convex).
    Sphere,
    /// Torus of radii 0.7 and 0.3 lying in the XY plane (concave, self-occluding).
    Torus,
}

/// What to render.
#[derive(Clone, Debug)]
pub struct SynthOptions {
    pub shape: Shape,
    /// Number of views; every 8th (index % 8 == 0) is a test view.
    pub views: usize,
    /// Square image size in pixels.
    pub size: u32,
    /// Linear albedo, GGX roughness r (α = r²) and IoR of the material.
    pub albedo: DVec3,
    pub roughness: f64,
    pub ior: f64,
}

impl Default for SynthOptions {
    fn default() -> Self {
        SynthOptions {
            shape: Shape::Sphere,
            views: 24,
            size: 96,
            albedo: DVec3::new(0.55, 0.2, 0.08),
            roughness: 0.3,
            ior: 1.5,
        }
    }
}

#[derive(Debug, Error)]
pub enum SynthError {
    #[error("synth: {0}")]
    Invalid(String),
    #[error("synth: cannot write {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error(transparent)]
    Image(#[from] ImageError),
    #[error(transparent)]
    EnvMap(#[from] EnvMapError),
}

/// Signed distance to the shape (negative inside).
fn signed_distance(shape: Shape, p: DVec3) -> f64 {
    match shape {
        Shape::Sphere => p.length() - 1.0,
        Shape::Torus => {
            let ring = (p.x * p.x + p.y * p.y).sqrt() - 0.7;
            (ring * ring + p.z * p.z).sqrt() - 0.3
        }
    }
}

/// Outward unit normal of the shape at a surface point.
fn surface_normal(shape: Shape, p: DVec3) -> DVec3 {
    match shape {
        Shape::Sphere => p.normalize(),
        Shape::Torus => {
            let radial = DVec3::new(p.x, p.y, 0.0).normalize_or_zero() * 0.7;
            (p - radial).normalize()
        }
    }
}

/// First hit of a ray with the shape by sphere tracing inside the bounding sphere of radius 1.05.
pub(crate) fn trace(shape: Shape, origin: DVec3, dir: DVec3) -> Option<f64> {
    // Enter the bounding sphere analytically, then march.
    let b = origin.dot(dir);
    let c = origin.length_squared() - 1.05 * 1.05;
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    let (t_in, t_out) = (-b - disc.sqrt(), -b + disc.sqrt());
    let mut t = t_in.max(0.0);
    for _ in 0..256 {
        let d = signed_distance(shape, origin + dir * t);
        if d.abs() < 1e-9 {
            return Some(t);
        }
        t += d;
        if t > t_out {
            return None;
        }
    }
    Some(t)
}

/// A procedural HDR sky (Z up) as a lat-long image in the capture format's mapping: a blue
/// gradient, a dim ground, and a small bright "sun" at `sun_dir`.
pub fn procedural_sky(height: usize, sun_dir: DVec3, sun_radiance: f64) -> Image {
    let width = 2 * height;
    let sun = sun_dir.normalize();
    Image::from_fn(width, height, 3, |j, i, out| {
        let theta = PI * i as f64 / (height - 1) as f64;
        let phi = 2.0 * PI * (j as f64 + 0.5) / width as f64;
        let d = DVec3::new(
            theta.sin() * phi.sin(),
            theta.sin() * phi.cos(),
            theta.cos(),
        );
        let up = d.z;
        let mut c = if up > 0.0 {
            DVec3::new(0.35, 0.55, 0.9).lerp(DVec3::new(0.9, 0.95, 1.0), (1.0 - up).powi(3)) * 1.2
        } else {
            DVec3::new(0.25, 0.2, 0.15) * (0.6 + 0.4 * (1.0 + up))
        };
        let cos_sun = d.dot(sun);
        if cos_sun > (6.0f64).to_radians().cos() {
            c += DVec3::splat(sun_radiance);
        } else {
            c += DVec3::splat(0.25 * sun_radiance * (-(1.0 - cos_sun) * 40.0).exp());
        }
        out[0] = c.x as f32;
        out[1] = c.y as f32;
        out[2] = c.z as f32;
    })
}

/// The cameras of a synthetic capture: a Fibonacci spiral at distance 4, elevations −10°…70°.
pub fn spiral_cameras(views: usize, size: u32) -> Vec<Camera> {
    let golden = PI * (3.0 - 5f64.sqrt());
    (0..views)
        .map(|k| {
            let t = (k as f64 + 0.5) / views as f64;
            let elevation = (-10.0 + 80.0 * t).to_radians();
            let azimuth = golden * k as f64;
            let eye = 4.0
                * DVec3::new(
                    elevation.cos() * azimuth.cos(),
                    elevation.cos() * azimuth.sin(),
                    elevation.sin(),
                );
            Camera::look_at(size, size, 40f64.to_radians(), eye, DVec3::ZERO, DVec3::Z)
        })
        .collect()
}

/// Rendered images of one view: Stokes, mask and ground-truth buffers.
struct ViewImages {
    s: [Image; 3],
    mask: Image,
    normal: Image,
    depth: Image,
    albedo: Image,
    roughness: Image,
    ior: Image,
}

fn render_view(
    options: &SynthOptions,
    camera: &Camera,
    env: &PreparedEnv,
    lut: &BrdfLut,
) -> ViewImages {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let mut v = ViewImages {
        s: std::array::from_fn(|_| Image::filled(w, h, 3, 0.0)),
        mask: Image::filled(w, h, 1, 0.0),
        normal: Image::filled(w, h, 3, 0.0),
        depth: Image::filled(w, h, 1, 0.0),
        albedo: Image::filled(w, h, 3, 0.0),
        roughness: Image::filled(w, h, 1, 0.0),
        ior: Image::filled(w, h, 1, 0.0),
    };
    let origin = camera.origin();
    for j in 0..h {
        for i in 0..w {
            let d = camera.pixel_dir(i as u32, j as u32);
            let Some(t) = trace(options.shape, origin, d) else {
                continue;
            };
            let p = origin + d * t;
            let n = surface_normal(options.shape, p);
            let (stokes_x, stokes_y) = camera.stokes_frame(d);
            let input = PixelInput {
                position: p,
                normal: n,
                view: -d,
                stokes_x,
                stokes_y,
                albedo: options.albedo,
                roughness: options.roughness,
                ior: options.ior,
            };
            let out = shading::shade(&input, env, lut);
            let px = j * w + i;
            for (img, val) in v.s.iter_mut().zip([out.s0, out.s1, out.s2]) {
                img.data[px * 3..px * 3 + 3].copy_from_slice(&val.as_vec3().to_array());
            }
            v.mask.data[px] = 1.0;
            v.normal.data[px * 3..px * 3 + 3].copy_from_slice(&n.as_vec3().to_array());
            v.depth.data[px] = camera.to_camera(p).z as f32;
            v.albedo.data[px * 3..px * 3 + 3].copy_from_slice(&options.albedo.as_vec3().to_array());
            v.roughness.data[px] = (options.roughness * options.roughness) as f32;
            v.ior.data[px] = options.ior as f32;
        }
    }
    v
}

/// Writes a synthetic capture into `out_dir` (created if needed): `transforms.json`, Stokes EXRs,
/// masks, ground-truth buffers (`normal`, `depth`, `albedo`, `roughness` as GGX α, `ior`), the
/// environment maps and, for test views, S0 relit under a second map.
pub fn synth(out_dir: &Path, options: &SynthOptions) -> Result<(), SynthError> {
    if options.views < 3 || options.size < 8 || options.size > 4096 {
        return Err(SynthError::Invalid(
            "need at least 3 views and an image size in 8..=4096".into(),
        ));
    }
    let _span = tracing::info_span!("synth", views = options.views, size = options.size).entered();
    let io_err = |path: &Path| {
        let path = path.to_owned();
        move |source| SynthError::Io { path, source }
    };
    for sub in [
        "env",
        "s0",
        "s1",
        "s2",
        "mask",
        "normal",
        "depth",
        "albedo",
        "roughness",
        "ior",
        "relight_s0",
    ] {
        let dir = out_dir.join(sub);
        std::fs::create_dir_all(&dir).map_err(io_err(&dir))?;
    }
    let lut = BrdfLut::shared();
    let sky = procedural_sky(64, DVec3::new(0.6, 0.4, 0.7), 30.0);
    let relight_sky = procedural_sky(64, DVec3::new(-0.5, -0.6, 0.4), 20.0);
    image_io::write_exr(&out_dir.join("env/sky.exr"), &sky)?;
    image_io::write_exr(&out_dir.join("env/relight.exr"), &relight_sky)?;
    let prepare = |latlong: &Image| -> Result<PreparedEnv, SynthError> {
        let cube = CubeMap::from_latlong(latlong, WorldUp::Z, ENV_FACE_SIZE)?;
        Ok(PreparedEnv::new(
            &cube,
            prefilter_plan(ENV_FACE_SIZE, false)?,
        )?)
    };
    let env = prepare(&sky)?;
    let relight_env = prepare(&relight_sky)?;

    let cameras = spiral_cameras(options.views, options.size);
    let rendered: Vec<Result<serde_json::Value, SynthError>> = cameras
        .par_iter()
        .enumerate()
        .map(|(k, camera)| {
            let name = format!("{k:03}");
            let images = render_view(options, camera, &env, lut);
            let path = |kind: &str, ext: &str| format!("{kind}/{name}.{ext}");
            let write = |rel: &str, img: &Image| -> Result<(), SynthError> {
                let p = out_dir.join(rel);
                if rel.ends_with(".png") {
                    image_io::write_png(&p, img, false)?;
                } else {
                    image_io::write_exr(&p, img)?;
                }
                Ok(())
            };
            for (kind, img) in ["s0", "s1", "s2"].iter().zip(&images.s) {
                write(&path(kind, "exr"), img)?;
            }
            write(&path("mask", "png"), &images.mask)?;
            write(&path("normal", "exr"), &images.normal)?;
            write(&path("depth", "exr"), &images.depth)?;
            write(&path("albedo", "exr"), &images.albedo)?;
            write(&path("roughness", "exr"), &images.roughness)?;
            write(&path("ior", "exr"), &images.ior)?;
            let is_test = k % 8 == 0;
            let rows = camera.c2w.transpose().to_cols_array_2d();
            let mut frame = json!({
                "split": if is_test { "test" } else { "train" },
                "transform_matrix": rows,
                "s0_path": path("s0", "exr"),
                "s1_path": path("s1", "exr"),
                "s2_path": path("s2", "exr"),
                "mask_path": path("mask", "png"),
                "normal_path": path("normal", "exr"),
                "depth_path": path("depth", "exr"),
                "albedo_path": path("albedo", "exr"),
                "roughness_path": path("roughness", "exr"),
                "ior_path": path("ior", "exr"),
            });
            if is_test {
                let relit = render_view(options, camera, &relight_env, lut);
                write(&path("relight_s0", "exr"), &relit.s[0])?;
                frame["relight_s0_path"] = json!(path("relight_s0", "exr"));
            }
            Ok(frame)
        })
        .collect();
    let frames = rendered.into_iter().collect::<Result<Vec<_>, _>>()?;
    let cam = &cameras[0];
    let transforms = json!({
        "camera_convention": "OpenGL",
        "stokes_convention": "image_y_up",
        "world_up": [0.0, 0.0, 1.0],
        "w": cam.width, "h": cam.height,
        "fl_x": cam.fx, "fl_y": cam.fy, "cx": cam.cx, "cy": cam.cy,
        "generator": "phygap synth",
        "shape": options.shape,
        "env_map": {"train_test": "env/sky.exr", "relight": "env/relight.exr"},
        "material": {
            "albedo_rgb_linear": options.albedo.to_array(),
            "alpha_ggx": options.roughness * options.roughness,
            "ior": options.ior,
        },
        "frames": frames,
    });
    let path = out_dir.join("transforms.json");
    let text = serde_json::to_string_pretty(&transforms)
        .map_err(|e| SynthError::Invalid(e.to_string()))?;
    std::fs::write(&path, text).map_err(io_err(&path))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tracing_hits_the_analytic_surfaces() {
        let t = trace(Shape::Sphere, DVec3::new(0.0, -4.0, 0.0), DVec3::Y).unwrap();
        assert!((t - 3.0).abs() < 1e-8);
        // Through the torus hole along z: miss; through the tube at x = 0.7: hit at z = 0.3.
        assert!(trace(Shape::Torus, DVec3::new(0.0, 0.0, 4.0), -DVec3::Z).is_none());
        let t = trace(Shape::Torus, DVec3::new(0.7, 0.0, 4.0), -DVec3::Z).unwrap();
        assert!((t - 3.7).abs() < 1e-8);
        let n = surface_normal(Shape::Torus, DVec3::new(0.7, 0.0, 0.3));
        assert!(n.abs_diff_eq(DVec3::Z, 1e-12));
    }

    #[test]
    fn spiral_cameras_look_at_the_origin() {
        for cam in spiral_cameras(10, 32) {
            let to_centre = (-cam.origin()).normalize();
            assert!(cam.forward().abs_diff_eq(to_centre, 1e-12));
            assert!((cam.origin().length() - 4.0).abs() < 1e-12);
        }
    }
}
