//! Fuzz target: parsing arbitrary bytes never panics and yields valid spans in both dialects.
//! The body is `lucent::syntax::fuzzing::check_parse_invariants_bytes`, which
//! `tests/syntax/corpus.rs` also runs on the seed corpus.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = lucent::syntax::fuzzing::check_parse_invariants_bytes(data) {
        panic!("{e}");
    }
});
