//! The report's plots, drawn here as SVG text (the style of `explain::draw`): grouped bars
//! (ours beside the paper's), stacked bars (fractions of plans) and a scatter plot (time
//! against scene size).
//!
//! Invariants: output is a pure function of the data (no clock, no hash order), so the same
//! results draw the same bytes; all text is XML-escaped; sizes come from fixed advances, so no
//! font metrics are needed; a missing value is drawn as "n/a", never as a bar of height zero.
//! A value's 95% interval (`interval`), when given, is drawn as a black whisker over its bar;
//! in a stacked bar, a part's whisker spans the part's own interval from the part's bottom.

use std::fmt::Write;

use super::interval::Interval;

/// Series colours, in order (ours, the paper's, then more).
const COLOURS: [&str; 6] = [
    "#1565c0", "#9e9e9e", "#2e7d32", "#ef6c00", "#6a1b9a", "#c62828",
];
/// Width of one character of the font, in pixels.
const CHAR_W: f64 = 6.6;
/// Plot area height.
const PLOT_H: f64 = 220.0;
/// Margins: left (axis labels), top (title and legend), bottom (group labels).
const LEFT: f64 = 56.0;
const TOP: f64 = 56.0;
const BOTTOM: f64 = 48.0;

/// The width a title needs (13 px bold: about 8 px per character) with a margin.
fn title_width(title: &str) -> f64 {
    8.0 * title.chars().count() as f64 + 24.0
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Grouped bars: one group per label, one bar per series.
#[derive(Clone, Debug)]
pub struct Bars {
    /// The title.
    pub title: String,
    /// Series names (the legend).
    pub series: Vec<String>,
    /// Groups: label and one value per series (`None`: not available).
    pub groups: Vec<(String, Vec<Option<f64>>)>,
    /// 95% intervals, by group and series like `groups` (missing entries: no whisker).
    pub errors: Vec<Vec<Option<Interval>>>,
    /// The top of the value axis.
    pub y_max: f64,
}

/// A whisker at `x` from value `lo` to `hi` (offset by `base`), on a scale of `y_max`.
fn whisker(out: &mut String, x: f64, base: f64, i: Interval, y_max: f64) {
    let y = |v: f64| TOP + PLOT_H - PLOT_H * ((base + v) / y_max).clamp(0.0, 1.0);
    let (top, bottom) = (y(i.hi), y(i.lo));
    let _ = writeln!(
        out,
        "<path d=\"M{:.1} {top:.1}H{:.1}M{x:.1} {top:.1}V{bottom:.1}M{:.1} {bottom:.1}H{:.1}\" \
         stroke=\"black\" fill=\"none\"><title>95% interval: {} to {}</title></path>",
        x - 3.0,
        x + 3.0,
        x - 3.0,
        x + 3.0,
        tick((i.lo * 100.0).round() / 100.0),
        tick((i.hi * 100.0).round() / 100.0)
    );
}

fn header(out: &mut String, width: f64, height: f64, title: &str) {
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" \
         viewBox=\"0 0 {width:.0} {height:.0}\" font-family=\"monospace\" font-size=\"11\">"
    );
    let _ = writeln!(
        out,
        "<rect width=\"{width:.0}\" height=\"{height:.0}\" fill=\"white\"/>"
    );
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"18\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">{}</text>",
        width / 2.0,
        xml_escape(title)
    );
}

/// The legend: series `i` in `COLOURS[i + first]`, the colour its marks are drawn in.
fn legend(out: &mut String, names: &[String], first: usize) {
    let mut x = LEFT;
    for (i, name) in names.iter().enumerate() {
        let _ = writeln!(
            out,
            "<rect x=\"{x:.1}\" y=\"30\" width=\"10\" height=\"10\" fill=\"{}\"/>\
             <text x=\"{:.1}\" y=\"39\">{}</text>",
            COLOURS[(i + first) % COLOURS.len()],
            x + 14.0,
            xml_escape(name)
        );
        x += 14.0 + CHAR_W * name.len() as f64 + 18.0;
    }
}

