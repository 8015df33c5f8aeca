//! Raw mosaic frames through the loader: full-Stokes captures (rendered by the project itself, and
//! the shared ground-truth captures) re-recorded by a simulated IMX250MZR / IMX250MYR and loaded
//! back round-trip to their Stokes images; wrong sizes, depths and keys are named; white balance,
//! the angle convention and DoLP statistics.

use std::path::Path;

use serde_json::{json, Value};

use super::mosaic::{Demosaic, Sensor};
use super::simulate::{write_counts, write_raw_capture, FrameFile, SimulateOptions};
use super::*;
use crate::formats::image_io::{write_png, Image};
use crate::pipeline::synth::{synth, SynthOptions};

/// Errors of a round trip, relative to the mean reference S0 over the compared pixels.
#[derive(Debug)]
struct RoundTrip {
    /// Mean |S_k(raw) − S_k(reference)| / mean S0, for k = 0, 1, 2.
    mean: [f64; 3],
    /// 99th percentile of the same.
    p99: [f64; 3],
    pixels: usize,
}

/// The smooth regions of a view: pixels whose whole window of `margin` pixels (Chebyshev) is
/// object, with the grey S0 varying by at most [`SMOOTH`] × its mean over a 5×5 window (away from
/// silhouettes, occlusion edges and highlights, where no demosaicing can follow the image).
fn smooth(mask: &Image, s0: &Image, margin: usize) -> Vec<bool> {
    let (w, h) = (mask.width, mask.height);
    let grey = |x: usize, y: usize| s0.pixel(x, y).iter().sum::<f32>() / s0.channels as f32;
    let mut out = vec![false; w * h];
    for y in margin..h.saturating_sub(margin) {
        for x in margin..w.saturating_sub(margin) {
            let window = |m: usize| {
                (y - m..=y + m).flat_map(move |yy| (x - m..=x + m).map(move |xx| (xx, yy)))
            };
            if !window(margin).all(|(xx, yy)| mask.pixel(xx, yy)[0] > 0.5) {
                continue;
            }
            let values: Vec<f32> = window(SMOOTH_RADIUS.min(margin))
                .map(|(xx, yy)| grey(xx, yy))
                .collect();
            let (lo, hi) = values
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
            let mean = values.iter().sum::<f32>() / values.len() as f32;
            out[y * w + x] = hi - lo <= SMOOTH * mean;
        }
    }
    out
}

/// Largest relative variation of S0 inside a window for it to count as smooth.
const SMOOTH: f32 = 0.25;
/// The window of the smoothness test is (2 × this + 1)² pixels.
const SMOOTH_RADIUS: usize = 2;

fn stokes(view: &View) -> [&Image; 3] {
    match &view.measurement {
        Measurement::Stokes { s0, s1, s2 } => [s0, s1, s2],
        _ => panic!("{} is not a full-Stokes view", view.name),
    }
}

