//! Set-up shared by the grounder's tests (`tests/ground/`, as `crate::support::ground`): a
//! program of the clingo dialect parsed and grounded.

use lucent::base::SourceMap;
use lucent::ground::{ground, GroundConfig, Grounding};
use lucent::syntax::ast::Dialect;
use lucent::syntax::parse;

/// `text`, as the file `name`, parsed and grounded with `config`: the grounding and the sources
/// its diagnostics point into. Panics on a parse or grounding error.
pub fn ground_text(name: &str, text: &str, config: &GroundConfig) -> (Grounding, SourceMap) {
    let mut sources = SourceMap::new();
    let id = sources.add(name, text);
    let parsed = parse(id, text, Dialect::Clingo);
    assert!(!parsed.has_errors(), "{name}: parse errors");
    let g = ground(&parsed.program, Some(&sources), config);
    assert!(
        !g.diagnostics.has_errors(),
        "{}",
        g.diagnostics.render(&sources)
    );
    (g, sources)
}
