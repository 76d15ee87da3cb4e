//! The repository a command is run in, found at run time from the current
//! directory, never through the path a binary was built at: a binary
//! installed elsewhere, or built from another checkout, must read the files
//! of the repository the user is in (`lemmas/last-run.json`,
//! `counterexamples/`), or say that there is none.

use std::path::{Path, PathBuf};

/// The files that mark the workspace's root.
const MARKERS: [&str; 3] = ["Cargo.toml", "lemmas", "counterexamples"];

/// The nearest ancestor of `from` (itself included) holding `Cargo.toml`,
/// `lemmas/` and `counterexamples/`.
pub fn root_from(from: &Path) -> Option<PathBuf> {
    from.ancestors()
        .find(|dir| MARKERS.iter().all(|m| dir.join(m).exists()))
        .map(Path::to_path_buf)
}

/// [`root_from`] the current directory, or an error that says where it was
/// looked for and what to do.
pub fn root() -> Result<PathBuf, String> {
    let here =
        std::env::current_dir().map_err(|e| format!("cannot read the current directory: {e}"))?;
    root_from(&here).ok_or_else(|| {
        format!(
            "{} is not inside a copy of this repository (no folder above it holds \
             Cargo.toml, lemmas/ and counterexamples/); run the command inside one",
            here.display()
        )
    })
}

/// `relative` under [`root`].
pub fn path(relative: &str) -> Result<PathBuf, String> {
    root().map(|r| r.join(relative))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_root_is_found_from_below_and_not_from_outside() {
        let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let repo = repo.canonicalize().unwrap();
        let inside = repo.join("crates/hunt/src");
        assert_eq!(root_from(&inside).as_deref(), Some(repo.as_path()));
        let outside = std::env::temp_dir();
        assert_eq!(root_from(&outside), None);
    }
}
