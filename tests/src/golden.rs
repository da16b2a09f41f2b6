//! Golden files: a line-based unified diff for failure messages, and blessing.
//!
//! `RTC_BLESS=1` (any value but `0` or empty) makes the suites write their actual output over the
//! golden files instead of comparing; commit the result after reviewing `git diff`.

use std::path::Path;

/// Whether `RTC_BLESS` asks for golden files to be (re)written.
pub fn blessing() -> bool {
    std::env::var("RTC_BLESS").is_ok_and(|v| !v.is_empty() && v != "0")
}

/// Compares `actual` with the golden file at `path` (or writes it when blessing). Returns a failure
/// message with a unified diff, or `None` when they agree. A missing golden file compares as empty.
pub fn check_golden(path: &Path, actual: &str) -> Option<String> {
    let expected = std::fs::read_to_string(path)
        .unwrap_or_default()
        .replace("\r\n", "\n");
    if expected == actual {
        return None;
    }
    if blessing() {
        return match std::fs::write(path, actual) {
            Ok(()) => None,
            Err(e) => Some(format!("cannot write {}: {e}", path.display())),
        };
    }
    let what = if path.exists() {
        "differs from"
    } else {
        "has no golden file"
    };
    Some(format!(
        "output {what} {} (run with RTC_BLESS=1 to accept it):\n{}",
        crate::paths::display_relative(path),
        unified(&expected, actual, "expected", "actual")
    ))
}

/// A unified diff of two texts, by lines, with three lines of context.
pub fn unified(old: &str, new: &str, old_name: &str, new_name: &str) -> String {
    let a: Vec<&str> = old.lines().collect();
    let b: Vec<&str> = new.lines().collect();
    let mut out = format!("--- {old_name}\n+++ {new_name}\n");
    let Some(ops) = line_ops(&a, &b) else {
        // Too big for the quadratic diff: show both in full.
        for l in &a {
            out.push_str(&format!("-{l}\n"));
        }
        for l in &b {
            out.push_str(&format!("+{l}\n"));
        }
        return out;
    };
    const CONTEXT: usize = 3;
    let changed: Vec<usize> = (0..ops.len())
        .filter(|&i| !matches!(ops[i], Op::Same(..)))
        .collect();
    let mut i = 0;
    while i < changed.len() {
        // Group changes closer than 2 * CONTEXT lines into one hunk.
        let mut j = i;
        while j + 1 < changed.len() && changed[j + 1] - changed[j] <= 2 * CONTEXT {
            j += 1;
        }
        let start = changed[i].saturating_sub(CONTEXT);
        let end = (changed[j] + CONTEXT + 1).min(ops.len());
        let (mut a_start, mut b_start) = (None, None);
        let (mut a_len, mut b_len) = (0, 0);
        let mut body = String::new();
        for op in &ops[start..end] {
            match *op {
                Op::Same(x, y) => {
                    a_start.get_or_insert(x);
                    b_start.get_or_insert(y);
                    a_len += 1;
                    b_len += 1;
                    body.push_str(&format!(" {}\n", a[x]));
                }
                Op::Del(x, y) => {
                    a_start.get_or_insert(x);
                    b_start.get_or_insert(y);
                    a_len += 1;
                    body.push_str(&format!("-{}\n", a[x]));
                }
                Op::Ins(x, y) => {
                    a_start.get_or_insert(x);
                    b_start.get_or_insert(y);
                    b_len += 1;
                    body.push_str(&format!("+{}\n", b[y]));
                }
            }
        }
        let first =
            |s: Option<usize>, len: usize| s.map_or(0, |s| if len == 0 { s } else { s + 1 });
        out.push_str(&format!(
            "@@ -{},{a_len} +{},{b_len} @@\n{body}",
            first(a_start, a_len),
            first(b_start, b_len)
        ));
        i = j + 1;
    }
    let ends_in_newline = |s: &str| s.is_empty() || s.ends_with('\n');
    if ends_in_newline(old) != ends_in_newline(new) {
        out.push_str("\\ the texts differ in their final newline\n");
    }
    out
}

/// One step of an edit script: a line kept (`Same(a, b)`), deleted from `a`, or inserted from `b`.
/// Every variant carries the current position in both texts.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Same(usize, usize),
    Del(usize, usize),
    Ins(usize, usize),
}

/// The edit script from a longest common subsequence; `None` if the texts are too large for it.
fn line_ops(a: &[&str], b: &[&str]) -> Option<Vec<Op>> {
    let (n, m) = (a.len(), b.len());
    if n.saturating_mul(m) > 16_000_000 {
        return None;
    }
    // lcs[i][j]: length of the LCS of a[i..] and b[j..].
    let w = m + 1;
    let mut lcs = vec![0u32; (n + 1) * w];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            lcs[i * w + j] = if a[i] == b[j] {
                lcs[(i + 1) * w + j + 1] + 1
            } else {
                lcs[(i + 1) * w + j].max(lcs[i * w + j + 1])
            };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut ops = Vec::with_capacity(n + m);
    while i < n || j < m {
        if i < n && j < m && a[i] == b[j] {
            ops.push(Op::Same(i, j));
            i += 1;
            j += 1;
        } else if j < m && (i == n || lcs[i * w + j + 1] > lcs[(i + 1) * w + j]) {
            ops.push(Op::Ins(i, j));
            j += 1;
        } else {
            ops.push(Op::Del(i, j));
            i += 1;
        }
    }
    Some(ops)
}

#[cfg(test)]
mod tests {
    use super::unified;

    #[test]
    fn unified_diff_has_hunks_with_context() {
        let old = "a\nb\nc\nd\ne\nf\ng\nh\ni\n";
        let new = "a\nb\nc\nd\nE\nf\ng\nh\ni\nj\n";
        let d = unified(old, new, "expected", "actual");
        assert_eq!(
            d,
            "--- expected\n+++ actual\n@@ -2,8 +2,9 @@\n b\n c\n d\n-e\n+E\n f\n g\n h\n i\n+j\n"
        );
    }

    #[test]
    fn diff_of_empty_and_text() {
        let d = unified("", "x\n", "expected", "actual");
        assert_eq!(d, "--- expected\n+++ actual\n@@ -0,0 +1,1 @@\n+x\n");
    }
}
