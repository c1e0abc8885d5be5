//! The HTML report of a run (`lucent run --report FILE.html`, and the demo's `report.html`): one
//! self-contained page a person opens in a browser to see what the robot did and why.
//!
//! The page holds, in order: the goal and the outcome; the camera picture before the first
//! action; every plan in English with the reason it was made (the first, or the discrepancy or
//! failure that forced a replan); each step with the action in English, what went wrong if it
//! failed, the discrepancies seen after it, and the camera picture after it; and a few questions
//! the robot answers about its own run ([`own_questions`]), each with its proof tree drawn as
//! SVG, the answer's path in green.
//!
//! Pictures are filmed while the loop runs: [`Filming`] wraps the acting world and renders the
//! framed, labelled camera view ([`fn@crate::sim::picture`]) after every executed action.
//!
//! Invariants: the page needs no network and no other file (pictures are PNG `data:` URIs,
//! proof trees inline SVG); every text from the run is HTML-escaped; a small script at the end
//! only checks that every picture decoded and says so in the page (`#pictures`), which the
//! headless-browser test reads.

use crate::control::Symbol;
use crate::explain::draw;
use crate::explain::pattern::SymbolExt;
use crate::explain::questions::Answer;
use crate::explain::verbalize::{ActionForm, Tense, Verbalizer};
use crate::plan::act::{self, Percept};
use crate::plan::history::History;
use crate::plan::tabletop::SimWorld;
use crate::sim::{self, Scene};
use crate::vision::see::Seeing;

/// Width and height of the pictures in the report.
const PICTURE: (u32, u32) = (480, 360);

/// A world whose scene can be pictured.
pub trait Pictured {
    /// The scene as it is now.
    fn scene(&self) -> &Scene;
}

impl Pictured for SimWorld {
    fn scene(&self) -> &Scene {
        &self.scene
    }
}

impl Pictured for Seeing {
    fn scene(&self) -> &Scene {
        &self.inner.scene
    }
}

/// One picture of the run: the scene at the start of `step`.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The step the scene is at (0 before the first action).
    pub step: u32,
    /// The PNG bytes.
    pub png: Vec<u8>,
    /// The object in the robot's hand (not in the picture).
    pub held: Option<String>,
}

/// Films a world: a picture at the start and after every executed action.
pub struct Filming<'w, W> {
    /// The world acted in.
    pub world: &'w mut W,
    /// The pictures taken, in order.
    pub frames: Vec<Frame>,
    /// The first error of the PNG encoder, if any (the run goes on without that picture).
    pub error: Option<String>,
}

impl<'w, W: Pictured> Filming<'w, W> {
    /// Starts filming `world`: takes the first picture.
    pub fn new(world: &'w mut W) -> Self {
        let mut f = Filming {
            world,
            frames: Vec::new(),
            error: None,
        };
        f.shoot();
        f
    }

    fn shoot(&mut self) {
        let scene = self.world.scene();
        match sim::picture(scene, PICTURE.0, PICTURE.1).image.to_png() {
            Ok(png) => self.frames.push(Frame {
                step: scene.step,
                png,
                held: scene.in_hand.clone(),
            }),
            Err(e) => {
                self.error.get_or_insert(e.to_string());
            }
        }
    }
}

impl<W: act::World + Pictured> act::World for Filming<'_, W> {
    fn objects(&self) -> Vec<String> {
        self.world.objects()
    }

    fn perceive(&mut self, look: u32) -> Percept {
        self.world.perceive(look)
    }

    fn execute(&mut self, action: &Symbol) -> Result<Option<String>, String> {
        let done = self.world.execute(action);
        if done.is_ok() {
            self.shoot();
        }
        done
    }

    fn holds_in_truth(&mut self, literal: &Symbol) -> Option<bool> {
        self.world.holds_in_truth(literal)
    }
}

