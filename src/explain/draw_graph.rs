//! A proof as a graph picture for programs (`lucent explain PROGRAM.lp --why A --svg F`, and as
//! Graphviz DOT with `--dot F`): each
//! literal drawn once, in a box with the rule instance that supports (or fails to support) it
//! and the rule's location, whatever the number of places the proof uses it; readable at 50
//! nodes because rows wrap at a fixed width instead of growing with the tree's bands.
//!
//! Layout: the literals reachable from the roots through children, merged by (literal, truth),
//! each represented by the first node met breadth-first (its rule, its children); a literal's
//! layer is its breadth-first depth from the roots; within a layer, literals are ordered by the
//! mean position of their parents in the layer above (one barycentric pass), then laid out left
//! to right and wrapped into further rows when a row would pass [`MAX_ROW_WIDTH`]. Edges run
//! from a parent's bottom to a child's top, the answer's path in green.
//!
//! Invariants: a pure function of the tree (no clock, no hash order); every distinct literal of
//! the reachable proof appears in exactly one box; boxes never overlap (rows are laid out left to
//! right, each row below the previous); text is XML-escaped; box sizes come from text length with
//! a fixed advance per character.

use std::collections::HashMap;
use std::fmt::Write;

use super::tree::{Kind, NodeId, ProofTree};
use crate::control::Symbol;

/// The widest a row of boxes gets before it wraps, in pixels.
pub const MAX_ROW_WIDTH: f64 = 1400.0;
/// The longest line of text in a box, in characters (longer rule texts are cut with `...`).
const MAX_CHARS: usize = 64;
const CHAR_W: f64 = 7.2;
const LINE_H: f64 = 16.0;
const PAD: f64 = 8.0;
const H_GAP: f64 = 20.0;
const V_GAP: f64 = 36.0;
const PATH_STROKE: &str = "#2e7d32";
const PATH_FILL: &str = "#e8f5e9";
const OFF_STROKE: &str = "#555555";
const FALSE_FILL: &str = "#fff3e0";

/// One box: a literal, its representative node, its lines, its place.
struct Cell {
    node: NodeId,
    lines: Vec<String>,
    layer: usize,
    x: f64,
    y: f64,
    w: f64,
    h: f64,
}

fn cut(s: String) -> String {
    if s.chars().count() <= MAX_CHARS {
        return s;
    }
    let mut t: String = s.chars().take(MAX_CHARS - 3).collect();
    t.push_str("...");
    t
}

fn box_lines(tree: &ProofTree, id: NodeId) -> Vec<String> {
    let n = tree.node(id);
    let mut out = vec![cut(if n.holds {
        n.literal.to_string()
    } else {
        format!("{} (false)", n.literal)
    })];
    match (&n.rule, &n.kind) {
        (Some(r), _) => {
            out.push(cut(r.to_string()));
            out.push(cut(n.kind.words()));
        }
        (None, Kind::Unsupported) if !n.blocked.is_empty() => {
            out.push(cut(format!("{} rule(s), each blocked", n.blocked.len())));
        }
        (None, k) => out.push(cut(k.words())),
    }
    for t in &n.no_evidence {
        out.push(cut(format!("no evidence of {t}")));
    }
    out
}

/// The merged graph: boxes, the box of each node, the distinct edges between boxes.
fn merge(tree: &ProofTree) -> (Vec<Cell>, Vec<(usize, usize)>) {
    let mut index: HashMap<(Symbol, bool), usize> = HashMap::new();
    let mut boxes: Vec<Cell> = Vec::new();
    let mut edges: Vec<(usize, usize)> = Vec::new();
    let mut queue: std::collections::VecDeque<(NodeId, usize)> = std::collections::VecDeque::new();
    let mut visit = |id: NodeId,
                     layer: usize,
                     boxes: &mut Vec<Cell>,
                     queue: &mut std::collections::VecDeque<(NodeId, usize)>| {
        let n = tree.node(id);
        let key = (n.literal.clone(), n.holds);
        if let Some(&b) = index.get(&key) {
            return b;
        }
        let b = boxes.len();
        index.insert(key, b);
        let lines = box_lines(tree, id);
        let chars = lines.iter().map(|l| l.chars().count()).max().unwrap_or(1);
        boxes.push(Cell {
            node: id,
            w: chars as f64 * CHAR_W + 2.0 * PAD,
            h: lines.len() as f64 * LINE_H + 2.0 * PAD - 4.0,
            lines,
            layer,
            x: 0.0,
            y: 0.0,
        });
        queue.push_back((id, b));
        b
    };
    for &r in tree.roots.iter().filter(|r| r.index() < tree.nodes.len()) {
        visit(r, 0, &mut boxes, &mut queue);
    }
    while let Some((id, b)) = queue.pop_front() {
        let layer = boxes[b].layer + 1;
        for &c in &tree.node(id).children {
            if c.index() >= tree.nodes.len() {
                continue;
            }
            let cb = visit(c, layer, &mut boxes, &mut queue);
            if cb != b && !edges.contains(&(b, cb)) {
                edges.push((b, cb));
            }
        }
    }
    (boxes, edges)
}

