//! Saving and loading surfels as PLY with the property names 3DGS/2DGS viewers read
//! (`x y z`, `nx ny nz`, `f_dc_0..2`, `opacity`, `scale_0 scale_1`, `rot_0..3`), plus the
//! material parameters as extra properties (`albedo_0..2`, `roughness`, `ior`, raw logits).
//!
//! Conventions: `opacity`, `scale_*`, `rot_*` are the raw parameters (logit, log, unnormalized
//! quaternion w x y z), as in 3DGS; `f_dc_*` is the albedo as the degree-0 spherical-harmonic
//! coefficient, (albedo − 0.5) / C0; `nx ny nz` is the surfel normal. Values are stored as float32.

use std::path::Path;

use crate::formats::ply::{read_ply, write_ply, Element, Ply, PlyError, PlyFormat, ScalarType};

use super::{logit, Surfels, IOR_MIN};

/// The degree-0 real spherical harmonic, 1 / (2 √π).
pub const SH_C0: f64 = 0.282_094_791_773_878_14;
/// Roughness given to surfels read from a plain 3DGS file (no `roughness` property).
const DEFAULT_ROUGHNESS: f64 = 0.1;
/// IoR given to surfels read from a plain 3DGS file (no `ior` property).
const DEFAULT_IOR: f64 = 1.8;

/// The PLY document of a set of surfels.
pub fn surfels_to_ply(surfels: &Surfels) -> Ply {
    let n = surfels.len();
    let activated: Vec<_> = (0..n).map(|i| surfels.get(i)).collect();
    let mut columns: Vec<(String, Vec<f64>)> = Vec::new();
    let mut add = |name: &str, f: &dyn Fn(usize) -> f64| {
        columns.push((name.to_owned(), (0..n).map(f).collect()));
    };
    for (a, name) in ["x", "y", "z"].iter().enumerate() {
        add(name, &|i| surfels.position[i][a]);
    }
    for (a, name) in ["nx", "ny", "nz"].iter().enumerate() {
        add(name, &|i| activated[i].rotation.z_axis[a]);
    }
    for c in 0..3 {
        add(&format!("f_dc_{c}"), &|i| {
            (activated[i].albedo[c] - 0.5) / SH_C0
        });
    }
    add("opacity", &|i| surfels.opacity[i]);
    for a in 0..2 {
        add(&format!("scale_{a}"), &|i| surfels.log_scale[i][a]);
    }
    for a in 0..4 {
        add(&format!("rot_{a}"), &|i| surfels.rotation[i][a]);
    }
    for c in 0..3 {
        add(&format!("albedo_{c}"), &|i| surfels.albedo[i][c]);
    }
    add("roughness", &|i| surfels.roughness[i]);
    add("ior", &|i| surfels.ior[i]);
    let vertex = columns
        .into_iter()
        .fold(Element::new("vertex", n), |element, (name, values)| {
            element.with_scalar(&name, ScalarType::F32, values)
        });
    Ply {
        format: PlyFormat::BinaryLittleEndian,
        comments: vec![
            "phygap 2D Gaussian surfels (2DGS layout: two scales); albedo_*, roughness, ior are raw logits"
                .into(),
        ],
        elements: vec![vertex],
    }
}

/// Writes surfels as a binary little-endian PLY.
pub fn save_ply(path: &Path, surfels: &Surfels) -> Result<(), PlyError> {
    write_ply(path, &surfels_to_ply(surfels))
}

/// Reads surfels from a PLY written by [`save_ply`] or by a 2DGS trainer (then the albedo comes
/// from `f_dc_*`, and roughness and IoR take their initial values).
pub fn load_ply(path: &Path) -> Result<Surfels, PlyError> {
    surfels_from_ply(&read_ply(path)?)
}