/// The questions a run is asked about itself (`done`: its successful actions with their steps):
/// describe the plan; why its first successful action; why not pick up an object it never
/// touched at that step; why it believed the first `on` goal at the end.
pub fn own_questions(
    history: &History,
    done: &[(u32, Symbol)],
    goal: &[Symbol],
    v: &Verbalizer<'_>,
) -> Vec<String> {
    let mut qs = vec!["Describe the plan.".to_string()];
    if let Some((i, a)) = done.first() {
        qs.push(format!(
            "Why did you {} at step {i}?",
            v.action(a, ActionForm::Base)
        ));
        let touched: Vec<&Symbol> = done.iter().filter_map(|(_, a)| a.arg(1)).collect();
        let untouched = history
            .objects
            .iter()
            .filter_map(|o| Symbol::parse(o).ok())
            .find(|o| !touched.contains(&o) && o.name() != Some("table"));
        if let Some(o) = untouched {
            qs.push(format!(
                "Why didn't you pick up {} at step {i}?",
                v.object(&o)
            ));
        }
    }
    if let Some(g) = goal
        .iter()
        .find(|g| g.is("relation", 3) && g.arg(0).and_then(Symbol::name) == Some("on"))
    {
        qs.push(format!(
            "Why did you believe that {} at the end?",
            v.fluent(g, Tense::Past)
        ));
    }
    qs
}

/// The successful actions of a run with their steps.
pub fn done_actions(history: &History) -> Vec<(u32, Symbol)> {
    history
        .steps
        .iter()
        .filter(|s| s.failure.is_none())
        .filter_map(|s| Some((s.step, Symbol::parse(s.happened.as_deref()?).ok()?)))
        .collect()
}

/// Everything the page shows besides the history.
pub struct Report<'a> {
    /// The page's title line.
    pub title: String,
    /// The run.
    pub history: &'a History,
    /// The pictures filmed.
    pub frames: &'a [Frame],
    /// The questions asked about the run with their answers.
    pub answers: &'a [(String, Answer)],
    /// Why the questions could not be asked, if they could not.
    pub unanswered: Option<String>,
    /// Says literals and actions in English.
    pub v: Verbalizer<'a>,
}

/// Escapes text for HTML content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Standard base64 with padding (RFC 4648), for `data:` URIs.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

