//! Solving: conflict-driven stable-model search over ground programs (issue 4).
//!
//! Not built yet: the command line reports that solving is unavailable and exits non-zero.