/// Compares raw-loaded views with their full-resolution references: in `half` mode against the
/// mean of each 2×2 block, in `bilinear` mode pixel by pixel; on the smooth regions (`margin`)
/// and the channels the sensor records (R alone for the mono sensor, which sees channel 0).
fn compare(
    reference: &Capture,
    loaded: &Capture,
    mode: Demosaic,
    colour: bool,
    full_scale: f32,
    margin: usize,
) -> RoundTrip {
    let channels = if colour { 3 } else { 1 };
    let mut errors: [Vec<f64>; 3] = Default::default();
    let mut s0_sum = 0.0;
    for (r, l) in reference.views.iter().zip(&loaded.views) {
        let (rs, ls) = (stokes(r), stokes(l));
        let inside = smooth(&r.mask, rs[0], margin);
        let w = r.mask.width;
        for y in 0..l.camera.height as usize {
            for x in 0..l.camera.width as usize {
                let (block, ok) = match mode {
                    Demosaic::Half => {
                        let px = [(0, 0), (1, 0), (0, 1), (1, 1)]
                            .map(|(dx, dy)| (2 * x + dx, 2 * y + dy));
                        (px.to_vec(), px.iter().all(|&(a, b)| inside[b * w + a]))
                    }
                    Demosaic::Bilinear => (vec![(x, y)], inside[y * w + x]),
                };
                if !ok {
                    continue;
                }
                for c in 0..channels {
                    let want = |k: usize| {
                        block
                            .iter()
                            .map(|&(a, b)| rs[k].pixel(a, b)[c] as f64)
                            .sum::<f64>()
                            / block.len() as f64
                    };
                    s0_sum += want(0);
                    for (k, e) in errors.iter_mut().enumerate() {
                        let got = ls[k].pixel(x, y)[c] as f64 * full_scale as f64;
                        e.push((got - want(k)).abs());
                    }
                }
            }
        }
    }
    let n = errors[0].len();
    assert!(n > 200, "only {n} pixels compared");
    let mean_s0 = s0_sum / n as f64;
    let stats = errors.map(|mut e| {
        e.sort_by(|a, b| a.total_cmp(b));
        let mean = e.iter().sum::<f64>() / n as f64;
        (mean / mean_s0, e[(0.99 * n as f64) as usize] / mean_s0)
    });
    RoundTrip {
        mean: stats.map(|s| s.0),
        p99: stats.map(|s| s.1),
        pixels: n,
    }
}

/// [`compare`] of the same frames loaded in both modes, on the smooth regions a sensor's
/// interpolation leaves (a wider margin for the colour sensor's Bayer pattern): (half, bilinear).
fn compare_modes(
    reference: &Capture,
    half: &Capture,
    bilinear: &Capture,
    sensor: Sensor,
    full_scale: f32,
) -> (RoundTrip, RoundTrip) {
    let colour = sensor.is_colour();
    let margin = if colour { 4 } else { 2 };
    (
        compare(reference, half, Demosaic::Half, colour, full_scale, margin),
        compare(
            reference,
            bilinear,
            Demosaic::Bilinear,
            colour,
            full_scale,
            margin,
        ),
    )
}

/// Asserts mean errors below `bound` and no heavy tail (99th percentile below 10 × the bound).
fn assert_within(errors: &RoundTrip, bound: [f64; 3], what: &str) {
    for (k, bound) in bound.iter().enumerate() {
        assert!(errors.mean[k] < *bound, "{what} S{k}: {errors:?}");
        assert!(errors.p99[k] < 10.0 * bound, "{what} S{k}: {errors:?}");
    }
    assert!(errors.pixels > 200, "{what}: {errors:?}");
}

/// The largest S0 of a capture (the simulated camera's full scale: nothing clips).
fn max_s0(capture: &Capture) -> f32 {
    capture
        .views
        .iter()
        .flat_map(|v| stokes(v)[0].data.iter().copied())
        .fold(0.0, f32::max)
}

/// Writes `reference` as raw frames into a new folder and loads it.
fn simulate(reference: &Capture, options: &SimulateOptions) -> (tempfile::TempDir, Capture) {
    let dir = tempfile::tempdir().unwrap();
    write_raw_capture(reference, dir.path(), options).unwrap();
    let loaded = load(dir.path()).unwrap();
    (dir, loaded)
}

/// Sets the `demosaic` key of a written raw capture and loads it again.
fn reload(dir: &Path, mode: Demosaic) -> Capture {
    let path = dir.join("transforms.json");
    let mut doc: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    doc["demosaic"] = json!(match mode {
        Demosaic::Half => "half",
        Demosaic::Bilinear => "bilinear",
    });
    std::fs::write(&path, doc.to_string()).unwrap();
    load(dir).unwrap()
}

fn synth_capture(views: usize, size: u32) -> (tempfile::TempDir, Capture) {
    let dir = tempfile::tempdir().unwrap();
    let options = SynthOptions {
        views,
        size,
        ..SynthOptions::default()
    };
    synth(dir.path(), &options).unwrap();
    let capture = load(dir.path()).unwrap();
    (dir, capture)
}

