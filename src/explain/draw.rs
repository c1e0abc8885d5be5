//! Proof trees as pictures: Graphviz DOT text, and an SVG drawn here with a layered tree layout
//! (the paper's belief-tracing figure: boxes with the literal and the axiom, the answer's path in
//! green).
//!
//! Layout: the root literal's alternatives side by side at the top, each level one row lower;
//! every subtree gets a horizontal band as wide as the larger of its own box and its children's
//! bands side by side, and a node is centred over its band, so boxes never overlap. A node shared
//! by several parents (a builder may share nodes, children before parents) is drawn once, at its
//! first place in depth-first order; its other parents get an edge to it all the same.
//!
//! Invariants: output is a pure function of the tree (no clock, no randomness, no hash order);
//! all text is escaped for its format (DOT strings, XML); box sizes come from the text length
//! with a fixed advance per character, so the SVG needs no font metrics.

use std::fmt::Write;

use super::tree::{Kind, NodeId, ProofTree};

/// Colour of the answer's path (the paper's green).
const PATH_STROKE: &str = "#2e7d32";
/// Fill of boxes on the path.
const PATH_FILL: &str = "#e8f5e9";
/// Colour of boxes and edges off the path.
const OFF_STROKE: &str = "#555555";
/// Fill of leaves off the path.
const LEAF_FILL: &str = "#f5f5f5";

/// Width of one character of the monospace font, in pixels.
const CHAR_W: f64 = 7.2;
/// Height of one line of text.
const LINE_H: f64 = 16.0;
/// Padding inside a box.
const PAD: f64 = 8.0;
/// Horizontal gap between bands.
const H_GAP: f64 = 24.0;
/// Vertical gap between rows.
const V_GAP: f64 = 40.0;

/// The lines of a node's box: the literal, its support, and "no evidence of" lines.
fn lines(tree: &ProofTree, id: NodeId) -> Vec<String> {
    let n = tree.node(id);
    let mut out = vec![n.literal.to_string(), n.kind.words()];
    for t in &n.no_evidence {
        out.push(format!("no evidence of {t}"));
    }
    out
}

/// The tree in Graphviz DOT: one box per node (literal, then its support), edges from a node to
/// its children labelled with blocked rules where the node does not hold, and the answer's path
/// in green.
pub fn dot(tree: &ProofTree) -> String {
    let mut out = String::new();
    out.push_str("digraph proof {\n");
    out.push_str("  rankdir=TB;\n");
    out.push_str(
        "  node [shape=box, style=\"rounded,filled\", fillcolor=white, fontname=\"monospace\"];\n",
    );
    out.push_str("  edge [arrowhead=none];\n");
    for (i, n) in tree.nodes.iter().enumerate() {
        let id = NodeId(i as u32);
        let label = lines(tree, id)
            .iter()
            .map(|l| dot_escape(l))
            .collect::<Vec<_>>()
            .join("\\n");
        let mut attrs = format!("label=\"{label}\"");
        if tree.on_path(id) {
            let _ = write!(
                attrs,
                ", color=\"{PATH_STROKE}\", fillcolor=\"{PATH_FILL}\", penwidth=2"
            );
        } else if n.children.is_empty() {
            let _ = write!(attrs, ", fillcolor=\"{LEAF_FILL}\"");
        }
        if n.kind == Kind::Unsupported {
            attrs.push_str(", style=\"rounded,dashed\"");
        }
        let _ = writeln!(out, "  n{i} [{attrs}];");
    }
    for e in tree.edges() {
        let on_path = tree
            .path
            .windows(2)
            .any(|w| w[0] == e.parent && w[1] == e.child);
        let mut attrs = Vec::new();
        if tree.node(e.parent).kind == Kind::Unsupported {
            attrs.push(format!("label=\"blocks {}\"", dot_escape(&e.rule.label)));
        }
        if on_path {
            attrs.push(format!("color=\"{PATH_STROKE}\", penwidth=2"));
        }
        let attrs = if attrs.is_empty() {
            String::new()
        } else {
            format!(" [{}]", attrs.join(", "))
        };
        let _ = writeln!(out, "  n{} -> n{}{attrs};", e.parent.0, e.child.0);
    }
    out.push_str("}\n");
    out
}

fn dot_escape(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Where a node is drawn.
#[derive(Clone, Copy, Debug)]
struct Place {
    /// Centre x.
    x: f64,
    /// Top y.
    y: f64,
    /// Box width.
    w: f64,
    /// Box height.
    h: f64,
}

/// Layout state: each node's place (drawn once), row heights.
struct Layout<'t> {
    tree: &'t ProofTree,
    place: Vec<Option<Place>>,
    /// Band width of each node's subtree, computed once.
    band: Vec<Option<f64>>,
    /// Height of the tallest box per depth.
    row_h: Vec<f64>,
}

