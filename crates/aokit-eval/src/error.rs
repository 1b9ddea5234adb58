//! The crate's one error type.

use std::path::{Path, PathBuf};

/// Everything that can go wrong reading or writing images.
///
/// Every message names the file and the problem, so a caller can print it as it is.
#[derive(Debug, thiserror::Error)]
pub enum EvalError {
    /// The operating system refused to read or write the file.
    #[error("cannot {action} {}: {error}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// `"read"` or `"write"`.
        action: &'static str,
        /// What the operating system said.
        error: std::io::Error,
    },
    /// The file's contents are not an image this crate reads (bad header, wrong channels,
    /// unsupported type, truncated data).
    #[error("{}: {problem}", path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        problem: String,
    },
    /// The data handed to a writer does not describe an image (zero size, wrong length, bad
    /// channel names).
    #[error("cannot write {}: {problem}", path.display())]
    Data {
        /// The file that was to be written.
        path: PathBuf,
        /// What is wrong with the data.
        problem: String,
    },
    /// The data handed to an in-memory PNG encoder does not describe an image.
    #[error("cannot encode a PNG in memory: {problem}")]
    Encode {
        /// What is wrong with the data.
        problem: String,
    },
}

impl EvalError {
    pub(crate) fn format(path: &Path, problem: impl Into<String>) -> Self {
        Self::Format {
            path: path.to_path_buf(),
            problem: problem.into(),
        }
    }

    pub(crate) fn data(path: &Path, problem: impl Into<String>) -> Self {
        Self::Data {
            path: path.to_path_buf(),
            problem: problem.into(),
        }
    }

    pub(crate) fn io(path: &Path, action: &'static str, error: std::io::Error) -> Self {
        Self::Io {
            path: path.to_path_buf(),
            action,
            error,
        }
    }
}

/// Shorthand for results whose error is [`EvalError`].
pub type Result<T, E = EvalError> = std::result::Result<T, E>;

/// The whole file, with the path in the error.
pub(crate) fn read_file(path: &Path) -> Result<Vec<u8>> {
    std::fs::read(path).map_err(|e| EvalError::io(path, "read", e))
}
