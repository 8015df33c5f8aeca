//! COLMAP sparse models (`cameras`, `images`, `points3D`) in both of COLMAP's formats: the binary
//! one (little-endian, as COLMAP's `read_write_model.py` reads it) and the text one, read into
//! plain records and written back (for tests and for exporting cameras).
//!
//! Binary layout: `cameras.bin` = u64 count, then per camera i32 id, i32 model id, u64 width,
//! u64 height, f64 params[n(model)]; `images.bin` = u64 count, per image i32 id, f64 qvec[4]
//! (w, x, y, z), f64 tvec[3], i32 camera id, NUL-terminated name, u64 n, then n × (f64 x, f64 y,
//! i64 point3D id); `points3D.bin` = u64 count, per point u64 id, f64 xyz[3], u8 rgb[3],
//! f64 error, u64 track length, then that many (i32 image id, i32 point2D index).
//! Every read is bounds-checked: a truncated or malformed file is a [`ColmapError`], never a panic.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::ColmapError;

/// COLMAP's camera models: (id, name, number of parameters).
pub const CAMERA_MODELS: [(i32, &str, usize); 12] = [
    (0, "SIMPLE_PINHOLE", 3),
    (1, "PINHOLE", 4),
    (2, "SIMPLE_RADIAL", 4),
    (3, "RADIAL", 5),
    (4, "OPENCV", 8),
    (5, "OPENCV_FISHEYE", 8),
    (6, "FULL_OPENCV", 12),
    (7, "FOV", 5),
    (8, "SIMPLE_RADIAL_FISHEYE", 4),
    (9, "RADIAL_FISHEYE", 5),
    (10, "THIN_PRISM_FISHEYE", 12),
    (11, "RAD_TAN_THIN_PRISM_FISHEYE", 16),
];

fn model_by_id(id: i32) -> Option<(&'static str, usize)> {
    CAMERA_MODELS.iter().find(|m| m.0 == id).map(|m| (m.1, m.2))
}

fn model_by_name(name: &str) -> Option<(i32, usize)> {
    CAMERA_MODELS
        .iter()
        .find(|m| m.1 == name)
        .map(|m| (m.0, m.2))
}

/// One camera (intrinsics) of a model.
#[derive(Clone, Debug, PartialEq)]
pub struct ColmapCamera {
    pub id: i32,
    /// Model name, e.g. `PINHOLE`.
    pub model: String,
    pub width: u64,
    pub height: u64,
    pub params: Vec<f64>,
}

/// One registered image: its world-to-camera pose (OpenCV axes) and 2D observations.
#[derive(Clone, Debug, PartialEq)]
pub struct ColmapImage {
    pub id: i32,
    /// Rotation quaternion (w, x, y, z) of world → camera.
    pub qvec: [f64; 4],
    /// Translation of world → camera: x_cam = R x_world + t.
    pub tvec: [f64; 3],
    pub camera_id: i32,
    pub name: String,
    /// (x, y, point3D id or −1).
    pub points2d: Vec<(f64, f64, i64)>,
}

/// One triangulated point.
#[derive(Clone, Debug, PartialEq)]
pub struct ColmapPoint {
    pub id: u64,
    pub xyz: [f64; 3],
    pub rgb: [u8; 3],
    pub error: f64,
    /// (image id, point2D index) per observation.
    pub track: Vec<(i32, i32)>,
}

/// A whole sparse model.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ColmapModel {
    pub cameras: BTreeMap<i32, ColmapCamera>,
    pub images: BTreeMap<i32, ColmapImage>,
    pub points: Vec<ColmapPoint>,
}

/// Which of COLMAP's two formats a model folder holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ModelFormat {
    Binary,
    Text,
}

impl ModelFormat {
    fn extension(self) -> &'static str {
        match self {
            ModelFormat::Binary => "bin",
            ModelFormat::Text => "txt",
        }
    }
}