/// Extracts surfels from a PLY document.
pub fn surfels_from_ply(ply: &Ply) -> Result<Surfels, PlyError> {
    let vertex = ply.require_element("vertex")?;
    let n = vertex.count;
    let get = |name: &str| vertex.require_scalar(name);
    let [x, y, z] = [get("x")?, get("y")?, get("z")?];
    let [s0, s1] = [get("scale_0")?, get("scale_1")?];
    let rot = [get("rot_0")?, get("rot_1")?, get("rot_2")?, get("rot_3")?];
    let opacity = get("opacity")?;
    let albedo: Vec<[f64; 3]> = match (
        vertex.scalar("albedo_0"),
        vertex.scalar("albedo_1"),
        vertex.scalar("albedo_2"),
    ) {
        (Some(a), Some(b), Some(c)) => (0..n).map(|i| [a[i], b[i], c[i]]).collect(),
        _ => {
            let dc = [get("f_dc_0")?, get("f_dc_1")?, get("f_dc_2")?];
            (0..n)
                .map(|i| dc.map(|d| logit(d[i] * SH_C0 + 0.5)))
                .collect()
        }
    };
    let roughness = match vertex.scalar("roughness") {
        Some(r) => r.to_vec(),
        None => vec![logit(DEFAULT_ROUGHNESS); n],
    };
    let ior = match vertex.scalar("ior") {
        Some(r) => r.to_vec(),
        None => vec![logit(DEFAULT_IOR - IOR_MIN); n],
    };
    let surfels = Surfels {
        position: (0..n).map(|i| [x[i], y[i], z[i]]).collect(),
        log_scale: (0..n).map(|i| [s0[i], s1[i]]).collect(),
        rotation: (0..n)
            .map(|i| [rot[0][i], rot[1][i], rot[2][i], rot[3][i]])
            .collect(),
        opacity: opacity.to_vec(),
        albedo,
        roughness,
        ior,
    };
    if let Some(i) = (0..n).find(|&i| {
        let q = surfels.rotation[i];
        q.iter().map(|v| v * v).sum::<f64>() == 0.0
    }) {
        return Err(PlyError::Body {
            element: "vertex".into(),
            row: i,
            message: "zero rotation quaternion".into(),
        });
    }
    Ok(surfels)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec2, DVec3};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_surfels(seed: u64, n: usize) -> Surfels {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut s = Surfels::default();
        for _ in 0..n {
            let mut r = || rng.random::<f64>();
            let q = DQuat::from_xyzw(r() - 0.5, r() - 0.5, r() - 0.5, r() - 0.5).normalize();
            s.push_activated(&super::super::Surfel {
                position: DVec3::new(r() * 2.0 - 1.0, r() * 2.0 - 1.0, r() * 2.0 - 1.0),
                scale: DVec2::new(0.01 + r() * 0.1, 0.01 + r() * 0.1),
                rotation: glam::DMat3::from_quat(q),
                opacity: 0.05 + 0.9 * r(),
                albedo: DVec3::new(0.05 + 0.9 * r(), 0.05 + 0.9 * r(), 0.05 + 0.9 * r()),
                roughness: 0.05 + 0.9 * r(),
                ior: 1.35 + 0.9 * r(),
            });
        }
        s
    }

    #[test]
    fn surfels_round_trip_through_ply() {
        for seed in 0..3 {
            let surfels = random_surfels(seed, 50);
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("s.ply");
            save_ply(&path, &surfels).unwrap();
            let back = load_ply(&path).unwrap();
            assert_eq!(back.len(), 50);
            for ((name, a), (_, b)) in surfels.groups().iter().zip(back.groups().iter()) {
                for (x, y) in a.iter().zip(b.iter()) {
                    assert!(
                        (x - y).abs() <= 1e-6 * x.abs().max(1.0),
                        "{name}: {x} vs {y} (float32 storage)"
                    );
                }
            }
        }
    }

    #[test]
    fn viewer_properties_hold_activated_values() {
        let surfels = random_surfels(7, 5);
        let ply = surfels_to_ply(&surfels);
        let v = ply.require_element("vertex").unwrap();
        let names: Vec<&str> = v.properties.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "x",
                "y",
                "z",
                "nx",
                "ny",
                "nz",
                "f_dc_0",
                "f_dc_1",
                "f_dc_2",
                "opacity",
                "scale_0",
                "scale_1",
                "rot_0",
                "rot_1",
                "rot_2",
                "rot_3",
                "albedo_0",
                "albedo_1",
                "albedo_2",
                "roughness",
                "ior"
            ]
        );
        for i in 0..5 {
            let s = surfels.get(i);
            let albedo_from_dc = v.scalar("f_dc_1").unwrap()[i] * SH_C0 + 0.5;
            assert!((albedo_from_dc - s.albedo.y).abs() < 1e-12);
            let normal = DVec3::new(
                v.scalar("nx").unwrap()[i],
                v.scalar("ny").unwrap()[i],
                v.scalar("nz").unwrap()[i],
            );
            assert!((normal - s.rotation.x_axis.cross(s.rotation.y_axis)).length() < 1e-12);
        }
    }

    #[test]
    fn plain_3dgs_files_get_albedo_from_dc_and_default_materials() {
        let surfels = random_surfels(3, 4);
        let mut ply = surfels_to_ply(&surfels);
        ply.elements[0]
            .properties
            .retain(|(n, _)| !n.starts_with("albedo") && n != "roughness" && n != "ior");
        let back = surfels_from_ply(&ply).unwrap();
        for i in 0..4 {
            let (a, b) = (surfels.get(i), back.get(i));
            assert!((a.albedo - b.albedo).abs().max_element() < 1e-9);
            assert!((b.roughness - DEFAULT_ROUGHNESS).abs() < 1e-9);
            assert!((b.ior - DEFAULT_IOR).abs() < 1e-9);
        }
        ply.elements[0].properties.retain(|(n, _)| n != "scale_1");
        let e = surfels_from_ply(&ply).unwrap_err().to_string();
        assert!(e.contains("scale_1"), "{e}");
    }
}
