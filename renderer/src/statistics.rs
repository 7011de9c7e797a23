//! What the world built from a scene holds and what its acceleration structures cost, for
//! benchmarks and reports.

use crate::build::{BuildError, BuildSettings, build_world};
use crate::object::Object;
use crate::shapes::Shape;
use analysis::scene::Scene;
use std::collections::HashSet;

/// Counts and sizes of a built world.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WorldStatistics {
    /// Top-level objects: shapes, and CSG trees counted once.
    pub objects: usize,
    /// The bytes the top-level objects take themselves, without what they share.
    pub object_bytes: usize,
    /// The bytes of the hierarchy over the objects.
    pub bvh_bytes: usize,
    /// Distinct meshes (copies share one) and their triangles.
    pub meshes: usize,
    pub mesh_triangles: usize,
    /// The bytes of the distinct meshes: their lists and their hierarchies.
    pub mesh_bytes: usize,
}

/// Builds the world of `scene` as a render would and measures it.
pub fn world_statistics(scene: &Scene) -> Result<WorldStatistics, BuildError> {
    let world = build_world(
        scene,
        BuildSettings {
            quality: 9,
            output_alpha: false,
            max_trace_level: None,
        },
    )?;
    let mut statistics = WorldStatistics {
        objects: 0,
        object_bytes: 0,
        bvh_bytes: world.bvh.memory(),
        meshes: 0,
        mesh_triangles: 0,
        mesh_bytes: 0,
    };
    let mut seen = HashSet::new();
    for object in world.bvh.objects() {
        statistics.objects += 1;
        statistics.object_bytes += std::mem::size_of::<Object>();
        count_meshes(object, &mut seen, &mut statistics);
    }
    Ok(statistics)
}

fn count_meshes(
    object: &Object,
    seen: &mut HashSet<*const crate::shapes::mesh::MeshData>,
    statistics: &mut WorldStatistics,
) {
    match object {
        Object::Leaf(leaf) => {
            if let Shape::Mesh(mesh) = &leaf.shape
                && seen.insert(std::sync::Arc::as_ptr(&mesh.data))
            {
                statistics.meshes += 1;
                statistics.mesh_triangles += mesh.data.face_count();
                statistics.mesh_bytes += mesh.data.memory();
            }
        }
        Object::Csg(csg) => {
            for child in &csg.children {
                count_meshes(child, seen, statistics);
            }
        }
    }
}
