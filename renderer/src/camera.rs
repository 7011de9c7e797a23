//! Primary rays for every POV-Ray projection. The camera's vectors are used as the scene
//! gives them (the evaluator has applied `look_at`, `angle` and `sky`), so a mirrored
//! `right` mirrors the picture, as in POV-Ray. The projections follow the manual's
//! description of each camera type: perspective and orthographic map the image onto the
//! `right`/`up` plane; fisheye, ultra_wide_angle, omnimax, panoramic, the four cylinder
//! cameras and spherical map it onto angles.

use crate::focal_blur::FocalBlur;
use crate::mesh_camera::MeshRays;
use crate::ray::Ray;
use crate::texture_point::TexturePoint;
use analysis::scene::{self, CameraKind};
use glam::{DMat3, DVec3};
use std::f64::consts::{FRAC_PI_2, PI};

#[derive(Debug, Clone)]
pub struct Camera {
    kind: CameraKind,
    location: DVec3,
    direction: DVec3,
    /// `direction` normalized: an orthographic camera's every ray, found once rather
    /// than for each (a square root and a division).
    unit_direction: DVec3,
    right: DVec3,
    up: DVec3,
    /// The viewing angle in degrees for the angular projections.
    angle: f64,
    right_len: f64,
    up_len: f64,
    /// Depth of field: each sample then looks through a point of the lens.
    pub focal_blur: Option<FocalBlur>,
    /// Bumps perturbing every ray's direction.
    normal: Option<scene::Normal>,
    /// A mesh camera's faces.
    mesh: Option<MeshRays>,
    /// A perspective camera without a normal pattern, at a finite location: the common
    /// camera, whose rays [`Camera::ray`] finds inline.
    plain_perspective: bool,
    /// An orthographic camera without a normal pattern, at a finite location, whose one
    /// ray direction is finite and not zero: its rays too are found inline.
    plain_orthographic: bool,
}

impl Camera {
    pub fn from_scene(camera: &scene::Camera) -> Result<Camera, String> {
        if let Some(normal) = &camera.normal {
            crate::normal::check(normal)?;
        }
        let (right_len, up_len) = (camera.right.length(), camera.up.length());
        let mut c = Camera {
            kind: camera.kind.clone(),
            location: camera.location,
            direction: camera.direction,
            unit_direction: camera.direction.normalize_or_zero(),
            right: camera.right,
            up: camera.up,
            angle: camera.angle.unwrap_or(90.0),
            right_len,
            up_len,
            focal_blur: FocalBlur::from_scene(camera)?,
            normal: camera.normal.clone(),
            mesh: match &camera.kind {
                CameraKind::Mesh(mesh) => {
                    Some(MeshRays::new(mesh, camera.location, camera.direction))
                }
                _ => None,
            },
            plain_perspective: matches!(camera.kind, CameraKind::Perspective)
                && camera.normal.is_none()
                && camera.location.is_finite(),
            plain_orthographic: false,
        };
        c.plain_orthographic = matches!(camera.kind, CameraKind::Orthographic)
            && camera.normal.is_none()
            && camera.location.is_finite()
            && c.unit_direction != DVec3::ZERO
            && c.unit_direction.is_finite();
        // These projections use unit vectors; the others use the vectors' lengths.
        if matches!(
            c.kind,
            CameraKind::Fisheye
                | CameraKind::Omnimax
                | CameraKind::UltraWideAngle
                | CameraKind::Cylinder(_)
        ) {
            c.right = c.right.normalize_or_zero();
            c.up = c.up.normalize_or_zero();
            c.direction = c.direction.normalize_or_zero();
        }
        Ok(c)
    }

    /// A mesh camera whose faces give the rays pixel by pixel, whatever the position in
    /// the pixel (distributions 0 to 2; the uv mapped one goes through [`Camera::ray`]).
    pub fn mesh(&self) -> Option<&MeshRays> {
        self.mesh.as_ref().filter(|mesh| mesh.by_pixel())
    }

