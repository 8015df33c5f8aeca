//! Lens distortion in `transforms.json`: OpenCV's radial-tangential terms `k1`, `k2`, `p1`, `p2`,
//! per frame or at the top level as nerfstudio writes them (a frame's own value wins; absent terms
//! are 0), and the undistortion of loaded views into the pinhole views training assumes
//! ([`super::undistort`], shared with COLMAP's `OPENCV` cameras).
//!
//! Terms this undistortion does not model (`k3`, `k4`, a `camera_model` other than `PINHOLE`,
//! `SIMPLE_PINHOLE` or `OPENCV`) are named problems rather than ignored, so a capture is never
//! trained through an uncorrected lens. Views are undistorted in parallel (rayon).

use rayon::prelude::*;
use serde_json::Value;

use super::error::Problem;
use super::frame::TOP_LEVEL;
use super::undistort::{undistort_image, undistort_mask, Distortion};
use super::{Capture, Measurement};

const TERMS: [&str; 4] = ["k1", "k2", "p1", "p2"];
const UNMODELLED_TERMS: [&str; 2] = ["k3", "k4"];
const PINHOLE_MODELS: [&str; 3] = ["PINHOLE", "SIMPLE_PINHOLE", "OPENCV"];

/// The distortion of each frame of `document` (`None` where it is the identity), and the problems
/// found.
pub(crate) fn frame_distortions(document: &Value) -> (Vec<Option<Distortion>>, Vec<Problem>) {
    let mut problems = Vec::new();
    let frames = document
        .get("frames")
        .and_then(Value::as_array)
        .map(Vec::as_slice)
        .unwrap_or_default();
    let distortions = frames
        .iter()
        .enumerate()
        .map(|(index, frame)| {
            let label = format!("frame {index}");
            let term = |key: &str, problems: &mut Vec<Problem>| {
                let (owner, value) = match frame.get(key) {
                    Some(value) => (label.as_str(), value),
                    None => match document.get(key) {
                        Some(value) => (TOP_LEVEL, value),
                        None => return 0.0,
                    },
                };
                match value.as_f64().filter(|v| v.is_finite()) {
                    Some(v) => v,
                    None => {
                        problems.push(Problem::new(
                            owner,
                            key,
                            format!("expected a finite number, found {value}"),
                        ));
                        0.0
                    }
                }
            };
            for key in UNMODELLED_TERMS {
                if term(key, &mut problems) != 0.0 {
                    problems.push(Problem::new(
                        label.as_str(),
                        key,
                        "only k1, k2, p1, p2 (OpenCV's radial-tangential model) are undistorted; \
                         undistort the images first (e.g. `colmap image_undistorter`)",
                    ));
                }
            }
            let model = frame
                .get("camera_model")
                .or_else(|| document.get("camera_model"));
            if let Some(model) = model {
                if !model.as_str().is_some_and(|m| PINHOLE_MODELS.contains(&m)) {
                    problems.push(Problem::new(
                        label.as_str(),
                        "camera_model",
                        format!(
                            "{model} is not supported (expected one of {PINHOLE_MODELS:?}); \
                             undistort the images to a pinhole camera first"
                        ),
                    ));
                }
            }
            let [k1, k2, p1, p2] = TERMS.map(|key| term(key, &mut problems));
            Some(Distortion { k1, k2, p1, p2 }).filter(|d| !d.is_identity())
        })
        .collect();
    (distortions, problems)
}

/// Undistorts every view whose frame has a distortion (indexed by the view's `frame_index`):
/// its measurement images and its mask.
pub(crate) fn undistort_views(capture: &mut Capture, distortions: &[Option<Distortion>]) {
    capture
        .views
        .par_iter_mut()
        .filter_map(|view| {
            let d = distortions.get(view.frame_index).copied().flatten()?;
            Some((view, d))
        })
        .for_each(|(view, d)| {
            let camera = view.camera;
            let fix = |image: &mut crate::formats::image_io::Image| {
                *image = undistort_image(image, &camera, &d).0;
            };
            match &mut view.measurement {
                Measurement::Stokes { s0, s1, s2 } => {
                    fix(s0);
                    fix(s1);
                    fix(s2);
                }
                Measurement::Polarizer { image, .. } | Measurement::Rgb { image } => fix(image),
            }
            view.mask = undistort_mask(&view.mask, &camera, &d);
        });
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn terms_come_from_the_frame_then_the_top_level() {
        let document = json!({
            "k1": -0.1, "p2": 0.002,
            "frames": [{"k1": 0.05}, {}, {"k2": "x"}],
        });
        let (distortions, problems) = frame_distortions(&document);
        let d = |k1, k2, p1, p2| Some(Distortion { k1, k2, p1, p2 });
        assert_eq!(distortions[0], d(0.05, 0.0, 0.0, 0.002));
        assert_eq!(distortions[1], d(-0.1, 0.0, 0.0, 0.002));
        assert_eq!(problems.len(), 1);
        assert_eq!(
            (problems[0].frame.as_str(), problems[0].key.as_str()),
            ("frame 2", "k2")
        );
    }

    #[test]
    fn no_terms_is_no_distortion() {
        let (distortions, problems) =
            frame_distortions(&json!({"k1": 0, "frames": [{}, {"p1": 0.0}]}));
        assert_eq!(distortions, [None, None]);
        assert!(problems.is_empty());
    }

    #[test]
    fn unmodelled_terms_and_models_are_problems() {
        let document = json!({
            "camera_model": "OPENCV_FISHEYE",
            "frames": [{"k3": 0.01}, {"camera_model": "OPENCV", "k4": 0}],
        });
        let (_, problems) = frame_distortions(&document);
        let keys: Vec<(&str, &str)> = problems
            .iter()
            .map(|p| (p.frame.as_str(), p.key.as_str()))
            .collect();
        assert_eq!(
            keys,
            [("frame 0", "k3"), ("frame 0", "camera_model")],
            "{problems:?}"
        );
    }
}
