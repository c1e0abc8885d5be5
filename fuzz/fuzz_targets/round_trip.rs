//! Fuzz target: for input that parses without errors, `parse(print(tree))` has the tree's shape.
//! The body is `lucent::syntax::fuzzing::check_round_trip_bytes`, which `tests/syntax/corpus.rs`
//! also runs on the seed corpus.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = lucent::syntax::fuzzing::check_round_trip_bytes(data) {
        panic!("{e}");
    }
});
