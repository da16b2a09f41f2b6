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
        Ok(self.file(id)?.line_index(byte_index))
    }

    fn column_number(
        &'a self,
        id: usize,
        line_index: usize,
        byte_index: usize,
    ) -> Result<usize, codespan_reporting::files::Error> {
        let f = self.file(id)?;
        let range = self.line_range(id, line_index)?;
        let end = byte_index.clamp(range.start, range.end);
        Ok(f.char_index(end) - f.char_index(range.start) + 1)
    }

    fn line_range(
        &'a self,
        id: usize,
        line_index: usize,
    ) -> Result<std::ops::Range<usize>, codespan_reporting::files::Error> {
        let f = self.file(id)?;
        f.line_range(line_index)
            .ok_or(codespan_reporting::files::Error::LineTooLarge {
                given: line_index,
                max: f.line_starts().len() - 1,
            })
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
        if shows_a_long_line(map, d) {
            out.extend_from_slice(render_excerpt(map, d).as_bytes());
            continue;
        }
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

/// A source line longer than this many bytes is shown as an excerpt around each label.
const LONG_LINE: usize = 400;
/// Bytes of context shown on either side of a label on a long line.
const CONTEXT: usize = 40;
/// At most this many bytes of a label are underlined on a long line.
const MAX_MARK: usize = 160;

/// Whether the human rendering of `d` would quote a line longer than [`LONG_LINE`] (a label's
/// first and last lines and the context lines codespan adds to a multi-line label).
fn shows_a_long_line(map: &SourceMap, d: &Diagnostic) -> bool {
    std::iter::once(&d.primary).chain(&d.secondary).any(|l| {
        if l.span.file.0 as usize >= map.len() {
            return false;
        }
        let f = map.get(l.span.file);
        let (first, last) = (
            f.line_index(l.span.lo as usize),
            f.line_index(l.span.hi as usize),
        );
        let long = |i: usize| f.line_range(i).is_some_and(|r| r.len() > LONG_LINE);
        (first..=last.min(first + 3)).any(long)
            || (last.saturating_sub(1).max(first)..=last).any(long)
    })
}

/// The rendering of a diagnostic that quotes a very long line (generated code on one line): like
/// codespan's, but each label shows only [`CONTEXT`] bytes around it, so the output and the time
/// taken grow with the number of diagnostics, not with their product with the line's length. Plain
/// text (no colours).
fn render_excerpt(map: &SourceMap, d: &Diagnostic) -> String {
    use std::fmt::Write;
    let sev = match d.severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Note => "note",
    };
    let mut labels: Vec<(&Label, bool)> = std::iter::once((&d.primary, true))
        .chain(d.secondary.iter().map(|l| (l, false)))
        .filter(|(l, _)| (l.span.file.0 as usize) < map.len())
        .collect();
    let line_of = |l: &Label| map.line_col(l.span.file, l.span.lo).0;
    let width = labels
        .iter()
        .map(|(l, _)| line_of(l).to_string().len())
        .max()
        .unwrap_or(1);
    let pad = " ".repeat(width + 1);
    let mut out = String::new();
    let _ = writeln!(out, "{sev}[{}]: {}", d.code.0, d.message);
    let loc = |l: &Label| {
        let (line, col) = map.line_col(l.span.file, l.span.lo);
        format!("{}:{line}:{col}", map.get(l.span.file).name)
    };
    let _ = writeln!(out, "{pad}┌─ {}", loc(&d.primary));
    let _ = writeln!(out, "{pad}│");
    labels.sort_by_key(|(l, _)| (l.span.file, l.span.lo, l.span.hi));
    let mut previous: Option<(crate::source::FileId, usize)> = None;
    for (l, primary) in labels {
        let f = map.get(l.span.file);
        let line = f.line_index(l.span.lo as usize);
        match previous {
            Some((file, _)) if file != l.span.file => {
                let _ = writeln!(out, "{pad}·");
                let _ = writeln!(out, "{pad}┌─ {}", loc(l));
                let _ = writeln!(out, "{pad}│");
            }
            Some((_, prev)) if line > prev + 1 => {
                let _ = writeln!(out, "{pad}·");
            }
            _ => {}
        }
        previous = Some((l.span.file, line));
        let range = f.line_range(line).unwrap_or(0..0);
        let text = &f.text;
        let end = range.start + text[range.clone()].trim_end_matches(['\n', '\r']).len();
        let lo = (l.span.lo as usize).clamp(range.start, end);
        let mark_end = (l.span.hi as usize).clamp(lo, end).min(lo + MAX_MARK);
        let mut ws = lo.saturating_sub(CONTEXT).max(range.start);
        while !text.is_char_boundary(ws) {
            ws -= 1;
        }
        let mut we = (mark_end + CONTEXT).min(end);
        while !text.is_char_boundary(we) {
            we += 1;
        }
        let mut mark_end = mark_end;
        while !text.is_char_boundary(mark_end) {
            mark_end += 1;
        }
        let (open, close) = (
            if ws > range.start { "…" } else { "" },
            if we < end { "…" } else { "" },
        );
        let _ = writeln!(out, "{:>width$} │ {open}{}{close}", line + 1, &text[ws..we]);
        let indent = f.char_index(lo) - f.char_index(ws) + usize::from(!open.is_empty());
        let marks = (f.char_index(mark_end) - f.char_index(lo)).max(1);
        let mark = if primary { "^" } else { "-" }.repeat(marks);
        let message = if l.message.is_empty() {
            String::new()
        } else {
            format!(" {}", l.message)
        };
        let _ = writeln!(out, "{pad}│ {}{mark}{message}", " ".repeat(indent));
    }
    if !d.notes.is_empty() || d.help.is_some() {
        let _ = writeln!(out, "{pad}│");
    }
    for n in &d.notes {
        let _ = writeln!(out, "{pad}= note: {n}");
    }
    if let Some(h) = &d.help {
        let _ = writeln!(out, "{pad}= help: {h}");
    }
    out.push('\n');
    out
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::codes;

    /// A warning on a line of 100,000 bytes quotes 40 bytes either side of its label, with the
    /// right line and column, in codespan's layout.
    #[test]
    fn a_long_line_is_quoted_as_an_excerpt() {
        let mut map = SourceMap::new();
        let line: String = (0..10_000).map(|i| format!("let v{i:04} = 1;")).collect();
        let text = format!("// first\n{line}\n");
        let f = map.add("long.rt", None, text.clone());
        let lo = text.find("v5000").unwrap() as u32;
        let d = Diagnostic::warning(
            codes::W0001,
            "unused variable `v5000`",
            Span::new(f, lo, lo + 5),
        )
        .with_label("never read")
        .with_help("prefix it with an underscore");
        let out = render_human(&map, &[d], false);
        let col = lo as usize - text.find('\n').unwrap();
        let expected = format!(
            "warning[W0001]: unused variable `v5000`\n  ┌─ long.rt:2:{col}\n  │\n\
             2 │ …{}…\n  │ {}^^^^^ never read\n  │\n  = help: prefix it with an underscore\n\n",
            &text[lo as usize - 40..lo as usize + 45],
            " ".repeat(41),
        );
        assert_eq!(out, expected);
    }

    /// Short lines still go through codespan unchanged.
    #[test]
    fn short_lines_are_rendered_by_codespan() {
        let mut map = SourceMap::new();
        let f = map.add("a.rt", None, "let x = 1;\n");
        let d = Diagnostic::warning(codes::W0001, "unused variable `x`", Span::new(f, 4, 5));
        let out = render_human(&map, &[d], false);
        assert!(out.contains("1 │ let x = 1;\n"), "{out}");
    }
}