#[test]
fn a_synthetic_capture_round_trips_through_simulated_sensors() {
    let (_synth_dir, reference) = synth_capture(6, 64);
    let full_scale = max_s0(&reference);
    let cases = [
        (Sensor::Imx250Mzr, 12, FrameFile::Png),
        (Sensor::Imx250Mzr, 16, FrameFile::Bytes),
        (Sensor::Imx250Myr, 12, FrameFile::Tiff),
        (Sensor::Imx250Myr, 16, FrameFile::Png),
    ];
    for (sensor, bit_depth, file) in cases {
        let options = SimulateOptions {
            sensor,
            bit_depth,
            file,
            full_scale,
            black_level: if bit_depth == 12 { 64 } else { 0 },
            ..SimulateOptions::default()
        };
        let (dir, bilinear) = simulate(&reference, &options);
        let half = reload(dir.path(), Demosaic::Half);
        let summary = bilinear.summary();
        assert_eq!(summary.kinds, ["raw"]);
        assert_eq!(
            summary.raw.as_ref().unwrap().frames,
            (0..6).collect::<Vec<_>>()
        );
        assert_eq!((summary.width, summary.height), (64, 64));
        let (r, h) = (&reference.views[2].camera, &half.views[2].camera);
        assert_eq!((h.width, h.height), (32, 32));
        assert_eq!(
            (h.fx, h.fy, h.cx, h.cy),
            (r.fx / 2.0, r.fy / 2.0, r.cx / 2.0, r.cy / 2.0)
        );
        assert_eq!(h.c2w, r.c2w);
        assert_eq!(bilinear.views[2].camera, *r);
        // Test views stay test views; masks come back (halved by 2×2 majority).
        assert_eq!(half.test_views().count(), reference.test_views().count());
        let object = |c: &Capture| c.views[1].mask.data.iter().sum::<f32>();
        assert!((object(&half) * 4.0 / object(&reference) - 1.0).abs() < 0.1);

        let colour = sensor.is_colour();
        let (h, b) = compare_modes(&reference, &half, &bilinear, sensor, full_scale);
        eprintln!("synth {sensor:?} {bit_depth}-bit {file:?}: half {h:?}\n    bilinear {b:?}");
        // About 1.5 × what was measured (docs/results.md, "Raw frames"): interpolation error, plus quantization.
        let (half_bound, bilinear_bound) = if colour {
            ([0.0075, 0.004, 0.004], [0.009, 0.0055, 0.005])
        } else {
            ([0.0015, 0.0011, 0.0011], [0.002, 0.002, 0.002])
        };
        assert_within(&h, half_bound, &format!("synth {sensor:?} half"));
        assert_within(&b, bilinear_bound, &format!("synth {sensor:?} bilinear"));

        // The polarization is there: the DoLP of the raw views matches the reference's.
        let (ours, theirs) = (summary.dolp.unwrap(), reference.summary().dolp.unwrap());
        eprintln!("DoLP raw {ours:?} reference {theirs:?}");
        assert!(
            (ours.median - theirs.median).abs() < 0.02,
            "{ours:?} {theirs:?}"
        );
        assert!(summary
            .frames
            .iter()
            .all(|f| f.dolp.is_some() && f.kind == "raw"));
    }
}

#[test]
fn angles_labelled_towards_image_down_give_the_same_stokes() {
    let (_synth_dir, reference) = synth_capture(4, 64);
    let full_scale = max_s0(&reference);
    let options = SimulateOptions {
        full_scale,
        bit_depth: 16,
        ..SimulateOptions::default()
    };
    let (_up_dir, up) = simulate(&reference, &options);
    let (down_dir, down) = simulate(
        &reference,
        &SimulateOptions {
            image_y_down: true,
            ..options.clone()
        },
    );
    // Both conventions recover the reference (the 45° and 135° samples sit on swapped pixels, so
    // the interpolation errors differ, not their size).
    let e_up = compare(&reference, &up, Demosaic::Bilinear, false, full_scale, 2);
    let e_down = compare(&reference, &down, Demosaic::Bilinear, false, full_scale, 2);
    // Reading image_y_down frames as image_y_up mirrors S2.
    let path = down_dir.path().join("transforms.json");
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, text.replace("image_y_down", "image_y_up")).unwrap();
    let wrong = load(down_dir.path()).unwrap();
    let e_wrong = compare(&reference, &wrong, Demosaic::Bilinear, false, full_scale, 2);
    eprintln!("image_y_up labels {e_up:?}\nimage_y_down labels {e_down:?}\nread as image_y_up {e_wrong:?}");
    for e in [&e_up, &e_down] {
        assert_within(e, [0.002; 3], "labels");
    }
    assert_eq!(
        e_wrong.mean[1], e_down.mean[1],
        "S1 does not depend on the convention"
    );
    assert!(e_wrong.mean[2] > 5.0 * e_down.mean[2], "{e_wrong:?}");
}