/// The value axis with five ticks from 0 to `y_max`.
fn y_axis(out: &mut String, width: f64, y_max: f64) {
    for k in 0..=5 {
        let v = y_max * k as f64 / 5.0;
        let y = TOP + PLOT_H - PLOT_H * k as f64 / 5.0;
        let _ = writeln!(
            out,
            "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"#e0e0e0\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
            width - 10.0,
            LEFT - 4.0,
            y + 4.0,
            tick(v)
        );
    }
    let _ = writeln!(
        out,
        "<line x1=\"{LEFT}\" y1=\"{TOP}\" x2=\"{LEFT}\" y2=\"{:.1}\" stroke=\"black\"/>",
        TOP + PLOT_H
    );
}

fn tick(v: f64) -> String {
    if v == v.round() {
        format!("{v:.0}")
    } else {
        format!("{v:.2}")
    }
}

/// Draws grouped bars.
pub fn bar_chart(b: &Bars) -> String {
    let bar_w = 18.0;
    let group_w = bar_w * b.series.len().max(1) as f64 + 24.0;
    let label_w = b
        .groups
        .iter()
        .map(|(g, _)| CHAR_W * g.len() as f64 + 8.0)
        .fold(group_w, f64::max);
    let width = LEFT + label_w * b.groups.len() as f64 + 20.0;
    let width = width.max(title_width(&b.title));
    let height = TOP + PLOT_H + BOTTOM;
    let mut out = String::new();
    header(&mut out, width, height, &b.title);
    legend(&mut out, &b.series, 0);
    y_axis(&mut out, width, b.y_max);
    for (gi, (label, values)) in b.groups.iter().enumerate() {
        let gx = LEFT + label_w * gi as f64 + (label_w - bar_w * values.len() as f64) / 2.0;
        for (si, v) in values.iter().enumerate() {
            let x = gx + bar_w * si as f64;
            match v {
                Some(v) => {
                    let h = PLOT_H * (v / b.y_max).clamp(0.0, 1.0);
                    let _ = writeln!(
                        out,
                        "<rect x=\"{x:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{h:.1}\" fill=\"{}\">\
                         <title>{}: {}</title></rect>",
                        TOP + PLOT_H - h,
                        bar_w - 2.0,
                        COLOURS[si % COLOURS.len()],
                        xml_escape(&b.series.get(si).cloned().unwrap_or_default()),
                        tick((v * 100.0).round() / 100.0)
                    );
                    let error = b.errors.get(gi).and_then(|e| e.get(si)).copied().flatten();
                    if let Some(i) = error {
                        whisker(&mut out, x + (bar_w - 2.0) / 2.0, 0.0, i, b.y_max);
                    }
                }
                None => {
                    let _ = writeln!(
                        out,
                        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"9\" \
                         transform=\"rotate(-90 {:.1} {:.1})\">n/a</text>",
                        x + bar_w / 2.0,
                        TOP + PLOT_H - 4.0,
                        x + bar_w / 2.0,
                        TOP + PLOT_H - 4.0
                    );
                }
            }
        }
        let _ = writeln!(
            out,
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
            LEFT + label_w * gi as f64 + label_w / 2.0,
            TOP + PLOT_H + 16.0,
            xml_escape(label)
        );
    }
    out.push_str("</svg>\n");
    out
}

/// One part of a stacked bar: its value and 95% interval.
pub type Part = (f64, Option<Interval>);

/// Stacked bars: each bar's parts add up to at most `y_max` (fractions of plans: 1).
#[derive(Clone, Debug)]
pub struct Stacks {
    /// The title.
    pub title: String,
    /// Part names (the legend), bottom to top.
    pub parts: Vec<String>,
    /// Bars: label and one value per part with its 95% interval (`None`: the bar is not
    /// available).
    pub bars: Vec<(String, Option<Vec<Part>>)>,
    /// The top of the value axis.
    pub y_max: f64,
}

