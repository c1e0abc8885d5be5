//! The `lucent` binary: everything lives in the library; `main` only calls `cli`. The binary
//! chooses mimalloc as its global allocator (`mi_alloc`; the library leaves the choice to its
//! clients).

mod mi_alloc;

#[global_allocator]
static GLOBAL: mi_alloc::Mi = mi_alloc::Mi;

fn main() {
    mi_alloc::purge_at_once();
    std::process::exit(lucent::cli::main());
}