/// Places the boxes: layers top to bottom, barycentric order, rows wrapped (module comment).
/// Returns the picture's width and height.
fn place(boxes: &mut [Cell], edges: &[(usize, usize)]) -> (f64, f64) {
    let layers = boxes.iter().map(|b| b.layer + 1).max().unwrap_or(0);
    let mut y = 20.0;
    let mut width: f64 = 40.0;
    let mut prev_order: HashMap<usize, f64> = HashMap::new();
    for layer in 0..layers {
        let mut members: Vec<usize> = (0..boxes.len())
            .filter(|&b| boxes[b].layer == layer)
            .collect();
        let key = |b: usize| {
            let ps: Vec<f64> = edges
                .iter()
                .filter(|(_, c)| *c == b)
                .filter_map(|(p, _)| prev_order.get(p).copied())
                .collect();
            if ps.is_empty() {
                f64::MAX
            } else {
                ps.iter().sum::<f64>() / ps.len() as f64
            }
        };
        let keys: Vec<f64> = members.iter().map(|&b| key(b)).collect();
        let mut order: Vec<usize> = (0..members.len()).collect();
        order.sort_by(|&i, &j| {
            keys[i]
                .total_cmp(&keys[j])
                .then(members[i].cmp(&members[j]))
        });
        members = order.into_iter().map(|i| members[i]).collect();
        prev_order.clear();
        let mut x = 20.0;
        let mut row_h: f64 = 0.0;
        for (k, &b) in members.iter().enumerate() {
            if x > 20.0 && x + boxes[b].w > MAX_ROW_WIDTH {
                y += row_h + V_GAP / 2.0;
                x = 20.0;
                row_h = 0.0;
            }
            boxes[b].x = x;
            boxes[b].y = y;
            x += boxes[b].w + H_GAP;
            row_h = row_h.max(boxes[b].h);
            width = width.max(x - H_GAP + 20.0);
            prev_order.insert(b, k as f64);
        }
        y += row_h + V_GAP;
    }
    (width, (y - V_GAP + 20.0).max(40.0))
}

/// The proof as a standalone SVG document, each literal once (module comment).
pub fn svg(tree: &ProofTree) -> String {
    let (mut boxes, edges) = merge(tree);
    let (width, height) = place(&mut boxes, &edges);
    let on_path = |b: &Cell| tree.on_path(b.node);
    let mut out = String::new();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" \
         viewBox=\"0 0 {width:.0} {height:.0}\" font-family=\"monospace\" font-size=\"12\">"
    );
    out.push_str("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    for &(p, c) in &edges {
        let (p, c) = (&boxes[p], &boxes[c]);
        let path = on_path(p) && on_path(c);
        let (stroke, w) = if path {
            (PATH_STROKE, 2.0)
        } else {
            (OFF_STROKE, 1.0)
        };
        let _ = writeln!(
            out,
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"{stroke}\" \
             stroke-width=\"{w}\" opacity=\"0.7\"/>",
            p.x + p.w / 2.0,
            p.y + p.h,
            c.x + c.w / 2.0,
            c.y
        );
    }
    for b in &boxes {
        let n = tree.node(b.node);
        let (stroke, fill, w) = if on_path(b) {
            (PATH_STROKE, PATH_FILL, 2.0)
        } else if !n.holds {
            (OFF_STROKE, FALSE_FILL, 1.0)
        } else {
            (OFF_STROKE, "white", 1.0)
        };
        let _ = writeln!(
            out,
            "<g><rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" rx=\"6\" \
             fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{w}\"/>",
            b.x, b.y, b.w, b.h
        );
        for (k, line) in b.lines.iter().enumerate() {
            let style = if k == 0 {
                " font-weight=\"bold\" fill=\"black\"".to_string()
            } else {
                format!(" fill=\"{OFF_STROKE}\"")
            };
            let _ = writeln!(
                out,
                "<text x=\"{:.1}\" y=\"{:.1}\"{style}>{}</text>",
                b.x + PAD,
                b.y + PAD + 8.0 + k as f64 * LINE_H,
                xml_escape(line)
            );
        }
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
}

