//! The OpenAPI 3.1 description of the service: `api/openapi.yaml`, compiled in and served as JSON.

/// The YAML source.
pub const SPEC_YAML: &str = include_str!("../openapi.yaml");

/// The spec as JSON.
pub fn spec_json() -> Result<serde_json::Value, serde_yaml::Error> {
    serde_yaml::from_str(SPEC_YAML)
}

/// `(METHOD, path)` pairs the spec declares, path templates as written (`{id}`).
pub fn spec_operations(spec: &serde_json::Value) -> Vec<(String, String)> {
    const METHODS: [&str; 7] = ["get", "put", "post", "delete", "patch", "head", "options"];
    let mut operations = Vec::new();
    if let Some(paths) = spec.get("paths").and_then(|p| p.as_object()) {
        for (path, item) in paths {
            for method in METHODS {
                if item.get(method).is_some() {
                    operations.push((method.to_ascii_uppercase(), path.clone()));
                }
            }
        }
    }
    operations.sort();
    operations
}

/// An axum path template in OpenAPI form (`{*name}` → `{name}`).
pub fn openapi_path(axum_path: &str) -> String {
    axum_path.replace("{*", "{")
}
