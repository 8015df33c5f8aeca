//! A capture at a working resolution: every view shrunk by a whole factor `k`. A working pixel
//! is the mean of a `k × k` block of the file's pixels (an area filter: Stokes images are
//! radiance, so their means are what a camera with `k` times larger pixels measures); a mask
//! becomes the fraction of its block that is object, as an alpha channel gives it; rows and
//! columns past the last whole block are dropped. The pinhole model scales exactly: pixel
//! coordinates divide by `k` (pixel centres at `i + ½` stay at centres), so `fx`, `fy`, `cx`,
//! `cy` divide by `k` and the pose is unchanged. Ground-truth G-buffers (normals, albedo, …)
//! average over the block's object pixels only ([`downscale_gbuffer`]).

use crate::core::camera::Camera;
use crate::formats::image_io::Image;

use super::{Measurement, View};

/// `view` shrunk by `k`: its measurement, its mask and its camera (ground-truth files are read
/// later and shrunk as they are read).
pub fn downscale_view(view: View, k: u32) -> View {
    if k <= 1 {
        return view;
    }
    let n = k as usize;
    let measurement = match view.measurement {
        Measurement::Stokes { s0, s1, s2 } => Measurement::Stokes {
            s0: downscale_image(&s0, n),
            s1: downscale_image(&s1, n),
            s2: downscale_image(&s2, n),
        },
        Measurement::Polarizer { image, angle } => Measurement::Polarizer {
            image: downscale_image(&image, n),
            angle,
        },
        Measurement::Rgb { image } => Measurement::Rgb {
            image: downscale_image(&image, n),
        },
    };
    View {
        measurement,
        mask: downscale_image(&view.mask, n),
        camera: downscale_camera(&view.camera, k),
        ..view
    }
}

/// `image` shrunk by `k`: each output pixel the mean of a `k × k` block, per channel.
pub fn downscale_image(image: &Image, k: usize) -> Image {
    if k <= 1 {
        return image.clone();
    }
    let (width, height, channels) = (image.width / k, image.height / k, image.channels);
    let scale = 1.0 / (k * k) as f64;
    Image::from_fn(width, height, channels, |x, y, out| {
        let mut sums = [0.0f64; 4];
        for dy in 0..k {
            for dx in 0..k {
                let pixel = image.pixel(k * x + dx, k * y + dy);
                for (sum, &v) in sums.iter_mut().zip(pixel) {
                    *sum += f64::from(v);
                }
            }
        }
        for (o, sum) in out.iter_mut().zip(sums) {
            *o = (sum * scale) as f32;
        }
    })
}

/// A ground-truth G-buffer (zero on the background) shrunk by `k`: each output pixel the mean
/// of the block's pixels that are not all zero, zero where the block holds none. Averaging the
/// background's zeros in would pull a silhouette's albedo or roughness towards black.
pub fn downscale_gbuffer(image: &Image, k: usize) -> Image {
    if k <= 1 {
        return image.clone();
    }
    let (width, height, channels) = (image.width / k, image.height / k, image.channels);
    Image::from_fn(width, height, channels, |x, y, out| {
        let mut sums = [0.0f64; 4];
        let mut count = 0usize;
        for dy in 0..k {
            for dx in 0..k {
                let pixel = image.pixel(k * x + dx, k * y + dy);
                if pixel.iter().any(|&v| v != 0.0) {
                    count += 1;
                    for (sum, &v) in sums.iter_mut().zip(pixel) {
                        *sum += f64::from(v);
                    }
                }
            }
        }
        for (o, sum) in out.iter_mut().zip(sums) {
            *o = if count == 0 {
                0.0
            } else {
                (sum / count as f64) as f32
            };
        }
    })
}

/// The camera of a view shrunk by `k` (see the module's note).
pub fn downscale_camera(camera: &Camera, k: u32) -> Camera {
    if k <= 1 {
        return *camera;
    }
    let f = f64::from(k);
    Camera {
        width: camera.width / k,
        height: camera.height / k,
        fx: camera.fx / f,
        fy: camera.fy / f,
        cx: camera.cx / f,
        cy: camera.cy / f,
        c2w: camera.c2w,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn blocks_average_and_partial_blocks_are_dropped() {
        let image = Image::from_fn(5, 4, 2, |x, y, o| {
            o[0] = (x + 10 * y) as f32;
            o[1] = 1.0;
        });
        let small = downscale_image(&image, 2);
        assert_eq!((small.width, small.height, small.channels), (2, 2, 2));
        // Block (1, 1): pixels (2..4, 2..4): 22, 23, 32, 33.
        assert_eq!(small.pixel(1, 1), &[27.5, 1.0]);
        assert_eq!(small.pixel(0, 0), &[5.5, 1.0]);
        assert_eq!(downscale_image(&image, 1), image);
    }

    #[test]
    fn gbuffers_average_the_object_alone() {
        let albedo = Image::from_fn(2, 2, 3, |x, _, o| o.fill(if x == 0 { 0.6 } else { 0.0 }));
        assert_eq!(downscale_gbuffer(&albedo, 2).pixel(0, 0), &[0.6; 3]);
        let background = Image::filled(2, 2, 1, 0.0);
        assert_eq!(downscale_gbuffer(&background, 2).pixel(0, 0), &[0.0]);
    }

    /// A point projects where it did, divided by `k`: the intrinsics scale exactly.
    #[test]
    fn cameras_project_to_the_same_place_at_a_k_th_of_the_scale() {
        let camera = Camera::look_at(
            1224,
            1024,
            0.9,
            DVec3::new(0.3, -3.0, 0.8),
            DVec3::ZERO,
            DVec3::Z,
        );
        let camera = Camera {
            cx: 600.25,
            cy: 530.5,
            ..camera
        };
        for k in [2u32, 3, 4] {
            let small = downscale_camera(&camera, k);
            assert_eq!((small.width, small.height), (1224 / k, 1024 / k));
            for point in [DVec3::ZERO, DVec3::new(0.2, 0.1, -0.3)] {
                let (u, v, depth) = camera.project(point).unwrap();
                let (su, sv, sdepth) = small.project(point).unwrap();
                let f = f64::from(k);
                assert!((su - u / f).abs() < 1e-9 && (sv - v / f).abs() < 1e-9);
                assert!((sdepth - depth).abs() < 1e-12);
            }
        }
    }
}
