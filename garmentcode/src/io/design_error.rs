//! The error of design files and design spaces.

use std::fmt;

/// Problems found in a design file: each names the file, the position, the parameter
/// path, the bad value and what is allowed.
#[derive(Clone, Debug, PartialEq)]
pub struct DesignError {
    /// File name as given.
    pub file: String,
    /// One line per problem.
    pub problems: Vec<String>,
}

impl DesignError {
    pub(crate) fn single(file: &str, problem: String) -> DesignError {
        DesignError { file: file.to_string(), problems: vec![problem] }
    }
}

/// Problems a [`DesignError`] shows; the rest are counted.
pub const MAX_SHOWN: usize = 20;

impl fmt::Display for DesignError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.problems.len() == 1 {
            return write!(f, "{}: {}", self.file, self.problems[0]);
        }
        write!(f, "{}: {} problems", self.file, self.problems.len())?;
        for p in self.problems.iter().take(MAX_SHOWN) {
            write!(f, "\n  {p}")?;
        }
        if self.problems.len() > MAX_SHOWN {
            write!(f, "\n  ... and {} more", self.problems.len() - MAX_SHOWN)?;
        }
        Ok(())
    }
}

impl std::error::Error for DesignError {}
