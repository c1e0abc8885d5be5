//! Set-up shared by the learner's tests (`tests/learn/`, as `crate::support::learn`): the H1
//! knowledge base of the RA domain (`domains/ra/scenes/h1.ald`) as the learner starts from it.

use lucent::learn::h1;
use lucent::learn::kb::KbSpec;

use super::ra_scenes;

/// `domains/ra/scenes/h1.ald` with the learner's options (`lucent learn`'s default knowledge
/// base). Panics on a parse error.
pub fn spec() -> KbSpec {
    let (description, sources) = ra_scenes::load_scene("h1.ald");
    KbSpec {
        description,
        options: h1::learner_options(),
        sources,
    }
}
