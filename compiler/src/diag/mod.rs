//! Diagnostics: what every phase reports to the user, and the one place they are rendered.
//!
//! Each phase keeps its own error enum with typed data and spans (see `syntax::error`, `sema::error`);
//! each converts its errors into [`Diagnostic`]s in one function. Rendering happens only here, at the
//! edge: [`render_human`] prints in the style of rustc (`error[E0401]: …`, `--> file:line:col`, the
//! source line and a caret, secondary labels, notes and a `help:` line); [`render_json`] prints one
//! JSON object per diagnostic for editors and tools.
//!
//! Invariants:
//! - Every user-facing diagnostic has a stable [`Code`] from the single table in [`codes`]; the spec's
//!   `spec/diagnostics.md` documents each one (checked by a test).
//! - An internal compiler error (a bug in rtc, e.g. naga rejecting IR we built) uses [`codes::ICE`] and
//!   says so; it is never a panic.

pub mod codes;
pub mod suggest;

use crate::source::{SourceMap, Span};
pub use codes::Code;
use serde::Serialize;

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// Informational note.
    Note,
    /// Suspicious but accepted.
    Warning,
    /// The program is rejected.
    Error,
}

/// A span with a message, shown under the source line.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What to say there (may be empty).
    pub message: String,
}

/// One message to the user.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error, warning or note.
    pub severity: Severity,
    /// Stable code from [`codes`].
    pub code: Code,
    /// The headline, lower case, no trailing period.
    pub message: String,
    /// The primary location (its message may be empty).
    pub primary: Label,
    /// Further locations that explain the primary one.
    pub secondary: Vec<Label>,
    /// `note:` lines.
    pub notes: Vec<String>,
    /// A `help:` line, where one helps.
    pub help: Option<String>,
}

impl Diagnostic {
    /// An error with a code, a message and a primary span.
    pub fn error(code: Code, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            code,
            message: message.into(),
            primary: Label {
                span,
                message: String::new(),
            },
            secondary: Vec::new(),
            notes: Vec::new(),
            help: None,
        }
    }

    /// A warning with a code, a message and a primary span.
    pub fn warning(code: Code, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            ..Diagnostic::error(code, message, span)
        }
    }

    /// Sets the message under the primary span.
    pub fn with_label(mut self, message: impl Into<String>) -> Diagnostic {
        self.primary.message = message.into();
        self
    }

    /// Adds a secondary label.
    pub fn with_secondary(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.secondary.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Adds a `note:` line.
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// Sets the `help:` line.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Whether any diagnostic in the list is an error.
pub fn has_errors(diags: &[Diagnostic]) -> bool {
    diags.iter().any(Diagnostic::is_error)
}

/// Whether `d` is a lexical or syntax error (E01xx, E02xx): a cause of what follows it.
pub fn is_syntax_error(d: &Diagnostic) -> bool {
    d.is_error() && (d.code.0.starts_with("E01") || d.code.0.starts_with("E02"))
}

/// Sorts diagnostics by file, then lexical and syntax errors before the others (a cause before
/// its consequences), then position and code, so output is stable.
pub fn sort(diags: &mut [Diagnostic]) {
    diags.sort_by(|a, b| {
        (
            a.primary.span.file,
            !is_syntax_error(a),
            a.primary.span.lo,
            a.primary.span.hi,
            a.code.0,
        )
            .cmp(&(
                b.primary.span.file,
                !is_syntax_error(b),
                b.primary.span.lo,
                b.primary.span.hi,
                b.code.0,
            ))
    });
}

fn to_codespan(d: &Diagnostic) -> codespan_reporting::diagnostic::Diagnostic<usize> {
    use codespan_reporting::diagnostic as cd;
    let sev = match d.severity {
        Severity::Error => cd::Severity::Error,
        Severity::Warning => cd::Severity::Warning,
        Severity::Note => cd::Severity::Note,
    };
    let mut labels =
        vec![
            cd::Label::primary(d.primary.span.file.0 as usize, d.primary.span.range())
                .with_message(d.primary.message.clone()),
        ];
    for l in &d.secondary {
        labels.push(
            cd::Label::secondary(l.span.file.0 as usize, l.span.range())
                .with_message(l.message.clone()),
        );
    }
    let mut notes: Vec<String> = d.notes.iter().map(|n| format!("note: {n}")).collect();
    if let Some(h) = &d.help {
        notes.push(format!("help: {h}"));
    }
    cd::Diagnostic::new(sev)
        .with_code(d.code.0)
        .with_message(d.message.clone())
        .with_labels(labels)
        .with_notes(notes)
}

struct Files<'a>(&'a SourceMap);

