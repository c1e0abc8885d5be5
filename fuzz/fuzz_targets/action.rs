//! Fuzz target: parsing arbitrary bytes as AL_d, then checking and translating the result,
//! never panics; diagnostics have valid spans; an error-free translation prints as a program
//! that parses. The body is `lucent::action::fuzzing::check_action_invariants`, which
//! `tests/action/fuzz_corpus.rs` also runs on the seed corpus.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = lucent::action::fuzzing::check_action_invariants(data) {
        panic!("{e}");
    }
});