/// The proof as Graphviz DOT, each literal once (merged as in [`svg`], by literal and truth),
/// with its rule instance and location; an edge per distinct (parent, child) pair, labelled
/// with the blocked rules (all of them) under a literal that does not hold; the answer's path
/// in green.
pub fn dot(tree: &ProofTree) -> String {
    let (boxes, _) = merge(tree);
    let index: HashMap<(Symbol, bool), usize> = boxes
        .iter()
        .enumerate()
        .map(|(b, cell)| {
            let n = tree.node(cell.node);
            ((n.literal.clone(), n.holds), b)
        })
        .collect();
    let on_path = |b: &Cell| tree.on_path(b.node);
    let mut out = String::from("digraph proof {\n  rankdir=TB;\n");
    out.push_str(
        "  node [shape=box, style=\"rounded,filled\", fillcolor=white, fontname=\"monospace\"];\n",
    );
    out.push_str("  edge [arrowhead=none];\n");
    for (b, cell) in boxes.iter().enumerate() {
        let n = tree.node(cell.node);
        let label: Vec<String> = cell.lines.iter().map(|l| dot_escape(l)).collect();
        let mut attrs = format!("label=\"{}\"", label.join("\\n"));
        if on_path(cell) {
            let _ = write!(
                attrs,
                ", color=\"{PATH_STROKE}\", fillcolor=\"{PATH_FILL}\", penwidth=2"
            );
        } else if !n.holds {
            let _ = write!(attrs, ", fillcolor=\"{FALSE_FILL}\"");
        }
        if n.kind == Kind::Unsupported {
            attrs.push_str(", style=\"rounded,dashed,filled\"");
        }
        let _ = writeln!(out, "  n{b} [{attrs}];");
    }
    // Distinct (parent, child) pairs in first-met order, each with the blocked rules it stands
    // for (several when a false literal blocks more than one rule of its parent).
    let mut edges: Vec<((usize, usize), Vec<String>)> = Vec::new();
    for (b, cell) in boxes.iter().enumerate() {
        let n = tree.node(cell.node);
        for (i, &c) in n.children.iter().enumerate() {
            let Some(child) = tree.nodes.get(c.index()) else {
                continue;
            };
            let Some(&cb) = index.get(&(child.literal.clone(), child.holds)) else {
                continue;
            };
            if cb == b {
                continue;
            }
            let k = match edges.iter().position(|e| e.0 == (b, cb)) {
                Some(k) => k,
                None => {
                    edges.push(((b, cb), Vec::new()));
                    edges.len() - 1
                }
            };
            if n.kind == Kind::Unsupported {
                if let Some(r) = n.blocked.get(i) {
                    if !edges[k].1.contains(&r.label) {
                        edges[k].1.push(r.label.clone());
                    }
                }
            }
        }
    }
    for ((b, cb), blocks) in &edges {
        let mut attrs = Vec::new();
        if !blocks.is_empty() {
            attrs.push(format!(
                "label=\"blocks {}\"",
                dot_escape(&blocks.join("; "))
            ));
        }
        if on_path(&boxes[*b]) && on_path(&boxes[*cb]) {
            attrs.push(format!("color=\"{PATH_STROKE}\", penwidth=2"));
        }
        let attrs = if attrs.is_empty() {
            String::new()
        } else {
            format!(" [{}]", attrs.join(", "))
        };
        let _ = writeln!(out, "  n{b} -> n{cb}{attrs};");
    }
    out.push_str("}\n");
    out
}

fn dot_escape(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}

/// The distinct literals drawn, in box order (for tests: each appears once).
pub fn drawn_literals(tree: &ProofTree) -> Vec<Symbol> {
    merge(tree)
        .0
        .iter()
        .map(|b| tree.node(b.node).literal.clone())
        .collect()
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows never pass the width (but for a single box wider than it) and boxes never overlap.
    #[test]
    fn rows_wrap_and_boxes_do_not_overlap() {
        let mut boxes: Vec<Cell> = (0..60)
            .map(|i| Cell {
                node: NodeId(i),
                lines: vec![format!("p({i})")],
                layer: (i as usize) / 40,
                x: 0.0,
                y: 0.0,
                w: 100.0 + (i % 7) as f64 * 30.0,
                h: 40.0,
            })
            .collect();
        let edges: Vec<(usize, usize)> = (40..60).map(|c| (c - 40, c)).collect();
        let (width, _) = place(&mut boxes, &edges);
        assert!(width <= MAX_ROW_WIDTH + 20.0, "{width}");
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                let apart =
                    a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
                assert!(apart, "({},{}) and ({},{}) overlap", a.x, a.y, b.x, b.y);
            }
        }
    }
}
