//! `lucent sim`: the subcommands end to end on files in a temporary directory.

use lucent::cli::sim::run_with;
use std::path::PathBuf;

/// Runs the subcommand; returns (exit code, stdout, stderr).
fn sim(line: &str) -> (i32, String, String) {
    let args: Vec<String> = shell_words(line);
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = run_with(&args, &mut out, &mut err);
    (
        code,
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
    )
}

/// Splits on spaces, keeping single-quoted words together.
fn shell_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    for (i, part) in line.split('\'').enumerate() {
        if i % 2 == 1 {
            words.push(part.to_string());
        } else {
            words.extend(part.split_whitespace().map(String::from));
        }
    }
    words
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lucent_sim_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn generate_observe_act_render() {
    let scene = temp("scene.json");
    let s = scene.display();
    let (code, out, err) = sim(&format!("generate --seed 7 --preset h1 -o {s}"));
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("8 objects"));
    let (code, out, _) = sim(&format!("observe {s}"));
    assert_eq!(code, 0);
    assert!(out.contains("obs(relation(on,"), "{out}");
    assert!(out.contains("has_size(red_cube_large,large)."));
    let (code, out, _) = sim(&format!("observe {s} --holds --error-rate 0"));
    assert_eq!(code, 0);
    assert!(out.contains("holds(relation(on,"));
    let (code, out, _) = sim(&format!("truth {s}"));
    assert_eq!(code, 0);
    assert!(out.contains("stable") && out.contains("hidden"));
    let (code, out, err) = sim(&format!(
        "act {s} 'pickup(rob1, yellow_duck)' --failure-rate 0"
    ));
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("hpd(pickup(rob1,yellow_duck),0)."), "{out}");
    assert!(out.contains(",1)."), "observations are of the next step");
    let saved = std::fs::read_to_string(&scene).unwrap();
    assert!(saved.contains("\"in_hand\": \"yellow_duck\""));
    let png = temp("scene.png");
    let (code, _, err) = sim(&format!("render {s} -o {}", png.display()));
    assert_eq!(code, 0, "{err}");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let (code, _, _) = sim(&format!(
        "render {s} --top --width 64 --height 48 -o {}",
        png.display()
    ));
    assert_eq!(code, 0);
    let (code, _, _) = sim(&format!("step {s} --seconds 0.5"));
    assert_eq!(code, 0);
}

#[test]
fn a_failed_action_is_an_observation_not_an_error() {
    let scene = temp("failing.json");
    let s = scene.display();
    assert_eq!(sim(&format!("generate --seed 3 --preset real -o {s}")).0, 0);
    let (code, out, err) = sim(&format!(
        "act {s} 'putdown(rob1,{},table)'",
        first_object(&scene)
    ));
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("failed: the object is not in the hand"),
        "{out}"
    );
}

fn first_object(scene: &PathBuf) -> String {
    let text = std::fs::read_to_string(scene).unwrap();
    lucent::sim::Scene::from_json(&text).unwrap().objects[0]
        .name
        .clone()
}

#[test]
fn bad_input_gets_a_clear_error_and_exit_code() {
    let bad = temp("bad.json");
    std::fs::write(&bad, "{\"objects\": [").unwrap();
    let (code, _, err) = sim(&format!("observe {}", bad.display()));
    assert_eq!(code, 65);
    assert!(err.contains("malformed scene"), "{err}");
    let (code, _, err) = sim("observe /nonexistent/scene.json");
    assert_eq!(code, 65);
    assert!(err.contains("cannot read"));
    let scene = temp("ok.json");
    assert_eq!(
        sim(&format!("generate --seed 1 -o {}", scene.display())).0,
        0
    );
    let (code, _, err) = sim(&format!("act {} 'pickup(rob1,unicorn)'", scene.display()));
    assert_eq!(code, 65);
    assert!(err.contains("unknown object `unicorn`"));
    let (code, _, err) = sim(&format!("act {} 'fly(rob1)'", scene.display()));
    assert_eq!(code, 65);
    assert!(err.contains("malformed action"));
    assert_eq!(sim("generate --preset kitchen").0, 65);
    assert_eq!(sim("generate --seed x").0, 1);
    assert_eq!(sim("observe").0, 1);
    assert_eq!(sim("frobnicate").0, 1);
    assert_eq!(sim(&format!("observe {} --top", scene.display())).0, 1);
    assert_eq!(
        sim(&format!("observe {} --error-rate 2", scene.display())).0,
        1
    );
}

#[test]
fn help_lists_every_command() {
    let (code, out, _) = sim("--help");
    assert_eq!(code, 0);
    for command in [
        "generate", "observe", "truth", "act", "step", "render", "--preset", "--holds",
    ] {
        assert!(out.contains(command), "{command}");
    }
}
