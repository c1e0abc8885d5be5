//! Directed graphs in compressed form and Tarjan's strongly connected components (iterative),
//! as the positive dependency graph (`deps`) needs them.
//!
//! Invariants: the successors of node `v` are `targets[first[v]..first[v + 1]]`, in the order
//! they were added (`first` starts at 0 and never decreases); `scc` numbers components in the
//! order the search completes them, so the numbering depends only on the graph.

/// A directed graph over nodes `0..len()` in compressed form: the successors of `v` are
/// `targets[first[v]..first[v + 1]]`, in the order they were added.
pub struct Graph {
    pub(super) first: Vec<usize>,
    pub(super) targets: Vec<u32>,
}

impl Graph {
    /// The graph with the given successor lists.
    pub fn from_lists(lists: &[Vec<u32>]) -> Graph {
        let mut first = vec![0usize];
        let mut targets = Vec::new();
        for l in lists {
            targets.extend_from_slice(l);
            first.push(targets.len());
        }
        Graph { first, targets }
    }

    /// The number of nodes.
    pub fn len(&self) -> usize {
        self.first.len() - 1
    }

    /// The successors of `v`.
    pub fn succ(&self, v: usize) -> &[u32] {
        &self.targets[self.first[v]..self.first[v + 1]]
    }
}

/// Tarjan's strongly connected components, iteratively; returns the component of each node.
pub fn scc(edges: &Graph) -> Vec<u32> {
    let n = edges.len();
    let mut index = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut on_stack = vec![false; n];
    let mut comp = vec![u32::MAX; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut next = 0u32;
    let mut ncomp = 0u32;
    // The depth-first path as (node, next successor to visit); empty between roots.
    let mut call: Vec<(u32, usize)> = Vec::new();
    for root in 0..n {
        if index[root] != u32::MAX {
            continue;
        }
        if edges.succ(root).is_empty() {
            // A root without successors is a component of its own (most atoms of most
            // programs): what the search below would find, in the same order.
            index[root] = next;
            next += 1;
            comp[root] = ncomp;
            ncomp += 1;
            continue;
        }
        call.push((root as u32, 0));
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root as u32);
        on_stack[root] = true;
        while let Some(&mut (v, ref mut k)) = call.last_mut() {
            let v = v as usize;
            let succ = edges.succ(v);
            if *k < succ.len() {
                let w = succ[*k] as usize;
                *k += 1;
                if index[w] == u32::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w as u32);
                    on_stack[w] = true;
                    call.push((w as u32, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
            } else {
                call.pop();
                if let Some(&(u, _)) = call.last() {
                    low[u as usize] = low[u as usize].min(low[v]);
                }
                if low[v] == index[v] {
                    loop {
                        let w = stack.pop().expect("Tarjan stack holds the component") as usize;
                        on_stack[w] = false;
                        comp[w] = ncomp;
                        if w == v {
                            break;
                        }
                    }
                    ncomp += 1;
                }
            }
        }
    }
    comp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scc_finds_cycles() {
        // 0 -> 1 -> 2 -> 1, 3 alone.
        let edges = vec![vec![1], vec![2], vec![1], vec![]];
        let c = scc(&Graph::from_lists(&edges));
        assert_eq!(c[1], c[2]);
        assert_ne!(c[0], c[1]);
        assert_ne!(c[3], c[1]);
    }
}
