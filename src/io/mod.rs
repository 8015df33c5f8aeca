//! What comes in and goes out of a run: captures (`transforms.json` with its images and masks,
//! validated before training) and the trained model folder. Uses [`crate::formats`] and
//! [`crate::core`].

pub mod capture;
pub mod model;