#[test]
fn white_balance_is_given_or_gray_world() {
    let (_synth_dir, reference) = synth_capture(4, 32);
    let full_scale = max_s0(&reference);
    let options = SimulateOptions {
        sensor: Sensor::Imx250Myr,
        full_scale,
        bit_depth: 16,
        ..SimulateOptions::default()
    };
    let (_a, neutral) = simulate(&reference, &options);
    let (_b, given) = simulate(
        &reference,
        &SimulateOptions {
            white_balance: Some([2.0, 1.0, 0.5]),
            ..options.clone()
        },
    );
    for (n, g) in neutral.views.iter().zip(&given.views) {
        for (x, y) in stokes(n).iter().zip(stokes(g)) {
            for (p, (a, b)) in x.data.iter().zip(&y.data).enumerate() {
                assert!((a * [2.0, 1.0, 0.5][p % 3] - b).abs() < 1e-6);
            }
        }
    }
    let report = given.raw.as_ref().unwrap();
    assert_eq!(report.white_balance.as_deref(), Some("given"));
    assert_eq!(report.white_balance_gains, Some([2.0, 1.0, 0.5]));

    let (_c, gray) = simulate(
        &reference,
        &SimulateOptions {
            white_balance: None,
            ..options.clone()
        },
    );
    let report = gray.raw.as_ref().unwrap();
    assert_eq!(report.white_balance.as_deref(), Some("gray_world"));
    let gains = report.white_balance_gains.unwrap();
    // The orange object on a bluish sky: red is boosted less than blue, green stays 1.
    let means = |c: &Capture| {
        let mut sums = [0.0f64; 3];
        for v in &c.views {
            for (p, x) in stokes(v)[0].data.iter().enumerate() {
                sums[p % 3] += *x as f64;
            }
        }
        sums
    };
    let (before, after) = (means(&neutral), means(&gray));
    assert_eq!(gains[1], 1.0);
    for c in 0..3 {
        assert!((gains[c] - before[1] / before[c]).abs() < 1e-9 * gains[c]);
        assert!((after[c] / after[1] - 1.0).abs() < 1e-5, "{after:?}");
    }
}

/// A small hand-made raw capture: `n` mono 12-bit 8×6 PNG frames on a ring of cameras.
struct Fixture {
    dir: tempfile::TempDir,
}

impl Fixture {
    fn new() -> Fixture {
        Fixture {
            dir: tempfile::tempdir().unwrap(),
        }
    }

    fn frame(&self, w: usize, h: usize, file: &str, bit_depth: u32, value: u16) {
        let counts: Vec<u16> = (0..w * h).map(|p| value + (p % 7) as u16).collect();
        let kind = if file.ends_with(".raw") {
            FrameFile::Bytes
        } else {
            FrameFile::Png
        };
        write_counts(&self.dir.path().join(file), w, h, &counts, bit_depth, kind).unwrap();
    }

    fn camera(k: usize) -> Value {
        let angle = k as f64 * 0.7;
        let eye = glam::DVec3::new(3.0 * angle.cos(), 3.0 * angle.sin(), 0.5);
        let cam = Camera::look_at(8, 6, 0.8, eye, glam::DVec3::ZERO, glam::DVec3::Z);
        json!((0..4)
            .map(|r| cam.c2w.row(r).to_array())
            .collect::<Vec<_>>())
    }

