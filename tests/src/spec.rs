//! The language reference as tests: its ` ```rt ` code blocks and its table of diagnostic codes.
//!
//! A block fenced ` ```rt ` must check without errors; one fenced ` ```rt fail E0401 ` must report
//! that code as its first error (diagnostics are sorted by position, so "first" is the first error in
//! the block). Any other info string starting with `rt` is a mistake in the spec and is reported as
//! such. Blocks in other languages are skipped. A fence is a line that starts (after indentation) with
//! three or more backticks; it closes at a line of at least as many backticks and nothing else.

/// What a block must do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expect {
    /// Check without errors (warnings are allowed).
    Ok,
    /// Report this code as its first error.
    Fail(String),
}

/// One ` ```rt ` block of a spec chapter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    /// The chapter, relative to the repository root (`spec/types.md`).
    pub file: String,
    /// 1-based line of the opening fence.
    pub line: usize,
    /// The code between the fences (each line ends in `\n`).
    pub code: String,
    /// What the block must do.
    pub expect: Expect,
}

impl Block {
    /// The name the block is checked under: `spec/types.md:53`, so `std/…` imports resolve against
    /// the standard library and diagnostics name the chapter and the block's fence line.
    pub fn name(&self) -> String {
        format!("{}:{}", self.file, self.line)
    }
}

/// Extracts the `rt` blocks of one Markdown file named `file`. Malformed fences and info strings are
/// returned as messages `file:line: …`.
pub fn extract(file: &str, markdown: &str) -> (Vec<Block>, Vec<String>) {
    let mut blocks = Vec::new();
    let mut errors = Vec::new();
    // (fence length, line, expectation if it is an rt block, code so far)
    let mut open: Option<(usize, usize, Option<Expect>, String)> = None;
    for (index, raw) in markdown.lines().enumerate() {
        let line_no = index + 1;
        let trimmed = raw.trim_start();
        let ticks = trimmed.chars().take_while(|&c| c == '`').count();
        match &mut open {
            Some((fence, start, expect, code)) => {
                if ticks >= *fence && trimmed[ticks..].trim().is_empty() {
                    if let Some(expect) = expect.take() {
                        blocks.push(Block {
                            file: file.to_owned(),
                            line: *start,
                            code: std::mem::take(code),
                            expect,
                        });
                    }
                    open = None;
                } else {
                    code.push_str(raw);
                    code.push('\n');
                }
            }
            None if ticks >= 3 => {
                let info = trimmed[ticks..].trim();
                let words: Vec<&str> = info.split_whitespace().collect();
                let first = words.first().copied().unwrap_or("");
                let rt_like = first.starts_with("rt")
                    && !first[2..].starts_with(|c: char| c.is_ascii_alphanumeric());
                let expect = match words.as_slice() {
                    _ if !rt_like => None,
                    ["rt"] => Some(Expect::Ok),
                    ["rt", "fail", code] if is_code(code) => Some(Expect::Fail((*code).to_owned())),
                    _ => {
                        errors.push(format!(
                            "{file}:{line_no}: info string `{info}` is neither `rt` nor `rt fail CODE`"
                        ));
                        None
                    }
                };
                open = Some((ticks, line_no, expect, String::new()));
            }
            None => {}
        }
    }
    if let Some((_, start, _, _)) = open {
        errors.push(format!("{file}:{start}: code block is never closed"));
    }
    (blocks, errors)
}

fn is_code(word: &str) -> bool {
    rtc_compiler::diag::codes::ALL
        .iter()
        .any(|(c, _)| c.0 == word)
}

/// The rows `| CODE | summary |` of `spec/diagnostics.md`'s table, in order, with their line numbers.
pub fn code_table(markdown: &str) -> Vec<(usize, String, String)> {
    let mut rows = Vec::new();
    for (index, line) in markdown.lines().enumerate() {
        let line = line.trim();
        if !line.starts_with('|') {
            continue;
        }
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        if cells.len() < 2 {
            continue;
        }
        let code = cells[0];
        let looks_like_code = code == "ICE"
            || (code.len() == 5
                && (code.starts_with('E') || code.starts_with('W'))
                && code[1..].chars().all(|c| c.is_ascii_digit()));
        if looks_like_code {
            rows.push((index + 1, code.to_owned(), cells[1..].join("|")));
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_and_expectations() {
        let md = "text ```rt inline``` text\n```rt\nfn a() {}\n```\n\n```text\n```rt\n```\n\
                  ```rt fail E0401\nlet x: f32 = true;\n```\n````rt\n```\nx\n````\n```rt,ignore\n```\n";
        let (blocks, errors) = extract("spec/x.md", md);
        assert_eq!(
            blocks,
            [
                Block {
                    file: "spec/x.md".into(),
                    line: 2,
                    code: "fn a() {}\n".into(),
                    expect: Expect::Ok
                },
                Block {
                    file: "spec/x.md".into(),
                    line: 9,
                    code: "let x: f32 = true;\n".into(),
                    expect: Expect::Fail("E0401".into())
                },
                Block {
                    file: "spec/x.md".into(),
                    line: 12,
                    code: "```\nx\n".into(),
                    expect: Expect::Ok
                },
            ]
        );
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(errors[0].starts_with("spec/x.md:16:"));
        assert_eq!(blocks[1].name(), "spec/x.md:9");
    }

    #[test]
    fn unclosed_block_is_an_error() {
        let (_, errors) = extract("spec/x.md", "```rt\nfn a() {}\n");
        assert_eq!(errors, ["spec/x.md:1: code block is never closed"]);
    }

    #[test]
    fn table_rows() {
        let md = "| code | meaning |\n|---|---|\n| E0101 | a thing |\n| ICE | a bug |\n| x | y |\n";
        let rows = code_table(md);
        assert_eq!(
            rows,
            [
                (3, "E0101".into(), "a thing".into()),
                (4, "ICE".into(), "a bug".into())
            ]
        );
    }
}