/// Reads `cameras`, `images` and (if present) `points3D` from `dir` in `format`.
pub fn read_model(dir: &Path, format: ModelFormat) -> Result<ColmapModel, ColmapError> {
    let file = |name: &str| dir.join(format!("{name}.{}", format.extension()));
    let read = |path: &Path| {
        std::fs::read(path).map_err(|source| ColmapError::Io {
            path: path.to_owned(),
            source,
        })
    };
    let (cameras, images) = (file("cameras"), file("images"));
    let points = file("points3D");
    let model = match format {
        ModelFormat::Binary => ColmapModel {
            cameras: read_cameras_binary(&cameras, &read(&cameras)?)?,
            images: read_images_binary(&images, &read(&images)?)?,
            points: if points.is_file() {
                read_points_binary(&points, &read(&points)?)?
            } else {
                Vec::new()
            },
        },
        ModelFormat::Text => {
            let text = |path: &Path| {
                String::from_utf8(read(path)?).map_err(|_| ColmapError::Malformed {
                    path: path.to_owned(),
                    message: "not UTF-8 text".into(),
                })
            };
            ColmapModel {
                cameras: read_cameras_text(&cameras, &text(&cameras)?)?,
                images: read_images_text(&images, &text(&images)?)?,
                points: if points.is_file() {
                    read_points_text(&points, &text(&points)?)?
                } else {
                    Vec::new()
                },
            }
        }
    };
    Ok(model)
}

/// Writes the model into `dir` (created if needed) in `format`.
pub fn write_model(
    model: &ColmapModel,
    dir: &Path,
    format: ModelFormat,
) -> Result<(), ColmapError> {
    std::fs::create_dir_all(dir).map_err(|source| ColmapError::Io {
        path: dir.to_owned(),
        source,
    })?;
    let files: [(&str, Vec<u8>); 3] = match format {
        ModelFormat::Binary => [
            ("cameras", cameras_binary(model)?),
            ("images", images_binary(model)),
            ("points3D", points_binary(model)),
        ],
        ModelFormat::Text => [
            ("cameras", cameras_text(model).into_bytes()),
            ("images", images_text(model).into_bytes()),
            ("points3D", points_text(model).into_bytes()),
        ],
    };
    for (name, bytes) in files {
        let path = dir.join(format!("{name}.{}", format.extension()));
        std::fs::write(&path, bytes).map_err(|source| ColmapError::Io { path, source })?;
    }
    Ok(())
}

