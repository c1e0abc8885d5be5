//! Fuzz target: the aspif reader never panics on arbitrary bytes, what it accepts writes back
//! and reads again, and small accepted programs solve with every model checked. The body is
//! `lucent::solve::fuzzing::check_aspif_bytes`, which `tests/ground/aspif_fuzz_corpus.rs` also runs
//! on the seed corpus.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = lucent::solve::fuzzing::check_aspif_bytes(data) {
        panic!("{e}");
    }
});