    fn load(&self, doc: &Value) -> Result<Capture, CaptureError> {
        std::fs::write(
            self.dir.path().join("transforms.json"),
            serde_json::to_string_pretty(doc).unwrap(),
        )
        .unwrap();
        load(self.dir.path())
    }
}

#[test]
fn a_hand_made_raw_capture_loads_with_defaults_and_masks_at_either_size() {
    let fx = Fixture::new();
    for k in 0..3 {
        fx.frame(8, 6, &format!("raw/{k}.png"), 12, 100);
    }
    // Mask of frame 0 at the sensor's size, of frame 1 at the half-mode view's size.
    write_png(
        &fx.dir.path().join("m0.png"),
        &Image::from_fn(8, 6, 1, |x, _, o| o[0] = if x < 4 { 1.0 } else { 0.0 }),
        false,
    )
    .unwrap();
    write_png(
        &fx.dir.path().join("m1.png"),
        &Image::from_fn(4, 3, 1, |x, _, o| o[0] = if x < 2 { 1.0 } else { 0.0 }),
        false,
    )
    .unwrap();
    let doc = json!({
        "w": 8, "h": 6, "fl_x": 10.0, "demosaic": "half",
        "raw": {"sensor": "IMX250MZR", "bit_depth": 12, "black_level": 60},
        "frames": [
            {"transform_matrix": Fixture::camera(0), "raw": "raw/0.png", "mask_path": "m0.png", "split": "test"},
            {"transform_matrix": Fixture::camera(1), "raw": {"file": "raw/1.png"}, "mask_path": "m1.png"},
            {"transform_matrix": Fixture::camera(2), "raw": {"file": "raw/2.png", "black_level": 0}},
        ]
    });
    let capture = fx.load(&doc).unwrap();
    assert_eq!(capture.views[0].name, "frame 0 (raw/0.png)");
    let expected_mask: Vec<f32> = (0..12).map(|p| if p % 4 < 2 { 1.0 } else { 0.0 }).collect();
    assert_eq!(capture.views[0].mask.data, expected_mask);
    assert_eq!(capture.views[1].mask.data, expected_mask);
    assert_eq!(capture.views[0].camera.width, 4);
    assert_eq!(capture.warnings.len(), 1, "frame 2 has no mask");
    // Counts 100 + (p mod 7) − 60 (frame 0) or − 0 (frame 2) over 4095 − black, each polarizer
    // taken at the first block's centre (9/16 of its own sample, 3/16 of the next block's on the
    // centre's side, 1/16 the diagonal one; at the border its own in their place): S0 is ½ Σ of
    // the four, S1 = I0 − I90.
    let [s0, s1, _] = stokes(&capture.views[0]);
    let count = |p: usize| 100.0 + (p % 7) as f64;
    let at_centre = |own: usize, across: usize, along: usize, diagonal: usize| {
        (9.0 * count(own) + 3.0 * count(across) + 3.0 * count(along) + count(diagonal)) / 16.0
    };
    let i90 = at_centre(0, 2, 16, 18);
    let i45 = at_centre(1, 1, 17, 17);
    let i135 = at_centre(8, 10, 8, 10);
    let i0 = count(9);
    let scale = 1.0 / (4095.0 - 60.0);
    let want_s0 = 0.5 * (i0 + i45 + i90 + i135 - 4.0 * 60.0) * scale;
    assert!((s0.data[0] as f64 - want_s0).abs() < 1e-6, "{}", s0.data[0]);
    assert!((s1.data[0] as f64 - (i0 - i90) * scale).abs() < 1e-6);
    assert_eq!(s0.channels, 3, "mono views are grey RGB");
}