impl<'a> codespan_reporting::files::Files<'a> for Files<'a> {
    type FileId = usize;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: usize) -> Result<&'a str, codespan_reporting::files::Error> {
        self.file(id).map(|f| f.name.as_str())
    }

    fn source(&'a self, id: usize) -> Result<&'a str, codespan_reporting::files::Error> {
        self.file(id).map(|f| f.text.as_str())
    }

    fn line_index(
        &'a self,
        id: usize,
        byte_index: usize,
    ) -> Result<usize, codespan_reporting::files::Error> {
        let f = self.file(id)?;
        let starts = f.line_starts();
        Ok(
            match starts.binary_search(&(byte_index.min(f.text.len()) as u32)) {
                Ok(l) => l,
                Err(l) => l - 1,
            },
        )
    }

    fn line_range(
        &'a self,
        id: usize,
        line_index: usize,
    ) -> Result<std::ops::Range<usize>, codespan_reporting::files::Error> {
        let f = self.file(id)?;
        let starts = f.line_starts();
        let start =
            *starts
                .get(line_index)
                .ok_or(codespan_reporting::files::Error::LineTooLarge {
                    given: line_index,
                    max: starts.len() - 1,
                })? as usize;
        let end = starts
            .get(line_index + 1)
            .map(|&e| e as usize)
            .unwrap_or(f.text.len());
        Ok(start..end)
    }
}

impl<'a> Files<'a> {
    fn file(
        &self,
        id: usize,
    ) -> Result<&'a crate::source::SourceFile, codespan_reporting::files::Error> {
        if id < self.0.len() {
            Ok(self.0.get(crate::source::FileId(id as u32)))
        } else {
            Err(codespan_reporting::files::Error::FileMissing)
        }
    }
}

/// Renders diagnostics as rustc-style text. `color` adds ANSI colours (for terminals).
pub fn render_human(map: &SourceMap, diags: &[Diagnostic], color: bool) -> String {
    use codespan_reporting::term;
    let config = term::Config::default();
    let files = Files(map);
    let mut out = Vec::new();
    for d in diags {
        let cd = to_codespan(d);
        let res = if color {
            let mut w = term::termcolor::Ansi::new(&mut out);
            term::emit_to_write_style(&mut w, &config, &files, &cd)
        } else {
            let mut w = term::termcolor::NoColor::new(&mut out);
            term::emit_to_write_style(&mut w, &config, &files, &cd)
        };
        if res.is_err() {
            // A span outside its file: fall back to a plain line rather than losing the message.
            let (line, col) = map.line_col(d.primary.span.file, d.primary.span.lo);
            let name = &map.get(d.primary.span.file).name;
            out.extend_from_slice(
                format!(
                    "error[{}]: {}\n  --> {name}:{line}:{col}\n\n",
                    d.code.0, d.message
                )
                .as_bytes(),
            );
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[derive(Serialize)]
struct JsonLabel<'a> {
    file: &'a str,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    byte_start: u32,
    byte_end: u32,
    message: &'a str,
}

#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    severity: Severity,
    code: &'a str,
    message: &'a str,
    primary: JsonLabel<'a>,
    secondary: Vec<JsonLabel<'a>>,
    notes: &'a [String],
    help: Option<&'a str>,
    rendered: String,
}

fn json_label<'a>(map: &'a SourceMap, l: &'a Label) -> JsonLabel<'a> {
    let (line, column) = map.line_col(l.span.file, l.span.lo);
    let (end_line, end_column) = map.line_col(l.span.file, l.span.hi);
    JsonLabel {
        file: &map.get(l.span.file).name,
        line,
        column,
        end_line,
        end_column,
        byte_start: l.span.lo,
        byte_end: l.span.hi,
        message: &l.message,
    }
}

/// Renders diagnostics as JSON lines: one object per diagnostic, with 1-based line/column positions
/// and the human rendering in `rendered`.
pub fn render_json(map: &SourceMap, diags: &[Diagnostic]) -> String {
    let mut out = String::new();
    for d in diags {
        let j = JsonDiagnostic {
            severity: d.severity,
            code: d.code.0,
            message: &d.message,
            primary: json_label(map, &d.primary),
            secondary: d.secondary.iter().map(|l| json_label(map, l)).collect(),
            notes: &d.notes,
            help: d.help.as_deref(),
            rendered: render_human(map, std::slice::from_ref(d), false),
        };
        // Serialising plain data into a String cannot fail.
        out.push_str(&serde_json::to_string(&j).unwrap_or_default());
        out.push('\n');
    }
    out
}
