//! The environment maps a capture folder's `scene.json` names (`DATA_FORMAT.md` §6 and §9):
//! `env_map.train_test`, the light of the training and test views, and `env_map.relight`, the
//! light of their `relight_s0` ground truth. Training never reads them; evaluation does.

use std::path::{Path, PathBuf};

/// The maps `scene.json` names, each where both the scene file and the map exist (a capture
/// without ground truth has neither, and that is not an error).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SceneMaps {
    /// `env_map.train_test`: the light the capture's views were taken under.
    pub train_test: Option<PathBuf>,
    /// `env_map.relight`: the light of the views' `relight_s0` images.
    pub relight: Option<PathBuf>,
}

impl SceneMaps {
    /// Reads `capture_dir/scene.json` once.
    pub fn read(capture_dir: &Path) -> Self {
        let Some(scene) = std::fs::read_to_string(capture_dir.join("scene.json"))
            .ok()
            .and_then(|text| serde_json::from_str::<serde_json::Value>(&text).ok())
        else {
            return SceneMaps::default();
        };
        let map = |key: &str| {
            let relative = scene["env_map"][key].as_str()?;
            Some(capture_dir.join(relative)).filter(|path| path.is_file())
        };
        SceneMaps {
            train_test: map("train_test"),
            relight: map("relight"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_maps_scene_json_names_where_they_exist() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(SceneMaps::read(dir.path()), SceneMaps::default());
        std::fs::create_dir(dir.path().join("env")).unwrap();
        std::fs::write(dir.path().join("env/sky.exr"), b"x").unwrap();
        std::fs::write(dir.path().join("env/studio.exr"), b"x").unwrap();
        std::fs::write(
            dir.path().join("scene.json"),
            r#"{"env_map": {"train_test": "env/sky.exr", "relight": "env/studio.exr"}}"#,
        )
        .unwrap();
        assert_eq!(
            SceneMaps::read(dir.path()),
            SceneMaps {
                train_test: Some(dir.path().join("env/sky.exr")),
                relight: Some(dir.path().join("env/studio.exr")),
            }
        );
        // A map the scene names but the folder lacks is not used; nor is a scene that is not JSON.
        std::fs::remove_file(dir.path().join("env/studio.exr")).unwrap();
        let maps = SceneMaps::read(dir.path());
        assert_eq!(maps.relight, None);
        assert_eq!(maps.train_test, Some(dir.path().join("env/sky.exr")));
        std::fs::write(dir.path().join("scene.json"), b"{not json").unwrap();
        assert_eq!(SceneMaps::read(dir.path()), SceneMaps::default());
    }
}