/// The colour index of a stacked chart's first part.
const STACK_COLOUR: usize = 2;

/// Draws stacked bars.
pub fn stacked_chart(s: &Stacks) -> String {
    let label_w = s
        .bars
        .iter()
        .map(|(g, _)| CHAR_W * g.len() as f64 + 10.0)
        .fold(48.0, f64::max);
    let width = (LEFT + label_w * s.bars.len() as f64 + 20.0).max(title_width(&s.title));
    let height = TOP + PLOT_H + BOTTOM;
    let mut out = String::new();
    header(&mut out, width, height, &s.title);
    // Stacks start at the third colour (the first two are the bar charts' with/without).
    legend(&mut out, &s.parts, STACK_COLOUR);
    y_axis(&mut out, width, s.y_max);
    for (bi, (label, parts)) in s.bars.iter().enumerate() {
        let x = LEFT + label_w * bi as f64 + (label_w - 28.0) / 2.0;
        match parts {
            Some(parts) => {
                let mut base = TOP + PLOT_H;
                let mut below = 0.0;
                let mut whiskers = Vec::new();
                for (pi, &(v, error)) in parts.iter().enumerate() {
                    let h = PLOT_H * (v / s.y_max).clamp(0.0, 1.0);
                    base -= h;
                    if let Some(i) = error {
                        whiskers.push((pi, below, i));
                    }
                    below += v;
                    let _ = writeln!(
                        out,
                        "<rect x=\"{x:.1}\" y=\"{base:.1}\" width=\"28\" height=\"{h:.1}\" fill=\"{}\">\
                         <title>{}: {}</title></rect>",
                        COLOURS[(pi + STACK_COLOUR) % COLOURS.len()],
                        xml_escape(&s.parts.get(pi).cloned().unwrap_or_default()),
                        tick((v * 100.0).round() / 100.0)
                    );
                }
                // Whiskers after the segments, so none is painted over; side by side.
                for (pi, below, i) in whiskers {
                    let wx = x + 6.0 + 8.0 * pi as f64;
                    whisker(&mut out, wx, below, i, s.y_max);
                }
            }
            None => {
                let _ = writeln!(
                    out,
                    "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">n/a</text>",
                    x + 14.0,
                    TOP + PLOT_H - 6.0
                );
            }
        }
        let _ = writeln!(
            out,
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
            x + 14.0,
            TOP + PLOT_H + 16.0,
            xml_escape(label)
        );
    }
    out.push_str("</svg>\n");
    out
}

/// A scatter plot of named point series.
#[derive(Clone, Debug)]
pub struct Scatter {
    /// The title.
    pub title: String,
    /// The x axis' name.
    pub x_label: String,
    /// The y axis' name.
    pub y_label: String,
    /// Series: name and points.
    pub series: Vec<(String, Vec<(f64, f64)>)>,
}

