//! Standard slot markers: the interfaces through which garment parts connect.
//!
//! An `#[interface]` field named like one of these (e.g. `top`, or `r#in` renamed
//! `"in"`) makes the component implement [`crate::Slot`] for the marker; a garment
//! that needs "something with a top interface" asks for `T: Slot<Top>`.

macro_rules! markers {
    ($($(#[$doc:meta])* $name:ident = $key:literal;)*) => {$(
        $(#[$doc])*
        #[doc = concat!("Interface `", $key, "`.")]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub struct $name;
    )*};
}

markers! {
    /// Where a bottom garment or band attaches from above.
    Top = "top";
    /// Where the next piece attaches below.
    Bottom = "bottom";
    /// Front part of the top interface.
    TopF = "top_f";
    /// Back part of the top interface.
    TopB = "top_b";
    /// Front part of the bottom interface.
    BottomF = "bottom_f";
    /// Back part of the bottom interface.
    BottomB = "bottom_b";
    /// Front seam.
    Front = "front";
    /// Back seam.
    Back = "back";
    /// Centre-front seam of a bodice half.
    FrontIn = "front_in";
    /// Centre-back seam of a bodice half.
    BackIn = "back_in";
    /// A sleeve's connection to the bodice.
    In = "in";
    /// A sleeve's or leg's free end (for cuffs).
    Out = "out";
    /// Left side.
    Left = "left";
    /// Right side.
    Right = "right";
    /// Inside seam.
    Inside = "inside";
    /// Outside seam.
    Outside = "outside";
    /// Shoulder seam.
    Shoulder = "shoulder";
}
