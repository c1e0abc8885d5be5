//! Malformed aspif gives an error with a position, never a panic. Each case names the error it
//! must produce and where (line, column).

use lucent::ground::aspif::{self, AspifErrorKind};

fn err(text: impl AsRef<[u8]>) -> aspif::AspifError {
    let text = text.as_ref();
    match aspif::read(text) {
        Ok(a) => panic!(
            "accepted malformed input {:?}: {a:?}",
            String::from_utf8_lossy(text)
        ),
        Err(e) => e,
    }
}

#[test]
fn truncated_inputs() {
    for text in [
        "",
        "asp 1 0 0\n",
        "asp 1 0 0\n1 0 1",
        "asp 1 0 0\n1 0 1 1 0 2 3",
        "asp 1 0 0\n4 10 abc",
        "asp 1 0 0\n2 0 2 1 1 2",
        "asp 1 0 0\n1 0 1 1 0 0\n",
    ] {
        let e = err(text);
        let ok = matches!(
            e.kind,
            AspifErrorKind::UnexpectedEof { .. } | AspifErrorKind::BadHeader(_)
        );
        assert!(ok, "{text:?}: {e}");
    }
    let e = err("asp 1 0 0\n1 0 1 1 0 2 3\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::Expected { .. }), "{e}");
    assert_eq!((e.line, e.column), (2, 14));
}

#[test]
fn bad_numbers() {
    let e = err("asp 1 0 0\n1 0 1 1x 0 0\n0\n");
    assert_eq!((e.line, e.column), (2, 7));
    assert!(
        matches!(
            e.kind,
            AspifErrorKind::Expected {
                expected: "atom",
                ..
            }
        ),
        "{e}"
    );
    let e = err("asp 1 0 0\n1 0 1 - 0 0\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::Expected { .. }), "{e}");
    let e = err("asp 1 0 0\n1 0 1 -3 0 0\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::OutOfRange { what: "atom", .. }),
        "{e}"
    );
    let e = err("asp 1 0 0\n1 0 0 1 2 1 1 -1\n0\n");
    assert_eq!(e.kind, AspifErrorKind::NegativeWeight(-1));
    assert_eq!((e.line, e.column), (2, 15));
}

#[test]
fn huge_numbers() {
    // Atoms beyond 2^31 - 1, literals beyond i32, weights beyond i64 and counts that promise
    // more items than the input holds are errors, not allocations or overflows.
    let e = err("asp 1 0 0\n1 0 1 2147483648 0 0\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::OutOfRange { what: "atom", .. }),
        "{e}"
    );
    let e = err("asp 1 0 0\n1 0 0 0 1 -2147483648\n0\n");
    assert!(
        matches!(
            e.kind,
            AspifErrorKind::OutOfRange {
                what: "literal",
                ..
            }
        ),
        "{e}"
    );
    let e = err("asp 1 0 0\n2 0 1 1 99999999999999999999999999999999\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::OutOfRange { what: "weight", .. }),
        "{e}"
    );
    let e = err("asp 1 0 0\n1 0 4294967295 1\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::Expected { .. }), "{e}");
    let e = err("asp 1 0 0\n4 18446744073709551615 a 0\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::OutOfRange { .. }), "{e}");
    let e = err("asp 1 0 0\n4 4294967295 a 0\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::UnexpectedEof { .. }),
        "{e}"
    );
}

#[test]
fn unknown_statements_and_values() {
    let e = err("asp 1 0 0\n11 1 2\n0\n");
    assert_eq!(e.kind, AspifErrorKind::UnknownStatement(11));
    assert_eq!((e.line, e.column), (2, 1));
    let e = err("asp 1 0 0\n1 2 0 0 0\n0\n");
    assert!(
        matches!(
            e.kind,
            AspifErrorKind::BadValue {
                what: "head type",
                found: 2,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!((e.line, e.column), (2, 3));
    let e = err("asp 1 0 0\n1 0 0 2 0\n0\n");
    assert!(
        matches!(
            e.kind,
            AspifErrorKind::BadValue {
                what: "body type",
                ..
            }
        ),
        "{e}"
    );
    let e = err("asp 1 0 0\n5 1 4\n0\n");
    assert!(
        matches!(
            e.kind,
            AspifErrorKind::BadValue {
                what: "external value",
                ..
            }
        ),
        "{e}"
    );
    let e = err("asp 1 0 0\n7 6 1 0 0 0\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::BadValue { .. }), "{e}");
}

#[test]
fn atom_zero() {
    let e = err("asp 1 0 0\n1 0 1 0 0 0\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::OutOfRange { what: "atom", .. }),
        "{e}"
    );
    assert_eq!((e.line, e.column), (2, 7));
    let e = err("asp 1 0 0\n1 0 1 1 0 1 0\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::OutOfRange { .. }), "{e}");
    let e = err("asp 1 0 0\n5 0 0\n0\n");
    assert!(
        matches!(e.kind, AspifErrorKind::OutOfRange { what: "atom", .. }),
        "{e}"
    );
}

#[test]
fn headers_and_structure() {
    assert!(matches!(
        err("clasp 1 0 0\n0\n").kind,
        AspifErrorKind::BadHeader(_)
    ));
    assert!(matches!(
        err("asp 2 0 0\n0\n").kind,
        AspifErrorKind::BadHeader(_)
    ));
    assert!(matches!(
        err("asp 1 0\n0\n").kind,
        AspifErrorKind::BadHeader(_)
    ));
    let e = err("asp 1 0 0\n0\n1 0 1 1 0 0\n0\n");
    assert_eq!(e.kind, AspifErrorKind::AfterEnd);
    assert_eq!(e.line, 3);
    let e = err("asp 1 0 0\n1 0 1 1 0 0 7\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::Trailing(_)), "{e}");
    let e = err("asp 1 0 0\n10 lucent-cr x r\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::BadLucentComment(_)), "{e}");
    let e = err("asp 1 0 0\n10 lucent-cr-minimize 1\n1 0 0 0 0\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::BadLucentComment(_)), "{e}");
    let e = err("asp 1 0 0\n10 lucent-cr 1 r\n10 lucent-cr-minimize 1\n2 1 1 1 2\n0\n");
    assert!(matches!(e.kind, AspifErrorKind::BadLucentComment(_)), "{e}");
    let e = err(b"asp 1 0 0\n4 1 \xff 0\n0\n");
    assert_eq!(e.kind, AspifErrorKind::NotUtf8("output symbol"));
}

#[test]
fn every_prefix_of_a_valid_file_is_handled() {
    // No prefix may panic; all but the complete file (and the file without its final newline)
    // are errors.
    let text = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/aspif/weights.aspif"
    ))
    .unwrap();
    for cut in 0..text.len() - 2 {
        assert!(
            aspif::read(&text[..cut]).is_err(),
            "prefix of {cut} bytes accepted"
        );
    }
    assert!(aspif::read(&text[..text.len() - 1]).is_ok());
}
