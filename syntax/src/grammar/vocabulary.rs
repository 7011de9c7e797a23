//! What the grammar knows about reserved words: which start expressions, which take no
//! argument, which node a keyword block becomes. Everything not listed here is treated
//! generically (a keyword with an optional argument, or a keyword block), so that a word
//! missing from a list costs precision in the tree, never a false error.

use crate::SyntaxKind::{self, *};
use crate::parsing::TokenSet;

/// Built-in values that stand alone in an expression.
pub(crate) const CONSTANTS: TokenSet = TokenSet::new(&[
    PI_KW,
    TAU_KW,
    TRUE_KW,
    FALSE_KW,
    YES_KW,
    NO_KW,
    ON_KW,
    OFF_KW,
    CLOCK_KW,
    CLOCK_DELTA_KW,
    CLOCK_ON_KW,
    FINAL_CLOCK_KW,
    FINAL_FRAME_KW,
    FRAME_NUMBER_KW,
    INITIAL_CLOCK_KW,
    INITIAL_FRAME_KW,
    IMAGE_WIDTH_KW,
    IMAGE_HEIGHT_KW,
    VERSION_KW,
    NOW_KW,
    INPUT_FILE_NAME_KW,
    X_KW,
    Y_KW,
    Z_KW,
    T_KW,
    U_KW,
    V_KW,
]);

/// Built-in functions, called as `name(arguments)`.
pub(crate) const FUNCTIONS: TokenSet = TokenSet::new(&[
    ABS_KW,
    ACOS_KW,
    ACOSH_KW,
    ASC_KW,
    ASIN_KW,
    ASINH_KW,
    ATAN_KW,
    ATAN2_KW,
    ATANH_KW,
    BITWISE_AND_KW,
    BITWISE_OR_KW,
    BITWISE_XOR_KW,
    CEIL_KW,
    CHR_KW,
    CONCAT_KW,
    COS_KW,
    COSH_KW,
    DATETIME_KW,
    DEFINED_KW,
    DEGREES_KW,
    DIMENSION_SIZE_KW,
    DIMENSIONS_KW,
    DIV_KW,
    EXP_KW,
    FILE_EXISTS_KW,
    FLOOR_KW,
    INSIDE_KW,
    INT_KW,
    INTERNAL_KW,
    LN_KW,
    LOG_KW,
    MAX_KW,
    MAX_EXTENT_KW,
    MIN_KW,
    MIN_EXTENT_KW,
    MOD_KW,
    POW_KW,
    PROD_KW,
    RADIANS_KW,
    RAND_KW,
    SEED_KW,
    SELECT_KW,
    SIN_KW,
    SINH_KW,
    SQR_KW,
    SQRT_KW,
    STR_KW,
    STRCMP_KW,
    STRLEN_KW,
    STRLWR_KW,
    STRUPR_KW,
    SUBSTR_KW,
    SUM_KW,
    TAN_KW,
    TANH_KW,
    TRACE_KW,
    VAL_KW,
    VAXIS_ROTATE_KW,
    VCROSS_KW,
    VDOT_KW,
    VLENGTH_KW,
    VNORMALIZE_KW,
    VROTATE_KW,
    VSTR_KW,
    VTURBULENCE_KW,
]);

/// Words that open a colour expression: `color Red`, `rgb <1, 0, 0>`, `red 1`.
pub(crate) const COLOR_STARTS: TokenSet = TokenSet::new(&[
    COLOR_KW, COLOUR_KW, RGB_KW, RGBF_KW, RGBT_KW, RGBFT_KW, SRGB_KW, SRGBF_KW, SRGBT_KW,
    SRGBFT_KW, RED_KW, GREEN_KW, BLUE_KW,
]);

/// The colour forms that take a vector or float operand.
pub(crate) const COLOR_VECTORS: TokenSet = TokenSet::new(&[
    RGB_KW, RGBF_KW, RGBT_KW, RGBFT_KW, SRGB_KW, SRGBF_KW, SRGBT_KW, SRGBFT_KW,
]);

/// Components that may follow a colour: `color Red filter 0.5`.
pub(crate) const COLOR_COMPONENTS: TokenSet =
    TokenSet::new(&[RED_KW, GREEN_KW, BLUE_KW, FILTER_KW, TRANSMIT_KW, GRAY_KW]);

