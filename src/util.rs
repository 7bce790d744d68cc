//! Small shared helpers.
use std::path::Path;

/// Writes a file through a temporary sibling and a rename, so a crash never leaves half a file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension(format!(
        "{}.tmp",
        path.extension().and_then(|e| e.to_str()).unwrap_or("")
    ));
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}

/// The value of environment variable `name` among `choices` (name, value); unset gives `None`,
/// and a value that is none of the names gives `None` with a warning naming the choices.
pub fn env_choice<T: Copy>(name: &str, choices: &[(&str, T)]) -> Option<T> {
    let v = std::env::var(name).ok()?;
    let found = choices.iter().find(|c| c.0 == v).map(|c| c.1);
    if found.is_none() {
        let names: Vec<&str> = choices.iter().map(|c| c.0).collect();
        eprintln!(
            "warning: {name}={v} is not one of {}; using the device's default",
            names.join("|")
        );
    }
    found
}

#[cfg(test)]
mod tests {
    use super::env_choice;

    #[test]
    fn env_choice_reads_known_values_and_ignores_others() {
        let var = "DREAMSCENE_TEST_ENV_CHOICE";
        let choices = [("a", 1), ("b", 2)];
        std::env::remove_var(var);
        assert_eq!(env_choice(var, &choices), None);
        std::env::set_var(var, "b");
        assert_eq!(env_choice(var, &choices), Some(2));
        std::env::set_var(var, "c");
        assert_eq!(env_choice(var, &choices), None);
        std::env::remove_var(var);
    }
}
