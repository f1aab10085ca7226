//! 3D rotations of panels, with the reference's Euler-angle conventions.
//!
//! Panels are written with intrinsic `XYZ` Euler angles in degrees exactly as scipy's
//! `Rotation.as_euler('XYZ', degrees=True)` produces them (same ranges, same
//! gimbal-lock rule), so files can be compared with the reference's.

use crate::math::Vec3;
use glam::DQuat;

/// A rotation in 3D (a unit quaternion).
///
/// ```
/// use garmentcode::{Rotation, Vec3};
///
/// let quarter = Rotation::from_euler_xyz_degrees([0.0, 90.0, 0.0]);
/// assert!((quarter.apply(Vec3::X) - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
/// // Written back as the same intrinsic XYZ Euler angles.
/// let angles = Rotation::from_euler_xyz_degrees([10.0, 20.0, 30.0]).as_euler_xyz_degrees();
/// assert!(angles.iter().zip([10.0, 20.0, 30.0]).all(|(x, y)| (x - y).abs() < 1e-9));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotation(pub DQuat);

impl Default for Rotation {
    fn default() -> Self {
        Rotation::IDENTITY
    }
}

impl Rotation {
    /// No rotation.
    pub const IDENTITY: Rotation = Rotation(DQuat::IDENTITY);

    /// Intrinsic `XYZ` Euler angles in degrees: `R = Rx(a)·Ry(b)·Rz(c)`.
    pub fn from_euler_xyz_degrees(angles: [f64; 3]) -> Rotation {
        let r = angles.map(f64::to_radians);
        Rotation::from_euler_xyz(r)
    }

    /// Intrinsic `XYZ` Euler angles in radians.
    pub fn from_euler_xyz(r: [f64; 3]) -> Rotation {
        let qx = DQuat::from_rotation_x(r[0]);
        let qy = DQuat::from_rotation_y(r[1]);
        let qz = DQuat::from_rotation_z(r[2]);
        Rotation(qx * qy * qz)
    }

    /// Rotation about `axis` (unit) by `angle` radians (a rotation vector).
    pub fn from_rotvec(v: Vec3) -> Rotation {
        let angle = v.length();
        if angle == 0.0 {
            return Rotation::IDENTITY;
        }
        Rotation(DQuat::from_axis_angle(v / angle, angle))
    }

    /// Apply to a vector.
    pub fn apply(&self, v: Vec3) -> Vec3 {
        self.matrix() * v
    }

    /// Rotation matrix.
    pub fn matrix(&self) -> glam::DMat3 {
        glam::DMat3::from_quat(self.0)
    }

    /// `self` applied after `other` (scipy's `self * other`).
    pub fn compose(&self, other: &Rotation) -> Rotation {
        Rotation(self.0 * other.0)
    }

    /// Intrinsic `XYZ` Euler angles in radians, as scipy computes them (quaternion
    /// based algorithm; at gimbal lock the third angle is set to zero).
    pub fn as_euler_xyz(&self) -> [f64; 3] {
        let q = self.0;
        let quat = [q.x, q.y, q.z, q.w];
        // 'XYZ' is intrinsic: scipy reverses the axis sequence -> (i, j, k) = (2, 1, 0).
        let (i, j, k) = (2usize, 1usize, 0usize);
        let sign = -1.0; // (i-j)*(j-k)*(k-i)/2
        let a = quat[3] - quat[j];
        let b = quat[i] + quat[k] * sign;
        let c = quat[j] + quat[3];
        let d = quat[k] * sign - quat[i];
        let eps = 1e-7;
        let mut angles = [0.0f64; 3];
        angles[1] = 2.0 * c.hypot(d).atan2(a.hypot(b));
        let case = if angles[1].abs() <= eps {
            1
        } else if (angles[1] - std::f64::consts::PI).abs() <= eps {
            2
        } else {
            0
        };
        let half_sum = b.atan2(a);
        let half_diff = d.atan2(c);
        // Intrinsic: the first angle of the (reversed) sequence is written last.
        let (angle_first, angle_third) = (2usize, 0usize);
        if case == 0 {
            angles[angle_first] = half_sum - half_diff;
            angles[angle_third] = half_sum + half_diff;
        } else {
            angles[2] = 0.0;
            if case == 1 {
                angles[0] = 2.0 * half_sum;
            } else {
                angles[0] = 2.0 * half_diff;
            }
        }
        angles[angle_third] *= sign;
        angles[1] -= std::f64::consts::FRAC_PI_2;
        for a in angles.iter_mut() {
            if *a < -std::f64::consts::PI {
                *a += 2.0 * std::f64::consts::PI;
            } else if *a > std::f64::consts::PI {
                *a -= 2.0 * std::f64::consts::PI;
            }
        }
        angles
    }

