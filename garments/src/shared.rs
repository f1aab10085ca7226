//! Types several garment modules share: the options components take instead of
//! booleans, and the values of a bodice half that its collar and sleeve follow. Every
//! module may depend on this one; it depends on none of them.

/// Loose or fitted cut (shirts and waistbands).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fit {
    /// Loose: a t-shirt block, a straight band.
    Loose,
    /// Fitted: darted bodice panels, a band following the body.
    Fitted,
}

/// Front or back of the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Front.
    Front,
    /// Back.
    Back,
}

/// Values a bodice half derives from its design and its torso panels (cm), which
/// its neckline, collar and armholes follow.
#[derive(Clone, Copy, Debug)]
pub struct Resolved {
    /// Armhole height.
    pub connecting_width: f64,
    /// Neckline width.
    pub collar_width: f64,
    /// Front neckline depth at the shoulder line.
    pub fc_depth: f64,
    /// Back neckline depth at the shoulder line.
    pub bc_depth: f64,
    /// Front depth below the shoulder slope (strapless crop).
    pub f_strapless_depth: f64,
    /// Back depth below the shoulder slope.
    pub b_strapless_depth: f64,
}