    /// How a perspective or orthographic camera's rays leave it, for the vista of the
    /// objects each may meet ([`crate::bvh::vista`]); `None` for the other projections.
    pub fn view(&self) -> Option<View> {
        let frame = DMat3::from_cols(self.right, self.up, self.direction);
        match self.kind {
            CameraKind::Perspective => Some(View::Perspective {
                eye: self.location,
                frame,
            }),
            // Every ray carries this one direction (see `ray`).
            CameraKind::Orthographic => Some(View::Orthographic {
                location: self.location,
                frame,
                ray_direction: self.unit_direction,
            }),
            _ => None,
        }
    }

    /// The ray through image position `(x, y)`, in pixels from the top-left corner of the
    /// image (pixel centres at half-integers). `None` where the projection has no ray.
    #[inline(always)]
    pub fn ray(&self, x: f64, y: f64, width: f64, height: f64) -> Option<Ray> {
        // The common camera's rays are found inline, without a call (the same arithmetic
        // as `projected_ray`'s, and the same rays). Its location is finite, and a
        // direction scaled by a finite, positive reciprocal of its length (the test of
        // `normalize_or_zero`) is finite and not zero, its largest component near 1:
        // the tests `projected_ray` makes of its normalized direction pass. An
        // orthographic camera's one direction passed them once, so only the origin is
        // left to test.
        if self.plain_perspective {
            let x0 = x / width - 0.5;
            let y0 = 0.5 - y / height;
            let direction = self.direction + x0 * self.right + y0 * self.up;
            let rcp = direction.length_recip();
            return (rcp.is_finite() && rcp > 0.0)
                .then(|| Ray::new(self.location, direction * rcp));
        }
        if self.plain_orthographic {
            let x0 = x / width - 0.5;
            let y0 = 0.5 - y / height;
            let origin = self.location + x0 * self.right + y0 * self.up;
            return origin
                .is_finite()
                .then(|| Ray::new(origin, self.unit_direction));
        }
        self.projected_ray(x, y, width, height)
    }

    /// [`Camera::ray`] through any camera.
    #[inline(never)]
    fn projected_ray(&self, x: f64, y: f64, width: f64, height: f64) -> Option<Ray> {
        // Image position as -0.5..0.5 across and 0.5..-0.5 down.
        let x0 = x / width - 0.5;
        let y0 = 0.5 - y / height;
        let (origin, direction) = match &self.kind {
            CameraKind::Perspective => (
                self.location,
                self.direction + x0 * self.right + y0 * self.up,
            ),
            CameraKind::Orthographic => (
                self.location + x0 * self.right + y0 * self.up,
                self.unit_direction,
            ),
            CameraKind::Fisheye => {
                let (u, v) = (2.0 * x0 * self.right_len, 2.0 * y0 * self.up_len);
                let rad = (u * u + v * v).sqrt();
                if rad > 1.0 {
                    return None;
                }
                let phi = polar_angle(u, v, rad);
                let theta = rad * self.angle.to_radians() / 2.0;
                (self.location, self.angular(phi, theta))
            }
            CameraKind::Omnimax => {
                let (mut u, mut v) = (2.0 * x0, 2.0 * y0);
                let a = ratio(self.right_len, self.up_len);
                if a > 1.0 {
                    if a > 1.283458 {
                        u *= a / 1.283458;
                        v = (v - 1.0) / 1.283458 + 1.0;
                    } else {
                        v = (v - 1.0) / a + 1.0;
                    }
                } else {
                    v /= a;
                }
                let rad = (u * u + v * v).sqrt();
                if rad > 1.0 {
                    return None;
                }
                let phi = polar_angle(u, v, rad);
                let theta = 1.411269 * rad - 0.09439 * rad.powi(3) + 0.25674 * rad.powi(5);
                let (st, ct) = theta.sin_cos();
                // Nothing below 45 degrees under the projection axis.
                if phi.sin() * st < (135f64).to_radians().tan() * ct {
                    return None;
                }
                (self.location, self.angular(phi, theta))
            }
            CameraKind::Panoramic => {
                let u = (1.0 - (x0 + 0.5)) * PI;
                let v = FRAC_PI_2 * 2.0 * y0;
                let ty = if (FRAC_PI_2 - v.abs()).abs() < 1e-10 {
                    v.signum() * 1e10
                } else {
                    v.tan()
                };
                (
                    self.location,
                    u.cos() * self.right + ty * self.up + u.sin() * self.direction,
                )
            }
            CameraKind::UltraWideAngle => {
                let u = x0 * self.angle.to_radians();
                let v = y0 * self.angle.to_radians() * ratio(self.up_len, self.right_len);
                (
                    self.location,
                    u.sin() * self.right + v.sin() * self.up + u.cos() * v.cos() * self.direction,
                )
            }
            CameraKind::Cylinder(n) => {
                let a = self.angle.to_radians();
                match n {
                    1 => {
                        let u = x0 * a;
                        let v = y0 * self.up_len;
                        (
                            self.location,
                            u.sin() * self.right + v * self.up + u.cos() * self.direction,
                        )
                    }
                    2 => {
                        let v = y0 * a;
                        let u = x0 * self.right_len;
                        (
                            self.location,
                            u * self.right + v.sin() * self.up + v.cos() * self.direction,
                        )
                    }
                    3 => {
                        let u = x0 * a;
                        let v = y0 * self.up_len;
                        (
                            self.location + v * self.up,
                            u.sin() * self.right + u.cos() * self.direction,
                        )
                    }
                    _ => {
                        let v = y0 * a;
                        let u = x0 * self.right_len;
                        (
                            self.location + u * self.right,
                            v.sin() * self.up + v.cos() * self.direction,
                        )
                    }
                }
            }
            CameraKind::Mesh(_) => return self.mesh_ray(x, y, width, height),
            CameraKind::Spherical { h_angle, v_angle } => {
                let lat = y0 * v_angle.to_radians();
                let lon = x0 * h_angle.to_radians();
                // Turn the direction up by the latitude about `right`, then about `up`
                // by the longitude.
                let v1 = DMat3::from_axis_angle(self.right, -lat) * self.direction;
                (self.location, DMat3::from_axis_angle(self.up, lon) * v1)
            }
        };
        let mut direction = match self.kind {
            CameraKind::Orthographic => direction,
            _ => direction.normalize_or_zero(),
        };
        if let Some(normal) = &self.normal {
            // POV-Ray samples the camera's normal pattern on the image itself, at the
            // position (x0, y0, 0), and pushes the ray's world direction by it.
            let at = TexturePoint::in_space(DVec3::new(x0, y0, 0.0));
            direction = crate::normal::perturb(normal, &at, direction);
        }
        (direction != DVec3::ZERO && direction.is_finite() && origin.is_finite())
            .then(|| Ray::new(origin, direction))
    }