#[test]
fn wrong_sizes_depths_and_keys_are_named() {
    let fx = Fixture::new();
    fx.frame(8, 6, "a.png", 12, 100);
    fx.frame(8, 6, "short.raw", 12, 100);
    std::fs::write(fx.dir.path().join("short.raw"), vec![0u8; 95]).unwrap();
    fx.frame(8, 6, "eight.png", 8, 100);
    fx.frame(8, 6, "hot.png", 16, 5000);
    let cam = Fixture::camera;
    let doc = json!({
        "w": 8, "h": 6, "fl_x": 10.0,
        "raw": {"bit_depth": 12},
        "frames": [
            // 0: the file is 8×6 but the camera 10×6.
            {"transform_matrix": cam(0), "w": 10, "raw": {"file": "a.png", "sensor": "IMX250MZR"}},
            // 1: 95 bytes where 8×6 12-bit samples need 96.
            {"transform_matrix": cam(1), "raw": {"file": "short.raw", "sensor": "IMX250MZR"}},
            // 2: an 8-bit file declared 12-bit.
            {"transform_matrix": cam(2), "raw": {"file": "eight.png", "sensor": "IMX250MZR"}},
            // 3: a sample above the 12-bit maximum.
            {"transform_matrix": cam(3), "raw": {"file": "hot.png", "sensor": "IMX250MZR"}},
            // 4: odd width.
            {"transform_matrix": cam(4), "w": 7, "raw": {"file": "a.png", "sensor": "IMX250MZR"}},
            // 5: a colour sensor needs multiples of 4.
            {"transform_matrix": cam(5), "raw": {"file": "a.png", "sensor": "IMX250MYR"}},
            // 6: unknown sensor and unknown key.
            {"transform_matrix": cam(6), "raw": {"file": "a.png", "sensor": "IMX999", "gain": 2}},
            // 7: no sensor anywhere; black level above the range.
            {"transform_matrix": cam(7), "raw": {"file": "a.png", "black_level": 5000}},
            // 8: an unsupported file type.
            {"transform_matrix": cam(8), "raw": {"file": "a.jpg", "sensor": "IMX250MZR"}},
            // 9: a raw.width that contradicts w.
            {"transform_matrix": cam(0), "raw": {"file": "a.png", "sensor": "IMX250MZR", "width": 16}},
        ]
    });
    let err = fx.load(&doc).unwrap_err();
    let problems = err.problems();
    let has = |frame: &str, key: &str, text: &str| {
        assert!(
            problems
                .iter()
                .any(|p| p.frame.starts_with(frame) && p.key == key && p.message.contains(text)),
            "no problem ({frame}, {key}, {text:?}) in:\n{}",
            problems
                .iter()
                .map(|p| p.to_string())
                .collect::<Vec<_>>()
                .join("\n")
        );
    };
    has(
        "frame 0 ",
        "raw.file",
        "a.png is 8×6 pixels but the camera's w×h is 10×6",
    );
    has(
        "frame 1 ",
        "raw.file",
        "holds 95 bytes but 8×6 samples of 12 bits (2 bytes, little-endian) need 96",
    );
    has(
        "frame 2 ",
        "raw.file",
        "holds 8-bit samples but raw.bit_depth is 12",
    );
    has("frame 3 ", "raw.file", "above the 12-bit maximum 4095");
    has("frame 4 ", "w", "multiples of 2");
    has("frame 5 ", "w", "multiples of 4");
    has("frame 6 ", "raw.sensor", "unknown sensor \"IMX999\"");
    has("frame 6 ", "raw.gain", "unknown key");
    has("frame 7 ", "raw.sensor", "missing required key");
    has("frame 7 ", "raw.black_level", "leaves no range");
    has("frame 8 ", "raw.file", "unsupported raw frame type a.jpg");
    has(
        "frame 9 ",
        "raw.width",
        "raw.width is 16 but the camera's w is 8",
    );
    eprintln!("{err}");

    let bad_top = json!({
        "w": 8, "h": 6, "fl_x": 10.0, "demosaic": "quarter", "white_balance": [1, 0, 1],
        "raw": {"sensor": "IMX250MZR", "bit_depth": 20},
        "frames": [{"transform_matrix": cam(0), "raw": "a.png"}, {"transform_matrix": cam(1), "raw": "a.png"}]
    });
    let err = fx.load(&bad_top).unwrap_err();
    let keys: Vec<(&str, &str)> = err
        .problems()
        .iter()
        .map(|p| (p.frame.as_str(), p.key.as_str()))
        .collect();
    assert_eq!(
        keys,
        [
            ("top level", "demosaic"),
            ("top level", "white_balance"),
            ("top level", "raw.bit_depth")
        ],
        "{err}"
    );
}

