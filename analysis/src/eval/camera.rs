//! `camera { }`. Items apply in POV-Ray's order, measured against POV-Ray 3.7: `angle`
//! rescales `direction` at once from the current `right`; `look_at` waits for the end of the
//! statement and keeps the lengths (and the handedness) of direction, right and up; then
//! transformations move the result.

use super::tokens::Token;
use super::value::{CameraValue, Value};
use super::{Evaluator, Result};
use crate::scene::mesh::MeshGeometry;
use crate::scene::{Camera, CameraKind, FocalBlur, MeshCamera, Shape};
use glam::{DAffine3, DVec3};
use std::sync::Arc;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// A camera statement, kept as a [`CameraValue`] so that a declared camera can be
    /// modified later.
    pub fn camera_value(&mut self) -> Result<CameraValue> {
        let keyword = self.expect(CAMERA_KW, "'camera'")?;
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut value = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Camera(c)) => CameraValue::clone(&c),
            _ => {
                self.unget(first);
                CameraValue {
                    camera: Camera::default(),
                    look_at: None,
                    transforms: Vec::new(),
                }
            }
        };
        if value.camera.origin.is_none() {
            value.camera.origin = Some(self.span(&keyword));
        }
        loop {
            let token = self.next()?;
            let camera = &mut value.camera;
            match token.kind {
                R_BRACE => return Ok(value),
                PERSPECTIVE_KW => camera.kind = CameraKind::Perspective,
                ORTHOGRAPHIC_KW => camera.kind = CameraKind::Orthographic,
                FISHEYE_KW => camera.kind = CameraKind::Fisheye,
                ULTRA_WIDE_ANGLE_KW => camera.kind = CameraKind::UltraWideAngle,
                OMNIMAX_KW => camera.kind = CameraKind::Omnimax,
                PANORAMIC_KW => camera.kind = CameraKind::Panoramic,
                CYLINDER_KW => {
                    let n = self.int()?;
                    if !(1..=4).contains(&n) {
                        return Err(self.error_at(
                            &token,
                            format!("cylinder camera type must be 1 to 4, not {n}"),
                        ));
                    }
                    value.camera.kind = CameraKind::Cylinder(n as u8);
                }
                SPHERICAL_KW => {
                    camera.kind = CameraKind::Spherical {
                        h_angle: 360.0,
                        v_angle: 180.0,
                    }
                }
                LOCATION_KW => camera.location = self.vector()?,
                DIRECTION_KW => camera.direction = self.vector()?,
                RIGHT_KW => camera.right = self.vector()?,
                UP_KW => camera.up = self.vector()?,
                SKY_KW => camera.sky = self.vector()?,
                LOOK_AT_KW => value.look_at = Some(self.vector()?),
                ANGLE_KW => {
                    let angle = self.float()?;
                    self.eat(COMMA)?;
                    let vertical = if self.value_follows()? {
                        Some(self.float()?)
                    } else {
                        None
                    };
                    self.apply_angle(&mut value.camera, &token, angle, vertical)?;
                }
                APERTURE_KW => blur(camera).aperture = self.float()?,
                BLUR_SAMPLES_KW => {
                    let first = self.int()?.max(0) as u32;
                    let (min, max) = if self.eat(COMMA)? {
                        (first, self.int()?.max(0) as u32)
                    } else {
                        // The manual's default minimum: 4 below 7 samples, 7 from there.
                        (if first < 7 { 4 } else { 7 }, first)
                    };
                    let b = blur(&mut value.camera);
                    b.min_samples = min.clamp(1, max.max(1));
                    b.max_samples = max;
                }
                FOCAL_POINT_KW => blur(camera).focal_point = self.vector()?,
                CONFIDENCE_KW => {
                    let confidence = self.float()?;
                    if !(0.0..1.0).contains(&confidence) {
                        return Err(self.error_at(
                            &token,
                            format!("confidence must be at least 0 and below 1, not {confidence}"),
                        ));
                    }
                    blur(camera).confidence = confidence;
                }
                VARIANCE_KW => {
                    let variance = self.float()?;
                    if variance == 1.0 {
                        // As POV-Ray does: 1 would accept any spread, so the default
                        // stands, with a warning.
                        self.warn_at(&token, "variance 1 ignored: using the default 1/128");
                    } else {
                        blur(&mut value.camera).variance = variance;
                    }
                }
                NORMAL_KW => camera.normal = Some(self.normal_body()?),
                MESH_CAMERA_KW => camera.kind = CameraKind::Mesh(Arc::new(self.mesh_camera()?)),
                // The manual puts `smooth` after the mesh_camera block; POV-Ray's examples
                // put it inside. Both are read.
                SMOOTH_KW => match &mut camera.kind {
                    CameraKind::Mesh(mesh) => Arc::make_mut(mesh).smooth = true,
                    _ => return Err(self.error_at(&token, "smooth is for a mesh_camera")),
                },
                BOKEH_KW => {
                    return Err(self.unsupported(&token, &format!("camera {}", self.text(&token))));
                }
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    value.transforms.push(t);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a camera item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `mesh_camera { rays distribution [max_distance] mesh { M [transformations] } ...
    /// [smooth] }`, after its keyword.
    fn mesh_camera(&mut self) -> Result<MeshCamera> {
        self.expect(L_BRACE, "'{'")?;
        let rays_at = self.next()?;
        self.unget(rays_at.clone());
        let rays = self.int()?;
        if rays < 1 {
            return Err(self.error_at(
                &rays_at,
                format!("a mesh_camera shoots at least 1 ray per pixel, not {rays}"),
            ));
        }
        self.eat(COMMA)?;
        let distribution_at = self.next()?;
        self.unget(distribution_at.clone());
        let distribution = self.int()?;
        if !(0..=3).contains(&distribution) {
            return Err(self.error_at(
                &distribution_at,
                format!("the mesh_camera distribution must be 0 to 3, not {distribution}"),
            ));
        }
        self.eat(COMMA)?;
        if self.value_follows()? {
            let at = self.next()?;
            self.unget(at.clone());
            if self.float()? > 1e-10 {
                return Err(self.unsupported(&at, "a mesh_camera's max distance"));
            }
        }
        let mut camera = MeshCamera {
            rays_per_pixel: rays as u32,
            distribution: distribution as u8,
            meshes: Vec::new(),
            smooth: false,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                MESH_KW => camera.meshes.push(self.camera_mesh(&token)?),
                SMOOTH_KW => camera.smooth = true,
                R_BRACE if camera.meshes.is_empty() => {
                    return Err(self.error_at(&token, "a mesh_camera needs at least one mesh"));
                }
                R_BRACE => break,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected mesh, smooth or '}}' in mesh_camera, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        // The manual's limits: distribution 0 takes each ray of a pixel from its own mesh,
        // 2 and 3 shoot one ray per pixel.
        let meshes = camera.meshes.len();
        if distribution == 0 && (rays as usize) > meshes {
            return Err(self.error_at(
                &rays_at,
                format!(
                    "mesh_camera distribution 0 takes each ray from its own mesh: {rays} rays per pixel need {rays} meshes, not {meshes}"
                ),
            ));
        }
        if distribution >= 2 && rays != 1 {
            return Err(self.error_at(
                &rays_at,
                format!(
                    "mesh_camera distribution {distribution} shoots 1 ray per pixel, not {rays}"
                ),
            ));
        }
        Ok(camera)
    }

    /// `mesh { M [transformations] }` in a mesh_camera: a declared mesh, placed.
    fn camera_mesh(&mut self, keyword: &Token) -> Result<(Arc<MeshGeometry>, DAffine3)> {
        self.expect(L_BRACE, "'{'")?;
        let mut object = self.object_or_identifier()?;
        self.object_modifiers(&mut object, keyword)?;
        self.expect(R_BRACE, "'}'")?;
        match object.shape {
            Shape::Mesh(mesh) => Ok((mesh.geometry.clone(), object.transform.matrix)),
            _ => Err(self.error_at(keyword, "a mesh_camera's mesh must be a mesh or mesh2")),
        }
    }

    fn apply_angle(
        &self,
        camera: &mut Camera,
        at: &super::tokens::Token,
        angle: f64,
        vertical: Option<f64>,
    ) -> Result<()> {
        if angle < 0.0 {
            return Err(self.error_at(at, "a camera angle must not be negative"));
        }
        camera.angle = Some(angle);
        match &mut camera.kind {
            CameraKind::Perspective => {
                if angle >= 180.0 {
                    return Err(self.error_at(
                        at,
                        "a perspective camera's angle must be less than 180 degrees",
                    ));
                }
                let length = 0.5 * camera.right.length() / (angle.to_radians() / 2.0).tan();
                camera.direction = camera.direction.normalize_or(DVec3::Z) * length;
            }
            CameraKind::Spherical { h_angle, v_angle } => {
                *h_angle = angle;
                *v_angle = vertical.unwrap_or(angle / 2.0);
            }
            _ => {}
        }
        Ok(())
    }

    /// The final camera: `look_at`, then the transformations.
    pub fn finish_camera(&self, value: &CameraValue) -> Camera {
        let mut camera = value.camera.clone();
        if let Some(target) = value.look_at {
            let direction_length = camera.direction.length();
            let up_length = camera.up.length();
            let right_length = camera.right.length();
            let handedness = camera.up.cross(camera.direction).dot(camera.right);
            let direction =
                (target - camera.location).normalize_or(camera.direction.normalize_or(DVec3::Z));
            let mut right = camera.sky.cross(direction);
            if right.length() < 1e-12 {
                right = camera.right;
            }
            let right = right.normalize_or(DVec3::X);
            let up = direction.cross(right).normalize_or(DVec3::Y);
            camera.direction = direction * direction_length;
            camera.right = right
                * if handedness > 0.0 {
                    right_length
                } else {
                    -right_length
                };
            camera.up = up * up_length;
        }
        for t in &value.transforms {
            camera.location = t.point(camera.location);
            camera.direction = t.vector(camera.direction);
            camera.right = t.vector(camera.right);
            camera.up = t.vector(camera.up);
            camera.sky = t.vector(camera.sky);
            // The focal point moves with the camera, as POV-Ray's does.
            if let Some(blur) = &mut camera.focal_blur {
                blur.focal_point = t.point(blur.focal_point);
            }
        }
        camera
    }
}

fn blur(camera: &mut Camera) -> &mut FocalBlur {
    // POV-Ray's defaults: no aperture and no samples, so that either alone blurs nothing.
    camera.focal_blur.get_or_insert(FocalBlur {
        aperture: 0.0,
        min_samples: 0,
        max_samples: 0,
        focal_point: DVec3::ZERO,
        confidence: 0.9,
        variance: 1.0 / 128.0,
    })
}

#[cfg(test)]
mod tests {
    use crate::eval::{EvalOptions, evaluate};
    use crate::files::MemoryFiles;
    use crate::scene::{CameraKind, FocalBlur};
    use glam::DVec3;

    fn blur_of(camera: &str) -> Option<FocalBlur> {
        let text = format!("#version 3.7;\ncamera {{ {camera} }}\n");
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        evaluation
            .scene
            .expect("the camera evaluates")
            .camera
            .focal_blur
    }

    #[test]
    fn blur_samples_take_the_manuals_default_minimum() {
        let blur = blur_of("aperture 1 blur_samples 5").unwrap();
        assert_eq!((blur.min_samples, blur.max_samples), (4, 5));
        let blur = blur_of("aperture 1 blur_samples 30").unwrap();
        assert_eq!((blur.min_samples, blur.max_samples), (7, 30));
        let blur = blur_of("aperture 1 blur_samples 2, 30").unwrap();
        assert_eq!((blur.min_samples, blur.max_samples), (2, 30));
        // A minimum above the maximum is the maximum.
        let blur = blur_of("aperture 1 blur_samples 3").unwrap();
        assert_eq!((blur.min_samples, blur.max_samples), (3, 3));
    }

    #[test]
    fn an_aperture_alone_takes_no_samples() {
        let blur = blur_of("aperture 1").unwrap();
        assert_eq!(blur.max_samples, 0);
        assert_eq!(blur.confidence, 0.9);
        assert_eq!(blur.variance, 1.0 / 128.0);
    }

    #[test]
    fn the_focal_point_moves_with_the_camera() {
        let blur =
            blur_of("aperture 1 blur_samples 9 focal_point <0, 0, 5> translate <1, 2, 3>").unwrap();
        assert_eq!(blur.focal_point, DVec3::new(1.0, 2.0, 8.0));
    }

    #[test]
    fn variance_one_keeps_the_default() {
        let blur = blur_of("aperture 1 blur_samples 9 variance 1").unwrap();
        assert_eq!(blur.variance, 1.0 / 128.0);
    }
    fn camera_of(camera: &str) -> Result<crate::scene::Camera, String> {
        let text = format!(
            "#version 3.7;\n#declare M = mesh {{ triangle {{ 0, x, y }} triangle {{ 0, y, z }} }}\ncamera {{ {camera} }}\n"
        );
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        match evaluation.diagnostics.iter().find(|d| d.is_error()) {
            Some(error) => Err(error.message.clone()),
            None => Ok(evaluation.scene.expect("the camera evaluates").camera),
        }
    }

    #[test]
    fn a_mesh_camera_keeps_its_placed_meshes() {
        let camera =
            camera_of("mesh_camera { 2, 1 mesh { M translate x } mesh { M } } smooth").unwrap();
        let CameraKind::Mesh(mesh) = camera.kind else {
            panic!("not a mesh camera: {:?}", camera.kind);
        };
        assert_eq!((mesh.rays_per_pixel, mesh.distribution), (2, 1));
        assert!(mesh.smooth);
        assert_eq!(mesh.meshes.len(), 2);
        assert_eq!(mesh.meshes[0].0.faces.len(), 2);
        assert_eq!(mesh.meshes[0].1.translation, DVec3::X);
        assert_eq!(mesh.meshes[1].1.translation, DVec3::ZERO);
    }

    #[test]
    fn mesh_camera_mistakes_are_errors() {
        let error = |camera: &str| camera_of(camera).unwrap_err();
        assert_eq!(
            error("mesh_camera { 1 4 mesh { M } }"),
            "the mesh_camera distribution must be 0 to 3, not 4"
        );
        assert_eq!(
            error("mesh_camera { 2 0 mesh { M } }"),
            "mesh_camera distribution 0 takes each ray from its own mesh: 2 rays per pixel need 2 meshes, not 1"
        );
        assert_eq!(
            error("mesh_camera { 2 2 mesh { M } mesh { M } }"),
            "mesh_camera distribution 2 shoots 1 ray per pixel, not 2"
        );
        assert_eq!(
            error("mesh_camera { 2 3 mesh { M } mesh { M } }"),
            "mesh_camera distribution 3 shoots 1 ray per pixel, not 2"
        );
        assert_eq!(
            error("mesh_camera { 1 0 }"),
            "a mesh_camera needs at least one mesh"
        );
        assert_eq!(
            error("mesh_camera { 1 0 mesh { sphere { 0, 1 } } }"),
            "a mesh_camera's mesh must be a mesh or mesh2"
        );
        assert_eq!(error("smooth"), "smooth is for a mesh_camera");
        assert_eq!(
            error("mesh_camera { 1 0 10 mesh { M } }"),
            "not supported yet: a mesh_camera's max distance"
        );
    }
}
