//! Whether a point lies inside a scene object, for the `object` pattern, which patterns
//! evaluate at parse time too (`function { pattern { object { } } }`), so the test works
//! on the scene description itself rather than on the renderer's runtime shapes.

use crate::scene::mesh::MeshGeometry;
use crate::scene::{CsgOp, Object, Shape};
use glam::DVec3;

/// Whether the object's inside can be told; `Err` names the shape that cannot.
pub fn check(object: &Object) -> Result<(), String> {
    match &object.shape {
        Shape::Sphere { .. }
        | Shape::Box { .. }
        | Shape::Cylinder { .. }
        | Shape::Cone { .. }
        | Shape::Plane { .. }
        | Shape::Disc { .. }
        | Shape::Torus { .. }
        | Shape::Quadric { .. }
        | Shape::Triangle { .. }
        | Shape::SmoothTriangle { .. }
        | Shape::Mesh(_)
        | Shape::Polygon(_)
        | Shape::BicubicPatch(_) => Ok(()),
        Shape::Csg { children, .. } => children.iter().try_for_each(check),
        Shape::LightGroup(group) => group.objects.iter().try_for_each(check),
        #[allow(unreachable_patterns)]
        _ => Err("not supported yet: this shape in the object pattern".into()),
    }
}

/// Whether `p` (in the coordinates the object was written in) is inside the object.
pub fn inside(object: &Object, p: DVec3) -> bool {
    let local = object.transform.inverse.transform_point3(p);
    let within = match &object.shape {
        Shape::Sphere { center, radius } => (local - *center).length_squared() < radius * radius,
        Shape::Box { corner1, corner2 } => {
            let (lo, hi) = (corner1.min(*corner2), corner1.max(*corner2));
            local.cmpgt(lo).all() && local.cmplt(hi).all()
        }
        Shape::Cylinder {
            base, cap, radius, ..
        } => {
            let axis = *cap - *base;
            let t = (local - *base).dot(axis) / axis.length_squared();
            let off = local - (*base + axis * t);
            (0.0..=1.0).contains(&t) && off.length_squared() < radius * radius
        }
        Shape::Cone {
            base,
            base_radius,
            cap,
            cap_radius,
            ..
        } => {
            let axis = *cap - *base;
            let t = (local - *base).dot(axis) / axis.length_squared();
            let off = local - (*base + axis * t);
            let r = base_radius + (cap_radius - base_radius) * t;
            (0.0..=1.0).contains(&t) && off.length() < r.abs()
        }
        Shape::Plane { normal, distance } => local.dot(normal.normalize_or_zero()) < *distance,
        Shape::Torus { major, minor, .. } => {
            let ring = (local.x * local.x + local.z * local.z).sqrt() - major;
            ring * ring + local.y * local.y < minor * minor
        }
        Shape::Quadric {
            squares,
            mixed,
            linear,
            constant,
        } => {
            let q = local;
            let value = squares.dot(q * q)
                + mixed.x * q.x * q.y
                + mixed.y * q.x * q.z
                + mixed.z * q.y * q.z
                + linear.dot(q)
                + constant;
            value < 0.0
        }
        Shape::Mesh(mesh) => mesh
            .inside_vector
            .is_some_and(|direction| odd_crossings(&mesh.geometry, local, direction)),
        Shape::LightGroup(group) => group.objects.iter().any(|c| inside(c, local)),
        Shape::Csg { op, children, .. } => match op {
            CsgOp::Union | CsgOp::Merge => children.iter().any(|c| inside(c, local)),
            CsgOp::Intersection => children.iter().all(|c| inside(c, local)),
            CsgOp::Difference => {
                let mut rest = children.iter();
                rest.next().is_some_and(|first| inside(first, local))
                    && rest.all(|c| !inside(c, local))
            }
        },
        #[allow(unreachable_patterns)]
        _ => false,
    };
    within != object.flags.inverse
}

/// Whether the ray from `p` along `direction` crosses the mesh's triangles an odd number
/// of times, POV-Ray's test for the inside of a mesh with an `inside_vector`. Every triangle
/// is tried: the scene description has no acceleration structure, and the object pattern
/// rarely meets large meshes.
fn odd_crossings(mesh: &MeshGeometry, p: DVec3, direction: DVec3) -> bool {
    let mut odd = false;
    for face in &mesh.faces {
        let [a, b, c] = face.vertices.map(|i| mesh.vertices[i as usize]);
        let (e1, e2) = (b - a, c - a);
        let pv = direction.cross(e2);
        let det = e1.dot(pv);
        if det == 0.0 {
            continue;
        }
        let tv = p - a;
        let u = tv.dot(pv) / det;
        let qv = tv.cross(e1);
        let v = direction.dot(qv) / det;
        let t = e2.dot(qv) / det;
        if u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 {
            odd = !odd;
        }
    }
    odd
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spheres_and_differences_have_insides() {
        let sphere = |r: f64| {
            Object::new(
                Shape::Sphere {
                    center: DVec3::ZERO,
                    radius: r,
                },
                None,
            )
        };
        assert!(inside(&sphere(1.0), DVec3::X * 0.5));
        assert!(!inside(&sphere(1.0), DVec3::X * 1.5));
        let ring = Object::new(
            Shape::Csg {
                op: CsgOp::Difference,
                children: vec![sphere(1.0), sphere(0.5)],
                lights: Vec::new(),
            },
            None,
        );
        assert!(inside(&ring, DVec3::X * 0.75));
        assert!(!inside(&ring, DVec3::X * 0.25));
        assert!(check(&ring).is_ok());
    }
}
