//! User functions (`function { }`), compiled once into a compact form that isosurfaces,
//! patterns and parse-time calls evaluate many times.

/// A compiled user function of any number of float parameters returning a float.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    pub params: Vec<String>,
}
