//! A small command-line argument reader: flags with values, boolean switches and
//! positionals, with errors that say which option is wrong and what it expects.

use std::collections::VecDeque;

/// Arguments of one sub-command, consumed as the command reads them.
pub struct Args {
    command: String,
    rest: VecDeque<String>,
    positionals: Vec<String>,
}

/// A usage error (exit status 2).
#[derive(Debug)]
pub struct UsageError(pub String);

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl Args {
    /// Arguments after the sub-command name.
    pub fn new(command: &str, args: Vec<String>) -> Args {
        Args { command: command.to_string(), rest: args.into(), positionals: Vec::new() }
    }

    /// Take `--name VALUE` (or `--name=VALUE`) if present.
    pub fn value(&mut self, name: &str) -> Result<Option<String>, UsageError> {
        let flag = format!("--{name}");
        let prefix = format!("--{name}=");
        let mut found = None;
        let mut i = 0;
        while i < self.rest.len() {
            if self.rest[i] == flag {
                let v = self.rest.remove(i + 1).ok_or_else(|| UsageError(format!("{} {flag}: expects a value", self.command)))?;
                self.rest.remove(i);
                if found.replace(v).is_some() {
                    return Err(UsageError(format!("{} {flag}: given twice", self.command)));
                }
                continue;
            }
            if let Some(v) = self.rest[i].strip_prefix(&prefix) {
                let v = v.to_string();
                self.rest.remove(i);
                if found.replace(v).is_some() {
                    return Err(UsageError(format!("{} {flag}: given twice", self.command)));
                }
                continue;
            }
            i += 1;
        }
        Ok(found)
    }

    /// Take a boolean `--name` switch.
    pub fn switch(&mut self, name: &str) -> bool {
        let flag = format!("--{name}");
        let before = self.rest.len();
        self.rest.retain(|a| *a != flag);
        before != self.rest.len()
    }

    /// Collect positionals; fails on any unknown `--option` left over.
    pub fn finish(&mut self) -> Result<Vec<String>, UsageError> {
        while let Some(a) = self.rest.pop_front() {
            if a == "--" {
                self.positionals.extend(self.rest.drain(..));
                break;
            }
            if a.starts_with("--") && a.len() > 2 {
                return Err(UsageError(format!("{}: unknown option {a} (see `garmentcode help`)", self.command)));
            }
            self.positionals.push(a);
        }
        Ok(std::mem::take(&mut self.positionals))
    }
}
