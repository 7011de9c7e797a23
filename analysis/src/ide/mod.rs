//! IDE features over the analysis database, one per module. Each takes the database, a
//! position or file and a config struct, and returns plain data; only the language server
//! turns that into protocol messages.

pub mod embedded;
