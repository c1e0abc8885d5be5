//! [`Name`]: the text of a name in the syntax tree (constants, variables, function and
//! predicate names), a string that needs no allocation when short.
//!
//! Role: a parse makes one name per identifier and variable token (some 330 for the 44-line
//! learner program) and drops them all with the tree; as `String`s they were a third of the
//! parser's allocations. A name of up to [`INLINE`] bytes is stored in the value itself; a
//! longer one is an `Arc<str>` shared by its clones.
//!
//! Invariants:
//! - A `Name` behaves as the `str` it holds: equality, order, hashing, `Display` and `Debug` are
//!   those of the text, whichever way it is stored (so a name is equal to itself whatever its
//!   length, and a tree compares equal to a copy of it).
//! - The inline bytes `bytes[..len]` are always a whole UTF-8 string: they are copied from a
//!   `&str` and never changed.

use std::borrow::Borrow;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::Deref;
use std::sync::Arc;

/// Longest name stored without allocation, in bytes.
pub const INLINE: usize = 22;

/// A name's text: inline when short, shared otherwise. 24 bytes, like a `String`.
#[derive(Clone)]
pub struct Name(Repr);

#[derive(Clone)]
enum Repr {
    /// `bytes[..len]` is the text (whole UTF-8, see the module's invariants).
    Inline { len: u8, bytes: [u8; INLINE] },
    /// A longer text.
    Heap(Arc<str>),
}

impl Name {
    /// The name with text `s`.
    #[inline]
    pub fn new(s: &str) -> Name {
        if s.len() <= INLINE {
            let mut bytes = [0u8; INLINE];
            bytes[..s.len()].copy_from_slice(s.as_bytes());
            Name(Repr::Inline {
                len: s.len() as u8,
                bytes,
            })
        } else {
            Name(Repr::Heap(Arc::from(s)))
        }
    }

    /// The text.
    #[inline]
    pub fn as_str(&self) -> &str {
        match &self.0 {
            Repr::Inline { len, bytes } => {
                let b = &bytes[..*len as usize];
                debug_assert!(std::str::from_utf8(b).is_ok());
                // SAFETY: `bytes[..len]` was copied whole from a `&str` in `Name::new` and is
                // never written afterwards (module invariant), so it is valid UTF-8. Checking
                // it again on every access cost ~25 instructions per name in the parser's and
                // the rewriter's hot paths (the learner-loop benchmark).
                unsafe { std::str::from_utf8_unchecked(b) }
            }
            Repr::Heap(s) => s,
        }
    }
}

impl Default for Name {
    fn default() -> Name {
        Name::new("")
    }
}

impl Deref for Name {
    type Target = str;
    #[inline]
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl AsRef<str> for Name {
    fn as_ref(&self) -> &str {
        self.as_str()
    }
}

impl Borrow<str> for Name {
    fn borrow(&self) -> &str {
        self.as_str()
    }
}

impl From<&str> for Name {
    fn from(s: &str) -> Name {
        Name::new(s)
    }
}

impl From<String> for Name {
    fn from(s: String) -> Name {
        Name::new(&s)
    }
}

impl From<&String> for Name {
    fn from(s: &String) -> Name {
        Name::new(s)
    }
}

impl From<Name> for String {
    fn from(n: Name) -> String {
        n.as_str().to_string()
    }
}

impl PartialEq for Name {
    #[inline]
    fn eq(&self, other: &Name) -> bool {
        self.as_str() == other.as_str()
    }
}

impl Eq for Name {}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        self.as_str() == other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl PartialEq<String> for Name {
    fn eq(&self, other: &String) -> bool {
        self.as_str() == other.as_str()
    }
}

impl PartialEq<Name> for str {
    fn eq(&self, other: &Name) -> bool {
        self == other.as_str()
    }
}

impl PartialEq<Name> for &str {
    fn eq(&self, other: &Name) -> bool {
        *self == other.as_str()
    }
}

impl PartialEq<Name> for String {
    fn eq(&self, other: &Name) -> bool {
        self.as_str() == other.as_str()
    }
}

impl PartialOrd for Name {
    fn partial_cmp(&self, other: &Name) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Name {
    fn cmp(&self, other: &Name) -> std::cmp::Ordering {
        self.as_str().cmp(other.as_str())
    }
}

impl Hash for Name {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.as_str().hash(state)
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self.as_str(), f)
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_and_long_names_behave_as_their_text() {
        let long = "a_name_longer_than_twenty_two_bytes";
        for s in [
            "",
            "p",
            "in_hand",
            "exactly_22_bytes_long_",
            long,
            "ünïcødé",
        ] {
            let n = Name::new(s);
            assert_eq!(n.as_str(), s);
            assert_eq!(n, s);
            assert_eq!(n.clone(), n);
            assert_eq!(format!("{n}"), s);
            assert_eq!(format!("{n:?}"), format!("{s:?}"));
            assert_eq!(String::from(n.clone()), s);
        }
        assert!(matches!(Name::new(long).0, Repr::Heap(_)));
        assert!(matches!(
            Name::new("exactly_22_bytes_long_").0,
            Repr::Inline { .. }
        ));
        assert!(Name::new("a") < Name::new("b"));
        assert_ne!(Name::new("a"), Name::new("ab"));
    }

    #[test]
    fn a_name_is_as_small_as_a_string() {
        assert_eq!(std::mem::size_of::<Name>(), std::mem::size_of::<String>());
    }
}