#[test]
fn dolp_is_reported_for_every_full_stokes_capture() {
    let (_dir, capture) = synth_capture(4, 32);
    let summary = capture.summary();
    let dolp = summary.dolp.unwrap();
    eprintln!("synth sphere DoLP {dolp:?}");
    assert!(dolp.pixels > 500 && dolp.mean > 0.01 && dolp.p90 >= dolp.median);
    assert_eq!(summary.frames.len(), 4);
    let per_view: u64 = summary.frames.iter().map(|f| f.dolp.unwrap().pixels).sum();
    assert_eq!(per_view, dolp.pixels);
    let text = serde_json::to_value(&summary).unwrap();
    assert!(text["frames"][0]["dolp"]["median"].is_number());
    assert!(text["dolp"]["p90"].is_number());
}

/// Mean and 99th-percentile figures of the shared captures re-recorded by the simulated sensors.
#[test]
fn shared_captures_round_trip_through_simulated_sensors() {
    let Some(data) = crate::testing::shared_data_dir() else {
        return;
    };
    for scene in ["sphere", "knot"] {
        let full = load(&data.join(scene)).unwrap();
        // Four views (three train, one test) keep the test quick.
        let reference = Capture {
            views: full.views.iter().take(4).cloned().collect(),
            ..full.clone()
        };
        let full_scale = max_s0(&reference);
        for sensor in [Sensor::Imx250Mzr, Sensor::Imx250Myr] {
            for bit_depth in [12, 16] {
                let options = SimulateOptions {
                    sensor,
                    bit_depth,
                    full_scale,
                    ..SimulateOptions::default()
                };
                let (dir, bilinear) = simulate(&reference, &options);
                let half = reload(dir.path(), Demosaic::Half);
                let colour = sensor.is_colour();
                let (h, b) = compare_modes(&reference, &half, &bilinear, sensor, full_scale);
                eprintln!(
                    "{scene} {sensor:?} {bit_depth}-bit (full scale {full_scale:.3}):\n    half {h:?}\n    bilinear {b:?}"
                );
                // About 1.5 × what was measured (docs/results.md, "Raw frames").
                let (half_bound, bilinear_bound) = match (scene, colour) {
                    ("sphere", false) => ([0.010, 0.014, 0.014], [0.02, 0.016, 0.016]),
                    ("sphere", true) => ([0.020, 0.021, 0.021], [0.029, 0.022, 0.022]),
                    (_, false) => ([0.014, 0.020, 0.018], [0.034, 0.027, 0.026]),
                    (_, true) => ([0.028, 0.024, 0.024], [0.055, 0.03, 0.03]),
                };
                let what = format!("{scene} {sensor:?} {bit_depth}-bit");
                assert_within(&h, half_bound, &format!("{what} half"));
                assert_within(&b, bilinear_bound, &format!("{what} bilinear"));
            }
        }
    }
}

/// Frames exposed so that highlights reach the sensor's maximum get a warning naming them; the
/// same frames exposed within range get none.
#[test]
fn clipped_raw_frames_are_a_warning() {
    let (_synth_dir, reference) = synth_capture(4, 32);
    let full_scale = max_s0(&reference);
    let within = SimulateOptions {
        bit_depth: 12,
        full_scale,
        ..SimulateOptions::default()
    };
    let (_dir, loaded) = simulate(&reference, &within);
    assert!(
        !loaded.warnings.iter().any(|w| w.contains("maximum")),
        "{:?}",
        loaded.warnings
    );
    let overexposed = SimulateOptions {
        full_scale: full_scale / 4.0,
        ..within
    };
    let (_dir, loaded) = simulate(&reference, &overexposed);
    let warning = loaded
        .warnings
        .iter()
        .find(|w| w.contains("sensor's maximum"))
        .unwrap_or_else(|| panic!("no clipping warning in {:?}", loaded.warnings));
    assert!(warning.starts_with("4 raw frame(s)"), "{warning}");
    assert!(warning.contains("frames 0 ("), "{warning}");
}
