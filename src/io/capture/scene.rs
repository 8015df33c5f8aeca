//! The environment maps a capture folder's `scene.json` names (`DATA_FORMAT.md` §6 and §9):
//! `env_map.train_test`, the light of the training and test views, and `env_map.relight`, the
//! light of their `relight_s0` ground truth. Training never reads them; evaluation does.

use std::path::{Path, PathBuf};

/// Which of the maps `scene.json` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneMap {
    /// `env_map.train_test`: the light the capture's views were taken under.
    TrainTest,
    /// `env_map.relight`: the light of the views' `relight_s0` images.
    Relight,
}

impl SceneMap {
    fn key(self) -> &'static str {
        match self {
            SceneMap::TrainTest => "train_test",
            SceneMap::Relight => "relight",
        }
    }
}

/// The path of the map `capture_dir/scene.json` names for `which`, where both the scene file and
/// the map exist (a capture without ground truth has neither, and that is not an error).
pub fn scene_map(capture_dir: &Path, which: SceneMap) -> Option<PathBuf> {
    let text = std::fs::read_to_string(capture_dir.join("scene.json")).ok()?;
    let scene: serde_json::Value = serde_json::from_str(&text).ok()?;
    let relative = scene["env_map"][which.key()].as_str()?;
    Some(capture_dir.join(relative)).filter(|path| path.is_file())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_maps_scene_json_names_where_they_exist() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(scene_map(dir.path(), SceneMap::Relight), None);
        std::fs::create_dir(dir.path().join("env")).unwrap();
        std::fs::write(dir.path().join("env/sky.exr"), b"x").unwrap();
        std::fs::write(dir.path().join("env/studio.exr"), b"x").unwrap();
        std::fs::write(
            dir.path().join("scene.json"),
            r#"{"env_map": {"train_test": "env/sky.exr", "relight": "env/studio.exr"}}"#,
        )
        .unwrap();
        assert_eq!(
            scene_map(dir.path(), SceneMap::TrainTest),
            Some(dir.path().join("env/sky.exr"))
        );
        assert_eq!(
            scene_map(dir.path(), SceneMap::Relight),
            Some(dir.path().join("env/studio.exr"))
        );
        // A map the scene names but the folder lacks is not used; nor is a scene that is not JSON.
        std::fs::remove_file(dir.path().join("env/studio.exr")).unwrap();
        assert_eq!(scene_map(dir.path(), SceneMap::Relight), None);
        std::fs::write(dir.path().join("scene.json"), b"{not json").unwrap();
        assert_eq!(scene_map(dir.path(), SceneMap::TrainTest), None);
    }
}
