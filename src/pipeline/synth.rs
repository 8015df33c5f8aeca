//! Synthetic full-Stokes captures rendered by the project's own PolarDR: analytic shapes (sphere,
//! torus, a four-legged horned creature with thin limbs) ray-marched through their signed
//! distance, with a plain or a checkered albedo, lit by a procedural HDR sky, written in the
//! capture format with ground-truth G-buffers. Like a camera (and the shared captures' renderer),
//! each pixel's Stokes images average its area: a pixel the silhouette or an albedo edge crosses
//! is shaded at 4 × 4 sub-pixel rays; the G-buffers and the mask are those of the centre ray. They make README's main command and the core's
//! tests work on a fresh clone without `../shared`, and give objects beyond the shared captures
//! to check the training defaults on.
//!
//! [`synth_layout`] writes the same captures in the IDR/NeuS and LLFF dataset layouts (per-angle
//! JPEG or 16-bit PNG folders, 3-channel masks, `cameras_sphere.npz` or `poses_bounds.npy`).
//!
//! Threading: views are rendered in parallel with rayon, one view per task.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use glam::DVec3;
use rayon::prelude::*;
use serde_json::json;
use thiserror::Error;

use crate::core::brdf_lut::BrdfLut;
use crate::core::camera::Camera;
use crate::core::envmap::{CubeMap, EnvMapError, PreparedEnv, WorldUp};
use crate::core::shading::{self, PixelInput};
use crate::formats::image_io::{self, Image, ImageError};
use crate::io::capture::layouts::write::{write_layout, LayoutWriteError, WrittenLayout};
use crate::io::capture::layouts::LayoutKind;
use crate::io::capture::{self, CaptureError};
use crate::pipeline::reconstruction::prefilter_plan;

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
    /// A four-legged animal made of capsules: a body, neck and head, legs 0.11 wide, two horns
    /// 0.07 wide and a tail 0.06 wide (thin parts a few pixels across, like real figurines).
    Creature,
}

/// The albedo pattern of a synthetic object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Texture {
    /// One albedo everywhere.
    #[default]
    Plain,
    /// A 3D checkerboard of cells 0.2 wide alternating the albedo and a pale complement.
    Checker,
}

/// The capsules of [`Shape::Creature`]: segment ends and radius.
const CREATURE: [(DVec3, DVec3, f64); 12] = {
    const fn v(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }
    [
        (v(-0.45, 0.0, 0.1), v(0.3, 0.0, 0.15), 0.28), // body
        (v(0.3, 0.0, 0.2), v(0.58, 0.0, 0.36), 0.12),  // neck
        (v(0.6, 0.0, 0.36), v(0.72, 0.0, 0.32), 0.15), // head
        (v(0.3, 0.15, 0.0), v(0.32, 0.18, -0.75), 0.055), // legs
        (v(0.3, -0.15, 0.0), v(0.32, -0.18, -0.75), 0.055),
        (v(-0.4, 0.15, 0.0), v(-0.42, 0.18, -0.75), 0.055),
        (v(-0.4, -0.15, 0.0), v(-0.42, -0.18, -0.75), 0.055),
        (v(0.62, 0.08, 0.46), v(0.64, 0.2, 0.72), 0.035), // horns
        (v(0.62, -0.08, 0.46), v(0.64, -0.2, 0.72), 0.035),
        (v(-0.62, 0.0, 0.2), v(-0.86, 0.0, 0.36), 0.03), // tail
        (v(0.8, 0.07, 0.36), v(0.84, 0.07, 0.36), 0.03), // eyes
        (v(0.8, -0.07, 0.36), v(0.84, -0.07, 0.36), 0.03),
    ]
};

/// Distance from `p` to a capsule (segment `a`–`b` of radius `r`).
fn capsule_distance(p: DVec3, a: DVec3, b: DVec3, r: f64) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
    (p - (a + ab * t)).length() - r
}

/// What to render.
#[derive(Clone, Debug)]
pub struct SynthOptions {
    pub shape: Shape,
    /// Number of views; every 8th (index % 8 == 0) is a test view.
    pub views: usize,
    /// Image width in pixels (and height, unless `height` is given).
    pub size: u32,
    /// Image height in pixels, for views that are not square (the width is `size`).
    pub height: Option<u32>,
    /// Linear albedo, GGX roughness r (α = r²) and IoR of the material.
    pub albedo: DVec3,
    pub roughness: f64,
    pub ior: f64,
    pub texture: Texture,
}

