//! [`Name`]: the text of a name in the syntax tree (constants, variables, function and
//! predicate names), a string that needs no allocation when short.
//!
//! Role: a parse makes one name per identifier and variable token (some 330 for the 44-line
//! learner program) and drops them all with the tree; as `String`s they were a third of the
//! parser's allocations. A name of up to `INLINE` bytes is stored in the value itself; a
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

impl Name {
    /// A hash of the text for small direct-mapped caches (the rewriter's name ids): for an
    /// inline name three multiplications over its bytes, whatever its length. Equal names have
    /// equal hashes.
    #[inline]
    pub fn quick_hash(&self) -> u64 {
        const K: u64 = 0x9e37_79b9_7f4a_7c15;
        match &self.0 {
            Repr::Inline { len, bytes } => {
                let (a, b, c) = words(bytes);
                (((a.wrapping_mul(K) ^ b).wrapping_mul(K) ^ c).wrapping_mul(K) ^ u64::from(*len))
                    .wrapping_mul(K)
            }
            Repr::Heap(s) => s
                .bytes()
                .fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                    (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
                })
                .wrapping_mul(K),
        }
    }
}

/// The inline bytes as three words (the last two overlap by two bytes): fixed-size loads, so
/// comparing and hashing a name costs a few instructions whatever its length.
#[inline]
fn words(bytes: &[u8; INLINE]) -> (u64, u64, u64) {
    let word = |i: usize| {
        let mut w = [0u8; 8];
        w.copy_from_slice(&bytes[i..i + 8]);
        u64::from_le_bytes(w)
    };
    (word(0), word(8), word(INLINE - 8))
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
    /// Two inline names compare as their 24 bytes (the bytes past `len` are zero); a text of
    /// up to `INLINE` bytes is always inline, so an inline name never equals a shared one.
    #[inline]
    fn eq(&self, other: &Name) -> bool {
        match (&self.0, &other.0) {
            (Repr::Inline { len: a, bytes: x }, Repr::Inline { len: b, bytes: y }) => {
                a == b && words(x) == words(y)
            }
            _ => self.as_str() == other.as_str(),
        }
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
        for (a, b) in [("p", "p"), ("in_hand", "in_hand"), (long, long)] {
            assert_eq!(Name::new(a).quick_hash(), Name::new(b).quick_hash());
        }
        assert_ne!(Name::new("p").quick_hash(), Name::new("q").quick_hash());
        assert_ne!(Name::new("a"), Name::new("ab"));
    }

    #[test]
    fn a_name_is_as_small_as_a_string() {
        assert_eq!(std::mem::size_of::<Name>(), std::mem::size_of::<String>());
    }
}