    /// Intrinsic `XYZ` Euler angles in degrees.
    pub fn as_euler_xyz_degrees(&self) -> [f64; 3] {
        self.as_euler_xyz().map(f64::to_degrees)
    }

    /// Shortest-arc rotation taking direction `v1` onto `v2` (the reference's
    /// `vector_align_3D`: parallel vectors give NaN, as there).
    pub fn align(v1: Vec3, v2: Vec3) -> Rotation {
        let cos = (v1.dot(v2) / (v1.length() * v2.length())).clamp(-1.0, 1.0);
        let angle = cos.acos();
        let axis = v1.cross(v2);
        let axis = axis / axis.length();
        Rotation::from_rotvec(axis * angle)
    }
}

/// Rotation matrix `Rz(c)·Ry(b)·Rx(a)` from angles in degrees: the convention the
/// reference's own *readers* use (panel order, legacy loaders), unlike its writer.
pub fn matrix_zyx_from_degrees(angles: [f64; 3]) -> glam::DMat3 {
    let [a, b, c] = angles.map(f64::to_radians);
    glam::DMat3::from_rotation_z(c) * glam::DMat3::from_rotation_y(b) * glam::DMat3::from_rotation_x(a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identity_is_written_like_scipy() {
        let e = Rotation::IDENTITY.as_euler_xyz_degrees();
        assert_eq!(e, [0.0, 0.0, 0.0]);
        assert!(e[0].is_sign_negative(), "scipy writes -0.0 for the first angle");
    }

    #[test]
    fn euler_round_trip() {
        for angles in [[10.0, 20.0, 30.0], [-170.0, 45.0, 100.0], [0.0, -72.973, 0.0], [90.0, 45.0, 0.0]] {
            let r = Rotation::from_euler_xyz_degrees(angles);
            let back = r.as_euler_xyz_degrees();
            for i in 0..3 {
                assert!((back[i] - angles[i]).abs() < 1e-9, "{angles:?} -> {back:?}");
            }
        }
    }

    #[test]
    fn y_rotation_beyond_ninety_degrees() {
        // A pure y rotation of 107° is written as [±180, 73, ±180].
        let r = Rotation::from_euler_xyz_degrees([0.0, 107.027, 0.0]);
        let e = r.as_euler_xyz_degrees();
        assert!((e[0].abs() - 180.0).abs() < 1e-9 && (e[2].abs() - 180.0).abs() < 1e-9, "{e:?}");
        assert!((e[1] - 72.973).abs() < 1e-9);
    }

    #[test]
    fn gimbal_lock_folds_into_first_angle() {
        let e = Rotation::from_euler_xyz_degrees([30.0, 90.0, 40.0]).as_euler_xyz_degrees();
        assert!((e[0] - 70.0).abs() < 1e-6 && (e[1] - 90.0).abs() < 1e-6 && e[2] == 0.0, "{e:?}");
    }

    #[test]
    fn intrinsic_matrix_order() {
        let r = Rotation::from_euler_xyz_degrees([30.0, 20.0, 10.0]);
        let m = glam::DMat3::from_rotation_x(30f64.to_radians())
            * glam::DMat3::from_rotation_y(20f64.to_radians())
            * glam::DMat3::from_rotation_z(10f64.to_radians());
        let v = Vec3::new(0.3, -1.2, 2.0);
        assert!((r.apply(v) - m * v).length() < 1e-12);
    }
    /// Quaternions (x, y, z, w) and scipy 1.17's `as_euler('XYZ', degrees=True)`.
    #[allow(clippy::approx_constant)] // recorded scipy output, digit for digit
    const SCIPY: [[f64; 7]; 40] = [
        [
            -0.5697444092412621,
            0.30870844659880226,
            -0.6739860436046022,
            0.3547297790756997,
            4.255784892092407,
            80.7569004847039,
            -128.10253942093186,
        ],
        [
            -0.3853879192462941,
            0.4119835308626775,
            0.7451974425943331,
            0.35556503420302543,
            -67.74067727622526,
            -16.344155453550957,
            117.97293377535901,
        ],
        [
            0.15059938068187229,
            -0.06936537092986012,
            0.7114387999222329,
            0.6829078311303896,
            17.853727562301426,
            6.865796379470094,
            91.26471912293037,
        ],
        [
            -0.3778957752206061,
            -0.3458538535498613,
            -0.4670224648762896,
            0.7207426117248814,
            -61.29658206032684,
            -8.37037989348273,
            -70.84986145500783,
        ],
        [
            -0.3872494511430052,
            -0.7709522002589609,
            -0.1068986603526414,
            0.494209716537543,
            -131.7449889910207,
            -42.7835987204671,
            -106.75611335658613,
        ],
        [
            0.4924159747310009,
            0.5075389597276645,
            0.46075540609739957,
            0.5363162946809454,
            90.1312821468189,
            86.53269596422297,
            -5.33124920461135,
        ],
        [
            0.9192714749605311,
            -0.16133745175859868,
            -0.3234089828332739,
            0.1559384872527581,
            166.19658971896325,
            -40.159583271833256,
            14.841667997076305,
        ],
        [
            -0.7336753180126929,
            -0.23766748196222826,
            0.516151097251488,
            0.37258923838832614,
            -122.16527684095436,
            -69.14418975526135,
            5.784690797236302,
        ],
        [
            0.4773261969184812,
            0.4248208630078162,
            0.471291851077423,
            0.6079234550473026,
            44.45631199350015,
            75.11358686236248,
            40.68118837909457,
        ],
        [
            -0.7506100253769012,
            -0.17579055114627667,
            0.6123261852293209,
            0.1753251687975329,
            -165.74656440088697,
            -78.77707575302237,
            -14.63908216125467,
        ],
        [
            0.28685142919665974,
            -0.43320989927656706,
            0.09032596173022006,
            0.8496391359713437,
            50.87814089017499,
            -43.18245940729981,
            33.458766517542244,
        ],
        [
            0.8137405343288688,
            0.15886339271913805,
            0.3541326729514299,
            0.43264167066084536,
            122.3573475713072,
            45.54543738639204,
            3.919998407951877,
        ],
        [
            -0.5684805324192781,
            0.6019372169319595,
            -0.10715755442015296,
            0.5504713704301007,
            -126.74806711741562,
            51.67744947986419,
            65.98328616117254,
        ],
        [
            -0.08365052376959076,
            -0.7337896886289341,
            -0.08493868245268521,
            0.668835333215977,
            -111.01814675275132,
            -75.32052887456771,
            -111.12338661940788,
        ],
        [
            0.3214997697521821,
            -0.8381287687829101,
            0.3912832266921648,
            0.2026709192190752,
            127.88171074334525,
            -5.056250515417763,
            135.55335470996897,
        ],
        [
            -0.4365704588392313,
            0.5013994187115349,
            0.11746534521210303,
            0.7377037007219358,
            -81.34258009906142,
            39.58368903156475,
            52.45952240698123,
        ],
        [
            0.44749968226339887,
            0.7291508794056987,
            -0.2579173595708312,
            0.448956195043641,
            120.80491794009868,
            25.079648411985822,
            -102.52145982132951,
        ],
        [
            0.386830829650311,
            0.720852486519676,
            -0.5219886427241414,
            0.24137410544103757,
            109.8197399322035,
            -3.201770124119409,
            -125.81106104837612,
        ],
        [
            0.6055261190470147,
            -0.40455307930210904,
            -0.5512017708125562,
            0.4072487360718806,
            142.0977103906224,
            -85.59167805119462,
            32.22074235025729,
        ],
        [
            0.6370997571706952,
            -0.1126963604705159,
            0.7543092299050084,
            0.1114496093750626,
            62.44555937505796,
            69.39364800779043,
            117.65711864041961,
        ],
        [
            0.0022956061525958305,
            -0.5790157929139872,
            0.4478344459503039,
            0.6813073834686978,
            57.72793698738841,
            -51.89854633064811,
            96.66611960265158,
        ],
        [
            0.17164929275734234,
            -0.7689520927012076,
            0.14679325803304077,
            0.598081047034917,
            119.25894047920605,
            -60.388692034661766,
            117.17561282168009,
        ],
        [
            -0.5287081614668787,
            -0.1794209032518958,
            0.6098869942312197,
            0.5624177039729413,
            -44.947081261208936,
            -57.857061928613064,
            68.88133269998683,
        ],
        [
            -0.15390596374562188,
            -0.30157954903881734,
            -0.6091244364288213,
            0.7171681468598181,
            -37.34778160188488,
            -14.186013438788057,
            -85.50190340996346,
        ],
        [
            -0.8662827352027956,
            -0.21996284042692268,
            -0.4171171676004295,
            0.16487522559159268,
            -141.86835478536318,
            40.552908853723004,
            -43.047262840848354,
        ],
        [
            -0.42060322611615314,
            0.5684126372457637,
            -0.5684126372457636,
            0.4206032261161532,
            90.00000000000003,
            73.00000000000001,
            179.99999999999997,
        ],
        [-0.42045440162355957, 0.5685227314324155, 0.5685227314324156, -0.4204544016235594, -90.0, -72.96999999999998, 180.0],
        [
            0.42060322611615314,
            0.5684126372457637,
            0.5684126372457636,
            0.4206032261161532,
            -90.00000000000003,
            73.00000000000001,
            -179.99999999999997,
        ],
        [0.030843564597231976, -0.706433772212892, -0.030843564597231865, 0.7064337722128922, 5.0000000000000036, -89.99999999999999, 0.0],
        [2.3432602026631493e-17, -0.3826834323650898, 0.9238795325112867, 5.657130561438501e-17, 45.0, 0.0, 180.0],
        [
            0.8038568606172173,
            4.922203656637576e-17,
            0.5948227867513414,
            3.642239109274694e-17,
            180.0,
            73.00000000000001,
            -1.2722218725854067e-14,
        ],
        [0.0, -0.7071067811865475, 0.0, 0.7071067811865476, -0.0, -89.99999999999999, 0.0],
        [0.5, -0.5, -0.4999999999999999, 0.5000000000000001, 90.0, -89.99999999999999, 0.0],
        [-0.6532814824381882, -0.27059805007309856, 0.6532814824381883, 0.2705980500730985, -135.0, -89.99999999999999, 0.0],
        [0.6830127018922194, 0.18301270189221938, 0.6830127018922193, 0.18301270189221935, 150.0, 90.0, 0.0],
        [0.7071067811865476, 4.329780281177466e-17, 0.7071067811865475, 4.329780281177467e-17, 180.0, 90.0, 0.0],
        [0.6408563820557885, 0.2988362387301199, 0.6408563820557884, 0.29883623873012, 129.99999999999997, 90.0, 0.0],
        [
            -0.5533875347222472,
            0.4401843209543404,
            -0.657904571655185,
            0.25915550272993904,
            90.00000000000004,
            73.00000000000001,
            149.99999999999997,
        ],
        [-0.3535533905932738, -0.6123724356957945, 0.3535533905932736, 0.6123724356957946, -60.00000000000001, -89.99999999999999, 0.0],
        [
            -0.4403291823856126,
            -0.5532722757735271,
            0.2589832548366978,
            0.6579723958603355,
            -89.99999999999999,
            -72.96999999999998,
            -29.99999999999998,
        ],
    ];

    #[test]
    fn euler_angles_match_scipy() {
        for row in SCIPY {
            let q = glam::DQuat::from_xyzw(row[0], row[1], row[2], row[3]);
            let e = Rotation(q).as_euler_xyz_degrees();
            for k in 0..3 {
                assert!((e[k] - row[4 + k]).abs() < 1e-9, "{row:?}: got {e:?}");
            }
        }
    }
}
