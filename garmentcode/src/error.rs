//! Errors of the runtime crate.
//!
//! Garment programs fail for geometric reasons (a neckline wider than the edge it is
//! cut into, a dart that cannot form a triangle, a stitch whose sides cannot be
//! matched); each gets a variant with a message that names what failed.

use thiserror::Error;

/// Result type of the runtime crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong while building or reading a pattern.
///
/// ```
/// use garmentcode::ops::{DartSize, dart_shape};
/// use garmentcode::{Arena, Error, Vec2};
///
/// let mut a = Arena::new();
/// let err = a.line(Vec2::ZERO, Vec2::ZERO).unwrap_err();
/// assert!(matches!(err, Error::DegenerateEdge { .. }));
/// // Legs of 2 cm cannot span a 10 cm dart.
/// let err = dart_shape(&mut a, 10.0, DartSize::Side(2.0)).unwrap_err();
/// assert!(matches!(err, Error::Dart(_)));
/// assert!(err.to_string().starts_with("dart shape: "));
/// ```
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// An edge whose start and end coincide (within 1e-4 cm).
    #[error("degenerate edge: start and end of an edge should differ (at ({x:.4}, {y:.4}))")]
    DegenerateEdge {
        /// x of the coincident end points.
        x: f64,
        /// y of the coincident end points.
        y: f64,
    },
    /// Subdivision fractions that do not sum to one.
    #[error("edge subdivision: fractions sum to {sum}, not 1")]
    Fractions {
        /// The sum found.
        sum: f64,
    },
    /// A dart shape that cannot be built.
    #[error("dart shape: {0}")]
    Dart(String),
    /// A shape that does not fit the edge it is cut into.
    #[error("cut into edge: {0}")]
    Cut(String),
    /// Stitch matching could not project one interface onto the other.
    #[error("stitch: projection on panels [{panels}] failed")]
    Projection {
        /// Names of the panels of the interface being split.
        panels: String,
    },
    /// An interface or placement request that makes no sense.
    #[error("interface: {0}")]
    Interface(String),
    /// Any other geometric impossibility.
    #[error("geometry: {0}")]
    Geometry(String),
    /// A panel outline that crosses itself, reported while building only when the
    /// arena is set to [`crate::Arena::stop_at_self_intersection`] (a validity filter
    /// stopping early, not a program failure).
    #[error("self-intersection: the outline of panel '{panel}' crosses itself")]
    SelfIntersecting {
        /// Name of the panel.
        panel: String,
    },
    /// A garment design the program cannot build.
    #[error("design: {0}")]
    Design(String),
    /// An input file that cannot be read or parsed.
    #[error("{0}")]
    Input(String),
}