/// A bounds-checked little-endian reader over one file's bytes.
struct Reader<'a> {
    path: &'a Path,
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> Reader<'a> {
    fn new(path: &'a Path, bytes: &'a [u8]) -> Self {
        Reader {
            path,
            bytes,
            pos: 0,
        }
    }

    fn take<const N: usize>(&mut self, what: &dyn Fn() -> String) -> Result<[u8; N], ColmapError> {
        let end = self.pos + N;
        if end > self.bytes.len() {
            return Err(ColmapError::Truncated {
                path: self.path.to_owned(),
                what: what(),
                offset: self.pos,
                len: self.bytes.len(),
            });
        }
        let out: [u8; N] = self.bytes[self.pos..end]
            .try_into()
            .expect("slice of length N");
        self.pos = end;
        Ok(out)
    }

    fn u8(&mut self, what: &dyn Fn() -> String) -> Result<u8, ColmapError> {
        Ok(self.take::<1>(what)?[0])
    }
    fn i32(&mut self, what: &dyn Fn() -> String) -> Result<i32, ColmapError> {
        Ok(i32::from_le_bytes(self.take(what)?))
    }
    fn u64(&mut self, what: &dyn Fn() -> String) -> Result<u64, ColmapError> {
        Ok(u64::from_le_bytes(self.take(what)?))
    }
    fn i64(&mut self, what: &dyn Fn() -> String) -> Result<i64, ColmapError> {
        Ok(i64::from_le_bytes(self.take(what)?))
    }
    fn f64(&mut self, what: &dyn Fn() -> String) -> Result<f64, ColmapError> {
        Ok(f64::from_le_bytes(self.take(what)?))
    }

    /// A NUL-terminated UTF-8 string.
    fn c_string(&mut self, what: &dyn Fn() -> String) -> Result<String, ColmapError> {
        let rest = &self.bytes[self.pos..];
        let Some(nul) = rest.iter().position(|&b| b == 0) else {
            return Err(ColmapError::Truncated {
                path: self.path.to_owned(),
                what: format!("{} (no terminating NUL byte)", what()),
                offset: self.pos,
                len: self.bytes.len(),
            });
        };
        let text = std::str::from_utf8(&rest[..nul]).map_err(|_| ColmapError::Malformed {
            path: self.path.to_owned(),
            message: format!("{} at byte {} is not UTF-8", what(), self.pos),
        })?;
        self.pos += nul + 1;
        Ok(text.to_owned())
    }

    /// A record count, checked against the bytes left (each record needs at least `min_size`).
    fn count(&mut self, what: &str, min_size: usize) -> Result<usize, ColmapError> {
        let n = self.u64(&|| format!("the number of {what}"))?;
        let left = (self.bytes.len() - self.pos) as u64;
        if n > left / min_size as u64 {
            return Err(ColmapError::Truncated {
                path: self.path.to_owned(),
                what: format!("{n} {what} (at least {min_size} bytes each)"),
                offset: self.pos,
                len: self.bytes.len(),
            });
        }
        Ok(n as usize)
    }

    fn finish(&self) -> Result<(), ColmapError> {
        if self.pos != self.bytes.len() {
            return Err(ColmapError::Malformed {
                path: self.path.to_owned(),
                message: format!(
                    "{} unexpected bytes after the last record (at byte {})",
                    self.bytes.len() - self.pos,
                    self.pos
                ),
            });
        }
        Ok(())
    }
}

fn read_cameras_binary(
    path: &Path,
    bytes: &[u8],
) -> Result<BTreeMap<i32, ColmapCamera>, ColmapError> {
    let mut r = Reader::new(path, bytes);
    let n = r.count("cameras", 24)?;
    let mut cameras = BTreeMap::new();
    for k in 0..n {
        let id = r.i32(&|| format!("camera {k}'s id"))?;
        let model_id = r.i32(&|| format!("camera {id}'s model id"))?;
        let (model, n_params) = model_by_id(model_id).ok_or_else(|| ColmapError::UnknownModel {
            path: path.to_owned(),
            camera: id,
            model: format!("id {model_id}"),
        })?;
        let width = r.u64(&|| format!("camera {id}'s width"))?;
        let height = r.u64(&|| format!("camera {id}'s height"))?;
        let params = (0..n_params)
            .map(|i| r.f64(&|| format!("camera {id}'s parameter {i} of {n_params} ({model})")))
            .collect::<Result<Vec<f64>, _>>()?;
        cameras.insert(
            id,
            ColmapCamera {
                id,
                model: model.to_owned(),
                width,
                height,
                params,
            },
        );
    }
    r.finish()?;
    Ok(cameras)
}

fn read_images_binary(
    path: &Path,
    bytes: &[u8],
) -> Result<BTreeMap<i32, ColmapImage>, ColmapError> {
    let mut r = Reader::new(path, bytes);
    let n = r.count("images", 73)?;
    let mut images = BTreeMap::new();
    for k in 0..n {
        let id = r.i32(&|| format!("image {k}'s id"))?;
        let mut qvec = [0.0; 4];
        for (i, q) in qvec.iter_mut().enumerate() {
            *q = r.f64(&|| format!("image {id}'s qvec[{i}]"))?;
        }
        let mut tvec = [0.0; 3];
        for (i, t) in tvec.iter_mut().enumerate() {
            *t = r.f64(&|| format!("image {id}'s tvec[{i}]"))?;
        }
        let camera_id = r.i32(&|| format!("image {id}'s camera id"))?;
        let name = r.c_string(&|| format!("image {id}'s name"))?;
        let n_points = r.count(&format!("2D points of image {id}"), 24)?;
        let mut points2d = Vec::with_capacity(n_points);
        for p in 0..n_points {
            let what = || format!("2D point {p} of image {id}");
            points2d.push((r.f64(&what)?, r.f64(&what)?, r.i64(&what)?));
        }
        images.insert(
            id,
            ColmapImage {
                id,
                qvec,
                tvec,
                camera_id,
                name,
                points2d,
            },
        );
    }
    r.finish()?;
    Ok(images)
}

