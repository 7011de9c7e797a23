//! The built-in functions behind `function { internal(N) }`, numbered as POV-Ray numbers
//! them (scenes write the numbers directly), with their documented extra parameters after
//! x, y and z. Each is written from its surface's mathematics, with the constants, scales,
//! signs and guards POV-Ray 3.7 uses measured by sampling its `functions.inc`.

mod algebraic;
mod blobs;
mod fractal;
mod lattices;
mod plane_curves;
mod shapes;
mod windings;

/// A built-in function by its POV-Ray number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Internal(pub u16);

/// One built-in: its number, name, number of parameters after x, y, z, and its code, which
/// reads `x, y, z` and then the parameters from its argument slice.
pub struct InternalInfo {
    pub number: u16,
    pub name: &'static str,
    pub extra_params: u8,
    pub eval: fn(&[f64]) -> f64,
}

macro_rules! internals {
    ($($number:literal $name:ident $extra:literal $eval:expr;)*) => {
        /// Every built-in function POV-Ray 3.7 numbers, in order of number.
        pub const INTERNALS: &[InternalInfo] = &[
            $(InternalInfo { number: $number, name: stringify!($name), extra_params: $extra, eval: $eval },)*
        ];
    };
}

internals! {
    0 f_algbr_cyl1 5 plane_curves::algbr_cyl1;
    1 f_algbr_cyl2 5 plane_curves::algbr_cyl2;
    2 f_algbr_cyl3 5 plane_curves::algbr_cyl3;
    3 f_algbr_cyl4 5 plane_curves::algbr_cyl4;
    4 f_bicorn 2 algebraic::bicorn;
    5 f_bifolia 2 algebraic::bifolia;
    6 f_blob 5 blobs::blob;
    7 f_blob2 4 blobs::blob2;
    8 f_boy_surface 2 algebraic::boy_surface;
    9 f_comma 1 shapes::comma;
    10 f_cross_ellipsoids 4 blobs::cross_ellipsoids;
    11 f_crossed_trough 1 algebraic::crossed_trough;
    12 f_cubic_saddle 1 algebraic::cubic_saddle;
    13 f_cushion 1 algebraic::cushion;
    14 f_devils_curve 1 algebraic::devils_curve;
    15 f_devils_curve_2d 6 plane_curves::devils_curve_2d;
    16 f_dupin_cyclid 6 algebraic::dupin_cyclid;
    17 f_ellipsoid 3 shapes::ellipsoid;
    18 f_enneper 1 algebraic::enneper;
    19 f_flange_cover 4 blobs::flange_cover;
    20 f_folium_surface 3 algebraic::folium_surface;
    21 f_folium_surface_2d 6 plane_curves::folium_surface_2d;
    22 f_glob 1 algebraic::glob;
    23 f_heart 1 algebraic::heart;
    24 f_helical_torus 10 windings::helical_torus;
    25 f_helix1 7 windings::helix1;
    26 f_helix2 7 windings::helix2;
    27 f_hex_x 1 lattices::hex_x;
    28 f_hex_y 1 lattices::hex_y;
    29 f_hetero_mf 6 fractal::hetero_mf;
    30 f_hunt_surface 1 algebraic::hunt_surface;
    31 f_hyperbolic_torus 3 algebraic::hyperbolic_torus;
    32 f_isect_ellipsoids 4 blobs::isect_ellipsoids;
    33 f_kampyle_of_eudoxus 3 algebraic::kampyle_of_eudoxus;
    34 f_kampyle_of_eudoxus_2d 6 plane_curves::kampyle_of_eudoxus_2d;
    35 f_klein_bottle 1 algebraic::klein_bottle;
    36 f_kummer_surface_v1 1 algebraic::kummer_surface_v1;
    37 f_kummer_surface_v2 4 algebraic::kummer_surface_v2;
    38 f_lemniscate_of_gerono 1 algebraic::lemniscate_of_gerono;
    39 f_lemniscate_of_gerono_2d 6 plane_curves::lemniscate_of_gerono_2d;
    40 f_mesh1 5 lattices::mesh1;
    41 f_mitre 1 algebraic::mitre;
    42 f_nodal_cubic 1 algebraic::nodal_cubic;
    43 f_odd 1 algebraic::cushion;
    44 f_ovals_of_cassini 4 algebraic::ovals_of_cassini;
    45 f_paraboloid 1 algebraic::paraboloid;
    46 f_parabolic_torus 3 algebraic::parabolic_torus;
    47 f_ph 0 shapes::ph;
    48 f_pillow 1 algebraic::pillow;
    49 f_piriform 1 algebraic::piriform;
    50 f_piriform_2d 7 plane_curves::piriform_2d;
    51 f_poly4 5 shapes::poly4;
    52 f_polytubes 6 shapes::polytubes;
    53 f_quantum 1 blobs::quantum;
    54 f_quartic_paraboloid 1 algebraic::quartic_paraboloid;
    55 f_quartic_saddle 1 algebraic::quartic_saddle;
    56 f_quartic_cylinder 3 algebraic::quartic_cylinder;
    57 f_r 0 shapes::r;
    58 f_ridge 6 fractal::ridge;
    59 f_ridged_mf 6 fractal::ridged_mf;
    60 f_rounded_box 4 shapes::rounded_box;
    61 f_sphere 1 shapes::sphere;
    62 f_spikes 5 blobs::spikes;
    63 f_spikes_2d 4 blobs::spikes_2d;
    64 f_spiral 6 windings::spiral;
    65 f_steiners_roman 1 algebraic::steiners_roman;
    66 f_strophoid 4 algebraic::strophoid;
    67 f_strophoid_2d 7 plane_curves::strophoid_2d;
    68 f_superellipsoid 2 shapes::superellipsoid;
    69 f_th 0 shapes::th;
    70 f_torus 2 shapes::torus;
    71 f_torus2 3 algebraic::torus2;
    72 f_torus_gumdrop 1 algebraic::torus_gumdrop;
    73 f_umbrella 1 algebraic::umbrella;
    74 f_witch_of_agnesi 2 algebraic::witch_of_agnesi;
    75 f_witch_of_agnesi_2d 6 plane_curves::witch_of_agnesi_2d;
    76 f_noise3d 0 fractal::noise3d;
    78 f_noise_generator 1 fractal::noise_generator;
}

impl Internal {
    pub fn info(self) -> Option<&'static InternalInfo> {
        INTERNALS
            .binary_search_by_key(&self.0, |info| info.number)
            .ok()
            .map(|index| &INTERNALS[index])
    }

    /// The function's value; NaN for an unknown number or too few arguments (compiled code
    /// always passes x, y, z and every parameter).
    pub fn eval(self, args: &[f64]) -> f64 {
        match self.info() {
            Some(info) if args.len() >= 3 + usize::from(info.extra_params) => (info.eval)(args),
            _ => f64::NAN,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_sorted_by_number() {
        assert!(INTERNALS.windows(2).all(|w| w[0].number < w[1].number));
        assert_eq!(
            Internal(60).info().map(|info| info.name),
            Some("f_rounded_box")
        );
        assert!(Internal(77).info().is_none());
    }

    #[test]
    fn too_few_arguments_give_nan() {
        assert!(Internal(61).eval(&[1.0, 2.0, 3.0]).is_nan());
        assert_eq!(Internal(61).eval(&[3.0, 4.0, 0.0, 1.0]), 4.0);
    }
}