const STYLE: &str = "\
body{font-family:system-ui,sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
figure{display:inline-block;margin:.5em 1em .5em 0}figcaption{font-size:.9em;color:#555}
img{border:1px solid #999;max-width:100%}
.step{border-left:4px solid #2e7d32;padding:.3em .8em;margin:1em 0}
.step.failed{border-color:#c62828}.failed .what{color:#c62828}
.plan{background:#f5f5f5;padding:.5em .8em;margin:.8em 0}
.code{font-family:monospace;font-size:.85em;color:#555}
.qa{margin:1em 0}.q{font-weight:bold}.tree svg{max-width:100%;height:auto}.tree{overflow-x:auto;border:1px solid #ddd;margin:.5em 0}
.ok{color:#2e7d32}.bad{color:#c62828}
";

/// The script that checks the pictures: every `<img>` must have decoded.
const CHECK: &str = "\
window.addEventListener('load',function(){var imgs=document.images,bad=[];
for(var i=0;i<imgs.length;i++){if(!imgs[i].complete||imgs[i].naturalWidth===0){bad.push(imgs[i].alt);}}
var p=document.getElementById('pictures');
p.textContent=bad.length===0?'All '+imgs.length+' pictures loaded.':'Pictures that did not load: '+bad.join('; ');
p.className=bad.length===0?'ok':'bad';});";

impl Report<'_> {
    fn say(&self, text: &str, tense: Tense) -> String {
        Symbol::parse(text).map_or_else(|_| text.to_string(), |t| self.v.fluent(&t, tense))
    }

    fn action(&self, text: &str, form: ActionForm) -> String {
        Symbol::parse(text).map_or_else(|_| text.to_string(), |t| self.v.action(&t, form))
    }

    fn picture(&self, html: &mut String, step: u32, caption: &str) {
        let Some(f) = self.frames.iter().rev().find(|f| f.step == step) else {
            return;
        };
        let caption = match &f.held {
            Some(o) => format!(
                "{caption} (in my hand: {})",
                Symbol::parse(o).map_or_else(|_| o.clone(), |t| self.v.object(&t))
            ),
            None => caption.to_string(),
        };
        html.push_str(&format!(
            "<figure><img src=\"data:image/png;base64,{}\" width=\"{}\" height=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n",
            base64(&f.png),
            PICTURE.0,
            PICTURE.1,
            escape(&caption),
            escape(&caption)
        ));
    }

    /// The page.
    pub fn html(&self) -> String {
        let h = self.history;
        let mut html = String::new();
        html.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n");
        html.push_str(&format!("<title>{}</title>\n", escape(&self.title)));
        html.push_str(&format!("<style>\n{STYLE}</style></head><body>\n"));
        html.push_str(&format!("<h1>{}</h1>\n", escape(&self.title)));
        let goal: Vec<String> = h.goal.iter().map(|g| self.say(g, Tense::Future)).collect();
        html.push_str(&format!(
            "<p><b>Goal:</b> {} <span class=\"code\">{}</span></p>\n",
            escape(&goal.join("; ")),
            escape(&h.goal.join(", "))
        ));
        let ending = h
            .ending
            .as_ref()
            .map_or("the run is unfinished".to_string(), |e| e.to_string());
        let truth = match h.goal_in_truth {
            Some(true) => "the goal holds in the world",
            Some(false) => "the goal does not hold in the world",
            None => "the world cannot check the goal",
        };
        let failed = h.steps.iter().filter(|s| s.failure.is_some()).count();
        html.push_str(&format!(
            "<p><b>Outcome:</b> <span class=\"{}\">{}</span>: {}; {}. {} action{} executed ({} failed), {} plan{} ({} replan{}), {} discrepanc{}.</p>\n",
            if h.succeeded() { "ok" } else { "bad" },
            if h.succeeded() { "goal reached" } else { "goal not reached" },
            escape(&ending),
            truth,
            h.actions().len(),
            if h.actions().len() == 1 { "" } else { "s" },
            failed,
            h.plans.len(),
            if h.plans.len() == 1 { "" } else { "s" },
            h.replans(),
            if h.replans() == 1 { "" } else { "s" },
            h.discrepancies.len(),
            if h.discrepancies.len() == 1 { "y" } else { "ies" },
        ));
        html.push_str("<p id=\"pictures\">Checking the pictures...</p>\n");

        html.push_str("<h2>The scene before</h2>\n");
        self.picture(
            &mut html,
            0,
            "The camera view at step 0, before the first action",
        );

        html.push_str("<h2>Plans</h2>\n");
        for (k, p) in h.plans.iter().enumerate() {
            let steps: Vec<(u32, Symbol)> = p
                .actions
                .iter()
                .enumerate()
                .filter_map(|(i, a)| Some((p.step + i as u32, Symbol::parse(a).ok()?)))
                .collect();
            let words = if steps.is_empty() {
                "Nothing left to do.".to_string()
            } else {
                self.v.plan(&steps, false)
            };
            html.push_str(&format!(
                "<div class=\"plan\"><b>{} at step {}</b> ({}; {} action{}{}):<br>{}<br><span class=\"code\">{}</span></div>\n",
                if k == 0 { "Plan" } else { "Replan" },
                p.step,
                escape(&p.reason),
                p.actions.len(),
                if p.actions.len() == 1 { "" } else { "s" },
                if p.alternatives > 1 {
                    format!(", one of {} minimal plans", p.alternatives)
                } else {
                    String::new()
                },
                escape(&words),
                escape(&p.actions.join("; "))
            ));
        }

        html.push_str("<h2>What happened, step by step</h2>\n");
        for s in &h.steps {
            let Some(a) = &s.happened else { continue };
            let class = if s.failure.is_some() {
                "step failed"
            } else {
                "step"
            };
            html.push_str(&format!("<div class=\"{class}\">\n"));
            let what = match &s.failure {
                None => format!("Step {}: I {}.", s.step, self.action(a, ActionForm::Past)),
                Some(f) => format!(
                    "Step {}: I tried to {}, but {f}.",
                    s.step,
                    self.action(a, ActionForm::Base)
                ),
            };
            html.push_str(&format!(
                "<p class=\"what\">{} <span class=\"code\">{}</span></p>\n",
                escape(&what),
                escape(a)
            ));
            if !s.doubted.is_empty() {
                let d: Vec<String> = s.doubted.iter().map(|l| self.say(l, Tense::Past)).collect();
                html.push_str(&format!(
                    "<p>Before acting I doubted what I saw: {}.</p>\n",
                    escape(&d.join("; "))
                ));
            }
            for d in h.discrepancies.iter().filter(|d| d.step == s.step) {
                let mut parts = Vec::new();
                if !d.unexpected.is_empty() {
                    let u: Vec<String> = d
                        .unexpected
                        .iter()
                        .map(|l| self.say(l, Tense::Past))
                        .collect();
                    parts.push(format!("I saw what I had not expected: {}", u.join("; ")));
                }
                if !d.extra.is_empty() {
                    let e: Vec<String> = d.extra.iter().map(|l| self.say(l, Tense::Past)).collect();
                    parts.push(format!(
                        "I did not see what I had expected: {}",
                        e.join("; ")
                    ));
                }
                if d.predicted.is_none() {
                    parts.push("my knowledge said the action could not be done".to_string());
                }
                if !parts.is_empty() {
                    html.push_str(&format!(
                        "<p>Discrepancy after the action: {}. So I replanned.</p>\n",
                        escape(&parts.join(". "))
                    ));
                }
            }
            self.picture(
                &mut html,
                s.step + 1,
                &format!("The camera view after step {}", s.step),
            );
            html.push_str("</div>\n");
        }

        html.push_str("<h2>Questions about the run</h2>\n");
        if let Some(why) = &self.unanswered {
            html.push_str(&format!(
                "<p class=\"bad\">I could not explain my run: {}</p>\n",
                escape(why)
            ));
        }
        for (q, a) in self.answers {
            html.push_str(&format!(
                "<div class=\"qa\"><p class=\"q\">Q: {}</p><p>A: {}</p>\n",
                escape(q),
                escape(&a.text)
            ));
            if let Some(tree) = &a.tree {
                let whole = draw::svg(tree);
                // A tree wider than the page is cut down to the answer's path.
                let (svg, what) = if svg_width(&whole) > MAX_TREE_WIDTH {
                    let cut = tree.around_path();
                    (
                        draw::svg(&cut),
                        format!(
                            "The answer's path in its proof tree, with what each step rests on \
                             ({} of its {} nodes; `lucent ask --svg` draws it whole)",
                            cut.nodes.len(),
                            tree.nodes.len()
                        ),
                    )
                } else {
                    (
                        whole,
                        "The proof tree of this answer (its path in green)".to_string(),
                    )
                };
                html.push_str(&format!(
                    "<details open><summary>{}</summary><div class=\"tree\">{}</div></details>\n",
                    escape(&what),
                    strip_prolog(&svg)
                ));
            }
            html.push_str("</div>\n");
        }
        html.push_str(&format!("<script>{CHECK}</script>\n</body></html>\n"));
        html
    }
}

/// The widest proof tree drawn whole, in pixels.
const MAX_TREE_WIDTH: f64 = 1400.0;

/// The `width` attribute of an SVG document (0 when it has none).
fn svg_width(svg: &str) -> f64 {
    svg.split_once(" width=\"")
        .and_then(|(_, rest)| rest.split_once('"'))
        .and_then(|(w, _)| w.parse().ok())
        .unwrap_or(0.0)
}

/// An SVG document without its XML declaration, to be inlined in HTML.
fn strip_prolog(svg: &str) -> &str {
    match svg.strip_prefix("<?xml") {
        Some(rest) => rest.find("?>").map_or(svg, |i| rest[i + 2..].trim_start()),
        None => svg,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_follows_the_rfc_test_vectors() {
        // RFC 4648, section 10.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn text_is_escaped_and_svg_loses_its_prolog() {
        assert_eq!(escape("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
        assert_eq!(
            strip_prolog("<?xml version=\"1.0\"?>\n<svg></svg>"),
            "<svg></svg>"
        );
        assert_eq!(strip_prolog("<svg/>"), "<svg/>");
        assert_eq!(
            svg_width("<svg x=\"1\" width=\"7450\" height=\"3\">"),
            7450.0
        );
        assert_eq!(svg_width("<svg>"), 0.0);
    }
}