fn read_points_binary(path: &Path, bytes: &[u8]) -> Result<Vec<ColmapPoint>, ColmapError> {
    let mut r = Reader::new(path, bytes);
    let n = r.count("points", 51)?;
    let mut points = Vec::with_capacity(n);
    for k in 0..n {
        let id = r.u64(&|| format!("point {k}'s id"))?;
        let what = || format!("point {id}");
        let xyz = [r.f64(&what)?, r.f64(&what)?, r.f64(&what)?];
        let rgb = [r.u8(&what)?, r.u8(&what)?, r.u8(&what)?];
        let error = r.f64(&what)?;
        let track_length = r.count(&format!("track entries of point {id}"), 8)?;
        let mut track = Vec::with_capacity(track_length);
        for _ in 0..track_length {
            let what = || format!("the track of point {id}");
            track.push((r.i32(&what)?, r.i32(&what)?));
        }
        points.push(ColmapPoint {
            id,
            xyz,
            rgb,
            error,
            track,
        });
    }
    r.finish()?;
    Ok(points)
}

/// Data lines of a text file: (1-based line number, line), skipping blank lines and `#` comments.
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

fn text_error(path: &Path, line: usize, message: impl Into<String>) -> ColmapError {
    ColmapError::Text {
        path: path.to_owned(),
        line,
        message: message.into(),
    }
}

/// Parses one whitespace-separated field.
fn field<T: std::str::FromStr>(
    path: &Path,
    line: usize,
    fields: &[&str],
    index: usize,
    what: &str,
) -> Result<T, ColmapError> {
    let text = fields
        .get(index)
        .ok_or_else(|| text_error(path, line, format!("missing {what} (field {})", index + 1)))?;
    text.parse()
        .map_err(|_| text_error(path, line, format!("{what} {text:?} is not a valid number")))
}

fn read_cameras_text(path: &Path, text: &str) -> Result<BTreeMap<i32, ColmapCamera>, ColmapError> {
    let mut cameras = BTreeMap::new();
    for (line, content) in data_lines(text) {
        let f: Vec<&str> = content.split_whitespace().collect();
        let id: i32 = field(path, line, &f, 0, "CAMERA_ID")?;
        let model = *f
            .get(1)
            .ok_or_else(|| text_error(path, line, "missing MODEL"))?;
        let (_, n_params) = model_by_name(model).ok_or_else(|| ColmapError::UnknownModel {
            path: path.to_owned(),
            camera: id,
            model: model.to_owned(),
        })?;
        let width = field(path, line, &f, 2, "WIDTH")?;
        let height = field(path, line, &f, 3, "HEIGHT")?;
        if f.len() != 4 + n_params {
            return Err(text_error(
                path,
                line,
                format!(
                    "{model} has {n_params} parameters, found {}",
                    f.len().saturating_sub(4)
                ),
            ));
        }
        let params = (0..n_params)
            .map(|i| field(path, line, &f, 4 + i, "parameter"))
            .collect::<Result<Vec<f64>, _>>()?;
        cameras.insert(
            id,
            ColmapCamera {
                id,
                model: model.to_owned(),
                width,
                height,
                params,
            },
        );
    }
    Ok(cameras)
}