/// Draws a scatter plot; both axes start at 0 and end at the largest value (at least 1).
pub fn scatter(s: &Scatter) -> String {
    let plot_w = 360.0;
    let width = (LEFT + plot_w + 30.0).max(title_width(&s.title));
    let height = TOP + PLOT_H + BOTTOM;
    let points = s.series.iter().flat_map(|(_, p)| p.iter());
    let (mut x_max, mut y_max) = (1.0f64, 0.0f64);
    for &(x, y) in points {
        x_max = x_max.max(x);
        y_max = y_max.max(y);
    }
    let y_max = if y_max > 0.0 { y_max * 1.1 } else { 1.0 };
    let x_max = x_max.ceil() + 1.0;
    let mut out = String::new();
    header(&mut out, width, height, &s.title);
    let names: Vec<String> = s.series.iter().map(|(n, _)| n.clone()).collect();
    legend(&mut out, &names, 0);
    y_axis(&mut out, width, y_max);
    let _ = writeln!(
        out,
        "<line x1=\"{LEFT}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"black\"/>",
        TOP + PLOT_H,
        LEFT + plot_w,
        TOP + PLOT_H
    );
    for k in 0..=(x_max as usize) {
        let x = LEFT + plot_w * k as f64 / x_max;
        let _ = writeln!(
            out,
            "<text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{k}</text>",
            TOP + PLOT_H + 14.0
        );
    }
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\
         <text x=\"12\" y=\"{:.1}\" text-anchor=\"middle\" transform=\"rotate(-90 12 {:.1})\">{}</text>",
        LEFT + plot_w / 2.0,
        TOP + PLOT_H + 34.0,
        xml_escape(&s.x_label),
        TOP + PLOT_H / 2.0,
        TOP + PLOT_H / 2.0,
        xml_escape(&s.y_label)
    );
    for (si, (_, pts)) in s.series.iter().enumerate() {
        // Series side by side within an x unit, so equal sizes do not hide each other.
        let shift = (si as f64 - (s.series.len() as f64 - 1.0) / 2.0) * 0.12;
        for &(x, y) in pts {
            let _ = writeln!(
                out,
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3\" fill=\"{}\" fill-opacity=\"0.6\"/>",
                LEFT + plot_w * (x + shift) / x_max,
                TOP + PLOT_H - PLOT_H * (y / y_max),
                COLOURS[si % COLOURS.len()]
            );
        }
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bars_escape_text_scale_values_and_mark_missing_ones() {
        let svg = bar_chart(&Bars {
            title: "a < b".into(),
            series: vec!["ours".into(), "paper".into()],
            groups: vec![("P".into(), vec![Some(50.0), None])],
            errors: vec![vec![Some(Interval { lo: 40.0, hi: 60.0 })]],
            y_max: 100.0,
        });
        assert!(svg.contains("a &lt; b"));
        assert!(svg.contains(&format!("height=\"{:.1}\"", PLOT_H / 2.0)));
        assert!(svg.contains(">n/a<"));
        // The whisker runs from 60 (y = TOP + 0.4 PLOT_H) down to 40 (TOP + 0.6 PLOT_H).
        let (top, bottom) = (TOP + 0.4 * PLOT_H, TOP + 0.6 * PLOT_H);
        assert!(
            svg.contains(&format!("V{bottom:.1}")) && svg.contains(&format!(" {top:.1}H")),
            "{svg}"
        );
        assert!(svg.contains("95% interval: 40 to 60"), "{svg}");
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
    }

    #[test]
    fn stacks_put_parts_on_top_of_each_other() {
        let svg = stacked_chart(&Stacks {
            title: "t".into(),
            parts: vec!["a".into(), "b".into()],
            bars: vec![(
                "x".into(),
                Some(vec![
                    (0.5, None),
                    (0.25, Some(Interval { lo: 0.2, hi: 0.3 })),
                ]),
            )],
            y_max: 1.0,
        });
        let y_a = TOP + PLOT_H - PLOT_H * 0.5;
        let y_b = y_a - PLOT_H * 0.25;
        assert!(svg.contains(&format!("y=\"{y_a:.1}\"")), "{svg}");
        // b's whisker spans 0.5 + [0.2, 0.3]; a has none.
        assert_eq!(svg.matches("95% interval").count(), 1, "{svg}");
        let (top, bottom) = (TOP + PLOT_H * 0.2, TOP + PLOT_H * 0.3);
        assert!(svg.contains(&format!("V{bottom:.1}")), "{svg}");
        assert!(svg.contains(&format!(" {top:.1}H")), "{svg}");
        assert!(svg.contains(&format!("y=\"{y_b:.1}\"")), "{svg}");
        // Each part's legend swatch has the colour of its bar segment.
        for (i, part) in ["a", "b"].iter().enumerate() {
            let colour = COLOURS[(i + STACK_COLOUR) % COLOURS.len()];
            let swatch = format!("fill=\"{colour}\"/><text x=");
            let segment = format!("fill=\"{colour}\"><title>{part}:");
            assert!(
                svg.contains(&swatch) && svg.contains(&segment),
                "{part}: {svg}"
            );
        }
    }
}
