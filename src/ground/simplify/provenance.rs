//! The provenance of the output program (when provenance is on): the origins of the output
//! rules with those of second rules for facts added to the fact's rule, the atom table (every
//! grounder atom's symbol, status and aspif number), and the removed rule instances still worth
//! explaining.
//!
//! Invariant: a dead rule is kept only when it headed an atom that ended up false (or a fact
//! among its heads satisfied it) and the literal that stopped it is still decided that way (one
//! that failed in an early round of a recursive component may have been derived later).

use super::Status;
use crate::ground::instantiate::Grounder;
use crate::ground::program::{AtomRecord, AtomStatus, DeadReason, DeadRule, Origin, Provenance};

/// The provenance of the output: the `origins` of the output rules with the `late` ones of
/// second rules for facts, the atom table of `g` by `status` and the aspif numbering `number`,
/// and the `dead_rules` still decided.
pub(super) fn provenance(
    g: &Grounder<'_>,
    status: &[Status],
    number: &[u32],
    origins: Provenance,
    late: Vec<(u32, Origin)>,
    mut dead_rules: Vec<DeadRule>,
) -> Provenance {
    let mut p = origins;
    p.add_origins(late);
    p.set_atoms(
        g.atoms
            .iter()
            .enumerate()
            .map(|(i, info)| AtomRecord {
                sym: info.sym.map(|s| s.0),
                status: match status[i] {
                    Status::Fact => AtomStatus::Fact,
                    Status::False => AtomStatus::False,
                    Status::Unknown => AtomStatus::Possible,
                },
                aspif: number[i + 1],
            })
            .collect(),
    );
    // Instances dropped during instantiation are kept only when they headed a false atom
    // (or were satisfied by a fact among their heads) and the literal that stopped them is
    // still decided that way (one that failed in an early round of a recursive component
    // may have been derived later).
    dead_rules.retain(|d| {
        let decided = match d.why {
            DeadReason::Literal { positive, atom } => {
                status[atom as usize - 1]
                    == if positive {
                        Status::False
                    } else {
                        Status::Fact
                    }
            }
            DeadReason::HeadFact(f) => status[f as usize - 1] == Status::Fact,
            DeadReason::Contradictory | DeadReason::Unreachable => true,
        };
        decided
            && (matches!(d.why, DeadReason::HeadFact(_))
                || d.head
                    .iter()
                    .any(|&h| status[h as usize - 1] == Status::False))
    });
    p.dead = dead_rules;
    p
}