fn read_images_text(path: &Path, text: &str) -> Result<BTreeMap<i32, ColmapImage>, ColmapError> {
    let mut images = BTreeMap::new();
    // An image is two lines; the second (its 2D points) may be empty, so it is taken as is.
    let lines: Vec<&str> = text.lines().collect();
    let mut i = 0;
    while i < lines.len() {
        let (line, content) = (i + 1, lines[i].trim());
        i += 1;
        if content.is_empty() || content.starts_with('#') {
            continue;
        }
        let f: Vec<&str> = content.split_whitespace().collect();
        if f.len() < 10 {
            return Err(text_error(
                path,
                line,
                format!(
                    "expected IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME; found {} fields",
                    f.len()
                ),
            ));
        }
        let id: i32 = field(path, line, &f, 0, "IMAGE_ID")?;
        let q: Vec<f64> = (1..5)
            .map(|k| field(path, line, &f, k, "quaternion component"))
            .collect::<Result<_, _>>()?;
        let t: Vec<f64> = (5..8)
            .map(|k| field(path, line, &f, k, "translation component"))
            .collect::<Result<_, _>>()?;
        let camera_id = field(path, line, &f, 8, "CAMERA_ID")?;
        let name = f[9].to_owned();
        let points_line = lines.get(i).copied().unwrap_or("");
        let p: Vec<&str> = points_line.split_whitespace().collect();
        if !p.len().is_multiple_of(3) {
            return Err(text_error(
                path,
                i + 1,
                format!(
                    "2D points of image {id} must be triples X Y POINT3D_ID, found {} values",
                    p.len()
                ),
            ));
        }
        let points2d = p
            .chunks(3)
            .enumerate()
            .map(|(k, c)| {
                Ok((
                    field(path, i + 1, c, 0, &format!("X of 2D point {k}"))?,
                    field(path, i + 1, c, 1, &format!("Y of 2D point {k}"))?,
                    field(path, i + 1, c, 2, &format!("POINT3D_ID of 2D point {k}"))?,
                ))
            })
            .collect::<Result<Vec<_>, ColmapError>>()?;
        i += 1;
        images.insert(
            id,
            ColmapImage {
                id,
                qvec: [q[0], q[1], q[2], q[3]],
                tvec: [t[0], t[1], t[2]],
                camera_id,
                name,
                points2d,
            },
        );
    }
    Ok(images)
}

fn read_points_text(path: &Path, text: &str) -> Result<Vec<ColmapPoint>, ColmapError> {
    let mut points = Vec::new();
    for (line, content) in data_lines(text) {
        let f: Vec<&str> = content.split_whitespace().collect();
        if f.len() < 8 || !(f.len() - 8).is_multiple_of(2) {
            return Err(text_error(
                path,
                line,
                "expected POINT3D_ID, X, Y, Z, R, G, B, ERROR, then (IMAGE_ID, POINT2D_IDX) pairs",
            ));
        }
        let id = field(path, line, &f, 0, "POINT3D_ID")?;
        let xyz = [
            field(path, line, &f, 1, "X")?,
            field(path, line, &f, 2, "Y")?,
            field(path, line, &f, 3, "Z")?,
        ];
        let rgb = [
            field(path, line, &f, 4, "R")?,
            field(path, line, &f, 5, "G")?,
            field(path, line, &f, 6, "B")?,
        ];
        let error = field(path, line, &f, 7, "ERROR")?;
        let track = (8..f.len())
            .step_by(2)
            .map(|k| {
                Ok((
                    field(path, line, &f, k, "IMAGE_ID")?,
                    field(path, line, &f, k + 1, "POINT2D_IDX")?,
                ))
            })
            .collect::<Result<Vec<_>, ColmapError>>()?;
        points.push(ColmapPoint {
            id,
            xyz,
            rgb,
            error,
            track,
        });
    }
    Ok(points)
}

