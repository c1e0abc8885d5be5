//! Progress bars for long jobs (experiments, learning, data generation), drawn with indicatif
//! on standard error.
//!
//! Invariants: a bar is drawn only when standard error is a terminal (indicatif hides it
//! otherwise, so logs and pipes get no control characters); its handle is `Send + Sync`, so
//! rayon workers may advance it; drawing never takes a lock the caller holds (the command
//! line does not lock the standard streams for the whole run, see `cli::main`).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar of `total` units named `unit` ("trials", "runs"): `[####----] 12/40 trials (3 reused)
/// 00:42`, redrawn at most 10 times a second.
pub fn bar(total: u64, unit: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr_with_hz(10));
    let template = format!("[{{bar:30}}] {{pos}}/{{len}} {unit} {{msg}} {{elapsed}}");
    if let Ok(style) = ProgressStyle::with_template(&template) {
        bar.set_style(style.progress_chars("#>-"));
    }
    bar
}
