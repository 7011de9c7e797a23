//! One module per subcommand: its arguments and what it does.

pub mod check;
pub mod fmt;
pub mod render;
pub mod stitch;
pub mod syntax;
