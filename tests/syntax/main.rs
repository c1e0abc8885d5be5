//! The `syntax` layer's integration tests: the parsers against the grammars, their
//! messages, the parse corpus and properties.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

mod corpus;
mod grammar;
mod messages;
mod props;
mod theory;
