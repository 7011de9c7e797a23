//! The one-line explanation and syntax of every reserved word, for hover and completion.
//! The text lives in `keyword_docs.txt`, written for Povrayst from the facts of POV-Ray's
//! reference, one word a line.

/// What we say about one reserved word.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KeywordDoc {
    pub word: &'static str,
    pub syntax: &'static str,
    pub summary: &'static str,
}

const TEXT: &str = include_str!("keyword_docs.txt");

/// Every entry, in the order of the file (sorted by word).
pub fn all() -> impl Iterator<Item = KeywordDoc> {
    TEXT.lines()
        .filter(|line| !line.starts_with('#') && !line.trim().is_empty())
        .filter_map(|line| {
            let mut fields = line.splitn(3, " | ");
            Some(KeywordDoc {
                word: fields.next()?,
                syntax: fields.next()?,
                summary: fields.next()?,
            })
        })
}

pub fn keyword_doc(word: &str) -> Option<KeywordDoc> {
    all().find(|doc| doc.word == word)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_reserved_word_is_explained_once_and_nothing_else_is() {
        let words: Vec<&str> = all().map(|doc| doc.word).collect();
        let mut sorted = words.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(
            words, sorted,
            "keyword_docs.txt must be sorted, without repeats"
        );
        let keywords: Vec<&str> = syntax::KEYWORDS.iter().map(|(word, _)| *word).collect();
        let missing: Vec<&&str> = keywords.iter().filter(|k| !words.contains(k)).collect();
        let extra: Vec<&&str> = words.iter().filter(|w| !keywords.contains(w)).collect();
        assert!(missing.is_empty(), "no hover text for {missing:?}");
        assert!(extra.is_empty(), "not reserved words: {extra:?}");
        for doc in all() {
            assert!(
                !doc.syntax.is_empty() && doc.summary.ends_with('.'),
                "{doc:?}"
            );
        }
    }
}
