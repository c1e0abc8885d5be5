//! `lucent demo`, the README's first command: with the simulator it generates its scene, writes
//! the camera view before and after as PNG files into the directory it names, prints the plan
//! and the plan in English, executes it in the physics world with replanning, and exits 0 when
//! the goal was reached; its run is deterministic. Bad arguments are exit 1. The run reports
//! (the demo's and `lucent run --report`'s) are rendered in headless Chromium.

use crate::support::cli as cli_support;

/// `lucent demo ARGS` (the binary).
fn demo(args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["demo"];
    all.extend_from_slice(args);
    cli_support::lucent_binary(&all, "")
}

#[cfg(feature = "sim")]
#[test]
fn the_demo_plans_acts_and_pictures_the_scene() {
    let dir = std::env::temp_dir().join(format!("lucent-demo-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (code, out, err) = demo(&["--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}\n{err}");
    for name in ["before.png", "after.png"] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        assert_eq!(&bytes[1..4], b"PNG", "{name}");
    }
    assert!(out.contains("plan "), "{out}");
    assert!(out.contains("In English: I will pick up the"), "{out}");
    assert!(out.contains("executed "), "{out}");
    assert!(out.contains("What I did: I picked up the"), "{out}");
    assert!(out.contains("Result: GOAL REACHED"), "{out}");
    // The robot explains its own run: the run is saved and three questions are answered, each
    // with a reason (seed 3's run moves the pot and the red cube, so every question has one).
    assert!(dir.join("run.json").exists());
    assert!(out.contains("Asked about my run:"), "{out}");
    let answers: Vec<&str> = out.lines().filter(|l| l.starts_with("  A: ")).collect();
    assert_eq!(answers.len(), 3, "{out}");
    assert!(
        answers.iter().all(|a| a.starts_with("  A: Because ")),
        "{out}"
    );
    // Deterministic: the same seed tells the same story (timings aside).
    let (_, again, _) = demo(&["--out", dir.to_str().unwrap()]);
    let story = |t: &str| -> Vec<String> {
        t.lines()
            .filter(|l| !l.starts_with("Time"))
            .map(String::from)
            .collect()
    };
    assert_eq!(story(&out), story(&again));
}

#[test]
fn bad_arguments_are_a_usage_error() {
    let (code, _, err) = demo(&["--frobnicate", "1"]);
    assert_eq!(code, 1, "{err}");
    let (code, out, _) = demo(&["--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("usage: lucent demo"));
}

/// The browser that renders the reports: Debian's `chromium` (scripts/test.sh installs it).
#[cfg(feature = "sim")]
fn browser() -> String {
    for name in ["chromium", "chromium-browser", "google-chrome"] {
        let found = std::process::Command::new(name)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success());
        if found {
            return name.to_string();
        }
    }
    panic!(
        "the report test renders HTML in headless Chromium, which is not installed: \
         `apt-get install -y chromium` (scripts/test.sh does it)"
    );
}

/// Runs the browser headless on a file with extra arguments, at most 120 s; its standard output.
#[cfg(feature = "sim")]
fn headless(
    browser: &str,
    profile: &std::path::Path,
    page: &std::path::Path,
    args: &[&str],
) -> String {
    use std::time::{Duration, Instant};
    let mut child = std::process::Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(format!("file://{}", page.display()))
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("the browser starts");
    let mut out = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut out, &mut s).ok();
        s
    });
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("the browser did not finish {} in 120 s", page.display());
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    reader.join().unwrap()
}

/// The reports of a run (`lucent run --report`) and of the demo, opened in headless Chromium:
/// every picture decodes (the page's own check, read from the rendered DOM), the screenshot is
/// not blank, and the page holds the plans, the steps and the answered questions with their
/// proof trees, with nothing fetched from the network.
#[cfg(feature = "sim")]
#[test]
fn run_and_demo_reports_render_in_a_headless_browser() {
    let browser = browser();
    let dir = std::env::temp_dir().join(format!("lucent-report-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let (code, out, err) = demo(&["--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}\n{err}");
    assert!(out.contains("report.html"), "{out}");
    let run_page = dir.join("run.html");
    // Seed 7 of the simulated preset replans after discrepancies.
    let (code, out, err) = cli_support::lucent_binary(
        &[
            "run",
            "--preset",
            "simulated",
            "--seed",
            "7",
            "--report",
            run_page.to_str().unwrap(),
        ],
        "",
    );
    assert_eq!(code, 0, "{out}\n{err}");
    for page in [dir.join("report.html"), run_page] {
        let html = std::fs::read_to_string(&page).unwrap();
        for fetch in [
            "src=\"http",
            "href=\"http",
            "src=\"//",
            "@import",
            "url(http",
        ] {
            assert!(!html.contains(fetch), "{}: fetches {fetch}", page.display());
        }
        for part in [
            "<h2>Plans</h2>",
            "What happened, step by step",
            "Questions about the run",
            "Q: Why did you",
            "<svg",
        ] {
            assert!(html.contains(part), "{}: no {part}", page.display());
        }
        let pictures = html.matches("<img ").count();
        // The scene before, and one picture after each action.
        assert!(pictures >= 3, "{}: {pictures} pictures", page.display());
        let profile = dir.join("profile");
        let dom = headless(&browser, &profile, &page, &["--dump-dom"]);
        assert!(
            dom.contains(&format!("All {pictures} pictures loaded.")),
            "{}: the page's picture check says {:?}",
            page.display(),
            dom.split_once("id=\"pictures\"")
                .map(|(_, r)| &r[..r.len().min(200)])
        );
        let shot = dir.join("shot.png");
        let _ = std::fs::remove_file(&shot);
        headless(
            &browser,
            &profile,
            &page,
            &[
                &format!("--screenshot={}", shot.display()),
                "--window-size=1000,1400",
            ],
        );
        let decoder =
            png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&shot).unwrap()));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        let channels = info.color_type.samples();
        let pixels = &buf[..info.buffer_size()];
        let mut colours = std::collections::HashSet::new();
        let mut inked = 0usize;
        for p in pixels.chunks(channels) {
            colours.insert((p[0], p[1], p[2]));
            if p[..3].iter().any(|&c| c < 200) {
                inked += 1;
            }
        }
        let total = pixels.len() / channels;
        // A blank page is one colour; the report's first screen has text and a camera picture.
        assert!(
            colours.len() > 100,
            "{}: {} colours",
            page.display(),
            colours.len()
        );
        assert!(
            inked * 20 > total,
            "{}: {inked} of {total} pixels inked",
            page.display()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
