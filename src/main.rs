//! The `lucent` binary: everything lives in the library; `main` only calls `cli`.

fn main() {
    std::process::exit(lucent::cli::main());
}
