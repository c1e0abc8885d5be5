//! The controlled vocabulary (docs/domain.md 6.1, 6.7) as data: the words the explainer hears and
//! the phrases it says, read from JSON text (`domains/ra/lexicon.json`, built into the library
//! as [`Lexicon::ra`]; `cli` may pass another file's text to [`Lexicon::from_json`]).
//!
//! Invariants: every phrase of the lexicon is stored normalized by [`Lexicon::normalize`], the
//! same pipeline questions go through (lower case, contractions expanded, number words read,
//! lemmas, then synonyms), so data may be written in plain English ("what was your plan"
//! matches "What's your plan?" as "what be your plan"); every literal and action pattern has
//! been parsed as a [`Pattern`]; no English phrase is written in code apart from the grammar's
//! function words ([`GRAMMAR_WORDS`]) and the tense forms of the template verbs.

use std::collections::{HashMap, HashSet};

use serde::Deserialize;

use super::pattern::{Pattern, PatternError};

/// The function words the grammar of `explain::english` itself uses; they are known words even
/// when no lexicon phrase contains them.
pub const GRAMMAR_WORDS: &[&str] = &[
    "why", "do", "you", "not", "believe", "that", "be", "what", "if", "have", "would", "happen",
    "can", "the", "a", "an", "and", "at", "in", "on", "step", "time", "instead", "your", "my",
    "during", "of", "it", "i", "there", "no",
];

/// The answer templates a lexicon must define, with the placeholders each must use.
pub const TEMPLATES: &[(&str, &[&str])] = &[
    ("plan_step", &["action"]),
    ("why", &["action", "literal"]),
    ("why_goal", &["goal"]),
    ("why_not", &["literals"]),
    ("why_not_observed", &["literal", "step"]),
    ("why_not_unrelated", &["object"]),
    ("why_not_not_planned", &[]),
    ("did_it", &["action", "step"]),
    ("belief_action", &["action", "step"]),
    ("belief_observed", &["literal", "step"]),
    ("belief_static", &[]),
    ("belief_frontier", &["literals"]),
    ("belief_assumed", &["literal", "default"]),
    ("not_believed", &["literal", "step"]),
    ("belief_default", &["literal"]),
    ("complement_instead", &["literal"]),
    ("step_chosen", &["steps"]),
    ("nothing_done", &["step"]),
    ("outside_history", &["step", "last"]),
    ("not_done", &["action", "step"]),
    ("no_reason", &[]),
    ("step", &["step"]),
    ("initial_state", &[]),
    ("what_if", &["action", "step", "later", "literals", "old"]),
    ("what_if_same", &["action", "step"]),
    ("what_if_impossible", &["action", "step", "reason"]),
    ("what_if_stuck", &["next"]),
    ("no_plan", &["steps", "reasons"]),
    ("no_plan_always", &["steps"]),
    ("plan_exists", &["steps"]),
    ("learned_axiom", &["label", "strength", "axiom"]),
];

