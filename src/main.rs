//! The `lucent` binary: everything lives in the library; `main` only calls `cli`. The binary
//! chooses mimalloc as its global allocator (the library leaves the choice to its clients).

#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(lucent::cli::main());
}