impl Layout<'_> {
    fn size(&self, id: NodeId) -> (f64, f64) {
        let ls = lines(self.tree, id);
        let chars = ls.iter().map(|l| l.chars().count()).max().unwrap_or(0);
        (
            chars as f64 * CHAR_W + 2.0 * PAD,
            ls.len() as f64 * LINE_H + 2.0 * PAD - 4.0,
        )
    }

    /// The band width of a subtree, with the nodes drawn first under `owner` (a shared node
    /// belongs to its first parent in depth-first order).
    fn band(&mut self, id: NodeId, depth: usize, owned: &mut Vec<bool>) -> f64 {
        owned[id.index()] = true;
        let (w, h) = self.size(id);
        if self.row_h.len() <= depth {
            self.row_h.resize(depth + 1, 0.0);
        }
        self.row_h[depth] = self.row_h[depth].max(h);
        let children: Vec<NodeId> = self.tree.node(id).children.clone();
        let mut sum = 0.0;
        let mut count = 0;
        for c in children {
            if owned[c.index()] {
                continue;
            }
            sum += self.band(c, depth + 1, owned);
            count += 1;
        }
        if count > 1 {
            sum += H_GAP * (count - 1) as f64;
        }
        let b = w.max(sum);
        self.band[id.index()] = Some(b);
        b
    }

    fn assign(&mut self, id: NodeId, depth: usize, left: f64, drawn: &mut Vec<bool>) {
        drawn[id.index()] = true;
        let (w, h) = self.size(id);
        let band = self.band[id.index()].unwrap_or(w);
        let y: f64 = self.row_h[..depth].iter().map(|r| r + V_GAP).sum::<f64>() + 20.0;
        self.place[id.index()] = Some(Place {
            x: left + band / 2.0,
            y,
            w,
            h,
        });
        let children: Vec<NodeId> = self.tree.node(id).children.clone();
        let own: Vec<NodeId> = children
            .into_iter()
            .filter(|c| !drawn[c.index()] && self.band[c.index()].is_some())
            .collect();
        let total: f64 = own
            .iter()
            .map(|c| self.band[c.index()].unwrap_or(0.0))
            .sum::<f64>()
            + H_GAP * own.len().saturating_sub(1) as f64;
        let mut x = left + (band - total) / 2.0;
        for c in own {
            if drawn[c.index()] {
                continue;
            }
            let b = self.band[c.index()].unwrap_or(0.0);
            self.assign(c, depth + 1, x, drawn);
            x += b + H_GAP;
        }
    }
}

/// The tree as a standalone SVG document.
pub fn svg(tree: &ProofTree) -> String {
    let mut layout = Layout {
        tree,
        place: vec![None; tree.nodes.len()],
        band: vec![None; tree.nodes.len()],
        row_h: Vec::new(),
    };
    let mut owned = vec![false; tree.nodes.len()];
    let roots: Vec<NodeId> = tree
        .roots
        .iter()
        .copied()
        .filter(|r| r.index() < tree.nodes.len())
        .collect();
    let bands: Vec<f64> = roots
        .iter()
        .map(|r| {
            if owned[r.index()] {
                0.0
            } else {
                layout.band(*r, 0, &mut owned)
            }
        })
        .collect();
    let mut drawn = vec![false; tree.nodes.len()];
    let mut left = 20.0;
    for (r, b) in roots.iter().zip(&bands) {
        if !drawn[r.index()] {
            layout.assign(*r, 0, left, &mut drawn);
            left += b + H_GAP;
        }
    }
    let width = (left - H_GAP + 20.0).max(40.0);
    let height = layout.row_h.iter().map(|r| r + V_GAP).sum::<f64>() - V_GAP + 40.0;
    let height = height.max(40.0);

    let mut out = String::new();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" \
         viewBox=\"0 0 {width:.0} {height:.0}\" font-family=\"monospace\" font-size=\"12\">"
    );
    out.push_str("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    // Edges first, so boxes cover their ends.
    for e in tree.edges() {
        let (Some(p), Some(c)) = (
            layout.place[e.parent.index()],
            layout.place[e.child.index()],
        ) else {
            continue;
        };
        let on_path = tree
            .path
            .windows(2)
            .any(|w| w[0] == e.parent && w[1] == e.child);
        let (stroke, width) = if on_path {
            (PATH_STROKE, 2.5)
        } else {
            (OFF_STROKE, 1.0)
        };
        let _ = writeln!(
            out,
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"{stroke}\" \
             stroke-width=\"{width}\"/>",
            p.x,
            p.y + p.h,
            c.x,
            c.y
        );
    }
    for (i, n) in tree.nodes.iter().enumerate() {
        let id = NodeId(i as u32);
        let Some(p) = layout.place[i] else { continue };
        let on_path = tree.on_path(id);
        let (stroke, fill, width) = if on_path {
            (PATH_STROKE, PATH_FILL, 2.5)
        } else if n.children.is_empty() {
            (OFF_STROKE, LEAF_FILL, 1.0)
        } else {
            (OFF_STROKE, "white", 1.0)
        };
        let dash = if n.kind == Kind::Unsupported {
            " stroke-dasharray=\"4 3\""
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "<g><rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" rx=\"6\" \
             fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{width}\"{dash}/>",
            p.x - p.w / 2.0,
            p.y,
            p.w,
            p.h
        );
        for (k, line) in lines(tree, id).iter().enumerate() {
            let weight = if k == 0 { " font-weight=\"bold\"" } else { "" };
            let colour = if k == 0 { "black" } else { OFF_STROKE };
            let _ = writeln!(
                out,
                "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" fill=\"{colour}\"{weight}>{}</text>",
                p.x,
                p.y + PAD + 8.0 + k as f64 * LINE_H,
                xml_escape(line)
            );
        }
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
}
