//! "Did you mean" suggestions for misspelt names: how far apart two names are, and the
//! nearest of some candidates. The evaluator's undeclared-identifier error, the
//! unknown-keyword lint and the quick fixes all suggest by the same measure.

/// Levenshtein distance, by characters.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitution = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(row[j + 1] + 1);
        }
    }
    row[b.len()]
}

/// The candidate nearest to `name`, ignoring case, if it is at most a third of the name's
/// length away (one to three edits); the shorter candidate wins a tie. `name` itself is no
/// suggestion.
pub fn closest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.len() / 3).clamp(1, 3);
    let lower = name.to_lowercase();
    candidates
        .into_iter()
        .filter(|candidate| *candidate != name)
        .map(|candidate| (edit_distance(&lower, &candidate.to_lowercase()), candidate))
        .filter(|(distance, _)| *distance <= limit)
        .min_by_key(|(distance, candidate)| (*distance, candidate.len()))
        .map(|(_, candidate)| candidate)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_counts_insertions_deletions_and_substitutions() {
        assert_eq!(edit_distance("pigmnet", "pigment"), 2);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("sphere", "sphere"), 0);
        assert_eq!(edit_distance("cafe", "café"), 1);
    }

    #[test]
    fn closest_stays_within_a_third_of_the_name() {
        let words = ["pigment", "finish", "pigment_map", "fog"];
        assert_eq!(closest("pigmnet", words), Some("pigment"));
        assert_eq!(closest("Pigmnet", words), Some("pigment"));
        assert_eq!(closest("fig", words), Some("fog"));
        assert_eq!(closest("zzzzzz", words), None);
        assert_eq!(closest("fog", ["fog"]), None);
    }
}