fn cameras_binary(model: &ColmapModel) -> Result<Vec<u8>, ColmapError> {
    let mut out = Vec::new();
    out.extend((model.cameras.len() as u64).to_le_bytes());
    for camera in model.cameras.values() {
        let (model_id, n) =
            model_by_name(&camera.model).ok_or_else(|| ColmapError::UnknownModel {
                path: PathBuf::from("cameras.bin"),
                camera: camera.id,
                model: camera.model.clone(),
            })?;
        if n != camera.params.len() {
            return Err(ColmapError::Malformed {
                path: PathBuf::from("cameras.bin"),
                message: format!(
                    "camera {} ({}) has {} parameters, the model needs {n}",
                    camera.id,
                    camera.model,
                    camera.params.len()
                ),
            });
        }
        out.extend(camera.id.to_le_bytes());
        out.extend(model_id.to_le_bytes());
        out.extend(camera.width.to_le_bytes());
        out.extend(camera.height.to_le_bytes());
        for p in &camera.params {
            out.extend(p.to_le_bytes());
        }
    }
    Ok(out)
}

fn images_binary(model: &ColmapModel) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend((model.images.len() as u64).to_le_bytes());
    for image in model.images.values() {
        out.extend(image.id.to_le_bytes());
        for v in image.qvec.iter().chain(&image.tvec) {
            out.extend(v.to_le_bytes());
        }
        out.extend(image.camera_id.to_le_bytes());
        out.extend(image.name.as_bytes());
        out.push(0);
        out.extend((image.points2d.len() as u64).to_le_bytes());
        for (x, y, id) in &image.points2d {
            out.extend(x.to_le_bytes());
            out.extend(y.to_le_bytes());
            out.extend(id.to_le_bytes());
        }
    }
    out
}

fn points_binary(model: &ColmapModel) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend((model.points.len() as u64).to_le_bytes());
    for point in &model.points {
        out.extend(point.id.to_le_bytes());
        for v in point.xyz {
            out.extend(v.to_le_bytes());
        }
        out.extend(point.rgb);
        out.extend(point.error.to_le_bytes());
        out.extend((point.track.len() as u64).to_le_bytes());
        for (image, index) in &point.track {
            out.extend(image.to_le_bytes());
            out.extend(index.to_le_bytes());
        }
    }
    out
}

/// Numbers are written with Rust's shortest round-trip formatting, so text models are exact.
fn cameras_text(model: &ColmapModel) -> String {
    let mut out = String::from(
        "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n",
    );
    let _ = writeln!(out, "# Number of cameras: {}", model.cameras.len());
    for c in model.cameras.values() {
        let _ = write!(out, "{} {} {} {}", c.id, c.model, c.width, c.height);
        for p in &c.params {
            let _ = write!(out, " {p:?}");
        }
        out.push('\n');
    }
    out
}

fn images_text(model: &ColmapModel) -> String {
    let mut out = String::from(
        "# Image list with two lines of data per image:\n#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n#   POINTS2D[] as (X, Y, POINT3D_ID)\n",
    );
    let _ = writeln!(out, "# Number of images: {}", model.images.len());
    for im in model.images.values() {
        let [qw, qx, qy, qz] = im.qvec;
        let [tx, ty, tz] = im.tvec;
        let _ = writeln!(
            out,
            "{} {qw:?} {qx:?} {qy:?} {qz:?} {tx:?} {ty:?} {tz:?} {} {}",
            im.id, im.camera_id, im.name
        );
        let points: Vec<String> = im
            .points2d
            .iter()
            .map(|(x, y, id)| format!("{x:?} {y:?} {id}"))
            .collect();
        out.push_str(&points.join(" "));
        out.push('\n');
    }
    out
}

fn points_text(model: &ColmapModel) -> String {
    let mut out = String::from(
        "# 3D point list with one line of data per point:\n#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n",
    );
    let _ = writeln!(out, "# Number of points: {}", model.points.len());
    for p in &model.points {
        let [x, y, z] = p.xyz;
        let [r, g, b] = p.rgb;
        let _ = write!(out, "{} {x:?} {y:?} {z:?} {r} {g} {b} {:?}", p.id, p.error);
        for (image, index) in &p.track {
            let _ = write!(out, " {image} {index}");
        }
        out.push('\n');
    }
    out
}