    /// The first ray of the pixel that holds image position `(x, y)` through a mesh camera
    /// (see [`crate::sampling::Sampler::mesh_pixel`]). Kept out of [`Self::ray`], which every
    /// other camera's rays go through.
    #[inline(never)]
    fn mesh_ray(&self, x: f64, y: f64, width: f64, height: f64) -> Option<Ray> {
        let mesh = self.mesh.as_ref()?;
        if !mesh.by_pixel() {
            return mesh.uv_ray(x, y, (width, height));
        }
        let size = (width as u32, height as u32);
        mesh.pixel_ray(0, MeshRays::pixel_at(x, y, size), size)
    }

    /// The direction at azimuth `phi` around the view axis and `theta` away from it.
    fn angular(&self, phi: f64, theta: f64) -> DVec3 {
        let (sp, cp) = phi.sin_cos();
        let (st, ct) = theta.sin_cos();
        (cp * st) * self.right + (sp * st) * self.up + ct * self.direction
    }
}

/// Where a camera's rays start and which way they go: the matrix `frame` has the camera's
/// `right`, `up` and `direction` as columns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum View {
    /// Every ray starts at `eye`, along `direction` plus the image position's shares of
    /// `right` and `up`.
    Perspective { eye: DVec3, frame: DMat3 },
    /// Every ray goes along `ray_direction` (the camera's `direction`, normalized), from
    /// `location` plus the image position's shares of `right` and `up`.
    Orthographic {
        location: DVec3,
        frame: DMat3,
        ray_direction: DVec3,
    },
}

fn ratio(a: f64, b: f64) -> f64 {
    if b > 0.0 { a / b } else { 1.0 }
}

fn polar_angle(u: f64, v: f64, rad: f64) -> f64 {
    if rad == 0.0 {
        0.0
    } else if u < 0.0 {
        PI - (v / rad).asin()
    } else {
        (v / rad).asin()
    }
}
