//! The scene's bounded objects in a bounding volume hierarchy ([`tree::Tree`]), built once
//! before tracing. Unbounded objects (planes and what contains them) are kept beside it and
//! tested for every ray.

pub mod tree;

use crate::bounds::Aabb;
use crate::object::{Hit, Object, Query};
use tree::Tree;

/// Objects in one leaf of the tree at most: an object's own test costs about what a box
/// test does, so small leaves pay.
const LEAF_SIZE: usize = 2;

/// The scene's objects with their acceleration structure.
#[derive(Debug, Clone)]
pub struct Bvh {
    tree: Tree,
    objects: Vec<Object>,
    unbounded: Vec<Object>,
}

impl Bvh {
    pub fn build(objects: Vec<Object>) -> Bvh {
        let (bounded, unbounded): (Vec<Object>, Vec<Object>) = objects
            .into_iter()
            .filter(|o| !o.bounds().is_empty())
            .partition(|o| o.bounds().is_finite());
        let boxes: Vec<Aabb> = bounded.iter().map(Object::bounds).collect();
        let (tree, order) = Tree::build(&boxes, LEAF_SIZE);
        let mut slots: Vec<Option<Object>> = bounded.into_iter().map(Some).collect();
        let objects = order
            .iter()
            .filter_map(|&i| slots[i as usize].take())
            .collect();
        Bvh {
            tree,
            objects,
            unbounded,
        }
    }

    /// Whether `p` is inside any object.
    pub fn contains(&self, p: glam::DVec3) -> bool {
        self.objects().any(|o| o.inside(p))
    }

    /// Every object, bounded or not.
    pub fn objects(&self) -> impl Iterator<Item = &Object> {
        self.objects.iter().chain(&self.unbounded)
    }

    /// The bytes of the hierarchy's nodes.
    pub fn memory(&self) -> usize {
        self.tree.memory()
    }

    /// Whether some object is unbounded (a plane, say).
    pub fn has_unbounded(&self) -> bool {
        !self.unbounded.is_empty()
    }

    /// Bounds of every bounded object; empty when there is none.
    pub fn bounds(&self) -> Aabb {
        self.tree.bounds()
    }

    /// The nearest crossing of any object inside the query's interval.
    pub fn nearest<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        let mut q = *q;
        let mut best = None;
        for object in &self.unbounded {
            if let Some(hit) = object.nearest(&q, scratch) {
                q.tmax = hit.t;
                best = Some(hit);
            }
        }
        let ray = q.ray;
        self.tree
            .traverse(&ray, q.inv_dir, q.tmin, q.tmax, |range, tmax| {
                q.tmax = tmax;
                for object in &self.objects[range] {
                    if let Some(hit) = object.nearest(&q, scratch) {
                        q.tmax = hit.t;
                        best = Some(hit);
                    }
                }
                q.tmax
            });
        best
    }
}
