//! Source positions and the info log, worded like Mesa's.
//!
//! Mesa prints every message as `SOURCE:LINE(COLUMN): KIND: TEXT`, where SOURCE is the
//! source-string number (0 unless `#line` changed it), LINE is 1-based and COLUMN is the
//! 1-based column. The preprocessor's messages (`preprocessor error`) count columns in
//! the source as written; the compiler's (`error`) count them in the preprocessed text,
//! where glcpp has collapsed each run of blanks and each comment into one space (see
//! [`crate::pp`] for how positions are carried through).

use std::fmt;

/// A position in the shader's source: source-string number, line and column, 1-based.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Pos {
    /// The source-string number (`#line`'s second argument, 0 by default).
    pub source: u32,
    /// The 1-based line.
    pub line: u32,
    /// The 1-based column.
    pub col: u32,
}

impl Pos {
    /// A position in source string 0.
    pub fn new(line: u32, col: u32) -> Pos {
        Pos {
            source: 0,
            line,
            col,
        }
    }
}

impl fmt::Display for Pos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}({})", self.source, self.line, self.col)
    }
}

/// How bad a message is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// The compile fails.
    Error,
    /// The compile goes on.
    Warning,
}

/// One line of the info log.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Message {
    /// Where the problem is.
    pub pos: Pos,
    /// Error or warning.
    pub severity: Severity,
    /// True for the preprocessor's messages (`preprocessor error:`).
    pub preprocessor: bool,
    /// The text after the kind.
    pub text: String,
}

impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        let pp = if self.preprocessor {
            "preprocessor "
        } else {
            ""
        };
        write!(f, "{}: {pp}{kind}: {}", self.pos, self.text)
    }
}

/// A compile's info log: its messages in order of discovery.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Log {
    /// The messages, errors and warnings mixed, in order.
    pub messages: Vec<Message>,
}

/// The most messages one log keeps (a hostile shader can make one per token).
pub const MAX_MESSAGES: usize = 100;

impl Log {
    fn push(&mut self, pos: Pos, severity: Severity, preprocessor: bool, text: String) {
        if self.messages.len() < MAX_MESSAGES {
            self.messages.push(Message {
                pos,
                severity,
                preprocessor,
                text,
            });
        }
    }

    /// Adds a compiler error.
    pub fn error(&mut self, pos: Pos, text: impl Into<String>) {
        self.push(pos, Severity::Error, false, text.into());
    }

    /// Adds a compiler warning.
    pub fn warning(&mut self, pos: Pos, text: impl Into<String>) {
        self.push(pos, Severity::Warning, false, text.into());
    }

    /// Adds a preprocessor error.
    pub fn pp_error(&mut self, pos: Pos, text: impl Into<String>) {
        self.push(pos, Severity::Error, true, text.into());
    }

    /// Adds a preprocessor warning.
    pub fn pp_warning(&mut self, pos: Pos, text: impl Into<String>) {
        self.push(pos, Severity::Warning, true, text.into());
    }

    /// True when the log holds an error.
    pub fn has_errors(&self) -> bool {
        self.messages.iter().any(|m| m.severity == Severity::Error)
    }

    /// The first error, if any.
    pub fn first_error(&self) -> Option<&Message> {
        self.messages.iter().find(|m| m.severity == Severity::Error)
    }
}

impl fmt::Display for Log {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for m in &self.messages {
            writeln!(f, "{m}")?;
        }
        Ok(())
    }
}