/// Keywords that never take an argument, so that what follows belongs to the parent:
/// `lathe { linear_spline 4, <0, 0>, ... }`.
pub(crate) const NO_ARGUMENT: TokenSet = TokenSet::new(&[
    LINEAR_SPLINE_KW,
    QUADRATIC_SPLINE_KW,
    CUBIC_SPLINE_KW,
    BEZIER_SPLINE_KW,
    B_SPLINE_KW,
    NATURAL_SPLINE_KW,
    LINEAR_SWEEP_KW,
    CONIC_SWEEP_KW,
    PERSPECTIVE_KW,
    ORTHOGRAPHIC_KW,
    FISHEYE_KW,
    ULTRA_WIDE_ANGLE_KW,
    OMNIMAX_KW,
    PANORAMIC_KW,
    SPHERICAL_KW,
    SPOTLIGHT_KW,
    SHADOWLESS_KW,
    PARALLEL_KW,
    OPEN_KW,
    INVERSE_KW,
    NO_SHADOW_KW,
    NO_IMAGE_KW,
    NO_REFLECTION_KW,
    NO_RADIOSITY_KW,
    DOUBLE_ILLUMINATE_KW,
    UV_MAPPING_KW,
    CUTAWAY_TEXTURES_KW,
    ONCE_KW,
    RAMP_WAVE_KW,
    SINE_WAVE_KW,
    TRIANGLE_WAVE_KW,
    SCALLOP_WAVE_KW,
    CUBIC_WAVE_KW,
    PLANAR_KW,
    BOXED_KW,
    CYLINDRICAL_KW,
    TOROIDAL_KW,
    USE_COLOR_KW,
    USE_COLOUR_KW,
    USE_INDEX_KW,
    USE_ALPHA_KW,
    AMBIENT_LIGHT_KW,
    PRECOMPUTE_KW,
    ASCII_KW,
    UTF8_KW,
]);

/// Keywords with an optional boolean: `hollow`, `hollow off`.
pub(crate) const OPTIONAL_BOOL: TokenSet = TokenSet::new(&[
    HOLLOW_KW,
    STURM_KW,
    SMOOTH_KW,
    HIERARCHY_KW,
    SPLIT_UNION_KW,
    FRESNEL_KW,
    CONSERVE_ENERGY_KW,
    MEDIA_ATTENUATION_KW,
    MEDIA_INTERACTION_KW,
    ALL_INTERSECTIONS_KW,
    ORIENT_KW,
    AREA_ILLUMINATION_KW,
    PASS_THROUGH_KW,
    COLLECT_KW,
    GLOBAL_LIGHTS_KW,
]);

pub(crate) const BOOL_CONSTANTS: TokenSet =
    TokenSet::new(&[ON_KW, OFF_KW, TRUE_KW, FALSE_KW, YES_KW, NO_KW]);

/// Patterns, whose optional argument is an amount (`bumps 0.5`), never a colour: in
/// `checker color Red color Blue` both colours are items of the pigment.
pub(crate) const PATTERNS: TokenSet = TokenSet::new(&[
    AGATE_KW,
    BOZO_KW,
    BRICK_KW,
    BUMPS_KW,
    CELLS_KW,
    CHECKER_KW,
    CRACKLE_KW,
    DENTS_KW,
    GRANITE_KW,
    HEXAGON_KW,
    LEOPARD_KW,
    MARBLE_KW,
    ONION_KW,
    RADIAL_KW,
    RIPPLES_KW,
    SPOTTED_KW,
    SQUARE_KW,
    TRIANGULAR_KW,
    WAVES_KW,
    WOOD_KW,
    WRINKLES_KW,
]);

/// The node a keyword block becomes.
pub(crate) fn block_kind(keyword: SyntaxKind) -> SyntaxKind {
    match keyword {
        SPHERE_KW | BOX_KW | CYLINDER_KW | CONE_KW | PLANE_KW | TORUS_KW | UNION_KW
        | INTERSECTION_KW | DIFFERENCE_KW | MERGE_KW | OBJECT_KW | BLOB_KW | BICUBIC_PATCH_KW
        | DISC_KW | HEIGHT_FIELD_KW | ISOSURFACE_KW | JULIA_FRACTAL_KW | LATHE_KW | LEMON_KW
        | MESH_KW | MESH2_KW | OVUS_KW | PARAMETRIC_KW | POLYGON_KW | POLY_KW | POLYNOMIAL_KW
        | PRISM_KW | QUADRIC_KW | QUARTIC_KW | CUBIC_KW | SOR_KW | SPHERE_SWEEP_KW
        | SUPERELLIPSOID_KW | TEXT_KW | TRIANGLE_KW | SMOOTH_TRIANGLE_KW | LIGHT_GROUP_KW => OBJECT,
        CAMERA_KW => CAMERA,
        LIGHT_SOURCE_KW => LIGHT_SOURCE,
        TEXTURE_KW | MATERIAL_KW | INTERIOR_TEXTURE_KW => TEXTURE,
        PIGMENT_KW => PIGMENT,
        NORMAL_KW => NORMAL,
        FINISH_KW => FINISH,
        INTERIOR_KW => INTERIOR,
        MEDIA_KW => MEDIA,
        DENSITY_KW => DENSITY,
        GLOBAL_SETTINGS_KW => GLOBAL_SETTINGS,
        BACKGROUND_KW | FOG_KW | RAINBOW_KW | SKY_SPHERE_KW => ATMOSPHERIC,
        TRANSFORM_KW => TRANSFORM,
        SPLINE_KW => SPLINE,
        _ => BLOCK,
    }
}