impl Default for SynthOptions {
    fn default() -> Self {
        SynthOptions {
            shape: Shape::Sphere,
            views: 24,
            size: 96,
            height: None,
            albedo: DVec3::new(0.55, 0.2, 0.08),
            roughness: 0.3,
            ior: 1.5,
            texture: Texture::Plain,
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
    #[error(transparent)]
    Capture(#[from] CaptureError),
    #[error(transparent)]
    Layout(#[from] LayoutWriteError),
}

/// Signed distance to the shape (negative inside).
fn signed_distance(shape: Shape, p: DVec3) -> f64 {
    match shape {
        Shape::Sphere => p.length() - 1.0,
        Shape::Torus => {
            let ring = (p.x * p.x + p.y * p.y).sqrt() - 0.7;
            (ring * ring + p.z * p.z).sqrt() - 0.3
        }
        Shape::Creature => CREATURE
            .iter()
            .map(|&(a, b, r)| capsule_distance(p, a, b, r))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The albedo at surface point `p`.
fn albedo_at(options: &SynthOptions, p: DVec3) -> DVec3 {
    match options.texture {
        Texture::Plain => options.albedo,
        Texture::Checker => {
            let cell = (p / 0.2).floor();
            if (cell.x + cell.y + cell.z).rem_euclid(2.0) < 1.0 {
                options.albedo
            } else {
                DVec3::splat(0.85) - options.albedo * 0.6
            }
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
        Shape::Creature => {
            // The union's distance is smooth away from seams: its central-difference gradient.
            let h = 1e-6;
            let d = |e: DVec3| signed_distance(shape, p + e) - signed_distance(shape, p - e);
            DVec3::new(d(DVec3::X * h), d(DVec3::Y * h), d(DVec3::Z * h)).normalize()
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

/// The cameras of a synthetic capture: a Fibonacci spiral at distance 4, elevations −10°…70°,
/// `width × height` views with a horizontal field of view of 40°.
pub fn spiral_cameras(views: usize, width: u32, height: u32) -> Vec<Camera> {
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
            Camera::look_at(
                width,
                height,
                40f64.to_radians(),
                eye,
                DVec3::ZERO,
                DVec3::Z,
            )
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
            let px = j * w + i;
            let d = camera.pixel_dir(i as u32, j as u32);
            let centre = trace(options.shape, origin, d).map(|t| (d, origin + d * t));
            let stokes = pixel_stokes(options, camera, env, lut, (i, j), centre);
            for (img, val) in v.s.iter_mut().zip(stokes) {
                img.data[px * 3..px * 3 + 3].copy_from_slice(&val.as_vec3().to_array());
            }
            // The ground truth is the surface the pixel's centre ray hits, as in the shared
            // captures.
            let Some((_, p)) = centre else {
                continue;
            };
            v.mask.data[px] = 1.0;
            let n = surface_normal(options.shape, p);
            v.normal.data[px * 3..px * 3 + 3].copy_from_slice(&n.as_vec3().to_array());
            v.depth.data[px] = camera.to_camera(p).z as f32;
            let albedo = albedo_at(options, p);
            v.albedo.data[px * 3..px * 3 + 3].copy_from_slice(&albedo.as_vec3().to_array());
            v.roughness.data[px] = (options.roughness * options.roughness) as f32;
            v.ior.data[px] = options.ior as f32;
        }
    }
    v
}

/// Sub-pixel rays per side where something changes within a pixel.
const EDGE_SUBSAMPLES: usize = 4;

/// S0, S1 and S2 of pixel (`i`, `j`) averaged over its area (a box filter, as a camera's pixel
/// and the shared captures' renderer integrate; the background is black): one ray through the
/// centre where the four corner rays agree on what they hit (nothing, or the same albedo),
/// [`EDGE_SUBSAMPLES`]² stratified rays where the silhouette or an albedo edge crosses it.
/// `centre` is what the centre ray hits (its direction and the point), already traced.
fn pixel_stokes(
    options: &SynthOptions,
    camera: &Camera,
    env: &PreparedEnv,
    lut: &BrdfLut,
    (i, j): (usize, usize),
    centre: Option<(DVec3, DVec3)>,
) -> [DVec3; 3] {
    let origin = camera.origin();
    let seen = |u: f64, v: f64| {
        let d = camera.ray_dir(u, v);
        trace(options.shape, origin, d).map(|t| (d, origin + d * t))
    };
    let shade_at = |d: DVec3, p: DVec3| {
        let (stokes_x, stokes_y) = camera.stokes_frame(d);
        let input = PixelInput {
            position: p,
            normal: surface_normal(options.shape, p),
            view: -d,
            stokes_x,
            stokes_y,
            albedo: albedo_at(options, p),
            roughness: options.roughness,
            ior: options.ior,
        };
        let out = shading::shade(&input, env, lut);
        [out.s0, out.s1, out.s2]
    };
    let (x, y) = (i as f64, j as f64);
    let corners = [(x, y), (x + 1.0, y), (x, y + 1.0), (x + 1.0, y + 1.0)]
        .map(|(u, v)| seen(u, v).map(|(_, p)| albedo_at(options, p)));
    if corners.iter().all(|c| *c == corners[0]) {
        return match centre {
            Some((d, p)) => shade_at(d, p),
            None => [DVec3::ZERO; 3],
        };
    }
    let n = EDGE_SUBSAMPLES;
    let mut sum = [DVec3::ZERO; 3];
    for sj in 0..n {
        for si in 0..n {
            let (u, v) = (
                x + (si as f64 + 0.5) / n as f64,
                y + (sj as f64 + 0.5) / n as f64,
            );
            if let Some((d, p)) = seen(u, v) {
                for (total, value) in sum.iter_mut().zip(shade_at(d, p)) {
                    *total += value;
                }
            }
        }
    }
    sum.map(|total| total / (n * n) as f64)
}

/// Writes a synthetic capture into `out_dir` (created if needed): `transforms.json`, Stokes EXRs,
/// masks, ground-truth buffers (`normal`, `depth`, `albedo`, `roughness` as GGX α, `ior`), the
/// environment maps and, for test views, S0 relit under a second map.
pub fn synth(out_dir: &Path, options: &SynthOptions) -> Result<(), SynthError> {
    let height = options.height.unwrap_or(options.size);
    let sizes = [options.size, height];
    if options.views < 3 || sizes.iter().any(|s| !(8..=4096).contains(s)) {
        return Err(SynthError::Invalid(
            "need at least 3 views and image sides in 8..=4096".into(),
        ));
    }
    if 2 * height < options.size || height > options.size {
        return Err(SynthError::Invalid(
            "the height must lie between half the width and the width (the object fits the \
             view's narrower side)"
                .into(),
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
            prefilter_plan(ENV_FACE_SIZE, false, 1)?,
        )?)
    };
    let env = prepare(&sky)?;
    let relight_env = prepare(&relight_sky)?;

    let cameras = spiral_cameras(options.views, options.size, height);
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
        "texture": options.texture,
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
    // Where the shared captures name their maps (DATA_FORMAT.md §9), so that `bench quality`
    // scores the relit views and `diagnose` lights with the true map.
    let scene = json!({
        "generator": "phygap synth",
        "env_map": {"train_test": "env/sky.exr", "relight": "env/relight.exr"},
    });
    let path = out_dir.join("scene.json");
    std::fs::write(&path, scene.to_string()).map_err(io_err(&path))?;
    Ok(())
}

/// Writes a synthetic capture in a dataset layout (IDR/NeuS or LLFF, see
/// [`write_layout`]): the capture rendered by [`synth`] goes to `out_dir/reference` (its
/// `transforms.json` form, with the ground truth), and its views in the layout to `out_dir`.
pub fn synth_layout(
    out_dir: &Path,
    options: &SynthOptions,
    kind: LayoutKind,
) -> Result<WrittenLayout, SynthError> {
    let reference = out_dir.join("reference");
    synth(&reference, options)?;
    let capture = capture::load(&reference)?;
    Ok(write_layout(&capture, out_dir, kind)?)
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
    fn the_creature_has_thin_legs_inside_the_bounding_sphere() {
        // A ray along +y through the nearer front leg's middle hits that leg's near side.
        let leg = DVec3::new(0.31, -0.165, -0.4);
        let t = trace(Shape::Creature, leg + DVec3::new(0.0, -3.0, 0.0), DVec3::Y).unwrap();
        let hit = leg + DVec3::new(0.0, -3.0, 0.0) + DVec3::Y * t;
        assert!((hit.y - (leg.y - 0.055)).abs() < 2e-3, "{hit}");
        // Just beside the leg: a miss (it is 0.11 wide).
        let beside = DVec3::new(0.31 + 0.08, -3.0, -0.4);
        assert!(trace(Shape::Creature, beside, DVec3::Y).is_none());
        // Every capsule lies inside the 1.05 sphere the tracer clips to.
        for (a, b, r) in CREATURE {
            assert!(a.length() + r < 1.05 && b.length() + r < 1.05);
        }
        let n = surface_normal(Shape::Creature, hit);
        assert!(n.dot(-DVec3::Y) > 0.95, "{n}");
    }

    #[test]
    fn the_checker_alternates_two_albedos() {
        let options = SynthOptions {
            texture: Texture::Checker,
            ..SynthOptions::default()
        };
        let a = albedo_at(&options, DVec3::new(0.05, 0.05, 0.05));
        let b = albedo_at(&options, DVec3::new(0.25, 0.05, 0.05));
        assert_eq!(a, options.albedo);
        assert!((a - b).abs().max_element() > 0.2);
        assert_eq!(albedo_at(&options, DVec3::new(0.25, 0.25, 0.05)), a);
    }

    #[test]
    fn spiral_cameras_look_at_the_origin() {
        for cam in spiral_cameras(10, 32, 32) {
            let to_centre = (-cam.origin()).normalize();
            assert!(cam.forward().abs_diff_eq(to_centre, 1e-12));
            assert!((cam.origin().length() - 4.0).abs() < 1e-12);
        }
    }

    /// S0 of every view of `capture`, in order.
    fn stokes_of(capture: &capture::Capture) -> Vec<[Image; 3]> {
        capture
            .views
            .iter()
            .map(|v| match &v.measurement {
                capture::Measurement::Stokes { s0, s1, s2 } => [s0.clone(), s1.clone(), s2.clone()],
                _ => panic!("{}: not Stokes", v.name),
            })
            .collect()
    }

    /// Synth in `kind`, read it back, and compare with the transforms form: the same cameras
    /// (1e-6), split, masks, and Stokes within `tolerance` (mean absolute error over the object,
    /// relative to the brightest polarizer sample).
    fn round_trip(kind: LayoutKind, tolerance: f32) {
        let dir = tempfile::tempdir().unwrap();
        let options = SynthOptions {
            views: 9,
            size: 40,
            height: Some(32),
            texture: Texture::Checker,
            ..SynthOptions::default()
        };
        let written = synth_layout(dir.path(), &options, kind).unwrap();
        let reference = capture::load(&dir.path().join("reference")).unwrap();
        let read = capture::load(dir.path()).unwrap();
        assert_eq!((written.views, read.views.len()), (9, 9));
        let peak = 1.0 / written.exposure;
        for (a, b) in read.views.iter().zip(&reference.views) {
            assert_eq!(
                (a.split, a.camera.width, a.camera.height),
                (b.split, 40, 32)
            );
            for (x, y) in [
                (a.camera.fx, b.camera.fx),
                (a.camera.fy, b.camera.fy),
                (a.camera.cx, b.camera.cx),
                (a.camera.cy, b.camera.cy),
            ] {
                assert!((x - y).abs() < 1e-6, "{kind:?} {}: {x} vs {y}", a.name);
            }
            let (ca, cb) = (a.camera.c2w.to_cols_array(), b.camera.c2w.to_cols_array());
            assert!(
                ca.iter().zip(&cb).all(|(x, y)| (x - y).abs() < 1e-6),
                "{kind:?} {}",
                a.name
            );
            assert_eq!(a.mask.data, b.mask.data, "{kind:?} {}: masks", a.name);
        }
        for (k, (a, b)) in stokes_of(&read)
            .iter()
            .zip(&stokes_of(&reference))
            .enumerate()
        {
            let mask = &reference.views[k].mask;
            for (component, (ia, ib)) in a.iter().zip(b).enumerate() {
                let (mut sum, mut count) = (0.0f32, 0usize);
                for (p, m) in mask.data.iter().enumerate() {
                    if *m > 0.5 {
                        for c in 0..3 {
                            sum += (ia.data[p * 3 + c] * peak - ib.data[p * 3 + c]).abs();
                            count += 1;
                        }
                    }
                }
                let error = sum / count.max(1) as f32 / peak;
                assert!(
                    error < tolerance,
                    "{kind:?} view {k} S{component}: mean error {error} of the peak"
                );
            }
        }
    }

    #[test]
    fn a_synthetic_idr_capture_reads_back_as_its_transforms_form() {
        // 8-bit JPEG at quality 95 behind four polarizers: a few levels of error, most of them
        // along the checker's anti-aliased edges at 40 × 32.
        round_trip(LayoutKind::Idr, 0.025);
    }

    #[test]
    fn a_synthetic_llff_capture_reads_back_as_its_transforms_form() {
        // 16-bit PNG: quantization only.
        round_trip(LayoutKind::Llff, 1e-4);
    }

    /// The conventions check reads what a layout folder states where the loader does (its
    /// `capture.json`), not the defaults of a transforms document it does not have.
    #[test]
    fn the_conventions_check_reads_what_a_layout_folder_states() {
        let dir = tempfile::tempdir().unwrap();
        let options = SynthOptions {
            views: 6,
            size: 40,
            ..SynthOptions::default()
        };
        synth_layout(dir.path(), &options, LayoutKind::Llff).unwrap();
        let stated = |dir: &Path| {
            let capture = capture::load(dir).unwrap();
            let report = capture::conventions::check_capture(dir, &capture);
            report.stokes.map(|s| s.stated)
        };
        assert_eq!(stated(dir.path()).as_deref(), Some("image_y_up"));
        std::fs::write(
            dir.path().join("capture.json"),
            r#"{"stokes_convention": "image_y_down"}"#,
        )
        .unwrap();
        assert_eq!(stated(dir.path()).as_deref(), Some("image_y_down"));
    }
}
