//! "Did you mean …?": the closest candidate to a misspelt name.
//!
//! Used for help lines such as ``help: did you mean `closest_hit`?`` (unknown attributes, scene
//! entries, undefined names, unknown fields). The rule follows rustc's `find_best_match_for_name`:
//! a candidate qualifies if it equals the name ignoring ASCII case, or if its edit distance
//! (Levenshtein, counted in characters) is at most a third of the name's length (at least 1).
//!
//! Invariants: the result is deterministic (ties go to the earliest candidate) and the cost is
//! `O(len(name) * len(candidate))` per candidate, with candidates whose length alone rules them out
//! skipped without computing a distance.

/// The candidate closest to `name`, if one is close enough to be worth suggesting.
///
/// `name` itself is never suggested (an exact match is not a typo).
pub fn closest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let len = name.chars().count();
    let max = (len.max(3) / 3).max(1);
    let mut best: Option<(usize, &'a str)> = None;
    for cand in candidates {
        if cand == name {
            continue;
        }
        if cand.eq_ignore_ascii_case(name) {
            return Some(cand);
        }
        let cand_len = cand.chars().count();
        if cand_len.abs_diff(len) > max {
            continue;
        }
        let limit = best.map_or(max, |(d, _)| d.saturating_sub(1));
        if let Some(d) = distance_at_most(name, cand, limit) {
            best = Some((d, cand));
        }
    }
    best.map(|(_, c)| c)
}

/// The Levenshtein distance between `a` and `b` if it is at most `limit`, else `None`.
pub fn distance_at_most(a: &str, b: &str, limit: usize) -> Option<usize> {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    if a.len().abs_diff(b.len()) > limit {
        return None;
    }
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.iter().enumerate() {
        cur[0] = i + 1;
        let mut row_min = cur[0];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
            row_min = row_min.min(cur[j + 1]);
        }
        if row_min > limit {
            return None;
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    let d = prev[b.len()];
    (d <= limit).then_some(d)
}

#[cfg(test)]
mod tests {
    use super::*;

    const ATTRS: &[&str] = &["closest_hit", "any_hit", "miss", "material", "light"];

    #[test]
    fn suggests_close_names() {
        assert_eq!(
            closest("closest_hti", ATTRS.iter().copied()),
            Some("closest_hit")
        );
        assert_eq!(closest("mis", ATTRS.iter().copied()), Some("miss"));
        assert_eq!(closest("Material", ATTRS.iter().copied()), Some("material"));
        assert_eq!(closest("lights", ATTRS.iter().copied()), Some("light"));
    }

    #[test]
    fn ignores_far_names_and_exact_matches() {
        assert_eq!(closest("banana", ATTRS.iter().copied()), None);
        assert_eq!(closest("miss", ATTRS.iter().copied()), None);
        assert_eq!(closest("", ATTRS.iter().copied()), None);
    }

    #[test]
    fn distance() {
        assert_eq!(distance_at_most("kitten", "sitting", 5), Some(3));
        assert_eq!(distance_at_most("kitten", "sitting", 2), None);
        assert_eq!(distance_at_most("", "abc", 3), Some(3));
    }
}
