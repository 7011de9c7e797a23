//! The built-in functions behind `function { internal(N) }`, numbered as POV-Ray numbers
//! them (scenes write the numbers directly), with their documented extra parameters after
//! x, y and z. Entries without an implementation are rejected when a scene declares them.

/// A built-in function by its POV-Ray number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Internal(pub u16);

/// One built-in: its number, name, number of parameters after x, y, z, and its code.
pub struct InternalInfo {
    pub number: u16,
    pub name: &'static str,
    pub extra_params: u8,
    pub eval: Option<fn(&[f64]) -> f64>,
}

macro_rules! internals {
    ($($number:literal $name:ident $extra:literal $eval:expr;)*) => {
        /// Every built-in function POV-Ray 3.7 numbers.
        pub const INTERNALS: &[InternalInfo] = &[
            $(InternalInfo { number: $number, name: stringify!($name), extra_params: $extra, eval: $eval },)*
        ];
    };
}

internals! {
    0 f_algbr_cyl1 5 None;
    1 f_algbr_cyl2 5 None;
    2 f_algbr_cyl3 5 None;
    3 f_algbr_cyl4 5 None;
    4 f_bicorn 2 None;
    5 f_bifolia 2 None;
    6 f_blob 5 None;
    7 f_blob2 4 None;
    8 f_boy_surface 2 None;
    9 f_comma 1 None;
    10 f_cross_ellipsoids 4 None;
    11 f_crossed_trough 1 None;
    12 f_cubic_saddle 1 None;
    13 f_cushion 1 None;
    14 f_devils_curve 1 None;
    15 f_devils_curve_2d 6 None;
    16 f_dupin_cyclid 6 None;
    17 f_ellipsoid 3 None;
    18 f_enneper 1 None;
    19 f_flange_cover 4 None;
    20 f_folium_surface 3 None;
    21 f_folium_surface_2d 6 None;
    22 f_glob 1 None;
    23 f_heart 1 None;
    24 f_helical_torus 10 None;
    25 f_helix1 7 None;
    26 f_helix2 7 None;
    27 f_hex_x 1 None;
    28 f_hex_y 1 None;
    29 f_hetero_mf 6 None;
    30 f_hunt_surface 1 None;
    31 f_hyperbolic_torus 3 None;
    32 f_isect_ellipsoids 4 None;
    33 f_kampyle_of_eudoxus 3 None;
    34 f_kampyle_of_eudoxus_2d 6 None;
    35 f_klein_bottle 1 None;
    36 f_kummer_surface_v1 1 None;
    37 f_kummer_surface_v2 4 None;
    38 f_lemniscate_of_gerono 1 None;
    39 f_lemniscate_of_gerono_2d 6 None;
    40 f_mesh1 5 None;
    41 f_mitre 1 None;
    42 f_nodal_cubic 1 None;
    43 f_odd 1 None;
    44 f_ovals_of_cassini 4 None;
    45 f_paraboloid 1 None;
    46 f_parabolic_torus 3 None;
    47 f_ph 0 None;
    48 f_pillow 1 None;
    49 f_piriform 1 None;
    50 f_piriform_2d 7 None;
    51 f_poly4 5 None;
    52 f_polytubes 6 None;
    53 f_quantum 1 None;
    54 f_quartic_paraboloid 1 None;
    55 f_quartic_saddle 1 None;
    56 f_quartic_cylinder 3 None;
    57 f_r 0 Some(f_r);
    58 f_ridge 6 None;
    59 f_ridged_mf 6 None;
    60 f_rounded_box 4 None;
    61 f_sphere 1 Some(f_sphere);
    62 f_spikes 5 None;
    63 f_spikes_2d 4 None;
    64 f_spiral 6 None;
    65 f_steiners_roman 1 None;
    66 f_strophoid 4 None;
    67 f_strophoid_2d 7 None;
    68 f_superellipsoid 2 None;
    69 f_th 0 None;
    70 f_torus 2 Some(f_torus);
    71 f_torus2 3 None;
    72 f_torus_gumdrop 1 None;
    73 f_umbrella 1 None;
    74 f_witch_of_agnesi 2 None;
    75 f_witch_of_agnesi_2d 6 None;
    76 f_noise3d 0 Some(f_noise3d);
    78 f_noise_generator 1 Some(f_noise3d);
}

impl Internal {
    pub fn info(self) -> Option<&'static InternalInfo> {
        INTERNALS.iter().find(|info| info.number == self.0)
    }

    pub fn eval(self, args: &[f64]) -> f64 {
        match self.info().and_then(|info| info.eval) {
            Some(f) => f(args),
            None => f64::NAN,
        }
    }
}

fn f_r(a: &[f64]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

fn f_sphere(a: &[f64]) -> f64 {
    f_r(a) - a[3]
}

fn f_torus(a: &[f64]) -> f64 {
    let ring = (a[0] * a[0] + a[2] * a[2]).sqrt() - a[3];
    (ring * ring + a[1] * a[1]).sqrt() - a[4]
}

/// POV-Ray's solid noise, 0..1 (the same noise the patterns use; statistically POV-Ray's,
/// not bit for bit).
fn f_noise3d(a: &[f64]) -> f64 {
    crate::noise::noise(glam::DVec3::new(a[0], a[1], a[2]))
}