/// The JSON shape of a lexicon file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LexiconFile {
    #[allow(dead_code)]
    about: Option<String>,
    robot: String,
    contractions: HashMap<String, String>,
    lemmas: HashMap<String, String>,
    synonyms: HashMap<String, String>,
    numbers: HashMap<String, u32>,
    politeness: Vec<String>,
    step_phrases: HashMap<String, u32>,
    last_step_phrases: Vec<String>,
    holding: Vec<String>,
    kinds: Vec<Vec<String>>,
    colours: Vec<String>,
    sizes: Vec<String>,
    names: HashMap<String, String>,
    verbs: Vec<VerbFile>,
    relations: Vec<RelationFile>,
    properties: Vec<PropertyFile>,
    requests: RequestsFile,
    templates: HashMap<String, String>,
    help_objects: Vec<String>,
    help: Vec<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct VerbFile {
    action: String,
    verb: String,
    particle: Option<String>,
    base: String,
    past: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RelationFile {
    name: String,
    hear: Vec<String>,
    say: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PropertyFile {
    literal: String,
    #[serde(rename = "static", default)]
    is_static: bool,
    hear: Vec<String>,
    say: String,
    negated: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RequestsFile {
    describe: Vec<String>,
    describe_step: Vec<String>,
    why: Vec<String>,
    no_plan: Vec<String>,
}

/// A lexicon that could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum LexiconError {
    /// The text is not JSON of the lexicon's shape.
    #[error("lexicon: {0}")]
    Json(#[from] serde_json::Error),
    /// A literal or action pattern is not a term.
    #[error("lexicon: {what} `{text}` is not a term: {error}")]
    Term {
        /// Which entry.
        what: &'static str,
        /// The pattern's text.
        text: String,
        /// Why it could not be read.
        error: PatternError,
    },
    /// An entry is inconsistent (a template without its placeholder, an empty phrase).
    #[error("lexicon: {0}")]
    Entry(String),
}

/// One word of normalized text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Token {
    /// The normalized word (lemma, synonym applied; digits for numbers).
    pub word: String,
    /// The word as written (for a contraction, the whole contraction).
    pub original: String,
    /// The number, if the word is a number or a number word.
    pub num: Option<u32>,
}

/// An action verb: how it is heard and said.
#[derive(Clone, Debug)]
pub struct Verb {
    /// The action pattern over `R` (the robot), `X` (the object) and `Y` (the target).
    pub action: Pattern,
    /// The normalized verb ("pick", "put").
    pub verb: String,
    /// The optional particle ("up", "down").
    pub particle: Option<String>,
    /// The base form ("pick up {X}").
    pub base: String,
    /// The past form ("picked up {X}").
    pub past: String,
}

/// A spatial relation: how it is heard and said.
#[derive(Clone, Debug)]
pub struct Relation {
    /// The relation constant of `relation(S, A, B)`.
    pub name: String,
    /// Normalized phrases, longest first.
    pub hear: Vec<Vec<String>>,
    /// The phrase said ("in front of").
    pub say: String,
}

/// A property of an object (a non-relational fluent or a static).
#[derive(Clone, Debug)]
pub struct Property {
    /// The literal pattern over `X` (subject), `Y` (second object), `N` (number), `R` (robot);
    /// classically negated for properties heard positively of a negative literal ("unstable").
    pub literal: Pattern,
    /// Whether the literal is a static (no step, said in the present tense).
    pub is_static: bool,
    /// Normalized phrases, longest first; `{Y}` and `{N}` are words of their own.
    pub hear: Vec<Vec<String>>,
    /// The clause template ("{X} {be} in my hand").
    pub say: String,
    /// The template of the complement, when inserting "not" after the first verb is wrong.
    pub negated: Option<String>,
}

/// The controlled vocabulary, normalized and indexed.
#[derive(Clone, Debug)]
pub struct Lexicon {
    /// The robot constant (`rob1`).
    pub robot: String,
    contractions: HashMap<String, Vec<String>>,
    lemmas: HashMap<String, String>,
    synonyms: HashMap<String, String>,
    numbers: HashMap<String, u32>,
    /// Normalized politeness phrases, longest first.
    pub politeness: Vec<Vec<String>>,
    /// Normalized phrases naming a step, longest first.
    pub step_phrases: Vec<(Vec<String>, u32)>,
    /// Normalized phrases naming the last step of the history ("at the end"), longest first.
    pub last_step_phrases: Vec<Vec<String>>,
    /// Normalized verbs of holding ("hold", "carry"): "why were you holding X" asks about
    /// `in_hand(robot, X)`.
    pub holding: Vec<String>,
    /// Kind word -> the first word of its class ("cube" -> "block").
    kind_class: HashMap<String, String>,
    /// Colour words.
    pub colours: HashSet<String>,
    /// Size words (also the size suffixes dropped from constants).
    pub sizes: HashSet<String>,
    /// Constants said in special words ("table" -> "the table").
    pub names: HashMap<String, String>,
    /// Action verbs.
    pub verbs: Vec<Verb>,
    /// Spatial relations.
    pub relations: Vec<Relation>,
    /// Properties.
    pub properties: Vec<Property>,
    /// Normalized phrases asking for the plan.
    pub describe: Vec<Vec<String>>,
    /// Normalized phrases asking what was done at one step; `{S}` stands for a step phrase.
    pub describe_step: Vec<Vec<String>>,
    /// Normalized phrases opening a why question ("why", "how come", "what be the reason
    /// for"), longest first.
    pub why: Vec<Vec<String>>,
    /// Normalized phrases asking why there is no plan.
    pub no_plan: Vec<Vec<String>>,
    /// Answer templates by name (docs/domain.md 6.7), see [`TEMPLATES`].
    pub templates: HashMap<String, String>,
    /// Example questions, said when a question was not understood; `{X}`, `{Y}`, `{Z}` are
    /// filled with objects of the scene.
    pub help: Vec<String>,
    /// The objects the examples name when the scene has too few (in words).
    pub help_objects: Vec<String>,
    /// Every word some phrase or grammar rule uses (normalized).
    known: HashSet<String>,
}

/// The built-in lexicon of the robot-assistant domain.
const RA_LEXICON: &str = include_str!("../../domains/ra/lexicon.json");

impl Lexicon {
    /// The robot-assistant lexicon (`domains/ra/lexicon.json`, built in).
    pub fn ra() -> Lexicon {
        Lexicon::from_json(RA_LEXICON).expect("domains/ra/lexicon.json is a valid lexicon")
    }

    /// The template `name` (one of [`TEMPLATES`]).
    pub fn template(&self, name: &str) -> &str {
        self.templates
            .get(name)
            .map(String::as_str)
            .unwrap_or_else(|| panic!("`{name}` is not one of the lexicon's templates"))
    }

    /// Reads a lexicon from JSON text.
    pub fn from_json(text: &str) -> Result<Lexicon, LexiconError> {
        let file: LexiconFile = serde_json::from_str(text)?;
        let mut lex = Lexicon {
            robot: file.robot,
            contractions: file
                .contractions
                .into_iter()
                .map(|(k, v)| {
                    let words = v.split_whitespace().map(str::to_lowercase).collect();
                    (k.to_lowercase(), words)
                })
                .collect(),
            lemmas: lower_map(file.lemmas),
            synonyms: lower_map(file.synonyms),
            numbers: file
                .numbers
                .into_iter()
                .map(|(k, v)| (k.to_lowercase(), v))
                .collect(),
            politeness: Vec::new(),
            step_phrases: Vec::new(),
            last_step_phrases: Vec::new(),
            holding: Vec::new(),
            kind_class: HashMap::new(),
            colours: HashSet::new(),
            sizes: HashSet::new(),
            names: file.names,
            verbs: Vec::new(),
            relations: Vec::new(),
            properties: Vec::new(),
            describe: Vec::new(),
            describe_step: Vec::new(),
            why: Vec::new(),
            no_plan: Vec::new(),
            templates: file.templates,
            help: file.help,
            help_objects: file.help_objects,
            known: HashSet::new(),
        };
        for (name, holes) in TEMPLATES {
            let Some(t) = lex.templates.get(*name) else {
                return Err(LexiconError::Entry(format!(
                    "the template `{name}` is missing"
                )));
            };
            for hole in *holes {
                if !t.contains(&format!("{{{hole}}}")) {
                    return Err(LexiconError::Entry(format!(
                        "the template `{name}` must use {{{hole}}}"
                    )));
                }
            }
        }
        lex.politeness = longest_first(file.politeness.iter().map(|p| lex.phrase(p)).collect());
        let mut steps: Vec<(Vec<String>, u32)> = file
            .step_phrases
            .iter()
            .map(|(p, n)| (lex.phrase(p), *n))
            .collect();
        steps.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then(a.0.cmp(&b.0)));
        lex.step_phrases = steps;
        lex.last_step_phrases = longest_first(
            file.last_step_phrases
                .iter()
                .map(|p| lex.phrase(p))
                .collect(),
        );
        lex.holding = file.holding.iter().map(|w| lex.word(w)).collect();
        for class in &file.kinds {
            let class: Vec<String> = class.iter().map(|w| lex.word(w)).collect();
            let Some(first) = class.first() else {
                return Err(LexiconError::Entry("an empty kind class".into()));
            };
            for w in &class {
                lex.kind_class.insert(w.clone(), first.clone());
            }
        }
        lex.colours = file.colours.iter().map(|w| lex.word(w)).collect();
        lex.sizes = file.sizes.iter().map(|w| lex.word(w)).collect();
        for v in &file.verbs {
            let action = Pattern::parse(&v.action).map_err(|error| LexiconError::Term {
                what: "action",
                text: v.action.clone(),
                error,
            })?;
            if !v.base.contains("{X}") || !v.past.contains("{X}") {
                return Err(LexiconError::Entry(format!(
                    "the verb `{}` must say its object {{X}}",
                    v.verb
                )));
            }
            lex.verbs.push(Verb {
                action,
                verb: lex.word(&v.verb),
                particle: v.particle.as_deref().map(|p| lex.word(p)),
                base: v.base.clone(),
                past: v.past.clone(),
            });
        }
        for r in &file.relations {
            let hear = longest_first(r.hear.iter().map(|p| lex.phrase(p)).collect());
            lex.relations.push(Relation {
                name: r.name.clone(),
                hear,
                say: r.say.clone(),
            });
        }
        for p in &file.properties {
            let literal = Pattern::parse(&p.literal).map_err(|error| LexiconError::Term {
                what: "literal",
                text: p.literal.clone(),
                error,
            })?;
            if !p.say.contains("{X}") {
                return Err(LexiconError::Entry(format!(
                    "the template of `{}` must say its subject {{X}}",
                    p.literal
                )));
            }
            let hear = longest_first(p.hear.iter().map(|h| lex.phrase(h)).collect());
            lex.properties.push(Property {
                literal,
                is_static: p.is_static,
                hear,
                say: p.say.clone(),
                negated: p.negated.clone(),
            });
        }
        lex.describe = longest_first(
            file.requests
                .describe
                .iter()
                .map(|p| lex.phrase(p))
                .collect(),
        );
        lex.no_plan = longest_first(
            file.requests
                .no_plan
                .iter()
                .map(|p| lex.phrase(p))
                .collect(),
        );
        let phrases = |list: &[String]| longest_first(list.iter().map(|p| lex.phrase(p)).collect());
        let (describe_step, why) = (
            phrases(&file.requests.describe_step),
            phrases(&file.requests.why),
        );
        lex.describe_step = describe_step;
        lex.why = why;
        if lex
            .describe_step
            .iter()
            .any(|p| !p.iter().any(|w| w == "{S}"))
        {
            return Err(LexiconError::Entry(
                "every describe_step phrase must have its step {S}".into(),
            ));
        }
        if lex
            .politeness
            .iter()
            .chain(lex.describe.iter())
            .chain(lex.describe_step.iter())
            .chain(lex.why.iter())
            .chain(lex.last_step_phrases.iter())
            .chain(lex.no_plan.iter())
            .any(Vec::is_empty)
        {
            return Err(LexiconError::Entry("an empty phrase".into()));
        }
        lex.known = lex.collect_known();
        Ok(lex)
    }

    /// Every normalized word the lexicon or the grammar uses.
    fn collect_known(&self) -> HashSet<String> {
        let mut known: HashSet<String> = GRAMMAR_WORDS.iter().map(|w| w.to_string()).collect();
        let mut add = |words: &[String]| {
            for w in words {
                if !w.starts_with('{') {
                    known.insert(w.clone());
                }
            }
        };
        for p in self
            .politeness
            .iter()
            .chain(&self.describe)
            .chain(&self.describe_step)
            .chain(&self.why)
            .chain(&self.last_step_phrases)
            .chain(&self.no_plan)
        {
            add(p);
        }
        add(&self.holding);
        for (p, _) in &self.step_phrases {
            add(p);
        }
        for r in &self.relations {
            for p in &r.hear {
                add(p);
            }
        }
        for p in &self.properties {
            for h in &p.hear {
                add(h);
            }
        }
        for v in &self.verbs {
            add(std::slice::from_ref(&v.verb));
            if let Some(p) = &v.particle {
                add(std::slice::from_ref(p));
            }
        }
        let words: Vec<String> = self
            .kind_class
            .keys()
            .chain(self.colours.iter())
            .chain(self.sizes.iter())
            .chain(self.synonyms.values())
            .cloned()
            .collect();
        add(&words);
        known
    }

    /// Whether a normalized word is part of the vocabulary (numbers always are).
    pub fn knows(&self, word: &str) -> bool {
        self.known.contains(word) || word.bytes().all(|b| b.is_ascii_digit())
    }

    /// The canonical kind of a kind word ("cube" -> "block"), if it is one.
    pub fn kind(&self, word: &str) -> Option<&str> {
        self.kind_class.get(word).map(String::as_str)
    }

    /// One word through lemmas and synonyms (no contractions or numbers).
    pub fn word(&self, word: &str) -> String {
        let w = word.to_lowercase();
        let w = self.lemmas.get(&w).cloned().unwrap_or(w);
        self.synonyms.get(&w).cloned().unwrap_or(w)
    }

    /// A phrase of the lexicon, normalized; `{Y}`-style placeholders are kept as words.
    fn phrase(&self, text: &str) -> Vec<String> {
        self.normalize_with(text, true)
            .into_iter()
            .map(|t| t.word)
            .collect()
    }

    /// Normalizes text into tokens: lower case; words are runs of letters, digits and
    /// apostrophes (anything else separates words, so `green_can` and `time-step` are two
    /// words); contractions expanded; a final `'s` dropped; the indefinite articles `a` and `an`
    /// dropped; numbers and number words read; then lemmas and synonyms.
    pub fn normalize(&self, text: &str) -> Vec<Token> {
        self.normalize_with(text, false)
    }

    fn normalize_with(&self, text: &str, placeholders: bool) -> Vec<Token> {
        let lower = text.to_lowercase().replace(['\u{2019}', '\u{2018}'], "'");
        let mut out = Vec::new();
        let is_word =
            |c: char| c.is_alphanumeric() || c == '\'' || (placeholders && (c == '{' || c == '}'));
        for raw in lower.split(|c: char| !is_word(c)) {
            let raw = raw.trim_matches('\'');
            if raw.is_empty() {
                continue;
            }
            if placeholders && raw.starts_with('{') {
                // Placeholders keep their case: `{Y}`, `{N}`.
                let upper = raw.to_uppercase();
                out.push(Token {
                    word: upper.clone(),
                    original: upper,
                    num: None,
                });
                continue;
            }
            let words: Vec<String> = match self.contractions.get(raw) {
                Some(ws) => ws.clone(),
                None => vec![raw.strip_suffix("'s").unwrap_or(raw).to_string()],
            };
            for w in words {
                // Indefinite articles carry nothing the grammar uses, and people leave them
                // out ("has flat surface"): dropped from questions and phrases alike.
                if w == "a" || w == "an" {
                    continue;
                }
                let num = if w.bytes().all(|b| b.is_ascii_digit()) {
                    w.parse::<u32>().ok()
                } else {
                    self.numbers.get(&w).copied()
                };
                let word = match num {
                    Some(n) => n.to_string(),
                    None => self.word(&w),
                };
                out.push(Token {
                    word,
                    original: raw.to_string(),
                    num,
                });
            }
        }
        out
    }
}

fn lower_map(map: HashMap<String, String>) -> HashMap<String, String> {
    map.into_iter()
        .map(|(k, v)| (k.to_lowercase(), v.to_lowercase()))
        .collect()
}

/// Sorts phrases longest first (then alphabetically), so a matcher that takes the first phrase
/// that fits takes the longest ("on top of" before "on").
fn longest_first(mut phrases: Vec<Vec<String>>) -> Vec<Vec<String>> {
    phrases.sort_by(|a, b| b.len().cmp(&a.len()).then(a.cmp(b)));
    phrases.dedup();
    phrases
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_lexicon_loads() {
        let lex = Lexicon::ra();
        assert_eq!(lex.robot, "rob1");
        assert_eq!(lex.kind("cube"), Some("block"));
        assert_eq!(lex.kind("sphere"), Some("ball"));
        assert!(lex.knows(&lex.word("grab")) && lex.knows("pick") && lex.knows("17"));
        assert!(!lex.knows("flibber"));
    }

    #[test]
    fn normalization() {
        let lex = Lexicon::ra();
        let words: Vec<String> = lex
            .normalize("Why didn't you grab the Green_Can at time-step Five?")
            .into_iter()
            .map(|t| t.word)
            .collect();
        assert_eq!(
            words,
            ["why", "do", "not", "you", "pick", "the", "green", "can", "at", "time", "step", "5"]
        );
        let words: Vec<String> = lex
            .normalize("What\u{2019}s the robot's plan")
            .into_iter()
            .map(|t| t.word)
            .collect();
        assert_eq!(words, ["what", "be", "the", "robot", "plan"]);
    }

    #[test]
    fn bad_lexicons_are_errors() {
        assert!(Lexicon::from_json("{").is_err());
        let text = RA_LEXICON.replace("\"pickup(R,X)\"", "\"pickup(R,\"");
        assert!(matches!(
            Lexicon::from_json(&text),
            Err(LexiconError::Term { .. })
        ));
    }
}
